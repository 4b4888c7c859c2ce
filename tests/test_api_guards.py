"""Guards of the Python API that cannot be sidestepped (issue 25, B2 and B4): arm.data goes through the
Arm's one-thread guard, armrt.ConcurrentUseError is exported, the control step and substep count are
bounded, set_state checks q as reset does, and masked arrays are refused wherever arrays come in."""
from __future__ import annotations

import copy
import dataclasses
import threading
import warnings

import numpy as np
import pytest

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")


# ------------------------------------------------------------------------------------ B2: one thread
def test_concurrent_use_error_is_exported():
    """The README names armrt.ConcurrentUseError; it is the class the guard raises."""
    assert armrt.ConcurrentUseError is armrt.arm.ConcurrentUseError
    assert "ConcurrentUseError" in armrt.__all__ and issubclass(armrt.ConcurrentUseError, RuntimeError)


def _while_simulating(arm, calls):
    """Runs each call on this thread while another thread is inside arm.simulate(); returns what each
    raised (None if it returned), and the run's Result."""
    inside, release = threading.Event(), threading.Event()
    out = {}

    def excitation(t):
        if t == 0.0:
            inside.set()
            release.wait(5.0)
        return {"bicb": 0.3}

    worker = threading.Thread(target=lambda: out.setdefault("res", arm.simulate(excitation, 0.02)))
    worker.start()
    assert inside.wait(5.0)
    raised = []
    try:
        for call in calls:
            try:
                call()
                raised.append(None)
            except Exception as exc:  # noqa: BLE001 (what each raised is the result)
                raised.append(exc)
    finally:
        release.set()
        worker.join()
    return raised, out["res"]


def test_arm_data_goes_through_the_arms_guard():
    """arm.data.outputs() evaluates into the workspace the stepping thread is using and set_state
    writes its state: from a second thread they raise ConcurrentUseError, as the Arm's own methods do,
    and the run finishes undisturbed."""
    arm = armrt.Arm(integrator="rk4")
    state = arm.get_state()
    d = arm.data
    calls = [d.outputs, d.get_state, lambda: d.set_state(state), lambda: copy.deepcopy(d), lambda: d.excitation,
             lambda: d.hand_force, lambda: d.hand_moment, lambda: d.time]
    raised, res = _while_simulating(arm, calls)
    for call, exc in zip(["outputs", "get_state", "set_state", "deepcopy", "excitation", "hand_force",
                          "hand_moment", "time"], raised):
        assert isinstance(exc, armrt.ConcurrentUseError), f"arm.data.{call} from a second thread: {exc!r}"
        assert "another thread" in str(exc)
    ref = armrt.Arm(integrator="rk4").simulate({"bicb": 0.3}, 0.02)
    assert np.array_equal(res.q, ref.q)


def test_data_on_the_stepping_thread_is_not_refused():
    """The guard is per thread: a callback of simulate() may read arm.data (re-entrant)."""
    arm = armrt.Arm(integrator="rk4")
    seen = []

    def excitation(t):
        seen.append(arm.data.get_state().time)
        arm.data.outputs()
        return 0.1
    arm.simulate(excitation, 0.005)
    assert len(seen) == 5


# ------------------------------------------------------------------------------------ B4: bounds
def test_control_step_is_bounded():
    """dt is the period the excitation is held for: above MAX_DT (1 s, 25 deactivation time constants)
    nothing is being controlled, and Arm(dt=1e6) meant 999 999 000 substeps per step()."""
    with pytest.raises(ValueError, match=r"dt must be .*at most 1 s.*got 1e\+06"):
        armrt.Arm(dt=1e6)
    with pytest.raises(ValueError, match=r"dt must be .*at most 1 s"):
        armrt.ArmBatch(2, dt=2.0, threads=1)
    for dt in (0.0, -1e-3, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="dt must be"):
            armrt.Arm(dt=dt)
    assert armrt.Arm(integrator="euler", dt=1.0).substeps == 10000  # the bound itself, default substeps


