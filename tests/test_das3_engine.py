"""The 11-DOF das3 model in the engine (issue 15): the girdle stage against its documented laws computed
independently in Python (codegen/eom_chain.py's numeric chain and the formulas of docs/das3.md), its
stiffness against finite differences, the arm's momentum rate against finite differences of the centres
of mass, the GH reaction in the moving scapula frame recomposed from the engine's outputs, the settling
of the relaxed arm, the scapula staying on the thorax, and ROS2 against CVODE from the settled state."""
from __future__ import annotations

import json
import warnings
from pathlib import Path

import numpy as np
import pytest

import armrt
from codegen.eom_chain import NumericChain

ROOT = Path(__file__).resolve().parents[1]
MODEL = json.loads((ROOT / "models" / "das3.json").read_text())
DOFS = [d["name"] for d in MODEL["dofs"]]
GF = MODEL["girdle_forces"]


@pytest.fixture(scope="module")
def chain():
    return NumericChain(DOFS, MODEL["bodies"], "thorax")


@pytest.fixture(scope="module")
def arm():
    return armrt.Arm(model="das3")


def random_postures(n, seed=0, spread=0.15):
    """Postures around equilibrium.mat (rad): the girdle near where the scapula rests on the thorax."""
    rng = np.random.default_rng(seed)
    rest = np.array([d["rest"] for d in MODEL["dofs"]])
    lo, hi = np.array([d["range"] for d in MODEL["dofs"]]).T
    return np.clip(rest + rng.uniform(-spread, spread, (n, len(DOFS))), lo, hi)


def girdle_reference(chain, q):
    """tau = sum J_k^T F_k from the formulas of docs/das3.md, on numpy (independent of girdle.cc)."""
    c, r = np.array(GF["thorax_ellipsoid"]["centre"]), np.array(GF["thorax_ellipsoid"]["radii"])
    k, eps = GF["contact"]["stiffness"], GF["contact"]["eps"]
    K = k * np.sum(r ** 2) / 2
    tau = np.zeros(len(DOFS))
    dist = []
    for pt in GF["contact"]["points"]:
        p, J = chain.point(q, pt["body"], pt["point"])
        f = np.sum(((p - c) / r) ** 2) - 1
        grad = 2 * (p - c) / r ** 2
        m = (f - np.sqrt(f * f + eps * eps)) / 2
        tau += J.T @ (-K * m * grad)
        dist.append(f / np.linalg.norm(grad))
    co = GF["conoid"]
    xo, Jo = chain.point(q, co["origin"]["body"], co["origin"]["point"])
    xi, Ji = chain.point(q, co["insertion"]["body"], co["insertion"]["point"])
    L = np.linalg.norm(xi - xo)
    d = L - co["length"]
    T = co["stiffness"] * (d + np.sqrt(d * d + co["eps"] ** 2)) / 2
    tau += (Ji - Jo).T @ (-T * (xi - xo) / L)
    return tau, np.array(dist), L, T


def test_girdle_forces_equal_the_documented_laws(arm, chain):
    for q in random_postures(20):
        got = arm.girdle_forces(q)
        tau, dist, L, T = girdle_reference(chain, q)
        np.testing.assert_allclose(got["tau"], tau, rtol=1e-9, atol=1e-9 * np.abs(tau).max())
        np.testing.assert_allclose(got["contact_distance"], dist, rtol=1e-9, atol=1e-12)
        assert got["conoid_length"] == pytest.approx(L, rel=1e-12)
        assert got["conoid_tension"] == pytest.approx(T, rel=1e-9)
    # The arm DOFs carry no girdle force (the points are on the clavicle and scapula).
    assert np.all(arm.girdle_forces(random_postures(1)[0])["tau"][6:] == 0)


