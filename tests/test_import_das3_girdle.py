"""The 11-DOF shoulder-girdle model file models/das3.json (codegen/importers/import_das3_girdle.py): one importer
command reproduces it byte for byte, its chain is das3.osim's, its paths are models/das3_paths.json's and
its girdle forces model_struct.mat's; bad inputs are refused by name."""
import argparse
import importlib.util
import json
import shutil

import numpy as np
import pytest
import scipy.io as sio

from codegen.importers import das3_source as src
from codegen.importers.das3_chain import das3_bodies
from codegen.importers.das3_source import ModelInputError
from codegen.importers.import_das3 import import_any, is_das2_call, is_das3_call, main
from codegen.importers.import_das3_girdle import DAS3_PATHS, build_das3_model, read_paths
from conftest import ROOT

SHIPPED = ROOT / "models" / "das3.json"
FREE = "SCy,SCz,SCx,ACy,ACz,ACx,GHy,GHz,GHyy,ELx,PSy"


@pytest.fixture(scope="module")
def model(das3_dir):
    return build_das3_model(das3_dir)


@pytest.fixture(scope="module")
def shipped():
    return json.loads(SHIPPED.read_text())


@pytest.fixture(scope="module")
def paths():
    return {e["name"]: e for e in json.loads(DAS3_PATHS.read_text())["elements"]}


@pytest.fixture(scope="module")
def struct(das3_dir):
    return sio.loadmat(das3_dir / "model_struct.mat", squeeze_me=True, struct_as_record=False)["model"]


def test_the_importer_command_reproduces_the_shipped_file(das3_dir, tmp_path, capsys):
    out = tmp_path / "das3.json"
    assert main([str(das3_dir / "model_struct.mat"), "--free", FREE, "-o", str(out)]) == 0
    assert out.read_bytes() == SHIPPED.read_bytes()
    # The same bytes whatever order the DOFs are named in and whichever entry runs it.
    spec = importlib.util.spec_from_file_location("model_cli", ROOT / "python" / "armrt" / "model_cli.py")
    cli = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(cli)
    ap = argparse.ArgumentParser()
    cli.add_cli(ap.add_subparsers(dest="command"), argparse.HelpFormatter)
    out2 = tmp_path / "das3_cli.json"
    args = ap.parse_args(["model", "import", str(das3_dir / "model_struct.mat"), "--free",
                          ",".join(reversed(FREE.split(","))), "-o", str(out2)])
    assert args.func(args) == 0
    assert out2.read_bytes() == SHIPPED.read_bytes()
    assert "das3, 11 DOFs, 138 elements, 28 muscles" in capsys.readouterr().out


