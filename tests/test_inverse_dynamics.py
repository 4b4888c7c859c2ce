"""armrt.inverse_dynamics (cpp/src/inverse_dynamics.cc): round trips with the engine's forward(), the hand
load's generalised force against the hand Jacobian, and OpenSim 4.6's InverseDynamicsSolver on das3.osim with
the girdle locked at the same pose."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import DAS3

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
# das3's settled pose lies slightly beyond its AC ranges (the girdle settles there): reset warns about it.
pytestmark = pytest.mark.filterwarnings("ignore:q slightly beyond the joint limits:RuntimeWarning")

RTOL = 1e-9
HAND = np.array([3.0, -20.0, 5.0]), np.array([0.3, -0.2, 0.1])


def settled_das3():
    arm = armrt.Arm("das3")
    arm.settle()
    return arm


def random_states(arm, count, seed):
    """(q, qdot, activation) near the arm's present pose (das3: its settled pose, within the girdle's
    contact domain) or across the joint ranges (das2)."""
    rng = np.random.default_rng(seed)
    lo, hi = arm.model.dof_ranges.T
    for _ in range(count):
        if arm.model.girdle_dofs:
            q = arm.q + rng.uniform(-0.01, 0.01, arm.n_dofs)
        else:
            q = rng.uniform(lo + 0.05, hi - 0.05)
        yield q, rng.uniform(-1.5, 1.5, arm.n_dofs), rng.uniform(0.0, 0.4, arm.n_elements)


@pytest.fixture(params=["das2", "das3"])
def any_arm(request):
    return armrt.Arm("das2") if request.param == "das2" else settled_das3()


def forward_at(arm, q, qd, act):
    """The engine's forward() outputs at (q, qd, equilibrium lce, act): reset puts the fibres in equilibrium."""
    arm.reset(q=q, qdot=qd, activation=act)
    return arm.outputs()


def test_forward_then_inverse_recovers_the_muscle_moments(any_arm):
    arm = any_arm
    arm.set_hand_load(*HAND)
    for q, qd, act in random_states(arm, 6, 1):
        o = forward_at(arm, q, qd, act)
        tau = arm.inverse_dynamics(arm.q, arm.qdot, o["qddot"])  # hand_load=None: the arm's own
        scale = max(np.abs(o["muscle_torque"]).max(), 1.0)
        assert np.abs(tau - o["muscle_torque"]).max() / scale < RTOL


def test_inverse_then_forward_recovers_qddot(any_arm):
    """tau = ID(qdd) for a random qdd; forward's qdd is M^-1 (tau_muscle + rest), so
    qdd_forward + M^-1 (tau - tau_muscle) must be qdd: the acceleration the muscles would give."""
    arm = any_arm
    rng = np.random.default_rng(2)
    for q, qd, act in random_states(arm, 6, 3):
        o = forward_at(arm, q, qd, act)
        qdd = rng.uniform(-20, 20, arm.n_dofs)
        tau = arm.inverse_dynamics(arm.q, arm.qdot, qdd, hand_load=HAND)
        arm.set_hand_load(*HAND)
        o = arm.outputs()
        M = arm.model.mass_matrix(arm.q)
        back = o["qddot"] + np.linalg.solve(M, tau - o["muscle_torque"])
        parts = arm.inverse_dynamics(arm.q, arm.qdot, qdd, parts=True)
        scale = max(np.abs(parts[k]).max() for k in ("mass_times_qddot", "bias", "passive", "external", "girdle"))
        # In moments: M (qdd_back - qdd) against the largest generalised force in the balance.
        assert np.abs(M @ (back - qdd)).max() / scale < RTOL
        if arm.model.girdle_dofs:
            # das3's M is ill-conditioned (the light clavicle and scapula under the arm: cond ~1e4-1e5), so
            # forward's own qdd carries cond(M) eps |M^-1 rhs| of rounding: a looser bound in accelerations.
            assert np.abs(back - qdd).max() / np.abs(qdd).max() < 1e-6
        else:
            assert np.abs(back - qdd).max() / np.abs(qdd).max() < RTOL
        arm.set_hand_load()


