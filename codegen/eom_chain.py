"""Equations of motion of a serial chain of revolutes as unrolled recursive algorithms (any DOF count).

Used for the 11-DOF DAS3 chain (thorax fixed; SC 3, AC 3, GH 3, elbow, forearm). The symbolic route of
`codegen/eom.py` (Kane's method in sympy, then `sympy.cse`) does not scale to it: its expressions grow
with the product of the rotations above each body, so generation takes minutes instead of a fraction of
a second and the code has more than twice the multiplications and runs several times slower
(`python -m codegen.importers.das3_eom_timing --out DIR --symbolic --bench` measures both; docs/das3.md
has the numbers).
Here the recursive algorithms themselves provide the common subexpressions:

* bias forces by the recursive Newton-Euler algorithm (RNEA) with zero joint accelerations and gravity
  as an upward base acceleration: `b = -RNEA(q, qd, qdd=0)`, so that `M qdd = b + tau`, the same
  convention as `codegen/eom.py`;
* the mass matrix by the composite-rigid-body algorithm (CRBA).

Both run once at generation time on a tracer (`Sym`) instead of numbers: every arithmetic operation
becomes one `const double` line of C++, constants are folded (the elementary SC/AC/GH axes make most
rotation entries 0 or 1, the massless intermediate links vanish), and identical operations are emitted
once. The same functions run on floats, which gives a Python reference of the generated code.

Links: every rotation is a link with its own frame (a 3-rotation joint is three links through massless
frames at one point); a body's mass, centre of mass and inertia sit on the last link of its joint; a weld
(the hand) is a link without a DOF. Quantities are kept in link coordinates, where every joint axis is a
constant.

Chain description (the `bodies` list of docs/model_schema.md, generalised): each body has `name`,
`parent` (a body name or the fixed base), `mass` (kg), `com` (m), `inertia` (kg m^2 about the COM, body
frame) and `joint` with `location_in_parent` (m), `axes` (unit, body-fixed sequence) and `dofs`.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .cxx import fmt
from .signatures import SIGNATURES


# ----------------------------------------------------------------------------- tracer

class Tracer:
    """Collects straight-line C++; identical operations are emitted once, unused ones dropped at the end."""

    def __init__(self):
        self.ops: list[tuple[str, str, tuple]] = []   # (name, expression, operand names)
        self.memo: dict[str, Sym] = {}

    def emit(self, expr: str, operands=()) -> "Sym":
        s = self.memo.get(expr)
        if s is None:
            s = Sym(self, f"t{len(self.memo)}")
            self.ops.append((s.name, expr, tuple(o.name for o in operands if isinstance(o, Sym))))
            self.memo[expr] = s
        return s

    def live_lines(self, roots) -> list[str]:
        """Lines needed for the names in `roots`, in emission order."""
        live = set(roots)
        for name, _, deps in reversed(self.ops):
            if name in live:
                live.update(deps)
        return [f"  const double {n} = {e};" for n, e, _ in self.ops if n in live]


def _lit(x) -> str:
    return x.name if isinstance(x, Sym) else f"({fmt(x)})"


class Sym:
    """A named double in the generated code; arithmetic with floats folds 0, 1 and -1."""

    __slots__ = ("tr", "name")

    def __init__(self, tr: Tracer, name: str):
        self.tr, self.name = tr, name

    def _bin(self, op, other, commutative):
        a, b = _lit(self), _lit(other)
        if commutative and b < a:
            a, b = b, a
        return self.tr.emit(f"{a} {op} {b}", (self, other))

    def __add__(self, o):
        if not isinstance(o, Sym) and o == 0.0:
            return self
        return self._bin("+", o, True)

    __radd__ = __add__

    def __sub__(self, o):
        if not isinstance(o, Sym) and o == 0.0:
            return self
        return self._bin("-", o, False)

    def __rsub__(self, o):
        if o == 0.0:
            return -self
        return self.tr.emit(f"{_lit(o)} - {self.name}", (self,))

    def __mul__(self, o):
        if not isinstance(o, Sym):
            if o == 0.0:
                return 0.0
            if o == 1.0:
                return self
            if o == -1.0:
                return -self
        return self._bin("*", o, True)

    __rmul__ = __mul__

    def __neg__(self):
        return self.tr.emit(f"-{self.name}", (self,))


# ----------------------------------------------------------------------------- 3-vector algebra on lists

def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def vadd(a, b):
    return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]


def vscale(s, a):
    return [s * a[0], s * a[1], s * a[2]]


def mv(M, v):
    return [M[i][0] * v[0] + M[i][1] * v[1] + M[i][2] * v[2] for i in range(3)]


def mtv(M, v):
    return [M[0][i] * v[0] + M[1][i] * v[1] + M[2][i] * v[2] for i in range(3)]


def mm(A, B):
    return [[A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j] for j in range(3)] for i in range(3)]


def mmt(A, B):
    return [[A[i][0] * B[j][0] + A[i][1] * B[j][1] + A[i][2] * B[j][2] for j in range(3)] for i in range(3)]


def madd(A, B):
    return [[A[i][j] + B[i][j] for j in range(3)] for i in range(3)]


def skew(v):
    return [[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]]


def rotation(axis, s, c):
    """Rotation about a constant unit axis from sin and cos of the angle (columns: child axes in parent).

    Coordinate axes give the elementary rotation in s and c directly; others Rodrigues' formula."""
    if sorted(abs(v) for v in axis) == [0.0, 0.0, 1.0]:
        k = [abs(v) for v in axis].index(1.0)
        sk = s if axis[k] > 0 else -s
        i, j = (k + 1) % 3, (k + 2) % 3
        R = [[1.0 if a == b else 0.0 for b in range(3)] for a in range(3)]
        R[i][i], R[j][j], R[i][j], R[j][i] = c, c, -sk, sk
        return R
    x, y, z = axis
    K = skew(axis)
    KK = [[x * x - 1.0, x * y, x * z], [x * y, y * y - 1.0, y * z], [x * z, y * z, z * z - 1.0]]
    one_c = 1.0 - c
    return [[(1.0 if i == j else 0.0) + s * K[i][j] + one_c * KK[i][j] for j in range(3)] for i in range(3)]


