"""The tasks behind armrt's Gymnasium environments, written once for n arms of an ArmBatch: the
single environment is the n = 1 case, the vector environment any n, so both run the same code.

Each env step holds the action for `env_dt` seconds (frame_skip control steps of the arm). Actions
are excitations in [0, 1] of the task's channels (muscles, or elements); a channel drives all the
elements of its muscle. FESElbowStimTask's actions are instead fractions in [0, 1] of its stimulation
map's channel commands (amplitude, pulse width or both with frequency). Observations are float32; units below.
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
        self.driven_channel = (self.channel_matrix[:, self.driven].argmax(axis=0) if len(channels)
                               else np.zeros(0, dtype=np.int64))   # a task without excitation channels
        self.channel_elements = [np.flatnonzero(row) for row in self.channel_matrix]
        self.action_space = spaces.Box(0.0, 1.0, (len(channels),), np.float32)
        self.steps = np.zeros(self.n, dtype=np.int64)
        self.dof = {name: j for j, name in enumerate(batch.dof_names)}

    # -- to be provided by a task
    observation_space: spaces.Box

    @classmethod
    def batch_options(cls, arm_kw: dict, task_kw: dict) -> dict:
        """ArmBatch keyword arguments the task needs beyond the arm's (popped from task_kw); none here."""
        return {}

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
        """Applies (n, channels) actions for env_dt; returns obs, reward, terminated, truncated, info. Values
        outside the Box are clipped to it; a NaN or an infinity is a broken policy, not a large command: ValueError
        naming the arm (nothing is applied)."""
        raw = np.asarray(action, dtype=np.float64).reshape(self.n, -1)
        bad = ~np.isfinite(raw).all(axis=1)
        if bad.any():
            raise ValueError(f"action of arm {int(np.flatnonzero(bad)[0])} is not finite (NaN or infinity); "
                             "nothing was applied")
        a = np.clip(raw, 0.0, 1.0)
        if a.shape[1] != self.action_space.shape[0]:
            raise ValueError(f"action must have {self.action_space.shape[0]} values per arm ({self._action_layout()}), "
                             f"got {a.shape[1]}")
        self._apply(a)
        self.batch.step(self.frame_skip, warn=False)
        self.steps += 1
        reward, terminated, info = self._reward(a)
        diverged = self.batch.diverged
        reward = np.where(diverged, -self.divergence_penalty, reward)
        terminated = terminated | diverged
        truncated = (self.steps >= self.max_steps) & ~terminated
        info["diverged"] = diverged
        return self.observe(), reward, terminated, truncated, info

    def _apply(self, a: np.ndarray) -> None:
        """Holds the (n, action size) clipped actions as the arms' inputs for the next env step."""
        u = np.tile(self.background, (self.n, 1))
        u[:, self.driven] = a[:, self.driven_channel]
        self.batch.set_excitation(u)

    def _action_layout(self) -> str:
        return ", ".join(self.channels)

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


# Hz: the default train rate of the stimulation env: fused (ripple under 5 % from 20 Hz, docs/fes.md) and inside
# the 20-40 Hz clinicians use, below the 50 Hz device limit, since a higher rate fatigues faster for little force.
DEFAULT_FREQUENCY_HZ = 30.0
MODULATIONS = ("amplitude", "pulse_width", "all")


def elbow_stimulation_map(muscles=FES_ELBOW_MUSCLES, kind: str = "intramuscular", fatigue: bool = True) -> dict:
    """The stimulation env's default map: one channel per muscle of `muscles`, named after it, reaching all
    its elements with weight 1, the kind's default limits and parameters (docs/fes.md), fatigue on."""
    return {"fatigue": bool(fatigue),
            "channels": [{"name": m, "kind": kind, "elements": [m]} for m in muscles]}


