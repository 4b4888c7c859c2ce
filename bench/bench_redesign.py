"""The engine redesign, old and new side by side in one run: speed and bytes per arm.

    python -m bench.bench_redesign --old <old build dir> --new <new build dir> [--rounds 5] [--reps 20000]
        [--models das2,das3] [--old-python PY --new-python PY] [--json ...] [--md ...]

The old engine is commit ca5c936 (armrt::Simulator: its own Model, Data and integrator), the new one
armrt::Arm (a reference to the shared immutable Model, its Data and its Stepper). Each build dir is a
CMake build of one tree with the armrt_bench target built (cmake --build <dir> --target armrt_bench);
both `armrt_bench` binaries are run **interleaved** (round r: old, then new, for each model), with the
same arguments, and the 1-minute load average is recorded before and after each round. Per item the
median over the rounds of each run's median is reported, the spread (min-max over the rounds), and the
ratio new/old (of those medians, and the median of the per-round paired ratios). Items: forward()
(record=false), the default ROS2 1 ms step, RK4 at 1/6 ms (RK4 x6 = six of them per 1 ms control step)
and, for completeness, forward(record=true) and Euler at 0.1 ms.

Bytes per arm: a tiny C++ program is compiled against each tree's headers (cpp/include, cpp/generated;
g++ -std=c++20) and prints sizeof of Simulator / Model / Data (old) and Arm / Data / Stepper / Model and
Batch::stride() (new). In a batch of n arms the old engine holds n Simulators (each its own Model copy),
the new one n Arms and one shared Model: old = sizeof(Simulator), new = sizeof(Arm) + sizeof(Model) / n.
The sizes are fixed capacities (kMaxElements, kMaxDofs ...), the same for das2 and das3; the only heap
memory is CVODE's (not counted).

With --old-python / --new-python (interpreters of venvs where each tree is pip-installed), also Arm.step()
per call and Arm.simulate of 1 s on das2 at the default integrator, interleaved the same way.

Writes bench/results/redesign.json and bench/results/redesign.md. When the load average exceeded the
number of cores during any round the markdown says so at the top: the figures are then not a clean
comparison (both sides suffer, but not necessarily alike).
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
RESULTS = ROOT / "bench" / "results"
OLD_COMMIT = "ca5c936"

# (item in armrt_bench's JSON, label in the tables)
ITEMS = [("forward", "forward() (record=false)"), ("forward_record", "forward() (record=true)"),
         ("ros2_step", "ROS2 step, 1 ms (the default)"), ("rk4_step", "RK4 step, 1/6 ms"),
         ("euler_step", "Euler step, 0.1 ms")]
HEADLINE = ("forward", "ros2_step", "rk4_step")

SIZEOF_OLD = r"""
#include <cstdio>
#include "armrt/simulator.h"
#include "armrt/batch.h"
int main() {
  std::printf("{\"Simulator\": %zu, \"Model\": %zu, \"Data\": %zu, \"batch_stride\": %td}\n",
              sizeof(armrt::Simulator), sizeof(armrt::Model), sizeof(armrt::Data), armrt::Batch::stride());
}
"""
SIZEOF_NEW = r"""
#include <cstdio>
#include "armrt/arm.h"
#include "armrt/batch.h"
int main() {
  std::printf("{\"Arm\": %zu, \"Model\": %zu, \"Data\": %zu, \"Stepper\": %zu, \"batch_stride\": %td}\n",
              sizeof(armrt::Arm), sizeof(armrt::Model), sizeof(armrt::Data), sizeof(armrt::Stepper),
              armrt::Batch::stride());
}
"""

# Run by each venv's interpreter (outside the checkouts, so the installed armrt is the one imported).
PY_WORKER = r"""
import json, sys, time
import numpy as np
import armrt
reps = int(sys.argv[1])
u = {"rotator_cuff": 0.05, "elbow_flexors": 0.3}
arm = armrt.Arm("das2")
arm.set_excitation(u)
for _ in range(200):
    arm.step()
ns = np.empty(reps)
clock = time.perf_counter_ns
k = 0
for i in range(reps):
    if k >= 2000:
        arm.reset(); arm.set_excitation(u); k = 0
    t0 = clock(); arm.step(); ns[i] = clock() - t0
    k += 1
walls = []
for _ in range(3):
    arm.reset()
    t0 = time.perf_counter()
    res = arm.simulate(u, duration=1.0)
    walls.append(time.perf_counter() - t0)
print(json.dumps({"armrt_file": armrt.__file__, "integrator": getattr(arm, "integrator", None), "dt": arm.dt,
                  "arm_step_median_ns": float(np.median(ns)), "arm_step_p99_ns": float(np.percentile(ns, 99)),
                  "simulate_1s_best_s": min(walls), "simulate_1s_median_s": float(np.median(walls)),
                  "steps": len(res.time)}))
