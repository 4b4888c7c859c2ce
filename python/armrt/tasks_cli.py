"""`armrt task centre-out|fitts|posture`: args -> a task run offline with the simulated decoder driving a point
cursor, or with --arm MODEL the arm's hand through the endpoint controller; a metrics table on stdout, JSON/CSV
with --out."""
from __future__ import annotations

import csv
import json
import math

from . import tasks

TRIAL_COLUMNS = ("trial", "target", "success", "time_to_target_s", "acquisition_time_s", "dial_in_time_s",
                 "path_efficiency", "n_entries", "gh_unstable_events", "hold_rms_m")


def add_cli(sub, formatter) -> None:
    p = sub.add_parser("task", formatter_class=formatter,
                       help="run a target task offline (simulated decoder, point cursor) and print its metrics")
    p.add_argument("kind", choices=["centre-out", "fitts", "posture"], help="the task")
    p.add_argument("--decoder", default="simulated", choices=["simulated"],
                   help="what drives the cursor (simulated: velocity towards the target + noise + lag)")
    p.add_argument("--centre", type=float, nargs=3, default=None, metavar=("X", "Y", "Z"),
                   help="task centre, m, thorax frame (default: 0 0 0 for the point cursor; with --arm the hand "
                        "at --q-deg)")
    p.add_argument("--arm", metavar="MODEL", default=None,
                   help="drive this model's hand (e.g. das2) through the endpoint controller instead of a point "
                        "cursor (dt = 1 ms; --dt is ignored)")
    p.add_argument("--q-deg", type=float, nargs="+", default=[30, 60, 10, 60, 80], metavar="DEG",
                   help="with --arm: start posture, deg, one per DOF")
    p.add_argument("--targets", type=int, default=8, help="centre-out: number of targets")
    p.add_argument("--distance", type=float, default=0.1, help="centre-out: target distance from the centre, m")
    p.add_argument("--radius", type=float, default=0.015, help="centre-out/posture: success radius, m")
    p.add_argument("--fitts", nargs="+", default=["0.1:0.02", "0.2:0.02"], metavar="D:W",
                   help="fitts: conditions, distance:width in m")
    p.add_argument("--per-condition", type=int, default=9, help="fitts: targets per condition (odd)")
    p.add_argument("--trials", type=int, default=3, help="posture: number of holds")
    p.add_argument("--dwell", type=float, default=0.3, help="dwell (posture: hold) time, s")
    p.add_argument("--timeout", type=float, default=5.0, help="trial timeout, s")
    p.add_argument("--iti", type=float, default=0.2, help="inter-trial interval, s")
    p.add_argument("--gain", type=float, default=4.0, help="decoder gain, 1/s")
    p.add_argument("--noise-sd", type=float, default=0.01, help="decoder noise SD per axis, m/s")
    p.add_argument("--lag", type=float, default=0.05, help="decoder lag, s")
    p.add_argument("--dt", type=float, default=0.002, help="sample interval, s")
    p.add_argument("--seed", type=int, default=0, help="decoder noise seed")
    p.add_argument("--out", metavar="FILE.json|FILE.csv", help="write the metrics (JSON: trials + block; CSV: trials)")
    p.set_defaults(func=cmd_task)


def _conditions(texts):
    out = []
    for s in texts:
        try:
            d, w = (float(x) for x in s.split(":"))
        except ValueError:
            raise ValueError(f"--fitts takes D:W in m (e.g. 0.2:0.02), got {s!r}") from None
        out.append((d, w))
    return out


def _fmt(v):
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, float):
        return "-" if math.isnan(v) else f"{v:.3f}"
    return str(v)


def cmd_task(args) -> int:
    arm = None
    if args.arm is not None:
        import numpy as np
        from .arm import Arm
        arm = Arm(args.arm)
        q0 = np.radians(args.q_deg)
        arm.reset(q=q0)
        args.dt = arm.dt
        if args.centre is None:
            args.centre = arm.model.hand_position(q0).tolist()
    if args.centre is None:
        args.centre = [0.0, 0.0, 0.0]
    if args.kind == "centre-out":
        targets = tasks.centre_out_targets(args.centre, args.distance, args.radius, args.targets)
        task = tasks.TargetTask(targets, args.dwell, args.timeout, args.iti)
    elif args.kind == "fitts":
        targets = tasks.fitts_targets(args.centre, _conditions(args.fitts), args.per_condition)
        task = tasks.TargetTask(targets, args.dwell, args.timeout, args.iti)
    else:
        task = tasks.PostureTask(args.centre, args.radius, args.dwell, args.timeout, args.trials, args.iti)
    dec = tasks.SimulatedDecoder(args.gain, args.noise_sd, args.lag, args.dt, seed=args.seed)
    start = list(args.centre)
    if args.kind == "posture":  # start away from the held target so there is something to reach
        start[1] += 0.05
    max_time = len(task.targets) * (args.timeout + args.iti) + 1.0
    if arm is None:
        tasks.run_cursor_task(task, dec, start, max_time_s=max_time)
    else:
        from .endpoint_control import EndpointController, run_task
        ctl = EndpointController(arm)  # posture: hold the hand where it starts, against gravity
        run_task(task, ctl, dec, max_time_s=max_time)
    rows, block = task.trial_metrics(), task.block_metrics()
    what = f"the {args.arm} hand (endpoint controller)" if arm is not None else "a point cursor"
    print(f"armrt task {args.kind} --decoder {args.decoder} driving {what}: gain {args.gain} 1/s, noise SD {args.noise_sd} m/s, "
          f"lag {args.lag} s, dt {args.dt} s, seed {args.seed}")
    print("  ".join(TRIAL_COLUMNS))
    for r in rows:
        print("  ".join(f"{_fmt(r[c]):>{len(c)}}" for c in TRIAL_COLUMNS))
    print("block:")
    for k, v in block.items():
        if k == "fitts":
            for cond, res in v.items():
                print(f"  fitts {cond}: " + ", ".join(f"{a} {_fmt(b)}" for a, b in res.items()))
        else:
            print(f"  {k}: {_fmt(v)}")
    if args.out:
        if args.out.endswith(".csv"):
            with open(args.out, "w", newline="") as fh:
                w = csv.writer(fh)
                w.writerow(TRIAL_COLUMNS)
                for r in rows:
                    w.writerow([r[c] for c in TRIAL_COLUMNS])
        elif args.out.endswith(".json"):
            with open(args.out, "w") as fh:
                json.dump({"trials": rows, "block": block}, fh, indent=1, default=str)
        else:
            raise ValueError(f"--out must end in .json or .csv, got {args.out!r}")
        print(f"wrote {args.out}")
    return 0
