"""Where a ROS2 step's work goes, stage by stage, by instruction counts (issue 26 item 1).

    python -m bench.profile_step [--build build/dev] [--models das2,das3] [--reps 300]

This VM exposes no hardware counters (`perf stat -e instructions` says <not supported>), so instructions come from
valgrind's callgrind, which counts every instruction retired whatever the machine's load: `armrt_bench` runs under
`valgrind --tool=callgrind --toggle-collect='armrt::step_ros2*'` (only instructions inside ROS2 steps are counted),
`callgrind_annotate --inclusive=yes --tree=calling` gives each function's cost and its callees', and this script
divides by the number of steps (the calls of jacobian_factor: one per step). The default ROS2 step of armrt_bench
computes the outputs at its first stage (record), as Arm.simulate does.

Alongside, the wall time per step (armrt_bench's median, a plain run of the same binary right after) gives
instructions per nanosecond. Writes bench/results/profile_step.json and .md.
"""
from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent

# A callgrind_annotate line: "  1,234 (12.34%)  *  ???:name(args) [object]" (">" for a callee, with its call count).
LINE = re.compile(r"^\s*([\d,]+)\s+\(\s*[\d.]+%\)\s+([*>])\s+(.*)$")
NAME = re.compile(r"(?:\?\?\?|[^:]*):(?:void )?((?:[\w]+::)*(?:\(anonymous namespace\)::)?[~\w<>]+)\(")
CALLS = re.compile(r"\(([\d,]+)x\)")


def short(name: str) -> str:
    n = name.replace("armrt::(anonymous namespace)::", "").replace("armrt::", "")
    return re.sub(r"^generated::\w+::", "generated ", n)


def call_tree(annotated: str) -> dict:
    """{function: {"cost": inclusive Ir, "callees": {callee: (Ir of the calls, number of calls)}}}."""
    tree, current = {}, None
    for line in annotated.splitlines():
        m = LINE.match(line)
        if not m:
            continue
        cost, kind, rest = int(m.group(1).replace(",", "")), m.group(2), m.group(3)
        nm = NAME.search(rest)
        if not nm:
            continue
        name = short(nm.group(1))
        if kind == "*":
            current = tree.setdefault(name, {"cost": cost, "callees": {}})
            current["cost"] = cost
        elif current is not None:
            calls = CALLS.search(rest)
            current["callees"][name] = (cost, int(calls.group(1).replace(",", "")) if calls else 0)
    return tree


def profile(bench: Path, model: str, reps: int) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "cg.out"
        subprocess.run(["valgrind", "--tool=callgrind", "--toggle-collect=armrt::step_ros2*",
                        f"--callgrind-out-file={out}", str(bench), "--model", model, "--reps", str(reps), "--no-pin",
                        "--json", str(Path(tmp) / "x.json")], check=True, capture_output=True, text=True)
        annotated = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--tree=calling", "--threshold=100",
                                    str(out)], check=True, capture_output=True, text=True).stdout
        subprocess.run([str(bench), "--model", model, "--reps", "20000", "--json", str(Path(tmp) / "t.json")],
                       check=True, capture_output=True, text=True)
        timing = json.loads((Path(tmp) / "t.json").read_text())["cpp"]
    tree = call_tree(annotated)
    steps = tree["ros2_stages"]["callees"]["jacobian_factor"][1]
    total = tree["step_ros2"]["cost"]

    def rows(parent: str) -> list:
        node = tree[parent]
        out = [(callee, cost / steps, calls / steps) for callee, (cost, calls) in node["callees"].items()]
        # (calls / steps is right only for callees that run inside steps alone: see markdown())
        out.sort(key=lambda r: -r[1])
        listed = sum(r[1] for r in out)
        out.append((f"({parent} itself)", node["cost"] / steps - listed, 1.0))
        return out

    return {"model": model, "steps": steps, "instructions_per_step": total / steps,
            "wall_ns_per_step": timing["ros2_step"]["median"],
            "step": rows("ros2_stages"), "forward_from_paths": rows("forward_from_paths"),
            "forward": rows("forward")}


def markdown(results: list, command: str) -> str:
    lines = ["# Where a ROS2 step's work goes (instructions, callgrind)", "", f"`{command}`", "",
             "Instructions retired inside ROS2 steps (valgrind callgrind, load-independent), per step; each table "
             "lists a function's direct callees (inclusive: a callee's own callees are in its row). Wall time: "
             "armrt_bench's median ROS2 step in a plain run right after.", ""]
    for r in results:
        ipn = r["instructions_per_step"] / r["wall_ns_per_step"]
        lines += [f"## {r['model']}: {r['instructions_per_step']:,.0f} instructions per step, "
                  f"{r['wall_ns_per_step']:,.0f} ns per step ({ipn:.2f} instructions/ns), {r['steps']} steps counted",
                  ""]
        for part, title in (("step", "the step (ros2_stages)"), ("forward", "forward() (the step's exact-path "
                                                                              "evaluations)"),
                            ("forward_from_paths", "forward_from_paths (every state derivative)")):
            # Calls are counted outside the collected steps too (callgrind counts calls while not collecting), so
            # only the step's own callees, which run inside steps only, have a meaningful count per step.
            with_calls = part == "step"
            lines += [f"### {title}", "", "| callee | instructions per step | share of the step |"
                      + (" calls per step |" if with_calls else ""), "|---|---:|---:|" + ("---:|" if with_calls else "")]
            for name, cost, calls in r[part]:
                lines.append(f"| {name} | {cost:,.0f} | {100 * cost / r['instructions_per_step']:.1f} % |"
                             + (f" {calls:.2f} |" if with_calls else ""))
            lines.append("")
    return "\n".join(lines) + "\n"


def callgrind_bench_args(doc: str, name: str, default_reps: int, argv=None):
    """(args, armrt_bench path, the command line to quote) of a callgrind benchmark over armrt_bench's steps
    (this one and bench/roofline.py): --build, --models, --reps, --json, --md with results/<name>.{json,md}."""
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    ap.add_argument("--build", default=str(REPO / "build" / "dev"), help="a CMake build dir with armrt_bench built")
    ap.add_argument("--models", default="das2,das3")
    ap.add_argument("--reps", type=int, default=default_reps,
                    help=f"armrt_bench --reps under callgrind (default {default_reps})")
    ap.add_argument("--json", default=str(HERE / "results" / f"{name}.json"))
    ap.add_argument("--md", default=str(HERE / "results" / f"{name}.md"))
    args = ap.parse_args(argv)
    bench = Path(args.build) / "cpp" / "tools" / "armrt_bench"
    if not bench.is_file():
        ap.error(f"no {bench}: cmake --build {args.build} --target armrt_bench")
    command = f"python -m bench.{name} " + " ".join(f"--{k} {v}" for k, v in
                                                    (("build", os.path.relpath(args.build, REPO)),
                                                     ("models", args.models), ("reps", args.reps)))
    return args, bench, command


def main(argv=None) -> int:
    args, bench, command = callgrind_bench_args(__doc__, "profile_step", 300, argv)
    results = [profile(bench, m, args.reps) for m in args.models.split(",")]
    Path(args.json).write_text(json.dumps({"command": command, "results": results}, indent=1) + "\n")
    Path(args.md).write_text(markdown(results, command))
    print(markdown(results, command))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
