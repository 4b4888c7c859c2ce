"""Time per static optimisation solve from Python (issue 28 item 2; docs/control.md "Static optimisation"):
das2 along a smooth 1 kHz reaching motion (every DOF a raised-cosine move of 0.3 rad over 1 s, a 1 kg weight in
the hand), one solve per millisecond, warm started from the previous frame (StaticOptimizer: what a controller
does), for the elastic and the rigid tendon, with and without a GH bound; and cold starts (a new optimiser per
frame) for comparison; all by the Python path's ProxQP (backend="python"; the C++ path is bench.static_optimization_cpp). Also the accuracy the rigid-tendon approximation costs: the moment residual its
activations leave with the elastic element. das3 along the same kind of motion about its settled pose, fewer
frames. Median and p99 per solve, the machine's load recorded (times depend on it).

    python -m bench.static_optimization [--frames 400] [--das3-frames 60]
Writes bench/results/static_optimization.json and .md.
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


def motion(arm: armrt.Arm, q0: np.ndarray, frames: int, dt: float = 1e-3, amplitude: float = 0.3):
    """(q, qdot, qddot) per frame: q0 + amplitude (1 - cos(pi t / T)) / 2 per DOF, T = frames dt."""
    T = frames * dt
    t = np.arange(frames) * dt
    w = np.pi / T
    s = 0.5 * amplitude * (1 - np.cos(w * t))
    sd = 0.5 * amplitude * w * np.sin(w * t)
    sdd = 0.5 * amplitude * w * w * np.cos(w * t)
    sign = np.where(np.arange(arm.n_dofs) % 2 == 0, 1.0, -1.0)
    return q0 + np.outer(s, sign), np.outer(sd, sign), np.outer(sdd, sign)


def run_case(arm, q, qd, qdd, hand, warm: bool, **kw) -> dict:
    times, iters, resid, stab, elastic, failed = [], [], [], [], [], []
    so = armrt.StaticOptimizer(arm, **kw)
    so.solve(q[0], qd[0], qdd[0], hand, on_infeasible="return")  # the solver's set-up and first factorisation are not timed
    for k in range(len(q)):
        if not warm:
            so = armrt.StaticOptimizer(arm, **kw)
        t0 = time.perf_counter()
        r = so.solve(q[k], qd[k], qdd[k], hand, on_infeasible="return")
        times.append(time.perf_counter() - t0)
        iters.append(r.iterations)
        if not r.feasible:  # no convergence to 1e-6 N m in max_iterations QPs: counted, kept out of the residual
            failed.append(k)
            continue
        resid.append(float(np.abs(r.residual).max()))
        stab.append(r.gh_stab)
        if r.elastic_residual is not None:
            elastic.append(float(np.abs(r.elastic_residual).max()))
    t = np.array(times) * 1e3
    out = {"median_ms": float(np.median(t)), "p99_ms": float(np.percentile(t, 99)), "max_ms": float(t.max()),
           "iterations_median": float(np.median(iters)), "iterations_max": int(max(iters)),
           "moment_residual_max_Nm": float(max(resid)),
           "frames_not_converged": len(failed), "frames_not_converged_at": failed[:20], "gh_stab_max": float(max(stab)), "frames": len(q)}
    if elastic:
        out["rigid_tendon_error_vs_elastic_max_Nm"] = float(max(elastic))
        out["rigid_tendon_error_vs_elastic_median_Nm"] = float(np.median(elastic))
    return out


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--frames", type=int, default=400)
    ap.add_argument("--das3-frames", type=int, default=60)
    args = ap.parse_args(argv)
    load_before = os.getloadavg()
    hand = np.array([0.0, -9.81, 0.0])
    arm = armrt.Arm("das2")
    q, qd, qdd = motion(arm, np.radians([20, 40, 0, 60, 60]), args.frames)
    cases = {}
    for name, warm, kw in [("das2 elastic, warm", True, {}),
                           ("das2 elastic, GHstab <= 0.3, warm", True, {"gh_stab_max": 0.3}),
                           ("das2 rigid tendon, warm", True, {"tendon": "rigid"}),
                           ("das2 rigid tendon, GHstab <= 0.3, warm", True, {"tendon": "rigid", "gh_stab_max": 0.3}),
                           ("das2 elastic, cubed, warm", True, {"criterion": "cubed"}),
                           ("das2 elastic, cold", False, {})]:
        n = args.frames if warm else max(args.frames // 4, 10)
        # The Python path's ProxQP (backend="python"): "auto" would hand the rigid tendon to C++, which
        # bench.static_optimization_cpp measures beside it.
        cases[name] = run_case(arm, q[:n], qd[:n], qdd[:n], hand, warm, backend="python", **kw)
        print(name, {k: round(v, 4) if isinstance(v, float) else v for k, v in cases[name].items()}, flush=True)
    arm3 = armrt.Arm("das3")
    arm3.settle()
    # das3's frames spread over 0.5 s (a 60 ms move of 0.1 rad would ask for ~140 rad/s^2).
    q3, qd3, qdd3 = motion(arm3, arm3.q, args.das3_frames, dt=0.5 / args.das3_frames, amplitude=0.1)
    held = np.array([j in arm3.model.girdle_dofs for j in range(arm3.n_dofs)])
    q3[:, held], qd3[:, held], qdd3[:, held] = arm3.q[held], 0.0, 0.0  # the girdle held at its settled pose
    cases["das3 elastic, warm"] = run_case(arm3, q3, qd3, qdd3, hand, True, backend="python")
    print("das3 elastic, warm", cases["das3 elastic, warm"], flush=True)
    load_after = os.getloadavg()
    import proxsuite
    out = {"command": "python -m bench.static_optimization " + " ".join(argv or []), "cases": cases,
           "loadavg_1min_before_after": [load_before[0], load_after[0]], "cpus": os.cpu_count(),
           "proxsuite": proxsuite.__version__, "target_ms": 1.0}
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "static_optimization.json").write_text(json.dumps(out, indent=2) + "\n")
    lines = ["# Static optimisation: time per solve from Python", "",
             f"`{out['command'].strip()}` (proxsuite {out['proxsuite']}, ProxQP dense). "
             f"1-min load average {load_before[0]:.2f} before, {load_after[0]:.2f} after, {out['cpus']} CPUs: times "
             f"scale with the load.", "",
             "| case | frames | not converged | median ms | p99 ms | QPs median (max) | moment residual max N m | "
             "GHstab max | rigid-tendon error vs elastic, max N m |", "|---|---|---|---|---|---|---|---|---|"]
    for name, c in cases.items():
        rig = c.get("rigid_tendon_error_vs_elastic_max_Nm")
        lines.append(f"| {name} | {c['frames']} | {c['frames_not_converged']} | {c['median_ms']:.2f} | {c['p99_ms']:.2f} | "
                     f"{c['iterations_median']:.0f} ({c['iterations_max']}) | {c['moment_residual_max_Nm']:.1e} | "
                     f"{c['gh_stab_max']:.3f} | {'' if rig is None else f'{rig:.3g}'} |")
    (RESULTS / "static_optimization.md").write_text("\n".join(lines) + "\n")
    return out


if __name__ == "__main__":
    main()
