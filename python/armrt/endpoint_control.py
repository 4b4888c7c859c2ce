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
import warnings
from dataclasses import dataclass

import numpy as np

from . import checks
from .arm import Arm
from .control import MAX_JOINT_ACCELERATION, StaticOptimizer, check_gh_stab_max, check_on_infeasible
from .control_tracking import ModelErrorObserver
from .errors import StaticOptimizationInfeasible


@dataclass
class EndpointGains:
    """kp (1/s^2), kd (1/s): the hand PD (kd = 2 sqrt(kp) x 0.95 by default: near critical damping of the
    point-mass error dynamics a = -kp e - kd edot); k_null (1/s): null-space joint damping; solve_every: steps
    between static-optimisation solves (10 at 1 ms: ~1-4 ms per solve cannot run every 1 ms step);
    gh_stab_max: None or the GH-stability bound (paper eq. 5, dimensionless) handed to StaticOptimizer, a finite
    number > 0. TypeError for a gain that is not a real number (a string, None for kp, kd, k_null, or a bool:
    True would be taken as 1) or a solve_every that is not an integer; ValueError for kp, kd, k_null negative or
    not finite, gh_stab_max <= 0 or not finite, solve_every < 1. The model-dependent upper limit of gh_stab_max
    (its ellipse must stay within MAX_BOUND_HALF_ANGLE of the glenoid normal, armrt.control.gh_polygon) is checked
    when a controller builds its StaticOptimizer: the gains are not tied to a model."""
    kp: float = 40.0
    kd: float = 12.0
    k_null: float = 5.0
    solve_every: int = 10
    gh_stab_max: float | None = None

    def __post_init__(self):
        for name in ("kp", "kd", "k_null"):
            # booleans=False: True would be taken as a gain of 1.
            v = checks.real_scalar(getattr(self, name), name, booleans=False)
            if not math.isfinite(v) or v < 0:
                raise ValueError(f"{name} must be a finite number >= 0, got {v}")
            setattr(self, name, v)
        self.solve_every = checks.count(self.solve_every, "solve_every", minimum=1)
        # StaticOptimizer's own rule (finite, > 0) here, so a bad bound is refused where it is written and not
        # only when a controller is built from these gains.
        self.gh_stab_max = check_gh_stab_max(self.gh_stab_max)


def _driven_arm(arm, who: str):
    """arm itself if it is an armrt.Arm whose excitations drive its elements: TypeError for anything else (a
    Model has no state to drive), ValueError for an arm with a stimulation map, whose elements ignore the
    excitation (set_excitation would be accepted and the hand would fall)."""
    if not isinstance(arm, Arm):
        raise TypeError(f"{who} needs an armrt.Arm (it sets the excitations of the arm it steps), got "
                        f"{type(arm).__name__}" + (": make one with armrt.Arm(model_name)" if
                                                   type(arm).__name__ == "Model" else ""))
    if arm.channel_names:
        raise ValueError(f"{who}: this arm has a stimulation map; the elements it drives follow the stimulation "
                         "channels, not the excitations computed here (clear the map: arm.set_stimulation_map(None), "
                         "or drive the stimulated arm with a controller of armrt.fes_control)")
    return arm


def _vec3(v, what):
    a = checks.real_array(v, what, booleans=False)  # a position or velocity, never a flag: True was 1 m
    if a.shape != (3,) or not np.all(np.isfinite(a)):
        raise ValueError(f"{what} must be 3 finite numbers (m or m/s, thorax frame), got {np.asarray(v)!r}")
    return a


