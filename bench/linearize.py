"""What Arm.linearize costs against the step it differentiates (issue 28 item 4; docs/control.md "Linearised dynamics", "Cost"): das2 and
das3 at the default ROS2 1 ms step, at a moving, co-contracted state, the engine's linearize() (through the binding,
which also allocates the numpy outputs) for the continuous df/dx, df/du alone and for A, B of one step, and the whole
Arm.linearize() call, against one step. Interleaved repetitions in one run, best of each, the machine's load recorded.

    python -m bench.linearize [--repeats 7] [--instructions]
    python -m bench.linearize --residuals     # the finite-difference residuals of tests/test_linearize.py's states
Writes bench/results/linearize.json and .md (--residuals: linearize_residuals.json and .md). With --instructions it also counts the instructions of the engine's
linearize() and step() under valgrind's callgrind (load-independent): each process runs twice, calling 0 and
--instruction-calls times after the same set-up, with only the engine function collected
(--toggle-collect='armrt::linearize(*' or 'armrt::step(*'), and the difference divided by the calls.
"""
from __future__ import annotations

import argparse
import copy
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import armrt

RESULTS = Path(__file__).resolve().parent / "results"
MODELS = ("das2", "das3")


def moving_arm(model: str) -> armrt.Arm:
    """An arm 200 steps into a co-contraction (every excitation 0.1-0.3, seeded) from its rest posture."""
    arm = armrt.Arm(model)
    u = np.random.default_rng(0).uniform(0.1, 0.3, arm.n_elements)
    arm.set_excitation(u)
    arm.reset(activation=u)
    arm.step(200)
    return arm


def workload(arm: armrt.Arm, what: str, calls: int) -> None:
    ws = armrt._core.LinearizeWorkspace()
    if what == "step":
        arm._sim.step(calls)
    else:
        for _ in range(calls):
            arm._sim.linearize(ws, what == "discrete")


def instructions(model: str, what: str, calls: int) -> float:
    if shutil.which("valgrind") is None:
        raise SystemExit("--instructions needs valgrind (Debian package valgrind)")
    fn = "armrt::step(*" if what == "step" else "armrt::linearize(*"
    counts = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in (0, calls):
            log = Path(tmp) / f"{n}.log"
            subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={tmp}/{n}.out",
                            f"--toggle-collect={fn}", f"--log-file={log}", sys.executable, "-m", "bench.linearize",
                            "--child", model, what, str(n)], check=True, cwd=Path(__file__).resolve().parent.parent)
            line = next(l for l in log.read_text().splitlines() if "Collected" in l)
            counts.append(int(line.split(":")[-1].replace(",", "")))
    return (counts[1] - counts[0]) / calls


