"""Endpoint control: a desired hand position or velocity (what a BMI decoder outputs), thorax frame -> muscle
excitations for an Arm, updated every `solve_every` steps and held in between. docs/control.md#endpoint-control.

Law (every solve_every steps, at the arm's state q, qdot):
    x = hand_position(q), J = hand_jacobian(q) (the engine's analytic Jv, 3 x ndof), xdot = J qdot
    a_d = kp (x_ref - x) + kd (v_ref - xdot)                     desired hand acceleration, m/s^2
    qddot_d = J+ a_d - (I - J+ J) k_null qdot                      J+: Moore-Penrose pseudo-inverse; the null-space
                                                                   term damps the joint motion the hand does not see
    activations = StaticOptimizer.solve(q, qdot, qddot_d)          (armrt.control: the muscle-force distribution)
and the excitations are set to those activations until the next solve. The J+ mapping of a task-space acceleration
is resolved-acceleration / operational-space control (Luh, Walker & Paul 1980; Khatib 1987, IEEE J Robot Autom 3:43).
A position command sets x_ref and v_ref = 0. A velocity command alone sets v_ref = v and makes x_ref follow the hand
(x_ref = x at each solve, then x_ref += v dt): the controller is a velocity servo, a_d = kd (v_ref - xdot), and the
position loop is the decoder's (the user aims from the cursor they see). A velocity command after a position command
in the same step is the position's feed-forward velocity (x_ref kept). Why (docs/control.md#endpoint-control): an
x_ref integrated from a decoder that already closes a loop on the hand winds up while the hand lags, and the two
loops in series oscillated (measured: hand - x_ref up to 0.34 m, growing oscillation, GH events).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import checks
from .control import StaticOptimizer


@dataclass
class EndpointGains:
    """kp (1/s^2), kd (1/s): the hand PD (kd = 2 sqrt(kp) x 0.95 by default: near critical damping of the
    point-mass error dynamics a = -kp e - kd edot); k_null (1/s): null-space joint damping; solve_every: steps
    between static-optimisation solves (10 at 1 ms: ~1-4 ms per solve cannot run every 1 ms step);
    gh_stab_max: None or the GH-stability bound handed to StaticOptimizer."""
    kp: float = 40.0
    kd: float = 12.0
    k_null: float = 5.0
    solve_every: int = 10
    gh_stab_max: float | None = None

    def __post_init__(self):
        for name in ("kp", "kd", "k_null"):
            v = checks.real_scalar(getattr(self, name), name)
            if not math.isfinite(v) or v < 0:
                raise ValueError(f"{name} must be a finite number >= 0, got {v}")
            setattr(self, name, v)
        self.solve_every = checks.count(self.solve_every, "solve_every", minimum=1)


def _vec3(v, what):
    a = checks.real_array(v, what)
    if a.shape != (3,) or not np.all(np.isfinite(a)):
        raise ValueError(f"{what} must be 3 finite numbers (m or m/s, thorax frame), got {np.asarray(v)!r}")
    return a


class EndpointController:
    """Drives arm's hand: command_position(x) (3,) m or command_velocity(v) (3,) m/s, then step() once per arm
    step (it steps the arm). State: x_ref, v_ref (3,), the last solve's activations (n,) and its feasibility.
    tendon: the static optimisation's tendon, "elastic" (the default: the element as simulated, Python SQP around
    ProxQP) or "rigid" (one QP, solved by the engine's C++ static optimisation; its activations are those of a
    different muscle model than the one simulated, see docs/tasks.md for what that did on a Fitts block).
    ValueError for bad commands, gains or tendon; an infeasible solve keeps its best activations (counted in
    n_infeasible)."""

    def __init__(self, arm, gains: EndpointGains | None = None, tendon: str = "elastic"):
        self.arm = arm
        self.gains = gains if gains is not None else EndpointGains()
        if not isinstance(self.gains, EndpointGains):
            raise TypeError(f"gains must be an EndpointGains, got {type(self.gains).__name__}")
        self._so = StaticOptimizer(arm, gh_stab_max=self.gains.gh_stab_max, tendon=tendon)
        self.x_ref = self.hand_position()
        self.v_ref = np.zeros(3)
        self._n = 0
        self.velocity_mode = False     # True while velocity commands alone drive the hand (x_ref follows it)
        self._position_this_step = False
        self.n_solves = 0
        self.n_infeasible = 0
        self.activation = None

    def hand_position(self) -> np.ndarray:
        """(3,) m, thorax frame, from the model's kinematics at the arm's q."""
        return self.arm.model.hand_position(self.arm.q)

    def command_position(self, x) -> None:
        """Hold the hand at x (3,) m: x_ref = x, v_ref = 0 (position mode)."""
        self.x_ref = _vec3(x, "hand position command").copy()
        self.v_ref = np.zeros(3)
        self.velocity_mode = False
        self._position_this_step = True

    def command_velocity(self, v) -> None:
        """Move the hand at v (3,) m/s. Alone (no position command in this step): velocity mode, x_ref follows
        the hand. After command_position in the same step: the feed-forward velocity of that position."""
        self.v_ref = _vec3(v, "hand velocity command").copy()
        self.velocity_mode = not self._position_this_step

    def _solve(self):
        arm, g = self.arm, self.gains
        q, qd = arm.q, arm.qdot
        x = arm.model.hand_position(q)
        if self.velocity_mode:
            self.x_ref = x.copy()   # no reference of its own to wind up: the decoder closes the position loop
        J, _ = arm.model.hand_jacobian(q)
        a = g.kp * (self.x_ref - x) + g.kd * (self.v_ref - J @ qd)
        Jp = np.linalg.pinv(J)
        qdd = Jp @ a - (np.eye(len(q)) - Jp @ J) @ (g.k_null * qd)
        r = self._so.solve(q, qd, qdd, on_infeasible="return")
        self.n_solves += 1
        self.n_infeasible += int(not r.feasible)
        self.activation = r.activation
        arm.set_excitation(r.activation)

    def step(self) -> None:
        """One arm step: integrate a velocity command into x_ref, re-solve every solve_every steps, step the arm."""
        self.x_ref = self.x_ref + self.v_ref * self.arm.dt
        if self._n % self.gains.solve_every == 0:
            self._solve()
        self._n += 1
        self._position_this_step = False
        self.arm.step(1)


def start_at_rest(arm, q) -> np.ndarray:
    """Reset arm at q (ndof,) rad, at rest, with the activations that hold it there: the static optimisation
    (elastic tendon) at (q, qdot = 0, qddot = 0), as armrt.track_motion starts its arm. Without it an arm reset with zero activation falls
    until its muscles activate, which a velocity decoder then has to undo (measured: 57 mm in 1 s with v = 0,
    docs/control.md#endpoint-control). Returns the activations (n,); an infeasible solve's best effort is used."""
    arm.reset(q=q)
    r = StaticOptimizer(arm).solve(arm.q, 0.0, 0.0, on_infeasible="return")
    a = np.minimum(r.activation, arm.max_activation)
    arm.reset(q=q, activation=a)
    return a


def run_task(task, controller: EndpointController, decoder=None, max_time_s: float = 600.0):
    """Close the loop with the arm: each arm step the task sees the hand (model.hand_position at the arm's q, m)
    and the GH stability (gh_stable = arm.gh_stab <= 1, paper eq. 5, so a loss emits a 'gh_unstable' event);
    between trials the controller holds the last reference. decoder None: the target position is commanded
    (position mode); else decoder.step(hand, target) (3,) m/s is commanded as a velocity (e.g.
    armrt.tasks.SimulatedDecoder with dt_s = arm.dt). Returns the task."""
    arm = controller.arm
    if decoder is not None and abs(decoder.dt_s - arm.dt) > 1e-12:
        raise ValueError(f"the decoder's dt_s ({decoder.dt_s} s) must equal the arm's dt ({arm.dt} s)")
    max_time_s = checks.real_scalar(max_time_s, "max_time_s")
    if not (math.isfinite(max_time_s) and max_time_s > 0):
        raise ValueError(f"max_time_s must be a finite number > 0, got {max_time_s}")
    t0 = arm.time
    for _ in range(int(math.ceil(max_time_s / arm.dt))):
        x = controller.hand_position()
        task.step(arm.time - t0, x, gh_stable=bool(arm.gh_stab <= 1.0))
        if task.done:
            break
        tg = task.current_target()
        if decoder is None:
            if tg is not None:
                controller.command_position(tg.position)
        else:
            controller.command_velocity(decoder.step(x, None if tg is None else tg.position))
        controller.step()
    return task