def test_girdle_stiffness_is_the_derivative_without_the_dJ_term(arm, chain):
    """stiffness = J^T dF/dp J: finite differences of tau minus those of J(q)^T F with F held fixed."""
    h = 1e-6
    for q in random_postures(5, seed=1):
        K = arm.girdle_forces(q)["stiffness"]
        np.testing.assert_allclose(K, K.T, atol=1e-9 * np.abs(K).max())
        fd = np.zeros_like(K)
        for j in range(len(DOFS)):
            e = np.zeros(len(DOFS))
            e[j] = h
            fd[:, j] = (arm.girdle_forces(q + e)["tau"] - arm.girdle_forces(q - e)["tau"]) / (2 * h)
        # The dJ/dq part: tau with the forces frozen at q, moved only by the Jacobians.
        dJ = np.zeros_like(K)
        pts = [(p["body"], p["point"]) for p in GF["contact"]["points"]]
        co = GF["conoid"]
        Fs = []
        c, r = np.array(GF["thorax_ellipsoid"]["centre"]), np.array(GF["thorax_ellipsoid"]["radii"])
        Kc = GF["contact"]["stiffness"] * np.sum(r ** 2) / 2
        for body, pt in pts:
            p, _ = chain.point(q, body, pt)
            f = np.sum(((p - c) / r) ** 2) - 1
            Fs.append(-Kc * (f - np.sqrt(f * f + GF["contact"]["eps"] ** 2)) / 2 * 2 * (p - c) / r ** 2)
        xo, _ = chain.point(q, co["origin"]["body"], co["origin"]["point"])
        xi, _ = chain.point(q, co["insertion"]["body"], co["insertion"]["point"])
        L = np.linalg.norm(xi - xo)
        d = L - co["length"]
        Fc = -co["stiffness"] * (d + np.sqrt(d * d + co["eps"] ** 2)) / 2 * (xi - xo) / L

        def frozen(qq):
            t = sum(chain.point(qq, b, pt)[1].T @ F for (b, pt), F in zip(pts, Fs))
            return t + (chain.point(qq, co["insertion"]["body"], co["insertion"]["point"])[1]
                        - chain.point(qq, co["origin"]["body"], co["origin"]["point"])[1]).T @ Fc
        for j in range(len(DOFS)):
            e = np.zeros(len(DOFS))
            e[j] = h
            dJ[:, j] = (frozen(q + e) - frozen(q - e)) / (2 * h)
        np.testing.assert_allclose(K, fd - dJ, atol=2e-5 * np.abs(K).max())


def test_arm_momentum_rate_is_the_second_derivative_of_the_arm_centres_of_mass(arm, chain):
    arm_bodies = [b for b in MODEL["bodies"][2:]]   # humerus, ulna, radius, hand: what the GH reaction holds

    def momentum(q):
        return sum(b["mass"] * chain.point(q, b["name"], b["com"])[0] for b in arm_bodies)

    rng = np.random.default_rng(2)
    for q in random_postures(4, seed=3):
        qd = rng.uniform(-3, 3, len(DOFS))
        A, c = arm._sim.arm_momentum_rate(q, qd)
        h = 1e-6
        fdA = np.column_stack([(momentum(q + h * e) - momentum(q - h * e)) / (2 * h) for e in np.eye(len(DOFS))])
        np.testing.assert_allclose(A, fdA, atol=1e-8)
        t = 1e-4   # along q(t) = q + qd t (qdd = 0): the second derivative is the velocity-product part c
        fdc = (momentum(q + qd * t) - 2 * momentum(q) + momentum(q - qd * t)) / t ** 2
        np.testing.assert_allclose(c, fdc, atol=2e-4 * max(1.0, np.abs(c).max()))