class FESElbowStimTask(FESElbowTask):
    """FES elbow by stimulation: the fes_elbow task (target, start, weakened arm, background tone, reward)
    with per-channel stimulation commands as the action and the muscles' fatigue (Ding et al. 2003) on.

    stimulation: the map (docs/fes.md): None (default: one intramuscular channel per muscle of
    FES_ELBOW_MUSCLES, `elbow_stimulation_map()`), "per_muscle" (all 22 muscles: the shoulder then follows
    the stimulation too and the background tone is ignored), a .json/.toml file or a dict. fatigue: True
    (default) turns the map's fatigue on whatever the map says; False off (a control run).
    Action (float32 Box in [0, 1], clipped there as every armrt env does; NaN raises ValueError), per
    channel in the map's order, with `modulation`:
      "amplitude" (default, as surface FES controllers modulate): a -> amplitude a * amp_max at a fixed
        pulse width (`pulse_width`, default the channel's recruitment reference pulse width, 200 us
        intramuscular, 300 us surface) and frequency (`frequency`, default 30 Hz); amp_max is the
        channel's max_amplitude_A, lowered to max_charge_C / pulse width where the charge cap binds;
      "pulse_width" (as implanted systems modulate): a -> pulse width a * pw_max at a fixed amplitude
        (`amplitude`, default the channel's saturation current, capped at its limit) and frequency;
        pw_max: max_pulse_width_s, lowered likewise to max_charge_C / amplitude;
      "all": three values per channel, [pulse width, amplitude, frequency] for channel 0, then channel 1,
        ...: each a fraction of the channel's limit, the amplitude then lowered to max_charge_C / pulse
        width where the charge would exceed it (the pulse width kept).
    pulse_width (s), amplitude (A), frequency (Hz): a number or one value per channel; ValueError naming
    the channel for one beyond its limits. No action maps beyond a channel's limits, so the engine never
    refuses one. `commands(action)` gives the (n, channels, 3) commands an action holds; the attributes
    pulse_width (s), amplitude (A), frequency (Hz), each (channels,), are the command at action 1 (before
    "all"'s charge rule).
    Observation (float32): q (dofs, rad) | qdot (dofs, rad/s) | activation of each channel (mean of the
    elements it reaches) | target elbow angle (1, rad) | elbow error (1, rad) | with observe_fatigue,
    each channel's fatigue 1 - A/A_rest in [0, 1] (channels). Fatigue is hidden by default: no sensor
    measures it in a person, so a deployable controller must infer it from the response's decline;
    observe_fatigue=True is the privileged setting (a teacher, an asymmetric critic, an upper bound).
    The one number per channel is the whole fatigue state: Ding's A, tau1 and Km drift by linear
    equations with the same tau_fat and the same force drive, so from rest their drifts stay
    proportional (tests/test_gym_fes.py checks it).
    Reward: -|elbow - target| (rad) - effort_weight * mean(action^2), as fes_elbow. info adds
    "mean_fatigue" (mean over channels). reset() rests every channel of the arms it resets and zeroes
    their commands.
    """

    def __init__(self, batch: ArmBatch, modulation: str = "amplitude", pulse_width=None, amplitude=None,
                 frequency=None, observe_fatigue: bool = False, **kwargs):
        if not batch.channel_names:
            raise ValueError("the stimulation task needs an ArmBatch with a stimulation map "
                             "(ArmBatch(n, model, stimulation=...); the env builds it)")
        if modulation not in MODULATIONS:
            raise ValueError(f"modulation must be one of {MODULATIONS}, got {modulation!r}")
        if "stimulated" in kwargs:
            raise ValueError("the stimulation task's channels are its map's: pass stimulation=..., not stimulated=")
        # No excitation channels: the map's channels replace them (they may overlap, with spill-over).
        super().__init__(batch, stimulated=(), **kwargs)
        self.modulation = modulation
        self.observe_fatigue = bool(observe_fatigue)
        self.channels = list(batch.channel_names)
        nc = len(self.channels)
        by_name = {c["name"]: c for c in batch.stimulation_map()["channels"]}
        spec = [by_name[c] for c in self.channels]
        self.reached = [np.unique(np.concatenate([batch.indices(e) for e in c["elements"]])) for c in spec]
        self.channel_elements = self.reached
        reached = np.unique(np.concatenate(self.reached))
        self.background[reached] = 0.0   # the engine ignores excitation there; kept out of the reset activation
        lim = {k: np.array([c["limits"][k] for c in spec]) for k in
               ("max_pulse_width_s", "max_amplitude_A", "max_frequency_Hz", "max_charge_C")}
        self.limits = lim
        self.frequency = self._fixed(frequency, np.minimum(DEFAULT_FREQUENCY_HZ, lim["max_frequency_Hz"]),
                                     lim["max_frequency_Hz"], "frequency", "Hz")
        if modulation == "amplitude":
            ref = np.array([c["recruitment"]["reference_pulse_width_s"] for c in spec])
            self.pulse_width = self._fixed(pulse_width, np.minimum(ref, lim["max_pulse_width_s"]),
                                           lim["max_pulse_width_s"], "pulse_width", "s")
            self.amplitude = np.minimum(lim["max_amplitude_A"], lim["max_charge_C"] / self.pulse_width)
        elif modulation == "pulse_width":
            sat = np.array([c["recruitment"]["saturation_A"] for c in spec])
            self.amplitude = self._fixed(amplitude, np.minimum(sat, lim["max_amplitude_A"]),
                                         lim["max_amplitude_A"], "amplitude", "A")
            self.pulse_width = np.minimum(lim["max_pulse_width_s"], lim["max_charge_C"] / self.amplitude)
        else:
            unused = [k for k, v in (("pulse_width", pulse_width), ("amplitude", amplitude), ("frequency", frequency))
                      if v is not None]
            if unused:
                raise ValueError(f"modulation='all' takes every value from the action; {unused} cannot be fixed")
            self.pulse_width, self.amplitude = lim["max_pulse_width_s"], lim["max_amplitude_A"]
            self.frequency = lim["max_frequency_Hz"]
        self.action_space = spaces.Box(0.0, 1.0, ((3 if modulation == "all" else 1) * nc,), np.float32)
        nd = batch.n_dofs
        a, v = ANGLE_BOUND, batch.max_joint_speed
        self.observation_space = _box([(nd, -a, a), (nd, -v, v), (nc, 0.0, 1.0), (1, -a, a), (1, -2 * a, 2 * a)]
                                      + ([(nc, 0.0, 1.0)] if self.observe_fatigue else []))

    @classmethod
    def batch_options(cls, arm_kw: dict, task_kw: dict) -> dict:
        """Pops `stimulation` and `fatigue` from the task's keyword arguments; returns the ArmBatch keyword
        arguments they make: {"stimulation": the map as a dict, fatigue set}."""
        stimulation = task_kw.pop("stimulation", None)
        fatigue = task_kw.pop("fatigue", True)
        if not isinstance(fatigue, (bool, np.bool_)):
            raise TypeError(f"fatigue must be True or False, got {fatigue!r}")
        if stimulation is None:
            return {"stimulation": elbow_stimulation_map(fatigue=fatigue)}
        from ..arm import Arm
        # A file or "per_muscle" is read by the engine once here (errors name the field), so that the
        # fatigue switch applies to any map.
        kw = {"model": arm_kw["model"]} if "model" in arm_kw else {}
        m = Arm(stimulation=stimulation, **kw).stimulation_map()
        m["fatigue"] = bool(fatigue)
        return {"stimulation": m}

    def _fixed(self, value, default: np.ndarray, limit: np.ndarray, what: str, unit: str) -> np.ndarray:
        """(channels,) a fixed command value (a number or one per channel) checked against each limit."""
        if value is None:
            return default
        v = np.broadcast_to(np.asarray(value, dtype=float), default.shape) if np.ndim(value) == 0 else \
            np.asarray(value, dtype=float)
        if v.shape != default.shape:
            raise ValueError(f"{what} must be a number or {len(default)} values (one per channel: "
                             f"{', '.join(self.channels)}), got shape {v.shape}")
        for k, (x, hi) in enumerate(zip(v, limit)):
            if not (np.isfinite(x) and 0.0 < x <= hi):
                raise ValueError(f"{what} of channel {self.channels[k]!r} must lie in (0, {hi:g}] {unit} "
                                 f"(its limit), got {x!r}")
        return v.copy()

    def commands(self, action) -> np.ndarray:
        """(n, channels, 3) [pulse width s, amplitude A, frequency Hz] that (n, action size) actions in
        [0, 1] hold (clipped there first)."""
        a = np.clip(np.asarray(action, dtype=np.float64).reshape(self.n, -1), 0.0, 1.0)
        nc = len(self.channels)
        cmd = np.empty((self.n, nc, 3))
        if self.modulation == "amplitude":
            cmd[:, :, 0], cmd[:, :, 1], cmd[:, :, 2] = self.pulse_width, a * self.amplitude, self.frequency
        elif self.modulation == "pulse_width":
            cmd[:, :, 0], cmd[:, :, 1], cmd[:, :, 2] = a * self.pulse_width, self.amplitude, self.frequency
        else:
            a = a.reshape(self.n, nc, 3)
            pw = a[:, :, 0] * self.pulse_width
            with np.errstate(divide="ignore"):   # a zero pulse width carries no charge: no cap
                cap = np.where(pw > 0, self.limits["max_charge_C"] / np.where(pw > 0, pw, 1.0), np.inf)
            cmd[:, :, 0], cmd[:, :, 1] = pw, np.minimum(a[:, :, 1] * self.amplitude, cap)
            cmd[:, :, 2] = a[:, :, 2] * self.frequency
        return cmd

    def _apply(self, a):
        self.batch.set_stimulation(self.commands(a))

    def _action_layout(self):
        if self.modulation == "all":
            return f"[pulse width, amplitude, frequency] of each channel: {', '.join(self.channels)}"
        return f"the {self.modulation.replace('_', ' ')} of each channel: {', '.join(self.channels)}"

    def reset(self, idx, rngs, options=None):
        super().reset(idx, rngs, options)   # ArmBatch.reset rests the channels of these arms only
        cmd = self.batch.stimulation
        cmd[np.asarray(idx)] = 0.0           # the held command survives a reset: an episode starts unstimulated
        self.batch.set_stimulation(cmd)

    def observe(self):
        b = self.batch
        elbow = b.q[:, self.elbow]
        parts = [b.q, b.qdot, self._channel_activation(), self.target[:, None], (elbow - self.target)[:, None]]
        return self._finite(np.concatenate(parts + ([b.fatigue] if self.observe_fatigue else []), axis=1))

    def _reward(self, a):
        reward, terminated, info = super()._reward(a)
        info["mean_fatigue"] = self.batch.fatigue.mean(axis=1)
        return reward, terminated, info


TASKS = {"reach": ReachTask, "fes_elbow": FESElbowTask, "fes_elbow_stim": FESElbowStimTask}
