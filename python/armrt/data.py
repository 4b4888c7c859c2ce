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

from dataclasses import dataclass, fields

import numpy as np

from . import _core


@dataclass(frozen=True, eq=False)
class State:
    """A snapshot of a simulated arm: everything its continuation depends on. Arrays are read-only copies.
    Restoring it (Arm.set_state / Data.set_state) and stepping gives bit for bit the trajectory the arm
    had from that point (fixed-step integrators; CVODE restarts its history at a restored state).

    Fields (ndof DOFs, n elements): model (name), source_hash (SHA-256 of the model file), time (s),
    q (ndof,) rad, qdot (ndof,) rad/s, lce (n,) m (fibre lengths), activation (n,), excitation (n,) in
    [0, 1], hand_force (3,) N and hand_moment (3,) N m (thorax frame), previous_q (ndof,) rad or None,
    previous_step (s).

    previous_q and previous_step are ROS2's memory: the q the integration step that reached this state
    started from and that step's size, dt / substeps (a halved ros2_adaptive step's half). The next step's
    second stage extrapolates the muscle paths from the moment arms there (docs/engine.md); a restored
    State rebuilds them from previous_q. None and 0.0 (a State built by hand, or not reached by a ROS2
    step): the next step evaluates the paths afresh, so a run continued from it differs from the original
    one by one extrapolation's error (das3: about 1e-7 rad after 20 steps, up to 2e-6 rad in fast
    transients)."""

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
    previous_q: np.ndarray | None = None  # (ndof,) rad, q at the start of the ROS2 step that led here
    previous_step: float = 0.0            # s, that step's size

    _ARRAYS = ("q", "qdot", "lce", "activation", "excitation", "hand_force", "hand_moment")

    def _array_fields(self) -> tuple:
        """The array fields this State holds: _ARRAYS, and previous_q unless it is None."""
        return self._ARRAYS + (("previous_q",) if self.previous_q is not None else ())

    def __post_init__(self):
        for k in ("model", "source_hash"):  # np.load gives 0-d string arrays
            object.__setattr__(self, k, str(getattr(self, k)))
        if self.previous_q is not None and np.size(self.previous_q) == 0:
            object.__setattr__(self, "previous_q", None)  # as_dict's stand-in for None (np.savez keeps it)
        for k in self._array_fields():
            a = np.array(getattr(self, k), dtype=float)
            a.flags.writeable = False
            object.__setattr__(self, k, a)
        object.__setattr__(self, "time", float(self.time))
        object.__setattr__(self, "previous_step", float(self.previous_step))

    def __eq__(self, other) -> bool:
        """Exactly equal (every bit of every value)."""
        if not isinstance(other, State):
            return NotImplemented
        if (self.previous_q is None) != (other.previous_q is None) or self.previous_step != other.previous_step:
            return False
        return (self.model, self.source_hash, self.time) == (other.model, other.source_hash, other.time) and all(
            np.array_equal(getattr(self, k), getattr(other, k)) for k in self._array_fields())

    __hash__ = None

    def as_dict(self) -> dict:
        """Plain dict (e.g. for np.savez(**state.as_dict()); State(**d) rebuilds it). A previous_q of None is
        an empty array here, which np.savez stores without pickling and State() reads back as None."""
        d = {f.name: getattr(self, f.name) for f in fields(self)}
        if d["previous_q"] is None:
            d["previous_q"] = np.empty(0)
        return d


