"""Readers for the DAS3 release files, with validation that names the offending field.

`model_struct.mat` (MATLAB v5, struct `model`), `equilibrium.mat` (vector `x`) and `das3.osim`
(OpenSim 3 XML, read here with ElementTree so the importer's structural part needs no OpenSim).
"""
from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import scipy.io as sio


class ModelInputError(ValueError):
    """Malformed or inconsistent input data; the message names the file and field."""


GIRDLE_DOFS = ["SCy", "SCz", "SCx", "ACy", "ACz", "ACx"]
ARM_DOFS = ["GHy", "GHz", "GHyy", "ELx", "PSy"]
ALL_DOFS = GIRDLE_DOFS + ARM_DOFS

# Muscles acting only on the shoulder girdle: with a fixed scapula they do nothing.
GIRDLE_ONLY_MUSCLES = ["trapscap", "trapclav", "levscap", "pectmin", "rhomboid", "serrant"]

# The paper's 22 muscles and their element counts (reference README).
PAPER_MUSCLES = {
    "deltscap": 11, "deltclav": 4, "coracobr": 3, "infra": 6, "termin": 3, "termaj": 4,
    "supra": 4, "subscap": 11, "bicl": 1, "bicb": 2, "triclong": 4, "latdorsi": 6,
    "pectmajt": 6, "pectmajc": 2, "tricmed": 5, "brachialis": 7, "brachiorad": 3,
    "pronteres": 2, "supinator": 5, "pronquad": 3, "triclat": 5, "anconeus": 5,
}
NUM_DAS3_ELEMENTS = 138
NUM_ELEMENTS = 102

ELEMENT_SCALARS = ["fmax", "lceopt", "lslack", "pennopt", "vmax", "tact", "tdeact", "PEEslack", "mass"]


def muscle_of(element_name: str) -> str:
    """'deltscap11' -> 'deltscap'; 'bicl' -> 'bicl'."""
    return element_name.rstrip("0123456789")


@dataclass
class Das3Element:
    name: str
    osim_name: str
    params: dict[str, float]
    dof_names: list[str]
    lparams: np.ndarray       # (terms, len(dof_names)) exponents
    lcoefs: np.ndarray        # (terms,)
    crosses_gh: bool
    direction: dict | None = None   # DAS3's own line-of-action polynomials, if present


@dataclass
class Das3Struct:
    dof_ranges: dict[str, tuple[float, float]]
    elements: list[Das3Element] = field(default_factory=list)


def _field(obj, name, where):
    if not hasattr(obj, name):
        raise ModelInputError(f"{where}: missing field '{name}'")
    return getattr(obj, name)


def _finite_array(value, name, where, shape=None, dtype=float):
    try:
        arr = np.atleast_1d(np.asarray(value, dtype=dtype))
    except (TypeError, ValueError) as exc:
        raise ModelInputError(f"{where}: field '{name}' is not numeric ({exc})") from None
    if shape is not None and arr.shape != shape:
        raise ModelInputError(f"{where}: field '{name}' has shape {arr.shape}, expected {shape}")
    if not np.all(np.isfinite(arr)):
        raise ModelInputError(f"{where}: field '{name}' contains NaN or infinite values")
    return arr


def _poly(obj, prefix, ndof, where):
    exps = _finite_array(_field(obj, prefix + "params", where), prefix + "params", where, dtype=float)
    coefs = _finite_array(_field(obj, prefix + "coefs", where), prefix + "coefs", where)
    exps = exps.reshape(len(coefs), -1) if exps.size else exps.reshape(0, ndof)
    if exps.shape != (len(coefs), ndof):
        raise ModelInputError(
            f"{where}: field '{prefix}params' has shape {exps.shape}, expected ({len(coefs)}, {ndof}) "
            f"(one row per coefficient, one column per DOF crossed)")
    if np.any(exps < 0) or np.any(exps != np.round(exps)):
        raise ModelInputError(f"{where}: field '{prefix}params' must hold non-negative integer exponents")
    return exps.astype(int), coefs


def read_model_struct(path: str | Path) -> Das3Struct:
    path = Path(path)
    try:
        mat = sio.loadmat(path, squeeze_me=True, struct_as_record=False)
    except Exception as exc:  # scipy raises several types for corrupt files
        raise ModelInputError(f"{path}: not a readable MATLAB file ({exc})") from None
    if "model" not in mat:
        raise ModelInputError(f"{path}: no variable 'model'")
    return parse_model_struct(mat["model"], f"{path.name}: model")


