"""The readers' boundary: what every site and model reader shares — the largest file read
(:data:`MAX_FILE_BYTES`) and :func:`reading`, which turns whatever a parser raises on
malformed content into an :class:`~planner.errors.InputError` naming the file.

>>> from planner.errors import InputError
>>> try:
...     with reading("a.csv", "csv"):
...         int("x")
... except InputError as exc:
...     print(str(exc)[:47])
a.csv: cannot read it as a CSV site (ValueError
"""

from __future__ import annotations

import contextlib
import csv
import stat
from collections.abc import Iterator
from pathlib import Path

from shapely.errors import GEOSException, ShapelyError

from planner.errors import InputError

__all__ = ["MAX_FILE_BYTES", "kind_words", "reading", "user_file"]


#: A site file larger than this is refused before it is read [bytes].
MAX_FILE_BYTES = 256_000_000

#: What a parser raises on data it cannot make sense of (turned into an InputError).
PARSE_ERRORS = (
    csv.Error,
    RecursionError,
    ValueError,
    TypeError,
    KeyError,
    AttributeError,
    IndexError,
    OverflowError,
    GEOSException,
    ShapelyError,
)


def kind_words(kind: str) -> str:
    """A file's kind as the messages name it: "a GEOJSON site", "a CityJSON model"."""
    if kind == "mesh":
        return "a mesh"
    if kind.startswith("City"):
        return f"a {kind} model"
    return f"a {kind.upper()} site"


@contextlib.contextmanager
def reading(origin: str, kind: str) -> Iterator[None]:
    """The reader's boundary: whatever the parsers raise on malformed content becomes an
    InputError naming the file (our own InputErrors pass unchanged)."""
    try:
        yield
    except InputError:
        raise
    except PARSE_ERRORS as exc:
        what = (
            "it is nested too deeply"
            if isinstance(exc, RecursionError)
            else f"{type(exc).__name__}: {str(exc).splitlines()[0][:200] if str(exc) else ''}"
        )
        raise InputError(
            f"{origin}: cannot read it as {kind_words(kind)} ({what}); check the file "
            "against the formats in the README"
        ) from None


def user_file(path: str | Path, what: str) -> Path:
    """The path of a file the user named (``what``: "site file", "terrain file"…) as a
    :class:`~pathlib.Path`, where it is a regular file; an InputError saying what it is
    instead — missing, a folder, a pipe or a device (never opened: a pipe would block).

    >>> try:
    ...     user_file("/", "site file")
    ... except InputError as exc:
    ...     print(exc)
    site file '/' is a folder, not a file
    """
    p = Path(path)
    try:
        mode = p.stat().st_mode
    except FileNotFoundError:
        raise InputError(f"{what} {str(p)!r} does not exist") from None
    except OSError as exc:
        raise InputError(f"{what} {str(p)!r} cannot be read ({exc.strerror})") from None
    if stat.S_ISDIR(mode):
        raise InputError(f"{what} {str(p)!r} is a folder, not a file")
    if not stat.S_ISREG(mode):
        kind = "a pipe" if stat.S_ISFIFO(mode) else "a device or socket"
        raise InputError(f"{what} {str(p)!r} is {kind}, not a file; give a file saved on disk")
    return p
