"""OpenSim 4.6 on das3.osim with the shoulder girdle free, for the same excitation (issue 15 item 6).

    python -m bench opensim-das3                     # or: python -m bench.bench_opensim_das3 [options]
    python -m bench.bench_opensim_das3 [--duration 0.5] [--reps 1] [--json bench/results/opensim_das3.json]
                                       [--osim ../shared/reference/das3/das3.osim] [--quick] [--armrt MODEL]
    python -m bench.bench_opensim_das3 --stability   # why fixed-step RKM at 1 ms diverges (about 1 min)

OpenSim side: das3.osim with all 11 coordinates unlocked and unclamped (SC, AC, GH, elbow, forearm; the
thorax stays welded to ground), the 138 muscles, the metabolics probe removed, the arm and girdle at
equilibrium.mat x[0:11] with zero speeds, zero initial activation and muscles equilibrated (as
bench_opensim does for das2). das3.osim itself holds nothing that keeps the scapula on the thorax (its
ForceSet is the 138 muscles only), so the two girdle forces of armrt's das3 (docs/das3.md,
cpp/include/armrt/girdle_forces.h) are added from OpenSim 4.6's stock components, no plugin:

- conoid ligament: an ExpressionBasedPointToPointForce from conoid_origin (clavicle_r) to
  conoid_insertion (scapula_r), tension k (d - L0 + sqrt((d - L0)^2 + eps^2)) / 2 (a positive value
  pulls the points together);
- scapulothoracic contact of TS and AI: one ExpressionBasedBushingForce per point, frame1 on the thorax
  at the ellipsoid centre (thorax axes), frame2 on the scapula at the point. The bushing's
  translational deflection (delta_x, delta_y, delta_z) is then the point's position from the centre in
  thorax axes, and the bushing applies minus its F expressions at the point, so F = K m(f) grad f there
  gives armrt's law F = -K m(f) grad f exactly (f the ellipsoid function, m its smooth negative part,
  K = k (rx^2 + ry^2 + rz^2) / 2); the moment expressions are 0 and the damping is 0. Frame2's axes are
  the thorax axes at the resting posture, so the bushing's Euler-angle deflection (unused, but computed)
  stays far from its gimbal lock at 90 deg;
- passive joint moments: an ExpressionBasedCoordinateForce per coordinate with armrt's law
  (cpp/src/passive_joints.cc): -k_in (q - rest) - c qdot - k_out e |e|, e the excursion beyond the range.
  Rest postures, ranges and constants come from armrt's das3 model when it is registered
  (armrt.Model("das3").info), else from models/das3.json, else rest = equilibrium.mat, arm ranges from
  models/das2.json, girdle ranges from das3.osim and das2's constants (the "passive_source" field says
  which).

Same excitation protocol as bench_opensim (rotator cuff 0.05, elbow flexors 0.3, constant, element names
from models/das2.json mapped to das3.osim's muscle names; every other muscle 0) through a
PrescribedController. Integrators (RUNS): the Manager's default (Runge-Kutta-Merson, accuracy 1e-5,
variable step), fixed-step RKM at 1 ms (diverges on this model: reported with the step it failed at) and
at 50 us. Wall time is Manager.integrate() only. The 11 coordinate trajectories (rad) are sampled at 1 ms
(the recorded steps linearly interpolated; the fixed steps fall on the grid) and saved to the JSON and
an .npz beside it.

compare_with_armrt(arm_factory) runs armrt from the same posture on the same excitation and reports the
speed ratio and the largest per-coordinate difference (deg) on the coordinates both models have.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
DAS3_DIR = ROOT.parent / "shared" / "reference" / "das3"
DEFAULT_OSIM = DAS3_DIR / "das3.osim"
DEFAULT_JSON = ROOT / "bench" / "results" / "opensim_das3.json"
DAS3_JSON = ROOT / "models" / "das3.json"
DAS3_COORDS = ["SC_y", "SC_z", "SC_x", "AC_y", "AC_z", "AC_x", "GH_y", "GH_z", "GH_yy", "EL_x", "PS_y"]
SAMPLE_DT = 1e-3  # s, the trajectory grid
# Manager runs: the default (RKM, accuracy 1e-5, variable step), fixed-step RKM at 1 ms (the das2 bench's;
# it diverges here, see docs/benchmarks.md "das3 against OpenSim") and at 50 us, the largest of
# 1 ms, 0.2 ms, 0.1 ms, 50 us that stayed finite over 20 ms: the passive joint damping on a nearly
# inertia-free girdle mode (M^-1 eigenvalue 3.9e4 / (kg m^2) at rest) needs h < about 80 us explicitly.
RUNS = {"opensim_default": None, "opensim_rkm_fixed_1ms": 1e-3, "opensim_rkm_fixed_50us": 5e-5}


# ---------------------------------------------------------------------------------------------- inputs
def das3_parameters(model_struct: Path = DAS3_DIR / "model_struct.mat") -> dict:
    """The girdle-force parameters of model_struct.mat (SI units, body-frame points as 3-lists)."""
    import scipy.io as sio

    m = sio.loadmat(model_struct, squeeze_me=True, struct_as_record=False)["model"]
    vec = lambda name: [float(v) for v in np.ravel(getattr(m, name))]  # noqa: E731
    return {"thorax_center": vec("thorax_center"), "thorax_radii": vec("thorax_radii"),
            "TS": vec("TSprojection"), "AI": vec("AIprojection"),
            "scap_thorax_k": float(m.scap_thorax_k), "scap_thorax_eps": float(m.scap_thorax_eps),
            "conoid_origin": vec("conoid_origin"), "conoid_insertion": vec("conoid_insertion"),
            "conoid_length": float(m.conoid_length), "conoid_stiffness": float(m.conoid_stiffness),
            "conoid_eps": float(m.conoid_eps)}


def equilibrium_q(path: Path = DAS3_DIR / "equilibrium.mat") -> np.ndarray:
    """(11,) rad: the DAS3 resting posture, in DAS3_COORDS order."""
    import scipy.io as sio

    return np.asarray(sio.loadmat(path, squeeze_me=True)["x"][:11], dtype=float)


def das2_stimulation() -> tuple[dict, dict]:
    """(STIM groups, {das3.osim muscle name: excitation}) of bench_opensim's protocol."""
    from bench.bench_opensim import STIM, excitation_vector, model_file

    model = model_file()
    u = excitation_vector(model)
    return STIM, {e["osim_name"]: float(u[i]) for i, e in enumerate(model["elements"]) if u[i] != 0.0}


