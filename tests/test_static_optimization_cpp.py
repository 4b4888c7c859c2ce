"""The C++ static optimisation (cpp/src/static_optimization.cc, StaticOptimizer(backend="cpp")) against the
Python path's ProxQP solve of the same rigid-tendon QP (backend="python"): same activations to the solvers'
tolerance at random das2 states, moments balanced, GHstab within its bound, infeasible requests reported with the
same closest solution, the GH polygon the same rows (docs/control.md)."""
import numpy as np
import pytest

import armrt
from armrt import _core
from armrt.control import gh_polygon

from tests.static_optimization_motions import das2_fast_motion, das3_motion


def random_states(arm, rng, k):
    lo, hi = arm.model.dof_ranges[:, 0], arm.model.dof_ranges[:, 1]
    for _ in range(k):
        q = lo + rng.uniform(0.2, 0.8, arm.n_dofs) * (hi - lo)
        yield q, rng.uniform(-0.5, 0.5, arm.n_dofs), rng.uniform(-2, 2, arm.n_dofs)


@pytest.mark.parametrize("gh_stab_max", [None, 0.3, 0.05])
def test_cpp_agrees_with_python_at_random_states(gh_stab_max):
    arm = armrt.Arm("das2")
    cpp = armrt.StaticOptimizer(arm, tendon="rigid", gh_stab_max=gh_stab_max, backend="cpp")
    py = armrt.StaticOptimizer(arm, tendon="rigid", gh_stab_max=gh_stab_max, backend="python")
    assert cpp.backend == "cpp" and py.backend == "python"
    hand = [0, -9.81, 0]
    agreed = 0
    for q, qd, qdd in random_states(arm, np.random.default_rng(11), 8):
        rc = cpp.solve(q, qd, qdd, hand, on_infeasible="return")
        rp = py.solve(q, qd, qdd, hand, on_infeasible="return")
        # Where ProxQP solves, so does the C++ path; with the GH bound binding ProxQP can stop at its iteration
        # limit (reported infeasible) where the dual Newton method still solves: that answer is checked below
        # on its own (moments, bounds, GH bound), without a reference.
        assert rc.feasible or not rp.feasible, (rc, rp)
        if not rc.feasible:
            assert np.abs(rc.residual).max() > 1e-6 and rc.report
            continue
        assert np.abs(rc.residual).max() < 1e-6
        assert np.all(rc.activation >= 0) and np.all(rc.activation <= arm.max_activation)
        if rp.feasible:
            agreed += 1
            np.testing.assert_allclose(rc.activation, rp.activation, atol=2e-6)
        # The moments of the C++ activations by the Python path's own pieces (paths, rigid-tendon forces).
        L, R = arm._sim.muscle_paths(q)
        _, Fa, Fp = arm._sim.rigid_tendon_forces(L, -(R @ qd))
        tau = armrt.inverse_dynamics(arm, q, qd, qdd, hand_load=hand)
        assert np.abs(R.T @ (Fa * rc.activation + Fp) - tau).max() < 1e-6
        np.testing.assert_allclose(rc.tau_required, tau, rtol=1e-12, atol=1e-12)
        if rp.feasible:
            np.testing.assert_allclose(rc.gh_force, rp.gh_force, rtol=1e-5, atol=1e-4)
            np.testing.assert_allclose(rc.elastic_residual, rp.elastic_residual, atol=1e-4)
            assert abs(rc.objective - rp.objective) <= 1e-6 * max(1.0, rp.objective)
        if gh_stab_max is not None:
            assert rc.gh_stab <= gh_stab_max + 1e-9
            assert arm.model.gh_rim(rc.gh_force)["gh_stab"] <= gh_stab_max + 1e-9
    assert agreed >= 4


