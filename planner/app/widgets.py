"""Widget helpers the dashboards share (the station planner's, the explorers' and the
calibration's): an error box, a download link, showing figures and tables in an Output
widget, the scanner dropdown, the target inventory box and the folder uploads go to. No
science."""

from __future__ import annotations

import base64
import html
import io
import os
import tempfile
from pathlib import Path
from typing import Any

import ipywidgets as w
import matplotlib.pyplot as plt

from planner.app.serve import UPLOAD_ROOT_ENV
from planner.app.wording import for_dashboard_html
from planner.atomic import write_text_atomic
from planner.errors import PlannerError
from planner.scanner import DEFAULT_SCANNER, catalogue, user_profile_dir, user_profiles
from planner.targets import DEFAULT_INVENTORY, parse_inventory

__all__ = [
    "download_link",
    "error_html",
    "inventory_box",
    "output",
    "scanner_dropdown",
    "show",
    "upload_folder",
]


def error_html(message: str, head: str = "Cannot plan") -> str:
    """A message (in the dashboard's words: :mod:`planner.app.wording`) as an error box."""
    return (
        f'<div class="planner-error" style="color:#922;background:#fdecea;border:1px solid #e6b0aa;'
        f'padding:6px 10px;border-radius:4px"><b>{html.escape(head)}:</b> '
        f"{for_dashboard_html(message)}</div>"
    )


def download_link(name: str, data: bytes, mime: str) -> str:
    """A link that downloads ``data`` as the file ``name`` (the data inline, base64)."""
    b64 = base64.b64encode(data).decode("ascii")
    return (
        f'<a download="{name}" href="data:{mime};base64,{b64}" class="planner-download" '
        f'style="margin-right:1em">⬇ {name}</a>'
    )


def output(obj: Any) -> dict:
    """One output of an Output widget: a figure as PNG, anything else as IPython shows it."""
    if isinstance(obj, plt.Figure):
        buf = io.BytesIO()
        obj.savefig(buf, format="png", dpi=96)
        plt.close(obj)
        data = {"image/png": base64.b64encode(buf.getvalue()).decode("ascii"), "text/plain": ""}
        return {"output_type": "display_data", "data": data, "metadata": {}}
    from IPython.core.interactiveshell import InteractiveShell

    data, metadata = InteractiveShell.instance().display_formatter.format(obj)
    return {"output_type": "display_data", "data": data, "metadata": metadata}


def show(out: w.Output, *objs: Any) -> None:
    """Replace what ``out`` shows (at once, from any thread: the plan runs in one), each
    object turned into an output by :func:`output`."""
    out.outputs = tuple(output(o) for o in objs)


def upload_folder() -> tempfile.TemporaryDirectory:
    """Where a dashboard writes uploaded files: inside the server's folder when served (removed
    when the server stops), else a temporary folder of its own."""
    root = os.environ.get(UPLOAD_ROOT_ENV)
    return tempfile.TemporaryDirectory(
        prefix="planner-upload-", dir=root if root and os.path.isdir(root) else None
    )


def scanner_dropdown() -> w.Dropdown:
    """The catalogue's scanners, then the profiles the user installed (by name)."""
    scanners = [*catalogue().values(), *user_profiles()[0].values()]
    return w.Dropdown(
        options=[(s.label or s.name, s.name) for s in scanners],
        value=DEFAULT_SCANNER,
        description="",
        tooltip="the scanner profile (its catalogue name is the --scanner of the command line)",
        layout=w.Layout(width="98%"),
        style={"description_width": "initial"},
    )


def inventory_text(items=DEFAULT_INVENTORY) -> str:
    """An inventory as the dashboard's text: one item a line, name, type, size mm and how
    many the crew has where it counts (read back by :func:`planner.targets.parse_inventory`)."""
    return "\n".join(
        f"{i.name}, {i.type}, {i.size_mm:g}" + (f", {i.count}" if i.count else "") for i in items
    )


def kit_file() -> Path:
    """Where the dashboard remembers the crew's kit between sessions: ``kit.txt`` beside the
    user's scanner profiles (:func:`planner.scanner.user_profile_dir`)."""
    return user_profile_dir() / "kit.txt"


def remembered_kit() -> str:
    """The kit last planned with in the dashboard (:func:`remember_kit`), else the default
    inventory; a file that no longer reads as an inventory is ignored."""
    try:
        text = kit_file().read_text(encoding="utf-8")
        parse_inventory(text)
    except (OSError, UnicodeDecodeError, PlannerError):
        return inventory_text()
    return text


def remember_kit(text: str) -> None:
    """Keep the kit ``text`` (an inventory that parsed) for the next session; a folder that
    cannot be written leaves it unremembered, silently (the plan does not depend on it)."""
    try:
        if kit_file().is_file() and kit_file().read_text(encoding="utf-8") == text:
            return
        write_text_atomic(kit_file(), text)
    except (OSError, PlannerError):
        return


def inventory_box(description: str, style: dict, layout: w.Layout) -> w.Textarea:
    """The target inventory as text, one item a line (name, type, size mm, and how many the
    crew has where it counts), starting from the kit remembered (:func:`remembered_kit`)."""
    return w.Textarea(value=remembered_kit(), description=description, style=style, layout=layout)