def passive_joints(osim_model=None) -> dict:
    """{"source", "stiffness_inside", "stiffness_outside", "damping", "dofs": {osim_name: (rest, lo, hi)}}
    of the passive joint law: armrt's registered das3 model when there is one, else the fallback in the
    module docstring (osim_model: an opensim.Model for the girdle ranges)."""
    def from_model(info: dict, source: str) -> dict | None:
        pj = info.get("passive_joint") or {}
        dofs = {d["osim_name"]: (float(d["rest"]), float(d["range"][0]), float(d["range"][1])) for d in info["dofs"]}
        if set(dofs) != set(DAS3_COORDS) or not {"stiffness_inside", "stiffness_outside", "damping"} <= set(pj):
            return None
        return {"source": source, **{k: float(pj[k]) for k in ("stiffness_inside", "stiffness_outside", "damping")},
                "dofs": dofs}

    try:
        import armrt

        got = from_model(armrt.Model("das3").info, "armrt das3 model (armrt.Model('das3').info)")
        if got:
            return got
    except Exception:  # noqa: BLE001 - no armrt, or no das3 in it yet: the model file, else the fallback
        pass
    if DAS3_JSON.exists():
        got = from_model(json.loads(DAS3_JSON.read_text()), "models/das3.json")
        if got:
            return got
    if osim_model is None:
        import opensim as osim

        osim_model = osim.Model(str(DEFAULT_OSIM))
    das2 = json.loads((ROOT / "models" / "das2.json").read_text())
    pj = das2["passive_joint"]
    q0 = dict(zip(DAS3_COORDS, equilibrium_q()))
    arm_ranges = {d["osim_name"]: d["range"] for d in das2["dofs"]}
    dofs = {}
    for name in DAS3_COORDS:
        if name in arm_ranges:
            lo, hi = arm_ranges[name]
        else:
            c = osim_model.getCoordinateSet().get(name)
            lo, hi = c.getRangeMin(), c.getRangeMax()
        dofs[name] = (float(q0[name]), float(lo), float(hi))
    return {"source": "fallback: rest equilibrium.mat, arm ranges models/das2.json, girdle ranges das3.osim, "
                      "das2 constants",
            "stiffness_inside": float(pj["stiffness_inside"]), "stiffness_outside": float(pj["stiffness_outside"]),
            "damping": float(pj["damping"]), "dofs": dofs}


# ---------------------------------------------------------------------------------------------- force laws
def _num(x: float) -> str:
    return repr(float(x))  # shortest exact decimal: the expression holds the double itself


def conoid_expression(p: dict) -> str:
    """Lepton expression of the conoid tension T(d) (N), d the origin-insertion distance (m)."""
    L0, k, eps = _num(p["conoid_length"]), _num(p["conoid_stiffness"]), _num(p["conoid_eps"])
    return f"{k}*((d-{L0})+sqrt((d-{L0})^2+{eps}^2))/2"


