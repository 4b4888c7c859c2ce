"""The OpenSim side of the das3 benchmark (bench/bench_opensim_das3.py, issue 15 item 6): das3.osim with
the girdle free and armrt's conoid, scapulothoracic contact and passive joint moments added from stock
OpenSim 4.6 components. Checked: every coordinate unlocked at equilibrium.mat; each added force equals
armrt's law (the C++ header girdle_forces.h, compiled as in test_girdle_forces) at the resting posture,
and acts on the dynamics as the generalised force J^T F (OpenSim's accelerations with and without it,
J by central differences of OpenSim's own point positions); compare_with_armrt on a short run."""
from __future__ import annotations

import numpy as np
import pytest

from test_girdle_forces import build_harness

osim = pytest.importorskip("opensim", reason="OpenSim not installed (pip install opensim)")
bench = pytest.importorskip("bench.bench_opensim_das3")


@pytest.fixture(scope="module")
def lib(tmp_path_factory):
    return build_harness(tmp_path_factory.mktemp("girdle_osim"))


@pytest.fixture(scope="module")
def built(das3_dir):
    m, state, info = bench.build_opensim(das3_dir / "das3.osim")
    return m, state, info


def test_coordinates_unlocked_at_equilibrium(built):
    m, state, info = built
    q0 = bench.equilibrium_q()
    cs = m.getCoordinateSet()
    assert cs.getSize() == 11
    for name, q in zip(bench.DAS3_COORDS, q0):
        c = cs.get(name)
        assert not c.getLocked(state), name
        assert not c.get_clamped(), name
        assert c.getValue(state) == pytest.approx(q, abs=1e-12), name
        assert c.getSpeedValue(state) == 0.0
    assert info["constraints"] == 0
    assert info["n_muscles"] == 138
    assert {"conoid", "scapulothoracic_TS", "scapulothoracic_AI"} <= set(info["added_forces"])
    # the das2 protocol: rotator cuff 0.05, elbow flexors 0.3, by das3.osim muscle name
    assert info["excited_muscles"]["supra_1"] == 0.05 and info["excited_muscles"]["bic_l"] == 0.3


def test_girdle_forces_at_rest_equal_armrt_laws(built, lib):
    m, state, _ = built
    g = bench.girdle_forces_at(m, state)
    # conoid: 29.1 mm against its 17.4 mm slack length, 938 N (docs/das3.md)
    L = g["conoid"]["length_m"]
    assert L == pytest.approx(0.0291, abs=1e-4)
    assert g["conoid"]["tension_N"] == pytest.approx(lib.tension(L)[0], rel=1e-12)
    assert g["conoid"]["tension_N"] == pytest.approx(938.0, abs=0.5)
    # contact: the C++ law at OpenSim's TS / AI positions; 264 N and 218 N at rest
    for label, magnitude in (("TS", 264.1), ("AI", 217.5)):
        p = np.array(g[label]["point_thorax_m"])
        f, F, _ = lib.contact(p)
        assert g[label]["f"] == pytest.approx(f, rel=1e-12)
        np.testing.assert_allclose(g[label]["force_N"], F, rtol=1e-12, atol=1e-9)
        assert np.linalg.norm(F) == pytest.approx(magnitude, abs=0.1)


def _generalised_force(m, state, force_name: str) -> np.ndarray:
    """M (qdd with the force - qdd without it) at zero speed: the force's generalised force (11,)."""
    fs = m.getForceSet()

    def qdd():
        m.realizeAcceleration(state)
        return np.array([m.getCoordinateSet().get(n).getAccelerationValue(state) for n in bench.DAS3_COORDS])

    with_force = qdd()
    fs.get(force_name).setAppliesForce(state, False)
    without = qdd()
    fs.get(force_name).setAppliesForce(state, True)
    m.realizePosition(state)
    M = osim.Matrix()
    m.getMatterSubsystem().calcM(state, M)
    M = np.array([[M.get(i, j) for j in range(11)] for i in range(11)])
    return M @ (with_force - without)


