"""The stimulation chain's validation runs (docs/fes.md "Validation against published behaviour" and
"Endurance at 20 % MVC"), as functions that return numbers and one script that draws every figure:

    python -m armrt.fes_validation --out docs/figures     # fes_twitch.png, fes_force_frequency.png,
                                                          # fes_recruitment.png, fes_fatigue_recovery.png,
                                                          # fes_endurance.png; numbers on stdout

Every run is on das2 (the chain does not depend on the model) with Ding et al. 2003's parameters, the
engine's defaults (docs/fes.md "Equations and parameters"); nothing here is fitted to a published figure.

Endurance (after PMC6370345, its protocol as the abstract gives it): hold 20 % of the maximal force
with feedback-controlled 25 Hz stimulation until it can no longer be held. What the abstract does not give
(the per-electrode rate, the controller, the fraction of the muscle one electrode reaches) is a parameter of
`endurance`, and docs/fes.md says which value each figure uses and why.
"""
from __future__ import annotations

import argparse
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import stimulation as _stimulation
from .arm import Arm

FORCE = _stimulation.STATE_COLUMNS["force"]
# Intramuscular recruitment (docs/fes.md table): 5 mA threshold, 20 mA saturation at 200 us.
PW_IM = 200e-6
AMP_MAX_IM = 0.020
# Endurance protocol (PMC6370345 abstract): 20 % of maximal voluntary force, 25 Hz.
TARGET = 0.20
FREQUENCY_HZ = 25.0
# Clinical endurance, mean +- SD (PMC6370345 abstract), s.
CLINICAL = {"one": (84.0, 19.0), "four": (232.0, 123.0)}


def _surface_arm(fatigue: bool) -> Arm:
    """das2 with one surface channel on bicl: a surface stimulator allows the 100 Hz the curves need."""
    return Arm("das2", stimulation={"fatigue": fatigue, "channels": [
        {"name": "biceps", "kind": "surface", "elements": ["bicl"]}]})


def _force_trace(arm: Arm, steps: int, channel: int = 0) -> np.ndarray:
    """(steps,) the channel's force level f = F / F_ref, read before each 1 ms step."""
    out = np.empty(steps)
    for i in range(steps):
        out[i] = arm.stimulation_state[channel, FORCE]
        arm.step(1)
    return out


def twitch(duration: float = 0.4) -> dict:
    """One saturating pulse at t = 0: time (s), force level f (dimensionless), time to peak (s) and
    half-relaxation time after the peak (s). Ding 2003's model: 78.4 ms and about 71 ms (docs/fes.md)."""
    arm = _surface_arm(fatigue=False)
    arm.set_stimulation({"biceps": (400e-6, 0.1, 0.0)})
    arm.queue_pulses("biceps", [0.0])
    n = int(round(duration / arm.dt))
    f = _force_trace(arm, n)
    peak = int(np.argmax(f))
    half = peak + int(np.argmax(f[peak:] < f[peak] / 2))
    return {"time": arm.dt * np.arange(n), "force": f, "time_to_peak_s": peak * arm.dt,
            "half_relaxation_s": (half - peak) * arm.dt}


def force_frequency(frequencies=(5, 10, 15, 20, 25, 30, 40, 50, 60, 80, 100), train_s: float = 1.0) -> dict:
    """Mean force level over the last 0.3 s of a 1 s saturating train per frequency (Hz), relative to
    100 Hz, and the ripple (max - min) / max over the same window."""
    mean, ripple = [], []
    for hz in frequencies:
        arm = _surface_arm(fatigue=False)
        arm.set_stimulation({"biceps": (400e-6, 0.1, float(hz))})
        f = _force_trace(arm, int(round(train_s / arm.dt)))[-300:]
        mean.append(f.mean())
        ripple.append((f.max() - f.min()) / f.max())
    mean = np.array(mean)
    ref = mean[list(frequencies).index(100)] if 100 in frequencies else mean.max()
    return {"frequency_Hz": np.array(frequencies, float), "relative": mean / ref, "ripple": np.array(ripple)}


def recruitment_curve(pulse_widths=(50e-6, 100e-6, 200e-6, 255e-6), amplitudes=None) -> dict:
    """Recruited fraction R (0-1) of an intramuscular channel against amplitude (A), one row per pulse
    width (s): the Weiss-Lapicque shift of the threshold and the linear ramp (docs/fes.md "Recruitment")."""
    amplitudes = np.linspace(0.0, AMP_MAX_IM, 81) if amplitudes is None else np.asarray(amplitudes, float)
    arm = Arm("das2", stimulation="per_muscle")
    r = np.array([[arm.recruitment_fraction("bicl", pw, a) for a in amplitudes] for pw in pulse_widths])
    return {"amplitude_A": amplitudes, "pulse_width_s": np.array(pulse_widths), "recruitment": r}


