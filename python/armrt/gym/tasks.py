"""The tasks behind armrt's Gymnasium environments, written once for n arms of an ArmBatch: the
single environment is the n = 1 case, the vector environment any n, so both run the same code.

Each env step holds the action for `env_dt` seconds (frame_skip control steps of the arm). Actions
are excitations in [0, 1] of the task's channels (muscles, or elements); a channel drives all the
elements of its muscle. Observations are float32; units below.
"""
from __future__ import annotations

import numpy as np
from gymnasium import spaces

from ..batch import ArmBatch


class Task:
    """Shared machinery: channels -> elements, frame skip, time limit, divergence.

    env_dt: s held per action; episode_duration: s, after which `truncated` is set.
    effort_weight: reward cost per unit mean squared action. divergence_penalty: reward of the step
    on which the arm's simulation diverged (the episode then terminates; info["diverged"]).
    background: {name: excitation} added to every step for muscles outside the channels (e.g. a
    small rotator-cuff tone, as the paper's baseline), or None.
    """

    def __init__(self, batch: ArmBatch, channels: list[str], env_dt: float, episode_duration: float,
                 effort_weight: float, divergence_penalty: float = 10.0, background: dict | None = None):
        self.batch = batch
        self.n = batch.n
        if not env_dt > 0 or not episode_duration > 0:
            raise ValueError(f"env_dt and episode_duration must be positive, got {env_dt}, {episode_duration}")
        self.frame_skip = int(round(env_dt / batch.dt))
        if self.frame_skip < 1 or abs(self.frame_skip * batch.dt - env_dt) > 1e-9:
            raise ValueError(f"env_dt ({env_dt} s) must be a whole multiple of the arm's control step dt ({batch.dt} s)")
        self.env_dt = self.frame_skip * batch.dt
        self.max_steps = int(round(episode_duration / self.env_dt))
        self.effort_weight = float(effort_weight)
        self.divergence_penalty = float(divergence_penalty)
        self.channels = list(channels)
        ne = batch.n_elements
        self.channel_matrix = np.zeros((len(channels), ne))   # (channels, elements) 0/1
        for c, name in enumerate(channels):
            self.channel_matrix[c, batch.indices(name)] = 1.0
        if (self.channel_matrix.sum(axis=0) > 1).any():
            raise ValueError(f"channels must not share elements: {channels}")
        self.background = np.zeros(ne)
        for name, level in (background or {}).items():
            self.background[batch.indices(name)] = float(level)
        self.background[self.channel_matrix.any(axis=0)] = 0.0
        # Per-element channel and per-channel elements: indexing, not matrix products, so each arm's
        # numbers do not depend on how many arms are stacked (BLAS may sum in another order).
        self.driven = np.flatnonzero(self.channel_matrix.any(axis=0))
        self.driven_channel = self.channel_matrix[:, self.driven].argmax(axis=0)
        self.channel_elements = [np.flatnonzero(row) for row in self.channel_matrix]
        self.action_space = spaces.Box(0.0, 1.0, (len(channels),), np.float32)
        self.steps = np.zeros(self.n, dtype=np.int64)
        self.dof = {name: j for j, name in enumerate(batch.dof_names)}

    # -- to be provided by a task
    observation_space: spaces.Box

    def _reset_arm(self, i: int, rng: np.random.Generator, options: dict) -> np.ndarray:
        """Samples arm i's task and start posture (values in `options` override the samples, which
        are drawn anyway so the generator advances alike); returns the posture (dofs,) rad."""
        raise NotImplementedError

    def observe(self) -> np.ndarray:
        raise NotImplementedError

    def _reward(self, action: np.ndarray):
        """(reward (n,), terminated (n,), info {name: (n,)}) at the arms' current state."""
        raise NotImplementedError

    # -- shared
    def reset(self, idx: np.ndarray, rngs, options: dict | None = None) -> None:
        """Starts new episodes for arms idx, sampling each from its own generator (in order)."""
        idx = np.asarray(idx)
        q = np.array([self._reset_arm(int(i), rng, options or {}) for i, rng in zip(idx, rngs)])
        # Activations start at the background tone (as the experiments' settle()): a weakened arm
        # hanging without it has its GH force far off the glenoid until the tone builds up.
        self.batch.reset(q=q, activation=self.background, arms=idx)
        exc = self.batch.excitation
        exc[idx] = self.background
        self.batch.set_excitation(exc)
        self.steps[idx] = 0

    def step(self, action):
        """Applies (n, channels) actions for env_dt; returns obs, reward, terminated, truncated, info."""
        a = np.clip(np.asarray(action, dtype=np.float64).reshape(self.n, -1), 0.0, 1.0)
        if a.shape[1] != len(self.channels):
            raise ValueError(f"action must have {len(self.channels)} values per arm ({', '.join(self.channels)}), got {a.shape[1]}")
        u = np.tile(self.background, (self.n, 1))
        u[:, self.driven] = a[:, self.driven_channel]
        self.batch.set_excitation(u)
        self.batch.step(self.frame_skip, warn=False)
        self.steps += 1
        reward, terminated, info = self._reward(a)
        diverged = self.batch.diverged
        reward = np.where(diverged, -self.divergence_penalty, reward)
        terminated = terminated | diverged
        truncated = (self.steps >= self.max_steps) & ~terminated
        info["diverged"] = diverged
        return self.observe(), reward, terminated, truncated, info

    def _effort(self, a: np.ndarray) -> np.ndarray:
        return np.mean(a * a, axis=1)

    def _channel_activation(self) -> np.ndarray:
        """(n, channels) mean activation of each channel's elements."""
        act = self.batch.activation
        return np.stack([act[:, e].mean(axis=1) for e in self.channel_elements], axis=1)

    def _finite(self, obs: np.ndarray) -> np.ndarray:
        # A diverged arm's state may hold NaN or leave the bounds: its final observation is zeroed
        # there and clipped so it stays inside the observation space (the episode terminates with
        # info["diverged"]). A live arm stays inside the bounds.
        obs = np.nan_to_num(obs, nan=0.0, posinf=0.0, neginf=0.0).astype(np.float32)
        return np.clip(obs, self.observation_space.low, self.observation_space.high)