def _point_jacobian(m, state, body: str, point) -> np.ndarray:
    """d(point in ground)/dq (3, 11) by central differences of OpenSim's station positions."""
    b = m.getBodySet().get(body)
    cs = m.getCoordinateSet()
    h = 1e-7
    J = np.zeros((3, 11))
    for j, name in enumerate(bench.DAS3_COORDS):
        c = cs.get(name)
        q = c.getValue(state)
        pos = []
        for sign in (1, -1):
            c.setValue(state, q + sign * h, False)
            m.realizePosition(state)
            v = b.findStationLocationInGround(state, osim.Vec3(*point))
            pos.append(np.array([v.get(i) for i in range(3)]))
        c.setValue(state, q, False)
        J[:, j] = (pos[0] - pos[1]) / (2 * h)
    m.realizePosition(state)
    return J


def test_mobility_order_is_coordinate_order(built):
    """calcM's rows follow DAS3_COORDS (one mobility per CustomJoint, in chain order)."""
    m, state, _ = built
    s = osim.State(state)
    s.updQ().set(0, 0.123)   # the first mobility
    s.updQ().set(10, 0.456)  # the last
    m.realizePosition(s)
    cs = m.getCoordinateSet()
    assert cs.get("SC_y").getValue(s) == 0.123 and cs.get("PS_y").getValue(s) == 0.456


def test_girdle_and_passive_forces_act_as_generalised_forces(built):
    m, state, _ = built
    s = osim.State(state)
    params = bench.das3_parameters()
    R_GT = None
    m.realizePosition(s)
    X = m.getBodySet().get("thorax").getTransformInGround(s)
    R_GT = np.array([[X.R().get(i, j) for j in range(3)] for i in range(3)])
    g = bench.girdle_forces_at(m, s, params)
    for label in ("TS", "AI"):
        J = _point_jacobian(m, s, "scapula_r", params[label])
        expected = J.T @ (R_GT @ np.array(g[label]["armrt_force_N"]))
        tau = _generalised_force(m, s, f"scapulothoracic_{label}")
        np.testing.assert_allclose(tau, expected, rtol=1e-6, atol=1e-6 * np.abs(expected).max())
    Jo = _point_jacobian(m, s, "clavicle_r", params["conoid_origin"])
    Ji = _point_jacobian(m, s, "scapula_r", params["conoid_insertion"])
    m.realizePosition(s)
    to_np = lambda v: np.array([v.get(i) for i in range(3)])  # noqa: E731
    xo = to_np(m.getBodySet().get("clavicle_r").findStationLocationInGround(s, osim.Vec3(*params["conoid_origin"])))
    xi = to_np(m.getBodySet().get("scapula_r").findStationLocationInGround(s, osim.Vec3(*params["conoid_insertion"])))
    u = (xi - xo) / np.linalg.norm(xi - xo)
    F_ins = -g["conoid"]["armrt_tension_N"] * u
    expected = (Ji - Jo).T @ F_ins
    tau = _generalised_force(m, s, "conoid")
    np.testing.assert_allclose(tau, expected, rtol=1e-6, atol=1e-6 * np.abs(expected).max())
    # passive joint moments: only the own coordinate, armrt's law; ACz at rest lies 0.053 rad below its
    # range, so about 14 N m pushes it back (docs/das3.md)
    pj = bench.passive_joints(m)
    for j, name in enumerate(bench.DAS3_COORDS):
        rest, lo, hi = pj["dofs"][name]
        q = m.getCoordinateSet().get(name).getValue(s)
        e = max(q - hi, 0.0) + min(q - lo, 0.0)
        want = -pj["stiffness_inside"] * (q - rest) - pj["stiffness_outside"] * e * abs(e)
        tau = _generalised_force(m, s, f"passive_{name}")
        assert tau[j] == pytest.approx(want, rel=1e-9, abs=1e-9), name
        assert np.abs(np.delete(tau, j)).max() < 1e-9 * max(abs(want), 1.0), name
    if pj["source"].startswith("fallback"):  # das3.osim's ACz range: rest lies 0.053 rad below it
        j = bench.DAS3_COORDS.index("AC_z")
        assert _generalised_force(m, s, "passive_AC_z")[j] == pytest.approx(14.25, abs=0.05)


