"""The DAS3 importer: structure of the imported model, girdle reduction, and refusal of bad input."""
import json
import math

import numpy as np
import pytest
import scipy.io as sio

from codegen.importers import das3_source as src
from codegen.importers.das3_source import ModelInputError
from codegen.importers.import_das3 import build_model, reduce_length_poly
from codegen.polynomial import evaluate, substitute
from conftest import ROOT


def load_struct(das3_dir):
    return sio.loadmat(das3_dir / "model_struct.mat", squeeze_me=True, struct_as_record=False)["model"]


@pytest.fixture(scope="module")
def das3_model(das3_dir):
    return build_model(das3_dir, paths="das3")


def test_structure_of_imported_model(das3_model):
    m = das3_model
    assert m["schema"] == "armrt-model" and m["schema_version"] == 1
    assert [d["name"] for d in m["dofs"]] == ["GHy", "GHz", "GHyy", "ELx", "PSy"]
    assert len(m["elements"]) == 102 and len(m["muscles"]) == 22
    counts = {mu["name"]: len(mu["elements"]) for mu in m["muscles"]}
    assert counts == src.PAPER_MUSCLES
    assert not any(src.muscle_of(e["name"]) in src.GIRDLE_ONLY_MUSCLES for e in m["elements"])
    assert set(m["groups"]["rotator_cuff"]) == {"infra", "termin", "supra", "subscap"}
    for e in m["elements"]:
        assert e["fmax"] > 0 and e["lceopt"] > 0 and e["tact"] > 0
        assert set(e["length_poly"]["dofs"]) <= {"GHy", "GHz", "GHyy", "ELx", "PSy"}


def test_bodies_match_reference_facts(das3_model):
    bodies = {b["name"]: b for b in das3_model["bodies"]}
    assert [b["name"] for b in das3_model["bodies"]] == ["humerus", "ulna", "radius", "hand"]
    for name, mass in {"humerus": 2.0519, "ulna": 0.5464, "radius": 0.5464, "hand": 0.5250}.items():
        assert bodies[name]["mass"] == pytest.approx(mass, abs=1e-4)
    el = np.array(bodies["ulna"]["joint"]["axes"][0])
    ps = np.array(bodies["radius"]["joint"]["axes"][0])
    assert np.allclose(el, np.array([0.999766, 0.008446, -0.019909]) / np.linalg.norm([0.999766, 0.008446, -0.019909]), atol=1e-5)
    assert np.allclose(ps, np.array([-0.113295, 0.974059, 0.195892]) / np.linalg.norm([-0.113295, 0.974059, 0.195892]), atol=1e-5)
    assert bodies["humerus"]["joint"]["dofs"] == ["GHy", "GHz", "GHyy"]
    for b in das3_model["bodies"]:
        I = np.array(b["inertia"])
        assert np.allclose(I, I.T) and np.all(np.linalg.eigvalsh(I) > 0)


def test_girdle_fixed_at_equilibrium(das3_model, das3_dir):
    x = sio.loadmat(das3_dir / "equilibrium.mat", squeeze_me=True)["x"]
    assert [g["angle"] for g in das3_model["girdle"]["dofs"]] == pytest.approx(list(x[:6]))
    assert [d["rest"] for d in das3_model["dofs"]] == pytest.approx(list(x[6:11]))
    R = np.array(das3_model["scapula"]["rotation_in_thorax"])
    assert np.allclose(R @ R.T, np.eye(3), atol=1e-12) and np.linalg.det(R) == pytest.approx(1.0)


def test_glenoid_basis(das3_model):
    g = das3_model["glenoid"]
    B = np.array([g["normal"], g["major_axis"], g["minor_axis"]])
    assert np.allclose(B @ B.T, np.eye(3), atol=1e-12)
    assert g["rim_half_angle_major"] == pytest.approx(math.radians(44.37))
    assert g["rim_half_angle_minor"] == pytest.approx(math.radians(38.55))
    # The glenoid centre lies along the normal from the GH centre, about 2.3 cm away (DSEM).
    d = np.array(g["glenoid_centre"]) - np.array(g["gh_centre"])
    assert np.linalg.norm(d) == pytest.approx(0.02314, abs=1e-4)
    assert np.dot(d / np.linalg.norm(d), g["normal"]) > 0.999


