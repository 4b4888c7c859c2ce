"""armrt's static optimisation against OpenSim 4.6's StaticOptimization on the same motion (issue 28 item 3):
das3.osim reduced to das2's problem as bench.bench_opensim builds it (girdle coordinates locked at das2's
angles, the same 102 elements, the same passive joint moments), the motion of bench.static_optimization (every arm
DOF a raised-cosine move of 0.3 rad, alternating signs) at --rate frames per second. Both minimise the sum of
squared activations with the muscles' force-length-velocity properties: OpenSim with a rigid tendon on its
Schutte1993 muscles and wrapping paths, armrt with its polynomial paths and its elastic (default) and rigid
tendons. Reported: per element, the correlation and RMS difference of the activation time courses (over elements
whose activation rises above 0.01 in either), and the wall time of each whole run.

    python -m bench.static_optimization_opensim [--duration 1.0] [--rate 100] [--quick]
Writes bench/results/static_optimization_opensim.json and .md.
"""
from __future__ import annotations

import argparse
import json
import os
import tempfile
import time
from pathlib import Path

import numpy as np

import armrt
from armrt.opensim_io import _write_storage, read_storage
from bench.bench_opensim import DEFAULT_OSIM, build_opensim, model_file

RESULTS = Path(__file__).resolve().parent / "results"
ACTIVE = 0.01  # an element enters the comparison when either solver activates it above this


def reference_motion(arm: armrt.Arm, duration: float, rate: float):
    """time (T,) s and q (T, 5) rad: rest + 0.15 (1 - cos(pi t / duration)) per DOF, signs alternating."""
    t = np.linspace(0.0, duration, int(round(duration * rate)) + 1)
    s = 0.15 * (1.0 - np.cos(np.pi * t / duration))
    sign = np.where(np.arange(arm.n_dofs) % 2 == 0, 1.0, -1.0)
    return t, arm.q + np.outer(s, sign)


def run_opensim(osim_path: Path, model: dict, t, q, workdir: Path) -> dict:
    import opensim as osim

    osim.Logger.setLevelString("error")
    m, state, info = build_opensim(osim_path, model, controller=False)
    labels = [g["osim_name"] for g in model["girdle"]["dofs"]] + [d["osim_name"] for d in model["dofs"]]
    girdle = np.array([g["angle"] for g in model["girdle"]["dofs"]])
    data = np.column_stack([np.tile(girdle, (t.size, 1)), q])
    mot = workdir / "motion.mot"
    _write_storage(mot, "motion", labels, t, data)
    so = osim.StaticOptimization()
    so.setModel(m)
    so.setStartTime(float(t[0]))
    so.setEndTime(float(t[-1]))
    so.setUseModelForceSet(True)
    so.setActivationExponent(2.0)
    so.setUseMusclePhysiology(True)
    so.setConvergenceCriterion(1e-6)
    so.setMaxIterations(200)
    m.addAnalysis(so)
    tool = osim.AnalyzeTool(m)
    tool.setName("armrt_so")
    tool.setModel(m)
    tool.setCoordinatesFileName(str(mot))
    tool.setLowpassCutoffFrequency(-1.0)
    tool.setInitialTime(float(t[0]))
    tool.setFinalTime(float(t[-1]))
    tool.setResultsDir(str(workdir))
    tool.setStatesFromMotion(state, osim.Storage(str(mot)), False)  # a kinematics-only input, in radians
    w = time.perf_counter()
    tool.run()
    wall = time.perf_counter() - w
    header, cols, table = read_storage(workdir / "armrt_so_StaticOptimization_activation.sto")
    return {"time": table[:, 0], "columns": cols[1:], "activation": table[:, 1:], "wall_s": wall,
            "n_muscles": info["n_muscles"]}


def run_armrt(t, q, tendon: str) -> dict:
    arm = armrt.Arm("das2")
    w = time.perf_counter()
    r = armrt.static_optimization_motion(arm, q, time=t, tendon=tendon, on_infeasible="return")
    wall = time.perf_counter() - w
    return {"activation": r.activation, "feasible": r.feasible, "wall_s": wall,
            "residual_max": float(np.abs(r.residual).max())}


