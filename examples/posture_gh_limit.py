"""Posture holding with GH stability kept under a limit (armrt.track_motion with gh_stab_max; docs/control.md): das2
holds the humerus elevated 0.3 rad above rest (GHy) with a 1 kg weight in the hand for 1 s, without a limit and with
GHstab <= 0.2, 0.15, 0.1: the largest GHstab of the simulation (the engine's, each 10 ms), the tracking error and the
mean sum of squared activations (the objective: what the limit costs).

    python examples/posture_gh_limit.py
"""
import numpy as np

import armrt


def main() -> None:
    arm = armrt.Arm("das2")
    q_hold = arm.q.copy()
    q_hold[arm.model.dof_names.index("GHy")] += 0.3
    t = np.linspace(0.0, 1.0, 11)
    q = np.tile(q_hold, (t.size, 1))
    print("| GHstab limit | largest GHstab simulated | max tracking error, deg | mean sum of squared activations (the objective) | infeasible intervals |")
    print("|---|---|---|---|---|")
    for limit in (None, 0.2, 0.15, 0.1):
        arm.set_hand_load(force=(0.0, -9.81, 0.0))
        r = armrt.track_motion(arm, q, t, gh_stab_max=limit)
        print(f"| {'none' if limit is None else limit} | {r.gh_stab.max():.3f} | {max(r.error_max_deg.values()):.3f} | "
              f"{(r.target_activation ** 2).sum(axis=1).mean():.4f} | {int((~r.feasible).sum())} of {r.feasible.size} |")


if __name__ == "__main__":
    main()
