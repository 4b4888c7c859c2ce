"""The das3 motion of bench.static_optimization for the static-optimisation tests: the arm DOFs (GHy..PSy) move
0.1 rad by a raised cosine over 0.5 s in 60 frames about the settled pose, alternating signs, the girdle held.
Warm started from frame to frame, the elastic SQP's first QP at frame 49 is infeasible as linearised."""
from __future__ import annotations

import numpy as np


def das3_motion(arm, frames: int = 60, duration: float = 0.5, amplitude: float = 0.1):
    """(q, qdot, qddot), each (frames, n_dofs) in rad, rad/s, rad/s^2, about arm.q (call arm.settle() first)."""
    t = np.arange(frames) * duration / frames
    w = np.pi / duration
    sign = np.where(np.arange(arm.n_dofs) % 2 == 0, 1.0, -1.0)
    sign[list(arm.model.girdle_dofs)] = 0.0
    half = 0.5 * amplitude
    return (arm.q + np.outer(half * (1 - np.cos(w * t)), sign), np.outer(half * w * np.sin(w * t), sign),
            np.outer(half * w * w * np.cos(w * t), sign))


def das2_fast_motion(arm, frames: int = 120, dt: float = 1e-3, amplitude: float = 0.3):
    """das2 from (20, 40, 0, 60, 60) deg, every DOF 0.3 rad by a raised cosine over 0.12 s, alternating signs
    (bench.static_optimization's motion, ten times faster): from about frame 28 the elastic elements cannot supply
    the moments at these fibre velocities (the closest solutions hold elements at their upper bound)."""
    t = np.arange(frames) * dt
    w = np.pi / (frames * dt)
    sign = np.where(np.arange(arm.n_dofs) % 2 == 0, 1.0, -1.0)
    half = 0.5 * amplitude
    q0 = np.radians([20.0, 40.0, 0.0, 60.0, 60.0])
    return (q0 + np.outer(half * (1 - np.cos(w * t)), sign), np.outer(half * w * np.sin(w * t), sign),
            np.outer(half * w * w * np.cos(w * t), sign))