def test_auto_backend_is_cpp_for_squared_activations():
    arm = armrt.Arm("das2")
    assert armrt.StaticOptimizer(arm, tendon="rigid").backend == "cpp"
    assert armrt.StaticOptimizer(arm.model, tendon="rigid").backend == "cpp"
    assert armrt.StaticOptimizer(arm).backend == "cpp"  # elastic
    assert armrt.StaticOptimizer(arm.model).backend == "cpp"
    assert armrt.StaticOptimizer(arm, tendon="rigid", criterion="cubed").backend == "python"
    assert armrt.StaticOptimizer(arm, criterion="cubed").backend == "python"
    assert armrt.StaticOptimizer(arm, backend="python").backend == "python"
    # The C++ SQP's QP count is fixed: another limit is the Python path's, and refused with backend="cpp".
    assert armrt.StaticOptimizer(arm, max_iterations=5).backend == "python"
    assert armrt.StaticOptimizer(arm, tendon="rigid", max_iterations=5).backend == "cpp"
    with pytest.raises(ValueError, match="at most 50 QPs"):
        armrt.StaticOptimizer(arm, max_iterations=5, backend="cpp")
    with pytest.raises(ValueError, match="squared activations only"):
        armrt.StaticOptimizer(arm, criterion="cubed", backend="cpp")
    with pytest.raises(ValueError, match="backend"):
        armrt.StaticOptimizer(arm, tendon="rigid", backend="fortran")


def test_cpp_polygon_rows_are_pythons():
    g = armrt.Model("das2").glenoid
    for bound in (0.05, 0.3, 1.0, 3.0):
        rows_py = gh_polygon(g["rim_half_angle_major"], g["rim_half_angle_minor"], bound, 24)
        rows_cpp = _core.gh_polygon(g["rim_half_angle_major"], g["rim_half_angle_minor"], bound, 24)
        np.testing.assert_allclose(rows_cpp, rows_py, rtol=1e-12, atol=1e-14)
    with pytest.raises(ValueError, match="gh_stab_max"):
        _core.gh_polygon(g["rim_half_angle_major"], g["rim_half_angle_minor"], 10.0, 24)


def test_cpp_infeasible_reported_with_the_closest_solution():
    arm = armrt.Arm("das2")
    q = np.radians([30, 60, 10, 60, 80])
    kw = dict(tendon="rigid", on_infeasible="return", hand_load=[0, -3000, 0])
    rc = armrt.static_optimization(arm, q, backend="cpp", **kw)
    rp = armrt.static_optimization(arm, q, backend="python", **kw)
    assert not rc.feasible and not rp.feasible
    assert np.abs(rc.residual).max() > 1.0
    np.testing.assert_allclose(rc.residual, rp.residual, rtol=1e-3, atol=1e-3)
    assert "residual moment" in rc.report and rc.at_upper_bound
    with pytest.raises(armrt.StaticOptimizationInfeasible, match="residual moment"):
        armrt.static_optimization(arm, q, tendon="rigid", hand_load=[0, -3000, 0], backend="cpp")
    # The next, feasible, request is solved by the same optimiser.
    so = armrt.StaticOptimizer(arm, tendon="rigid", backend="cpp")
    so.solve(q, hand_load=[0, -3000, 0], on_infeasible="return")
    assert so.solve(q, hand_load=[0, -9.81, 0]).feasible


