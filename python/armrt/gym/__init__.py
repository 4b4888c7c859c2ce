"""Gymnasium (1.x) environments of armrt, registered on import:

    import armrt.gym, gymnasium as gym
    env = gym.make("armrt/Reach-v0")                            # one arm
    envs = gym.make_vec("armrt/Reach-v0", num_envs=64)          # ArmBatch: C++ threads, next-step autoreset
    env = gym.make("armrt/FESElbow-v0", strength=0.4, max_activation=0.6)
    env = gym.make("armrt/FESElbowStim-v0", observe_fatigue=True)  # stimulation actions, fatigue on

Without importing first: gym.make("armrt.gym:armrt/Reach-v0") (Gymnasium's module:id form).
Ids: armrt/Reach-v0 (hand to a target), armrt/FESElbow-v0 (elbow angle tracking by exciting
the elbow muscles of a weakened arm), armrt/FESElbowStim-v0 (the same task driven by per-channel
stimulation commands through a stimulation map, with muscle fatigue). Task definitions, units and
rewards: armrt.gym.tasks.
"""
from __future__ import annotations

import gymnasium

from .envs import (ArmEnv, ArmVectorEnv, FESElbowEnv, FESElbowStimEnv, FESElbowStimVectorEnv, FESElbowVectorEnv,
                   ReachEnv, ReachVectorEnv)
from .tasks import FES_ELBOW_MUSCLES, TASKS, FESElbowStimTask, FESElbowTask, ReachTask, elbow_stimulation_map

ENV_IDS = {
    "armrt/Reach-v0": ("ReachEnv", "ReachVectorEnv"),
    "armrt/FESElbow-v0": ("FESElbowEnv", "FESElbowVectorEnv"),
    "armrt/FESElbowStim-v0": ("FESElbowStimEnv", "FESElbowStimVectorEnv"),
}


def register_envs() -> None:
    """Registers armrt's environments with Gymnasium (idempotent; also the package's
    `gymnasium.envs` entry point)."""
    for env_id, (single, vector) in ENV_IDS.items():
        if env_id not in gymnasium.registry:
            gymnasium.register(env_id, entry_point=f"armrt.gym.envs:{single}",
                               vector_entry_point=f"armrt.gym.envs:{vector}")


register_envs()

__all__ = ["ArmEnv", "ArmVectorEnv", "ReachEnv", "FESElbowEnv", "FESElbowStimEnv", "ReachVectorEnv",
           "FESElbowVectorEnv", "FESElbowStimVectorEnv", "ReachTask", "FESElbowTask", "FESElbowStimTask", "TASKS",
           "FES_ELBOW_MUSCLES", "elbow_stimulation_map", "ENV_IDS", "register_envs"]
