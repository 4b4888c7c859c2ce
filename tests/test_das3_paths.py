"""das3 muscle paths: the girdle-and-arm region (codegen/importers/das3_rom.py), the 11-DOF OpenSim sampler and
scoring (codegen/importers/das3_paths.py)."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import DAS3, ROOT
from codegen.importers import das3_paths as dp
from codegen.importers.das3_chain import DAS3_DOFS


@pytest.fixture(scope="module")
def rom():
    if not (DAS3 / "model_struct.mat").exists():
        pytest.skip(f"DAS3 reference data not found at {DAS3}")
    from codegen.importers.das3_rom import Das3Rom
    return Das3Rom(DAS3, n_grid=16)


def test_crossed_dofs_follow_the_serial_chain():
    assert dp.crossed_dofs(["thorax", "clavicle_r"]) == ["SCy", "SCz", "SCx"]
    assert dp.crossed_dofs(["thorax", "scapula_r", "thorax"]) == DAS3_DOFS[:6]
    assert dp.crossed_dofs(["clavicle_r", "humerus_r", "humerus_r"]) == DAS3_DOFS[3:9]
    assert dp.crossed_dofs(["scapula_r", "radius_r"]) == DAS3_DOFS[6:]
    assert dp.crossed_dofs(["radius_r", "hand_r"]) == []      # the wrist is a weld
    assert dp.crossed_dofs(["ground", "humerus_r"]) == DAS3_DOFS[:9]


def test_polynomial_moment_arms_are_minus_the_gradient():
    rng = np.random.default_rng(1)
    exps = [[0, 0], [1, 0], [0, 2], [1, 1], [3, 1]]
    coefs = rng.normal(0, 0.05, 5)
    q = rng.uniform(-1, 1, (6, 11))
    ma = dp.polynomial_moment_arms(exps, coefs, ["SCz", "GHyy"], q)
    from codegen.polynomial import evaluate
    h = 1e-6
    for j, d in enumerate(DAS3_DOFS):
        e = np.zeros(11)
        e[j] = h
        fd = -(evaluate(exps, coefs, (q + e)[:, [1, 8]]) - evaluate(exps, coefs, (q - e)[:, [1, 8]])) / (2 * h)
        np.testing.assert_allclose(ma[:, j], fd, atol=1e-8)
    assert np.all(ma[:, [0, 2, 3, 4, 5, 6, 7, 9, 10]] == 0)


def test_score_applies_the_paper_criterion():
    q = np.zeros((4, 11))
    cross = np.zeros((2, 11), bool)
    cross[0, [6, 7]] = True
    cross[1, 9] = True
    ma = np.full((4, 2, 11), np.nan)
    ma[:, 0, 6], ma[:, 0, 7] = [0.05, 0.04, 0.03, 0.02], 0.01      # peak 50 mm: criterion 5 mm
    ma[:, 1, 9] = 0.005                                              # peak 5 mm: criterion 2 mm
    samples = {"q": q, "ma": ma, "cross": cross, "names": np.array(["a", "b"])}
    pred = [np.nan_to_num(ma[:, 0]), np.nan_to_num(ma[:, 1])]
    pred[0][1, 7] += 0.0049                                          # inside
    pred[0][2, 6] -= 0.0051                                          # over
    pred[1][3, 9] += 0.0021                                          # over the 2 mm floor
    bad = np.zeros((4, 2), bool)
    bad[3, 1] = True                                                 # ... but a wrap jump: excluded
    a, b = dp.score(samples, pred, bad)
    assert (a["criterion_m"], a["n_over"], a["pass"], a["worst_dof"]) == (pytest.approx(0.005), 1, False, "GHy")
    assert (b["criterion_m"], b["n_over"], b["pass"], b["n_wrap_jumps"], b["n_scored"]) == (0.002, 0, True, 1, 3)


def test_rhythm_path_keeps_contact_and_rotates_the_scapula_upward(rom):
    from codegen.importers.das3_rom import RHYTHM
    geo = rom.geo
    rest_f = geo.contact_f(rom.rest[:6])
    for g in rom.path:
        np.testing.assert_allclose(geo.contact_f(g), rest_f, atol=2e-4)
    # through the resting posture at the resting elevation
    np.testing.assert_allclose(rom.girdle_on_path(rom.rest[7]), rom.rest[:6], atol=2e-3)
    # the scapula turns about its plane normal by RHYTHM per rad of GHz, and AI moves laterally
    z0, z1 = 0.6, 0.7
    R0, _ = geo.scapula(rom.girdle_on_path(z0))
    R1, _ = geo.scapula(rom.girdle_on_path(z1))
    W = R0.T @ R1
    angle = np.arctan2(geo.normal @ np.array([W[2, 1] - W[1, 2], W[0, 2] - W[2, 0], W[1, 0] - W[0, 1]]) / 2,
                       (np.trace(W) - 1) / 2)
    assert abs(angle) == pytest.approx(RHYTHM * (z1 - z0), rel=0.05)
    ai0 = geo.scapula(rom.girdle_on_path(z0))
    ai1 = geo.scapula(rom.girdle_on_path(z1))
    assert (ai1[1] + ai1[0] @ geo.ai)[0] > (ai0[1] + ai0[0] @ geo.ai)[0]


def test_samples_stay_in_the_region(rom):
    from codegen.importers.das3_rom import ARM_DOFS, ARM_ROM, GIRDLE_DOFS
    P = rom.sample(32, 3)
    np.testing.assert_array_equal(P, rom.sample(32, 3))             # reproducible by seed
    for j, d in enumerate(GIRDLE_DOFS):
        assert np.all(P[:, j] >= rom.girdle_range[d][0]) and np.all(P[:, j] <= rom.girdle_range[d][1])
    for j, d in enumerate(ARM_DOFS):
        assert np.all(P[:, 6 + j] >= ARM_ROM[d][0]) and np.all(P[:, 6 + j] <= ARM_ROM[d][1])
    # near the path, not spread over the girdle box: within 4 scatter SDs of the path in every DOF
    dev = P[:, :6] - rom.girdle_on_path(P[:, 7])
    assert np.abs(dev).max() < 4 * 0.05 + 1e-9
    f = np.array([rom.geo.contact_f(p[:6]) for p in P])
    assert f.min() > -0.15 and f.max() < 0.1                        # TS and AI within ~5 mm of the thorax


@pytest.mark.opensim
def test_sampler_against_opensim_length_derivative(rom):
    pytest.importorskip("opensim", reason="opensim (pip install opensim) is not installed")
    els = [{"name": "trapclav1", "osim_name": "trap_clav_1"}, {"name": "serrant1", "osim_name": "serr_ant_1"},
           {"name": "bicl", "osim_name": "bic_l"}]
    from codegen.importers.das3_source import read_model_struct
    osim_names = {e.name: e.osim_name for e in read_model_struct(DAS3 / "model_struct.mat").elements}
    for e in els:
        e["osim_name"] = osim_names[e["name"]]
    s = dp.sample_poses(DAS3 / "das3.osim", els, rom.sample(4, 9), processes=1)
    assert [list(np.array(DAS3_DOFS)[c]) for c in s["cross"]] == [DAS3_DOFS[:3], DAS3_DOFS[:6], DAS3_DOFS[6:]]
    for k in range(3):
        c = s["cross"][k]
        np.testing.assert_allclose(s["ma"][:, k, c], s["ma_fd"][:, k, c], atol=2e-3)
        assert np.all(np.isnan(s["ma"][:, k, ~c]))
    assert np.all((s["length"] > 0.05) & (s["length"] < 0.6))


PATHS = ROOT / "models" / "das3_paths.json"
# Bounds for the committed paths on a fresh 32-pose sample of the kinematic fit region (seed 987). Achieved
# after the term re-selection over das3's simulated motions (codegen/importers/das3_refit_simulated.py --reselect):
# 126 of 138 elements meet the criterion at every scored pose, 1.02% of element-poses over it (stop 11's
# coefficient-only refit: 111, 1.52%). About 1.5x the achieved fraction, 7 elements of slack.
MIN_FRESH_PASSING = 119
MAX_FRESH_OVER = 0.016
# On 41 poses of a das3 simulation the refit never saw (below): achieved 125 of 138 elements at every pose,
# 1.48% of element-poses over the criterion (stop 11, before the re-selection: 86, 6.5%).
MIN_SIMULATED_PASSING = 118
MAX_SIMULATED_OVER = 0.023
# GH lines of action on those poses: achieved RMS 1.82 deg over the 67 GH-crossing elements (worst 4.1), x 1.5.
BOUND_UNSEEN_DIRECTION_RMS_DEG = 2.7


@pytest.fixture(scope="module")
def fitted():
    if not PATHS.exists():
        pytest.skip(f"{PATHS} not present")
    import json
    return json.loads(PATHS.read_text())


def test_fitted_paths_file_is_consistent(fitted):
    assert fitted["schema"] == "armrt-das3-paths" and fitted["schema_version"] == 1
    assert fitted["dofs"] == DAS3_DOFS and len(fitted["elements"]) == 138
    joints = [DAS3_DOFS[0:3], DAS3_DOFS[3:6], DAS3_DOFS[6:9], DAS3_DOFS[9:10], DAS3_DOFS[10:11]]
    for e in fitted["elements"]:
        lp = e["length_poly"]
        # the DOFs of consecutive whole joints, as the serial chain gives
        spans = [j for j in joints if set(j) & set(e["dofs"])]
        assert e["dofs"] == [d for j in spans for d in j] and spans == joints[joints.index(spans[0]):][:len(spans)]
        assert lp["dofs"] == e["dofs"]
        E = np.asarray(lp["exponents"])
        assert E.shape == (len(lp["coefs"]), len(e["dofs"])) and E.min() >= 0 and E.sum(axis=1).max() <= 16
        f = e["fit"]
        assert f["pass"] == (f["max_err_m"] < f["criterion_m"]) and f["pass"] == (f["n_over"] == 0)


def score_against_opensim(fitted, poses, label):
    """(elements meeting the criterion at every pose, fraction of element-poses over it) of the committed
    paths against OpenSim's geometry at poses (n, 11); checks each element's DOFs on the way."""
    from codegen.importers import opensim_geometry as og
    els = [{"name": e["name"], "osim_name": e["osim_name"]} for e in fitted["elements"]]
    s = dp.sample_poses(DAS3 / "das3.osim", els, poses, processes=2)
    for k, e in enumerate(fitted["elements"]):
        assert [d for d, c in zip(DAS3_DOFS, s["cross"][k]) if c] == e["dofs"], e["name"]
    pred = [dp.polynomial_moment_arms(e["length_poly"]["exponents"], e["length_poly"]["coefs"], e["dofs"], s["q"])
            for e in fitted["elements"]]
    stats = dp.score(s, pred, og.wrap_jumps(s))
    n_pass = sum(st["pass"] for st in stats)
    over = sum(st["n_over"] for st in stats) / sum(st["n_scored"] for st in stats)
    print(f"{label}: {n_pass}/138 pass, {100 * over:.2f}% element-poses over")
    return n_pass, over


@pytest.mark.opensim
def test_fitted_paths_against_a_fresh_opensim_sample(fitted, rom):
    """The committed fits on poses neither fitted nor scored before (seed 987): the bounds of
    docs/das3_path_accuracy.md with slack for the smaller sample."""
    pytest.importorskip("opensim", reason="opensim (pip install opensim) is not installed")
    n_pass, over = score_against_opensim(fitted, rom.sample(32, 987), "fresh sample")
    assert n_pass >= MIN_FRESH_PASSING and over <= MAX_FRESH_OVER


@pytest.mark.opensim
def test_fitted_paths_on_a_das3_simulation_they_never_saw(fitted):
    """Poses from das3 itself (an abduction ramp at 60 % of the refit's protocol, from the settled arm; the
    refit trained at 100 %, stopped its term selection at 85 % and scored at 70 %), where the girdle sits
    outside the kinematic fit region: the refit over simulated motions holds there."""
    pytest.importorskip("opensim", reason="opensim (pip install opensim) is not installed")
    import armrt
    from codegen.importers.das3_simulated_poses import PROTOCOLS, ramp
    arm = armrt.Arm(model="das3")
    arm.settle()
    q = arm.simulate(ramp(arm.model, PROTOCOLS[0][1], 0.6), 2.0, record_every=50).q
    n_pass, over = score_against_opensim(fitted, q, "simulated poses")
    assert n_pass >= MIN_SIMULATED_PASSING and over <= MAX_SIMULATED_OVER


def test_gh_directions_in_the_paths_file(fitted):
    gh = [e for e in fitted["elements"] if "GHy" in e["dofs"]]
    assert len(gh) == 67                                   # as in das2: the girdle-only muscles do not cross GH
    assert all("gh_direction" not in e for e in fitted["elements"] if "GHy" not in e["dofs"])
    rms = []
    for e in gh:
        gd = e["gh_direction"]
        assert gd["dofs"] == e["dofs"]
        assert gd["x"]["exponents"] == gd["y"]["exponents"] == gd["z"]["exponents"]
        assert len(gd["x"]["coefs"]) <= 8
        rms.append(e["fit"]["direction"]["rms_deg"])
    # achieved 2.20 deg overall on the kinematic test poses (docs/das3_path_accuracy.md); das2: 2.04
    assert np.sqrt(np.mean(np.square(rms))) < 2.8
    # fitted over das3's simulated motions too (codegen.importers.das3_directions --with-simulated): 1.51 deg there
    sim = [e["fit"]["direction"]["simulated"]["rms_deg"] for e in gh]
    assert np.sqrt(np.mean(np.square(sim))) < 2.3


@pytest.mark.opensim
def test_gh_directions_on_a_das3_simulation_they_never_saw(fitted, tmp_path):
    """The GH lines of action against OpenSim's at poses of a das3 run neither fit saw (the 60 % abduction
    ramp of test_fitted_paths_on_a_das3_simulation_they_never_saw), in the moving scapula frame."""
    pytest.importorskip("opensim", reason="opensim (pip install opensim) is not installed")
    import armrt
    from codegen.importers import fit_paths as fp
    from codegen.importers.das3_directions import direction_stats, sample_directions
    from codegen.importers.das3_simulated_poses import PROTOCOLS, ramp
    arm = armrt.Arm(model="das3")
    arm.settle()
    q = arm.simulate(ramp(arm.model, PROTOCOLS[0][1], 0.6), 2.0, record_every=50).q
    gh = [e for e in fitted["elements"] if "GHy" in e["dofs"]]
    d = sample_directions(DAS3 / "das3.osim", [e["osim_name"] for e in gh], q, tmp_path, "unseen", processes=2)
    rms = [direction_stats(e["gh_direction"], q, d[:, k])["rms_deg"] for k, e in enumerate(gh)]
    overall = float(np.sqrt(np.mean(np.square(rms))))
    print(f"GH directions on unseen simulated poses: overall RMS {overall:.2f} deg, worst {max(rms):.1f} deg")
    assert overall < BOUND_UNSEEN_DIRECTION_RMS_DEG


@pytest.mark.opensim
def test_direction_sampler_matches_the_das2_sampler_with_the_girdle_at_rest(rom):
    """At the resting girdle the moving-scapula directions equal das2's fixed-scapula ones."""
    pytest.importorskip("opensim", reason="opensim (pip install opensim) is not installed")
    from codegen.importers import opensim_geometry as og
    from codegen.importers.das3_directions import DirectionSampler
    names = ["delt_scap_5", "lat_dorsi_1"]
    girdle = dict(zip(["SC_y", "SC_z", "SC_x", "AC_y", "AC_z", "AC_x"], rom.rest[:6]))
    old = og._Sampler(str(DAS3 / "das3.osim"), girdle, names, np.ones((2, 5), bool), np.ones(2, bool))
    new = DirectionSampler(DAS3 / "das3.osim", names)
    for arm in ([0.4, 0.6, 0.2, 0.7, 1.4], [0.9, 1.3, -0.2, 1.5, 0.5]):
        old._set(np.array(arm))
        d_old = np.array([old._direction(k) for k in range(2)])
        np.testing.assert_allclose(new.sample(np.concatenate([rom.rest[:6], arm])), d_old, atol=1e-12)


