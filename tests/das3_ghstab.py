"""DAS3's own glenohumeral stability value beside the paper's eq. (5), for docs/conventions.md.

DAS3's MATLAB code (das3test.m and the optimisation scripts that call glenoid_scap; read, not copied)
computes the stability of a GH force differently from the paper's eq. (5), which armrt keeps
(cpp/src/gh_reaction.cc). Written here from that reading, in DAS3's glenoid frame (x the glenoid
axis, y superior-inferior, z the other axis):

- the force is normalised, theta = asin(-y) and phi = asin(z / sqrt(x^2 + z^2)): arcsines, so a force
  and its mirror through the glenoid plane (pulling the head off instead of pressing it in) get the
  same value;
- the angles (rad) are divided by tan(44.37 deg) = 0.978 and tan(38.55 deg) = 0.797 instead of by the
  rim half-angles 0.774 and 0.673 rad, and 1 is subtracted (DAS3's value <= 0 is stable): the rim
  DAS3 tests against along the major axis is at 0.978 rad = 56.0 deg, not 44.37 deg;
- the glenoid frame itself (glenoid_scap) takes the arcsine of the GH-centre-to-glenoid-centre vector
  in cm, not normalised (length 2.31 cm), so its axis is off the landmarks' direction.

`python -m tests.das3_ghstab` prints the table of docs/conventions.md; tests/test_gh_signal.py checks it.
"""
from __future__ import annotations

import numpy as np

from codegen.importers.glenoid import DSEM_CM, RIM_HALF_ANGLE_MAJOR_DEG, RIM_HALF_ANGLE_MINOR_DEG

TA = np.radians(RIM_HALF_ANGLE_MAJOR_DEG)   # rad, the paper's rim half-angles
PA = np.radians(RIM_HALF_ANGLE_MINOR_DEG)


def paper_ghstab(f: np.ndarray) -> float:
    """Eq. (5) for a force in a glenoid frame (x normal, y major, z minor), as the engine does it."""
    theta, phi = np.arctan2(f[1], f[0]), np.arctan2(f[2], f[0])
    return float((theta / TA) ** 2 + (phi / PA) ** 2)


def das3_ghstab(f: np.ndarray) -> float:
    """DAS3's value plus 1 (so that 1 is its rim too), for the same force and frame."""
    u = f / np.linalg.norm(f)
    theta = np.arcsin(-u[1])
    xz = np.hypot(u[0], u[2])
    phi = 0.0 if xz == 0 else np.arcsin(u[2] / xz)
    return float((theta / np.tan(TA)) ** 2 + (phi / np.tan(PA)) ** 2)


def tilted(major_deg: float, minor_deg: float) -> np.ndarray:
    """Unit force whose angles from the normal are major_deg (x-y plane) and minor_deg (x-z plane),
    pressing into the glenoid for angles below 90 deg."""
    t, p = np.radians(major_deg), np.radians(minor_deg)
    f = np.array([np.cos(t) * np.cos(p), np.sin(t) * np.cos(p), np.cos(t) * np.sin(p)])
    return f / np.linalg.norm(f)


# (what, force): the rows of the table.
CASES = [
    ("along the normal", tilted(0, 0)),
    ("20 deg superior", tilted(20, 0)),
    ("44.37 deg superior (eq. (5) rim)", tilted(44.37, 0)),
    ("56.0 deg superior (DAS3's rim)", tilted(np.degrees(np.tan(TA)), 0)),
    ("38.55 deg anterior (eq. (5) rim)", tilted(0, 38.55)),
    ("20 deg superior and 20 deg anterior", tilted(20, 20)),
    ("20 deg superior, pulling the head off", -tilted(20, 0) * np.array([1, -1, -1])),
]


def glenoid_axis_error_deg() -> float:
    """Angle (deg) between DAS3's glenoid axis (glenoid_scap: arcsines of the cm vector from the GH
    centre to the glenoid centre in the landmark frame) and the direction of that vector, which the
    model file records (glenoid.normal: the scapula frame is the landmark frame, codegen/importers/glenoid.py)."""
    import json

    import armrt
    glenoid = json.loads(armrt.Model("das2").model_file.read_text())["glenoid"]
    d = {k: np.asarray(v, float) for k, v in DSEM_CM.items()}
    unit = np.asarray(glenoid["normal"])
    g = unit * np.linalg.norm(d["glenoid"] - d["GH"])   # cm, as DAS3 leaves it
    # DAS3 takes asin of the unnormalised component; phi it normalises, so the axes differ by theta only.
    return float(np.degrees(abs(np.arcsin(-g[1]) - np.arcsin(-unit[1]))))


def table() -> str:
    rows = ["| force (glenoid frame) | eq. (5) GHstab | DAS3 value + 1 |", "|---|---|---|"]
    rows += [f"| {what} | {paper_ghstab(f):.3f} | {das3_ghstab(f):.3f} |" for what, f in CASES]
    return "\n".join(rows)


if __name__ == "__main__":
    print(table())
    print(f"\nDAS3's glenoid axis is {glenoid_axis_error_deg():.2f} deg off the GH-to-glenoid direction.")
