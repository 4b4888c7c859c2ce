"""Golden runs that the engine redesign (issue 25) must reproduce bit for bit (tests/test_golden.py).

`python -m tests.golden_runs` wrote tests/data/golden_ca5c936.npz at commit ca5c936, before the redesign:
das2 and das3, every fixed-step integrator, every recorded array (state and outputs), a hand load, a
weakened arm, a batch of three, and the outputs properties after a run. A refactor that keeps the physics
must give the same bits; rewrite the file only when the physics changes on purpose, and say why."""
from pathlib import Path

import numpy as np

DATA = Path(__file__).resolve().parent / "data"
FILE = DATA / "golden_ca5c936.npz"


def _record(out, key, res):
    for name in res.ARRAYS + tuple(getattr(res, "OPTIONAL_ARRAYS", ())):
        value = getattr(res, name, None)
        if value is None or name == "tet_ns":
            continue
        out[f"{key}/{name}"] = np.asarray(value)


def runs(models=("das2", "das3")) -> dict[str, np.ndarray]:
    import armrt
    out = {}
    rng = np.random.default_rng(20261202)
    for model in models:
        arm = armrt.Arm(model)
        ne = arm.n_elements
        U = np.repeat(rng.uniform(0, 1, size=(4, ne)) * (rng.uniform(size=(4, ne)) < 0.3), 100, axis=0)
        for integ, sub in (("ros2", None), ("rk4", 6 if model == "das2" else 10), ("euler", 10 if model == "das2" else 20)):
            if model == "das3" and integ != "ros2":
                continue  # das3 refuses explicit steps at these sizes (docs/das3.md)
            arm = armrt.Arm(model, integrator=integ, substeps=sub)
            arm.reset()
            arm.set_hand_load(force=(0, -10.0, 0))
            _record(out, f"{model}/{integ}/random_load", arm.simulate(U[:250], 0.25))
            out[f"{model}/{integ}/random_load/final_x"] = np.concatenate([arm.q, arm.qdot, arm.lce, arm.activation])
            out[f"{model}/{integ}/random_load/final_gh_stab"] = np.asarray(arm.gh_stab)
            out[f"{model}/{integ}/random_load/final_hand"] = np.asarray(arm.hand_position)
        arm = armrt.Arm(model)
        strength = np.linspace(0.3, 1.0, ne)
        arm.strength = strength
        arm.reset()
        _record(out, f"{model}/ros2/weak", arm.simulate({"deltoid": 0.3, "rotator_cuff": 0.1}, 0.2))
        batch = armrt.ArmBatch(3, model=model, threads=1)
        batch.reset()
        for k in range(50):
            batch.set_excitation(U[k * 4 % len(U)][None, :] * np.array([[0.5], [1.0], [0.2]]))
            batch.step(1, outputs=(k % 7 == 0))
        out[f"{model}/batch/x"] = np.concatenate([batch.q, batch.qdot, batch.lce, batch.activation], axis=1)
        out[f"{model}/batch/gh_stab"] = np.asarray(batch.gh_stab).copy()
    return out


if __name__ == "__main__":
    np.savez_compressed(FILE, **runs())
    print(f"wrote {FILE}")
