"""Fatigue in armrt/FESElbowStim-v0: every channel of the default elbow map held at full stimulation (20 mA,
200 us, 30 Hz, intramuscular) for a long episode, the stimulated muscles' total tendon force and mean fatigue
printed as they fall, then reset() and the first seconds again, which match the first episode's exactly.

    python examples/fes_stim_fatigue.py                    # 60 s episode
    python examples/fes_stim_fatigue.py --duration 120 --observe-fatigue
"""
from __future__ import annotations

import argparse

import numpy as np


def run(duration: float, observe_fatigue: bool = False, fatigue: bool = True, seed: int = 0):
    """{"t" (steps,) s, "force" (steps,) N: total tendon force of the stimulated elements, "fatigue" (steps,)
    mean over channels, "obs" (steps + 1, obs size)} of one episode at full stimulation."""
    import gymnasium as gym
    import armrt.gym  # noqa: F401  (registers the ids)
    env = gym.make("armrt/FESElbowStim-v0", episode_duration=duration, observe_fatigue=observe_fatigue,
                   fatigue=fatigue).unwrapped
    reached = np.concatenate(env.task.reached)
    obs, _ = env.reset(seed=seed, options={"target": 1.0, "start": 0.5})
    full = np.ones(env.action_space.shape, np.float32)
    out = {"t": [], "force": [], "fatigue": [], "obs": [obs]}
    truncated = False
    while not truncated:
        obs, _, terminated, truncated, info = env.step(full)
        if terminated:
            raise RuntimeError(f"the arm diverged: {info.get('error')}")
        out["t"].append(float(env.batch.time[0]))
        out["force"].append(float(env.batch.muscle_force[0, reached].sum()))
        out["fatigue"].append(info["mean_fatigue"])
        out["obs"].append(obs)
    return {k: np.array(v) for k, v in out.items()}, env


def main(argv=None) -> dict:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--duration", type=float, default=60.0, help="episode length, s")
    p.add_argument("--observe-fatigue", action="store_true", help="append each channel's fatigue to the observation")
    a = p.parse_args(argv)
    first, env = run(a.duration, a.observe_fatigue)
    print(f"armrt/FESElbowStim-v0, channels {', '.join(env.task.channels)}; observation {env.observation_space.shape}")
    print("   t (s)   force (N)   mean fatigue")
    for t in (1.0, 2.0, 5.0, 10.0, 20.0, 30.0, 45.0, 60.0, 90.0, 120.0):
        if t <= first["t"][-1] + 1e-9:
            k = int(np.argmin(np.abs(first["t"] - t)))
            print(f"{first['t'][k]:8.2f} {first['force'][k]:11.1f} {first['fatigue'][k]:14.3f}")
    again, _ = run(min(2.0, a.duration), a.observe_fatigue)
    same = np.array_equal(again["force"], first["force"][:len(again["force"])])
    print(f"after reset: force at {again['t'][-1]:.2f} s {again['force'][-1]:.1f} N, "
          f"the first episode's exactly: {same}")
    return {"first": first, "again": again, "same": same}


if __name__ == "__main__":
    main()
