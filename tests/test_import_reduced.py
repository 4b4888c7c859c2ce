"""The generalised importer (codegen/importers/import_reduced.py): any DAS-format .mat with chosen free DOFs,
the participant models, the default posture, and refusal of bad requests and bad model files."""
import json
import math

import numpy as np
import pytest
import scipy.io as sio

from codegen.importers.das3_source import ModelInputError
from codegen.importers.das_struct import read_das_struct
from codegen.importers.import_reduced import build_reduced_model, joint_pose
from codegen.polynomial import evaluate
from conftest import REFERENCE, ROOT

PARTICIPANT = REFERENCE / "participant_A"
VARIANTS = ["", "_FES", "_injured", "_paralysed"]
ARM5 = ["GHy", "GHz", "GHyy", "ELx", "PSy"]


@pytest.fixture(scope="module")
def participant_dir():
    if not (PARTICIPANT / "model_struct_A.mat").exists():
        pytest.skip(f"participant data not found at {PARTICIPANT} (needs ../shared beside the repository)")
    return PARTICIPANT


@pytest.fixture(scope="module")
def equilibrium(das3_dir):
    return das3_dir / "equilibrium.mat"


@pytest.fixture(scope="module")
def elbow_fes(participant_dir, equilibrium):
    return build_reduced_model(participant_dir / "model_struct_A_FES.mat", ["ELx", "PSy"], "participant_A_FES",
                               equilibrium_path=equilibrium)


def test_mat_kinematics_match_the_osim_path_of_das2(das3_dir, equilibrium):
    """The .mat joints/segments reader gives das2's bodies, scapula and glenoid (which come from das3.osim)."""
    m = build_reduced_model(das3_dir / "model_struct.mat", ARM5, "das3_mat", equilibrium_path=equilibrium)
    d = json.loads((ROOT / "models" / "das2.json").read_text())
    assert [x["rest"] for x in m["dofs"]] == [x["rest"] for x in d["dofs"]]
    for a, b in zip(m["bodies"], d["bodies"]):
        assert a["mass"] == b["mass"] and a["joint"]["type"] == b["joint"]["type"]
        for k in ("com", "inertia"):
            assert np.allclose(a[k], b[k], atol=1e-15)
        assert np.allclose(a["joint"]["location_in_parent"], b["joint"]["location_in_parent"], atol=1e-15)
        assert np.allclose(np.reshape(a["joint"]["axes"], (-1, 3)), np.reshape(b["joint"]["axes"], (-1, 3)), atol=1e-12)
    for k in ("rotation_in_thorax", "origin_in_thorax"):
        assert np.allclose(m["scapula"][k], d["scapula"][k], atol=1e-12)
    assert np.allclose(m["glenoid"]["normal"], d["glenoid"]["normal"], atol=1e-12)


def test_das3_elbow_forearm_drops_shoulder_elements(das3_dir, equilibrium):
    m = build_reduced_model(das3_dir / "model_struct.mat", ["ELx", "PSy"], "das3_elbow", equilibrium_path=equilibrium)
    assert [d["name"] for d in m["dofs"]] == ["ELx", "PSy"]
    assert len(m["elements"]) == 42 and len(m["source"]["dropped_elements"]) == 138 - 42
    assert "deltscap1" in m["source"]["dropped_elements"] and "bicl" not in m["source"]["dropped_elements"]
    # GH-crossing elements keep their GH line of action, constant now that GH is fixed.
    bicl = next(e for e in m["elements"] if e["name"] == "bicl")
    assert bicl["crosses_gh"] and not m["source"]["gh_direction_missing"]
    assert all(not any(row) for c in "xyz" for row in bicl["gh_direction"][c]["exponents"])
    assert m["bodies"][0]["joint"]["type"] == "weld" and "rotation" in m["bodies"][0]["joint"]


@pytest.mark.parametrize("variant", VARIANTS)
def test_participant_imports_as_elbow_forearm_model(participant_dir, equilibrium, variant):
    path = participant_dir / f"model_struct_A{variant}.mat"
    m = build_reduced_model(path, ["ELx", "PSy"], "participant_A" + variant, equilibrium_path=equilibrium)
    raw = sio.loadmat(path, squeeze_me=True, struct_as_record=False)["model"]
    assert [d["name"] for d in m["dofs"]] == ["ELx", "PSy"] and len(m["elements"]) == 42
    assert not m["source"]["dropped_elements"] and m["source"]["opensim_file_available"] is False
    assert "No OpenSim file exists" in m["description"]
    for e, mu in zip(m["elements"], raw.muscles):
        assert e["name"] == mu.name
        assert e["fmax"] == float(mu.fmax) and e["max_activation"] == float(mu.maxact)
    fixed = {d["name"] for d in m["fixed_dofs"]["dofs"]}
    assert fixed == {"THx", "THy", "THz", "SCy", "SCz", "SCx", "ACy", "ACz", "ACx", "GHy", "GHz", "GHyy"}


