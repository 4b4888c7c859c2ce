"""The das3 experiments of issue 15 (items 3 and 4): the 11-DOF shoulder girdle beside das2.

`armrt experiments --model das3` (run_all) writes, under one folder:

1. Settling: das3 with zero excitation from its resting posture (equilibrium.mat) until it stands still,
   with CVODE and the default ROS2; the settled angle minus the equilibrium.mat angle per DOF, the
   largest TS/AI penetration and lift-off, the conoid tension. Every other das3 experiment starts from
   this settled state (the ROS2 one), so none of them carries the settling transient.
2. The paper's Fig. 1-3 protocols on das3 beside das2, with das2's excitations (levels tuned on das2 by
   `experiments.paper_tasks`, applied to das3 by the same muscle and element names; the girdle-only
   muscles stay at zero): elevation reached, GH angles, GH stability, the scapula's motion.
3. Scapulohumeral rhythm: a humeral elevation driven by ramps of deltoid, rotator cuff, serratus
   anterior and trapezius; scapular upward rotation (scapula_angles) against thorax-humerus elevation,
   with a fitted ratio, for several levels of the two scapular rotators.
4. The largest TS/AI penetration and lift-off of every das3 run, and
5. ROS2 at 1 ms against CVODE on every das3 run (largest joint-angle difference).

Definitions (thorax frame, scapula landmarks, upward rotation) are in docs/experiments.md, section das3.
"""
from __future__ import annotations

import json
import math
import warnings
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from .arm import Arm
from .experiments_protocol import (CUFF, DT, INTEGRATOR, Phase, Sequence, deltoid_sequence, fig3_limit,
                                   middle_anterior_deltoid, paper_tasks, plateau_elevation, tune_cuff_boost)
from .experiments_protocol import new_arm as new_das2_arm
from .progress import Progress, quiet

MODEL = "das3"
SETTLE_DURATION = 6.0      # s: the relaxed das3 moves for ~2 s; over 5.5-6 s its joints turn < 0.1 deg/s
SETTLE_TAIL = 0.5          # s: the window whose largest joint speed says "settled"
REFERENCE = "cvode"        # the accuracy reference (BDF, rtol 1e-8)
# Scapulohumeral rhythm protocol: all drives ramped linearly from RHYTHM_ON to RHYTHM_FULL, then held.
RHYTHM_ON, RHYTHM_FULL, RHYTHM_DURATION = 1.0, 5.0, 7.0          # s
RHYTHM_DELTOID, RHYTHM_CUFF = 0.3, 0.1                          # excitation at full ramp
RHYTHM_SCAPULAR = (0.0, 0.1, 0.2, 0.3, 0.4)                     # serratus anterior and trapezius levels
# CVODE restarts at every change of excitation (cpp/src/cvode.cc), i.e. every 1 ms of a ramp, at 30-50 s
# of wall time per simulated second of ramp for das3's 298 states on this shared machine: the reference is
# run for one rhythm level only (rhythm_references runs them all).
RHYTHM_REFERENCE_LEVEL = 0.2
RHYTHM_BINS = (0.0, 30.0, 60.0, 90.0, 120.0, 180.0)             # deg of thorax-humerus elevation
CLASSIC_SLOPE = 1.0 / 3.0  # Inman 1944: glenohumeral 2 : scapulothoracic 1 of the humerus' elevation


def new_arm(integrator: str = INTEGRATOR, dt: float = DT) -> Arm:
    return Arm(model=MODEL, integrator=integrator, dt=dt)


def _reset(arm: Arm, q, activation=None) -> None:
    # The settled posture has ACz and ACx 1-3 deg past the model's girdle ranges (and equilibrium.mat lies
    # below DAS3's own): the passive joint moments there are part of the model, not an input error.
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="q slightly beyond the joint limits", category=RuntimeWarning)
        arm.reset(q=q, activation=activation)


# ----------------------------------------------------------------------------- scapula orientation

def scapula_landmarks(model) -> dict[str, np.ndarray]:
    """AA, TS, AI (m) in the scapula frame: AA is the scapula's origin in DAS3 (the acromial angle), TS and
    AI the scapulothoracic contact points of the model file (DAS3's TSprojection and AIprojection: the
    trigonum spinae and angulus inferior projected onto the thorax surface). model: an Arm or Model."""
    from .geometry import find_model_file
    m = getattr(model, "model", model)
    path = find_model_file(m.name)
    if path is None:
        raise FileNotFoundError(f"model file of {m.name!r} not found (its contact points name TS and AI)")
    spec = json.loads(Path(path).read_text()).get("girdle_forces")
    if not spec:
        raise ValueError(f"model {m.name!r} has no girdle_forces: its scapula does not move")
    pts = {p["name"]: np.asarray(p["point"], dtype=float) for p in spec["contact"]["points"] if p["body"] == "scapula"}
    missing = {"TS", "AI"} - set(pts)
    if missing:
        raise ValueError(f"model {m.name!r}: scapula contact points {sorted(missing)} missing")
    return {"AA": np.zeros(3), "TS": pts["TS"], "AI": pts["AI"]}


