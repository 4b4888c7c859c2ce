"""Girdle-and-arm range of motion of the 11-DOF `das3` model, for fitting and scoring its muscle paths.

Not a box over all 11 DOFs: the scapula does not move independently of the humerus, and most of an
11-D box is postures no shoulder takes (scapula lifted off or sunk into the thorax, the girdle at one end
of its range with the arm at the other). The region sampled is

* arm DOFs GHy, GHz, GHyy, ELx, PSy: the das2 range of motion (`codegen/importers/rom.py`, chosen around the DAS3
  resting posture inside the DAS3 ranges);
* girdle DOFs SCy .. ACx: a scapulohumeral rhythm path through the resting posture (equilibrium.mat
  x[0:6]) as a function of the gleno-humeral elevation GHz, plus scatter around it.

The rhythm path: the classic 2:1 ratio of humerothoracic to scapulothoracic motion (Inman 1944) means
RHYTHM = 0.5 rad of scapular upward rotation (rotation about the normal of the scapular plane, the
plane through AA = the scapula origin, TS and AI) per rad of gleno-humeral elevation. Along the path
the girdle angles change at the least rate (minimum-norm in rad) that gives that upward rotation while
keeping the scapulothoracic contact state of TS and AI unchanged (their ellipsoid functions f stay at
their resting values), integrated from the resting GHz in both directions (`girdle_path`). The scatter
(SCATTER_RAD per girdle DOF, normal) is projected onto the directions that leave f of TS and AI unchanged
to first order, so sampled scapulae stay on the thorax, and then clipped to the DAS3 ranges widened to
contain the path (the resting ACz and ACx lie outside their DAS3 ranges).

Why a kinematic rule: issue 15 asks for the region the scapula visits in the model's own simulated
motions, but the engine cannot simulate das3 until issue 13 lands. Replace `girdle_path` by simulated
trajectories then; the rest of the path pipeline takes any poses.
"""
from __future__ import annotations

import numpy as np

from .das3_chain import BASE, DAS3_DOFS, das3_bodies
from ..eom_chain import NumericChain
from .rom import ROM as ARM_ROM

ARM_DOFS = ["GHy", "GHz", "GHyy", "ELx", "PSy"]
GIRDLE_DOFS = DAS3_DOFS[:6]
RHYTHM = 0.5          # rad scapular upward rotation per rad gleno-humeral elevation (2:1 rhythm)
SCATTER_RAD = 0.05    # standard deviation of the girdle angles around the rhythm path (rad)
PATH_STEP = 0.01      # rad of GHz per integration step of the path


class GirdleGeometry:
    """Scapula orientation and TS/AI contact state as functions of the six girdle angles."""

    def __init__(self, das3_dir, struct):
        self.chain = NumericChain(DAS3_DOFS, das3_bodies(f"{das3_dir}/das3.osim"), BASE)
        self.ts = np.ravel(struct.TSprojection).astype(float)
        self.ai = np.ravel(struct.AIprojection).astype(float)
        self.centre = np.ravel(struct.thorax_center).astype(float)
        self.radii = np.ravel(struct.thorax_radii).astype(float)
        n = np.cross(self.ts, self.ai)                      # AA is the scapula origin
        self.normal = n / np.linalg.norm(n)

    def _q(self, girdle):
        q = np.zeros(len(DAS3_DOFS))
        q[:6] = girdle
        return q

    def scapula(self, girdle):
        return self.chain.body_pose(self._q(girdle), "scapula")

    def contact_f(self, girdle):
        R, p = self.scapula(girdle)
        return np.array([np.sum(((p + R @ x - self.centre) / self.radii) ** 2) - 1 for x in (self.ts, self.ai)])

    def jacobians(self, girdle, h=1e-6):
        """(upward-rotation rate row (6,), d f_TS,AI / d girdle (2, 6)); the sign makes AI move laterally."""
        R0, _ = self.scapula(girdle)
        up, df = np.zeros(6), np.zeros((2, 6))
        for j in range(6):
            e = np.zeros(6)
            e[j] = h
            Rp, _ = self.scapula(girdle + e)
            Rm, _ = self.scapula(girdle - e)
            W = R0.T @ (Rp - Rm) / (2 * h)                 # skew: angular velocity in scapula coordinates
            up[j] = self.normal @ np.array([W[2, 1], W[0, 2], W[1, 0]])
            df[:, j] = (self.contact_f(girdle + e) - self.contact_f(girdle - e)) / (2 * h)
        return up * self._upward_sign(girdle), df

    def _upward_sign(self, girdle):
        """+1 if rotating about +normal moves AI laterally (+x of the thorax, away from the spine)."""
        R, _ = self.scapula(girdle)
        return 1.0 if (R @ np.cross(self.normal, self.ai))[0] > 0 else -1.0