def _exact_axis(axis):
    """Coordinate axes as exact 0/1 so that their rotations fold to elementary ones."""
    a = [float(v) for v in axis]
    n = math.sqrt(sum(v * v for v in a))
    a = [v / n for v in a]
    for k in range(3):
        if abs(abs(a[k]) - 1.0) < 1e-15:
            return [(math.copysign(1.0, a[k]) if i == k else 0.0) for i in range(3)]
    return a


# ----------------------------------------------------------------------------- chain

@dataclass
class Link:
    parent: int                 # parent link index, -1 for the fixed base
    offset: list                # link origin in parent-link coordinates (m)
    axis: list | None           # unit axis (own = parent coordinates), None for a weld
    dof: int | None
    mass: float = 0.0
    com: tuple = (0.0, 0.0, 0.0)
    inertia: tuple = ((0.0,) * 3,) * 3   # about the COM
    body: str | None = None


def links_of(dof_names: list[str], bodies: list[dict], base: str) -> list[Link]:
    """One link per rotation, bodies in order (each body's parent listed before it)."""
    index = {d: i for i, d in enumerate(dof_names)}
    last = {base: -1}
    links: list[Link] = []
    for b in bodies:
        if b["parent"] not in last:
            raise ValueError(f"body '{b['name']}': parent '{b['parent']}' not listed before it")
        parent = last[b["parent"]]
        jt = b["joint"]
        offset = [float(v) for v in jt["location_in_parent"]]
        mass_props = dict(mass=float(b["mass"]), com=tuple(float(v) for v in b["com"]),
                          inertia=tuple(tuple(float(v) for v in row) for row in b["inertia"]), body=b["name"])
        if not jt["axes"]:
            links.append(Link(parent, offset, None, None, **mass_props))
        for k, (ax, d) in enumerate(zip(jt["axes"], jt["dofs"])):
            final = k == len(jt["axes"]) - 1
            links.append(Link(parent, offset if k == 0 else [0.0, 0.0, 0.0], _exact_axis(ax), index[d],
                              **(mass_props if final else {})))
            parent = len(links) - 1
        last[b["name"]] = len(links) - 1
    return links


