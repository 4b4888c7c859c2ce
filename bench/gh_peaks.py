"""GH stability peaks by integrator on the README's example (docs/engine.md, "What the joint-angle figures do
not show"): `armrt simulate elbow_flexors=0.3 rotator_cuff=0.05` (2 s from das2's rest posture), without and
with a 200 N upward hand load, for ROS2 at 1 ms, ROS2 with 2 substeps, RK4 (its default substeps) and CVODE.

    python bench/gh_peaks.py
"""
import numpy as np

import armrt

EXCITATION = {"elbow_flexors": 0.3, "rotator_cuff": 0.05}
RUNS = (("ros2", None), ("ros2", 2), ("rk4", None), ("cvode", None))


def peak(integrator: str, substeps, force) -> tuple[float, float]:
    """(peak GHstab, its time in s) over 2 s."""
    arm = armrt.Arm("das2", integrator=integrator, substeps=substeps)
    arm.set_hand_load(force=force)
    res = arm.simulate(EXCITATION, duration=2.0)
    k = int(np.argmax(res.gh_stab))
    return float(res.gh_stab[k]), float(res.time[k])


def main() -> None:
    print("| hand load | " + " | ".join(f"{i}{'' if s is None else f' x{s}'}" for i, s in RUNS) + " |")
    print("|---" * (len(RUNS) + 1) + "|")
    for label, force in (("none", (0.0, 0.0, 0.0)), ("200 N up", (0.0, 200.0, 0.0))):
        cells = [f"{g:.3f} at {1e3 * t:.0f} ms" for g, t in (peak(i, s, force) for i, s in RUNS)]
        print(f"| {label} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