def fatigue_recovery(stimulate_s: float = 60.0, rest_s: float = 60.0, hz: float = 33.0) -> dict:
    """Continuous saturating stimulation at `hz`, rest, then a 1 s test train: the force level and Â =
    A / A_rest over time, and the peaks relative to the first second's. Ding 2003's model: 0.233 after
    60 s at 33 Hz, 0.697 after 60 s of rest (docs/fes.md)."""
    arm = _surface_arm(fatigue=True)
    a_col = _stimulation.STATE_COLUMNS["fatigue_A"]
    pieces, a_hat = [], []
    for hz_now, secs in ((hz, stimulate_s), (0.0, rest_s), (hz, 1.0)):
        arm.set_stimulation({"biceps": (400e-6, 0.1, hz_now)})
        for _ in range(int(round(secs / 0.01))):   # Â sampled every 10 ms: it moves on the 127 s scale
            pieces.append(_force_trace(arm, 10))
            a_hat.append(arm.stimulation_state[0, a_col])
    f = np.concatenate(pieces)
    n1, n2 = int(round(stimulate_s / arm.dt)), int(round((stimulate_s + rest_s) / arm.dt))
    f0 = f[:1000].max()
    return {"time": arm.dt * np.arange(len(f)), "force": f, "a_time": 0.01 * (1 + np.arange(len(a_hat))),
            "a_hat": np.array(a_hat), "end_of_stimulation": f[n1 - 1000:n1].max() / f0,
            "after_rest": f[n2:].max() / f0}


@dataclass
class EnduranceRun:
    """One endurance trial: what was held and for how long. Times in s, force as the muscle's activation
    (its force relative to Fmax in an isometric contraction at optimal length), amplitude in A."""
    label: str
    electrodes: int
    reach: float               # fraction of the muscle's fibres one electrode recruits at saturation
    per_electrode_Hz: float
    endurance_s: float | None  # None: still held at max_duration
    saturation_s: float | None  # first time the amplitude reached its maximum
    time: np.ndarray
    force: np.ndarray
    amplitude: np.ndarray


def endurance(electrodes: int = 1, reach: float = 1.0, rotate: bool = False, target: float = TARGET,
              max_duration: float = 600.0, muscle: str = "brachialis", ki: float = 0.04, kp: float = 0.005,
              label: str | None = None) -> EnduranceRun:
    """Holds `target` (fraction of the maximal force) on `muscle` of das2 with `electrodes` intramuscular
    channels, each reaching a disjoint `reach` of the muscle's fibres (weight `reach`; electrodes x reach
    <= 1), all at one amplitude set by a PI controller every 40 ms (one 25 Hz period) at 200 us pulse width.

    rotate=False: every electrode at 25 Hz. rotate=True: a carousel, each electrode at 25/electrodes Hz,
    started 40 ms after the one before, so the muscle receives 25 Hz in all (sequential stimulation).
    Endurance: the time at which, with the amplitude at its 20 mA maximum, the force's 1 s mean falls below
    95 % of the target. ki (A per unit force per s) and kp (A per unit force) bring a rested muscle to the
    target within about 5 s without overshoot and hold it within 2 % until the last seconds before
    saturation, when the PI lags the fast-rising amplitude (force down to 0.189 at reach 0.5).
    Raises ValueError for electrodes x reach > 1 (the electrodes would share fibres the map counts twice)."""
    if electrodes < 1 or not (0 < reach <= 1) or electrodes * reach > 1 + 1e-12:
        raise ValueError(f"{electrodes} electrodes each reaching {reach} of the muscle: need 0 < reach and "
                         "electrodes x reach <= 1 (disjoint fibre populations)")
    hz = FREQUENCY_HZ / electrodes if rotate else FREQUENCY_HZ
    period = 1.0 / FREQUENCY_HZ
    chans = [{"name": f"electrode{k + 1}", "kind": "intramuscular", "elements": {muscle: reach}}
             for k in range(electrodes)]
    arm = Arm("das2", stimulation={"channels": chans})
    idx = arm.indices(muscle)
    names = arm.channel_names
    sub = int(round(period / arm.dt / 4))
    for k, name in enumerate(names):           # the carousel's phases: electrode k fires k periods later
        arm.set_stimulation({name: (PW_IM, 0.0, hz)})
        if rotate and k < len(names) - 1:
            arm.step(4 * sub)
    integral, t, f_out, a_out = 0.0, [], [], []
    window = int(round(1.0 / period))
    endured = saturated = None
    while arm.time < max_duration:
        level = 0.0
        for _ in range(4):                      # the force averaged over the period the controller acts on
            arm.step(sub)
            level += float(np.mean(arm.activation[idx])) / 4
        e = target - level
        u = integral + ki * e * period + kp * e
        amp = float(np.clip(u, 0.0, AMP_MAX_IM))
        if u == amp or (u > AMP_MAX_IM and e < 0) or (u < 0 and e > 0):   # no wind-up at the limits
            integral += ki * e * period
        arm.set_stimulation({c: (PW_IM, amp, hz) for c in names})
        t.append(arm.time)
        f_out.append(level)
        a_out.append(amp)
        if saturated is None and amp >= AMP_MAX_IM:
            saturated = arm.time
        if amp >= AMP_MAX_IM and len(f_out) > window and np.mean(f_out[-window:]) < 0.95 * target:
            endured = arm.time
            break
    return EnduranceRun(label or f"{electrodes} electrode{'s' if electrodes > 1 else ''}, reach {reach:g}"
                        + (", rotating" if rotate else ""), electrodes, reach, hz, endured, saturated,
                        np.array(t), np.array(f_out), np.array(a_out))