def compare(ours: np.ndarray, theirs: np.ndarray, names: list[str]) -> dict:
    active = np.maximum(ours.max(axis=0), theirs.max(axis=0)) > ACTIVE
    corr, rms = {}, {}
    for i in np.flatnonzero(active):
        a, b = ours[:, i], theirs[:, i]
        rms[names[i]] = float(np.sqrt(np.mean((a - b) ** 2)))
        corr[names[i]] = float(np.corrcoef(a, b)[0, 1]) if a.std() > 1e-9 and b.std() > 1e-9 else float("nan")
    c = np.array([v for v in corr.values() if np.isfinite(v)])
    r = np.array(list(rms.values()))
    return {"elements_compared": int(active.sum()), "correlation_median": float(np.median(c)) if c.size else None,
            "correlation_positive": int((c > 0).sum()), "rms_median": float(np.median(r)), "rms_max": float(r.max()),
            "sum_activation_ours": float(ours.sum(axis=1).mean()), "sum_activation_opensim": float(theirs.sum(axis=1).mean()),
            "per_element": {k: {"correlation": corr[k], "rms": rms[k]} for k in rms}}


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--duration", type=float, default=1.0)
    ap.add_argument("--rate", type=float, default=100.0)
    ap.add_argument("--osim", type=Path, default=DEFAULT_OSIM)
    ap.add_argument("--quick", action="store_true", help="0.2 s at 50 frames/s (a check that it runs)")
    ap.add_argument("--out", type=Path, default=RESULTS / "static_optimization_opensim.json")
    args = ap.parse_args(argv)
    if args.quick:
        args.duration, args.rate = 0.2, 50.0
    model = model_file()
    arm = armrt.Arm("das2")
    t, q = reference_motion(arm, args.duration, args.rate)
    load_before = os.getloadavg()[0]
    with tempfile.TemporaryDirectory() as d:
        theirs = run_opensim(args.osim, model, t, q, Path(d))
    osim_names = [e["osim_name"] for e in model["elements"]]
    col = {c: k for k, c in enumerate(theirs["columns"])}
    missing = [n for n in osim_names if n not in col]
    if missing:
        raise RuntimeError(f"OpenSim's activations lack elements {missing[:5]}")
    frames = np.searchsorted(theirs["time"], t - 1e-9)
    if theirs["time"].size != t.size or np.abs(theirs["time"] - t).max() > 1e-6:
        raise RuntimeError(f"OpenSim solved {theirs['time'].size} frames, the motion has {t.size}")
    a_osim = theirs["activation"][frames][:, [col[n] for n in osim_names]]
    names = list(arm.element_names)
    out = {"duration_s": args.duration, "frames": int(t.size), "osim": str(args.osim),
           "opensim": {"wall_s": theirs["wall_s"], "n_muscles": theirs["n_muscles"]}, "armrt": {}}
    for tendon in ("elastic", "rigid"):
        ours = run_armrt(t, q, tendon)
        out["armrt"][tendon] = {"wall_s": ours["wall_s"], "infeasible_frames": int((~ours["feasible"]).sum()),
                                "residual_max_Nm": ours["residual_max"],
                                "vs_opensim": compare(ours["activation"], a_osim, names)}
    out["load"] = {"before": load_before, "after": os.getloadavg()[0], "cpus": os.cpu_count()}
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(out, indent=1))
    args.out.with_suffix(".md").write_text(markdown(out))
    print(markdown(out))
    return out


def markdown(out: dict) -> str:
    lines = [f"Static optimisation, armrt vs OpenSim 4.6 (`python -m bench.static_optimization_opensim`): das2's "
             f"problem, {out['frames']} frames over {out['duration_s']:g} s, load {out['load']['before']:.2f} -> "
             f"{out['load']['after']:.2f} on {out['load']['cpus']} CPUs.", "",
             "| solver | wall time, s | per frame, ms | infeasible frames | elements compared | activation correlation with OpenSim, median (positive) | RMS difference, median / max | mean sum of activations |",
             "|---|---|---|---|---|---|---|---|"]
    n = out["frames"]
    lines.append(f"| OpenSim StaticOptimization (rigid tendon) | {out['opensim']['wall_s']:.2f} | "
                 f"{1e3 * out['opensim']['wall_s'] / n:.1f} | - | - | - | - | "
                 f"{next(iter(out['armrt'].values()))['vs_opensim']['sum_activation_opensim']:.2f} |")
    for tendon, r in out["armrt"].items():
        c = r["vs_opensim"]
        lines.append(f"| armrt, {tendon} tendon | {r['wall_s']:.2f} | {1e3 * r['wall_s'] / n:.1f} | "
                     f"{r['infeasible_frames']} | {c['elements_compared']} | {c['correlation_median']:.2f} "
                     f"({c['correlation_positive']}) | {c['rms_median']:.3f} / {c['rms_max']:.3f} | "
                     f"{c['sum_activation_ours']:.2f} |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