def test_parameters_agree_with_models_das3(das3_dir):
    """The girdle forces added to OpenSim (model_struct.mat) are the ones armrt's das3 model file holds,
    and the passive joint law is taken from that file (or the registered model built from it)."""
    import json

    if not bench.DAS3_JSON.exists():
        pytest.skip("models/das3.json not there")
    gf = json.loads(bench.DAS3_JSON.read_text())["girdle_forces"]
    p = bench.das3_parameters(das3_dir / "model_struct.mat")
    assert gf["thorax_ellipsoid"]["centre"] == p["thorax_center"]
    assert gf["thorax_ellipsoid"]["radii"] == p["thorax_radii"]
    assert (gf["contact"]["stiffness"], gf["contact"]["eps"]) == (p["scap_thorax_k"], p["scap_thorax_eps"])
    assert {c["name"]: c["point"] for c in gf["contact"]["points"]} == {"TS": p["TS"], "AI": p["AI"]}
    con = gf["conoid"]
    assert (con["origin"]["body"], con["insertion"]["body"]) == ("clavicle", "scapula")
    assert (con["origin"]["point"], con["insertion"]["point"]) == (p["conoid_origin"], p["conoid_insertion"])
    assert (con["length"], con["stiffness"], con["eps"]) == (p["conoid_length"], p["conoid_stiffness"], p["conoid_eps"])
    assert not bench.passive_joints()["source"].startswith("fallback")


def test_expressions_parse_the_exact_parameters():
    p = bench.das3_parameters()
    assert "80000.0*((d-0.0174)" in bench.conoid_expression(p)
    fx = bench.contact_expressions(p)[0]
    assert "delta_x/0.147" in fx and "0.01^2" in fx


def test_compare_with_armrt_das2_short(das3_dir):
    """The comparison's code path on das2's 5 arm coordinates (10 ms): same start, finite, mapped by name."""
    armrt = pytest.importorskip("armrt", reason="armrt is not built/installed")
    run = bench.run_opensim(0.01, None, das3_dir / "das3.osim")
    assert run["error"] is None
    assert run["q_grid"].shape == (11, 11) and np.isfinite(run["q_grid"]).all()
    cmp = bench.compare_with_armrt(lambda: armrt.Arm(model="das2"), 0.01, opensim_run=run, reps=1)
    assert cmp["coordinates"] == ["GH_y", "GH_z", "GH_yy", "EL_x", "PS_y"]
    assert cmp["q_armrt"].shape == cmp["q_opensim"].shape == (11, 5)
    np.testing.assert_allclose(cmp["q_armrt"][0], cmp["q_opensim"][0], atol=1e-12)   # same posture
    np.testing.assert_allclose(cmp["q_opensim"][0], bench.equilibrium_q()[6:], atol=1e-12)
    assert np.isfinite(cmp["q_armrt"]).all() and cmp["speed_ratio"] > 0
    # the same 37 elements excited on both sides (armrt got them by das3.osim name)
    _, exc = bench.das2_stimulation()
    arm = armrt.Arm(model="das2")
    assert cmp["armrt_excited_elements"] == sorted(arm.element_names[arm.indices(n)[0]] for n in exc)
    assert len(exc) == 37


@pytest.mark.slow
def test_compare_with_armrt_das3(das3_dir):
    """All 11 coordinates against armrt's das3 (50 ms), once Arm(model="das3") exists."""
    armrt = pytest.importorskip("armrt", reason="armrt is not built/installed")
    try:
        armrt.Arm(model="das3")
    except Exception as exc:  # noqa: BLE001
        pytest.skip(f"armrt has no das3 model yet ({exc})")
    run = bench.run_opensim(0.05, None, das3_dir / "das3.osim")
    cmp = bench.compare_with_armrt(lambda: armrt.Arm(model="das3"), 0.05, opensim_run=run, reps=1)
    assert cmp["coordinates"] == bench.DAS3_COORDS
    np.testing.assert_allclose(cmp["q_armrt"][0], cmp["q_opensim"][0], atol=1e-12)
    assert np.isfinite(cmp["q_armrt"]).all() and np.isfinite(cmp["q_opensim"]).all()
