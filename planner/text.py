"""User text made safe to show: no control character reaches a file or a terminal.

An id, a name or a file name comes from the user's files. A control character in it (ESC
starts a terminal's escape sequence, NUL, vertical tab and most of C0 are not allowed in
XML 1.0, so Google Earth refuses a KML holding one) or a bidirectional override (which
shows text in another order than it is stored, Unicode Technical Standard #39, §3) is
shown as a visible escape instead; a file name that is not valid UTF-8 (Python keeps its
bytes as lone surrogates) shows its bytes the same way. :func:`printable` is the one helper
every writer and the terminal use.
"""

from __future__ import annotations

import re

__all__ = ["printable"]

#: C0 and C1 controls, DEL, the bidirectional embeddings/overrides/isolates, and lone
#: surrogates (undecodable bytes of a file name).
_UNSAFE = re.compile("[\x00-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069\ud800-\udfff]")


def _escape(m: re.Match[str]) -> str:
    c = ord(m.group())
    if 0xDC80 <= c <= 0xDCFF:  # a byte that was not UTF-8 (surrogateescape)
        return f"\\x{c - 0xDC00:02x}"
    return f"\\x{c:02x}" if c < 0x100 else f"\\u{c:04x}"


def printable(text: str, keep: str = "") -> str:
    """``text`` with every control character except those in ``keep`` (e.g. ``"\\n\\t"``
    for a multi-line text) written as a visible escape (``\\x1b``, ``\\u202e``).

    >>> printable("S01\\x1b[31m red")
    'S01\\\\x1b[31m red'
    >>> printable("line one\\nline two", keep="\\n")
    'line one\\nline two'
    """
    if not _UNSAFE.search(text):
        return text
    return _UNSAFE.sub(lambda m: m.group() if m.group() in keep else _escape(m), text)
