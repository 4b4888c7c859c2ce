"""Saved das2 trajectories that engine refactors must reproduce within 1e-9 rad (tests/test_ros2.py).

`python -m tests.regression_runs` rewrites tests/data/das2_trajectories.npz; do that only when the model's
physics changes on purpose, and say why (the file keeps the reason given).
History: forward_42b5e0e.npz (commit 42b5e0e) guarded the forward() speed-up; das2_trajectories.npz was
made when issue 11 removed the 10 N/m linear tendon/PEE terms and added the fibre compressive element, and
rewritten when ROS2's second stage began to extrapolate its paths (only the ROS2 run moved: 4.7e-5 rad), and
when ROS2 began to evaluate the paths at one step in three only (only the ROS2 run moved: 2.3e-4 rad)."""
from pathlib import Path

import numpy as np

DATA = Path(__file__).resolve().parent / "data"
FILE = DATA / "das2_trajectories.npz"


def _run(integ, substeps, exc, load=None, duration=1.5):
    import armrt
    arm = armrt.Arm(integrator=integ, dt=1e-3, substeps=substeps)
    arm.reset()
    if load is not None:
        arm.set_hand_load(force=load)
    return arm.simulate(exc, duration)


def runs() -> dict[str, np.ndarray]:
    """Four runs from rest: RK4 x6 with elbow flexors, RK4 x6 with random excitations and a 10 N hand
    load, Euler x10 with deltoid and cuff, and the default ROS2 with the random excitations."""
    rng = np.random.default_rng(20261129)
    out = {}
    res = _run("rk4", 6, {"elbow_flexors": 0.3, "rotator_cuff": 0.05})
    out["rk4_flexors_q"], out["rk4_flexors_lce"] = res.q, res.lce[::100]
    U = np.repeat(rng.uniform(0, 1, size=(6, 102)) * (rng.uniform(size=(6, 102)) < 0.3), 250, axis=0)
    out["rk4_random_load_q"] = _run("rk4", 6, U, load=(0, -10.0, 0)).q
    out["euler_deltoid_q"] = _run("euler", 10, {"deltoid": 0.4, "rotator_cuff": 0.1}, duration=1.0).q
    out["ros2_random_load_q"] = _run("ros2", 1, U, load=(0, -10.0, 0)).q
    return out


if __name__ == "__main__":
    import sys
    if len(sys.argv) != 2 or sys.argv[1].startswith("-"):  # `--help` must not rewrite the reference
        sys.exit('usage: python -m tests.regression_runs "why the physics changed"')
    np.savez_compressed(FILE, reason=np.array(sys.argv[1]), **runs())
    print(f"wrote {FILE}")
