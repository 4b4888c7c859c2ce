"""The Python API: names, inputs, state views, simulate, results, and every bad-input path."""
import math
import warnings

import numpy as np
import pytest

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")


@pytest.mark.parametrize("model", ["das2", "das3"])
def test_the_outputs_docstring_names_every_key_with_its_shape(model):
    """A new user found muscle_torque in outputs() but not in its docstring ("torques"). One text serves Arm.outputs
    and Data.outputs; it names every key the engine returns (the layout table's rows and the derived ones), and
    says each array's shape where it gives one."""
    import re
    from armrt.data import OUTPUTS_DOC
    arm = armrt.Arm(model)
    data = armrt.Data(arm.model)
    assert armrt.Arm.outputs.__doc__ == armrt.Data.outputs.__doc__ == OUTPUTS_DOC
    n, ndof = arm.model.n_elements, arm.model.n_dofs
    words = set(re.findall(r"[a-z_]+", OUTPUTS_DOC))
    for outputs in (arm.outputs(), data.outputs()):
        missing = sorted(set(outputs) - words)
        assert not missing, missing
        for key, value in outputs.items():
            said = re.search(re.escape(key) + r" \(([^)]*)\)", OUTPUTS_DOC)
            if said and re.fullmatch(r"[\w, ]+,?", said.group(1)):
                shape = tuple(int(eval(dim, {"n": n, "ndof": ndof})) for dim in said.group(1).rstrip(",").split(","))
                assert np.shape(value) == shape, (key, np.shape(value), shape)


def test_a_radian_pose_just_beyond_its_range_is_not_called_degrees():
    """GHy = 1.4 rad (0.4 rad beyond its range) got 'These look like degrees' (a new user's trial through
    UdpClient.send_target): with the 0.35 rad margin, np.radians of almost any radian pose is in range. The hint
    now also needs a value beyond a full turn, which degrees give and radians of a joint do not."""
    arm = armrt.Arm("das2")
    q = arm.rest_posture.copy()
    q[0] = 1.4
    with pytest.raises(ValueError, match="q beyond the joint limits") as err:
        arm.reset(q=q)
    assert "look like degrees" not in str(err.value)
    with pytest.raises(ValueError, match="These look like degrees"):
        arm.reset(q=np.degrees(arm.rest_posture))


def test_names(arm):
    assert arm.dof_names == ["GHy", "GHz", "GHyy", "ELx", "PSy"]
    assert len(arm.element_names) == 102 and len(arm.muscle_names) == 22
    assert arm.element_names[0] == "deltscap1" and arm.element_names[-1] == "anconeus5"
    assert "rotator_cuff" in arm.group_names
    cuff = arm.indices("rotator_cuff")
    assert sorted(cuff) == sorted(arm.indices("infra") + arm.indices("termin") + arm.indices("supra") + arm.indices("subscap"))
    assert len(arm.indices("deltscap")) == 11 and arm.indices("bicl") == [arm.element_names.index("bicl")]


def test_set_excitation_by_array_dict_and_scalar(arm):
    arm.set_excitation(np.full(102, 0.25))
    assert np.all(arm.excitation == 0.25)
    arm.set_excitation({"rotator_cuff": 0.05, "bicb": 0.3, "deltscap3": 0.7})
    u = arm.excitation
    assert np.all(u[arm.indices("infra")] == 0.05)
    assert np.all(u[arm.indices("bicb")] == 0.3) and u[arm.element_names.index("deltscap3")] == 0.7
    assert u[arm.element_names.index("deltscap1")] == 0.0
    arm.set_excitation(0.1)
    assert np.all(arm.excitation == 0.1)


def test_bad_excitation(arm):
    with pytest.raises(ValueError, match="NaN"):
        arm.set_excitation(np.r_[np.full(101, 0.1), np.nan])
    with pytest.raises(ValueError, match="NaN"):
        arm.set_excitation({"bicb": float("inf")})
    with pytest.raises(ValueError, match=r"shape \(102,\)"):
        arm.set_excitation(np.zeros(5))
    with pytest.raises(KeyError, match="did you mean 'bicb'"):
        arm.set_excitation({"bicbb": 0.1})
    with pytest.raises(KeyError, match="unknown element, muscle or group name 'zzz'"):
        arm.set_excitation({"zzz": 0.1})
    with pytest.raises(TypeError, match="must be a number, got the string 'lots'"):
        arm.set_excitation({"bicb": "lots"})
    with pytest.warns(RuntimeWarning, match="clipped"):
        arm.set_excitation({"bicb": 1.5, "bicl": -0.2})
    assert arm.excitation[arm.indices("bicb")].max() == 1.0 and arm.excitation[arm.indices("bicl")][0] == 0.0


