"""Input checks shared by the API (Arm, ArmBatch, Model, the real-time client): real numbers, counts,
registered model names, and the unit helpers deg/rad. Each names the input it refuses."""
from __future__ import annotations

import numbers
import operator
import warnings
from typing import Mapping

import numpy as np

from . import _core

# Largest step count or record interval the engine counts (C++ long on every supported platform).
MAX_COUNT = 2**63 - 1
# reset(q=...) refuses a joint further than this (rad, ~11 deg) beyond its range (model.h kStartRangeMargin, which
# armrt-rt --q0 applies with the same words: snapshot.h start_pose_error).
RANGE_MARGIN = _core.START_RANGE_MARGIN
# rad: the engine's physical domain (model.h kJointRangeMargin, 0.35): a step stops beyond it, and the engine's
# snapshot check refuses a state beyond it.
STATE_MARGIN = _core.JOINT_RANGE_MARGIN


def _masked_count(values) -> int:
    """How many values are masked in a numpy masked array, or in a list/tuple holding some (np.asarray
    would drop the masks and use the values under them)."""
    if isinstance(values, np.ma.MaskedArray):
        return int(np.ma.count_masked(values))
    if isinstance(values, (list, tuple)):
        return sum(_masked_count(v) for v in values)
    return 0


def _first_bool(values):
    """The first bool (Python's or numpy's) in nested lists / tuples, or None."""
    for v in values:
        if isinstance(v, (bool, np.bool_)):
            return bool(v)
        if isinstance(v, (list, tuple)):
            found = _first_bool(v)
            if found is not None:
                return found
    return None


def real_array(values, what: str, booleans: bool = True) -> np.ndarray:
    """`values` as a float array; TypeError for what is not real numbers (complex, strings, None,
    other objects) instead of numpy's silent casts (complex -> real part, None -> NaN); ValueError for
    a numpy masked array with masked values (np.asarray would use the values hidden under the mask).
    booleans=False: TypeError for a bool or an array of bools too (True would be taken as 1), for the inputs
    that are a quantity (a gain, a time, a posture, a weight) and never a flag, a bool inside a list or tuple of
    other numbers included (numpy would cast [True, 0, 0] to integers before it could be seen)."""
    if isinstance(values, (str, bytes)):
        raise TypeError(f"{what} must be numbers, got the string {values!r}")
    masked = _masked_count(values)
    if masked:
        raise ValueError(f"{what} is a masked array with {masked} masked value{'s' if masked > 1 else ''}: armrt "
                         f"would see the values under the mask; give every value (values.filled(x)) or drop the "
                         f"masked ones")
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
            if not booleans and isinstance(v, bool):
                raise TypeError(f"{what} must be numbers, got the bool {v!r} among them")
        arr = arr.astype(float)
    if not booleans and arr.dtype.kind == "b":
        if arr.ndim == 0:
            raise TypeError(f"{what} must be a number, got the bool {bool(arr)!r}")
        raise TypeError(f"{what} must be numbers, got an array of bools (shape {arr.shape}): True and False "
                        f"would be taken as 1 and 0")
    if not booleans and arr.dtype.kind in "iuf" and isinstance(values, (list, tuple)):
        found = _first_bool(values)  # [True, 0, 0]: numpy made the bool an integer
        if found is not None:
            raise TypeError(f"{what} must be numbers, got the bool {found!r} among them")
    if arr.dtype.kind not in "biuf":
        kind = {"c": "complex", "U": "string", "S": "bytes", "M": "datetime", "m": "timedelta", "V": "structured"}
        raise TypeError(f"{what} must be real numbers, got {kind.get(arr.dtype.kind, str(arr.dtype))} values "
                        f"(dtype {arr.dtype})")
    return arr.astype(float, copy=False)


def real_scalar(value, what: str, booleans: bool = True) -> float:
    """One real number (see real_array, booleans included); TypeError for anything else, ValueError for arrays."""
    if isinstance(value, (str, bytes)):
        raise TypeError(f"{what} must be a number, got the string {value!r}")
    arr = real_array(value, what, booleans)
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


