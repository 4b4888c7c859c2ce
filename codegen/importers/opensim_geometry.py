"""Sample muscle-path geometry of the fixed-scapula DAS3 model from OpenSim.

OpenSim (das3.osim) is the geometry oracle for the polynomial path model. The shoulder girdle
coordinates (SC_y .. AC_x) are held at the fixed posture and only the five arm coordinates
GH_y, GH_z, GH_yy, EL_x, PS_y are moved. Per pose and per muscle element this module records

* ``length``: muscle-tendon length (``Muscle.getLength`` after ``realizePosition``);
* ``ma``: moment arm about each of the five DOFs (``GeometryPath.computeMomentArm``), NaN for DOFs
  the element does not cross;
* ``ma_fd``: the moment arm by central difference of OpenSim's own path length,
  ``-(L(q + h e_j) - L(q - h e_j)) / 2h`` with ``h = FD_STEP``;
* ``direction``: for elements crossing GH, the unit direction, in the ``scapula_r`` body frame, of
  the force the muscle exerts ON THE ARM at the GH joint.

Line of action. ``GeometryPath.getCurrentPath`` lists the active path points in order, including
the ``PathWrapPoint``s (tangent points) whose frame is the body that carries the wrap surface.
Every point is classified by the body it is fixed to: scapula side (thorax/ground, clavicle*,
scapula*) or arm side (humerus and everything distal). The first segment whose two ends lie on
opposite sides is the segment that spans the GH joint; the force on the arm acts along it, from the
arm-side end toward the scapula-side end. The deltoid and rotator-cuff wrap surfaces (``deltoid``,
``inf_sup_sub``, ``infra_cyl``, ``ter_min_cyl``, ``ter_lat_pec``) are on ``humerus_r``, so a tangent
point on them is an arm-side point and the spanning segment runs from the tangent point to the
origin on the scapula/clavicle/thorax: the line of action then follows the wrapped path, as it
should. Path order does not matter (triceps longus runs ulna -> scapula).

Wrap-engagement jumps. Where a path starts or stops touching a wrap surface, or a wrap flips side,
OpenSim's length has kinks or steps and ``computeMomentArm`` disagrees with the derivative of the
length. A pose is marked invalid for an element when, for some DOF it crosses,
``|ma - ma_fd| > max(JUMP_ABS, JUMP_REL * peak)`` with ``peak`` the element's largest
``|ma|`` over the sample (robust 99.5th percentile so that the jumps do not set it themselves).
Such poses are excluded from fitting and scoring, and counted.

Sampling runs in "spawn" worker processes (each loads its own model; OpenSim objects cannot be
pickled); the workers only import this module, and a process that is itself a multiprocessing child
samples serially, so importing a caller from a worker cannot respawn pools. The result is cached in an ``.npz`` whose name is a hash of every input that changes it.
"""
from __future__ import annotations

import hashlib
import json
import multiprocessing as mp
import os
from pathlib import Path

import numpy as np

DOF_NAMES = ["GHy", "GHz", "GHyy", "ELx", "PSy"]
OSIM_DOF = {"GHy": "GH_y", "GHz": "GH_z", "GHyy": "GH_yy", "ELx": "EL_x", "PSy": "PS_y"}

# Bodies on the proximal side of each joint; everything else is distal of it.
SCAPULA_SIDE = ("ground", "thorax", "clavicle_1", "clavicle_2", "clavicle_r",
                "scapula_1", "scapula_2", "scapula_r")
HUMERUS_SIDE = SCAPULA_SIDE + ("humerus_1", "humerus_2", "humerus_r")
ULNA_SIDE = HUMERUS_SIDE + ("ulna_r",)
JOINT_PROXIMAL = {"GH": SCAPULA_SIDE, "HU": HUMERUS_SIDE, "RU": ULNA_SIDE}
JOINT_DOFS = {"GH": ["GHy", "GHz", "GHyy"], "HU": ["ELx"], "RU": ["PSy"]}

FD_STEP = 1e-4        # rad; paths are smooth at this scale except at wrap switches
JUMP_ABS = 2e-3       # m; OpenSim moment arms of wrapped paths differ smoothly from dL/dq by up to ~2 mm
JUMP_REL = 0.10       # of the element's peak moment arm
SAMPLE_VERSION = 1    # bump when what is sampled changes, to invalidate caches