def test_constructor_errors():
    with pytest.raises(ValueError, match="unknown integrator 'rk5'"):
        armrt.Arm(integrator="rk5")
    with pytest.raises(ValueError, match="dt must be a positive"):
        armrt.Arm(dt=0.0)
    with pytest.raises(ValueError, match="dt must be a positive"):
        armrt.Arm(dt=float("nan"))
    with pytest.raises(ValueError, match="unknown model 'das9'.*das2"):
        armrt.Arm(model="das9")


def test_state_views_are_zero_copy_and_read_only(arm):
    q = arm.q
    before = q.copy()
    arm.step(20)
    assert not np.array_equal(q, before), "the view follows the simulation"
    with pytest.raises(ValueError):
        q[0] = 1.0
    assert arm.lce.shape == (102,) and arm.activation.shape == (102,) and arm.qdot.shape == (5,)


def test_reset(arm):
    q0 = np.array([0.3, 0.4, 0.2, 1.0, 1.2])
    arm.reset(q=q0, activation={"rotator_cuff": 0.05})
    assert np.array_equal(arm.q, q0) and np.all(arm.qdot == 0) and arm.time == 0.0
    assert np.all(arm.activation[arm.indices("rotator_cuff")] == 0.05)
    # The contractile elements start in static equilibrium: no CE velocity at t = 0.
    assert np.max(np.abs(arm.outputs()["fibre_velocity"])) < 1e-6
    arm.reset(q={"ELx": 1.5})
    assert arm.q[3] == 1.5 and arm.q[0] == pytest.approx(arm.rest_posture[0])
    with pytest.raises(ValueError, match=r"q must have shape \(5,\)"):
        arm.reset(q=[0.1, 0.2])
    with pytest.raises(KeyError, match="unknown DOF 'EL'"):
        arm.reset(q={"EL": 1.0})
    with pytest.raises(ValueError, match="NaN"):
        arm.reset(qdot=[0, 0, np.nan, 0, 0])


def test_simulate_returns_consistent_time_series(arm):
    res = arm.simulate({"elbow_flexors": 0.2}, duration=0.05)
    T = 51
    assert res.time.shape == (T,) and res.q.shape == (T, 5) and res.muscle_force.shape == (T, 102)
    assert res.gh_force.shape == (T, 3) and res.hand_position.shape == (T, 3) and res.thorax_humerus.shape == (T, 3)
    assert np.allclose(np.diff(res.time), 1e-3)
    assert res.time[-1] == pytest.approx(0.05) and arm.time == pytest.approx(0.05)
    assert np.array_equal(res.q[-1], arm.q)
    assert np.all(res.tet_ns[:-1] > 0)
    assert np.all(res.excitation[:, arm.indices("bicb")] == 0.2)


