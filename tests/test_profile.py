"""Arm.apply_profile: a participant's weakness (fmax, maxact) onto any arm, by element name."""
import shutil

import numpy as np
import pytest
import scipy.io as sio

from conftest import REFERENCE, ROOT

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
PARTICIPANT = REFERENCE / "participant_A"


@pytest.fixture(scope="module")
def pdir():
    if not (PARTICIPANT / "model_struct_A_FES.mat").exists():
        pytest.skip(f"participant data not found at {PARTICIPANT} (needs ../shared beside the repository)")
    return PARTICIPANT


def muscles(path):
    return {m.name: m for m in sio.loadmat(path, squeeze_me=True, struct_as_record=False)["model"].muscles}


@pytest.mark.parametrize("variant", ["_FES", "_injured", "_paralysed"])
def test_round_trip_on_das2(pdir, variant):
    arm = armrt.Arm("das2")
    arm.strength = {"deltscap": 0.3}       # not in the profile: must be left alone
    report = arm.apply_profile(pdir / f"model_struct_A{variant}.mat")
    var, intact = muscles(pdir / f"model_struct_A{variant}.mat"), muscles(pdir / "model_struct_A.mat")
    assert report.unmatched == [] and len(report.applied) == 42 and len(report.untouched) == 60
    assert report.reference.endswith("model_struct_A.mat")
    for name, mu in var.items():
        i = arm.element_names.index(name)
        assert arm.strength[i] * intact[name].fmax == pytest.approx(mu.fmax, rel=1e-14)
        assert arm.max_activation[i] == mu.maxact
    d = arm.indices("deltscap")
    assert np.all(arm.strength[d] == 0.3) and np.all(arm.max_activation[d] == 1.0)
    assert "none" in str(report).splitlines()[1]


def test_unmatched_names_are_reported_and_others_applied(pdir, tmp_path):
    mat = sio.loadmat(pdir / "model_struct_A_FES.mat", squeeze_me=True, struct_as_record=False)
    mat["model"].muscles[0].name = "bicepsX"
    mat["model"].muscles[0].osim_name = "bicepsX"
    sio.savemat(tmp_path / "model_struct_B_FES.mat", {"model": mat["model"]})
    shutil.copy(pdir / "model_struct_A.mat", tmp_path / "model_struct_B.mat")
    arm = armrt.Arm("das2")
    report = arm.apply_profile(tmp_path / "model_struct_B_FES.mat")     # reference: model_struct_B.mat beside it
    assert report.unmatched == ["bicepsX"] and len(report.applied) == 41
    assert "bicepsX" in str(report)
    assert arm.strength[arm.element_names.index("bicl")] == 1.0       # not named by the profile: untouched
    fes, intact = muscles(pdir / "model_struct_A_FES.mat"), muscles(pdir / "model_struct_A.mat")
    assert arm.strength[arm.element_names.index("bicb1")] == pytest.approx(fes["bicb1"].fmax / intact["bicb1"].fmax)
    # A reference that lacks an element the profile and the arm share is an error, not a silent 1.
    with pytest.raises(ValueError, match="reference .* has no element 'bicl'"):
        arm.apply_profile(pdir / "model_struct_A_FES.mat", reference=tmp_path / "model_struct_B_FES.mat")


def test_without_an_intact_file_fmax_is_absolute(pdir, tmp_path):
    shutil.copy(pdir / "model_struct_A_FES.mat", tmp_path / "fes.mat")
    arm = armrt.Arm("das2")
    report = arm.apply_profile(tmp_path / "fes.mat")
    assert report.reference.startswith("absolute")
    fmax = {e["name"]: e["fmax"] for e in arm.info["elements"]}
    for name, mu in muscles(tmp_path / "fes.mat").items():
        assert arm.strength[arm.element_names.index(name)] * fmax[name] == pytest.approx(mu.fmax, rel=1e-14)


def test_model_file_profile_by_name_equals_the_mat(pdir, monkeypatch):
    if not (ROOT / "models" / "participant_A_FES.json").exists():
        pytest.skip("models/participant_A_FES.json absent")
    monkeypatch.setenv("ARMRT_MODEL_DIR", str(ROOT / "models"))    # this checkout's files, not an installed copy
    a, b = armrt.Arm("das2"), armrt.Arm("das2")
    ra = a.apply_profile(pdir / "model_struct_A_FES.mat")
    rb = b.apply_profile("participant_A_FES")
    assert rb.reference.endswith("participant_A.json")
    assert np.array_equal(a.strength, b.strength) and np.array_equal(a.max_activation, b.max_activation)
    assert ra.applied == rb.applied


def test_profile_caps_the_held_excitation(pdir):
    arm = armrt.Arm("das2")
    arm.set_excitation({"triceps": 1.0})
    arm.apply_profile(pdir / "model_struct_A_injured.mat")     # triceps paralysed (maxact 0)
    assert np.all(arm.excitation[arm.indices("triceps")] == 0.0)


def test_bad_profiles_are_refused(pdir, tmp_path):
    arm = armrt.Arm("das2")
    with pytest.raises(FileNotFoundError, match="no profile named 'nobody'"):
        arm.apply_profile("nobody")
    with pytest.raises(FileNotFoundError):
        arm.apply_profile(tmp_path / "missing.mat")
    mat = sio.loadmat(pdir / "model_struct_A_FES.mat", squeeze_me=True, struct_as_record=False)
    mat["model"].muscles[2].maxact = 1.5
    sio.savemat(tmp_path / "bad.mat", {"model": mat["model"]})
    with pytest.raises(ValueError, match="'bicb2': maximum activation 1.5"):
        arm.apply_profile(tmp_path / "bad.mat")
    (tmp_path / "junk.mat").write_bytes(b"not a mat file")
    with pytest.raises(ValueError, match="not a readable MATLAB file"):
        arm.apply_profile(tmp_path / "junk.mat")


def test_profile_names_fall_back_to_opensim_names(pdir, tmp_path):
    mat = sio.loadmat(pdir / "model_struct_A_FES.mat", squeeze_me=True, struct_as_record=False)
    mat["model"].muscles[0].name = "biceps_long"            # not an armrt name; osim_name stays bic_l
    sio.savemat(tmp_path / "fes.mat", {"model": mat["model"]})
    arm = armrt.Arm("das2")
    report = arm.apply_profile(tmp_path / "fes.mat", reference=pdir / "model_struct_A_FES.mat")
    assert report.unmatched == [] and "bicl" in report.applied
    assert arm.max_activation[arm.element_names.index("bicl")] == pytest.approx(0.4203335240475676)
