"""The 11-DOF DAS3 chain (thorax fixed) read from das3.osim, in the `bodies` form of docs/model_schema.md.

das3.osim models each 3-DOF joint (SC, AC, GH) as three CustomJoints in series through massless bodies
(clavicle_1, clavicle_2; scapula_1, scapula_2; humerus_1, humerus_2), each CustomJoint turning about one
axis by one coordinate. Each is collapsed here into one body with a joint of three body-fixed rotations
at the first CustomJoint's location, after checking that what is dropped is really zero (the constant
rotations, the offsets of the second and third CustomJoints, every translation) and that the slopes are 1,
so that the coordinate is the angle.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from . import das3_source as src
from .das3_source import ModelInputError

DAS3_DOFS = src.ALL_DOFS   # SCy SCz SCx ACy ACz ACx GHy GHz GHyy ELx PSy
OSIM_DOF = {"SCy": "SC_y", "SCz": "SC_z", "SCx": "SC_x", "ACy": "AC_y", "ACz": "AC_z", "ACx": "AC_x",
            "GHy": "GH_y", "GHz": "GH_z", "GHyy": "GH_yy", "ELx": "EL_x", "PSy": "PS_y"}
# (our body, osim bodies from proximal to the one carrying the mass, joint name, parent body)
DAS3_BODIES = [
    ("clavicle", ["clavicle_1", "clavicle_2", "clavicle_r"], "sc", "thorax"),
    ("scapula", ["scapula_1", "scapula_2", "scapula_r"], "ac", "clavicle"),
    ("humerus", ["humerus_1", "humerus_2", "humerus_r"], "gh", "scapula"),
    ("ulna", ["ulna_r"], "hu", "humerus"),
    ("radius", ["radius_r"], "ur", "ulna"),
    ("hand", ["hand_r"], "rc", "radius"),
]
BASE = "thorax"


def das3_bodies(osim_path: str | Path) -> list[dict]:
    """Bodies clavicle .. hand with their joints; raises ModelInputError naming what does not fit."""
    osim = src.read_osim(osim_path)
    inverse = {v: k for k, v in OSIM_DOF.items()}
    thorax = osim.get("thorax")
    if thorax is None or thorax.joint is None or thorax.joint.parent != "ground" or thorax.joint.rotations \
            or np.any(thorax.joint.location_in_parent != 0) or np.any(thorax.joint.translation != 0):
        raise ModelInputError("das3.osim: thorax must be welded to ground at its origin (thorax frame = ground)")
    out = []
    for name, chain, jname, parent in DAS3_BODIES:
        axes, dofs = [], []
        for k, link in enumerate(chain):
            if link not in osim or osim[link].joint is None:
                raise ModelInputError(f"das3.osim: missing Body '{link}' or its joint")
            b, j = osim[link], osim[link].joint
            expected_parent = {"thorax": "thorax", "clavicle": "clavicle_r", "scapula": "scapula_r",
                               "humerus": "humerus_r", "ulna": "ulna_r", "radius": "radius_r"}[parent] \
                if k == 0 else chain[k - 1]
            if j.parent != expected_parent:
                raise ModelInputError(f"das3.osim: joint '{j.name}' has parent '{j.parent}', expected '{expected_parent}'")
            if k < len(chain) - 1 and b.mass != 0.0:
                raise ModelInputError(f"das3.osim: intermediate body '{link}' has mass {b.mass}")
            if k > 0 and np.any(j.location_in_parent != 0):
                raise ModelInputError(f"das3.osim: joint '{j.name}' is offset from its parent")
            if np.any(j.translation != 0):
                raise ModelInputError(f"das3.osim: joint '{j.name}' has a translation")
            for axis, coord, slope, const in j.rotations:
                if coord is None:
                    if const != 0.0:
                        raise ModelInputError(f"das3.osim: joint '{j.name}' has a constant rotation {const}")
                    continue
                if slope != 1.0 or const != 0.0:
                    raise ModelInputError(f"das3.osim: joint '{j.name}' coordinate {coord}: angle = "
                                          f"{slope} q + {const}, expected q")
                if coord not in inverse:
                    raise ModelInputError(f"das3.osim: joint '{j.name}' moves unknown coordinate '{coord}'")
                axes.append([float(v) for v in axis])
                dofs.append(inverse[coord])
        last = osim[chain[-1]]
        out.append({"name": name, "osim_name": chain[-1], "parent": parent, "mass": float(last.mass),
                    "com": last.com.tolist(), "inertia": last.inertia.tolist(),
                    "joint": {"name": jname, "location_in_parent": osim[chain[0]].joint.location_in_parent.tolist(),
                              "axes": axes, "dofs": dofs}})
    got = [d for b in out for d in b["joint"]["dofs"]]
    if got != DAS3_DOFS:
        raise ModelInputError(f"das3.osim: the chain carries {got}, expected {DAS3_DOFS} in this order")
    return out


def girdle_points(model_struct_path: str | Path) -> list[tuple[str, str, list[float]]]:
    """(label, body, point in body coordinates, m) of the points the girdle forces act at, from
    model_struct.mat: TS and AI (the scapula's contact points on the thorax) and the conoid ligament's
    origin (clavicle) and insertion (scapula)."""
    import scipy.io as sio
    try:
        m = sio.loadmat(model_struct_path, squeeze_me=True, struct_as_record=False)["model"]
    except Exception as exc:  # scipy raises several types for corrupt files
        raise ModelInputError(f"{model_struct_path}: not a readable DAS3 model_struct ({exc})") from None
    out = []
    for label, body, field in [("TS", "scapula", "TSprojection"), ("AI", "scapula", "AIprojection"),
                               ("conoid_origin", "clavicle", "conoid_origin"),
                               ("conoid_insertion", "scapula", "conoid_insertion")]:
        if not hasattr(m, field):
            raise ModelInputError(f"{model_struct_path}: model has no field '{field}'")
        v = np.ravel(np.asarray(getattr(m, field), dtype=float))
        if v.shape != (3,) or not np.all(np.isfinite(v)) or np.abs(v).max() > 0.5:
            raise ModelInputError(f"{model_struct_path}: model.{field} must be 3 finite coordinates (m), got {v}")
        out.append((label, body, v.tolist()))
    return out
