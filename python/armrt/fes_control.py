"""Reference FES controllers (issue 28 item 5; docs/control.md "Reference FES controllers"): joint angles and speeds
in -> a stimulation command per channel out (pulse width at a held amplitude and frequency, docs/fes.md).

Each controller is an object with dataclass parameters and state and one contract,
``update(t, q, qdot) -> (channels, 3)`` (pulse width s, amplitude A, frequency Hz per channel, the order of
``Arm.channel_names``), so the same object drives an offline ``Arm`` (``run_offline``) and a real-time runner over
UDP (``UdpClient.send_stimulation``, examples/fes_controllers_udp.py).

- ``FeedforwardPID``: Blana, Kirsch & Chadwick 2009 (Med Biol Eng Comput 47:533) -- an inverse model of the arm
  gives the activations the reference movement needs (here static optimisation, ``armrt.StaticOptimizer``, in place
  of their neural network) and a PID on the joint angles corrects it through the same inverse model. With
  ``gh_stab_max`` the inverse model keeps the GH force inside the glenoid polygon: posture holding with GHstab under a
  limit (item (c)).
- ``PDController``: Jagodnik & van den Bogert 2010 (J Biomech 43:1086) -- proportional-derivative feedback from the
  joint angles straight to the muscles' stimulation, with two gains (their smallest controller); the gains are
  optimised by ``armrt.fes_controllers_validation optimise-pd``.
- ``StimulationCoding``: the lab's calibration behind both: a muscle activation level -> the pulse width that gives
  it at the held amplitude and frequency (the recruitment law inverted, docs/fes.md "Recruitment", times the rested
  fused force level measured on the arm).
"""
from __future__ import annotations

import math
import time as _time
import warnings
from dataclasses import dataclass, field

import numpy as np

from .arm import Arm
from .checks import applied_moments, dof_vector, joint_range, joint_speed_within, real_array, real_scalar
from .control import _INF, StaticOptimizer, _hand_load, _state, check_gh_stab_max

#: Implanted-system coding (docs/fes.md): pulse width modulated at a held 20 mA (the intramuscular channels'
#: saturation and the NNP device maximum) and 20 Hz, the lowest rate at which Ding 2003's force fuses (ripple 1.6 %).
AMPLITUDE_A = 0.020
FREQUENCY_HZ = 20.0
CONTROL_INTERVAL_S = 0.01  # s: 100 Hz, as examples/fes_elbow_hold_pi.py and Thelen 2003's 10 ms
#: Activation step of the channel optimiser's secant slopes (ChannelStaticOptimizer).
SECANT = 0.02


def minimum_jerk(q0, q1, t0: float, duration: float, t) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Flash & Hogan 1985 minimum-jerk movement from q0 to q1 (ndof,) rad starting at t0 s and lasting duration s,
    at times t (T,) s (held at q0 before t0 and at q1 after): (q, qdot, qddot), each (T, ndof). ValueError for a
    NaN or infinite input (np.clip would carry a NaN time or start through as a NaN posture) or duration <= 0."""
    q0, q1 = real_array(q0, "q0").ravel(), real_array(q1, "q1").ravel()
    if q0.shape != q1.shape:
        raise ValueError(f"q0 and q1 must have the same shape, got {q0.shape} and {q1.shape}")
    duration, t0 = real_scalar(duration, "duration"), real_scalar(t0, "t0")
    if not (np.isfinite(duration) and duration > 0):
        raise ValueError(f"duration must be finite and > 0 s, got {duration}")
    t = np.atleast_1d(real_array(t, "t"))
    for name, v in (("q0", q0), ("q1", q1), ("t0", t0), ("t", t)):
        if not np.all(np.isfinite(v)):
            raise ValueError(f"{name} must be finite, got {v if np.ndim(v) == 0 else v[~np.isfinite(v)][:3]}")
    s = np.clip((t - t0) / duration, 0.0, 1.0)[:, None]
    d = (q1 - q0)[None, :]
    pos = 10 * s ** 3 - 15 * s ** 4 + 6 * s ** 5
    vel = (30 * s ** 2 - 60 * s ** 3 + 30 * s ** 4) / duration
    acc = (60 * s - 180 * s ** 2 + 120 * s ** 3) / duration ** 2
    return q0[None, :] + d * pos, d * vel, d * acc


class Reference:
    """A reference movement: q(t) (ndof,) rad with its speed and acceleration, from samples (time (T,) s, q (T, ndof))
    by a cubic spline (as track_motion), held at its ends. ValueError for a bad motion (control_motion.check_motion)."""

    def __init__(self, time, q, model):
        from scipy.interpolate import CubicSpline  # noqa: PLC0415 (scipy is a dependency)

        from .control_motion import check_motion  # noqa: PLC0415
        time, q = real_array(time, "time"), real_array(q, "q_ref")
        check_motion(model, q, time, "q_ref", 4)
        self.time, self.q_samples = time.copy(), q.copy()
        self._s = CubicSpline(time, q, axis=0)
        self._v, self._a = self._s.derivative(1), self._s.derivative(2)

    def __call__(self, t: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(q, qdot, qddot) at t s; before the first sample and after the last, the end posture at rest."""
        if t <= self.time[0]:
            return self.q_samples[0].copy(), np.zeros(self.q_samples.shape[1]), np.zeros(self.q_samples.shape[1])
        if t >= self.time[-1]:
            return self.q_samples[-1].copy(), np.zeros(self.q_samples.shape[1]), np.zeros(self.q_samples.shape[1])
        return self._s(t), self._v(t), self._a(t)


