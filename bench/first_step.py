"""Time to first step (issue 26 item 4): how long a new Python process takes from its start to the arm's first
control step, split into `import numpy` (armrt's one heavy dependency, imported first so that the next figure
is armrt's own), `import armrt`, `armrt.Arm(model)` (the model's load and the arm's construction) and the
first `arm.step()`, for the built-in das2, das3 and participant_A, and for a model built on demand from its file
(models/participant_A_FES.json) with its library already in the cache (a cold build compiles C++: see
bench/results/models.json, `first_build_s`). Each figure comes from its own fresh process (the operating
system's file cache is warm, as it is for a user's second run); the interpreter's own start-up is measured
beside it (`python -c pass`). Best and median of `--repeats` processes, with the machine's load recorded.

    python -m bench.first_step [--repeats 7]
Writes bench/results/first_step.json and .md.
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "bench" / "results"

# Runs in the measured process: times from just before `import armrt` (the interpreter already started).
PROBE = """
import json, sys, time
tn = time.perf_counter()
import numpy
t0 = time.perf_counter()
import armrt
t1 = time.perf_counter()
arm = armrt.Arm(sys.argv[1])
t2 = time.perf_counter()
arm.step()
t3 = time.perf_counter()
assert arm.time > 0
print(json.dumps({"numpy_s": t0 - tn, "import_s": t1 - t0, "arm_s": t2 - t1, "first_step_s": t3 - t2, "total_s": t3 - tn}))
"""

MODELS = {"das2": "das2", "das3": "das3", "participant_A": "participant_A",
          "participant_A_FES (on demand, cached)": str(ROOT / "models" / "participant_A_FES.json")}


def one(model: str) -> dict:
    r = subprocess.run([sys.executable, "-c", PROBE, model], capture_output=True, text=True, check=True)
    return json.loads(r.stdout.strip().splitlines()[-1])


def interpreter_start_s() -> float:
    t = time.perf_counter()
    subprocess.run([sys.executable, "-c", "pass"], check=True)
    return time.perf_counter() - t


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=7)
    args = ap.parse_args(argv)
    for model in MODELS.values():
        one(model)  # a model built on demand is built here if its library is not cached yet
    load0 = os.getloadavg()
    runs = {name: [one(model) for _ in range(args.repeats)] for name, model in MODELS.items()}
    python_start = [interpreter_start_s() for _ in range(args.repeats)]
    load1 = os.getloadavg()
    keys = ("numpy_s", "import_s", "arm_s", "first_step_s", "total_s")
    out = {"command": " ".join(["python -m bench.first_step", *(argv if argv is not None else sys.argv[1:])]),
           "repeats": args.repeats, "cpus": os.cpu_count(), "load_average_before": [round(x, 2) for x in load0],
           "load_average_after": [round(x, 2) for x in load1],
           "time": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
           "python_start_ms": {"best": round(1e3 * min(python_start), 1),
                               "median": round(1e3 * statistics.median(python_start), 1)},
           "models": {name: {k: {"best_ms": round(1e3 * min(r[k] for r in rs), 2),
                                 "median_ms": round(1e3 * statistics.median(r[k] for r in rs), 2)} for k in keys}
                      for name, rs in runs.items()}}
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "first_step.json").write_text(json.dumps(out, indent=1) + "\n")
    lines = [f"# Time to first step (`{out['command']}`)", "",
             f"Median (best) of {args.repeats} fresh processes each; 1-min load average {load0[0]:.2f} before, "
             f"{load1[0]:.2f} after, {out['cpus']} CPUs. The interpreter's own start-up (`python -c pass`): "
             f"{out['python_start_ms']['median']} ms ({out['python_start_ms']['best']}).", "",
             "| model | `import numpy` (ms) | then `import armrt` (ms) | `armrt.Arm(model)` (ms) | first `arm.step()` (ms) "
             "| total (ms) |",
             "|---|---|---|---|---|---|"]
    for name, m in out["models"].items():
        cells = [f"{m[k]['median_ms']:.1f} ({m[k]['best_ms']:.1f})" for k in keys]
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    (RESULTS / "first_step.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