def residuals() -> None:
    """Largest block-relative residual |A - A_fd| / max|A_fd| (and of B, dfdx, dfdu) over each (row block, column
    block) at the states of tests/test_linearize.py (run from the repository root: it imports the test's helpers),
    the kinked columns left out as there; also how many columns had a kink."""
    sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
    from tests.test_linearize import differences, random_arm
    rows = []
    for model, seed in (("das2", 1), ("das2", 2), ("das2", 3), ("das3", 1)):
        arm = random_arm(model, seed)
        lin = arm.linearize()
        A, B, J, Ju, _, kinks = differences(arm, lin)
        keep = np.setdiff1d(np.arange(lin.x0.size), kinks)
        worst = {}
        for name, got, ref, by_cols in (("A", lin.A, A, True), ("dfdx", lin.dfdx, J, True), ("B", lin.B, B, False),
                                        ("dfdu", lin.dfdu, Ju, False)):
            w = 0.0
            for rs in lin.slices.values():
                for cs in (lin.slices.values() if by_cols else [slice(None)]):
                    cols = np.intersect1d(np.arange(lin.x0.size)[cs], keep) if by_cols else np.arange(ref.shape[1])
                    r, g = ref[rs][:, cols], got[rs][:, cols]
                    scale = np.abs(r).max(initial=0.0)
                    if scale > 1e-6 * np.abs(ref[rs]).max(initial=0.0) and scale > 0:
                        w = max(w, float(np.abs(g - r).max() / scale))
            worst[name] = w
        # At the kinked columns: how far the linearisation is from the central difference and from the nearer of the
        # one-sided ones (the side it belongs to), relative to the column's largest entry.
        kink_central = kink_one_sided = 0.0
        for k in kinks:
            e = np.zeros(lin.x0.size)
            block = next(i for i, s in enumerate(lin.slices.values()) if s.start <= k < s.stop)
            eps = (1e-6, 1e-5, 1e-7, 1e-6)[block]  # the test's steps: rad, rad/s, m, 1
            e[k] = eps
            step = lambda x: (arm.set_state_vector(x, armrt.StatePart.PHYSICS), arm.set_excitation(lin.u0),
                              arm.step(1), arm.get_state_vector(armrt.StatePart.PHYSICS))[-1]
            p, m, x1 = step(lin.x0 + e), step(lin.x0 - e), lin.x0_next
            scale = np.abs(A[:, k]).max()
            kink_central = max(kink_central, np.abs(lin.A[:, k] - A[:, k]).max() / scale)
            kink_one_sided = max(kink_one_sided, min(np.abs(lin.A[:, k] - (p - x1) / eps).max(),
                                                     np.abs(lin.A[:, k] - (x1 - m) / eps).max()) / scale)
        arm.set_state_vector(lin.x0, armrt.StatePart.PHYSICS)
        # No kinked column: nothing was measured there, so None (JSON null, "-" in the table), not a residual of 0.
        worst["A_kinked_central"] = kink_central if kinks else None
        worst["A_kinked_one_sided"] = kink_one_sided if kinks else None
        rows.append({"model": model, "seed": seed, "state_size": int(lin.x0.size), "kinked_columns": len(kinks),
                     "kinked": [lin.state_names[k] for k in kinks], "worst_block_relative": worst})
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "linearize_residuals.json").write_text(json.dumps({"command": "python -m bench.linearize --residuals",
                                                                  "states": rows}, indent=2) + "\n")
    md = ("# Linearisation residuals (`python -m bench.linearize --residuals`)\n\n"
          "Largest |X - X_fd| / max|X_fd| over the (row block, column block) pairs, central differences of the real "
          "step (A, B) and of forward() (dfdx, dfdu); kinked columns left out.\n\n"
          "The last two columns: A at the kinked columns against the central and the nearer one-sided difference, "
          "relative to the column's largest entry.\n\n"
          "| model | seed | ns | kinked columns | A | B | dfdx | dfdu | A kinked: central | one-sided |\n"
          "|---|---|---|---|---|---|---|---|---|---|\n")
    fmt = lambda v: "-" if v is None else f"{v:.1e}"
    for r in rows:
        w = r["worst_block_relative"]
        md += (f"| {r['model']} | {r['seed']} | {r['state_size']} | {r['kinked_columns']} | {w['A']:.1e} | "
               f"{w['B']:.1e} | {w['dfdx']:.1e} | {w['dfdu']:.1e} | {fmt(w['A_kinked_central'])} | "
               f"{fmt(w['A_kinked_one_sided'])} |\n")
    (RESULTS / "linearize_residuals.md").write_text(md)
    print(md)