def test_parts_add_up_and_the_hand_load_is_the_jacobian_transpose(any_arm):
    arm = any_arm
    q = arm.q
    qd = np.linspace(-0.5, 0.5, arm.n_dofs)
    qdd = np.linspace(1.0, -2.0, arm.n_dofs)
    p = arm.inverse_dynamics(q, qd, qdd, hand_load=HAND, parts=True)
    np.testing.assert_allclose(p["tau_muscle"], p["mass_times_qddot"] - p["bias"] - p["passive"] - p["external"]
                               - p["girdle"], rtol=0, atol=1e-12)
    Jv, Jw = arm.model.hand_jacobian(q)  # thorax frame: an independent path (model.py, not the stage)
    np.testing.assert_allclose(p["external"], Jv.T @ HAND[0] + Jw.T @ HAND[1], rtol=1e-12, atol=1e-12)
    free = arm.inverse_dynamics(q, qd, qdd, hand_load=np.zeros(3))
    np.testing.assert_allclose(free - p["tau_muscle"], p["external"], atol=1e-10)
    np.testing.assert_allclose(p["mass_times_qddot"], arm.model.mass_matrix(q) @ qdd, rtol=1e-12, atol=1e-12)
    if arm.model.girdle_dofs:
        np.testing.assert_allclose(p["girdle"], arm._sim.girdle_forces(q)["tau"], atol=1e-12)
    else:
        assert not np.any(p["girdle"])


def test_model_and_arm_agree_and_the_gh_force_adds_up():
    arm = armrt.Arm("das2")
    q, qd, qdd = arm.rest_posture + 0.2, np.full(5, 0.4), np.full(5, -3.0)
    np.testing.assert_allclose(arm.model.inverse_dynamics(q, qd, qdd, hand_load=HAND),
                               arm.inverse_dynamics(q, qd, qdd, hand_load=HAND), rtol=0, atol=1e-12)
    np.testing.assert_allclose(armrt.inverse_dynamics(arm.model, q, qd, qdd, HAND),
                               arm.inverse_dynamics(q, qd, qdd, HAND), rtol=0, atol=1e-12)
    # The GH force of the loads but the muscles, plus sum F_i dir_i, is the engine's recorded GH force.
    arm.set_hand_load(*HAND)
    arm.reset(q=q, qdot=qd, activation=np.full(arm.n_elements, 0.2))
    o = arm.outputs()
    p = arm.inverse_dynamics(arm.q, arm.qdot, o["qddot"], parts=True)
    gh = p["gh_force_without_muscles"] + arm.model.gh_directions(arm.q).T @ o["muscle_force"]
    np.testing.assert_allclose(gh, o["gh_force"], rtol=1e-10, atol=1e-9)


def test_bad_input_names_the_problem():
    arm = armrt.Arm("das2")
    q = arm.rest_posture
    with pytest.raises(ValueError, match="NaN"):
        arm.inverse_dynamics(np.array([np.nan, 0, 0, 0, 0]))
    with pytest.raises(ValueError, match=r"shape \(5,\)"):
        arm.inverse_dynamics(q[:4])
    with pytest.raises(ValueError, match="qddot"):
        arm.inverse_dynamics(q, 0.0, np.zeros(3))
    with pytest.raises(ValueError, match="scalar must be 0"):
        arm.inverse_dynamics(q, 1.0)
    with pytest.raises(ValueError, match="hand_load"):
        arm.inverse_dynamics(q, hand_load=np.zeros(4))
    with pytest.raises(ValueError, match="hand force"):
        arm.inverse_dynamics(q, hand_load=[np.inf, 0, 0])
    with pytest.raises(TypeError):
        armrt.inverse_dynamics(object(), q)
    with pytest.raises(TypeError, match="parts must be True or False"):
        armrt.inverse_dynamics(arm, q, parts="yes")