def scapula_landmark_frame(landmarks: dict[str, np.ndarray]) -> np.ndarray:
    """(3, 3) columns x_s, y_s, z_s of the scapula landmark frame in scapula coordinates: x_s from TS to AA
    (along the spine, lateral), z_s = x_s x (AA - AI) normalised (normal to the scapular plane through AA,
    TS, AI; posterior), y_s = z_s x x_s (in the plane, superior). DSEM's convention, as in the thorax frame."""
    aa, ts, ai = landmarks["AA"], landmarks["TS"], landmarks["AI"]
    x = (aa - ts) / np.linalg.norm(aa - ts)
    z = np.cross(x, aa - ai)
    z /= np.linalg.norm(z)
    return np.stack([x, np.cross(z, x), z], axis=1)


def yzx_angles(M) -> np.ndarray:
    """(..., 3) rad (a, b, c) with M = Ry(a) Rz(b) Rx(c) for rotation matrices M (..., 3, 3); b in
    [-pi/2, pi/2]. In DAS3's axes (x lateral, y up, z posterior) this is ISB's Y-X-Z scapula sequence (Wu et
    al. 2005: axes x forward, y up, z lateral) with x and z relabelled."""
    M = np.asarray(M, dtype=float)
    # First column (cos a cos b, sin b, -sin a cos b); row y (sin b, cos b cos c, -cos b sin c).
    b = np.arcsin(np.clip(M[..., 1, 0], -1.0, 1.0))
    a = np.arctan2(-M[..., 2, 0], M[..., 0, 0])
    c = np.arctan2(-M[..., 1, 2], M[..., 1, 1])
    return np.stack([a, b, c], axis=-1)


def scapula_angles(model, q, landmarks: dict | None = None) -> np.ndarray:
    """(3,) or (k, 3) rad: the orientation of the scapula landmark frame (scapula_landmark_frame) in the
    thorax frame (x lateral, y superior, z posterior) as yzx_angles: protraction a about thorax y (positive
    turns the spine's lateral end forward), upward rotation b about the scapular plane's normal as it is
    after protraction (positive turns the glenoid up and AI laterally), posterior tilt c about the spine
    (positive tilts the superior border back). q: (ndof,) or (k, ndof) rad. model: an Arm or Model whose
    scapula moves (ValueError otherwise)."""
    m = getattr(model, "model", model)
    sb = m.info["scapula_body"]
    if sb < 0:
        raise ValueError(f"model {m.name!r} has a fixed scapula: no scapular rotation to measure")
    lm = landmarks or scapula_landmarks(m)
    R, _ = m.body_poses(np.asarray(q, dtype=float))
    return yzx_angles(R[..., sb, :, :] @ scapula_landmark_frame(lm))


# ----------------------------------------------------------------------------- contact and accuracy

CONTACT_POINTS = ("TS", "AI")


def contact_extremes(res) -> dict[str, dict[str, float]]:
    """Largest penetration (mm, how far inside the thorax surface) and lift-off (mm, how far outside) of
    TS and AI over a run (Result.contact_distance: first-order signed distance, negative inside); 0 when
    the point never was on that side."""
    d = np.asarray(res.contact_distance) * 1e3
    return {p: {"penetration_mm": float(max(0.0, -d[:, k].min())), "lift_off_mm": float(max(0.0, d[:, k].max()))}
            for k, p in enumerate(CONTACT_POINTS)}


def max_difference(a, b, dof_names) -> dict:
    """Largest |a.q - b.q| (deg) over the common rows, with the DOF and time where it occurs."""
    n = min(len(a.time), len(b.time))
    d = np.degrees(np.abs(a.q[:n] - b.q[:n]))
    k, j = np.unravel_index(int(np.argmax(d)), d.shape)
    return {"max_deg": float(d[k, j]), "dof": dof_names[j], "time": float(a.time[k]),
            "per_dof_deg": d.max(axis=0).round(4).tolist()}


# ----------------------------------------------------------------------------- 1. settling

@dataclass
class Settling:
    q_equilibrium: np.ndarray          # (11,) rad, equilibrium.mat (the model's rest posture)
    q: dict                            # integrator -> (11,) rad, settled posture
    speed_tail: dict                   # integrator -> rad/s, largest joint speed over the last SETTLE_TAIL
    contact: dict                      # contact_extremes of the ROS2 run
    contact_end_mm: list               # TS, AI signed distance at the end (mm)
    conoid_tension: dict               # N: start, end, min, max (ROS2)
    ros2_vs_cvode: dict | None         # max_difference over the run
    ros2_vs_cvode_settled: float | None  # deg, after the first second
    duration: float
    results: dict                      # integrator -> Result


