"""The DSEM cadaver landmarks (reference README) and a model's GH joint centre in the scapula frame -> the
glenoid of an armrt model file: centre, normal, rim axes and half-angles, checked against anatomical
version and inclination. Shared by every importer (das2, das3, the reduced models).
"""
from __future__ import annotations

import math

import numpy as np

from .das3_source import ModelInputError

# DSEM cadaver landmarks (cm, DSEM global frame) and glenoid rim half-angles, from the reference README.
DSEM_CM = {
    "GH": [17.08, -1.92, 6.55], "glenoid": [15.14, -1.98, 7.81],
    "AA": [18.26, 0.75, 10.56], "TS": [7.50, -1.17, 15.60], "AI": [10.16, -12.62, 15.67],
}
RIM_HALF_ANGLE_MAJOR_DEG = 44.37
RIM_HALF_ANGLE_MINOR_DEG = 38.55

# The glenoid's version and inclination must fall in these anatomical ranges (deg). Version: CT series
# report means of -1 to -5 deg with single shoulders from -16.7 to +11.6 deg (retroversion negative);
# inclination: a few degrees superior on average, -10..+20 covering the published spread. A glenoid basis
# outside them is a registration error, not anatomy (issue 24: the old Kabsch fit gave -28.5 deg).
VERSION_RANGE_DEG = (-20.0, 10.0)
INCLINATION_RANGE_DEG = (-10.0, 20.0)
# The DSEM GH centre expressed in the landmark frame and the model's GH joint centre (das3.osim's gh1
# location in scapula_r) agree to 0.03 mm; more than this means the scapula frame is not the landmark frame.
GH_CENTRE_TOLERANCE_M = 1e-3


def landmark_frame() -> tuple[np.ndarray, np.ndarray]:
    """DSEM scapula landmark frame (reference README): rows x, y, z in the DSEM global frame, origin AA (m).

    x from TS to AA; z perpendicular to x and to the line AA-AI; y = z x x. DAS3's scapula_r body frame is
    this frame (its origin is AA and das3.osim's gh1 joint sits at the DSEM GH centre expressed in it), so
    no registration is needed: a vector v in DSEM coordinates is R @ v in scapula_r."""
    d = {k: np.array(v) / 100.0 for k, v in DSEM_CM.items()}
    x = d["AA"] - d["TS"]
    x /= np.linalg.norm(x)
    z = np.cross(x, d["AA"] - d["AI"])
    z /= np.linalg.norm(z)
    y = np.cross(z, x)
    return np.array([x, y, z]), d["AA"]


def landmarks_in_scapula() -> dict[str, np.ndarray]:
    """The DSEM landmarks (GH, glenoid, AA, TS, AI) in the scapula_r (= landmark) frame, m."""
    R, origin = landmark_frame()
    return {k: R @ (np.array(v) / 100.0 - origin) for k, v in DSEM_CM.items()}


def glenoid_version_inclination(normal: np.ndarray) -> tuple[float, float]:
    """Clinical version and inclination (deg) of a glenoid normal given in the scapula_r frame.

    normal: unit vector from the GH centre to the glenoid centre (the engine's convention); the
    articular face points the other way. Reference axis: the scapular axis from TS to the glenoid centre
    (Friedman's axis, taken in 3-D). Version: the face's angle from that axis towards anterior in the
    plane of the axis and the scapular plane's normal (z, posterior for a right scapula), so
    retroversion is negative. Inclination: its angle from the axis towards superior in the plane of the
    axis and the in-plane superior direction. Raises ValueError for a zero, non-finite or non-(3,)
    normal, TypeError for a non-numeric one."""
    try:
        n = np.asarray(normal, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"glenoid normal must be 3 real numbers, got {normal!r}") from None
    if n.shape != (3,):
        raise ValueError(f"glenoid normal must have shape (3,), got {n.shape}")
    if not np.all(np.isfinite(n)):
        raise ValueError(f"glenoid normal contains NaN or infinite values: {n.tolist()}")
    if not np.linalg.norm(n) > 0:
        raise ValueError("glenoid normal is zero")
    face = -n / np.linalg.norm(n)
    lm = landmarks_in_scapula()
    axis = lm["glenoid"] - lm["TS"]
    axis /= np.linalg.norm(axis)
    posterior = np.array([0.0, 0.0, 1.0]) - axis[2] * axis
    posterior /= np.linalg.norm(posterior)
    superior = np.cross(posterior, axis)
    version = math.degrees(math.atan2(-(face @ posterior), face @ axis))
    inclination = math.degrees(math.atan2(face @ superior, face @ axis))
    return version, inclination


