"""The C++ static optimisation (cpp/src/static_optimization.cc, StaticOptimizer(backend="cpp")) against the
Python path's ProxQP solve of the same rigid-tendon QP (backend="python"): same activations to the solvers'
tolerance at random das2 states, moments balanced, GHstab within its bound, infeasible requests reported with the
same closest solution, the GH polygon the same rows (docs/control.md)."""
import numpy as np
import pytest

import armrt
from armrt import _core
from armrt.control import gh_polygon


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


def test_auto_backend_is_cpp_for_the_rigid_tendon_only():
    arm = armrt.Arm("das2")
    assert armrt.StaticOptimizer(arm, tendon="rigid").backend == "cpp"
    assert armrt.StaticOptimizer(arm.model, tendon="rigid").backend == "cpp"
    assert armrt.StaticOptimizer(arm).backend == "python"  # elastic
    assert armrt.StaticOptimizer(arm, tendon="rigid", criterion="cubed").backend == "python"
    with pytest.raises(ValueError, match="rigid tendon with squared"):
        armrt.StaticOptimizer(arm, backend="cpp")
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