def settle(duration: float = SETTLE_DURATION, integrators=(INTEGRATOR, REFERENCE)) -> Settling:
    """das3 with zero excitation from equilibrium.mat for `duration` s with each integrator."""
    results, qs, speeds = {}, {}, {}
    q_eq = None
    for integ in integrators:
        arm = new_arm(integ)
        q_eq = np.array(arm.rest_posture)
        _reset(arm, q_eq)
        res = arm.simulate(np.zeros(arm.n_elements), duration=duration, record_every=1)
        tail = res.time >= res.time[-1] - SETTLE_TAIL
        results[integ], qs[integ] = res, res.q[-1].copy()
        speeds[integ] = float(np.abs(res.qdot[tail]).max())
    main = results[integrators[0]]
    cmp, cmp_settled = None, None
    if REFERENCE in results and INTEGRATOR in results:
        a, b = results[INTEGRATOR], results[REFERENCE]
        cmp = max_difference(a, b, list(a.dof_names))
        late = a.time >= 1.0
        n = min(len(a.time), len(b.time))
        cmp_settled = float(np.degrees(np.abs(a.q[:n][late[:n]] - b.q[:n][late[:n]])).max())
    ct = main.conoid_tension
    return Settling(q_equilibrium=q_eq, q=qs, speed_tail=speeds, contact=contact_extremes(main),
                    contact_end_mm=(main.contact_distance[-1] * 1e3).tolist(),
                    conoid_tension={"start": float(ct[0]), "end": float(ct[-1]), "min": float(ct.min()), "max": float(ct.max())},
                    ros2_vs_cvode=cmp, ros2_vs_cvode_settled=cmp_settled, duration=duration, results=results)


def settling_table(s: Settling, dof_names) -> list[dict]:
    """One row per DOF: equilibrium.mat angle, settled angle and their difference (deg) per integrator."""
    rows = []
    for j, name in enumerate(dof_names):
        row = {"dof": name, "equilibrium_deg": float(np.degrees(s.q_equilibrium[j]))}
        for integ, q in s.q.items():
            row[f"settled_{integ}_deg"] = float(np.degrees(q[j]))
            row[f"difference_{integ}_deg"] = float(np.degrees(q[j] - s.q_equilibrium[j]))
        rows.append(row)
    return rows


# ----------------------------------------------------------------------------- runs from the settled state

def run_on(model: str, seq: Sequence, integrator: str = INTEGRATOR, dt: float = DT, record_every: int = 1):
    """A stimulation sequence on `model` from its start posture (seq.q0) with activations at their first
    excitations and contractile elements in equilibrium; returns (arm, Result)."""
    arm = Arm(model=model, integrator=integrator, dt=dt)
    n = int(round(seq.duration / dt))
    u = seq.excitation(arm, n, dt)
    _reset(arm, seq.q0, u[0])
    return arm, arm.simulate(u, duration=seq.duration, record_every=record_every)


# Columns of the GH angles (GHy, GHz, GHyy) in each model's q.
GH_DOFS = ("GHy", "GHz", "GHyy")


def protocol_summary(arm: Arm, res, name: str) -> dict:
    """What each figure compares: elevation reached, GH angles there, GHstab, elbow and forearm; for
    das3 also the scapula's rotation and the contact extremes."""
    th = np.degrees(res.thorax_humerus)
    q = np.degrees(res.q)
    k = int(np.argmax(th[:, 1]))
    gh = [arm.dof_names.index(d) for d in GH_DOFS]
    el, ps = arm.dof_names.index("ELx"), arm.dof_names.index("PSy")
    at = lambda t, j: float(np.interp(t, res.time, q[:, j]))
    out = {"elevation_start": float(th[0, 1]), "elevation_max": float(th[k, 1]), "time_of_max": float(res.time[k]),
           "plane_at_max": float(th[k, 0]), "gh_angles_at_max": q[k, gh].round(2).tolist(),
           "gh_angles_start": q[0, gh].round(2).tolist(),
           "gh_stab_max": float(res.gh_stab.max()), "gh_stab_start": float(res.gh_stab[0]),
           "gh_stab_at_max": float(res.gh_stab[k]),
           "gh_stab_max_time": float(res.time[int(np.argmax(res.gh_stab))])}
    if name == "fig1":  # the paper's moments that the run reaches (a --quick run is cut short)
        for key, t, j in (("elbow_at_10s", 9.999, el), ("pronation_at_10s", 9.999, ps), ("elbow_at_14s", 13.999, el),
                          ("pronation_at_18s", 17.999, ps)):
            if t <= res.time[-1]:
                out[key] = at(t, j)
        out.update(elbow_final=float(q[-1, el]), pronation_final=float(q[-1, ps]))
    if res.contact_distance is not None:
        sa = np.degrees(scapula_angles(arm, res.q[[0, k]]))
        out["scapula_start_deg"] = sa[0].round(2).tolist()
        out["scapula_at_max_deg"] = sa[1].round(2).tolist()
        out["contact"] = contact_extremes(res)
        out["conoid_tension_range"] = [float(res.conoid_tension.min()), float(res.conoid_tension.max())]
    return out


# ----------------------------------------------------------------------------- 3. scapulohumeral rhythm

def rhythm_sequence(deltoid: list[str], scapular: float, q0, deltoid_level: float = RHYTHM_DELTOID,
                    cuff: float = RHYTHM_CUFF, duration: float = RHYTHM_DURATION,
                    on: float = RHYTHM_ON, full: float = RHYTHM_FULL) -> Sequence:
    """Humeral elevation: the middle+anterior deltoid elements, the four cuff muscles, serratus anterior
    and trapezius ramped together from zero at `on` to their levels at `full` (s), then held."""
    groups = {e: deltoid_level for e in deltoid}
    groups.update({m: cuff for m in CUFF})
    if scapular > 0:
        groups.update({"serratus_anterior": scapular, "trapezius": scapular})
    return Sequence(f"rhythm_{scapular:g}", duration, [Phase(0.0, {}), Phase(on, groups, full - on)], {}, q0)