def parse_model_struct(model, where: str = "model") -> Das3Struct:
    """Validates a loaded DAS3 `model` struct (scipy mat_struct) and extracts what the importer uses."""
    dofs = np.atleast_1d(_field(model, "dofs", where))
    dof_ranges = {}
    for i, d in enumerate(dofs):
        dname = str(_field(d, "name", f"{where}.dofs[{i}]"))
        dof_ranges[dname] = tuple(_finite_array(_field(d, "range", f"{where}.dofs[{i}]"), "range",
                                                f"{where}.dofs[{i}]", shape=(2,)))
    missing = [n for n in ALL_DOFS if n not in dof_ranges]
    if missing:
        raise ModelInputError(f"{where}.dofs: missing DOFs {missing}")

    muscles = np.atleast_1d(_field(model, "muscles", where))
    if len(muscles) != NUM_DAS3_ELEMENTS:
        raise ModelInputError(
            f"{where}.muscles: {len(muscles)} elements, expected {NUM_DAS3_ELEMENTS} (the DAS3 release)")
    out = Das3Struct(dof_ranges=dof_ranges)
    for k, mu in enumerate(muscles):
        w = f"{where}.muscles[{k}]"
        name = str(_field(mu, "name", w))
        w = f"{where}.muscles[{k}] ('{name}')"
        muscle = muscle_of(name)
        if muscle not in PAPER_MUSCLES and muscle not in GIRDLE_ONLY_MUSCLES:
            raise ModelInputError(f"{w}: unknown muscle '{muscle}'")
        params = {p: float(_finite_array(_field(mu, p, w), p, w, shape=(1,))[0]) for p in ELEMENT_SCALARS}
        for p in ["fmax", "lceopt", "vmax", "tact", "tdeact", "PEEslack"]:
            if params[p] <= 0:
                raise ModelInputError(f"{w}: field '{p}' must be positive, got {params[p]}")
        if params["lslack"] < 0:
            raise ModelInputError(f"{w}: field 'lslack' must be non-negative, got {params['lslack']}")
        dof_names = [str(s) for s in np.atleast_1d(_field(mu, "dof_names", w))]
        unknown = [d for d in dof_names if d not in dof_ranges]
        if unknown:
            raise ModelInputError(f"{w}: field 'dof_names' names unknown DOFs {unknown}")
        lparams, lcoefs = _poly(mu, "l", len(dof_names), w)
        crosses_gh = bool(int(_finite_array(_field(mu, "crossesGH", w), "crossesGH", w, shape=(1,))[0]))
        direction = None
        if crosses_gh and all(hasattr(mu, f"{a}params") for a in "xyz"):
            direction = {a: _poly(mu, a, len(dof_names), w) for a in "xyz"}
        out.elements.append(Das3Element(name=name, osim_name=str(_field(mu, "osim_name", w)),
                                        params=params, dof_names=dof_names, lparams=lparams,
                                        lcoefs=lcoefs, crosses_gh=crosses_gh, direction=direction))
    arm = [e for e in out.elements if muscle_of(e.name) in PAPER_MUSCLES]
    counts: dict[str, int] = {}
    for e in arm:
        counts[muscle_of(e.name)] = counts.get(muscle_of(e.name), 0) + 1
    if counts != PAPER_MUSCLES or len(arm) != NUM_ELEMENTS:
        raise ModelInputError(f"{where}.muscles: element counts per muscle {counts} differ from the "
                              f"paper's 22 muscles / 102 elements {PAPER_MUSCLES}")
    return out


def read_equilibrium(path: str | Path) -> dict[str, float]:
    """All 11 DAS3 DOF angles of the resting posture, by name."""
    path = Path(path)
    try:
        mat = sio.loadmat(path, squeeze_me=True)
    except Exception as exc:
        raise ModelInputError(f"{path}: not a readable MATLAB file ({exc})") from None
    if "x" not in mat:
        raise ModelInputError(f"{path}: no variable 'x'")
    x = np.atleast_1d(np.asarray(mat["x"], dtype=float))
    if x.ndim != 1 or x.size < len(ALL_DOFS):
        raise ModelInputError(f"{path}: field 'x' has shape {x.shape}, expected at least ({len(ALL_DOFS)},)")
    if not np.all(np.isfinite(x[:len(ALL_DOFS)])):
        raise ModelInputError(f"{path}: field 'x' contains NaN or infinite values in x[0:11]")
    return {n: float(v) for n, v in zip(ALL_DOFS, x[:len(ALL_DOFS)])}


# ----------------------------------------------------------------------------- das3.osim

@dataclass
class OsimJoint:
    name: str
    parent: str
    location_in_parent: np.ndarray
    orientation_in_parent: np.ndarray
    # Each rotation: (unit axis, coordinate name or None, slope, constant value in rad).
    rotations: list[tuple[np.ndarray, str | None, float, float]]
    translation: np.ndarray


@dataclass
class OsimBody:
    name: str
    mass: float
    com: np.ndarray
    inertia: np.ndarray
    joint: OsimJoint | None


def _vec(el, tag, where, n=3):
    node = el.find(tag)
    if node is None or node.text is None:
        raise ModelInputError(f"{where}: missing <{tag}>")
    try:
        v = np.array([float(t) for t in node.text.split()])
    except ValueError:
        raise ModelInputError(f"{where}: <{tag}> is not numeric: '{node.text.strip()}'") from None
    if v.shape != (n,):
        raise ModelInputError(f"{where}: <{tag}> has {v.size} values, expected {n}")
    if not np.all(np.isfinite(v)):
        raise ModelInputError(f"{where}: <{tag}> contains NaN or infinite values")
    return v


