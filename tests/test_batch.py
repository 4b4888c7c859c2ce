"""ArmBatch: every arm bit-identical to a lone Arm on 1 and 2 threads, for every integrator; a
diverging arm stops alone and is named; inputs and outputs as (n, ...) arrays."""
import warnings

import numpy as np
import pytest

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
from armrt.arm import DEFAULT_INTEGRATOR, INTEGRATORS, Arm  # noqa: E402
from armrt.batch import ArmBatch  # noqa: E402


def arm_setups(n, n_dofs, n_elements, rest, seed=0):
    """Different excitations, postures, strengths, maximum activations and hand loads per arm."""
    rng = np.random.default_rng(seed)
    return dict(
        u=rng.uniform(0.0, 0.4, (n, n_elements)),
        q=rest + rng.uniform(-0.15, 0.15, (n, n_dofs)),
        strength=rng.uniform(0.3, 1.0, (n, n_elements)),
        max_activation=rng.uniform(0.5, 1.0, (n, n_elements)),
        force=rng.uniform(-5.0, 5.0, (n, 3)),
    )


def lone_arm(setup, i, **kw):
    arm = Arm(**kw)
    arm.strength = setup["strength"][i]
    arm.max_activation = setup["max_activation"][i]
    arm.reset(q=setup["q"][i])
    arm.set_hand_load(force=setup["force"][i])
    arm.set_excitation(setup["u"][i])
    return arm


def configured_batch(setup, n, threads, **kw):
    b = ArmBatch(n, threads=threads, **kw)
    b.strength = setup["strength"]
    b.max_activation = setup["max_activation"]
    b.reset(q=setup["q"])
    b.set_hand_load(force=setup["force"])
    b.set_excitation(setup["u"])
    return b


@pytest.mark.parametrize("integrator", INTEGRATORS)
def test_each_arm_bit_identical_to_a_lone_arm_on_1_and_2_threads(integrator):
    n = 5
    steps = (7, 5) if integrator == "cvode" else (20, 13)
    probe = ArmBatch(1, integrator=integrator)
    setup = arm_setups(n, probe.n_dofs, probe.n_elements, probe.rest_posture)
    lone = []
    for i in range(n):
        arm = lone_arm(setup, i, integrator=integrator)
        arm.step(steps[0])
        arm.set_excitation(setup["u"][(i + 1) % n])   # inputs change between calls
        arm.step(steps[1])
        lone.append((np.array(arm.q), np.array(arm.qdot), np.array(arm.lce), np.array(arm.activation),
                     arm.time, arm.outputs()))
    for threads in (1, 2):
        b = configured_batch(setup, n, threads, integrator=integrator)
        assert b.integrator == integrator
        b.step(steps[0])
        b.set_excitation(np.roll(setup["u"], -1, axis=0))
        b.step(steps[1])
        for i, (q, qd, lce, act, t, out) in enumerate(lone):
            assert np.array_equal(b.q[i], q), (threads, i)
            assert np.array_equal(b.qdot[i], qd)
            assert np.array_equal(b.lce[i], lce)
            assert np.array_equal(b.activation[i], act)
            assert b.time[i] == t
            assert b.gh_stab[i] == out["gh_stab"]
            assert np.array_equal(b.hand_position[i], out["hand_position"])
            assert np.array_equal(b.gh_force[i], out["gh_force"])
            assert np.array_equal(b.muscle_force[i], out["muscle_force"])
            assert np.array_equal(b.outputs()["gh_force"][i], out["gh_force"])
        # The arms really differ (the check above is not comparing one trajectory with itself).
        assert len({b.q[i].tobytes() for i in range(n)}) == n


def test_defaults_and_sizes_come_from_arm_and_the_model():
    b = ArmBatch(3)
    arm = Arm()
    assert b.integrator == DEFAULT_INTEGRATOR == arm.integrator
    assert (b.dt, b.substeps) == (arm.dt, arm.substeps)
    assert b.q.shape == (3, len(arm.dof_names))
    assert b.activation.shape == b.muscle_force.shape == (3, arm.n_elements)
    assert b.gh_stab.shape == (3,) and b.hand_position.shape == (3, 3)
    assert np.array_equal(b.q, np.tile(arm.rest_posture, (3, 1)))
    # Outputs are valid right after construction (rest posture), like Arm.outputs().
    assert np.array_equal(b.gh_stab, np.full(3, arm.outputs()["gh_stab"]))


