"""armrt.Data: the changing part of one simulated arm (like mjData / pinocchio.Data): state, inputs,
outputs and the integrator's workspace, for one armrt.Model. Several Data (several Arms) share one Model.

    model = armrt.Model("das2")
    data = armrt.Data(model)            # at the rest posture, time 0, no excitation
    data.q, data.activation             # read-only views that follow the simulation
    s = data.get_state()                # armrt.State: a copy of everything a continuation depends on
    data.set_state(s)

Arm (armrt/arm.py) steps a Data with an integrator; Arm.data is its Data.
"""
from __future__ import annotations

import threading
import warnings
from contextlib import contextmanager
from dataclasses import InitVar, dataclass, fields

import numpy as np

from . import _core
from .checks import joint_range
from .errors import ConcurrentUseError
from .integrators import DEFAULT_INTEGRATOR
from .model import Model


@dataclass(frozen=True, eq=False)
class State:
    """A snapshot of a simulated arm: everything its continuation depends on. Arrays are read-only copies.
    Restoring it (Arm.set_state / Data.set_state) and stepping gives bit for bit the trajectory the arm
    had from that point (fixed-step integrators; CVODE restarts its history at a restored state).

    Fields (ndof DOFs, n elements): model (name), source_hash (SHA-256 of the model file), time (s),
    q (ndof,) rad, qdot (ndof,) rad/s, lce (n,) m (fibre lengths), activation (n,), excitation (n,) in
    [0, 1], hand_force (3,) N and hand_moment (3,) N m (thorax frame), path_anchors (k, ndof) rad or None,
    path_anchor_steps (2 ints), previous_step (s).

    path_anchors, path_anchor_steps and previous_step are ROS2's memory (docs/engine.md): it evaluates the
    muscle-path polynomials at one step in three of a run of equal steps and extrapolates them from the last
    two such evaluations everywhere else. path_anchors holds the q of those evaluations (k = 1 or 2, oldest
    first), path_anchor_steps the steps between them (0 with one) and the steps from the newest to this
    state, previous_step the step size (dt / substeps; a halved ros2_adaptive step's half). A restored State
    evaluates the polynomials there again. None (a State built by hand, or not reached by a ROS2 step): the
    next step evaluates the paths afresh, so a run continued from it differs from the original one by the
    extrapolation's error (das3: about 1e-6 rad after 20 steps, up to 7e-6 rad in fast transients)."""

    model: str                # model name
    source_hash: str          # SHA-256 of the model file: a State fits only the same model
    time: float               # s
    q: np.ndarray             # (ndof,) rad
    qdot: np.ndarray          # (ndof,) rad/s
    lce: np.ndarray           # (n,) m, contractile-element (fibre) lengths
    activation: np.ndarray    # (n,)
    excitation: np.ndarray    # (n,) the held neural excitation in [0, 1]
    hand_force: np.ndarray    # (3,) N, thorax frame
    hand_moment: np.ndarray   # (3,) N m, thorax frame
    path_anchors: np.ndarray | None = None  # (k, ndof) rad, k = 1 or 2: q of ROS2's last path evaluations
    path_anchor_steps: tuple = (0, 0)       # (steps between the anchors, steps from the newest to this state)
    previous_step: float = 0.0              # s, the size of the steps that led here
    # armrt before 2026-11-30 saved ROS2's memory as previous_q: accepted when read back, and dropped (below).
    previous_q: InitVar[np.ndarray | None] = None

    _ARRAYS = ("q", "qdot", "lce", "activation", "excitation", "hand_force", "hand_moment")

    def _array_fields(self) -> tuple:
        """The array fields this State holds: _ARRAYS, and path_anchors unless it is None."""
        return self._ARRAYS + (("path_anchors",) if self.path_anchors is not None else ())

    def __post_init__(self, previous_q=None):
        if previous_q is not None and np.size(previous_q) > 0:
            warnings.warn("State.previous_q (a State saved by an older armrt) is no longer ROS2's memory and is "
                          "ignored: the next ROS2 step evaluates the muscle paths afresh, so the continuation "
                          "differs from the original run by about 1e-6 rad", stacklevel=3)
        for k in ("model", "source_hash"):  # np.load gives 0-d string arrays
            object.__setattr__(self, k, str(getattr(self, k)))
        if self.path_anchors is not None and np.size(self.path_anchors) == 0:
            object.__setattr__(self, "path_anchors", None)  # as_dict's stand-in for None (np.savez keeps it)
        for k in self._array_fields():
            a = np.array(getattr(self, k), dtype=float)
            a.flags.writeable = False
            object.__setattr__(self, k, a)
        try:
            steps = np.asarray(self.path_anchor_steps, dtype=float).ravel()
        except (TypeError, ValueError):
            steps = np.empty(0)
        if steps.shape != (2,) or not np.all((steps == np.round(steps)) & (steps >= 0) & (steps < 1e6)):
            raise ValueError(f"State.path_anchor_steps must be two whole numbers >= 0, got {self.path_anchor_steps!r}")
        object.__setattr__(self, "path_anchor_steps", (int(steps[0]), int(steps[1])))
        if self.path_anchors is None and self.path_anchor_steps != (0, 0):
            raise ValueError(f"State.path_anchor_steps must be (0, 0) without path_anchors, got "
                             f"{self.path_anchor_steps}")
        object.__setattr__(self, "time", float(self.time))
        object.__setattr__(self, "previous_step", float(self.previous_step))

    def __eq__(self, other) -> bool:
        """Exactly equal (every bit of every value)."""
        if not isinstance(other, State):
            return NotImplemented
        if ((self.path_anchors is None) != (other.path_anchors is None) or self.previous_step != other.previous_step
                or self.path_anchor_steps != other.path_anchor_steps):
            return False
        return (self.model, self.source_hash, self.time) == (other.model, other.source_hash, other.time) and all(
            np.array_equal(getattr(self, k), getattr(other, k)) for k in self._array_fields())

    __hash__ = None

    def as_dict(self) -> dict:
        """Plain dict (e.g. for np.savez(**state.as_dict()); State(**d) rebuilds it). path_anchors of None is
        an empty array here and path_anchor_steps an integer array, which np.savez stores without pickling
        and State() reads back."""
        d = {f.name: getattr(self, f.name) for f in fields(self)}
        if d["path_anchors"] is None:
            d["path_anchors"] = np.empty(0)
        d["path_anchor_steps"] = np.array(d["path_anchor_steps"], dtype=np.int64)
        return d