def timed(fn, calls: int) -> float:
    t0 = time.perf_counter()
    for _ in range(calls):
        fn()
    return (time.perf_counter() - t0) / calls


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--instructions", action="store_true", help="also count instructions (valgrind)")
    ap.add_argument("--instruction-calls", type=int, default=20)
    ap.add_argument("--residuals", action="store_true", help="finite-difference residuals instead of the cost")
    ap.add_argument("--child", nargs=3, metavar=("MODEL", "WHAT", "CALLS"), help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:
        arm = moving_arm(args.child[0])
        workload(arm, args.child[1], int(args.child[2]))
        return
    if args.residuals:
        residuals()
        return
    load_before = os.getloadavg()
    out = {"command": "python -m bench.linearize" + (" --instructions" if args.instructions else ""),
           "integrator": "ros2", "dt_s": 1e-3, "repeats": args.repeats, "models": {}}
    for model in MODELS:
        arm = moving_arm(model)
        ws = armrt._core.LinearizeWorkspace()
        x = arm.get_state_vector(armrt.StatePart.FULL)
        fns = {"step": (lambda: (arm.set_state_vector(x), arm._sim.step(1)), 200),
               "continuous": (lambda: arm._sim.linearize(ws, False), 50),
               "discrete": (lambda: arm._sim.linearize(ws, True), 10),
               "arm_linearize": (lambda: arm.linearize(), 10),
               # what Arm.linearize() took on top until 2026-12-04 for x0_next: a deep copy of the arm, stepped
               "deepcopy": (lambda: copy.deepcopy(arm), 10)}
        best = {k: float("inf") for k in fns}
        for _ in range(args.repeats):
            for k, (fn, calls) in fns.items():
                best[k] = min(best[k], timed(fn, calls))
        # The step as timed includes setting the state back (the linearisation's own step starts from a set state);
        # one set_state_vector alone:
        t_set = min(timed(lambda: arm.set_state_vector(x), 200) for _ in range(args.repeats))
        us = {k: 1e6 * v for k, v in best.items()}
        us["step"] -= 1e6 * t_set
        rec = {"state_size": int(x.size) if False else 2 * arm.n_dofs + 2 * arm.n_elements,
               "us": us, "ratio_to_step": {k: us[k] / us["step"] for k in ("continuous", "discrete")}}
        for k in ("arm_linearize", "deepcopy"):
            rec["ratio_to_step"][k] = us[k] / us["step"]
        if args.instructions:
            ins = {k: instructions(model, k, args.instruction_calls if k != "step" else 200)
                   for k in ("step", "continuous", "discrete")}
            rec["instructions"] = ins
            rec["instruction_ratio_to_step"] = {k: ins[k] / ins["step"] for k in ("continuous", "discrete")}
        out["models"][model] = rec
    load_after = os.getloadavg()
    out["loadavg_1min_before_after"] = [load_before[0], load_after[0]]
    out["cpus"] = os.cpu_count()
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "linearize.json").write_text(json.dumps(out, indent=2) + "\n")
    md = (f"# Linearisation cost (`{out['command']}`)\n\n"
          f"ROS2 1 ms step; best of {args.repeats} interleaved repetitions; 1-min load average {load_before[0]:.2f} "
          f"before, {load_after[0]:.2f} after, {out['cpus']} CPUs. The step's time excludes setting its state.\n\n"
          "Engine: the engine's linearize() through the binding (which also allocates the numpy outputs); "
          "`Arm.linearize()`: the whole Python call (A, B, df/dx, df/du and x0_next in a Linearization).\n\n"
          "| model | ns | step (us) | df/dx, df/du (us, x step) | A, B (us, x step) | Arm.linearize() (us, x step) |"
          + (" instructions: step / continuous / discrete |" if args.instructions else "") + "\n"
          "|---|---|---|---|---|---|" + ("---|" if args.instructions else "") + "\n")
    for model, r in out["models"].items():
        u, q = r["us"], r["ratio_to_step"]
        md += (f"| {model} | {r['state_size']} | {u['step']:.1f} | {u['continuous']:.0f} ({q['continuous']:.1f}x) | "
               f"{u['discrete']:.0f} ({q['discrete']:.0f}x) | {u['arm_linearize']:.0f} ({q['arm_linearize']:.0f}x) |")
        if args.instructions:
            i, iq = r["instructions"], r["instruction_ratio_to_step"]
            md += (f" {i['step'] / 1e3:.0f} k / {i['continuous'] / 1e3:.0f} k ({iq['continuous']:.1f}x) / "
                   f"{i['discrete'] / 1e3:.0f} k ({iq['discrete']:.0f}x) |")
        md += "\n"
    md += ("\nThe deep copy of the arm that Arm.linearize() stepped for x0_next until 2026-12-04 (now taken from the "
           "linearisation's own stages), timed in the same run: "
           + ", ".join(f"{m} {r['us']['deepcopy']:.0f} us" for m, r in out["models"].items()) + ".\n")
    (RESULTS / "linearize.md").write_text(md)
    print(md)


if __name__ == "__main__":
    main()