def test_girdle_reduction_is_exact(das3_dir):
    struct = src.read_model_struct(das3_dir / "model_struct.mat")
    x = sio.loadmat(das3_dir / "equilibrium.mat", squeeze_me=True)["x"]
    girdle = dict(zip(src.GIRDLE_DOFS, x[:6]))
    rng = np.random.default_rng(1)
    reduced_any = 0
    for e in struct.elements:
        if src.muscle_of(e.name) not in ("deltclav", "latdorsi", "pectmajt", "pectmajc"):
            continue
        reduced = reduce_length_poly(e, girdle)
        assert not set(reduced["dofs"]) & set(src.GIRDLE_DOFS)
        assert len(reduced["coefs"]) <= len(e.lcoefs)
        reduced_any += len(reduced["coefs"]) < len(e.lcoefs)
        for _ in range(20):
            arm_q = {d: rng.uniform(-1, 1) for d in src.ARM_DOFS}
            full_q = [girdle.get(d, arm_q.get(d)) for d in e.dof_names]
            red_q = [arm_q[d] for d in reduced["dofs"]]
            assert evaluate(reduced["exponents"], reduced["coefs"], [red_q])[0] == pytest.approx(
                evaluate(e.lparams, e.lcoefs, [full_q])[0], rel=1e-12, abs=1e-15)
    assert reduced_any > 0, "substituting the girdle should merge equal monomials"


def test_substitute_merges_monomials():
    # c0 + c1 x y + c2 x^2 y with x fixed at 2: (c0) + (2 c1 + 4 c2) y
    kept, exps, coefs = substitute([[0, 0], [1, 1], [2, 1]], [1.0, 3.0, 5.0], {0: 2.0})
    assert kept == [1] and exps == [[0], [1]] and coefs == pytest.approx([1.0, 26.0])


# ----------------------------------------------------------------------------- bad input

@pytest.mark.parametrize("mutate, message", [
    (lambda m: delattr(m.muscles[40], "fmax"), "missing field 'fmax'"),
    (lambda m: setattr(m.muscles[40], "lparams", m.muscles[40].lparams[:, :1]), "'lparams' has shape"),
    (lambda m: m.muscles[40].lcoefs.__setitem__(0, np.nan), "'lcoefs' contains NaN"),
    (lambda m: setattr(m, "muscles", m.muscles[:-1]), "137 elements, expected 138"),
    (lambda m: setattr(m.muscles[40], "name", "bogus1"), "unknown muscle 'bogus'"),
    (lambda m: setattr(m.muscles[40], "fmax", -5.0), "'fmax' must be positive"),
    (lambda m: setattr(m.muscles[40], "dof_names", np.array(["GHy", "XXq", "GHyy"], dtype=object)), "unknown DOFs ['XXq']"),
    (lambda m: setattr(m.dofs[7], "range", np.array([0.0, 1.0, 2.0])), "'range' has shape"),
])
def test_bad_model_struct_is_refused(das3_dir, mutate, message):
    model = load_struct(das3_dir)
    mutate(model)
    with pytest.raises(ModelInputError) as err:
        src.parse_model_struct(model, "model_struct.mat: model")
    assert message in str(err.value)


def test_bad_element_counts_are_refused(das3_dir):
    model = load_struct(das3_dir)
    model.muscles[40].name = "serrant13"  # one infraspinatus element too few
    with pytest.raises(ModelInputError, match="element counts per muscle"):
        src.parse_model_struct(model)


def test_bad_equilibrium_is_refused(tmp_path):
    sio.savemat(tmp_path / "eq.mat", {"x": np.array([0.1, np.nan] + [0.0] * 20)})
    with pytest.raises(ModelInputError, match="'x' contains NaN"):
        src.read_equilibrium(tmp_path / "eq.mat")
    sio.savemat(tmp_path / "short.mat", {"x": np.zeros(4)})
    with pytest.raises(ModelInputError, match="expected at least"):
        src.read_equilibrium(tmp_path / "short.mat")
    sio.savemat(tmp_path / "nox.mat", {"y": np.zeros(11)})
    with pytest.raises(ModelInputError, match="no variable 'x'"):
        src.read_equilibrium(tmp_path / "nox.mat")
    (tmp_path / "junk.mat").write_bytes(b"not a mat file")
    with pytest.raises(ModelInputError, match="not a readable MATLAB file"):
        src.read_equilibrium(tmp_path / "junk.mat")