def glenoid_geometry(gh_centre_scapula: np.ndarray) -> dict:
    """Glenoid basis in the scapula (scapula_r) frame from the DSEM landmarks (reference README).

    gh_centre_scapula: (3,) m, the model's GH joint centre in the scapula frame. The normal is the
    direction from the DSEM GH centre to the glenoid centre expressed in the landmark frame, which is
    the scapula frame itself (landmark_frame); the major axis is the frame's y (superior) made orthogonal
    to the normal, minor = normal x major. A scaled model (a participant's) has its scapula scaled about
    AA: the scale is the least-squares factor taking the DSEM GH centre onto the model's, and the glenoid
    centre is placed with it (directions do not change under a uniform scale). Raises ModelInputError
    when the GH centres still differ by more than 1 mm, the scale is outside 0.7..1.4 (a scapula frame
    that is not DAS3's), or the normal falls outside the anatomical version/inclination ranges."""
    gh_centre_scapula = np.asarray(gh_centre_scapula, dtype=float)
    lm = landmarks_in_scapula()
    scale = float(gh_centre_scapula @ lm["GH"] / (lm["GH"] @ lm["GH"]))
    mismatch = float(np.linalg.norm(scale * lm["GH"] - gh_centre_scapula))
    if not (0.7 <= scale <= 1.4 and mismatch <= GH_CENTRE_TOLERANCE_M):
        raise ModelInputError(
            f"the model's GH joint centre {np.round(gh_centre_scapula, 4).tolist()} m does not match the DSEM GH "
            f"centre in the scapula landmark frame {np.round(lm['GH'], 4).tolist()} m (best scale {scale:.3f}, "
            f"{mismatch * 1e3:.1f} mm apart): the scapula frame is not DAS3's scapula_r, so the DSEM glenoid "
            f"cannot be placed in it")
    normal = lm["glenoid"] - lm["GH"]
    normal /= np.linalg.norm(normal)
    superior = np.array([0.0, 1.0, 0.0])
    major = superior - normal * (superior @ normal)
    major /= np.linalg.norm(major)
    minor = np.cross(normal, major)
    version, inclination = glenoid_version_inclination(normal)
    if not (VERSION_RANGE_DEG[0] <= version <= VERSION_RANGE_DEG[1]
            and INCLINATION_RANGE_DEG[0] <= inclination <= INCLINATION_RANGE_DEG[1]):
        raise ModelInputError(f"glenoid version {version:.1f} deg / inclination {inclination:.1f} deg outside "
                              f"the anatomical ranges {VERSION_RANGE_DEG} / {INCLINATION_RANGE_DEG}")
    return {
        "gh_centre": gh_centre_scapula.tolist(),
        # Anchored at the model's GH centre; the DSEM offset is the same vector in this frame, scaled.
        "glenoid_centre": (gh_centre_scapula + scale * (lm["glenoid"] - lm["GH"])).tolist(),
        "normal": normal.tolist(),
        "major_axis": major.tolist(),
        "minor_axis": minor.tolist(),
        "version_deg": version,
        "inclination_deg": inclination,
        "rim_half_angle_major": math.radians(RIM_HALF_ANGLE_MAJOR_DEG),
        "rim_half_angle_minor": math.radians(RIM_HALF_ANGLE_MINOR_DEG),
        "landmarks_dsem_cm": DSEM_CM,
        # The same landmarks in this model's scapula frame (scaled with it), m: what a viewer draws.
        "landmarks_scapula_m": {k: (scale * v).tolist() for k, v in lm.items()},
        "frame": {"method": "DSEM landmark frame (origin AA; x TS->AA; z perpendicular to x and AA-AI; y = z x x), "
                            "which is DAS3's scapula_r frame: no registration",
                  "gh_centre_from_landmarks_m": lm["GH"].tolist(),
                  "scapula_scale": scale,
                  "gh_centre_mismatch_m": mismatch},
    }
