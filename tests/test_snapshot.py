"""Snapshots by signature (issue 25): armrt.StatePart comes from the engine's table (layouts.h ARMRT_SNAPSHOT),
armrt.State is the full snapshot, partial vectors set only their parts, the engine checks every snapshot before
writing it (Arm, Data and ArmBatch alike), copies and pickles (old formats included) continue bit for bit, and
the held excitation reads back as the dynamics use it in Arm and ArmBatch alike."""
import copy
import dataclasses
import pickle

import numpy as np
import pytest

import armrt
from armrt import StatePart, _core
from armrt.data import State


def _running_arm(model="das2"):
    arm = armrt.Arm(model)
    arm.set_excitation({"elbow_flexors": 0.4, "deltoid": 0.2})
    arm.set_hand_load(force=(0.0, -3.0, 0.0))
    arm.step(7)
    return arm


def test_state_parts_are_the_engine_table_and_state_holds_them_all():
    rows = _core.snapshot_rows()
    assert [m.name.lower() for m in StatePart if bin(int(m)).count("1") == 1] == [r[0] for r in rows]
    assert int(StatePart.FULL) == (1 << len(rows)) - 1
    assert StatePart.PHYSICS == StatePart.Q | StatePart.QDOT | StatePart.LCE | StatePart.ACTIVATION
    # Every part but ROS2's packed memory is a State field of the same name (the memory is three fields).
    fields = {f.name for f in dataclasses.fields(State)}
    assert {r[0] for r in rows} - {"ros2_path_history"} <= fields
    arm = armrt.Arm()
    where = arm.state_vector_slices(StatePart.FULL)
    assert list(where) == [r[0] for r in rows]
    assert where["ros2_path_history"].stop - where["ros2_path_history"].start == 4 + 2 * arm.n_dofs
    # PHYSICS is the engine's state vector, in its layout.
    np.testing.assert_array_equal(arm.get_state_vector(StatePart.PHYSICS), arm.data.state)


def test_full_vector_and_state_agree_and_partial_vectors_set_their_parts_only():
    arm = _running_arm()
    s = arm.get_state()
    x = arm.get_state_vector()
    where = arm.state_vector_slices()
    for name in ("q", "qdot", "lce", "activation", "excitation", "hand_force", "hand_moment"):
        np.testing.assert_array_equal(x[where[name]], getattr(s, name))
    assert x[where["time"]][0] == s.time
    history = x[where["ros2_path_history"]]
    assert tuple(history[:4]) == (s.previous_step, 2, *s.path_anchor_steps)
    # Inputs only: the state and ROS2's memory stay, so the run continues as it would have.
    ahead = copy.deepcopy(arm)
    ahead.step(20)
    u = arm.get_state_vector(StatePart.INPUTS)
    arm.set_state_vector(u, StatePart.INPUTS)
    assert arm.get_state() == s
    arm.step(20)
    np.testing.assert_array_equal(arm.q, ahead.q)
    # By name, and groups OR-ed.
    qv = arm.get_state_vector("q")
    assert qv.shape == (arm.n_dofs,)
    tq = arm.get_state_vector(StatePart.TIME | StatePart.Q)
    assert tq[0] == arm.time and np.array_equal(tq[1:], arm.q)
    arm.set_state_vector(np.r_[0.0, qv], StatePart.TIME | StatePart.Q)
    assert arm.time == 0.0 and np.array_equal(arm.q, qv)


def test_engine_refuses_bad_vectors_and_writes_nothing():
    arm = _running_arm()
    before = arm.get_state()
    x = arm.get_state_vector(StatePart.PHYSICS)
    far = x.copy()
    far[0] += 100.0
    with pytest.raises(ValueError, match=r"state vector: q\[GHy\] = 100.* rad is more than 0.35 rad beyond its range"):
        arm.set_state_vector(far, StatePart.PHYSICS)
    fast = x.copy()
    fast[arm.n_dofs + 2] = 1e4
    with pytest.raises(ValueError, match=r"qdot\[.*\] = 1e\+04 rad/s is beyond max_joint_speed"):
        arm.set_state_vector(fast, StatePart.PHYSICS)
    nan = x.copy()
    nan[-1] = np.nan
    with pytest.raises(ValueError, match=r"activation\[.*\] is not finite"):
        arm.set_state_vector(nan, StatePart.PHYSICS)
    with pytest.raises(ValueError, match=r"must have shape \(214,\)"):
        arm.set_state_vector(x[:-1], StatePart.PHYSICS)
    with pytest.raises(ValueError, match="unknown state part 'velocity'"):
        arm.get_state_vector("velocity")
    with pytest.raises(ValueError, match="bits beyond StatePart.FULL"):
        arm.get_state_vector(1 << 20)
    with pytest.raises(TypeError, match="StatePart"):
        arm.get_state_vector(1.5)
    assert arm.get_state() == before