# ------------------------------------------------------------------------------------------ stimulation coding
@dataclass
class StimulationCoding:
    """activation level per channel -> (channels, 3) command: the pulse width that recruits level / fused of the
    channel's fibres at the held amplitude and frequency (docs/fes.md: Weiss-Lapicque strength-duration, Veltink
    1992 threshold-saturation ramp, inverted), so that the Ding 2003 force level of the rested channel is `level`.

    channel_names (C,); element_index: per channel the element indices it reaches and weights (its map entries);
    threshold_A, saturation_A, reference_pulse_width_s, chronaxie_s, max_pulse_width_s, max_charge_C: (C,) from the
    map; fused (C,): the rested channel's steady force level at frequency_Hz with full recruitment, measured on the
    arm (steady_force_level); element_names (n,): the arm's elements (from_arm fills them; they fix the shape
    `levels` accepts and name the elements in its errors).

    Every per-channel input (recruitment, pulse_width, command) is (C,) or one number for every channel, and each
    refuses a wrong shape or a NaN/infinite value with a ValueError naming the input and the channels (a NaN
    would otherwise code as zero stimulation, hiding a failed controller), and a non-number with a TypeError."""
    channel_names: list
    element_index: list
    weights: list
    threshold_A: np.ndarray
    saturation_A: np.ndarray
    reference_pulse_width_s: np.ndarray
    chronaxie_s: np.ndarray
    max_pulse_width_s: np.ndarray
    max_charge_C: np.ndarray
    fused: np.ndarray
    amplitude_A: float = AMPLITUDE_A
    frequency_Hz: float = FREQUENCY_HZ
    element_names: list = field(default_factory=list)

    @classmethod
    def from_arm(cls, arm, amplitude_A: float = AMPLITUDE_A, frequency_Hz: float = FREQUENCY_HZ) -> "StimulationCoding":
        """The coding of `arm`'s stimulation map (Arm.stimulation_map(), every default filled in). ValueError for an
        arm without a map, an amplitude beyond a channel's limit or one that cannot reach saturation."""
        if not arm.channel_names:
            raise ValueError("StimulationCoding needs an arm with a stimulation map (Arm(..., stimulation=...))")
        amplitude_A = real_scalar(amplitude_A, "amplitude_A")
        frequency_Hz = real_scalar(frequency_Hz, "frequency_Hz")
        m = arm.stimulation_map()
        names, idx, w = [], [], []
        cols = {k: [] for k in ("threshold_A", "saturation_A", "reference_pulse_width_s", "chronaxie_s",
                                "max_pulse_width_s", "max_charge_C")}
        for ch in m["channels"]:
            names.append(ch["name"])
            ii, ww = [], []
            for el, weight in ch["elements"].items():
                for i in arm.indices(el):
                    ii.append(i)
                    ww.append(float(weight))
            idx.append(np.array(ii, int))
            w.append(np.array(ww))
            rec, lim = ch["recruitment"], ch["limits"]
            for k in ("threshold_A", "saturation_A", "reference_pulse_width_s", "chronaxie_s"):
                cols[k].append(float(rec[k]))
            cols["max_pulse_width_s"].append(float(lim["max_pulse_width_s"]))
            cols["max_charge_C"].append(float(lim["max_charge_C"]))
            if amplitude_A > float(lim["max_amplitude_A"]) or frequency_Hz > float(lim["max_frequency_Hz"]) \
                    or amplitude_A <= 0 or frequency_Hz <= 0:
                raise ValueError(f"channel {ch['name']!r}: amplitude {amplitude_A} A / frequency {frequency_Hz} Hz "
                                 f"outside (0, {lim['max_amplitude_A']}] A / (0, {lim['max_frequency_Hz']}] Hz")
        c = {k: np.array(v) for k, v in cols.items()}
        coding = cls(names, idx, w, fused=np.ones(len(names)), amplitude_A=amplitude_A, frequency_Hz=frequency_Hz,
                     element_names=list(arm.element_names), **c)
        if np.any(coding.pulse_width(np.ones(len(names)) * 1.0, clip=False) > c["max_pulse_width_s"] + 1e-15):
            bad = [n for n, p, mx in zip(names, coding.pulse_width(np.ones(len(names)), clip=False),
                                         c["max_pulse_width_s"]) if p > mx]
            raise ValueError(f"at {amplitude_A} A the channels {bad} cannot reach saturation within their pulse-width "
                             "limit: raise the amplitude")
        coding.fused = steady_force_level(arm, amplitude_A, frequency_Hz, coding.pulse_width(np.ones(len(names))))
        return coding

    def _per_channel(self, values, what: str) -> np.ndarray:
        """values as a (C,) float array (one number: the same for every channel); TypeError for non-numbers,
        ValueError for another shape or NaN/infinite values, naming `what` and the channels."""
        a = real_array(values, what)
        C = len(self.channel_names)
        if a.ndim == 0:
            a = np.full(C, float(a))
        if a.shape != (C,):
            raise ValueError(f"{what} must have shape ({C},) (one value per channel) or be one number, got {a.shape}")
        bad = ~np.isfinite(a)
        if bad.any():
            raise ValueError(f"{what} contains NaN or infinite values (channels "
                             f"{[self.channel_names[k] for k in np.flatnonzero(bad)[:5]]})")
        return a

    def _clipped_unit(self, a: np.ndarray, what: str, names, stacklevel: int = 3) -> np.ndarray:
        """a clipped to [0, 1], with one RuntimeWarning naming the first names outside (as Arm's excitations:
        checks.per_element); stacklevel 3 points at the caller of the public method."""
        outside = (a < 0) | (a > 1)
        if outside.any():
            warnings.warn(f"{what} outside [0, 1] clipped for {[names[k] for k in np.flatnonzero(outside)[:5]]}",
                          RuntimeWarning, stacklevel=stacklevel)
        return np.clip(a, 0.0, 1.0)

    def recruitment(self, pulse_width_s) -> np.ndarray:
        """(C,) the recruited fraction R of each channel at pulse_width_s (C,) s (or one number for all) and the held
        amplitude (docs/fes.md). ValueError for a wrong shape or a NaN, infinite or negative pulse width, TypeError
        for non-numbers."""
        pw = self._per_channel(pulse_width_s, "pulse_width_s")
        if (pw < 0).any():
            raise ValueError(f"pulse_width_s must be >= 0 s; channels "
                             f"{[self.channel_names[k] for k in np.flatnonzero(pw < 0)[:5]]} are negative")
        c, pref = self.chronaxie_s, self.reference_pulse_width_s
        with np.errstate(divide="ignore", invalid="ignore"):
            i_eff = np.where(pw > 0, self.amplitude_A * (1 + c / pref) / (1 + c / np.where(pw > 0, pw, 1.0)), 0.0)
        return np.clip((i_eff - self.threshold_A) / (self.saturation_A - self.threshold_A), 0.0, 1.0) * (pw > 0)

    def pulse_width(self, recruitment, clip: bool = True) -> np.ndarray:
        """(C,) s: the pulse width that recruits `recruitment` (C,) in [0, 1] (or one number for all) at the held
        amplitude (0 for none); clip: within each channel's pulse-width and charge limits. Values outside [0, 1] are
        clipped with one RuntimeWarning; ValueError for a wrong shape or NaN/infinite values, TypeError for
        non-numbers."""
        r = self._clipped_unit(self._per_channel(recruitment, "recruitment"), "recruitment", self.channel_names)
        i_eff = self.threshold_A + r * (self.saturation_A - self.threshold_A)
        c, pref = self.chronaxie_s, self.reference_pulse_width_s
        den = self.amplitude_A * (1 + c / pref) / i_eff - 1.0
        with np.errstate(divide="ignore"):
            pw = np.where(den > 0, c / np.where(den > 0, den, 1.0), np.inf)
        pw = np.where(r > 0, pw, 0.0)
        if clip:
            pw = np.minimum(pw, np.minimum(self.max_pulse_width_s, self.max_charge_C / self.amplitude_A))
        return pw

    def levels(self, activation) -> np.ndarray:
        """(C,): per channel the level Σ w a / Σ w² over the elements it reaches (least squares: one channel drives
        its elements together, each to w times its level), from element activations (n,) in [0, 1] (or one number
        for all; n the arm's element count, element_names). Values outside [0, 1] are clipped with one
        RuntimeWarning (as Arm's excitations); ValueError for a wrong shape or NaN/infinite values (naming the
        elements), TypeError for non-numbers."""
        a = real_array(activation, "activation")
        n = len(self.element_names) if self.element_names else \
            1 + max((int(i.max()) for i in self.element_index if i.size), default=-1)
        names = self.element_names or [f"element {i}" for i in range(n)]
        if a.ndim == 0:
            a = np.full(n, float(a))
        if a.shape != (n,):
            raise ValueError(f"activation must have shape ({n},) (one value per element) or be one number, "
                             f"got {a.shape}")
        bad = ~np.isfinite(a)
        if bad.any():
            raise ValueError(f"activation contains NaN or infinite values (elements "
                             f"{[names[i] for i in np.flatnonzero(bad)[:5]]})")
        a = self._clipped_unit(a, "activation", names)
        return np.array([float(w @ a[i]) / float(w @ w) for i, w in zip(self.element_index, self.weights)])

    def command(self, levels) -> np.ndarray:
        """(C, 3) stimulation command (pulse width s, amplitude A, frequency Hz per channel) for force levels (C,) in
        [0, 1] (or one number for all): recruitment level / fused, clipped to [0, 1] (a level above the channel's
        fused level saturates it). Levels outside [0, 1] are clipped with one RuntimeWarning; ValueError for a wrong
        shape or NaN/infinite values (naming the channels), TypeError for non-numbers."""
        lv = self._clipped_unit(self._per_channel(levels, "levels"), "levels", self.channel_names)
        pw = self.pulse_width(np.clip(lv / self.fused, 0.0, 1.0))
        out = np.empty((len(self.channel_names), 3))
        out[:, 0], out[:, 1], out[:, 2] = pw, self.amplitude_A, self.frequency_Hz
        return out