def test_bad_osim_is_refused(das3_dir, tmp_path):
    text = (das3_dir / "das3.osim").read_text()
    bad = tmp_path / "bad.osim"
    bad.write_text(text.replace("<mass>2.0519</mass>", "<mass>heavy</mass>", 1))
    with pytest.raises(ModelInputError, match=r"Body 'humerus_r': <mass> is not numeric"):
        src.read_osim(bad)
    bad.write_text(text.replace("<mass_center> 0.0064 -0.0776 -0.0036</mass_center>", "<mass_center> 0.0064 nan -0.0036</mass_center>", 1))
    with pytest.raises(ModelInputError, match="mass_center> contains NaN"):
        src.read_osim(bad)
    bad.write_text(text[: len(text) // 2])
    with pytest.raises(ModelInputError, match="not a readable OpenSim XML"):
        src.read_osim(bad)


def test_missing_input_file_is_named(tmp_path):
    with pytest.raises(ModelInputError, match="missing input file .*model_struct.mat"):
        build_model(tmp_path, paths="das3")


def test_cli_reports_bad_input(tmp_path, capsys):
    from codegen.importers.import_das3 import main
    assert main(["--das3", str(tmp_path), "--out", str(tmp_path / "m.json"), "--paths", "das3"]) == 2
    assert "missing input file" in capsys.readouterr().err
    assert not (tmp_path / "m.json").exists()


# ----------------------------------------------------------------------------- the committed model

def test_committed_model_file():
    m = json.loads((ROOT / "models" / "das2.json").read_text())
    assert m["schema_version"] == 1 and m["name"] == "das2" and len(m["elements"]) == 102
    for e in m["elements"]:
        lp = e["length_poly"]
        assert len(lp["exponents"]) == len(lp["coefs"]) > 0
        assert all(len(row) == len(lp["dofs"]) for row in lp["exponents"])
        assert (e["gh_direction"] is not None) == e["crosses_gh"]
    for d in m["dofs"]:
        lo, hi = d["range"]
        dlo, dhi = d["das3_range"]
        assert dlo <= lo < hi <= dhi


# ----------------------------------------------------------------------------- the glenoid (issue 24)

from codegen.importers.glenoid import (GH_CENTRE_TOLERANCE_M, INCLINATION_RANGE_DEG, VERSION_RANGE_DEG,  # noqa: E402
                                      glenoid_geometry, glenoid_version_inclination, landmarks_in_scapula)

MODEL_FILES = ["das2", "das3", "participant_A", "participant_A_FES", "participant_A_injured", "participant_A_paralysed"]
# The basis every model carried before issue 24: the DSEM landmarks Kabsch-fitted onto DAS3's
# TSprojection/AIprojection (thorax-surface points), 10.3 mm rms residual (models/das2.json at 0fc0442).
OLD_KABSCH_NORMAL = [-0.9919263132468168, 0.07241959091211116, -0.10410375565127088]


def test_landmark_frame_is_the_scapula_frame():
    """The DSEM GH centre, expressed in the landmark frame by the README's recipe, is das3.osim's gh1
    location in scapula_r (0.002, -0.023, -0.0439): the two frames are one, no registration needed."""
    lm = landmarks_in_scapula()
    np.testing.assert_allclose(lm["AA"], 0.0, atol=1e-15)
    assert abs(lm["TS"][1]) < 1e-12 and abs(lm["TS"][2]) < 1e-12 and lm["TS"][0] < 0  # x from TS to AA
    assert abs(lm["AI"][2]) < 1e-12 and lm["AI"][1] < 0                                 # AI in the x-y plane, inferior
    assert np.linalg.norm(lm["GH"] - [0.002, -0.023, -0.0439]) < 1e-4


@pytest.mark.parametrize("name", MODEL_FILES)
def test_model_glenoid_in_its_scapula_frame(name):
    """Every DAS3-family model: the (scaled) DSEM GH centre in the model's scapula frame is its GH joint
    centre within 1 mm; the normal's clinical version and inclination are anatomical; the stored
    basis is the landmark-frame one."""
    m = json.loads((ROOT / "models" / f"{name}.json").read_text())
    g = m["glenoid"]
    humerus = next(b for b in m["bodies"] if b["name"] == "humerus")
    gh_joint = np.array(humerus["joint"]["location_in_parent"])
    np.testing.assert_allclose(g["gh_centre"], gh_joint, atol=1e-12)
    scale = g["frame"]["scapula_scale"]
    assert 0.9 < scale < 1.1
    assert np.linalg.norm(scale * landmarks_in_scapula()["GH"] - gh_joint) < GH_CENTRE_TOLERANCE_M
    if name.startswith("das"):  # DAS3 itself is not scaled
        assert abs(scale - 1.0) < 2e-3 and np.linalg.norm(landmarks_in_scapula()["GH"] - gh_joint) < 1e-3
    version, inclination = glenoid_version_inclination(g["normal"])
    assert VERSION_RANGE_DEG[0] <= version <= VERSION_RANGE_DEG[1]
    assert INCLINATION_RANGE_DEG[0] <= inclination <= INCLINATION_RANGE_DEG[1]
    assert version == pytest.approx(g["version_deg"]) and inclination == pytest.approx(g["inclination_deg"])
    lm = landmarks_in_scapula()
    n = (lm["glenoid"] - lm["GH"]) / np.linalg.norm(lm["glenoid"] - lm["GH"])
    np.testing.assert_allclose(g["normal"], n, atol=1e-12)
    B = np.array([g["normal"], g["major_axis"], g["minor_axis"]])
    np.testing.assert_allclose(B @ B.T, np.eye(3), atol=1e-12)
    assert np.linalg.det(B) > 0 and g["major_axis"][1] > 0.99  # right-handed; major axis superior
    # The glenoid centre lies 2.3 cm (scaled) from the GH centre along the normal (DSEM).
    d = np.array(g["glenoid_centre"]) - gh_joint
    assert np.linalg.norm(d) == pytest.approx(0.02314 * scale, abs=1e-4)


def test_old_registration_fails_the_anatomy_check():
    """The Kabsch-fitted basis of before issue 24 is 28 deg retroverted: outside every published range,
    so the version check refuses it, while the landmark-frame normal passes."""
    version, _ = glenoid_version_inclination(OLD_KABSCH_NORMAL)
    assert version < VERSION_RANGE_DEG[0]
    assert version == pytest.approx(-27.7, abs=0.1)
    new = np.array(glenoid_geometry(np.array([0.002, -0.023, -0.0439]))["normal"])
    assert math.degrees(math.acos(float(new @ OLD_KABSCH_NORMAL))) == pytest.approx(14.85, abs=0.05)


def test_version_inclination_by_hand():
    """The clinical angles of faces turned by known angles about the scapular axis' frame."""
    lm = landmarks_in_scapula()
    axis = (lm["glenoid"] - lm["TS"]) / np.linalg.norm(lm["glenoid"] - lm["TS"])
    posterior = np.array([0.0, 0.0, 1.0]) - axis[2] * axis
    posterior /= np.linalg.norm(posterior)
    superior = np.cross(posterior, axis)
    for a in (-15.0, 0.0, 7.5):
        face = math.cos(math.radians(a)) * axis - math.sin(math.radians(a)) * posterior  # anterior = -posterior
        v, i = glenoid_version_inclination(-face)
        assert v == pytest.approx(a, abs=1e-9) and i == pytest.approx(0.0, abs=1e-9)
        face = math.cos(math.radians(a)) * axis + math.sin(math.radians(a)) * superior
        v, i = glenoid_version_inclination(-face)
        assert v == pytest.approx(0.0, abs=1e-9) and i == pytest.approx(a, abs=1e-9)
    with pytest.raises(ValueError, match="zero"):
        glenoid_version_inclination([0.0, 0.0, 0.0])
    for bad, err, needle in (([np.nan, 0.0, 0.0], ValueError, "NaN"), ([1.0, 0.0], ValueError, "shape"),
                             (np.eye(3), ValueError, "shape"), (["a", "b", "c"], TypeError, "real numbers"),
                             (None, ValueError, "shape")):
        with pytest.raises(err, match=needle):
            glenoid_version_inclination(bad)


def test_foreign_scapula_frame_is_refused():
    """A GH centre that the DSEM landmark frame cannot give (another scapula frame) is refused, naming it."""
    with pytest.raises(ModelInputError, match="not DAS3's scapula_r"):
        glenoid_geometry(np.array([0.03, -0.01, 0.0]))
    with pytest.raises(ModelInputError, match="best scale"):
        glenoid_geometry(np.array([0.0, -0.046, -0.0878]) * 0.5 + np.array([0.004, 0.0, 0.0]))
