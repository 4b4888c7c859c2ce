"""armrt/FESElbowStim-v0 (issue 27): stimulation commands as actions, within every channel's limits; fatigue
on, observed or hidden; reset rests it, per arm in the vector env; the vector env's arm k is a lone env."""
import warnings

import numpy as np
import pytest

gym = pytest.importorskip("gymnasium", reason="needs gymnasium (pip install gymnasium)")
pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
import armrt.gym  # noqa: E402
from armrt.stimulation import STATE_COLUMNS  # noqa: E402
from gymnasium.utils.env_checker import check_env  # noqa: E402

ENV_ID = "armrt/FESElbowStim-v0"

# A surface map with spill-over (channels share brachialis) and a charge cap narrower than amplitude x pulse
# width, so that the charge rule decides the largest amplitude.
SURFACE_MAP = {"fatigue": False, "channels": [
    {"name": "flexors", "kind": "surface", "elements": {"bicl": 1.0, "bicb": 1.0, "brachialis": 0.6},
     "limits": {"max_charge_C": 12e-6}},
    {"name": "brachialis_deep", "kind": "surface", "elements": {"brachialis": 0.4, "brachiorad": 1.0}},
    {"name": "triceps", "kind": "surface", "elements": ["triclong", "tricmed", "triclat"]}]}


def run(env, actions, seed=0, options=None):
    obs, _ = env.reset(seed=seed, options=options)
    out = [obs]
    for a in actions:
        out.append(env.step(a)[0])
    return np.array(out)


@pytest.mark.parametrize("modulation,observe", [("amplitude", False), ("pulse_width", True), ("all", True)])
def test_passes_check_env_without_warnings(modulation, observe):
    env = gym.make(ENV_ID, modulation=modulation, observe_fatigue=observe)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check_env(env.unwrapped)
    assert [str(w.message) for w in caught] == []


def test_default_map_elbow_channels_with_fatigue_on_and_the_fatigue_switch():
    env = gym.make(ENV_ID).unwrapped
    m = env.batch.stimulation_map()
    assert m["fatigue"] is True
    assert env.task.channels == list(armrt.gym.FES_ELBOW_MUSCLES) == env.batch.channel_names
    assert env.action_space.shape == (len(armrt.gym.FES_ELBOW_MUSCLES),)
    # A map saying fatigue = false gets it on unless fatigue=False is asked for.
    assert gym.make(ENV_ID, stimulation=SURFACE_MAP).unwrapped.batch.stimulation_map()["fatigue"] is True
    assert gym.make(ENV_ID, stimulation=SURFACE_MAP, fatigue=False).unwrapped.batch.stimulation_map()["fatigue"] is False


@pytest.mark.parametrize("modulation", ["amplitude", "pulse_width", "all"])
@pytest.mark.parametrize("stimulation", [None, SURFACE_MAP])
def test_no_action_in_the_box_exceeds_a_channel_limit(modulation, stimulation):
    env = gym.make(ENV_ID, stimulation=stimulation, modulation=modulation).unwrapped
    task = env.task
    lim = {c["name"]: c["limits"] for c in env.batch.stimulation_map()["channels"]}
    rng = np.random.default_rng(1)
    corners = [np.ones(env.action_space.shape), np.zeros(env.action_space.shape)]
    for a in corners + [rng.uniform(0, 1, env.action_space.shape) for _ in range(50)]:
        cmd = task.commands(a[None])[0]
        for k, name in enumerate(task.channels):
            pw, amp, f = cmd[k]
            assert 0 <= pw <= lim[name]["max_pulse_width_s"]
            assert 0 <= amp <= lim[name]["max_amplitude_A"]
            assert 0 <= f <= lim[name]["max_frequency_Hz"]
            assert pw * amp <= lim[name]["max_charge_C"] * (1 + 1e-12)
        env.batch.set_stimulation(cmd[None])   # the engine's own check refuses none of them
    full = task.commands(np.ones((1,) + env.action_space.shape))[0]
    if stimulation is SURFACE_MAP and modulation == "amplitude":
        # 12 uC at the surface reference pulse width of 300 us: 40 mA, below the 130 mA device limit.
        assert full[0, 1] == pytest.approx(12e-6 / 300e-6) and full[2, 1] == 0.130
    if stimulation is None and modulation == "pulse_width":
        # Intramuscular: 20 mA (saturation, the limit), pulse width up to the 255 us limit (5.1 uC).
        assert np.allclose(full[:, 0], 255e-6) and np.allclose(full[:, 1], 0.020)


