"""A simple FES controller: PD on the elbow angle through the stimulated elbow muscles of a weakened
arm (armrt/FESElbow-v0: biceps, brachialis, brachioradialis, triceps; strength 0.5, at most 0.7
activation), one episode per target angle, plotted with the stimulation and GH stability.

    python examples/fes_elbow_pd.py                     # writes fes_elbow_pd.png
    python examples/fes_elbow_pd.py --kp 2 --kd 0.3 --targets 30 60 100 --out my_run

The controller maps the PD command to flexor stimulation when positive and to extensor stimulation
when negative (no co-contraction), plus a constant flexor bias that holds the forearm's weight.
"""
import argparse

import gymnasium as gym
import numpy as np

import armrt.gym  # noqa: F401  registers armrt/FESElbow-v0


def pd_action(obs, channels, flexors, extensors, elbow, n_dofs, kp, kd, bias):
    """Stimulation in [0, 1] per channel from the observation (elbow error and speed)."""
    error = -obs[-1]                       # target - elbow angle, rad
    speed = obs[n_dofs + elbow]            # rad/s
    command = bias + kp * error - kd * speed
    a = np.zeros(len(channels), np.float32)
    a[flexors] = np.clip(command, 0.0, 1.0)
    a[extensors] = np.clip(-command, 0.0, 1.0)
    return a


def run(targets_deg, kp, kd, bias, duration, seed=0):
    """One episode per target; returns a list of dicts of time series."""
    env = gym.make("armrt/FESElbow-v0", episode_duration=duration).unwrapped
    task = env.task
    channels = task.channels
    flexors = [i for i, m in enumerate(channels) if not m.startswith("tric")]
    extensors = [i for i, m in enumerate(channels) if m.startswith("tric")]
    runs = []
    for k, target in enumerate(np.radians(targets_deg)):
        obs, _ = env.reset(seed=seed + k, options={"target": target, "start": np.radians(15.0)})
        rec = {"t": [0.0], "elbow": [env.batch.q[0, task.elbow]], "gh_stab": [env.batch.gh_stab[0]],
               "flex": [0.0], "ext": [0.0], "target": target}
        done = False
        while not done:
            a = pd_action(obs, channels, flexors, extensors, task.elbow, env.batch.n_dofs, kp, kd, bias)
            obs, reward, terminated, truncated, info = env.step(a)
            done = terminated or truncated
            rec["t"].append(float(env.batch.time[0]))
            rec["elbow"].append(float(env.batch.q[0, task.elbow]))
            rec["gh_stab"].append(float(env.batch.gh_stab[0]))
            rec["flex"].append(float(a[flexors].max()))
            rec["ext"].append(float(a[extensors].max()))
        runs.append({k: np.asarray(v) for k, v in rec.items()})
    return runs


def plot(runs, path):
    import matplotlib
    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(3, 1, figsize=(8, 7.5), sharex=True, dpi=100)
    for r in runs:
        line, = axes[0].plot(r["t"], np.degrees(r["elbow"]), lw=1.5)
        axes[0].axhline(np.degrees(r["target"]), color=line.get_color(), ls="--", lw=0.8)
        axes[1].plot(r["t"], r["flex"], color=line.get_color(), lw=1)
        axes[1].plot(r["t"], -r["ext"], color=line.get_color(), lw=1, ls=":")
        axes[2].plot(r["t"], r["gh_stab"], color=line.get_color(), lw=1)
    axes[0].set_ylabel("elbow flexion (deg)\n(dashed: target)")
    axes[1].set_ylabel("stimulation\n(+ flexors, - triceps)")
    axes[2].set_ylabel("GHstab")
    axes[2].axhline(1.0, color="tab:red", ls="--", lw=0.8)
    axes[2].set_xlabel("time (s)")
    axes[0].set_title("PD elbow control by FES on a weakened arm (armrt/FESElbow-v0)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--targets", type=float, nargs="+", default=[40.0, 80.0, 110.0], help="deg")
    p.add_argument("--kp", type=float, default=1.5, help="stimulation per rad of error")
    p.add_argument("--kd", type=float, default=0.15, help="stimulation per rad/s")
    p.add_argument("--bias", type=float, default=0.1, help="constant flexor stimulation")
    p.add_argument("--duration", type=float, default=3.0, help="s per target")
    p.add_argument("--out", default="fes_elbow_pd")
    a = p.parse_args(argv)
    runs = run(a.targets, a.kp, a.kd, a.bias, a.duration)
    plot(runs, a.out + ".png")
    for r in runs:
        tail = r["t"] >= r["t"][-1] - 0.5
        err = np.degrees(np.abs(r["elbow"][tail] - r["target"])).mean()
        print(f"target {np.degrees(r['target']):5.1f} deg: mean |error| over the last 0.5 s {err:4.1f} deg, "
              f"max GHstab {r['gh_stab'].max():.2f}")
    print(f"wrote {a.out}.png")
    return runs


if __name__ == "__main__":
    main()
