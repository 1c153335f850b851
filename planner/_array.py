"""Input handling shared by the vectorised formula functions.

Scalars, lists, NumPy arrays and pandas Series are accepted; NaN passes through; a value
outside its valid range raises :class:`~planner.errors.InputError` naming the argument,
the valid range and the first offending value.
"""

from __future__ import annotations

import sys
from typing import Any

import numpy as np

from planner.errors import InputError


def as_float_array(value: Any, name: str) -> np.ndarray:
    """``value`` as a float ndarray, or an InputError that names ``name``."""
    if isinstance(value, str):
        raise InputError(f"{name} must be a number or an array of numbers, not the text {value!r}")
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        shown = repr(value)
        shown = shown if len(shown) <= 60 else shown[:57] + "..."
        raise InputError(f"{name} must be a number or an array of numbers (got {shown})") from None


def check_range(
    arr: np.ndarray,
    name: str,
    unit: str,
    *,
    lo: float | None = None,
    hi: float | None = None,
    lo_inclusive: bool = True,
    absolute: bool = False,
) -> np.ndarray:
    """Raise InputError if any non-NaN value of ``arr`` is outside ``[lo, hi]``.

    With ``absolute=True`` the bound applies to ``|arr|`` (``-hi <= arr <= hi``).
    Infinite values are always rejected.
    """
    vals = np.abs(arr) if absolute else arr
    with np.errstate(invalid="ignore"):
        bad = np.isinf(arr)
        if lo is not None:
            bad |= (vals < lo) if lo_inclusive else (vals <= lo)
        if hi is not None:
            bad |= vals > hi
    if np.any(bad):
        idx = np.argwhere(bad)[0]
        where = "" if arr.ndim == 0 else f" at index {tuple(int(i) for i in idx)}"
        first = float(arr[tuple(idx)]) if arr.ndim else float(arr)
        if absolute:
            rule = f"-{hi:g} <= {name} <= {hi:g}"
        elif lo is not None and hi is not None:
            rule = f"{lo:g} {'<=' if lo_inclusive else '<'} {name} <= {hi:g}"
        elif lo is not None:
            rule = f"{name} {'>=' if lo_inclusive else '>'} {lo:g}"
        else:
            rule = f"{name} <= {hi:g}"
        raise InputError(
            f"{name} must satisfy {rule} [{unit}] (got {first:g}{where}); NaN is allowed"
        )
    return arr


def like_input(result: np.ndarray, *inputs: Any) -> Any:
    """Give ``result`` the shape of the caller's input.

    A float for all-scalar input, a Series (with the first Series' index) when a Series
    came in and the shapes agree, otherwise the ndarray.
    """
    pd = sys.modules.get("pandas")  # a Series can only come in if pandas is loaded
    for x in inputs:
        if pd is not None and isinstance(x, pd.Series) and result.shape == (len(x),):
            return pd.Series(result, index=x.index)
    if result.ndim == 0:
        return float(result)
    return result