def steady_force_level(arm, amplitude_A: float, frequency_Hz: float, pulse_width_s, duration: float = 1.0,
                       average: float = 0.3) -> np.ndarray:
    """(C,) each channel's mean Ding force level over the last `average` s of `duration` s of stimulation at
    (pulse_width_s (C,), amplitude_A, frequency_Hz), from rest, without fatigue: measured on a fresh arm of the same
    model and map (the calibration a lab makes before a trial)."""
    from .arm import Arm  # noqa: PLC0415 (arm imports control)
    m = dict(arm.stimulation_map())
    m["fatigue"] = False
    probe = Arm(arm.model, stimulation=m)
    probe.reset(q=arm.rest_posture)
    names = probe.channel_names
    pw = np.asarray(pulse_width_s, float)
    probe.set_stimulation({c: (float(pw[k]), amplitude_A, frequency_Hz) for k, c in enumerate(names)})
    n_total, n_avg = int(round(duration / probe.dt)), int(round(average / probe.dt))
    probe.step(n_total - n_avg)
    acc = np.zeros(len(names))
    for _ in range(n_avg):
        probe.step(1)
        fl = probe.force_level
        acc += [fl[c] for c in names]
    return acc / n_avg


def chain_time_constant(arm, coding: StimulationCoding, level: float = 0.3, duration: float = 0.6) -> float:
    """s: the time the rested force level of the arm's first channel takes to reach 1 - 1/e of its final value after
    a step of its command from 0 to `level` (coding.command), without fatigue, on a fresh arm of the same map: the
    lag of stimulation -> activation (Ding 2003's calcium and force dynamics) a controller has to lead."""
    from .arm import Arm  # noqa: PLC0415
    m = dict(arm.stimulation_map())
    m["fatigue"] = False
    probe = Arm(arm.model, stimulation=m)
    probe.reset(q=arm.rest_posture)
    probe.set_stimulation(coding.command(np.full(len(coding.channel_names), float(level))))
    name = probe.channel_names[0]
    n = int(round(duration / probe.dt))
    t, f = np.empty(n), np.empty(n)
    for k in range(n):
        probe.step(1)
        t[k], f[k] = probe.time, probe.force_level[name]
    final = f[-int(0.1 / probe.dt):].mean()
    return float(t[np.argmax(f >= (1 - math.exp(-1)) * final)])


def model_arm(arm):
    """The controller's model of the plant `arm`: an Arm of the same model with its strength, gravity and hand load
    as the controller knows them at the start, no stimulation map (the inverse model solves for activations), and
    each reached element's max_activation lowered to what its channels give at most (their fused level times
    their weight), so that the inverse model asks nothing stimulation cannot give."""
    from .arm import Arm  # noqa: PLC0415
    m = Arm(arm.model, integrator=arm.integrator, dt=arm.dt)
    m.strength = arm.strength
    m.max_activation = arm.max_activation
    m._sim.gravity = np.array(arm._sim.gravity)
    m.set_hand_load(np.array(arm._sim.hand_force), np.array(arm._sim.hand_moment))
    return m


