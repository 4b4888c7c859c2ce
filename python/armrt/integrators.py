"""The integrators an Arm can step with, the default one, and the largest step each was validated at."""
from __future__ import annotations

import warnings

import numpy as np

from . import _core
from .checks import count, real_scalar
from .errors import StepSizeWarning

INTEGRATORS = ("ros2", "ros2_adaptive", "euler", "rk4", "cvode")
DEFAULT_INTEGRATOR = "ros2"
# Largest integration step used by default (s), from the engine (simulator.cc default_max_step):
# ROS2 (linearly implicit, docs/engine.md) one step per 1 ms control step; ros2_adaptive up to 2 ms, a
# step whose error estimate is too large redone as two halves (offline use: its cost is not fixed);
# RK4 6 substeps per 1 ms and Euler 0.1 ms (the paper's explicit solvers); CVODE picks its own (inf).
DEFAULT_MAX_STEP = {name: _core.default_max_step(name) for name in INTEGRATORS}

# Longest control step (s) the Python API takes. The control step is how long an excitation is held:
# the elements' activation dynamics have time constants of 10-40 ms (DAS3 tact, tdeact), so above a
# second a "control step" holds its input for 25 and more of them and controls nothing; and the
# default substeps grow with dt (Arm(dt=1e6) meant 999 999 000 integration steps per step()).
MAX_DT = 1.0
# Most integration steps per control step. The finest step anything in armrt runs is 25 us (the solver
# study's grid, experiments.STEP_GRID); 100 000 substeps allow 10 us steps at the longest control step
# (Euler's default 0.1 ms at dt = 1 s is 10 000), and one control step of them takes about a second of
# CPU (1-10 us per integration step), so a step() stays interruptible and no count is a typo's 10**9.
MAX_SUBSTEPS = 100_000


def control_step(integrator: str, dt, substeps) -> tuple[float, int]:
    """(dt s, substeps) checked for an Arm: the integrator one of INTEGRATORS, dt in (0, MAX_DT],
    substeps (None: enough for DEFAULT_MAX_STEP) an integer in [1, MAX_SUBSTEPS]. ValueError,
    TypeError for a dt or substeps that is not a real number / an integer, OverflowError for a count
    beyond the engine's int; StepSizeWarning for an integration step above the validated one."""
    if integrator not in INTEGRATORS:
        raise ValueError(f"unknown integrator {integrator!r}; expected one of {INTEGRATORS}")
    dt = real_scalar(dt, "dt")
    if not (np.isfinite(dt) and 0 < dt <= MAX_DT):
        raise ValueError(f"dt must be a positive number of seconds, at most {MAX_DT:g} s (the control step: the "
                         f"excitation is held for a whole step, muscle activation follows it within 10-40 ms), got {dt:g}")
    if substeps is None:
        substeps = _core.default_substeps(integrator, dt)
    if isinstance(substeps, (float, np.floating)) and float(substeps).is_integer():
        substeps = int(substeps)
    substeps = count(substeps, "substeps", minimum=1)
    if substeps > 2**31 - 1:
        raise OverflowError(f"substeps = {substeps} is too large (at most 2**31 - 1)")
    if substeps > MAX_SUBSTEPS:
        raise ValueError(f"substeps must be at most {MAX_SUBSTEPS} per control step (integration steps of "
                         f"{dt / MAX_SUBSTEPS:.3g} s at dt = {dt:g} s; armrt's finest validated step is 25 us), "
                         f"got {substeps}")
    step = dt / substeps
    if step > DEFAULT_MAX_STEP[integrator] * (1 + 1e-6):
        # Not an error (a user may study it), but nothing in docs/engine.md vouches for it: a
        # 2 ms ROS2 step was measured 5.6 deg off CVODE, one explicit step of 1 ms diverges.
        warnings.warn(StepSizeWarning(f"integration step {step * 1e3:g} ms is above the {DEFAULT_MAX_STEP[integrator] * 1e3:g} ms "
                      f"validated for {integrator!r} against CVODE (docs/engine.md); expect errors of degrees or "
                      f"divergence; leave substeps=None for the validated step"), stacklevel=3)
    return dt, substeps