def joint_range(q: np.ndarray, dof_names, dof_ranges: np.ndarray, warn: bool = True) -> np.ndarray:
    """q (ndof,) rad itself; ValueError if a joint is more than RANGE_MARGIN rad beyond its range
    (dof_ranges (ndof, 2) rad), with a hint when the values look like degrees. Beyond it by less:
    a RuntimeWarning if `warn` (the passive joint limits are springs, so a simulated state can end
    slightly outside). Without `warn` (a pose that may come from a simulation: the functions of a pose)
    the bound is the engine's own, STATE_MARGIN: every state a step accepts is accepted."""
    lo, hi = dof_ranges[:, 0], dof_ranges[:, 1]
    margin = RANGE_MARGIN if warn else STATE_MARGIN
    outside = (q < lo) | (q > hi)
    if not outside.any():
        return q
    desc = "; ".join(f"{dof_names[j]} = {q[j]:.4g} rad ({np.degrees(q[j]):.1f} deg) outside "
                     f"[{np.degrees(lo[j]):.1f}, {np.degrees(hi[j]):.1f}] deg" for j in np.flatnonzero(outside))
    far = (q < lo - margin) | (q > hi + margin)
    if far.any():
        r = np.radians(q)
        # Degrees only if some value is beyond a full turn, which no joint angle in radians is: with the margin,
        # np.radians of almost any radian pose lands in range, and GHy = 1.4 rad got the hint (a new user's trial).
        hint = (" These look like degrees: q is in radians (np.radians(q) or armrt.rad(q); "
                "armrt simulate --q-deg on the command line)."
                if np.abs(q).max() > 2 * np.pi and np.all((r >= lo - margin) & (r <= hi + margin)) else "")
        raise ValueError(f"q beyond the joint limits: {desc}.{hint}")
    if warn:
        warnings.warn(f"q slightly beyond the joint limits: {desc}", RuntimeWarning, stacklevel=4)
    return q


def named_items(model_name: str, values: Mapping, what: str) -> list[tuple[str, float]]:
    """[(name, value)] of a {name: value} dict, for the engine's values_from_names (Arm, Data and ArmBatch
    refuse the same dicts): KeyError naming every unknown name with close matches, TypeError or ValueError
    for a value that is not one real number."""
    unknown = [name for name in values if not (isinstance(name, str) and _core.is_name(model_name, name))]
    if unknown:
        raise KeyError(_core.unknown_names_message(model_name, [str(name) for name in unknown]))
    return [(name, real_scalar(v, f"{what}[{name!r}]", booleans=False)) for name, v in values.items()]


def per_element(model_name: str, element_names, values, what: str, lo: float, hi: float | None, clip: bool,
                current: np.ndarray | None = None, stacklevel: int = 3) -> np.ndarray:
    """(n,) values of a per-element input or setting from an array of n, a scalar, or {name: value} with
    element, muscle or group names (OpenSim aliases too); overlapping names follow the engine's one rule
    (names.h: the most specific name wins, in any order; equal specificity takes the largest), and elements no
    name covers keep `current` (None: 0). KeyError for unknown names (with close matches), TypeError for
    non-numbers, ValueError for NaN/infinite values or, unless `clip` (then a RuntimeWarning), values outside
    [lo, hi] (hi None: no upper bound)."""
    n = len(element_names)
    if isinstance(values, Mapping):
        items = named_items(model_name, values, what)
        base = np.zeros(n) if current is None else np.asarray(current, dtype=float)
        out = np.asarray(_core.values_from_names(model_name, items, base))
    else:
        arr = real_array(values, what, booleans=False)  # a quantity per element: True was 1
        if arr.ndim == 0:
            arr = np.full(n, float(arr))
        if arr.shape != (n,):
            raise ValueError(f"{what} must have shape ({n},) (one value per element), got {arr.shape}")
        out = arr.copy()
    bad = ~np.isfinite(out)
    if bad.any():
        names = [element_names[i] for i in np.flatnonzero(bad)[:5]]
        raise ValueError(f"{what} contains NaN or infinite values (elements {names})")
    hi_ = np.inf if hi is None else hi
    outside = (out < lo) | (out > hi_)
    if outside.any():
        names = [element_names[i] for i in np.flatnonzero(outside)[:5]]
        if not clip:
            raise ValueError(f"{what} must lie in [{lo}, {hi_}]; elements {names} do not")
        warnings.warn(f"{what} outside [{lo}, {hi_}] clipped for elements {names}", RuntimeWarning,
                      stacklevel=stacklevel + 1)
        out = np.clip(out, lo, hi_)
    return out