# ------------------------------------------------------------------------------------------ inverse model
class ChannelStaticOptimizer(StaticOptimizer):
    """Static optimisation in the stimulator's channel space: the levels (C,) of the channels, each driving its
    elements together (element activation min(max_activation, w level), as the engine's stimulation stage), that
    supply the moments of inverse dynamics with the least sum of squared levels; GHstab <= gh_stab_max as
    StaticOptimizer's polygon. Element-wise static optimisation (StaticOptimizer) would ask elements of one
    muscle for different activations that one electrode cannot give. Sequential QP on the elastic-tendon model
    (steady_forces, slopes as secants) with free moment residuals weighted 1e4 above the levels (StaticOptimizer's
    slack form), so an infeasible posture returns the closest levels (feasible False) instead of failing mid-trial.
    solve_levels(q, qdot, qddot) -> (levels (C,), StaticOptimizationResult of their element activations)."""

    def __init__(self, model, coding, gh_stab_max=None, iterations: int = 6):
        # Its own SQP in the channels' space (solve_levels), on the Python path's muscle model and result builder.
        super().__init__(model, gh_stab_max=gh_stab_max, backend="python")
        n, C = model.n_elements, len(coding.channel_names)
        S = np.zeros((n, C))
        for c, (i, w) in enumerate(zip(coding.element_index, coding.weights)):
            S[i, c] = w
        self.S, self.coding, self.iterations = S, coding, int(iterations)
        amax = np.asarray(model.max_activation, float)
        # A channel's level goes at most to its fused force level, and to the lowest cap of its elements
        # (max_activation / weight): within it no element saturates, so the moments are smooth in the levels.
        # Above it the elements with higher caps could still give more (brachialis: caps 0.12-0.19 in
        # participant_A_FES); a Jacobian switching as elements saturate made the SQP cycle between two points.
        self.level_max = np.minimum(coding.fused, np.array([float(np.min(amax[i] / w)) for i, w in
                                                            zip(coding.element_index, coding.weights)]))
        self.last_levels = np.zeros(C)
        self.reached = S.sum(axis=1) > 0

    def solve_levels(self, q, qdot, qddot):
        """(levels (C,), StaticOptimizationResult of the element activations they give)."""
        from proxsuite import proxqp  # noqa: PLC0415 (a dependency, imported where the solver runs, as control.py)
        model, sim = self.model, self._sim
        q, qd, qdd = _state(model, q, qdot, qddot)
        idyn = sim.inverse_dynamics(q, qd, qdd, np.array(sim.hand_force), np.array(sim.hand_moment))
        tau_req = idyn["tau_muscle"]
        L, R = sim.muscle_paths(q)
        v = np.ascontiguousarray(-(R @ qd))
        P = self._axes @ sim.gh_directions(q).T
        f0 = self._axes @ idyn["gh_force_without_muscles"]
        amax = np.asarray(sim.get_max_activation(), float)
        self._rigid = sim.rigid_tendon_forces(L, v)
        if self._lce_guess is None or self._last_L is None or np.abs(L - self._last_L).max() > 0.01:
            self._lce_guess = self._rigid[0].copy()
        self._last_L = L
        C, nq = self.S.shape[1], model.n_dofs
        n_in = self._gh_rows.shape[0]
        lv = np.clip(self.last_levels, 0.0, self.level_max)
        H = np.zeros((C + nq, C + nq))
        H[np.arange(C), np.arange(C)] = 2e-4
        H[np.arange(C, C + nq), np.arange(C, C + nq)] = 2.0
        g = np.zeros(C + nq)
        lbox = np.concatenate([np.zeros(C), -_INF * np.ones(nq)])
        ubox = np.concatenate([self.level_max, _INF * np.ones(nq)])
        it = 0
        for it in range(1, self.iterations + 1):
            a = np.minimum(self.S @ lv, amax)
            lce, F, _ = self._forces(L, v, a)
            # Slopes as secants over +SECANT in activation: at a = 0 the element's tangent is ~0 (the damper's
            # low-activation floor, muscle.cc), which would keep an unused channel unused for good.
            guess = self._lce_guess
            _, F_hi, _ = self._sim.steady_forces(L, v, np.minimum(a + SECANT, 1.0), lce)
            self._lce_guess = guess
            dF = (F_hi - F) / (np.minimum(a + SECANT, 1.0) - a + 1e-300)
            J = dF[:, None] * self.S      # (n, C): dF/dlevel (no element is above its cap: level_max)
            A = R.T @ J
            b = tau_req - R.T @ F + A @ lv
            A_ = np.hstack([A, np.eye(nq)])
            if n_in:
                Cg = self._gh_rows @ P @ J
                ug = -(self._gh_rows @ (f0 + P @ F - P @ J @ lv))
                C_ = np.hstack([Cg, np.zeros((n_in, nq))])
            qp = proxqp.dense.QP(C + nq, nq, n_in, True)
            qp.settings.eps_abs, qp.settings.eps_rel, qp.settings.verbose = 1e-9, 0.0, False
            qp.init(H, g, A_, b, C_ if n_in else None, np.full(n_in, -_INF) if n_in else None,
                    ug if n_in else None, lbox, ubox)
            qp.solve()
            new = np.clip(qp.results.x[:C], 0.0, self.level_max)
            step = float(np.abs(new - lv).max())
            lv = new
            if step < 1e-6:
                break
        a = np.minimum(self.S @ lv, amax)
        lce, F, _ = self._forces(L, v, a)
        ok = float(np.abs(R.T @ F - tau_req).max()) < 1e-3  # N m: what the levels leave unbalanced
        self.last_levels = lv
        return lv, self._result(a, lce, F, L, v, R, P, f0, tau_req, amax, it, feasible=ok)


# ------------------------------------------------------------------------------------------ controllers
def _check_gains(params, names) -> None:
    """The named fields of a controller's parameters as finite floats >= 0 (ValueError naming the field; TypeError
    for a non-number or a bool, which would be taken as 0 or 1, as EndpointGains), the control interval > 0."""
    for k in names:
        v = real_scalar(getattr(params, k), k, booleans=False)
        if not (v >= 0 and math.isfinite(v)):
            raise ValueError(f"{k} must be finite and >= 0, got {v}")
        setattr(params, k, v)
    if not params.control_interval_s > 0:
        raise ValueError("control_interval_s must be > 0")