def test_simulate_with_array_and_callable_agree(arm):
    n = 40
    u = np.zeros((n, 102))
    u[n // 2:, arm.indices("brachialis")] = 0.4
    a = arm.simulate(u, duration=n * arm.dt)
    arm.reset()
    b = arm.simulate(lambda t: {"brachialis": 0.4 if t >= 0.0195 else 0.0}, duration=n * arm.dt)
    assert np.array_equal(a.q, b.q)


def test_simulate_callable_arrays_checked_per_block_as_per_step(arm):
    # A callable returning float arrays takes simulate()'s block check; dicts, scalars and other dtypes the per-step
    # one: both give the same run, the same clipping and errors that name the step and element.
    n = 30
    u = np.zeros((n, 102))
    u[:, arm.indices("brachialis")] = 0.4
    u[n // 2:, arm.indices("tric_long")] = 1.3   # clipped to 1
    rows = iter(range(n))

    def mixed(t):
        k = next(rows)
        v = u[k].copy()
        return v if k % 3 else {name: v[i] for i, name in enumerate(arm.element_names) if v[i]}  # dict: slow path
    with pytest.warns(RuntimeWarning, match="clipped"):
        a = arm.simulate(u, duration=n * arm.dt)
    arm.reset()
    with pytest.warns(RuntimeWarning, match="clipped"):
        b = arm.simulate(mixed, duration=n * arm.dt)
    assert np.array_equal(a.q, b.q) and np.array_equal(a.excitation, b.excitation)
    assert b.excitation[:, arm.indices("tric_long")].max() == 1.0
    arm.reset()

    def nan_at_step_12(t):
        v = np.zeros(102)
        if round(t / arm.dt) == 12:
            v[5] = np.inf
        return v
    with pytest.raises(ValueError, match=rf"first at step 12, element {arm.element_names[5]}, t = 0.012 s"):
        arm.simulate(nan_at_step_12, duration=0.03)
    arm.reset()
    with pytest.raises(ValueError, match=r"shape \(102,\)"):
        arm.simulate(lambda t: np.zeros(101), duration=0.01)
    c = arm.simulate(lambda t: np.full(102, 0.2, dtype=np.float32), duration=0.01)  # not float64: per step
    assert np.allclose(c.excitation, 0.2)


def test_simulate_bad_input(arm):
    with pytest.raises(ValueError, match=r"shape \(40, 102\)"):
        arm.simulate(np.zeros((39, 102)), duration=0.04)
    bad = np.zeros((40, 102))
    bad[7, 3] = np.nan
    with pytest.raises(ValueError, match="first at step 7, element deltscap4"):
        arm.simulate(bad, duration=0.04)
    with pytest.raises(ValueError, match="duration"):
        arm.simulate(0.0, duration=-1)
    with pytest.raises(ValueError, match="NaN"):
        arm.simulate(lambda t: np.full(102, np.nan), duration=0.01)


def test_divergence_is_reported_not_returned(arm):
    arm._sim.max_joint_speed = 1e-6
    with pytest.raises(armrt.SimulationError, match=r"qdot\[\w+\] = .* exceeds the bound .* at t = "):
        arm.step(10)
    with pytest.raises(armrt.SimulationError, match="call reset"):
        arm.simulate(0.0, duration=0.01)
    arm._sim.max_joint_speed = 100.0
    arm.reset()
    arm.step(10)


def test_result_save_and_load(arm, tmp_path):
    res = arm.simulate({"triceps": 0.1}, duration=0.02)
    res.save(tmp_path / "r.npz")
    back = armrt.Result.load(tmp_path / "r.npz")
    for k in armrt.Result.ARRAYS:
        assert np.array_equal(getattr(back, k), getattr(res, k))
    assert back.element_names == arm.element_names and back.integrator == "rk4" and back.dt == 1e-3
    np.savez(tmp_path / "other.npz", a=np.zeros(3))
    with pytest.raises(ValueError, match="not an armrt result"):
        armrt.Result.load(tmp_path / "other.npz")


def test_moment_arms_are_minus_length_gradient(arm):
    q = np.array([0.5, 0.6, 0.1, 1.2, 1.0])
    R = arm.moment_arms(q)
    assert R.shape == (102, 5)
    h = 1e-6
    for j in range(5):
        dq = np.zeros(5)
        dq[j] = h
        fd = -(arm.muscle_lengths(q + dq) - arm.muscle_lengths(q - dq)) / (2 * h)
        assert np.allclose(R[:, j], fd, atol=1e-8)
    # Elements not crossing a DOF have no moment arm about it.
    for i, e in enumerate(arm.info["elements"]):
        for j in set(range(5)) - set(e["dofs"]):
            assert R[i, j] == 0.0


def test_gh_directions_unit_for_gh_elements(arm):
    d = arm.gh_directions(arm.rest_posture)
    crosses = np.array([e["crosses_gh"] for e in arm.info["elements"]])
    assert np.allclose(np.linalg.norm(d[crosses], axis=1), 1.0)
    assert np.all(d[~crosses] == 0.0)


def test_gh_stability_values(arm):
    n = np.array(arm.info["glenoid_normal"])
    major = np.array(arm.info["glenoid_major_axis"])
    minor = np.array(arm.info["glenoid_minor_axis"])
    assert arm.gh_stability(100 * n)[2] == pytest.approx(0.0, abs=1e-12)
    ta, pa = arm.info["rim_half_angle_major"], arm.info["rim_half_angle_minor"]
    assert arm.gh_stability(math.cos(ta) * n + math.sin(ta) * major)[2] == pytest.approx(1.0)
    assert arm.gh_stability(math.cos(pa) * n - math.sin(pa) * minor)[2] == pytest.approx(1.0)
    assert arm.gh_stability(math.cos(1.2 * ta) * n + math.sin(1.2 * ta) * major)[2] > 1.0
    with pytest.raises(ValueError):
        arm.gh_stability([1.0, np.nan, 0.0])


def test_strength_and_max_activation(arm):
    q = arm.rest_posture
    arm.reset(activation={"bicb": 0.5})
    f_full = arm.outputs()["muscle_force"][arm.indices("bicb")]
    arm.strength = {"bicb": 0.5}
    assert np.all(arm.strength[arm.indices("bicb")] == 0.5) and arm.strength[0] == 1.0
    arm.reset(q=q, activation={"bicb": 0.5})
    f_weak = arm.outputs()["muscle_force"][arm.indices("bicb")]
    assert np.allclose(f_weak, 0.5 * f_full, rtol=0.05)
    # Paralysis: excitation has no effect on activation.
    arm.max_activation = {"brachialis": 0.0}
    arm.reset()
    arm.set_excitation({"brachialis": 1.0})
    arm.step(50)
    assert np.all(arm.activation[arm.indices("brachialis")] == 0.0)
    with pytest.raises(ValueError, match=r"max_activation must lie in \[0.0, 1.0\]"):
        arm.max_activation = {"bicb": 1.5}
    with pytest.raises(ValueError, match="strength must lie"):
        arm.strength = -1.0


def test_hand_load(arm):
    arm.set_hand_load(force=(0, -20.0, 0))
    out = arm.outputs()
    assert np.any(np.abs(out["external_torque"]) > 0.5)
    with pytest.raises(ValueError, match=r"hand force must have shape \(3,\)"):
        arm.set_hand_load(force=(0, 1))
    with pytest.raises(ValueError, match="hand moment contains NaN"):
        arm.set_hand_load(moment=(0, np.nan, 0))


def test_step_counts_and_tet(arm):
    arm.step(25)
    tet = arm.tet
    assert tet["count"] == 25 and 0 < tet["min_ns"] <= tet["mean_ns"] <= tet["max_ns"]
    assert arm.time == pytest.approx(0.025)
    with pytest.raises(ValueError):
        arm.step(-1)


def test_degree_helpers():
    assert armrt.deg(math.pi) == pytest.approx(180.0)
    assert np.allclose(armrt.rad(np.array([90.0, 180.0])), [math.pi / 2, math.pi])


def test_thorax_humerus_angles(arm):
    # Hanging arm: small elevation; at GHz raised, elevation grows.
    rest = arm.thorax_humerus_angles(arm.rest_posture)
    q = arm.rest_posture.copy()
    q[1] += 0.5
    raised = arm.thorax_humerus_angles(q)
    assert raised[1] > rest[1]
    assert 0.0 <= rest[1] <= math.pi


@pytest.mark.parametrize("integrator,dt", [("euler", 2e-4), ("rk4", 1e-3), ("cvode", 1e-3)])
def test_integrators_run(integrator, dt):
    a = armrt.Arm(integrator=integrator, dt=dt)
    res = a.simulate({"elbow_flexors": 0.3, "rotator_cuff": 0.05}, duration=0.2)
    assert np.all(np.isfinite(res.q)) and a.integrator == integrator


def test_simulate_into_storage_refuses_rows_that_do_not_fit(arm):
    # The binding leaves this check to the engine (recorder.cc): it must still refuse, before stepping.
    sim = arm._sim
    out = {k: np.zeros(shape) for k, shape in sim.recording_shapes(5).items()}
    u = np.zeros((1, 102))
    t0 = arm.time
    with pytest.raises(ValueError, match="7 rows to record, room for 3"):   # 6 steps: their 6 starts and the end
        sim.simulate(u, 6, 1, out=out, row=2)
    assert arm.time == t0
    done = sim.simulate(u, 2, 1, out=out, row=2)
    assert done == {"steps": 2, "rows": 3}
    with pytest.raises(ValueError, match="row outside"):
        sim.simulate(u, 1, 1, out=out, row=6)
