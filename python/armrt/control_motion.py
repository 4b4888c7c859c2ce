"""Static optimisation along a motion (issue 28 item 3; docs/control.md): a .mot of joint angles (OpenSim names) or
arrays -> activations per frame, one warm-started StaticOptimizer over the frames."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .checks import joint_range_rows, real_array
from .control import StaticOptimizer, check_on_infeasible
from .errors import StaticOptimizationInfeasible


@dataclass
class MotionActivations:
    """Per frame (T rows): time (T,) s, q, qdot, qddot (T, ndof), activation and lce (T, n), residual (T, ndof) N m,
    gh_stab (T,), feasible (T,) bool, iterations (T,); reports: {frame: report} of the infeasible frames."""
    time: np.ndarray
    q: np.ndarray
    qdot: np.ndarray
    qddot: np.ndarray
    activation: np.ndarray
    lce: np.ndarray
    residual: np.ndarray
    gh_stab: np.ndarray
    feasible: np.ndarray
    iterations: np.ndarray
    reports: dict

    def __repr__(self) -> str:
        return (f"MotionActivations({len(self.time)} frames, t = {self.time[0]:.4g}-{self.time[-1]:.4g} s, "
                f"{int(np.count_nonzero(~self.feasible))} infeasible, |residual| max "
                f"{np.abs(self.residual).max():.2e} N m, gh_stab max {np.max(self.gh_stab):.3f})")


def check_motion(model, q, time, what: str, min_frames: int) -> None:
    """q (T, ndof) rad and time (T,) s of a motion: ValueError for another shape, fewer than min_frames frames,
    NaN/infinite values, time not strictly increasing, or a frame beyond the engine's joint domain
    (checks.joint_range without the warning; a motion in degrees is refused with a hint, here and not at the
    frame or controller update that first meets it). what names q in the messages."""
    if q.ndim != 2 or q.shape[1] != model.n_dofs:
        raise ValueError(f"{what} must have shape (T, {model.n_dofs}) ({', '.join(model.dof_names)}), got {q.shape}")
    if time.shape != (q.shape[0],):
        raise ValueError(f"time must have shape ({q.shape[0]},), got {time.shape}")
    if q.shape[0] < min_frames:
        raise ValueError(f"a motion needs at least {min_frames} frames (for its accelerations)")
    if not (np.all(np.isfinite(q)) and np.all(np.isfinite(time))):
        raise ValueError(f"{what} or time contains NaN or infinite values")
    if np.any(np.diff(time) <= 0):
        raise ValueError("time must be strictly increasing")
    joint_range_rows(q, model.dof_names, model.dof_ranges, warn=False,
                     label=lambda r: f"{what} frame {r} (t = {time[r]:g} s)")


def static_optimization_motion(arm_or_model, motion, time=None, hand_load=None, gh_stab_max=None, weights=None,
                               criterion: str = "squared", tendon: str = "elastic", on_infeasible: str = "raise"):
    """Activations per frame along a motion: `motion` a .mot/.sto path (armrt.opensim_io.read_motion: OpenSim
    coordinate names, inDegrees honoured) or q (T, ndof) rad with `time` (T,) s. qdot and qddot are the motion's
    second-order finite differences (numpy.gradient; filter noisy data first). Each frame is solved warm started
    from the previous one (StaticOptimizer's options). on_infeasible="raise" raises StaticOptimizationInfeasible
    at the first infeasible frame, its time in the message; "return" keeps going and marks the frame
    (feasible False, its report in reports). ValueError for a bad motion (shapes, NaN, time not increasing) or a
    time given with a .mot file."""
    check_on_infeasible(on_infeasible)  # the frames are solved with "return": a misspelt "raise" must not pass
    model = arm_or_model.model if hasattr(arm_or_model, "_sim") else arm_or_model
    if isinstance(motion, (str, bytes)) or hasattr(motion, "__fspath__"):
        from .opensim_io import read_motion  # noqa: PLC0415 (opensim_io imports arm, which imports control)
        if time is not None:
            raise ValueError("time: a .mot file has its own time column; give time only with q as an array")
        m = read_motion(motion, model=model.name)
        time, q = m.time, m.q
    else:
        q = real_array(motion, "motion")
        if time is None:
            raise ValueError("time (T,) s is needed with a motion given as an array")
        time = real_array(time, "time")
    check_motion(model, q, time, "motion", 3)
    qd = np.gradient(q, time, axis=0, edge_order=2)
    qdd = np.gradient(qd, time, axis=0, edge_order=2)
    so = StaticOptimizer(arm_or_model, gh_stab_max=gh_stab_max, weights=weights, criterion=criterion, tendon=tendon)
    T, n = q.shape[0], model.n_elements
    act, lce = np.zeros((T, n)), np.zeros((T, n))
    resid = np.zeros((T, model.n_dofs))
    stab, feas, its = np.zeros(T), np.zeros(T, bool), np.zeros(T, int)
    reports = {}
    for k in range(T):
        r = so.solve(q[k], qd[k], qdd[k], hand_load, on_infeasible="return")
        if not r.feasible:
            if on_infeasible == "raise":
                raise StaticOptimizationInfeasible(f"frame {k} (t = {time[k]:g} s): {r.report}", r)
            reports[k] = r.report
        act[k], lce[k], resid[k], stab[k], feas[k], its[k] = r.activation, r.lce, r.residual, r.gh_stab, r.feasible, r.iterations
    return MotionActivations(time=time, q=q, qdot=qd, qddot=qdd, activation=act, lce=lce, residual=resid, gh_stab=stab,
                             feasible=feas, iterations=its, reports=reports)