@dataclass
class PIDParams:
    """Feedback gains of FeedforwardPID on the joint-angle error (per DOF, the same for all): kp s^-2, ki s^-3,
    kd s^-1 (PIDParams.pole_placement derives them from the stimulated force's lag), preview_s (s: how far ahead of
    the control interval the reference and the posture are taken), integral_limit rad s (anti-windup: the integral of
    the error is held within +-integral_limit; default 10: through the inverse model ki x 10 rad s is 32 rad/s^2 at the
    pole-placed ki, about the elbow's whole gravitational moment, 3.2 N m on its 0.083 kg m^2 at the two-joint
    movement's end, so the integral can make up for a loss of force up to all of it; a bound of 1 rad s held the
    fatigued elbow 22 deg low for good, docs/control.md), control_interval_s (the update period the
    controller assumes for its one-step prediction), gh_stab_max (None, or the GHstab bound of the inverse model).
    TypeError for a field that is not a number (a bool included: True would be a gain or a bound of 1), ValueError
    for a negative or non-finite gain, a control interval <= 0, a gh_stab_max not finite and > 0
    (control.check_gh_stab_max, StaticOptimizer's rule); the model-dependent upper limit of gh_stab_max is checked
    when FeedforwardPID builds its inverse model (the parameters are not tied to a model)."""
    kp: float
    ki: float
    kd: float
    preview_s: float = 0.0
    integral_limit: float = 10.0
    control_interval_s: float = CONTROL_INTERVAL_S
    gh_stab_max: float | None = None

    @classmethod
    def pole_placement(cls, lag_s: float, **kw) -> "PIDParams":
        """Gains that place the four poles of the tracking error's dynamics at -1/(4 lag_s): the arm's joint as a
        double integrator behind the stimulated force's first-order lag (time constant lag_s, measured by
        chain_time_constant), tau s^4 + s^3 + kd s^2 + kp s + ki = tau (s + w)^4 with w = 1/(4 tau), i.e.
        kd = 6 w^2 tau, kp = 4 w^3 tau, ki = w^4 tau. preview_s defaults to lag_s: the inverse model is evaluated
        lag_s ahead so that the feedforward leads the lag (e^{s tau} ~ 1 + s tau, the lag's first-order inverse)."""
        tau = real_scalar(lag_s, "lag_s", booleans=False)
        # An infinite lag gives w = 0 and gains inf * 0 = NaN, which PIDParams would report as a bad kp.
        if not (tau > 0 and math.isfinite(tau)):
            raise ValueError(f"lag_s must be a finite time > 0 s, got {tau}")
        w = 1.0 / (4.0 * tau)
        kw.setdefault("preview_s", tau)
        return cls(kp=4 * w ** 3 * tau, ki=w ** 4 * tau, kd=6 * w ** 2 * tau, **kw)

    def __post_init__(self):
        _check_gains(self, ("kp", "ki", "kd", "preview_s", "integral_limit", "control_interval_s"))
        # The static optimiser's rule, applied where the bound is written (an infinite one used to pass here and be
        # refused only by FeedforwardPID's optimiser); its model-dependent upper limit is checked there.
        self.gh_stab_max = check_gh_stab_max(self.gh_stab_max)


@dataclass
class PIDState:
    """What FeedforwardPID carries between updates: integral (ndof,) rad s, last_t s (None before the first update),
    the last inverse-model result's feasibility and GHstab, the element activations it asked for (n,)."""
    integral: np.ndarray
    last_t: float | None = None
    feasible: bool = True
    gh_stab: float = float("nan")
    activation: np.ndarray | None = None
    infeasible_updates: int = 0


class FeedforwardPID:
    """Blana, Kirsch & Chadwick 2009's structure on this arm: feedforward from an inverse model plus PID feedback.

    Each update at time t, with the error e = q_ref(t) - q and T = control_interval_s + preview_s, the inverse model
    (channel-space static optimisation on `model`, an Arm without a map: ``model_arm(plant)``) is solved at the
    reference's posture and speed T ahead (the feedforward: what the muscles, whose force lags the stimulation by
    about preview_s, must produce then) for the accelerations
    ``qdd = qdd_ref(t + T) + kp e + kd (qdot_ref(t) - qdot) + ki ∫ e dt``: the PID's correction passes through the
    same inverse model, as Blana 2009's PID passes through their second network of the muscles' properties.
    The levels found are coded into pulse widths. kp = ki = kd = 0 plays the feedforward alone.

    model: an Arm (the controller's model of the plant), coding: StimulationCoding of the plant's map, reference: a
    Reference (or (time, q) samples), params: PIDParams, required: docs/control.md's gains are
    ``PIDParams.pole_placement(chain_time_constant(plant, coding))``, and the lag they are placed on is measured on
    the plant's stimulation map (its Ding force dynamics), which neither `model` (no map) nor `coding` holds, so the
    constructor cannot derive them. reference: a Reference, (time (T,) s, q (T, ndof) rad), or a .mot/.sto path
    (armrt.opensim_io.read_motion: OpenSim coordinate names, inDegrees honoured). ValueError for a model with a
    map or a bad reference, TypeError for a coding that is not a StimulationCoding, params that are not PIDParams
    or a reference of another kind."""

    def __init__(self, model, coding: StimulationCoding, reference, params: PIDParams):
        if not hasattr(model, "_sim") or model.channel_names:
            raise ValueError("FeedforwardPID's model must be an armrt.Arm without a stimulation map (model_arm(plant))")
        _check_coding(coding, "FeedforwardPID")
        if not isinstance(params, PIDParams):
            raise TypeError(f"params must be PIDParams (e.g. PIDParams.pole_placement(chain_time_constant(plant, "
                            f"coding))), got {type(params).__name__}")
        self.model, self.coding = model, coding
        self.reference = _reference(reference, model.model)
        self.params = params
        self.optimizer = ChannelStaticOptimizer(model, coding, gh_stab_max=self.params.gh_stab_max)
        self.state = PIDState(integral=np.zeros(model.n_dofs))

    def reset(self) -> None:
        """Forget the integral and the last update (a new trial)."""
        self.state = PIDState(integral=np.zeros(self.model.n_dofs))

    def update(self, t, q, qdot) -> np.ndarray:
        """(C, 3) stimulation for the arm at time t s, posture q (ndof,) rad and speeds qdot (ndof,) rad/s.
        ValueError for a non-finite t or one before the last update's (reset() starts a new trial), a wrong shape, a
        non-finite value or q beyond the engine's domain (checks.joint_range); TypeError for non-numbers."""
        t = _finite_time(t)
        q, qdot = _state_vectors(self.model, q, qdot)
        p, s = self.params, self.state
        if s.last_t is not None and t < s.last_t:
            # The integral would not advance and the trial's time would be another's: a new trial starts with reset().
            raise ValueError(f"t = {t:g} s is before the last update's {s.last_t:g} s: time runs forward within a "
                             "trial (call reset() to start a new one)")
        h = p.control_interval_s + p.preview_s
        qr, vr, ar = self.reference(t + h)    # what the muscles' force, lagging by preview_s, has to produce
        q_now, v_now, _ = self.reference(t)
        e = q_now - q
        dt = 0.0 if s.last_t is None else max(0.0, t - s.last_t)
        s.integral = np.clip(s.integral + e * dt, -p.integral_limit, p.integral_limit)
        s.last_t = t
        qdd = ar + p.kp * e + p.kd * (v_now - qdot) + p.ki * s.integral
        levels, res = self.optimizer.solve_levels(qr, vr, qdd)
        s.feasible, s.gh_stab, s.activation = bool(res.feasible), float(res.gh_stab), res.activation
        s.infeasible_updates += 0 if res.feasible else 1
        return self.coding.command(levels)