def endurance_set(max_duration: float = 600.0, reaches=(1.0, 0.8, 0.6, 0.5, 0.4, 0.3)) -> dict:
    """The runs docs/fes.md reports: one electrode at each reach in `reaches`, and four electrodes reaching a
    quarter each (the whole muscle), at 25 Hz each and as a 4 x 6.25 Hz carousel."""
    one = [endurance(1, r, max_duration=max_duration) for r in reaches]
    four = [endurance(4, 0.25, rotate=False, max_duration=max_duration, label="4 electrodes, 25 Hz each"),
            endurance(4, 0.25, rotate=True, max_duration=max_duration, label="4 electrodes, rotating 4 x 6.25 Hz")]
    return {"one": one, "four": four}


# ---------------------------------------------------------------------------------------------- figures
def _plt():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def _save(plt, fig, path: Path) -> None:
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_twitch(res: dict, path: Path) -> None:
    plt = _plt()
    fig, ax = plt.subplots(figsize=(6, 3.4))
    ax.plot(1e3 * res["time"], res["force"], lw=1.6)
    ttp = res["time_to_peak_s"]
    ax.axvline(1e3 * ttp, color="0.6", lw=0.8)
    ax.set_xlabel("time after the pulse (ms)")
    ax.set_ylabel("force level f = F / F_ref")
    ax.set_title(f"Twitch (Ding 2003 parameters): time to peak {1e3 * ttp:.0f} ms, half-relaxation "
                 f"{1e3 * res['half_relaxation_s']:.0f} ms\nDing 2003 model 78.4 ms; human motor units median "
                 "58 ms (47-102), PMC1779696", fontsize=8)
    _save(plt, fig, path)


def plot_force_frequency(res: dict, path: Path) -> None:
    plt = _plt()
    fig, ax = plt.subplots(figsize=(6, 3.6))
    ax.plot(res["frequency_Hz"], res["relative"], "o-", label="armrt (Ding 2003 parameters)")
    ding = {10: 0.53, 20: 0.76, 30: 0.85, 50: 0.93, 80: 0.98}
    ax.plot(list(ding), list(ding.values()), "s", mfc="none", label="Ding 2003, integrated independently (design notes)")
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel("force relative to 100 Hz")
    ax2 = ax.twinx()
    ax2.plot(res["frequency_Hz"], 100 * res["ripple"], ":", color="C2")
    ax2.set_ylabel("ripple (%)", color="C2")
    ax.set_title("Force-frequency curve and fusion (1 s saturating trains)", fontsize=9)
    ax.legend(fontsize=8, loc="center right")
    _save(plt, fig, path)


def plot_recruitment(res: dict, path: Path) -> None:
    plt = _plt()
    fig, ax = plt.subplots(figsize=(6, 3.4))
    for pw, r in zip(res["pulse_width_s"], res["recruitment"]):
        ax.plot(1e3 * res["amplitude_A"], r, label=f"{1e6 * pw:.0f} us")
    ax.set_xlabel("amplitude (mA)")
    ax.set_ylabel("recruited fraction R")
    ax.set_title("Intramuscular recruitment: 5 mA threshold, 20 mA saturation at 200 us,\n"
                 "Weiss-Lapicque shift with pulse width (chronaxie 0.45 ms)", fontsize=9)
    ax.legend(title="pulse width", fontsize=8)
    _save(plt, fig, path)


