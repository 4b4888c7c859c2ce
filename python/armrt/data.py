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
from dataclasses import MISSING, InitVar, dataclass, field, fields

import numpy as np

from . import _core
from .checks import applied_moments, hand_load, per_element, real_array
from .errors import ConcurrentUseError
from .integrators import DEFAULT_INTEGRATOR
from .model import Model
from .snapshot import StatePart, part_slices, signature



# The outputs() dict, key by key (Data.outputs and Arm.outputs; tests/test_api.py checks it names every key the
# engine's layout table gives, cpp/include/armrt/layouts.h ARMRT_OUTPUTS, plus the derived ones).
OUTPUTS_DOC = """The outputs at the current state, a dict of numpy arrays (computed once per state, then read; n elements,
        ndof DOFs):
        output_q (ndof,) rad, the joint angles they describe; muscle_length (n,) m, muscle-tendon lengths;
        muscle_force (n,) N, tendon forces; fibre_velocity (n,) m/s, lengthening positive; moment_arm (n, ndof) m;
        muscle_torque (ndof,) N m, the muscles' generalised forces R^T F; passive_torque (ndof,) N m, the passive
        joint moments; external_torque (ndof,) N m, the generalised forces of the hand force and moment;
        hand_position (3,) m, thorax frame; qddot (ndof,) rad/s^2; gh_force (3,) N, the humeral head's force on the
        glenoid, scapula frame; gh_angles (2,) rad = (gh_theta, gh_phi), that force's angles from the glenoid
        normal along the major (+ superior) and minor axis; gh_stab, (theta/theta_a)^2 + (phi/phi_a)^2 (paper eq.
        5, > 1 beyond the rim); gh_rim_margin rad, how far the force can still turn to the rim (< 0 beyond);
        gh_rim_direction rad, atan2(phi, theta) (0 superior, pi/2 anterior); thorax_humerus (3,) rad, plane of
        elevation, elevation, axial rotation. Only for a model whose scapula moves (das3): girdle_torque (ndof,)
        N m, the scapulothoracic contact's and conoid's generalised forces; contact_distance (2,) m and
        contact_force (2,) N of the contact points TS, AI (distance negative inside the thorax); conoid_length m;
        conoid_tension N."""

