"""The 11-DOF DAS3 shoulder-girdle model `das3` (thorax fixed) as an armrt model file.

    python -m codegen.import_das3 --free SCy,SCz,SCx,ACy,ACz,ACx,GHy,GHz,GHyy,ELx,PSy -o models/das3.json

(also `armrt model import .../model_struct.mat --free <the same 11>`): `import_das3.import_any` sends
the DAS3 release with all 11 DOFs free here. Nothing is fitted: bodies and joints come from das3.osim
(`das3_chain.das3_bodies`), Hill parameters and the girdle-force parameters from model_struct.mat, the
resting posture from equilibrium.mat, and every element's `length_poly`, `gh_direction` and `fit` from
`models/das3_paths.json` (fitted against OpenSim by `codegen.importers.das3_fit` / `codegen.importers.das3_directions`).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from . import das3_source as src
from .das3_chain import BASE, OSIM_DOF, das3_bodies, girdle_points
from .das3_source import ModelInputError
from .glenoid import glenoid_geometry
from .model_defaults import GRAVITY_THORAX, GROUPS, PASSIVE_JOINT, SCHEMA_VERSION, check_against_readme, sha256

DAS3_PATHS = Path(__file__).resolve().parents[2] / "models" / "das3_paths.json"
COMMAND = "python -m codegen.import_das3 --free " + ",".join(src.ALL_DOFS) + " -o models/das3.json"
JOINT_TYPES = {"sc": "gimbal_yzx", "ac": "gimbal_yzx", "gh": "gimbal_yzy", "hu": "pin", "ur": "pin", "rc": "weld"}
# The engine's joint labels of muscles[].crosses, by the DOFs each joint carries.
JOINT_DOFS = [("SC", {"SCy", "SCz", "SCx"}), ("AC", {"ACy", "ACz", "ACx"}), ("GH", {"GHy", "GHz", "GHyy"}),
              ("HU", {"ELx"}), ("RU", {"PSy"})]
GH_DOFS = {"GHy", "GHz", "GHyy"}
# das2's groups plus the scapular muscles (DAS3 muscle names: trapscap/trapclav = scapular and clavicular
# trapezius, serrant, rhomboid, levscap, pectmin).
GIRDLE_GROUPS = {
    "trapezius": ["trapscap", "trapclav"],
    "serratus_anterior": ["serrant"],
    "rhomboids": ["rhomboid"],
    "levator_scapulae": ["levscap"],
    "pectoralis_minor": ["pectmin"],
}
# model_struct.mat scalars of the girdle forces: (field, lower bound exclusive, upper bound) in SI units.
GIRDLE_SCALARS = {"scap_thorax_k": (0.0, 1e8), "scap_thorax_eps": (0.0, 1.0), "conoid_length": (0.0, 0.5),
                  "conoid_stiffness": (0.0, 1e8), "conoid_eps": (0.0, 0.1)}


def _struct_vector(ms, field: str, where: str) -> list[float]:
    if not hasattr(ms, field):
        raise ModelInputError(f"{where}: model has no field '{field}'")
    v = np.ravel(np.asarray(getattr(ms, field), dtype=float))
    if v.shape != (3,) or not np.all(np.isfinite(v)) or np.abs(v).max() > 0.5:
        raise ModelInputError(f"{where}: model.{field} must be 3 finite coordinates (m), got {v}")
    return [float(x) for x in v]


def _struct_scalar(ms, field: str, where: str) -> float:
    if not hasattr(ms, field):
        raise ModelInputError(f"{where}: model has no field '{field}'")
    v = np.ravel(np.asarray(getattr(ms, field), dtype=float))
    lo, hi = GIRDLE_SCALARS[field]
    if v.shape != (1,) or not np.isfinite(v[0]) or not lo < v[0] <= hi:
        raise ModelInputError(f"{where}: model.{field} must be one number in ({lo}, {hi}], got {v}")
    return float(v[0])


def girdle_forces(model_struct_path: Path) -> dict:
    """The `girdle_forces` block (docs/model_schema.md): thorax ellipsoid (thorax frame, m), TS/AI contact
    (stiffness scap_thorax_k, dimensionless eps), conoid ligament (N/m, m) from model_struct.mat."""
    import scipy.io as sio
    where = Path(model_struct_path).name
    try:
        ms = sio.loadmat(model_struct_path, squeeze_me=True, struct_as_record=False)["model"]
    except Exception as exc:  # scipy raises several types for corrupt files
        raise ModelInputError(f"{model_struct_path}: not a readable DAS3 model_struct ({exc})") from None
    points = {label: (body, p) for label, body, p in girdle_points(model_struct_path)}
    radii = _struct_vector(ms, "thorax_radii", where)
    if min(radii) <= 0:
        raise ModelInputError(f"{where}: model.thorax_radii must be positive, got {radii}")
    return {
        "thorax_ellipsoid": {"centre": _struct_vector(ms, "thorax_center", where), "radii": radii},
        "contact": {"stiffness": _struct_scalar(ms, "scap_thorax_k", where),
                    "eps": _struct_scalar(ms, "scap_thorax_eps", where),
                    "points": [{"name": n, "body": points[n][0], "point": points[n][1]} for n in ("TS", "AI")]},
        "conoid": {"origin": {"body": points["conoid_origin"][0], "point": points["conoid_origin"][1]},
                   "insertion": {"body": points["conoid_insertion"][0], "point": points["conoid_insertion"][1]},
                   "length": _struct_scalar(ms, "conoid_length", where),
                   "stiffness": _struct_scalar(ms, "conoid_stiffness", where),
                   "eps": _struct_scalar(ms, "conoid_eps", where)},
    }


def read_paths(paths_file: Path, struct: src.Das3Struct) -> dict[str, dict]:
    """das3_paths.json's elements by name, checked against model_struct.mat's 138 elements (same names and
    OpenSim names, DOFs among the 11, gh_direction present exactly for elements crossing GH)."""
    import json
    try:
        data = json.loads(Path(paths_file).read_text())
    except (OSError, json.JSONDecodeError) as exc:
        raise ModelInputError(f"{paths_file}: not a readable das3 paths file ({exc})") from None
    where = Path(paths_file).name
    if not isinstance(data, dict) or data.get("schema") != "armrt-das3-paths" or data.get("schema_version") != 1:
        raise ModelInputError(f"{where}: not an armrt-das3-paths file of schema_version 1")
    if data.get("dofs") != src.ALL_DOFS:
        raise ModelInputError(f"{where}: field 'dofs' is {data.get('dofs')}, expected {src.ALL_DOFS}")
    paths = {}
    for k, e in enumerate(data.get("elements") or []):
        name = e.get("name")
        if name in paths:
            raise ModelInputError(f"{where}: element '{name}' appears twice")
        paths[name] = e
    struct_names = [e.name for e in struct.elements]
    missing = [n for n in struct_names if n not in paths]
    extra = [n for n in paths if n not in struct_names]
    if missing or extra:
        raise ModelInputError(f"{where}: its elements differ from model_struct.mat's: missing "
                              f"{missing or 'none'}, not in model_struct.mat {extra or 'none'}")
    for e in struct.elements:
        p = paths[e.name]
        w = f"{where}: element '{e.name}'"
        if p.get("osim_name") != e.osim_name:
            raise ModelInputError(f"{w}: osim_name {p.get('osim_name')!r}, model_struct.mat says {e.osim_name!r}")
        dofs = p.get("dofs")
        if not dofs or any(d not in src.ALL_DOFS for d in dofs) or len(set(dofs)) != len(dofs):
            raise ModelInputError(f"{w}: field 'dofs' {dofs} must name distinct DOFs from {src.ALL_DOFS}")
        for key in ("length_poly", "fit"):
            if not isinstance(p.get(key), dict):
                raise ModelInputError(f"{w}: missing field '{key}'")
        if set(p["length_poly"].get("dofs", [None])) - set(dofs):
            raise ModelInputError(f"{w}: length_poly.dofs {p['length_poly'].get('dofs')} not among its dofs {dofs}")
        if (p.get("gh_direction") is not None) != bool(GH_DOFS & set(dofs)):
            raise ModelInputError(f"{w}: has {'a' if p.get('gh_direction') is not None else 'no'} gh_direction "
                                  f"but crosses DOFs {dofs} (a GH line of action exactly for GH-crossing elements)")
    return data


# Source data kept as published although no rigid body has it (codegen/generate.py check_sense asks why).
INERTIA_NOTES = {"clavicle": "das3.osim clavicle_r as published: its principal moments (1.26e-6, 2.26e-5, "
                             "3.31e-5 kg m^2) break the triangle inequality by 38 %; kept so that the dynamics "
                             "equal OpenSim's (tests/test_das3_dynamics.py)"}


def build_das3_model(das3_dir: Path, paths_file: Path = DAS3_PATHS) -> dict:
    """The model-file dict of `das3` (docs/model_schema.md, `base: thorax`) from the DAS3 release folder
    (model_struct.mat, equilibrium.mat, das3.osim) and the fitted paths `paths_file`. Raises
    ModelInputError naming the missing file or the inconsistent field."""
    das3_dir = Path(das3_dir)
    files = {k: das3_dir / k for k in ["model_struct.mat", "equilibrium.mat", "das3.osim"]}
    files["das3_paths.json"] = Path(paths_file)
    for f in files.values():
        if not f.exists():
            raise ModelInputError(f"missing input file {f}")
    struct = src.read_model_struct(files["model_struct.mat"])
    posture = src.read_equilibrium(files["equilibrium.mat"])
    paths = read_paths(files["das3_paths.json"], struct)
    by_name = {e["name"]: e for e in paths["elements"]}
    rom = paths.get("rom") or {}
    try:
        # The girdle's passive-moment range is the region its paths were fitted over (rom.girdle_range):
        # DAS3's ranges widened to contain the equilibrium.mat posture, whose ACz and ACx lie below them
        # (docs/das3.md). With DAS3's own ranges the resting scapula would be pushed by ~14 N m at ACz.
        ranges = {d: [float(v) for v in rom["girdle_range"][d]] for d in src.GIRDLE_DOFS}
        ranges.update({d: [float(v) for v in rom["arm_range"][d]] for d in src.ARM_DOFS})
        das3_ranges = {d: [float(v) for v in rom["das3_range"][d]] for d in src.GIRDLE_DOFS}
    except (KeyError, TypeError, ValueError) as exc:
        raise ModelInputError(f"{files['das3_paths.json'].name}: field 'rom' lacks a DOF range ({exc})") from None
    for d in src.GIRDLE_DOFS:
        if das3_ranges[d] != [float(v) for v in struct.dof_ranges[d]]:
            raise ModelInputError(f"{files['das3_paths.json'].name}: rom.das3_range.{d} {das3_ranges[d]} differs from "
                                  f"model_struct.mat's {list(struct.dof_ranges[d])}")
        if not ranges[d][0] <= posture[d] <= ranges[d][1]:
            raise ModelInputError(f"{files['das3_paths.json'].name}: rom.girdle_range.{d} {ranges[d]} does not contain "
                                  f"the equilibrium.mat angle {posture[d]}")

    bodies = []
    for b in das3_bodies(files["das3.osim"]):
        j = b["joint"]
        note = {"inertia_note": INERTIA_NOTES[b["name"]]} if b["name"] in INERTIA_NOTES else {}
        bodies.append({**{k: b[k] for k in ("name", "osim_name", "parent", "mass", "com", "inertia")}, **note,
                       "joint": {"name": j["name"], "type": JOINT_TYPES[j["name"]],
                                 "location_in_parent": j["location_in_parent"], "axes": j["axes"], "dofs": j["dofs"]}})
    named = {b["name"]: b for b in bodies}
    check_against_readme(named, {d: np.asarray(a) for b in bodies for a, d in zip(b["joint"]["axes"], b["joint"]["dofs"])})

    forces = girdle_forces(files["model_struct.mat"])
    contact = {p["name"]: np.asarray(p["point"]) for p in forces["contact"]["points"]}
    glenoid = glenoid_geometry(np.asarray(named["humerus"]["joint"]["location_in_parent"]))

    elements = []
    for e in struct.elements:
        p, f = e.params, by_name[e.name]
        elements.append({
            "name": e.name, "osim_name": e.osim_name, "muscle": src.muscle_of(e.name),
            "fmax": p["fmax"], "lceopt": p["lceopt"], "lslack": p["lslack"], "pennopt": p["pennopt"],
            "vmax": p["vmax"], "tact": p["tact"], "tdeact": p["tdeact"], "peeslack": p["PEEslack"],
            "mass": p["mass"], "dofs": list(f["dofs"]), "crosses_gh": f.get("gh_direction") is not None,
            "length_poly": f["length_poly"], "gh_direction": f.get("gh_direction"), "fit": f["fit"]})

    muscles = []
    for e in elements:
        if not muscles or muscles[-1]["name"] != e["muscle"]:
            if any(m["name"] == e["muscle"] for m in muscles):
                raise ModelInputError(f"model_struct.mat: the elements of muscle '{e['muscle']}' are not contiguous")
            muscles.append({"name": e["muscle"], "elements": [], "crosses": []})
        muscles[-1]["elements"].append(e["name"])
    for m in muscles:
        dofs = {d for e in elements if e["muscle"] == m["name"] for d in e["dofs"]}
        m["crosses"] = [j for j, ds in JOINT_DOFS if dofs & ds]
    names = [m["name"] for m in muscles]
    groups = {**GROUPS, **GIRDLE_GROUPS,
              "scapular": [m["name"] for m in muscles if set(m["crosses"]) <= {"SC", "AC"}]}
    for g, ms in groups.items():
        if any(x not in names for x in ms):
            raise ModelInputError(f"model_struct.mat: group '{g}' names muscles {[x for x in ms if x not in names]} "
                                  f"that the file does not have")

    return {
        "schema": "armrt-model",
        "schema_version": SCHEMA_VERSION,
        "name": "das3",
        # As models/das3.json records it (its bytes are hashed into cpp/generated): the fitters named below
        # have moved to codegen/importers/ since.
        "description": (
            "The DAS3 shoulder-girdle model: thorax fixed, 11 DOF (SC 3, AC 3, GH 3, elbow flexion, forearm "
            "pronation), 28 muscles in 138 Hill-type elements, with the scapulothoracic contact of TS and AI on "
            "the thorax ellipsoid and the conoid ligament (girdle_forces), from the DAS3 release. Ranges "
            "(dofs[].range, the passive joint limits): for SCy..ACx the region the girdle paths were fitted over "
            "(das3_paths.json rom.girdle_range: the DAS3 ranges, dofs[].das3_range, widened to contain the "
            "equilibrium.mat posture, where ACz and ACx lie 0.053 and 0.017 rad below them); das2's ranges (the "
            "fixed-scapula range of motion of docs/path_accuracy.md) for GHy, GHz, GHyy, ELx, PSy. The rest "
            "posture is equilibrium.mat. "
            "Muscle paths: length and GH line-of-action polynomials fitted against das3.osim over the girdle-"
            "and-arm range of docs/das3.md, read from models/das3_paths.json (codegen/importers/das3_fit.py, "
            "codegen/importers/das3_directions.py; docs/das3_path_accuracy.md). Groups: das2's, plus trapezius "
            "(trapscap, trapclav), serratus_anterior (serrant), rhomboids (rhomboid), levator_scapulae "
            "(levscap), pectoralis_minor (pectmin), and scapular (the muscles crossing only SC/AC)."),
        "source": {"importer": COMMAND, "files": {k: sha256(f) for k, f in files.items()}},
        "gravity_thorax": GRAVITY_THORAX,
        "base": BASE,
        "dofs": [{"name": d, "osim_name": OSIM_DOF[d], "range": ranges[d],
                  "das3_range": [float(v) for v in struct.dof_ranges[d]], "rest": posture[d]}
                 for d in src.ALL_DOFS],
        "bodies": bodies,
        "hand_point": {"body": "hand", "point": named["hand"]["com"]},
        "glenoid": glenoid,
        "girdle_forces": forces,
        "passive_joint": PASSIVE_JOINT,
        "muscles": muscles,
        "groups": groups,
        "elements": elements,
    }