def test_participant_polynomials_are_its_own_with_fixed_angles_substituted(participant_dir, elbow_fes):
    struct = read_das_struct(participant_dir / "model_struct_A_FES.mat")
    fixed = {d["name"]: d["angle"] for d in elbow_fes["fixed_dofs"]["dofs"]}
    rng = np.random.default_rng(3)
    for e, src in zip(elbow_fes["elements"], struct.elements):
        lp = e["length_poly"]
        for _ in range(5):
            free = {"ELx": rng.uniform(0.1, 2.4), "PSy": rng.uniform(0.1, 2.7)}
            full = [fixed.get(d, free.get(d)) for d in src.dof_names]
            want = evaluate(src.lparams, src.lcoefs, [full])[0]
            got = evaluate(lp["exponents"], lp["coefs"], [[free[d] for d in lp["dofs"]]])[0]
            assert got == pytest.approx(want, rel=1e-12, abs=1e-15)
        if src.direction is not None:
            gd = e["gh_direction"]
            full = [fixed.get(d, 1.0) for d in src.dof_names]
            for axis in "xyz":
                want = evaluate(*src.direction[axis], [full])[0]
                assert evaluate(gd[axis]["exponents"], gd[axis]["coefs"], [[1.0] * len(gd["dofs"])])[0] == pytest.approx(want)


def test_default_posture_hangs_the_arm(participant_dir, elbow_fes):
    struct = read_das_struct(participant_dir / "model_struct_A_FES.mat")
    pose = {d["name"]: d["angle"] for d in elbow_fes["fixed_dofs"]["dofs"]}
    pose.update({d["name"]: d["rest"] for d in elbow_fes["dofs"]})
    R_sc, _ = joint_pose(struct.chain("scapular", "thorax"), pose)
    R_h, _ = joint_pose(struct.chain("humerusr", "scapular"), pose)
    hu = struct.joints["ulnar"]
    down = (R_sc @ R_h) @ (hu.location / np.linalg.norm(hu.location))
    assert math.degrees(math.acos(-down[1])) < 0.5           # humerus along gravity
    el = (R_sc @ R_h) @ hu.rotations[0].axis
    assert math.degrees(math.acos(el[0])) < 5.0                # elbow axis lateral
    assert elbow_fes["gravity_thorax"] == [0.0, -9.80665, 0.0]
    assert "hanging" in elbow_fes["fixed_dofs"]["source"]


def test_user_posture_overrides_and_is_checked(participant_dir, equilibrium):
    m = build_reduced_model(participant_dir / "model_struct_A.mat", ["ELx", "PSy"], "p", equilibrium_path=equilibrium,
                            posture={"GHz": 0.5, "THx": 0.1, "ELx": 1.0})
    fixed = {d["name"]: d["angle"] for d in m["fixed_dofs"]["dofs"]}
    assert fixed["GHz"] == 0.5 and fixed["THx"] == 0.1 and m["dofs"][0]["rest"] == 1.0
    # A thorax tilted about its x axis sees gravity tilted the other way: R_x(0.1)^T g.
    g = 9.80665
    assert m["gravity_thorax"] == pytest.approx([0.0, -g * math.cos(0.1), g * math.sin(0.1)], abs=1e-12)
    with pytest.raises(ModelInputError, match="GHz = 45 rad"):
        build_reduced_model(participant_dir / "model_struct_A.mat", ["ELx", "PSy"], "p", equilibrium_path=equilibrium,
                            posture={"GHz": 45.0})
    with pytest.raises(ModelInputError, match="'XXq' is not a DOF"):
        build_reduced_model(participant_dir / "model_struct_A.mat", ["ELx", "PSy"], "p", equilibrium_path=equilibrium,
                            posture={"XXq": 0.0})


@pytest.mark.parametrize("free, message", [
    (["GHz", "ELx"], "free all of them or none"),
    (["SCy", "ELx"], "thorax and girdle DOFs are fixed"),
    (["ELz"], "'ELz' is not a DOF"),
    ([], "at least one DOF"),
])
def test_bad_free_sets_are_refused(participant_dir, equilibrium, free, message):
    with pytest.raises(ModelInputError, match=message):
        build_reduced_model(participant_dir / "model_struct_A.mat", free, "p", equilibrium_path=equilibrium)