def test_gh_force_is_in_the_moving_scapula_frame(arm):
    """Recomposed from the engine's own outputs: R_scapula^T (m g + hand load - A qdd - c) + sum F_i d_i."""
    a = armrt.Arm(model="das3")
    rng = np.random.default_rng(4)
    for q in random_postures(3, seed=5):
        with warnings.catch_warnings():   # postures off the thorax surface on purpose: any state will do here
            warnings.simplefilter("ignore", RuntimeWarning)
            a.reset(q=q, qdot=rng.uniform(-1, 1, len(DOFS)))
        u = rng.uniform(0, 0.3, a.model.n_elements)
        a.set_excitation(u)
        a.set_hand_load(force=(5.0, -10.0, 2.0))
        o = a.outputs()
        R, _ = a.model.body_poses(a.q, frame="thorax")
        Rs = R[a.model.info["scapula_body"]]
        A, c = a._sim.arm_momentum_rate(a.q, a.qdot)
        f_base = a.model.arm_mass * a.model.gravity_base + np.array([5.0, -10.0, 2.0]) - (A @ o["qddot"] + c)
        expect = Rs.T @ f_base + o["muscle_force"] @ a.gh_directions(a.q)
        np.testing.assert_allclose(o["gh_force"], expect, rtol=1e-9, atol=1e-9)
        # The scapula really moved: its frame is not the resting one.
        R0, _ = a.model.body_poses(a.model.rest_posture, frame="thorax")
        assert np.abs(Rs - R0[a.model.info["scapula_body"]]).max() > 1e-3


@pytest.fixture(scope="module")
def settled():
    a = armrt.Arm(model="das3", integrator="cvode")
    r = a.simulate(np.zeros(a.model.n_elements), 3.0, record_every=10)
    return a.get_state(), r


def test_the_relaxed_arm_settles_near_equilibrium_mat_with_the_scapula_on_the_thorax(settled):
    state, r = settled
    assert np.abs(r.qdot[-1]).max() < 0.01   # rad/s: at rest after 3 s
    diff = np.degrees(r.q[-1] - r.q[0])
    # The girdle within 8 deg of equilibrium.mat; the elbow sags as das2's does (ELx ~ -27 deg).
    assert np.abs(diff[:6]).max() < 8.0, diff
    assert np.abs(diff[6:9]).max() < 15.0, diff
    # TS and AI stay on the thorax surface: within a few millimetres, never lifted off by more than 1 mm.
    assert r.contact_distance.min() > -0.004 and r.contact_distance.max() < 0.001
    assert np.all(r.conoid_tension > 500)   # the conoid is taut throughout (docs/das3.md: 938 N at rest)


def test_ros2_at_1ms_follows_cvode_from_the_settled_arm(settled):
    state, _ = settled
    out = {}
    for integ in ("ros2", "cvode"):
        a = armrt.Arm(model="das3", integrator=integ)
        a.set_state(state)
        u = np.zeros(a.model.n_elements)
        for g, v in (("serratus_anterior", 0.3), ("trapezius", 0.3), ("deltoid", 0.2)):
            u[list(a.model.indices(g))] = v
        out[integ] = a.simulate(u, 0.5)
    err = np.degrees(np.abs(out["ros2"].q - out["cvode"].q)).max()
    assert err < 0.1, err
    # The girdle really moved (scapular elevation and upward rotation), by tens of degrees.
    assert np.degrees(np.abs(out["cvode"].q[-1, :6] - out["cvode"].q[0, :6]).max()) > 10


def test_a_scapula_pushed_into_the_thorax_is_refused_by_name():
    """A 2000 N pull forward on the hand drives TS into the thorax: the step that takes it beyond 20 mm
    stops with an error naming the contact point and its depth (kMaxContactPenetration), not with the
    speed at which the contact then throws the scapula out."""
    a = armrt.Arm(model="das3")
    a.set_hand_load(force=(2000.0, 0.0, 0.0))
    with pytest.raises(armrt.SimulationError,
                       match=r"girdle contact point (TS|AI) is \d+\.\d mm inside the thorax \(more than 20 mm\)"):
        a.simulate(np.zeros(a.model.n_elements), 0.3)


