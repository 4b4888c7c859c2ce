"""Input checks shared by the API (Arm, ArmBatch, Model, the real-time client): real numbers, counts,
registered model names, and the unit helpers deg/rad. Each names the input it refuses."""
from __future__ import annotations

import numbers
import operator

import numpy as np

from . import _core

# Largest step count or record interval the engine counts (C++ long on every supported platform).
MAX_COUNT = 2**63 - 1


def real_array(values, what: str) -> np.ndarray:
    """`values` as a float array; TypeError for what is not real numbers (complex, strings, None,
    other objects) instead of numpy's silent casts (complex -> real part, None -> NaN)."""
    if isinstance(values, (str, bytes)):
        raise TypeError(f"{what} must be numbers, got the string {values!r}")
    try:
        arr = np.asarray(values)
    except ValueError as exc:  # ragged nesting
        raise ValueError(f"{what} must be a regular array of numbers: {exc}") from None
    if arr.dtype.kind == "O":
        for v in arr.ravel():
            if v is None:
                raise TypeError(f"{what} contains None; give a number for every value")
            if not isinstance(v, numbers.Real) or isinstance(v, (str, bytes)):
                raise TypeError(f"{what} must be real numbers, got {type(v).__name__} {v!r}")
        arr = arr.astype(float)
    if arr.dtype.kind not in "biuf":
        kind = {"c": "complex", "U": "string", "S": "bytes", "M": "datetime", "m": "timedelta", "V": "structured"}
        raise TypeError(f"{what} must be real numbers, got {kind.get(arr.dtype.kind, str(arr.dtype))} values "
                        f"(dtype {arr.dtype})")
    return arr.astype(float, copy=False)


def real_scalar(value, what: str) -> float:
    """One real number (see real_array); TypeError for anything else, ValueError for arrays."""
    arr = real_array(value, what)
    if arr.ndim != 0:
        raise ValueError(f"{what} must be a single number, got shape {arr.shape}")
    return float(arr)


def count(value, what: str, minimum: int = 0) -> int:
    """An integer count in [minimum, MAX_COUNT]; TypeError for 1.7 or '3', OverflowError above."""
    if isinstance(value, bool):
        raise TypeError(f"{what} must be an integer, got {value!r}")
    try:
        n = operator.index(value)
    except TypeError:
        raise TypeError(f"{what} must be an integer, got {type(value).__name__} {value!r}") from None
    if n < minimum:
        raise ValueError(f"{what} must be >= {minimum}, got {n}")
    if n > MAX_COUNT:
        raise OverflowError(f"{what} = {n} is too large (at most 2**63 - 1)")
    return n


def deg(x):
    """Radians to degrees (arrays welcome)."""
    return np.degrees(x)


def rad(x):
    """Degrees to radians (arrays welcome)."""
    return np.radians(x)


def known_model(name) -> str:
    """`name` if it is a registered model (built in, or loaded in this process); ValueError otherwise
    (so a name read from a file can never become a path)."""
    if not isinstance(name, str):
        raise ValueError(f"model must be a model name, got {type(name).__name__}")
    try:
        _core.model_info(name)
    except ValueError as exc:
        raise ValueError(str(exc)) from None
    return name
