"""Generate the C++ model code (cpp/generated/) from an armrt model file (docs/model_schema.md).

    python -m codegen.generate --model models/das2.json --out cpp/generated

Writes <name>.h, <name>_model.cc (parameter tables, ModelDef), <name>_dynamics.cc (equations of
motion, kinematics) and <name>_paths.cc (muscle path polynomials). Output depends only on the bytes
of the model file, so regenerating from the same file gives byte-identical sources.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import math
import re
import sys
import time
from pathlib import Path

from . import cxx, eom

SCHEMA = "armrt-model"
SCHEMA_VERSION = 1
MAX_DOFS = 16        # the engine's capacities (cpp/include/armrt/model.h kMaxDofs, model_def.h kMaxElements)
MAX_ELEMENTS = 160
MAX_CONTACT_POINTS = 4   # cpp/include/armrt/model_def.h kMaxContactPoints
BODY_CHAIN = [("humerus", "scapula"), ("ulna", "humerus"), ("radius", "ulna"), ("hand", "radius")]
# The base frame and the body chain it carries: "scapula" (das2: girdle fixed, the scapula is the base) or
# "thorax" (das3: clavicle and scapula move; the girdle forces hold the scapula on the thorax).
BODY_CHAINS = {"scapula": BODY_CHAIN,
               "thorax": [("clavicle", "thorax"), ("scapula", "clavicle")] + BODY_CHAIN}
JOINT_AXES = {"gimbal_yzy": 3, "gimbal_yzx": 3, "pin": 1, "weld": 0}


MAX_FILE_BYTES = 64 * 1024**2


class ModelFileError(ValueError):
    """The model file does not follow the schema; the message names the offending field."""


# ---------------------------------------------------------------------------------------------
# Model file validation

def _get(obj, key, where):
    if not isinstance(obj, dict):
        raise ModelFileError(f"model file: '{where}' must be an object")
    if key not in obj:
        raise ModelFileError(f"model file: missing field '{where}.{key}'" if where else
                             f"model file: missing field '{key}'")
    return obj[key]


def _path(where, key):
    return f"{where}.{key}" if where else key


def _number(obj, key, where, positive=False, nonneg=False):
    v = _get(obj, key, where)
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        raise ModelFileError(f"model file: field '{_path(where, key)}' must be a finite number, got {v!r}")
    if positive and not v > 0:
        raise ModelFileError(f"model file: field '{_path(where, key)}' must be > 0, got {v!r}")
    if nonneg and not v >= 0:
        raise ModelFileError(f"model file: field '{_path(where, key)}' must be >= 0, got {v!r}")
    return float(v)


def _array(v, shape, name):
    """Check a nested list of finite numbers of the given shape; returns it as nested floats."""
    def rec(x, dims, label):
        if not dims:
            if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x):
                raise ModelFileError(f"model file: field '{name}' must hold finite numbers, got {x!r} at {label}")
            return float(x)
        if not isinstance(x, list) or (dims[0] is not None and len(x) != dims[0]):
            want = "x".join("n" if d is None else str(d) for d in shape)
            raise ModelFileError(f"model file: field '{name}' must have shape {want}")
        return [rec(y, dims[1:], f"{label}[{i}]") for i, y in enumerate(x)]
    return rec(v, list(shape), "")


def _vector(obj, key, where, n=3):
    return _array(_get(obj, key, where), (n,), _path(where, key))


def _string(obj, key, where):
    v = _get(obj, key, where)
    if not isinstance(v, str) or not v:
        raise ModelFileError(f"model file: field '{_path(where, key)}' must be a non-empty string")
    return v


def _list(obj, key, where, n=None):
    v = _get(obj, key, where)
    if not isinstance(v, list) or (n is not None and len(v) != n):
        raise ModelFileError(f"model file: field '{_path(where, key)}' must be a list"
                             + (f" of {n}" if n is not None else ""))
    return v


def _poly(obj, where, ndof):
    exps = _list(obj, "exponents", where)
    coefs = _array(_get(obj, "coefs", where), (len(exps),), _path(where, "coefs"))
    for k, row in enumerate(exps):
        if (not isinstance(row, list) or len(row) != ndof
                or any(isinstance(e, bool) or not isinstance(e, int) or e < 0 for e in row)):
            raise ModelFileError(f"model file: field '{where}.exponents[{k}]' must be {ndof} non-negative ints")
    return exps, coefs


def validate(model) -> dict:
    """Check every field the generator reads; raise ModelFileError naming the first bad one."""
    if not isinstance(model, dict):
        raise ModelFileError("model file: top level must be a JSON object")
    schema = _get(model, "schema", "")
    if schema != SCHEMA:
        raise ModelFileError(f"model file: field 'schema' is {schema!r}, expected {SCHEMA!r}")
    version = _get(model, "schema_version", "")
    if version != SCHEMA_VERSION or isinstance(version, bool):
        raise ModelFileError(f"model file: field 'schema_version' is {version!r}; this generator reads "
                             f"version {SCHEMA_VERSION} only")
    name = _string(model, "name", "")
    if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name):
        raise ModelFileError(f"model file: field 'name' must be a C identifier, got {name!r}")
    _vector(model, "gravity_thorax", "")

    dofs = _list(model, "dofs", "")
    if not 1 <= len(dofs) <= MAX_DOFS:
        raise ModelFileError(f"model file: field 'dofs' has {len(dofs)} entries; the engine takes 1 to {MAX_DOFS}")
    dof_names = []
    for i, d in enumerate(dofs):
        w = f"dofs[{i}]"
        dof_names.append(_string(d, "name", w))
        _string(d, "osim_name", w)
        lo, hi = _vector(d, "range", w, 2)
        if not lo < hi:
            raise ModelFileError(f"model file: field '{w}.range' must have lo < hi")
        _number(d, "rest", w)
    if len(set(dof_names)) != len(dof_names):
        raise ModelFileError("model file: field 'dofs' has repeated names")

    base = model.get("base", "scapula")
    if base not in BODY_CHAINS:
        raise ModelFileError(f"model file: field 'base' is {base!r}, expected one of {sorted(BODY_CHAINS)}")
    chain = BODY_CHAINS[base]
    if base == "scapula":
        scap = _get(model, "scapula", "")
        _array(_get(scap, "rotation_in_thorax", "scapula"), (3, 3), "scapula.rotation_in_thorax")
        _vector(scap, "origin_in_thorax", "scapula")
    else:
        _validate_girdle_forces(_get(model, "girdle_forces", ""))

    bodies = _list(model, "bodies", "", len(chain))
    used_dofs = []
    for i, (b, (bname, parent)) in enumerate(zip(bodies, chain)):
        w = f"bodies[{i}]"
        if _string(b, "name", w) != bname:
            raise ModelFileError(f"model file: field '{w}.name' must be {bname!r}")
        if _string(b, "parent", w) != parent:
            raise ModelFileError(f"model file: field '{w}.parent' must be {parent!r}")
        _number(b, "mass", w, positive=True)
        _vector(b, "com", w)
        _array(_get(b, "inertia", w), (3, 3), f"{w}.inertia")
        jt = _get(b, "joint", w)
        jw = f"{w}.joint"
        jtype = _string(jt, "type", jw)
        if jtype not in JOINT_AXES:
            raise ModelFileError(f"model file: field '{jw}.type' is {jtype!r}, expected one of {sorted(JOINT_AXES)}")
        _vector(jt, "location_in_parent", jw)
        naxes = JOINT_AXES[jtype]
        axes = _array(_get(jt, "axes", jw), (naxes, 3), f"{jw}.axes")
        for k, a in enumerate(axes):
            if abs(math.sqrt(sum(x * x for x in a)) - 1.0) > 1e-9:
                raise ModelFileError(f"model file: field '{jw}.axes[{k}]' must be a unit vector")
        jd = _list(jt, "dofs", jw, naxes)
        used_dofs.extend(jd)
        if jt.get("rotation") is not None:
            # A DOF fixed at a posture (elbow-forearm models weld the humerus at fixed GH angles).
            Rj = _array(jt["rotation"], (3, 3), f"{jw}.rotation")
            err = max(abs(sum(Rj[k][r] * Rj[k][c] for k in range(3)) - (r == c)) for r in range(3) for c in range(3))
            det = (Rj[0][0] * (Rj[1][1] * Rj[2][2] - Rj[1][2] * Rj[2][1]) - Rj[0][1] * (Rj[1][0] * Rj[2][2] - Rj[1][2] * Rj[2][0])
                   + Rj[0][2] * (Rj[1][0] * Rj[2][1] - Rj[1][1] * Rj[2][0]))
            if err > 1e-9 or det < 0:
                raise ModelFileError(f"model file: field '{jw}.rotation' must be a rotation matrix (orthonormal, det +1)")
    if used_dofs != dof_names:
        raise ModelFileError(f"model file: field 'bodies[].joint.dofs' must be {dof_names} in chain order, "
                             f"got {used_dofs}")

    hp = _get(model, "hand_point", "")
    if _string(hp, "body", "hand_point") not in [b for b, _ in chain]:
        raise ModelFileError("model file: field 'hand_point.body' must name a body")
    _vector(hp, "point", "hand_point")

    gl = _get(model, "glenoid", "")
    for k in ("gh_centre", "normal", "major_axis", "minor_axis"):
        _vector(gl, k, "glenoid")
    for k in ("rim_half_angle_major", "rim_half_angle_minor"):
        _number(gl, k, "glenoid", positive=True)
    pj = _get(model, "passive_joint", "")
    for k in ("stiffness_inside", "stiffness_outside", "damping"):
        _number(pj, k, "passive_joint", nonneg=True)

    elements = _list(model, "elements", "")
    if not elements:
        raise ModelFileError("model file: field 'elements' is empty")
    if len(elements) > MAX_ELEMENTS:
        raise ModelFileError(f"model file: field 'elements' has {len(elements)} entries; the engine takes at most "
                             f"{MAX_ELEMENTS}")
    el_names = []
    for i, e in enumerate(elements):
        try:
            _validate_element(e, i, dof_names, el_names)
        except ModelFileError as exc:
            name = e.get("name") if isinstance(e, dict) else None
            raise ModelFileError(f"{exc} (element {name!r})" if isinstance(name, str) else str(exc)) from None
    if len(set(el_names)) != len(el_names):
        raise ModelFileError("model file: field 'elements' has repeated names")

    muscles = _list(model, "muscles", "")
    mus_names = []
    for i, m in enumerate(muscles):
        w = f"muscles[{i}]"
        mus_names.append(_string(m, "name", w))
        els = _list(m, "elements", w)
        for e in els:
            if e not in el_names:
                raise ModelFileError(f"model file: field '{w}.elements' names unknown element {e!r}")
    groups = _get(model, "groups", "")
    if not isinstance(groups, dict):
        raise ModelFileError("model file: field 'groups' must be an object")
    for g, ms in groups.items():
        if not isinstance(ms, list) or any(x not in mus_names for x in ms):
            raise ModelFileError(f"model file: field 'groups.{g}' must list muscle names")
    check_sense(model)
    return model


def _validate_girdle_forces(gf):
    """The scapulothoracic contact and conoid ligament of a thorax-based model (docs/das3.md)."""
    w = "girdle_forces"
    el = _get(gf, "thorax_ellipsoid", w)
    _vector(el, "centre", f"{w}.thorax_ellipsoid")
    radii = _vector(el, "radii", f"{w}.thorax_ellipsoid")
    if any(not r > 0 for r in radii):
        raise ModelFileError(f"model file: field '{w}.thorax_ellipsoid.radii' must be positive (m)")
    ct = _get(gf, "contact", w)
    _number(ct, "stiffness", f"{w}.contact", positive=True)
    _number(ct, "eps", f"{w}.contact", positive=True)
    pts = _list(ct, "points", f"{w}.contact")
    if not 1 <= len(pts) <= MAX_CONTACT_POINTS:
        raise ModelFileError(f"model file: field '{w}.contact.points' has {len(pts)} entries; 1 to "
                             f"{MAX_CONTACT_POINTS} allowed")
    for k, pt in enumerate(pts):
        pw = f"{w}.contact.points[{k}]"
        _string(pt, "name", pw)
        if _string(pt, "body", pw) != "scapula":
            raise ModelFileError(f"model file: field '{pw}.body' must be 'scapula' (the points glide on the thorax)")
        _vector(pt, "point", pw)
    co = _get(gf, "conoid", w)
    for end, body in (("origin", "clavicle"), ("insertion", "scapula")):
        ew = f"{w}.conoid.{end}"
        if _string(_get(co, end, f"{w}.conoid"), "body", ew) != body:
            raise ModelFileError(f"model file: field '{ew}.body' must be {body!r}")
        _vector(co[end], "point", ew)
    for k in ("length", "stiffness", "eps"):
        _number(co, k, f"{w}.conoid", positive=True)


def _validate_element(e, i, dof_names, el_names):
    """Schema checks of elements[i]; ModelFileError names the field (validate() adds the element name)."""
    w = f"elements[{i}]"
    el_names.append(_string(e, "name", w))
    _string(e, "muscle", w)
    if e.get("max_activation") is not None:
        # The participant's `maxact` (0 = paralysed, 1 = intact); absent means 1.
        _number(e, "max_activation", w, nonneg=True)
        if e["max_activation"] > 1.0:
            raise ModelFileError(f"model file: field '{w}.max_activation' must lie in [0, 1], got {e['max_activation']!r}")
    for k in ("fmax", "lceopt", "lslack", "vmax", "tact", "tdeact", "peeslack", "mass"):
        _number(e, k, w, positive=True)
    _number(e, "pennopt", w, nonneg=True)
    edofs = _list(e, "dofs", w)
    if not edofs or any(d not in dof_names for d in edofs):
        raise ModelFileError(f"model file: field '{w}.dofs' must name DOFs from {dof_names}")
    cgh = _get(e, "crosses_gh", w)
    if not isinstance(cgh, bool):
        raise ModelFileError(f"model file: field '{w}.crosses_gh' must be true/false")
    lp = _get(e, "length_poly", w)
    lpd = _list(lp, "dofs", f"{w}.length_poly")
    if any(d not in dof_names for d in lpd) or len(set(lpd)) != len(lpd):
        raise ModelFileError(f"model file: field '{w}.length_poly.dofs' must name distinct DOFs from {dof_names}")
    _poly(lp, f"{w}.length_poly", len(lpd))
    gd = _get(e, "gh_direction", w)
    if cgh:
        if not isinstance(gd, dict):
            raise ModelFileError(f"model file: field '{w}.gh_direction' must be an object for a GH-crossing element")
        gdd = _list(gd, "dofs", f"{w}.gh_direction")
        if any(d not in dof_names for d in gdd) or len(set(gdd)) != len(gdd):
            raise ModelFileError(f"model file: field '{w}.gh_direction.dofs' must name distinct DOFs")
        for c in "xyz":
            _poly(_get(gd, c, f"{w}.gh_direction"), f"{w}.gh_direction.{c}", len(gdd))
    elif gd is not None:
        raise ModelFileError(f"model file: field '{w}.gh_direction' must be null for an element not crossing GH")


# ---------------------------------------------------------------------------------------------
# Physical sense: a file can follow the schema and still describe no arm (negative inertia, a zero
# glenoid normal, a polynomial of degree 10^9 that would exhaust memory in sympy). Each bound below
# is far outside every human arm model (DAS3 values in docs/model_schema.md) and inside what the
# generated code and the integrators can take.

MAX_NESTING = 16            # JSON depth (the schema needs 7)
MAX_POLY_DEGREE = 16        # total degree of a path polynomial term (DAS3 fits: 9)
MAX_POLY_TERMS = 4096       # terms per polynomial (DAS3 fits: 36)
ELEMENT_BOUNDS = {          # (lo, hi) of a muscle element parameter, SI units
    "fmax": (0.0, 1e4), "lceopt": (1e-3, 1.0), "lslack": (0.0, 2.0), "vmax": (0.1, 100.0),
    "tact": (1e-4, 1.0), "tdeact": (1e-4, 1.0), "peeslack": (0.5, 5.0), "mass": (0.0, 5.0),
}


def _fail(field: str, reason: str):
    raise ModelFileError(f"model file: field '{field}' {reason}")


def nesting_depth(x, limit: int = MAX_NESTING) -> int:
    """Depth of nested lists/objects, iteratively (no recursion limit); stops counting past limit."""
    deepest, stack = 0, [(x, 1)]
    while stack:
        v, d = stack.pop()
        if isinstance(v, (dict, list)):
            deepest = max(deepest, d)
            if deepest > limit:
                return deepest
            stack.extend((c, d + 1) for c in (v.values() if isinstance(v, dict) else v))
    return deepest


def _norm(v) -> float:
    return math.sqrt(sum(x * x for x in v))


def check_sense(model: dict) -> None:
    """Refuse a schema-valid model that is not physically meaningful; ModelFileError names the field
    path and the reason."""
    g = model["gravity_thorax"]
    if _norm(g) > 100.0:
        _fail("gravity_thorax", f"has magnitude {_norm(g):.3g} m/s^2 (more than 10 g)")
    for i, d in enumerate(model["dofs"]):
        lo, hi = d["range"]
        if lo < -2 * math.pi or hi > 2 * math.pi:
            _fail(f"dofs[{i}].range", f"[{lo}, {hi}] rad goes beyond one turn either way (radians expected)")
        if not lo <= d["rest"] <= hi:
            _fail(f"dofs[{i}].rest", f"{d['rest']} rad is outside the range [{lo}, {hi}]")
    for i, b in enumerate(model["bodies"]):
        w = f"bodies[{i}]"
        if not b["mass"] <= 50.0:
            _fail(f"{w}.mass", f"is {b['mass']} kg (an arm segment is under 50 kg)")
        if _norm(b["com"]) > 1.0:
            _fail(f"{w}.com", "is more than 1 m from the body origin")
        inertia = b["inertia"]
        scale = max(abs(x) for row in inertia for x in row) or 1.0
        if any(abs(inertia[r][c] - inertia[c][r]) > 1e-9 * scale for r in range(3) for c in range(3)):
            _fail(f"{w}.inertia", "is not symmetric")
        lam = _eigvalsh3(inertia)
        if lam[0] <= 0:
            _fail(f"{w}.inertia", f"is not positive definite (principal moments {[f'{x:.3g}' for x in lam]} kg m^2)")
        # A source model's own data may break it (das3.osim's clavicle, by 38 %); such a body must say why
        # it is kept (`inertia_note`); M(q) stays positive definite as long as the inertia is.
        if lam[2] > lam[0] + lam[1] + 1e-9 * scale and not isinstance(b.get("inertia_note"), str):
            _fail(f"{w}.inertia", f"violates the triangle inequality (principal moments "
                                  f"{[f'{x:.3g}' for x in lam]} kg m^2: no rigid body has them)")
        axes = b["joint"]["axes"]
        for k, a in enumerate(axes):
            if _norm(a) == 0:
                _fail(f"{w}.joint.axes[{k}]", "is zero")
    gl = model["glenoid"]
    for k in ("normal", "major_axis", "minor_axis"):
        n = _norm(gl[k])
        if n == 0:
            _fail(f"glenoid.{k}", "is zero (GH stability needs a direction)")
        if abs(n - 1.0) > 1e-6:
            _fail(f"glenoid.{k}", f"must be a unit vector, has length {n:.6g}")
    for a, b in (("normal", "major_axis"), ("normal", "minor_axis"), ("major_axis", "minor_axis")):
        dot = sum(x * y for x, y in zip(gl[a], gl[b]))
        if abs(dot) > 1e-6:
            _fail(f"glenoid.{b}", f"must be perpendicular to glenoid.{a} (dot product {dot:.3g})")
    for k in ("rim_half_angle_major", "rim_half_angle_minor"):
        if not gl[k] < math.pi / 2:
            _fail(f"glenoid.{k}", f"is {gl[k]} rad; a rim half-angle is below pi/2")
    for i, e in enumerate(model["elements"]):
        try:
            _check_element_sense(e, i)
        except ModelFileError as exc:
            raise ModelFileError(f"{exc} (element {e['name']!r})") from None
    _check_partition(model)


def _check_element_sense(e: dict, i: int) -> None:
    w = f"elements[{i}]"
    for k, (lo, hi) in ELEMENT_BOUNDS.items():
        if not lo <= e[k] <= hi:
            _fail(f"{w}.{k}", f"is {e[k]}, outside the physical range [{lo}, {hi}]")
    if not e["pennopt"] < math.pi / 2:
        _fail(f"{w}.pennopt", f"is {e['pennopt']} rad; pennation is below pi/2")
    if set(e["length_poly"]["dofs"]) - set(e["dofs"]):
        _fail(f"{w}.length_poly.dofs", f"{e['length_poly']['dofs']} include DOFs the element does not cross "
                                       f"({e['dofs']})")
    polys = [("length_poly", e["length_poly"])]
    if e["gh_direction"]:
        polys += [(f"gh_direction.{c}", e["gh_direction"][c]) for c in "xyz"]
    for name, poly in polys:
        if len(poly["exponents"]) > MAX_POLY_TERMS:
            _fail(f"{w}.{name}.exponents", f"has {len(poly['exponents'])} terms (at most {MAX_POLY_TERMS})")
        for t, row in enumerate(poly["exponents"]):
            if sum(row) > MAX_POLY_DEGREE:
                _fail(f"{w}.{name}.exponents[{t}]", f"has degree {sum(row)} (at most {MAX_POLY_DEGREE}; "
                                                    f"the path fits use up to 9)")


def _check_partition(model: dict) -> None:
    # Element and muscle tables must describe the same partition.
    owner: dict[str, str] = {}
    for i, m in enumerate(model["muscles"]):
        for el in m["elements"]:
            if el in owner:
                _fail(f"muscles[{i}].elements", f"lists {el!r}, already in muscle {owner[el]!r}")
            owner[el] = m["name"]
    if len({m["name"] for m in model["muscles"]}) != len(model["muscles"]):
        _fail("muscles", "has repeated names")
    for i, e in enumerate(model["elements"]):
        if e["name"] not in owner:
            _fail(f"elements[{i}].muscle", f"element {e['name']!r} is in no muscle's 'elements' list")
        if owner[e["name"]] != e["muscle"]:
            _fail(f"elements[{i}].muscle", f"is {e['muscle']!r} but muscle {owner[e['name']]!r} lists the element")


def _eigvalsh3(a) -> list[float]:
    """Eigenvalues of a symmetric 3x3 matrix, ascending (closed form; no numpy in the generator)."""
    p1 = a[0][1] ** 2 + a[0][2] ** 2 + a[1][2] ** 2
    q = (a[0][0] + a[1][1] + a[2][2]) / 3
    if p1 == 0:
        return sorted([a[0][0], a[1][1], a[2][2]])
    p2 = sum((a[k][k] - q) ** 2 for k in range(3)) + 2 * p1
    p = math.sqrt(p2 / 6)
    b = [[(a[r][c] - (q if r == c else 0)) / p for c in range(3)] for r in range(3)]
    det = (b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) - b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0])
           + b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]))
    phi = math.acos(max(-1.0, min(1.0, det / 2))) / 3
    e1 = q + 2 * p * math.cos(phi)
    e3 = q + 2 * p * math.cos(phi + 2 * math.pi / 3)
    return sorted([e1, 3 * q - e1 - e3, e3])


def load_model(path) -> tuple[dict, str]:
    """Read and validate a model file; returns (model, sha256 of its bytes)."""
    path = Path(path)
    try:
        size = path.stat().st_size
        if size > MAX_FILE_BYTES:
            raise ModelFileError(f"model file {path}: {size} bytes, more than {MAX_FILE_BYTES} (das2.json: 0.3 MB)")
        data = path.read_bytes()
    except OSError as exc:
        raise ModelFileError(f"model file {path}: {exc.strerror or exc}") from None
    try:
        model = json.loads(data)
    except json.JSONDecodeError as exc:
        raise ModelFileError(f"model file {path}: not valid JSON ({exc})") from None
    except RecursionError:
        raise ModelFileError(f"model file {path}: nesting deeper than {MAX_NESTING} levels") from None
    depth = nesting_depth(model)
    if depth > MAX_NESTING:
        raise ModelFileError(f"model file {path}: nesting deeper than {MAX_NESTING} levels (the schema needs 7)")
    return validate(model), hashlib.sha256(data).hexdigest()


# ---------------------------------------------------------------------------------------------
# Code emission

def _banner(model_file: str, digest: str, command: str | None = None) -> str:
    command = command or f"python -m codegen.generate --model models/{model_file} --out cpp/generated"
    return (f"// GENERATED FILE - DO NOT EDIT BY HAND.\n"
            f"// Written by `{command}`\n"
            f"// from the model file {model_file} (sha256 {digest}).\n"
            f"// Change the model file or the generator and regenerate instead.\n")


def _global_poly(poly: dict, dofs: list, dof_index: dict):
    """Terms of a polynomial as (coef, exponent tuple over all of the model's dofs)."""
    idx = [dof_index[d] for d in dofs]
    terms = []
    for row, c in zip(poly["exponents"], poly["coefs"]):
        e = [0] * len(dof_index)
        for j, k in zip(idx, row):
            e[j] += int(k)
        terms.append((float(c), tuple(e)))
    return terms


class _Monomials:
    """Shares each monomial (and each power of each q) once per function."""

    def __init__(self, ndof: int):
        self.ndof = ndof
        self.names: dict[tuple, str] = {}
        self.order: list[tuple] = []

    def ref(self, e: tuple) -> str | None:
        if not any(e):
            return None
        if e not in self.names:
            self.names[e] = f"m{len(self.order)}"
            self.order.append(e)
        return self.names[e]

    def preamble(self) -> list[str]:
        maxpow = [max((e[j] for e in self.order), default=0) for j in range(self.ndof)]
        lines = []
        for j in range(self.ndof):
            if maxpow[j] >= 1:
                lines.append(f"  const double q{j} = q[{j}];")
            for p in range(2, maxpow[j] + 1):
                prev = f"q{j}" if p == 2 else f"q{j}_{p - 1}"
                lines.append(f"  const double q{j}_{p} = {prev}*q{j};")
        if not any(maxpow):
            lines.append("  (void)q;")
        for e in self.order:
            factors = [f"q{j}" if k == 1 else f"q{j}_{k}" for j, k in enumerate(e) if k]
            lines.append(f"  const double {self.names[e]} = {'*'.join(factors)};")
        return lines


def _sum(terms, mono: _Monomials) -> str:
    parts = []
    for c, e in terms:
        if c == 0.0:
            continue
        name = mono.ref(e)
        parts.append(cxx.fmt(c) if name is None else f"{cxx.fmt(c)}*{name}")
    if not parts:
        return "0.0"
    return " + ".join(parts).replace("+ -", "- ")


def _gradient(terms, j):
    out = []
    for c, e in terms:
        if e[j]:
            d = list(e)
            d[j] -= 1
            out.append((c * e[j], tuple(d)))
    return out


def paths_source(model: dict, ns: str) -> str:
    dof_index = {d["name"]: i for i, d in enumerate(model["dofs"])}
    NDOF = len(dof_index)
    els = model["elements"]
    lengths = [_global_poly(e["length_poly"], e["length_poly"]["dofs"], dof_index) for e in els]

    out = []
    # muscle_lengths: the lengths of muscle_paths, bit for bit (one summation order for both).
    out.append("void muscle_lengths(const double* q, double* L) {\n"
               f"  double moment_arm[{NDOF} * kMaxElements];\n  muscle_paths(q, L, moment_arm);\n}}\n")

    # muscle_paths: lengths and moment arms -dL/dq in one pass. Each monomial m carries the vector
    # G(m) = [-dm/dq0, ..., -dm/dq4, m, 0, 0] (das2; W lanes in general); every term of a length
    # polynomial adds c G(m) (one 8-wide multiply-add gives a length and its five moment arms), instead of one scalar polynomial per
    # moment arm. G is built along a tree of monomials, each from its parent m' = m / q_j by the
    # product rule: G(q_j m') = q_j G(m') - m' E_j (E_j: unit vector of lane j), two vector operations.
    # The same polynomials summed in another order: results differ by rounding only.
    for i, e in enumerate(els):
        crossed = {dof_index[d] for d in e["dofs"]}
        for c, m in lengths[i]:
            bad = [j for j in range(NDOF) if m[j] and j not in crossed and c != 0.0]
            if bad:
                raise ValueError(f"element {e['name']}: length depends on {model['dofs'][bad[0]]['name']}, "
                                 f"which it does not cross")
    used = sorted({m for t in lengths for c, m in t if c != 0.0 and any(m)}, key=lambda m: (sum(m), m))
    tree: dict[tuple, tuple[int, tuple]] = {}  # monomial -> (dof j, parent m / q_j)
    pending = list(used)
    while pending:
        m = pending.pop()
        if m in tree or not any(m):
            continue
        j = max(k for k in range(NDOF) if m[k])
        parent = tuple(p - (k == j) for k, p in enumerate(m))
        tree[m] = (j, parent)
        pending.append(parent)
    order = sorted(tree, key=lambda m: (sum(m), m))
    if NDOF > 7:
        crossed_dofs = [[dof_index[d] for d in e["dofs"]] for e in els]
        out.append(_grouped_paths(crossed_dofs, lengths, order, tree, NDOF))
        return _paths_file(ns, out, els, dof_index, NDOF, 4)
    # Up to 7 DOFs one 8-lane vector holds an element's moment arms and its length (more: _grouped_paths).
    W = 8
    vt = f"v{W}d"
    gname = {(0,) * NDOF: "g_one"}
    pname = {(0,) * NDOF: "1.0"}
    for k, m in enumerate(order):
        gname[m], pname[m] = f"g{k}", f"p{k}"
    lines = [f"  const {vt} g_one = {{" + ", ".join(["0.0"] * NDOF + ["1.0"] + ["0.0"] * (W - NDOF - 1)) + "};"]
    for j in range(NDOF):
        lines.append(f"  const {vt} e{j} = {{" + ", ".join("1.0" if k == j else "0.0" for k in range(W)) + "};")
    qs = set()
    parents = {tree[m][1] for m in order}
    for m in order:
        j, parent = tree[m]
        qs.add(j)
        if m in parents:  # the scalar monomial is only needed by its children
            lines.append(f"  const double {pname[m]} = " + (f"q{j}*{pname[parent]};" if any(parent) else f"q{j};"))
        if any(parent):
            lines.append(f"  const {vt} {gname[m]} = q{j}*{gname[parent]} - {pname[parent]}*e{j};")
        else:
            lines.append(f"  const {vt} {gname[m]} = q{j}*g_one - e{j};")
    body = []
    for i, t in enumerate(lengths):
        parts = [f"{cxx.fmt(c)}*{gname[m]}" for c, m in t if c != 0.0]
        # Two interleaved partial sums halve the chain of dependent multiply-adds per element.
        halves = [" + ".join(parts[0::2]) or "0.0*g_one", " + ".join(parts[1::2]) or "0.0*g_one"]
        expr = f"({halves[0]}) + ({halves[1]})"
        body.append(f"  {{ const {vt} a = {expr};")
        # Moment arms by DOF (model_def.h): row j holds every element's moment arm about DOF j.
        stores = " ".join(f"moment_arm[{j} * kMaxElements + {i}] = a[{j}];" for j in range(NDOF))
        body.append(f"    {stores} L[{i}] = a[{NDOF}]; }}")
    head = [f"  const double q{j} = q[{j}];" for j in sorted(qs)] or ["  (void)q;"]
    out.append("void muscle_paths(const double* q, double* L, double* moment_arm) {\n"
               + "\n".join(head + lines + body) + "\n}\n")
    return _paths_file(ns, out, els, dof_index, NDOF, W)


GROUP_SIZE = 3  # DOFs per 4-lane vector in _grouped_paths: three moment-arm lanes and a length lane


def _grouped_paths(crossed_dofs, lengths, order, tree, NDOF):
    """muscle_paths for more than 7 DOFs: the DOFs in groups of three (das3: SC, AC, GH, elbow and forearm),
    each group one 4-lane vector [-dm/dq of its DOFs, m]. A monomial m carries a vector only for the groups
    of the DOFs it contains, so a term c m costs one 4-wide multiply-add per such group (1.3 on average for
    das3) instead of an 8- or 16-wide one over lanes that are mostly zero (perf: the multiply-adds set the
    cost of the paths). m itself is summed in the length lane of one group only, its home, the first of its
    groups, so that an element's length is the sum of its groups' length lanes; a constant term goes to the
    element's first group. Sums are ordered differently from the one-vector form: results differ by
    rounding only."""
    group = [j // GROUP_SIZE for j in range(NDOF)]
    n_groups = group[-1] + 1
    sizes = [sum(1 for j in range(NDOF) if group[j] == b) for b in range(n_groups)]
    VAL = GROUP_SIZE  # the length lane
    n_el = len(lengths)

    def groups_of(m):
        return sorted({group[j] for j in range(NDOF) if m[j]})

    lines = [f"  const v4d e_len = {{0.0, 0.0, 0.0, 1.0}};"]
    for j in range(NDOF):
        lane = j - GROUP_SIZE * group[j]
        lines.append(f"  const v4d e{j} = {{" + ", ".join("1.0" if x == lane else "0.0" for x in range(4)) + "};")
    pname = {(0,) * NDOF: "1.0"}
    for n, m in enumerate(order):
        pname[m] = f"p{n}"
    gname = {}
    qs = set()
    # Scalar monomials first (every vector below may need its own or its parent's), then the vectors:
    # for m = q_j m' and a group b of m,
    #   b a group of m':  G_b(m) = q_j G_b(m') - [j in b] m' e_j, its length lane q_j m' moved out of b if b is
    #                     home for m' but not for m (j's group comes first), or into b if the reverse;
    #   b only j's group: G_b(m) = -m' e_j (+ m e_len if b is home for m).
    for m in order:
        j, parent = tree[m]
        qs.add(j)
        lines.append(f"  const double {pname[m]} = " + (f"q{j}*{pname[parent]};" if any(parent) else f"q{j};"))
    for n, m in enumerate(order):
        j, parent = tree[m]
        gm, gp = groups_of(m), groups_of(parent)
        home_m, home_p = gm[0], (gp[0] if gp else None)
        for b in gm:
            name = f"g{n}_{b}"
            gname[(m, b)] = name
            terms = []
            if b in gp:
                terms.append(f"q{j}*{gname[(parent, b)]}")
                if b == home_p and b != home_m:
                    terms.append(f"- {pname[m]}*e_len")
            elif b == home_m:
                terms.append(f"{pname[m]}*e_len")
            if group[j] == b:
                terms.append(f"- {pname[parent]}*e{j}" if any(parent) else f"- e{j}")
            expr = " ".join(terms)
            if expr.startswith("- "):
                expr = "-" + expr[2:]
            lines.append(f"  const v4d {name} = {expr};")
    body = []
    for i, t in enumerate(lengths):
        crossed = sorted({group[j] for j in crossed_dofs[i]})
        stmts = []
        for b in crossed:
            terms = [(c, m) for c, m in t if c != 0.0 and any(m) and b in groups_of(m)]
            parts = [f"{cxx.fmt(c)}*{gname[(m, b)]}" for c, m in terms]
            const = [c for c, m in t if c != 0.0 and not any(m)]
            if b == crossed[0] and const:
                parts.insert(0, f"{cxx.fmt(const[0])}*e_len")
            halves = [" + ".join(parts[0::2]) or "v4d{}", " + ".join(parts[1::2]) or "v4d{}"]
            stmts.append(f"const v4d a{b} = ({halves[0]}) + ({halves[1]});")
        # Moment arms by DOF (model_def.h); the groups the element does not cross stay as the memset left them.
        out_lines = [f"moment_arm[{GROUP_SIZE * b + k} * kMaxElements + {i}] = a{b}[{k}];"
                     for b in crossed for k in range(sizes[b])]
        length = " + ".join(f"a{b}[{VAL}]" for b in crossed) if crossed else "0.0"
        body.append("  { " + " ".join(stmts))
        body.append("    " + " ".join(out_lines) + f" L[{i}] = {length}; }}")
    head = [f"  const double q{j} = q[{j}];" for j in sorted(qs)] or ["  (void)q;"]
    names = ", ".join(f"{b}: DOFs {GROUP_SIZE * b}..{GROUP_SIZE * b + sizes[b] - 1}" for b in range(n_groups))
    zero = (f"  std::memset(moment_arm, 0, ({NDOF - 1} * kMaxElements + {n_el}) * sizeof(double));"
            "  // the DOFs an element does not cross")
    lines = _drop_unused_scalars(lines, body)
    return ("void muscle_paths(const double* q, double* L, double* moment_arm) {\n"
            f"  // DOF groups (_grouped_paths) {names}.\n"
            + "\n".join([zero] + head + lines + body) + "\n}\n")


def _drop_unused_scalars(lines, body):
    """lines without the `const double pN = ...;` monomials nothing reads (a monomial whose vectors need only
    its parent's value): the generated file then compiles without -Wunused-variable warnings."""
    define = re.compile(r"^  const double (p\d+) = ")
    while True:
        text = "\n".join(body + [ln.split(" = ", 1)[1] if define.match(ln) else ln for ln in lines])
        used = set(re.findall(r"\bp\d+\b", text))
        kept = [ln for ln in lines if not (define.match(ln) and define.match(ln).group(1) not in used)]
        if len(kept) == len(lines):
            return lines
        lines = kept


def _paths_file(ns, out, els, dof_index, NDOF, W):
    vt = f"v{W}d"
    # gh_directions: the polynomials into three arrays, then one loop normalises them, which the compiler
    # vectorises (a square root and a division per element were most of its cost as scalar code). No pragma:
    # the file must compile warning-free with any flags (tests/gen_lib.py builds it with -Wall -Werror).
    # Each element's x, y, z as the lanes of one vector, one multiply-add per monomial (three scalar ones were
    # 3 % of a recorded das3 step).
    mono = _Monomials(NDOF)
    n_el = len(els)
    body = ["  using v3d = double __attribute__((vector_size(32)));  // x, y, z and an unused lane",
            f"  double gx[{n_el}], gy[{n_el}], gz[{n_el}];"]
    for i, e in enumerate(els):
        gd = e["gh_direction"]
        if gd is None:
            body.append(f"  gx[{i}] = 0.0; gy[{i}] = 0.0; gz[{i}] = 0.0;")
            continue
        coefs: dict = {}
        for k, c in enumerate("xyz"):
            for coef, ex in _global_poly(gd[c], gd["dofs"], dof_index):
                if coef != 0.0:
                    coefs.setdefault(ex, [0.0, 0.0, 0.0])[k] += coef
        if not coefs:
            body.append(f"  gx[{i}] = 0.0; gy[{i}] = 0.0; gz[{i}] = 0.0;")
            continue
        parts = []
        for ex, (cx, cy, cz) in coefs.items():
            vec = f"v3d{{{cxx.fmt(cx)}, {cxx.fmt(cy)}, {cxx.fmt(cz)}, 0.0}}"
            name = mono.ref(ex)
            parts.append(vec if name is None else f"{vec}*{name}")
        body.append(f"  {{ const v3d g = {' + '.join(parts)}; gx[{i}] = g[0]; gy[{i}] = g[1]; gz[{i}] = g[2]; }}")
    body += [f"  for (int i = 0; i < {n_el}; ++i) {{",
             "    const double n2 = gx[i]*gx[i] + gy[i]*gy[i] + gz[i]*gz[i];",
             "    const double s = n2 > 0.0 ? 1.0/std::sqrt(n2) : 0.0;",
             "    d[3*i] = gx[i]*s; d[3*i + 1] = gy[i]*s; d[3*i + 2] = gz[i]*s;",
             "  }"]
    out.append("void gh_directions(const double* q, double* d) {\n" + "\n".join(mono.preamble() + body) + "\n}\n")

    return ("#include <cmath>\n#include <cstring>\n\n#include \"" + ns + ".h\"\n\n"
            f"namespace armrt::generated::{ns} {{\n\n"
            f"// muscle_paths writes its moment arms in rows of {MAX_ELEMENTS} (model_def.h): the engine must agree.\n"
            f"static_assert(kMaxElements == {MAX_ELEMENTS}, \"rebuild this model: the engine's kMaxElements changed\");\n\n"
            + ("// Eight doubles, one SIMD register with AVX-512 (two with AVX2): a length and its moment arms.\n"
               if NDOF <= 7 else "// Four doubles, one AVX2 register: one group's moment arms and a length lane.\n")
            + f"using {vt} = double __attribute__((vector_size({8 * W})));\n\n" + "\n".join(out) + f"\n}}  // namespace armrt::generated::{ns}\n")


def chain_dynamics_source(model: dict, ns: str) -> tuple[str, dict]:
    """The equations of motion and kinematics of a thorax-based chain (das3) as unrolled recursive
    algorithms (codegen/eom_chain.py; docs/das3.md says why not Kane's method at 11 DOFs)."""
    from . import eom_chain as ec
    dof_names = [d["name"] for d in model["dofs"]]
    n = len(dof_names)
    links = ec.links_of(dof_names, model["bodies"], "thorax")
    body_link = {l.body: i for i, l in enumerate(links) if l.body}
    body_names = [b["name"] for b in model["bodies"]]
    hp = model["hand_point"]
    arm_links = ec.links_below(links, body_link, "humerus")
    gf = model["girdle_forces"]
    points = ([(p["name"], p["body"], p["point"]) for p in gf["contact"]["points"]]
              + [("conoid_origin", gf["conoid"]["origin"]["body"], gf["conoid"]["origin"]["point"]),
                 ("conoid_insertion", gf["conoid"]["insertion"]["body"], gf["conoid"]["insertion"]["point"])])

    def E_of(s):
        return ec._rotations(links, s["sin"], s["cos"])

    def M_of(s):
        M = ec.crba(links, E_of(s), n)
        return [M[i][j] for i in range(n) for j in range(n)]

    def b_of(s):
        return [-t for t in ec.rnea(links, E_of(s), s["qd"], s["g"])]

    def hand(s):
        return ec.point_and_jacobian(links, E_of(s), body_link[hp["body"]], [float(v) for v in hp["point"]], n)

    def poses(s):
        R, p = ec.body_poses(links, E_of(s))
        return [("R", [x for b in body_names for row in R[body_link[b]] for x in row]),
                ("p", [x for b in body_names for x in p[body_link[b]]])]

    def momentum(s):
        A, c = ec.momentum_rate(links, E_of(s), s["qd"], arm_links, n)
        return [("A", [x for row in A for x in row]), ("c", c)]

    q_in, qd_in, g_in = ("q", n, True), ("qd", n, False), ("g_base", 3, False)
    fns, stats = [], {}
    for name, sig, inputs, build in [
        ("mass_matrix", "void mass_matrix(const double* q, double* M)", [q_in], lambda s: [("M", M_of(s))]),
        ("bias_force", "void bias_force(const double* q, const double* qd, const double* g_base, double* b)",
         [q_in, qd_in, g_in], lambda s: [("b", b_of({**s, "g": s["g_base"]}))]),
        ("dynamics", "void dynamics(const double* q, const double* qd, const double* g_base, double* M, double* b)",
         [q_in, qd_in, g_in], lambda s: [("M", M_of(s)), ("b", b_of({**s, "g": s["g_base"]}))]),
        ("hand_position", "void hand_position(const double* q, double* p)", [q_in], lambda s: [("p", hand(s)[0])]),
        ("hand_jacobian", "void hand_jacobian(const double* q, double* Jv, double* Jw)", [q_in],
         lambda s: [("Jv", [x for row in hand(s)[1] for x in row]),
                    ("Jw", [x for row in ec.angular_jacobian(links, E_of(s), body_link[hp["body"]], n) for x in row])]),
        ("arm_momentum_rate", "void arm_momentum_rate(const double* q, const double* qd, double* A, double* c)",
         [q_in, qd_in], momentum),
        ("body_poses", "void body_poses(const double* q, double* R, double* p)", [q_in], poses),
        ("girdle_points", "void girdle_points(const double* q, double* p, double* J)", [q_in],
         lambda s: ec._points_outputs(links, E_of(s), body_link, points, n)),
    ]:
        text, ops = ec._function(sig, inputs, build)
        stats[name] = ops
        fns.append(text)
    src = ("#include <cmath>\n\n#include \"armrt/fast_math.h\"\n#include \"" + ns + ".h\"\n\n"
           "// Unrolled composite-rigid-body and recursive Newton-Euler algorithms (codegen/eom_chain.py).\n"
           f"namespace armrt::generated::{ns} {{\n\n" + "\n".join(fns) + f"\n}}  // namespace armrt::generated::{ns}\n")
    return src, stats


def dynamics_source(model: dict, ns: str) -> tuple[str, dict]:
    if model.get("base", "scapula") == "thorax":
        return chain_dynamics_source(model, ns)
    NDOF = len(model["dofs"])
    ex = eom.derive(model)
    q, qd, g = ex.q, ex.qd, ex.g
    fns = []
    stats = {}

    def fn(name, sig, inputs, outputs):
        code, ntemps = cxx.emit_function(sig, inputs, outputs, trig_of=q)
        stats[name] = ntemps
        fns.append(code)

    M = ex.mass_matrix
    fn("mass_matrix", "void mass_matrix(const double* q, double* M)", [("q", q)],
       [("M", [M[i, j] for i in range(NDOF) for j in range(NDOF)])])
    fn("bias_force", "void bias_force(const double* q, const double* qd, const double* g_base, double* b)",
       [("q", q), ("qd", qd), ("g_base", g)], [("b", list(ex.bias_force))])
    # M and b together share their sines, cosines and common subexpressions: the engine's hot path.
    fn("dynamics", "void dynamics(const double* q, const double* qd, const double* g_base, double* M, double* b)",
       [("q", q), ("qd", qd), ("g_base", g)],
       [("M", [M[i, j] for i in range(NDOF) for j in range(NDOF)]), ("b", list(ex.bias_force))])
    fn("hand_position", "void hand_position(const double* q, double* p)", [("q", q)],
       [("p", list(ex.hand_position))])
    fn("hand_jacobian", "void hand_jacobian(const double* q, double* Jv, double* Jw)", [("q", q)],
       [("Jv", list(ex.hand_jv)), ("Jw", list(ex.hand_jw))])
    fn("arm_momentum_rate", "void arm_momentum_rate(const double* q, const double* qd, double* A, double* c)",
       [("q", q), ("qd", qd)], [("A", list(ex.momentum_a)), ("c", list(ex.momentum_c))])
    Rs = [x for R in ex.body_rotations for x in R]        # sympy Matrix iterates row-major
    ps = [x for p in ex.body_origins for x in p]
    fn("body_poses", "void body_poses(const double* q, double* R, double* p)", [("q", q)], [("R", Rs), ("p", ps)])

    src = ("#include <cmath>\n\n#include \"armrt/fast_math.h\"\n#include \"" + ns + ".h\"\n\n"
           f"namespace armrt::generated::{ns} {{\n\n" + "\n".join(fns) + f"\n}}  // namespace armrt::generated::{ns}\n")
    return src, stats


def header_source(ns: str) -> str:
    return f"""#pragma once

#include "armrt/model_def.h"

namespace armrt::generated::{ns} {{

const armrt::ModelDef& model_def();

void mass_matrix(const double* q, double* M);
void bias_force(const double* q, const double* qd, const double* g_base, double* b);
void dynamics(const double* q, const double* qd, const double* g_base, double* M, double* b);
void hand_position(const double* q, double* p);
void hand_jacobian(const double* q, double* Jv, double* Jw);
void arm_momentum_rate(const double* q, const double* qd, double* A, double* c);
void body_poses(const double* q, double* R, double* p);
void muscle_lengths(const double* q, double* L);
void muscle_paths(const double* q, double* L, double* moment_arm);
void gh_directions(const double* q, double* d);
void girdle_points(const double* q, double* p, double* J);  // thorax-based models only

}}  // namespace armrt::generated::{ns}
"""


def _arr(vals) -> str:
    return "{" + ", ".join(cxx.fmt(v) for v in vals) + "}"


def model_source(model: dict, ns: str, digest: str) -> str:
    f = cxx.fmt
    dof_index = {d["name"]: i for i, d in enumerate(model["dofs"])}
    NDOF = len(dof_index)
    els = model["elements"]
    el_index = {e["name"]: i for i, e in enumerate(els)}
    lines = ["#include \"" + ns + ".h\"", "", f"namespace armrt::generated::{ns} {{", "", "namespace {", ""]

    # Every struct is filled by member name (C++20 designated initialisers), never by position.
    lines.append(f"const DofParams kDofs[{NDOF}] = {{")
    for d in model["dofs"]:
        lines.append(f"    {{.name = {cxx.cstr(d['name'])}, .osim_name = {cxx.cstr(d['osim_name'])}, "
                     f".range_min = {f(d['range'][0])}, .range_max = {f(d['range'][1])}, .rest = {f(d['rest'])}}},")
    lines.append("};")
    lines.append("")
    lines.append(f"const ElementParams kElements[{len(els)}] = {{")
    for e in els:
        mask = sum(1 << dof_index[d] for d in e["dofs"])
        lines.append(f"    {{.name = {cxx.cstr(e['name'])}, .muscle = {cxx.cstr(e['muscle'])}, "
                     f".osim_name = {cxx.cstr(e.get('osim_name') or '')}, .fmax = {f(e['fmax'])}, "
                     f".lceopt = {f(e['lceopt'])}, .lslack = {f(e['lslack'])}, .pennopt = {f(e['pennopt'])}, "
                     f".vmax = {f(e['vmax'])}, .tact = {f(e['tact'])}, .tdeact = {f(e['tdeact'])}, "
                     f".peeslack = {f(e['peeslack'])}, .mass = {f(e['mass'])}, "
                     f".crosses_gh = {1 if e['crosses_gh'] else 0}, .dof_mask = {mask}, "
                     f".max_activation = {f(e.get('max_activation', 1.0))}}},")
    lines.append("};")
    lines.append("")

    muscle_elements = {}
    for k, m in enumerate(model["muscles"]):
        idx = [el_index[n] for n in m["elements"]]
        muscle_elements[m["name"]] = idx
        lines.append(f"const int kMuscle{k}[{len(idx)}] = {{{', '.join(map(str, idx))}}};")
    lines.append("")
    lines.append(f"const GroupDef kMuscles[{len(model['muscles'])}] = {{")
    for k, m in enumerate(model["muscles"]):
        lines.append(f"    {{.name = {cxx.cstr(m['name'])}, .num_elements = {len(muscle_elements[m['name']])}, "
                     f".elements = kMuscle{k}}},")
    lines.append("};")
    lines.append("")
    groups = list(model["groups"].items())
    for k, (gname, ms) in enumerate(groups):
        idx = sorted({i for mname in ms for i in muscle_elements[mname]})
        lines.append(f"const int kGroup{k}[{max(len(idx), 1)}] = {{{', '.join(map(str, idx)) or '0'}}};")
    lines.append("")
    if groups:
        lines.append(f"const GroupDef kGroups[{len(groups)}] = {{")
        for k, (gname, ms) in enumerate(groups):
            n = len({i for mname in ms for i in muscle_elements[mname]})
            lines.append(f"    {{.name = {cxx.cstr(gname)}, .num_elements = {n}, .elements = kGroup{k}}},")
        lines.append("};")
        groups_ptr = "kGroups"
    else:
        groups_ptr = "nullptr"
    lines.append("")

    base = model.get("base", "scapula")
    if base == "scapula":
        R, origin = model["scapula"]["rotation_in_thorax"], model["scapula"]["origin_in_thorax"]
    else:
        R, origin = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], [0.0, 0.0, 0.0]
    gt = model["gravity_thorax"]
    g_base = [math.fsum(R[i][k] * gt[i] for i in range(3)) for k in range(3)]   # R^T g
    gl = model["glenoid"]
    pj = model["passive_joint"]
    body_names = [b["name"] for b in model["bodies"]]
    humerus = body_names.index("humerus")
    arm_mass = math.fsum(b["mass"] for b in model["bodies"][humerus:])
    lines.append(f"const char* const kBodyNames[{len(body_names)}] = {{{', '.join(cxx.cstr(b) for b in body_names)}}};")
    if base == "thorax":
        gf = model["girdle_forces"]
        el, ct, co = gf["thorax_ellipsoid"], gf["contact"], gf["conoid"]
        pts = ct["points"]
        lines += [
            f"const char* const kContactPointNames[{len(pts)}] = {{{', '.join(cxx.cstr(p['name']) for p in pts)}}};",
            "",
            "const GirdleDef kGirdle = {",
            f"    .thorax = {{.centre = {_arr(el['centre'])}, .radii = {_arr(el['radii'])}, "
            f".k = {f(ct['stiffness'])}, .eps = {f(ct['eps'])}}},",
            f"    .num_contact_points = {len(pts)},",
            "    .contact_point_names = kContactPointNames,",
            f"    .conoid = {{.origin = {_arr(co['origin']['point'])}, .insertion = {_arr(co['insertion']['point'])}, "
            f".length = {f(co['length'])}, .stiffness = {f(co['stiffness'])}, .eps = {f(co['eps'])}}},",
            "    .points = &girdle_points,",
            "};",
        ]
    lines.append("")
    lines += [
        "const ModelDef kModel = {",
        f"    .name = {cxx.cstr(model['name'])},",
        f"    .source_hash = {cxx.cstr(digest)},",
        f"    .num_dofs = {NDOF},",
        f"    .num_elements = {len(els)},",
        "    .dofs = kDofs,",
        "    .elements = kElements,",
        f"    .num_muscles = {len(model['muscles'])},",
        "    .muscles = kMuscles,",
        f"    .num_groups = {len(groups)},",
        f"    .groups = {groups_ptr},",
        f"    .base_body = {cxx.cstr(base)},",
        f"    .gravity_base = {_arr(g_base)},",
        f"    .base_rotation_in_thorax = {_arr([x for row in R for x in row])},",
        f"    .base_origin_in_thorax = {_arr(origin)},",
        f"    .num_bodies = {len(body_names)},",
        "    .body_names = kBodyNames,",
        f"    .scapula_body = {body_names.index('scapula') if 'scapula' in body_names else -1},",
        f"    .humerus_body = {humerus},",
        f"    .girdle = {'&kGirdle' if base == 'thorax' else 'nullptr'},",
        f"    .gh_centre = {_arr(gl['gh_centre'])},",
        f"    .glenoid_normal = {_arr(gl['normal'])},",
        f"    .glenoid_major_axis = {_arr(gl['major_axis'])},",
        f"    .glenoid_minor_axis = {_arr(gl['minor_axis'])},",
        f"    .rim_half_angle_major = {f(gl['rim_half_angle_major'])},",
        f"    .rim_half_angle_minor = {f(gl['rim_half_angle_minor'])},",
        f"    .arm_mass = {f(arm_mass)},",
        f"    .passive_stiffness_inside = {f(pj['stiffness_inside'])},",
        f"    .passive_stiffness_outside = {f(pj['stiffness_outside'])},",
        f"    .passive_damping = {f(pj['damping'])},",
        "    .mass_matrix = &mass_matrix,",
        "    .bias_force = &bias_force,",
        "    .dynamics = &dynamics,",
        "    .hand_position = &hand_position,",
        "    .hand_jacobian = &hand_jacobian,",
        "    .arm_momentum_rate = &arm_momentum_rate,",
        "    .body_poses = &body_poses,",
        "    .muscle_lengths = &muscle_lengths,",
        "    .muscle_paths = &muscle_paths,",
        "    .gh_directions = &gh_directions,",
        "};",
        "",
        "}  // namespace",
        "",
        "const armrt::ModelDef& model_def() { return kModel; }",
        "",
        f"}}  // namespace armrt::generated::{ns}",
        "",
    ]
    return "\n".join(lines)


def entry_source(ns: str) -> str:
    """The extern "C" entry point of a model built as a shared library on demand (armrt/model_build.py):
    the engine dlopens the library, checks the ModelDef layout version and registers the model
    (cpp/src/registry.cc). Not part of the engine's own build: built-in models are registered by name."""
    return f"""#include "{ns}.h"

extern "C" __attribute__((visibility("default"))) int armrt_model_abi_version() {{
  return armrt::kModelDefAbiVersion;
}}

extern "C" __attribute__((visibility("default"))) const armrt::ModelDef* armrt_model_def() {{
  return &armrt::generated::{ns}::model_def();
}}
"""


def generate(model_path, out_dir, verbose=False, command: str | None = None, entry_point=False) -> dict:
    """Write the generated sources for the model file into out_dir; returns {file name: bytes written}.
    command: the command line the banner names (default: the das2 one, models/NAME -> cpp/generated).
    entry_point: also write <name>_entry.cc, the entry point of a model library built on demand."""
    t0 = time.perf_counter()
    model, digest = load_model(model_path)
    ns = model["name"]
    banner = _banner(Path(model_path).name, digest, command)
    dyn, stats = dynamics_source(model, ns)
    files = {
        f"{ns}.h": banner + header_source(ns),
        f"{ns}_model.cc": banner + "\n" + model_source(model, ns, digest),
        f"{ns}_dynamics.cc": banner + "\n" + dyn,
        f"{ns}_paths.cc": banner + "\n" + paths_source(model, ns),
    }
    if entry_point:
        files[f"{ns}_entry.cc"] = banner + "\n" + entry_source(ns)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    written = {}
    for fname, text in files.items():
        data = text.encode("utf-8")
        path = out / fname
        # Leave an identical file untouched so that build systems do not recompile it.
        if not path.exists() or path.read_bytes() != data:
            path.write_bytes(data)
        written[fname] = len(data)
    if verbose:
        print(f"generated {', '.join(f'{k} ({v} bytes)' for k, v in written.items())} in {out} "
              f"in {time.perf_counter() - t0:.1f} s; CSE temporaries: {stats}")
    return written


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--model", required=True, help="model file, e.g. models/das2.json")
    ap.add_argument("--out", required=True, help="output directory, e.g. cpp/generated")
    ap.add_argument("--entry-point", action="store_true",
                    help="also write <name>_entry.cc, the extern \"C\" entry point of a model library "
                         "built on demand (armrt model build)")
    args = ap.parse_args(argv)
    try:
        # The banner names the standard command for the project's models (whatever paths were typed, so
        # regeneration stays byte-identical), and the command as typed for any other model file or an
        # on-demand build (--entry-point).
        root = Path(__file__).resolve().parents[1]
        in_models = Path(args.model).resolve().parent == root / "models"
        command = f"python -m codegen.generate --model {args.model} --out {args.out}"
        if in_models and not args.entry_point:
            # cpp/generated or cpp/tests/generated, named from the root whatever the working directory;
            # elsewhere (a scratch directory) the standard cpp/generated one.
            out = Path(args.out).resolve()
            command = (f"python -m codegen.generate --model models/{Path(args.model).name} --out {out.relative_to(root)}"
                       if out.is_relative_to(root) else None)
        elif args.entry_point:
            command += " --entry-point"
        generate(args.model, args.out, verbose=True, command=command, entry_point=args.entry_point)
    except ModelFileError as exc:
        print(f"codegen.generate: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