@dataclass(frozen=True, eq=False)
class State:
    """A snapshot of a simulated arm: everything its continuation depends on. Arrays are read-only copies.
    Restoring it (Arm.set_state / Data.set_state) and stepping gives bit for bit the trajectory the arm
    had from that point (fixed-step integrators; CVODE restarts its history at a restored state).

    Fields (ndof DOFs, n elements): model (name), source_hash (SHA-256 of the model file), time (s),
    q (ndof,) rad, qdot (ndof,) rad/s, lce (n,) m (fibre lengths), activation (n,), excitation (n,) in
    [0, 1], hand_force (3,) N and hand_moment (3,) N m (thorax frame), path_anchors (k, ndof) rad or None,
    path_anchor_steps (2 ints), previous_step (s), applied_moment (ndof,) N m (generalised forces applied at
    the joints; empty in a State saved before 2026-12-04, restored as zero).

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
    # An arm with a stimulation map (armrt.stimulation): per channel [pulse width s, amplitude A, frequency Hz]
    # flattened (3 x channels,), and the chain's memory per channel, flattened (channels x STIM_STATE_SIZE,);
    # empty without a map.
    stimulation: np.ndarray = field(default_factory=lambda: np.zeros(0))
    stimulation_state: np.ndarray = field(default_factory=lambda: np.zeros(0))
    # (ndof,) N m applied at the joints (Data.set_applied_moment); empty: a State from before 2026-12-04 (zero).
    applied_moment: np.ndarray = field(default_factory=lambda: np.zeros(0))
    # armrt before 2026-11-30 saved ROS2's memory as previous_q: accepted when read back, and dropped (below).
    previous_q: InitVar[np.ndarray | None] = None

    _ARRAYS = ("q", "qdot", "lce", "activation", "excitation", "hand_force", "hand_moment", "stimulation",
               "stimulation_state", "applied_moment")

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

    def __setstate__(self, state: dict) -> None:
        """Unpickling: a State pickled before a field existed gets that field's empty default (an empty
        stimulation or applied_moment, restored as none and zero), as State(...) would give it; the arrays are
        read-only again (pickle gives writeable copies)."""
        for f in fields(self):
            if f.name not in state and f.default_factory is not MISSING:
                state[f.name] = f.default_factory()
        self.__dict__.update(state)
        for k in self._array_fields():
            getattr(self, k).flags.writeable = False

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

    def __repr__(self) -> str:
        """One line: the model, time and sizes (the arrays are the fields; print(s.q) shows one)."""
        memory = ("no ROS2 memory" if self.path_anchors is None else
                  f"ROS2 memory: {self.path_anchors.shape[0]} anchor(s), steps {self.path_anchor_steps}, "
                  f"h {self.previous_step:g} s")
        return (f"armrt.State({self.model}, t = {self.time:g} s, {self.q.size} DOFs, {self.lce.size} elements, "
                f"max excitation {self.excitation.max(initial=0.0):g}, {memory})")

    def as_dict(self) -> dict:
        """Plain dict (e.g. for np.savez(**state.as_dict()); State(**d) rebuilds it). path_anchors of None is
        an empty array here and path_anchor_steps an integer array, which np.savez stores without pickling
        and State() reads back."""
        d = {f.name: getattr(self, f.name) for f in fields(self)}
        if d["path_anchors"] is None:
            d["path_anchors"] = np.empty(0)
        d["path_anchor_steps"] = np.array(d["path_anchor_steps"], dtype=np.int64)
        return d


# ROS2's packed memory in a snapshot (layouts.h ARMRT_SNAPSHOT ros2_path_history): h, anchors, anchor spacing,
# steps since the newest anchor, then two rows of anchor q.
_HISTORY_HEADER = 4


def _state_from_snapshot(model: Model, sim, x: np.ndarray) -> State:
    """The engine's full snapshot x -> a State."""
    where = part_slices(sim, StatePart.FULL)
    values = {name: x[sl] for name, sl in where.items() if name != "ros2_path_history"}
    history = x[where["ros2_path_history"]]
    h, k, spacing, since = history[:_HISTORY_HEADER]
    nd = model.n_dofs
    anchors = history[_HISTORY_HEADER:_HISTORY_HEADER + int(k) * nd].reshape(int(k), nd) if k else None
    values["time"] = float(values["time"][0])
    return State(model=model.name, source_hash=model.source_hash, **values, path_anchors=anchors,
                 path_anchor_steps=(int(spacing), int(since)), previous_step=float(h))


def _snapshot_from_state(model: Model, sim, state: State) -> np.ndarray:
    """A State -> the engine's full snapshot (ValueError for arrays of the wrong shape; the values are the
    engine's to check)."""
    where = part_slices(sim, StatePart.FULL)
    x = np.zeros(max(sl.stop for sl in where.values()))
    nd = model.n_dofs
    for name, sl in where.items():
        if name == "time":
            x[sl] = state.time
        elif name == "ros2_path_history":
            anchors = state.path_anchors
            history = np.zeros(sl.stop - sl.start)
            history[:_HISTORY_HEADER] = (state.previous_step, 0 if anchors is None else anchors.shape[0],
                                         *state.path_anchor_steps)
            if anchors is not None:
                if anchors.ndim != 2 or anchors.shape[0] not in (1, 2) or anchors.shape[1] != nd:
                    raise ValueError(f"State.path_anchors must have shape (1, {nd}) or (2, {nd}) or be None, "
                                     f"got {anchors.shape}")
                history[_HISTORY_HEADER:_HISTORY_HEADER + anchors.size] = anchors.ravel()
            x[sl] = history
        else:
            a = getattr(state, name)
            if name == "applied_moment" and a.size == 0:
                a = np.zeros(sl.stop - sl.start)  # a State saved before applied moments: none were applied
            if a.shape != (sl.stop - sl.start,):
                raise ValueError(f"State.{name} must have shape ({sl.stop - sl.start},), got {a.shape}")
            x[sl] = a
    return x