def test_a_start_with_the_scapula_in_or_off_the_thorax_is_refused_or_warned():
    """The girdle's ranges are a box; the scapula rests on the thorax only on a surface inside it."""
    a = armrt.Arm(model="das3")
    q = a.model.rest_posture.copy()
    q[a.model.dof_index("ACy")] -= 0.14          # AI 27 mm inside
    with pytest.raises(ValueError, match=r"q puts the scapula into the thorax: TS .* AI 2\d\.\d mm inside"), \
            pytest.warns(RuntimeWarning, match="beyond the joint limits"):
        a.reset(q=q)
    for dof, dq, where in (("ACx", 0.08, "AI 11.1 mm inside"), ("ACy", 0.08, "AI 11.5 mm outside")):
        q = a.model.rest_posture.copy()
        q[a.model.dof_index(dof)] += dq           # within the ranges: simulated, with a warning
        with pytest.warns(RuntimeWarning, match=f"q starts the scapula off the thorax surface: .*{where}"):
            a.reset(q=q)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        a.reset()                                # the rest posture: TS, AI 1.6 and 0.7 mm inside, silent


def test_the_built_in_dynamics_equal_the_chain_checked_against_opensim(arm, chain):
    """das3's compiled M(q), b(q, qd, g), hand point and Jacobians equal codegen/eom_chain.py's numeric
    chain, which tests/test_das3_dynamics.py checks against OpenSim's calcM and inverse dynamics on
    das3.osim (1e-15): so the engine's equations of motion are OpenSim's."""
    rng = np.random.default_rng(6)
    m = arm.model
    hand = MODEL["hand_point"]
    for q in random_postures(10, seed=7, spread=0.5):
        qd = rng.uniform(-4, 4, len(DOFS))
        M = chain.mass_matrix(q)
        np.testing.assert_allclose(arm.mass_matrix(q), M, rtol=1e-12, atol=1e-14)
        np.testing.assert_allclose(arm._sim.bias_force(q, qd), chain.bias_force(q, qd, m.gravity_base),
                                   rtol=1e-11, atol=1e-11)
        p, J = chain.point(q, hand["body"], hand["point"])
        np.testing.assert_allclose(m.hand_position(q), p, atol=1e-14)
        np.testing.assert_allclose(m.hand_jacobian(q)[0], J, atol=1e-13)


@pytest.mark.slow
def test_a_thorax_based_model_file_builds_on_demand_and_runs_like_the_built_in_das3(tmp_path, monkeypatch):
    """models/das3.json under another name through the generator, the compiler and dlopen (14 s): the
    girdle forces and the chain dynamics of a model built on demand give das3's trajectory bit for bit."""
    monkeypatch.setenv("ARMRT_CACHE_DIR", str(tmp_path / "cache"))
    path = tmp_path / "das3_copy.json"
    path.write_text(json.dumps({**MODEL, "name": "das3_copy"}))
    m = armrt.Model.load(path)
    assert not m.builtin and m.info["base_body"] == "thorax"
    u = np.zeros(m.n_elements)
    u[list(m.indices("serratus_anterior"))] = 0.3
    got, ref = armrt.Arm(m).simulate(u, 0.3), armrt.Arm("das3").simulate(u, 0.3)
    np.testing.assert_array_equal(got.q, ref.q)
    np.testing.assert_array_equal(got.contact_distance, ref.contact_distance)


def test_settle_relaxes_the_arm_and_restarts_the_clock():
    a = armrt.Arm(model="das3")
    a.set_excitation({"deltoid": 0.2})
    a.settle()
    assert a.time == 0.0 and np.abs(a.qdot).max() < 0.01          # rad/s: at rest after 3 s relaxed
    assert a.excitation[list(a.model.indices("deltoid"))].min() == 0.2   # the excitation as it was
    assert np.degrees(abs(a.q[a.model.dof_index("ELx")] - a.model.rest_posture[a.model.dof_index("ELx")])) > 20


def test_girdle_arrays_are_result_channels():
    r = armrt.Arm(model="das3").simulate(np.zeros(138), 0.01)
    cols = r.to_dataframe().columns
    assert {"contact_distance.TS", "contact_distance.AI", "conoid_tension"} <= set(cols)
    assert "conoid_tension" in r.channels() and "contact_distance" not in armrt.Arm().simulate(
        np.zeros(102), 0.01).channels()