def contact_expressions(p: dict) -> list[str]:
    """Lepton Fx, Fy, Fz of the bushing (its force on the point is minus these): K m(f) grad f."""
    r = p["thorax_radii"]
    K = p["scap_thorax_k"] * sum(x * x for x in r) / 2
    f = "(" + "+".join(f"(delta_{a}/{_num(ri)})^2" for a, ri in zip("xyz", r)) + "-1)"
    m = f"({f}-sqrt({f}^2+{_num(p['scap_thorax_eps'])}^2))/2"
    return [f"{_num(K)}*{m}*2*delta_{a}/{_num(ri * ri)}" for a, ri in zip("xyz", r)]


def passive_expression(rest: float, lo: float, hi: float, k_in: float, k_out: float, damping: float) -> str:
    """Lepton expression of armrt's passive joint moment (N m) in q (rad) and qdot (rad/s)."""
    e = f"(max(q-{_num(hi)},0)+min(q-{_num(lo)},0))"
    return f"-{_num(k_in)}*(q-{_num(rest)})-{_num(damping)}*qdot-{_num(k_out)}*{e}*abs({e})"


def body_fixed_xyz(R: np.ndarray) -> list[float]:
    """Body-fixed X-Y-Z Euler angles (rad) of a rotation matrix R = Rx(a) Ry(b) Rz(c) (|b| < 90 deg)."""
    return [float(np.arctan2(-R[1, 2], R[2, 2])), float(np.arcsin(np.clip(R[0, 2], -1, 1))),
            float(np.arctan2(-R[0, 1], R[0, 0]))]


def contact_force(p: dict, point_thorax: np.ndarray) -> np.ndarray:
    """armrt's scapulothoracic contact force (N, thorax axes) on a point at point_thorax (m)."""
    c, r = np.asarray(p["thorax_center"]), np.asarray(p["thorax_radii"])
    K = p["scap_thorax_k"] * np.sum(r ** 2) / 2
    f = np.sum(((point_thorax - c) / r) ** 2) - 1
    m = (f - np.sqrt(f * f + p["scap_thorax_eps"] ** 2)) / 2
    return -K * m * 2 * (point_thorax - c) / r ** 2


def conoid_tension(p: dict, L: float) -> float:
    """armrt's conoid tension (N) at length L (m)."""
    d = L - p["conoid_length"]
    return p["conoid_stiffness"] * (d + np.sqrt(d * d + p["conoid_eps"] ** 2)) / 2


