"""The participant experiment (armrt/participant.py): Fig. 1 at full stimulation for participant A's
intact, injured, paralysed and FES variants, on the participant model and on das2 carrying the profiles."""
import json

import numpy as np
import pytest

from conftest import REFERENCE, ROOT

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
from armrt import participant  # noqa: E402


@pytest.fixture(autouse=True)
def model_files(monkeypatch):
    if not (ROOT / "models" / "participant_A_FES.json").exists():
        pytest.skip("models/participant_A*.json absent")
    monkeypatch.setenv("ARMRT_MODEL_DIR", str(ROOT / "models"))


def built(name: str) -> bool:
    try:
        armrt.arm.known_model(name)
        return True
    except ValueError:
        return False


def models():
    """das2 with the participant's profiles, and participant A's own model once it is compiled in."""
    return ["das2"] + [m for m in ["participant_A"] if built(m)]


@pytest.mark.parametrize("model", models())
def test_quick_sequence_orders_the_variants(model, tmp_path):
    assert participant.run_all(model, out_dir=tmp_path, quick=True) == 0
    out = json.loads((tmp_path / f"{model}.json").read_text())["variants"]
    assert list(out) == ["intact", "injured", "paralysed", "FES"]
    intact, injured, paralysed, fes = (out[k] for k in ["intact", "injured", "paralysed", "FES"])
    # The injured and paralysed files are identical (same fmax and maxact element by element).
    assert injured == {**paralysed, "profile": injured["profile"]}
    # Triceps: maxact 0 when injured/paralysed (passive force only), 0.5 with FES, 1 intact.
    assert paralysed["peak_triceps_moment_Nm"] < fes["peak_triceps_moment_Nm"] < intact["peak_triceps_moment_Nm"]
    assert paralysed["peak_triceps_moment_Nm"] < 0.1 * intact["peak_triceps_moment_Nm"]
    # Weak flexors (maxact 0.12-0.42 on reduced fmax) flex the elbow less than intact ones.
    assert fes["elbow_range_deg"][1] < intact["elbow_range_deg"][1]
    assert fes["peak_flexor_moment_Nm"] < 0.5 * intact["peak_flexor_moment_Nm"]
    assert (tmp_path / f"{model}_fig1.png").stat().st_size > 10_000
    assert "| FES |" in (tmp_path / f"{model}.md").read_text()


def test_excitation_follows_the_fig1_phases():
    arm = armrt.Arm("das2")
    u = participant.excitation(arm)
    t = participant.DT * np.arange(len(u))
    flex = arm.indices("bicl")[0]
    tri = arm.indices("triclong")[0]
    pron = arm.indices("pronquad")[0]
    assert u[(t < 4.0), :].max() == 0.0 and u[t >= 18.0, :].max() == 0.0
    assert np.all(u[(t >= 4.0) & (t < 18.0), flex] == 1.0)
    assert np.all(u[(t >= 10.0) & (t < 18.0), tri] == 1.0) and np.all(u[t < 10.0, tri] == 0.0)
    assert np.all(u[(t >= 14.0) & (t < 18.0), pron] == 1.0) and np.all(u[t < 14.0, pron] == 0.0)
