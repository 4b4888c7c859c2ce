"""Computed muscle control (armrt.track_motion, docs/control.md) of a 0.5 rad elbow flexion in 1 s on das2, with
and without the feedback term, and with the muscle-model error corrected (track_motion(correct_model_error=True)):
the tracking error per DOF (deg) and the time taken.

    python examples/cmc_elbow.py
"""
import time

import numpy as np

import armrt


def main() -> None:
    arm = armrt.Arm("das2")
    q0 = arm.q.copy()
    t = np.linspace(0.0, 1.0, 101)
    q = np.tile(q0, (t.size, 1))
    j = arm.model.dof_names.index("ELx")
    q[:, j] = q0[j] + 0.25 * (1.0 - np.cos(np.pi * t))  # 0.5 rad of elbow flexion, zero velocity at both ends
    print("| tendon | feedback (kp, kv) | model error corrected | RMS error per DOF, deg | max error, deg | "
          "infeasible intervals | time, s |")
    print("|---|---|---|---|---|---|---|")
    for tendon, kp, kv, corrected in [("elastic", 100.0, 20.0, False), ("elastic", 0.0, 0.0, False),
                                      ("rigid", 100.0, 20.0, False), ("elastic", 100.0, 20.0, True),
                                      ("elastic", 0.0, 0.0, True), ("rigid", 100.0, 20.0, True)]:
        w = time.perf_counter()
        r = armrt.track_motion(arm, q, t, kp=kp, kv=kv, tendon=tendon, correct_model_error=corrected)
        took = time.perf_counter() - w
        rms = ", ".join(f"{d} {v:.2f}" for d, v in r.error_rms_deg.items())
        print(f"| {tendon} | {kp:g}, {kv:g} | {'yes' if corrected else 'no'} | {rms} | {max(r.error_max_deg.values()):.2f} | "
              f"{int((~r.feasible).sum())} of {r.feasible.size} | {took:.2f} |")


if __name__ == "__main__":
    main()
