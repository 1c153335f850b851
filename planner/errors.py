"""The planner's error family, rooted in one base class (as shapely does).

Every error a user can cause is an :class:`InputError`: its message says what was wrong,
the valid range, and what to do. Nothing the user types should surface as a traceback
from deep inside NumPy or GEOS.
"""

from __future__ import annotations


class PlannerError(Exception):
    """Base class of every error raised on purpose by :mod:`planner`."""


class InputError(PlannerError, ValueError):
    """Bad input: a value out of its valid range, an unknown name, an unreadable file."""