def _rotations(links, q_sin, q_cos):
    eye = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    return [eye if l.axis is None else rotation(l.axis, q_sin[l.dof], q_cos[l.dof]) for l in links]


def forward_pass(links, E, qd, base_acc):
    """The outward recursion of RNEA at qdd = 0: per link its angular velocity w, angular acceleration wd,
    origin acceleration a (link coordinates, the base accelerating at base_acc) and, for links with mass,
    the acceleration of the centre of mass (link coordinates; None for massless links)."""
    n = len(links)
    w, wd, a, acom = [None] * n, [None] * n, [None] * n, [None] * n
    zero = [0.0, 0.0, 0.0]
    for i, l in enumerate(links):
        wp, wdp, ap = (zero, zero, base_acc) if l.parent < 0 else (w[l.parent], wd[l.parent], a[l.parent])
        r = l.offset
        a[i] = mtv(E[i], vadd(ap, vadd(cross(wdp, r), cross(wp, cross(wp, r)))))
        w0 = mtv(E[i], wp)
        wd0 = mtv(E[i], wdp)
        if l.axis is None:
            w[i], wd[i] = w0, wd0
        else:
            sq = vscale(qd[l.dof], l.axis)
            w[i] = vadd(w0, sq)
            wd[i] = vadd(wd0, cross(w0, sq))
        if l.mass != 0.0:
            c = list(l.com)
            acom[i] = vadd(a[i], vadd(cross(wd[i], c), cross(w[i], cross(w[i], c))))
    return w, wd, a, acom


def rnea(links, E, qd, g):
    """Joint torques for qdd = 0 under gravity g (base coordinates): tau = C(q, qd) qd - gravity torques."""
    n = len(links)
    w, wd, _, acom = forward_pass(links, E, qd, [-g[0], -g[1], -g[2]])
    f, nm = [None] * n, [None] * n
    zero = [0.0, 0.0, 0.0]
    for i, l in enumerate(links):
        if l.mass != 0.0:
            c, I = list(l.com), [list(row) for row in l.inertia]
            f[i] = vscale(l.mass, acom[i])
            nm[i] = vadd(vadd(mv(I, wd[i]), cross(w[i], mv(I, w[i]))), cross(c, f[i]))
        else:
            f[i], nm[i] = zero, zero
    tau = [0.0] * (max([l.dof for l in links if l.dof is not None], default=-1) + 1)
    for i in reversed(range(n)):
        l = links[i]
        if l.dof is not None:
            tau[l.dof] = dot(l.axis, nm[i])
        if l.parent >= 0:
            fp = mv(E[i], f[i])
            np_ = vadd(mv(E[i], nm[i]), cross(l.offset, fp))
            f[l.parent] = vadd(f[l.parent], fp)
            nm[l.parent] = vadd(nm[l.parent], np_)
    return tau


def crba(links, E, ndof):
    """Joint-space mass matrix (ndof x ndof, nested lists) by composite rigid bodies."""
    n = len(links)
    m = [l.mass for l in links]
    h = [[l.mass * x for x in l.com] for l in links]
    J = []
    for l in links:
        c = l.com
        cc = c[0] * c[0] + c[1] * c[1] + c[2] * c[2]
        J.append([[l.inertia[i][j] + l.mass * ((cc if i == j else 0.0) - c[i] * c[j]) for j in range(3)]
                  for i in range(3)])
    for i in reversed(range(n)):
        l = links[i]
        p = l.parent
        if p < 0:
            continue
        r = l.offset
        Eh = mv(E[i], h[i])
        Jp = mmt(mm(E[i], J[i]), E[i])
        rr, rE = skew(r), skew(Eh)
        shift = madd(madd(vscale_m(m[i], mm(rr, rr)), mm(rr, rE)), mm(rE, rr))
        J[p] = madd(J[p], madd(Jp, vscale_m(-1.0, shift)))
        h[p] = vadd(h[p], vadd(vscale(m[i], r), Eh))
        m[p] = m[p] + m[i]
    M = [[0.0] * ndof for _ in range(ndof)]
    for i, l in enumerate(links):
        if l.dof is None:
            continue
        nvec = mv(J[i], l.axis)
        fvec = cross(l.axis, h[i])
        M[l.dof][l.dof] = dot(l.axis, nvec)
        j = i
        while links[j].parent >= 0:
            lj = links[j]
            fvec = mv(E[j], fvec)
            nvec = vadd(mv(E[j], nvec), cross(lj.offset, fvec))
            j = lj.parent
            if links[j].dof is not None:
                M[l.dof][links[j].dof] = M[links[j].dof][l.dof] = dot(links[j].axis, nvec)
    return M