def dof_vector(v, what: str, dof_names, booleans: bool = True) -> np.ndarray:
    """v as a (ndof,) real array, one value per DOF of dof_names: ValueError for another shape (naming the DOFs)
    or NaN/infinite values (naming where); booleans as real_array's."""
    a = real_array(v, what, booleans)
    nd = len(dof_names)
    if a.shape != (nd,):
        raise ValueError(f"{what} must have shape ({nd},) ({', '.join(dof_names)}), got {a.shape}")
    if not np.all(np.isfinite(a)):
        bad = [dof_names[j] for j in np.flatnonzero(~np.isfinite(a))]
        raise ValueError(f"{what} contains NaN or infinite values (at {', '.join(bad)})")
    return a


def applied_moments(values, dof_names, what: str = "applied moment", rows: int | None = None,
                    model_name: str | None = None) -> np.ndarray:
    """(ndof,) N m from an array of one value per DOF, {dof name: value} (DOFs not named get 0) or the number 0
    (none); with rows (ArmBatch), (rows, ndof) arrays are accepted too. With model_name, a dict's names may also be
    the OpenSim coordinate names (EL_x), as Arm.dof_index takes them. KeyError naming an unknown DOF and the
    model's DOFs, ValueError for another shape, NaN/infinite values (naming the DOF, and the arm) or two names of
    one DOF."""
    if not isinstance(values, (Mapping, str, bytes)) and np.ndim(values) == 0:
        if real_scalar(values, what) != 0.0:
            raise ValueError(f"{what}: a single number must be 0 (no applied moment), got {values!r}; give one "
                             f"value per DOF ({', '.join(dof_names)}) or {{dof name: value}}")
        return np.zeros(len(dof_names))
    if rows is not None and not isinstance(values, Mapping):
        a = real_array(values, what)
        if a.ndim == 2:
            if a.shape != (rows, len(dof_names)):
                raise ValueError(f"{what} must have shape ({rows}, {len(dof_names)}) or ({len(dof_names)},) "
                                 f"({', '.join(dof_names)}), got {a.shape}")
            for i in range(rows):
                dof_vector(a[i], f"{what} of arm {i}", dof_names)
            return a
        if a.shape != (len(dof_names),):
            raise ValueError(f"{what} must have shape ({rows}, {len(dof_names)}) or ({len(dof_names)},) "
                             f"({', '.join(dof_names)}), got {a.shape}")
    if isinstance(values, Mapping):
        names = list(dof_names)

        def index_of(k):
            if k in names:
                return names.index(k)
            if model_name is not None and isinstance(k, str):
                try:
                    return _core.find_dof(model_name, k)
                except (KeyError, ValueError, RuntimeError):
                    return None
            return None
        index = {k: index_of(k) for k in values}
        unknown = [k for k, j in index.items() if j is None]
        if unknown:
            raise KeyError(f"{what}: unknown DOF(s) {unknown}; the model's DOFs are {', '.join(dof_names)}"
                           + (" (or their OpenSim coordinate names)" if model_name is not None else ""))
        out = np.zeros(len(dof_names))
        seen = {}
        for k, v in values.items():
            j = index[k]
            if j in seen:
                raise ValueError(f"{what}: {seen[j]!r} and {k!r} both name DOF {names[j]}; give it once")
            seen[j] = k
            out[j] = real_scalar(v, f"{what}[{k!r}]")
        values = out
    return dof_vector(values, what, dof_names)


# The largest hand load anything takes (N, N m; the engine's kMaxHandForce, kMaxHandMoment, engine.h): 1e5 N is ten
# tonnes in the hand, a wrong unit, never a load. Not a stability limit: 1e5 N itself throws das2 past the joint-speed
# bound in its first step. Beyond it the static optimisation's QPs ran for minutes (1e16 N) and inverse dynamics
# returned 1e299 N m for 1e300 N.
MAX_HAND_FORCE = _core.STATIC_OPTIMIZATION_MAX_HAND_FORCE
MAX_HAND_MOMENT = _core.STATIC_OPTIMIZATION_MAX_HAND_MOMENT


