"""Gymnasium environments over armrt tasks: one arm (`ArmEnv`) or n arms on an ArmBatch
(`ArmVectorEnv`, a gymnasium.vector.VectorEnv). Same task code for both (armrt.gym.tasks)."""
from __future__ import annotations

from types import SimpleNamespace

import gymnasium as gym
import numpy as np
from gymnasium.utils import seeding
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

from ..batch import ArmBatch
from .tasks import TASKS

ARM_KWARGS = ("model", "integrator", "dt", "substeps")


def _split(kwargs: dict) -> tuple[dict, dict]:
    arm = {k: kwargs.pop(k) for k in ARM_KWARGS if k in kwargs}
    return arm, kwargs


class ArmEnv(gym.Env):
    """One arm on a task ("reach", "fes_elbow" or "fes_elbow_stim"; see armrt.gym.tasks for observation, action,
    reward and termination). Keyword arguments: model, integrator, dt, substeps (as armrt.Arm) and
    the task's own (env_dt, episode_duration, ...). render_mode="rgb_array": render() returns the
    `armrt animate` figure of the episode so far as an (H, W, 3) uint8 array."""

    metadata = {"render_modes": ["rgb_array"], "render_fps": 25}

    def __init__(self, task: str = "reach", render_mode: str | None = None, **kwargs):
        if task not in TASKS:
            raise ValueError(f"unknown task {task!r}; expected one of {sorted(TASKS)}")
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode must be one of {self.metadata['render_modes']} or None, got {render_mode!r}")
        arm_kw, task_kw = _split(dict(kwargs))
        arm_kw.update(TASKS[task].batch_options(arm_kw, task_kw))
        self.batch = ArmBatch(1, threads=1, **arm_kw)
        self.task = TASKS[task](self.batch, **task_kw)
        self.task_name = task
        self.render_mode = render_mode
        self.action_space = self.task.action_space
        self.observation_space = self.task.observation_space
        self._history: list = []

    def reset(self, *, seed: int | None = None, options: dict | None = None):
        super().reset(seed=seed)
        self.task.reset(np.array([0]), [self.np_random], options)
        self._history.clear()
        self._record()
        return self.task.observe()[0], {}

    def step(self, action):
        obs, reward, terminated, truncated, info = self.task.step(np.asarray(action)[None])
        self._record()
        out = {k: v[0].item() for k, v in info.items()}
        if out["diverged"]:
            out["error"] = self.batch.errors.get(0, "")
        return obs[0], float(reward[0]), bool(terminated[0]), bool(truncated[0]), out

    def _record(self):
        if self.render_mode is None:
            return
        b = self.batch
        self._history.append((float(b.time[0]), np.array(b.q[0]), float(b.gh_stab[0]), np.array(b.activation[0])))

    def render(self):
        """(H, W, 3) uint8: front and side views of the arm now, GHstab over the episode, muscle
        activations (the `armrt animate` figure), with the reaching target as a star."""
        if self.render_mode is None:
            gym.logger.warn("render() called without render_mode; pass render_mode='rgb_array' to gymnasium.make")
            return None
        if not self._history:
            raise gym.error.ResetNeeded("call reset() before render()")
        from .render import render_frame
        t, q, stab, act = (np.array(v) for v in zip(*self._history))
        result = SimpleNamespace(time=t, q=q, gh_stab=stab, activation=act, element_names=self.batch.element_names,
                                 model=self.batch.model_name)
        target = self.task.target[0] if self.task_name == "reach" else None
        return render_frame(result, target=target)