class Data:
    """State, inputs and outputs of one arm of `model` (an armrt.Model, or what Model() accepts).

    State (read-only views that follow the simulation): time (s), q, qdot ((ndof,) rad, rad/s), lce ((n,) m),
    activation ((n,)), state (the whole engine state vector [q, qdot, lce, activation]).
    Inputs: excitation ((n,), a copy), hand_force, hand_moment ((3,) N, N m, thorax frame; copies).
    Outputs: outputs() evaluates them at the current state.
    Snapshots: get_state() -> State, set_state(State).
    Data(model) starts at the rest posture, time 0, no excitation; Arm(model) creates the Data it steps
    (Arm.data), with the workspace of its integrator.

    One thread at a time: every call that reads or writes the engine (the inputs, time, outputs(),
    get_state, set_state, deepcopy) raises ConcurrentUseError while another thread is inside one, or
    inside a call of the Arm that steps this Data. The state views are live: read from a second thread
    during a step they show that step half done; take get_state() for a consistent copy."""

    def __init__(self, model="das2"):
        model = Model(model)
        self._attach(model, _core.Arm(model._def, DEFAULT_INTEGRATOR, 1e-3,
                                            _core.default_substeps(DEFAULT_INTEGRATOR, 1e-3)))

    @classmethod
    def _wrap(cls, model, sim) -> "Data":
        d = object.__new__(cls)
        d._attach(model, sim)
        return d

    def _attach(self, model, sim) -> None:
        self.model = model
        self._sim = sim
        # The engine's Data is a single workspace: the Arm stepping it shares this lock (Arm._exclusive).
        self._lock = threading.RLock()
        state = sim.state
        # Offsets from the engine (data.h defines the layout once; model_info exports it).
        self._views = {k: state[o:o + n] for k, (o, n) in model.state_layout.items()}
        self._views["state"] = state[:]
        for v in self._views.values():
            v.flags.writeable = False

    def _step(self, integrator: str, dt: float, substeps: int, n: int) -> None:
        """n control steps with this integrator (armrt.step): the engine's stepper is set up anew only when the
        integrator, dt or substeps differ from the last ones. SimulationError on divergence."""
        from .errors import simulation_error
        with self._exclusive():
            s = self._sim
            if (s.integrator, s.dt, s.substeps) != (integrator, dt, substeps):
                s.set_integrator(integrator, dt, substeps)
            try:
                s.step(n)
            except RuntimeError as exc:
                raise simulation_error(exc) from None

    @contextmanager
    def _exclusive(self):
        """Held while a call reads or changes the engine's state or workspace. A second thread arriving
        meanwhile gets ConcurrentUseError instead of interleaving with the first (both would use the
        same state and workspace: silently wrong results). Re-entrant for callbacks on the same thread."""
        if not self._lock.acquire(blocking=False):
            raise ConcurrentUseError(
                "this Arm is being used by another thread; an Arm is not thread-safe: give each thread its "
                "own Arm, or serialise the calls with a lock")
        try:
            yield
        finally:
            self._lock.release()

    def __repr__(self) -> str:
        return f"Data({self.model.name}, t = {self._sim.time:g} s)"  # a repr never raises ConcurrentUseError

    def __deepcopy__(self, memo):
        """An independent Data: the same Model, state, inputs, per-arm settings (strength, maximum
        activation, gravity) and integrator workspace configuration, in a new engine."""
        with self._exclusive():
            s = self._sim
            sim = _core.Arm(self.model._def, s.integrator, s.dt, s.substeps)
            sim.set_strength_and_max_activation(s.get_strength(), s.get_max_activation())
            sim.gravity = np.asarray(s.gravity, dtype=float)
            sim.max_joint_speed = s.max_joint_speed
            new = Data._wrap(self.model, sim)
            new._load(np.array(s.state), s.excitation, s.hand_force, s.hand_moment, s.time, s.ros2_history())
            memo[id(self)] = new
            return new

    # ------------------------------------------------------------------ state
    @property
    def time(self) -> float:
        with self._exclusive():
            return self._sim.time

    @property
    def q(self) -> np.ndarray:
        return self._views["q"]

    @property
    def qdot(self) -> np.ndarray:
        return self._views["qdot"]

    @property
    def lce(self) -> np.ndarray:
        return self._views["lce"]

    @property
    def activation(self) -> np.ndarray:
        return self._views["activation"]

    @property
    def state(self) -> np.ndarray:
        """(2 ndof + 2 n,) the engine's state vector [q | qdot | lce | activation], read-only view."""
        return self._views["state"]

    # ------------------------------------------------------------------ inputs
    @property
    def excitation(self) -> np.ndarray:
        with self._exclusive():
            return self._sim.excitation.copy()

    @property
    def hand_force(self) -> np.ndarray:
        with self._exclusive():
            return self._sim.hand_force.copy()

    @property
    def hand_moment(self) -> np.ndarray:
        with self._exclusive():
            return self._sim.hand_moment.copy()

    # ------------------------------------------------------------------ outputs
    def outputs(self) -> dict:
        """Outputs at the current state: qddot, muscle_force (N), muscle_length (m), moment_arm (n x ndof,
        m), fibre_velocity, muscle/passive/external torque, hand_position (thorax frame), gh_force
        (scapula frame), gh_theta, gh_phi, gh_stab."""
        with self._exclusive():
            self._sim.evaluate_outputs()
            return self._sim.outputs()

    # ------------------------------------------------------------------ snapshots
    def get_state(self) -> State:
        """A State: time, q, qdot, lce, activation, excitation, hand force and moment, and ROS2's memory
        (path_anchors, path_anchor_steps, previous_step; None, (0, 0) and 0.0 when the state was not reached
        by a ROS2 step) (copies)."""
        with self._exclusive():
            history = self._sim.ros2_history()
            anchors, spacing, since, h = history if history is not None else (None, 0, 0, 0.0)
            return State(model=self.model.name, source_hash=self.model.source_hash, time=self._sim.time,
                         q=self.q, qdot=self.qdot, lce=self.lce, activation=self.activation,
                         excitation=self._sim.excitation, hand_force=self._sim.hand_force,
                         hand_moment=self._sim.hand_moment, path_anchors=anchors,
                         path_anchor_steps=(spacing, since), previous_step=h)

    def set_state(self, state: State) -> None:
        """Restores a State taken from an arm of the same model (ValueError otherwise, for arrays of
        the wrong shape or with NaN, or a q more than checks.RANGE_MARGIN beyond the joint ranges). Clears a divergence error; restarts CVODE's history."""
        if not isinstance(state, State):
            raise TypeError(f"set_state takes an armrt.State (from get_state()), got {type(state).__name__}")
        if state.source_hash != self.model.source_hash:
            raise ValueError(f"this State is of model {state.model!r} (sha256 {state.source_hash[:12]}...), "
                             f"not of {self.model.name!r} (sha256 {self.model.source_hash[:12]}...)")
        nd, n = self.model.n_dofs, self.model.n_elements
        shapes = {"q": (nd,), "qdot": (nd,), "lce": (n,), "activation": (n,), "excitation": (n,),
                  "hand_force": (3,), "hand_moment": (3,)}
        for k, shape in shapes.items():
            a = getattr(state, k)
            if a.shape != shape:
                raise ValueError(f"State.{k} must have shape {shape}, got {a.shape}")
            if not np.all(np.isfinite(a)):
                raise ValueError(f"State.{k} contains NaN or infinite values")
        # As reset(q=...) checks q, without its warning for slightly beyond: a simulated state can end there.
        joint_range(state.q, self.model.dof_names, self.model.dof_ranges, warn=False)
        if not np.isfinite(state.time):
            raise ValueError(f"State.time must be finite, got {state.time}")
        if not (np.isfinite(state.previous_step) and state.previous_step >= 0):
            raise ValueError(f"State.previous_step must be finite and >= 0 (s), got {state.previous_step}")
        history = None
        if state.path_anchors is not None:
            anchors = state.path_anchors
            if anchors.ndim != 2 or anchors.shape[0] not in (1, 2) or anchors.shape[1] != nd:
                raise ValueError(f"State.path_anchors must have shape (1, {nd}) or (2, {nd}) or be None, "
                                 f"got {anchors.shape}")
            if not np.all(np.isfinite(anchors)):
                raise ValueError("State.path_anchors contains NaN or infinite values")
            spacing, since = state.path_anchor_steps
            h = state.previous_step
            if not h > 0:
                raise ValueError(f"State.previous_step must be > 0 (s) with path_anchors, got {h}")
            error = _core.ros2_history_error(anchors.shape[0], spacing, since)
            if error:  # counts no run leaves, by the engine's own rule (rosenbrock.cc), before anything is written
                raise ValueError(f"State.path_anchor_steps {state.path_anchor_steps}: {error}")
            # The anchors some steps before q: no joint faster than the arm's bound between them. This catches
            # a mistaken anchor that would otherwise only show as a distorted or diverging next step; anchors
            # are the q of exact evaluations and must come from get_state unchanged (an edit within the bound
            # moves the continuation by what it implies).
            gaps = [("path_anchors[-1]", anchors[-1], state.q, since)]
            if anchors.shape[0] == 2:
                gaps.append(("path_anchors[0]", anchors[0], anchors[1], spacing))
            for name, a, b, steps in gaps:
                speed = np.abs(b - a) / (steps * h)
                j = int(np.argmax(speed))
                if speed[j] > self._sim.max_joint_speed:
                    raise ValueError(f"State.{name} is not {steps} step(s) of {h:g} s before the next anchor or "
                                     f"q: {self.model.dof_names[j]} would have moved at {speed[j]:.3g} rad/s, "
                                     f"beyond max_joint_speed {self._sim.max_joint_speed:g} rad/s")
            history = (anchors, spacing, since, h)
        x = np.empty(self._sim.state.shape)
        for k, (o, n) in self.model.state_layout.items():
            x[o:o + n] = getattr(state, k)
        self._load(x, state.excitation, state.hand_force, state.hand_moment, state.time, history)

    def _load(self, x, excitation, hand_force, hand_moment, time: float, ros2_history=None) -> None:
        """Writes a state as is (set_state validates first; Arm.__deepcopy__ copies a diverged state too);
        ros2_history: (anchors (k, ndof), anchor spacing, steps since the newest anchor, step size) or None."""
        with self._exclusive():
            self._write(x, excitation, hand_force, hand_moment, time, ros2_history)

    def _write(self, x, excitation, hand_force, hand_moment, time: float, ros2_history) -> None:
        self._sim.state[:] = x
        self._sim.excitation[:] = excitation
        self._sim.hand_force[:] = hand_force
        self._sim.hand_moment[:] = hand_moment
        self._sim.time = time
        self._sim.clear_error()
        if ros2_history is None or len(ros2_history) == 2:  # 2: (previous_q, h) of an Arm pickled by an older armrt
            self._sim.restore_ros2_history(np.zeros((0, self.model.n_dofs)), 0, 0, 0.0)  # clears it
        else:
            anchors, spacing, since, h = ros2_history
            self._sim.restore_ros2_history(np.asarray(anchors, dtype=float), int(spacing), int(since), float(h))
        # CVODE keeps a history of past steps: start it afresh from the restored state.
        if self._sim.integrator == "cvode":
            self._sim.set_integrator("cvode", self._sim.dt, self._sim.substeps)
