"""Arm geometry for drawing: joint centres and segment endpoints in the thorax frame, per pose.

Everything comes from the compiled model (no guessed dimensions):

* bones: the body origins from the engine's forward kinematics (`Simulator.body_poses`), i.e. the
  joint centres GH (humerus origin), elbow (ulna origin, the HU joint), proximal radius (radius
  origin, the UR joint) and wrist (hand origin, the RC weld); the hand segment runs from the wrist to
  the hand point (the hand's centre of mass, where the engine reports hand position);
* the distal ulna: the point of the pronation-supination axis level with the wrist (the PS axis
  passes through both radio-ulnar joints);
* the fixed girdle: the scapula origin (acromial angle, AA) and GH centre from `model_info`, the
  clavicle drawn from the thorax origin (IJ; the DAS3 SC joint is 1.5 cm from it) to AA; when the model
  file (`models/<name>.json`) is found, the scapula blade (AA, TS, AI landmarks) and the glenoid
  rim (an ellipse with the model's rim half-angles) are added;
* the thorax: IJ, the sagittal plane and a mirrored left clavicle/scapula (symmetry), drawn as a
  schematic; DAS2 has no thorax geometry beyond the thorax frame.

Thorax frame (docs/conventions.md): x lateral (right), y superior, z posterior, metres.
Muscle paths are not part of the model (only length and GH line-of-action polynomials), so muscles
are not drawn as paths; `gh_lines_of_action` gives the honest alternative: each GH-crossing
element's line of action at the GH joint.
"""
from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np

from . import _core

BONES = ("humerus", "ulna", "radius", "hand")
# Points returned by ArmGeometry.points, in this order.
POINTS = ("gh", "elbow", "ulna_distal", "radius_proximal", "wrist", "hand")
# Segments as (name, start point, end point).
SEGMENTS = (("humerus", "gh", "elbow"), ("ulna", "elbow", "ulna_distal"),
            ("radius", "radius_proximal", "wrist"), ("hand", "wrist", "hand"))