def vscale_m(s, A):
    return [[s * A[i][j] for j in range(3)] for i in range(3)]


def body_poses(links, E):
    """(R, p) of every link in base coordinates."""
    R, p = [], []
    for i, l in enumerate(links):
        if l.parent < 0:
            Rp, pp = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], [0.0, 0.0, 0.0]
        else:
            Rp, pp = R[l.parent], p[l.parent]
        p.append(vadd(pp, mv(Rp, l.offset)))
        R.append(mm(Rp, E[i]))
    return R, p


def point_and_jacobian(links, E, link, point, ndof):
    """Position (base coordinates) of a point fixed in `link` (link coordinates) and dp/dq (3 x ndof):
    column j is axis_j x (p - origin_j) for every revolute above the point, zero otherwise."""
    R, o = body_poses(links, E)
    p = vadd(o[link], mv(R[link], list(point)))
    J = [[0.0] * ndof for _ in range(3)]
    j = link
    while j >= 0:
        lj = links[j]
        if lj.dof is not None:
            col = cross(mv(R[j], lj.axis), [p[0] - o[j][0], p[1] - o[j][1], p[2] - o[j][2]])
            for i in range(3):
                J[i][lj.dof] = col[i]
        j = lj.parent
    return p, J


def angular_jacobian(links, E, link, ndof):
    """d(omega)/d(qd) (3 x ndof, base coordinates) of `link`: column j is the axis of every revolute above it."""
    R, _ = body_poses(links, E)
    J = [[0.0] * ndof for _ in range(3)]
    j = link
    while j >= 0:
        lj = links[j]
        if lj.dof is not None:
            col = mv(R[j], lj.axis)
            for i in range(3):
                J[i][lj.dof] = col[i]
        j = lj.parent
    return J


def velocity_product_accelerations(links, E, qd):
    """Acceleration of every massive link's centre of mass (base coordinates; None for massless links) at
    qdd = 0 without gravity: the velocity-product part (Jdot qd) of each COM acceleration, by RNEA's
    forward pass."""
    R, _ = body_poses(links, E)
    acom = forward_pass(links, E, qd, [0.0, 0.0, 0.0])[3]
    return [None if ac is None else mv(R[i], ac) for i, ac in enumerate(acom)]


def momentum_rate(links, E, qd, link_set, ndof):
    """sum over the links in `link_set` of m a_com = A qdd + c (base coordinates): (A (3 x ndof), c (3))."""
    A = [[0.0] * ndof for _ in range(3)]
    c = [0.0, 0.0, 0.0]
    acc = velocity_product_accelerations(links, E, qd)
    for i in sorted(link_set):
        l = links[i]
        if l.mass == 0.0:
            continue
        _, J = point_and_jacobian(links, E, i, list(l.com), ndof)
        for r in range(3):
            c[r] = c[r] + l.mass * acc[i][r]
            for j in range(ndof):
                A[r][j] = A[r][j] + l.mass * J[r][j]
    return A, c


def links_below(links, body_link, body):
    """Indices of the links of `body` and of every body distal to it (its joint's massless links included)."""
    first = body_link[body]
    while links[first].parent >= 0 and links[links[first].parent].body is None:
        first = links[first].parent
    below = {first}
    for i in range(first + 1, len(links)):
        if links[i].parent in below:
            below.add(i)
    return below


# ----------------------------------------------------------------------------- numeric reference

