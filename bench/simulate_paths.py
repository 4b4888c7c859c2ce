"""Arm.simulate's input paths against Arm.step (issue 26 item 2: "Arm.simulate recording every step within 1.5x of
Arm.step"): das2 at the default ROS2 1 ms step, `--steps` steps from rest with the elbow flexors at 0.3, each path
timed in the same process, interleaved round by round, best of `--repeats`:

- `Arm.step(T)`: the engine's loop, nothing recorded (the reference);
- `simulate(u)` with a (T, n) array, every step recorded;
- `simulate(f)` with a callable returning an (n,) float array (what a controller returns), every step recorded,
  and every 10th;
- `simulate(f)` with a callable returning a {name: value} dict (checked per step by checks.per_element);
- `simulate(u0)` with an (n,) array held.

    python -m bench.simulate_paths [--steps 5000] [--repeats 5] [--baseline PYTHON]
Writes bench/results/simulate_paths.json and .md, with the machine's load before and after (a loaded run's ratios
are noisier than its times are wrong: the paths are interleaved so that load hits all of them alike). --baseline
names another interpreter with another armrt installed (e.g. a venv of an older commit): each round then runs
both, one after the other in fresh processes, and the table shows them side by side.
"""
from __future__ import annotations

import argparse
import json
import os
import time
from pathlib import Path

import numpy as np

RESULTS = Path(__file__).resolve().parent / "results"


def measure(steps: int, repeats: int) -> dict:
    import armrt
    arm = armrt.Arm("das2")
    n = arm.n_elements
    u0 = np.zeros(n)
    u0[arm.indices("elbow_flexors")] = 0.3
    table = np.tile(u0, (steps, 1))
    named = {"elbow_flexors": 0.3}
    duration = steps * arm.dt

    def engine_step():
        arm.set_excitation(u0)
        arm.step(steps)

    paths = {
        "Arm.step(T)": engine_step,
        "simulate(array), every step": lambda: arm.simulate(table, duration),
        "simulate(callable -> array), every step": lambda: arm.simulate(lambda t: u0, duration),
        "simulate(callable -> array), every 10th": lambda: arm.simulate(lambda t: u0, duration, record_every=10),
        "simulate(callable -> dict), every step": lambda: arm.simulate(lambda t: named, duration),
        "simulate(held array), every step": lambda: arm.simulate(u0, duration),
    }
    best = {k: np.inf for k in paths}
    for _ in range(repeats):
        for name, f in paths.items():
            arm.reset()
            t = time.perf_counter()
            f()
            best[name] = min(best[name], time.perf_counter() - t)
    ref = best["Arm.step(T)"]
    return {name: {"us_per_step": 1e6 * b / steps, "real_time_factor": duration / b, "vs_step": b / ref}
            for name, b in best.items()}


def _in_process(python: str, steps: int, repeats: int) -> dict:
    """measure() in a fresh process of interpreter python (its own armrt)."""
    import subprocess
    code = ("import json, sys; sys.path.insert(0, sys.argv[1]); from bench.simulate_paths import measure; "
            "print(json.dumps(measure(int(sys.argv[2]), int(sys.argv[3]))))")
    out = subprocess.run([python, "-c", code, str(RESULTS.parents[1]), str(steps), str(repeats)], check=True,
                         capture_output=True, text=True, cwd="/")
    return json.loads(out.stdout.strip().splitlines()[-1])


def _best(a: dict, b: dict) -> dict:
    return {k: min(a[k], b[k], key=lambda r: r["us_per_step"]) for k in a}


def main(argv=None) -> int:
    import sys
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=5000)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--baseline", metavar="PYTHON", help="an interpreter with another armrt, run side by side")
    args = ap.parse_args(argv)
    load0 = os.getloadavg()[0]
    base = None
    if args.baseline:
        rows = base = None
        for _ in range(args.repeats):   # rounds alternate: the load hits both alike
            # 2 repeats per process: the first path of a fresh process pays its warm-up (page faults, first calls)
            b = _in_process(args.baseline, args.steps, 2)
            r = _in_process(sys.executable, args.steps, 2)
            base, rows = (b, r) if base is None else (_best(base, b), _best(rows, r))
        ref_b, ref_r = base["Arm.step(T)"]["us_per_step"], rows["Arm.step(T)"]["us_per_step"]
        for k in base:   # vs_step from the best of each path
            base[k]["vs_step"] = base[k]["us_per_step"] / ref_b
            rows[k]["vs_step"] = rows[k]["us_per_step"] / ref_r
    else:
        rows = measure(args.steps, args.repeats)
    load1 = os.getloadavg()[0]
    data = {"steps": args.steps, "repeats": args.repeats, "cpus": os.cpu_count(), "load_1min_before": load0,
            "load_1min_after": load1, "date": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()), "paths": rows,
            "baseline": None if base is None else {"python": args.baseline, "paths": base}}
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "simulate_paths.json").write_text(json.dumps(data, indent=1) + "\n")
    lines = [f"# Arm.simulate's input paths against Arm.step (`python -m bench.simulate_paths`)", "",
             f"das2, ROS2 1 ms, {args.steps} steps, best of {args.repeats} interleaved rounds; {data['date']}; "
             f"1-min load average {load0:.2f} before, {load1:.2f} after, {data['cpus']} CPUs"
             f"{' (loaded: times are high, ratios noisy)' if max(load0, load1) > 0.5 * (data['cpus'] or 1) else ''}.", "",
             "| path | us per step | real-time factor | / Arm.step |"
             + (" baseline us per step | baseline / Arm.step |" if base else ""),
             "|---|---:|---:|---:|" + ("---:|---:|" if base else "")]
    for name, r in rows.items():
        extra = f" {base[name]['us_per_step']:.2f} | {base[name]['vs_step']:.2f} |" if base else ""
        lines.append(f"| {name} | {r['us_per_step']:.2f} | {r['real_time_factor']:.0f}x | {r['vs_step']:.2f} |{extra}")
    if base:
        lines += ["", f"Baseline: `{args.baseline}` (another armrt build), each round in fresh processes, alternating."]
    (RESULTS / "simulate_paths.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
