"""A second experiment on real participant data: the paper's Fig. 1 elbow/forearm sequence with full
stimulation, on participant A's elbow-forearm model, intact and with the injured, paralysed and FES
weakness profiles.

    armrt experiments --model participant_A --out results

Sequence (the paper's Fig. 1 timing): elbow flexors (biceps, brachialis, brachioradialis) on at 4 s,
triceps added at 10 s, pronators (pronator teres and quadratus) added at 14 s, all off at 18 s, end
at 24 s; every stimulated muscle gets excitation 1 ("full stimulation"), which the engine caps at
each element's maximum activation, so what a variant reaches is what its `maxact` and `fmax` allow.
Reported per variant: the elbow flexion and forearm pronation ranges reached, and the peak elbow
moments of the stimulated flexors and of the stimulated triceps (sum of r_i F_i over their elements,
N m, flexion positive).

The variants are one geometry with profiles (Arm.apply_profile): the four participant files share
every polynomial, joint and segment; they differ in fmax and maxact (runtime parameters of the
engine) and in lceopt/lslack of 16 elements by at most 1.4e-4 relative (0.012 mm), which the
profile does not carry (docs/experiments.md).
"""
from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .arm import Arm

FLEXORS = ("bicl", "bicb", "brachialis", "brachiorad")
TRICEPS = ("triclong", "tricmed", "triclat")
PRONATORS = ("pronteres", "pronquad")
# (time s, groups on from then): the paper's Fig. 1 sequence (experiments.fig1_sequence), at full stimulation.
PHASES = ((0.0, ()), (4.0, FLEXORS), (10.0, FLEXORS + TRICEPS), (14.0, FLEXORS + TRICEPS + PRONATORS), (18.0, ()))
DURATION = 24.0
DT = 1e-3
RECORD_EVERY = 10
VARIANTS = ("intact", "injured", "paralysed", "FES")


@dataclass
class VariantResult:
    name: str
    profile: str | None
    elbow_range_deg: tuple[float, float]
    pronation_range_deg: tuple[float, float]
    peak_flexor_moment: float      # N m, max over the run of the stimulated flexors' elbow moment
    peak_triceps_moment: float     # N m, max over the run of the triceps' extension moment (positive)
    time: np.ndarray
    elbow_deg: np.ndarray
    pronation_deg: np.ndarray
    flexor_moment: np.ndarray
    triceps_moment: np.ndarray


def excitation(arm: Arm, duration: float = DURATION, dt: float = DT, phases=PHASES) -> np.ndarray:
    """(steps, elements): 1 on the stimulated muscles of each phase (capped by the engine at max_activation)."""
    n = int(round(duration / dt))
    t = dt * np.arange(n)
    u = np.zeros((n, arm.n_elements))
    for k, (start, groups) in enumerate(phases):
        end = phases[k + 1][0] if k + 1 < len(phases) else duration
        rows = (t >= start - 1e-12) & (t < end - 1e-12)
        for g in groups:
            u[np.ix_(rows, arm.indices(g))] = 1.0
    return u


def group_moment(arm: Arm, res, groups, dof: int) -> np.ndarray:
    """(T,) N m: sum over the groups' elements of moment arm x force about DOF `dof`, per recorded row."""
    idx = sorted({i for g in groups for i in arm.indices(g)})
    out = np.empty(len(res.time))
    for k, q in enumerate(res.q):
        R = arm.moment_arms(q)
        out[k] = float(R[idx, dof] @ res.muscle_force[k, idx])
    return out


def run_variant(model: str, name: str, profile: str | None, duration: float = DURATION,
                phases=PHASES) -> VariantResult:
    arm = Arm(model=model, dt=DT)
    if profile is not None:
        report = arm.apply_profile(profile)
        if report.unmatched:
            raise ValueError(f"profile {profile}: elements {report.unmatched} are not in model {model}")
    el, ps = arm.dof_index("ELx"), arm.dof_index("PSy")
    u = excitation(arm, duration, DT, phases)
    arm.reset()
    res = arm.simulate(u, duration=duration, record_every=RECORD_EVERY)
    elbow, pron = np.degrees(res.q[:, el]), np.degrees(res.q[:, ps])
    flex = group_moment(arm, res, FLEXORS, el)
    tri = -group_moment(arm, res, TRICEPS, el)
    return VariantResult(name=name, profile=profile,
                         elbow_range_deg=(float(elbow.min()), float(elbow.max())),
                         pronation_range_deg=(float(pron.min()), float(pron.max())),
                         peak_flexor_moment=float(flex.max()), peak_triceps_moment=float(tri.max()),
                         time=res.time, elbow_deg=elbow, pronation_deg=pron, flexor_moment=flex, triceps_moment=tri)


