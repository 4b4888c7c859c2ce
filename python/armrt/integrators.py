"""The integrators an Arm can step with, the default one, and the largest step each was validated at."""
from __future__ import annotations

from . import _core

INTEGRATORS = ("ros2", "ros2_adaptive", "euler", "rk4", "cvode")
DEFAULT_INTEGRATOR = "ros2"
# Largest integration step used by default (s), from the engine (simulator.cc default_max_step):
# ROS2 (linearly implicit, docs/engine.md) one step per 1 ms control step; ros2_adaptive up to 2 ms, a
# step whose error estimate is too large redone as two halves (offline use: its cost is not fixed);
# RK4 6 substeps per 1 ms and Euler 0.1 ms (the paper's explicit solvers); CVODE picks its own (inf).
DEFAULT_MAX_STEP = {name: _core.default_max_step(name) for name in INTEGRATORS}