def test_fixed_values_are_checked_against_the_limits():
    with pytest.raises(ValueError, match="pulse_width of channel 'bicl' must lie in"):
        gym.make(ENV_ID, pulse_width=300e-6)          # intramuscular limit 255 us
    with pytest.raises(ValueError, match="frequency of channel 'triceps'"):
        gym.make(ENV_ID, stimulation=SURFACE_MAP, frequency=[30.0, 30.0, 120.0])
    with pytest.raises(ValueError, match="cannot be fixed"):
        gym.make(ENV_ID, modulation="all", frequency=20.0)
    with pytest.raises(ValueError, match="modulation must be one of"):
        gym.make(ENV_ID, modulation="current")
    with pytest.raises(TypeError, match="fatigue must be True or False"):
        gym.make(ENV_ID, fatigue="yes")
    with pytest.raises(ValueError, match="unknown"):
        gym.make(ENV_ID, stimulation={"channels": [{"name": "x", "elements": ["bicepz"]}]})
    env = gym.make(ENV_ID, frequency=20.0, pulse_width=[100e-6] * 7).unwrapped
    cmd = env.task.commands(np.full((1, 7), 0.5))[0]
    assert np.all(cmd[:, 0] == 100e-6) and np.all(cmd[:, 2] == 20.0) and np.allclose(cmd[:, 1], 0.010)


def test_actions_outside_the_box_are_clipped_as_fes_elbow_and_nan_refused():
    env = gym.make(ENV_ID).unwrapped
    n = env.action_space.shape[0]
    inside = [np.r_[np.ones(n - 3), np.zeros(3)].astype(np.float32)] * 5
    outside = [np.r_[np.full(n - 3, 3.0), np.full(3, -2.0)].astype(np.float32)] * 5
    assert np.array_equal(run(env, inside), run(env, outside))
    env.reset(seed=0)
    with pytest.raises(ValueError, match="not finite"):
        env.step(np.full(n, np.nan, np.float32))
    with pytest.raises(ValueError, match="7 values per arm"):
        env.step(np.ones(n + 1, np.float32))


def _flexor_force(env):
    return env.batch.muscle_force[0, np.concatenate(env.task.reached)].sum()


def _force_trace(env, seconds):
    """Total tendon force (N) of the stimulated elements after each env step under constant full stimulation."""
    env.reset(seed=0, options={"target": 1.0, "start": 0.5})
    a = np.ones(env.action_space.shape, np.float32)
    out = []
    for _ in range(int(round(seconds / env.task.env_dt))):
        env.step(a)
        out.append(_flexor_force(env))
    return np.array(out)


def test_constant_full_stimulation_fatigues_and_reset_restores():
    env = gym.make(ENV_ID, episode_duration=40.0).unwrapped
    first = _force_trace(env, 40.0)
    fatigue_end = env.batch.fatigue[0].copy()
    at = lambda t: first[int(round(t / env.task.env_dt)) - 1]   # noqa: E731
    # max_activation 0.7 caps the activation while the fibres' force is above it (the first ~10 s), then the
    # force falls with Ding's fatigue.
    assert at(40.0) < 0.6 * at(2.0)
    assert np.all(fatigue_end > 0.5)
    again = _force_trace(env, 2.0)          # reset rests every channel: the same episode again, bit for bit
    assert np.array_equal(again, first[:len(again)])
    # The control: without fatigue the same stimulation holds its force.
    rested = _force_trace(gym.make(ENV_ID, episode_duration=40.0, fatigue=False).unwrapped, 40.0)
    assert abs(rested[-1] - rested[199]) < 0.01 * rested[199]
    assert rested[199] == pytest.approx(at(2.0), rel=1e-3)


def test_observe_fatigue_appends_the_channels_fatigue():
    hidden = gym.make(ENV_ID).unwrapped
    shown = gym.make(ENV_ID, observe_fatigue=True).unwrapped
    nc = len(hidden.task.channels)
    assert shown.observation_space.shape[0] == hidden.observation_space.shape[0] + nc
    actions = [np.full(nc, 0.8, np.float32)] * 30
    a, b = run(hidden, actions), run(shown, actions)
    assert np.array_equal(a, b[:, :-nc])           # the same arm; the fatigue is only hidden
    assert np.array_equal(b[-1, -nc:], shown.batch.fatigue[0].astype(np.float32))
    assert np.all(b[0, -nc:] == 0.0) and np.all(b[-1, -nc:] > 0.0)