def test_committed_participant_files_match_a_fresh_import(participant_dir, tmp_path):
    from codegen.importers.import_das3 import main
    for v in VARIANTS:
        out = tmp_path / f"participant_A{v}.json"
        assert main([str(participant_dir / f"model_struct_A{v}.mat"), "--free", "ELx,PSy", "--name",
                     f"participant_A{v}", "-o", str(out)]) == 0
        assert out.read_bytes() == (ROOT / "models" / f"participant_A{v}.json").read_bytes(), \
            f"models/participant_A{v}.json is stale: rerun the command in docs/model_schema.md"


def test_importer_cli_reports_bad_requests(participant_dir, tmp_path, capsys):
    from codegen.importers.import_das3 import main
    assert main([str(participant_dir / "model_struct_A.mat"), "--free", "GHz,ELx", "-o", str(tmp_path / "m.json")]) == 2
    assert "free all of them or none" in capsys.readouterr().err
    assert main([str(participant_dir / "model_struct_A.mat"), "--free", "ELx", "--posture", "ELx=abc",
                 "-o", str(tmp_path / "m.json")]) == 2
    assert "'abc'" in capsys.readouterr().err
    assert not (tmp_path / "m.json").exists()


def test_bad_participant_struct_names_field_and_element(participant_dir):
    from codegen.importers.das_struct import parse_das_struct
    model = sio.loadmat(participant_dir / "model_struct_A.mat", squeeze_me=True, struct_as_record=False)["model"]
    model.muscles[5].maxact = 1.5
    with pytest.raises(ModelInputError, match=r"muscles\[5\] \('triclong3'\): field 'maxact' must lie in \[0, 1\]"):
        parse_das_struct(model, participant_dir / "model_struct_A.mat")
    model.muscles[5].maxact = 1.0
    model.muscles[7].fmax = -3.0
    with pytest.raises(ModelInputError, match=r"\('tricmed1'\): field 'fmax' must be positive"):
        parse_das_struct(model, participant_dir / "model_struct_A.mat")


# ----------------------------------------------------------------------------- generator

@pytest.fixture(scope="module")
def model_file():
    path = ROOT / "models" / "participant_A_FES.json"
    if not path.exists():
        pytest.skip("models/participant_A_FES.json absent")
    return json.loads(path.read_text())


def test_generator_accepts_the_elbow_forearm_model(model_file):
    from codegen.generate import validate
    validate(model_file)


@pytest.mark.parametrize("mutate, needles", [
    (lambda m: m["elements"][3].__setitem__("fmax", -1.0), ["elements[3].fmax", "'triclong1'"]),
    (lambda m: m["elements"][4].__setitem__("max_activation", 1.5), ["elements[4].max_activation", "'triclong2'"]),
    (lambda m: m["elements"][0].__setitem__("lceopt", 5.0), ["elements[0].lceopt", "'bicl'"]),
    (lambda m: m["bodies"][0]["joint"].__setitem__("rotation", [[2, 0, 0], [0, 1, 0], [0, 0, 1]]), ["bodies[0].joint.rotation"]),
    (lambda m: m.__setitem__("dofs", []), ["field 'dofs' has 0 entries"]),
])
def test_generator_refuses_bad_model_naming_field_and_element(model_file, mutate, needles):
    import copy
    from codegen.generate import ModelFileError, validate
    m = copy.deepcopy(model_file)
    mutate(m)
    with pytest.raises(ModelFileError) as err:
        validate(m)
    for n in needles:
        assert n in str(err.value)


def test_armrt_model_import_writes_the_same_file(participant_dir, tmp_path):
    cli = pytest.importorskip("armrt.cli", reason="armrt is not built/installed")
    out = tmp_path / "participant_A_injured.json"
    assert cli.main(["model", "import", str(participant_dir / "model_struct_A_injured.mat"), "--free", "ELx,PSy",
                     "--name", "participant_A_injured", "-o", str(out)]) == 0
    assert out.read_bytes() == (ROOT / "models" / "participant_A_injured.json").read_bytes()
    assert cli.main(["model", "import", str(participant_dir / "model_struct_A.mat"), "--free", "ELx,SCy",
                     "-o", str(tmp_path / "bad.json")]) == 2


@pytest.mark.parametrize("name, out", [("participant_A", "cpp/generated"),           # built in
                                       ("participant_A_FES", "cpp/tests/generated")])  # C++ tests only