def test_substep_count_is_bounded():
    from armrt.integrators import MAX_SUBSTEPS
    with pytest.raises(ValueError, match=rf"substeps must be at most {MAX_SUBSTEPS}.*got 1000000000"):
        armrt.Arm(dt=1e-3, substeps=10**9)
    assert armrt.Arm(integrator="rk4", dt=1e-3, substeps=MAX_SUBSTEPS).substeps == MAX_SUBSTEPS


def test_set_state_checks_q_as_reset_does():
    """A State whose q is far beyond the joint ranges is refused by set_state (Arm and Data alike) by the
    engine's domain check (snapshot_error), degrees hint included; a State slightly beyond them (where a
    simulation can end: the passive limits are springs) is restored without a warning."""
    arm = armrt.Arm()
    s = arm.get_state()
    far = dataclasses.replace(s, q=s.q + 100.0)
    with pytest.raises(ValueError, match=r"State.q\[GHy\] = 100.4 rad is more than 0.35 rad beyond its range"):
        arm.set_state(far)
    with pytest.raises(ValueError, match=r"State.q\[GHy\] = 100.4 rad"):
        arm.data.set_state(far)
    with pytest.raises(ValueError, match="these values look like degrees"):
        arm.set_state(dataclasses.replace(s, q=np.degrees(s.q)))
    assert arm.get_state() == s, "nothing was written"
    hi = arm.dof_ranges[:, 1]
    near = dataclasses.replace(s, q=np.where(np.arange(arm.n_dofs) == 3, hi + 0.05, s.q))
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        arm.set_state(near)
    assert arm.q[3] == hi[3] + 0.05


MASKED = np.ma.masked_array([0.1, 0.2, 0.3, 0.4, 0.5], mask=[0, 0, 1, 0, 0])


@pytest.mark.parametrize("call", [
    lambda arm: arm.reset(q=MASKED),
    lambda arm: arm.reset(qdot=MASKED),
    lambda arm: arm.set_hand_load(force=MASKED[:3]),
    lambda arm: arm.set_excitation(np.ma.masked_array(np.full(102, 0.2), mask=np.arange(102) == 7)),
    lambda arm: arm.set_excitation({"bicb": np.ma.masked}),
    lambda arm: arm.reset(q=[np.ma.masked_array([0.1, 0.2], mask=[0, 1]), np.zeros(3)]),
    lambda arm: arm.model.moment_arms(MASKED),
    lambda arm: arm.simulate(0.0, np.ma.masked_array(0.01, mask=True)),
], ids=["q", "qdot", "hand_force", "excitation", "dict_value", "nested", "model_q", "duration"])
def test_masked_arrays_are_refused(call):
    """np.asarray drops a mask and uses the values under it: refused in the one input check (real_array)."""
    arm = armrt.Arm()
    with pytest.raises(ValueError, match="masked array with 1 masked value.*filled"):
        call(arm)


def test_real_array_refuses_bools_where_asked_and_keeps_them_by_default():
    """booleans=False (the control layer's gains, times, postures, weights): a bool, np.bool_, a bool array and a
    Python bool inside an object array are TypeErrors naming the input; by default bools stay numbers (0 and 1), as
    before, for the entry points that did not ask."""
    from armrt import checks
    for bad, match in ((True, "x must be a number, got the bool True"),
                       (np.bool_(False), "x must be a number, got the bool False"),
                       (np.ones(3, bool), r"x must be numbers, got an array of bools \(shape \(3,\)\)"),
                       ([True, False], "x must be numbers, got an array of bools"),
                       # Mixed in a list or tuple (a trial's command_velocity([True, 0, 0]) and a stimulation
                       # (200e-6, 0.01, True) were taken as 1): numpy casts them to integers, so they are looked for.
                       ([True, 0, 0], "x must be numbers, got the bool True among them"),
                       (([0.0, 1.0], (2.0, np.False_)), "x must be numbers, got the bool False among them"),
                       (np.array([1.0, True], dtype=object), "x must be numbers, got the bool True among them")):
        with pytest.raises(TypeError, match=match):
            checks.real_array(bad, "x", booleans=False)
    with pytest.raises(TypeError, match="kp must be a number, got the bool True"):
        checks.real_scalar(True, "kp", booleans=False)
    with pytest.raises(TypeError, match="q must be numbers"):
        checks.dof_vector(np.ones(5, bool), "q", list("abcde"), booleans=False)
    assert checks.real_scalar(True, "x") == 1.0 and checks.real_array([True, False], "x").tolist() == [1.0, 0.0]
    assert checks.real_scalar(np.float32(0.5), "x", booleans=False) == 0.5