def variant_profiles(model: str) -> dict[str, str | None]:
    """Profiles of the four variants: none (the model as built: intact) and <base>_injured, _paralysed,
    _FES, where base is the model name (participant_A) or, for another model such as das2,
    participant_A (its weakness relative to participant A's intact file moves onto that model)."""
    base = model if model.startswith("participant_") else "participant_A"
    return {"intact": None, "injured": f"{base}_injured", "paralysed": f"{base}_paralysed", "FES": f"{base}_FES"}


def run(model: str = "participant_A", duration: float = DURATION, phases=PHASES) -> list[VariantResult]:
    return [run_variant(model, name, prof, duration, phases) for name, prof in variant_profiles(model).items()]


def table(results: list[VariantResult], model: str) -> str:
    how = (f"`armrt experiments --model {model}`" if model != "das2" else "`armrt.participant.run_all('das2')`")
    lines = [f"Participant A, Fig. 1 sequence at full stimulation (model {model}; {how})",
             "",
             "| variant | elbow flexion reached (deg) | pronation reached (deg) | peak flexor moment (N m) | peak triceps moment (N m) |",
             "|---|---|---|---|---|"]
    for r in results:
        lines.append(f"| {r.name} | {r.elbow_range_deg[0]:.1f} to {r.elbow_range_deg[1]:.1f} | "
                     f"{r.pronation_range_deg[0]:.1f} to {r.pronation_range_deg[1]:.1f} | "
                     f"{r.peak_flexor_moment:.1f} | {r.peak_triceps_moment:.1f} |")
    return "\n".join(lines)


def plot(results: list[VariantResult], path: Path, model: str) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, figsize=(8, 7.5), sharex=True)
    # Injured and paralysed coincide (identical files): a wide pale line under a narrow one keeps both visible.
    style = {"injured": {"lw": 4, "alpha": 0.45}, "paralysed": {"lw": 1.2, "ls": (0, (4, 2))}}
    for r in results:
        kw = style.get(r.name, {"lw": 1.5})
        ax[0].plot(r.time, r.elbow_deg, label=r.name, **kw)
        ax[1].plot(r.time, r.pronation_deg, label=r.name, **kw)
        ax[2].plot(r.time, r.flexor_moment, label=f"{r.name}: flexors (+), triceps (-)", **kw)
        ax[2].plot(r.time, -r.triceps_moment, color=ax[2].lines[-1].get_color(), **kw)
    for t, _ in PHASES[1:]:
        for a in ax:
            a.axvline(t, color="0.8", lw=0.8, zorder=0)
    ax[0].set_ylabel("elbow flexion (deg)")
    ax[1].set_ylabel("pronation (deg)")
    ax[2].set_ylabel("elbow moment (N m)")
    ax[0].set_title(f"Participant A ({model}): Fig. 1 sequence, full stimulation (flexors 4 s, triceps 10 s, "
                    f"pronators 14 s, off 18 s)", fontsize=9)
    ax[0].legend(fontsize=8, loc="upper right")
    ax[2].legend(fontsize=7, loc="lower left", ncol=2)
    ax[2].set_xlabel("time (s)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def run_all(model: str = "participant_A", out_dir="results", quick: bool = False) -> int:
    """Runs the four variants, prints the table, writes <out>/<model>_fig1.png, .md and .json."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    duration, phases = DURATION, PHASES
    if quick:   # the same sequence, each phase 1/4 as long
        duration, phases = DURATION / 4, tuple((t / 4, g) for t, g in PHASES)
    results = run(model, duration, phases)
    text = table(results, model)
    print(text)
    plot(results, out / f"{model}_fig1.png", model)
    (out / f"{model}.md").write_text(text + "\n")
    (out / f"{model}.json").write_text(json.dumps({
        "model": model, "dt": DT, "duration": duration, "phases": [[t, list(g)] for t, g in phases],
        "variants": {r.name: {"profile": r.profile, "elbow_range_deg": r.elbow_range_deg,
                              "pronation_range_deg": r.pronation_range_deg,
                              "peak_flexor_moment_Nm": r.peak_flexor_moment,
                              "peak_triceps_moment_Nm": r.peak_triceps_moment} for r in results}}, indent=1) + "\n")
    print(f"wrote {out}/{model}.md, {model}.json, {model}_fig1.png")
    return 0
