"""Independent numerical reference for the arm dynamics: recursive Newton-Euler in numpy.

Built straight from the model file, separately from the symbolic derivation in codegen/eom.py
(which works in the scapula frame with Jacobians). Here every joint rotation is a link with its own
frame (the GH gimbal is three revolutes through massless links), quantities are propagated in link
coordinates, and gravity enters as an upward base acceleration.
"""
from __future__ import annotations

import numpy as np


def rotation(axis, angle):
    """Rotation by `angle` about unit `axis`: columns are the rotated axes in the original frame."""
    a = np.asarray(axis, dtype=float)
    a = a / np.linalg.norm(a)
    K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(angle) * K + (1.0 - np.cos(angle)) * (K @ K)


class Link:
    def __init__(self, parent, offset, axis, dof, mass, com, inertia, body):
        self.parent = parent      # index of the parent link, -1 for the scapula
        self.offset = np.asarray(offset, dtype=float)   # link origin in parent-link coordinates
        self.axis = None if axis is None else np.asarray(axis, dtype=float) / np.linalg.norm(axis)
        self.dof = dof            # generalised coordinate index, None for a weld
        self.mass = float(mass)
        self.com = np.asarray(com, dtype=float)
        self.inertia = np.asarray(inertia, dtype=float)
        self.body = body          # model body name for the link that carries it, else None


class ArmReference:
    def __init__(self, model: dict):
        dof_index = {d["name"]: i for i, d in enumerate(model["dofs"])}
        self.links: list[Link] = []
        last = {"scapula": -1}
        for b in model["bodies"]:
            jt = b["joint"]
            parent = last[b["parent"]]
            axes, dofs = jt["axes"], jt["dofs"]
            offset = jt["location_in_parent"]
            if not axes:
                self.links.append(Link(parent, offset, None, None, b["mass"], b["com"], b["inertia"], b["name"]))
            for k, (ax, d) in enumerate(zip(axes, dofs)):
                final = k == len(axes) - 1
                self.links.append(Link(parent, offset if k == 0 else np.zeros(3), ax, dof_index[d],
                                       b["mass"] if final else 0.0, b["com"] if final else np.zeros(3),
                                       b["inertia"] if final else np.zeros((3, 3)),
                                       b["name"] if final else None))
                parent = len(self.links) - 1
            last[b["name"]] = len(self.links) - 1
        self.body_link = {l.body: i for i, l in enumerate(self.links) if l.body}
        self.body_names = [b["name"] for b in model["bodies"]]
        self.hand_body = model["hand_point"]["body"]
        self.hand_point = np.asarray(model["hand_point"]["point"], dtype=float)
        self.ndof = len(model["dofs"])

    def _local_rotation(self, link, q):
        return np.eye(3) if link.axis is None else rotation(link.axis, q[link.dof])

    def kinematics(self, q):
        """Rotations (link -> scapula) and origins (scapula frame) of every link."""
        R, p = [], []
        for l in self.links:
            Rp = np.eye(3) if l.parent < 0 else R[l.parent]
            pp = np.zeros(3) if l.parent < 0 else p[l.parent]
            p.append(pp + Rp @ l.offset)
            R.append(Rp @ self._local_rotation(l, q))
        return R, p

    def body_poses(self, q):
        R, p = self.kinematics(q)
        return (np.array([R[self.body_link[n]] for n in self.body_names]),
                np.array([p[self.body_link[n]] for n in self.body_names]))

    def hand_position(self, q):
        R, p = self.kinematics(q)
        i = self.body_link[self.hand_body]
        return p[i] + R[i] @ self.hand_point

    def com_positions(self, q):
        R, p = self.kinematics(q)
        return {n: p[self.body_link[n]] + R[self.body_link[n]] @ self.links[self.body_link[n]].com
                for n in self.body_names}

    def masses(self):
        return {n: self.links[self.body_link[n]].mass for n in self.body_names}

    def inverse_dynamics(self, q, qd, qdd, g_scapula, return_accel=False):
        """Joint torques tau with M qdd + c(q, qd) - Q_gravity = tau."""
        q, qd, qdd = (np.asarray(x, dtype=float) for x in (q, qd, qdd))
        n = len(self.links)
        w = [None] * n
        wd = [None] * n
        vd = [None] * n
        E = [None] * n           # parent-link coordinates -> link coordinates
        F = [None] * n
        N = [None] * n
        acc_com = {}
        for i, l in enumerate(self.links):
            if l.parent < 0:
                wp, wdp, vdp = np.zeros(3), np.zeros(3), -np.asarray(g_scapula, dtype=float)
            else:
                wp, wdp, vdp = w[l.parent], wd[l.parent], vd[l.parent]
            E[i] = self._local_rotation(l, q).T
            vd[i] = E[i] @ (vdp + np.cross(wdp, l.offset) + np.cross(wp, np.cross(wp, l.offset)))
            w[i] = E[i] @ wp
            wd[i] = E[i] @ wdp
            if l.axis is not None:
                wd[i] = wd[i] + l.axis * qdd[l.dof] + np.cross(w[i], l.axis * qd[l.dof])
                w[i] = w[i] + l.axis * qd[l.dof]
            ac = vd[i] + np.cross(wd[i], l.com) + np.cross(w[i], np.cross(w[i], l.com))
            F[i] = l.mass * ac
            N[i] = l.inertia @ wd[i] + np.cross(w[i], l.inertia @ w[i])
            if l.body:
                acc_com[l.body] = ac
        f = [F[i].copy() for i in range(n)]
        nn = [N[i] + np.cross(self.links[i].com, F[i]) for i in range(n)]
        tau = np.zeros(self.ndof)
        for i in reversed(range(n)):
            l = self.links[i]
            if l.axis is not None:
                tau[l.dof] = l.axis @ nn[i]
            if l.parent >= 0:
                fp = E[i].T @ f[i]
                f[l.parent] += fp
                nn[l.parent] += E[i].T @ nn[i] + np.cross(l.offset, fp)
        if return_accel:
            R, _ = self.kinematics(q)
            return tau, {b: R[self.body_link[b]] @ a for b, a in acc_com.items()}
        return tau

    def mass_matrix(self, q):
        M = np.zeros((self.ndof, self.ndof))
        z = np.zeros(self.ndof)
        for j in range(self.ndof):
            e = np.zeros(self.ndof)
            e[j] = 1.0
            M[:, j] = self.inverse_dynamics(q, z, e, np.zeros(3))
        return M

    def bias_force(self, q, qd, g_scapula):
        return -self.inverse_dynamics(q, qd, np.zeros(self.ndof), g_scapula)

    def com_accelerations(self, q, qd, qdd):
        """COM accelerations of the bodies (scapula frame, no gravity)."""
        return self.inverse_dynamics(q, qd, qdd, np.zeros(3), return_accel=True)[1]