class ArmVectorEnv(VectorEnv):
    """num_envs arms of one task stepped together on an ArmBatch (C++ threads, GIL released).

    Autoreset: next-step (Gymnasium 1.x's default, as SyncVectorEnv): the step after an arm's
    episode ends resets that arm, ignores its action and returns its first observation with reward
    0. Seeding as SyncVectorEnv: reset(seed=s) seeds arm i with s + i (or with seed[i] for a list),
    so each arm's episodes are those of ArmEnv(seed=s + i), bit for bit. reset(options=...) gives
    every arm the same options (e.g. the FES target); autoresets use none. threads: for the batch
    (default: OMP_NUM_THREADS if set, else the cores available). Other keyword arguments as ArmEnv.
    """

    metadata = {"autoreset_mode": AutoresetMode.NEXT_STEP, "render_modes": []}

    def __init__(self, num_envs: int, task: str = "reach", threads: int | None = None, **kwargs):
        if task not in TASKS:
            raise ValueError(f"unknown task {task!r}; expected one of {sorted(TASKS)}")
        arm_kw, task_kw = _split(dict(kwargs))
        arm_kw.update(TASKS[task].batch_options(arm_kw, task_kw))
        self.batch = ArmBatch(num_envs, threads=threads, **arm_kw)
        self.task = TASKS[task](self.batch, **task_kw)
        self.num_envs = self.batch.n
        self.single_action_space = self.task.action_space
        self.single_observation_space = self.task.observation_space
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self.render_mode = None
        self._rngs: list = [None] * self.num_envs
        self._autoreset = np.zeros(self.num_envs, dtype=bool)

    def reset(self, *, seed: int | list | None = None, options: dict | None = None):
        if seed is None:
            seeds = [None] * self.num_envs
        elif isinstance(seed, (int, np.integer)):
            seeds = [int(seed) + i for i in range(self.num_envs)]
        else:
            seeds = list(seed)
            if len(seeds) != self.num_envs:
                raise ValueError(f"seed must be an int or a list of {self.num_envs} seeds, got {len(seeds)}")
        if seed is not None:
            self._np_random, self._np_random_seed = seeding.np_random(seeds[0])
        for i, s in enumerate(seeds):
            if s is not None or self._rngs[i] is None:
                self._rngs[i] = seeding.np_random(s)[0]
        self.task.reset(np.arange(self.num_envs), self._rngs, options)
        self._autoreset[:] = False
        return self.task.observe(), {}

    def step(self, actions):
        obs, reward, terminated, truncated, info = self.task.step(actions)
        done_before = np.flatnonzero(self._autoreset)
        if done_before.size:
            self.task.reset(done_before, [self._rngs[i] for i in done_before])
            obs = self.task.observe()
            reward[done_before] = 0.0
            terminated[done_before] = False
            truncated[done_before] = False
        infos = {}
        live = ~self._autoreset
        for k, v in info.items() if live.any() else ():   # as SyncVectorEnv: no keys when all arms reset
            infos[k] = np.where(live, v, np.zeros_like(v))
            infos["_" + k] = live.copy()
        diverged = np.flatnonzero(live & info["diverged"])
        if diverged.size:   # as ArmEnv's info["error"], gathered as SyncVectorEnv gathers strings
            infos["error"] = np.full(self.num_envs, None, dtype=object)
            infos["_error"] = np.zeros(self.num_envs, dtype=bool)
            errors = self.batch.errors
            for i in diverged:
                infos["error"][i], infos["_error"][i] = errors.get(int(i), ""), True
        self._autoreset = terminated | truncated
        return obs, reward, terminated, truncated, infos


def _fixed(task: str, vector: bool):
    base = ArmVectorEnv if vector else ArmEnv

    class Env(base):
        __doc__ = base.__doc__

        def __init__(self, *args, **kwargs):
            super().__init__(*args, task=task, **kwargs)

    return Env


ReachEnv = _fixed("reach", False)
ReachEnv.__name__ = ReachEnv.__qualname__ = "ReachEnv"
FESElbowEnv = _fixed("fes_elbow", False)
FESElbowEnv.__name__ = FESElbowEnv.__qualname__ = "FESElbowEnv"
ReachVectorEnv = _fixed("reach", True)
ReachVectorEnv.__name__ = ReachVectorEnv.__qualname__ = "ReachVectorEnv"
FESElbowVectorEnv = _fixed("fes_elbow", True)
FESElbowVectorEnv.__name__ = FESElbowVectorEnv.__qualname__ = "FESElbowVectorEnv"
FESElbowStimEnv = _fixed("fes_elbow_stim", False)
FESElbowStimEnv.__name__ = FESElbowStimEnv.__qualname__ = "FESElbowStimEnv"
FESElbowStimVectorEnv = _fixed("fes_elbow_stim", True)
FESElbowStimVectorEnv.__name__ = FESElbowStimVectorEnv.__qualname__ = "FESElbowStimVectorEnv"
