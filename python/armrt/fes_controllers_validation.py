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
import json
import math
from pathlib import Path

import numpy as np

from . import fes_control as fc

PROFILE = "participant_A_FES"
HOLD_S = 1.0    # s the arm is supported at the start while the stimulation builds up (run_offline hold_s)
AFTER_S = 1.0   # s of holding the end posture after the movement, inside the error window

#: (a) Blana 2009: "goal-oriented movements of varying amplitudes and durations" of the shoulder and elbow. Their
#: exact set was not retrieved: these are minimum-jerk movements (Flash & Hogan 1985) from the rest posture, of two
#: amplitudes and two durations per joint and one of both joints, within what the weakened elbow flexors can hold
#: (elbow flexion above about +70 deg from rest is infeasible for them: ChannelStaticOptimizer).
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


def movement_reference(arm, amplitude_deg: dict, duration: float, dt: float = 0.01):
    """(time (T,), q_ref (T, ndof)): HOLD_S at rest, a minimum-jerk movement of duration s, AFTER_S at its end."""
    q0 = arm.rest_posture.copy()
    q1 = q0.copy()
    for d, a in amplitude_deg.items():
        q1[arm.dof_index(d)] += math.radians(a)
    t = np.arange(0.0, HOLD_S + duration + AFTER_S + 1e-9, dt)
    q, _, _ = fc.minimum_jerk(q0, q1, HOLD_S, duration, t)
    return t, q


def blana_trial(movement, fatigue_s: float = 0.0, disturbance_N: float = 0.0, gains: str = "pid", setup=None):
    """One trial of (a): returns {"run": ControlRun, "rms_deg": the largest per-DOF RMS error, "max_deg": the largest
    error, both over the movement and the hold after it, "per_dof": ControlRun.error_deg, "infeasible": updates}.
    gains: "pid" (PIDParams.pole_placement of the measured lag) or "feedforward" (no feedback)."""
    name, amp, dur = movement
    arm, coding, tau = setup if setup is not None else _setup()
    plant = arm.copy() if hasattr(arm, "copy") else __import__("copy").deepcopy(arm)
    t, q = movement_reference(plant, amp, dur)
    params = fc.PIDParams.pole_placement(tau)
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


if __name__ == "__main__":
    main()
