"""Validated model -> <name>_dynamics.cc: the equations of motion and kinematics (M(q), b(q, qd, g),
hand point and Jacobians, body poses, girdle points), by Kane's method in sympy for a scapula-based
model (codegen/eom.py) or unrolled recursive algorithms for a thorax-based one (codegen/eom_chain.py).
"""
from __future__ import annotations

from . import cxx, eom
from . import eom_chain as ec
from .signatures import SIGNATURES, check_emitted


def _chain_function(name: str, inputs, build):
    """eom_chain's unrolled function for name, with its signature from the table, checked against the
    arrays it reads (inputs) and writes (build's outputs)."""
    sig = SIGNATURES[name]

    def checked(s):
        outs = build(s)
        sig.check_arrays([a for a, *_ in inputs] + [a for a, _ in outs])
        return outs
    return ec._function(sig.declaration(), inputs, checked)


def chain_dynamics_source(model: dict, ns: str) -> tuple[str, dict]:
    """The equations of motion and kinematics of a thorax-based chain (das3) as unrolled recursive
    algorithms (codegen/eom_chain.py; docs/das3.md says why not Kane's method at 11 DOFs)."""
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
    for name, inputs, build in [
        ("mass_matrix", [q_in], lambda s: [("M", M_of(s))]),
        ("bias_force", [q_in, qd_in, g_in], lambda s: [("b", b_of({**s, "g": s["g_base"]}))]),
        ("dynamics", [q_in, qd_in, g_in], lambda s: [("M", M_of(s)), ("b", b_of({**s, "g": s["g_base"]}))]),
        ("hand_position", [q_in], lambda s: [("p", hand(s)[0])]),
        ("hand_jacobian", [q_in],
         lambda s: [("Jv", [x for row in hand(s)[1] for x in row]),
                    ("Jw", [x for row in ec.angular_jacobian(links, E_of(s), body_link[hp["body"]], n) for x in row])]),
        ("arm_momentum_rate", [q_in, qd_in], momentum),
        ("body_poses", [q_in], poses),
        ("girdle_points", [q_in], lambda s: ec._points_outputs(links, E_of(s), body_link, points, n)),
    ]:
        text, ops = _chain_function(name, inputs, build)
        stats[name] = ops
        fns.append(text)
    check_emitted("dynamics", list(stats), thorax=True)
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

    def fn(name, inputs, outputs):
        SIGNATURES[name].check_arrays([a for a, _ in inputs] + [a for a, _ in outputs])
        code, ntemps = cxx.emit_function(SIGNATURES[name].declaration(), inputs, outputs, trig_of=q)
        stats[name] = ntemps
        fns.append(code)

    M = ex.mass_matrix
    fn("mass_matrix", [("q", q)], [("M", [M[i, j] for i in range(NDOF) for j in range(NDOF)])])
    fn("bias_force", [("q", q), ("qd", qd), ("g_base", g)], [("b", list(ex.bias_force))])
    # M and b together share their sines, cosines and common subexpressions: the engine's hot path.
    fn("dynamics", [("q", q), ("qd", qd), ("g_base", g)],
       [("M", [M[i, j] for i in range(NDOF) for j in range(NDOF)]), ("b", list(ex.bias_force))])
    fn("hand_position", [("q", q)], [("p", list(ex.hand_position))])
    fn("hand_jacobian", [("q", q)], [("Jv", list(ex.hand_jv)), ("Jw", list(ex.hand_jw))])
    fn("arm_momentum_rate", [("q", q), ("qd", qd)], [("A", list(ex.momentum_a)), ("c", list(ex.momentum_c))])
    Rs = [x for R in ex.body_rotations for x in R]        # sympy Matrix iterates row-major
    ps = [x for p in ex.body_origins for x in p]
    fn("body_poses", [("q", q)], [("R", Rs), ("p", ps)])
    check_emitted("dynamics", list(stats))

    src = ("#include <cmath>\n\n#include \"armrt/fast_math.h\"\n#include \"" + ns + ".h\"\n\n"
           f"namespace armrt::generated::{ns} {{\n\n" + "\n".join(fns) + f"\n}}  // namespace armrt::generated::{ns}\n")
    return src, stats
