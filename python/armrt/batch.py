"""`ArmBatch`: n independent arms of one model stepped together in C++ across threads.

For sweeps, optimisation and vectorised environments. Each arm is an engine Arm, its own Data and Stepper on the shared Model (the
same code `Arm` drives), so every integrator `Arm` accepts works here, and each arm's trajectory is
bit-identical to stepping the same arm alone with `Arm`, whatever the number of threads.
"""
from __future__ import annotations

import os
import warnings
from typing import Mapping

import numpy as np

# OpenMP threads that finish early sleep instead of spinning (unless the user chose otherwise): on a
# machine shared with other work, or between the Python steps of a vector env, a spinning thread
# takes the core the next call or the main thread needs. libgomp reads this when _batch loads it.
os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")

from . import _batch, _core  # noqa: E402
from .arm import Arm, SimulationError  # noqa: E402
from .checks import applied_moments, count, each_row, hand_load_within, joint_range_rows, real_array  # noqa: E402
from .snapshot import StatePart, part_slices, signature  # noqa: E402

# The engine counts its arms in a C int.
MAX_ARMS = 2**31 - 1
# Outputs of the girdle stage, for models whose scapula moves (das3): as Arm.outputs() names them.
GIRDLE_OUTPUTS = ("girdle_torque", "contact_distance", "contact_force", "conoid_length", "conoid_tension")