@pytest.mark.parametrize("target", ["arm", "model"])
def test_a_bool_posture_speed_or_acceleration_is_refused_not_taken_as_1_and_0(target):
    """q=[True, False, ...] was taken as 1 and 0 rad and answered; now a TypeError naming the input, as
    StaticOptimizer(gh_stab_max=True) and EndpointGains(kp=True) refuse a bool."""
    arm = armrt.Arm("das2")
    who = arm if target == "arm" else arm.model
    with pytest.raises(TypeError, match=r"q must be numbers, got an array of bools \(shape \(5,\)\)"):
        armrt.inverse_dynamics(who, np.array([True, False, True, False, True]))
    q = arm.rest_posture
    with pytest.raises(TypeError, match="qdot must be a number, got the bool False"):
        armrt.inverse_dynamics(who, q, qdot=False)
    with pytest.raises(TypeError, match="qddot must be numbers"):
        armrt.inverse_dynamics(who, q, qddot=np.zeros(5, bool))
    assert np.all(np.isfinite(armrt.inverse_dynamics(who, q, qdot=0, qddot=0.0)))   # the number 0 still means zero
    # The hand load in every form too (hand_load=[True, False, False] was a 1 N force; a new user's trial), and
    # the arm's own set_hand_load.
    for load in ([True, False, False], np.zeros(6, bool), ([0.0, 0.0, 0.0], [True, False, False]),
                 {"force": np.ones(3, bool)}):
        with pytest.raises(TypeError, match="must be numbers, got an array of bools"):
            armrt.inverse_dynamics(who, q, hand_load=load)
        with pytest.raises(TypeError, match="must be numbers, got an array of bools"):
            armrt.static_optimization(who, q, hand_load=load)
    with pytest.raises(TypeError, match="hand force must be numbers, got an array of bools"):
        arm.set_hand_load([True, False, False])


@pytest.mark.parametrize("target", ["arm", "model"])
def test_inputs_near_the_largest_double_are_refused_where_the_answer_overflows(target):
    """A 1.7e308 N hand force is finite, so the input checks pass it; J^T F overflows to NaN, which was returned as
    the answer (2026-12-07). Now a ValueError naming the overflow; a large but representable answer is returned."""
    obj = armrt.Arm("das2") if target == "arm" else armrt.Model("das2")
    q = armrt.Arm("das2").rest_posture
    # A hand load that large is refused before (checks.hand_load's 1e5 N, the bound of every hand load); 1e9 N and
    # 1e300 N were taken and returned as 1e9-1e299 N m (a fourth trial).
    for force in ([1.7e308] * 3, [0.0, -1e9, 0.0], [0.0, 0.0, 1e300]):
        with pytest.raises(ValueError, match=r"hand force of .* N is beyond 1e\+05 N, more than any arm bears"):
            obj.inverse_dynamics(q, hand_load=force)
    with pytest.raises(ValueError, match=r"hand moment of 20000 N m is beyond 10000 N m"):
        obj.inverse_dynamics(q, hand_load={"moment": [0.0, 2e4, 0.0]})
    assert np.all(np.isfinite(obj.inverse_dynamics(q, hand_load=[0.0, -1e5, 0.0])))  # the bound itself is a load
    with pytest.raises(ValueError, match="overflowed"):
        obj.inverse_dynamics(q, 0.0, np.full(5, 1.7e308) * np.array([1, -1, 1, -1, 1]))
    tau = obj.inverse_dynamics(q, 0.0, np.full(5, 1e300))
    assert np.all(np.isfinite(tau)) and np.max(np.abs(tau)) > 1e298


# ----------------------------------------------------------------------------------------------
# OpenSim 4.6 on das3.osim: its InverseDynamicsSolver with the girdle locked at the pose