def test_an_array_with_nothing_masked_is_accepted():
    arm = armrt.Arm()
    arm.reset(q=np.ma.masked_array(arm.rest_posture, mask=False))
    assert np.array_equal(arm.q, arm.rest_posture)


def test_reset_refuses_a_joint_speed_the_first_step_would_stop_at():
    arm = armrt.Arm()
    with pytest.raises(ValueError, match=r"qdot\[GHy\] = 1e\+06 rad/s is beyond max_joint_speed"):
        arm.reset(qdot=[1e6] * 5)


# ------------------------------------------------------------------- ArmBatch refuses what Arm refuses
DEGREES = np.array([25, 28, 16, 40, 80.0])   # das2's rest posture written in degrees


def test_batch_reset_checks_every_posture_as_arm_reset():
    """Degrees, or a joint far beyond its range, diverged at the next step; each row is now checked by
    checks.joint_range, the error naming the arm."""
    b = armrt.ArmBatch(2, threads=1)
    with pytest.raises(ValueError, match=r"arm 0: q beyond the joint limits.*look like degrees"):
        b.reset(q=DEGREES)
    q = np.tile(b.rest_posture, (2, 1))
    q[1] = b.dof_ranges[:, 1] + 0.3
    with pytest.raises(ValueError, match=r"arm 1: q beyond the joint limits"):
        b.reset(q=q)
    with pytest.raises(ValueError, match=r"arm 1: q beyond the joint limits"):
        b.reset(q=b.dof_ranges[:, 1] + 0.3, arms=[1])
    near = b.rest_posture.copy()
    near[3] = b.dof_ranges[3, 1] + 0.05
    with pytest.warns(RuntimeWarning, match=r"arm 1: q slightly beyond the joint limits"):
        b.reset(q=near, arms=[1])
    assert b.q[1, 3] == near[3]


def test_batch_reset_refuses_non_numbers_and_fractional_arms():
    b = armrt.ArmBatch(2, threads=1)
    with pytest.raises(TypeError, match="q must be real numbers, got complex"):
        b.reset(q=b.rest_posture + 0j)
    with pytest.raises(TypeError, match="qdot must be real numbers"):
        b.reset(qdot=np.zeros(b.n_dofs, dtype=complex))
    with pytest.raises(TypeError, match="activation must be numbers"):
        b.reset(activation="0.1")
    with pytest.raises(TypeError, match="arm indices must be integers"):
        b.reset(arms=[1.5])
    with pytest.raises(TypeError, match="arm indices must be integers"):
        b.reset(arms=["1"])
    b.reset(arms=[])                   # nothing selected: nothing reset
    b.reset(arms=np.array([1], dtype=np.uint8))


def test_batch_reset_checks_the_girdle_contact_as_arm_reset():
    """das3: a posture in range that puts the scapula into the thorax is refused by Arm.reset; ArmBatch
    too, naming the arm."""
    arm = armrt.Arm("das3")
    q = arm.rest_posture.copy()
    q[arm.dof_names.index("SCx")] = arm.dof_ranges[arm.dof_names.index("SCx"), 1]
    with pytest.raises(ValueError, match="into the thorax"):
        arm.reset(q=q)
    b = armrt.ArmBatch(2, "das3", threads=1)
    rows = np.tile(arm.rest_posture, (2, 1))
    rows[1] = q
    with pytest.raises(ValueError, match=r"arm 1: q puts the scapula into the thorax"):
        b.reset(q=rows)


@pytest.mark.parametrize("k, error", [(1.5, TypeError), ("3", TypeError), (2.9, TypeError), (True, TypeError),
                                      (10**30, OverflowError), (-1, ValueError)])