def test_fit_element_handles_girdle_dof_counts():
    """A 9-DOF element (SC, AC, GH, as latissimus dorsi) from a known smooth length: the fit meets the
    criterion on validation poses, with the budgets das3_fit adds for more than 5 DOFs."""
    from codegen.importers import das3_fit
    rng = np.random.default_rng(2)
    cols = np.zeros(11, bool)
    cols[:9] = True

    def length(q):
        x = q[:, :9]
        return 0.25 + 0.03 * np.sin(x[:, 0] + 0.5 * x[:, 6]) + 0.02 * x[:, 1] * x[:, 7] - 0.01 * x[:, 4] ** 2

    def sample(n):
        q = rng.uniform(-0.5, 0.5, (n, 11))
        h = 1e-6
        ma = np.full((n, 1, 11), np.nan)
        for j in np.flatnonzero(cols):
            e = np.zeros(11)
            e[j] = h
            ma[:, 0, j] = -(length(q + e) - length(q - e)) / (2 * h)
        return {"q": q, "length": length(q)[:, None], "ma": ma, "cross": cols[None, :]}

    s_tr, s_va = sample(600), sample(300)
    no_jumps = np.zeros((600, 1), bool), np.zeros((300, 1), bool)
    fit = das3_fit.fit_element(0, s_tr, s_va, *no_jumps)
    assert fit["dofs"] == DAS3_DOFS[:9] and len(fit["coefs"]) <= das3_fit.EXTRA_EXT_TERMS[9]
    s_te = sample(200)
    pred = dp.polynomial_moment_arms(fit["exponents"], fit["coefs"], fit["dofs"], s_te["q"])
    err = np.abs(pred[:, :9] - s_te["ma"][:, 0, :9]).max()
    assert err < max(0.1 * np.abs(s_te["ma"][:, 0, :9]).max(), 2e-3)