def find_model_file(model: str) -> Path | None:
    """The model file models/<model>.json: the file a model was loaded from (armrt.Model.load), in
    $ARMRT_MODEL_DIR, installed beside the package (armrt/models/), or in the source checkout
    (python/armrt/../../models); None if absent."""
    # A model name is a plain identifier: never a path (a result file's `model` field reaches here).
    if not isinstance(model, str) or not model.replace("_", "").isalnum() or not model.isascii():
        raise ValueError(f"model name must be letters, digits and '_', got {str(model)[:80]!r}")
    from .model import _LOADED
    if model in _LOADED:  # loaded from a file in this process (armrt.Model.load)
        return _LOADED[model][0]
    here = Path(__file__).resolve().parent
    dirs = [Path(os.environ["ARMRT_MODEL_DIR"])] if os.environ.get("ARMRT_MODEL_DIR") else []
    dirs += [here / "models", here.parents[1] / "models"]
    for d in dirs:
        if (d / f"{model}.json").exists():
            return d / f"{model}.json"
    return None


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
        self._sim = _core.Simulator(model, "euler", 1e-3)
        self.R_scapula = np.array(self.info["base_rotation_in_thorax"], dtype=float).reshape(3, 3)
        self.o_scapula = np.array(self.info["base_origin_in_thorax"], dtype=float)
        self.gh_centre_scapula = np.array(self.info["gh_centre"], dtype=float)
        self.rest = np.array([d["rest"] for d in self.info["dofs"]])
        self.dof_names = [d["name"] for d in self.info["dofs"]]
        self.osim_names = [d["osim_name"] for d in self.info["dofs"]]
        self._derive_body_points()
        path = Path(model_file) if model_file is not None else find_model_file(model)
        self.model_file = path
        self.model_json = json.loads(path.read_text()) if path is not None else None

    # -------------------------------------------------------------- derived once
    def _derive_body_points(self) -> None:
        q = self.rest.copy()
        R, p = self._sim.body_poses(q)
        # Hand point in the hand frame, from the engine's hand position at rest (thorax frame).
        self._sim.reset(q, None, None)
        self._sim.evaluate_outputs()
        h_thorax = np.asarray(self._sim.outputs()["hand_position"], dtype=float)
        h_scap = self.R_scapula.T @ (h_thorax - self.o_scapula)
        self.hand_point_in_hand = R[3].T @ (h_scap - p[3])
        # Pronation-supination axis in the ulna frame: the rotation axis of the radius relative to the
        # ulna between two values of the DOF that turns the radius (das2: PSy). A model whose radius
        # is welded to the ulna has none: the ulna's long axis (its origin to the wrist) stands in.
        q2 = q.copy()
        if "PSy" in self.dof_names:
            q2[self.dof_names.index("PSy")] += 0.5
        R2, p2 = self._sim.body_poses(q2)
        rel = R2[2] @ R[2].T                     # scapula frame rotation taking radius(q) to radius(q2)
        axis = np.array([rel[2, 1] - rel[1, 2], rel[0, 2] - rel[2, 0], rel[1, 0] - rel[0, 1]])
        if np.linalg.norm(axis) < 1e-12:
            axis = p[3] - p[1]
        axis /= np.linalg.norm(axis)
        axis_u = R[1].T @ axis
        r0_u = R[1].T @ (p[2] - p[1])            # radius origin (on the axis), ulna frame
        wrist_u = R[1].T @ (p[3] - p[1])
        self.ps_axis_in_ulna = axis_u
        self.ulna_distal_in_ulna = r0_u + axis_u * float(np.dot(wrist_u - r0_u, axis_u))

    # -------------------------------------------------------------- frames
    def to_thorax(self, x_scapula: np.ndarray) -> np.ndarray:
        """Scapula-frame points (..., 3) to the thorax frame."""
        return np.asarray(x_scapula) @ self.R_scapula.T + self.o_scapula

    def body_poses(self, q) -> tuple[np.ndarray, np.ndarray]:
        """(R (4, 3, 3), p (4, 3)) of humerus, ulna, radius, hand in the thorax frame."""
        R, p = self._sim.body_poses(np.asarray(q, dtype=float))
        return np.einsum("ij,bjk->bik", self.R_scapula, R), self.to_thorax(p)

    def points(self, q) -> np.ndarray:
        """(6, 3) thorax-frame points of pose q, in the order of POINTS."""
        R, p = self._sim.body_poses(np.asarray(q, dtype=float))
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
        q = np.atleast_2d(np.asarray(q, dtype=float))
        return np.stack([self.points(qk) for qk in q])

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
        centre along its line of action (the direction of its force on the arm), thorax frame.
        Not muscle paths: the model stores only their length and GH-direction polynomials."""
        d = np.asarray(self._sim.gh_directions(np.asarray(q, dtype=float)))
        idx = np.flatnonzero(np.linalg.norm(d, axis=1) > 0.5)
        gh = self.to_thorax(self.gh_centre_scapula)
        dirs = d[idx] @ self.R_scapula.T
        seg = np.stack([np.broadcast_to(gh, dirs.shape), gh + length * dirs], axis=1)
        return seg, idx

    # -------------------------------------------------------------- fixed parts
    def static(self) -> dict[str, np.ndarray]:
        """Fixed polylines (name -> (k, 3), thorax frame): clavicles, scapula, glenoid, midline."""
        aa = self.o_scapula.copy()
        gh = self.to_thorax(self.gh_centre_scapula)
        out: dict[str, np.ndarray] = {"clavicle_r": np.array([[0.0, 0.0, 0.0], aa])}
        scap = [aa, gh]
        m = self.model_json
        if m is not None and "glenoid" in m and "landmarks_dsem_cm" in m["glenoid"]:
            g = m["glenoid"]
            lm = {k: np.asarray(v, dtype=float) / 100.0 for k, v in g["landmarks_dsem_cm"].items()}
            # DSEM landmarks (cadaver posture) registered onto the model's girdle by the three points
            # known in both: GH centre, AA (scapula origin) and glenoid centre.
            glen = self.to_thorax(np.asarray(g["glenoid_centre"], dtype=float))
            R, t = _kabsch(np.array([lm["GH"], lm["AA"], lm["glenoid"]]), np.array([gh, aa, glen]))
            ts, ai = R @ lm["TS"] + t, R @ lm["AI"] + t
            scap = [aa, ts, ai, gh, aa]
            # Glenoid rim: ellipse seen from the GH centre at the rim half-angles.
            n = self.R_scapula @ np.asarray(self.info["glenoid_normal"])
            e1 = self.R_scapula @ np.asarray(self.info["glenoid_major_axis"])
            e2 = self.R_scapula @ np.asarray(self.info["glenoid_minor_axis"])
            dist = float(np.dot(glen - gh, n))
            a = dist * np.tan(self.info["rim_half_angle_major"])
            b = dist * np.tan(self.info["rim_half_angle_minor"])
            th = np.linspace(0, 2 * np.pi, 33)
            out["glenoid"] = gh + dist * n + np.outer(a * np.cos(th), e1) + np.outer(b * np.sin(th), e2)
        out["scapula_r"] = np.array(scap)
        mirror = np.array([-1.0, 1.0, 1.0])
        out["clavicle_l"] = out["clavicle_r"] * mirror
        out["scapula_l"] = out["scapula_r"] * mirror
        # Sagittal midline from IJ down to the level of the elbow at rest (schematic trunk).
        elbow_y = self.points(self.rest)[1, 1]
        out["midline"] = np.array([[0.0, 0.0, 0.0], [0.0, elbow_y, 0.0]])
        return out

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Axis-aligned box (lo, hi) containing the girdle and the arm at full reach."""
        reach = sum(self.segment_lengths()[s] for s in ("humerus", "radius", "hand")) + 0.05
        gh = self.to_thorax(self.gh_centre_scapula)
        lo = np.minimum(gh - reach, -0.25)
        hi = np.maximum(gh + reach, 0.25)
        return lo, hi