@dataclass
class PDParams:
    """Jagodnik & van den Bogert 2010's two-gain PD: kp (stimulation per rad), kd (per rad/s), control_interval_s;
    checked as PIDParams' (TypeError for a non-number or a bool, ValueError for a negative or non-finite value)."""
    kp: float
    kd: float
    control_interval_s: float = CONTROL_INTERVAL_S

    def __post_init__(self):
        _check_gains(self, ("kp", "kd", "control_interval_s"))


@dataclass
class PDState:
    """What PDController carries: the target posture (ndof,) rad and the last recruitment it asked for (C,)."""
    target: np.ndarray
    recruitment: np.ndarray | None = None


class PDController:
    """Jagodnik & van den Bogert 2010: stimulation from joint-angle and joint-speed feedback alone,
    ``R = clip(G (kp (q_target - q) - kd qdot), 0, 1)`` per channel, where G (C, ndof) gives each channel's share of
    each DOF: its muscle's moment arms at the target posture (m; the model's), each column scaled so that its largest
    entry is 1. A channel whose muscle flexes a DOF gets stimulation for a positive error of that DOF, its antagonist
    for a negative one; G fixes the gain matrix's structure and the two gains its size (their 2-parameter
    controller; the structure they gave it was not retrieved). The target is a step: the controller is set a new
    one with set_target.

    model: an Arm of the plant's model (moment arms), coding: StimulationCoding, target (ndof,) rad, params:
    PDParams, dofs: the DOF names fed back (default all; the others get no feedback), schedule: [(t s, target)]
    targets that take over at their times. ValueError for a target of another shape than (ndof,), with NaN/infinite
    values or beyond the joints' domain, or a schedule time that is negative or not finite; TypeError for a coding
    that is not a StimulationCoding or params that are not PDParams."""

    def __init__(self, model, coding: StimulationCoding, target, params: PDParams, dofs=None, schedule=()):
        _check_coding(coding, "PDController")
        if not isinstance(params, PDParams):
            raise TypeError(f"params must be PDParams, got {type(params).__name__}")
        self.model, self.coding, self.params = model, coding, params
        names = model.dof_names
        self.dofs = list(names) if dofs is None else [names[model.dof_index(d)] for d in dofs]
        self._cols = [names.index(d) for d in self.dofs]
        self.state = PDState(target=np.zeros(model.n_dofs))
        self.set_target(target)
        # [(t s, target (ndof,) rad)]: from each time on, its target (a reaching trial's step)
        self.schedule = sorted([(_schedule_time(t),
                                 _state_vectors(model, q, np.zeros(model.n_dofs), "schedule target")[0])
                                for t, q in map(_schedule_entry, schedule)], key=lambda x: x[0])

    def set_target(self, target) -> None:
        """A new target posture (ndof,) rad: G is recomputed from the moment arms there. ValueError for another shape,
        NaN/infinite values or a joint beyond the engine's domain (checks.joint_range), TypeError for non-numbers."""
        tgt = _state_vectors(self.model, target, np.zeros(self.model.n_dofs), "target")[0]
        R = np.asarray(self.model.moment_arms(tgt))  # (n, ndof), m
        G = np.zeros((len(self.coding.channel_names), self.model.n_dofs))
        for c, (i, w) in enumerate(zip(self.coding.element_index, self.coding.weights)):
            G[c] = (w[:, None] * R[i]).sum(axis=0) / w.sum()
        for j in range(self.model.n_dofs):
            mx = np.abs(G[:, j]).max()
            G[:, j] = G[:, j] / mx if (j in self._cols and mx > 0) else 0.0
        self.gain_structure = G
        self.state = PDState(target=tgt)

    def update(self, t, q, qdot) -> np.ndarray:
        """(C, 3) stimulation for the state (t s, q (ndof,) rad, qdot (ndof,) rad/s). ValueError for a non-finite t
        (a scheduled target would never take over), a wrong shape, a non-finite value or q beyond the engine's domain
        (checks.joint_range); TypeError for non-numbers."""
        t = _finite_time(t)
        q, qdot = _state_vectors(self.model, q, qdot)
        while self.schedule and self.schedule[0][0] <= t + 1e-12:
            self.set_target(self.schedule.pop(0)[1])
        p = self.params
        drive = p.kp * (self.state.target - q) - p.kd * qdot
        r = np.clip(self.gain_structure @ drive, 0.0, 1.0)
        self.state.recruitment = r
        out = np.empty((len(self.coding.channel_names), 3))
        out[:, 0] = self.coding.pulse_width(r)
        out[:, 1], out[:, 2] = self.coding.amplitude_A, self.coding.frequency_Hz
        return out