def test_batch_vectors_match_lone_arms_and_a_bad_row_is_refused_before_any_is_written():
    batch = armrt.ArmBatch(3)
    batch.set_excitation({"elbow_flexors": 0.4, "deltoid": 0.2})
    batch.step(7)
    arm = armrt.Arm()
    arm.set_excitation({"elbow_flexors": 0.4, "deltoid": 0.2})
    arm.step(7)
    v = batch.get_state_vector(StatePart.FULL)
    assert v.shape == (3, arm.get_state_vector().size)
    for row in v:
        np.testing.assert_array_equal(row, arm.get_state_vector())
    assert batch.state_vector_slices("physics") == arm.state_vector_slices("physics")
    # One arm's snapshot into arm 2 of the batch: it continues as the lone arm does.
    later = copy.deepcopy(arm)
    later.step(30)
    batch.set_state_vector(later.get_state_vector(), arms=[2])
    batch.step(10)
    arm.set_state(later.get_state())
    arm.step(10)
    np.testing.assert_array_equal(batch.q[2], arm.q)
    before = batch.get_state_vector()
    bad = before.copy()
    where = arm.state_vector_slices()
    bad[1, where["lce"].start] = 10.0
    with pytest.raises(ValueError, match=r"state vector of arm 1: fibre length lce\[.*\] = 10 m is outside"):
        batch.set_state_vector(bad)
    np.testing.assert_array_equal(batch.get_state_vector(), before)


def test_copies_and_pickles_continue_bit_for_bit_including_the_previous_format():
    arm = _running_arm()
    ahead = copy.deepcopy(arm)
    ahead.step(25)
    for other in (copy.deepcopy(arm), pickle.loads(pickle.dumps(arm))):
        assert other.get_state() == arm.get_state()
        other.step(25)
        np.testing.assert_array_equal(other.q, ahead.q)
    # An Arm pickled between 2026-11-30 and 2026-12-02: (state, excitation, force, moment, time, ROS2 memory).
    func, (cls, model, settings, raw, extras) = arm.__reduce__()
    s = arm.get_state()
    memory = (s.path_anchors, s.path_anchor_steps[0], s.path_anchor_steps[1], s.previous_step)
    old = (arm.data.state.copy(), arm.excitation, arm.data.hand_force, arm.data.hand_moment, arm.time, memory)
    restored = func(cls, model, settings, old, extras)
    assert restored.get_state() == s
    restored.step(25)
    np.testing.assert_array_equal(restored.q, ahead.q)


def test_a_diverged_arm_is_copied_as_it_stopped():
    arm = armrt.Arm()
    x = arm.get_state_vector(StatePart.PHYSICS)
    x[arm.n_dofs] = 1e6  # GHy turning at 1e6 rad/s: the engine refuses it ...
    with pytest.raises(ValueError):
        arm.set_state_vector(x, StatePart.PHYSICS)
    arm.data._load_snapshot(np.r_[0.0, x, arm.get_state_vector(StatePart.INPUTS | StatePart.INTEGRATOR)])
    twin = copy.deepcopy(arm)  # ... but a copy takes a state as it is
    np.testing.assert_array_equal(twin.data.state, arm.data.state)


def test_the_held_excitation_reads_back_as_the_dynamics_use_it_in_arm_and_batch():
    arm = armrt.Arm()
    batch = armrt.ArmBatch(2)
    for target in (arm, batch):
        target.max_activation = {"deltoid": 0.2}
        target.set_excitation(0.5)
    deltoid = arm.indices("deltoid")
    assert np.all(arm.excitation[deltoid] == 0.2) and np.all(batch.excitation[:, deltoid] == 0.2)
    assert arm.excitation.max() == 0.5 and batch.excitation.max() == 0.5
    # Lowering the cap lowers the held excitation, in both.
    for target in (arm, batch):
        target.max_activation = 0.1
    assert arm.excitation.max() == 0.1 and batch.excitation.max() == 0.1
    # A recording holds what the dynamics used.
    res = arm.simulate(np.full((5, arm.n_elements), 0.7), 5 * arm.dt)
    assert res.excitation.max() == 0.1
    # A State's excitation is capped as it is restored.
    s = dataclasses.replace(arm.get_state(), excitation=np.full(arm.n_elements, 0.9))
    arm.set_state(s)
    assert arm.excitation.max() == 0.1


def test_overlapping_names_follow_one_rule_for_every_setting_given_by_names():
    arm = armrt.Arm()
    batch = armrt.ArmBatch(2)
    infra = arm.indices("infra")
    supra = arm.indices("supra")
    for order in ({"rotator_cuff": 0.5, "infra": 0.9}, {"infra": 0.9, "rotator_cuff": 0.5}):
        for target in (arm, batch):
            target.strength = 1.0
            target.strength = order
            target.max_activation = 1.0
            target.max_activation = order
        for values in (arm.strength, arm.max_activation, batch.strength[1], batch.max_activation[0]):
            assert np.all(values[infra] == 0.9) and np.all(values[supra] == 0.5)
        # elements no name covers keep their values
        other = np.setdiff1d(np.arange(arm.n_elements), arm.indices("rotator_cuff"))
        assert np.all(arm.strength[other] == 1.0) and np.all(batch.max_activation[:, other] == 1.0)
    with pytest.raises(KeyError, match="infrx"):
        arm.strength = {"infrx": 0.5}
    with pytest.raises(ValueError, match="must be finite"):
        batch.strength = {"infra": float("nan")}


def test_a_state_prints_on_one_line():
    s = _running_arm().get_state()
    text = repr(s)
    assert "\n" not in text and len(text) < 200, text
    assert text.startswith("armrt.State(das2, t = 0.007 s, 5 DOFs, 102 elements") and "2 anchor(s)" in text
    assert "no ROS2 memory" in repr(armrt.Arm().get_state())
