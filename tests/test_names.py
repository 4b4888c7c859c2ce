"""The engine's name service (cpp/src/names.cc) behind armrt.Arm, the runner, the LSL bridge and the
viewer: its suggestions are difflib's, and every user of names goes through it."""
import difflib

import pytest

from armrt import _core


def _choices(model="das2"):
    info = _core.model_info(model)
    names = [e["name"] for e in info["elements"]] + [m for m, _ in info["muscles"]] + [g for g, _ in info["groups"]]
    aliases = []
    for e in info["elements"]:
        osim = e["osim_name"]
        stem = osim.rstrip("0123456789").rstrip("_")
        for a in (osim, stem):
            if a and a not in names and a not in aliases:
                aliases.append(a)
    return names + aliases


@pytest.mark.parametrize("word", ["bicbb", "tricepz", "delt", "rotatorcuff", "elbow_flex", "supra5", "bic_b",
                                  "delt_scap_12", "x", "pronator", "anconeus9", "pect_maj"])
def test_suggestions_are_difflibs(word):
    assert _core.close_matches("das2", word) == difflib.get_close_matches(word, _choices(), n=3)


def test_dof_suggestions_and_aliases():
    info = _core.model_info("das2")
    dofs = [d["name"] for d in info["dofs"]] + [d["osim_name"] for d in info["dofs"]]
    for word in ("ELy", "GH_x", "ps", "GHyz"):
        assert _core.close_matches("das2", word, dofs=True) == difflib.get_close_matches(word, dofs, n=3)
    assert _core.find_dof("das2", "PS_y") == 4
    with pytest.raises(KeyError, match="unknown DOF 'ELy'; did you mean 'ELx'"):
        _core.find_dof("das2", "ELy")


def test_arm_and_mapping_use_it():
    import armrt
    from armrt.realtime import GroupMapping
    arm = armrt.Arm()
    assert arm.indices("delt_scap") == list(_core.find_elements("das2", "delt_scap"))
    with pytest.raises(KeyError, match=r"unknown element, muscle or group name 'bicbb' \(did you mean 'bicb'"):
        arm.set_excitation({"bicbb": 0.1})
    m = GroupMapping.from_model("channels", "das2", ["bic_b", "triceps"])  # an OpenSim alias as a channel
    assert m.index["bic_b"] == list(_core.find_elements("das2", "bic_b"))
    with pytest.raises(KeyError, match="channels: unknown element, muscle or group name 'tricep' \\(did you mean"):
        GroupMapping.from_model("channels", "das2", ["tricep"])
