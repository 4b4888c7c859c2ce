"""Arm geometry for drawing: joint centres and segment endpoints in the thorax frame, per pose.

Everything comes from the compiled model (no guessed dimensions):

* bones: the body origins from the engine's forward kinematics (`armrt._core.Arm.body_poses`), i.e. the
  joint centres GH (humerus origin), elbow (ulna origin, the HU joint), proximal radius (radius
  origin, the UR joint) and wrist (hand origin, the RC weld); the hand segment runs from the wrist to
  the hand point (the hand's centre of mass, where the engine reports hand position);
* the distal ulna: the point of the pronation-supination axis level with the wrist (the PS axis
  passes through both radio-ulnar joints);
* the girdle: the scapula origin (acromial angle, AA) and GH centre from `model_info`; when the model
  file (`models/<name>.json`) is found, the scapula blade (AA, TS, AI landmarks) and the glenoid
  rim (an ellipse with the model's rim half-angles) are added. A scapula-based model (das2) has it
  fixed (`static()`), the clavicle drawn from the thorax origin (IJ; the DAS3 SC joint is 1.5 cm from
  it) to AA. A thorax-based model (das3) moves it with q (`girdle(q)`): the clavicle from its body
  origin (the SC joint) to the scapula's (the AC joint, at AA), the scapula and glenoid carried by the
  scapula's body pose, and the scapulothoracic contact points (TS, AI of `girdle_forces`);
* the thorax: IJ, the sagittal plane and a mirrored left clavicle/scapula (symmetry, at the rest
  posture), drawn as a schematic; a model with a thorax ellipsoid (das3's contact surface) adds its
  three principal sections (in the front and side views the first two are its outline).

Thorax frame (docs/conventions.md): x lateral (right), y superior, z posterior, metres.
Muscle paths are not part of the model (only length and GH line-of-action polynomials), so muscles
are not drawn as paths; `gh_lines_of_action` gives the honest alternative: each GH-crossing
element's line of action at the GH joint.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from . import _core
from .checks import joint_range, joint_range_rows, real_array
from .model_files import find_model_file  # noqa: F401 (armrt.geometry.find_model_file)

BONES = ("humerus", "ulna", "radius", "hand")
# Moving girdle polylines of a thorax-based model (ArmGeometry.girdle), in drawing order.
GIRDLE_PARTS = ("clavicle_r", "scapula_r", "glenoid", "contact_points")
# Points returned by ArmGeometry.points, in this order.
POINTS = ("gh", "elbow", "ulna_distal", "radius_proximal", "wrist", "hand")
# Segments as (name, start point, end point).
SEGMENTS = (("humerus", "gh", "elbow"), ("ulna", "elbow", "ulna_distal"),
            ("radius", "radius_proximal", "wrist"), ("hand", "wrist", "hand"))


def _kabsch(a: np.ndarray, b: np.ndarray):
    """R, t minimising |R a_i + t - b_i|."""
    ca, cb = a.mean(0), b.mean(0)
    u, _, vt = np.linalg.svd((a - ca).T @ (b - cb))
    d = np.sign(np.linalg.det(vt.T @ u.T))
    R = vt.T @ np.diag([1.0, 1.0, d]) @ u.T
    return R, cb - R @ ca


class ArmGeometry:
    """Geometry of one model: `points(q)` (thorax frame) for any pose, `static()` for the girdle."""

    def __init__(self, model: str = "das2", model_file: str | Path | None = None):
        self.model = model
        self.info = _core.model_info(model)
        self._sim = _core.Arm(model, "euler", 1e-3)
        # The engine's base frame (das2: the fixed scapula; das3: the thorax) in the thorax frame.
        self.R_base = np.array(self.info["base_rotation_in_thorax"], dtype=float).reshape(3, 3)
        self.o_base = np.array(self.info["base_origin_in_thorax"], dtype=float)
        self.body_names = list(self.info["body_names"])
        missing = [b for b in BONES if b not in self.body_names]
        if missing:
            raise ValueError(f"model {model!r} has no bodies {missing} (bodies: {self.body_names}); the "
                             f"drawing needs {', '.join(BONES)}")
        self._bone_ix = [self.body_names.index(b) for b in BONES]
        self.scapula_body = int(self.info["scapula_body"])          # -1: the scapula is the base
        self.clavicle_body = self.body_names.index("clavicle") if "clavicle" in self.body_names else -1
        self.moving_girdle = self.scapula_body >= 0
        self.gh_centre_scapula = np.array(self.info["gh_centre"], dtype=float)
        self.rest = np.array([d["rest"] for d in self.info["dofs"]])
        self.dof_names = [d["name"] for d in self.info["dofs"]]
        self.osim_names = [d["osim_name"] for d in self.info["dofs"]]
        self.dof_ranges = np.array([d["range"] for d in self.info["dofs"]], dtype=float)
        # The fixed scapula's pose (das2), or the rest posture's (das3: the mirrored left side).
        self.R_scapula, self.o_scapula = self.scapula_pose(self.rest)
        self._derive_body_points()
        path = Path(model_file) if model_file is not None else find_model_file(model)
        self.model_file = path
        self.model_json = json.loads(path.read_text()) if path is not None else None
        self._derive_scapula_points()

    # -------------------------------------------------------------- poses given
    def _pose(self, q) -> np.ndarray:
        """q (ndof,) rad as the engine takes it; ValueError more than checks.STATE_MARGIN (the engine's
        domain, 0.35 rad) beyond the joint ranges, with the degrees hint (degrees given as radians would draw the arm folded through itself). No warning closer
        in: a recorded run may be slightly beyond its range."""
        a = real_array(q, "q")
        if a.shape != (len(self.dof_names),) or not np.all(np.isfinite(a)):
            raise ValueError(f"q must be {len(self.dof_names)} finite joint angles ({', '.join(self.dof_names)}), "
                             f"got shape {a.shape}")
        return joint_range(a, self.dof_names, self.dof_ranges, warn=False)

    def _poses(self, q) -> np.ndarray:
        """A (T, ndof) series of q, every row checked as _pose checks one (errors name the row)."""
        a = np.atleast_2d(real_array(q, "q"))
        if a.ndim != 2 or a.shape[1] != len(self.dof_names) or not np.all(np.isfinite(a)):
            raise ValueError(f"q must be (T, {len(self.dof_names)}) finite joint angles, got shape {a.shape}")
        return joint_range_rows(a, self.dof_names, self.dof_ranges, lambda r: f"q row {r}", warn=False)

    # -------------------------------------------------------------- derived once
    def _arm_poses(self, q) -> tuple[np.ndarray, np.ndarray]:
        """(R (4, 3, 3), p (4, 3)) of humerus, ulna, radius, hand in the base frame."""
        R, p = self._sim.body_poses(np.asarray(q, dtype=float))
        return R[self._bone_ix], p[self._bone_ix]

    def _derive_body_points(self) -> None:
        q = self.rest.copy()
        R, p = self._arm_poses(q)
        # Hand point in the hand frame, from the engine's hand position at rest (thorax frame).
        self._sim.reset(q, None, None)
        self._sim.evaluate_outputs()
        h_thorax = np.asarray(self._sim.outputs()["hand_position"], dtype=float)
        h_base = self.R_base.T @ (h_thorax - self.o_base)
        self.hand_point_in_hand = R[3].T @ (h_base - p[3])
        # Pronation-supination axis in the ulna frame: the rotation axis of the radius relative to the
        # ulna between two values of the DOF that turns the radius (das2: PSy). A model whose radius
        # is welded to the ulna has none: the ulna's long axis (its origin to the wrist) stands in.
        q2 = q.copy()
        if "PSy" in self.dof_names:
            q2[self.dof_names.index("PSy")] += 0.5
        R2, p2 = self._arm_poses(q2)
        rel = R2[2] @ R[2].T                     # base frame rotation taking radius(q) to radius(q2)
        axis = np.array([rel[2, 1] - rel[1, 2], rel[0, 2] - rel[2, 0], rel[1, 0] - rel[0, 1]])
        if np.linalg.norm(axis) < 1e-12:
            axis = p[3] - p[1]
        axis /= np.linalg.norm(axis)
        axis_u = R[1].T @ axis
        r0_u = R[1].T @ (p[2] - p[1])            # radius origin (on the axis), ulna frame
        wrist_u = R[1].T @ (p[3] - p[1])
        self.ps_axis_in_ulna = axis_u
        self.ulna_distal_in_ulna = r0_u + axis_u * float(np.dot(wrist_u - r0_u, axis_u))

    def _derive_scapula_points(self) -> None:
        """Scapula-frame points drawn with the scapula: the DSEM landmarks TS and AI in the model's scapula
        frame (the model file's glenoid.landmarks_scapula_m; older files: registered by GH centre, AA =
        scapula origin and glenoid centre), and the contact points."""
        self.scapula_landmarks: dict[str, np.ndarray] = {}
        self.contact_points_scapula: dict[str, np.ndarray] = {}
        m = self.model_json
        if m is None:
            return
        g = m.get("glenoid", {})
        if "landmarks_scapula_m" in g:
            self.scapula_landmarks = {k: np.asarray(g["landmarks_scapula_m"][k], dtype=float) for k in ("TS", "AI")}
        elif "landmarks_dsem_cm" in g and "glenoid_centre" in g:
            lm = {k: np.asarray(v, dtype=float) / 100.0 for k, v in g["landmarks_dsem_cm"].items()}
            R, t = _kabsch(np.array([lm["GH"], lm["AA"], lm["glenoid"]]),
                           np.array([self.gh_centre_scapula, np.zeros(3), np.asarray(g["glenoid_centre"], dtype=float)]))
            self.scapula_landmarks = {"TS": R @ lm["TS"] + t, "AI": R @ lm["AI"] + t}
        for c in m.get("girdle_forces", {}).get("contact", {}).get("points", []):
            if c.get("body") == "scapula":
                self.contact_points_scapula[c["name"]] = np.asarray(c["point"], dtype=float)

    # -------------------------------------------------------------- frames
    def to_thorax(self, x_base: np.ndarray) -> np.ndarray:
        """Base-frame points (..., 3) (das2: the scapula frame; das3: the thorax frame) to the thorax frame."""
        return np.asarray(x_base) @ self.R_base.T + self.o_base

    def scapula_pose(self, q) -> tuple[np.ndarray, np.ndarray]:
        """(R (3, 3), o (3,)): the scapula frame in the thorax frame at pose q (fixed for das2)."""
        q = self._pose(q)
        if self.scapula_body < 0:
            return self.R_base.copy(), self.o_base.copy()
        R, p = self._sim.body_poses(q)
        return self.R_base @ R[self.scapula_body], self.to_thorax(p[self.scapula_body])

    def scapula_to_thorax(self, x_scapula: np.ndarray, q=None) -> np.ndarray:
        """Scapula-frame points (..., 3) to the thorax frame, at pose q (default: rest; das2: fixed)."""
        R, o = self.scapula_pose(self.rest if q is None else q)
        return np.asarray(x_scapula) @ R.T + o

    def body_poses(self, q) -> tuple[np.ndarray, np.ndarray]:
        """(R (4, 3, 3), p (4, 3)) of humerus, ulna, radius, hand in the thorax frame."""
        R, p = self._arm_poses(self._pose(q))
        return np.einsum("ij,bjk->bik", self.R_base, R), self.to_thorax(p)

    def points(self, q) -> np.ndarray:
        """(6, 3) thorax-frame points of pose q, in the order of POINTS."""
        return self._points(self._pose(q))

    def _points(self, q: np.ndarray) -> np.ndarray:
        R, p = self._arm_poses(q)
        pts = np.empty((6, 3))
        pts[0] = p[0]
        pts[1] = p[1]
        pts[2] = p[1] + R[1] @ self.ulna_distal_in_ulna
        pts[3] = p[2]
        pts[4] = p[3]
        pts[5] = p[3] + R[3] @ self.hand_point_in_hand
        return self.to_thorax(pts)

    def points_series(self, q: np.ndarray) -> np.ndarray:
        """(T, 6, 3) points for a (T, n_dofs) series of poses."""
        return np.stack([self._points(qk) for qk in self._poses(q)])

    @staticmethod
    def segments(points: np.ndarray) -> np.ndarray:
        """(4, 2, 3) segment endpoints (humerus, ulna, radius, hand) from points(q)."""
        ix = {n: i for i, n in enumerate(POINTS)}
        return np.stack([[points[ix[a]], points[ix[b]]] for _, a, b in SEGMENTS])

    def segment_lengths(self) -> dict[str, float]:
        seg = self.segments(self.points(self.rest))
        return {name: float(np.linalg.norm(s[1] - s[0])) for (name, _, _), s in zip(SEGMENTS, seg)}

    # -------------------------------------------------------------- muscles
    def gh_lines_of_action(self, q, length: float = 0.06) -> tuple[np.ndarray, np.ndarray]:
        """(segments (k, 2, 3), element indices (k,)): for each GH-crossing element, a line from the GH
        centre along its line of action (the direction of its force on the arm), thorax frame; the
        directions are in the scapula frame, which moves with q in a thorax-based model.
        Not muscle paths: the model stores only their length and GH-direction polynomials."""
        q = self._pose(q)
        d = np.asarray(self._sim.gh_directions(q))
        idx = np.flatnonzero(np.linalg.norm(d, axis=1) > 0.5)
        R, o = self.scapula_pose(q)
        gh = self.gh_centre_scapula @ R.T + o
        dirs = d[idx] @ R.T
        seg = np.stack([np.broadcast_to(gh, dirs.shape), gh + length * dirs], axis=1)
        return seg, idx

    # -------------------------------------------------------------- the girdle
    def _scapula_polylines(self, R: np.ndarray, o: np.ndarray) -> dict[str, np.ndarray]:
        """Scapula blade (AA, TS, AI, GH, AA, or AA-GH without the landmarks) and glenoid rim, thorax
        frame, for the scapula at (R, o)."""
        def th(x):
            return np.asarray(x) @ R.T + o
        aa, gh = o.copy(), th(self.gh_centre_scapula)
        out: dict[str, np.ndarray] = {}
        m = self.model_json
        if self.scapula_landmarks:
            out["scapula_r"] = np.array([aa, th(self.scapula_landmarks["TS"]), th(self.scapula_landmarks["AI"]), gh, aa])
            # Glenoid rim: ellipse seen from the GH centre at the rim half-angles.
            glen = th(np.asarray(m["glenoid"]["glenoid_centre"], dtype=float))
            n = R @ np.asarray(self.info["glenoid_normal"])
            e1 = R @ np.asarray(self.info["glenoid_major_axis"])
            e2 = R @ np.asarray(self.info["glenoid_minor_axis"])
            dist = float(np.dot(glen - gh, n))
            a = dist * np.tan(self.info["rim_half_angle_major"])
            b = dist * np.tan(self.info["rim_half_angle_minor"])
            th_ = np.linspace(0, 2 * np.pi, 33)
            out["glenoid"] = gh + dist * n + np.outer(a * np.cos(th_), e1) + np.outer(b * np.sin(th_), e2)
        else:
            out["scapula_r"] = np.array([aa, gh])
        return out

    def girdle(self, q) -> dict[str, np.ndarray]:
        """Moving girdle polylines (name -> (k, 3), thorax frame) at pose q, GIRDLE_PARTS order:
        clavicle_r (SC joint to AC joint), scapula_r, glenoid (with the model file), contact_points
        (TS, AI of the scapulothoracic contact, when the model has them). Empty for a model whose
        scapula is fixed (das2: static() holds it)."""
        q = self._pose(q)
        return self._girdle(q) if self.moving_girdle else {}

    def _girdle(self, q: np.ndarray) -> dict[str, np.ndarray]:
        R, p = self._sim.body_poses(q)
        Rs, os_ = self.R_base @ R[self.scapula_body], self.to_thorax(p[self.scapula_body])
        sc = self.to_thorax(p[self.clavicle_body]) if self.clavicle_body >= 0 else self.o_base
        out = {"clavicle_r": np.array([sc, os_])}
        out.update(self._scapula_polylines(Rs, os_))
        if self.contact_points_scapula:
            out["contact_points"] = np.array(list(self.contact_points_scapula.values())) @ Rs.T + os_
        return {k: out[k] for k in GIRDLE_PARTS if k in out}

    def girdle_series(self, q: np.ndarray) -> dict[str, np.ndarray]:
        """{part: (T, k, 3)} girdle(q) for a (T, n_dofs) series of poses (empty for a fixed girdle)."""
        q = self._poses(q)
        if not self.moving_girdle:
            return {}
        frames = [self._girdle(qk) for qk in q]
        return {k: np.stack([f[k] for f in frames]) for k in (frames[0] if frames else {})}

    def thorax_ellipsoid(self, n: int = 49) -> dict[str, np.ndarray]:
        """The scapulothoracic contact surface's three principal sections (thorax frame), or {} for a
        model without one. Sections through the centre normal to z, x, y: in the front (x-y) and side
        (z-y) views the first two are the ellipsoid's outline."""
        gf = (self.info.get("girdle") or {})
        if "thorax_centre" not in gf:
            return {}
        c, r = np.asarray(gf["thorax_centre"], dtype=float), np.asarray(gf["thorax_radii"], dtype=float)
        t = np.linspace(0, 2 * np.pi, n)
        cos, sin, zero = np.cos(t), np.sin(t), np.zeros(n)
        return {"thorax_frontal": c + np.column_stack([r[0] * cos, r[1] * sin, zero]),
                "thorax_sagittal": c + np.column_stack([zero, r[1] * sin, r[2] * cos]),
                "thorax_transverse": c + np.column_stack([r[0] * cos, zero, r[2] * sin])}

    # -------------------------------------------------------------- fixed parts
    def static(self) -> dict[str, np.ndarray]:
        """Fixed polylines (name -> (k, 3), thorax frame): the midline and the left clavicle/scapula
        (mirrored); the right clavicle, scapula and glenoid when the scapula is fixed (das2; a moving
        girdle is girdle(q), mirrored here at rest); the thorax ellipsoid's sections when the model
        has one (das3)."""
        R, o = self.R_scapula, self.o_scapula
        right = self.girdle(self.rest) if self.moving_girdle else {}
        out: dict[str, np.ndarray] = {}
        if not self.moving_girdle:
            out["clavicle_r"] = np.array([[0.0, 0.0, 0.0], o])
            out.update(self._scapula_polylines(R, o))
            right = out
        mirror = np.array([-1.0, 1.0, 1.0])
        out["clavicle_l"] = right["clavicle_r"] * mirror
        out["scapula_l"] = right["scapula_r"] * mirror
        out.update(self.thorax_ellipsoid())
        # Sagittal midline from IJ down to the level of the elbow at rest (schematic trunk).
        elbow_y = self.points(self.rest)[1, 1]
        out["midline"] = np.array([[0.0, 0.0, 0.0], [0.0, elbow_y, 0.0]])
        return out

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Axis-aligned box (lo, hi) containing the girdle and the arm at full reach."""
        reach = sum(self.segment_lengths()[s] for s in ("humerus", "radius", "hand")) + 0.05
        gh = self.scapula_to_thorax(self.gh_centre_scapula)
        lo = np.minimum(gh - reach, -0.25)
        hi = np.maximum(gh + reach, 0.25)
        return lo, hi
