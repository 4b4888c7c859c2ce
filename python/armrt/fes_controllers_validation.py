"""The reference FES controllers against their papers' results (docs/control.md "Reference FES controllers"):
protocols, tables and figures.

    python -m armrt.fes_controllers_validation --out docs/figures            # every table and figure
    python -m armrt.fes_controllers_validation blana --out docs/figures      # (a) only
    python -m armrt.fes_controllers_validation optimise-pd                   # (b)'s gains, saved to PD_GAINS_FILE
    python -m armrt.fes_controllers_validation jagodnik --out docs/figures   # (b) with the saved gains
    python -m armrt.fes_controllers_validation posture --out docs/figures    # (c)

The arm of every protocol is das2 with participant A's FES profile (models/participant_A_FES.json: the elbow and
forearm muscles' strength 0.14-0.59 of participant A's and their maxact; the shoulder muscles, which the profile does
not name, intact) and one intramuscular channel per muscle (stimulation="per_muscle"), pulse width modulated at
20 mA and 20 Hz (fes_control.StimulationCoding). Every number the docs give comes from this module's printout.
"""
from __future__ import annotations

import argparse
import copy
import json
import math
from pathlib import Path

import numpy as np

from . import fes_control as fc
from .checks import real_scalar

PROFILE = "participant_A_FES"
HOLD_S = 1.0    # s the arm is supported at the start while the stimulation builds up (run_offline hold_s)
AFTER_S = 1.0   # s of holding the end posture after the movement, inside the error window

#: (a) Blana 2009: "goal-oriented movements of varying amplitudes and durations" of the shoulder and elbow. Their
#: exact set was not retrieved: these are minimum-jerk movements (Flash & Hogan 1985) from the rest posture, of two
#: amplitudes and two durations per joint and one of both joints, within what the weakened elbow flexors can hold
#: (a static elbow hold at +70 deg from rest is feasible for them, at +80 deg not: blana() prints it).
BLANA_MOVEMENTS = [
    ("elbow +20 deg, 1 s", {"ELx": 20.0}, 1.0),
    ("elbow +40 deg, 2 s", {"ELx": 40.0}, 2.0),
    ("shoulder +15 deg, 1 s", {"GHy": 15.0}, 1.0),
    ("shoulder +30 deg, 2 s", {"GHy": 30.0}, 2.0),
    ("shoulder +20, elbow +30 deg, 1.5 s", {"GHy": 20.0, "ELx": 30.0}, 1.5),
]
#: Conditions. Their fatigue and disturbance were not retrieved; ours: fatigue as the Ding 2003 state of every
#: channel after FATIGUE_S of continuous saturating 20 Hz stimulation (a probe arm's fatigue states copied into the
#: plant: the controller is not told), disturbance a downward hand force of DISTURBANCE_N for 0.5 s from the
#: movement's middle (Arm.set_hand_load; the controller's model does not know it).
FATIGUE_S = (10.0, 20.0)
DISTURBANCE_N = (2.0, 5.0)
BLANA_CONDITIONS = [("ideal", 0.0, 0.0), ("fatigue 10 s", 10.0, 0.0), ("fatigue 20 s", 20.0, 0.0),
                    ("disturbance 2 N", 0.0, 2.0), ("disturbance 5 N", 0.0, 5.0),
                    ("fatigue 10 s + disturbance 2 N", 10.0, 2.0)]
BLANA_PUBLISHED = {"ideal": "< 4 deg", "fatigue": "< 10 deg", "disturbance": "< 10 deg"}


def weakened_arm():
    """das2 with participant_A_FES's strength and maxact and a per-muscle intramuscular map."""
    from .arm import Arm  # noqa: PLC0415
    arm = Arm("das2", stimulation="per_muscle")
    arm.apply_profile(PROFILE)
    return arm


def fatigue_states(arm, coding, seconds: float) -> np.ndarray:
    """(C, 3) the Ding fatigue states (A, tau1, Km over rested) of every channel after `seconds` s of continuous
    saturating stimulation at the coding's amplitude and frequency, on a probe arm of the same map."""
    from .arm import Arm  # noqa: PLC0415
    probe = Arm(arm.model, stimulation=arm.stimulation_map())
    probe.reset(q=arm.rest_posture)
    probe.set_stimulation(coding.command(coding.fused))
    probe.step(int(round(seconds / probe.dt)))
    return np.array(probe.stimulation_state[:, 3:6])


def set_fatigue(arm, states) -> None:
    """Writes (C, 3) fatigue states into arm's stimulation state (snapshot, per channel rows)."""
    from .stimulation import STATE_COLUMNS, STATE_SIZE  # noqa: PLC0415
    x = arm.get_state_vector()
    sl = arm.state_vector_slices()["stimulation_state"]
    blk = x[sl].reshape(len(arm.channel_names), STATE_SIZE)
    k = STATE_COLUMNS["fatigue_A"]
    blk[:, k:k + 3] = states
    x[sl] = blk.ravel()
    arm.set_state_vector(x)