def _state_vectors(model, q, qdot, what: str = "q") -> tuple[np.ndarray, np.ndarray]:
    """(q, qdot) as (ndof,) arrays (checks.dof_vector: no other shape, (ndof, 1) included, as the rest of armrt),
    q within the engine's domain (checks.joint_range without the warning: a simulated state may end slightly
    beyond a joint's range; degrees given as radians are refused with a hint), qdot within the arm's
    max_joint_speed (as static_optimization: a 1e6 rad/s sensor glitch gave the largest pulse widths)."""
    q = joint_range(dof_vector(q, what, model.dof_names), model.dof_names, model.dof_ranges, warn=False)
    qdot = dof_vector(qdot, "qdot", model.dof_names)
    joint_speed_within(qdot, model.dof_names, model._sim.max_joint_speed, "the controller (the bound its arm's step holds)")
    return q, qdot


def _check_coding(coding, who: str) -> None:
    """TypeError unless coding is a StimulationCoding (it would fail later as an AttributeError)."""
    if not isinstance(coding, StimulationCoding):
        raise TypeError(f"{who}'s coding must be a StimulationCoding (StimulationCoding.from_arm(plant)), got "
                        f"{type(coding).__name__}")


def _reference(reference, model) -> Reference:
    """A Reference from a Reference, (time, q) samples or a .mot/.sto path (read_motion, for this model)."""
    if isinstance(reference, Reference):
        return reference
    if isinstance(reference, (str, bytes)) or hasattr(reference, "__fspath__"):
        from .opensim_io import read_motion  # noqa: PLC0415 (opensim_io imports arm: imported where it is used)
        m = read_motion(reference, model=model.name)
        return Reference(m.time, m.q, model)
    if not (isinstance(reference, (tuple, list)) and len(reference) == 2):
        raise TypeError("reference must be a Reference, (time (T,) s, q (T, ndof) rad) or a .mot/.sto path, got "
                        f"{type(reference).__name__}" + (f" of length {len(reference)}"
                                                         if isinstance(reference, (tuple, list)) else ""))
    return Reference(*reference, model)


def _schedule_entry(entry):
    """One schedule entry as (t, target): ValueError naming the form for anything else (a bare posture, the time
    left out, gave Python's 'too many values to unpack')."""
    if isinstance(entry, (str, bytes)) or not hasattr(entry, "__len__") or len(entry) != 2:
        raise ValueError(f"a schedule entry must be a pair (t s, target (ndof,) rad), got {entry!r}")
    return entry


def _schedule_time(t) -> float:
    """A schedule entry's time as a finite float >= 0 s: the times compare with the plant's, which start at 0, so a
    negative one is a mistake (it would take over at the first update, as if given 0)."""
    t = _finite_time(t, "schedule time")
    if t < 0:
        raise ValueError(f"schedule time must be >= 0 s (the plant's time starts at 0), got {t}")
    return t


def _finite_time(t, what: str = "t") -> float:
    """t as a finite float s: a NaN time compares false with every schedule time and reference sample."""
    t = real_scalar(t, what, booleans=False)  # update(True, ...) was taken as t = 1 s
    if not math.isfinite(t):
        raise ValueError(f"{what} must be a finite time in s, got {t}")
    return t


# ------------------------------------------------------------------------------------------ offline runs
@dataclass
class ControlRun:
    """An offline run: per control update (K rows) time (K,) s, q and q_ref (K, ndof) rad, stimulation (K, C, 3),
    gh_stab (K,), fatigue (K, C) 1 - A/A_rest, force_total (K,) N the sum of every element's tendon force, update_s
    (K,) the controller's update time (wall clock, this machine: information, not a claim), feasible (K,) bool:
    False where the controller's inverse model found no stimulation for what it asked (FeedforwardPID's
    state.feasible: the closest levels were sent; True for the first row and for controllers without one)."""
    time: np.ndarray
    q: np.ndarray
    q_ref: np.ndarray
    stimulation: np.ndarray
    gh_stab: np.ndarray
    fatigue: np.ndarray
    update_s: np.ndarray
    force_total: np.ndarray | None = None
    channel_names: list = field(default_factory=list)
    feasible: np.ndarray | None = None

    @property
    def infeasible_updates(self) -> int:
        """How many updates sent the closest stimulation instead of a solution (0 if none was recorded)."""
        return 0 if self.feasible is None else int(np.count_nonzero(~self.feasible))

    def error_deg(self, dofs, model, t_from: float = -np.inf, t_to: float = np.inf) -> dict:
        """{dof: (rms, max)} deg of q - q_ref over t_from <= t <= t_to."""
        sel = (self.time >= t_from) & (self.time <= t_to)
        out = {}
        for d in dofs:
            j = model.dof_index(d)
            e = np.degrees(self.q[sel, j] - self.q_ref[sel, j])
            out[d] = (float(np.sqrt(np.mean(e ** 2))), float(np.abs(e).max()))
        return out


