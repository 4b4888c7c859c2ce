"""Two minutes of holding the elbow at 90 deg by FES: a PI controller on the pulse width of three intramuscular
electrodes in participant A's elbow flexors (biceps, brachialis, brachioradialis), at a fixed 20 mA and 20 Hz.
As the stimulated fibres fatigue (Ding et al. 2003), the controller raises the pulse width to keep the angle,
until recruitment saturates and the forearm starts to drop.

    python examples/fes_elbow_hold_pi.py                       # writes fes_elbow_hold_pi.png, prints the numbers
    python examples/fes_elbow_hold_pi.py --out docs/figures/fes_elbow_hold_pi --duration 120

Why pulse width: implanted systems (the Cleveland FES systems the paper's group builds on) hold the amplitude at
about 20 mA and modulate the pulse width (docs/fes.md "Recruitment", where the 20 mA saturation is marked an
assumption); at 20 mA recruitment starts at 37.5 us (the Weiss-Lapicque shift of the 5 mA threshold at 200 us,
chronaxie 0.45 ms) and saturates at 200 us.
Why 20 Hz: the lowest rate at which Ding 2003's force fuses (ripple below 5 %, docs/fes.md validation table),
so the angle does not tremble and the fibres fire no faster than needed.

The arm is participant_A_FES (models/participant_A_FES.json) with the file's maxact: the flexors' caps
(0.12-0.42) are the participant's measured maximum voluntary excitations, and the engine caps stimulation at
max_activation as it caps excitation, so stimulation here reaches no more than the participant's own best
effort. The participant's shipped map stimulates the triceps (stimulation="default"); this example installs
its own flexor map, as a lab testing flexor electrodes would.
"""
import argparse
from pathlib import Path

import numpy as np

import armrt

MODEL = Path(__file__).resolve().parents[1] / "models" / "participant_A_FES.json"
FLEXOR_MAP = {"fatigue": True, "channels": [
    {"name": "biceps", "kind": "intramuscular", "elements": ["bicl", "bicb"]},
    {"name": "brachialis", "kind": "intramuscular", "elements": ["brachialis"]},
    {"name": "brachiorad", "kind": "intramuscular", "elements": ["brachiorad"]},
]}
AMPLITUDE_A = 0.020       # held: the device's maximum (docs/fes.md "Safety")
FREQUENCY_HZ = 20.0
PW_MAX_S = 255e-6         # the device's pulse-width limit; recruitment already saturates at 200 us
PW_SATURATED_S = 200e-6   # the intramuscular map's reference pulse width: R = 1 at 20 mA
CONTROL_DT = 0.01         # s: the controller runs at 100 Hz
# Gains: without a derivative term the loop (forearm inertia, the muscles' ~80 ms force lag) limit-cycles at
# 400/600 us; these are the largest of a coarse sweep that settle to a 0.1 deg peak-to-peak error.
KP = 150e-6               # s of pulse width per rad of elbow error
KI = 200e-6               # s of pulse width per rad s
CALIBRATION_S = 20.0


def holding_pulse_width(target_deg=90.0, kp=KP, ki=KI, model=MODEL):
    """s: the pulse width that holds the rested arm at target_deg, found as a lab finds it before a trial:
    the same controller run for CALIBRATION_S on unfatiguing muscle, its last 5 s averaged."""
    r = run(CALIBRATION_S, target_deg, kp, ki, model, fatigue=False, start_pulse_width=0.0)
    return float(r["pulse_width"][r["t"] > CALIBRATION_S - 5.0].mean())


def run(duration=120.0, target_deg=90.0, kp=KP, ki=KI, model=MODEL, fatigue=True, start_pulse_width=None):
    """Holds the elbow at target_deg for `duration` s, from rest with the elbow at the target and the
    controller's integral at start_pulse_width (s; None: holding_pulse_width(), so the trial starts without a
    drop). Returns time (s), elbow angle (rad), pulse width (s), recruitment (channels), fatigue 1 - A/A_rest
    (channels), all sampled every CONTROL_DT, and the target (rad)."""
    if start_pulse_width is None:
        start_pulse_width = holding_pulse_width(target_deg, kp, ki, model)
    arm = armrt.Arm(str(model), stimulation=dict(FLEXOR_MAP, fatigue=fatigue))
    el = arm.dof_index("ELx")
    q = arm.rest_posture.copy()
    q[el] = np.radians(target_deg)
    arm.reset(q=q)
    target = q[el]
    steps = int(round(CONTROL_DT / arm.dt))
    names = arm.channel_names
    integral = start_pulse_width
    n = int(round(duration / CONTROL_DT))
    out = {k: np.empty(n) for k in ("t", "elbow", "pulse_width")}
    out["recruitment"], out["fatigue"] = np.empty((n, len(names))), np.empty((n, len(names)))
    for i in range(n):
        e = target - arm.q[el]
        u = integral + kp * e
        pw = float(np.clip(u, 0.0, PW_MAX_S))
        if u == pw or (u > PW_MAX_S and e < 0) or (u < 0 and e > 0):   # no wind-up at the limits
            integral += ki * e * CONTROL_DT
        arm.set_stimulation({c: (pw, AMPLITUDE_A, FREQUENCY_HZ) for c in names})
        arm.step(steps)
        out["t"][i], out["elbow"][i], out["pulse_width"][i] = arm.time, arm.q[el], pw
        out["recruitment"][i] = [arm.recruitment_fraction(c, pw, AMPLITUDE_A) for c in names]
        out["fatigue"][i] = [arm.fatigue[c] for c in names]
    out["target"] = target
    out["channels"] = names
    out["start_pulse_width"] = start_pulse_width
    return out


