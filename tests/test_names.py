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


# ---------------------------------------------------------------- one rule for overlapping names (issue 25)
def _cuff_groups():
    infra = list(_core.find_elements("das2", "infra"))
    supra = list(_core.find_elements("das2", "supra"))
    return infra, supra


def test_the_rule_most_specific_wins_equal_specificity_takes_the_largest():
    infra, supra = _cuff_groups()
    for items in ([("rotator_cuff", 0.05), ("infra", 0.3)], [("infra", 0.3), ("rotator_cuff", 0.05)]):
        u = _core.excitations_from_names("das2", items)
        assert all(u[i] == 0.3 for i in infra) and all(u[i] == 0.05 for i in supra)
    # element over muscle, in either order
    one = _core.model_info("das2")["elements"][infra[0]]["name"]
    for items in ([("infra", 0.3), (one, 0.1)], [(one, 0.1), ("infra", 0.3)]):
        u = _core.excitations_from_names("das2", items)
        assert u[infra[0]] == 0.1 and u[infra[1]] == 0.3
    # two groups sharing elements: the larger value, in either order
    groups = dict(_core.model_info("das2")["groups"])
    a, b = next((g, h) for g in groups for h in groups if g < h and set(groups[g]) & set(groups[h]))
    shared = sorted(set(groups[a]) & set(groups[b]))[0]
    for items in ([(a, 0.2), (b, 0.7)], [(b, 0.7), (a, 0.2)]):
        assert _core.excitations_from_names("das2", items)[shared] == 0.7
    with pytest.raises(KeyError, match="'infrx'.*did you mean"):
        _core.excitations_from_names("das2", [("infrx", 0.1), ("infra", 0.2)])


def test_arm_and_armbatch_follow_the_rule_in_either_order():
    import armrt
    infra, supra = _cuff_groups()
    arm = armrt.Arm()
    batch = armrt.ArmBatch(2)
    for u in ({"rotator_cuff": 0.05, "infra": 0.3}, {"infra": 0.3, "rotator_cuff": 0.05}):
        arm.set_excitation(u)
        assert all(arm.excitation[i] == 0.3 for i in infra) and all(arm.excitation[i] == 0.05 for i in supra)
        batch.set_excitation(u)
        assert (batch.excitation[:, infra] == 0.3).all() and (batch.excitation[:, supra] == 0.05).all()
    # the order that used to give 0.05 for infra ("last wins") now gives 0.3 too; unknown names are named
    with pytest.raises(KeyError, match="infrx"):
        arm.set_excitation({"infrx": 0.1})
    with pytest.raises(KeyError, match="infrx"):
        batch.set_excitation({"infrx": 0.1})


def test_several_unknown_names_are_counted_first_and_another_case_is_suggested():
    """"unknown element, muscle or group 2 names" read garbled; 'BICB' got no suggestion (difflib's ratio is
    case-sensitive)."""
    import armrt
    arm = armrt.Arm()
    with pytest.raises(KeyError) as err:
        arm.set_excitation({"bicepz": 0.3, "tricepz": 0.2})
    assert err.value.args[0].startswith("2 unknown element, muscle or group names: 'bicepz' (did you mean")
    with pytest.raises(KeyError, match=r"unknown element, muscle or group name 'BICB' \(did you mean 'bicb'"):
        arm.set_excitation({"BICB": 0.3})
    assert _core.close_matches("das2", "Rotator_Cuff")[0] == "rotator_cuff"
    assert _core.close_matches("das2", "elx", dofs=True)[0] == "ELx"
