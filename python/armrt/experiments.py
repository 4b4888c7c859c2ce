"""The paper's experiments (section II-G, III): figures (PNG), tables and the report (markdown) of the
protocol in armrt.experiments_protocol (baseline rotator-cuff activations, Table III; the stimulation
sequences of Fig. 1-3; the solver comparison of Fig. 4 / Table IV), whose names are importable from here too.

`armrt experiments` (run_all) regenerates every figure and table under one folder.
"""
from __future__ import annotations

import json
import math
import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np

from .arm import Arm, StepSizeWarning
from .experiments_protocol import (  # noqa: F401 (armrt.experiments.<name>, as before the split)
    ACCURACY_DEG, AXIAL_TOLERANCE, Baseline, bisect, CUFF, cuff_excitation, CuffBoost, cvode_references,
    deltoid_sequence, DT, EXTENSORS, fig1_sequence, Fig1Levels, fig3_limit, find_baseline, FLEXORS, GH_LIMIT,
    held_baseline, INTEGRATOR, middle_anterior_deltoid, new_arm, normal_sensitivity, paper_tasks, PaperTasks,
    passive_support_summary, Phase, plateau_elevation, PRONATORS, run_sequence, Sequence, settle, Settled,
    solver_study, SOLVERS, static_support, STEP_GRID, Support, support_table, tune_cuff_boost, tune_deltoid,
    tune_fig1, value_at)
from .progress import Progress, quiet


# ----------------------------------------------------------------------------- plots and report

