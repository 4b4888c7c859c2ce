"""participant_A_FES's default stimulation map (models/participant_A_FES.stimulation.toml): it stimulates
exactly the muscles the participant files mark for FES, and full stimulation reaches the file's maxact."""
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import armrt
from armrt import stimulation as stim

ROOT = Path(__file__).resolve().parents[1]
FES_MODEL = ROOT / "models" / "participant_A_FES.json"
MAT = ROOT / ".." / "shared" / "reference" / "participant_A"
FULL = (200e-6, 0.020, 50.0)  # saturating intramuscular pulse (20 mA at 200 us), the device's top frequency


def maxact(path):
    return {e["name"]: e.get("max_activation", 1.0) for e in json.loads(Path(path).read_text())["elements"]}


def fes_muscles_from(fes, paralysed):
    """Elements the FES file can activate and the paralysed one cannot: the stimulated ones."""
    return sorted(n for n in fes if fes[n] > 0 and paralysed[n] == 0)


@pytest.fixture(scope="module")
def fes_arm_factory():
    return lambda **kw: armrt.Arm(str(FES_MODEL), stimulation="default", **kw)


def test_the_map_reaches_exactly_the_muscles_the_fes_file_stimulates(fes_arm_factory):
    fes, par = maxact(FES_MODEL), maxact(ROOT / "models" / "participant_A_paralysed.json")
    stimulated = fes_muscles_from(fes, par)
    assert stimulated and all(n.startswith(("triclong", "tricmed", "triclat")) for n in stimulated)
    arm = fes_arm_factory()
    m = arm.stimulation_map()
    reached = sorted(e for ch in m["channels"] for e in ch["elements"])
    assert reached == stimulated
    assert [ch["kind"] for ch in m["channels"]] == ["intramuscular"] * 3
    # One channel per muscle: each channel's elements are one muscle's.
    for ch in m["channels"]:
        assert sorted(ch["elements"]) == sorted(arm.element_names[i] for i in arm.indices(ch["name"]))


def test_the_mat_files_agree_with_the_model_files():
    pytest.importorskip("scipy.io")
    if not (MAT / "model_struct_A_FES.mat").exists():
        pytest.skip(f"participant A reference data not found at {MAT} (needs ../shared beside the repository)")
    from armrt.profile import read_profile
    fes = read_profile(MAT / "model_struct_A_FES.mat").max_activation
    par = read_profile(MAT / "model_struct_A_paralysed.mat").max_activation
    # The .mat files name elements by DAS3 name (bicl, triclong1, ...), as the model files do.
    assert fes_muscles_from(fes, par) == fes_muscles_from(maxact(FES_MODEL),
                                                          maxact(ROOT / "models" / "participant_A_paralysed.json"))
    assert {fes[n] for n in fes_muscles_from(fes, par)} == {0.5}


def test_full_stimulation_reaches_maxact_and_unreached_muscles_stay_paralysed(fes_arm_factory):
    arm = fes_arm_factory()
    cap = np.array(arm.max_activation)
    arm.set_excitation(1.0)  # every element asked for full excitation: only the unreached ones may follow it
    arm.set_stimulation({c: FULL for c in arm.channel_names})
    arm.step(1000)
    reached = sorted({i for c in arm.channel_names for i in arm.indices(c)})
    # At saturation a channel's force level is that of a fused tetanus (above the 0.5 cap) ...
    assert all(0.8 < f < 1.0 for f in arm.force_level.values())
    # ... so every reached element sits at its maxact, the file's 0.5.
    assert np.allclose(arm.activation[reached], cap[reached], atol=2e-3) and np.allclose(cap[reached], 0.5)
    anconeus = arm.indices("anconeus")
    assert np.all(arm.activation[anconeus] == 0.0)  # maxact 0: paralysed, not reached
    flexors = arm.indices("elbow_flexors")  # voluntary: excitation drives them, capped at their maxact
    assert np.allclose(arm.activation[flexors], cap[flexors], atol=0.02)


def test_half_recruitment_gives_half_the_force_level(fes_arm_factory):
    arm = fes_arm_factory()
    arm.set_stimulation({"triclat": (200e-6, 0.0125, 50.0)})  # (12.5 - 5) / (20 - 5) = half recruited
    arm.step(1000)
    i = arm.indices("triclat")[0]
    assert arm.activation[i] == pytest.approx(arm.force_level["triclat"], abs=2e-3)
    assert 0.4 < arm.activation[i] < 0.5


def test_default_is_refused_for_a_model_that_ships_no_map():
    with pytest.raises(ValueError, match="model 'das2' ships no default stimulation map"):
        armrt.Arm("das2", stimulation="default")
    with pytest.raises(ValueError, match="ships no default stimulation map"):
        stim.default_map_path("participant_A")


def test_a_batch_takes_the_default_map_too():
    b = armrt.ArmBatch(2, str(FES_MODEL), stimulation="default", threads=1)
    assert b.channel_names == ["triclong", "tricmed", "triclat"]
    b.set_stimulation({c: FULL for c in b.channel_names})
    b.step(500)
    assert b.fatigue.shape == (2, 3) and np.all(b.fatigue > 0)


def test_the_fes_model_by_name_points_to_its_shipped_file_then_works_once_loaded(fes_arm_factory):
    # In a fresh process participant_A_FES is a model file, not a registered model: the error says where the
    # file is. Once built from its file the name is registered, and the name takes the default map too.
    code = ("import armrt\ntry:\n    armrt.Arm('participant_A_FES', stimulation='default')\n"
            "except ValueError as e:\n    print(e)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120,
                         env={**os.environ, "PYTHONPATH": os.pathsep.join(sys.path)}).stdout
    assert re.search(r"unknown model 'participant_A_FES'.*ships at .*participant_A_FES\.json", out), out
    fes_arm_factory()
    assert armrt.Arm("participant_A_FES", stimulation="default").channel_names == ["triclong", "tricmed", "triclat"]