class NumericChain:
    """The same algorithms on floats: M(q), b(q, qd, g), body poses; numpy arrays in and out."""

    def __init__(self, dof_names, bodies, base):
        self.links = links_of(dof_names, bodies, base)
        self.ndof = len(dof_names)
        self.body_link = {l.body: i for i, l in enumerate(self.links) if l.body}

    def _E(self, q):
        return _rotations(self.links, [math.sin(v) for v in q], [math.cos(v) for v in q])

    def mass_matrix(self, q):
        return np.array(crba(self.links, self._E(q), self.ndof))

    def bias_force(self, q, qd, g):
        return -np.array(rnea(self.links, self._E(q), [float(v) for v in qd], [float(v) for v in g]))

    def point(self, q, body, point):
        """(p (3,), dp/dq (3, ndof)) of a point fixed in `body` (body coordinates), in base coordinates."""
        p, J = point_and_jacobian(self.links, self._E(q), self.body_link[body], point, self.ndof)
        return np.array(p), np.array(J)

    def body_pose(self, q, body):
        R, p = body_poses(self.links, self._E(q))
        k = self.body_link[body]
        return np.array(R[k]), np.array(p[k])


# ----------------------------------------------------------------------------- C++ emission

def _function(signature, inputs, build):
    """C++ function text and its operation count; `build(syms)` returns [(array, [values])].

    inputs: (array name, length, trig): element k is read as array[k]; trig also provides sin/cos."""
    tr = Tracer()
    syms, head = {}, []
    for arr, n, trig in inputs:
        syms[arr] = [Sym(tr, f"{arr}[{k}]") for k in range(n)]
        if trig:
            syms["sin"] = [Sym(tr, f"s{k}") for k in range(n)]
            syms["cos"] = [Sym(tr, f"c{k}") for k in range(n)]
    outs = build(syms)
    roots = {v.name for _, vals in outs for v in vals if isinstance(v, Sym)}
    lines = tr.live_lines(roots)
    used = " ".join(lines) + " " + " ".join(roots)
    tokens = set(re.findall(r"[A-Za-z_]\w*", used))
    for arr, n, trig in inputs:
        if trig:
            for k in range(n):
                if f"s{k}" in tokens or f"c{k}" in tokens:
                    head.append(f"  double s{k}, c{k};")
                    head.append(f"  armrt::sin_cos({arr}[{k}], &s{k}, &c{k});")
        if not any(f"{arr}[" in h for h in head) and f"{arr}[" not in used:
            head.append(f"  (void){arr};")
    body = [f"  {arr}[{k}] = {_lit(v)};" for arr, vals in outs for k, v in enumerate(vals)]
    text = "\n".join([signature + " {"] + head + lines + body + ["}"]) + "\n"
    return text, len(lines)