class EndpointController:
    """Drives arm's hand: command_position(x) (3,) m or command_velocity(v) (3,) m/s, then step() once per arm
    step (it steps the arm). State: x_ref, v_ref (3,), the last solve's activations (n,) and its feasibility.
    tendon: the static optimisation's tendon, "elastic" (the default: the element as simulated) or "rigid" (one QP;
    its activations are those of a different muscle model than the one simulated, see docs/tasks.md for what that
    did on a Fitts block); either is solved by the engine's C++ static optimisation (StaticOptimizer's
    backend="auto": the elastic tendon's SQP and the rigid tendon's QP in C++, self._so.backend == "cpp";
    docs/control.md "The elastic tendon in C++").
    TypeError for an arm that is not an armrt.Arm (a Model) or gains that are not an EndpointGains; ValueError
    for bad commands, gains or tendon, and for an arm with a stimulation map (at construction, and at the next
    solve if a map is installed later: its elements would ignore the excitations); ValueError from step() where a
    command asks for a joint acceleration beyond the static optimisation's bound (1e5 rad/s^2: with the default
    gains, on das2 at 30 60 10 60 80 deg, a hand velocity command of 2-3 km/s or a position 650-1000 m away),
    naming the command, before the arm steps; an infeasible solve keeps its best activations (counted in
    n_infeasible; the first one warns, a RuntimeWarning naming the command).
    correct_model_error: as track_motion's (armrt.control_tracking.ModelErrorObserver, off by default): each solve
    asks for the desired joint accelerations less M^-1 times the optimiser's muscle-model error and what the last
    solves' plans missed; TypeError unless a bool."""

    def __init__(self, arm, gains: EndpointGains | None = None, tendon: str = "elastic",
                 correct_model_error: bool = False):
        self.arm = _driven_arm(arm, "EndpointController")
        self.gains = gains if gains is not None else EndpointGains()
        if not isinstance(self.gains, EndpointGains):
            raise TypeError(f"gains must be an EndpointGains, got {type(self.gains).__name__}")
        if not isinstance(correct_model_error, (bool, np.bool_)):
            raise TypeError(f"correct_model_error must be True or False, got {type(correct_model_error).__name__} "
                            f"{correct_model_error!r}")
        self._so = StaticOptimizer(arm, gh_stab_max=self.gains.gh_stab_max, tendon=tendon)
        # track_motion's correction of the optimiser's muscle model (docs/control.md "Endpoint control"): its
        # elements recruited from slack give no force yet, and the hand is kicked off a reached target.
        self._observer = ModelErrorObserver(arm, tendon, self.gains.solve_every * arm.dt) if correct_model_error \
            else None
        self._last_feasible = False
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
        _driven_arm(arm, "EndpointController")  # a map installed since construction would take the elements over
        q, qd = arm.q, arm.qdot
        x = arm.model.hand_position(q)
        if self.velocity_mode:
            self.x_ref = x.copy()   # no reference of its own to wind up: the decoder closes the position loop
        J, _ = arm.model.hand_jacobian(q)
        a = g.kp * (self.x_ref - x) + g.kd * (self.v_ref - J @ qd)
        Jp = np.linalg.pinv(J)
        qdd = Jp @ a - (np.eye(len(q)) - Jp @ J) @ (g.k_null * qd)
        # The solve refuses this too; here the message can name the command that asked for it.
        checks.joint_acceleration_within(
            qdd, arm.dof_names, MAX_JOINT_ACCELERATION,
            f"EndpointController (the command: x_ref {np.linalg.norm(self.x_ref - x):.3g} m from the hand, v_ref "
            f"{np.linalg.norm(self.v_ref):.3g} m/s, so a desired hand acceleration of {np.linalg.norm(a):.3g} m/s^2; "
            "the arm was not stepped)")
        if self._observer is not None:
            qdd = self._observer.asked(qdd, q, qd, self._last_feasible)
        r = self._so.solve(q, qd, qdd, on_infeasible="return")
        self._last_feasible = bool(r.feasible)
        self.n_solves += 1
        if not r.feasible and self.n_infeasible == 0:
            # Once per controller: a decoder's unreachable command (a target metres away, a hand speed of
            # 100 m/s) flung the arm past the GH rim with only the counter to tell (a trial's finding).
            why = r.report.splitlines()[0] if r.report else "infeasible"
            warnings.warn("EndpointController: a solve has no activations that give the commanded hand motion (x_ref "
                          f"{np.linalg.norm(self.x_ref - x):.3g} m from the hand, v_ref {np.linalg.norm(self.v_ref):.3g} "
                          "m/s); its closest activations are applied and the arm may not follow; this and later "
                          f"ones are counted in n_infeasible (warned once): {why}", RuntimeWarning, stacklevel=3)
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


def start_at_rest(arm, q, on_infeasible: str = "raise", gh_stab_max=None) -> np.ndarray:
    """Reset arm at q (ndof,) rad (or a dict of DOF names, as Arm.reset), at rest, with the activations that hold
    it there: the static optimisation (elastic tendon, the arm's hand load and settings) at (q, qdot = 0,
    qddot = 0), as armrt.track_motion starts its arm. Without it an arm reset with zero activation falls until
    its muscles activate, which a velocity decoder then has to undo (measured: 57 mm in 1 s with v = 0,
    docs/control.md#endpoint-control). Returns the activations (n,), in [0, max_activation]; the arm's qdot is 0,
    its time 0, its held excitation and hand load are kept (as reset does).

    gh_stab_max: None (no bound) or the bound (> 0) on GHstab the activations keep, as StaticOptimizer takes it;
    give the controller's own (EndpointGains.gh_stab_max) so the arm starts within it. Without it the rest
    activations of the trial pose gave GHstab 0.123 against a controller's 0.08, exceeded for the first ~150 ms.

    on_infeasible (as StaticOptimizer.solve): "raise" (the default) raises armrt.StaticOptimizationInfeasible (a
    ValueError; the message and .report give the residual moment per DOF, .result the closest solution) when no
    activations hold the arm at q, and leaves the arm as it was (not reset); "return" resets the arm with that
    closest solution anyway and emits a RuntimeWarning with the report (the hand then moves from the first step).
    TypeError for an arm that is not an armrt.Arm; ValueError for an arm with a stimulation map (its elements
    ignore the activations' excitation: the controllers of armrt.fes_control drive such an arm), a bad
    on_infeasible, or a q reset refuses (NaN, wrong shape, far beyond the joint ranges); TypeError for a q of
    non-numbers."""
    _driven_arm(arm, "start_at_rest")
    check_on_infeasible(on_infeasible)
    gh_stab_max = check_gh_stab_max(gh_stab_max)
    # reset's own checks of q first (a dict of DOF names, the range, das3's scapula on the thorax), so a bad q gets
    # reset's error rather than an infeasible solve; their warnings are left to the reset below, which repeats them.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        q = arm._check_girdle_contact(arm._check_range(arm._dof_vector(q, "q")))
    # Solved before the reset: the solve depends on q, the arm's settings and hand load only, so an infeasible hold
    # is refused with the arm untouched.
    try:
        r = StaticOptimizer(arm, gh_stab_max=gh_stab_max).solve(q, 0.0, 0.0, on_infeasible="raise")
    except StaticOptimizationInfeasible as exc:
        if on_infeasible == "raise":
            err = StaticOptimizationInfeasible(
                "start_at_rest: no activations within [0, max_activation] hold the arm at rest at q (the arm was "
                "not reset; on_infeasible='return' resets it with the closest activations): " + exc.report,
                exc.result)
            err.report = exc.report
            raise err from exc
        r = exc.result
        warnings.warn("start_at_rest: no activations hold the arm at rest at q; it was reset with the closest "
                      "activations (on_infeasible='return') and will move: " + exc.report, RuntimeWarning,
                      stacklevel=2)
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