def summary(r, settle_s=3.0, tolerance_deg=2.0):
    """The numbers docs/fes.md reports: pulse width at 10 s steps, when recruitment saturates (first time the
    pulse width reaches 200 us), when the elbow first drops more than tolerance_deg below the target after
    settling, and the largest error while not saturated."""
    t, err = r["t"], np.degrees(r["target"] - r["elbow"])
    sat = np.flatnonzero((t > settle_s) & (r["pulse_width"] >= PW_SATURATED_S))
    t_sat = float(t[sat[0]]) if sat.size else None
    lost = np.flatnonzero((t > settle_s) & (err > tolerance_deg))
    t_lost = float(t[lost[0]]) if lost.size else None
    held = (t > settle_s) & (t < (t_sat if t_sat is not None else np.inf))
    return {"saturation_s": t_sat, "lost_s": t_lost,
            "max_error_unsaturated_deg": float(np.abs(err[held]).max()) if held.any() else None,
            "pulse_width_us": {int(s): float(1e6 * np.interp(s, t, r["pulse_width"]))
                               for s in np.arange(10, t[-1] + 1e-9, 10)},
            "fatigue_end": dict(zip(r["channels"], map(float, r["fatigue"][-1])))}


def plot(r, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    s = summary(r)
    fig, ax = plt.subplots(3, 1, figsize=(8, 7), sharex=True)
    ax[0].plot(r["t"], np.degrees(r["elbow"]))
    ax[0].axhline(np.degrees(r["target"]), color="0.6", lw=0.8)
    ax[0].set_ylabel("elbow flexion (deg)")
    ax[1].plot(r["t"], 1e6 * r["pulse_width"])
    ax[1].axhline(1e6 * PW_SATURATED_S, color="C3", lw=0.8, ls="--")
    ax[1].text(r["t"][0], 1e6 * PW_SATURATED_S, " recruitment saturates (200 us at 20 mA)", fontsize=7,
               va="bottom", color="C3")
    ax[1].set_ylabel("pulse width (us)")
    for k, c in enumerate(r["channels"]):
        ax[2].plot(r["t"], r["fatigue"][:, k], label=c)
    ax[2].set_ylabel("fatigue 1 - A/A_rest")
    ax[2].set_xlabel("time (s)")
    ax[2].legend(fontsize=8)
    for a in ax:
        if s["saturation_s"] is not None:
            a.axvline(s["saturation_s"], color="C3", lw=0.8, ls=":")
    ax[0].set_title("participant_A_FES: PI on pulse width (20 mA, 20 Hz) holding the elbow at 90 deg with the "
                    "flexors", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--duration", type=float, default=120.0, help="s (default 120)")
    p.add_argument("--target", type=float, default=90.0, help="elbow angle to hold, deg (default 90)")
    p.add_argument("--out", default="fes_elbow_hold_pi", help="figure path without .png")
    args = p.parse_args(argv)
    r = run(args.duration, args.target)
    s = summary(r)
    plot(r, f"{args.out}.png")
    sat = f"{s['saturation_s']:.1f} s" if s["saturation_s"] is not None else f"not within {args.duration:g} s"
    lost = f"{s['lost_s']:.1f} s" if s["lost_s"] is not None else f"not within {args.duration:g} s"
    print(f"recruitment saturates (pulse width 200 us): {sat}; elbow more than 2 deg below the target: {lost}")
    print(f"holding pulse width of the rested arm (calibration): {1e6 * r['start_pulse_width']:.1f} us")
    print(f"largest elbow error while not saturated (after 3 s): {s['max_error_unsaturated_deg']:.2f} deg")
    print("pulse width (us) at " + ", ".join(f"{k} s {v:.0f}" for k, v in s["pulse_width_us"].items()))
    print("fatigue at the end: " + ", ".join(f"{k} {v:.3f}" for k, v in s["fatigue_end"].items()))
    print(f"wrote {args.out}.png")
    return r


if __name__ == "__main__":
    main()
