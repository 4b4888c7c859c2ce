"""The code generator: determinism, the committed output, refusals of bad model files, compile check."""
from __future__ import annotations

import copy
import hashlib
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from gen_lib import GENERATED, MODEL_PATH, ROOT, GenModel, build_library, gen_model  # noqa: F401 (fixture)

from codegen.generate import ModelFileError, generate, load_model, validate  # noqa: E402 (path set by gen_lib)

NAME = json.loads(MODEL_PATH.read_text())["name"]
FILES = [f"{NAME}.h", f"{NAME}_model.cc", f"{NAME}_dynamics.cc", f"{NAME}_paths.cc"]


@pytest.fixture(scope="module")
def fresh(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("gen_fresh")
    generate(MODEL_PATH, out)
    return out


def _model():
    return json.loads(MODEL_PATH.read_text())


def test_regeneration_is_byte_identical(fresh, tmp_path):
    # A separate process with another hash seed: set/dict ordering must not leak into the output.
    env = dict(os.environ, PYTHONHASHSEED="12345", PYTHONPATH=str(ROOT))
    subprocess.run([sys.executable, "-m", "codegen.generate", "--model", str(MODEL_PATH), "--out", str(tmp_path)],
                   check=True, cwd=ROOT, env=env, capture_output=True)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(FILES)
    for f in FILES:
        assert (tmp_path / f).read_bytes() == (fresh / f).read_bytes(), f


def test_committed_generated_code_matches_model_file(fresh):
    for f in FILES:
        committed = GENERATED / f
        assert committed.exists(), f"{committed} missing: run python -m codegen.generate --model models/das2.json --out cpp/generated"
        assert committed.read_bytes() == (fresh / f).read_bytes(), (
            f"{committed} differs from a fresh generation from {MODEL_PATH.name}: it was edited by hand or not "
            f"regenerated; run python -m codegen.generate --model models/das2.json --out cpp/generated")


def test_banner_names_generator_and_model_hash(fresh):
    digest = hashlib.sha256(MODEL_PATH.read_bytes()).hexdigest()
    for f in FILES:
        head = (fresh / f).read_text().splitlines()[:4]
        text = "\n".join(head)
        assert "GENERATED FILE - DO NOT EDIT BY HAND" in text
        assert "python -m codegen.generate" in text
        assert digest in text and MODEL_PATH.name in text


def _refused(model, *needles):
    with pytest.raises(ModelFileError) as exc:
        validate(model)
    for n in needles:
        assert n in str(exc.value), str(exc.value)


def test_refuses_wrong_schema_and_version():
    m = _model()
    m["schema_version"] = 2
    _refused(m, "schema_version")
    m = _model()
    m["schema"] = "something-else"
    _refused(m, "schema")


@pytest.mark.parametrize("path,field", [
    (("bodies", 1, "inertia"), "bodies[1].inertia"),
    (("gravity_thorax",), "gravity_thorax"),
    (("elements", 7, "length_poly"), "elements[7].length_poly"),
    (("glenoid", "normal"), "glenoid.normal"),
    (("hand_point",), "hand_point"),
    (("dofs", 3, "rest"), "dofs[3].rest"),
    (("elements", 0, "gh_direction", "y"), "elements[0].gh_direction.y"),
])
def test_refuses_missing_field(path, field):
    m = _model()
    obj = m
    for k in path[:-1]:
        obj = obj[k]
    del obj[path[-1]]
    _refused(m, "missing", field)


def test_refuses_wrong_shapes():
    m = _model()
    m["bodies"][2]["inertia"] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
    _refused(m, "bodies[2].inertia", "3x3")
    m = _model()
    m["elements"][5]["length_poly"]["exponents"][0] = [1, 0]
    _refused(m, "elements[5].length_poly.exponents[0]")
    m = _model()
    m["elements"][5]["length_poly"]["coefs"] = m["elements"][5]["length_poly"]["coefs"][:-1]
    _refused(m, "elements[5].length_poly.coefs")
    m = _model()
    m["dofs"] = m["dofs"][:4]
    _refused(m, "dofs")
    m = _model()
    m["bodies"][0]["mass"] = "heavy"
    _refused(m, "bodies[0].mass")
    m = _model()
    m["elements"][0]["dofs"] = ["GHx"]
    _refused(m, "elements[0].dofs")


def test_cli_refuses_bad_file_with_message(tmp_path):
    m = _model()
    m["schema_version"] = 7
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(m))
    out = tmp_path / "out"
    r = subprocess.run([sys.executable, "-m", "codegen.generate", "--model", str(bad), "--out", str(out)],
                       cwd=ROOT, env=dict(os.environ, PYTHONPATH=str(ROOT)), capture_output=True, text=True)
    assert r.returncode == 2
    assert "schema_version" in r.stderr
    assert not out.exists()