def _path_bodies(model, osim_name):
    path = model.getMuscles().get(osim_name).getGeometryPath()
    pps = path.getPathPointSet()
    bodies = {pps.get(i).getParentFrame().getName() for i in range(pps.getSize())}
    ws = path.getWrapSet()
    for i in range(ws.getSize()):
        bodies.add(ws.get(i).getWrapObject().getFrame().getName())
    return bodies


def crossed_joints(bodies):
    """Joints (GH, HU, RU) whose proximal and distal sides both hold points of the path."""
    out = []
    for joint, prox in JOINT_PROXIMAL.items():
        if any(b in prox for b in bodies) and any(b not in prox for b in bodies):
            out.append(joint)
    return out


def element_topology(osim_path, elements):
    """Crossed DOFs of every element from the bodies its path points and wrap surfaces sit on."""
    import opensim as osim
    osim.Logger.setLevelString("error")
    model = osim.Model(osim_path)
    model.initSystem()
    out = []
    for el in elements:
        bodies = _path_bodies(model, el["osim_name"])
        joints = crossed_joints(bodies)
        dofs = [d for j in joints for d in JOINT_DOFS[j]]
        out.append({"name": el["name"], "bodies": sorted(bodies), "joints": joints, "dofs": dofs,
                    "crosses_gh": "GH" in joints})
    return out


class _Sampler:
    """One OpenSim model with the girdle fixed; evaluates the quantities above at a pose."""

    def __init__(self, osim_path, girdle, osim_names, cross_mask, gh_mask):
        import opensim as osim
        osim.Logger.setLevelString("error")
        self.model = osim.Model(osim_path)
        cs = self.model.getCoordinateSet()
        for name, angle in girdle.items():
            cs.get(name).setDefaultValue(float(angle))
            cs.get(name).setDefaultLocked(True)
        self.state = self.model.initSystem()
        self.coords = [cs.get(OSIM_DOF[d]) for d in DOF_NAMES]
        muscles = self.model.getMuscles()
        self.muscles = [muscles.get(n) for n in osim_names]
        self.paths = [m.getGeometryPath() for m in self.muscles]
        self.cross = np.asarray(cross_mask, bool)
        self.gh = np.asarray(gh_mask, bool)
        self.model.realizePosition(self.state)
        scap = self.model.getBodySet().get("scapula_r")
        R = scap.getTransformInGround(self.state).R()
        self.R_scap = np.array([[R.get(i, j) for j in range(3)] for i in range(3)])

    def _set(self, q):
        for c, v in zip(self.coords, q):
            c.setValue(self.state, float(v), False)
        self.model.realizePosition(self.state)

    def _lengths(self):
        return np.array([m.getLength(self.state) for m in self.muscles])

    def _direction(self, k):
        path = self.paths[k].getCurrentPath(self.state)
        pts = []
        for i in range(path.getSize()):
            p = path.get(i)
            g = p.getLocationInGround(self.state)
            pts.append((p.getParentFrame().getName() in SCAPULA_SIDE,
                        np.array([g.get(0), g.get(1), g.get(2)])))
        for (side_a, pa), (side_b, pb) in zip(pts[:-1], pts[1:]):
            if side_a != side_b:
                arm, scap = (pb, pa) if side_a else (pa, pb)
                d = self.R_scap.T @ (scap - arm)
                return d / np.linalg.norm(d)
        return np.full(3, np.nan)

    def sample(self, q):
        n_el = len(self.muscles)
        self._set(q)
        length = self._lengths()
        ma = np.full((n_el, 5), np.nan)
        for j, c in enumerate(self.coords):
            for k in np.flatnonzero(self.cross[:, j]):
                ma[k, j] = self.paths[k].computeMomentArm(self.state, c)
        direction = np.full((n_el, 3), np.nan)
        for k in np.flatnonzero(self.gh):
            direction[k] = self._direction(k)
        ma_fd = np.full((n_el, 5), np.nan)
        for j in range(5):
            cols = self.cross[:, j]
            if not cols.any():
                continue
            qp = np.array(q, float); qp[j] += FD_STEP
            qm = np.array(q, float); qm[j] -= FD_STEP
            self._set(qp); lp = self._lengths()
            self._set(qm); lm = self._lengths()
            ma_fd[cols, j] = -(lp[cols] - lm[cols]) / (2 * FD_STEP)
        return length, ma, ma_fd, direction


