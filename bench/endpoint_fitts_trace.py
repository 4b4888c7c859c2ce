"""Endpoint control on a Fitts block: why trials fail and where the time goes (issue 29 item 1; not a test).

Runs armrt.endpoint_control.run_task's loop on das2 (q = 30 60 10 60 80 deg, the CLI's start posture, after a plain
arm.reset: zero activation, as the CLI started before start_at_rest, so older controllers run the same) over an ISO 9241-9
Fitts block (armrt.tasks.fitts_targets around the start hand) driven by the simulated decoder (velocity commands;
the CLI's defaults) or, with --position, by the targets as position commands, and records each step the hand, the
controller's reference x_ref and GHstab. Prints per trial success / entries / GH events, the hand - x_ref distance
(RMS, max), GHstab max, the joint ranges, solves and infeasible solves, wall and CPU time and the load average.

    python -m bench.endpoint_fitts_trace [--fitts 0.08:0.02 ...] [--per-condition 5] [--noise-sd 0.01]
                                         [--position] [--tendon elastic|rigid] [--profile]
"""
from __future__ import annotations

import argparse
import cProfile
import os
import pstats
import time

import numpy as np


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fitts", nargs="+", default=["0.08:0.02"], metavar="D:W", help="conditions, m")
    ap.add_argument("--per-condition", type=int, default=5)
    ap.add_argument("--noise-sd", type=float, default=0.01, help="decoder noise SD per axis, m/s")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--position", action="store_true", help="command the target positions (no decoder)")
    ap.add_argument("--tendon", default="elastic", choices=["elastic", "rigid"])
    ap.add_argument("--profile", action="store_true", help="cProfile the loop: the 12 largest cumulative times")
    a = ap.parse_args(argv)
    import armrt
    from armrt import tasks
    from armrt.endpoint_control import EndpointController

    arm = armrt.Arm("das2")
    q0 = np.radians([30, 60, 10, 60, 80])
    arm.reset(q=q0)
    centre = arm.model.hand_position(q0)
    conds = [tuple(float(x) for x in c.split(":")) for c in a.fitts]
    targets = tasks.fitts_targets(centre, conds, a.per_condition)
    task = tasks.TargetTask(targets, 0.3, 5.0, 0.2)          # the CLI's dwell, timeout, ITI
    # the default tendon without the argument: the same script then runs against an older controller (before
    # velocity mode, 0bde281), which is how docs/tasks.md's "before" figures were measured
    ctl = EndpointController(arm) if a.tendon == "elastic" else EndpointController(arm, tendon=a.tendon)
    dec = tasks.SimulatedDecoder(4.0, a.noise_sd, 0.05, arm.dt, seed=a.seed)
    gap, gh, qs = [], [], []

    def loop():
        for _ in range(int(len(targets) * 5.2 / arm.dt) + 1000):
            x = ctl.hand_position()
            task.step(arm.time, x, gh_stable=bool(arm.gh_stab <= 1.0))
            if task.done:
                break
            tg = task.current_target()
            if a.position:
                if tg is not None:
                    ctl.command_position(tg.position)
            else:
                ctl.command_velocity(dec.step(x, None if tg is None else tg.position))
            ctl.step()
            gap.append(float(np.linalg.norm(ctl.hand_position() - ctl.x_ref)))
            gh.append(float(arm.gh_stab))
            qs.append(np.array(arm.q))

    load0 = os.getloadavg()
    w0, c0 = time.perf_counter(), time.process_time()
    prof = cProfile.Profile() if a.profile else None
    if prof:
        prof.enable()
    loop()
    if prof:
        prof.disable()
    wall, cpu = time.perf_counter() - w0, time.process_time() - c0
    print(f"{'position' if a.position else 'decoder'} commands, tendon {a.tendon}, noise SD {a.noise_sd} m/s, "
          f"conditions {a.fitts} x {a.per_condition}: {arm.time:.2f} s simulated, {wall:.1f} s wall, {cpu:.1f} s CPU, "
          f"load average {load0[0]:.1f} -> {os.getloadavg()[0]:.1f}")
    for m in task.trial_metrics():
        print(f"  trial {m['trial']}: success {m['success']}, entries {m['n_entries']}, GH events "
              f"{m['gh_unstable_events']}, time to target {m['time_to_target_s']:.3f} s")
    b = task.block_metrics()
    g = np.array(gap)
    q = np.degrees(np.array(qs))
    print(f"success rate {b['success_rate']:.2f}, GH events {b['gh_unstable_events']}, GHstab max {max(gh):.3f}")
    print(f"hand - x_ref: RMS {np.sqrt(np.mean(g ** 2)):.4f} m, max {g.max():.4f} m")
    print("q range, deg: " + ", ".join(f"{n} {lo:.0f}..{hi:.0f}" for n, lo, hi in
                                       zip(arm.model.dof_names, q.min(0), q.max(0))))
    print(f"solves {ctl.n_solves}, infeasible {ctl.n_infeasible}")
    if "fitts" in b:
        for c, r in b["fitts"].items():
            print(f"  {c}: We {r['We_m']:.4f} m, IDe {r['IDe_bits']:.3f} bits, MT {r['MT_s']:.3f} s, "
                  f"TP {r['TP_bits_per_s']:.3f} bits/s")
    if prof:
        pstats.Stats(prof).sort_stats("cumulative").print_stats(12)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