def test_load_model_hash():
    model, digest = load_model(MODEL_PATH)
    assert digest == hashlib.sha256(MODEL_PATH.read_bytes()).hexdigest()
    assert model["name"] == NAME


def test_tables_match_model_file(gen_model):
    lib, m = gen_model.lib, gen_model.model
    assert lib.h_name().decode() == m["name"]
    assert lib.h_source_hash().decode() == hashlib.sha256(MODEL_PATH.read_bytes()).hexdigest()
    assert lib.h_num_dofs() == 5
    assert gen_model.nel == len(m["elements"])
    dof_index = {d["name"]: i for i, d in enumerate(m["dofs"])}
    for i, e in enumerate(m["elements"]):
        assert lib.h_element_name(i).decode() == e["name"]
        assert lib.h_element_dof_mask(i) == sum(1 << dof_index[d] for d in e["dofs"])
        assert lib.h_element_crosses_gh(i) == int(e["crosses_gh"])
        assert lib.h_element_fmax(i) == e["fmax"]
    el_index = {e["name"]: i for i, e in enumerate(m["elements"])}
    assert lib.h_num_muscles() == len(m["muscles"])
    for k, mus in enumerate(m["muscles"]):
        assert lib.h_muscle_name(k).decode() == mus["name"]
        assert [lib.h_muscle_element(k, j) for j in range(lib.h_muscle_size(k))] == [el_index[n] for n in mus["elements"]]
    elements_of = {mus["name"]: {el_index[n] for n in mus["elements"]} for mus in m["muscles"]}
    assert lib.h_num_groups() == len(m["groups"])
    for k, (g, ms) in enumerate(m["groups"].items()):
        assert lib.h_group_name(k).decode() == g
        got = [lib.h_group_element(k, j) for j in range(lib.h_group_size(k))]
        assert got == sorted(set().union(*(elements_of[x] for x in ms)))
    assert lib.h_arm_mass() == pytest.approx(sum(b["mass"] for b in m["bodies"]), rel=1e-15)
    R = np.array(m["scapula"]["rotation_in_thorax"])
    np.testing.assert_allclose(gen_model.gravity_base(), R.T @ np.array(m["gravity_thorax"]), rtol=0, atol=1e-14)


def _poly_eval(exps, coefs, qsub):
    e = np.asarray(exps, dtype=int).reshape(len(coefs), -1)
    return float(np.sum(np.asarray(coefs) * np.prod(qsub[None, :] ** e, axis=1)))


def test_generator_follows_changed_path_polynomials(tmp_path):
    """Paths come from whatever the model file holds: new dofs, exponents and coefficients."""
    m = _model()
    rng = np.random.default_rng(7)
    names = [d["name"] for d in m["dofs"]]
    for idx, dofs in [(0, names[:3]), (70, ["ELx", "PSy"]), (101, names)]:
        e = m["elements"][idx]
        e["dofs"] = list(dofs)
        nterm = int(rng.integers(3, 9))
        exps = rng.integers(0, 5, size=(nterm, len(dofs))).tolist()
        e["length_poly"] = {"dofs": list(reversed(dofs)), "exponents": exps,
                            "coefs": rng.normal(0, 0.05, nterm).tolist()}
    path = tmp_path / "variant.json"
    path.write_text(json.dumps(m))
    gen = tmp_path / "gen"
    generate(path, gen)
    lib = GenModel(build_library(gen, m["name"], tmp_path), m)
    dof_index = {n: i for i, n in enumerate(names)}
    for _ in range(5):
        q = rng.uniform(-1, 1.5, 5)
        L, r = lib.muscle_paths(q)
        np.testing.assert_array_equal(lib.muscle_lengths(q), L)
        for idx in (0, 70, 101):
            lp = m["elements"][idx]["length_poly"]
            qs = np.array([q[dof_index[d]] for d in lp["dofs"]])
            assert L[idx] == pytest.approx(_poly_eval(lp["exponents"], lp["coefs"], qs), rel=1e-13, abs=1e-15)


