"""The Python API: `Arm` drives one simulated arm; arrays in, arrays out, SI units and radians."""
from __future__ import annotations

import difflib
import warnings
from dataclasses import dataclass, field
from typing import Callable, Mapping

import numpy as np

from . import _core

INTEGRATORS = ("ros2", "ros2_adaptive", "euler", "rk4", "cvode")
DEFAULT_INTEGRATOR = "ros2"
# Largest integration step used by default (s), from the engine (simulator.cc default_max_step):
# ROS2 (linearly implicit, docs/engine.md) one step per 1 ms control step; ros2_adaptive up to 2 ms, a
# step whose error estimate is too large redone as two halves (offline use: its cost is not fixed);
# RK4 6 substeps per 1 ms and Euler 0.1 ms (the paper's explicit solvers); CVODE picks its own (inf).
DEFAULT_MAX_STEP = {name: _core.default_max_step(name) for name in INTEGRATORS}


class SimulationError(RuntimeError):
    """The simulation diverged (non-finite state, or a joint faster than the physical bound)."""


def deg(x):
    """Radians to degrees (arrays welcome)."""
    return np.degrees(x)


def rad(x):
    """Degrees to radians (arrays welcome)."""
    return np.radians(x)


@dataclass
class Result:
    """Time series of a simulation; row k is the state at time[k] and the outputs at that state."""

    time: np.ndarray            # (T,) s
    q: np.ndarray               # (T, 5) rad
    qdot: np.ndarray            # (T, 5) rad/s
    lce: np.ndarray             # (T, n) m, contractile-element lengths
    activation: np.ndarray      # (T, n)
    excitation: np.ndarray      # (T, n)
    muscle_force: np.ndarray    # (T, n) N
    muscle_length: np.ndarray   # (T, n) m, muscle-tendon lengths
    gh_force: np.ndarray        # (T, 3) N, humeral head on glenoid, scapula frame
    gh_stab: np.ndarray         # (T,)
    gh_angles: np.ndarray       # (T, 2) rad, theta (major axis), phi (minor axis)
    hand_position: np.ndarray   # (T, 3) m, thorax frame
    thorax_humerus: np.ndarray  # (T, 3) rad: plane of elevation, elevation, axial rotation
    tet_ns: np.ndarray          # (T,) ns, task execution time of the step that started at that row
    dof_names: list = field(default_factory=list)
    element_names: list = field(default_factory=list)
    integrator: str = ""
    dt: float = 0.0             # control step (s)
    substeps: int = 1           # integration steps per control step
    model: str = ""

    ARRAYS = ("time", "q", "qdot", "lce", "activation", "excitation", "muscle_force", "muscle_length",
              "gh_force", "gh_stab", "gh_angles", "hand_position", "thorax_humerus", "tet_ns")

    @property
    def q_deg(self) -> np.ndarray:
        return np.degrees(self.q)

    def save(self, path) -> None:
        """Saves to a compressed .npz (load with Result.load)."""
        np.savez_compressed(path, **{k: getattr(self, k) for k in self.ARRAYS},
                            dof_names=np.array(self.dof_names), element_names=np.array(self.element_names),
                            integrator=self.integrator, dt=self.dt, substeps=self.substeps, model=self.model)

    @classmethod
    def load(cls, path) -> "Result":
        with np.load(path, allow_pickle=False) as z:
            missing = [k for k in cls.ARRAYS if k not in z.files]
            if missing:
                raise ValueError(f"{path}: not an armrt result, missing arrays {missing}")
            return cls(**{k: z[k] for k in cls.ARRAYS}, dof_names=[str(s) for s in z["dof_names"]],
                       element_names=[str(s) for s in z["element_names"]], integrator=str(z["integrator"]),
                       dt=float(z["dt"]), substeps=int(z["substeps"]) if "substeps" in z.files else 1,
                       model=str(z["model"]))