def _scalar(el, tag, where):
    return float(_vec(el, tag, where, n=1)[0])


def _transform_function(ta, where):
    """(slope, constant) of a TransformAxis function: Constant or LinearFunction only."""
    func = ta.find("function")
    if func is None:
        func = ta
    const = func.find("Constant")
    lin = func.find("LinearFunction")
    if lin is not None:
        c = _vec(lin, "coefficients", where, n=2)
        return float(c[0]), float(c[1])
    if const is not None:
        return 0.0, _scalar(const, "value", where)
    raise ModelInputError(f"{where}: unsupported transform function (only Constant and LinearFunction)")


def read_osim(path: str | Path) -> dict[str, OsimBody]:
    path = Path(path)
    try:
        root = ET.parse(path).getroot()
    except (ET.ParseError, OSError) as exc:
        raise ModelInputError(f"{path}: not a readable OpenSim XML file ({exc})") from None
    bodies = {}
    for b in root.iter("Body"):
        name = b.get("name")
        where = f"{path.name}: Body '{name}'"
        mass = _scalar(b, "mass", where)
        com = _vec(b, "mass_center", where)
        I = np.array([[_scalar(b, "inertia_xx", where), _scalar(b, "inertia_xy", where), _scalar(b, "inertia_xz", where)],
                      [0, _scalar(b, "inertia_yy", where), _scalar(b, "inertia_yz", where)],
                      [0, 0, _scalar(b, "inertia_zz", where)]])
        I = np.triu(I) + np.triu(I, 1).T
        joint = None
        jnode = b.find("Joint")
        if jnode is not None and len(jnode):
            j = jnode[0]
            jw = f"{where}: {j.tag} '{j.get('name')}'"
            parent = j.findtext("parent_body")
            if parent is None:
                raise ModelInputError(f"{jw}: missing <parent_body>")
            rotations, translation = [], np.zeros(3)
            if j.tag == "CustomJoint":
                st = j.find("SpatialTransform")
                if st is None:
                    raise ModelInputError(f"{jw}: missing <SpatialTransform>")
                for ta in st.findall("TransformAxis"):
                    axname = ta.get("name")
                    tw = f"{jw} {axname}"
                    axis = _vec(ta, "axis", tw)
                    coord = (ta.findtext("coordinates") or "").strip() or None
                    slope, const = _transform_function(ta, tw)
                    if axname.startswith("rotation"):
                        rotations.append((axis / np.linalg.norm(axis), coord, slope, const))
                    elif coord is not None and slope != 0.0:
                        raise ModelInputError(f"{tw}: coordinate-driven translations are not supported")
                    else:
                        translation = translation + axis * const
            elif j.tag != "WeldJoint":
                raise ModelInputError(f"{jw}: unsupported joint type (CustomJoint and WeldJoint only)")
            joint = OsimJoint(name=j.get("name"), parent=parent,
                              location_in_parent=_vec(j, "location_in_parent", jw),
                              orientation_in_parent=_vec(j, "orientation_in_parent", jw),
                              rotations=rotations, translation=translation)
            if np.any(joint.orientation_in_parent != 0) or np.any(_vec(j, "location", jw) != 0) \
                    or np.any(_vec(j, "orientation", jw) != 0):
                raise ModelInputError(f"{jw}: non-zero joint frame offsets in the child are not supported")
        bodies[name] = OsimBody(name=name, mass=mass, com=com, inertia=I, joint=joint)
    return bodies


def axis_rotation(axis, angle):
    """Rotation matrix for a rotation by `angle` about unit `axis` (Rodrigues)."""
    a = np.asarray(axis, dtype=float)
    a = a / np.linalg.norm(a)
    K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * (K @ K)


def joint_transform(joint: OsimJoint, coords: dict[str, float]):
    """(R, p) of the child frame in the parent frame: rotations applied in order about body-fixed axes."""
    R = np.eye(3)
    for axis, coord, slope, const in joint.rotations:
        angle = const + (slope * coords[coord] if coord else 0.0)
        R = R @ axis_rotation(axis, angle)
    return R, joint.location_in_parent + joint.translation


def body_in_frame(bodies: dict[str, OsimBody], body: str, base: str, coords: dict[str, float]):
    """(R, p) of `body` in the frame of its ancestor `base`."""
    R, p = np.eye(3), np.zeros(3)
    name = body
    while name != base:
        b = bodies[name]
        if b.joint is None:
            raise ModelInputError(f"das3.osim: body '{base}' is not an ancestor of '{body}'")
        Rj, pj = joint_transform(b.joint, coords)
        R, p = Rj @ R, Rj @ p + pj
        name = b.joint.parent
    return R, p