def _state_error(error: str) -> str:
    """The engine's snapshot_error message in a State's words."""
    prefix = "ros2_path_history: "
    if error.startswith(prefix):
        return "State's ROS2 memory (path_anchors, path_anchor_steps, previous_step): " + error[len(prefix):]
    return "State." + error


class Data:
    """State, inputs and outputs of one arm of `model` (an armrt.Model, or what Model() accepts).

    State (read-only views that follow the simulation): time (s), q, qdot ((ndof,) rad, rad/s), lce ((n,) m),
    activation ((n,)), state (the whole engine state vector [q, qdot, lce, activation]).
    Inputs: excitation ((n,), a copy), hand_force, hand_moment ((3,) N, N m, thorax frame; copies),
    applied_moment ((ndof,) N m at the joints, a copy); set with set_excitation(u), set_hand_load(force,
    moment) and set_applied_moment(moment).
    Per-arm settings: strength, max_activation ((n,), set with arrays, scalars or {name: value}).
    Outputs: outputs() evaluates them at the current state.
    Snapshots: get_state() -> State, set_state(State); get_state_vector(parts) -> a flat array of the parts
    (armrt.StatePart) and set_state_vector(x, parts), checked in the engine.
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
        # True when an Arm steps this Data with its own integrator (Arm.__init__): armrt.step with another
        # Stepper then leaves the Arm's integrator as it was.
        self._arm_stepper = False
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
        integrator, dt or substeps differ from the last ones. An Arm's Data goes back to the Arm's own
        integrator afterwards (its memory restarted): a Stepper passed to armrt.step is the caller's, and
        must not change what the Arm does next. SimulationError on divergence."""
        from .errors import simulation_error
        with self._exclusive():
            s = self._sim
            own = (s.integrator, s.dt, s.substeps)
            foreign = own != (integrator, dt, substeps)
            if foreign:
                s.set_integrator(integrator, dt, substeps)
            try:
                s.step(n)
            except RuntimeError as exc:
                raise simulation_error(exc) from None
            finally:
                if foreign and self._arm_stepper:
                    s.set_integrator(*own)

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

    def _settings(self) -> dict:
        """The integrator and per-arm settings a copy is rebuilt with (call under _exclusive)."""
        s = self._sim
        return dict(integrator=s.integrator, dt=s.dt, substeps=s.substeps, strength=s.get_strength(),
                    max_activation=s.get_max_activation(), gravity=np.array(s.gravity),
                    max_joint_speed=s.max_joint_speed,
                    stimulation_map=s.stimulation_map_json() if s.num_channels else None)

    def _restore(self, settings: dict, snapshot: np.ndarray) -> None:
        """Applies _settings() (but the integrator, which the engine arm was made with) and a full snapshot, as
        is (a diverged state too)."""
        with self._exclusive():
            self._sim.set_strength_and_max_activation(settings["strength"], settings["max_activation"])
            self._sim.gravity = np.asarray(settings["gravity"], dtype=float)
            self._sim.max_joint_speed = settings["max_joint_speed"]
            if settings.get("stimulation_map"):  # before the snapshot: its stimulation parts are sized by the map
                self._sim.set_stimulation_map_json(settings["stimulation_map"])
            self._load_snapshot(snapshot)

    @classmethod
    def _rebuild(cls, model: Model, settings: dict, snapshot: np.ndarray) -> "Data":
        new = cls._wrap(model, _core.Arm(model._def, settings["integrator"], settings["dt"], settings["substeps"]))
        new._restore(settings, snapshot)
        return new

    def __deepcopy__(self, memo):
        """An independent Data: the same Model, state, inputs, per-arm settings (strength, maximum
        activation, gravity, joint-speed bound) and integrator configuration, in a new engine."""
        with self._exclusive():
            new = Data._rebuild(self.model, self._settings(), self._sim.get_snapshot(_core.SNAPSHOT_FULL))
            memo[id(self)] = new
            return new

    def __reduce__(self):
        """Pickling (multiprocessing, Ray): the Model (by name or model file, as Model pickles), the settings
        and the full snapshot of deepcopy."""
        with self._exclusive():
            return (_unpickle_data, (self.model, self._settings(), self._sim.get_snapshot(_core.SNAPSHOT_FULL)))

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

    def set_excitation(self, u) -> None:
        """Neural excitation of the elements, held over the next steps: an array of n, a scalar, or
        {name: value} with element, muscle or group names (unnamed elements get 0; overlapping names: the
        most specific wins, in any order). Values outside [0, 1] are clipped with a RuntimeWarning; values
        above max_activation are stored capped at it (what the dynamics use). ValueError for NaN or
        infinite values, TypeError for non-numbers, KeyError for unknown names."""
        u = per_element(self.model.name, self.model.element_names, u, "excitation", 0.0, 1.0, clip=True, stacklevel=4)
        with self._exclusive():
            self._sim.set_excitation(u)  # the engine's data_set_excitation: the one cap rule

    def set_hand_load(self, force=(0.0, 0.0, 0.0), moment=(0.0, 0.0, 0.0)) -> None:
        """External force (3,) N at the hand point and moment (3,) N m on the hand, thorax frame (x lateral,
        y up, z posterior): a 1 kg weight is force=(0, -9.81, 0). ValueError for another shape or NaN."""
        f, m = hand_load(force, moment)
        with self._exclusive():
            self._sim.hand_force[:], self._sim.hand_moment[:] = f, m

    def set_applied_moment(self, moment=0.0) -> None:
        """Generalised forces (ndof,) N m applied at the joints and held over the next steps, as MuJoCo's
        qfrc_applied: joint friction, an exoskeleton's or a perturbation's moments, added to the muscles',
        passive joints', gravity's and the hand load's in the equations of motion (not to the muscles' share
        that inverse_dynamics returns). moment: an array of one value per DOF (positive along the DOF),
        {dof name: value} (armrt or OpenSim coordinate names; other DOFs 0), or 0 to remove them. KeyError for an
        unknown DOF name, ValueError for another shape, NaN/infinite values or one DOF named twice."""
        a = applied_moments(moment, self.model.dof_names, model_name=self.model.name)
        with self._exclusive():
            self._sim.applied_moment[:] = a

    # ------------------------------------------------------------------ per-arm settings
    @property
    def strength(self) -> np.ndarray:
        """(n,) strength scale per element (multiplies DAS3 fmax; 1 = intact, < 1 weakness), a copy. Set
        with an array, a scalar or {name: value} (unnamed elements keep theirs); ValueError below 0."""
        with self._exclusive():
            return self._sim.get_strength()

    @strength.setter
    def strength(self, values) -> None:
        with self._exclusive():
            s = per_element(self.model.name, self.model.element_names, values, "strength", 0.0, None, clip=False,
                            current=self._sim.get_strength(), stacklevel=4)
            self._sim.set_strength_and_max_activation(s, self._sim.get_max_activation())

    @property
    def max_activation(self) -> np.ndarray:
        """(n,) maximum activation per element in [0, 1] (0 = paralysed), a copy; excitations are capped at
        it (the held one too, when it is lowered). Set like strength; ValueError outside [0, 1]."""
        with self._exclusive():
            return self._sim.get_max_activation()

    @max_activation.setter
    def max_activation(self, values) -> None:
        with self._exclusive():
            m = per_element(self.model.name, self.model.element_names, values, "max_activation", 0.0, 1.0,
                            clip=False, current=self._sim.get_max_activation(), stacklevel=4)
            # The engine caps the held excitation at the new bound (data_apply_settings).
            self._sim.set_strength_and_max_activation(self._sim.get_strength(), m)

    @property
    def hand_force(self) -> np.ndarray:
        with self._exclusive():
            return self._sim.hand_force.copy()

    @property
    def hand_moment(self) -> np.ndarray:
        with self._exclusive():
            return self._sim.hand_moment.copy()

    @property
    def applied_moment(self) -> np.ndarray:
        """(ndof,) N m applied at the joints (set_applied_moment), a copy."""
        with self._exclusive():
            return self._sim.applied_moment.copy()

    # ------------------------------------------------------------------ outputs
    def outputs(self) -> dict:
        with self._exclusive():
            self._sim.evaluate_outputs()
            return self._sim.outputs()

    outputs.__doc__ = OUTPUTS_DOC

    # ------------------------------------------------------------------ snapshots
    def get_state(self) -> State:
        """A State: time, q, qdot, lce, activation, excitation, hand force and moment, and ROS2's memory
        (path_anchors, path_anchor_steps, previous_step; None, (0, 0) and 0.0 when the state was not reached
        by a ROS2 step) (copies): the engine's full snapshot (get_state_vector(StatePart.FULL))."""
        with self._exclusive():
            x = self._sim.get_snapshot(_core.SNAPSHOT_FULL)
        return _state_from_snapshot(self.model, self._sim, x)

    def set_state(self, state: State) -> None:
        """Restores a State taken from an arm of the same model. The engine checks it first (snapshot.h
        snapshot_error) and writes nothing when it refuses: ValueError for a non-finite value, a state outside
        the physical domain a step accepts (a joint more than 0.35 rad beyond its range, with a hint when q
        looks like degrees; a joint faster than max_joint_speed; a fibre length or activation out of range; a
        girdle contact point deep in the thorax), an excitation outside [0, 1], or ROS2 memory no run of steps
        leaves; also for another model's State or arrays of the wrong shape. The excitation is capped at this
        arm's max_activation; a divergence error is cleared; CVODE's history restarts."""
        if not isinstance(state, State):
            raise TypeError(f"set_state takes an armrt.State (from get_state()), got {type(state).__name__}")
        if state.source_hash != self.model.source_hash:
            raise ValueError(f"this State is of model {state.model!r} (sha256 {state.source_hash[:12]}...), "
                             f"not of {self.model.name!r} (sha256 {self.model.source_hash[:12]}...)")
        x = _snapshot_from_state(self.model, self._sim, state)
        with self._exclusive():
            error = self._sim.snapshot_error(_core.SNAPSHOT_FULL, x)
            if error:
                raise ValueError(_state_error(error))
            self._sim.set_snapshot(_core.SNAPSHOT_FULL, x, False)

    def get_state_vector(self, parts=StatePart.FULL) -> np.ndarray:
        """The parts of the state selected by `parts` (an armrt.StatePart such as StatePart.PHYSICS, OR-able,
        or a part name) as one flat array in the engine's order (as MuJoCo's mj_getState); state_vector_slices
        says where each part lies."""
        sig = signature(parts)
        with self._exclusive():
            return self._sim.get_snapshot(sig)

    def set_state_vector(self, x, parts=StatePart.FULL) -> None:
        """Sets the parts selected by `parts` from a flat array of get_state_vector(parts)'s layout; the others
        are kept. Checked in the engine as set_state checks a State (ValueError, nothing written). Setting
        any physics part restarts the integrator's memory unless ROS2_PATH_HISTORY is set with it."""
        sig = signature(parts)
        a = real_array(x, "state vector")
        with self._exclusive():
            n = self._sim.snapshot_size(sig)
            if a.shape != (n,):
                raise ValueError(f"state vector of {StatePart(sig)!r} must have shape ({n},), got {a.shape}")
            error = self._sim.snapshot_error(sig, a)
            if error:
                raise ValueError(f"state vector: {error}")
            self._sim.set_snapshot(sig, a, False)

    def state_vector_slices(self, parts=StatePart.FULL) -> dict:
        """{part name: slice} of get_state_vector(parts)'s array (names as StatePart's, lower case)."""
        return part_slices(self._sim, parts)

    def _load_snapshot(self, x) -> None:
        """Writes a full snapshot as is (Arm.__deepcopy__ copies a diverged state too). A snapshot pickled by
        armrt 2026-12-02 .. 2026-12-03, before the applied_moment row, is read with a zero applied moment."""
        x = np.asarray(x, dtype=float).ravel()
        with self._exclusive():
            applied = part_slices(self._sim, StatePart.FULL)["applied_moment"]
            if x.size == self._sim.snapshot_size(_core.SNAPSHOT_FULL) - (applied.stop - applied.start):
                x = np.concatenate([x[:applied.start], np.zeros(applied.stop - applied.start), x[applied.start:]])
            self._sim.set_snapshot(_core.SNAPSHOT_FULL, x, False)



def _unpickle_data(model: Model, settings: dict, snapshot: np.ndarray) -> Data:
    return Data._rebuild(model, settings, snapshot)