def hand_load(force, moment) -> tuple[np.ndarray, np.ndarray]:
    """(force (3,) N, moment (3,) N m) checked: ValueError for another shape, NaN/infinite values or a magnitude
    beyond MAX_HAND_FORCE (1e5 N) or MAX_HAND_MOMENT (1e4 N m); TypeError for bools (a load is a quantity:
    [True, False, False] was a 1 N force). The one rule of set_hand_load, inverse dynamics, static optimisation,
    the controllers and armrt-rt's --hand-force / --hand-moment."""
    values = []
    for name, v in (("force", force), ("moment", moment)):
        a = real_array(v, f"hand {name}", booleans=False)
        if a.shape != (3,):
            raise ValueError(f"hand {name} must have shape (3,), got {a.shape}")
        if not np.all(np.isfinite(a)):
            raise ValueError(f"hand {name} contains NaN or infinite values")
        hand_load_within(a, name)
        values.append(a)
    return values[0], values[1]


def hand_load_within(a: np.ndarray, name: str) -> None:
    """ValueError where a hand force (name "force", N) or moment ("moment", N m), (3,) or (k, 3) finite, is beyond
    MAX_HAND_FORCE or MAX_HAND_MOMENT in magnitude (row r named for (k, 3)): the engine's hand_load_error, so that
    armrt-rt, the state vectors and this agree to the last bit."""
    rows = np.atleast_2d(a)
    for r, v in enumerate(rows):
        what = f"hand {name}" + (f" (row {r})" if np.ndim(a) == 2 else "")
        problem = _core.hand_load_error(what, np.ascontiguousarray(v, dtype=float), name == "moment")
        if problem:
            raise ValueError(problem)


def each_row(check, q: np.ndarray, rows, label, stacklevel: int = 2) -> None:
    """check(q[r]) for each r in rows, its ValueError prefixed with label(r); the RuntimeWarnings it
    gives are collected into one naming their rows, so k rows do not print k warnings. stacklevel:
    counted from the caller of each_row, as for warnings.warn."""
    slight = []
    for r in rows:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                check(q[r])
            except ValueError as exc:
                raise ValueError(f"{label(r)}: {exc}") from None
        slight += [f"{label(r)}: {w.message}" for w in caught]
    if slight:
        more = f"; and {len(slight) - 3} more" if len(slight) > 3 else ""
        warnings.warn("; ".join(slight[:3]) + more, RuntimeWarning, stacklevel=stacklevel + 1)


def joint_range_rows(q: np.ndarray, dof_names, dof_ranges: np.ndarray, label=None, warn: bool = True,
                     stacklevel: int = 2) -> np.ndarray:
    """q (k, ndof) itself: joint_range for every row, each error and warning naming its row (label(r),
    default "row r"); stacklevel as for warnings.warn, from the caller."""
    lo, hi = dof_ranges[:, 0], dof_ranges[:, 1]
    # Postures in range, the usual case, cost one vectorised test, not a Python loop over rows.
    rows = np.flatnonzero(((q < lo) | (q > hi)).any(axis=1))
    each_row(lambda row: joint_range(row, dof_names, dof_ranges, warn=warn), q, rows,
             label or (lambda r: f"row {r}"), stacklevel=stacklevel + 1)
    return q


def joint_speed_within(qd, dof_names, max_joint_speed: float, who: str) -> None:
    """ValueError naming the DOF where |qd| (ndof,) rad/s exceeds max_joint_speed (rad/s, the bound a step holds):
    who refuses it (the static optimisation, inverse dynamics, armrt-rt's client)."""
    j = int(np.argmax(np.abs(qd)))
    if abs(qd[j]) > max_joint_speed:
        raise ValueError(f"qdot[{dof_names[j]}] = {qd[j]:g} rad/s is beyond max_joint_speed {max_joint_speed:g} rad/s: "
                         f"{who} refuses it (faster means a diverged simulation, or deg/s given as rad/s)")


def joint_acceleration_within(qdd, dof_names, limit: float, who: str) -> None:
    """ValueError naming the DOF where |qdd| (ndof,) rad/s^2 exceeds limit (static_optimization.h's bound): who
    refuses it (the static optimisation, armrt-rt's client)."""
    j = int(np.argmax(np.abs(qdd)))
    if abs(qdd[j]) > limit:
        raise ValueError(f"qddot[{dof_names[j]}] = {qdd[j]:.3g} rad/s^2 is beyond {limit:.0e} rad/s^2, more than any "
                         f"arm does: {who} refuses it")