def test_compiled_das3_paths_equal_the_paths_file(fitted):
    """The generated das3 muscle_paths (4-lane vectors per group of three DOFs; codegen/paths_emitter.py
    _grouped_paths) against the polynomials of models/das3_paths.json evaluated in numpy, at random poses."""
    armrt = pytest.importorskip("armrt", reason="armrt is not built")
    m = armrt.Model("das3")
    rng = np.random.default_rng(5)
    lo, hi = m.dof_ranges.T
    q = lo + (hi - lo) * rng.random((200, 11))
    L, R = m.muscle_lengths(q), m.moment_arms(q)
    assert L.shape == (200, 138) and R.shape == (200, 138, 11)
    for k, e in enumerate(fitted["elements"]):
        lp = e["length_poly"]
        idx = [DAS3_DOFS.index(d) for d in lp["dofs"]]
        E, c = np.asarray(lp["exponents"]), np.asarray(lp["coefs"])
        L_ref = (np.prod(q[:, None, idx] ** E[None], axis=2) * c).sum(axis=1)
        R_ref = dp.polynomial_moment_arms(lp["exponents"], lp["coefs"], lp["dofs"], q)
        np.testing.assert_allclose(L[:, k], L_ref, rtol=1e-12, atol=1e-14, err_msg=e["name"])
        np.testing.assert_allclose(R[:, k], R_ref, rtol=1e-10, atol=1e-13, err_msg=e["name"])
        assert np.all(R[:, k, [j for j in range(11) if j not in idx]] == 0.0), e["name"]