@dataclass
class RhythmFit:
    slope: float            # deg of upward rotation per deg of thorax-humerus elevation
    intercept: float        # deg
    r2: float
    gh_to_st: float         # (1 - slope) / slope: glenohumeral : scapulothoracic (classic 2)
    elevation_range: tuple  # deg, (start, end) of the fitted part
    bins: list              # (low, high, slope, samples) per elevation bin with >= 2 deg of motion in it


def fit_rhythm(elevation_deg, upward_deg, bins=RHYTHM_BINS) -> RhythmFit:
    """Least-squares line of upward rotation against elevation (deg), and its slope in elevation bins.
    Raises ValueError when elevation covers less than 5 deg (no ratio to fit)."""
    e, u = np.asarray(elevation_deg, float), np.asarray(upward_deg, float)
    if e.size < 3 or np.ptp(e) < 5.0:
        raise ValueError(f"elevation spans {np.ptp(e) if e.size else 0:.1f} deg: too little to fit a rhythm")
    A = np.stack([e, np.ones_like(e)], axis=1)
    (k, c), *_ = np.linalg.lstsq(A, u, rcond=None)
    ss = float(np.sum((u - u.mean()) ** 2))
    r2 = 1.0 - float(np.sum((u - A @ [k, c]) ** 2)) / ss if ss > 0 else 1.0
    out = []
    for lo, hi in zip(bins[:-1], bins[1:]):
        sel = (e >= lo) & (e < hi)
        if sel.sum() >= 3 and np.ptp(e[sel]) >= 2.0:
            kb = float(np.polyfit(e[sel], u[sel], 1)[0])
            out.append((lo, hi, kb, int(sel.sum())))
    return RhythmFit(slope=float(k), intercept=float(c), r2=r2,
                     gh_to_st=float((1 - k) / k) if k != 0 else math.inf,
                     elevation_range=(float(e.min()), float(e.max())), bins=out)


def rhythm_window(res, on: float = RHYTHM_ON) -> np.ndarray:
    """Rows of the rising phase: from the start of the ramp to the first time elevation is at its maximum."""
    th = res.thorax_humerus[:, 1]
    k_max = int(np.argmax(th))
    return np.flatnonzero((res.time >= on) & (np.arange(len(th)) <= k_max))


def at_range_limit(arm: Arm, q, margin_deg: float = 1.0) -> list[str]:
    """DOFs within margin_deg of the end of their range, or beyond it (where the passive joint moment acts)."""
    lo, hi = arm.dof_ranges[:, 0], arm.dof_ranges[:, 1]
    m = math.radians(margin_deg)
    return [n for j, n in enumerate(arm.dof_names) if q[j] < lo[j] + m or q[j] > hi[j] - m]


def rhythm_run(arm: Arm, res, on: float = RHYTHM_ON) -> dict:
    """The rhythm of one run: scapula angles, elevation, the fit (RhythmFit as a dict)."""
    rows = rhythm_window(res, on)
    sa = np.degrees(scapula_angles(arm, res.q))
    up = sa[:, 1] - sa[0, 1]
    el = np.degrees(res.thorax_humerus[:, 1])
    k = int(np.argmax(el))
    out = {"elevation_max": float(el.max()), "upward_rotation_at_max": float(up[k]),
           "upward_rotation_max": float(up.max()), "q_at_max_deg": np.degrees(res.q[k]).round(2).tolist(),
           "at_range_limit": at_range_limit(arm, res.q[k]),
           "gh_stab_max": float(res.gh_stab.max()), "contact": contact_extremes(res)}
    try:
        f = fit_rhythm(el[rows], up[rows])
        out["fit"] = f.__dict__
    except ValueError as exc:
        out["fit"] = None
        out["fit_error"] = str(exc)
    return out


# ----------------------------------------------------------------------------- plots