"""


def load1() -> float:
    return os.getloadavg()[0]


def machine() -> dict:
    cpu = ""
    try:
        m = re.search(r"^model name\s*:\s*(.+)$", Path("/proc/cpuinfo").read_text(), re.M)
        cpu = m.group(1).strip() if m else ""
    except OSError:
        pass
    return {"cpus": os.cpu_count(), "cpu": cpu or platform.processor(), "kernel": platform.release(),
            "python": platform.python_version(), "load_avg_start": os.getloadavg()}


def source_dir(build: Path) -> Path:
    """The source tree of a CMake build dir (CMakeCache.txt's CMAKE_HOME_DIRECTORY)."""
    cache = build / "CMakeCache.txt"
    if cache.exists():
        m = re.search(r"^CMAKE_HOME_DIRECTORY:INTERNAL=(.+)$", cache.read_text(), re.M)
        if m:
            return Path(m.group(1).strip())
    raise SystemExit(f"{build}: not a CMake build dir (no CMakeCache.txt)")


def commit_of(tree: Path) -> str:
    r = subprocess.run(["git", "-C", str(tree), "log", "-1", "--format=%h %s"], capture_output=True, text=True)
    return r.stdout.strip()[:100] if r.returncode == 0 else "?"


def bench_binary(build: Path) -> Path:
    b = build / "cpp" / "tools" / "armrt_bench"
    if not b.exists():
        raise SystemExit(f"{b} not found: cmake --build {build} --target armrt_bench")
    return b


def run_bench(binary: Path, model: str, reps: int) -> dict:
    with tempfile.TemporaryDirectory(prefix="armrt-redesign-") as tmp:
        out = Path(tmp) / "r.json"
        subprocess.run([str(binary), "--model", model, "--reps", str(reps), "--json", str(out)], check=True,
                       capture_output=True, text=True)
        d = json.loads(out.read_text())
    return {"pinned_cpu": d.get("pinned_cpu"), **{k: {s: v[s] for s in ("median", "p99", "min", "max")}
                                                  for k, v in d["cpp"].items()}}


def sizes(tree: Path, source: str) -> dict:
    with tempfile.TemporaryDirectory(prefix="armrt-sizeof-") as tmp:
        src, exe = Path(tmp) / "sizeof.cc", Path(tmp) / "sizeof"
        src.write_text(source)
        cmd = ["g++", "-std=c++20", "-O1", f"-I{tree / 'cpp' / 'include'}", f"-I{tree / 'cpp' / 'generated'}",
               "-I/usr/include/eigen3", str(src), "-o", str(exe)]
        subprocess.run(cmd, check=True, capture_output=True, text=True)
        return json.loads(subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout)


def run_python(py: str, reps: int) -> dict:
    r = subprocess.run([py, "-c", PY_WORKER, str(reps)], check=True, capture_output=True, text=True,
                       cwd=tempfile.gettempdir(), env={k: v for k, v in os.environ.items() if k != "PYTHONPATH"})
    return json.loads(r.stdout.strip().splitlines()[-1])


def summary(old: list[float], new: list[float]) -> dict:
    o, n = np.asarray(old, float), np.asarray(new, float)
    return {"old": {"median": float(np.median(o)), "min": float(o.min()), "max": float(o.max()), "runs": o.tolist()},
            "new": {"median": float(np.median(n)), "min": float(n.min()), "max": float(n.max()), "runs": n.tolist()},
            "ratio_new_old": float(np.median(n) / np.median(o)),
            "paired_ratio_median": float(np.median(n / o)),
            "paired_ratio_range": [float((n / o).min()), float((n / o).max())]}


def bytes_table(old: dict, new: dict, ns=(1, 8, 64, 1024)) -> list[dict]:
    return [{"n": n, "old_bytes_per_arm": old["Simulator"], "new_bytes_per_arm": new["Arm"] + new["Model"] / n,
             "new_over_old": (new["Arm"] + new["Model"] / n) / old["Simulator"]} for n in ns]


def markdown(r: dict) -> str:
    m = r["machine"]
    loads = [x for rd in r["rounds"] for x in (rd["load_before"], rd["load_after"])]
    L = ["# Redesign: old and new engine side by side", "",
         f"`{r['command']}`, {r['date']}; old = {r['old']['commit']} ({r['old']['build']}), "
         f"new = {r['new']['commit']} ({r['new']['build']}).", "",
         f"Machine: {m['cpus']} CPUs ({m['cpu']}), 1-min load average {min(loads):.2f}-{max(loads):.2f} over the "
         f"{r['rounds_n']} rounds (before/after each round below)."]
    if r.get("note"):
        L += ["", f"Note: {r['note']}"]
    if r["contended"]:
        L += ["", f"**CONTENDED: the load average exceeded the {m['cpus']} cores during the run "
                  f"(max {max(loads):.2f}); other work shared the CPUs, so these figures are not a clean comparison "
                  f"(old and new ran interleaved, so both saw the contention, but not necessarily alike).**"]
    else:
        L += ["", f"The load average stayed at or below the {m['cpus']} cores throughout."]
    L += ["", "## C++ (`armrt_bench`, ns per call, median over the rounds of each run's median; spread = min-max)", "",
          "| model | item | old | new | new/old | paired new/old (range) |", "|---|---|---:|---:|---:|---:|"]
    for model, items in r["cpp"].items():
        for key, label in ITEMS:
            if key not in items:
                continue
            s = items[key]
            L.append(f"| {model} | {label} | {s['old']['median']:.0f} ({s['old']['min']:.0f}-{s['old']['max']:.0f}) | "
                     f"{s['new']['median']:.0f} ({s['new']['min']:.0f}-{s['new']['max']:.0f}) | {s['ratio_new_old']:.3f} | "
                     f"{s['paired_ratio_median']:.3f} ({s['paired_ratio_range'][0]:.2f}-{s['paired_ratio_range'][1]:.2f}) |")
        missing = [label for key, label in ITEMS if key not in items]
        if missing:
            L.append(f"| {model} | not timed: {', '.join(missing)} | | | | |")
        if "rk4_step" in items:
            s = items["rk4_step"]
            L.append(f"| {model} | RK4 x6 per 1 ms control step (6 x the RK4 step) | {6 * s['old']['median']:.0f} | "
                     f"{6 * s['new']['median']:.0f} | {s['ratio_new_old']:.3f} | |")
    L += ["", "An item not timed was refused by armrt_bench on both sides (das3's stiffest resting fibre needs "
              "shorter explicit steps than 0.1 ms Euler / 1/6 ms RK4), or absent from one side's output.",
          "", "ROS2 steps are timed in runs of three (one exact evaluation of the muscle paths, two extrapolated): "
              "the figure is per step. p99 per item and every round's figures are in redesign.json."]
    b = r["bytes"]
    L += ["", "## Bytes per arm (sizeof, g++ -std=c++20 against each tree's headers)", "",
          f"- old: `sizeof(Simulator)` = {b['old']['Simulator']} (its own Model {b['old']['Model']} + Data "
          f"{b['old']['Data']} + integrator), `Batch::stride()` = {b['old']['batch_stride']}",
          f"- new: `sizeof(Arm)` = {b['new']['Arm']} (a reference to the shared Model + Data {b['new']['Data']} + "
          f"Stepper {b['new']['Stepper']}), `Batch::stride()` = {b['new']['batch_stride']}; the one shared Model is "
          f"{b['new']['Model']}", "",
          "| arms in a batch | old bytes/arm | new bytes/arm | new/old |", "|---:|---:|---:|---:|"]
    for row in b["per_arm"]:
        L.append(f"| {row['n']} | {row['old_bytes_per_arm']:.0f} | {row['new_bytes_per_arm']:.0f} | {row['new_over_old']:.3f} |")
    L += ["", "Fixed capacities (kMaxElements = 160, kMaxDofs = 16, ...), so the same for every model; CVODE's heap "
              "memory (only when that integrator is chosen) is not counted."]
    py = r.get("python")
    L += ["", "## Python (das2, default integrator, `Arm.step()` per call and `Arm.simulate` of 1 s)", ""]
    if not py:
        L.append(r.get("python_skipped", "skipped"))
    else:
        L += ["| item | old | new | new/old |", "|---|---:|---:|---:|"]
        for key, label, unit, scale in (("arm_step_median_ns", "Arm.step() median", "us", 1e-3),
                                        ("simulate_1s_best_s", "Arm.simulate 1 s, best of 3", "ms", 1e3)):
            s = py[key]
            L.append(f"| {label} ({unit}) | {s['old']['median'] * scale:.2f} ({s['old']['min'] * scale:.2f}-"
                     f"{s['old']['max'] * scale:.2f}) | {s['new']['median'] * scale:.2f} ({s['new']['min'] * scale:.2f}-"
                     f"{s['new']['max'] * scale:.2f}) | {s['ratio_new_old']:.3f} |")
        L += ["", f"Interpreters: old `{py['old_python']}`, new `{py['new_python']}` (armrt from "
                  f"`{py['old_armrt']}` and `{py['new_armrt']}`)."]
    L += ["", "## Load per round (1-min load average)", "", "| round | before | after |", "|---:|---:|---:|"]
    for k, rd in enumerate(r["rounds"]):
        L.append(f"| {k + 1} | {rd['load_before']:.2f} | {rd['load_after']:.2f} |")
    return "\n".join(L) + "\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--old", type=Path, required=True, help="CMake build dir of the old tree (armrt_bench built)")
    ap.add_argument("--new", type=Path, required=True, help="CMake build dir of the new tree (armrt_bench built)")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--reps", type=int, default=20000, help="armrt_bench --reps")
    ap.add_argument("--models", default="das2,das3")
    ap.add_argument("--old-python", help="interpreter with the old tree pip-installed (for the Python figures)")
    ap.add_argument("--new-python", help="interpreter with the new tree pip-installed")
    ap.add_argument("--py-reps", type=int, default=20000, help="Arm.step() calls timed per round")
    ap.add_argument("--note", default="", help="a remark printed under the header (e.g. how a venv was prepared)")
    ap.add_argument("--json", type=Path, default=RESULTS / "redesign.json")
    ap.add_argument("--md", type=Path, default=RESULTS / "redesign.md")
    a = ap.parse_args(argv)
    old_b, new_b = a.old.resolve(), a.new.resolve()
    old_src, new_src = source_dir(old_b), source_dir(new_b)
    old_bin, new_bin = bench_binary(old_b), bench_binary(new_b)
    models = [m for m in a.models.split(",") if m]
    python = bool(a.old_python and a.new_python)
    res: dict = {"command": "python -m bench.bench_redesign " + " ".join(argv if argv is not None else sys.argv[1:]),
                 "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "machine": machine(),
                 "old": {"build": str(old_b), "source": str(old_src), "commit": commit_of(old_src)},
                 "new": {"build": str(new_b), "source": str(new_src), "commit": commit_of(new_src)},
                 "note": a.note, "rounds_n": a.rounds, "reps": a.reps, "models": models, "order": "each round: old then new, per model"}
    print("sizeof ...", file=sys.stderr)
    b_old, b_new = sizes(old_src, SIZEOF_OLD), sizes(new_src, SIZEOF_NEW)
    res["bytes"] = {"old": b_old, "new": b_new, "per_arm": bytes_table(b_old, b_new)}
    runs = {m: {"old": [], "new": []} for m in models}
    pyruns = {"old": [], "new": []}
    rounds = []
    for k in range(a.rounds):
        rd = {"load_before": load1()}
        t0 = time.perf_counter()
        for m in models:
            runs[m]["old"].append(run_bench(old_bin, m, a.reps))
            runs[m]["new"].append(run_bench(new_bin, m, a.reps))
        if python:
            pyruns["old"].append(run_python(a.old_python, a.py_reps))
            pyruns["new"].append(run_python(a.new_python, a.py_reps))
        rd["load_after"] = load1()
        rd["seconds"] = round(time.perf_counter() - t0, 1)
        rounds.append(rd)
        fw = runs[models[0]]
        print(f"round {k + 1}/{a.rounds}: load {rd['load_before']:.2f} -> {rd['load_after']:.2f}, {models[0]} "
              f"ros2_step old {fw['old'][-1]['ros2_step']['median']:.0f} new {fw['new'][-1]['ros2_step']['median']:.0f} ns "
              f"({rd['seconds']} s)", file=sys.stderr)
    res["rounds"] = rounds
    cpus = os.cpu_count() or 1
    res["contended"] = any(max(rd["load_before"], rd["load_after"]) > cpus for rd in rounds)
    res["cpp"] = {}
    for m in models:
        items = {}
        for key, _ in ITEMS:
            if all(key in r for r in runs[m]["old"] + runs[m]["new"]):
                items[key] = summary([r[key]["median"] for r in runs[m]["old"]], [r[key]["median"] for r in runs[m]["new"]])
                items[key]["p99"] = summary([r[key]["p99"] for r in runs[m]["old"]], [r[key]["p99"] for r in runs[m]["new"]])
        res["cpp"][m] = items
    res["pinned_cpu"] = {s: sorted({r["pinned_cpu"] for m in models for r in runs[m][s]}) for s in ("old", "new")}
    if python:
        res["python"] = {key: summary([r[key] for r in pyruns["old"]], [r[key] for r in pyruns["new"]])
                         for key in ("arm_step_median_ns", "arm_step_p99_ns", "simulate_1s_best_s", "simulate_1s_median_s")}
        res["python"].update(old_python=a.old_python, new_python=a.new_python, old_armrt=pyruns["old"][0]["armrt_file"],
                             new_armrt=pyruns["new"][0]["armrt_file"], integrator=pyruns["new"][0]["integrator"],
                             dt=pyruns["new"][0]["dt"], steps=pyruns["new"][0]["steps"])
    else:
        res["python_skipped"] = "Skipped: no --old-python/--new-python given (each tree pip-installed into its own venv)."
    a.json.parent.mkdir(parents=True, exist_ok=True)
    a.json.write_text(json.dumps(res, indent=1) + "\n")
    a.md.write_text(markdown(res))
    print(markdown(res))
    print(f"wrote {a.json} and {a.md}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
