"""armrt-rt --static-optimization in a RealtimeSession (docs/realtime.md): das2 from the rest posture with the elbow
at 60 deg, the loop starting at zero activation, a Python client sending the target every 5 ms: held for 1 s, then
a raised-cosine elbow move of 20 deg over 1 s, held 0.5 s; with the computed-torque gains (kp 100 1/s^2, kd 20 1/s)
and as pure feedforward (0, 0). The joint errors over time and the runner's solve-time statistics; the machine's
load recorded (the solve times scale with it).

    python -m bench.rt_static_optimization
Writes bench/results/rt_static_optimization.json and .md.
"""
from __future__ import annotations

import json
import os
import time

import numpy as np

import armrt
from armrt import realtime as rt

from .static_optimization import RESULTS

ELX = 3


def run(kp: float, kd: float, t_move: float = 1.0, T: float = 1.0, t_end: float = 2.5, infeasible: bool = False) -> dict:
    """One case; infeasible=True: a target no activations reach (50 rad/s and 1000 rad/s^2 in every DOF, GHstab <=
    0.05; a new-user trial's, 2026-12-07), held throughout: every solve infeasible, zero excitation, the arm falls."""
    q_hold = np.array(armrt.Model("das2").rest_posture, dtype=float)
    q_hold[ELX] = np.radians(60.0)
    amp, w = np.radians(20.0), np.pi / T

    def target(t):
        if infeasible:
            return q_hold.copy(), np.full(5, 50.0), np.full(5, 1000.0)
        q, qd, qdd = q_hold.copy(), np.zeros(5), np.zeros(5)
        s = min(max(t - t_move, 0.0), T)
        q[ELX] += 0.5 * amp * (1 - np.cos(w * s))
        if 0 < t - t_move < T:
            qd[ELX], qdd[ELX] = 0.5 * amp * w * np.sin(w * s), 0.5 * amp * w * w * np.cos(w * s)
        return q, qd, qdd

    states = []
    with rt.RealtimeSession(listen="127.0.0.1:0", q0=q_hold, static_optimization=True, so_kp=kp, so_kd=kd,
                            so_gh_stab_max=0.05 if infeasible else None, state_rate_hz=100, input_timeout=0.5) as s, rt.UdpClient(s.port) as c:
        c.join(timeout=1.0)
        t0 = time.monotonic()
        while True:
            c.send_target(*target(time.monotonic() - t0))
            st = c.latest_state(timeout=0.005)
            if st is not None:
                states.append(st)
                if st.time >= t_end:
                    break
        stats = s.stop()
    err = np.array([np.degrees(st.q - target(st.time)[0]) for st in states])
    t = np.array([st.time for st in states])

    def worst(lo, hi):
        m = (t >= lo) & (t <= hi)
        return float(np.abs(err[m]).max()) if m.any() else None

    return {"kp": kp, "kd": kd, "sag_max_deg_0_to_0.3s": worst(0.0, 0.3), "error_max_deg_0.9_to_1s": worst(0.9, t_move),
            "error_max_deg_during_move": worst(t_move, t_move + T), "error_max_deg_last_0.2s": worst(t_end - 0.2, t_end),
            "elbow_error_deg_at_end": float(err[-1, ELX]), "static_optimization": stats["static_optimization"],
            "overruns": stats["overruns"], "scheduler": stats["scheduler"]}


def main(argv=None) -> dict:
    load_before = os.getloadavg()
    cases = {"computed torque (kp 100, kd 20)": run(100.0, 20.0), "pure feedforward (kp 0, kd 0)": run(0.0, 0.0),
             "infeasible target held (kp 0, kd 0; errors: the arm falls)": run(0.0, 0.0, infeasible=True)}
    load_after = os.getloadavg()
    out = {"command": "python -m bench.rt_static_optimization", "cases": cases, "cpus": os.cpu_count(),
           "loadavg_1min_before_after": [load_before[0], load_after[0]]}
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "rt_static_optimization.json").write_text(json.dumps(out, indent=2) + "\n")
    lines = ["# armrt-rt --static-optimization: das2 elbow held at 60 deg, then moved to 80 deg", "",
             f"`{out['command']}`. 1-min load average {load_before[0]:.2f} before, {load_after[0]:.2f} after, "
             f"{out['cpus']} CPUs shared with other jobs.", "",
             "| case | sag max 0-0.3 s deg | error max 0.9-1 s deg | error max during the move deg | error max last "
             "0.2 s deg | solves | infeasible | not converged | solve median us | p99 us | max us | overruns |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for name, c in cases.items():
        so = c["static_optimization"]
        p = so["solve_ns"]
        lines.append(f"| {name} | {c['sag_max_deg_0_to_0.3s']:.2f} | {c['error_max_deg_0.9_to_1s']:.2f} | "
                     f"{c['error_max_deg_during_move']:.2f} | {c['error_max_deg_last_0.2s']:.2f} | {so['solves']} | "
                     f"{so['infeasible']} | {so['not_converged']} | {p['median'] / 1e3:.1f} | {p['p99'] / 1e3:.1f} | "
                     f"{p['max'] / 1e3:.1f} | {c['overruns']} |")
    (RESULTS / "rt_static_optimization.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    return out


if __name__ == "__main__":
    main()
