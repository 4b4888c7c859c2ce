"""Reader for any DAS-format `model_struct*.mat` (DAS3 release, scaled participant models), with
validation that names the file, field and element.

Unlike `das3_source.parse_model_struct`, which checks the DAS3 release itself (11 DOF, 138 elements,
the paper's 22 muscles), this reader takes any DOF set and element set: the kinematic chain comes from
`model.joints` / `model.segments`, the muscle paths from each element's own polynomials. What each
field is, and which the engine uses, is in docs/model_schema.md ("DAS-format input files").
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import scipy.io as sio

from .das3_source import ModelInputError, _field, _finite_array, _poly, muscle_of

ELEMENT_SCALARS = ["fmax", "lceopt", "lslack", "pennopt", "vmax", "tact", "tdeact", "PEEslack", "mass"]
POSITIVE = ["fmax", "lceopt", "vmax", "tact", "tdeact", "PEEslack"]


@dataclass
class DasDof:
    name: str
    osim_name: str
    range: tuple[float, float]


@dataclass
class DasRotation:
    axis: np.ndarray          # unit, in the joint's (parent-side) frame after the previous rotations
    dof: str | None           # coordinate driving it, or None for a constant rotation
    coefs: tuple[float, ...]  # angle = sum_k coefs[k] * q^k (DAS: [0, 1] = q; [0, 0] = no rotation)


@dataclass
class DasJoint:
    name: str
    parent: str
    child: str
    location: np.ndarray      # m, in the parent segment frame
    rotations: list[DasRotation]

    def angles(self, posture: dict[str, float]) -> list[float]:
        out = []
        for r in self.rotations:
            q = posture[r.dof] if r.dof is not None else 0.0
            out.append(float(sum(c * q ** k for k, c in enumerate(r.coefs))))
        return out


@dataclass
class DasSegment:
    name: str
    mass: float
    com: np.ndarray           # m, segment frame
    inertia: np.ndarray       # kg m^2 about the COM, segment frame


@dataclass
class DasElement:
    name: str
    osim_name: str
    muscle: str
    params: dict[str, float]
    max_activation: float     # `maxact` where the file has it, else 1
    dof_names: list[str]
    lparams: np.ndarray
    lcoefs: np.ndarray
    crosses_gh: bool
    direction: dict | None    # {"x": (exps, coefs), "y": ..., "z": ...} over dof_names, or None


@dataclass
class DasStruct:
    path: Path
    name: str                 # model.name
    osimfile: str             # model.osimfile: the OpenSim file it was made from (may not be present)
    gravity: np.ndarray       # m/s^2, ground frame
    dofs: list[DasDof]
    joints: dict[str, DasJoint]         # by child segment name
    segments: dict[str, DasSegment]
    elements: list[DasElement]
    ts_projection: np.ndarray | None    # m, scapula frame (TS landmark on the thorax surface)
    ai_projection: np.ndarray | None    # m, scapula frame (AI landmark)
    extra_fields: list[str] = field(default_factory=list)   # top-level fields this reader does not use

    def dof(self, name: str) -> DasDof:
        for d in self.dofs:
            if d.name == name:
                return d
        raise KeyError(name)

    def chain(self, child: str, base: str) -> list[DasJoint]:
        """Joints from `base` down to `child`, proximal first."""
        out, seg = [], child
        while seg != base:
            if seg not in self.joints:
                raise ModelInputError(f"{self.path.name}: segment '{base}' is not an ancestor of '{child}' "
                                      f"(model.joints)")
            j = self.joints[seg]
            out.append(j)
            seg = j.parent
        return out[::-1]


USED_TOP_LEVEL = {"name", "osimfile", "gravity", "joints", "segments", "dofs", "muscles", "TSprojection",
                  "AIprojection", "nJoints", "nSegments", "nDofs", "nMus", "dof_indeces"}


def _str(obj, name, where) -> str:
    v = _field(obj, name, where)
    if not isinstance(v, str):
        raise ModelInputError(f"{where}: field '{name}' must be text, got {type(v).__name__}")
    return v


def _rotation(j, k, where, dof_names) -> DasRotation | None:
    axis = getattr(j, f"r{k}_axis", None)
    if axis is None or (isinstance(axis, np.ndarray) and axis.size == 0):
        return None
    axis = _finite_array(axis, f"r{k}_axis", where, shape=(3,))
    coefs = _finite_array(_field(j, f"r{k}_coefs", where), f"r{k}_coefs", where)
    dof = getattr(j, f"r{k}_coordinates", None)
    dof = str(dof) if isinstance(dof, str) and dof else None
    if dof is None and np.any(coefs != 0):
        raise ModelInputError(f"{where}: field 'r{k}_coefs' is {coefs.tolist()} but no r{k}_coordinates names "
                              f"its DOF")
    if dof is not None and dof not in dof_names:
        raise ModelInputError(f"{where}: field 'r{k}_coordinates' names unknown DOF '{dof}'")
    if dof is None:
        return None   # a rotation fixed at zero: nothing to apply
    n = np.linalg.norm(axis)
    if n == 0:
        raise ModelInputError(f"{where}: field 'r{k}_axis' is zero")
    return DasRotation(axis=axis / n, dof=dof, coefs=tuple(float(c) for c in coefs))


def read_das_struct(path: str | Path) -> DasStruct:
    path = Path(path)
    try:
        mat = sio.loadmat(path, squeeze_me=True, struct_as_record=False)
    except Exception as exc:  # scipy raises several types for corrupt files
        raise ModelInputError(f"{path}: not a readable MATLAB file ({exc})") from None
    if "model" not in mat:
        raise ModelInputError(f"{path}: no variable 'model'")
    return parse_das_struct(mat["model"], path)


def parse_das_struct(model, path: Path) -> DasStruct:
    where = f"{Path(path).name}: model"
    dofs = []
    for i, d in enumerate(np.atleast_1d(_field(model, "dofs", where))):
        w = f"{where}.dofs[{i}]"
        name = _str(d, "name", w)
        osim = str(getattr(d, "osim_name", name))
        lo, hi = _finite_array(_field(d, "range", w), "range", w, shape=(2,))
        if not lo < hi:
            raise ModelInputError(f"{w} ('{name}'): field 'range' must have lo < hi, got [{lo}, {hi}]")
        dofs.append(DasDof(name=name, osim_name=osim, range=(float(lo), float(hi))))
    dof_names = [d.name for d in dofs]
    if len(set(dof_names)) != len(dof_names):
        raise ModelInputError(f"{where}.dofs: repeated DOF names {dof_names}")

    segments = {}
    for i, s in enumerate(np.atleast_1d(_field(model, "segments", where))):
        w = f"{where}.segments[{i}]"
        name = _str(s, "name", w)
        w = f"{w} ('{name}')"
        mass = float(_finite_array(_field(s, "mass", w), "mass", w, shape=(1,))[0])
        if mass < 0:
            raise ModelInputError(f"{w}: field 'mass' must be non-negative, got {mass}")
        com = _finite_array(_field(s, "mass_center", w), "mass_center", w, shape=(3,))
        inertia = _finite_array(_field(s, "inertia", w), "inertia", w)
        if inertia.size != 9:
            raise ModelInputError(f"{w}: field 'inertia' has {inertia.size} values, expected 9 (3x3)")
        segments[name] = DasSegment(name=name, mass=mass, com=com, inertia=inertia.reshape(3, 3))

    joints = {}
    for i, j in enumerate(np.atleast_1d(_field(model, "joints", where))):
        w = f"{where}.joints[{i}]"
        name = _str(j, "name", w)
        w = f"{w} ('{name}')"
        parent, child = _str(j, "parent_segment", w), _str(j, "segment", w)
        for s in (parent, child):
            if s not in segments:
                raise ModelInputError(f"{w}: names segment '{s}', which is not in model.segments")
        orient = _finite_array(_field(j, "orientation", w), "orientation", w, shape=(3,))
        if np.any(orient != 0):
            raise ModelInputError(f"{w}: field 'orientation' is {orient.tolist()}; only zero joint "
                                  f"orientations are supported")
        for k in (1, 2, 3):
            tc = getattr(j, f"t{k}_coefs", None)
            if tc is not None and np.any(_finite_array(tc, f"t{k}_coefs", w) != 0):
                raise ModelInputError(f"{w}: field 't{k}_coefs' is non-zero; coordinate-driven translations "
                                      f"are not supported")
        rots = [r for r in (_rotation(j, k, w, dof_names) for k in (1, 2, 3)) if r is not None]
        if child in joints:
            raise ModelInputError(f"{w}: segment '{child}' has two parent joints")
        joints[child] = DasJoint(name=name, parent=parent, child=child,
                                 location=_finite_array(_field(j, "location", w), "location", w, shape=(3,)),
                                 rotations=rots)

    elements = []
    for k, mu in enumerate(np.atleast_1d(_field(model, "muscles", where))):
        w = f"{where}.muscles[{k}]"
        name = _str(mu, "name", w)
        w = f"{w} ('{name}')"
        params = {p: float(_finite_array(_field(mu, p, w), p, w, shape=(1,))[0]) for p in ELEMENT_SCALARS}
        for p in POSITIVE:
            if params[p] <= 0:
                raise ModelInputError(f"{w}: field '{p}' must be positive, got {params[p]}")
        for p in ("lslack", "pennopt", "mass"):
            if params[p] < 0:
                raise ModelInputError(f"{w}: field '{p}' must be non-negative, got {params[p]}")
        maxact = 1.0
        if hasattr(mu, "maxact"):
            maxact = float(_finite_array(mu.maxact, "maxact", w, shape=(1,))[0])
            if not 0.0 <= maxact <= 1.0:
                raise ModelInputError(f"{w}: field 'maxact' must lie in [0, 1], got {maxact}")
        names = [str(s) for s in np.atleast_1d(_field(mu, "dof_names", w))]
        unknown = [d for d in names if d not in dof_names]
        if unknown:
            raise ModelInputError(f"{w}: field 'dof_names' names unknown DOFs {unknown}")
        lparams, lcoefs = _poly(mu, "l", len(names), w)
        if len(lcoefs) == 0:
            raise ModelInputError(f"{w}: field 'lcoefs' is empty (no length polynomial)")
        crosses_gh = bool(int(_finite_array(_field(mu, "crossesGH", w), "crossesGH", w, shape=(1,))[0]))
        direction = None
        if crosses_gh and all(hasattr(mu, f"{a}params") for a in "xyz"):
            direction = {a: _poly(mu, a, len(names), w) for a in "xyz"}
        elements.append(DasElement(name=name, osim_name=str(getattr(mu, "osim_name", name)),
                                   muscle=muscle_of(name), params=params, max_activation=maxact,
                                   dof_names=names, lparams=lparams, lcoefs=lcoefs, crosses_gh=crosses_gh,
                                   direction=direction))
    if not elements:
        raise ModelInputError(f"{where}.muscles: no elements")
    if len({e.name for e in elements}) != len(elements):
        raise ModelInputError(f"{where}.muscles: repeated element names")

    def landmark(n):
        v = getattr(model, n, None)
        return None if v is None else _finite_array(v, n, where, shape=(3,))

    gravity = _finite_array(getattr(model, "gravity", [0.0, -9.80665, 0.0]), "gravity", where, shape=(3,))
    return DasStruct(path=Path(path), name=str(getattr(model, "name", "")), osimfile=str(getattr(model, "osimfile", "")),
                     gravity=gravity, dofs=dofs, joints=joints, segments=segments, elements=elements,
                     ts_projection=landmark("TSprojection"), ai_projection=landmark("AIprojection"),
                     extra_fields=[f for f in model._fieldnames if f not in USED_TOP_LEVEL])