def test_batch_step_counts_as_arm_step(k, error):
    b = armrt.ArmBatch(1, threads=1)
    with pytest.raises(error, match=r"k \(number of steps\)"):
        b.step(k)
    assert b.time[0] == 0.0
    b.step(np.int64(2))
    assert b.time[0] == pytest.approx(2 * b.dt)


@pytest.mark.parametrize("setting", ["excitation", "strength", "max_activation"])
@pytest.mark.parametrize("value, error", [({"bicb": "0.3"}, TypeError), ({"bicb": 0.3j}, TypeError),
                                          ({"bicb": [0.1, 0.2]}, ValueError), ({"bicbb": 0.3}, KeyError),
                                          ([{"bicb": 0.3}, {"bicb": 0.2}], TypeError), ("0.3", TypeError)])
def test_batch_settings_by_name_refuse_what_arm_refuses(setting, value, error):
    """The same helper for both (Arm._named_items, real_array), so the same error and message."""
    arm, b = armrt.Arm(), armrt.ArmBatch(2, threads=1)

    def apply(target):
        if setting == "excitation":
            target.set_excitation(value)
        else:
            setattr(target, setting, value)
    with pytest.raises(error) as from_arm:
        apply(arm)
    with pytest.raises(error) as from_batch:
        apply(b)
    assert str(from_batch.value) == str(from_arm.value)


def test_batch_hand_load_refuses_non_numbers():
    b = armrt.ArmBatch(2, threads=1)
    with pytest.raises(TypeError, match="hand force must be real numbers, got complex"):
        b.set_hand_load(force=[0, 1j, 0])
    with pytest.raises(TypeError, match="hand force must be numbers, got an array of bools"):
        b.set_hand_load(force=[True, False, False])


def test_hand_loads_beyond_any_arm_are_refused_by_arm_and_batch_alike():
    """One bound for every hand load (checks.hand_load: 1e5 N, 1e4 N m): Arm.set_hand_load took 1e7 N, which
    diverged in the first step, and ArmBatch's own rule took it too. The batch names the arm's row."""
    arm = armrt.Arm()
    b = armrt.ArmBatch(2, threads=1)
    for setter in (arm.set_hand_load, b.set_hand_load):
        with pytest.raises(ValueError, match=r"hand force of 1e\+07 N is beyond 1e\+05 N, more than any arm bears"):
            setter(force=[0.0, -1e7, 0.0])
        with pytest.raises(ValueError, match=r"hand moment of 20000 N m is beyond 10000 N m"):
            setter(moment=[2e4, 0.0, 0.0])
        setter(force=[0.0, -1e5, 0.0])  # the bound itself is accepted
    with pytest.raises(ValueError, match=r"hand force \(row 1\) of 2e\+05 N"):
        b.set_hand_load(force=[[0.0, -9.81, 0.0], [0.0, -2e5, 0.0]])
    np.testing.assert_array_equal(np.array(arm._sim.hand_force), [0.0, -1e5, 0.0])
    # One ulp beyond is refused and shown in full (the engine's rule, which armrt-rt applies too).
    with pytest.raises(ValueError, match=r"hand force of 100000.00000000001 N is beyond 1e\+05 N"):
        arm.set_hand_load(force=[0.0, np.nextafter(1e5, 2e5), 0.0])


@pytest.mark.parametrize("part", ["hand_force", "hand_moment"])
def test_a_state_vector_holds_its_hand_load_to_the_same_bound(part):
    """A fifth trial set 1e7 N (and 1e300 N) through set_state_vector's hand_force part, around set_hand_load's
    check: inverse dynamics then returned 1e300 N m and a static optimisation ran for 265 s. The snapshot check
    (the engine's, for Arm and ArmBatch alike) refuses it, nothing written."""
    arm = armrt.Arm()
    x = arm.get_state_vector()
    s = arm.state_vector_slices()[part]
    x[s] = [0.0, 1e7, 0.0]
    before = arm.get_state_vector()
    with pytest.raises(ValueError, match=rf"{part} of 1e\+07 N( m)? is beyond (1e\+05|10000) N"):
        arm.set_state_vector(x)
    np.testing.assert_array_equal(arm.get_state_vector(), before)
    b = armrt.ArmBatch(2, threads=1)
    with pytest.raises(ValueError, match=rf"{part} of 1e\+07 N"):
        b.set_state_vector(x)


