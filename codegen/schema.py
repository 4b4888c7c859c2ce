"""Model file (docs/model_schema.md) -> validated model dict and the SHA-256 of its bytes, or a
ModelFileError naming the offending field: the schema, its limits (the engine's capacities) and the
physical-sense checks, everything the emitters may rely on.
"""
from __future__ import annotations

import hashlib
import json
import math
import re
from pathlib import Path

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
