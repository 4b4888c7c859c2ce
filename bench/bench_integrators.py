"""Integrators side by side in one run (issue 10): cost per simulated millisecond, accuracy against CVODE.

    python -m bench.bench_integrators [--part all|cost|tasks|random|forward] [--runs 50] [--quick]

Parts (each merged into bench/results/integrators.json; integrators.md is rewritten from it):

- cost: per integrator at a 1 ms control step (ros2 1 step, ros2_adaptive at 2 ms, rk4 6 substeps,
  euler 10 substeps), the task execution time of every control step over the Fig. 1 task (24 s) from
  Arm.simulate's tet_ns, as ns per simulated ms (median, p99, max); forward()-equivalents per ms (that
  cost over forward()'s median, timed by armrt_bench in the same run); the real-time factor of
  Arm.simulate at the default integrator (every step recorded, and every 10th); ratios to RK4 x6.
- tasks: max joint-angle error against CVODE (BDF, rtol 1e-8) at every control step on the paper's
  three tasks (tuned by experiments.paper_tasks), per integrator.
- random: the same error over seeded random protocols (armrt.accuracy; --runs of 5 s): max, p99,
  per-run max, divergences; with a perturbed start (1e-9 rad) for the default.
- forward: forward() of this build against the baseline commit 42b5e0e's, both armrt_bench binaries
  run alternately in this run (the baseline is built from a git worktree under build/baseline).

Needs armrt importable and the C++ tools built (cmake --build build/bench --target armrt_bench).
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
RESULTS = ROOT / "bench" / "results"
JSON = RESULTS / "integrators.json"
BASELINE_COMMIT = "42b5e0e"

# (name in the tables, integrator, control step s, substeps)
SOLVERS = [("ros2", "ros2", 1e-3, 1), ("ros2_adaptive_2ms", "ros2_adaptive", 2e-3, 1),
           ("rk4_x6", "rk4", 1e-3, 6), ("euler_x10", "euler", 1e-3, 10)]


def _load() -> dict:
    return json.loads(JSON.read_text()) if JSON.exists() else {}


def _save(data: dict) -> None:
    RESULTS.mkdir(parents=True, exist_ok=True)
    JSON.write_text(json.dumps(data, indent=1, default=float) + "\n")
    (RESULTS / "integrators.md").write_text(markdown(data))


def _tasks():
    from armrt import experiments as ex
    return ex.paper_tasks().sequences


def _bench_binary(root: Path) -> Path | None:
    """The most recently built armrt_bench of this checkout (build/<dir>/cpp/tools)."""
    found = sorted(root.glob("build/*/cpp/tools/armrt_bench"), key=lambda p: p.stat().st_mtime)
    return found[-1] if found else None


def _forward_ns(binary: Path, reps: int = 20000) -> dict:
    out = RESULTS / f".forward_{os.getpid()}.json.tmp"
    subprocess.run([str(binary), "--json", str(out), "--reps", str(reps), "--batch", "10"], check=True,
                   capture_output=True)
    data = json.loads(out.read_text())["cpp"]
    out.unlink()
    return {k: data[k] for k in ("forward", "forward_record", "muscle_paths", "mass_matrix") if k in data}


def part_forward(data: dict, rounds: int = 5) -> None:
    """forward() now against the baseline commit, alternating binaries so drift hits both alike."""
    new = _bench_binary(ROOT)
    base_dir = ROOT / "build" / "baseline"
    if not (base_dir / "CMakeLists.txt").exists():
        subprocess.run(["git", "worktree", "add", "--force", "--detach", str(base_dir), BASELINE_COMMIT], cwd=ROOT,
                       check=True, capture_output=True)
    base_bin = base_dir / "build" / "bench" / "cpp" / "tools" / "armrt_bench"
    if not base_bin.exists():
        subprocess.run(["cmake", "-S", str(base_dir), "-B", str(base_dir / "build" / "bench"), "-G", "Ninja",
                        "-DARMRT_BUILD_TESTS=OFF", "-DARMRT_BUILD_PYTHON=OFF"], check=True, capture_output=True)
        subprocess.run(["cmake", "--build", str(base_dir / "build" / "bench"), "-j2", "--target", "armrt_bench"],
                       check=True, capture_output=True)
    if new is None:
        raise SystemExit("armrt_bench of this build not found (cmake --build build/bench --target armrt_bench)")
    runs = {"new": [], "baseline": []}
    for _ in range(rounds):
        runs["baseline"].append(_forward_ns(base_bin))
        runs["new"].append(_forward_ns(new))
    med = lambda side, item, stat: float(np.median([r[item][stat] for r in runs[side]]))
    out = {"rounds": rounds, "baseline_commit": BASELINE_COMMIT}
    for item in ("forward", "forward_record", "muscle_paths", "mass_matrix"):
        out[item] = {side: {stat: med(side, item, stat) for stat in ("median", "p99", "min")} for side in runs}
        out[item]["speedup_median"] = out[item]["baseline"]["median"] / out[item]["new"]["median"]
        out[item]["speedup_min"] = out[item]["baseline"]["min"] / out[item]["new"]["min"]
    data["forward_vs_baseline"] = out
    print(f"forward(): baseline {out['forward']['baseline']['median']:.0f} ns, now {out['forward']['new']['median']:.0f} ns "
          f"(x{out['forward']['speedup_median']:.2f} median, x{out['forward']['speedup_min']:.2f} min)")


def part_cost(data: dict, quick: bool = False) -> None:
    import armrt
    from armrt import experiments as ex
    seq = ex.fig1_sequence({m: 0.0 for m in ex.CUFF}, 0.4, 0.39, 0.41)
    if quick:
        from dataclasses import replace
        seq = replace(seq, duration=6.0)
    new = _bench_binary(ROOT)
    fwd = _forward_ns(new)["forward"]["median"] if new else None
    rows = {}
    for name, integ, dt, sub in SOLVERS:
        tets = []
        for _ in range(3):
            arm = armrt.Arm(integrator=integ, dt=dt, substeps=sub)
            u = seq.excitation(arm, int(round(seq.duration / dt)), dt)
            arm.reset(activation=u[0])
            res = arm.simulate(u, seq.duration)
            tets.append(res.tet_ns[:-1])
        per_ms = np.concatenate(tets) / (dt / 1e-3)
        rows[name] = {"integrator": integ, "dt": dt, "substeps": sub,
                      "ns_per_ms": {"median": float(np.median(per_ms)), "p99": float(np.percentile(per_ms, 99)),
                                    "max": float(per_ms.max()), "mean": float(per_ms.mean())},
                      "steps": int(per_ms.size)}
        if fwd:
            rows[name]["forward_equivalents_per_ms"] = rows[name]["ns_per_ms"]["median"] / fwd
    ref = rows["rk4_x6"]["ns_per_ms"]["median"]
    for r in rows.values():
        r["ratio_rk4x6_over_this"] = ref / r["ns_per_ms"]["median"]
    # Arm.simulate at the default integrator: 10 s held stimulation, best of 3.
    rtf = {}
    for every in (1, 10):
        walls = []
        for _ in range(3):
            arm = armrt.Arm()
            arm.reset()
            t0 = time.perf_counter()
            arm.simulate({"rotator_cuff": 0.05, "elbow_flexors": 0.3}, 10.0, record_every=every)
            walls.append(time.perf_counter() - t0)
        rtf[f"record_every_{every}"] = 10.0 / min(walls)
    rk4_walls = []
    for _ in range(3):
        arm = armrt.Arm(integrator="rk4")
        arm.reset()
        t0 = time.perf_counter()
        arm.simulate({"rotator_cuff": 0.05, "elbow_flexors": 0.3}, 10.0)
        rk4_walls.append(time.perf_counter() - t0)
    rtf["rk4_x6_record_every_1"] = 10.0 / min(rk4_walls)
    data["cost"] = {"task": f"Fig. 1 sequence, {seq.duration:g} s", "forward_ns_median": fwd, "solvers": rows,
                    "simulate_real_time_factor": rtf, "cpus": os.cpu_count(), "load_avg": os.getloadavg()}
    for name, r in rows.items():
        print(f"{name:18s} {r['ns_per_ms']['median']:9.0f} ns/ms (p99 {r['ns_per_ms']['p99']:.0f}, max {r['ns_per_ms']['max']:.0f}),"
              f" x{r['ratio_rk4x6_over_this']:.1f} vs RK4 x6")
    print(f"Arm.simulate at the default: {rtf['record_every_1']:.0f}x real time ({rtf['record_every_10']:.0f}x recording every 10th step)")


def part_tasks(data: dict, quick: bool = False) -> None:
    from dataclasses import replace
    from armrt import experiments as ex
    tasks = _tasks()
    if quick:
        tasks = [replace(s, duration=min(s.duration, 4.0)) for s in tasks]
    out = {}
    refs = {}
    for seq in tasks:
        for dt in sorted({dt for _, _, dt, _ in SOLVERS}):
            refs[(seq.name, dt)] = ex.run_sequence(seq, "cvode", dt)[1]
        out[seq.name] = {}
        for name, integ, dt, sub in SOLVERS:
            _, res = ex.run_sequence(seq, integ, dt, substeps=sub)
            ref = refs[(seq.name, dt)]
            n = min(len(res.q), len(ref.q))
            out[seq.name][name] = float(np.degrees(np.abs(res.q[:n] - ref.q[:n])).max())
        print(seq.name, {k: round(v, 4) for k, v in out[seq.name].items()})
    data["tasks"] = {"max_error_deg": out, "durations_s": {s.name: s.duration for s in tasks}}


def part_random(data: dict, runs: int = 50, duration: float = 5.0) -> None:
    import armrt
    from armrt import accuracy as acc
    from armrt.arm import SimulationError
    arm = armrt.Arm()
    muscles = acc.muscles_of(arm)
    per_run = []
    errors = {name: [] for name, *_ in SOLVERS}
    errors["ros2_perturbed"] = []
    t0 = time.perf_counter()
    for seed in range(runs):
        p = acc.random_protocol(seed, arm.n_elements, duration, muscles)
        row = {"seed": seed, "label": p.label}
        ref = acc.run_protocol(p, "cvode", 1e-3)  # switch times on a 10 ms grid: also the 2 ms reference
        refs = {1e-3: ref, 2e-3: _every_other(ref)}
        for name, integ, dt, sub in SOLVERS + [("ros2_perturbed", "ros2", 1e-3, 1)]:
            q0 = arm.rest_posture + (1e-9 if name == "ros2_perturbed" else 0.0)
            try:
                res = acc.run_protocol(p, integ, dt, q0=q0, substeps=sub)
                e = acc.joint_errors_deg(res, refs[dt])
                errors[name].append(e)
                row[name] = float(e.max())
            except SimulationError as exc:
                row[name] = f"diverged: {exc}"
        per_run.append(row)
        print(f"[{seed + 1}/{runs}, {time.perf_counter() - t0:.0f} s] {p.label}: "
              + ", ".join(f"{k} {v:.3f}" if isinstance(v, float) else f"{k} {v}" for k, v in row.items()
                          if k not in ("seed", "label")), flush=True)
    summary = {}
    for name, es in errors.items():
        allv = np.concatenate(es) if es else np.zeros(1)
        summary[name] = {"max_deg": float(allv.max()), "p99_deg": float(np.percentile(allv, 99)),
                         "median_run_max_deg": float(np.median([e.max() for e in es])) if es else None,
                         "diverged": sum(1 for r in per_run if isinstance(r.get(name), str))}
    data["random"] = {"runs": runs, "duration_s": duration, "summary": summary, "per_run": per_run,
                      "note": "error: largest joint-angle difference from CVODE (BDF, rtol 1e-8, same control step) at "
                              "every control step; p99 over all control steps of all runs"}


def _every_other(res):
    """The 1 ms CVODE result sampled every 2 ms (the rows a 2 ms control step records)."""
    from dataclasses import replace
    return replace(res, time=res.time[::2], q=res.q[::2])


def markdown(d: dict) -> str:
    L = ["# Integrators side by side", "",
         "Regenerate with `python -m bench.bench_integrators` (bench/bench_integrators.py says what each part measures).", ""]
    if "cost" in d:
        c = d["cost"]
        L += [f"## Cost per simulated millisecond ({c['task']}, {c['cpus']} CPUs, load {', '.join(f'{x:.1f}' for x in c['load_avg'])})", "",
              "| integrator | control step | ns per simulated ms: median | p99 | max | forward()-equivalents per ms | RK4 x6 / this |",
              "|---|---|---|---|---|---|---|"]
        for name, r in c["solvers"].items():
            fe = r.get("forward_equivalents_per_ms")
            L.append(f"| {name} | {r['dt'] * 1e3:g} ms, {r['substeps']} step(s) | {r['ns_per_ms']['median']:.0f} | "
                     f"{r['ns_per_ms']['p99']:.0f} | {r['ns_per_ms']['max']:.0f} | {fe:.1f} | {r['ratio_rk4x6_over_this']:.1f} |"
                     if fe else f"| {name} | | {r['ns_per_ms']['median']:.0f} | | | | |")
        rtf = c["simulate_real_time_factor"]
        L += ["", f"`Arm.simulate` real-time factor at the default (ros2, 1 ms, 10 s): {rtf['record_every_1']:.0f}x recording every "
              f"step, {rtf['record_every_10']:.0f}x recording every 10th; RK4 x6: {rtf['rk4_x6_record_every_1']:.0f}x. "
              f"forward() median in this run: {c['forward_ns_median']:.0f} ns.", ""]
    if "forward_vs_baseline" in d:
        f = d["forward_vs_baseline"]
        L += [f"## forward() against {f['baseline_commit']} (both binaries, alternating, {f['rounds']} rounds)", "",
              "| item | baseline median (ns) | now median (ns) | speed-up (median) | speed-up (min) |", "|---|---|---|---|---|"]
        for item in ("forward", "forward_record", "muscle_paths", "mass_matrix"):
            r = f[item]
            L.append(f"| {item} | {r['baseline']['median']:.0f} | {r['new']['median']:.0f} | {r['speedup_median']:.2f} | {r['speedup_min']:.2f} |")
        L.append("")
    if "tasks" in d:
        t = d["tasks"]["max_error_deg"]
        names = list(next(iter(t.values())))
        L += ["## Max joint-angle error against CVODE on the paper's tasks (deg)", "",
              "| task | " + " | ".join(names) + " |", "|---|" + "---|" * len(names)]
        for task, row in t.items():
            L.append(f"| {task} | " + " | ".join(f"{row[n]:.4f}" for n in names) + " |")
        L.append("")
    if "random" in d:
        r = d["random"]
        L += [f"## Seeded random protocols ({r['runs']} runs of {r['duration_s']:g} s; armrt/accuracy.py)", "",
              "| integrator | max error (deg) | p99 (deg) | median of run maxima | diverged |", "|---|---|---|---|---|"]
        for name, s in r["summary"].items():
            L.append(f"| {name} | {s['max_deg']:.3f} | {s['p99_deg']:.4f} | {s['median_run_max_deg']:.4f} | {s['diverged']} |")
        L += ["", r["note"] + ".", ""]
    return "\n".join(L) + "\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m bench.bench_integrators", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--part", default="all", choices=["all", "cost", "tasks", "random", "forward"])
    ap.add_argument("--runs", type=int, default=50, help="random protocols (default 50)")
    ap.add_argument("--quick", action="store_true", help="shorter tasks and 4 random runs (smoke test)")
    a = ap.parse_args(argv)
    data = _load()
    parts = ["forward", "cost", "tasks", "random"] if a.part == "all" else [a.part]
    for part in parts:
        if part == "forward":
            part_forward(data, rounds=2 if a.quick else 5)
        elif part == "cost":
            part_cost(data, a.quick)
        elif part == "tasks":
            part_tasks(data, a.quick)
        else:
            part_random(data, runs=4 if a.quick else a.runs, duration=2.0 if a.quick else 5.0)
        _save(data)
    print(f"wrote {JSON} and integrators.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
