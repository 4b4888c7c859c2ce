"""What every imported armrt model file shares -> its schema version, gravity, passive joint, muscle
groups and source hashes, and the reference README's cross-checks of das3.osim (das2, das3 and the reduced
importers alike).
"""
from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np

from .das3_source import ModelInputError

SCHEMA_VERSION = 1
GRAVITY_THORAX = [0.0, -9.80665, 0.0]
# DAS3 real-time code's passive joint moments (reference README).
PASSIVE_JOINT = {"stiffness_inside": 1.0, "stiffness_outside": 5000.0, "damping": 1.0}
# Facts from the reference README used to cross-check das3.osim.
README_MASSES = {"humerus": 2.0519, "ulna": 0.5464, "radius": 0.5464, "hand": 0.5250}
README_AXES = {"ELx": [0.999766, 0.008446, -0.019909], "PSy": [-0.113295, 0.974059, 0.195892]}

GROUPS = {
    "rotator_cuff": ["infra", "termin", "supra", "subscap"],
    "deltoid": ["deltscap", "deltclav"],
    "elbow_flexors": ["bicl", "bicb", "brachialis", "brachiorad"],
    "elbow_extensors": ["triclong", "tricmed", "triclat", "anconeus"],
    "pronators": ["pronteres", "pronquad"],
    "supinators": ["supinator"],
    "biceps": ["bicl", "bicb"],
    "triceps": ["triclong", "tricmed", "triclat"],
    "pectoralis_major": ["pectmajt", "pectmajc"],
}


def sha256(path: Path) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def check_against_readme(bodies: dict, dof_axes: dict[str, np.ndarray]):
    for name, mass in README_MASSES.items():
        if abs(bodies[name]["mass"] - mass) > 1e-3:
            raise ModelInputError(f"das3.osim: body '{name}' mass {bodies[name]['mass']} differs from the "
                                  f"reference value {mass} kg")
    for dof, axis in README_AXES.items():
        a = np.asarray(axis) / np.linalg.norm(axis)
        if np.degrees(np.arccos(min(1.0, abs(float(a @ dof_axes[dof]))))) > 0.1:
            raise ModelInputError(f"das3.osim: {dof} axis {dof_axes[dof]} differs from the reference {axis}")
