"""What the stimulation chain adds to the default step (issue 27 item 5; docs/fes.md "Cost"): das2 at the default
ROS2 1 ms step driven by 40 stimulation channels (the 22 per-muscle intramuscular channels and 18 surface channels
with spill-over onto neighbouring elements), every channel pulsing at 20-40 Hz, against the same arm driven by
excitation (no map) held at the activations the stimulation settled to, so that both step the same physics
(muscle states decide the ROS2 limiter's work). Interleaved repetitions in one run, best of each, with the
machine's load recorded.

    python -m bench.stimulation_cost [--steps 5000] [--repeats 7] [--instructions]
Writes bench/results/stimulation.json and .md. With --instructions it also counts the instructions of a step in
either mode under valgrind's callgrind (counts do not depend on the machine's load, times do): each mode's
process is run twice, stepping 0 and --instruction-steps steps after the same set-up, with only the engine's
step collected (--toggle-collect='armrt::step(*'), and the difference divided by the steps.
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

import armrt

RESULTS = Path(__file__).resolve().parent / "results"


def forty_channel_map(arm: armrt.Arm) -> dict:
    """22 intramuscular channels, one per muscle, and 18 surface channels each over two elements of two
    muscles (weights 0.6 and 0.3: spill-over)."""
    chans = [{"name": m, "kind": "intramuscular", "elements": [m]} for m in arm.muscle_names]
    els = arm.element_names
    for k in range(40 - len(chans)):
        a, b = els[(5 * k) % len(els)], els[(5 * k + 37) % len(els)]
        chans.append({"name": f"surface{k}", "kind": "surface", "elements": {a: 0.6, b: 0.3}})
    return {"channels": chans}


def settled_arms() -> tuple[armrt.Arm, armrt.Arm]:
    """(excitation arm, stimulated arm), both settled: the stimulated arm 2000 steps under the 40 channels, then
    the excitation arm 2000 steps held at the activations the stimulation reached."""
    off = armrt.Arm("das2")
    on = armrt.Arm("das2", stimulation=forty_channel_map(off))
    rng = np.random.default_rng(0)
    cmd = np.column_stack([np.full(40, 150e-6), np.full(40, 0.012), rng.uniform(20, 40, 40)])
    cmd[22:, 1] = 0.04  # surface channels: 40 mA
    on.set_stimulation(cmd)
    on.step(2000)
    off.set_excitation(np.clip(on.activation, 0.0, 1.0))
    off.step(2000)
    return off, on


def instructions_per_step(steps: int) -> dict:
    """Instructions per engine step in each mode, by callgrind (see the module's docstring)."""
    if shutil.which("valgrind") is None:
        raise SystemExit("--instructions needs valgrind (Debian package valgrind)")
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        for mode in ("excitation", "stimulation"):
            counts = []
            for n in (0, steps):
                log = Path(tmp) / f"{mode}{n}.log"
                subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={tmp}/{mode}{n}.out",
                                "--toggle-collect=armrt::step(*", f"--log-file={log}", sys.executable, "-m",
                                "bench.stimulation_cost", "--child", mode, str(n)],
                               check=True, cwd=Path(__file__).resolve().parent.parent)
                line = next(l for l in log.read_text().splitlines() if "Collected" in l)
                counts.append(int(line.split(":")[-1].replace(",", "")))
            out[mode] = (counts[1] - counts[0]) / steps
    return out


def timed(arm: armrt.Arm, steps: int) -> float:
    t0 = time.perf_counter()
    arm.step(steps)
    return (time.perf_counter() - t0) / steps


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=5000)
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--instructions", action="store_true", help="also count instructions per step (valgrind)")
    ap.add_argument("--instruction-steps", type=int, default=1000)
    ap.add_argument("--child", nargs=2, metavar=("MODE", "STEPS"), help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:  # one callgrind process: set up as the timed run does, then step one arm
        off, on = settled_arms()
        (on if args.child[0] == "stimulation" else off).step(int(args.child[1]))
        return
    off, on = settled_arms()
    load_before = os.getloadavg()
    t_off, t_on = [], []
    for _ in range(args.repeats):
        t_off.append(timed(off, args.steps))
        t_on.append(timed(on, args.steps))
    load_after = os.getloadavg()
    best_off, best_on = min(t_off), min(t_on)
    out = {"command": "python -m bench.stimulation_cost", "model": "das2", "integrator": "ros2", "dt_s": 1e-3,
           "channels": 40,
           "map_entries": sum(len(c["elements"]) for c in on.stimulation_map()["channels"]),
           "steps": args.steps, "repeats": args.repeats,
           "us_per_step_excitation": 1e6 * best_off, "us_per_step_stimulation": 1e6 * best_on,
           "added_fraction": best_on / best_off - 1.0,
           "loadavg_1min_before_after": [load_before[0], load_after[0]], "cpus": os.cpu_count()}
    if args.instructions:
        ins = instructions_per_step(args.instruction_steps)
        out["instructions_per_step"] = ins
        out["instructions_added_fraction"] = ins["stimulation"] / ins["excitation"] - 1.0
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "stimulation.json").write_text(json.dumps(out, indent=2) + "\n")
    md = (f"# Stimulation chain cost (`{out['command']}`)\n\n"
          f"das2, ROS2 1 ms step, best of {args.repeats} interleaved runs of {args.steps} steps through `Arm.step`; "
          f"1-min load average {load_before[0]:.2f} before, {load_after[0]:.2f} after, {out['cpus']} CPUs.\n\n"
          "| input | us per step |\n|---|---|\n"
          f"| excitation (no map) | {out['us_per_step_excitation']:.2f} |\n"
          f"| 40 stimulation channels ({out['map_entries']} channel-element entries), 20-40 Hz | "
          f"{out['us_per_step_stimulation']:.2f} |\n\n"
          f"The chain adds {100 * out['added_fraction']:.1f} % to the step.\n")
    if args.instructions:
        md += (f"\nInstructions per step (callgrind, {args.instruction_steps} steps, engine step only): "
               f"excitation {ins['excitation'] / 1e3:.1f} k, stimulation {ins['stimulation'] / 1e3:.1f} k: "
               f"{100 * out['instructions_added_fraction']:.1f} % more.\n")
    (RESULTS / "stimulation.md").write_text(md)
    print(md)


if __name__ == "__main__":
    main()