# ------------------------------------------------------------------- functions of a pose check q
def _pose_calls():
    m = armrt.Model("das2")
    arm = armrt.Arm()
    calls = {f"Model.{name}": getattr(m, name) for name in ("moment_arms", "muscle_lengths", "gh_directions",
                                                             "mass_matrix", "body_poses", "hand_position",
                                                             "hand_jacobian")}
    calls.update({f"Arm.{name}": getattr(arm, name) for name in ("moment_arms", "muscle_lengths", "gh_directions",
                                                                  "mass_matrix", "girdle_forces",
                                                                  "thorax_humerus_angles")})
    from armrt.geometry import ArmGeometry
    g = ArmGeometry("das2")
    calls.update({f"ArmGeometry.{name}": getattr(g, name) for name in ("points", "body_poses", "gh_lines_of_action",
                                                                        "girdle", "points_series", "girdle_series",
                                                                        "scapula_pose")})
    return calls


POSE_CALLS = _pose_calls()


@pytest.mark.parametrize("name", sorted(POSE_CALLS))
def test_functions_of_a_pose_refuse_q_far_beyond_the_ranges(name):
    """Degrees given as radians: moment arms of -4.7e6 m before; now checks.joint_range's error with its
    degrees hint. In range, and slightly beyond it (a simulated state may be), the values come back."""
    call = POSE_CALLS[name]
    m = armrt.Model("das2")
    with pytest.raises(ValueError, match="q beyond the joint limits.*look like degrees"):
        call(DEGREES)
    with pytest.raises(ValueError, match="q beyond the joint limits"):
        call(np.full(m.n_dofs, 1e3))
    near = m.rest_posture.copy()
    near[3] = m.dof_ranges[3, 1] + 0.05
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        call(near)


@pytest.mark.parametrize("name", ["Model.moment_arms", "Model.hand_position", "ArmGeometry.points_series"])
def test_rows_of_q_are_checked_naming_the_row(name):
    m = armrt.Model("das2")
    rows = np.tile(m.rest_posture, (3, 1))
    rows[2] = DEGREES
    with pytest.raises(ValueError, match=r"q row 2: q beyond the joint limits.*look like degrees"):
        POSE_CALLS[name](rows)
    assert len(POSE_CALLS[name](rows[:2])) == 2


def test_moment_arms_in_range_are_unchanged():
    m = armrt.Model("das2")
    arm = armrt.Arm()
    q = m.rest_posture
    assert np.array_equal(m.moment_arms(q), arm._sim.muscle_paths(q)[1])
    assert np.abs(m.moment_arms(q)).max() < 0.2


# ------------------------------------------------------------------- ArmBatch's memory
def test_batch_too_large_for_memory_says_how_much_it_needs():
    """10**7 arms gave a bare std::bad_alloc; now refused before any allocation, with the bytes per arm
    (the engine's Batch::stride) and the total."""
    per_arm = armrt._batch.ARM_BYTES
    assert per_arm > 1000
    with pytest.raises(MemoryError, match=rf"needs {per_arm} bytes per arm x 10000000 arms = [\d.e+]+ GB.*arms fit"):
        armrt.ArmBatch(10**7)
    with pytest.raises(ValueError, match="at most 2147483647"):
        armrt.ArmBatch(2**31)


def test_batch_memory_check_uses_the_memory_available(monkeypatch):
    from armrt import batch
    monkeypatch.setattr(batch, "available_memory", lambda: 10 * armrt._batch.ARM_BYTES)
    with pytest.raises(MemoryError, match="at most 10 arms fit"):
        armrt.ArmBatch(11)
    assert len(armrt.ArmBatch(10, threads=1)) == 10
    monkeypatch.setattr(batch, "available_memory", lambda: None)   # unknown: not refused
    assert len(armrt.ArmBatch(2, threads=1)) == 2
