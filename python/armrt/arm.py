"""The Python API: `Arm` drives one simulated arm; arrays in, arrays out, SI units and radians.

Arm's pieces live in modules of their own, re-exported here so `armrt.arm.<name>` keeps working:
checks (real_array, real_scalar, count, deg, rad, known_model), integrators (INTEGRATORS,
DEFAULT_INTEGRATOR, DEFAULT_MAX_STEP), errors (SimulationError, StepSizeWarning, ConcurrentUseError)
and result (Result).
"""
from __future__ import annotations

import copy
import warnings
from typing import Mapping

import numpy as np

from . import _core
from .checks import MAX_COUNT, RANGE_MARGIN, count, deg, dof_vector, joint_range, known_model, named_items, per_element, rad, real_array, real_scalar
from .data import OUTPUTS_DOC, Data, State, _snapshot_from_state
from .snapshot import StatePart
from .errors import ConcurrentUseError, SimulationError, StepSizeWarning
from .errors import RESET_HINT as _RESET_HINT
from .errors import simulation_error as _simulation_error
from .linearization import STATE_UNITS, Linearization
from .linearization import state_names as linearization_state_names
from .integrators import DEFAULT_INTEGRATOR, DEFAULT_MAX_STEP, INTEGRATORS, MAX_DT, MAX_SUBSTEPS, control_step
from .model import Model
from .profile import profile_values
from .progress import bar as progress_bar
from . import stimulation as _stimulation
from .control import inverse_dynamics as _inverse_dynamics
from .result import Result, _recorded_rows, _row_bytes
from .result import _rim_of_recorded_angles  # noqa: F401 (armrt.arm._rim_of_recorded_angles, as before)

__all__ = ["Arm", "Result", "SimulationError", "StepSizeWarning", "ConcurrentUseError", "INTEGRATORS",
           "DEFAULT_INTEGRATOR", "DEFAULT_MAX_STEP", "MAX_DT", "MAX_SUBSTEPS", "MAX_COUNT", "RANGE_MARGIN", "RESULT_MEMORY_LIMIT",
           "real_array", "real_scalar", "count", "deg", "rad", "known_model"]

# simulate() refuses a Result above this (bytes) unless max_bytes says otherwise.
RESULT_MEMORY_LIMIT = 2 * 1024**3
# Steps per C++ call in simulate(): bounds the excitation block a callable fills.
SIMULATE_BLOCK_STEPS = 2000


def _check_excitation_block(u: np.ndarray, rows, first_step: int, t0: float, dt: float, element_names,
                            clip: bool = True, stacklevel: int = 4) -> None:
    """simulate()'s check of a block of excitation rows, the first being step first_step of a run from t0 (s)
    (rows: a mask of the rows to check, None for all):
    ValueError naming the first NaN/infinite value's step, time (s) and element; values outside [0, 1] give one
    RuntimeWarning and, with clip, are clipped in place (the engine clips them too; Result.excitation holds them)."""
    part = u if rows is None else u[rows]
    bad = ~np.isfinite(part)
    if bad.any():
        row, col = np.argwhere(bad)[0]
        step = first_step + int(row if rows is None else np.flatnonzero(rows)[row])
        raise ValueError(f"excitation contains NaN or infinite values (first at step {step}, element "
                         f"{element_names[col]}, t = {t0 + dt * step:.6g} s)")
    if (part < 0).any() or (part > 1).any():
        warnings.warn("excitation outside [0, 1] clipped", RuntimeWarning, stacklevel=stacklevel)
        if clip:
            np.clip(u, 0.0, 1.0, out=u)