def test_fatigue_is_one_number_per_channel():
    # Why observe_fatigue shows 1 - A/A_rest alone: from rest, tau1's and Km's drifts stay proportional to A's
    # (linear equations, the same tau_fat and force drive), so A's fatigue determines the other two.
    env = gym.make(ENV_ID, episode_duration=20.0).unwrapped
    env.reset(seed=0)
    ratios = []
    for k in range(1500):
        env.step(np.full(7, 1.0 if k < 1000 else 0.3, np.float32))   # stimulation then lower: drift and recovery
        if k % 250 == 249:
            st = env.batch.stimulation_state[0]
            drift_a = 1.0 - st[:, STATE_COLUMNS["fatigue_A"]]
            ratios.append(np.stack([(st[:, STATE_COLUMNS["fatigue_tau1"]] - 1.0) / drift_a,
                                    (st[:, STATE_COLUMNS["fatigue_Km"]] - 1.0) / drift_a]))
    ratios = np.array(ratios)
    np.testing.assert_allclose(ratios, np.broadcast_to(ratios[0], ratios.shape), rtol=1e-9)


def test_vector_env_arm_k_is_a_lone_env_with_the_same_seed_and_actions():
    n, kw = 3, {"stimulation": SURFACE_MAP, "modulation": "all", "observe_fatigue": True, "episode_duration": 0.1}
    vec = gym.make_vec(ENV_ID, num_envs=n, vectorization_mode="vector_entry_point", threads=2, **kw)
    assert isinstance(vec, armrt.gym.FESElbowStimVectorEnv)
    rng = np.random.default_rng(3)
    actions = rng.uniform(-0.2, 1.2, (25, n) + vec.single_action_space.shape).astype(np.float32)
    steps = [vec.reset(seed=11)[0]] + [vec.step(a)[:4] for a in actions]
    for k in range(n):
        lone = armrt.gym.FESElbowStimEnv(**kw)
        obs, _ = lone.reset(seed=11 + k)
        assert np.array_equal(obs, steps[0][k])
        done = False
        for a, (o, r, term, trunc) in zip(actions, steps[1:]):
            if done:   # next-step autoreset: the vector env's arm starts its next episode, seeded on
                obs, _ = lone.reset()
                assert np.array_equal(obs, o[k]) and r[k] == 0.0
                done = False
                continue
            obs, rew, te, tr, _ = lone.step(a[k])
            assert np.array_equal(obs, o[k]) and rew == r[k] and (te, tr) == (term[k], trunc[k])
            done = te or tr
        assert sum(1 for _, _, _, trunc in steps[1:] if trunc[k]) >= 2   # episodes of 10 steps: resets happened


def test_vector_env_autoreset_rests_only_that_arms_fatigue():
    vec = armrt.gym.FESElbowStimVectorEnv(3, threads=2, episode_duration=10.0)
    vec.reset(seed=0)
    a = np.ones((3,) + vec.single_action_space.shape, np.float32)
    for _ in range(300):
        vec.step(a)
    before = vec.batch.fatigue.copy()
    assert np.all(before > 0.01)
    force = np.zeros((3, 3))
    force[1] = (0.0, 1e5, 0.0)        # the largest load taken: throws arm 1 past the speed bound, alone
    vec.batch.set_hand_load(force=force)
    terminated = vec.step(a)[2]
    assert terminated.tolist() == [False, True, False]
    vec.batch.set_hand_load()
    vec.step(a)                       # next-step autoreset of arm 1 only
    after = vec.batch.fatigue
    assert np.all(after[1] == 0.0) and np.all(vec.batch.stimulation[1] == 0.0)
    assert np.all(after[[0, 2]] > before[[0, 2]])   # the others go on fatiguing
    assert vec.batch.time[1] == 0.0 and vec.batch.time[0] > 3.0


def test_infinite_actions_are_refused_like_nan_and_nothing_is_applied():
    import gymnasium as gym
    import armrt.gym  # noqa: F401
    env = gym.make("armrt/FESElbowStim-v0")
    env.reset(seed=0)
    n = env.action_space.shape[0]
    before = env.unwrapped.batch.stimulation.copy()
    for bad in (np.inf, -np.inf, np.nan):
        a = np.zeros(n, np.float32)
        a[2] = bad
        with pytest.raises(ValueError, match="arm 0 is not finite"):
            env.step(a)
        np.testing.assert_array_equal(env.unwrapped.batch.stimulation, before)
    env.step(np.full(n, 5.0, np.float32))  # finite and outside the Box: clipped, as documented