def hand_pulse(force_N: float, t_on: float, length_s: float = 0.5):
    """t -> (force, moment): force_N downward (-y, the base frame's vertical) for t_on <= t < t_on + length_s."""
    def load(t):
        on = t_on <= t < t_on + length_s
        return (0.0, -force_N if on else 0.0, 0.0), (0.0, 0.0, 0.0)
    return load


def movement_reference(arm, amplitude_deg: dict, duration: float, dt: float = 0.01, after_s: float = AFTER_S):
    """(time (T,), q_ref (T, ndof)): HOLD_S at rest, a minimum-jerk movement of duration s, after_s at its end."""
    q0 = arm.rest_posture.copy()
    q1 = q0.copy()
    for d, a in amplitude_deg.items():
        q1[arm.dof_index(d)] += math.radians(a)
    t = np.arange(0.0, HOLD_S + duration + after_s + 1e-9, dt)
    q, _, _ = fc.minimum_jerk(q0, q1, HOLD_S, duration, t)
    return t, q


def blana_trial(movement, fatigue_s: float = 0.0, disturbance_N: float = 0.0, gains: str = "pid", setup=None,
                after_s: float = AFTER_S, integral_limit: float | None = None):
    """One trial of (a): returns {"run": ControlRun, "rms_deg": the largest per-DOF RMS error, "max_deg": the largest
    error, both over the movement and the hold after it, "per_dof": ControlRun.error_deg, "infeasible": updates}.
    gains: "pid" (PIDParams.pole_placement of the measured lag) or "feedforward" (no feedback)."""
    name, amp, dur = movement
    arm, coding, tau = setup if setup is not None else _setup()
    plant = copy.deepcopy(arm)   # an independent Arm with the same settings (Arm.__deepcopy__)
    t, q = movement_reference(plant, amp, dur, after_s=after_s)
    params = fc.PIDParams.pole_placement(tau)
    if integral_limit is not None:
        params.integral_limit = float(integral_limit)
    if gains == "feedforward":
        params.kp = params.ki = params.kd = 0.0
    ctl = fc.FeedforwardPID(fc.model_arm(plant), coding, (t, q), params)
    plant.reset(q=q[0])
    if fatigue_s > 0:
        set_fatigue(plant, fatigue_states(plant, coding, fatigue_s))
    load = hand_pulse(disturbance_N, HOLD_S + 0.5 * dur) if disturbance_N else None
    run = fc.run_offline(plant, ctl, float(t[-1]), hold_s=HOLD_S, hand_load=load)
    per = run.error_deg(plant.dof_names, plant, t_from=HOLD_S)
    return {"run": run, "per_dof": per, "rms_deg": max(v[0] for v in per.values()),
            "max_deg": max(v[1] for v in per.values()), "infeasible": ctl.state.infeasible_updates,
            "fatigue": float(np.mean(run.fatigue[0])), "params": params}


def _setup():
    arm = weakened_arm()
    coding = fc.StimulationCoding.from_arm(arm)
    return arm, coding, fc.chain_time_constant(arm, coding)


