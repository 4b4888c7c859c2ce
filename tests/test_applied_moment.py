"""Applied joint moments (Arm.set_applied_moment; MuJoCo's qfrc_applied): what the equations of motion see, checked
against the hand-load stage (a hand force's J^T F applied as joint moments moves the joints identically), kept by
snapshots, in the linearisation's step, in ArmBatch as in Arm, and refused when malformed."""
import numpy as np
import pytest

import armrt
from armrt.data import State


def _moving_das2():
    arm = armrt.Arm("das2")
    arm.reset()
    arm.set_excitation({"bicl": 0.4, "tric_long": 0.2, "delt_clav": 0.3})
    for _ in range(30):
        arm.step()
    return arm


def test_a_hand_force_and_its_generalised_forces_as_applied_moments_move_the_joints_alike():
    loaded, applied = _moving_das2(), _moving_das2()
    loaded.set_hand_load(force=(4.0, -12.0, 3.0), moment=(0.3, 0.0, -0.2))
    tau_ext = loaded.outputs()["external_torque"].copy()
    assert np.abs(tau_ext).max() > 1.0  # a load the joints feel
    applied.set_applied_moment(tau_ext)
    out = applied.outputs()
    assert np.all(out["external_torque"] == 0.0)
    np.testing.assert_allclose(out["qddot"], loaded.outputs()["qddot"], rtol=1e-12, atol=1e-9)
    # Over steps, re-applied at each step's start: the hand load's J(q)^T F follows q inside the step too (ROS2's
    # second stage and its Jacobian see it), the applied moment is held, so they part by the step's O(h^2)
    # change of J^T F: 1.5e-5 rad in 50 ms of this motion (measured), not a bit-level identity.
    for _ in range(50):
        applied.set_applied_moment(loaded.outputs()["external_torque"])
        loaded.step()
        applied.step()
    np.testing.assert_allclose(applied.q, loaded.q, rtol=0, atol=1e-4)
    free = _moving_das2()
    for _ in range(50):
        free.step()
    assert np.abs(free.q - loaded.q).max() > 1e-2  # the load itself moved the arm 100 times more


def test_applied_moments_give_qddot_plus_m_inverse_a():
    arm = _moving_das2()
    q = arm.q.copy()
    before = arm.outputs()["qddot"].copy()
    a = np.array([0.5, -0.3, 0.2, 1.0, -0.1])
    arm.set_applied_moment(a)
    after = arm.outputs()["qddot"]
    np.testing.assert_allclose(after - before, np.linalg.solve(arm.mass_matrix(q), a), rtol=1e-9, atol=1e-9)


def test_names_zero_and_errors():
    arm = armrt.Arm("das2")
    arm.set_applied_moment({"ELx": 1.5})
    assert arm.applied_moment.tolist() == [0, 0, 0, 1.5, 0]
    arm.set_applied_moment(0)
    assert not arm.applied_moment.any()
    with pytest.raises(KeyError, match="unknown DOF.*'EL'.*GHy, GHz, GHyy, ELx, PSy"):
        arm.set_applied_moment({"EL": 1.0})
    with pytest.raises(ValueError, match=r"shape \(5,\)"):
        arm.set_applied_moment([1.0, 2.0])
    with pytest.raises(ValueError, match="NaN or infinite.*ELx"):
        arm.set_applied_moment({"ELx": np.inf})
    assert not arm.applied_moment.any()  # refused inputs change nothing


def test_a_state_keeps_the_applied_moments_and_an_older_state_restores_none():
    arm = _moving_das2()
    arm.set_applied_moment({"ELx": -2.0, "GHy": 0.7})
    state = arm.get_state()
    assert state.applied_moment.tolist() == [0.7, 0, 0, -2.0, 0]
    other = armrt.Arm("das2")
    other.set_state(state)
    assert other.applied_moment.tolist() == [0.7, 0, 0, -2.0, 0]
    for _ in range(20):
        arm.step()
        other.step()
    assert np.array_equal(arm.q, other.q)
    # A State saved before applied moments existed has none: restored as zero.
    d = state.as_dict()
    d["applied_moment"] = np.zeros(0)
    other.set_state(State(**d))
    assert not other.applied_moment.any()
    flat = arm.get_state_vector(armrt.StatePart.APPLIED_MOMENT)
    assert flat.tolist() == [0.7, 0, 0, -2.0, 0]


def test_the_linearisation_steps_with_the_applied_moments():
    arm = _moving_das2()
    arm.set_applied_moment({"ELx": 3.0, "GHz": -1.0})
    lin = arm.linearize()
    x0 = arm.get_state_vector(armrt.StatePart.PHYSICS)
    arm.set_state_vector(x0, armrt.StatePart.PHYSICS)  # a state set from outside, as linearize steps it
    arm.step()
    np.testing.assert_allclose(lin.x0_next, arm.get_state_vector(armrt.StatePart.PHYSICS), rtol=0, atol=1e-12)