def test_committed_participant_code_matches_a_fresh_generation(tmp_path, name, out):
    from codegen.generate import generate
    cmd = f"python -m codegen.generate --model models/{name}.json --out {out}"
    generate(ROOT / "models" / f"{name}.json", tmp_path, command=cmd)
    for f in [f"{name}.h", f"{name}_model.cc", f"{name}_dynamics.cc", f"{name}_paths.cc"]:
        assert (tmp_path / f).read_bytes() == (ROOT / out / f).read_bytes(), f"{out}/{f} is stale: {cmd}"


@pytest.mark.slow
def test_welded_gh_dynamics_equal_the_free_gh_model_at_the_fixed_angles(participant_dir, equilibrium):
    """The 2-DOF model (humerus welded at the fixed GH angles) has the mass matrix and generalised
    gravity/Coriolis forces of the 5-DOF model's elbow-forearm block at those angles, GH at rest."""
    import sympy as sp
    from codegen.eom import derive
    m2 = build_reduced_model(participant_dir / "model_struct_A.mat", ["ELx", "PSy"], "p2", equilibrium_path=equilibrium)
    gh = {d["name"]: d["angle"] for d in m2["fixed_dofs"]["dofs"] if d["name"] in ("GHy", "GHz", "GHyy")}
    m5 = build_reduced_model(participant_dir / "model_struct_A.mat", ARM5, "p5", equilibrium_path=equilibrium,
                             posture={**gh, "ELx": m2["dofs"][0]["rest"], "PSy": m2["dofs"][1]["rest"]})
    assert np.allclose(m5["scapula"]["rotation_in_thorax"], m2["scapula"]["rotation_in_thorax"], atol=1e-15)
    e2, e5 = derive(m2), derive(m5)
    f2 = sp.lambdify(e2.q + e2.qd + e2.g, [e2.mass_matrix, e2.bias_force, e2.hand_position], "numpy")
    f5 = sp.lambdify(e5.q + e5.qd + e5.g, [e5.mass_matrix, e5.bias_force, e5.hand_position], "numpy")
    rng = np.random.default_rng(7)
    ghv = [gh["GHy"], gh["GHz"], gh["GHyy"]]
    for _ in range(5):
        q, qd, g = rng.uniform(0.2, 2.0, 2), rng.normal(size=2), rng.normal(size=3) * 5
        M2, b2, h2 = f2(*q, *qd, *g)
        M5, b5, h5 = f5(*ghv, *q, 0.0, 0.0, 0.0, *qd, *g)
        assert np.allclose(np.asarray(M2, float), np.asarray(M5, float)[3:, 3:], rtol=1e-12, atol=1e-14)
        assert np.allclose(np.asarray(b2, float).ravel(), np.asarray(b5, float).ravel()[3:], rtol=1e-12, atol=1e-12)
        assert np.allclose(np.asarray(h2, float).ravel(), np.asarray(h5, float).ravel(), rtol=1e-12, atol=1e-14)


def test_variants_share_the_geometry_so_profiles_suffice():
    """Why the variants are profiles on participant_A (docs/experiments.md): what enters the elbow-forearm
    dynamics is the same in the four model files except fmax and max_activation (runtime parameters)
    and lceopt/lslack of 16 elements (at most 1.4e-4 relative). The variant .mat files also change
    the thorax, scapula and humerus inertias and the GHz/GHyy ranges, none of which moves here: the
    humerus is welded (its inertia enters no equation of a model whose DOFs are distal to it)."""
    files = {v: json.loads((ROOT / "models" / f"participant_A{v}.json").read_text()) for v in VARIANTS}
    intact = files[""]
    changed = set()
    for v in VARIANTS[1:]:
        m = files[v]
        for k in ("dofs", "scapula", "glenoid", "muscles", "groups", "gravity_thorax", "fixed_dofs"):
            assert m[k] == intact[k], (v, k)
        assert m["bodies"][1:] == intact["bodies"][1:]
        hum, hum0 = dict(m["bodies"][0]), dict(intact["bodies"][0])
        assert hum.pop("inertia") != hum0.pop("inertia") and hum == hum0
        for a, b in zip(m["elements"], intact["elements"]):
            for k in a:
                if k in ("fmax", "max_activation"):
                    continue
                if k in ("lceopt", "lslack"):
                    assert abs(a[k] - b[k]) <= 1.4e-4 * b[k], (v, a["name"], k)
                    if a[k] != b[k]:
                        changed.add(a["name"])
                else:
                    assert a[k] == b[k], (v, a["name"], k)
    assert len(changed) == 16
    inj, par = files["_injured"]["elements"], files["_paralysed"]["elements"]
    assert [(e["fmax"], e["max_activation"]) for e in inj] == [(e["fmax"], e["max_activation"]) for e in par]