def blana(out: Path | None = None, movements=None, conditions=None) -> list[dict]:
    """(a): every movement under every condition; prints the table docs/control.md gives, draws the figure."""
    setup = _setup()
    arm, coding, tau = setup
    p = fc.PIDParams.pole_placement(tau)
    print(f"coding: {coding.amplitude_A * 1e3:g} mA, {coding.frequency_Hz:g} Hz, fused level "
          f"{coding.fused.min():.3f}-{coding.fused.max():.3f} (steady_force_level)")
    print(f"(a) Blana 2009 feedforward + PID: stimulated-force lag {tau * 1e3:.0f} ms (chain_time_constant); gains "
          f"kp {p.kp:.3g} s^-2, ki {p.ki:.3g} s^-3, kd {p.kd:.3g} s^-1, preview {p.preview_s * 1e3:.0f} ms")
    rows = []
    for cond, fat, dist in (conditions or BLANA_CONDITIONS):
        for mv in (movements or BLANA_MOVEMENTS):
            r = blana_trial(mv, fat, dist, setup=setup)
            r.update(movement=mv[0], condition=cond)
            rows.append(r)
            print(f"| {cond} | {mv[0]} | {r['rms_deg']:.2f} | {r['max_deg']:.2f} | {r['fatigue']:.2f} | "
                  f"{r['infeasible']} |")
    # How long the slow integral needs: the two-joint movement at 0.52 fatigue, held 10 s after it instead of 1 s,
    # with the anti-windup bound at its default and at 1 rad s.
    if movements is None and conditions is None:
        for bound in (fc.PIDParams.pole_placement(tau).integral_limit, 1.0):
            r = blana_trial(BLANA_MOVEMENTS[-1], 20.0, setup=setup, after_s=10.0, integral_limit=bound)
            run = r["run"]
            errs = []
            for t_after in (1.0, 3.0, 6.0, 10.0):
                k = np.argmin(np.abs(run.time - (run.time[-1] - 10.0 + t_after)))
                errs.append(f"{t_after:g} s {np.degrees(np.abs(run.q[k] - run.q_ref[k])).max():.2f}")
            print(f"fatigue 20 s, {BLANA_MOVEMENTS[-1][0]}, integral bound {bound:g} rad s: largest error (deg) "
                  f"after the movement: " + ", ".join(errs))
        # The feedback's stiffness in torque terms, and what half the force lost asks of it, at that movement's end.
        t, q = movement_reference(arm, BLANA_MOVEMENTS[-1][1], BLANA_MOVEMENTS[-1][2])
        j = arm.dof_index("ELx")
        probe = fc.model_arm(arm)
        tau_el = float(np.asarray(probe.inverse_dynamics(q[-1]))[j])
        m_el = float(np.asarray(probe.mass_matrix(q[-1]))[j, j])
        print(f"elbow at that movement's end: moment {tau_el:.2f} N m, inertia {m_el:.4f} kg m^2; kp x inertia "
              f"{p.kp * m_el:.2f} N m/rad; half the moment / inertia {0.5 * abs(tau_el) / m_el:.1f} rad/s^2; "
              f"ki x bound {p.ki * p.integral_limit:.1f} rad/s^2")
        so = fc.ChannelStaticOptimizer(fc.model_arm(arm), coding)
        feas = []
        for d in (40, 50, 60, 70, 80, 90):
            qh = arm.rest_posture.copy()
            qh[j] += math.radians(d)
            ok = so.solve_levels(qh, np.zeros(arm.n_dofs), np.zeros(arm.n_dofs))[1].feasible
            feas.append(f"+{d} {'yes' if ok else 'no'}")
        print("static elbow holds (deg from rest) the weakened flexors can supply (ChannelStaticOptimizer): "
              + ", ".join(feas))
        ff = blana_trial(BLANA_MOVEMENTS[-1], 10.0, gains="feedforward", setup=setup)
        pid = [r for r in rows if r["condition"] == "fatigue 10 s" and r["movement"] == BLANA_MOVEMENTS[-1][0]]
        print(f"fatigue 10 s, {BLANA_MOVEMENTS[-1][0]}: feedforward alone RMS {ff['rms_deg']:.2f} / max "
              f"{ff['max_deg']:.2f} deg" + (f", with the PID {pid[0]['rms_deg']:.2f} / {pid[0]['max_deg']:.2f}"
                                            if pid else ""))
    if out is not None:
        _plot_blana(rows, Path(out) / "fes_blana_pid.png")
    return rows