# Issue 11 item 6: schema-valid files that describe no arm are refused, naming the field and the reason.
def _set(m, path, value):
    obj = m
    for k in path[:-1]:
        obj = obj[k]
    obj[path[-1]] = value
    return m


@pytest.mark.parametrize("path, value, needles", [
    (("bodies", 0, "mass"), -2.0, ["bodies[0].mass", "> 0"]),
    (("bodies", 1, "inertia"), [[-0.003, 0, 0], [0, 0.003, 0], [0, 0, 0.0005]], ["bodies[1].inertia", "not positive definite"]),
    (("bodies", 1, "inertia"), [[0.001, 0, 0], [0, 0.001, 0], [0, 0, 0.01]], ["bodies[1].inertia", "triangle inequality"]),
    (("bodies", 2, "inertia"), [[0.003, 0.001, 0], [0, 0.003, 0], [0, 0, 0.0005]], ["bodies[2].inertia", "not symmetric"]),
    (("bodies", 3, "mass"), 500.0, ["bodies[3].mass", "under 50 kg"]),
    (("glenoid", "normal"), [0.0, 0.0, 0.0], ["glenoid.normal", "is zero"]),
    (("glenoid", "major_axis"), [0.0, 0.0, 2.0], ["glenoid.major_axis", "unit vector"]),
    (("glenoid", "rim_half_angle_major"), 2.0, ["glenoid.rim_half_angle_major", "below pi/2"]),
    (("elements", 4, "fmax"), 1e7, ["elements[4].fmax", "outside the physical range"]),
    (("elements", 4, "tact"), 30.0, ["elements[4].tact", "outside the physical range"]),
    (("elements", 4, "muscle"), "bicb", ["elements[4].muscle", "is 'bicb' but muscle 'deltscap' lists the element"]),
    (("elements", 4, "crosses_gh"), False, ["elements[4].gh_direction", "not crossing GH"]),
    (("dofs", 3, "range"), [5.0, 140.0], ["dofs[3].range", "radians expected"]),
    (("gravity_thorax",), [0.0, -981.0, 0.0], ["gravity_thorax", "more than 10 g"]),
])
def test_refuses_physical_nonsense(path, value, needles):
    _refused(_set(_model(), path, value), *needles)


def test_refuses_absurd_polynomial_exponents_before_generating(tmp_path):
    """The issue's example: an exponent of 10^9 exhausted memory in the generator."""
    m = _model()
    m["elements"][7]["length_poly"]["exponents"][0][0] = 10**9
    _refused(m, "elements[7].length_poly.exponents[0]", "degree 1000000000")
    bad = tmp_path / "huge.json"
    bad.write_text(json.dumps(m))
    out = tmp_path / "out"
    r = subprocess.run([sys.executable, "-m", "codegen.generate", "--model", str(bad), "--out", str(out)],
                       cwd=ROOT, env=dict(os.environ, PYTHONPATH=str(ROOT)), capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 2 and "degree 1000000000" in r.stderr and not out.exists()


def test_refuses_tables_that_disagree():
    m = _model()
    m["muscles"][1]["elements"].append(m["muscles"][0]["elements"][0])
    _refused(m, "muscles[1].elements", "already in muscle 'deltscap'")
    m = _model()
    m["muscles"][0]["elements"].remove("deltscap3")
    _refused(m, "elements[2].muscle", "'deltscap3' is in no muscle")


def test_refuses_excessive_nesting(tmp_path):
    for depth in (40, 100_000):   # beyond the limit; beyond Python's recursion limit
        m = _model()
        text = json.dumps(m)[:-1] + ', "extra": ' + "[" * depth + "]" * depth + "}"
        bad = tmp_path / f"deep{depth}.json"
        bad.write_text(text)
        with pytest.raises(ModelFileError, match="nesting deeper than 16 levels"):
            load_model(bad)


def test_the_shipped_model_passes_the_sense_checks():
    from codegen.generate import check_sense
    check_sense(validate(_model()))


def test_committed_das3_code_matches_its_model_file(tmp_path):
    # das3 (thorax-based, unrolled recursive dynamics; docs/das3.md) is generated in 0.2 s: check it whole.
    das3 = ROOT / "models" / "das3.json"
    generate(das3, tmp_path)
    for f in sorted(p.name for p in tmp_path.iterdir()):
        assert (GENERATED / f).read_bytes() == (tmp_path / f).read_bytes(), (
            f"cpp/generated/{f} differs from a fresh generation: run python -m codegen.generate --model "
            f"models/das3.json --out cpp/generated")