def generate_source(dof_names, bodies, base, ns, body_names=None, points=()):
    """C++ (header, source, stats) for mass_matrix, bias_force, dynamics, body_poses and, if `points` lists
    (label, body, [x, y, z] in body coordinates), points(q, p, J): their positions in base coordinates
    (npoints x 3) and Jacobians dp/dq (npoints x 3 x ndof, row-major), for forces acting at them."""
    links = links_of(dof_names, bodies, base)
    n = len(dof_names)
    body_names = body_names or [b["name"] for b in bodies]
    body_link = {l.body: i for i, l in enumerate(links) if l.body}
    stats = {}

    def M_of(s):
        return crba(links, _rotations(links, s["sin"], s["cos"]), n)

    def b_of(s):
        tau = rnea(links, _rotations(links, s["sin"], s["cos"]), s["qd"], s["g_base"])
        return [-t for t in tau]

    def flatM(M):
        return [M[i][j] for i in range(n) for j in range(n)]

    def poses(s):
        R, p = body_poses(links, _rotations(links, s["sin"], s["cos"]))
        return [("R", [x for b in body_names for row in R[body_link[b]] for x in row]),
                ("p", [x for b in body_names for x in p[body_link[b]]])]

    q_in, qd_in, g_in = ("q", n, True), ("qd", n, False), ("g_base", 3, False)
    fns = []
    # (name defined, signature in codegen/signatures.py, inputs, outputs): `points` has girdle_points' type.
    for name, sig, inputs, build in [
        ("mass_matrix", "mass_matrix", [q_in], lambda s: [("M", flatM(M_of(s)))]),
        ("bias_force", "bias_force", [q_in, qd_in, g_in], lambda s: [("b", b_of(s))]),
        ("dynamics", "dynamics", [q_in, qd_in, g_in], lambda s: [("M", flatM(M_of(s))), ("b", b_of(s))]),
        ("body_poses", "body_poses", [q_in], poses),
    ] + ([("points", "girdle_points", [q_in],
           lambda s: _points_outputs(links, _rotations(links, s["sin"], s["cos"]), body_link, points, n))]
         if points else []):
        text, ops = _function(SIGNATURES[sig].declaration(name), inputs, build)
        stats[name] = ops
        fns.append(text)
    header = (f"#pragma once\n\n// Generated by codegen/eom_chain.py; do not edit.\n"
              f"namespace armrt::generated::{ns} {{\n\n"
              f"constexpr int kNumDofs = {n};\n"
              f"constexpr int kNumPoseBodies = {len(body_names)};  // {' '.join(body_names)}\n"
              "// M (n x n, row-major) and b (n) with M qdd = b + tau; g is gravity in base coordinates (m/s^2).\n"
              + "".join(SIGNATURES[f].declaration() + ";\n" for f in ("mass_matrix", "bias_force", "dynamics")) +
              "// Rotation (3x3 row-major, columns are body axes) and origin of each body in base coordinates.\n"
              + SIGNATURES["body_poses"].declaration() + ";\n"
              + (f"// Points fixed in bodies: {', '.join(f'{k} ({label}, {b})' for k, (label, b, _) in enumerate(points))}.\n"
                 f"constexpr int kNumPoints = {len(points)};\n"
                 "// Their positions p (kNumPoints x 3, base coordinates, m) and dp/dq (kNumPoints x 3 x kNumDofs).\n"
                 + SIGNATURES["girdle_points"].declaration("points") + ";\n" if points else "")
              + f"\n}}  // namespace armrt::generated::{ns}\n")
    source = (f"// Generated by codegen/eom_chain.py (unrolled CRBA and RNEA); do not edit.\n"
              f"#include \"armrt/fast_math.h\"\n#include \"{ns}_dynamics.h\"\n\n"
              f"namespace armrt::generated::{ns} {{\n\n" + "\n".join(fns) + f"\n}}  // namespace armrt::generated::{ns}\n")
    return header, source, stats


def _points_outputs(links, E, body_link, points, n):
    ps, Js = [], []
    for _, body, point in points:
        p, J = point_and_jacobian(links, E, body_link[body], [float(v) for v in point], n)
        ps += p
        Js += [x for row in J for x in row]
    return [("p", ps), ("J", Js)]


# ----------------------------------------------------------------------------- symbolic baseline (timing only)