# m: bound of hand and target coordinates in the thorax frame (the arm is well under 1 m long).
WORKSPACE_BOUND = 2.0
# rad: bound of the joint angles in the observation (the joints' ranges lie well inside).
ANGLE_BOUND = 2.0 * np.pi


def _box(parts):
    """A float32 Box from [(size, low, high), ...]."""
    low = np.concatenate([np.full(k, lo) for k, lo, _ in parts]).astype(np.float32)
    high = np.concatenate([np.full(k, hi) for k, _, hi in parts]).astype(np.float32)
    return spaces.Box(low, high, dtype=np.float32)


class ReachTask(Task):
    """Reaching: bring the hand to a target sampled in the reachable workspace.

    Target: the hand position at a posture drawn uniformly inside the joint ranges (shrunk by
    `target_margin` of each range at both ends). Start: the rest posture plus uniform noise of
    +-start_noise rad per joint. A model with a moving girdle (das3) keeps its girdle DOFs
    (Model.girdle_dofs) at the rest posture in both: girdle angles drawn independently put the
    scapula's TS and AI into or off the thorax (+-0.05 rad on the six girdle angles: up to 14 mm
    inside it, and the stiff contact throws the scapula at tens of rad/s; ros2 at 1 ms can fail on
    the first step), so the target is one the arm reaches from the resting girdle, and the girdle
    then moves as the muscles and the contact make it.
    Actions: excitation of each muscle (actions="muscles", one channel per muscle) or of each
    element (actions="elements"), in [0, 1].
    Observation (float32): q (dofs, rad) | qdot (dofs, rad/s) | activation (channels, mean of each
    channel's elements) | hand position (3, m, thorax frame) | target position (3, m) | GH stability (1).
    Reward per step: -distance(hand, target) (m) - effort_weight * mean(action^2)
    - gh_weight * max(0, GHstab - 1).
    Terminated when GHstab stays above 1 (the humeral head's force outside the glenoid rim: the joint
    would dislocate) for longer than `dislocation_time` s, checked once per env step, or when the
    simulation diverges; truncated at episode_duration.
    """

    def __init__(self, batch: ArmBatch, actions: str = "muscles", env_dt: float = 0.01,
                 episode_duration: float = 2.0, effort_weight: float = 0.05, gh_weight: float = 1.0,
                 dislocation_time: float = 0.2, target_margin: float = 0.15, start_noise: float = 0.05,
                 background: dict | None = None):
        if actions == "muscles":
            channels = list(batch.muscle_names)
        elif actions == "elements":
            channels = list(batch.element_names)
        else:
            raise ValueError(f"actions must be 'muscles' or 'elements', got {actions!r}")
        super().__init__(batch, channels, env_dt, episode_duration, effort_weight, background=background)
        self.gh_weight = float(gh_weight)
        self.dislocation_time = float(dislocation_time)
        self.target_margin = float(target_margin)
        self.start_noise = float(start_noise)
        self.target = np.zeros((self.n, 3))
        self.unstable_time = np.zeros(self.n)
        self.sampled = np.ones(batch.n_dofs, dtype=bool)   # DOFs drawn at random (not the girdle's)
        self.sampled[list(batch.model.girdle_dofs)] = False
        nd, nc = batch.n_dofs, len(channels)
        w, v = WORKSPACE_BOUND, batch.max_joint_speed
        self.observation_space = _box([(nd, -ANGLE_BOUND, ANGLE_BOUND), (nd, -v, v), (nc, 0.0, 1.0),
                                       (3, -w, w), (3, -w, w), (1, 0.0, batch.gh_stab_bound)])

    def _reset_arm(self, i, rng, options):
        lo, hi = self.batch.dof_ranges[:, 0], self.batch.dof_ranges[:, 1]
        m = self.target_margin
        rest = self.batch.rest_posture
        q_target = lo + (hi - lo) * (m + (1.0 - 2.0 * m) * rng.uniform(size=len(lo)))
        q0 = rest + rng.uniform(-self.start_noise, self.start_noise, size=len(lo))
        q_target = np.where(self.sampled, q_target, rest)
        q0 = np.where(self.sampled, q0, rest)
        if "target_posture" in options:
            q_target = np.asarray(options["target_posture"], dtype=float)
        self.target[i] = self.batch.hand_position_at(q_target)[0]
        self.unstable_time[i] = 0.0
        return np.clip(np.asarray(options.get("start_posture", q0), dtype=float), lo, hi)

    def observe(self):
        b = self.batch
        return self._finite(np.concatenate([b.q, b.qdot, self._channel_activation(), b.hand_position,
                                            self.target, b.gh_stab[:, None]], axis=1))

    def _reward(self, a):
        b = self.batch
        distance = np.linalg.norm(b.hand_position - self.target, axis=1)
        excess = np.maximum(0.0, b.gh_stab - 1.0)
        self.unstable_time = np.where(b.gh_stab > 1.0, self.unstable_time + self.env_dt, 0.0)
        reward = -distance - self.effort_weight * self._effort(a) - self.gh_weight * excess
        dislocated = self.unstable_time > self.dislocation_time
        return reward, dislocated, {"distance": distance, "gh_stab": np.array(b.gh_stab), "dislocated": dislocated}