def test_arm_batch_applies_per_arm_moments_as_arm_does():
    moments = np.array([[0.0, 0.0, 0.0, 1.0, 0.0], [0.5, -0.5, 0.0, -1.0, 0.2]])
    batch = armrt.ArmBatch(2, "das2", threads=1)
    batch.reset()
    batch.set_applied_moment(moments)
    arms = [armrt.Arm("das2") for _ in range(2)]
    for arm, a in zip(arms, moments):
        arm.reset()
        arm.set_applied_moment(a)
    for _ in range(100):
        batch.step()
        for arm in arms:
            arm.step()
    for k, arm in enumerate(arms):
        assert np.array_equal(batch.q[k], arm.q)
    assert np.array_equal(batch.applied_moment, moments)
    with pytest.raises(ValueError, match=r"shape \(2, 5\) or \(5,\)"):
        batch.set_applied_moment(np.zeros((3, 5)))


def test_an_arm_data_and_state_pickled_before_applied_moments_load_with_none():
    """Pickles of 2026-12-02 .. 2026-12-03 hold a full snapshot without the applied_moment row, and States without
    the field: they load, with the applied moment zero and everything else as it was."""
    import pickle

    from armrt.arm import _unpickle_arm
    from armrt.data import _unpickle_data
    arm = _moving_das2()
    arm.set_applied_moment({"ELx": 1.0})
    settings, snapshot = arm._snapshot()
    cut = arm.state_vector_slices()["applied_moment"]
    old = np.delete(snapshot, np.arange(cut.start, cut.stop))
    loaded = _unpickle_arm(armrt.Arm, arm.model, settings, old, {})
    assert not loaded.applied_moment.any()
    assert np.array_equal(loaded.q, arm.q) and np.array_equal(loaded.lce, arm.lce)
    assert np.array_equal(loaded.excitation, arm.excitation)
    data = _unpickle_data(arm.model, settings, old)
    assert not data.applied_moment.any() and np.array_equal(data.q, arm.q)
    with pytest.raises(ValueError, match="expected"):
        _unpickle_data(arm.model, settings, old[:-1])   # any other length is still refused
    state = arm.get_state()
    fields = dict(state.__dict__)
    for k in ("applied_moment", "stimulation", "stimulation_state"):
        del fields[k]
    old_state = State.__new__(State)
    old_state.__setstate__(fields)          # what unpickling an older State does
    restored = pickle.loads(pickle.dumps(old_state))
    assert restored.applied_moment.size == 0 and not restored.applied_moment.flags.writeable
    other = armrt.Arm("das2")
    other.set_applied_moment({"GHy": 2.0})
    other.set_state(restored)
    assert not other.applied_moment.any() and np.array_equal(other.q, arm.q)


def test_scalar_zero_and_per_arm_errors():
    arm = armrt.Arm("das2")
    arm.set_applied_moment({"ELx": 1.0})
    arm.set_applied_moment(np.array(0.0))
    assert not arm.applied_moment.any()
    with pytest.raises(ValueError, match="a single number must be 0"):
        arm.set_applied_moment(2.0)
    batch = armrt.ArmBatch(3, "das2", threads=1)
    bad = np.zeros((3, 5))
    bad[2, 3] = np.nan
    with pytest.raises(ValueError, match="of arm 2 contains NaN.*ELx"):
        batch.set_applied_moment(bad)
    assert not batch.applied_moment.any()


def test_arm_batch_outputs_follow_a_change_between_steps():
    """After set_applied_moment or set_hand_load between steps, ArmBatch's outputs describe the changed arm, as
    Arm.outputs() does (they were the outputs before the change until the next step)."""
    batch = armrt.ArmBatch(2, "das2", threads=1)
    batch.reset()
    batch.step(10)
    arm = armrt.Arm("das2")
    arm.reset()
    arm.step(10)
    view = batch.qddot
    batch.set_applied_moment({"ELx": 2.0})
    arm.set_applied_moment({"ELx": 2.0})
    np.testing.assert_array_equal(batch.outputs()["qddot"][1], arm.outputs()["qddot"])
    np.testing.assert_array_equal(view[0], arm.outputs()["qddot"])   # a view taken before is updated in place
    batch.set_hand_load(force=(0.0, 0.0, -20.0))
    arm.set_hand_load(force=(0.0, 0.0, -20.0))
    np.testing.assert_array_equal(batch.gh_force[0], arm.outputs()["gh_force"])


def test_opensim_coordinate_names_are_accepted_once_per_dof():
    """set_applied_moment's dict takes the OpenSim coordinate names (EL_x) as Arm.dof_index does; one DOF named
    twice (ELx and EL_x) is refused, an unknown name is a KeyError naming the DOFs."""
    arm = armrt.Arm("das2")
    arm.set_applied_moment({"EL_x": 1.5, "GHy": -0.5})
    np.testing.assert_array_equal(arm.applied_moment, [-0.5, 0, 0, 1.5, 0])
    with pytest.raises(ValueError, match="both name DOF ELx"):
        arm.set_applied_moment({"EL_x": 1.0, "ELx": 2.0})
    with pytest.raises(KeyError, match="unknown DOF.*EL_y.*OpenSim coordinate names"):
        arm.set_applied_moment({"EL_y": 1.0})
    np.testing.assert_array_equal(arm.applied_moment, [-0.5, 0, 0, 1.5, 0])  # a refused call changes nothing
    batch = armrt.ArmBatch(2, "das2")
    batch.set_applied_moment({"PS_y": 0.25})
    np.testing.assert_array_equal(batch.applied_moment, [[0, 0, 0, 0, 0.25]] * 2)