def symbolic_dynamics(dof_names, bodies, base):
    """M (n x n) and b (n) as sympy expressions by Kane's method, as codegen/eom.py does for 5 DOFs.

    For the comparison of generation time and run cost only (`--symbolic`); returns (q, qd, g, M, b)."""
    import sympy as sp
    n = len(dof_names)
    q = list(sp.symbols(f"q0:{n}", real=True))
    qd = list(sp.symbols(f"qd0:{n}", real=True))
    g = sp.Matrix(sp.symbols("g0:3", real=True))
    index = {d: i for i, d in enumerate(dof_names)}

    def num(v):
        return sp.Matrix([sp.Float(float(x), 17) for x in v])

    def rot(axis, ang):
        c, s_ = sp.cos(ang), sp.sin(ang)
        K = sp.Matrix([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
        return sp.eye(3) + s_ * K + (1 - c) * K * K

    z = sp.zeros(3, 1)
    R, p, w, al0, a0, joints = {base: sp.eye(3)}, {base: z}, {base: z}, {base: z}, {base: z}, {base: []}
    M, bias = sp.zeros(n, n), sp.zeros(n, 1)
    for b in bodies:
        jt, par = b["joint"], b["parent"]
        r = R[par] * num(jt["location_in_parent"])
        origin = p[par] + r
        a_origin = a0[par] + al0[par].cross(r) + w[par].cross(w[par].cross(r))
        Rc, wc, alc, js = R[par], w[par], al0[par], list(joints[par])
        for ax, d in zip(jt["axes"], jt["dofs"]):
            j = index[d]
            a = sp.Matrix([sp.Integer(int(v)) if v in (0.0, 1.0, -1.0) else sp.Float(v, 17) for v in _exact_axis(ax)])
            sw = Rc * a
            alc = alc + wc.cross(sw) * qd[j]
            wc = wc + sw * qd[j]
            js.append((j, sw, origin))
            Rc = Rc * rot(a, q[j])
        R[b["name"]], p[b["name"]], w[b["name"]], al0[b["name"]], a0[b["name"]] = Rc, origin, wc, alc, a_origin
        joints[b["name"]] = js
        if b["mass"] == 0.0:
            continue
        m = sp.Float(float(b["mass"]), 17)
        rc = Rc * num(b["com"])
        c = origin + rc
        jv, jw = sp.zeros(3, n), sp.zeros(3, n)
        for j, sj, o in js:
            jw[:, j] = sj
            jv[:, j] = sj.cross(c - o)
        I = sp.Matrix([[sp.Float(float(v), 17) for v in row] for row in b["inertia"]])
        jwb, wb, alb = Rc.T * jw, Rc.T * wc, Rc.T * alc
        a_com = a_origin + alc.cross(rc) + wc.cross(wc.cross(rc))
        M += m * (jv.T * jv) + jwb.T * I * jwb
        bias += jv.T * (m * (g - a_com)) - jwb.T * (I * alb + wb.cross(I * wb))
    return q, qd, list(g), M, bias


def symbolic_source(dof_names, bodies, base):
    """C++ `dynamics(q, qd, g, M, b)` by the symbolic route (codegen/cxx.py, sympy.cse); (text, temporaries)."""
    from . import cxx
    q, qd, g, M, b = symbolic_dynamics(dof_names, bodies, base)
    n = len(q)
    for i in range(n):
        for j in range(i):
            M[i, j] = M[j, i]
    return cxx.emit_function(SIGNATURES["dynamics"].declaration(), [("q", q), ("qd", qd), ("g_base", g)],
                             [("M", [M[i, j] for i in range(n) for j in range(n)]), ("b", list(b))], trig_of=q)


def bench(out, variants, calls=200000):
    """ns per call of each variant's `dynamics`, compiled with g++ -O2 -march=native (as the engine)."""
    import subprocess
    include = Path(__file__).resolve().parents[1] / "cpp" / "include"
    results = []
    for label, src_name, ns in variants:
        main_cc = out / "bench_main.cc"
        main_cc.write_text(
            "#include <chrono>\n#include <cstdio>\n"
            f"namespace {ns} {{ {SIGNATURES['dynamics'].declaration()}; }}\n"
            "int main() {\n  double q[11], qd[11], g[3] = {0, -9.80665, 0}, M[121], b[11], acc = 0;\n"
            "  for (int i = 0; i < 11; ++i) { q[i] = 0.1 * i; qd[i] = 0.2; }\n"
            "  auto t0 = std::chrono::steady_clock::now();\n"
            f"  for (int k = 0; k < {calls}; ++k) {{ q[k % 11] += 1e-7; {ns}::dynamics(q, qd, g, M, b); acc += M[0] + b[0]; }}\n"
            "  auto t1 = std::chrono::steady_clock::now();\n"
            f"  std::printf(\"%.3f %g\\n\", std::chrono::duration<double, std::nano>(t1 - t0).count() / {calls}, acc);\n}}\n")
        exe = out / "bench_main"
        subprocess.run(["g++", "-O2", "-march=native", "-std=c++17", f"-I{include}", f"-I{out}", str(main_cc),
                        str(out / src_name), "-o", str(exe)], check=True)
        best = min(float(subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout.split()[0])
                   for _ in range(5))
        results.append((label, best))
    return results


def _distal_subchain(bodies, dofs, k):
    """The distal bodies carrying the last k DOFs, based at the parent of the first of them."""
    keep = dofs[len(dofs) - k:]
    sub, base = [], None
    for b in bodies:
        jd = b["joint"]["dofs"]
        if any(d in keep for d in jd) or (not jd and sub):
            if base is None:
                if not all(d in keep for d in jd):
                    raise ValueError(f"k={k} splits the joint of {b['name']}")
                base = b["parent"]
            sub.append(b)
    return keep, sub, base

