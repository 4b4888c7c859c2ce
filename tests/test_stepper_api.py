"""The engine's three-part API in Python (issue 25): a shared Model, a Data per arm, a Stepper; step() and
forward() as free functions; Arm = Model + Data + Stepper + checks gives the same bits."""
import numpy as np
import pytest

import armrt


def test_step_of_model_data_stepper_is_the_arm_bit_for_bit():
    model = armrt.Model("das2")
    data = armrt.Data(model)
    stepper = armrt.Stepper(model, "ros2", dt=1e-3)
    arm = armrt.Arm(model)
    exc = np.linspace(0.0, 0.4, model.n_elements)
    arm.set_excitation(exc)
    data._sim.excitation[:] = exc
    armrt.step(model, data, stepper, n=200)
    arm.step(200)
    assert np.array_equal(data.state, arm.data.state)
    assert armrt.forward(model, data)["gh_stab"] == arm.gh_stab


def test_two_data_share_one_model_and_keep_their_own_state():
    model = armrt.Model("das2")
    a, b = armrt.Data(model), armrt.Data(model)
    assert a.model is b.model is model
    stepper = armrt.Stepper(model)
    a._sim.excitation[:] = 0.3
    armrt.step(model, a, stepper, n=50)
    assert not np.array_equal(a.q, b.q)  # b did not move
    assert np.array_equal(b.q, model.rest_posture)


def test_step_refuses_another_models_data_and_bad_steppers():
    das2, das3 = armrt.Model("das2"), armrt.Model("das3")
    with pytest.raises(ValueError, match="belongs to model 'das2'"):
        armrt.step(das3, armrt.Data(das2), armrt.Stepper(das3))
    with pytest.raises(ValueError, match="stepper is for model 'das3'"):
        armrt.step(das2, armrt.Data(das2), armrt.Stepper(das3))
    with pytest.raises(TypeError, match="armrt.Stepper"):
        armrt.step(das2, armrt.Data(das2), "ros2")
    with pytest.raises(ValueError, match="dt"):
        armrt.Stepper(das2, dt=2.0)
    with pytest.raises(ValueError, match="integrator"):
        armrt.Stepper(das2, "leapfrog")


def test_output_properties_read_the_outputs_once_per_state():
    """Arm's output properties compute the outputs when the state changed and read them afterwards: they
    describe the current state, and a second read runs no forward()."""
    arm = armrt.Arm("das2")
    arm.set_excitation({"deltoid": 0.3})
    arm.step(20)
    assert not arm._sim.outputs_current()  # stepping computes no outputs
    first = arm.gh_stab
    assert arm._sim.outputs_current()
    assert arm.gh_stab == first and arm.hand_position.tolist() == arm.outputs()["hand_position"].tolist()
    arm.set_hand_load(force=(0.0, -20.0, 0.0))  # a load changes the GH force: outputs are stale
    assert not arm._sim.outputs_current()
    assert arm.gh_stab != first
    # The properties equal a fresh evaluation at the same state (a new arm set to it).
    other = armrt.Arm("das2")
    other.set_hand_load(force=(0.0, -20.0, 0.0))
    other.set_state(arm.get_state())
    assert other.gh_stab == arm.gh_stab


def test_data_takes_inputs_and_settings_as_arm_does():
    """The three-part API drives muscles without an Arm: Data.set_excitation (arrays, scalars, names with the
    engine's overlap rule, the max_activation cap), set_hand_load, strength and max_activation; the same
    steps then give an Arm's trajectory bit for bit."""
    model = armrt.Model("das2")
    data = armrt.Data(model)
    arm = armrt.Arm(model)
    for target in (data, arm):
        target.max_activation = {"deltoid": 0.2}
        target.strength = {"elbow_flexors": 0.5}
        target.set_excitation({"rotator_cuff": 0.05, "infra": 0.3, "deltoid": 0.9})
        target.set_hand_load(force=(0.0, -9.81, 0.0))
    np.testing.assert_array_equal(data.excitation, arm.excitation)
    assert data.excitation[arm.indices("deltoid")].max() == 0.2
    np.testing.assert_array_equal(data.strength, arm.strength)
    armrt.step(model, data, armrt.Stepper(model), 50)
    arm.step(50)
    np.testing.assert_array_equal(data.q, arm.q)
    with pytest.raises(KeyError, match="infrx"):
        data.set_excitation({"infrx": 0.1})
    with pytest.raises(ValueError, match="NaN"):
        data.set_excitation(np.full(model.n_elements, np.nan))
    with pytest.raises(ValueError, match=r"hand force must have shape \(3,\)"):
        data.set_hand_load(force=(1.0, 2.0))
    with pytest.raises(ValueError, match="max_activation must lie in"):
        data.max_activation = 1.5


def test_stepping_an_arms_data_with_another_stepper_leaves_the_arm_as_it_was():
    arm = armrt.Arm()
    before = (arm.integrator, arm.dt, arm.substeps)
    armrt.step(arm.model, arm.data, armrt.Stepper(arm.model, "euler"), 1)
    assert (arm.integrator, arm.dt, arm.substeps) == before
    assert arm.time == pytest.approx(1e-3)


def test_data_pickles_and_copies_with_its_settings_and_state():
    import copy
    import pickle
    model = armrt.Model("das2")
    data = armrt.Data(model)
    data.strength = 0.7
    data.set_excitation({"elbow_flexors": 0.4})
    armrt.step(model, data, armrt.Stepper(model), 20)
    for twin in (pickle.loads(pickle.dumps(data)), copy.deepcopy(data)):
        assert twin.get_state() == data.get_state()
        np.testing.assert_array_equal(twin.strength, data.strength)
        armrt.step(model, twin, armrt.Stepper(model), 20)
    armrt.step(model, data, armrt.Stepper(model), 20)
    np.testing.assert_array_equal(twin.q, data.q)