def test_cpp_infeasible_frame_solved_again_costs_no_more_than_the_first_time():
    """ProxQP warm starts from its last result and penalty parameters even through init: after an infeasible QP the
    same frame again took 340-380 ms (7600-7800 ProxQP iterations, against 22 the first time; an EndpointController
    told to move the hand at 1 km/s, a fresh-user trial 2026-12-07), inside armrt-rt's 1 ms cycle too. A failed QP
    is now cleaned up (static_optimization.cc forget_failed): each repeat costs at most the first solve's iterations,
    and the next feasible frame is the fresh optimiser's answer."""
    arm = armrt.Arm("das2")
    q = arm.model.rest_posture
    J, _ = arm.model.hand_jacobian(q)
    qdd = np.linalg.pinv(J) @ np.array([1.2e4, 0.0, 0.0])   # rad/s^2, within the 1e5 bound, beyond the muscles
    z = np.zeros(3)
    so = armrt.StaticOptimizer(arm, tendon="rigid", backend="cpp")
    _, first = so._cpp.solve(arm._sim, q, np.zeros(arm.n_dofs), qdd, z, z, "rigid")
    assert not first["feasible"] and first["qps"] == 2
    for _ in range(3):
        _, again = so._cpp.solve(arm._sim, q, np.zeros(arm.n_dofs), qdd, z, z, "rigid")
        assert not again["feasible"] and again["status"] == "infeasible"
        assert again["qp_iterations"] <= first["qp_iterations"], (again["qp_iterations"], first["qp_iterations"])
        np.testing.assert_allclose(again["residual"], first["residual"], rtol=1e-6, atol=1e-6)
    load = [0.0, -9.81, 0.0]
    res = so.solve(q, hand_load=load)
    fresh = armrt.StaticOptimizer(arm, tendon="rigid", backend="cpp").solve(q, hand_load=load)
    assert res.feasible
    np.testing.assert_allclose(res.activation, fresh.activation, atol=1e-7)


def test_cpp_follows_the_arms_settings():
    """Paralysis and weakness are read from the arm at each solve (the engine's Data), as the Python path."""
    arm = armrt.Arm("das2")
    q = arm.rest_posture + 0.2
    kw = dict(qddot=np.full(5, 2.0), hand_load=[0, -10, 0], on_infeasible="return")
    so = armrt.StaticOptimizer(arm, tendon="rigid", backend="cpp")
    before = so.solve(q, **kw)
    tri = list(arm.indices("triceps"))
    assert before.feasible
    arm.max_activation = {"triceps": 0.0, "deltscap": 0.3}
    arm.strength = {"bicl": 0.5}
    after = so.solve(q, **kw)
    ref = armrt.StaticOptimizer(arm, tendon="rigid", backend="python").solve(q, **kw)
    amax = arm.max_activation
    assert after.feasible and ref.feasible
    assert np.all(after.activation >= 0) and np.all(after.activation <= amax + 1e-12)
    assert not np.any(after.activation[tri])
    np.testing.assert_allclose(after.activation, ref.activation, atol=2e-6)
    assert np.abs(after.activation - before.activation).max() > 1e-3


def test_cpp_agrees_with_python_on_das3():
    """das3 (11 DOFs, 138 elements, the girdle's contact and conoid forces in the inverse dynamics) about its
    settled pose, the girdle held, with and without a GH bound."""
    arm = armrt.Arm("das3")
    arm.settle()
    rng = np.random.default_rng(4)
    q0 = arm.q.copy()
    moving = np.array([j not in arm.model.girdle_dofs for j in range(arm.n_dofs)], float)
    for gh in (None, 0.5):
        cpp = armrt.StaticOptimizer(arm, tendon="rigid", gh_stab_max=gh, backend="cpp")
        py = armrt.StaticOptimizer(arm, tendon="rigid", gh_stab_max=gh, backend="python")
        solved = 0
        for k in range(3):
            q = q0 + rng.uniform(-0.05, 0.05, arm.n_dofs) * moving
            qd = rng.uniform(-0.5, 0.5, arm.n_dofs) * moving
            qdd = rng.uniform(-2, 2, arm.n_dofs) * moving
            rc = cpp.solve(q, qd, qdd, [0, -5.0, 0], on_infeasible="return")
            rp = py.solve(q, qd, qdd, [0, -5.0, 0], on_infeasible="return")
            assert rc.feasible or not rp.feasible
            if rc.feasible and rp.feasible:
                solved += 1
                assert np.abs(rc.residual).max() < 1e-6
                np.testing.assert_allclose(rc.activation, rp.activation, atol=2e-6)
                if gh is not None:
                    assert rc.gh_stab <= gh + 1e-9
        assert solved >= 2


