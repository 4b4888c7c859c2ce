"""Any DAS-format `model_struct*.mat` -> an armrt model file with a chosen set of free DOFs.

Every DOF not chosen is fixed at a posture; element polynomials that cross fixed DOFs get the fixed
angles substituted (equal monomials merge); elements that cross no free DOF are dropped (listed in
the file's `source.dropped_elements`). The kinematic chain comes from the file's own `joints` and
`segments`, the muscle paths from its own polynomials (no OpenSim fit): this is the path for models
that have no OpenSim file, such as the participant models in ../shared/reference/participant_A/.
The DAS3 release with the paper's five free DOFs (das2) keeps its own path in `import_das3.build_model`
(bodies from das3.osim, polynomials fitted against OpenSim), which `import_das3.main` picks for it.

The engine's root frame is the scapula, so thorax and girdle DOFs can only be fixed; within one joint
(GH: GHy GHz GHyy) the DOFs are either all free or all fixed.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from .das3_source import ALL_DOFS, ModelInputError, axis_rotation
from .das_struct import DasStruct, read_das_struct
from .glenoid import glenoid_geometry
from .model_defaults import GRAVITY_THORAX, GROUPS, PASSIVE_JOINT, SCHEMA_VERSION, sha256
from ..polynomial import substitute

# DAS segment names of the arm chain and the body names of the armrt schema.
THORAX, SCAPULA = "thorax", "scapular"
ARM_SEGMENTS = [("humerus", "humerusr", "scapular"), ("ulna", "ulnar", "humerusr"),
                ("radius", "radiusr", "ulnar"), ("hand", "handr", "radiusr")]
ARM_JOINT_DOFS = ["GHy", "GHz", "GHyy", "ELx", "PSy"]
GIRDLE = ["SCy", "SCz", "SCx", "ACy", "ACz", "ACx"]
GH = ["GHy", "GHz", "GHyy"]


def joint_pose(joints, posture):
    """(R, p) of the last joint's child in the first joint's parent frame, for a list of DasJoints."""
    R, p = np.eye(3), np.zeros(3)
    for j in joints:
        p = p + R @ j.location
        for rot, angle in zip(j.rotations, j.angles(posture)):
            R = R @ axis_rotation(rot.axis, angle)
    return R, p


def load_equilibrium(path: Path | None, struct: DasStruct) -> tuple[dict[str, float], str] | tuple[None, None]:
    if path is None or not Path(path).exists():
        return None, None
    from .das3_source import read_equilibrium
    return read_equilibrium(path), Path(path).name


def hanging_gh(struct: DasStruct, posture: dict[str, float]) -> dict[str, float]:
    """GH angles that hang the humerus along gravity with the elbow flexion axis horizontal and
    lateral (the forearm flexes forward in the sagittal plane): least squares from the given start."""
    from scipy.optimize import least_squares

    R_th, _ = joint_pose(struct.chain(THORAX, struct.joints[THORAX].parent), posture)
    g = R_th.T @ struct.gravity
    down = g / np.linalg.norm(g)
    R_sc, _ = joint_pose(struct.chain(SCAPULA, THORAX), posture)
    gh_chain = struct.chain("humerusr", SCAPULA)
    hu = struct.joints["ulnar"]
    humerus_axis = hu.location / np.linalg.norm(hu.location)       # GH centre -> elbow, humerus frame
    el_axis = hu.rotations[0].axis if hu.rotations else np.array([1.0, 0.0, 0.0])
    lateral = np.array([1.0, 0.0, 0.0])   # thorax x: lateral (right arm), docs/conventions.md

    def residual(x):
        p = dict(posture, **dict(zip(GH, x)))
        R_h, _ = joint_pose(gh_chain, p)
        R = R_sc @ R_h
        return np.concatenate([R @ humerus_axis - down, 0.5 * (R @ el_axis - lateral)])

    # Unbounded (the answer must not depend on the file's GH ranges, which the participant variants
    # change); default_posture's caller checks the result against the ranges.
    x0 = np.array([posture[d] for d in GH], dtype=float)
    sol = least_squares(residual, x0, method="lm", xtol=1e-15, ftol=1e-15, gtol=1e-15)
    # Rounded to a microradian: the solver's last bits depend on the platform's floating point, and the
    # committed model files must be reproducible byte for byte.
    return {d: round(float(v), 6) for d, v in zip(GH, sol.x)}


def default_posture(struct: DasStruct, equilibrium: dict[str, float] | None, eq_name: str | None):
    """(posture of every DOF, description). equilibrium.mat as is where it names every DOF of the model
    (the DAS3 release); otherwise the arm hanging at the side (see docs/model_schema.md): thorax
    upright, girdle at equilibrium.mat's angles, GH solved so the humerus hangs along gravity with the
    elbow flexion axis lateral, elbow and forearm at equilibrium.mat's angles (clamped into range)."""
    names = [d.name for d in struct.dofs]
    eq = equilibrium or {}
    if equilibrium is not None and all(n in eq for n in names):
        return {n: eq[n] for n in names}, f"{eq_name} (DAS3 equilibrium posture), by DOF name"
    posture = {}
    for d in struct.dofs:
        v = eq.get(d.name, 0.0)
        if d.name in ARM_JOINT_DOFS or d.name not in eq:
            v = float(min(max(v, d.range[0]), d.range[1]))
        posture[d.name] = v
    if all(g in posture for g in GH):
        posture.update(hanging_gh(struct, posture))
    src = ("arm hanging at the side: thorax upright (0), girdle " + (f"at {eq_name} (DAS3 equilibrium)" if eq else "at 0")
           + ", GH solved so the humerus hangs along gravity with the elbow flexion axis lateral (thorax x), "
           + "elbow and forearm rest " + (f"at {eq_name}" if eq else "at the lower range limit"))
    return posture, src