# ---------------------------------------------------------------------------------------------- OpenSim
def build_opensim(osim_path: Path = DEFAULT_OSIM, excitations: dict | None = None, girdle_forces: bool = True,
                  passive: bool = True, equilibrate: bool = True, passive_damping: float | None = None):
    """das3.osim with the girdle free and armrt's girdle and passive joint forces added.

    excitations: {das3.osim muscle name: constant excitation}, default the das2 protocol.
    passive_damping: overrides the passive joint damping (N m s/rad; for fixed_step_stability). Returns
    (opensim.Model, initialised State at equilibrium.mat, info dict). Raises KeyError for an excitation
    naming no muscle of the model, FileNotFoundError when das3.osim or the DAS3 .mat files are missing."""
    import opensim as osim

    for f in (osim_path, DAS3_DIR / "model_struct.mat", DAS3_DIR / "equilibrium.mat"):
        if not Path(f).exists():
            raise FileNotFoundError(f"{f} not found (needs ../shared/reference/das3 beside the repository)")
    if excitations is None:
        excitations = das2_stimulation()[1]
    t0 = time.perf_counter()
    params = das3_parameters()
    q0 = equilibrium_q()
    m = osim.Model(str(osim_path))
    cs = m.updCoordinateSet()
    for name, q in zip(DAS3_COORDS, q0):
        c = cs.get(name)
        c.setDefaultValue(float(q))
        c.setDefaultSpeedValue(0.0)
        c.setDefaultLocked(False)
        c.set_clamped(False)  # armrt does not clamp: stiff passive moments outside the range instead
    n_probes = m.getProbeSet().getSize()
    m.updProbeSet().clearAndDestroy()
    muscles = m.getMuscles()
    names = {muscles.get(k).getName() for k in range(muscles.getSize())}
    unknown = sorted(set(excitations) - names)
    if unknown:
        raise KeyError(f"excitations name muscles that das3.osim does not have: {unknown[:5]}")
    added = []
    pj = passive_joints(m) if passive else None
    if pj is not None and passive_damping is not None:
        pj = {**pj, "damping": float(passive_damping), "source": pj["source"] + f", damping {passive_damping}"}
    if passive:
        for name in DAS3_COORDS:
            rest, lo, hi = pj["dofs"][name]
            fc = osim.ExpressionBasedCoordinateForce(name, passive_expression(
                rest, lo, hi, pj["stiffness_inside"], pj["stiffness_outside"], pj["damping"]))
            fc.setName(f"passive_{name}")
            m.addForce(fc)
            added.append(fc.getName())
    if girdle_forces:
        conoid = osim.ExpressionBasedPointToPointForce(
            "clavicle_r", osim.Vec3(*params["conoid_origin"]), "scapula_r", osim.Vec3(*params["conoid_insertion"]),
            conoid_expression(params))
        conoid.setName("conoid")
        m.addForce(conoid)
        added.append("conoid")
        # frame2's axes = thorax axes at rest: needs the resting pose, so realise a copy first
        state = m.initSystem()
        R_rest = m.getBodySet().get("scapula_r").findTransformBetween(state, m.getBodySet().get("thorax")).R()
        # R_rest: scapula axes in thorax axes; frame2 = scapula rotated by R_rest^T has thorax axes at rest
        xyz = body_fixed_xyz(np.array([[R_rest.get(i, j) for j in range(3)] for i in range(3)]).T)
        for label in ("TS", "AI"):
            b = osim.ExpressionBasedBushingForce(
                f"scapulothoracic_{label}", m.getBodySet().get("thorax"), osim.Vec3(*params["thorax_center"]),
                osim.Vec3(0, 0, 0), m.getBodySet().get("scapula_r"), osim.Vec3(*params[label]), osim.Vec3(*xyz))
            fx, fy, fz = contact_expressions(params)
            b.setFxExpression(fx)
            b.setFyExpression(fy)
            b.setFzExpression(fz)
            m.addForce(b)
            added.append(b.getName())
    ctrl = osim.PrescribedController()
    ctrl.setName("excitations")
    for k in range(muscles.getSize()):
        mus = muscles.get(k)
        ctrl.addActuator(mus)
        ctrl.prescribeControlForActuator(mus.getName(), osim.Constant(float(excitations.get(mus.getName(), 0.0))))
    m.addController(ctrl)
    m.setUseVisualizer(False)
    state = m.initSystem()
    for k in range(muscles.getSize()):
        muscles.get(k).setActivation(state, 0.0)  # as bench_opensim: zero activation (OpenSim clamps to its minimum)
    if equilibrate:
        m.equilibrateMuscles(state)
    info = {"n_muscles": muscles.getSize(), "muscle_class": muscles.get(0).getConcreteClassName(),
            "removed_probes": n_probes, "constraints": m.getConstraintSet().getSize(), "added_forces": added,
            "passive_source": pj["source"] if pj else None, "n_states": m.getNumStateVariables(),
            "excited_muscles": {k: v for k, v in sorted(excitations.items()) if v != 0.0},
            "build_s": time.perf_counter() - t0}
    return m, state, info


def girdle_forces_at(m, state, params: dict | None = None) -> dict:
    """OpenSim's girdle forces at a state, beside armrt's formulas at the same point positions:
    {"conoid": {"length_m", "tension_N", "armrt_tension_N"}, "TS"/"AI": {"point_thorax_m", "force_N",
    "armrt_force_N", "f"}} (forces on the scapula, thorax axes)."""
    import opensim as osim

    params = params or das3_parameters()
    m.realizeDynamics(state)
    bodies = m.getBodySet()
    thorax, scap, clav = bodies.get("thorax"), bodies.get("scapula_r"), bodies.get("clavicle_r")
    to_np = lambda v: np.array([v.get(i) for i in range(3)])  # noqa: E731
    out = {}
    fs = m.getForceSet()
    conoid = osim.ExpressionBasedPointToPointForce.safeDownCast(fs.get("conoid"))
    xo = to_np(clav.findStationLocationInGround(state, osim.Vec3(*params["conoid_origin"])))
    xi = to_np(scap.findStationLocationInGround(state, osim.Vec3(*params["conoid_insertion"])))
    L = float(np.linalg.norm(xi - xo))
    out["conoid"] = {"length_m": L, "tension_N": float(conoid.getForceMagnitude(state)),
                     "armrt_tension_N": float(conoid_tension(params, L))}
    X_GT = thorax.getTransformInGround(state)
    R_GT = np.array([[X_GT.R().get(i, j) for j in range(3)] for i in range(3)])
    p_GT = to_np(X_GT.p())
    for label in ("TS", "AI"):
        b = fs.get(f"scapulothoracic_{label}")
        vals = b.getRecordValues(state)
        labels = b.getRecordLabels()
        rec = {labels.get(i): vals.get(i) for i in range(labels.size())}
        # frame2 is the offset frame on the scapula: its force columns are the force on the scapula (ground axes)
        f2 = [k for k in rec if k.endswith(".force.X") and "scapula" in k][0][:-len(".force.X")]
        F_ground = np.array([rec[f"{f2}.force.{a}"] for a in "XYZ"])
        p_ground = to_np(scap.findStationLocationInGround(state, osim.Vec3(*params[label])))
        p_thorax = R_GT.T @ (p_ground - p_GT)
        c, r = np.asarray(params["thorax_center"]), np.asarray(params["thorax_radii"])
        out[label] = {"point_thorax_m": p_thorax.tolist(), "force_N": (R_GT.T @ F_ground).tolist(),
                      "armrt_force_N": contact_force(params, p_thorax).tolist(),
                      "f": float(np.sum(((p_thorax - c) / r) ** 2) - 1)}
    return out