def _elastic_moments(arm, q, qd, qdd, hand, a):
    """The moments of activations a through the engine's element at the CE length where its fibre velocity is
    the path's dL/dt (steady_forces: the Python path's pieces), and the inverse dynamics' required ones."""
    L, R = arm._sim.muscle_paths(q)
    v = -(R @ qd)
    _, F, _ = arm._sim.steady_forces(L, v, a, arm._sim.rigid_tendon_forces(L, v)[0])
    return R.T @ F, armrt.inverse_dynamics(arm, q, qd, qdd, hand_load=hand)


@pytest.mark.parametrize("gh_stab_max", [None, 0.3])
def test_cpp_elastic_agrees_with_python_along_a_motion(gh_stab_max):
    """The elastic tendon's SQP in C++ (static_optimization_elastic) against the Python path's along the first
    120 frames of bench/static_optimization.py's das2 motion (warm started frame to frame, as a controller solves):
    feasible wherever Python's is, the moments balanced through the engine's element, GHstab within the bound.
    The elastic problem is not convex (docs/control.md): the two SQPs can stop at different local optima near the
    damper floor's kink (here from frame 66 on: activations up to 0.013 apart, objectives within 0.3 %, C++'s the
    lower where they differ most; 105 and 106 of the 120 frames within 1e-4, measured 2026-12-06 with
    `pytest -s -k elastic_agrees`); elsewhere they agree to the SQP's tolerance."""
    from bench.static_optimization import motion
    arm = armrt.Arm("das2")
    q, qd, qdd = motion(arm, np.radians([20, 40, 0, 60, 60]), 400)
    hand = [0, -9.81, 0]
    cpp = armrt.StaticOptimizer(arm, gh_stab_max=gh_stab_max, backend="cpp")
    py = armrt.StaticOptimizer(arm, gh_stab_max=gh_stab_max, backend="python")
    same, worst_objective = 0, 0.0
    for k in range(120):
        rc = cpp.solve(q[k], qd[k], qdd[k], hand, on_infeasible="return")
        rp = py.solve(q[k], qd[k], qdd[k], hand, on_infeasible="return")
        assert rc.feasible or not rp.feasible, k
        if not rc.feasible:
            continue
        assert rc.tendon == "elastic" and rc.elastic_residual is None
        assert np.all(rc.activation >= 0) and np.all(rc.activation <= arm.max_activation)
        tau, tau_req = _elastic_moments(arm, q[k], qd[k], qdd[k], hand, rc.activation)
        assert np.abs(tau - tau_req).max() < 1e-6, k
        np.testing.assert_allclose(rc.tau_required, tau_req, rtol=1e-12, atol=1e-12)
        if gh_stab_max is not None:
            assert rc.gh_stab <= gh_stab_max + 1e-9
        if rp.feasible:
            # Never a worse optimum by more than 0.1 %, nor a different one by more than 1 %.
            assert rc.objective <= (1 + 1e-3) * rp.objective and abs(rc.objective - rp.objective) <= 1e-2 * rp.objective, k
            worst_objective = max(worst_objective, abs(rc.objective - rp.objective) / rp.objective)
            same += np.abs(rc.activation - rp.activation).max() < 1e-4
    assert same >= 0.8 * 120, (same, worst_objective)
    print(f"elastic, GHstab <= {gh_stab_max}: {same} of 120 frames within 1e-4, objectives within {worst_objective:.2g}")