class Arm:
    """One simulated arm: the paper's fixed-scapula, 5-DOF, 102-element model.

    arm = Arm(model="das2", integrator="ros2", dt=1e-3)
    arm.set_excitation({"rotator_cuff": 0.05, "bicb": 0.3})
    result = arm.simulate(lambda t: {"elbow_flexors": 0.2 if t > 1 else 0.0}, duration=3.0)
    """

    def __init__(self, model: str = "das2", integrator: str = DEFAULT_INTEGRATOR, dt: float = 1e-3,
                 substeps: int | None = None):
        """dt is the control step (s: inputs held, outputs reported, TET measured per dt); fixed-step
        integrators take `substeps` steps of dt / substeps inside it. Default integrator: "ros2", the
        linearly implicit ROS2 with one step per 1 ms control step, within 0.1 deg of CVODE on the
        paper's tasks (docs/engine.md). Default substeps: enough for a step of at most
        DEFAULT_MAX_STEP[integrator] (ROS2 1 ms, ros2_adaptive 2 ms, RK4 0.17 ms, Euler 0.1 ms): one
        explicit RK4 step of 1 ms is not stable because the model's short-tendon elements are stiff at
        low activation. "ros2_adaptive" redoes a step as two halves when its error estimate is too
        large: for offline runs at dt = 2 ms, not for hard real time.

        Raises ValueError for an unknown integrator, a non-positive or non-finite dt, or substeps
        that is not a positive integer."""
        if integrator not in INTEGRATORS:
            raise ValueError(f"unknown integrator {integrator!r}; expected one of {INTEGRATORS}")
        dt = float(dt)
        if not (np.isfinite(dt) and dt > 0):
            raise ValueError(f"dt must be a positive number of seconds, got {dt}")
        if substeps is None:
            substeps = _core.default_substeps(integrator, dt)
        if int(substeps) != substeps or substeps < 1:
            raise ValueError(f"substeps must be a positive integer, got {substeps!r}")
        self._sim = _core.Simulator(model, integrator, dt, int(substeps))
        info = _core.model_info(model)
        self.model_name = info["name"]
        self.info = info
        self.dof_names = [d["name"] for d in info["dofs"]]
        self.dof_ranges = np.array([d["range"] for d in info["dofs"]])
        self.rest_posture = np.array([d["rest"] for d in info["dofs"]])
        self.element_names = [e["name"] for e in info["elements"]]
        self.muscle_names = [m for m, _ in info["muscles"]]
        self.group_names = [g for g, _ in info["groups"]]
        self._index: dict[str, list[int]] = {n: [i] for i, n in enumerate(self.element_names)}
        self._index.update({m: list(ix) for m, ix in info["muscles"]})
        self._index.update({g: list(ix) for g, ix in info["groups"]})
        self.n_elements = len(self.element_names)
        n = self.n_elements
        state = self._sim.state
        self._views = {"q": state[0:5], "qdot": state[5:10], "lce": state[10:10 + n], "activation": state[10 + n:10 + 2 * n]}
        for v in self._views.values():
            v.flags.writeable = False

    # ------------------------------------------------------------------ names
    def indices(self, name: str) -> list[int]:
        """Element indices of an element, muscle or group name."""
        try:
            return self._index[name]
        except KeyError:
            close = difflib.get_close_matches(name, list(self._index), n=3)
            hint = f"; did you mean {', '.join(repr(c) for c in close)}?" if close else ""
            raise KeyError(f"unknown element, muscle or group name {name!r}{hint}") from None

    def _per_element(self, values, what: str, lo: float, hi: float | None, clip: bool) -> np.ndarray:
        """Array of n from an array of n, a scalar or a {name: value} dict (names as in indices())."""
        n = self.n_elements
        if isinstance(values, Mapping):
            out = np.zeros(n) if what == "excitation" else self._current(what)
            for name, v in values.items():
                out[self.indices(name)] = self._scalar(v, f"{what}[{name!r}]")
        else:
            arr = np.asarray(values, dtype=float)
            if arr.ndim == 0:
                arr = np.full(n, float(arr))
            if arr.shape != (n,):
                raise ValueError(f"{what} must have shape ({n},) (one value per element), got {arr.shape}")
            out = arr.copy()
        bad = ~np.isfinite(out)
        if bad.any():
            names = [self.element_names[i] for i in np.flatnonzero(bad)[:5]]
            raise ValueError(f"{what} contains NaN or infinite values (elements {names})")
        hi_ = np.inf if hi is None else hi
        outside = (out < lo) | (out > hi_)
        if outside.any():
            names = [self.element_names[i] for i in np.flatnonzero(outside)[:5]]
            if not clip:
                raise ValueError(f"{what} must lie in [{lo}, {hi_}]; elements {names} do not")
            warnings.warn(f"{what} outside [{lo}, {hi_}] clipped for elements {names}", RuntimeWarning, stacklevel=3)
            out = np.clip(out, lo, hi_)
        return out

    @staticmethod
    def _scalar(v, what: str) -> float:
        try:
            return float(v)
        except (TypeError, ValueError):
            raise ValueError(f"{what} must be a number, got {v!r}") from None

    def _current(self, what: str) -> np.ndarray:
        return {"strength": self._sim.get_strength, "max_activation": self._sim.get_max_activation}[what]()

    # ------------------------------------------------------------------ inputs
    def set_excitation(self, u) -> None:
        """Neural excitation of the elements: an array of n, a scalar, or {name: value} with element,
        muscle or group names (unnamed elements get 0). Values outside [0, 1] are clipped with a
        RuntimeWarning; NaN or infinite values raise ValueError."""
        self._sim.excitation[:] = self._per_element(u, "excitation", 0.0, 1.0, clip=True)

    @property
    def excitation(self) -> np.ndarray:
        return self._sim.excitation.copy()

    def set_hand_load(self, force=(0.0, 0.0, 0.0), moment=(0.0, 0.0, 0.0)) -> None:
        """External force (N) at the hand point and moment (N m) on the hand, thorax frame
        (x lateral, y up, z posterior): e.g. a 1 kg weight is force=(0, -9.81, 0)."""
        for name, v, target in (("force", force, self._sim.hand_force), ("moment", moment, self._sim.hand_moment)):
            a = np.asarray(v, dtype=float)
            if a.shape != (3,):
                raise ValueError(f"hand {name} must have shape (3,), got {a.shape}")
            if not np.all(np.isfinite(a)):
                raise ValueError(f"hand {name} contains NaN or infinite values")
            target[:] = a

    @property
    def strength(self) -> np.ndarray:
        """Per-element strength scale (multiplies DAS3 fmax, 1 = intact)."""
        return self._sim.get_strength()

    @strength.setter
    def strength(self, values) -> None:
        s = self._per_element(values, "strength", 0.0, None, clip=False)
        self._sim.set_strength_and_max_activation(s, self._sim.get_max_activation())

    @property
    def max_activation(self) -> np.ndarray:
        """Per-element maximum activation in [0, 1] (0 = paralysed): excitations are capped at it."""
        return self._sim.get_max_activation()

    @max_activation.setter
    def max_activation(self, values) -> None:
        m = self._per_element(values, "max_activation", 0.0, 1.0, clip=False)
        self._sim.set_strength_and_max_activation(self._sim.get_strength(), m)

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
        """Back to a state: q (5, rad; default the rest posture), qdot (default 0), activations (n,
        default 0, or a dict of names); contractile elements start in static equilibrium."""
        q = None if q is None else self._dof_vector(q, "q")
        qdot = None if qdot is None else self._dof_vector(qdot, "qdot")
        if activation is not None:
            activation = self._per_element(activation, "excitation", 0.0, 1.0, clip=False)
        self._sim.clear_error()
        self._sim.reset(q, qdot, activation)
        self._sim.time = float(time)

    def _dof_vector(self, v, what: str) -> np.ndarray:
        if isinstance(v, Mapping):
            out = (self.rest_posture if what == "q" else np.zeros(5)).copy()
            for name, x in v.items():
                if name not in self.dof_names:
                    close = difflib.get_close_matches(name, self.dof_names, n=3)
                    raise KeyError(f"unknown DOF {name!r}" + (f"; did you mean {close}?" if close else f"; DOFs are {self.dof_names}"))
                out[self.dof_names.index(name)] = self._scalar(x, f"{what}[{name!r}]")
            v = out
        a = np.asarray(v, dtype=float)
        if a.shape != (5,):
            raise ValueError(f"{what} must have shape (5,) ({', '.join(self.dof_names)}), got {a.shape}")
        if not np.all(np.isfinite(a)):
            raise ValueError(f"{what} contains NaN or infinite values")
        return a

    # ------------------------------------------------------------------ stepping
    def step(self, n: int = 1) -> None:
        """Advances n steps with the current excitation and load (loop in C++, GIL released)."""
        n = int(n)
        if n < 0:
            raise ValueError(f"n must be >= 0, got {n}")
        try:
            self._sim.step(n)
        except RuntimeError as exc:
            raise SimulationError(f"{exc}; call reset() to continue") from None

    def simulate(self, excitation, duration: float, record_every: int = 1) -> Result:
        """Runs for `duration` seconds from the current state and returns the time series.

        excitation: a (T, n) array with one row per step (T = round(duration / dt)), an (n,) array,
        scalar or {name: value} dict held constant, or a callable f(t) -> any of those, evaluated at
        each step's start time before the loop (the loop itself runs in C++ without the GIL; for
        feedback control use step()).
        """
        duration = float(duration)
        if not (np.isfinite(duration) and duration >= 0):
            raise ValueError(f"duration must be a non-negative number of seconds, got {duration}")
        n_steps = int(round(duration / self.dt))
        n = self.n_elements
        if callable(excitation) and not isinstance(excitation, Mapping):
            times = self.time + self.dt * np.arange(n_steps)
            u = np.empty((max(n_steps, 1), n))
            for k, t in enumerate(times):
                u[k] = self._per_element(excitation(float(t)), "excitation", 0.0, 1.0, clip=True)
            if n_steps == 0:
                u[0] = self.excitation
        elif isinstance(excitation, np.ndarray) and excitation.ndim == 2:
            if excitation.shape != (n_steps, n):
                raise ValueError(f"excitation must have shape ({n_steps}, {n}) for {duration} s at dt = {self.dt} s, "
                                 f"got {excitation.shape}")
            u = np.asarray(excitation, dtype=float)
            if not np.all(np.isfinite(u)):
                row, col = np.argwhere(~np.isfinite(u))[0]
                raise ValueError(f"excitation contains NaN or infinite values (first at step {row}, "
                                 f"element {self.element_names[col]})")
            if (u < 0).any() or (u > 1).any():
                warnings.warn("excitation outside [0, 1] clipped", RuntimeWarning, stacklevel=2)
                u = np.clip(u, 0.0, 1.0)
        else:
            u = self._per_element(excitation, "excitation", 0.0, 1.0, clip=True)[None, :]
        try:
            raw = self._sim.simulate(np.ascontiguousarray(u), n_steps, int(record_every))
        except RuntimeError as exc:
            raise SimulationError(f"{exc}; call reset() to continue") from None
        raw.pop("steps")
        return Result(**raw, dof_names=list(self.dof_names), element_names=list(self.element_names),
                      integrator=self.integrator, dt=self.dt, substeps=self.substeps, model=self.model_name)

    # ------------------------------------------------------------------ outputs
    def outputs(self) -> dict:
        """Outputs at the current state: qddot, muscle_force (N), muscle_length (m), moment_arm
        (n x 5, m), fibre_velocity, torques, hand_position (thorax frame), gh_force (scapula frame),
        gh_theta, gh_phi, gh_stab."""
        self._sim.evaluate_outputs()
        return self._sim.outputs()

    @property
    def gh_stab(self) -> float:
        return self.outputs()["gh_stab"]

    @property
    def hand_position(self) -> np.ndarray:
        return self.outputs()["hand_position"]

    @property
    def tet(self) -> dict:
        """Task execution time statistics of the steps so far (ns): count, mean, min, max, last."""
        return self._sim.tet_stats()

    # ------------------------------------------------------------------ model at any pose
    def moment_arms(self, q) -> np.ndarray:
        """(n, 5) moment arms (m) at pose q: -dL/dq of the path polynomials."""
        return self._sim.muscle_paths(self._dof_vector(q, "q"))[1]

    def muscle_lengths(self, q) -> np.ndarray:
        """(n,) muscle-tendon lengths (m) at pose q."""
        return self._sim.muscle_paths(self._dof_vector(q, "q"))[0]

    def gh_directions(self, q) -> np.ndarray:
        """(n, 3) unit lines of action at GH (scapula frame); zero rows for elements not crossing GH."""
        return self._sim.gh_directions(self._dof_vector(q, "q"))

    def mass_matrix(self, q) -> np.ndarray:
        return self._sim.mass_matrix(self._dof_vector(q, "q"))

    def thorax_humerus_angles(self, q) -> np.ndarray:
        """Plane of elevation, elevation, axial rotation (rad) of the humerus relative to the thorax."""
        return self._sim.thorax_humerus_angles(self._dof_vector(q, "q"))

    def gh_stability(self, force) -> tuple[float, float, float]:
        """(theta, phi, GHstab) of a force of the humeral head on the glenoid (scapula frame, N)."""
        f = np.asarray(force, dtype=float)
        if f.shape != (3,) or not np.all(np.isfinite(f)):
            raise ValueError(f"force must be 3 finite values, got {force!r}")
        return self._sim.gh_stability(f)