def run_opensim(duration: float, fixed_dt: float | None, osim_path: Path = DEFAULT_OSIM,
                excitations: dict | None = None) -> dict:
    """One Manager run from the resting posture. fixed_dt None: the default integrator (RKM, accuracy
    1e-5); else fixed-step RKM. Returns wall_s (integrate() only), steps, time (steps,), q (steps, 11)
    rad, and t_grid / q_grid sampled every SAMPLE_DT (s, rad)."""
    import opensim as osim

    m, state, info = build_opensim(osim_path, excitations)
    mgr = osim.Manager(m)
    if fixed_dt is not None:
        mgr.setIntegratorMethod(osim.Manager.IntegratorMethod_RungeKuttaMerson)
        mgr.setIntegratorFixedStepSize(fixed_dt)
    state.setTime(0.0)
    mgr.initialize(state)
    t0 = time.perf_counter()
    error = None
    try:
        mgr.integrate(duration)
    except Exception as exc:  # noqa: BLE001 - a failed integration is a result too (reported, not hidden)
        error = f"{type(exc).__name__}: {exc}"
    wall = time.perf_counter() - t0
    table = mgr.getStatesTable()
    times = np.array(table.getIndependentColumn())
    labels = list(table.getColumnLabels())
    q = np.zeros((len(times), len(DAS3_COORDS)))
    for j, name in enumerate(DAS3_COORDS):
        lab = next(lbl for lbl in labels if lbl.endswith(f"/{name}/value"))
        col = table.getDependentColumn(lab)
        q[:, j] = [col[i] for i in range(col.size())]
    # Explicit fixed steps can diverge without an exception (the state turns NaN): keep the finite part
    # (no DAS3 range reaches 4 rad: beyond 10 rad the integration has blown up)
    finite = (np.isfinite(q) & (np.abs(q) < 10.0)).all(axis=1)
    if not finite.all():
        bad = int(np.argmin(finite))
        error = error or (f"diverged: non-finite or > 10 rad coordinates from step {bad} (t = {times[bad]:.6g} s)")
        times, q = times[:bad], q[:bad]
    t_end = float(times[-1]) if len(times) else 0.0
    grid = np.arange(0.0, t_end + 1e-9, SAMPLE_DT)
    q_grid = (np.column_stack([np.interp(grid, times, q[:, j]) for j in range(q.shape[1])]) if len(times)
              else np.zeros((0, len(DAS3_COORDS))))
    del mgr  # before the model it refers to
    contact_f = scapulothoracic_f(m, q_grid)
    return {"wall_s": wall, "steps": max(len(times) - 1, 0), "simulated_s": t_end, "time": times, "q": q,
            "t_grid": grid, "q_grid": q_grid, "rtf": t_end / wall if wall > 0 else float("nan"),
            "contact_f": contact_f, "info": info, "error": error}


def scapulothoracic_f(m, q_poses: np.ndarray, params: dict | None = None) -> dict:
    """At each pose (rows of q_poses, DAS3_COORDS order, rad): the ellipsoid function f of TS and AI
    (< 0 inside the thorax) and f / |grad f|, the distance from the surface to first order (m, < 0 inside).
    Returns {"TS": (n, 2) array, "AI": (n, 2) array}."""
    import opensim as osim

    params = params or das3_parameters()
    c, r = np.asarray(params["thorax_center"]), np.asarray(params["thorax_radii"])
    state = m.initSystem()
    cs = m.getCoordinateSet()
    thorax, scap = m.getBodySet().get("thorax"), m.getBodySet().get("scapula_r")
    out = {label: np.zeros((len(q_poses), 2)) for label in ("TS", "AI")}
    for k, q in enumerate(q_poses):
        for name, v in zip(DAS3_COORDS, q):
            cs.get(name).setValue(state, float(v), False)
        m.realizePosition(state)
        for label in ("TS", "AI"):
            v = scap.findStationLocationInAnotherFrame(state, osim.Vec3(*params[label]), thorax)
            p = np.array([v.get(i) for i in range(3)])
            f = float(np.sum(((p - c) / r) ** 2) - 1)
            out[label][k] = (f, f / np.linalg.norm(2 * (p - c) / r ** 2))
    return out