def test_cpp_elastic_infeasible_goes_to_the_python_paths_closest_solution():
    """C++ has no closest-solution QP for the elastic tendon: an infeasible request is solved again by the Python
    path, which reports the residuals and raises as the Python backend does; the next feasible one is C++'s."""
    arm = armrt.Arm("das2")
    q = np.radians([30, 60, 10, 60, 80])
    rc = armrt.static_optimization(arm, q, hand_load=[0, -3000, 0], backend="cpp", on_infeasible="return")
    rp = armrt.static_optimization(arm, q, hand_load=[0, -3000, 0], backend="python", on_infeasible="return")
    assert not rc.feasible and not rp.feasible and "residual moment" in rc.report
    np.testing.assert_allclose(rc.residual, rp.residual, rtol=1e-3, atol=1e-3)
    with pytest.raises(armrt.StaticOptimizationInfeasible, match="residual moment"):
        armrt.static_optimization(arm, q, hand_load=[0, -3000, 0], backend="cpp")
    so = armrt.StaticOptimizer(arm, backend="cpp")
    so.solve(q, hand_load=[0, -3000, 0], on_infeasible="return")
    r = so.solve(q, hand_load=[0, -9.81, 0])
    tau, tau_req = _elastic_moments(arm, q, np.zeros(5), np.zeros(5), [0, -9.81, 0], r.activation)
    assert r.feasible and np.abs(tau - tau_req).max() < 1e-6


def _record_cpp_reports(so):
    """The C++ workspace's report dict of every solve of so (backend "cpp"), appended to the list returned."""
    reports = []

    class Recording:
        def __init__(self, ws):
            self.ws = ws

        def solve(self, *args):
            a, r = self.ws.solve(*args)
            reports.append(r)
            return a, r

    so._cpp = Recording(so._cpp)
    return reports


def test_cpp_elastic_sqp_takes_an_elastic_step_where_its_linearisation_is_infeasible():
    """das3 along bench.static_optimization's motion (tests/static_optimization_motions.py): where the QP linearised
    about the previous frame's activations has no solution (frame 49), the C++ SQP steps to its closest moments
    (elastic_mode_steps) and converges, as the Python path does, instead of handing the frame to Python; the
    moments balance through the engine's element."""
    arm = armrt.Arm("das3")
    arm.settle()
    q, qd, qdd = das3_motion(arm)
    hand = [0.0, -9.81, 0.0]
    so = armrt.StaticOptimizer(arm, backend="cpp")
    reports = _record_cpp_reports(so)
    so._solve_python = lambda *a, **k: pytest.fail("an elastic frame went to the Python path")
    activations = []
    for k in range(len(q)):
        res = so.solve(q[k], qd[k], qdd[k], hand)
        assert res.feasible and reports[-1]["feasible"], k
        activations.append(res.activation)
    steps = [r["elastic_mode_steps"] for r in reports]
    assert steps[49] >= 1, steps
    tau, tau_req = _elastic_moments(arm, q[49], qd[49], qdd[49], hand, activations[49])
    assert np.abs(tau - tau_req).max() < 1e-6


def test_cpp_elastic_sqp_stops_early_on_frames_out_of_the_muscles_reach():
    """das2 along a motion too fast for its elastic elements (tests/static_optimization_motions.py): the C++ SQP
    reports the frames from 28 on not converged after a few QPs and elastic-mode steps (each step must halve the
    moment residual), and the Python path then reports them infeasible with elements at their upper bound."""
    arm = armrt.Arm("das2")
    q, qd, qdd = das2_fast_motion(arm)
    so = armrt.StaticOptimizer(arm, backend="cpp")
    reports = _record_cpp_reports(so)
    infeasible = []
    for k in range(70):
        res = so.solve(q[k], qd[k], qdd[k], on_infeasible="return")
        if not reports[-1]["feasible"]:
            infeasible.append(k)
            assert reports[-1]["qps"] <= 8 and reports[-1]["elastic_mode_steps"] <= 4, (k, reports[-1]["qps"])
            assert not res.feasible and res.at_upper_bound, (k, res.report)
    assert len(infeasible) >= 30 and infeasible[-1] == 69, infeasible


def test_cpp_solve_refuses_an_unknown_tendon():
    arm = armrt.Arm("das2")
    ws = _core.StaticOptimizationWorkspace(arm._sim, 0.0, None, 24)
    z = np.zeros(5)
    with pytest.raises(ValueError, match="tendon must be"):
        ws.solve(arm._sim, z, z, z, np.zeros(3), np.zeros(3), "compliant")
