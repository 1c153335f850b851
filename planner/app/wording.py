"""One wording, two renderings: the planner's messages name the command line's options
(``--make-valid``, ``--height H``); the dashboard shows the same message with its own
controls in their place (‘Repair the site…’), or says that an option is the command
line's only.

The dashboard's controls take their labels from here (:data:`SITE_LABELS`) and from the
requirement and setting specs (:func:`planner.pipeline.inputs.requirements.field_specs`), so a
label and the message naming it cannot drift apart.
"""

from __future__ import annotations

import html
import re
from functools import cache

from planner.pipeline.inputs.requirements import PlanSettings, Requirements, field_specs

__all__ = [
    "SITE_LABELS",
    "dashboard_labels",
    "for_dashboard",
    "for_dashboard_html",
    "time_words",
]

#: The dashboard's labels of the command line's options that are not requirement or setting
#: fields (those carry their own label).
SITE_LABELS = {
    "--make-valid": "Repair the site (outlines, overlapping buildings)",
    "--height": "Height where missing [m] (0: none)",
    "--storey-height-m": "Storey height for levels [m]",
    "--crs": "CRS of the coordinates",
    "--buildings": "Buildings to plan (ids)",
    "--scanner": "Scanner",
    "--class": "accuracy class",
    "--model": "accuracy model",
    "--registration": "registration",
    "--registration-processing": "registration processing",
    "--tilt-readings": "tilt readings",
    "--height-control": "height control",
    "--link-check": "cloud links",
    "--registration-error": "count the registration error",
    "--no-registration-error": "count the registration error",
    "--inventory": "targets you own (name, type, size mm, count)",
    "--preset": "scanner setting",
    "--imaging": "count the images (HDR) in the field time",
    "--demand-roofs": "demand the roofs too (3-D models; an elevated station)",
    "--sight-engine": "sight lines",
    "--surface-condition": "survey day",
    "--default-material": "walls made of",
    "--control": "Control CSV",
    "--levelling-rms-arcsec": "Scanner levelling [″] (0: the profile's)",
    "--zone": "Zones",
    "--zones": "Zones",
}

#: An option as the messages write it: the flag and, where one follows, its argument's
#: placeholder or example (``H``, ``ID,ID``, ``EPSG:4326``, ``125``).
_FLAG = re.compile(r"--([a-z][a-z0-9-]*)(?: (?:[A-Z][A-Z0-9,:]*|\d+(?:\.\d+)?)\b)?")
#: Hints for the Python API written beside a flag (``repair=True, --make-valid``).
_API_HINT = re.compile(r"\b[a-z_]+=True, (?=--)")


@cache
def dashboard_labels() -> dict[str, str]:
    """Every option the dashboard has a control for: ``--flag`` → its label."""
    out = {
        spec.flag: spec.label
        for cls in (Requirements, PlanSettings)
        for spec in field_specs(cls).values()
    }
    out.update(SITE_LABELS)
    return out


def for_dashboard(text: str) -> str:
    """``text`` with every command-line option replaced by the dashboard's control (or
    marked as the command line's own where the page has none)."""
    labels = dashboard_labels()

    def control(hit: re.Match) -> str:
        flag = "--" + hit[1]
        if flag in labels:
            return f"the ‘{labels[flag]}’ control"
        return f"the command line's {hit[0]}"

    return _FLAG.sub(control, _API_HINT.sub("", text))


def for_dashboard_html(text: str) -> str:
    """:func:`for_dashboard`, escaped for HTML, its line breaks kept."""
    return html.escape(for_dashboard(text)).replace("\n", "<br>")


def time_words(took_s: float, fraction: float) -> str:
    """The seconds a piece of work has taken and, once a tenth is done, about how many are
    left at its pace so far — the one wording of the command line's progress bar and the
    dashboard's status line.

    >>> time_words(12.0, 0.05), time_words(12.0, 0.4), time_words(30.0, 1.0)
    ('12 s', '12 s, about 18 s left', '30 s')
    """
    if 0.1 <= fraction < 1.0:
        return f"{took_s:.0f} s, about {took_s * (1 - fraction) / fraction:.0f} s left"
    return f"{took_s:.0f} s"