def fixed_step_stability(dts=(1e-3, 2e-4, 1e-4, 5e-5), duration: float = 0.02) -> dict:
    """Why fixed-step RKM fails at 1 ms: for each step size (s) and each of the full model, no passive
    joint forces, no girdle forces and neither, the first recorded step with a non-finite or > 10 rad
    coordinate (None: finite over `duration`), and the largest eigenvalues of M^-1 at rest (1/(kg m^2))
    with the coordinates of the extreme mode. Explicit RKM's damping limit is h < about 3 / (c lambda)."""
    import opensim as osim

    out = {"duration_s": duration, "diverged_at_step": {}}
    for label, kw in {"full": {}, "no passive": {"passive": False}, "passive without damping": {"passive_damping": 0.0},
                      "no girdle forces": {"girdle_forces": False},
                      "neither": {"passive": False, "girdle_forces": False}}.items():
        row = {}
        for dt in dts:
            m, state, _ = build_opensim(**kw)
            mgr = osim.Manager(m)
            mgr.setIntegratorMethod(osim.Manager.IntegratorMethod_RungeKuttaMerson)
            mgr.setIntegratorFixedStepSize(dt)
            state.setTime(0.0)
            mgr.initialize(state)
            mgr.integrate(duration)
            table = mgr.getStatesTable()
            mat = table.getMatrix().to_numpy()
            labels = list(table.getColumnLabels())
            cols = [labels.index(next(lbl for lbl in labels if lbl.endswith(f"/{n}/value"))) for n in DAS3_COORDS]
            bad = np.flatnonzero(~(np.isfinite(mat[:, cols]) & (np.abs(mat[:, cols]) < 10.0)).all(axis=1))
            row[f"{dt:g}"] = int(bad[0]) if len(bad) else None
            del mgr
        out["diverged_at_step"][label] = row
    m, state, _ = build_opensim(equilibrate=False)
    m.realizePosition(state)
    M = osim.Matrix()
    m.getMatterSubsystem().calcM(state, M)
    M = np.array([[M.get(i, j) for j in range(M.ncol())] for i in range(M.nrow())])
    w, V = np.linalg.eigh(np.linalg.inv(M))
    out["Minv_largest_eigenvalues"] = w[-3:][::-1].tolist()
    out["Minv_extreme_mode"] = dict(zip(DAS3_COORDS, np.round(V[:, -1], 3).tolist()))
    return out


# ---------------------------------------------------------------------------------------------- armrt
def compare_with_armrt(arm_factory, duration: float = 0.2, opensim_run: dict | None = None,
                       reps: int = 3, fixed_dt: float | None = None) -> dict:
    """armrt on the same excitation from the same posture, against an OpenSim run of this module.

    arm_factory: () -> armrt.Arm (das3, or das2 to compare on its 5 arm coordinates). opensim_run:
    a run_opensim() result of at least `duration` (run here with `fixed_dt` if None). The arm starts at
    equilibrium.mat (its coordinates, by OpenSim name) with zero speeds and activations and gets the
    excitations by das3.osim muscle name (Arm accepts OpenSim force names). Returns speed_ratio
    (OpenSim wall / armrt wall, median of `reps` armrt runs), the max and RMS per-coordinate
    difference (deg) on the common coordinates at the 1 ms grid, and both trajectories.
    Raises ValueError when the two share no coordinate."""
    _, exc = das2_stimulation()
    if opensim_run is None:
        opensim_run = run_opensim(duration, fixed_dt)
    arm = arm_factory()
    common = [n for n in arm.dof_osim_names if n in DAS3_COORDS]
    if not common:
        raise ValueError(f"armrt model {arm.model_name} shares no coordinate with das3.osim")
    q0 = dict(zip(DAS3_COORDS, equilibrium_q()))
    q_start = np.array([q0.get(n, r) for n, r in zip(arm.dof_osim_names, arm.rest_posture)])
    walls, res = [], None
    for _ in range(reps):
        arm.reset(q=q_start)
        t0 = time.perf_counter()
        res = arm.simulate(exc, duration=duration)
        walls.append(time.perf_counter() - t0)
    t_arm = np.append(res.time, arm.time)
    q_arm = np.vstack([res.q, arm.q[None, :]])
    grid = opensim_run["t_grid"][opensim_run["t_grid"] <= min(duration, t_arm[-1]) + 1e-9]
    jo = [DAS3_COORDS.index(n) for n in common]
    ja = [arm.dof_osim_names.index(n) for n in common]
    qo = opensim_run["q_grid"][: len(grid)][:, jo]
    qa = np.column_stack([np.interp(grid, t_arm, q_arm[:, j]) for j in ja])
    diff = np.degrees(qa - qo)
    wall = float(np.median(walls))
    # OpenSim's wall scaled to the compared duration when it ran longer (its cost per simulated second)
    sim = opensim_run["simulated_s"]
    os_wall = opensim_run["wall_s"] * duration / sim if sim > 0 else float("nan")
    return {"armrt_model": arm.model_name, "integrator": arm.integrator, "dt": arm.dt, "substeps": arm.substeps,
            "duration_s": duration, "coordinates": common, "armrt_wall_s": wall, "armrt_wall_all_s": walls,
            "armrt_rtf": duration / wall, "opensim_wall_s": os_wall, "speed_ratio": os_wall / wall,
            "max_abs_deg_per_coordinate": dict(zip(common, np.abs(diff).max(axis=0).tolist())),
            "rms_deg_per_coordinate": dict(zip(common, np.sqrt((diff ** 2).mean(axis=0)).tolist())),
            "max_abs_deg": float(np.abs(diff).max()),
            "armrt_excited_elements": sorted(arm.element_names[i] for i in np.flatnonzero(res.excitation[0] > 0)),
            "t_grid": grid, "q_armrt": qa, "q_opensim": qo}


