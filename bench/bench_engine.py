"""Engine benchmark: the C++ micro-benchmark (armrt_bench) plus the Python-side overhead.

    python -m bench.bench_engine [--json bench/results/engine.json] [--reps N] [--no-cpp]

Merges everything into one JSON file (sections "cpp" and "python") and prints a markdown table.
See bench/README.md for what each figure means.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_JSON = ROOT / "bench" / "results" / "engine.json"
DT = {"euler": 1e-4, "rk4": 1e-3}  # the step sizes used everywhere in the benchmark


def find_cpp_bench() -> Path | None:
    """armrt_bench of this tree: build/bench's (what ./run.sh bench builds), else the newest under build/, or on
    PATH. Never build/baseline's: bench_integrators builds an old commit there for its forward() comparison, and
    on a fresh clone that binary is the newest (its armrt_bench has no --model: the das3 part failed with it)."""
    preferred = ROOT / "build" / "bench" / "cpp" / "tools" / "armrt_bench"
    if preferred.is_file() and os.access(preferred, os.X_OK):
        return preferred
    baseline = ROOT / "build" / "baseline"
    found = sorted((p for p in (ROOT / "build").rglob("armrt_bench")
                    if p.is_file() and os.access(p, os.X_OK) and baseline not in p.parents),
                   key=lambda p: p.stat().st_mtime, reverse=True) if (ROOT / "build").is_dir() else []
    if found:
        return found[0]
    on_path = shutil.which("armrt_bench")
    return Path(on_path) if on_path else None


def run_cpp(reps: int, model: str = "das2") -> dict | None:
    """armrt_bench's JSON for `model` (None, with a message, if the tool is missing or fails)."""
    exe = find_cpp_bench()
    if exe is None:
        print("armrt_bench not built (cmake ... && ninja -C build/cmake armrt_bench): C++ figures skipped", file=sys.stderr)
        return None
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "cpp.json"
        proc = subprocess.run([str(exe), "--model", model, "--json", str(out), "--reps", str(reps)],
                              capture_output=True, text=True)
        if proc.returncode != 0:
            print(f"{exe} failed ({proc.returncode}):\n{proc.stderr}", file=sys.stderr)
            return None
        data = json.loads(out.read_text())
    data["binary"] = str(exe.relative_to(ROOT)) if exe.is_relative_to(ROOT) else str(exe)
    return data


def pin_cpu() -> int:
    try:
        cpu = 1 if (os.cpu_count() or 1) > 1 else 0
        os.sched_setaffinity(0, {cpu})
        return cpu
    except (AttributeError, OSError):
        return -1


def stimulation(arm) -> None:
    arm.set_excitation({"rotator_cuff": 0.05, "elbow_flexors": 0.3})


def percentiles(ns: np.ndarray) -> dict:
    return {"median": float(np.median(ns)), "p99": float(np.percentile(ns, 99)), "max": float(ns.max()),
            "mean": float(ns.mean()), "samples": int(ns.size)}


def bench_python(reps: int) -> dict:
    import armrt

    out: dict = {}
    for integ in ("euler", "rk4"):
        dt = DT[integ]
        # Per-call cost of Arm.step() (one step, through pybind11), wall time per call.
        arm = armrt.Arm(integrator=integ, dt=dt)
        stimulation(arm)
        window = int(round(2.0 / dt))
        for _ in range(200):
            arm.step()
        ns = np.empty(reps)
        k = 0
        clock = time.perf_counter_ns
        for i in range(reps):
            if k >= window:  # keep the state physiological
                arm.reset()
                k = 0
            t0 = clock()
            arm.step()
            ns[i] = clock() - t0
            k += 1
        out[f"arm_step_{integ}"] = {**percentiles(ns), "dt": dt,
                                    "what": f"Arm.step() one {integ} step through pybind11, dt = {dt} s"}

        # Throughput of Arm.simulate (loop in C++, recording every step).
        arm = armrt.Arm(integrator=integ, dt=dt)
        duration = 2.0
        runs = []
        for _ in range(3):
            arm.reset()
            t0 = time.perf_counter()
            res = arm.simulate({"rotator_cuff": 0.05, "elbow_flexors": 0.3}, duration=duration)
            runs.append(time.perf_counter() - t0)
        wall = min(runs)
        steps = len(res.time)
        out[f"simulate_{integ}"] = {"steps_per_s": steps / wall, "real_time_factor": duration / wall,
                                    "wall_s": wall, "sim_s": duration, "dt": dt,
                                    "what": f"Arm.simulate {duration} s of {integ} at dt = {dt} s, best of 3"}
    return out


def markdown(result: dict) -> str:
    lines = ["| item | median (ns) | p99 (ns) | max (ns) | what |", "|---|---:|---:|---:|---|"]
    for name, s in (result.get("cpp") or {}).items():
        lines.append(f"| {name} | {s['median']:.0f} | {s['p99']:.0f} | {s['max']:.0f} | {s.get('what', '')} |")
    py = result.get("python") or {}
    for name, s in py.items():
        if "median" in s:
            lines.append(f"| {name} | {s['median']:.0f} | {s['p99']:.0f} | {s['max']:.0f} | {s['what']} |")
    lines += ["", "| simulate | steps/s | real-time factor | wall (s) |", "|---|---:|---:|---:|"]
    for name, s in py.items():
        if "steps_per_s" in s:
            lines.append(f"| {name} (dt = {s['dt']:g} s) | {s['steps_per_s']:.0f} | {s['real_time_factor']:.1f} | {s['wall_s']:.3f} |")
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--json", type=Path, default=DEFAULT_JSON)
    ap.add_argument("--reps", type=int, default=20000, help="repetitions per timed item")
    ap.add_argument("--no-cpp", action="store_true", help="skip the C++ benchmark binary")
    args = ap.parse_args(argv)

    result: dict = {}
    if args.json.exists():
        try:
            result = json.loads(args.json.read_text())
        except json.JSONDecodeError:
            result = {}
    if not args.no_cpp:
        cpp = run_cpp(args.reps)
        if cpp is not None:
            meta = {k: v for k, v in cpp.items() if k != "cpp"}
            result["cpp"] = cpp["cpp"]
            result["cpp_meta"] = meta
    cpu = pin_cpu()
    result["python"] = bench_python(max(1000, args.reps // 4))
    result["python_meta"] = {"pinned_cpu": cpu, "python": sys.version.split()[0],
                             "timestamp": time.strftime("%Y-%m-%dT%H:%M:%S")}
    args.json.parent.mkdir(parents=True, exist_ok=True)
    args.json.write_text(json.dumps(result, indent=2) + "\n")
    print(markdown(result))
    print(f"\nwrote {args.json}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
