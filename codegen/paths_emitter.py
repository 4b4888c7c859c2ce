"""Validated model -> <name>_paths.cc: the muscle-path polynomials (lengths, moment arms -dL/dq and GH
lines of action) as straight-line vector C++.
"""
from __future__ import annotations

import re

from . import cxx
from .schema import MAX_ELEMENTS
from .signatures import SIGNATURES, check_emitted

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



def _define(name: str, arrays, body: str) -> str:
    """The definition of name with its signature from the table; arrays: the names body uses for them."""
    sig = SIGNATURES[name]
    sig.check_arrays(arrays)
    return sig.declaration() + " {\n" + body + "}\n"


def paths_source(model: dict, ns: str) -> str:
    dof_index = {d["name"]: i for i, d in enumerate(model["dofs"])}
    NDOF = len(dof_index)
    els = model["elements"]
    lengths = [_global_poly(e["length_poly"], e["length_poly"]["dofs"], dof_index) for e in els]

    out = []
    # muscle_lengths: the lengths of muscle_paths, bit for bit (one summation order for both).
    out.append(_define("muscle_lengths", ("q", "L"),
                       f"  double moment_arm[{NDOF} * kMaxElements];\n  muscle_paths(q, L, moment_arm);\n"))

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
    out.append(_define("muscle_paths", ("q", "L", "moment_arm"), "\n".join(head + lines + body) + "\n"))
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
    # The DOFs an element does not cross: each row's first n_el entries (model_def.h leaves the rest of a row
    # unspecified, as the one-vector form does). One memset per row, not one across the rows' padding: 12 % fewer
    # bytes on das3, and each piece is below glibc's rep-stosb threshold (2 kB).
    zero = (f"  for (int j = 0; j < {NDOF}; ++j)  // the DOFs an element does not cross\n"
            f"    std::memset(moment_arm + j * kMaxElements, 0, {n_el} * sizeof(double));")
    lines = _drop_unused_scalars(lines, body)
    return _define("muscle_paths", ("q", "L", "moment_arm"),
                   f"  // DOF groups (_grouped_paths) {names}.\n" + "\n".join([zero] + head + lines + body) + "\n")


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
    out.append(_define("gh_directions", ("q", "d"), "\n".join(mono.preamble() + body) + "\n"))
    check_emitted("paths", [re.match(r"void (\w+)\(", text).group(1) for text in out])

    return ("#include <cmath>\n#include <cstring>\n\n#include \"" + ns + ".h\"\n\n"
            f"namespace armrt::generated::{ns} {{\n\n"
            f"// muscle_paths writes its moment arms in rows of {MAX_ELEMENTS} (model_def.h): the engine must agree.\n"
            f"static_assert(kMaxElements == {MAX_ELEMENTS}, \"rebuild this model: the engine's kMaxElements changed\");\n\n"
            + ("// Eight doubles, one SIMD register with AVX-512 (two with AVX2): a length and its moment arms.\n"
               if NDOF <= 7 else "// Four doubles, one AVX2 register: one group's moment arms and a length lane.\n")
            + f"using {vt} = double __attribute__((vector_size({8 * W})));\n\n" + "\n".join(out) + f"\n}}  // namespace armrt::generated::{ns}\n")