# Elbow muscles an FES system typically stimulates (surface or implanted electrodes).
FES_ELBOW_MUSCLES = ("bicl", "bicb", "brachialis", "brachiorad", "triclong", "tricmed", "triclat")


class FESElbowTask(Task):
    """FES elbow: track a target elbow flexion angle on a weakened arm, stimulating only the
    elbow muscles in `stimulated` (default: biceps, brachialis, brachioradialis, triceps).

    The arm is weakened: `strength` (scale of DAS3 fmax) and `max_activation` (the largest
    activation stimulation recruits) apply to every element: each a number or a {name: value} dict
    (element, muscle or group names; unnamed elements stay intact). The shoulder gets only the
    `background` tone (default rotator cuff 0.05, as the paper's baseline); unstimulated muscles
    are otherwise silent.
    Start: rest posture with the elbow at an angle drawn uniformly in `start_range` (rad).
    Target: elbow angle drawn uniformly in `target_range` (rad), held for the episode.
    reset(options={"target": rad, "start": rad}) sets them.
    Observation (float32): q (dofs, rad) | qdot (dofs, rad/s) | activation of each stimulated muscle
    (mean of its elements) | target elbow angle (1, rad) | elbow error, angle - target (1, rad).
    Reward per step: -|elbow - target| (rad) - effort_weight * mean(action^2).
    Terminated only if the simulation diverges; truncated at episode_duration.
    """

    def __init__(self, batch: ArmBatch, stimulated=FES_ELBOW_MUSCLES, strength=0.5, max_activation=0.7,
                 env_dt: float = 0.01, episode_duration: float = 3.0, effort_weight: float = 0.1,
                 target_range=(0.3, 2.0), start_range=(0.2, 1.0), background=None, elbow_dof: str = "ELx"):
        super().__init__(batch, list(stimulated), env_dt, episode_duration, effort_weight,
                         background={"rotator_cuff": 0.05} if background is None else background)
        batch.strength = strength if isinstance(strength, dict) else float(strength)
        batch.max_activation = max_activation if isinstance(max_activation, dict) else float(max_activation)
        if elbow_dof not in self.dof:
            raise ValueError(f"unknown elbow DOF {elbow_dof!r}; DOFs are {batch.dof_names}")
        self.elbow = self.dof[elbow_dof]
        self.target_range, self.start_range = tuple(map(float, target_range)), tuple(map(float, start_range))
        self.target = np.zeros(self.n)
        nd, nc = batch.n_dofs, len(self.channels)
        a, v = ANGLE_BOUND, batch.max_joint_speed
        self.observation_space = _box([(nd, -a, a), (nd, -v, v), (nc, 0.0, 1.0), (1, -a, a), (1, -2 * a, 2 * a)])

    def _reset_arm(self, i, rng, options):
        target, start = rng.uniform(*self.target_range), rng.uniform(*self.start_range)
        self.target[i] = float(options.get("target", target))
        q0 = self.batch.rest_posture.copy()
        q0[self.elbow] = float(options.get("start", start))
        return q0

    def observe(self):
        b = self.batch
        elbow = b.q[:, self.elbow]
        return self._finite(np.concatenate([b.q, b.qdot, self._channel_activation(), self.target[:, None],
                                            (elbow - self.target)[:, None]], axis=1))

    def _reward(self, a):
        error = self.batch.q[:, self.elbow] - self.target
        reward = -np.abs(error) - self.effort_weight * self._effort(a)
        return reward, np.zeros(self.n, dtype=bool), {"elbow_error": error}


TASKS = {"reach": ReachTask, "fes_elbow": FESElbowTask}