class Arm:
    """One simulated arm of a model (default das2: the paper's fixed-scapula, 5-DOF, 102-element model).

    arm = Arm(model="das2", integrator="ros2", dt=1e-3)
    arm.set_excitation({"rotator_cuff": 0.05, "bicb": 0.3})
    result = arm.simulate(lambda t: {"elbow_flexors": 0.2 if t > 1 else 0.0}, duration=3.0)
    """

    def __init__(self, model="das2", integrator: str = DEFAULT_INTEGRATOR, dt: float = 1e-3,
                 substeps: int | None = None, stimulation=None):
        """model: a registered model's name (armrt.models(); "das2" is built in), a model file path
        (built on demand and cached, see armrt.Model.load) or an armrt.Model; `arm.model` is the
        armrt.Model, `arm.data` the armrt.Data this arm steps.

        dt is the control step (s: inputs held, outputs reported, TET measured per dt); fixed-step
        integrators take `substeps` steps of dt / substeps inside it. Default integrator: "ros2", the
        linearly implicit ROS2 with one step per 1 ms control step, within 0.1 deg of CVODE on the
        paper's tasks (0.013 deg at worst, docs/engine.md). Default substeps: enough for a step of at most
        DEFAULT_MAX_STEP[integrator] (ROS2 1 ms, ros2_adaptive 2 ms, RK4 0.17 ms, Euler 0.1 ms): one
        explicit RK4 step of 1 ms is not stable because the model's short-tendon elements are stiff at
        low activation. "ros2_adaptive" redoes a step as two halves when its error estimate is too
        large: for offline runs at dt = 2 ms, not for hard real time.

        stimulation: None (excitation drives every element), "per_muscle" (one intramuscular channel per
        muscle, named after it), "default" (the map the model ships, models/<model>.stimulation.toml, e.g.
        participant_A_FES's triceps; ValueError for a model without one), or a stimulation map (a .json/.toml path or a dict; armrt.stimulation,
        docs/fes.md): the elements it reaches then follow the stimulation (set_stimulation) and ignore
        their excitation.

        Raises ValueError for an unknown integrator, a dt outside (0, 1] s (integrators.MAX_DT: the
        excitation is held for a whole control step), or substeps outside [1, 100 000]
        (integrators.MAX_SUBSTEPS); TypeError for a dt or substeps that is not a real number / an integer."""
        dt, substeps = control_step(integrator, dt, substeps)
        self.model = Model(model)  # a name, a model file (built on demand) or a Model
        self._sim = _core.Arm(self.model._def, integrator, dt, substeps)
        self.data = Data._wrap(self.model, self._sim)
        self.data._arm_stepper = True
        # One thread at a time: the engine's Data is a single workspace, so the Arm and its Data share
        # one guard (Data._exclusive): arm.data.outputs() from a second thread is refused like arm.outputs().
        self._lock = self.data._lock
        info = self.model.info
        self.model_name = info["name"]
        self.info = info
        self.dof_names = [d["name"] for d in info["dofs"]]
        self.dof_osim_names = [d["osim_name"] for d in info["dofs"]]
        self.dof_ranges = np.array([d["range"] for d in info["dofs"]])
        self.rest_posture = np.array([d["rest"] for d in info["dofs"]])
        self.element_names = [e["name"] for e in info["elements"]]
        self.muscle_names = [m for m, _ in info["muscles"]]
        self.group_names = [g for g, _ in info["groups"]]
        self._index: dict[str, list[int]] = {n: [i] for i, n in enumerate(self.element_names)}
        self._index.update({m: list(ix) for m, ix in info["muscles"]})
        self._index.update({g: list(ix) for g, ix in info["groups"]})
        self.n_elements = len(self.element_names)
        self.n_dofs = len(self.dof_names)
        if stimulation is not None:
            _stimulation.install_map(self._sim, stimulation, self.model_name)
        # The state views are Data's, from the engine's state layout (data.h via model_info).
        self._views = self.data._views
        self._linearize_workspace = None  # linearize()'s engine workspace, made on first use
        # What Arm itself sets; anything else on an arm is the user's, carried by copies and pickles.
        self._base_attributes = frozenset(self.__dict__) | {"_base_attributes"}

    def _exclusive(self):
        """Held while a call steps or changes the simulation: its Data's guard (Data._exclusive), so a
        second thread gets ConcurrentUseError whether it comes through the Arm or through arm.data."""
        return self.data._exclusive()

    # ------------------------------------------------------------------ names
    def indices(self, name: str) -> list[int]:
        """Element indices of an element, muscle or group name; OpenSim force names (delt_scap_1) and
        muscle names (delt_scap: the elements delt_scap_1 ...) are accepted as aliases. KeyError
        with close matches otherwise (the engine's name service, cpp/src/names.cc)."""
        if not isinstance(name, str):
            raise KeyError(f"element, muscle or group names must be strings, got {name!r}")
        ix = self._index.get(name)
        if ix is None:
            ix = list(_core.find_elements(self.model_name, name))  # aliases, or KeyError with close matches
        return ix

    def dof_index(self, name: str) -> int:
        """Index of a DOF by armrt name (GHy) or OpenSim coordinate name (GH_y); KeyError with close matches."""
        return _core.find_dof(self.model_name, str(name))

    def _per_element(self, values, what: str, lo: float, hi: float | None, clip: bool) -> np.ndarray:
        """Array of n from an array of n, a scalar or a {name: value} dict (checks.per_element)."""
        current = None if what in ("excitation", "activation") else self._current(what)
        return per_element(self.model_name, self.element_names, values, what, lo, hi, clip, current, stacklevel=4)

    def _named_items(self, values: Mapping, what: str) -> list[tuple[str, float]]:
        """checks.named_items for this arm's model (ArmBatch refuses the same dicts)."""
        return named_items(self.model_name, values, what)

    def _current(self, what: str) -> np.ndarray:
        return {"strength": self._sim.get_strength, "max_activation": self._sim.get_max_activation}[what]()

    # ------------------------------------------------------------------ inputs
    def set_excitation(self, u) -> None:
        """Neural excitation of the elements: an array of n, a scalar, or {name: value} with element,
        muscle or group names (unnamed elements get 0; overlapping names: the most specific wins). Values
        outside [0, 1] are clipped with a RuntimeWarning and values above max_activation are capped at it
        (so `excitation` reads back what the dynamics use); NaN or infinite values raise ValueError,
        non-numbers TypeError. (Data.set_excitation.)"""
        with self._exclusive():
            self.data.set_excitation(u)

    @property
    def excitation(self) -> np.ndarray:
        return self._sim.excitation.copy()

    # ------------------------------------------------------------------ stimulation (docs/fes.md)
    def set_stimulation_map(self, stimulation) -> None:
        """Installs a stimulation map (None, "per_muscle", a .json/.toml path or a dict; see __init__):
        commands zero, every channel rested. ValueError naming the field for a map the engine refuses."""
        with self._exclusive():
            _stimulation.install_map(self._sim, stimulation, self.model_name)

    @property
    def channel_names(self) -> list[str]:
        """The stimulation map's channels, in command order ([] without a map)."""
        return list(self._sim.channel_names)

    def stimulation_map(self) -> dict:
        """The installed map with every default explicit (a dict a file or set_stimulation_map accepts)."""
        import json
        return json.loads(self._sim.stimulation_map_json()) if self._sim.num_channels else {}

    def set_stimulation(self, values) -> None:
        """Holds each channel's command over the next steps: {channel: (pulse_width_s, amplitude_A,
        frequency_Hz)} (unnamed channels keep theirs) or a (channels, 3) array. Frequency 0 stops the
        channel's train; a changed frequency takes effect from the last pulse. ValueError for an unknown
        channel, a non-finite or negative value, or one beyond the channel's limits (pulse width, amplitude,
        frequency, charge per phase = amplitude x pulse width); nothing is changed then."""
        with self._exclusive():
            cmd = _stimulation.commands(self._sim, values, self._sim.stimulation)
            self._sim.set_stimulation(cmd.ravel())

    @property
    def stimulation(self) -> np.ndarray:
        """(channels, 3): the held [pulse width s, amplitude A, frequency Hz] per channel."""
        return self._sim.stimulation

    def queue_pulses(self, channel: str, times) -> None:
        """Queues single pulses on a channel at explicit times (s, increasing, not before arm.time), with the
        channel's held pulse width and amplitude, besides any frequency train (set frequency 0 for pulses
        alone). At most 16 ahead per channel (ValueError beyond: queue the rest later)."""
        names = self.channel_names
        if channel not in names:
            raise ValueError(f"unknown stimulation channel {channel!r}; channels: {', '.join(names) or 'none'}")
        t = np.atleast_1d(np.asarray(times, dtype=float))
        with self._exclusive():
            self._sim.queue_pulses(names.index(channel), np.ascontiguousarray(t))

    @property
    def stimulation_state(self) -> np.ndarray:
        """(channels, armrt.stimulation.STATE_SIZE): the chain's memory (columns: armrt.stimulation.STATE_COLUMNS:
        calcium_sum, calcium (CN), force (F/F_ref), fatigue_A, fatigue_tau1, fatigue_Km (over rested values),
        last_pulse (s), recruitment, queued, then the queued pulse times)."""
        return self._sim.stimulation_state

    @property
    def fatigue(self) -> dict:
        """{channel: 1 - A/A_rest} now: the fraction of Ding's force-scaling factor A the channel's fibres have
        lost (0 rested). reset() rests every channel."""
        st = self._sim.stimulation_state
        return {n: float(1.0 - st[k, _stimulation.STATE_COLUMNS["fatigue_A"]]) for k, n in enumerate(self.channel_names)}

    @property
    def force_level(self) -> dict:
        """{channel: f = F/F_ref} now: the normalised force of the fibres the channel recruits (docs/fes.md)."""
        st = self._sim.stimulation_state
        return {n: float(st[k, _stimulation.STATE_COLUMNS["force"]]) for k, n in enumerate(self.channel_names)}

    def recruitment_fraction(self, channel: str, pulse_width: float, amplitude: float) -> float:
        """The fraction of what `channel` reaches that one pulse recruits (pulse width s, amplitude A)."""
        names = self.channel_names
        if channel not in names:
            raise ValueError(f"unknown stimulation channel {channel!r}; channels: {', '.join(names) or 'none'}")
        return float(self._sim.recruitment_fraction(names.index(channel), float(pulse_width), float(amplitude)))

    def inverse_dynamics(self, q, qdot=0.0, qddot=0.0, hand_load=None, parts: bool = False):
        """(ndof,) N m: the generalised forces the muscles must supply for accelerations qddot at (q, qdot),
        with this arm's gravity and (hand_load=None) its present hand load; passive joint moments, the hand
        load and das3's girdle contact and conoid forces accounted for (armrt.inverse_dynamics has the details
        and parts=True)."""
        return _inverse_dynamics(self, q, qdot, qddot, hand_load, parts)

    def set_hand_load(self, force=(0.0, 0.0, 0.0), moment=(0.0, 0.0, 0.0)) -> None:
        """External force (N) at the hand point and moment (N m) on the hand, thorax frame
        (x lateral, y up, z posterior): e.g. a 1 kg weight is force=(0, -9.81, 0)."""
        with self._exclusive():
            self.data.set_hand_load(force, moment)

    def set_applied_moment(self, moment=0.0) -> None:
        """Generalised forces (ndof,) N m applied at the joints, held over the next steps (MuJoCo's
        qfrc_applied): joint friction, a device, a push. An array per DOF, {dof name: value} or 0; KeyError
        for an unknown DOF, ValueError for another shape or NaN (Data.set_applied_moment)."""
        with self._exclusive():
            self.data.set_applied_moment(moment)

    @property
    def applied_moment(self) -> np.ndarray:
        """(ndof,) N m applied at the joints (set_applied_moment), a copy."""
        return self.data.applied_moment

    @property
    def strength(self) -> np.ndarray:
        """Per-element strength scale (multiplies DAS3 fmax, 1 = intact)."""
        return self.data.strength

    @strength.setter
    def strength(self, values) -> None:
        with self._exclusive():
            self.data.strength = values

    @property
    def max_activation(self) -> np.ndarray:
        """Per-element maximum activation in [0, 1] (0 = paralysed): excitations are capped at it, and so
        every activation reached from then on. Lowered during a run, it does not cut the present activation:
        that decays to the new bound with the element's deactivation dynamics (tdeact, tens of ms), as a
        muscle does when its drive drops; reset() starts within the bound."""
        return self.data.max_activation

    @max_activation.setter
    def max_activation(self, values) -> None:
        with self._exclusive():
            self.data.max_activation = values

    def apply_profile(self, path_or_name, reference=None):
        """Set strength and max_activation element by element from a participant file, by element
        name (OpenSim force names as aliases): a DAS-format `.mat` (its `fmax`, `maxact`), an armrt
        model file, or a model name (models/<name>.json). strength = fmax(profile) / fmax(reference),
        the reference being `reference=` or the intact file beside the profile (model_struct_A_FES.mat
        -> model_struct_A.mat); without one, the profile's fmax are absolute (divided by this model's).
        Elements the profile does not name keep their values.

        arm = armrt.Arm("das2"); report = arm.apply_profile("../shared/reference/participant_A/model_struct_A_FES.mat")

        Returns a ProfileReport (prints as a summary): elements set, profile names this arm lacks
        (`unmatched`), arm elements left unchanged (`untouched`). Raises FileNotFoundError for a
        missing file or unknown name, ValueError for an unreadable file or values out of range."""
        s, m, report = profile_values(self, path_or_name, reference)
        with self._exclusive():
            self._sim.set_strength_and_max_activation(s, m)
        return report

    # ------------------------------------------------------------------ state
    @property
    def q(self) -> np.ndarray:
        """Joint angles (rad), a read-only view that follows the simulation."""
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
    def time(self) -> float:
        return self._sim.time

    @property
    def integrator(self) -> str:
        return self._sim.integrator

    @property
    def dt(self) -> float:
        """Control step (s)."""
        return self._sim.dt

    @property
    def substeps(self) -> int:
        """Integration steps per control step (1 for CVODE, which picks its own)."""
        return self._sim.substeps

    def reset(self, q=None, qdot=None, activation=None, time: float = 0.0) -> None:
        """Back to a state: q (ndof, rad; default the rest posture), qdot (default 0), activations (n,
        default 0, or a dict of names; capped at max_activation with a RuntimeWarning); contractile
        elements start in static equilibrium. The inputs are kept: the held excitation (or stimulation), hand load
        and applied moment act on the first step after reset as before it (set them to zero to start unloaded).
        time: finite, s. Raises ValueError for NaN/infinite values, TypeError for non-numbers."""
        q = None if q is None else self._check_girdle_contact(self._check_range(self._dof_vector(q, "q")))
        qdot = None if qdot is None else self._dof_vector(qdot, "qdot")
        if qdot is not None and np.any(np.abs(qdot) > self._sim.max_joint_speed):
            j = int(np.argmax(np.abs(qdot)))
            raise ValueError(f"qdot[{self.dof_names[j]}] = {qdot[j]:g} rad/s is beyond max_joint_speed "
                             f"{self._sim.max_joint_speed:g} rad/s (the first step would stop there)")
        if activation is not None:
            activation = self._per_element(activation, "activation", 0.0, 1.0, clip=False)
            capped = self._sim.cap_excitation(activation)  # the engine's cap rule, for activations too
            over = activation > capped
            if over.any():
                names = [self.element_names[i] for i in np.flatnonzero(over)[:5]]
                warnings.warn(f"activation above max_activation capped for elements {names}", RuntimeWarning,
                              stacklevel=2)
                activation = capped
        time = real_scalar(time, "time")
        if not np.isfinite(time):
            raise ValueError(f"time must be a finite number of seconds, got {time}")
        with self._exclusive():
            self._sim.clear_error()
            self._sim.reset(q, qdot, activation)
            self._sim.time = time

    # A scapula contact point (TS, AI) further than this from the thorax surface at a start (m): its
    # contact force is kilonewtons inside, nothing holds the scapula outside; the first steps are violent.
    CONTACT_START_TOLERANCE = 0.005

    def _check_girdle_contact(self, q: np.ndarray) -> np.ndarray:
        """q itself, for a model whose scapula glides on the thorax (das3): ValueError if a contact point
        would start more than _core.MAX_CONTACT_PENETRATION (20 mm, the domain check's limit, engine.md)
        inside the thorax, RuntimeWarning if more than CONTACT_START_TOLERANCE inside or outside. The
        girdle's ranges are a box, but the scapula rests on the thorax only on a surface within it
        (docs/das3.md)."""
        if self.model.base_body != "thorax":
            return q
        g = self._sim.girdle_forces(q)
        names = self.model.info["girdle"]["contact_points"]
        dist = g["contact_distance"]
        desc = ", ".join(f"{n} {abs(d) * 1e3:.1f} mm {'inside' if d < 0 else 'outside'} the thorax "
                         f"({f:.0f} N)" for n, d, f in zip(names, dist, g["contact_force"]))
        limit = _core.MAX_CONTACT_PENETRATION
        if dist.min() < -limit:
            raise ValueError(f"q puts the scapula into the thorax: {desc}; at most {limit * 1e3:.0f} mm inside is "
                             "simulated. Start near the rest posture (the scapula on the thorax) or from a settled "
                             "state.")
        if np.abs(dist).max() > self.CONTACT_START_TOLERANCE:
            warnings.warn(f"q starts the scapula off the thorax surface: {desc} (at rest: 0.7-1.6 mm inside); "
                          "expect a violent first transient, or start near the rest posture", RuntimeWarning,
                          stacklevel=3)
        return q

    def _check_range(self, q: np.ndarray) -> np.ndarray:
        """q itself; reset's range check (checks.joint_range: ValueError more than RANGE_MARGIN rad
        beyond a joint's range, with a degrees hint; RuntimeWarning beyond it by less)."""
        return joint_range(q, self.dof_names, self.dof_ranges)

    def _pose(self, q) -> np.ndarray:
        """q of the functions of a pose: refused more than checks.STATE_MARGIN (the engine's domain,
        0.35 rad) beyond a joint's range, with the degrees hint (the path polynomials are fitted over the ranges: at 25 rad, degrees given as
        radians, they return moment arms of kilometres). No warning closer in: a simulated state may be
        slightly beyond its range."""
        return joint_range(self._dof_vector(q, "q"), self.dof_names, self.dof_ranges, warn=False)

    def _dof_vector(self, v, what: str) -> np.ndarray:
        if isinstance(v, Mapping):
            out = (self.rest_posture if what == "q" else np.zeros(self.n_dofs)).copy()
            for name, x in v.items():
                out[self.dof_index(name)] = real_scalar(x, f"{what}[{name!r}]")
            v = out
        return dof_vector(v, what, self.dof_names)

    # ------------------------------------------------------------------ snapshots
    def get_state(self):
        """An armrt.State: time, q, qdot, lce (fibre lengths), activations, the held excitation and the
        hand force and moment, and ROS2's memory (path_anchors, path_anchor_steps, previous_step: where
        and how many steps ago it last evaluated the muscle paths, and the step size), as copies.
        set_state(s) later and the same steps give bit for bit the same trajectory (fixed-step
        integrators; CVODE restarts its history at a restored state)."""
        with self._exclusive():
            return self.data.get_state()

    def set_state(self, state) -> None:
        """Restores an armrt.State from get_state() of an arm of the same model (ValueError otherwise: the
        engine's snapshot check, Data.set_state, refuses what a step would stop at, such as a q more than
        0.35 rad beyond the joint ranges, or path anchors farther from q than max_joint_speed allows). ROS2's memory is rebuilt from
        path_anchors; a State without it makes the next step evaluate the paths afresh.
        The excitation is stored capped at this arm's max_activation; a divergence error is cleared. Strength,
        max_activation, gravity and the integrator are the arm's own, not part of the State."""
        with self._exclusive():
            self.data.set_state(state)

    def get_state_vector(self, parts=StatePart.FULL) -> np.ndarray:
        """The parts of the state selected by `parts` (armrt.StatePart, OR-able: TIME, Q, QDOT, LCE,
        ACTIVATION, EXCITATION, HAND_FORCE, HAND_MOMENT, ROS2_PATH_HISTORY; groups PHYSICS, INPUTS, INTEGRATOR,
        FULL; or a part name) as one flat array in the engine's order, as MuJoCo's mj_getState; e.g. PHYSICS
        is [q | qdot | lce | activation]. state_vector_slices(parts) says where each part lies."""
        with self._exclusive():
            return self.data.get_state_vector(parts)

    def set_state_vector(self, x, parts=StatePart.FULL) -> None:
        """Sets the parts selected by `parts` from a flat array laid out as get_state_vector(parts); the others
        are kept. Checked in the engine as set_state checks a State (ValueError naming the value; nothing
        written). Setting a physics part without ROS2_PATH_HISTORY makes the next step evaluate the paths
        afresh; CVODE restarts."""
        with self._exclusive():
            self.data.set_state_vector(x, parts)

    def state_vector_slices(self, parts=StatePart.FULL) -> dict:
        """{part name: slice} of get_state_vector(parts)'s array."""
        return self.data.state_vector_slices(parts)

    def _snapshot(self) -> tuple[dict, np.ndarray]:
        """(settings, full snapshot): what a copy or an unpickled arm is rebuilt from (call under _exclusive)."""
        return self.data._settings(), self._sim.get_snapshot(_core.SNAPSHOT_FULL)

    @classmethod
    def _rebuild(cls, model, settings: dict, raw: tuple) -> "Arm":
        new = cls.__new__(cls)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", StepSizeWarning)  # warned when the original was made
            Arm.__init__(new, model, settings["integrator"], settings["dt"], settings["substeps"])
        if isinstance(raw, tuple):  # pickled by armrt before 2026-12-02: (x, excitation, force, moment, time, memory)
            raw = _legacy_snapshot(new, raw)
        new.data._restore(settings, raw)
        return new

    def __deepcopy__(self, memo):
        """An independent Arm: same model, integrator, dt, substeps, strength, max_activation, gravity,
        joint-speed bound and state (a diverged arm's state is copied as is, its error cleared); its
        own engine, lock and TET statistics. Attributes added to the arm are deep-copied."""
        with self._exclusive():
            new = self._rebuild(self.model, *self._snapshot())
            memo[id(self)] = new
            for k, v in self.__dict__.items():
                if k not in self._base_attributes:
                    new.__dict__[k] = copy.deepcopy(v, memo)
            return new

    def __copy__(self):
        """Same as copy.deepcopy: two Arms never share an engine."""
        return self.__deepcopy__({})

    def __reduce__(self):
        """Pickling (multiprocessing, Ray): the model (its name, or its model file, built or found in the
        cache where it is unpickled), the settings and the state of deepcopy; added attributes too."""
        with self._exclusive():
            settings, raw = self._snapshot()
        extras = {k: v for k, v in self.__dict__.items() if k not in self._base_attributes}
        return (_unpickle_arm, (type(self), self.model, settings, raw, extras))

    # ------------------------------------------------------------------ stepping
    def settle(self, duration: float = 3.0) -> None:
        """Relaxes the arm from its current state: `duration` s (default 3) with zero excitation, under the
        hand load as set, then the clock back to 0 and the excitation as it was. das3 starts at DAS3's
        equilibrium.mat posture, which is not this model's equilibrium: it moves by up to 27 deg (the
        elbow) over about 3 s (docs/das3.md); settle() first keeps that transient out of an experiment.
        Raises SimulationError as step() does."""
        duration = real_scalar(duration, "duration")
        if not np.isfinite(duration) or duration < 0:
            raise ValueError(f"duration must be a finite number of seconds >= 0, got {duration}")
        n = self._n_steps(duration)
        with self._exclusive():
            try:
                self._sim.settle(n)  # Arm::settle (arm.h), the engine's one settle path (armrt-rt --settle's too)
            except RuntimeError as exc:
                raise _simulation_error(exc) from None

    def step(self, n: int = 1, progress: bool | None = None) -> None:
        """Advances n control steps (an integer >= 0) with the current excitation and load (loop in
        C++, GIL released). Ctrl-C stops it within about 50 ms, leaving the state of the last
        completed step (KeyboardInterrupt). progress: a tqdm bar on stderr (None: on a terminal, for
        calls over a second). Raises TypeError for a non-integer n, SimulationError on divergence,
        ConcurrentUseError if another thread is using this Arm."""
        n = count(n, "n (number of steps)")
        with self._exclusive():
            try:
                if n <= SIMULATE_BLOCK_STEPS or progress is False:
                    self._sim.step(n)
                    return
                with progress_bar(n, "step", unit="step", enabled=progress, delay=0.0 if progress else 1.0) as pbar:
                    for k0 in range(0, n, SIMULATE_BLOCK_STEPS):
                        k = min(SIMULATE_BLOCK_STEPS, n - k0)
                        self._sim.step(k)
                        pbar.update(k)
            except RuntimeError as exc:
                raise _simulation_error(exc) from None

    def result_bytes(self, duration: float, record_every: int = 1) -> int:
        """Memory (bytes) of the Result simulate(duration, record_every=...) returns."""
        n_steps = self._n_steps(real_scalar(duration, "duration"))
        rows = _recorded_rows(n_steps, count(record_every, "record_every", minimum=1))
        return rows * _row_bytes(self.n_elements, self.n_dofs, self._contact_points(), self._sim.num_channels)

    def _contact_points(self) -> int:
        girdle = self.model._info["girdle"]  # the Model's own description (Model.info would copy it: 1 ms)
        return len(girdle["contact_points"]) if girdle else 0

    def _n_steps(self, duration: float) -> int:
        if not (np.isfinite(duration) and duration >= 0):
            raise ValueError(f"duration must be a non-negative number of seconds, got {duration}")
        steps = round(duration / self.dt)
        if steps > MAX_COUNT:
            raise OverflowError(f"duration = {duration} s is {steps:.3g} steps of {self.dt} s, more than can be counted")
        return int(steps)

    def simulate(self, excitation, duration: float, record_every: int = 1, max_bytes: float | None = None,
                 progress: bool | None = None) -> Result:
        """Runs for `duration` seconds from the current state and returns the time series.

        excitation: a (T, n) array with one row per step (T = round(duration / dt)), an (n,) array,
        scalar or {name: value} dict held constant, or a callable f(t) -> any of those, evaluated at
        each step's start time (in blocks of steps between C++ loops without the GIL; for feedback
        control use step()). Values are clipped to [0, 1] (RuntimeWarning) and capped at
        max_activation without a warning; Result.excitation holds the values the dynamics used.
        record_every: keep every k-th step (integer >= 1). max_bytes: refuse (MemoryError, with the
        record_every that fits) a Result larger than this; default RESULT_MEMORY_LIMIT (2 GiB),
        None to allow any. progress: a tqdm bar on stderr (None: only on a terminal and for runs
        longer than a second of wall time). Ctrl-C stops within about 50 ms (KeyboardInterrupt,
        state left at the last completed step).
        """
        duration = real_scalar(duration, "duration")
        n_steps = self._n_steps(duration)
        record_every = count(record_every, "record_every", minimum=1)
        rows = _recorded_rows(n_steps, record_every)
        limit = RESULT_MEMORY_LIMIT if max_bytes is None else real_scalar(max_bytes, "max_bytes")
        need = rows * _row_bytes(self.n_elements, self.n_dofs, self._contact_points(), self._sim.num_channels)
        if need > limit:
            fit = int(np.ceil(need / limit)) * record_every
            raise MemoryError(
                f"simulate({duration:g} s) would record {rows} rows = {need / 1e9:.1f} GB, above the limit of "
                f"{limit / 1e9:.1f} GB: pass record_every={fit} (every {fit * self.dt:g} s) or more, a shorter "
                f"duration, or max_bytes={need:.3g} if the memory is there")
        n = self.n_elements
        array_in = isinstance(excitation, np.ndarray) and excitation.ndim == 2
        if callable(excitation) and not isinstance(excitation, Mapping):
            def block(k0: int, k1: int) -> np.ndarray:
                # A float (n,) array (what a controller returns) is copied as it is and the block checked once
                # (finite, [0, 1]) like an array input: per_element's checks on every step cost more than the step.
                u = np.empty((k1 - k0, n))
                fast = np.zeros(k1 - k0, dtype=bool)
                for k in range(k0, k1):
                    v = excitation(float(t0 + self.dt * k))
                    if type(v) is np.ndarray and v.shape == (n,) and v.dtype == np.float64:
                        u[k - k0] = v
                        fast[k - k0] = True
                    else:
                        u[k - k0] = self._per_element(v, "excitation", 0.0, 1.0, clip=True)
                if fast.any():
                    _check_excitation_block(u, fast, k0, t0, self.dt, self.element_names)
                return u
        elif array_in:
            if excitation.shape != (n_steps, n):
                raise ValueError(f"excitation must have shape ({n_steps}, {n}) for {duration} s at dt = {self.dt} s, "
                                 f"got {excitation.shape}")
            u_all = real_array(excitation, "excitation")
            _check_excitation_block(u_all, None, 0, self.time, self.dt, self.element_names, clip=False,
                                    stacklevel=3)

            def block(k0: int, k1: int) -> np.ndarray:
                return u_all[k0:k1]
        else:
            held = self._per_element(excitation, "excitation", 0.0, 1.0, clip=True)[None, :]

            def block(k0: int, k1: int) -> np.ndarray:
                return held

        # The engine writes the rows straight into the Result's arrays, block by block. Blocks are whole record
        # intervals: a block's closing row (the state after it) is the next block's first row, which overwrites
        # it, so it is kept only at the end.
        chunk = record_every * max(1, -(-SIMULATE_BLOCK_STEPS // record_every))
        with self._exclusive():
            out = {k: np.empty(shape) for k, shape in self._sim.recording_shapes(rows).items()}
            t0 = self.time
            row = 0
            with progress_bar(n_steps * self.dt, "simulate", unit="s", enabled=progress,
                              delay=0.0 if progress else 1.0) as pbar:
                for k0 in range(0, max(n_steps, 1), chunk):
                    k1 = min(n_steps, k0 + chunk)
                    u = np.ascontiguousarray(block(k0, k1), dtype=float) if n_steps else \
                        self._sim.excitation[None, :].copy()
                    try:
                        done = self._sim.simulate(u, k1 - k0, record_every, out=out, row=row)
                    except RuntimeError as exc:
                        raise _simulation_error(exc) from None
                    row += done["rows"] if k1 >= n_steps else (k1 - k0) // record_every
                    pbar.update((k1 - k0) * self.dt)
        assert row == rows, (row, rows)
        if "stimulation" in out:  # (T, 3 x channels) -> (T, channels, 3)
            out["stimulation"] = out["stimulation"].reshape(rows, -1, 3)
        return Result(**out, dof_names=list(self.dof_names), element_names=list(self.element_names),
                      channel_names=self.channel_names, integrator=self.integrator, dt=self.dt, substeps=self.substeps, model=self.model_name,
                      model_hash=self.model.source_hash)

    # ------------------------------------------------------------------ outputs
    def outputs(self) -> dict:
        with self._exclusive():
            self._sim.evaluate_outputs()  # once per state: computed only if they no longer describe it
            return self._sim.outputs()

    outputs.__doc__ = OUTPUTS_DOC

    def _output(self, name: str):
        """One output at the current state (computed once per state, then read)."""
        with self._exclusive():
            return self._sim.output(name)

    @property
    def gh_stab(self) -> float:
        """1, (theta/theta_a)^2 + (phi/phi_a)^2 of the GH force now (the paper's eq. (5)); > 1 beyond the rim."""
        return self._output("gh_stab")

    @property
    def gh_theta(self) -> float:
        """rad, angle of the GH force from the glenoid normal along the major axis (+ superior)."""
        return float(self._output("gh_angles")[0])

    @property
    def gh_phi(self) -> float:
        """rad, angle of the GH force from the glenoid normal along the minor axis (+ anterior)."""
        return float(self._output("gh_angles")[1])

    @property
    def gh_rim_margin(self) -> float:
        """rad, how far the GH force can still turn towards gh_rim_direction before it reaches the rim
        (< 0: beyond it); see gh_rim."""
        return self._output("gh_rim_margin")

    @property
    def gh_rim_direction(self) -> float:
        """rad, psi = atan2(phi, theta), where in the glenoid the GH force leans: 0 superior, pi/2 anterior."""
        return self._output("gh_rim_direction")

    @property
    def hand_position(self) -> np.ndarray:
        return self._output("hand_position")

    @property
    def tet(self) -> dict:
        """Task execution time statistics of the steps so far (ns): count, mean, min, max, last."""
        return self._sim.tet_stats()

    # ------------------------------------------------------------------ linearisation
    def linearize(self, continuous: bool = False) -> Linearization:
        """The dynamics linearised at the current state x0 = [q | qdot | lce | activation] and excitation u0, hand load,
        applied moment and settings as set (armrt.linearization.Linearization: A, B, dfdx, dfdu, slices by block
        name, units). The inputs u are the excitations only: the hand load and the applied moment are held at their
        values (their effect is in x0_next and A, not a column of B; an applied moment a enters as
        d qddot / d a = M^-1, arm.mass_matrix()).

        continuous=False (default): A = dx+/dx (ns, ns) and B = dx+/du (ns, n_elements) of one ROS2 step of dt taken
        from x0 as a step from a state set from outside takes it (muscle paths evaluated at both stages), the step
        differentiated exactly (its matrix I - h gamma J too, J's own derivatives by central differences), plus dfdx,
        dfdu. continuous=True: dfdx = d(dx/dt)/dx and dfdu = d(dx/dt)/du of forward() only (A, B None): the
        structured Jacobian's exact per-element blocks and the mechanical terms the step leaves out (gravity,
        Coriolis, dM/dq, moment-arm derivatives, the hand load's J^T F) by central differences of the skeleton and
        path stages with the tendon forces held (docs/control.md "Linearised dynamics"). The state and inputs are unchanged.

        Kinks (docs/control.md "Linearised dynamics"): at u = 0 or u = max_activation dfdu/B are the derivatives from inside [0, max];
        the muscle kernel's one-sided points (CE floor, damping floor), the fibre limiter's on/off conditions and the
        passive joint limits make A one-sided or discontinuous there.

        Raises ValueError for an arm with a stimulation map (the elements it drives follow the stimulation stage's
        memory, which is not part of x), for an integrator other than "ros2" or substeps != 1 (continuous=False
        only), and SimulationError for an arm whose last step failed or (continuous=False) where the step from x0 would
        leave the physical domain, as step() would. x0_next is x0 + h (3/2 k1 + 1/2 k2) of the stages linearize()
        forms: the step's own arithmetic, no second step."""
        if not isinstance(continuous, (bool, np.bool_)):
            raise TypeError(f"continuous must be True or False, got {continuous!r}")
        with self._exclusive():
            if len(self._sim.channel_names) > 0:
                raise ValueError("linearize: this arm has a stimulation map; the elements it drives follow the "
                                 "stimulation stage's memory, which is not part of the state x (clear the map first)")
            if not continuous and (self.integrator != "ros2" or self.substeps != 1):
                raise ValueError(f"linearize: A and B are of one ROS2 step (integrator 'ros2', substeps 1); this arm "
                                 f"has integrator {self.integrator!r} with substeps {self.substeps} "
                                 f"(continuous=True gives df/dx, df/du for any integrator)")
            if self._linearize_workspace is None:
                self._linearize_workspace = _core.LinearizeWorkspace()
            try:
                out = self._sim.linearize(self._linearize_workspace, not continuous)
            except RuntimeError as exc:  # the arm's last step failed: its state is no operating point
                raise _simulation_error(RuntimeError(f"linearize: the arm's last step failed ({exc}); there is "
                                                     f"no state to linearise at")) from None
            x0 = self.data.get_state_vector(StatePart.PHYSICS)
            u0 = self.excitation.copy()
        x_next = None
        if not continuous:
            # Where the step lands, from the stages linearize() formed (the step's own arithmetic; a deepcopy of the
            # arm stepped once cost 4x the linearisation, docs/control.md "Cost"). Where that step would stop, the
            # step itself, on a copy, raises the SimulationError step() raises, said of the step from x0: this arm
            # was not stepped and needs no reset.
            x_next, in_domain = out[4], out[5]
            if not in_domain:
                probe = copy.deepcopy(self)
                probe.set_state_vector(x0, StatePart.PHYSICS)
                try:
                    probe.step(1)
                except SimulationError as exc:
                    said = str(exc).removesuffix(_RESET_HINT)
                    raise SimulationError(f"linearize: the step from this state would fail ({said}); A and B are "
                                          f"of no step. The arm is unchanged (not stepped)") from None
                x_next = probe.get_state_vector(StatePart.PHYSICS)
        slices = {k: slice(o, o + n) for k, (o, n) in self.model.state_layout.items()}
        return Linearization(A=None if continuous else out[2], B=None if continuous else out[3], dfdx=out[0],
                             dfdu=out[1], x0=x0, u0=u0, x0_next=x_next, dt=self.dt, slices=slices,
                             units=dict(STATE_UNITS), state_names=linearization_state_names(self),
                             input_names=list(self.element_names))

    # ------------------------------------------------------------------ model at any pose
    def moment_arms(self, q) -> np.ndarray:
        """(n, ndof) moment arms (m) at pose q: -dL/dq of the path polynomials."""
        return self._sim.muscle_paths(self._pose(q))[1]

    def muscle_lengths(self, q) -> np.ndarray:
        """(n,) muscle-tendon lengths (m) at pose q."""
        return self._sim.muscle_paths(self._pose(q))[0]

    def gh_directions(self, q) -> np.ndarray:
        """(n, 3) unit lines of action at GH (scapula frame); zero rows for elements not crossing GH."""
        return self._sim.gh_directions(self._pose(q))

    def mass_matrix(self, q) -> np.ndarray:
        return self._sim.mass_matrix(self._pose(q))

    def girdle_forces(self, q) -> dict:
        """The girdle stage at pose q (docs/das3.md; zeros for a model with a fixed girdle): 'tau' (ndof,)
        N m, the generalised forces of the scapulothoracic contact and the conoid ligament; 'stiffness'
        (ndof, ndof) N m/rad, J^T dF/dp J (the ROS2 Jacobian's part; the dJ/dq term is left out);
        'contact_distance' (P,) m, first-order signed distance of each contact point (TS, AI) from the
        thorax surface, negative inside; 'contact_force' (P,) N; 'conoid_length' m; 'conoid_tension' N."""
        return self._sim.girdle_forces(self._pose(q))

    def thorax_humerus_angles(self, q) -> np.ndarray:
        """Plane of elevation, elevation, axial rotation (rad) of the humerus relative to the thorax."""
        return self._sim.thorax_humerus_angles(self._pose(q))

    def gh_stability(self, force) -> tuple[float, float, float]:
        """(theta, phi, GHstab) of a force of the humeral head on the glenoid (scapula frame, N)."""
        f = real_array(force, "force")
        if f.shape != (3,) or not np.all(np.isfinite(f)):
            raise ValueError(f"force must be 3 finite values, got {force!r}")
        return self._sim.gh_stability(f)

    def gh_rim(self, force) -> dict:
        """theta, phi, GHstab, the margin to the rim and the rim direction of any forces of the humeral head
        on the glenoid, for a controller to weigh a force before it applies it. force: (3,) or (k, 3) N,
        scapula frame; returns {"gh_theta", "gh_phi", "gh_stab", "gh_rim_margin", "gh_rim_direction"}, each
        of shape () or (k,), rad (gh_stab 1), the same numbers as the properties of those names give for
        arm.outputs()["gh_force"] (armrt.Model.gh_rim, docs/conventions.md)."""
        return self.model.gh_rim(force)


def _legacy_snapshot(arm: Arm, raw: tuple) -> np.ndarray:
    """The full snapshot of an Arm pickled before snapshots by signature: (state vector, excitation, hand force,
    hand moment, time, ROS2 memory (anchors, spacing, steps since, h) or None, or (previous_q, h) before
    2026-11-30, which is dropped)."""
    x, excitation, hand_force, hand_moment, time, history = raw
    x = np.asarray(x, dtype=float)
    blocks = {name: x[offset:offset + n] for name, (offset, n) in arm.model.state_layout.items()}
    anchors, steps, h = None, (0, 0), 0.0
    if history is not None and len(history) == 4:
        anchors, spacing, since, h = history
        steps = (spacing, since)
    # Packed as any State is (data.py), so the two formats cannot drift apart.
    state = State(model=arm.model.name, source_hash=arm.model.source_hash, time=time, excitation=excitation,
                  hand_force=hand_force, hand_moment=hand_moment, path_anchors=anchors, path_anchor_steps=steps,
                  previous_step=h, **blocks)
    return _snapshot_from_state(arm.model, arm._sim, state)


def _unpickle_arm(cls, model, settings: dict, raw, extras: dict) -> Arm:
    arm = cls._rebuild(model, settings, raw)
    arm.__dict__.update(extras)
    return arm
