"""A controller found by random search over the vectorised environment: the FES PD elbow law of
fes_elbow_pd.py with its gains (kp, kd, flexor bias) drawn at random, one candidate per arm of
armrt/FESElbow-v0's vector env (ArmBatch: all candidates step together in C++), scored on the same
targets; a second round searches around the best. The winner is then run and plotted like the
hand-tuned example.

    python examples/fes_elbow_search.py [--candidates 32] [--rounds 2] [--out fes_elbow_search]
"""
import argparse
import sys
from pathlib import Path

import gymnasium as gym
import numpy as np

import armrt.gym  # noqa: F401  registers armrt/FESElbow-v0

sys.path.insert(0, str(Path(__file__).resolve().parent))
import fes_elbow_pd  # noqa: E402

TARGETS_DEG = (40.0, 80.0, 110.0)
LOW, HIGH = np.array([0.0, 0.0, 0.0]), np.array([4.0, 0.5, 0.3])   # kp (1/rad), kd (s/rad), bias


def score(vec, gains, targets_deg, start_deg=15.0):
    """Sum of episode returns of each candidate (row of gains) over the targets."""
    task = vec.task
    flex = np.array([not m.startswith("tric") for m in task.channels])
    nd = vec.batch.n_dofs
    total = np.zeros(len(gains))
    for target in np.radians(targets_deg):
        obs, _ = vec.reset(seed=0, options={"target": target, "start": np.radians(start_deg)})
        for _ in range(task.max_steps):
            error, speed = -obs[:, -1], obs[:, nd + task.elbow]
            command = gains[:, 2] + gains[:, 0] * error - gains[:, 1] * speed
            a = np.where(flex, np.clip(command, 0, 1)[:, None], np.clip(-command, 0, 1)[:, None]).astype(np.float32)
            obs, reward, terminated, truncated, _ = vec.step(a)
            total += reward
    return total


HAND_TUNED = np.array([1.5, 0.15, 0.1])   # fes_elbow_pd.py's defaults


def search(candidates, rounds, seed=0, targets_deg=TARGETS_DEG):
    """Returns (best gains, best return, {"hand_tuned": return, "no_stimulation": return}): round 1
    also scores fes_elbow_pd.py's hand-tuned gains and zero gains, for comparison."""
    rng = np.random.default_rng(seed)
    vec = gym.make_vec("armrt/FESElbow-v0", num_envs=candidates, vectorization_mode="vector_entry_point")
    gains = LOW + (HIGH - LOW) * rng.uniform(size=(candidates, 3))
    gains[0], gains[1] = HAND_TUNED, 0.0
    best, best_score, reference = None, -np.inf, {}
    for r in range(rounds):
        s = score(vec, gains, targets_deg)
        if r == 0:
            reference = {"hand_tuned": float(s[0]), "no_stimulation": float(s[1])}
            print(f"hand-tuned gains: return {s[0]:.1f}; no stimulation: {s[1]:.1f}")
        k = int(np.argmax(s))
        if s[k] > best_score:
            best, best_score = gains[k].copy(), float(s[k])
        print(f"round {r + 1}: best return {s[k]:.1f} (median {np.median(s):.1f}) at kp {gains[k, 0]:.2f}, "
              f"kd {gains[k, 1]:.3f}, bias {gains[k, 2]:.3f}")
        spread = (HIGH - LOW) * 0.15 / (r + 1)
        gains = np.clip(best + spread * rng.standard_normal((candidates, 3)), LOW, HIGH)
        gains[0] = best
    return best, best_score, reference


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--candidates", type=int, default=32)
    p.add_argument("--rounds", type=int, default=2)
    p.add_argument("--out", default="fes_elbow_search")
    a = p.parse_args(argv)
    best, best_score, reference = search(a.candidates, a.rounds)
    runs = fes_elbow_pd.run(TARGETS_DEG, kp=best[0], kd=best[1], bias=best[2], duration=3.0)
    fes_elbow_pd.plot(runs, a.out + ".png")
    print(f"best gains: kp {best[0]:.2f} /rad, kd {best[1]:.3f} s/rad, bias {best[2]:.3f}; return {best_score:.1f}; "
          f"wrote {a.out}.png")
    return best, best_score, reference, runs


if __name__ == "__main__":
    main()
