"""The generated dynamics and paths against an independent Newton-Euler reference, OpenSim, and physics."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from gen_lib import ROOT, gen_model  # noqa: F401 (fixture)
from newton_euler import ArmReference

OSIM_PATH = ROOT.parent / "shared" / "reference" / "das3" / "das3.osim"
RTOL = 1e-9


def rel_err(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return float(np.max(np.abs(a - b)) / max(np.max(np.abs(b)), 1e-300))


def random_states(model, n, seed):
    rng = np.random.default_rng(seed)
    lo = np.array([d["range"][0] for d in model["dofs"]])
    hi = np.array([d["range"][1] for d in model["dofs"]])
    for _ in range(n):
        yield rng.uniform(lo, hi), rng.uniform(-4.0, 4.0, 5), rng.uniform(-20.0, 20.0, 5), rng.normal(0, 10.0, 3)


@pytest.fixture(scope="module")
def ref(gen_model):
    return ArmReference(gen_model.model)


def test_mass_matrix_and_bias_vs_newton_euler(gen_model, ref):
    worst = {"M": 0.0, "b": 0.0}
    for q, qd, _, g in random_states(gen_model.model, 50, 1):
        M = gen_model.mass_matrix(q)
        worst["M"] = max(worst["M"], rel_err(M, ref.mass_matrix(q)))
        np.testing.assert_array_equal(M, M.T)
        assert np.all(np.linalg.eigvalsh(M) > 0)
        worst["b"] = max(worst["b"], rel_err(gen_model.bias_force(q, qd, g), ref.bias_force(q, qd, g)))
        gs = gen_model.gravity_base()
        worst["b"] = max(worst["b"], rel_err(gen_model.bias_force(q, qd, gs), ref.bias_force(q, qd, gs)))
    print(f"max relative error vs Newton-Euler: {worst}")
    assert worst["M"] < RTOL and worst["b"] < RTOL


def test_bias_splits_into_gravity_and_velocity_terms(gen_model):
    for q, qd, _, g in random_states(gen_model.model, 10, 2):
        b = gen_model.bias_force(q, qd, g)
        bg = gen_model.bias_force(q, np.zeros(5), g)
        bv = gen_model.bias_force(q, qd, np.zeros(3))
        np.testing.assert_allclose(b, bg + bv, rtol=0, atol=1e-12 * np.max(np.abs(b)))
        # velocity terms are quadratic in qd
        np.testing.assert_allclose(gen_model.bias_force(q, 2 * qd, np.zeros(3)), 4 * bv, rtol=1e-12, atol=1e-14)


def test_kinematics_vs_newton_euler(gen_model, ref):
    for q, _, _, _ in random_states(gen_model.model, 30, 3):
        R, p = gen_model.body_poses(q)
        Rr, pr = ref.body_poses(q)
        np.testing.assert_allclose(R, Rr, rtol=0, atol=1e-13)
        np.testing.assert_allclose(p, pr, rtol=0, atol=1e-13)
        np.testing.assert_allclose(gen_model.hand_position(q), ref.hand_position(q), rtol=0, atol=1e-13)
        for Rb in R:
            np.testing.assert_allclose(Rb @ Rb.T, np.eye(3), atol=1e-13)
            assert np.linalg.det(Rb) == pytest.approx(1.0, abs=1e-13)


def test_hand_jacobian_vs_finite_differences(gen_model, ref):
    h = 1e-6
    hand = gen_model.model["bodies"].index(next(b for b in gen_model.model["bodies"]
                                                 if b["name"] == gen_model.model["hand_point"]["body"]))
    for q, _, _, _ in random_states(gen_model.model, 10, 4):
        Jv, Jw = gen_model.hand_jacobian(q)
        for j in range(5):
            dq = np.zeros(5)
            dq[j] = h
            dp = (ref.hand_position(q + dq) - ref.hand_position(q - dq)) / (2 * h)
            np.testing.assert_allclose(Jv[:, j], dp, rtol=0, atol=1e-8)
            Rp, Rm = ref.body_poses(q + dq)[0][hand], ref.body_poses(q - dq)[0][hand]
            W = (Rp - Rm) / (2 * h) @ ref.body_poses(q)[0][hand].T    # skew(omega)
            np.testing.assert_allclose(Jw[:, j], [W[2, 1], W[0, 2], W[1, 0]], rtol=0, atol=1e-8)


def test_arm_momentum_rate_vs_newton_euler(gen_model, ref):
    masses = ref.masses()
    for q, qd, qdd, _ in random_states(gen_model.model, 20, 5):
        A, c = gen_model.arm_momentum_rate(q, qd)
        acc = ref.com_accelerations(q, qd, qdd)
        expect = sum(masses[b] * acc[b] for b in acc)
        assert rel_err(A @ qdd + c, expect) < RTOL


def _numpy_poly(poly, dofs, q, dof_index):
    e = np.asarray(poly["exponents"], dtype=int).reshape(len(poly["coefs"]), -1)
    qs = np.array([q[dof_index[d]] for d in dofs])
    return float(np.sum(np.asarray(poly["coefs"]) * np.prod(qs[None, :] ** e, axis=1)))


def test_muscle_lengths_vs_model_polynomials(gen_model):
    m = gen_model.model
    dof_index = {d["name"]: i for i, d in enumerate(m["dofs"])}
    for q, _, _, _ in random_states(m, 10, 6):
        L = gen_model.muscle_lengths(q)
        L2, _ = gen_model.muscle_paths(q)
        np.testing.assert_array_equal(L, L2)
        expect = [_numpy_poly(e["length_poly"], e["length_poly"]["dofs"], q, dof_index) for e in m["elements"]]
        np.testing.assert_allclose(L, expect, rtol=1e-12, atol=1e-14)


def test_moment_arms_vs_finite_differences(gen_model):
    m = gen_model.model
    h = 1e-6
    for q, _, _, _ in random_states(m, 10, 7):
        _, r = gen_model.muscle_paths(q)
        for j in range(5):
            dq = np.zeros(5)
            dq[j] = h
            fd = -(gen_model.muscle_lengths(q + dq) - gen_model.muscle_lengths(q - dq)) / (2 * h)
            np.testing.assert_allclose(r[:, j], fd, rtol=0, atol=1e-8)
        for i in range(gen_model.nel):
            for j in range(5):
                if not gen_model.lib.h_element_dof_mask(i) >> j & 1:
                    assert r[i, j] == 0.0


def test_gh_directions_are_normalised_polynomials(gen_model):
    m = gen_model.model
    dof_index = {d["name"]: i for i, d in enumerate(m["dofs"])}
    for q, _, _, _ in random_states(m, 10, 8):
        d = gen_model.gh_directions(q)
        for i, e in enumerate(m["elements"]):
            gd = e["gh_direction"]
            if gd is None:
                assert np.all(d[i] == 0.0)
                continue
            v = np.array([_numpy_poly(gd[c], gd["dofs"], q, dof_index) for c in "xyz"])
            np.testing.assert_allclose(d[i], v / np.linalg.norm(v), rtol=0, atol=1e-13)


def _energy(gen_model, ref, q, qd, g):
    M = gen_model.mass_matrix(q)
    coms = ref.com_positions(q)
    masses = ref.masses()
    return 0.5 * qd @ M @ qd - sum(masses[b] * g @ coms[b] for b in coms)


def test_energy_conservation_passive_pendulum(gen_model, ref):
    """Muscle-free, undamped arm under gravity: RK4 on M qdd = b conserves kinetic + potential energy."""
    g = gen_model.gravity_base()

    def f(x):
        q, qd = x[:5], x[5:]
        return np.concatenate([qd, np.linalg.solve(gen_model.mass_matrix(q), gen_model.bias_force(q, qd, g))])

    x = np.concatenate([[0.4, 0.9, -0.5, 1.2, 1.0], [1.0, -0.5, 2.0, -1.5, 3.0]])
    dt, T = 2.5e-4, 2.0
    e0 = _energy(gen_model, ref, x[:5], x[5:], g)
    drift = 0.0
    scale = abs(e0) + 0.5 * x[5:] @ gen_model.mass_matrix(x[:5]) @ x[5:]
    for _ in range(int(round(T / dt))):
        k1 = f(x)
        k2 = f(x + 0.5 * dt * k1)
        k3 = f(x + 0.5 * dt * k2)
        k4 = f(x + dt * k3)
        x = x + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        drift = max(drift, abs(_energy(gen_model, ref, x[:5], x[5:], g) - e0))
    print(f"energy drift over {T} s: {drift:.3e} J of {scale:.3e} J (relative {drift / scale:.3e})")
    assert drift / scale < 1e-6


# ----------------------------------------------------------------------------------------------
# OpenSim, the geometry and dynamics oracle

@pytest.fixture(scope="module")
def osim_arm(gen_model):
    osim = pytest.importorskip("opensim", reason="opensim (pip install opensim) is not installed")
    if not OSIM_PATH.exists():
        pytest.skip(f"{OSIM_PATH} not present (../shared/reference/das3)")
    try:
        osim.Logger.setLevelString("error")
    except AttributeError:
        pass
    model = osim.Model(str(OSIM_PATH))
    model.updForceSet().clearAndDestroy()     # muscles off: only gravity acts
    state = model.initSystem()
    coords = model.getCoordinateSet()
    for d in gen_model.model["girdle"]["dofs"]:
        coords.get(d["osim_name"]).setValue(state, d["angle"], False)
        coords.get(d["osim_name"]).setSpeedValue(state, 0.0)
    # mobility (u) index of each of our DOFs
    for i, d in enumerate(gen_model.model["dofs"]):
        coords.get(d["osim_name"]).setSpeedValue(state, 10.0 + i)
    U = state.getU()
    u = np.array([U.get(k) for k in range(U.size())])
    uidx = [int(np.flatnonzero(u == 10.0 + i)[0]) for i in range(5)]
    return osim, model, state, uidx


def _osim_state(osim_arm, dofs, q, qd):
    osim, model, state, uidx = osim_arm
    coords = model.getCoordinateSet()
    for i, d in enumerate(dofs):
        coords.get(d["osim_name"]).setValue(state, float(q[i]), False)
        coords.get(d["osim_name"]).setSpeedValue(state, float(qd[i]))
    model.realizeAcceleration(state)
    return state


def _transform(body, state):
    T = body.getTransformInGround(state)
    R = np.array([[T.R().get(i, j) for j in range(3)] for i in range(3)])
    return R, np.array([T.p().get(i) for i in range(3)])


@pytest.mark.opensim
def test_dynamics_vs_opensim(gen_model, osim_arm):
    osim, model, _, uidx = osim_arm
    m = gen_model.model
    matter = model.getMatterSubsystem()
    worst = {"M": 0.0, "b": 0.0}
    for q, qd, _, _ in random_states(m, 20, 11):
        state = _osim_state(osim_arm, m["dofs"], q, qd)
        Mo = osim.Matrix()
        matter.calcM(state, Mo)
        Mfull = np.array([[Mo.get(i, j) for j in range(Mo.ncol())] for i in range(Mo.nrow())])
        worst["M"] = max(worst["M"], rel_err(gen_model.mass_matrix(q), Mfull[np.ix_(uidx, uidx)]))
        # Forward dynamics under gravity alone with the girdle at rest: M udot = b for every mobility,
        # so the 5 GH..PS rows of M udot are our bias (gravity in ground = thorax).
        UD = state.getUDot()
        udot = np.array([UD.get(k) for k in range(UD.size())])
        b_osim = (Mfull @ udot)[uidx]
        worst["b"] = max(worst["b"], rel_err(gen_model.bias_force(q, qd, gen_model.gravity_base()), b_osim))
        # and OpenSim's inverse-dynamics residual M*0 + C - 0 is minus our velocity terms
        res = osim.Vector()
        matter.calcResidualForceIgnoringConstraints(state, osim.Vector(0, 0.0), osim.VectorOfSpatialVec(),
                                                    osim.Vector(UD.size(), 0.0), res)
        c_osim = np.array([res.get(k) for k in uidx])
        assert rel_err(gen_model.bias_force(q, qd, np.zeros(3)), -c_osim) < RTOL
    print(f"max relative error vs OpenSim: {worst}")
    assert worst["M"] < RTOL and worst["b"] < RTOL


@pytest.mark.opensim
def test_kinematics_vs_opensim(gen_model, osim_arm):
    osim, model, _, _ = osim_arm
    m = gen_model.model
    bodies = model.getBodySet()
    for q, _, _, _ in random_states(m, 10, 12):
        state = _osim_state(osim_arm, m["dofs"], q, np.zeros(5))
        Rs, ps = _transform(bodies.get("scapula_r"), state)
        np.testing.assert_allclose(Rs, m["scapula"]["rotation_in_thorax"], atol=1e-12)
        np.testing.assert_allclose(ps, m["scapula"]["origin_in_thorax"], atol=1e-12)
        R, p = gen_model.body_poses(q)
        for k, b in enumerate(m["bodies"]):
            Rb, pb = _transform(bodies.get(b["osim_name"]), state)
            np.testing.assert_allclose(R[k], Rs.T @ Rb, rtol=0, atol=1e-12)
            np.testing.assert_allclose(p[k], Rs.T @ (pb - ps), rtol=0, atol=1e-12)
        hb = next(b for b in m["bodies"] if b["name"] == m["hand_point"]["body"])
        Rh, ph = _transform(bodies.get(hb["osim_name"]), state)
        hand = ph + Rh @ np.array(m["hand_point"]["point"])
        np.testing.assert_allclose(gen_model.hand_position(q), Rs.T @ (hand - ps), rtol=0, atol=1e-12)
