"""Computed muscle control (armrt.track_motion) of a slow elbow flexion on das2: 20 deg with a raised cosine over
D s from q = 30 60 10 60 80 deg, the other DOFs held. With Thelen et al.'s gains (kp 100 s^-2, kv 20 s^-1) the
forearm's rotation (PSy, the smallest inertia) drifts by degrees on some durations; stiffer feedback holds it
(docs/control.md "Computed muscle control"), and so does correcting the optimiser's muscle-model error
(track_motion(correct_model_error=True)). Prints the largest error per case.

    python examples/cmc_slow_motion.py
"""
import warnings

import numpy as np

import armrt


def main() -> None:
    q0 = np.radians([30, 60, 10, 60, 80])
    print("| D, s | gains (kp, kv) | control interval, ms | model error corrected | PSy max error, deg | "
          "ELx max error, deg | infeasible |")
    print("|---|---|---|---|---|---|---|")
    for duration in (3.0, 10.0):
        t = np.linspace(0.0, duration, 31)
        q = q0 + np.outer((1 - np.cos(np.pi * t / duration)) / 2, np.radians([0, 0, 0, 20, 0]))
        for kp, kv, interval, corrected in [(100.0, 20.0, 0.010, False), (100.0, 20.0, 0.005, False),
                                            (400.0, 40.0, 0.010, False), (100.0, 20.0, 0.010, True),
                                            (100.0, 20.0, 0.005, True)]:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)
                r = armrt.track_motion(armrt.Arm("das2"), q, t, kp=kp, kv=kv, control_interval=interval,
                                       correct_model_error=corrected)
            print(f"| {duration:g} | {kp:g}, {kv:g} | {1e3 * interval:g} | {'yes' if corrected else 'no'} | "
                  f"{r.error_max_deg['PSy']:.2f} | "
                  f"{r.error_max_deg['ELx']:.2f} | {int((~r.feasible).sum())} of {r.feasible.size} |")


if __name__ == "__main__":
    main()