_worker = None


def _init_worker(args):
    global _worker
    _worker = _Sampler(*args)


def _run_chunk(qs):
    out = [_worker.sample(q) for q in qs]
    return [np.array([o[i] for o in out]) for i in range(4)]


def sobol_poses(rom, n, seed, with_corners=True):
    """Scrambled Sobol points over the ROM box (DOF_NAMES order), plus the 32 box corners."""
    from scipy.stats import qmc
    lo = np.array([rom[d][0] for d in DOF_NAMES])
    hi = np.array([rom[d][1] for d in DOF_NAMES])
    u = qmc.Sobol(d=5, scramble=True, seed=seed).random(n)
    if with_corners:
        corners = np.array(np.meshgrid(*[[0.0, 1.0]] * 5, indexing="ij")).reshape(5, -1).T
        u = np.vstack([corners, u])
    return lo + u * (hi - lo)


def sample_poses(osim_path, girdle, elements, poses, processes=2):
    """Evaluate OpenSim at the given poses (n x 5, DOF_NAMES order). Returns a dict of arrays."""
    topo = element_topology(osim_path, elements)
    cross = np.array([[d in t["dofs"] for d in DOF_NAMES] for t in topo])
    gh = np.array([t["crosses_gh"] for t in topo])
    args = (osim_path, dict(girdle), [e["osim_name"] for e in elements], cross, gh)
    poses = np.asarray(poses, float)
    n_chunks = max(1, min(len(poses), 8 * processes))
    chunks = np.array_split(poses, n_chunks)
    # Never start a pool from inside a worker (a spawned child that re-imports a caller's module
    # must not spawn again): sample serially there.
    if mp.parent_process() is not None:
        processes = 1
    if processes > 1:
        with mp.get_context("spawn").Pool(processes, _init_worker, (args,)) as pool:
            parts = pool.map(_run_chunk, chunks)
    else:
        _init_worker(args)
        parts = [_run_chunk(c) for c in chunks]
    length, ma, ma_fd, direction = [np.concatenate([p[i] for p in parts]) for i in range(4)]
    return {"q": poses, "length": length, "ma": ma, "ma_fd": ma_fd, "direction": direction,
            "cross": cross, "crosses_gh": gh, "names": np.array([e["name"] for e in elements])}


def wrap_jumps(samples):
    """Boolean (n_poses x n_elements): pose invalid for that element (see module docstring)."""
    ma, fd, cross = samples["ma"], samples["ma_fd"], samples["cross"]
    bad = np.zeros(ma.shape[:2], bool)
    for k in range(ma.shape[1]):
        cols = cross[k]
        a = np.abs(ma[:, k, cols])
        peak = np.percentile(a, 99.5) if a.size else 0.0
        thr = max(JUMP_ABS, JUMP_REL * peak)
        diff = np.abs(ma[:, k, cols] - fd[:, k, cols])
        bad[:, k] = ~np.all(diff <= thr, axis=1) | ~np.all(np.isfinite(ma[:, k, cols]), axis=1)
    return bad


def _file_hash(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        h.update(f.read())
    return h.hexdigest()


def cached_sample(osim_path, girdle, elements, poses, cache_dir, tag, processes=2):
    """sample_poses with an .npz cache keyed by model file, girdle, elements, poses and method."""
    key = json.dumps({"osim": _file_hash(osim_path), "girdle": sorted(girdle.items()),
                      "elements": [(e["name"], e["osim_name"]) for e in elements],
                      "poses": hashlib.sha256(np.ascontiguousarray(poses).tobytes()).hexdigest(),
                      "fd": FD_STEP, "v": SAMPLE_VERSION})
    digest = hashlib.sha256(key.encode()).hexdigest()[:16]
    path = Path(cache_dir) / f"opensim_samples_{tag}_{digest}.npz"
    if path.exists():
        with np.load(path, allow_pickle=False) as z:
            return {k: z[k] for k in z.files}
    samples = sample_poses(osim_path, girdle, elements, poses, processes)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(f".tmp{os.getpid()}.npz")
    np.savez(tmp, **samples)
    os.replace(tmp, path)
    return samples