class Data:
    """State, inputs and outputs of one arm of `model` (an armrt.Model, or what Model() accepts).

    State (read-only views that follow the simulation): time (s), q, qdot ((ndof,) rad, rad/s), lce ((n,) m),
    activation ((n,)), state (the whole engine state vector [q, qdot, lce, activation]).
    Inputs: excitation ((n,), a copy), hand_force, hand_moment ((3,) N, N m, thorax frame; copies).
    Outputs: outputs() evaluates them at the current state.
    Snapshots: get_state() -> State, set_state(State).
    Data(model) starts at the rest posture, time 0, no excitation; Arm(model) creates the Data it steps
    (Arm.data), with the workspace of its integrator."""

    def __init__(self, model="das2"):
        from .arm import DEFAULT_INTEGRATOR
        from .model import Model
        model = Model(model)
        self._attach(model, _core.Simulator(model._def, DEFAULT_INTEGRATOR, 1e-3,
                                            _core.default_substeps(DEFAULT_INTEGRATOR, 1e-3)))

    @classmethod
    def _wrap(cls, model, sim) -> "Data":
        d = object.__new__(cls)
        d._attach(model, sim)
        return d

    def _attach(self, model, sim) -> None:
        self.model = model
        self._sim = sim
        state = sim.state
        # Offsets from the engine (data.h defines the layout once; model_info exports it).
        self._views = {k: state[o:o + n] for k, (o, n) in model.state_layout.items()}
        self._views["state"] = state[:]
        for v in self._views.values():
            v.flags.writeable = False

    def __repr__(self) -> str:
        return f"Data({self.model.name}, t = {self.time:g} s)"

    def __deepcopy__(self, memo):
        """An independent Data: the same Model, state, inputs, per-arm settings (strength, maximum
        activation, gravity) and integrator workspace configuration, in a new engine."""
        s = self._sim
        sim = _core.Simulator(self.model._def, s.integrator, s.dt, s.substeps)
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
        return self._sim.excitation.copy()

    @property
    def hand_force(self) -> np.ndarray:
        return self._sim.hand_force.copy()

    @property
    def hand_moment(self) -> np.ndarray:
        return self._sim.hand_moment.copy()

    # ------------------------------------------------------------------ outputs
    def outputs(self) -> dict:
        """Outputs at the current state: qddot, muscle_force (N), muscle_length (m), moment_arm (n x ndof,
        m), fibre_velocity, muscle/passive/external torque, hand_position (thorax frame), gh_force
        (scapula frame), gh_theta, gh_phi, gh_stab."""
        self._sim.evaluate_outputs()
        return self._sim.outputs()

    # ------------------------------------------------------------------ snapshots
    def get_state(self) -> State:
        """A State: time, q, qdot, lce, activation, excitation, hand force and moment, and ROS2's memory
        (previous_q, previous_step; None and 0.0 when the state was not reached by a ROS2 step) (copies)."""
        history = self._sim.ros2_history()
        previous_q, previous_step = history if history is not None else (None, 0.0)
        return State(model=self.model.name, source_hash=self.model.source_hash, time=self._sim.time,
                     q=self.q, qdot=self.qdot, lce=self.lce, activation=self.activation,
                     excitation=self._sim.excitation, hand_force=self._sim.hand_force,
                     hand_moment=self._sim.hand_moment, previous_q=previous_q, previous_step=previous_step)

    def set_state(self, state: State) -> None:
        """Restores a State taken from an arm of the same model (ValueError otherwise, or for arrays of
        the wrong shape or with NaN). Clears a divergence error; restarts CVODE's history."""
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
        if not np.isfinite(state.time):
            raise ValueError(f"State.time must be finite, got {state.time}")
        if state.previous_q is not None:
            if state.previous_q.shape != (nd,):
                raise ValueError(f"State.previous_q must have shape {(nd,)} or be None, got {state.previous_q.shape}")
            if not np.all(np.isfinite(state.previous_q)):
                raise ValueError("State.previous_q contains NaN or infinite values")
        if not (np.isfinite(state.previous_step) and state.previous_step >= 0):
            raise ValueError(f"State.previous_step must be finite and >= 0 (s), got {state.previous_step}")
        if state.previous_q is not None and state.previous_step > 0:
            # One step from previous_q to q: no joint faster than the arm's bound (a mistaken previous_q would
            # otherwise only show as a distorted or diverging next step).
            speed = np.abs(state.q - state.previous_q) / state.previous_step
            j = int(np.argmax(speed))
            if speed[j] > self._sim.max_joint_speed:
                raise ValueError(f"State.previous_q is not one step of {state.previous_step:g} s before q: "
                                 f"{self.model.dof_names[j]} would have moved at {speed[j]:.3g} rad/s, beyond "
                                 f"max_joint_speed {self._sim.max_joint_speed:g} rad/s")
        x = np.empty(self._sim.state.shape)
        for k, (o, n) in self.model.state_layout.items():
            x[o:o + n] = getattr(state, k)
        history = (state.previous_q, state.previous_step) if state.previous_q is not None else None
        self._load(x, state.excitation, state.hand_force, state.hand_moment, state.time, history)

    def _load(self, x, excitation, hand_force, hand_moment, time: float, ros2_history=None) -> None:
        """Writes a state as is (set_state validates first; Arm.__deepcopy__ copies a diverged state too);
        ros2_history: (previous_q, previous_step) or None."""
        self._sim.state[:] = x
        self._sim.excitation[:] = excitation
        self._sim.hand_force[:] = hand_force
        self._sim.hand_moment[:] = hand_moment
        self._sim.time = time
        self._sim.clear_error()
        if ros2_history is None:
            self._sim.restore_ros2_history(np.zeros(self.model.n_dofs), 0.0)  # clears it
        else:
            self._sim.restore_ros2_history(np.asarray(ros2_history[0], dtype=float), float(ros2_history[1]))
        # CVODE keeps a history of past steps: start it afresh from the restored state.
        if self._sim.integrator == "cvode":
            self._sim.set_integrator("cvode", self._sim.dt, self._sim.substeps)
