"""The C++ static optimisation (cpp/src/static_optimization.cc; issue 28 item 2): per-solve time from Python
(StaticOptimizer(tendon="rigid", backend="cpp") against backend="python", the same QP), and in C++ alone
(cpp/tools/bench_static_optimization.cc: wall time and, with --instructions, callgrind's instruction count per
solve, which the machine's load does not change), along bench.static_optimization's das2 motion (400 frames, 1 kHz,
1 kg in the hand, warm started), without a GH bound, with GHstab <= 0.3 (not binding on this motion) and <= 0.1
(binding); and the elastic tendon's SQP (StaticOptimizer(backend="cpp") against backend="python";
static_optimization_elastic alone, the tool's --elastic) without a bound and with GHstab <= 0.3. The machine's load
is recorded: wall times scale with it.

    python -m bench.static_optimization_cpp [--frames 400] [--tool build/dev/cpp/tools/armrt_bench_static_optimization]
        [--instructions]
Writes bench/results/static_optimization_cpp.json and .md.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import tempfile
from pathlib import Path

import numpy as np

import armrt

from .static_optimization import RESULTS, motion, run_case

ROOT = Path(__file__).resolve().parent.parent
CASES = [("no GH bound", None), ("GHstab <= 0.3", 0.3), ("GHstab <= 0.1 (binding)", 0.1)]
ELASTIC_CASES = [("elastic tendon, no GH bound", None), ("elastic tendon, GHstab <= 0.3", 0.3)]


def cpp_tool(tool: Path, frames: int, gh, extra=()) -> dict:
    args = [str(tool), "--frames", str(frames), *(["--gh-stab-max", str(gh)] if gh else []), *extra]
    return json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)


def instructions_per_solve(tool: Path, frames: int, gh, extra=()) -> float:
    """callgrind's inclusive instruction count of static_optimization_rigid (or _elastic, with --elastic) / frames."""
    function = "armrt::static_optimization_elastic(" if "--elastic" in extra else "armrt::static_optimization_rigid("
    with tempfile.TemporaryDirectory() as d:
        out = Path(d) / "cg.out"
        subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", str(tool), "--frames", str(frames),
                        *(["--gh-stab-max", str(gh)] if gh else []), *extra], check=True, capture_output=True)
        ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", str(out)], check=True, capture_output=True,
                             text=True).stdout
    for line in ann.splitlines():
        if function in line:
            return float(line.split()[0].replace(",", "")) / frames
    raise RuntimeError(f"{function} not in the callgrind profile")


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--frames", type=int, default=400)
    ap.add_argument("--tool", type=Path, default=ROOT / "build/dev/cpp/tools/armrt_bench_static_optimization")
    ap.add_argument("--instructions", action="store_true", help="callgrind instruction counts (needs valgrind)")
    args = ap.parse_args(argv)
    load_before = os.getloadavg()
    hand = np.array([0.0, -9.81, 0.0])
    arm = armrt.Arm("das2")
    q, qd, qdd = motion(arm, np.radians([20, 40, 0, 60, 60]), args.frames)
    python_api, cpp_only = {}, {}
    # (case, GH bound, tendon, the C++ tool's runs: (label, extra arguments))
    rigid_runs = (("dual Newton (fallback ProxQP)", ()), ("ProxQP only", ("--proxqp",)))
    elastic_runs = (("SQP, dual Newton (fallback ProxQP)", ("--elastic",)),)
    for name, gh, tendon, runs in [(n, g, "rigid", rigid_runs) for n, g in CASES] + \
                                  [(n, g, "elastic", elastic_runs) for n, g in ELASTIC_CASES]:
        for backend in ("cpp", "python"):
            c = run_case(arm, q, qd, qdd, hand, True, tendon=tendon, gh_stab_max=gh, backend=backend)
            python_api[f"{name}, backend={backend}"] = c
            print(name, backend, {k: c[k] for k in ("median_ms", "p99_ms", "frames_not_converged")}, flush=True)
        if args.tool.exists():
            for solver, extra in runs:
                r = cpp_tool(args.tool, args.frames, gh, extra)
                if args.instructions and shutil.which("valgrind"):
                    r["instructions_per_solve"] = instructions_per_solve(args.tool, args.frames, gh, extra)
                cpp_only[f"{name}, {solver}"] = r
                print(name, solver, r, flush=True)
    load_after = os.getloadavg()
    import proxsuite
    cmd = "python -m bench.static_optimization_cpp " + " ".join(argv or [])
    out = {"command": cmd.strip(), "python_api": python_api, "cpp": cpp_only, "cpus": os.cpu_count(),
           "loadavg_1min_before_after": [load_before[0], load_after[0]], "proxsuite": proxsuite.__version__,
           "target": "<= 1 ms per solve from Python, <= 200 us in C++ (issue 28)"}
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "static_optimization_cpp.json").write_text(json.dumps(out, indent=2) + "\n")
    lines = ["# Static optimisation in C++: time per solve", "",
             f"`{out['command']}` (proxsuite {out['proxsuite']}). 1-min load average {load_before[0]:.2f} before, "
             f"{load_after[0]:.2f} after, {out['cpus']} CPUs shared with other jobs: wall times scale with the load; "
             "instruction counts do not.", "",
             "From Python (StaticOptimizer.solve, warm, the whole call):", "",
             "| case | frames | infeasible | median ms | p99 ms | moment residual max N m | GHstab max |",
             "|---|---|---|---|---|---|---|"]
    for name, c in python_api.items():
        lines.append(f"| {name} | {c['frames']} | {c['frames_not_converged']} | {c['median_ms']:.3f} | {c['p99_ms']:.3f} | "
                     f"{c['moment_residual_max_Nm']:.1e} | {c['gh_stab_max']:.3f} |")
    if cpp_only:
        lines += ["", "In C++ (static_optimization_rigid or _elastic alone, `cpp/tools/bench_static_optimization.cc`):", "",
                  "| case | infeasible | median us | p99 us | max us | instructions per solve | Newton iterations max | "
                  "ProxQP solves | QPs max | moment residual max N m |", "|---|---|---|---|---|---|---|---|---|---|"]
        for name, r in cpp_only.items():
            ins = r.get("instructions_per_solve")
            lines.append(f"| {name} | {r['infeasible']} | {r['median_ns'] / 1e3:.1f} | {r['p99_ns'] / 1e3:.1f} | "
                         f"{r['max_ns'] / 1e3:.1f} | {'' if ins is None else f'{ins / 1e3:.0f} k'} | "
                         f"{r['newton_iterations_max']} | {r['proxqp_solves']} | {r['qps_max']} | "
                         f"{r['residual_max']:.1e} |")
    (RESULTS / "static_optimization_cpp.md").write_text("\n".join(lines) + "\n")
    return out


if __name__ == "__main__":
    main()