def available_cores() -> int:
    """CPUs this process may run on (its affinity mask)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not Linux
        return os.cpu_count() or 1


def available_memory() -> int | None:
    """Bytes this process may still take (Linux: MemAvailable, within the cgroup's memory.max when
    that is lower), else the physical memory; None if unknown."""
    avail = None
    try:
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemAvailable:"):
                    avail = int(line.split()[1]) * 1024
                    break
    except (OSError, ValueError):
        pass
    if avail is None:
        try:
            avail = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
        except (AttributeError, ValueError, OSError):
            return None
    # In a container MemAvailable is the host's: the cgroup's limit is what the OOM killer enforces.
    try:
        with open("/sys/fs/cgroup/memory.max") as f:
            limit = f.read().strip()
        if limit != "max":
            with open("/sys/fs/cgroup/memory.current") as f:
                used = int(f.read())
            avail = min(avail, max(int(limit) - used, 0))
    except (OSError, ValueError):
        pass
    return avail


def check_batch_memory(n: int) -> None:
    """MemoryError, naming the bytes per arm and the total, if n arms do not fit in the memory available:
    the engine would otherwise fail with a bare std::bad_alloc, or have the process killed as it fills them."""
    per_arm = _batch.ARM_BYTES
    need = n * per_arm
    avail = available_memory()
    if avail is not None and need > avail:
        raise MemoryError(f"ArmBatch({n}) needs {per_arm} bytes per arm x {n} arms = {need / 1e9:.3g} GB, more than "
                          f"the {avail / 1e9:.3g} GB of memory available: at most {avail // per_arm} arms fit")


def default_threads() -> int:
    """OMP_NUM_THREADS when set to a positive integer (Ray sets it to a task's CPUs, so a batch inside
    a Ray task does not oversubscribe the node), else the cores available."""
    try:
        n = int(os.environ.get("OMP_NUM_THREADS", "").split(",")[0])
    except ValueError:
        n = 0
    return n if n > 0 else available_cores()


class ArmBatch:
    """n arms of one model, stepped in C++ on `threads` OpenMP threads with the GIL released.

    batch = ArmBatch(64, dt=1e-3)                 # integrator and substeps: Arm's defaults
    batch.reset(q=postures)                       # (64, dofs) rad, or (dofs,) for every arm
    batch.set_excitation(U)                       # (64, elements) in [0, 1]
    batch.step(100)                               # 100 control steps of every live arm
    batch.q, batch.gh_stab                        # (64, dofs) rad, (64,): zero-copy views

    State and outputs are read-only numpy views into the engine's memory: they follow the
    simulation without copies (copy them to keep a snapshot). Outputs (forces, hand position, GH
    force and stability) describe each arm's current state after step() and reset(); after a change
    between steps (set_hand_load, set_applied_moment, strength, max_activation, set_state_vector) the
    next read of an output evaluates them at the changed arms first (a view taken before it is updated
    in place). step(..., outputs=False) leaves them as they were until evaluate_outputs().

    An arm that diverges stops alone: step() returns its index, `diverged` marks it, `errors` says
    which state went bad and when, and a RuntimeWarning names it; the other arms go on. reset() that
    arm (reset(arms=[i])) to use it again.

    One Python thread at a time: step() releases the GIL while the arms run, so changing inputs
    from another thread meanwhile would race with the engine (as with Arm).
    """

    def __init__(self, n: int, model="das2", integrator: str | None = None, dt: float | None = None,
                 substeps: int | None = None, threads: int | None = None, stimulation=None):
        """n: number of arms (>= 1). model: a name, a model file or an armrt.Model, as for `Arm`.
        integrator, dt (control step, s) and substeps: as for `Arm`
        (None: Arm's defaults). threads: OpenMP threads for step() (None: OMP_NUM_THREADS if set,
        else the cores available).
        stimulation: one stimulation map for every arm, as for `Arm` (None, "per_muscle", "default", a file or
        a dict);
        commands per arm with set_stimulation, fatigue per arm and channel in `fatigue`.
        Raises ValueError for a bad n, integrator, dt, substeps, threads or stimulation map."""
        if int(n) != n or n < 1:
            raise ValueError(f"n must be a positive integer number of arms, got {n!r}")
        if n > MAX_ARMS:
            raise ValueError(f"n = {n} arms: at most {MAX_ARMS} (the engine counts arms in a C int)")
        check_batch_memory(int(n))
        kw = {k: v for k, v in (("integrator", integrator), ("dt", dt), ("substeps", substeps)) if v is not None}
        # A single Arm resolves the defaults and validates exactly as Arm does, and gives the names.
        self._arm = Arm(model=model, stimulation=stimulation, **kw)  # validates the map too
        a = self._arm
        # By name: the engine (libarmrt) has one registry, where Arm's model is already registered.
        self._raw = _batch.Batch(a.model_name, int(n), a.integrator, a.dt, a.substeps)
        self.n = int(n)
        self.model = a.model  # armrt.Model
        self.model_name = a.model_name
        self.info = a.info
        self.dof_names, self.element_names = list(a.dof_names), list(a.element_names)
        self.muscle_names, self.group_names = list(a.muscle_names), list(a.group_names)
        self.dof_ranges, self.rest_posture = a.dof_ranges.copy(), a.rest_posture.copy()
        self.n_dofs, self.n_elements = len(self.dof_names), a.n_elements
        self.threads = threads
        self._errors: dict[int, str] = {}
        state = self._raw.state
        # The state layout is the engine's (data.h), read from it: {block: (offset, size)}.
        views = {k: state[:, o:o + size] for k, (o, size) in self.info["state_layout"].items()}
        views["time"] = self._raw.time
        # Every output of forward() is a view, from the engine's table (layouts.h ARMRT_OUTPUTS).
        for name, _size, _unit, _stage, girdle_only, _doc in _core.output_rows():
            if not girdle_only or self.info["girdle"]:
                views[name] = self._raw.output_view(name)
        views["gh_theta"], views["gh_phi"] = views["gh_angles"][:, 0], views["gh_angles"][:, 1]
        for v in views.values():
            v.flags.writeable = False
        self._views = views
        self._excitation = self._raw.excitation
        self._hand_force, self._hand_moment = self._raw.hand_force, self._raw.hand_moment
        self._applied_moment = self._raw.applied_moment
        if stimulation is not None:
            self._raw.set_stimulation_map_json(self._arm._sim.stimulation_map_json())
        self.channel_names = self._arm.channel_names
        self._raw.reset(np.arange(self.n))  # outputs at the rest posture
        # True after an input, setting or state was changed between steps: the output views then describe the
        # arms before the change, and reading one (outputs(), gh_force, ...) evaluates them first, as
        # Arm.outputs() would at the changed arm.
        self._outputs_stale = False

    # ------------------------------------------------------------------ configuration
    @property
    def threads(self) -> int:
        """OpenMP threads used by step() (default: OMP_NUM_THREADS if set, else the cores available)."""
        return self._threads

    @threads.setter
    def threads(self, value) -> None:
        value = default_threads() if value is None else value
        if int(value) != value or value < 1:
            raise ValueError(f"threads must be a positive integer, got {value!r}")
        self._threads = int(value)

    @property
    def integrator(self) -> str:
        return self._raw.integrator

    @property
    def dt(self) -> float:
        """Control step (s)."""
        return self._raw.dt

    @property
    def substeps(self) -> int:
        return self._raw.substeps

    def indices(self, name: str) -> list[int]:
        """Element indices of an element, muscle or group name (as Arm.indices)."""
        return self._arm.indices(name)

    @property
    def max_joint_speed(self) -> float:
        """rad/s: a joint faster than this means the simulation diverged (the arm then stops)."""
        return float(self._arm._sim.max_joint_speed)

    @property
    def gh_stab_bound(self) -> float:
        """Largest GH stability the model can report: the force pointing away from the glenoid
        (angles of pi from its normal along both axes)."""
        return float((np.pi / self.info["rim_half_angle_major"]) ** 2 + (np.pi / self.info["rim_half_angle_minor"]) ** 2)

    def hand_position_at(self, q) -> np.ndarray:
        """(m, 3) hand positions (m, thorax frame) at postures q of shape (m, dofs) rad (kinematics only)."""
        q = np.atleast_2d(real_array(q, "q"))
        out = np.empty((len(q), 3))
        for k, qk in enumerate(q):
            self._arm.reset(q=qk)
            out[k] = self._arm.outputs()["hand_position"]
        return out

    # ------------------------------------------------------------------ inputs
    def _per_arm(self, values, what: str, lo: float, hi: float | None, clip: bool, current=None) -> np.ndarray:
        """(n, elements) from an (n, elements) array, or anything Arm accepts for one arm (an array
        of elements, a scalar, a {name: value} dict) applied to every arm."""
        ne = self.n_elements
        if isinstance(values, Mapping):
            # Overlapping names, for every setting given by names: the engine's one rule (names.h: the most
            # specific name wins, in any order; equal specificity takes the largest), as Arm.
            items = self._arm._named_items(values, what)
            for name, v in items:
                # Before the engine: NaN is the marker below for the elements no name covers.
                if not np.isfinite(v):
                    raise ValueError(f"{what}[{name!r}] must be finite, got {v!r}")
            # NaN marks the elements no name covers: they keep their current value (0 for an excitation).
            named = np.asarray(_core.values_from_names(self.model_name, items, np.full(ne, np.nan)))
            base = np.zeros((self.n, ne)) if current is None else current
            out = np.where(np.isnan(named)[None, :], base, named[None, :])
        else:
            arr = real_array(values, what)
            if arr.ndim <= 1:
                arr = np.broadcast_to(arr, (ne,)) if arr.ndim == 0 else arr
                if arr.shape != (ne,):
                    raise ValueError(f"{what} must have shape ({self.n}, {ne}) or ({ne},), got {arr.shape}")
                arr = np.broadcast_to(arr, (self.n, ne))
            if arr.shape != (self.n, ne):
                raise ValueError(f"{what} must have shape ({self.n}, {ne}) (arms, elements) or ({ne},), got {arr.shape}")
            out = np.array(arr, dtype=float)
        bad = ~np.isfinite(out)
        if bad.any():
            i, e = np.argwhere(bad)[0]
            raise ValueError(f"{what} contains NaN or infinite values (first: arm {i}, element {self.element_names[e]})")
        hi_ = np.inf if hi is None else hi
        outside = (out < lo) | (out > hi_)
        if outside.any():
            i, e = np.argwhere(outside)[0]
            if not clip:
                raise ValueError(f"{what} must lie in [{lo}, {hi_}]; arm {i}, element {self.element_names[e]} does not")
            warnings.warn(f"{what} outside [{lo}, {hi_}] clipped ({int(outside.sum())} values)", RuntimeWarning, stacklevel=3)
            np.clip(out, lo, hi_, out=out)
        return out

    def set_excitation(self, u) -> None:
        """Excitations: an (n, elements) array, or one arm's (elements,) array, scalar or {name: value}
        dict for every arm (overlapping names: as Arm.set_excitation). Values outside [0, 1] are clipped with a
        RuntimeWarning and values above an arm's max_activation capped at it (so `excitation` reads back what
        the dynamics use); NaN raises ValueError."""
        ne = self.n_elements
        arr = None if isinstance(u, Mapping) else real_array(u, "excitation")
        if arr is not None and arr.shape == (self.n, ne) and np.isfinite(arr).all() and arr.min() >= 0 and arr.max() <= 1:
            self._raw.set_excitation(arr)  # the common case, checked without a copy
            return
        # Stored as the dynamics use it, capped at each arm's max_activation (the engine's one cap rule, as Arm).
        self._raw.set_excitation(self._per_arm(u, "excitation", 0.0, 1.0, clip=True))

    @property
    def excitation(self) -> np.ndarray:
        """(n, elements) excitations now applied, as the dynamics use them (a copy)."""
        return np.array(self._excitation)

    def set_stimulation(self, values) -> None:
        """Stimulation commands: an (n, channels, 3) array of [pulse width s, amplitude A, frequency Hz], or
        what Arm.set_stimulation takes ({channel: (pw, amp, f)} or (channels, 3)) for every arm. Refused
        (ValueError naming the arm and channel, nothing written) beyond a channel's limits."""
        nc = len(self.channel_names)
        a = None if isinstance(values, Mapping) else real_array(values, "stimulation")
        if a is not None and a.shape == (self.n, nc, 3):
            cmd = a
        else:
            from .stimulation import commands
            one = commands(self._arm._sim, values, np.zeros((nc, 3)))
            if isinstance(values, Mapping):  # unnamed channels keep each arm's command
                cmd = self.stimulation.copy()
                named = [self.channel_names.index(k) for k in values]
                cmd[:, named] = one[named]
            else:
                cmd = np.broadcast_to(one, (self.n, nc, 3))
        self._raw.set_stimulation(np.ascontiguousarray(cmd, dtype=float).reshape(self.n, 3 * nc))

    def stimulation_map(self) -> dict:
        """The map every arm shares, with every default explicit (as Arm.stimulation_map(): channel names,
        kinds, elements and weights, limits in SI units, recruitment and Ding parameters); {} without a map."""
        return self._arm.stimulation_map()

    @property
    def stimulation(self) -> np.ndarray:
        """(n, channels, 3) held commands (a copy)."""
        return self._raw.get_snapshot(int(StatePart.STIMULATION)).reshape(self.n, -1, 3)

    @property
    def stimulation_state(self) -> np.ndarray:
        """(n, channels, armrt.stimulation.STATE_SIZE) each arm's chain memory, as Arm.stimulation_state (columns:
        armrt.stimulation.STATE_COLUMNS; a copy)."""
        return np.array(self._raw.stimulation_state)

    @property
    def fatigue(self) -> np.ndarray:
        """(n, channels): 1 - A/A_rest per arm and channel (docs/fes.md)."""
        from .stimulation import STATE_COLUMNS
        return 1.0 - self._raw.stimulation_state[:, :, STATE_COLUMNS["fatigue_A"]]

    def set_hand_load(self, force=(0.0, 0.0, 0.0), moment=(0.0, 0.0, 0.0)) -> None:
        """External force (N) at the hand and moment (N m) on it, thorax frame: (n, 3) or (3,) for every arm.
        ValueError for another shape, NaN or a load beyond Arm.set_hand_load's bound (checks.hand_load: 1e5 N,
        1e4 N m); TypeError for bools."""
        checked = []
        for name, v in (("force", force), ("moment", moment)):
            a = real_array(v, f"hand {name}", booleans=False)
            if a.shape not in ((3,), (self.n, 3)):
                raise ValueError(f"hand {name} must have shape ({self.n}, 3) or (3,), got {a.shape}")
            if not np.all(np.isfinite(a)):
                raise ValueError(f"hand {name} contains NaN or infinite values")
            hand_load_within(a, name)
            checked.append(a)
        self._hand_force[...], self._hand_moment[...] = checked
        self._outputs_stale = True

    def set_applied_moment(self, moment=0.0) -> None:
        """Generalised forces N m applied at the joints (as Arm.set_applied_moment): (n, ndof) per arm, (ndof,)
        or {dof name: value} for every arm, or 0. KeyError for an unknown DOF, ValueError for another shape or
        NaN/infinite values."""
        self._applied_moment[...] = applied_moments(moment, self._arm.model.dof_names, rows=self.n,
                                                     model_name=self._arm.model.name)
        self._outputs_stale = True

    @property
    def applied_moment(self) -> np.ndarray:
        """(n, ndof) N m applied at each arm's joints, a copy."""
        return np.array(self._applied_moment)

    @property
    def strength(self) -> np.ndarray:
        """(n, elements) strength scale (multiplies DAS3 fmax; 1 = intact). Set with (n, elements),
        (elements,), a scalar or a {name: value} dict (for every arm; unnamed elements unchanged)."""
        return self._raw.get_strength()

    @strength.setter
    def strength(self, values) -> None:
        s = self._per_arm(values, "strength", 0.0, None, clip=False, current=self.strength)
        self._raw.set_strength_and_max_activation(s, self._raw.get_max_activation())
        self._outputs_stale = True

    @property
    def max_activation(self) -> np.ndarray:
        """(n, elements) maximum activation in [0, 1] (0 = paralysed); set like `strength`."""
        return self._raw.get_max_activation()

    @max_activation.setter
    def max_activation(self, values) -> None:
        m = self._per_arm(values, "max_activation", 0.0, 1.0, clip=False, current=self.max_activation)
        self._raw.set_strength_and_max_activation(self._raw.get_strength(), m)
        self._outputs_stale = True

    # ------------------------------------------------------------------ state
    def _arms(self, arms) -> np.ndarray:
        if arms is None:
            return np.arange(self.n)
        a = np.asarray(arms)
        if a.dtype == bool:
            if a.shape != (self.n,):
                raise ValueError(f"a boolean arm mask must have shape ({self.n},), got {a.shape}")
            return np.flatnonzero(a)
        a = np.atleast_1d(a)
        # astype would truncate 1.5 to arm 1; an empty list is float64 to numpy and selects nothing.
        if a.dtype.kind not in "iu" and a.size:
            raise TypeError(f"arm indices must be integers (or a boolean mask), got {arms!r}")
        a = a.astype(np.int64)
        if a.ndim != 1 or ((a < 0) | (a >= self.n)).any():
            raise IndexError(f"arm indices must be in [0, {self.n}), got {arms!r}")
        return a

    def _rows(self, v, m: int, width: int, what: str):
        if v is None:
            return None
        a = real_array(v, what)
        if a.shape == (width,):
            a = np.broadcast_to(a, (m, width))
        if a.shape != (m, width):
            raise ValueError(f"{what} must have shape ({m}, {width}) (one row per arm reset) or ({width},), got {a.shape}")
        if not np.all(np.isfinite(a)):
            raise ValueError(f"{what} contains NaN or infinite values")
        return np.ascontiguousarray(a)

    def reset(self, q=None, qdot=None, activation=None, arms=None) -> None:
        """Resets the arms `arms` (indices or a boolean mask; None: all) to a state at time 0 and
        clears their errors. q: (m, dofs) rad, one posture per reset arm, or (dofs,) for all
        (default: rest posture); qdot likewise (default 0); activation (m, elements) or (elements,)
        in [0, 1] (default 0). Contractile elements start in static equilibrium."""
        idx = self._arms(arms)
        m = len(idx)
        q = self._rows(q, m, self.n_dofs, "q")
        qdot = self._rows(qdot, m, self.n_dofs, "qdot")
        act = self._rows(activation, m, self.n_elements, "activation")
        if act is not None and ((act < 0) | (act > 1)).any():
            raise ValueError("activation must lie in [0, 1]")
        if q is not None:
            # As Arm.reset: a posture far beyond the joint ranges (degrees, say) diverges at the first step.
            def label(r):
                return f"arm {idx[r]}"
            joint_range_rows(q, self.dof_names, self.dof_ranges, label)
            if self.model.base_body == "thorax":  # Arm.reset's girdle contact check (das3), row by row
                each_row(self._arm._check_girdle_contact, q, range(m), label)
        self._raw.reset(idx, q, qdot, act)
        for i in idx:
            self._errors.pop(int(i), None)

    def get_state_vector(self, parts=StatePart.FULL) -> np.ndarray:
        """(n, size) the parts of every arm's state selected by `parts` (armrt.StatePart, OR-able, or a part
        name), one row per arm laid out as Arm.get_state_vector(parts)."""
        return self._raw.get_snapshot(signature(parts))

    def set_state_vector(self, x, parts=StatePart.FULL, arms=None) -> None:
        """Sets the parts selected by `parts` of the arms `arms` (indices or a boolean mask; None: all) from
        x (m, size), one row per selected arm, or (size,) for all of them; the other parts are kept. Every
        row is checked in the engine as Arm.set_state_vector checks one before any is written (ValueError
        naming the arm and the value). Clears the arms' errors."""
        sig = signature(parts)
        idx = self._arms(arms)
        size = self._raw.snapshot_size(sig)
        rows = self._rows(x, len(idx), size, "state vector")
        if rows is None:
            raise ValueError("state vector: expected an array, got None")
        self._raw.set_snapshot(sig, idx, rows)
        self._outputs_stale = True
        for i in idx:
            self._errors.pop(int(i), None)

    def state_vector_slices(self, parts=StatePart.FULL) -> dict:
        """{part name: slice} of a row of get_state_vector(parts)."""
        return part_slices(self._raw, parts)

    # ------------------------------------------------------------------ stepping
    def step(self, k: int = 1, outputs: bool = True, warn: bool = True) -> np.ndarray:
        """Advances every live arm by k control steps (threads in C++, GIL released). Returns the
        indices of the arms that diverged during this call (each is also in `errors` and, with
        `warn`, named in a RuntimeWarning); they stay where they stopped until reset. With
        outputs=False the output views are left as they were (saves one state-derivative
        evaluation per arm and call; evaluate_outputs() brings them up to date)."""
        k = count(k, "k (number of steps)")
        failed = self._raw.step(k, self._threads, bool(outputs))
        if outputs:
            self._outputs_stale = False
        for i in failed:
            msg = self._raw.error_message(int(i))
            self._errors[int(i)] = msg
            if warn:
                warnings.warn(f"arm {int(i)}: {msg}; the other arms go on (reset(arms=[{int(i)}]) to reuse it)",
                              RuntimeWarning, stacklevel=2)
        return failed

    def evaluate_outputs(self) -> None:
        """Outputs of every live arm at its current state (after step(..., outputs=False))."""
        self._raw.evaluate_outputs(self._threads)
        self._outputs_stale = False

    def _output(self, name: str) -> np.ndarray:
        """The view of output `name`, evaluated first if an input, setting or state changed since the last
        evaluation (not after step(..., outputs=False), whose caller chose to leave them)."""
        if self._outputs_stale:
            self.evaluate_outputs()
        return self._views[name]

    def outputs(self) -> dict:
        """Copies of the outputs at each arm's current state (as Arm.outputs(), one row per arm):
        qddot (n, dofs), muscle_force and muscle_length (n, elements), hand_position and gh_force
        (n, 3), gh_theta, gh_phi, gh_stab, gh_rim_margin, gh_rim_direction (n,); for a model whose scapula moves (das3) also girdle_torque
        (n, dofs) N m, contact_distance and contact_force (n, contact points: TS, AI) m and N, conoid_length
        (n,) m and conoid_tension (n,) N. Rows of diverged arms are as they stopped."""
        return {k: np.array(self._output(k)) for k in ("qddot", "muscle_force", "muscle_length", "hand_position",
                                                      "gh_force", "gh_theta", "gh_phi", "gh_stab",
                                                      "gh_rim_margin", "gh_rim_direction")
                + (GIRDLE_OUTPUTS if self.info["girdle"] else ())}

    @property
    def diverged(self) -> np.ndarray:
        """(n,) bool: arms stopped by divergence (until reset)."""
        return self._raw.status() != 0

    @property
    def errors(self) -> dict[int, str]:
        """{arm index: what diverged and when} for the arms stopped by divergence."""
        return dict(self._errors)

    def raise_if_diverged(self) -> None:
        """Raises SimulationError naming every diverged arm."""
        if self._errors:
            raise SimulationError("; ".join(f"arm {i}: {m}" for i, m in sorted(self._errors.items())))

    # ------------------------------------------------------------------ state and output views
    q = property(lambda self: self._views["q"], doc="(n, dofs) joint angles, rad (read-only view)")
    qdot = property(lambda self: self._views["qdot"], doc="(n, dofs) joint velocities, rad/s")
    lce = property(lambda self: self._views["lce"], doc="(n, elements) contractile-element lengths, m")
    activation = property(lambda self: self._views["activation"], doc="(n, elements) activations")
    time = property(lambda self: self._views["time"], doc="(n,) simulated time of each arm, s")
    hand_position = property(lambda self: self._output("hand_position"), doc="(n, 3) m, thorax frame")
    gh_force = property(lambda self: self._output("gh_force"), doc="(n, 3) N, humeral head on glenoid, scapula frame")
    gh_stab = property(lambda self: self._output("gh_stab"), doc="(n,) GH stability; > 1: dislocating")
    gh_theta = property(lambda self: self._output("gh_theta"), doc="(n,) rad, GH force from the glenoid normal, major axis")
    gh_phi = property(lambda self: self._output("gh_phi"), doc="(n,) rad, minor axis")
    gh_rim_margin = property(lambda self: self._output("gh_rim_margin"),
                             doc="(n,) rad, how far the GH force can still turn towards the rim; < 0 beyond it")
    gh_rim_direction = property(lambda self: self._output("gh_rim_direction"),
                                doc="(n,) rad, psi = atan2(phi, theta): 0 superior, pi/2 anterior")
    muscle_force = property(lambda self: self._output("muscle_force"), doc="(n, elements) N, tendon forces")
    muscle_length = property(lambda self: self._output("muscle_length"), doc="(n, elements) m, muscle-tendon lengths")
    qddot = property(lambda self: self._output("qddot"), doc="(n, dofs) rad/s^2")

    def _girdle_view(self, name: str) -> np.ndarray:
        if name not in self._views:
            raise AttributeError(f"ArmBatch.{name}: model {self.info['name']} has no moving girdle "
                                 "(the girdle outputs are for models whose scapula moves, such as das3)")
        return self._output(name)

    girdle_torque = property(lambda self: self._girdle_view("girdle_torque"),
                             doc="(n, dofs) N m, generalised forces of the thorax contact and the conoid (das3)")
    contact_distance = property(lambda self: self._girdle_view("contact_distance"),
                                doc="(n, contact points) m, signed distance of TS, AI from the thorax surface, "
                                    "negative inside (das3)")
    contact_force = property(lambda self: self._girdle_view("contact_force"),
                             doc="(n, contact points) N, magnitude of each contact force (das3)")
    conoid_length = property(lambda self: self._girdle_view("conoid_length"), doc="(n,) m, conoid ligament (das3)")
    conoid_tension = property(lambda self: self._girdle_view("conoid_tension"), doc="(n,) N, conoid tension (das3)")

    def __len__(self) -> int:
        return self.n

    def __repr__(self) -> str:
        return (f"ArmBatch(n={self.n}, model={self.model_name!r}, integrator={self.integrator!r}, dt={self.dt}, "
                f"substeps={self.substeps}, threads={self.threads})")