def plot_fatigue_recovery(res: dict, path: Path) -> None:
    plt = _plt()
    fig, ax = plt.subplots(figsize=(7, 3.6))
    ax.plot(res["time"], res["force"], lw=0.4, label="force level f")
    ax.plot(res["a_time"], res["a_hat"], lw=1.5, label="A / A_rest")
    ax.set_xlabel("time (s)")
    ax.set_title(f"Continuous 33 Hz for 60 s, 60 s rest, 1 s test train: end {res['end_of_stimulation']:.3f}, "
                 f"after rest {res['after_rest']:.3f} of the start\n(Ding 2003 model 0.233 and 0.697)", fontsize=8)
    ax.legend(fontsize=8)
    _save(plt, fig, path)


def plot_endurance(runs: dict, path: Path) -> None:
    plt = _plt()
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    for r in runs["one"] + runs["four"]:
        ls = "-" if r.electrodes == 1 else "--"
        ax[0].plot(r.time, 1e3 * r.amplitude, ls, lw=1, label=r.label)
    ax[0].set_xlabel("time (s)")
    ax[0].set_ylabel("amplitude (mA), PI-controlled to hold 20 % of Fmax")
    ax[0].legend(fontsize=7)
    reach = [r.reach for r in runs["one"]]
    cap = max(r.time[-1] for r in runs["one"] + runs["four"])
    end = [r.endurance_s if r.endurance_s is not None else np.nan for r in runs["one"]]
    ax[1].plot(reach, end, "o-", label="armrt, one electrode")
    for k, r in enumerate(runs["four"]):
        ax[1].axhline(r.endurance_s if r.endurance_s is not None else cap, color=f"C{k + 1}", ls="--",
                      label=f"armrt, {r.label}" + ("" if r.endurance_s is not None else " (held to the end)"))
    for key, color in (("one", "k"), ("four", "0.5")):
        m, s = CLINICAL[key]
        ax[1].axhspan(m - s, m + s, color=color, alpha=0.12)
        ax[1].axhline(m, color=color, lw=0.8)
        ax[1].text(reach[-1], m, f" PMC6370345 {key} IM electrode{'s' if key == 'four' else ''}: "
                                 f"{m:.0f} +- {s:.0f} s", fontsize=7, va="bottom")
    ax[1].set_xlabel("fraction of the muscle one electrode recruits at saturation")
    ax[1].set_ylabel("endurance at 20 % of Fmax (s)")
    ax[1].legend(fontsize=7, loc="upper left")
    fig.suptitle("Endurance at 20 % MVC, 25 Hz, feedback-controlled amplitude (das2 brachialis, Ding 2003 "
                 "parameters, nothing fitted)", fontsize=9)
    _save(plt, fig, path)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m armrt.fes_validation", description=__doc__.split("\n\n")[0])
    p.add_argument("--out", default="docs/figures", help="directory for the PNG files (default: docs/figures)")
    p.add_argument("--max-duration", type=float, default=600.0, help="endurance trials stop here (s)")
    args = p.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    tw = twitch()
    plot_twitch(tw, out / "fes_twitch.png")
    print(f"twitch: time to peak {1e3 * tw['time_to_peak_s']:.0f} ms, half-relaxation "
          f"{1e3 * tw['half_relaxation_s']:.0f} ms")
    ff = force_frequency()
    plot_force_frequency(ff, out / "fes_force_frequency.png")
    print("force-frequency (relative to 100 Hz): " + ", ".join(
        f"{hz:g} Hz {r:.3f} (ripple {100 * rp:.1f} %)" for hz, r, rp in zip(ff["frequency_Hz"], ff["relative"],
                                                                          ff["ripple"])))
    plot_recruitment(recruitment_curve(), out / "fes_recruitment.png")
    fr = fatigue_recovery()
    plot_fatigue_recovery(fr, out / "fes_fatigue_recovery.png")
    print(f"fatigue: {fr['end_of_stimulation']:.3f} of the start after 60 s at 33 Hz, {fr['after_rest']:.3f} "
          "after 60 s of rest")
    runs = endurance_set(args.max_duration)
    plot_endurance(runs, out / "fes_endurance.png")
    for r in runs["one"] + runs["four"]:
        end = f"{r.endurance_s:.1f} s" if r.endurance_s is not None else f"held to {r.time[-1]:.0f} s"
        sat = f"{r.saturation_s:.1f} s" if r.saturation_s is not None else "never"
        print(f"endurance, {r.label}: {end} (amplitude at its maximum from {sat})")
    print(f"wrote {out}/fes_twitch.png, fes_force_frequency.png, fes_recruitment.png, fes_fatigue_recovery.png, "
          "fes_endurance.png")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
