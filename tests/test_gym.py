"""armrt.gym: registered ids pass Gymnasium's env checker; seeding, truncation, termination and
render behave as Gymnasium 1.x specifies; the vector env on ArmBatch matches SyncVectorEnv."""
import warnings

import numpy as np
import pytest

gym = pytest.importorskip("gymnasium", reason="needs gymnasium (pip install gymnasium)")
pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
import armrt.gym  # noqa: E402
from gymnasium.utils.env_checker import check_env  # noqa: E402
from gymnasium.vector import AutoresetMode, SyncVectorEnv  # noqa: E402

IDS = sorted(armrt.gym.ENV_IDS)


@pytest.mark.parametrize("env_id", IDS)
def test_registered_env_passes_check_env_without_warnings(env_id):
    env = gym.make(env_id, render_mode="rgb_array")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check_env(env.unwrapped)
    assert [str(w.message) for w in caught] == []
    assert env_id.startswith("armrt/")


def test_module_id_form_and_entry_point():
    env = gym.make("armrt.gym:armrt/FESElbow-v0")
    assert isinstance(env.unwrapped, armrt.gym.FESElbowEnv)
    from importlib.metadata import entry_points
    eps = [ep for ep in entry_points(group="gymnasium.envs") if ep.value.startswith("armrt.gym")]
    if not eps:
        pytest.skip("armrt installed without its entry points (pip install . to refresh the metadata)")
    assert eps[0].load() is armrt.gym.register_envs


@pytest.mark.parametrize("env_id", IDS)
def test_seeding_reproducible_and_random_across_seeds(env_id):
    env = gym.make(env_id).unwrapped
    action = np.full(env.action_space.shape, 0.2, np.float32)
    runs = []
    for _ in range(2):
        obs, _ = env.reset(seed=123)
        traj = [obs] + [env.step(action)[0] for _ in range(3)]
        runs.append(np.array(traj))
    assert np.array_equal(runs[0], runs[1])
    firsts = {env.reset(seed=s)[0].tobytes() for s in range(6)}
    assert len(firsts) == 6
    # Unseeded resets continue the generator: two episodes in a row differ.
    env.reset(seed=0)
    a, b = env.reset()[0], env.reset()[0]
    assert not np.array_equal(a, b)


def test_truncated_exactly_at_the_time_limit():
    env = gym.make("armrt/FESElbow-v0", env_dt=0.01, episode_duration=0.05).unwrapped
    env.reset(seed=0)
    flags = [env.step(env.action_space.sample())[3] for _ in range(5)]
    assert flags == [False] * 4 + [True]


def test_reach_terminates_when_the_joint_would_dislocate():
    env = gym.make("armrt/Reach-v0", dislocation_time=0.05).unwrapped
    env.reset(seed=0)
    action = np.zeros(env.action_space.shape, np.float32)
    for m in ("deltscap", "deltclav"):   # deltoid alone, no rotator cuff: the paper's Fig. 2 hazard
        action[env.task.channels.index(m)] = 1.0
    for k in range(50):
        obs, reward, terminated, truncated, info = env.step(action)
        if terminated:
            break
    assert terminated and not truncated and info["dislocated"] and info["gh_stab"] > 1
    assert reward < -info["distance"]          # the GH penalty was charged
    assert k * env.task.env_dt > 0.05 - 1e-9     # not before the documented time


def test_fes_elbow_weakened_arm_and_stimulated_channels_only():
    env = gym.make("armrt/FESElbow-v0", strength={"elbow_flexors": 0.4}, max_activation=0.6).unwrapped
    b = env.batch
    flex = b.indices("elbow_flexors")
    assert np.all(b.strength[0, flex] == 0.4) and b.strength[0].max() == 1.0
    assert np.all(b.max_activation == 0.6)
    env.reset(seed=1)
    env.step(np.ones(env.action_space.shape, np.float32))
    u = b.excitation[0]
    stimulated = np.concatenate([b.indices(m) for m in armrt.gym.FES_ELBOW_MUSCLES])
    cuff = b.indices("rotator_cuff")
    # Read back as the dynamics use it: a full command capped at max_activation 0.6 (issue 25, as Arm).
    assert np.all(u[stimulated] == 0.6) and np.all(u[cuff] == 0.05)
    others = np.setdiff1d(np.arange(b.n_elements), np.concatenate([stimulated, cuff]))
    assert np.all(u[others] == 0.0)
    assert env.observation_space.shape == (2 * b.n_dofs + len(armrt.gym.FES_ELBOW_MUSCLES) + 2,)


def test_render_is_the_animate_figure_as_rgb():
    env = gym.make("armrt/Reach-v0", render_mode="rgb_array")
    env.reset(seed=0)
    env.step(env.action_space.sample())
    img = env.render()
    assert img.dtype == np.uint8 and img.ndim == 3 and img.shape[2] == 3
    assert img.std() > 10   # a drawing, not a blank canvas


@pytest.mark.parametrize("task_id", IDS)
def test_vector_env_matches_sync_vector_env_bit_for_bit(task_id):
    n = 3
    kw = {"episode_duration": 0.08}   # 8 steps: several next-step autoresets in 20 steps
    vec = gym.make_vec(task_id, num_envs=n, vectorization_mode="vector_entry_point", threads=2, **kw)
    assert isinstance(vec, armrt.gym.ArmVectorEnv)
    assert vec.metadata["autoreset_mode"] == AutoresetMode.NEXT_STEP
    entry = armrt.gym.ENV_IDS[task_id][0]
    sync = SyncVectorEnv([lambda: getattr(armrt.gym, entry)(**kw) for _ in range(n)])
    assert sync.metadata["autoreset_mode"] == vec.metadata["autoreset_mode"]
    assert vec.single_observation_space == sync.single_observation_space
    o1, _ = vec.reset(seed=7)
    o2, _ = sync.reset(seed=7)
    assert np.array_equal(o1, o2)
    rng = np.random.default_rng(0)
    resets = 0
    for _ in range(20):
        a = rng.uniform(0, 1, (n,) + vec.single_action_space.shape).astype(np.float32)
        r1, r2 = vec.step(a), sync.step(a)
        for x, y in zip(r1[:4], r2[:4]):
            assert np.array_equal(x, y)
        assert set(r1[4]) == set(r2[4])
        for k in r1[4]:
            assert np.array_equal(r1[4][k], r2[4][k]), k
        resets += int(r1[3].sum())
    assert resets >= n


def test_vector_env_a_diverging_arm_terminates_alone_and_restarts():
    vec = armrt.gym.ReachVectorEnv(3, threads=2)
    vec.reset(seed=0)
    force = np.zeros((3, 3))
    force[1] = (0.0, 1e5, 0.0)        # the largest load taken: throws arm 1 past the joint-speed bound
    vec.batch.set_hand_load(force=force)
    a = np.full((3,) + vec.single_action_space.shape, 0.05, np.float32)
    obs, reward, terminated, truncated, info = vec.step(a)
    assert terminated.tolist() == [False, True, False]
    assert info["diverged"].tolist() == [False, True, False] and "qdot[" in info["error"][1]
    assert reward[1] == -vec.task.divergence_penalty
    assert vec.single_observation_space.contains(obs[1])
    vec.batch.set_hand_load()
    obs, reward, terminated, truncated, info = vec.step(a)   # next-step autoreset of arm 1
    assert not vec.batch.diverged.any() and reward[1] == 0.0 and not terminated.any()
    assert vec.batch.time[1] == 0.0 and vec.batch.time[0] > 0.0
