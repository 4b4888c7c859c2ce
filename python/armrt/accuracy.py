"""Accuracy of the fixed-step integrators against CVODE (BDF, rtol 1e-8) at every control step:
seeded random-excitation protocols (docs/engine.md), used by the tests and by `python -m bench integrators`.

A protocol is what a lab would throw at the arm offline: piecewise-constant excitations that change
every 50-500 ms at levels 0-1 (uniform, bang-bang or a few muscles at a time), with or without a hand
load of up to 20 N, on an intact, weakened or partly paralysed arm. The same seed gives the same protocol.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .arm import Arm, Result

KINDS = ("uniform", "bang_bang", "sparse")
PROFILES = ("intact", "weak", "paralysed")


@dataclass
class Protocol:
    seed: int
    kind: str                     # one of KINDS
    profile: str                  # one of PROFILES
    duration: float               # s
    switch_times: np.ndarray      # (K,) s, when the excitation changes (first is 0)
    levels: np.ndarray            # (K, n) excitation held from each switch time
    hand_force: np.ndarray        # (3,) N, thorax frame
    strength: np.ndarray          # (n,) strength scale
    max_activation: np.ndarray    # (n,)

    @property
    def label(self) -> str:
        load = f"{np.linalg.norm(self.hand_force):.0f} N" if np.any(self.hand_force) else "no load"
        return f"seed {self.seed}: {self.kind}, {self.profile}, {load}"

    def excitation(self, dt: float) -> np.ndarray:
        """(T, n) excitation, one row per control step of dt (s)."""
        t = dt * np.arange(int(round(self.duration / dt)))
        k = np.searchsorted(self.switch_times, t + 1e-12, side="right") - 1
        return self.levels[k]


def random_protocol(seed: int, n_elements: int, duration: float = 5.0, muscles: list[list[int]] | None = None) -> Protocol:
    """A seeded protocol (see the module docstring). muscles: element indices of each muscle (weakness and
    paralysis are drawn per muscle, as a lesion would affect them); default one element per muscle."""
    rng = np.random.default_rng(seed)
    muscles = muscles or [[i] for i in range(n_elements)]
    kind = KINDS[seed % len(KINDS)]
    profile = PROFILES[(seed // len(KINDS)) % len(PROFILES)]
    # Switch times on a 10 ms grid, so control steps of 1 and 2 ms see the same input.
    times = [0.0]
    while times[-1] < duration:
        times.append(times[-1] + round(rng.uniform(0.05, 0.5), 2))
    times = np.array(times[:-1])
    K = len(times)
    per_muscle = np.zeros((K, len(muscles)))
    if kind == "uniform":
        per_muscle = rng.uniform(0.0, 1.0, (K, len(muscles))) * (rng.uniform(size=(K, len(muscles))) < 0.5)
    elif kind == "bang_bang":
        per_muscle = (rng.uniform(size=(K, len(muscles))) < 0.35).astype(float)
    else:  # a few muscles at a time, strongly
        for k in range(K):
            on = rng.choice(len(muscles), size=rng.integers(1, 5), replace=False)
            per_muscle[k, on] = rng.uniform(0.3, 1.0, len(on))
    levels = np.zeros((K, n_elements))
    for m, idx in enumerate(muscles):
        levels[:, idx] = per_muscle[:, m:m + 1]
    hand = np.zeros(3)
    if seed % 2 == 1:
        d = rng.normal(size=3)
        hand = rng.uniform(2.0, 20.0) * d / np.linalg.norm(d)
    strength = np.ones(n_elements)
    max_act = np.ones(n_elements)
    if profile == "weak":
        for idx in muscles:
            strength[idx] = rng.uniform(0.1, 1.0)
    elif profile == "paralysed":
        for idx in muscles:
            if rng.uniform() < 0.4:
                max_act[idx] = 0.0
    return Protocol(seed, kind, profile, float(duration), times, levels, hand, strength, max_act)


def run_protocol(p: Protocol, integrator: str, dt: float = 1e-3, q0=None, substeps: int | None = None,
                 record_every: int = 1) -> Result:
    """Runs p from rest (q0: start posture, rad; default the model's rest posture) with the integrator."""
    arm = Arm(integrator=integrator, dt=dt, substeps=substeps)
    arm.strength = p.strength
    arm.max_activation = p.max_activation
    arm.set_hand_load(force=p.hand_force)
    arm.reset(q=q0)
    return arm.simulate(p.excitation(dt), p.duration, record_every=record_every)


def joint_errors_deg(res: Result, ref: Result) -> np.ndarray:
    """Largest joint-angle difference (deg) at each common time of res and ref (same sampling)."""
    n = min(len(res.time), len(ref.time))
    if not np.allclose(res.time[:n], ref.time[:n], atol=1e-9):
        raise ValueError("results sampled at different times")
    return np.degrees(np.abs(res.q[:n] - ref.q[:n]).max(axis=1))


def muscles_of(arm: Arm) -> list[list[int]]:
    return [arm.indices(m) for m in arm.muscle_names]