def run_offline(plant, controller, duration: float, reference=None, hand_load=None, hold_s: float = 0.0,
                joint_moment=None) -> ControlRun:
    """Runs `controller` on the Arm `plant` (with a stimulation map) for `duration` s from the plant's present state,
    one update every controller.params.control_interval_s. hold_s: for the first hold_s s the joints are held at
    their start (q and qdot restored after each interval, every other state kept): the arm supported while the
    stimulation builds up from rest, as a trial starts from a supported arm. reference: a callable t -> q_ref (ndof,)
    recorded beside q (default: the controller's own reference, or its target). hand_load: None or a callable
    t -> a hand load in any of inverse_dynamics' forms (a force (3,) N, (force (3,), moment (3,) N m), a (6,)
    [force, moment]), thorax frame, applied before each interval (a disturbance). joint_moment: None or a
    callable (t, q (ndof,) rad, qdot (ndof,) rad/s, copies) -> (ndof,) N m added at the joints to the moment the
    plant had applied when called (Arm.set_applied_moment) before each of the plant's steps, so a state-dependent
    moment such as joint friction follows the arm at its step rate, not the controller's; while it is called the
    plant holds only its own moment, and that moment is the plant's again when the run ends (or raises).
    The run makes floor(duration / control_interval_s) updates (K = that + 1 rows, the first the start).
    ValueError for a plant without a map or with other channels than the coding's, a control interval that is not
    a whole number of plant steps, a duration that is not finite or shorter than one control interval (no update
    would be made), a hold_s that is not finite and >= 0; TypeError for a plant that is not an armrt.Arm, a
    controller without update/coding/params (the two swapped), a duration or hold_s that is not a number (a bool
    included: True would be 1 s) and for a reference, hand_load or joint_moment that is not callable; during the
    run, the hand load's own TypeError or ValueError (a bad shape, NaN) for what hand_load(t) returns, naming
    hand_load and t. Returns the ControlRun; a RuntimeWarning if any update's inverse model found no stimulation
    for what it asked (ControlRun.feasible marks them)."""
    if not isinstance(plant, Arm):
        raise TypeError(f"run_offline(plant, controller, duration): plant must be an armrt.Arm with a stimulation "
                        f"map, got {type(plant).__name__}")
    if not (callable(getattr(controller, "update", None)) and hasattr(controller, "coding")
            and hasattr(controller, "params")):
        raise TypeError(f"run_offline(plant, controller, duration): controller must be a FeedforwardPID, a "
                        f"PDController or one with their update(t, q, qdot), coding and params, got "
                        f"{type(controller).__name__}")
    if not plant.channel_names or list(plant.channel_names) != list(controller.coding.channel_names):
        raise ValueError("the plant's stimulation channels must be the controller's coding's channels")
    h = controller.params.control_interval_s
    steps = int(round(h / plant.dt))
    if steps < 1 or abs(steps * plant.dt - h) > 1e-9:
        raise ValueError(f"control_interval_s {h} is not a whole number of the plant's steps ({plant.dt} s)")
    duration = real_scalar(duration, "duration", booleans=False)  # True was a run of 1 s
    if not (math.isfinite(duration) and duration > 0):
        raise ValueError(f"duration must be finite and > 0 s, got {duration}")
    n = int(math.floor(duration / h + 1e-9))
    if n < 1:
        raise ValueError(f"duration {duration} s is shorter than one control interval ({h} s): the run would make "
                         "no update")
    # The hold compares the elapsed time with hold_s: a NaN would never hold and a string fail mid-run.
    hold_s = real_scalar(hold_s, "hold_s", booleans=False)
    if not (math.isfinite(hold_s) and hold_s >= 0):
        raise ValueError(f"hold_s must be finite and >= 0 s, got {hold_s}")
    for name, f in (("reference", reference), ("hand_load", hand_load), ("joint_moment", joint_moment)):
        if f is not None and not callable(f):
            raise TypeError(f"{name} must be None or a callable, got {type(f).__name__}")
    if reference is None:
        if hasattr(controller, "reference"):
            reference = lambda t: controller.reference(t)[0]  # noqa: E731
        else:
            reference = lambda t: controller.state.target  # noqa: E731
    names = plant.channel_names
    nq, C = plant.n_dofs, len(names)
    out = ControlRun(time=np.empty(n + 1), q=np.empty((n + 1, nq)), q_ref=np.empty((n + 1, nq)),
                     stimulation=np.zeros((n + 1, C, 3)), gh_stab=np.empty(n + 1), fatigue=np.empty((n + 1, C)),
                     update_s=np.zeros(n + 1), force_total=np.zeros(n + 1), channel_names=list(names),
                     feasible=np.ones(n + 1, dtype=bool))

    def record(k, cmd, dt_upd):
        fat = plant.fatigue
        out.time[k], out.q[k], out.q_ref[k] = plant.time, plant.q, reference(plant.time)
        out.gh_stab[k], out.fatigue[k] = plant.gh_stab, [fat[c] for c in names]
        out.stimulation[k], out.update_s[k] = cmd, dt_upd
        out.feasible[k] = k == 0 or bool(getattr(controller.state, "feasible", True))
        out.force_total[k] = float(np.sum(plant.outputs()["muscle_force"]))

    record(0, np.zeros((C, 3)), 0.0)
    base_moment = plant.applied_moment
    try:
        _control_loop(plant, controller, n, steps, hand_load, joint_moment, base_moment, hold_s, record)
    finally:
        plant.set_applied_moment(base_moment)
    if out.infeasible_updates:
        # Never a silent best effort: the run's errors may come from asking the muscles for what they cannot give.
        bad = np.flatnonzero(~out.feasible)
        warnings.warn(f"run_offline: {bad.size} of {n} updates found no stimulation for what the controller asked "
                      f"(the closest levels were sent; first at t = {out.time[bad[0]]:.3f} s): ControlRun.feasible "
                      "marks them", RuntimeWarning, stacklevel=2)
    return out


def _returned_hand_load(hand_load, t: float) -> tuple[np.ndarray, np.ndarray]:
    """(force (3,) N, moment (3,) N m) from run_offline's hand_load(t): any form a hand load takes elsewhere (a force
    (3,), (force, moment), a (6,) [force, moment], {"force", "moment"}: control._hand_load, inverse_dynamics'
    parser), its errors naming hand_load and t. A force alone failed with Python's bare "too many values to unpack"."""
    value = hand_load(t)
    if value is None:
        raise TypeError(f"hand_load({t:g}) returned None; it must return a force (3,) N, (force (3,) N, moment (3,) "
                        f"N m) or a (6,) [force, moment] (thorax frame)")
    try:
        return _hand_load(value, None)
    except (TypeError, ValueError, KeyError) as exc:
        raise type(exc)(f"hand_load({t:g}) returned an invalid hand load: {exc}") from None


def _control_loop(plant, controller, n, steps, hand_load, joint_moment, base_moment, hold_s, record) -> None:
    """run_offline's loop: n controller updates of `steps` plant steps each."""
    sl = plant.state_vector_slices()
    held = plant.get_state_vector()
    t_start = plant.time
    for k in range(n):
        t0 = _time.perf_counter()
        cmd = controller.update(plant.time, plant.q, plant.qdot)
        dt_upd = _time.perf_counter() - t0
        if hand_load is not None:
            plant.set_hand_load(*_returned_hand_load(hand_load, plant.time))
        plant.set_stimulation(cmd)
        if joint_moment is None:
            plant.step(steps)
        else:
            for _ in range(steps):
                plant.set_applied_moment(base_moment)
                extra = joint_moment(plant.time, plant.q.copy(), plant.qdot.copy())
                plant.set_applied_moment(base_moment + applied_moments(extra, plant.dof_names, "joint_moment",
                                                                               model_name=plant.model_name))
                plant.step()
        if plant.time - t_start <= hold_s + 1e-9:
            x = plant.get_state_vector()
            x[sl["q"]], x[sl["qdot"]] = held[sl["q"]], held[sl["qdot"]]
            plant.set_state_vector(x)
        record(k + 1, cmd, dt_upd)