def test_views_are_zero_copy_and_read_only():
    b = ArmBatch(4, threads=1)
    q = b.q
    b.set_excitation({"elbow_flexors": 0.5})
    b.step(20)
    assert np.array_equal(q, b.q)           # the same memory follows the simulation
    assert not np.array_equal(q, np.tile(b.rest_posture, (4, 1)))
    with pytest.raises(ValueError):
        q[0, 0] = 1.0


def test_a_diverging_arm_stops_alone_and_is_named():
    n = 4
    b = ArmBatch(n, threads=2)
    ref = ArmBatch(n, threads=2)
    force = np.zeros((n, 3))
    force[2] = (0.0, 1e5, 0.0)   # the largest hand load taken, upward: it throws arm 2 faster than the joint-speed bound
    b.set_hand_load(force=force)
    for x in (b, ref):
        x.set_excitation({"rotator_cuff": 0.05})
    with pytest.warns(RuntimeWarning, match=r"arm 2: simulation diverged: qdot\[\w+\]"):
        failed = b.step(30)
    ref.step(30)
    assert failed.tolist() == [2]
    assert b.diverged.tolist() == [False, False, True, False]
    assert set(b.errors) == {2} and "rad/s" in b.errors[2]
    t_stop = b.time[2]
    assert t_stop < b.time[0]
    for i in (0, 1, 3):   # the others went on, unaffected
        assert np.array_equal(b.q[i], ref.q[i])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert b.step(5).size == 0       # not reported twice; it stays where it stopped
    assert b.time[2] == t_stop
    with pytest.raises(armrt.SimulationError, match="arm 2"):
        b.raise_if_diverged()
    b.set_hand_load()
    b.reset(arms=[2])
    assert not b.diverged.any() and b.errors == {} and b.time[2] == 0.0
    b.step(5)
    assert not b.diverged.any()


def test_inputs_broadcast_validate_and_name_the_problem():
    b = ArmBatch(3, threads=1)
    ne, nd = b.n_elements, b.n_dofs
    with pytest.raises(ValueError, match=rf"\(3, {ne}\)"):
        b.set_excitation(np.zeros((2, ne)))
    with pytest.raises(ValueError, match="NaN"):
        b.set_excitation(np.full((3, ne), np.nan))
    with pytest.warns(RuntimeWarning, match="clipped"):
        b.set_excitation(np.full((3, ne), 1.5))
    assert b.excitation.max() == 1.0
    b.set_excitation({"bicb": 0.3})
    assert np.all(b.excitation[:, b.indices("bicb")] == 0.3) and b.excitation.sum() == pytest.approx(3 * 0.3 * len(b.indices("bicb")))
    with pytest.raises(KeyError, match="did you mean"):
        b.set_excitation({"bicepz": 0.3})
    b.strength = {"deltscap": 0.3}
    s = b.strength
    assert np.all(s[:, b.indices("deltscap")] == 0.3) and np.all(np.delete(s, b.indices("deltscap"), axis=1) == 1.0)
    with pytest.raises(ValueError, match="max_activation must lie in"):
        b.max_activation = np.full((3, ne), 2.0)
    q = np.tile(b.rest_posture, (2, 1)) + 0.1
    b.reset(q=q, arms=np.array([True, False, True]))
    assert np.array_equal(b.q[[0, 2]], q) and np.array_equal(b.q[1], b.rest_posture)
    with pytest.raises(ValueError, match=rf"\(2, {nd}\)"):
        b.reset(q=np.zeros((3, nd)), arms=[0, 1])
    with pytest.raises(IndexError):
        b.reset(arms=[5])
    with pytest.raises(ValueError, match="positive integer"):
        ArmBatch(0)
    with pytest.raises(ValueError, match="integrator"):
        ArmBatch(2, integrator="leapfrog")


def test_default_threads_follow_omp_num_threads(monkeypatch):
    from armrt.batch import available_cores
    monkeypatch.setenv("OMP_NUM_THREADS", "1")
    assert ArmBatch(2).threads == 1
    monkeypatch.delenv("OMP_NUM_THREADS")
    assert ArmBatch(2).threads == available_cores()
    with pytest.raises(ValueError, match="threads"):
        ArmBatch(2, threads=0)