# ---------------------------------------------------------------------------------------------- main
def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--duration", type=float, default=0.5, help="simulated seconds (both sides)")
    ap.add_argument("--reps", type=int, default=1, help="OpenSim repeats per integrator (median)")
    ap.add_argument("--osim", type=Path, default=DEFAULT_OSIM)
    ap.add_argument("--json", type=Path, default=DEFAULT_JSON)
    ap.add_argument("--quick", action="store_true", help="0.02 s, one repeat (smoke test)")
    ap.add_argument("--stability", action="store_true",
                    help="only the fixed-step stability diagnosis (fixed_step_stability), printed as JSON")
    ap.add_argument("--armrt", default="das3",
                    help="armrt model to compare with (das3; das2 on its 5 arm coordinates; none to skip)")
    args = ap.parse_args(argv)
    if args.quick:
        args.duration, args.reps = 0.02, 1
    from bench.bench_opensim import opensim_ready
    if not opensim_ready("bench_opensim_das3", args.osim):
        return 2
    if args.stability:
        print(json.dumps(fixed_step_stability(), indent=1))
        return 0
    dur = args.duration
    stim, exc = das2_stimulation()
    m, state, info = build_opensim(args.osim, exc)
    at_rest = girdle_forces_at(m, state)
    del m, state
    runs = {}
    for name, fdt in RUNS.items():
        tries = []
        for _ in range(args.reps):
            tries.append(run_opensim(dur, fdt, args.osim, exc))
            r = tries[-1]
            print(f"{name}: {r['wall_s']:.2f} s wall for {r['simulated_s']:.4g} of {dur} s, {r['steps']} steps"
                  + (f", {r['error']}" if r["error"] else ""), file=sys.stderr, flush=True)
            if r["error"]:
                break
        tries.sort(key=lambda r: r["wall_s"])
        runs[name] = tries[len(tries) // 2]
        runs[name]["wall_all_s"] = [r["wall_s"] for r in tries]
    out = {"duration_s": dur, "stimulation": stim, "reps_opensim": args.reps,
           "command": " ".join(["python -m bench.bench_opensim_das3",
                                *(argv if argv is not None else sys.argv[1:])]),
           "timestamp_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
           "machine": {"cpus": os.cpu_count(), "load_avg": os.getloadavg(), "note": "shared machine, 2 cores"},
           "opensim_model": info, "girdle_forces_at_rest": at_rest, "coordinates": DAS3_COORDS, "runs": {}}
    arrays = {}
    for name, r in runs.items():
        out["runs"][name] = {"wall_s": r["wall_s"], "wall_all_s": r["wall_all_s"], "simulated_s": r["simulated_s"],
                             "real_time_factor": r["rtf"], "steps": r["steps"], "error": r["error"],
                             "final_q_deg": np.degrees(r["q"][-1]).tolist() if len(r["q"]) else None,
                             "scapulothoracic_distance_mm": {  # first order, < 0 inside the thorax
                                 label: {"min": float(1e3 * f[:, 1].min()), "max": float(1e3 * f[:, 1].max())}
                                 for label, f in r["contact_f"].items() if len(f)},
                             "q_1ms_rad": r["q_grid"].round(9).tolist()}
        arrays[f"{name}_t"] = r["t_grid"]
        arrays[f"{name}_q"] = r["q_grid"]
        for label, f in r["contact_f"].items():
            arrays[f"{name}_{label}_f_and_distance_m"] = f
    a = runs["opensim_default"]
    out["vs_opensim_default_max_abs_deg"] = {}
    for name, b in runs.items():
        n = min(len(a["t_grid"]), len(b["t_grid"]))
        if name != "opensim_default" and n > 0 and not b["error"]:
            out["vs_opensim_default_max_abs_deg"][name] = dict(zip(DAS3_COORDS, np.degrees(
                np.abs(a["q_grid"][:n] - b["q_grid"][:n]).max(axis=0)).tolist()))
    if args.armrt != "none":
        try:
            import armrt

            cmp = compare_with_armrt(lambda: armrt.Arm(model=args.armrt), dur, opensim_run=a)
            out["armrt"] = {k: v for k, v in cmp.items() if not isinstance(v, np.ndarray)}
            # OpenSim's wall per simulated second over armrt's, for every run that completed
            out["armrt"]["speed_ratio_per_run"] = {
                name: (r["wall_s"] / r["simulated_s"]) / (cmp["armrt_wall_s"] / dur)
                for name, r in runs.items() if not r["error"] and r["simulated_s"] > 0}
            arrays["armrt_t"], arrays["armrt_q"] = cmp["t_grid"], cmp["q_armrt"]
            if cmp["coordinates"] == DAS3_COORDS:  # armrt's scapula against the same thorax, same geometry
                m, _, _ = build_opensim(args.osim, exc)
                f = scapulothoracic_f(m, cmp["q_armrt"])
                del m
                out["armrt"]["scapulothoracic_distance_mm"] = {
                    label: {"min": float(1e3 * v[:, 1].min()), "max": float(1e3 * v[:, 1].max())}
                    for label, v in f.items()}
        except Exception as exc_:  # noqa: BLE001 - no armrt or no such model yet: say so in the results
            out["armrt"] = {"error": f"{type(exc_).__name__}: {exc_}"}
            print(f"armrt comparison skipped: {out['armrt']['error']}", file=sys.stderr)
    args.json.parent.mkdir(parents=True, exist_ok=True)
    args.json.write_text(json.dumps(out, indent=1) + "\n")
    np.savez_compressed(args.json.with_suffix(".npz"), coordinates=np.array(DAS3_COORDS), **arrays)
    print(markdown(out))
    print(f"\nwrote {args.json} and {args.json.with_suffix('.npz')}")
    return 0


def markdown(out: dict) -> str:
    lines = [f"Simulated {out['duration_s']} s, excitations {out['stimulation']} (constant), from equilibrium.mat.",
             "", "| run | wall (s) | simulated (s) | real-time factor | steps |", "|---|---:|---:|---:|---:|"]
    for name, r in out["runs"].items():
        lines.append(f"| {name} | {r['wall_s']:.4g} | {r['simulated_s']:.4g} | {r['real_time_factor']:.3g} | "
                     f"{r['steps']} |" + (f" failed: {r['error']}" if r["error"] else ""))
    g = out["girdle_forces_at_rest"]
    for name, r in out["runs"].items():
        d = r.get("scapulothoracic_distance_mm") or {}
        if d and not r["error"]:
            lines.append("")
            lines.append(f"{name}: TS {d['TS']['min']:.2f} to {d['TS']['max']:.2f} mm, AI {d['AI']['min']:.2f} to "
                         f"{d['AI']['max']:.2f} mm from the thorax surface (< 0 inside) over the run.")
    lines += ["", f"At rest: conoid {g['conoid']['tension_N']:.1f} N "
              f"(armrt formula {g['conoid']['armrt_tension_N']:.1f} N), "
              f"TS {np.linalg.norm(g['TS']['force_N']):.1f} N, AI {np.linalg.norm(g['AI']['force_N']):.1f} N."]
    a = out.get("armrt")
    if a and "error" not in a:
        lines += ["", f"armrt {a['armrt_model']} ({a['integrator']}, dt {a['dt']} s): wall {a['armrt_wall_s']:.4g} s, "
                  f"real-time factor {a['armrt_rtf']:.3g}, "
                  f"speed ratio (OpenSim default / armrt) {a['speed_ratio']:.0f}, "
                  f"max difference {a['max_abs_deg']:.3g} deg",
                  "", "| coordinate | max abs diff (deg) | RMS (deg) |", "|---|---:|---:|"]
        lines += [f"| {c} | {a['max_abs_deg_per_coordinate'][c]:.3g} | {a['rms_deg_per_coordinate'][c]:.3g} |"
                  for c in a["coordinates"]]
        d = a.get("scapulothoracic_distance_mm")
        if d:
            lines += ["", f"armrt: TS {d['TS']['min']:.2f} to {d['TS']['max']:.2f} mm, AI {d['AI']['min']:.2f} to "
                      f"{d['AI']['max']:.2f} mm from the thorax surface over the run (das3.osim geometry)."]
    elif a:
        lines += ["", f"armrt comparison not run: {a['error']}"]
    return "\n".join(lines)


if __name__ == "__main__":
    if str(ROOT) not in sys.path:
        sys.path.insert(0, str(ROOT))
    sys.exit(main())