def test_default_output_is_das3_json_not_das2(das3_dir, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main([str(das3_dir / "model_struct.mat"), "--free", FREE]) == 0
    assert (tmp_path / "models" / "das3.json").read_bytes() == SHIPPED.read_bytes()
    assert not (tmp_path / "models" / "das2.json").exists()


def test_dispatch_das3_only_with_all_eleven_free(das3_dir):
    mat = das3_dir / "model_struct.mat"
    assert is_das3_call(mat, FREE.split(","), {}) and not is_das2_call(mat, FREE.split(","), {})
    assert not is_das3_call(mat, src.ARM_DOFS, {}) and is_das2_call(mat, src.ARM_DOFS, {})
    assert not is_das3_call(mat, FREE.split(","), {"GHz": 0.3})


def test_dofs_elements_and_order(model, das3_dir):
    st = src.read_model_struct(das3_dir / "model_struct.mat")
    posture = src.read_equilibrium(das3_dir / "equilibrium.mat")
    assert model["name"] == "das3" and model["base"] == "thorax"
    assert "scapula" not in model and "girdle" not in model
    assert [d["name"] for d in model["dofs"]] == FREE.split(",")
    assert [d["rest"] for d in model["dofs"]] == [posture[d] for d in FREE.split(",")]
    assert [e["name"] for e in model["elements"]] == [e.name for e in st.elements] and len(model["elements"]) == 138
    das2 = json.loads((ROOT / "models" / "das2.json").read_text())
    rom = json.loads(DAS3_PATHS.read_text())["rom"]
    for d in model["dofs"]:
        assert d["das3_range"] == list(st.dof_ranges[d["name"]])
        if d["name"] in src.GIRDLE_DOFS:
            assert d["range"] == rom["girdle_range"][d["name"]]
            assert d["range"][0] <= d["rest"] <= d["range"][1]
    assert model["dofs"][6:] == das2["dofs"]   # the arm DOFs as das2 (range, das3_range, rest)
    for k in ("schema_version", "gravity_thorax", "passive_joint", "hand_point", "glenoid"):
        assert model[k] == das2[k], k
    for e, s in zip(model["elements"], st.elements):
        assert e["fmax"] == s.params["fmax"] and e["peeslack"] == s.params["PEEslack"] and e["osim_name"] == s.osim_name


def test_bodies_are_das3_osim_chain(model, das3_dir):
    ref = das3_bodies(das3_dir / "das3.osim")
    types = {"sc": "gimbal_yzx", "ac": "gimbal_yzx", "gh": "gimbal_yzy", "hu": "pin", "ur": "pin", "rc": "weld"}
    assert [b["name"] for b in model["bodies"]] == ["clavicle", "scapula", "humerus", "ulna", "radius", "hand"]
    for b, r in zip(model["bodies"], ref):
        j = dict(b["joint"])
        assert j.pop("type") == types[r["joint"]["name"]]
        b = dict(b)
        note = b.pop("inertia_note", None)
        assert {**b, "joint": j} == r
        # A published inertia no rigid body has is kept only with its reason (the clavicle's).
        assert (note is not None) == (b["name"] == "clavicle")
    # The arm bodies are das2's, unchanged.
    das2 = json.loads((ROOT / "models" / "das2.json").read_text())
    assert model["bodies"][2:] == das2["bodies"]


def test_every_element_path_is_das3_paths(model, paths):
    assert {e["name"] for e in model["elements"]} == set(paths)
    for e in model["elements"]:
        p = paths[e["name"]]
        assert e["dofs"] == p["dofs"] and e["length_poly"] == p["length_poly"] and e["fit"] == p["fit"]
        assert e["gh_direction"] == p.get("gh_direction")
        assert e["crosses_gh"] == bool({"GHy", "GHz", "GHyy"} & set(e["dofs"])) == (e["gh_direction"] is not None)
    assert sum(e["crosses_gh"] for e in model["elements"]) == 67


def test_girdle_parameters_are_model_structs(model, struct):
    gf = model["girdle_forces"]
    assert gf["thorax_ellipsoid"]["centre"] == np.asarray(struct.thorax_center, float).tolist()
    assert gf["thorax_ellipsoid"]["radii"] == np.asarray(struct.thorax_radii, float).tolist()
    c = gf["contact"]
    assert (c["stiffness"], c["eps"]) == (float(struct.scap_thorax_k), float(struct.scap_thorax_eps))
    assert [(p["name"], p["body"]) for p in c["points"]] == [("TS", "scapula"), ("AI", "scapula")]
    assert c["points"][0]["point"] == np.asarray(struct.TSprojection, float).tolist()
    assert c["points"][1]["point"] == np.asarray(struct.AIprojection, float).tolist()
    k = gf["conoid"]
    assert k["origin"] == {"body": "clavicle", "point": np.asarray(struct.conoid_origin, float).tolist()}
    assert k["insertion"] == {"body": "scapula", "point": np.asarray(struct.conoid_insertion, float).tolist()}
    assert (k["length"], k["stiffness"], k["eps"]) == (float(struct.conoid_length), float(struct.conoid_stiffness),
                                                       float(struct.conoid_eps))


def test_muscles_and_groups(model):
    muscles = {m["name"]: m for m in model["muscles"]}
    assert len(muscles) == 28
    assert [x for m in model["muscles"] for x in m["elements"]] == [e["name"] for e in model["elements"]]
    assert muscles["trapclav"]["crosses"] == ["SC"] and muscles["serrant"]["crosses"] == ["SC", "AC"]
    assert muscles["latdorsi"]["crosses"] == ["SC", "AC", "GH"] and muscles["bicl"]["crosses"] == ["GH", "HU", "RU"]
    g = model["groups"]
    assert g["scapular"] == ["trapscap", "trapclav", "levscap", "pectmin", "rhomboid", "serrant"]
    assert g["trapezius"] == ["trapscap", "trapclav"] and g["serratus_anterior"] == ["serrant"]
    das2 = json.loads((ROOT / "models" / "das2.json").read_text())
    assert {k: g[k] for k in das2["groups"]} == das2["groups"]


def test_the_shipped_file_is_the_built_model(model, shipped):
    assert shipped == model


def _copy_release(das3_dir, dst, skip=()):
    dst.mkdir()
    for f in ("model_struct.mat", "equilibrium.mat", "das3.osim"):
        if f not in skip:
            shutil.copy(das3_dir / f, dst / f)
    return dst


def test_a_missing_file_is_named(das3_dir, tmp_path):
    d = _copy_release(das3_dir, tmp_path / "no_osim", skip=("das3.osim",))
    with pytest.raises(ModelInputError, match=r"missing input file .*das3\.osim"):
        build_das3_model(d)
    with pytest.raises(ModelInputError, match=r"missing input file .*nowhere\.json"):
        build_das3_model(das3_dir, paths_file=tmp_path / "nowhere.json")


def test_paths_lacking_an_element_are_refused(das3_dir, tmp_path):
    data = json.loads(DAS3_PATHS.read_text())
    data["elements"] = [e for e in data["elements"] if e["name"] != "serrant7"]
    bad = tmp_path / "das3_paths.json"
    bad.write_text(json.dumps(data))
    with pytest.raises(ModelInputError, match=r"missing \['serrant7'\], not in model_struct.mat none"):
        build_das3_model(das3_dir, paths_file=bad)
    data = json.loads(DAS3_PATHS.read_text())
    data["elements"].append(dict(data["elements"][0], name="trapscap99"))
    bad.write_text(json.dumps(data))
    with pytest.raises(ModelInputError, match=r"not in model_struct.mat \['trapscap99'\]"):
        build_das3_model(das3_dir, paths_file=bad)
    data = json.loads(DAS3_PATHS.read_text())
    data["elements"][0]["gh_direction"] = data["elements"][40]["gh_direction"]
    bad.write_text(json.dumps(data))
    with pytest.raises(ModelInputError, match="trapscap1.*has a gh_direction"):
        read_paths(bad, src.read_model_struct(das3_dir / "model_struct.mat"))


def test_das3_call_refuses_other_options(das3_dir, tmp_path):
    mat = das3_dir / "model_struct.mat"
    with pytest.raises(ModelInputError, match="--paths opensim: das3 takes its paths"):
        import_any(mat, FREE.split(","), tmp_path / "x.json", paths="opensim")
    with pytest.raises(ModelInputError, match="--name: .* is das3"):
        import_any(mat, FREE.split(","), tmp_path / "x.json", name="shoulder")
    assert not (tmp_path / "x.json").exists()