def _plot_blana(rows, path):
    import matplotlib  # noqa: PLC0415
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: PLC0415
    from .arm import Arm  # noqa: PLC0415
    names = Arm("das2").dof_names
    pick = [r for r in rows if r["movement"] == BLANA_MOVEMENTS[-1][0]]
    fig, ax = plt.subplots(len(pick), 1, figsize=(8, 2.0 * len(pick) + 0.6), sharex=True)
    for a, r in zip(np.atleast_1d(ax), pick):
        run = r["run"]
        for d, c in (("GHy", "C0"), ("ELx", "C1")):
            j = names.index(d)
            a.plot(run.time, np.degrees(run.q[:, j]), color=c, label=f"{d}")
            a.plot(run.time, np.degrees(run.q_ref[:, j]), color=c, ls="--", lw=0.8)
        a.set_ylabel("deg")
        a.set_title(f"{r['condition']}: RMS {r['rms_deg']:.2f} deg, max {r['max_deg']:.2f} deg", fontsize=8)
        a.legend(fontsize=7, loc="lower right")
    np.atleast_1d(ax)[-1].set_xlabel("time (s); dashed: reference")
    fig.suptitle("(a) feedforward + PID (Blana 2009) on das2 + participant_A_FES, per-muscle FES", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    print(f"wrote {path}")


# ------------------------------------------------------------------------------------------ (b) Jagodnik 2010
#: Jagodnik & van den Bogert 2010 (J Biomech 43:1086, PMC3853125): reaching movements between random postures of
#: the shoulder and elbow, 2 s each; a trial fails if either joint is not within 5 deg of its target by its end; the
#: steady state starts when both are within 5 deg and stay there; Table 4 gives, for their 2-gain PD over 1000
#: movements: error 5.50 deg (generality), 7.51 (randomly weakened muscles, 122 failed), 6.18 (doubled mass),
#: steady-state error 1.17 / 4.59 / 1.55 deg, effort 25.1 / 17.3 / 34.5 N. Their error (eq. 5) and effort (eq. 6)
#: formulas and the cost's weight were not retrieved: ours are the mean over the trial of the mean |angle - target|
#: of the two moving joints (deg) and the mean muscle force (N, each muscle's elements summed, the 22 averaged).
JAGODNIK_PUBLISHED = {"generality": (5.50, 1.17, 25.10, 0), "weakened": (7.51, 4.59, 17.31, 122),
                      "added friction": (6.08, 4.06, 26.83, 14), "doubled mass": (6.18, 1.55, 34.50, 0)}
#: Table 4's footnote: "Added friction was 1.0 N m" (at their two joints, shoulder and elbow: our GHy and ELx). Its
#: law was not retrieved; ours is dry (Coulomb) friction of that size, stick and slip, as below.
JAGODNIK_FRICTION_NM = 1.0
PD_DOFS = ("GHy", "ELx")
#: The random postures' box (rad): shoulder GHy from rest (0.43) to 0.9, elbow from 0.5 (29 deg) to 1.4 (80 deg),
#: inside what the weakened flexors hold (a static hold at rest + 70 deg, 1.88 rad, is feasible: blana() prints it).
PD_BOX = {"GHy": (0.40, 0.90), "ELx": (0.50, 1.40)}
PD_TRIAL_S = 2.0
PD_HOLD_S = 0.5     # s supported at the start posture with the PD holding it, before the target steps
#: The cost's effort weight (deg per N): not retrieved from the paper; ours, so that effort only breaks ties
#: between gains of nearly equal error (at 20 N effort it weighs 0.2 deg).
PD_EFFORT_WEIGHT = 0.01
PD_START_GAINS = (2.0, 0.3)   # examples/fes_elbow_pd.py's kp (per rad) and kd (per rad/s): the search's start
PD_GAINS_FILE = Path(__file__).with_name("fes_pd_gains.json")
#: Random weakening of "weakened": every muscle's strength times U(WEAKEN_RANGE), one draw per muscle and trial
#: (Jagodnik's range not retrieved).
WEAKEN_RANGE = (0.5, 1.0)


def pd_movements(n: int, seed: int, rest) -> list:
    """n (start, target) posture pairs (ndof,) rad: GHy and ELx uniform in PD_BOX, the others at rest; pairs at
    least 10 deg apart in one joint."""
    rng = np.random.default_rng(seed)
    from .arm import Arm  # noqa: PLC0415
    names = Arm("das2").dof_names
    out = []
    while len(out) < n:
        pair = []
        for _ in range(2):
            q = np.array(rest, float)
            for d in PD_DOFS:
                q[names.index(d)] = rng.uniform(*PD_BOX[d])
            pair.append(q)
        if np.degrees(np.abs(pair[1] - pair[0])).max() >= 10.0:
            out.append(tuple(pair))
    return out


def elbow_weight_load(arm, q) -> np.ndarray:
    """(3,) N: the downward hand force that doubles the gravitational moment of the forearm and hand about the elbow
    at posture q (found from two inverse-dynamics calls: gravity's ELx moment, and a unit hand force's) -- "the arm's
    mass doubled" for the elbow; the segments' inertia and the upper arm's weight are not doubled (segment masses are
    the model's generated code)."""
    from .arm import Arm  # noqa: PLC0415
    probe = Arm(arm.model)
    j = probe.dof_index("ELx")
    tau_g = probe.inverse_dynamics(q, 0.0, 0.0, hand_load=((0, 0, 0), (0, 0, 0)))
    tau_1 = probe.inverse_dynamics(q, 0.0, 0.0, hand_load=((0, -1.0, 0), (0, 0, 0)))
    g = np.asarray(tau_g["tau_muscle"] if isinstance(tau_g, dict) else tau_g)[j]
    g1 = np.asarray(tau_1["tau_muscle"] if isinstance(tau_1, dict) else tau_1)[j]
    return np.array([0.0, -g / (g1 - g), 0.0])


def joint_friction(arm, friction_Nm: float = JAGODNIK_FRICTION_NM, dofs=PD_DOFS, iterations: int = 30,
                   refinements: int = 2):
    """A callable (t, q, qdot) -> (ndof,) N m for fes_control.run_offline's joint_moment: dry friction of at most
    friction_Nm N m at each of `dofs` (Jagodnik & van den Bogert 2010's added-friction test, Table 4: 1.0 N m), the
    time-stepping form of Coulomb friction (Stewart & Trinkle 1996; MuJoCo's joint frictionloss, a velocity-level
    constraint with box bounds). Each step it finds the moments a (|a_j| <= friction_Nm) for which the joints'
    velocity after the step, v(a) = v0 + G a, solves the friction law: v_j = 0 where |a_j| < friction_Nm (the joint
    sticks), a_j = -friction_Nm sign(v_j) otherwise (it slides against friction). v0 (the next velocity without
    friction) and G (its response to each friction moment) are measured by stepping a copy of the arm from its
    present state with the arm's own integrator, so a stiff implicit step (das3's girdle) is followed as the arm
    will take it; the law is the box-constrained mixed LCP of v0 + G a (G ~ h (M^-1)_FF, whose diagonal
    dominates enough for the sweeps to converge), solved by projected Gauss-Seidel (`iterations` sweeps), then re-centred `refinements` times on the velocity the
    step with the solved moments gives (the step is linear in a held moment only to O(h^2)). `arm` must be the Arm run_offline steps, with the moments other than the
    friction applied when this is called (run_offline does so); its excitation, stimulation and hand load are
    those of the coming step. ValueError for friction_Nm not finite and >= 0, or an unknown DOF (KeyError)."""
    friction_Nm = real_scalar(friction_Nm, "friction_Nm")
    if not math.isfinite(friction_Nm) or friction_Nm < 0:
        raise ValueError(f"friction_Nm must be finite and >= 0, got {friction_Nm}")
    cols = np.array([arm.dof_index(d) for d in dofs])
    scratch = copy.deepcopy(arm)
    n_free = cols.size
    probe_Nm = min(friction_Nm, 1.0)

    def next_velocity(x, moment):
        scratch.set_state_vector(x)
        scratch.set_applied_moment(moment)
        scratch.step()
        return scratch.qdot[cols].copy()

    def moment(t, q, qdot):
        out = np.zeros(arm.n_dofs)
        if friction_Nm == 0.0:
            return out
        x, base = arm.get_state_vector(), arm.applied_moment
        v0 = next_velocity(x, base)
        G = np.empty((n_free, n_free))
        for k, c in enumerate(cols):  # probes of at most 1 N m: the step is linear in a held moment to O(h^2)
            probe = base.copy()
            probe[c] += probe_Nm
            G[:, k] = (next_velocity(x, probe) - v0) / probe_Nm
        a = np.zeros(n_free)
        for refinement in range(refinements + 1):
            if refinement:  # the step's response to a is linear only to O(h^2): re-centre v0 on the step taken
                probe = base.copy()
                probe[cols] += a
                v0 = next_velocity(x, probe) - G @ a
            for _ in range(iterations):
                for i in range(n_free):
                    r = v0[i] + G[i] @ a - G[i, i] * a[i]
                    a[i] = np.clip(-r / G[i, i], -friction_Nm, friction_Nm)
        out[cols] = a
        return out
    return moment


def pd_trial(kp: float, kd: float, movement, setup, hand_force=None, strength_scale=None, friction_Nm=None) -> dict:
    """One reaching trial of (b): the PD holds the start for PD_HOLD_S (arm supported), then the target steps and
    PD_TRIAL_S s follow. friction_Nm: Coulomb friction at GHy and ELx (joint_friction), None for none. Returns
    error_deg, ss_error_deg (None if failed), effort_N, failed, run, and stick_fraction ({GHy, ELx: fraction of
    the trial's plant steps in which the friction held the joint below its bound}; None without friction)."""
    arm, coding, _ = setup
    start, target = movement
    plant = copy.deepcopy(arm)
    if strength_scale is not None:
        plant.strength = plant.strength * strength_scale
    plant.reset(q=start)
    ctl = fc.PDController(arm, coding, start, fc.PDParams(kp, kd), schedule=[(PD_HOLD_S, target)])
    load = None
    if hand_force is not None:
        load = lambda t: (tuple(hand_force), (0.0, 0.0, 0.0))  # noqa: E731
    cols = [plant.dof_index(d) for d in PD_DOFS]
    friction, sticking = None, []
    if friction_Nm is not None:
        law = joint_friction(plant, friction_Nm)

        def friction(t, q, qdot):  # records, per plant step of the trial, which joints stick (|a| below the bound)
            a = law(t, q, qdot)
            if t > PD_HOLD_S + 1e-9:
                sticking.append(np.abs(a[cols]) < friction_Nm * (1 - 1e-9))
            return a
    run = fc.run_offline(plant, ctl, PD_HOLD_S + PD_TRIAL_S, reference=lambda t: target if t >= PD_HOLD_S else start,
                         hold_s=PD_HOLD_S, hand_load=load, joint_moment=friction)
    sel = run.time > PD_HOLD_S + 1e-9
    err = np.degrees(np.abs(run.q[sel][:, cols] - target[cols]))   # (K, 2)
    within = np.all(err < 5.0, axis=1)
    # the steady state: from the first sample after which both joints stay within 5 deg
    bad = np.flatnonzero(~within)
    k0 = 0 if bad.size == 0 else bad[-1] + 1
    failed = k0 >= within.size
    n_muscles = len(plant.muscle_names)
    return {"error_deg": float(err.mean()), "ss_error_deg": None if failed else float(err[k0:].mean()),
            "effort_N": float(run.force_total[sel].mean() / n_muscles), "failed": bool(failed), "run": run,
            "stick_fraction": dict(zip(PD_DOFS, np.mean(sticking, axis=0))) if sticking else None}


def pd_cost(gains, movements, setup, weight=PD_EFFORT_WEIGHT) -> float:
    """The optimisation's cost: mean over movements of error_deg + weight * effort_N (failed trials count their
    error like the others: a trial that does not arrive has a large mean error)."""
    kp, kd = gains
    if kp <= 0 or kd < 0:
        return 1e6
    rs = [pd_trial(kp, kd, mv, setup) for mv in movements]
    return float(np.mean([r["error_deg"] + weight * r["effort_N"] for r in rs]))


def optimise_pd(n_train: int = 6, seed: int = 1, max_evaluations: int = 40, save: Path | None = PD_GAINS_FILE) -> dict:
    """(b)'s gains: Nelder-Mead (scipy.optimize.minimize) on (log kp, log kd) from PD_START_GAINS, minimising pd_cost
    over n_train random training movements (pd_movements(n_train, seed)); Jagodnik 2010 optimised theirs on a
    training set too (their optimiser and set size were not retrieved). Saves and returns {kp, kd, cost, ...}."""
    from scipy.optimize import minimize  # noqa: PLC0415
    setup = _setup()
    movements = pd_movements(n_train, seed, setup[0].rest_posture)
    history = []

    def f(x):
        c = pd_cost(np.exp(x), movements, setup)
        history.append((float(np.exp(x[0])), float(np.exp(x[1])), c))
        print(f"  kp {np.exp(x[0]):.4g} /rad, kd {np.exp(x[1]):.4g} s/rad: cost {c:.4f}", flush=True)
        return c

    res = minimize(f, np.log(PD_START_GAINS), method="Nelder-Mead",
                   options={"maxfev": max_evaluations, "xatol": 0.02, "fatol": 0.01})
    kp, kd = np.exp(res.x)
    out = {"kp_per_rad": float(kp), "kd_s_per_rad": float(kd), "cost": float(res.fun), "evaluations": len(history),
           "procedure": "scipy.optimize.minimize Nelder-Mead on (log kp, log kd), start "
                        f"{PD_START_GAINS}, maxfev {max_evaluations}, xatol 0.02, fatol 0.01",
           "cost_definition": "mean over training movements of mean |q - target| (deg, GHy and ELx) + "
                              f"{PD_EFFORT_WEIGHT} deg/N x mean muscle force (N)",
           "training": {"n": n_train, "seed": seed, "box_rad": PD_BOX, "trial_s": PD_TRIAL_S, "hold_s": PD_HOLD_S},
           "command": "python -m armrt.fes_controllers_validation optimise-pd"}
    if save is not None:
        Path(save).write_text(json.dumps(out, indent=1) + "\n")
        print(f"wrote {save}")
    return out


def saved_pd_gains() -> tuple[float, float]:
    """(kp, kd) from PD_GAINS_FILE (optimise_pd's result). FileNotFoundError naming the command that makes it."""
    if not PD_GAINS_FILE.exists():
        raise FileNotFoundError(f"{PD_GAINS_FILE} missing: run python -m armrt.fes_controllers_validation optimise-pd")
    d = json.loads(PD_GAINS_FILE.read_text())
    return d["kp_per_rad"], d["kd_s_per_rad"]


def jagodnik(out: Path | None = None, n_test: int = 20, seed: int = 2, gains=None) -> dict:
    """(b): the saved gains on n_test random test movements (not the training set) in five conditions: generality
    (nominal), weakened (strength x U(WEAKEN_RANGE) per muscle), added friction (JAGODNIK_FRICTION_NM at GHy and ELx,
    joint_friction), doubled mass (elbow_weight_load), doubled mass and weakened. Prints the table docs/control.md
    gives beside Jagodnik 2010's Table 4."""
    setup = _setup()
    arm = setup[0]
    kp, kd = gains if gains is not None else saved_pd_gains()
    movements = pd_movements(n_test, seed, arm.rest_posture)
    rng = np.random.default_rng(seed + 100)
    muscle_of = np.zeros(arm.n_elements, int)
    for m, name in enumerate(arm.muscle_names):
        muscle_of[arm.indices(name)] = m
    conds = {}
    print(f"(b) Jagodnik 2010 PD, kp {kp:.4g} per rad, kd {kd:.4g} per rad/s, {n_test} test movements (seed {seed})")
    loads = [-elbow_weight_load(arm, mv[0])[1] for mv in movements]
    print(f"doubled mass: downward hand force {min(loads):.1f}-{max(loads):.1f} N (elbow_weight_load at each start)")
    for cond in ("generality", "weakened", "added friction", "doubled mass", "doubled mass + weakened"):
        rows = []
        for mv in movements:
            scale = rng.uniform(*WEAKEN_RANGE, len(arm.muscle_names))[muscle_of] if "weakened" in cond else None
            load = elbow_weight_load(arm, mv[0]) if "doubled" in cond else None
            friction = JAGODNIK_FRICTION_NM if cond == "added friction" else None
            rows.append(pd_trial(kp, kd, mv, setup, hand_force=load, strength_scale=scale, friction_Nm=friction))
        ok = [r for r in rows if not r["failed"]]
        # Which side of its target a failed trial ends on: below (q < target in the joint further off) is the
        # gravity side for both GHy (elevation) and ELx (flexion).
        below = 0
        for mv, r in zip(movements, rows):
            if r["failed"]:
                end = r["run"].q[-1]
                e = [end[arm.dof_index(d)] - mv[1][arm.dof_index(d)] for d in PD_DOFS]
                below += int(e[int(np.argmax(np.abs(e)))] < 0)
        conds[cond] = {"failed_below_target": below, "error_deg": float(np.mean([r["error_deg"] for r in rows])),
                       "ss_error_deg": float(np.mean([r["ss_error_deg"] for r in ok])) if ok else float("nan"),
                       "effort_N": float(np.mean([r["effort_N"] for r in rows])),
                       "failed": sum(r["failed"] for r in rows), "n": len(rows), "example": rows[0]}
        c = conds[cond]
        pub = JAGODNIK_PUBLISHED.get(cond)
        pub_s = f"{pub[0]:.2f} | {pub[1]:.2f} | {pub[2]:.1f} | {pub[3]} of 1000" if pub else "- | - | - | -"
        print(f"| {cond} | {c['error_deg']:.2f} | {c['ss_error_deg']:.2f} | {c['effort_N']:.1f} | "
              f"{c['failed']} of {c['n']} | {pub_s} |  (failed trials ending below their target: "
              f"{c['failed_below_target']})")
        if c["example"]["stick_fraction"]:
            print("   the figure's trial: joints stick (friction below its bound) for "
                  + ", ".join(f"{d} {100 * x:.0f} %" for d, x in c["example"]["stick_fraction"].items())
                  + " of the plant steps")
    if out is not None:
        _plot_jagodnik(conds, Path(out) / "fes_jagodnik_pd.png", arm)
    return conds


def _plot_jagodnik(conds, path, arm):
    import matplotlib  # noqa: PLC0415
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: PLC0415
    fig, ax = plt.subplots(len(conds), 1, figsize=(8, 1.9 * len(conds) + 0.6), sharex=True)
    for a, (cond, c) in zip(ax, conds.items()):
        run = c["example"]["run"]
        for d, col in (("GHy", "C0"), ("ELx", "C1")):
            j = arm.dof_index(d)
            a.plot(run.time, np.degrees(run.q[:, j]), color=col, label=d)
            a.plot(run.time, np.degrees(run.q_ref[:, j]), color=col, ls="--", lw=0.8)
        a.set_ylabel("deg")
        a.set_title(f"{cond}: mean error over {c['n']} movements {c['error_deg']:.2f} deg, failed {c['failed']}",
                    fontsize=8)
        a.legend(fontsize=7, loc="lower right")
    ax[-1].set_xlabel("time (s); dashed: target (first test movement)")
    fig.suptitle("(b) two-gain PD (Jagodnik & van den Bogert 2010), optimised gains", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    print(f"wrote {path}")


# ------------------------------------------------------------------------------------------ over UDP
def jagodnik_udp_controller(arm, coding, t_start: float, lead_s: float):
    """(b) for examples/fes_controllers_udp.py: the saved gains hold the runner's start posture (rest) for lead_s s
    of simulated time from t_start, then reach the first test movement's target; (controller, dofs, t_from, t_end)."""
    kp, kd = saved_pd_gains()
    target = pd_movements(1, 2, arm.rest_posture)[0][1]
    ctl = fc.PDController(arm, coding, arm.rest_posture, fc.PDParams(kp, kd), schedule=[(t_start + lead_s, target)])
    return ctl, list(PD_DOFS), t_start + lead_s, t_start + lead_s + PD_TRIAL_S


def posture_udp_controller(arm, coding, tau, t_start: float, lead_s: float, limit: float = 0.03,
                           duration: float = 5.0):
    """(c) for examples/fes_controllers_udp.py: the posture of posture_trial without the hand weight (the runner
    takes no hand load; unconstrained, that hold's GHstab is 0.038) and GHstab <= limit; (controller, dofs, t_from,
    t_end)."""
    q = arm.rest_posture.copy()
    q[arm.dof_index("GHy")] += POSTURE_GHY_RAD
    t = np.array([t_start, t_start + 1.0, t_start + 2.0, t_start + lead_s + duration + 1.0])
    ctl = fc.FeedforwardPID(fc.model_arm(arm), coding, (t, np.tile(q, (4, 1))),
                            fc.PIDParams.pole_placement(tau, gh_stab_max=limit))
    return ctl, ["GHy"], t_start + lead_s, t_start + lead_s + duration


# ------------------------------------------------------------------------------------------ (c) posture, GHstab limit
#: (c): the humerus held elevated POSTURE_GHY_RAD above rest (examples/posture_gh_limit.py's posture) with a
#: POSTURE_HAND_KG weight in the hand, for POSTURE_S s under stimulation with Ding fatigue, by FeedforwardPID whose
#: inverse model keeps GHstab <= the limit (ChannelStaticOptimizer's glenoid polygon). The limits 0.08, 0.06, 0.04
#: are below the unconstrained hold's GHstab (0.095), so that they bind (the example's 0.2-0.1 do not bind with this
#: lighter load). The GHstab reported is the engine's, of the simulated arm, every 10 ms.
POSTURE_GHY_RAD = 0.3
POSTURE_HAND_KG = 0.5
POSTURE_S = 20.0
POSTURE_LIMITS = (None, 0.08, 0.06, 0.04)
G = 9.81


def posture_trial(limit, duration: float = POSTURE_S, setup=None, hand_kg: float = POSTURE_HAND_KG) -> dict:
    """One posture hold of (c): returns rms_deg / max_deg (largest per-DOF error after the first second),
    gh_stab_max (the simulated arm's), model_gh_stab_max (the inverse model's), infeasible updates, run."""
    arm, coding, tau = setup if setup is not None else _setup()
    plant = copy.deepcopy(arm)
    q = plant.rest_posture.copy()
    q[plant.dof_index("GHy")] += POSTURE_GHY_RAD
    load = (0.0, -hand_kg * G, 0.0)
    plant.set_hand_load(load)
    plant.reset(q=q)
    t = np.array([0.0, 1.0, 2.0, duration + 1.0])
    ctl = fc.FeedforwardPID(fc.model_arm(plant), coding, (t, np.tile(q, (4, 1))),
                            fc.PIDParams.pole_placement(tau, gh_stab_max=limit))
    model_gh = []
    orig = ctl.update

    def update(t_, q_, qd_):
        cmd = orig(t_, q_, qd_)
        model_gh.append(ctl.state.gh_stab)
        return cmd
    ctl.update = update
    run = fc.run_offline(plant, ctl, duration, hold_s=0.5)
    per = run.error_deg(plant.dof_names, plant, t_from=1.0)
    return {"run": run, "rms_deg": max(v[0] for v in per.values()), "max_deg": max(v[1] for v in per.values()),
            "gh_stab_max": float(run.gh_stab[run.time >= 1.0].max()), "model_gh_stab_max": float(np.max(model_gh)),
            "infeasible": ctl.state.infeasible_updates, "fatigue_end": float(run.fatigue[-1].max()), "limit": limit}


def posture(out: Path | None = None, duration: float = POSTURE_S, limits=POSTURE_LIMITS) -> list:
    """(c) for each limit; prints the table docs/control.md gives and draws the figure."""
    setup = _setup()
    rows = []
    print(f"(c) posture GHy +{POSTURE_GHY_RAD} rad with {POSTURE_HAND_KG} kg in the hand for {duration:g} s")
    free = posture_trial(None, 2.0, setup, hand_kg=0.0)
    print(f"without the hand weight (the UDP run's case), unconstrained, 2 s: largest GHstab {free['gh_stab_max']:.4f}")
    for lim in limits:
        r = posture_trial(lim, duration, setup)
        rows.append(r)
        print(f"| {'none' if lim is None else lim} | {r['gh_stab_max']:.4f} | {r['model_gh_stab_max']:.4f} | "
              f"{r['rms_deg']:.2f} | {r['max_deg']:.2f} | {r['fatigue_end']:.2f} | {r['infeasible']} |")
    if out is not None:
        import matplotlib  # noqa: PLC0415
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt  # noqa: PLC0415
        fig, ax = plt.subplots(2, 1, figsize=(8, 5), sharex=True)
        j = setup[0].dof_index("GHy")
        for k, r in enumerate(rows):
            lab = "no limit" if r["limit"] is None else f"GHstab <= {r['limit']}"
            ax[0].plot(r["run"].time, r["run"].gh_stab, color=f"C{k}", label=lab)
            if r["limit"] is not None:
                ax[0].axhline(r["limit"], color=f"C{k}", ls=":", lw=0.8)
            ax[1].plot(r["run"].time, np.degrees(r["run"].q[:, j] - r["run"].q_ref[:, j]), color=f"C{k}")
        ax[0].set_ylabel("GHstab (simulated)")
        ax[0].legend(fontsize=7)
        ax[1].set_ylabel("GHy error (deg)")
        ax[1].set_xlabel("time (s)")
        fig.suptitle(f"(c) posture holding under FES with GHstab limits (GHy +{POSTURE_GHY_RAD} rad, "
                     f"{POSTURE_HAND_KG} kg in the hand)", fontsize=9)
        fig.tight_layout()
        path = Path(out) / "fes_posture_gh_limit.png"
        fig.savefig(path, dpi=100)
        plt.close(fig)
        print(f"wrote {path}")
    return rows


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("what", nargs="?", default="all", choices=["all", "blana", "optimise-pd", "jagodnik", "posture"])
    ap.add_argument("--out", default=None, help="folder for the figures (none: no figures)")
    a = ap.parse_args(argv)
    out = Path(a.out) if a.out else None
    if out is not None:
        out.mkdir(parents=True, exist_ok=True)
    if a.what in ("all", "blana"):
        blana(out)
    if a.what == "optimise-pd":
        optimise_pd()
    if a.what in ("all", "jagodnik"):
        jagodnik(out)
    if a.what in ("all", "posture"):
        posture(out)


if __name__ == "__main__":
    main()