def _plot_sequence(res, arm: Arm, groups: dict[str, list[str]], path: Path, title: str, gh: bool):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    nrows = 3 if gh else 2
    fig, ax = plt.subplots(nrows, 1, figsize=(8, 2.6 * nrows), sharex=True)
    for label, names in groups.items():
        idx = [i for n in names for i in arm.indices(n)]
        ax[0].plot(res.time, res.excitation[:, idx].max(axis=1), label=label)
    ax[0].set_ylabel("excitation")
    ax[0].legend(loc="upper right", fontsize=8)
    ax[0].set_title(title)
    q = np.degrees(res.q)
    th = np.degrees(res.thorax_humerus)
    if gh:
        ax[1].plot(res.time, th[:, 1], label="thorax-humerus elevation")
        ax[1].plot(res.time, th[:, 0], label="plane of elevation")
        ax[1].plot(res.time, th[:, 2], label="axial rotation")
        ax[1].plot(res.time, q[:, 3], "--", label="elbow flexion")
        ax[2].plot(res.time, res.gh_stab, color="k")
        ax[2].axhline(1.0, color="r", lw=0.8, ls="--", label="rim (1)")
        ax[2].axhline(GH_LIMIT, color="g", lw=0.8, ls=":", label="safety factor 2 (0.5)")
        ax[2].set_ylabel("GHstab")
        ax[2].legend(loc="upper right", fontsize=8)
    else:
        ax[1].plot(res.time, q[:, 3], label="elbow flexion")
        ax[1].plot(res.time, q[:, 4], label="forearm pronation")
    ax[1].set_ylabel("angle (deg)")
    ax[1].legend(loc="upper right", fontsize=8)
    ax[-1].set_xlabel("time (s)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _plot_solvers(tasks, study, ref, path: Path):
    """ref: the CVODE run of tasks[0]."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    seq = tasks[0]
    fig, ax = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    for integ, style in (("euler", "-"), ("rk4", "--"), ("ros2", "-.")):
        dt = study[integ]["largest_stable_dt"]
        if dt is None:
            continue
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", StepSizeWarning)
            _, res = run_sequence(seq, integ, dt, record_every=max(1, int(round(1e-3 / dt))), substeps=1)
        n = min(len(res.time), len(ref.time))
        lbl = f"{integ} dt = {dt * 1e3:g} ms"
        ax[0].plot(res.time, np.degrees(res.q[:, 3]), style, label=lbl)
        ax[1].plot(res.time[:n], np.degrees(res.q[:n, 3] - ref.q[:n, 3]), style, label=lbl)
    ax[0].plot(ref.time, np.degrees(ref.q[:, 3]), ":", color="k", label="CVODE")
    ax[0].set_ylabel("elbow flexion (deg)")
    ax[0].legend(fontsize=8)
    ax[0].set_title("Fig. 4: solvers at their largest stable steps (Fig. 1 task)")
    ax[1].set_ylabel("difference from CVODE (deg)")
    ax[1].set_xlabel("time (s)")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def run_all(out_dir="results", quick: bool = False, progress: bool = True) -> int:
    """Regenerates every figure and table of the paper's results section into out_dir."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    # Stages: baseline, two tunings, Figs. 1-3, CVODE references, one sweep per solver, Fig. 4, report.
    prog = Progress(total=9 + len(SOLVERS), enabled=progress)
    try:
        with quiet():  # one bar for the job, none for each simulate() inside it
            return _run_all(out, quick, prog)
    finally:
        prog.close()


def _run_all(out: Path, quick: bool, prog: Progress) -> int:
    arm = new_arm()
    summary: dict = {"dt": DT, "integrator": INTEGRATOR}

    pt = paper_tasks(arm, prog)
    base, levels, deltoid, delt_level, tuned = pt.baseline, pt.fig1_levels, pt.deltoid, pt.deltoid_level, pt.cuff_boost
    seq1, seq2, seq3 = pt.sequences
    summary["baseline"] = {"levels": base.levels, "gh_stab": base.settled.gh_stab_tail,
                           "gh_stab_passive": base.passive.gh_stab_tail,
                           "posture_deg": np.degrees(base.settled.q).round(2).tolist(),
                           "axial_rotation_deg": math.degrees(base.settled.axial),
                           "evaluations": base.evaluations, "met": base.met,
                           "common_level_scan": sorted(base.scan.items()) if base.scan else None}
    summary["support"] = passive_support_summary(arm, base.passive.q)

    prog.start("Fig. 1")
    arm1, res1 = run_sequence(seq1)
    _plot_sequence(res1, arm1, {"flexors": list(FLEXORS), "triceps": list(EXTENSORS), "pronators": list(PRONATORS),
                                "rotator cuff": list(CUFF)}, out / "fig1.png", "Fig. 1: elbow and forearm", gh=False)
    q1 = np.degrees(res1.q)
    at = lambda t, j: float(np.interp(t, res1.time, q1[:, j]))
    summary["fig1"] = {"levels": levels.__dict__,
                       "elbow_at_10s": at(9.999, 3), "pronation_at_10s": at(9.999, 4),
                       "elbow_at_14s": at(13.999, 3), "pronation_at_18s": at(17.999, 4),
                       "elbow_final": at(24.0, 3), "pronation_final": at(24.0, 4),
                       "gh_stab_max": float(res1.gh_stab.max()),
                       "gh_stab_max_time": float(res1.time[np.argmax(res1.gh_stab)])}
    prog.step("Fig. 1")

    prog.start("Fig. 2")
    arm2, res2 = run_sequence(seq2)
    _plot_sequence(res2, arm2, {"middle+anterior deltoid": deltoid, "rotator cuff": list(CUFF)}, out / "fig2.png",
                   "Fig. 2: deltoid with baseline rotator cuff", gh=True)
    th2 = np.degrees(res2.thorax_humerus)
    summary["fig2"] = {"deltoid_elements": deltoid, "level": delt_level, "gh_stab_max": float(res2.gh_stab.max()),
                       "elevation_rest": float(th2[0, 1]), "elevation_max": float(th2[:, 1].max()),
                       "plane_at_max": float(th2[np.argmax(th2[:, 1]), 0])}
    prog.step("Fig. 2")

    prog.start("Fig. 3")
    boost = dict(zip(CUFF, tuned.boost))
    arm3, res3 = run_sequence(seq3)
    _plot_sequence(res3, arm3, {"middle+anterior deltoid": deltoid, "rotator cuff": list(CUFF)}, out / "fig3.png",
                   "Fig. 3: deltoid with increased rotator cuff", gh=True)
    th3 = np.degrees(res3.thorax_humerus)
    summary["fig3"] = {"cuff_boost": boost, "gh_stab_limit": tuned.limit, "uniform_boost_scan": tuned.uniform_scan, "evaluations": tuned.evaluations, "gh_stab_max": float(res3.gh_stab.max()),
                       "elevation_max": float(th3[:, 1].max()), "plane_at_max": float(th3[np.argmax(th3[:, 1]), 0])}
    prog.step("Fig. 3")

    tasks = [seq1, seq2, seq3]
    if quick:
        tasks = [replace(s, duration=min(s.duration, 6.0)) for s in tasks]
    prog.start("CVODE references")
    refs = cvode_references(tasks)
    study = solver_study(tasks, prog, STEP_GRID[3:] if quick else STEP_GRID, refs)
    summary["solvers"] = study
    prog.start("Fig. 4")
    _plot_solvers(tasks, study, refs[tasks[0].name], out / "fig4.png")
    prog.step("Fig. 4")

    prog.start("report")
    (out / "results.json").write_text(json.dumps(summary, indent=1, default=float) + "\n")
    (out / "results.md").write_text(report(summary))
    prog.step("report")
    print(f"wrote {out}/results.md, results.json, fig1.png .. fig4.png")
    return 0


def report(s: dict) -> str:
    b = s["baseline"]
    lines = ["# armrt: the paper's experiments", "",
             f"Model das2, {s['integrator']} at {s['dt'] * 1e3:g} ms unless stated. Regenerate with `armrt experiments`.", "",
             "## Table III: baseline rotator-cuff activations (GHstab < 0.5, arm hanging at rest)", "",
             "| muscle | activation |", "|---|---|"]
    lines += [f"| {m} | {v:.4f} |" for m, v in b["levels"].items()]
    lines += ["", f"Largest: {max(b['levels'].values()):.4f} (paper: 0.07). GHstab over the last second at rest: "
              f"{b['gh_stab']:.3f} (without the cuff: {b['gh_stab_passive']:.3f}). Settled posture (deg, "
              f"GHy GHz GHyy ELx PSy): {b['posture_deg']}; thorax-humerus axial rotation {b['axial_rotation_deg']:.1f} deg. "
              f"{b['evaluations']} settling simulations.", ""]
    if not b.get("met", True):
        scan = ", ".join(f"{lvl:g}: {g:.3f}" for lvl, g in b["common_level_scan"])
        lines += ["No cuff activation brings the hanging arm below GHstab 0.5 in this model (common cuff level: "
                  f"settled GHstab {scan}); the level with the lowest GHstab is kept as the baseline.", ""]
    elif max(b["levels"].values()) == 0.0:
        lines += ["The passively hanging arm already meets GHstab < 0.5 in this model, so the minimum is zero "
                  "(what carries it: below; docs/experiments.md).", ""]
    sup = s.get("support")
    if sup:
        lines += ["### What carries the hanging arm (held still, no muscle excited)", "",
                  "| posture | GHy GHz GHyy ELx PSy (deg) | lifted by muscles | GH force | theta, phi (deg) | GHstab |",
                  "|---|---|---|---|---|---|"]
        for key, label in (("settled", "where it settles"), ("equilibrium_mat", "DAS3 equilibrium.mat")):
            r = sup[key]
            lines.append(f"| {label} | {r['posture_deg']} | {r['muscle_lift_N']:.1f} of {r['weight_N']:.1f} N "
                         f"({100 * r['muscle_share']:.0f} %, {r['elements_lifting']} elements pulling) | "
                         f"{r['gh_force_norm_N']:.1f} N | {r['gh_theta_deg']:.1f}, {r['gh_phi_deg']:.1f} | "
                         f"{r['gh_stab']:.3f} |")
        lines += ["", "Largest lifts where the arm settles (tendon force, upward component, share of the arm's weight, "
                  "PEEslack):", "", "| element | force (N) | lift (N) | share | PEEslack |", "|---|---|---|---|---|"]
        lines += [f"| {t['element']} | {t['force_N']:.2f} | {t['lift_N']:.2f} | {100 * t['share']:.1f} % | "
                  f"{t['peeslack'] if t['peeslack'] is not None else '-'} |" for t in sup["settled"]["top"]]
        hb = sup["held_baseline"]
        scan = ", ".join(f"{lvl:g}: {g:.3f}" for lvl, g in hb["common_level_scan"])
        lines += ["", "Table III at DAS3's equilibrium.mat posture held still (static GHstab, COBYLA): "
                  + ", ".join(f"{m} {v:.4f}" for m, v in hb["levels"].items())
                  + f" (GHstab {hb['gh_stab']:.3f}); one common cuff level gives {scan}.", ""]
        ns = sup.get("normal_sensitivity")
        if ns:
            lines += ["### GHstab of the settled arm's GH force with the glenoid normal tilted", "",
                      "| tilt (deg) | superior | inferior | +minor (anterior) | -minor (posterior) |", "|---|---|---|---|---|"]
            for tilt in sorted({r["tilt_deg"] for r in ns["tilts"]}):
                row = {r["towards"]: r["gh_stab"] for r in ns["tilts"] if r["tilt_deg"] == tilt}
                lines.append(f"| {tilt:g} | {row['superior']:.3f} | {row['inferior']:.3f} | {row['+minor']:.3f} | "
                             f"{row['-minor']:.3f} |")
            lines += ["", f"Untilted: {ns['gh_stab']:.3f}."]
            hh = ns.get("humeral_head_centre")
            if hh:
                lines[-1] += (f" Humeral-head-centre normal (from das3.osim's gh1 rather than the DSEM GH centre, "
                              f"{hh['angle_deg']:.2f} deg away): {hh['gh_stab']:.3f}.")
            lines.append("")
    f1 = s["fig1"]
    lines += ["## Fig. 1: elbow flexors, co-contraction, pronators", "",
              f"Levels on top of the baseline: flexors {f1['levels']['flex']}, triceps {f1['levels']['ext']}, "
              f"pronators {f1['levels']['pron']}.", "",
              "| moment | paper | armrt |", "|---|---|---|",
              f"| end of flexion (10 s): elbow | 140 deg | {f1['elbow_at_10s']:.1f} deg |",
              f"| end of flexion (10 s): pronation | full supination | {f1['pronation_at_10s']:.1f} deg |",
              f"| end of co-contraction (14 s): elbow | 100 deg | {f1['elbow_at_14s']:.1f} deg |",
              f"| end of pronation (18 s): pronation | 160 deg | {f1['pronation_at_18s']:.1f} deg |",
              f"| after deactivation (24 s): elbow | 5 deg | {f1['elbow_final']:.1f} deg |",
              f"| after deactivation (24 s): pronation | 70 deg | {f1['pronation_final']:.1f} deg |",
              f"| largest GHstab (not shown in the paper) | | {f1['gh_stab_max']:.2f} at {f1['gh_stab_max_time']:.1f} s |", ""]
    f2, f3 = s["fig2"], s["fig3"]
    lines += ["## Fig. 2 and 3: middle and anterior deltoid", "",
              f"Deltoid elements ({len(f2['deltoid_elements'])}): {', '.join(f2['deltoid_elements'])}, at {f2['level']}.", "",
              "| | paper | armrt |", "|---|---|---|",
              f"| Fig. 2 (baseline cuff): max GHstab | > 1 | {f2['gh_stab_max']:.2f} |",
              f"| Fig. 2: thorax-humerus elevation | rises | {f2['elevation_rest']:.1f} -> {f2['elevation_max']:.1f} deg, plane {f2['plane_at_max']:.0f} deg |",
              f"| Fig. 3 (cuff boost {', '.join(f'{m} +{v:.3f}' for m, v in f3['cuff_boost'].items())}): max GHstab | < 0.5 | {f3['gh_stab_max']:.3f} (target < {f3.get('gh_stab_limit', 0.5):g}) |",
              f"| Fig. 3: elevation | similar, slightly higher | {f3['elevation_max']:.1f} deg, plane {f3['plane_at_max']:.0f} deg |", ""]
    lines += ["## Table IV: solvers", "",
              "Stable: the three tasks complete and every joint angle stays within 1 deg of CVODE.", "",
              "| solver | largest stable step | TET mean | TET max | max error vs CVODE |", "|---|---|---|---|---|"]
    for integ in SOLVERS:
        st = s["solvers"][integ]
        dt = st["largest_stable_dt"]
        row = next((r for r in st["rows"] if r["dt"] == dt), None)
        if row is None:
            lines.append(f"| {integ} | none on the grid | | | |")
        else:
            lines.append(f"| {integ} | {dt * 1e3:g} ms | {row['tet_mean_us']:.2f} us | {row['tet_max_us']:.1f} us | "
                         f"{row['max_error_deg']:.3f} deg |")
    lines += ["", "All steps tried:", "", "| solver | dt | stable | max error (deg) | TET mean (us) | note |", "|---|---|---|---|---|---|"]
    for integ in SOLVERS:
        for r in s["solvers"][integ]["rows"]:
            tm = f"{r['tet_mean_us']:.2f}" if r["tet_mean_us"] else ""
            lines.append(f"| {integ} | {r['dt'] * 1e3:g} ms | {'yes' if r['stable'] else 'no'} | {r['max_error_deg']:.3f} | {tm} | {r.get('failure', '')} |")
    return "\n".join(lines) + "\n"
