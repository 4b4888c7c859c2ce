"""What the stimulation chain adds to the default step (issue 27 item 5; docs/fes.md "Cost"): das2 at the default
ROS2 1 ms step driven by 40 stimulation channels (the 22 per-muscle intramuscular channels and 18 surface channels
with spill-over onto neighbouring elements), every channel pulsing at 20-40 Hz, against the same arm driven by
excitation (no map) held at the activations the stimulation settled to, so that both step the same physics
(muscle states decide the ROS2 limiter's work). Interleaved repetitions in one run, best of each, with the
machine's load recorded.

    python -m bench.stimulation_cost [--steps 5000] [--repeats 7]
Writes bench/results/stimulation.json and .md.
"""
from __future__ import annotations

import argparse
import json
import os
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


def timed(arm: armrt.Arm, steps: int) -> float:
    t0 = time.perf_counter()
    arm.step(steps)
    return (time.perf_counter() - t0) / steps


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=5000)
    ap.add_argument("--repeats", type=int, default=7)
    args = ap.parse_args()
    off = armrt.Arm("das2")
    on = armrt.Arm("das2", stimulation=forty_channel_map(off))
    rng = np.random.default_rng(0)
    cmd = np.column_stack([np.full(40, 150e-6), np.full(40, 0.012), rng.uniform(20, 40, 40)])
    cmd[22:, 1] = 0.04  # surface channels: 40 mA
    on.set_stimulation(cmd)
    on.step(2000)  # settled: then the excitation arm holds what the stimulation reached
    off.set_excitation(np.clip(on.activation, 0.0, 1.0))
    off.step(2000)
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
    (RESULTS / "stimulation.md").write_text(md)
    print(md)


if __name__ == "__main__":
    main()
