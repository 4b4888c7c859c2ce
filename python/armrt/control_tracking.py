"""Computed muscle control (issue 28 item 3; docs/control.md): a reference motion (T, ndof) -> excitations per control
interval that make the forward simulation track it, with the tracking error per DOF.

Thelen, Anderson & Delp 2003 (J Biomech 36:321, "Generating dynamic simulations of movement using computed muscle
control") and Thelen & Anderson 2006 (J Biomech 39:1107): every control interval T the desired accelerations are
the reference's plus PD feedback on the tracking error,

    qddot_des = qddot_ref(t+T) + kv (qdot_ref(t+T) - qdot) + kp (q_ref(t+T) - q),

static optimisation gives the activations a* that produce qddot_des, and the excitation held over the interval is
the one whose activation dynamics reach a* at t+T. Their gains, kp = 100 s^-2 and kv = 20 s^-1 (= 2 sqrt(kp),
critically damped), and T = 10 ms, are the defaults. The state the accelerations are asked at is the arm's own at
t, its position extrapolated to t+T with its velocity (q + T qdot), a first-order stand-in for CMC's integration
over the interval.

With correct_model_error=True (ours, not Thelen's) the moments asked of the optimiser are corrected by its own
muscle model's error at the arm's present state, d = R^T (F_arm - F_model(a)) (F_arm: the tendon forces of the
simulated fibres; F_model: the optimiser's at the same activations, fibres at the steady state of the path's
velocity or a rigid tendon), asking R^T F_model = tau(qddot_des) - d = tau(qddot_des - M^-1 d) since the inverse
dynamics is linear in qddot. It removes the slow-motion drift docs/control.md measures: an element the optimiser
recruits from zero gives no force for 0.1-0.5 s (slack fibre), and that elbow moment reaches the forearm's
rotation through the mass matrix. d alone misses the error within an interval (the activations reach a* only at
its end), which on a fast elastic-tendon flexion had cancelled part of it, so d alone made that worse; the
correction adds the remainder the last intervals' plans missed beyond d, measured from the arm's mean acceleration
and averaged over MODEL_ERROR_WINDOW (a disturbance observer: Ohnishi, Shibata & Murakami 1996, IEEE/ASME Trans
Mechatronics 1:56; time-delay estimation: Youcef-Toumi & Ito 1990, J Dyn Syst Meas Control 112:133)."""
from __future__ import annotations

import warnings
from collections import deque
from dataclasses import dataclass

import numpy as np

from .checks import STATE_MARGIN, joint_acceleration_within, real_array, real_scalar
from .control import MAX_JOINT_ACCELERATION, StaticOptimizer
from .control_motion import check_motion

KP_THELEN_2003 = 100.0  # s^-2, Thelen et al. 2003
KV_THELEN_2003 = 20.0  # s^-1, 2 sqrt(kp)
CONTROL_INTERVAL_THELEN_2003 = 0.010  # s
# s: correct_model_error's remainder (what the last plans missed beyond the present fibre-state error) is the mean
# over the intervals within this window, a disturbance observer's low-pass filter (ours: docs/control.md says what
# shorter windows did).
MODEL_ERROR_WINDOW = 0.040
# s: track_motion uses the remainder at control intervals up to this, where it was measured to help (5 and 10 ms); at
# 20-40 ms it made slow motions unstable (PSy 17.6-81 deg against 0.16-3.9 without a correction), while d alone
# helped at every interval measured (docs/control.md "Why d alone was not enough").
MODEL_ERROR_REMAINDER_MAX_INTERVAL = 0.010


@dataclass
class TrackingResult:
    """Per control interval (K rows, at the end of each): time (K,) s, q and q_ref (K, ndof) rad, excitation (K, n)
    held over the interval, target_activation (K, n) from static optimisation, feasible (K,) bool (False where the
    static optimisation found no exact solution and its best effort was used: counted, never silent), gh_stab
    (K,). error_rms_deg and error_max_deg: {DOF name: deg} of q - q_ref over the intervals."""
    time: np.ndarray
    q: np.ndarray
    q_ref: np.ndarray
    excitation: np.ndarray
    target_activation: np.ndarray
    feasible: np.ndarray
    gh_stab: np.ndarray
    error_rms_deg: dict
    error_max_deg: dict

    def __repr__(self) -> str:
        worst = max(self.error_max_deg, key=self.error_max_deg.get)
        return (f"TrackingResult({len(self.time)} intervals to t = {self.time[-1]:.3f} s, "
                f"{int(np.count_nonzero(~self.feasible))} infeasible, largest error {worst} "
                f"{self.error_max_deg[worst]:.3g} deg (RMS {self.error_rms_deg[worst]:.3g}), "
                f"gh_stab max {np.max(self.gh_stab):.3f})")


