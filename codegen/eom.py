"""Symbolic equations of motion of the arm chain (scapula fixed), by Kane's method.

The chain is scapula -[gh: y, z, y body-fixed rotations]-> humerus -[hu pin]-> ulna -[ur pin]-> radius
-[weld]-> hand (das2: 5 DOFs; each joint may also be a weld or a pin, so a model file can free any
subset of them, e.g. a one-DOF elbow pendulum; a weld may carry a fixed `rotation`, a DOF fixed at a
posture: the elbow-forearm models weld the humerus at fixed GH angles). Every revolute (the three GH rotations count as three revolutes through massless
intermediate frames at one point) contributes a partial angular velocity s_j (its axis, scapula
frame) and partial velocities s_j x (P - o_j) for points P distal to it. Kane's equations
F_r + F*_r = 0 then give

    M   = sum_b  Jv_b^T m_b Jv_b + Jw_b^T I_b Jw_b
    b   = sum_b  Jv_b^T m_b (g - a0_b) - Jw_b^T (I_b alpha0_b + w_b x I_b w_b)

with a0_b, alpha0_b the COM / angular accelerations at qdd = 0 (velocity-product terms), obtained
by a forward recursion. Only geometric Jacobians and that recursion are formed, never a symbolic
derivative, so the expressions stay small enough for sympy.cse on the whole set.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

def _vec(v):
    return sp.Matrix([sp.Float(float(x), 17) for x in v])


def _mat(m):
    return sp.Matrix([[sp.Float(float(x), 17) for x in row] for row in m])


def _axis_rotation(axis: sp.Matrix, angle: sp.Symbol) -> sp.Matrix:
    """Rodrigues rotation about a numeric unit axis (columns: child axes in parent coordinates)."""
    c, s = sp.cos(angle), sp.sin(angle)
    x, y, z = axis
    unit = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    if list(axis) in ([1, 0, 0], [0, 1, 0], [0, 0, 1]):
        # Exact elementary rotations keep the GH gimbal free of 0.0*sin(q) terms.
        k = [int(round(float(a))) for a in axis].index(1)
        i, j = (k + 1) % 3, (k + 2) % 3
        r = sp.Matrix(unit)
        r[i, i] = c
        r[j, j] = c
        r[i, j] = -s
        r[j, i] = s
        return r
    K = sp.Matrix([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    outer = axis * axis.T
    return c * sp.eye(3) + s * K + (1 - c) * outer


@dataclass
class Body:
    name: str
    mass: float
    com: list
    inertia: list


@dataclass
class ChainExprs:
    q: list
    qd: list
    g: list
    mass_matrix: sp.Matrix          # n x n (n = number of DOFs)
    bias_force: sp.Matrix           # n x 1
    hand_position: sp.Matrix        # 3x1
    hand_jv: sp.Matrix              # 3 x n
    hand_jw: sp.Matrix              # 3 x n
    momentum_a: sp.Matrix           # 3 x n
    momentum_c: sp.Matrix           # 3x1
    body_rotations: list            # 4 x (3x3)
    body_origins: list              # 4 x (3x1)


def _exact_axis(axis):
    """Exact integers for coordinate axes so that their rotations are elementary."""
    a = [float(x) for x in axis]
    if sorted(abs(x) for x in a) == [0.0, 0.0, 1.0] and max(a) == 1.0:
        return sp.Matrix([int(x) for x in a])
    return _vec(a)


def derive(model: dict) -> ChainExprs:
    """Kane's equations of the chain described by a validated model file dict."""
    NDOF = len(model["dofs"])
    q = list(sp.symbols(f"q0:{NDOF}", real=True))
    qd = list(sp.symbols(f"qd0:{NDOF}", real=True))
    g = sp.Matrix(sp.symbols("g0:3", real=True))
    dof_index = {d["name"]: i for i, d in enumerate(model["dofs"])}

    bodies = {b["name"]: b for b in model["bodies"]}
    order = ["humerus", "ulna", "radius", "hand"]

    # Forward kinematics in the scapula frame; joints are recorded as (dof, axis_world, point_world).
    R = {"scapula": sp.eye(3)}
    p = {"scapula": sp.zeros(3, 1)}
    w = {"scapula": sp.zeros(3, 1)}           # angular velocity
    alpha0 = {"scapula": sp.zeros(3, 1)}      # angular acceleration at qdd = 0
    a0 = {"scapula": sp.zeros(3, 1)}          # origin acceleration at qdd = 0
    joints_upto = {"scapula": []}
    for name in order:
        b = bodies[name]
        parent = b["parent"]
        jt = b["joint"]
        Rp, pp = R[parent], p[parent]
        r_loc = Rp * _vec(jt["location_in_parent"])
        origin = pp + r_loc
        wp = w[parent]
        # origin acceleration at qdd = 0: carried by the parent's rotation
        a_origin = a0[parent] + alpha0[parent].cross(r_loc) + wp.cross(wp.cross(r_loc))
        Rc = Rp
        if jt.get("rotation") is not None:
            # A joint fixed at a posture: its child frame is rotated, and nothing moves at it.
            Rc = Rc * _mat(jt["rotation"])
        wc, alc = wp, alpha0[parent]
        joints = list(joints_upto[parent])
        for axis, dof in zip(jt["axes"], jt["dofs"]):
            j = dof_index[dof]
            ax = _exact_axis(axis)
            s_world = Rc * ax
            alc = alc + wc.cross(s_world) * qd[j]
            wc = wc + s_world * qd[j]
            joints.append((j, s_world, origin))
            Rc = Rc * _axis_rotation(ax, q[j])
        R[name], p[name], w[name], alpha0[name], a0[name] = Rc, origin, wc, alc, a_origin
        joints_upto[name] = joints

    def jacobians(body, point_world):
        jv = sp.zeros(3, NDOF)
        jw = sp.zeros(3, NDOF)
        for j, s, o in joints_upto[body]:
            jw[:, j] = s
            jv[:, j] = s.cross(point_world - o)
        return jv, jw

    M = sp.zeros(NDOF, NDOF)
    bias = sp.zeros(NDOF, 1)
    mom_a = sp.zeros(3, NDOF)
    mom_c = sp.zeros(3, 1)
    for name in order:
        b = bodies[name]
        m = sp.Float(float(b["mass"]), 17)
        Rb = R[name]
        rc = Rb * _vec(b["com"])
        c = p[name] + rc
        jv, jw = jacobians(name, c)
        # Rotational terms in the body frame: I_world = Rb I Rb^T, so Jw^T I_world Jw = (Rb^T Jw)^T I (Rb^T Jw).
        Ib = _mat(b["inertia"])
        jw_body = Rb.T * jw
        wb_body = Rb.T * w[name]
        alb_body = Rb.T * alpha0[name]
        a_com = a0[name] + alpha0[name].cross(rc) + w[name].cross(w[name].cross(rc))
        M += m * (jv.T * jv) + jw_body.T * Ib * jw_body
        inertia_torque = Ib * alb_body + wb_body.cross(Ib * wb_body)
        bias += jv.T * (m * (g - a_com)) - jw_body.T * inertia_torque
        mom_a += m * jv
        mom_c += m * a_com

    hp = model["hand_point"]
    hb = hp["body"]
    hand_pos = p[hb] + R[hb] * _vec(hp["point"])
    hjv, hjw = jacobians(hb, hand_pos)

    # M is symmetric by construction; only the upper triangle is kept for code generation.
    for i in range(NDOF):
        for j in range(i):
            M[i, j] = M[j, i]
    return ChainExprs(q=q, qd=qd, g=list(g), mass_matrix=M, bias_force=bias, hand_position=hand_pos,
                      hand_jv=hjv, hand_jw=hjw, momentum_a=mom_a, momentum_c=mom_c,
                      body_rotations=[R[n] for n in order], body_origins=[p[n] for n in order])
