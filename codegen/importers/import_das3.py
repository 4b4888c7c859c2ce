"""Import the DAS3 release into the armrt model file (docs/model_schema.md).

    python -m codegen.import_das3 --das3 ../shared/reference/das3 --out models/das2.json

builds the paper's fixed-scapula, 5-DOF, 102-element model: DOFs and ranges, the fixed SC/AC posture,
the arm's bodies and joints from das3.osim, the Hill parameters of the 102 elements, glenoid geometry,
and muscle paths. `--paths opensim` (the default) fits length and line-of-action polynomials against
OpenSim path geometry (codegen/importers/fit_paths.py; needs `pip install opensim`); `--paths das3` keeps the
DAS3 release polynomials with the girdle angles substituted, which needs no OpenSim but does not
match das3.osim for a fixed girdle (see docs/path_accuracy.md). With all 11 DOFs free (`--free
SCy,SCz,SCx,ACy,ACz,ACx,GHy,GHz,GHyy,ELx,PSy`) it builds the shoulder-girdle model das3
(codegen/importers/import_das3_girdle.py); other DOF sets go to codegen/importers/import_reduced.py.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import math
import sys
from pathlib import Path

import numpy as np

from . import das3_source as src
from .das3_source import ModelInputError
from ..polynomial import substitute

SCHEMA_VERSION = 1
ARM_BODIES = [("humerus", "humerus_r"), ("ulna", "ulna_r"), ("radius", "radius_r"), ("hand", "hand_r")]
OSIM_DOF = {"SCy": "SC_y", "SCz": "SC_z", "SCx": "SC_x", "ACy": "AC_y", "ACz": "AC_z", "ACx": "AC_x",
            "GHy": "GH_y", "GHz": "GH_z", "GHyy": "GH_yy", "ELx": "EL_x", "PSy": "PS_y"}
GRAVITY_THORAX = [0.0, -9.80665, 0.0]

# DSEM cadaver landmarks (cm, DSEM global frame) and glenoid rim half-angles, from the reference README.
DSEM_CM = {
    "GH": [17.08, -1.92, 6.55], "glenoid": [15.14, -1.98, 7.81],
    "AA": [18.26, 0.75, 10.56], "TS": [7.50, -1.17, 15.60], "AI": [10.16, -12.62, 15.67],
}
RIM_HALF_ANGLE_MAJOR_DEG = 44.37
RIM_HALF_ANGLE_MINOR_DEG = 38.55
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


def reduce_length_poly(element: src.Das3Element, girdle: dict[str, float]) -> dict:
    """The DAS3 length polynomial with the fixed girdle angles substituted and equal monomials merged."""
    fixed = {j: girdle[d] for j, d in enumerate(element.dof_names) if d in girdle}
    kept, exps, coefs = substitute(element.lparams, element.lcoefs, fixed)
    return {"dofs": [element.dof_names[j] for j in kept], "exponents": exps, "coefs": coefs}


def reduce_direction_poly(element: src.Das3Element, girdle: dict[str, float]) -> dict | None:
    if element.direction is None:
        return None
    fixed = {j: girdle[d] for j, d in enumerate(element.dof_names) if d in girdle}
    out = {"dofs": [d for d in element.dof_names if d not in girdle]}
    for axis, (e, c) in element.direction.items():
        _, exps, coefs = substitute(e, c, fixed)
        out[axis] = {"exponents": exps, "coefs": coefs}
    return out


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


def check_against_readme(bodies: dict, dof_axes: dict[str, np.ndarray]):
    for name, mass in README_MASSES.items():
        if abs(bodies[name]["mass"] - mass) > 1e-3:
            raise ModelInputError(f"das3.osim: body '{name}' mass {bodies[name]['mass']} differs from the "
                                  f"reference value {mass} kg")
    for dof, axis in README_AXES.items():
        a = np.asarray(axis) / np.linalg.norm(axis)
        if np.degrees(np.arccos(min(1.0, abs(float(a @ dof_axes[dof]))))) > 0.1:
            raise ModelInputError(f"das3.osim: {dof} axis {dof_axes[dof]} differs from the reference {axis}")


def build_model(das3_dir: Path, paths: str = "opensim", cache_dir: Path | None = None, seed: int = 0) -> dict:
    das3_dir = Path(das3_dir)
    files = {k: das3_dir / k for k in ["model_struct.mat", "equilibrium.mat", "das3.osim"]}
    for f in files.values():
        if not f.exists():
            raise ModelInputError(f"missing input file {f}")
    struct = src.read_model_struct(files["model_struct.mat"])
    posture = src.read_equilibrium(files["equilibrium.mat"])
    osim = src.read_osim(files["das3.osim"])
    girdle = {d: posture[d] for d in src.GIRDLE_DOFS}
    coords = {OSIM_DOF[d]: v for d, v in posture.items()}

    for needed in ["scapula_r", "humerus_r", "ulna_r", "radius_r", "hand_r"]:
        if needed not in osim:
            raise ModelInputError(f"das3.osim: missing Body '{needed}'")
    R_scap, p_scap = src.body_in_frame(osim, "scapula_r", "ground", coords)

    # Arm bodies. The GH joint is three massless CustomJoints in series (gh1..gh3), collapsed into one
    # joint of three body-fixed rotations at gh1's location in the scapula.
    bodies, dof_axes = {}, {}
    for name, osim_name in ARM_BODIES:
        b = osim[osim_name]
        if name == "humerus":
            chain, jname, parent = ["humerus_1", "humerus_2", "humerus_r"], "gh", "scapula"
        else:
            chain, jname = [osim_name], b.joint.name
            parent = {"ulna": "humerus", "radius": "ulna", "hand": "radius"}[name]
        axes, dofs = [], []
        for link in chain:
            j = osim[link].joint
            for axis, coord, slope, const in j.rotations:
                if coord is None:
                    if const != 0.0:
                        raise ModelInputError(f"das3.osim: joint '{j.name}' has a constant rotation")
                    continue
                if slope != 1.0:
                    raise ModelInputError(f"das3.osim: joint '{j.name}' coordinate {coord} has slope {slope}")
                dof = {v: k for k, v in OSIM_DOF.items()}[coord]
                axes.append(axis.tolist())
                dofs.append(dof)
                dof_axes[dof] = axis
            if link != chain[0] and np.any(j.location_in_parent != 0):
                raise ModelInputError(f"das3.osim: joint '{j.name}' is offset from its parent")
        jtype = {3: "gimbal_yzy", 1: "pin", 0: "weld"}[len(dofs)]
        bodies[name] = {
            "name": name, "osim_name": osim_name, "parent": parent,
            "mass": b.mass, "com": b.com.tolist(), "inertia": b.inertia.tolist(),
            "joint": {"name": jname, "type": jtype,
                      "location_in_parent": osim[chain[0]].joint.location_in_parent.tolist(),
                      "axes": axes, "dofs": dofs},
        }
    if [d for b in bodies.values() for d in b["joint"]["dofs"]] != src.ARM_DOFS:
        raise ModelInputError("das3.osim: the arm joints do not carry GHy, GHz, GHyy, ELx, PSy in order")
    check_against_readme(bodies, dof_axes)

    arm = [e for e in struct.elements if src.muscle_of(e.name) in src.PAPER_MUSCLES]
    gh_centre = np.array(bodies["humerus"]["joint"]["location_in_parent"])
    import scipy.io as sio
    ms = sio.loadmat(files["model_struct.mat"], squeeze_me=True, struct_as_record=False)["model"]
    glenoid = glenoid_geometry(gh_centre)

    if paths == "opensim":
        from .fit_paths import fit_paths  # needs OpenSim
        fits = fit_paths(str(files["das3.osim"]), {OSIM_DOF[d]: v for d, v in girdle.items()},
                         [{"name": e.name, "osim_name": e.osim_name} for e in arm],
                         str(cache_dir or Path("build")), seed=seed)
        rom = {d: [float(v) for v in fits["rom"][d]] for d in src.ARM_DOFS}
        # The model file's words as models/das2.json records them (its bytes are hashed into cpp/generated):
        # the module has moved to codegen/importers/ since.
        path_note = "length and line-of-action polynomials fitted against das3.osim (codegen/fit_paths.py)"
    elif paths == "das3":
        fits = None
        rom = {d: [float(v) for v in struct.dof_ranges[d]] for d in src.ARM_DOFS}
        path_note = "DAS3 release polynomials with the fixed girdle angles substituted (not refitted)"
    else:
        raise ValueError(f"paths must be 'opensim' or 'das3', got {paths!r}")

    elements = []
    for e in arm:
        p = e.params
        entry = {
            "name": e.name, "osim_name": e.osim_name, "muscle": src.muscle_of(e.name),
            "fmax": p["fmax"], "lceopt": p["lceopt"], "lslack": p["lslack"], "pennopt": p["pennopt"],
            "vmax": p["vmax"], "tact": p["tact"], "tdeact": p["tdeact"], "peeslack": p["PEEslack"],
            "mass": p["mass"],
        }
        if fits is None:
            length = reduce_length_poly(e, girdle)
            entry.update({"dofs": [d for d in src.ARM_DOFS if d in length["dofs"]], "crosses_gh": e.crosses_gh,
                          "length_poly": length, "gh_direction": reduce_direction_poly(e, girdle),
                          "fit": None})
        else:
            f = fits["elements"][e.name]
            entry.update({"dofs": list(f["dofs"]), "crosses_gh": bool(f["crosses_gh"]),
                          "length_poly": f["length_poly"], "gh_direction": f["gh_direction"], "fit": f["fit"]})
        elements.append(entry)

    muscles = []
    for m in src.PAPER_MUSCLES:
        members = [e for e in elements if e["muscle"] == m]
        dofs = {d for e in members for d in e["dofs"]}
        crosses = [j for j, ds in [("GH", {"GHy", "GHz", "GHyy"}), ("HU", {"ELx"}), ("RU", {"PSy"})] if dofs & ds]
        muscles.append({"name": m, "elements": [e["name"] for e in members], "crosses": crosses})

    return {
        "schema": "armrt-model",
        "schema_version": SCHEMA_VERSION,
        "name": "das2",
        "description": ("The paper's real-time arm model: fixed scapula, 5 DOF (GH 3, elbow flexion, forearm "
                        "pronation), 22 muscles in 102 Hill-type elements, from the DAS3 release. Ranges of "
                        "motion: the paper's Table I (Gunal et al.) was lost; see dofs[].range and "
                        "docs/path_accuracy.md for how the fixed-scapula range was chosen inside the DAS3 "
                        "ranges. Muscle paths: " + path_note + "."),
        "source": {"importer": "python -m codegen.import_das3 --paths " + paths,
                   "files": {k: sha256(f) for k, f in files.items()}},
        "gravity_thorax": GRAVITY_THORAX,
        "dofs": [{"name": d, "osim_name": OSIM_DOF[d], "range": rom[d],
                  "das3_range": [float(v) for v in struct.dof_ranges[d]], "rest": posture[d]}
                 for d in src.ARM_DOFS],
        "girdle": {"dofs": [{"name": d, "osim_name": OSIM_DOF[d], "angle": v} for d, v in girdle.items()],
                   "source": "equilibrium.mat x[0:6]"},
        "scapula": {"rotation_in_thorax": R_scap.tolist(), "origin_in_thorax": p_scap.tolist()},
        "bodies": [bodies[n] for n, _ in ARM_BODIES],
        "hand_point": {"body": "hand", "point": bodies["hand"]["com"]},
        "glenoid": glenoid,
        "passive_joint": PASSIVE_JOINT,
        "muscles": muscles,
        "groups": GROUPS,
        "elements": elements,
    }


def write_model(model: dict, path: Path):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(model, indent=1, sort_keys=False) + "\n")


DEFAULT_DAS3 = Path(__file__).resolve().parents[2] / ".." / "shared" / "reference" / "das3"


def is_das2_call(mat: Path, free: list[str], posture: dict) -> bool:
    """The paper's model: the DAS3 release (das3.osim and equilibrium.mat beside model_struct.mat) with
    the five arm DOFs free and the default posture. It keeps its OpenSim-based path (build_model)."""
    return (mat.name == "model_struct.mat" and (mat.parent / "das3.osim").exists()
            and (mat.parent / "equilibrium.mat").exists() and sorted(free) == sorted(src.ARM_DOFS) and not posture)


def is_das3_call(mat: Path, free: list[str], posture: dict) -> bool:
    """The 11-DOF shoulder-girdle model: the DAS3 release with all 11 DOFs free (thorax fixed) and the
    default posture. Built by import_das3_girdle.build_das3_model from models/das3_paths.json."""
    return (mat.name == "model_struct.mat" and (mat.parent / "das3.osim").exists()
            and (mat.parent / "equilibrium.mat").exists() and sorted(free) == sorted(src.ALL_DOFS) and not posture)


def import_any(mat: Path, free: list[str], out: Path, name: str | None = None, posture: dict | None = None,
               equilibrium: Path | None = None, paths: str | None = None, cache_dir: Path | None = None,
               seed: int = 0, command: str = "") -> dict:
    """One entry for every DAS-format file (`armrt model import` and `python -m codegen.import_das3`):
    das2 when is_das2_call(), das3 when is_das3_call(), else import_reduced.build_reduced_model. Writes
    `out`; returns the model."""
    from .import_reduced import build_reduced_model
    mat = Path(mat)
    if not mat.exists():
        raise ModelInputError(f"missing input file {mat}")
    if is_das3_call(mat, free, posture or {}):
        from .import_das3_girdle import build_das3_model
        if paths is not None:
            raise ModelInputError(f"--paths {paths}: das3 takes its paths, already fitted against das3.osim, from "
                                  "models/das3_paths.json (python -m codegen.importers.das3_fit refits them)")
        if equilibrium is not None and Path(equilibrium).resolve() != (mat.parent / "equilibrium.mat").resolve():
            raise ModelInputError("--equilibrium: das3 rests at the equilibrium.mat beside model_struct.mat")
        model = build_das3_model(mat.parent)
        if name is not None and name != model["name"]:
            raise ModelInputError(f"--name: the DAS3 release with all 11 DOFs free is das3 (got {name!r})")
    elif is_das2_call(mat, free, posture or {}):
        model = build_model(mat.parent, paths=paths or "opensim", cache_dir=cache_dir, seed=seed)
        if name is not None and name != model["name"]:
            raise ModelInputError(f"--name: the DAS3 release with the five arm DOFs free is das2 (got {name!r})")
    else:
        if paths == "opensim":
            raise ModelInputError("--paths opensim: OpenSim-fitted paths exist for das2 only (the DAS3 release with "
                                  "GHy,GHz,GHyy,ELx,PSy free); other imports use the file's own polynomials")
        if equilibrium is None:
            for cand in (mat.parent / "equilibrium.mat", DEFAULT_DAS3 / "equilibrium.mat"):
                if cand.exists():
                    equilibrium = cand
                    break
        default_name = mat.stem.replace("model_struct", "model").strip("_") or "model"
        model = build_reduced_model(mat, free, name or default_name, posture=posture,
                                    equilibrium_path=equilibrium, command=command)
    write_model(model, out)
    return model


def main(argv=None, prog="python -m codegen.import_das3"):
    ap = argparse.ArgumentParser(prog=prog, description=__doc__.split("\n\n")[0] + " Any DAS-format "
                                 "model_struct*.mat with chosen free DOFs (docs/model_schema.md).")
    ap.add_argument("mat", nargs="?", type=Path, help="DAS-format model_struct*.mat (default: --das3/model_struct.mat)")
    ap.add_argument("--das3", type=Path, default=DEFAULT_DAS3,
                    help="folder with model_struct.mat, equilibrium.mat, das3.osim (used when MAT is not given)")
    ap.add_argument("--free", default=",".join(src.ARM_DOFS),
                    help="comma-separated free DOFs (default: the paper's five, GHy,GHz,GHyy,ELx,PSy)")
    ap.add_argument("--posture", action="append", default=[], metavar="NAME=RAD[,...]",
                    help="fixed angles in radians overriding the default posture (repeatable)")
    ap.add_argument("--posture-deg", action="append", default=[], metavar="NAME=DEG[,...]",
                    help="the same in degrees")
    ap.add_argument("--equilibrium", type=Path, default=None,
                    help="equilibrium.mat for the default posture (default: beside MAT, else the DAS3 release's)")
    ap.add_argument("--name", default=None, help="model name (a C identifier; default das2 for das2, else from MAT)")
    ap.add_argument("-o", "--out", type=Path, default=None,
                    help="model file to write (default: models/das3.json for all 11 DOFs, else models/das2.json)")
    ap.add_argument("--paths", choices=["opensim", "das3"], default=None,
                    help="das2 only: fit paths against OpenSim (default) or keep the DAS3 polynomials")
    ap.add_argument("--cache", type=Path, default=Path("build"), help="where OpenSim samples are cached")
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    from .import_reduced import posture_angles
    mat = args.mat if args.mat is not None else args.das3 / "model_struct.mat"
    try:
        posture = posture_angles(args.posture)
        posture.update(posture_angles(args.posture_deg, degrees=True))
        free = [f.strip() for f in args.free.split(",") if f.strip()]
        if args.out is None:
            args.out = Path("models/das3.json" if sorted(free) == sorted(src.ALL_DOFS) else "models/das2.json")
        # The same command whichever entry ran it (armrt model import calls this main), so both write
        # the same bytes.
        cmd = f"python -m codegen.import_das3 {mat.name} --free {','.join(free)}" + "".join(f" --posture {p}" for p in args.posture) \
            + "".join(f" --posture-deg {p}" for p in args.posture_deg) + (f" --name {args.name}" if args.name else "")
        model = import_any(mat, free, args.out, name=args.name, posture=posture, equilibrium=args.equilibrium,
                           paths=args.paths, cache_dir=args.cache, seed=args.seed, command=cmd)
    except ModelInputError as exc:
        print(f"{prog.split()[-1]}: {exc}", file=sys.stderr)
        return 2
    dropped = model["source"].get("dropped_elements", [])
    print(f"wrote {args.out}: {model['name']}, {len(model['dofs'])} DOFs, {len(model['elements'])} elements, "
          f"{len(model['muscles'])} muscles" + (f"; dropped {len(dropped)} elements crossing no free DOF: "
                                                  f"{', '.join(dropped)}" if dropped else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