def excitation_reaching(a0, a_target, c1, c2, interval: float, u_max):
    """Constant excitations u (n,) in [0, u_max] with which the activation dynamics da/dt = (c1 u + c2)(u - a)
    (He et al. 1991, the model's; c2 = 1/tdeact, c1 = 1/tact - c2) take a from a0 to a_target in `interval` s;
    clamped to the bound where a_target is out of reach. Solved by bisection: a(interval) = u + (a0 - u)
    exp(-(c1 u + c2) interval) rises with u above a0 but need not below it, so each side is bracketed on its own."""
    a0, at = np.asarray(a0, float), np.asarray(a_target, float)
    c1, c2, u_max = np.asarray(c1, float), np.asarray(c2, float), np.asarray(u_max, float)
    at = np.clip(at, 0.0, u_max)

    def reached(u):
        return u + (a0 - u) * np.exp(-(c1 * u + c2) * interval)

    up = at >= a0
    lo = np.where(up, at, 0.0)
    hi = np.where(up, u_max, at)
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        below = reached(mid) < at
        lo = np.where(below, mid, lo)
        hi = np.where(below, hi, mid)
    u = 0.5 * (lo + hi)
    u = np.where(up & (reached(u_max) < at), u_max, u)
    u = np.where(~up & (reached(np.zeros_like(u)) > at), 0.0, u)
    return np.clip(u, 0.0, u_max)


def muscle_model_error(arm, tendon: str = "elastic") -> np.ndarray:
    """(ndof,) N m: the generalised forces of the arm's simulated tendon forces minus those static optimisation's
    muscle model gives at the same state and activations, R^T (F_arm - F_model(a)); F_model with tendon="elastic"
    has the fibres at the steady state of the path's velocity (StaticOptimizer's elastic element), with "rigid" a
    rigid tendon. Zero where the arm's fibres are at that steady state (at rest after arm.reset, for instance)."""
    sim = arm._sim
    L, R = sim.muscle_paths(arm.q)  # (n,), (n, ndof)
    v = np.ascontiguousarray(-(R @ arm.qdot))  # dL/dt: moment arms are -dL/dq
    a = np.ascontiguousarray(arm.activation)
    if tendon == "elastic":
        _, f_model, _ = sim.steady_forces(L, v, a, arm.lce.copy())
    else:
        _, f_active, f_passive = sim.rigid_tendon_forces(L, v)
        f_model = f_active * a + f_passive
    return R.T @ (arm.outputs()["muscle_force"] - f_model)


class ModelErrorObserver:
    """correct_model_error's two terms for a controller that solves a static optimisation every interval_s seconds
    of an armrt.Arm (track_motion, EndpointController): asked(qddot_des, q, qdot, last_feasible) -> the qddot (ndof,)
    rad/s^2 to ask the optimiser for, qddot_des - M^-1 (d + mean r), with d = muscle_model_error(arm, tendon) at the
    arm's present state and r what each of the last intervals' plans missed beyond d, M (qdot - qdot_last) /
    interval_s - M qddot_asked_last - (d_last + d) / 2, over the last MODEL_ERROR_WINDOW (feasible intervals only):
    a disturbance observer (Ohnishi, Shibata & Murakami 1996; docs/control.md "Why d alone was not enough"); with
    remainder=False, d alone. Call it once per solve, at the solve's state, before the arm moves on."""

    def __init__(self, arm, tendon: str, interval_s: float, window_s: float = MODEL_ERROR_WINDOW,
                 remainder: bool = True):
        self.arm, self.tendon, self.interval_s, self.remainder = arm, tendon, float(interval_s), bool(remainder)
        self._missed = deque(maxlen=max(1, int(round(window_s / self.interval_s))))  # r, N m per DOF, one per interval
        self._last = None  # (qdot rad/s, qddot asked rad/s^2, M kg m^2, d N m) at the last solve

    def asked(self, qdd_des, q, qd, last_feasible: bool) -> np.ndarray:
        d = muscle_model_error(self.arm, self.tendon)
        mass = self.arm.mass_matrix(q)
        if self.remainder and self._last is not None and last_feasible:  # an infeasible plan's shortfall is none
            qd_last, qdd_last, mass_last, d_last = self._last
            self._missed.append(mass_last @ ((qd - qd_last) / self.interval_s - qdd_last) - 0.5 * (d_last + d))
        correction = d + (np.mean(self._missed, axis=0) if self._missed else 0.0)
        qdd_asked = qdd_des - np.linalg.solve(mass, correction)
        self._last = (np.array(qd, dtype=float), qdd_asked, mass, d)
        return qdd_asked