def girdle_rate(geo: GirdleGeometry, girdle):
    """Minimum-norm d girdle / d GHz giving RHYTHM upward rotation with f(TS), f(AI) unchanged."""
    up, df = geo.jacobians(girdle)
    A = np.vstack([up, df])
    return np.linalg.pinv(A) @ np.array([RHYTHM, 0.0, 0.0])


def girdle_path(geo: GirdleGeometry, rest_girdle, rest_ghz, ghz_grid):
    """Girdle angles along the rhythm path at each GHz of the increasing grid (midpoint-rule integration)."""
    out = {}
    for direction in (+1, -1):
        g, z = np.array(rest_girdle, float), float(rest_ghz)
        targets = sorted((v for v in ghz_grid if (v - rest_ghz) * direction >= 0), key=lambda v: abs(v - rest_ghz))
        for t in targets:
            while abs(t - z) > 1e-12:
                h = direction * min(PATH_STEP, abs(t - z))
                mid = g + 0.5 * h * girdle_rate(geo, g)
                g = g + h * girdle_rate(geo, mid)
                z += h
            out[t] = g.copy()
    return np.array([out[v] for v in ghz_grid])


class Das3Rom:
    """Sampler of the das3 girdle-and-arm region (see the module docstring); poses in DAS3_DOFS order."""

    def __init__(self, das3_dir, n_grid=64):
        import scipy.io as sio
        struct = sio.loadmat(f"{das3_dir}/model_struct.mat", squeeze_me=True, struct_as_record=False)["model"]
        x = np.ravel(sio.loadmat(f"{das3_dir}/equilibrium.mat", squeeze_me=True)["x"])[:11].astype(float)
        self.rest = x
        self.geo = GirdleGeometry(das3_dir, struct)
        self.das3_range = {str(d.name): tuple(float(v) for v in d.range) for d in np.atleast_1d(struct.dofs)}
        lo, hi = ARM_ROM["GHz"]
        self.ghz_grid = np.linspace(lo, hi, n_grid)
        self.path = girdle_path(self.geo, x[:6], x[7], self.ghz_grid)
        # girdle limits: the DAS3 ranges widened to hold the path
        self.girdle_range = {d: (min(self.das3_range[d][0], self.path[:, j].min()),
                                 max(self.das3_range[d][1], self.path[:, j].max()))
                             for j, d in enumerate(GIRDLE_DOFS)}

    def girdle_on_path(self, ghz):
        return np.array([np.interp(ghz, self.ghz_grid, self.path[:, j]) for j in range(6)]).T

    def sample(self, n, seed):
        """(n, 11) poses: Sobol over the arm box, girdle on the path plus projected scatter, clipped."""
        from scipy.stats import qmc
        rng = np.random.default_rng(seed)
        lo = np.array([ARM_ROM[d][0] for d in ARM_DOFS])
        hi = np.array([ARM_ROM[d][1] for d in ARM_DOFS])
        arm = lo + qmc.Sobol(d=5, scramble=True, seed=seed).random(n) * (hi - lo)   # n: a power of 2 for balance
        girdle = self.girdle_on_path(arm[:, 1])
        glo = np.array([self.girdle_range[d][0] for d in GIRDLE_DOFS])
        ghi = np.array([self.girdle_range[d][1] for d in GIRDLE_DOFS])
        for i in range(n):
            _, df = self.geo.jacobians(girdle[i])
            null = np.eye(6) - np.linalg.pinv(df) @ df       # keeps f(TS), f(AI) to first order
            girdle[i] = np.clip(girdle[i] + null @ rng.normal(0.0, SCATTER_RAD, 6), glo, ghi)
        return np.hstack([girdle, arm])

    def describe(self):
        """Plain-data summary for reports: ranges and the path at a few elevations."""
        rows = []
        for z in np.linspace(self.ghz_grid[0], self.ghz_grid[-1], 6):
            g = self.girdle_on_path(z)
            rows.append({"GHz": float(z), **{d: float(v) for d, v in zip(GIRDLE_DOFS, g)},
                         "f_TS_AI": self.geo.contact_f(g).tolist()})
        return {"arm_range": {d: list(ARM_ROM[d]) for d in ARM_DOFS},
                "girdle_range": {d: list(v) for d, v in self.girdle_range.items()},
                "das3_range": self.das3_range, "rhythm": RHYTHM, "scatter_rad": SCATTER_RAD, "path": rows}
