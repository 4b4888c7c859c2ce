"""examples/: the FES PD elbow controller runs, reaches its targets and writes its plot."""
import importlib.util
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("gymnasium", reason="needs gymnasium (pip install gymnasium)")
pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def load(name):
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_fes_elbow_pd_reaches_targets_and_plots(tmp_path):
    ex = load("fes_elbow_pd")
    runs = ex.main(["--targets", "40", "100", "--duration", "2.0", "--out", str(tmp_path / "pd")])
    assert (tmp_path / "pd.png").stat().st_size > 10_000
    for r in runs:
        tail = r["t"] >= r["t"][-1] - 0.5
        assert np.degrees(np.abs(r["elbow"][tail] - r["target"])).mean() < 5.0
        assert abs(r["elbow"][0] - np.radians(15.0)) < 1e-9   # started away from the target
    # Without stimulation the weakened arm stays near its start: the controller did the work.
    still = ex.run([100.0], kp=0.0, kd=0.0, bias=0.0, duration=2.0)[0]
    assert np.degrees(still["elbow"][-1]) < 60.0


def test_random_search_over_the_vector_env_beats_doing_nothing():
    ex = load("fes_elbow_search")
    best, best_score, reference = ex.search(candidates=6, rounds=1, targets_deg=(90.0,))
    assert best_score >= reference["hand_tuned"] > reference["no_stimulation"]
    assert np.all(best >= ex.LOW) and np.all(best <= ex.HIGH)


def test_fes_stim_fatigue_force_falls_and_reset_restores(capsys):
    ex = load("fes_stim_fatigue")
    out = ex.main(["--duration", "25", "--observe-fatigue"])
    first = out["first"]
    assert out["same"]
    # max_activation 0.7 holds the force while the fibres' force is above it; from 20 s it falls.
    assert first["force"][-1] < 0.9 * first["force"][199]
    assert np.all(np.diff(first["fatigue"]) > 0) and first["fatigue"][-1] > 0.5
    assert np.array_equal(first["obs"][-1][-7:], np.full(7, first["fatigue"][-1], np.float32))
    assert "the first episode's exactly: True" in capsys.readouterr().out


def test_lqr_posture_holds_against_a_push():
    """examples/lqr_posture.py, short: the baseline holds the posture (an equilibrium of forward()), open loop the push
    throws the arm off, the LQR on Arm.linearize()'s (A, B) keeps the hand within a fraction of that, u in [0, 1]."""
    ex = load("lqr_posture")
    out = ex.main(["--duration", "0.6"])
    runs = out["runs"]
    assert out["qdd0"] < 1e-5 and out["rho"] < 1.0
    assert runs["open loop, no push"]["joint_dev_deg"] < 0.01
    assert runs["LQR"]["hand_dev_mm"] < 0.2 * runs["open loop"]["hand_dev_mm"]
    assert runs["LQR"]["joint_dev_deg"] < 0.2 * runs["open loop"]["joint_dev_deg"]
    lo, hi = runs["LQR"]["u_range"]
    assert 0.0 <= lo and hi <= 1.0


def test_lqr_posture_warns_where_its_baseline_is_no_equilibrium():
    """A fourth trial's posture (GHy 0.8, GHz 1.2, GHyy 0.3, ELx 2.0, PSy 0.5 rad): the baseline's corrections stop
    at |qdd| 0.15 rad/s^2 and the example went on to design its LQR about that point with the number only printed.
    Now a RuntimeWarning says so; the example's own posture balances without one."""
    import warnings

    import armrt
    ex = load("lqr_posture")
    arm = armrt.Arm("das2")
    with pytest.warns(RuntimeWarning, match=r"no equilibrium of this posture: \|qdd\| = .* rad/s\^2 after 20"):
        ex.baseline_excitation(arm, np.array([0.8, 1.2, 0.3, 2.0, 0.5]), 0.05)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ex.baseline_excitation(arm, np.array([ex.POSTURE[d] for d in arm.dof_names]), 0.05)
    for bad in ("0.6", "-0.1"):  # lsq_linear's bounds error and a traceback before (a fifth trial)
        with pytest.raises(SystemExit) as stop:
            ex.main(["--cocontraction", bad])
        assert stop.value.code == 2


@pytest.mark.parametrize("name, rows", [("cmc_elbow", 6), ("posture_gh_limit", 4)])
def test_control_examples_print_their_tables(name, rows, capsys):
    load(name).main()
    lines = [ln for ln in capsys.readouterr().out.splitlines() if ln.startswith("| ") and not ln.startswith("| tendon")
             and not ln.startswith("| GHstab limit")]
    assert len(lines) == rows  # the table docs/control.md quotes, one row per case
    assert all("nan" not in ln for ln in lines)


def test_the_code_blocks_of_docs_control_md_run():
    """docs/control.md's python blocks, top to bottom in one namespace as a reader runs them: they used names they
    never defined (trajectory, q_ref, time; t, q_start, kp, kd, q_target) and the linearisation block overwrote its
    discrete result before reading lin.A."""
    import re

    text = (EXAMPLES.parent / "docs" / "control.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert len(blocks) == 3
    ns: dict = {}
    for i, block in enumerate(blocks):
        exec(compile(block, f"docs/control.md python block {i + 1}", "exec"), ns)  # noqa: S102 (the docs' own code)
    assert ns["track"].feasible.all() and ns["lin"].A is not None and ns["lin_c"].A is None
    assert ns["run"].q.shape == (351, 5) and ns["run"].error_deg(["ELx"], ns["plant"])["ELx"][1] < 2.0