@pytest.mark.opensim
def test_das3_inverse_dynamics_vs_opensim_with_the_girdle_locked():
    osim_path = DAS3 / "das3.osim"
    if not osim_path.exists():
        pytest.skip(f"{osim_path} not present (needs ../shared/reference/das3 beside the repository)")
    osim = pytest.importorskip("opensim", reason="opensim (pip install opensim) is not installed")
    osim.Logger.setLevelString("error")
    model = osim.Model(str(osim_path))
    model.updForceSet().clearAndDestroy()  # OpenSim's muscles and contact off: our passive, girdle parts are ours
    state = model.initSystem()
    arm = settled_das3()
    m = arm.model
    coords = [model.getCoordinateSet().get(name) for name in m.dof_osim_names]
    girdle = set(m.girdle_dofs)
    # Mobility order of OpenSim's U against our DOF order, found by tagging speeds.
    for i, c in enumerate(coords):
        c.setSpeedValue(state, 10.0 + i)
    U = state.getU()
    u = np.array([U.get(k) for k in range(U.size())])
    uidx = [int(np.flatnonzero(u == 10.0 + i)[0]) for i in range(m.n_dofs)]
    g = model.getGravity()
    np.testing.assert_allclose([g.get(k) for k in range(3)], m.gravity_base, atol=1e-12)
    solver = osim.InverseDynamicsSolver(model)
    rng = np.random.default_rng(5)
    worst = 0.0
    for _ in range(8):
        q = arm.q + rng.uniform(-0.03, 0.03, m.n_dofs)
        qd = rng.uniform(-2, 2, m.n_dofs)
        qdd = rng.uniform(-10, 10, m.n_dofs)
        for j in girdle:  # locked: the girdle holds still at the pose
            qd[j] = qdd[j] = 0.0
        for c in coords:  # a locked coordinate keeps its value: unlock, set, then lock the girdle at the pose
            c.setLocked(state, False)
        for i, c in enumerate(coords):
            c.setValue(state, float(q[i]), False)
            c.setSpeedValue(state, float(qd[i]))
        for j in girdle:
            coords[j].setLocked(state, True)
        model.realizeVelocity(state)
        udot = np.zeros(m.n_dofs)
        udot[uidx] = qdd
        t = solver.solve(state, osim.Vector.createFromMat(udot))
        tau_osim = np.array([t.get(k) for k in range(m.n_dofs)])[uidx]
        p = m.inverse_dynamics(q, qd, qdd, parts=True)
        # OpenSim has no passive joint moments, girdle contact or hand load here: they are added back.
        ours = p["tau_muscle"] + p["passive"] + p["girdle"] + p["external"]
        arm_dofs = [j for j in range(m.n_dofs) if j not in girdle]
        err = np.abs(ours - tau_osim).max() / np.abs(tau_osim).max()
        worst = max(worst, err)
        assert np.abs(ours[arm_dofs] - tau_osim[arm_dofs]).max() / np.abs(tau_osim[arm_dofs]).max() < RTOL
    print(f"max relative error vs OpenSim's InverseDynamicsSolver (all 11 DOFs, girdle locked): {worst:.2e}")
    assert worst < RTOL


def test_every_form_of_the_hand_load_is_the_same_and_a_misspelt_key_is_refused():
    """(force, moment), [force, moment], a (6,) array and {"force", "moment"} give the same moments; a dict key
    other than "force"/"moment" is a KeyError (a misspelt "moment" was a silent zero moment)."""
    arm = armrt.Arm("das2")
    q = np.radians([30, 60, 10, 60, 80])
    f, m = np.array([1.0, -20.0, 3.0]), np.array([0.5, 0.0, -0.2])
    ref = arm.inverse_dynamics(q, hand_load=(f, m))
    assert np.abs(ref - arm.inverse_dynamics(q)).max() > 1.0
    for form in ([f, m], np.concatenate([f, m]), {"force": f, "moment": m}):
        np.testing.assert_array_equal(arm.inverse_dynamics(q, hand_load=form), ref)
    np.testing.assert_array_equal(arm.inverse_dynamics(q, hand_load={"force": f}), arm.inverse_dynamics(q, hand_load=f))
    for bad in ({"forse": f}, {"force": f, "momnet": m}):
        with pytest.raises(KeyError, match="unknown key"):
            arm.inverse_dynamics(q, hand_load=bad)
    with pytest.raises(ValueError, match=r"qdot\[ELx\] = -500 rad/s is beyond max_joint_speed"):
        arm.inverse_dynamics(q, qdot=[0, 0, 0, -500, 0])