def track_motion(arm, q_ref, time=None, kp: float = KP_THELEN_2003, kv: float = KV_THELEN_2003,
                 control_interval: float = CONTROL_INTERVAL_THELEN_2003, gh_stab_max=None,
                 weights=None, criterion: str = "squared", tendon: str = "elastic",
                 correct_model_error: bool = False) -> TrackingResult:
    """Computed muscle control of `arm` (an armrt.Arm with its settings: strength, max_activation, hand load from
    arm.set_hand_load, integrator) along q_ref (T, ndof) rad at time (T,) s (strictly increasing, at least 4 frames;
    interpolated by a cubic spline, whose derivatives are the reference velocities and accelerations), or along a
    .mot/.sto path given as q_ref with time None (armrt.opensim_io.read_motion: OpenSim names, inDegrees
    honoured). The arm is reset to q_ref[0] with the reference velocity and the static-optimisation activations there, then simulated one
    control interval at a time (a whole number of the arm's steps; a last part of the motion shorter than an
    interval is not run). kp (s^-2), kv (s^-1) >= 0: the feedback gains (kp = kv = 0 plays the feedforward alone).
    gh_stab_max, weights, criterion, tendon: as armrt.StaticOptimizer. correct_model_error: subtract the optimiser's
    muscle-model error at the arm's present state, and (at control intervals up to
    MODEL_ERROR_REMAINDER_MAX_INTERVAL, 10 ms) what the last intervals' plans missed beyond it, averaged over
    MODEL_ERROR_WINDOW, from the moments it is asked for (module docstring; off by default, Thelen's method as
    published). An interval whose static optimisation is
    infeasible keeps its closest solution and is counted False in `feasible`; so is one whose predicted posture lies
    beyond the engine's domain (joint ranges + 0.35 rad: the arm has fallen away), solved at the domain's edge.
    A RuntimeWarning says when the simulated GHstab at an interval's end passed gh_stab_max (which bounds the
    solves, not the moving arm).
    ValueError for bad input (shapes, NaN, a frame beyond the joint domain,
    gains, an interval not a whole number of steps, a motion shorter than one interval, an arm with a stimulation
    map), and during the run for an interval whose feedforward plus feedback asks for a joint acceleration beyond
    the static optimisation's bound (1e5 rad/s^2: gains far too high), naming the interval and the gains;
    TypeError for a Model, for kp, kv or control_interval not a number (a bool included), and for
    correct_model_error not a bool."""
    from scipy.interpolate import CubicSpline  # noqa: PLC0415 (scipy is a dependency; only this needs it)

    if not hasattr(arm, "_sim"):
        raise TypeError("track_motion needs an armrt.Arm (it simulates the arm), got " + type(arm).__name__)
    if arm.channel_names:
        raise ValueError("track_motion: this arm has a stimulation map; the elements it drives follow the stimulation "
                         "channels, not the excitations computed here (clear the map: arm.set_stimulation_map(None))")
    model = arm.model
    if isinstance(q_ref, (str, bytes)) or hasattr(q_ref, "__fspath__"):
        from .opensim_io import read_motion  # noqa: PLC0415 (opensim_io imports arm, which imports control)
        if time is not None:
            raise ValueError("time: a .mot file has its own time column; give time only with q_ref as an array")
        m = read_motion(q_ref, model=model.name)
        q_ref, time = m.q, m.time
    if time is None:
        raise ValueError("time (T,) s is needed with q_ref given as an array")
    q_ref = real_array(q_ref, "q_ref")
    time = real_array(time, "time")
    check_motion(model, q_ref, time, "q_ref", 4)
    # booleans=False: kp=True was a gain of 1 and control_interval=True an interval of 1 s.
    kp, kv = real_scalar(kp, "kp", booleans=False), real_scalar(kv, "kv", booleans=False)
    if not (np.isfinite(kp) and np.isfinite(kv) and kp >= 0 and kv >= 0):
        raise ValueError(f"kp and kv must be finite and >= 0, got kp={kp:g}, kv={kv:g}")
    interval = real_scalar(control_interval, "control_interval", booleans=False)
    if not (np.isfinite(interval) and interval > 0):
        raise ValueError(f"control_interval must be a finite number of seconds > 0, got {interval:g}")
    steps = int(round(interval / arm.dt))
    if steps < 1 or abs(steps * arm.dt - interval) > 1e-9 * max(1.0, interval):
        raise ValueError(f"control_interval must be a whole number (>= 1) of the arm's step {arm.dt:g} s, "
                         f"got {interval:g} s")

    if not isinstance(correct_model_error, (bool, np.bool_)):
        raise TypeError(f"correct_model_error must be True or False, got {type(correct_model_error).__name__} "
                        f"{correct_model_error!r}")

    spline = CubicSpline(time, q_ref, axis=0)
    ref_v, ref_a = spline.derivative(1), spline.derivative(2)
    so = StaticOptimizer(arm, gh_stab_max=gh_stab_max, weights=weights, criterion=criterion, tendon=tendon)
    t0 = float(time[0])
    start = so.solve(q_ref[0], ref_v(t0), ref_a(t0), on_infeasible="return")
    arm.reset(q=q_ref[0], qdot=ref_v(t0), activation=np.minimum(start.activation, arm.max_activation), time=t0)

    p = model.parameters
    c2 = 1.0 / np.asarray(p["tdeact"])
    c1 = 1.0 / np.asarray(p["tact"]) - c2
    k_total = int(np.floor((time[-1] - t0) / interval + 1e-9))  # a last part shorter than an interval is not run
    if k_total < 1:
        raise ValueError(f"the motion lasts {time[-1] - t0:g} s, less than one control interval ({interval:g} s)")
    nq, n = model.n_dofs, model.n_elements
    domain_lo = model.dof_ranges[:, 0] - 0.999 * STATE_MARGIN
    domain_hi = model.dof_ranges[:, 1] + 0.999 * STATE_MARGIN
    out_t, out_q, out_r = np.empty(k_total), np.empty((k_total, nq)), np.empty((k_total, nq))
    out_u, out_a = np.empty((k_total, n)), np.empty((k_total, n))
    feasible, gh = np.empty(k_total, bool), np.empty(k_total)
    observer = ModelErrorObserver(arm, tendon, interval,
                                  remainder=interval <= MODEL_ERROR_REMAINDER_MAX_INTERVAL * (1 + 1e-9)) \
        if correct_model_error else None
    for k in range(k_total):
        t = arm.time
        t_next = t + interval
        q, qd = arm.q, arm.qdot
        q_pred = q + interval * qd
        qdd_des = ref_a(t_next) + kv * (ref_v(t_next) - qd) + kp * (spline(t_next) - q_pred)
        # An arm that has fallen away from the motion (infeasible intervals before) can be predicted beyond the
        # engine's domain, where the static optimisation refuses a pose: solve at the domain's edge instead, and
        # count the interval infeasible.
        q_solve = np.clip(q_pred, domain_lo, domain_hi)
        # The solve refuses this too; here the message can name the interval and the gains that asked for it.
        joint_acceleration_within(qdd_des, model.dof_names, MAX_JOINT_ACCELERATION,
                                  f"track_motion (interval {k}, t = {t:.4g} s; the feedback kp = {kp:g} s^-2, kv = "
                                  f"{kv:g} s^-1 on the error; the arm is left where the run stopped)")
        qdd_asked = qdd_des
        if observer is not None:
            qdd_asked = observer.asked(qdd_des, q_solve, qd, k > 0 and bool(feasible[k - 1]))
        res = so.solve(q_solve, qd, qdd_asked, on_infeasible="return")
        amax = arm.max_activation
        u = excitation_reaching(arm.activation, res.activation, c1, c2, interval, amax)
        arm.set_excitation(u)
        arm.step(steps)
        out_t[k], out_q[k], out_r[k] = arm.time, arm.q, spline(arm.time)
        out_u[k], out_a[k], gh[k] = u, res.activation, arm.gh_stab
        feasible[k] = res.feasible and bool(np.array_equal(q_solve, q_pred))
    bound = so.gh_stab_max
    if bound is not None and gh.max() > bound * (1 + 1e-6):
        # The bound holds each interval's solve, not the moving arm: above it, the user is told (a trial's 1e-6
        # bound gave 1.1e-3, every interval feasible, nothing said).
        k = int(np.argmax(gh))
        warnings.warn(f"track_motion: the simulated GHstab reached {gh[k]:.4g} at t = {out_t[k]:.4g} s, above "
                      f"gh_stab_max {bound:.4g} ({gh[k] / bound:.3g} times; {int((gh > bound).sum())} of {gh.size} "
                      "interval ends): the bound holds each interval's static optimisation, not the arm between "
                      "solves (docs/control.md); choose a margin under the limit to be kept", RuntimeWarning,
                      stacklevel=2)
    err = np.degrees(out_q - out_r)
    names = model.dof_names
    return TrackingResult(time=out_t, q=out_q, q_ref=out_r, excitation=out_u, target_activation=out_a,
                          feasible=feasible, gh_stab=gh,
                          error_rms_deg={d: float(np.sqrt(np.mean(err[:, j] ** 2))) for j, d in enumerate(names)},
                          error_max_deg={d: float(np.abs(err[:, j]).max()) for j, d in enumerate(names)})