def _plot_settling(s: Settling, dof_names, path: Path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    res = s.results[INTEGRATOR]
    d = np.degrees(res.q - s.q_equilibrium)
    for j, n in enumerate(dof_names):
        ax[0].plot(res.time, d[:, j], label=n, lw=1, color=f"C{j % 10}", ls="-" if j < 10 else "--")
    ax[0].set_ylabel("q - equilibrium.mat (deg)")
    ax[0].legend(ncol=6, fontsize=7, loc="lower right")
    ax[0].set_title("das3 settling from equilibrium.mat, zero excitation (ROS2 1 ms)")
    if REFERENCE in s.results:
        ref = s.results[REFERENCE]
        n = min(len(res.time), len(ref.time))
        ax[1].semilogy(res.time[:n], np.degrees(np.abs(res.q[:n] - ref.q[:n])).max(axis=1) + 1e-6, color="k")
        ax[1].axhline(0.1, color="r", ls="--", lw=0.8, label="0.1 deg target")
        ax[1].set_ylabel("max |ROS2 - CVODE| (deg)")
        ax[1].legend(fontsize=8)
    for k, p in enumerate(CONTACT_POINTS):
        ax[2].plot(res.time, res.contact_distance[:, k] * 1e3, label=p)
    ax[2].axhline(0.0, color="k", lw=0.6)
    ax[2].set_ylabel("distance from thorax (mm)")
    ax[2].set_xlabel("time (s)")
    ax[2].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _plot_protocol(name: str, runs: dict, path: Path, title: str):
    """runs: model -> (arm, Result)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    for model, (arm, res) in runs.items():
        style = "-" if model == "das2" else "--"
        q = np.degrees(res.q)
        if name == "fig1":
            ax[0].plot(res.time, q[:, arm.dof_names.index("ELx")], style, color="C0", label=f"{model} elbow flexion")
            ax[0].plot(res.time, q[:, arm.dof_names.index("PSy")], style, color="C1", label=f"{model} pronation")
        else:
            ax[0].plot(res.time, np.degrees(res.thorax_humerus[:, 1]), style, color="C0",
                       label=f"{model} thorax-humerus elevation")
            ax[0].plot(res.time, q[:, arm.dof_names.index("GHz")], style, color="C2", label=f"{model} GHz")
        ax[1].plot(res.time, res.gh_stab, style, color="k" if model == "das2" else "C3", label=model)
        if res.contact_distance is not None:
            sa = np.degrees(scapula_angles(arm, res.q))
            for k, lbl in enumerate(("protraction", "upward rotation", "posterior tilt")):
                ax[2].plot(res.time, sa[:, k] - sa[0, k], label=f"das3 scapula {lbl}")
    ax[0].set_ylabel("angle (deg)")
    ax[0].legend(fontsize=7, loc="upper right")
    ax[0].set_title(title)
    ax[1].axhline(1.0, color="r", lw=0.8, ls="--")
    ax[1].set_ylabel("GHstab")
    ax[1].legend(fontsize=8, loc="upper right")
    ax[2].set_ylabel("scapula, change (deg)")
    ax[2].legend(fontsize=7, loc="upper right")
    ax[2].set_xlabel("time (s)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _plot_rhythm(curves: dict, path: Path):
    """curves: scapular level -> (elevation deg, upward rotation deg, fit dict or None) on the rising phase."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 1, figsize=(7, 5))
    for i, (level, (el, up, fit)) in enumerate(curves.items()):
        lbl = f"serratus + trapezius {level:g}"
        if fit:
            lbl += f": slope {fit['slope']:.2f}"
        ax.plot(el, up, color=f"C{i}", label=lbl)
    e0 = min(float(np.min(c[0])) for c in curves.values())
    e = np.linspace(e0, max(float(np.max(c[0])) for c in curves.values()), 2)
    ax.plot(e, CLASSIC_SLOPE * (e - e0), "k:", label="classic 1:2 (slope 1/3)")
    ax.set_xlabel("thorax-humerus elevation (deg)")
    ax.set_ylabel("scapular upward rotation from rest (deg)")
    ax.set_title("das3: scapulohumeral rhythm (deltoid 0.3, cuff 0.1 ramped)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


# ----------------------------------------------------------------------------- the job

PROTOCOL_TITLES = {"fig1": "Fig. 1 on das3 (dashed) beside das2 (solid): elbow flexors, triceps, pronators",
                   "fig2": "Fig. 2 on das3 (dashed) beside das2 (solid): middle+anterior deltoid",
                   "fig3": "Fig. 3 on das3 (dashed) beside das2 (solid): deltoid with das2's cuff boost"}


def run_all(out_dir="results", quick: bool = False, progress: bool = True) -> int:
    """Regenerates the das3 figures, tables (das3.md) and numbers (das3.json) into out_dir.
    quick: shorter runs (settling 2 s, protocols cut to 4 s, one 3 s rhythm run), for tests: CVODE on the
    excitation ramps is most of the time (RHYTHM_REFERENCE_LEVEL)."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    # Stages: settling, das2's baseline and two tunings (paper_tasks), Fig. 1-3, rhythm, report.
    prog = Progress(total=10, enabled=progress)
    try:
        with quiet():
            summary = _run_all(out, quick, prog)
    finally:
        prog.close()
    print(f"wrote {out}/das3.md, das3.json, das3_*.png")
    return 0 if summary else 1


def _run_all(out: Path, quick: bool, prog: Progress) -> dict:
    summary: dict = {"model": MODEL, "dt": DT, "integrator": INTEGRATOR, "reference": REFERENCE, "quick": quick,
                     "dof_names": list(new_arm().dof_names)}
    accuracy: dict = {}
    contacts: dict = {}

    prog.start("das3 settling (ROS2 and CVODE)")
    s = settle(2.0 if quick else SETTLE_DURATION)
    arm3 = new_arm()
    names = list(arm3.dof_names)
    q0 = s.q[INTEGRATOR]
    summary["settling"] = {"duration": s.duration, "table": settling_table(s, names), "speed_tail": s.speed_tail,
                           "contact": s.contact, "contact_end_mm": s.contact_end_mm,
                           "conoid_tension": s.conoid_tension, "start_state_deg": np.degrees(q0).round(3).tolist(),
                           "scapula_equilibrium_deg": np.degrees(scapula_angles(arm3, s.q_equilibrium)).round(2).tolist(),
                           "scapula_settled_deg": np.degrees(scapula_angles(arm3, q0)).round(2).tolist()}
    accuracy["settling"] = dict(s.ros2_vs_cvode or {}, after_1s_deg=s.ros2_vs_cvode_settled)
    contacts["settling"] = s.contact
    _plot_settling(s, names, out / "das3_settling.png")
    prog.step("das3 settling")

    pt = paper_tasks(None, prog)  # das2: baseline, Fig. 1 levels, deltoid level and cuff boost
    summary["das2_levels"] = {"baseline": pt.baseline.levels, "fig1": pt.fig1_levels.__dict__,
                              "deltoid_elements": pt.deltoid, "deltoid": pt.deltoid_level,
                              "cuff_boost": dict(zip(CUFF, pt.cuff_boost.boost))}
    protocols = {}
    for seq in pt.sequences:
        if quick:
            seq = replace(seq, duration=min(seq.duration, 4.0))
        prog.start(f"{seq.name} on das2 and das3")
        runs = {"das2": run_on("das2", seq)}
        seq3 = replace(seq, q0=q0)
        runs["das3"] = run_on(MODEL, seq3)
        ref = run_on(MODEL, seq3, REFERENCE)[1]
        protocols[seq.name] = {m: protocol_summary(a, r, seq.name) for m, (a, r) in runs.items()}
        accuracy[seq.name] = max_difference(runs["das3"][1], ref, names)
        contacts[seq.name] = protocols[seq.name]["das3"]["contact"]
        _plot_protocol(seq.name, runs, out / f"das3_{seq.name}.png", PROTOCOL_TITLES[seq.name])
        prog.step(f"{seq.name} on das2 and das3")
    summary["protocols"] = protocols

    # The paper's Fig. 3 method on das3 itself: the smallest uniform cuff boost (then pattern) keeping
    # GHstab < 0.5 at every step with das3's own arm, beside das2's boost applied above.
    prog.start("Fig. 3 cuff boost tuned on das3")
    fig2_das3 = run_on(MODEL, replace(pt.sequences[1], q0=q0))[1]
    own = tune_cuff_boost(pt.baseline.levels, pt.deltoid, pt.deltoid_level, q0,
                          min_elevation_deg=plateau_elevation(fig2_das3) - 5.0, limit=fig3_limit(pt.baseline),
                          run=lambda seq: run_on(MODEL, seq))
    seq3 = deltoid_sequence("fig3", pt.baseline.levels, pt.deltoid, pt.deltoid_level, own.boost, q0)
    arm, res = run_on(MODEL, seq3)
    summary["fig3_das3_boost"] = {"cuff_boost": dict(zip(CUFF, own.boost)), "limit": own.limit,
                                  "evaluations": own.evaluations, "uniform_scan": own.uniform_scan,
                                  "summary": protocol_summary(arm, res, "fig3")}
    prog.step("Fig. 3 cuff boost tuned on das3")

    prog.start("scapulohumeral rhythm")
    levels = (RHYTHM_REFERENCE_LEVEL,) if quick else RHYTHM_SCAPULAR
    rhythm, curves = {}, {}
    ramp = (0.5, 2.0, 3.0) if quick else (RHYTHM_ON, RHYTHM_FULL, RHYTHM_DURATION)  # on, full, end (s)
    for level in levels:
        prog.tick(f"serratus + trapezius {level:g}")
        seq = rhythm_sequence(pt.deltoid, level, q0, duration=ramp[2], on=ramp[0], full=ramp[1])
        arm, res = run_on(MODEL, seq)
        r = rhythm_run(arm, res, ramp[0])
        rhythm[f"{level:g}"] = r
        if level == RHYTHM_REFERENCE_LEVEL:
            accuracy[seq.name] = max_difference(res, run_on(MODEL, seq, REFERENCE)[1], names)
        contacts[seq.name] = r["contact"]
        rows = rhythm_window(res, ramp[0])
        sa = np.degrees(scapula_angles(arm, res.q[rows]))[:, 1] - math.degrees(scapula_angles(arm, res.q[0])[1])
        curves[level] = (np.degrees(res.thorax_humerus[rows, 1]), sa, r["fit"])
    summary["rhythm"] = {"deltoid": RHYTHM_DELTOID, "cuff": RHYTHM_CUFF, "ramp": list(ramp[:2]),
                         "reference_level": RHYTHM_REFERENCE_LEVEL,
                         "classic_slope": CLASSIC_SLOPE, "runs": rhythm}
    _plot_rhythm(curves, out / "das3_rhythm.png")
    prog.step("scapulohumeral rhythm")

    prog.start("report")
    summary["contact"] = contacts
    summary["ros2_vs_cvode"] = accuracy
    (out / "das3.json").write_text(json.dumps(summary, indent=1, default=float) + "\n")
    (out / "das3.md").write_text(report(summary))
    prog.step("report")
    return summary


def _fmt(v, spec=".2f"):
    return "" if v is None else format(v, spec)


def report(s: dict) -> str:
    st = s["settling"]
    cmd = "armrt experiments --model das3" + (" --quick" if s.get("quick") else "")
    lines = ["# armrt: das3 experiments (issue 15)", "",
             f"Model das3, {s['integrator']} at {s['dt'] * 1e3:g} ms, reference {s['reference']}. "
             f"Regenerate with `{cmd}`.", "",
             f"## Settling: zero excitation from equilibrium.mat for {st['duration']:g} s", "",
             "| DOF | equilibrium.mat (deg) | settled ROS2 (deg) | settled - equilibrium ROS2 (deg) | settled - equilibrium CVODE (deg) |",
             "|---|---|---|---|---|"]
    for r in st["table"]:
        lines.append(f"| {r['dof']} | {r['equilibrium_deg']:.2f} | {r.get('settled_ros2_deg', float('nan')):.2f} | "
                     f"{r.get('difference_ros2_deg', float('nan')):+.2f} | {_fmt(r.get('difference_cvode_deg'), '+.2f')} |")
    c = st["contact"]
    lines += ["", "Largest joint speed over the last 0.5 s: " +
              ", ".join(f"{k} {v:.2g} rad/s" for k, v in st["speed_tail"].items()) + ". "
              f"TS: penetration up to {c['TS']['penetration_mm']:.2f} mm, lift-off {c['TS']['lift_off_mm']:.2f} mm; "
              f"AI: penetration up to {c['AI']['penetration_mm']:.2f} mm, lift-off {c['AI']['lift_off_mm']:.2f} mm; "
              f"at the end TS {st['contact_end_mm'][0]:+.2f} mm, AI {st['contact_end_mm'][1]:+.2f} mm. "
              f"Conoid tension {st['conoid_tension']['start']:.0f} N at the start, {st['conoid_tension']['end']:.0f} N "
              f"settled (range {st['conoid_tension']['min']:.0f}-{st['conoid_tension']['max']:.0f} N). "
              f"Scapula (protraction, upward rotation, posterior tilt, deg): {st['scapula_equilibrium_deg']} at "
              f"equilibrium.mat, {st['scapula_settled_deg']} settled. Every other das3 run starts from the settled "
              "ROS2 state (activations at their first excitation, contractile elements in equilibrium).", ""]
    lv = s["das2_levels"]
    lines += ["## Fig. 1-3 protocols on das3 beside das2", "",
              f"das2's levels (tuned on das2 by the default run's code): baseline cuff {lv['baseline']}, Fig. 1 "
              f"{lv['fig1']}, deltoid {lv['deltoid']} on {', '.join(lv['deltoid_elements'])}, Fig. 3 cuff boost "
              f"{lv['cuff_boost']}. Same names on das3; its girdle-only muscles stay at zero.", ""]
    p = s["protocols"]
    lines += ["| protocol | quantity | das2 | das3 |", "|---|---|---|---|"]
    if "fig1" in p:
        a, b = p["fig1"]["das2"], p["fig1"]["das3"]
        for key, lbl in (("elbow_at_10s", "elbow at 10 s (deg)"), ("pronation_at_10s", "pronation at 10 s (deg)"),
                         ("elbow_at_14s", "elbow at 14 s (deg)"), ("pronation_at_18s", "pronation at 18 s (deg)"),
                         ("elbow_final", "elbow at the end (deg)"), ("pronation_final", "pronation at the end (deg)"),
                         ("gh_stab_max", "largest GHstab")):
            if key in a:
                lines.append(f"| Fig. 1 | {lbl} | {a[key]:.2f} | {b[key]:.2f} |")
    for name in ("fig2", "fig3"):
        if name not in p:
            continue
        a, b = p[name]["das2"], p[name]["das3"]
        lbl = "Fig. 2" if name == "fig2" else "Fig. 3"
        lines += [f"| {lbl} | thorax-humerus elevation, start -> max (deg) | {a['elevation_start']:.1f} -> {a['elevation_max']:.1f} | "
                  f"{b['elevation_start']:.1f} -> {b['elevation_max']:.1f} |",
                  f"| {lbl} | plane of elevation at max (deg) | {a['plane_at_max']:.1f} | {b['plane_at_max']:.1f} |",
                  f"| {lbl} | GH angles GHy, GHz, GHyy at start (deg) | {a['gh_angles_start']} | {b['gh_angles_start']} |",
                  f"| {lbl} | GH angles at max elevation (deg) | {a['gh_angles_at_max']} | {b['gh_angles_at_max']} |",
                  f"| {lbl} | GHstab at start, largest, at max elevation | {a['gh_stab_start']:.2f}, {a['gh_stab_max']:.2f}, "
                  f"{a['gh_stab_at_max']:.2f} | {b['gh_stab_start']:.2f}, {b['gh_stab_max']:.2f}, {b['gh_stab_at_max']:.2f} |",
                  f"| {lbl} | scapula (protraction, upward rot., post. tilt) start -> at max (deg) | fixed | "
                  f"{b['scapula_start_deg']} -> {b['scapula_at_max_deg']} |"]
    own = s.get("fig3_das3_boost")
    if own:
        b = own["summary"]
        lines += ["", "Fig. 3 by the paper's method on das3 itself (the cuff boost tuned on das3, GHstab < "
                  f"{own['limit']:g} at every 1 ms step, {own['evaluations']} simulations): boost "
                  + ", ".join(f"{m} +{v:.4f}" for m, v in own["cuff_boost"].items())
                  + f"; GHstab largest {b['gh_stab_max']:.3f} at {b['gh_stab_max_time']:.2f} s, elevation "
                  f"{b['elevation_start']:.1f} -> {b['elevation_max']:.1f} deg."]
    r = s["rhythm"]
    names = s["dof_names"]
    lines += ["", "## Scapulohumeral rhythm", "",
              f"Middle+anterior deltoid {r['deltoid']}, rotator cuff {r['cuff']}, serratus anterior and trapezius "
              f"at the level in the first column, ramped together from 0 at {r['ramp'][0]:g} s to full at "
              f"{r['ramp'][1]:g} s. Fit: upward rotation (from rest) = slope x thorax-humerus elevation + c over the "
              f"rising phase; classic slope {r['classic_slope']:.3f} (glenohumeral 2 : scapular 1).", "",
              "| serratus + trapezius | elevation fitted (deg) | slope | GH : ST | R^2 | slope per elevation bin | largest GHstab | "
              "upward rotation at highest elevation (deg) | DOFs at a range end there |",
              "|---|---|---|---|---|---|---|---|---|"]
    for level, run in r["runs"].items():
        f = run["fit"]
        if f is None:
            lines.append(f"| {level} | {run.get('fit_error', '')} | | | | | {run['gh_stab_max']:.2f} |")
            continue
        bins = "; ".join(f"{lo:g}-{hi:g}: {k:.2f}" for lo, hi, k, _ in f["bins"])
        lim = ", ".join(f"{n} {run['q_at_max_deg'][names.index(n)]:.1f}" for n in run["at_range_limit"])
        lines.append(f"| {level} | {f['elevation_range'][0]:.1f} -> {f['elevation_range'][1]:.1f} | {f['slope']:.3f} | "
                     f"{f['gh_to_st']:.2f} | {f['r2']:.2f} | {bins} | {run['gh_stab_max']:.2f} | "
                     f"{run['upward_rotation_at_max']:.1f} | {lim} |")
    lines += ["", "## The scapula stays on the thorax: largest TS/AI penetration and lift-off (mm)", "",
              "| run | TS penetration | TS lift-off | AI penetration | AI lift-off |", "|---|---|---|---|---|"]
    for run, c in s["contact"].items():
        lines.append(f"| {run} | {c['TS']['penetration_mm']:.2f} | {c['TS']['lift_off_mm']:.2f} | "
                     f"{c['AI']['penetration_mm']:.2f} | {c['AI']['lift_off_mm']:.2f} |")
    lines += ["", "## ROS2 at 1 ms against CVODE (largest joint-angle difference over the run, target 0.1 deg)", "",
              "| run | max (deg) | DOF | time (s) |", "|---|---|---|---|"]
    for run, a in s["ros2_vs_cvode"].items():
        extra = f" (after 1 s: {a['after_1s_deg']:.3f})" if a.get("after_1s_deg") is not None else ""
        lines.append(f"| {run} | {a['max_deg']:.3f}{extra} | {a['dof']} | {a['time']:.3f} |")
    lines += ["", f"The rhythm's CVODE reference is run at serratus + trapezius {r['reference_level']:g} only: CVODE restarts "
              "at every excitation change, 1000 times per second of ramp (docs/experiments.md, das3)."]
    return "\n".join(lines) + "\n"


def rhythm_references(levels=RHYTHM_SCAPULAR) -> dict:
    """ROS2 against CVODE on the full rhythm run at each serratus + trapezius level (run_all checks
    RHYTHM_REFERENCE_LEVEL only; CVODE takes minutes per level here). Returns level -> max_difference."""
    deltoid = middle_anterior_deltoid(new_das2_arm())
    q0 = settle(SETTLE_DURATION, (INTEGRATOR,)).q[INTEGRATOR]
    out = {}
    for level in levels:
        seq = rhythm_sequence(deltoid, level, q0)
        arm, res = run_on(MODEL, seq)
        out[level] = max_difference(res, run_on(MODEL, seq, REFERENCE)[1], list(arm.dof_names))
        print(f"serratus + trapezius {level:g}: ROS2 - CVODE up to {out[level]['max_deg']:.3f} deg "
              f"({out[level]['dof']} at {out[level]['time']:.3f} s)", flush=True)
    return out


if __name__ == "__main__":  # python -m armrt.experiments_das3 --rhythm-references [LEVEL ...]
    import argparse
    ap = argparse.ArgumentParser(prog="python -m armrt.experiments_das3",
                                 description="ROS2 against CVODE on the das3 rhythm runs (every level by default)")
    ap.add_argument("--rhythm-references", nargs="*", type=float, default=None, metavar="LEVEL")
    args = ap.parse_args()
    if args.rhythm_references is None:
        ap.error("nothing to do: pass --rhythm-references [LEVEL ...] (armrt experiments --model das3 runs the rest)")
    rhythm_references(args.rhythm_references or RHYTHM_SCAPULAR)