def _poly_dict(dofs, exps, coefs):
    return {"dofs": dofs, "exponents": exps, "coefs": coefs}


def build_reduced_model(mat_path, free: list[str], name: str, posture: dict[str, float] | None = None,
                        equilibrium_path: Path | None = None, command: str = "") -> dict:
    """The model-file dict (docs/model_schema.md) of `mat_path` with DOFs `free` free.

    posture: angles (rad) by DOF name overriding the default posture (equilibrium.mat where it fits
    the model, else the arm hanging at the side). Raises ModelInputError naming the problem."""

    mat_path = Path(mat_path)
    struct = read_das_struct(mat_path)
    names = [d.name for d in struct.dofs]
    if not free:
        raise ModelInputError("--free: name at least one DOF")
    for f in free:
        if f not in names:
            raise ModelInputError(f"--free: '{f}' is not a DOF of {mat_path.name} (its DOFs: {', '.join(names)})")
        if f not in ARM_JOINT_DOFS:
            raise ModelInputError(f"--free: '{f}' cannot be free: the engine's root frame is the scapula, so "
                                  f"thorax and girdle DOFs are fixed (free DOFs come from {ARM_JOINT_DOFS})")
    if len(set(free)) != len(free):
        raise ModelInputError(f"--free: repeated DOF names {free}")
    free = [d for d in ARM_JOINT_DOFS if d in free]   # chain order
    for seg in [THORAX, SCAPULA] + [s for _, s, _ in ARM_SEGMENTS]:
        if seg not in struct.segments:
            raise ModelInputError(f"{mat_path.name}: model.segments has no '{seg}' (the DAS arm chain needs "
                                  f"thorax, scapular, humerusr, ulnar, radiusr, handr)")

    equilibrium, eq_name = load_equilibrium(equilibrium_path, struct)
    pose, pose_source = default_posture(struct, equilibrium, eq_name)
    files = {mat_path.name: sha256(mat_path)}
    if eq_name is not None:
        files[eq_name] = sha256(equilibrium_path)
    if posture:
        for k, v in posture.items():
            if k not in names:
                raise ModelInputError(f"--posture: '{k}' is not a DOF of {mat_path.name} (its DOFs: {', '.join(names)})")
            if not math.isfinite(v):
                raise ModelInputError(f"--posture: {k} = {v} is not a finite angle")
            pose[k] = float(v)
        pose_source += "; given on the command line: " + ", ".join(f"{k}={v:.6g} rad" for k, v in posture.items())
    outside = []
    for d in struct.dofs:
        lo, hi = d.range
        v = pose[d.name]
        # A rest posture of a free DOF must be inside its range; a fixed DOF may sit a little outside
        # (DAS3's own equilibrium has ACz and ACx 3 and 1 deg beyond the release's ranges), but not
        # by more than the 0.2 rad Arm.reset tolerates (degrees given as radians, a sign slip).
        slack = 0.0 if d.name in free else 0.2
        if not lo - slack <= v <= hi + slack:
            raise ModelInputError(f"posture: {d.name} = {v:.6g} rad ({math.degrees(v):.1f} deg) is outside its range "
                                  f"[{lo:.4g}, {hi:.4g}] rad" + ("" if d.name in free else " by more than 0.2 rad"))
        if not lo <= v <= hi:
            outside.append(f"{d.name} {math.degrees(v):.1f} deg (range {math.degrees(lo):.1f} to {math.degrees(hi):.1f})")
    if outside:
        pose_source += "; fixed outside the file's range: " + ", ".join(outside)
    fixed = {n: pose[n] for n in names if n not in free}

    # Kinematics at the fixed posture, from model.joints / model.segments.
    R_th, _ = joint_pose(struct.chain(THORAX, struct.joints[THORAX].parent), pose)
    gravity_thorax = (R_th.T @ struct.gravity).tolist()
    if np.allclose(gravity_thorax, GRAVITY_THORAX, atol=1e-9, rtol=0):
        gravity_thorax = list(GRAVITY_THORAX)
    R_scap, p_scap = joint_pose(struct.chain(SCAPULA, THORAX), pose)
    bodies = []
    for body, seg, parent_seg in ARM_SEGMENTS:
        chain = struct.chain(seg, parent_seg)
        for j in chain[1:]:
            if np.any(j.location != 0):
                raise ModelInputError(f"{mat_path.name}: joint '{j.name}' is offset from its parent joint "
                                      f"'{chain[0].name}' (one joint centre per arm joint expected)")
        rots = [r for j in chain for r in j.rotations]
        dofs = [r.dof for r in rots]
        free_here = [d for d in dofs if d in free]
        if free_here and len(free_here) != len(dofs):
            raise ModelInputError(f"--free: joint {chain[0].name} carries {dofs}; free all of them or none")
        joint = {"name": chain[0].name.rstrip("0123456789") if len(chain) > 1 else chain[0].name,
                 "location_in_parent": chain[0].location.tolist()}
        if free_here:
            for r in rots:
                if r.coefs[:2] != (0.0, 1.0) or any(r.coefs[2:]):
                    raise ModelInputError(f"{mat_path.name}: joint rotation driven by {r.dof} has coefficients "
                                          f"{list(r.coefs)}; a free DOF must be the joint angle itself ([0, 1])")
            joint.update({"type": {3: "gimbal_yzy", 1: "pin"}.get(len(rots)) or "?", "axes": [r.axis.tolist() for r in rots],
                          "dofs": dofs})
            if joint["type"] == "?":
                raise ModelInputError(f"--free: joint {chain[0].name} has {len(rots)} rotations; a free joint "
                                      f"needs 1 (pin) or 3 (gimbal)")
        else:
            R_fixed, _ = joint_pose(chain, pose)
            joint.update({"type": "weld", "axes": [], "dofs": []})
            if not np.allclose(R_fixed, np.eye(3), atol=0, rtol=0):
                joint["rotation"] = R_fixed.tolist()
        s = struct.segments[seg]
        bodies.append({"name": body, "osim_name": seg[:-1] + "_r", "parent": {"humerus": "scapula", "ulna": "humerus",
                                                                              "radius": "ulna", "hand": "radius"}[body],
                       "mass": s.mass, "com": s.com.tolist(), "inertia": s.inertia.tolist(), "joint": joint})

    glenoid = glenoid_geometry(np.asarray(bodies[0]["joint"]["location_in_parent"]))

    elements, dropped, no_direction = [], [], []
    for e in struct.elements:
        edofs = [d for d in free if d in e.dof_names]
        if not edofs:
            dropped.append(e.name)
            continue
        fx = {j: fixed[d] for j, d in enumerate(e.dof_names) if d in fixed}
        kept, exps, coefs = substitute(e.lparams, e.lcoefs, fx)
        kept_names = [e.dof_names[j] for j in kept]
        crosses_gh, gh_direction = e.crosses_gh, None
        if e.crosses_gh and e.direction is not None:
            gh_direction = {"dofs": kept_names}
            for axis, (de, dc) in e.direction.items():
                _, dx, cx = substitute(de, dc, fx)
                gh_direction[axis] = {"exponents": dx, "coefs": cx}
        elif e.crosses_gh:
            crosses_gh = False
            no_direction.append(e.name)
        p = e.params
        elements.append({
            "name": e.name, "osim_name": e.osim_name, "muscle": e.muscle,
            "fmax": p["fmax"], "lceopt": p["lceopt"], "lslack": p["lslack"], "pennopt": p["pennopt"],
            "vmax": p["vmax"], "tact": p["tact"], "tdeact": p["tdeact"], "peeslack": p["PEEslack"],
            "mass": p["mass"], "max_activation": e.max_activation,
            "dofs": edofs, "crosses_gh": crosses_gh,
            "length_poly": _poly_dict(kept_names, exps, coefs),
            "gh_direction": gh_direction, "fit": None,
        })
    if not elements:
        raise ModelInputError(f"{mat_path.name}: no element crosses the free DOFs {free}")

    muscles, seen = [], []
    for e in elements:
        if e["muscle"] not in seen:
            seen.append(e["muscle"])
    by_muscle = {m: [e for e in elements if e["muscle"] == m] for m in seen}
    src_by_name = {e.name: e for e in struct.elements}
    for m in seen:
        anat = {d for e in by_muscle[m] for d in src_by_name[e["name"]].dof_names}
        crosses = [j for j, ds in [("GH", set(GH)), ("HU", {"ELx"}), ("RU", {"PSy"})] if anat & ds]
        muscles.append({"name": m, "elements": [e["name"] for e in by_muscle[m]], "crosses": crosses})
    groups = {g: [m for m in ms if m in by_muscle] for g, ms in GROUPS.items()}
    groups = {g: ms for g, ms in groups.items() if ms}

    osim_note = (f"No OpenSim file exists for this model: model.osimfile names '{struct.osimfile}', which is not "
                 f"part of the data, so bodies and joints come from the .mat's own joints and segments and the "
                 f"muscle paths are its own polynomials, not refitted")
    osim_here = struct.osimfile and (mat_path.parent / struct.osimfile).exists()
    if osim_here:
        osim_note = (f"{struct.osimfile} is present but not used on this path: bodies and joints come from the .mat's "
                     f"joints and segments, muscle paths are its own polynomials")
    return {
        "schema": "armrt-model",
        "schema_version": SCHEMA_VERSION,
        "name": name,
        "description": (f"{struct.name or mat_path.stem} ({mat_path.name}) with {', '.join(free)} free and every "
                        f"other DOF fixed ({len(elements)} elements of {len(struct.elements)}; "
                        f"{len(dropped)} cross no free DOF and are dropped). {osim_note}."),
        "source": {"importer": command or f"python -m codegen.import_das3 {mat_path.name} --free {','.join(free)}",
                   "files": files, "osimfile": struct.osimfile, "opensim_file_available": bool(osim_here),
                   "kinematics": "model.joints and model.segments of the .mat",
                   "paths": "the .mat's own length and GH-direction polynomials, fixed DOFs substituted",
                   "dropped_elements": dropped, "gh_direction_missing": no_direction,
                   "unused_fields": struct.extra_fields},
        "gravity_thorax": gravity_thorax,
        "dofs": [{"name": d, "osim_name": struct.dof(d).osim_name, "range": list(struct.dof(d).range),
                  "das3_range": list(struct.dof(d).range), "rest": pose[d]} for d in free],
        "girdle": {"dofs": [{"name": d, "osim_name": struct.dof(d).osim_name, "angle": pose[d]}
                            for d in GIRDLE if d in names], "source": pose_source},
        "fixed_dofs": {"dofs": [{"name": d, "osim_name": struct.dof(d).osim_name, "angle": v} for d, v in fixed.items()],
                       "source": pose_source},
        "scapula": {"rotation_in_thorax": R_scap.tolist(), "origin_in_thorax": p_scap.tolist()},
        "bodies": bodies,
        "hand_point": {"body": "hand", "point": bodies[3]["com"]},
        "glenoid": glenoid,
        "passive_joint": PASSIVE_JOINT,
        "muscles": muscles,
        "groups": groups,
        "elements": elements,
    }


def posture_angles(items: list[str], degrees: bool = False) -> dict[str, float]:
    """['GHz=0.1,ELx=0.5', ...] -> {name: rad}; ModelInputError on bad syntax."""
    out = {}
    for item in items or []:
        for part in item.split(","):
            if not part.strip():
                continue
            if "=" not in part:
                raise ModelInputError(f"--posture: '{part}' is not NAME=ANGLE")
            k, v = part.split("=", 1)
            try:
                x = float(v)
            except ValueError:
                raise ModelInputError(f"--posture: '{v}' in '{part}' is not a number") from None
            out[k.strip()] = math.radians(x) if degrees else x
    return out


__all__ = ["build_reduced_model", "posture_angles", "default_posture", "ALL_DOFS"]
