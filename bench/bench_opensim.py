"""armrt against OpenSim 4.6 on the same model and the same problem.

    python -m bench.bench_opensim [--duration 0.5] [--reps 3] [--json bench/results/opensim.json]
                                  [--osim ../shared/reference/das3/das3.osim] [--quick]

OpenSim side: das3.osim with the six SC/AC coordinates locked at the model file's girdle angles
(models/das2.json "girdle"), only the 102 elements whose osim_name appears in models/das2.json (the 36
girdle-only elements and the metabolics probes removed), the same passive joint moment inside the
range of motion as armrt (a SpringGeneralizedForce per arm DOF: 1 N m/rad about the rest posture,
1 N m s/rad damping), the arm at our rest posture, muscles at zero activation in equilibrium, and the
same constant excitations through a PrescribedController (rotator cuff 0.05, elbow flexors 0.3).
Integrators: the Manager's default (Runge-Kutta-Merson, default accuracy 1e-5, variable step), and
fixed-step Runge-Kutta-Merson at 1 ms (setIntegratorFixedStepSize: the nearest to our RK4 at 1 ms).

armrt side: Arm.simulate of the same duration with the default ROS2 (one linearly implicit step per
1 ms), RK4 at 1 ms in 6 substeps of 0.17 ms (Arm's default for RK4, the default before ROS2; one RK4
step of 1 ms is refused since issue 11: unstable even for the resting arm), Euler at 0.1 ms (and CVODE as the accuracy reference). Wall times are medians over --reps repeats (OpenSim: fewer, it is slow).
The muscle model differs (OpenSim's Schutte1993Muscle_Deprecated vs our Hill model, muscle paths with
wrapping surfaces vs our polynomials), so the joint-angle trajectories differ somewhat: the RMS
difference is reported to show both solve the same problem, not to validate either.
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
MODEL_JSON = ROOT / "models" / "das2.json"
DEFAULT_OSIM = ROOT.parent / "shared" / "reference" / "das3" / "das3.osim"
DEFAULT_JSON = ROOT / "bench" / "results" / "opensim.json"
STIM = {"rotator_cuff": 0.05, "elbow_flexors": 0.3}


def make_arm(integrator: str, dt: float, substeps: int | None = 1):
    """armrt.Arm with an explicit number of substeps (1: one step of dt, the paper's setting); None: Arm's default."""
    import armrt
    try:
        return armrt.Arm(integrator=integrator, dt=dt, substeps=substeps)
    except TypeError:  # an armrt without substeps
        return armrt.Arm(integrator=integrator, dt=dt)


def model_file() -> dict:
    return json.loads(MODEL_JSON.read_text())


def excitation_vector(model: dict) -> np.ndarray:
    """Per-element excitation of STIM, DAS3 element order (same as armrt's)."""
    names = [e["name"] for e in model["elements"]]
    muscle_elems = {m["name"]: m["elements"] for m in model["muscles"]}
    u = np.zeros(len(names))
    for group, value in STIM.items():
        for mus in model["groups"][group]:
            for el in muscle_elems[mus]:
                u[names.index(el)] = value
    return u


# ---------------------------------------------------------------------------------------------- OpenSim
def build_opensim(osim_path: Path, model: dict, controller: bool = True):
    """The das3.osim model reduced to our problem; returns (opensim model, initialised state, info). controller
    False: no PrescribedController (for tools that compute the controls, such as StaticOptimization)."""
    import opensim as osim

    t0 = time.perf_counter()
    m = osim.Model(str(osim_path))
    cs = m.updCoordinateSet()
    for g in model["girdle"]["dofs"]:
        c = cs.get(g["osim_name"])
        c.setDefaultValue(g["angle"])
        c.setDefaultLocked(True)
    for d in model["dofs"]:
        c = cs.get(d["osim_name"])
        c.setDefaultValue(d["rest"])
        c.setDefaultSpeedValue(0.0)
        c.setDefaultLocked(False)
        c.set_clamped(False)  # armrt does not clamp either (it has a stiff passive moment outside the range)
    keep = {e["osim_name"] for e in model["elements"]}
    fs = m.updForceSet()
    removed = 0
    for k in reversed(range(fs.getSize())):
        if fs.get(k).getName() not in keep:
            fs.remove(k)
            removed += 1
    n_probes = m.getProbeSet().getSize()
    m.updProbeSet().clearAndDestroy()
    n_constraints = m.getConstraintSet().getSize()
    # Girdle constraints: das3.osim has none (checked); a locked coordinate is a constraint of its own.
    pj = model.get("passive_joint", {})
    k_in = float(pj.get("stiffness_inside", 1.0))
    damp = float(pj.get("damping", 1.0))
    for d in model["dofs"]:
        s = osim.SpringGeneralizedForce(d["osim_name"])
        s.setName(f"passive_{d['name']}")
        s.setStiffness(k_in)
        s.setRestLength(d["rest"])
        s.setViscosity(damp)
        m.addForce(s)

    muscles = m.getMuscles()
    n_muscles = muscles.getSize()
    if not controller:
        m.setUseVisualizer(False)
        state = m.initSystem()
        return m, state, {"n_muscles": n_muscles, "removed_forces": removed, "build_s": time.perf_counter() - t0}
    u = excitation_vector(model)
    by_osim = {e["osim_name"]: u[i] for i, e in enumerate(model["elements"])}
    ctrl = osim.PrescribedController()
    ctrl.setName("excitations")
    for k in range(n_muscles):
        mus = muscles.get(k)
        ctrl.addActuator(mus)
        ctrl.prescribeControlForActuator(mus.getName(), osim.Constant(float(by_osim[mus.getName()])))
    m.addController(ctrl)
    m.setUseVisualizer(False)
    state = m.initSystem()
    for k in range(n_muscles):
        mus = muscles.get(k)
        mus.setActivation(state, 0.0)  # armrt starts at zero activation (OpenSim clamps to its minimum)
    m.equilibrateMuscles(state)
    info = {"n_muscles": n_muscles, "removed_forces": removed, "removed_probes": n_probes,
            "constraints": n_constraints, "muscle_class": muscles.get(0).getConcreteClassName(),
            "n_states": m.getNumStateVariables(), "build_s": time.perf_counter() - t0}
    return m, state, info


def run_opensim(osim_path: Path, model: dict, duration: float, method: str, fixed_dt: float | None,
                accuracy: float | None = None) -> dict:
    import opensim as osim

    m, state, info = build_opensim(osim_path, model)
    mgr = osim.Manager(m)
    methods = {"rkm": osim.Manager.IntegratorMethod_RungeKuttaMerson,
               "euler": osim.Manager.IntegratorMethod_ExplicitEuler,
               "semi_euler2": osim.Manager.IntegratorMethod_SemiExplicitEuler2}
    if method != "default":
        mgr.setIntegratorMethod(methods[method])
    if accuracy is not None:
        mgr.setIntegratorAccuracy(accuracy)
    if fixed_dt is not None:
        mgr.setIntegratorFixedStepSize(fixed_dt)
    state.setTime(0.0)
    mgr.initialize(state)
    t0 = time.perf_counter()
    mgr.integrate(duration)
    wall = time.perf_counter() - t0
    table = mgr.getStatesTable()  # the Manager records the state after every integration step
    times = np.array(table.getIndependentColumn())
    labels = list(table.getColumnLabels())
    q = np.zeros((len(times), 5))
    for j, d in enumerate(model["dofs"]):
        lab = next(lbl for lbl in labels if lbl.endswith(f"/{d['osim_name']}/value"))
        col = table.getDependentColumn(lab)
        q[:, j] = [col[i] for i in range(col.size())]
    steps = len(times) - 1
    return {"wall_s": wall, "steps": steps, "time": times, "q": q, "info": info,
            "rtf": duration / wall}


# ---------------------------------------------------------------------------------------------- armrt
def run_armrt(integrator: str, dt: float, duration: float, reps: int, substeps: int | None = 1) -> dict:
    arm = make_arm(integrator, dt, substeps)
    walls = []
    res = None
    for _ in range(reps):
        arm.reset()
        t0 = time.perf_counter()
        res = arm.simulate(STIM, duration=duration)
        walls.append(time.perf_counter() - t0)
    wall = float(np.median(walls))
    # row k is the state at time[k]; append the final state so the trajectory covers [0, duration]
    times = np.append(res.time, arm.time)
    q = np.vstack([res.q, arm.q[None, :]])
    return {"wall_s": wall, "wall_all_s": walls, "steps": int(round(duration / dt)), "time": times, "q": q,
            "rtf": duration / wall}


def rms_deg(ta, qa, tb, qb, duration) -> dict:
    grid = np.linspace(0.0, duration, 101)
    a = np.column_stack([np.interp(grid, ta, qa[:, j]) for j in range(5)])
    b = np.column_stack([np.interp(grid, tb, qb[:, j]) for j in range(5)])
    diff = np.degrees(a - b)
    return {"rms_deg_per_dof": np.sqrt((diff ** 2).mean(axis=0)).tolist(),
            "rms_deg": float(np.sqrt((diff ** 2).mean())), "max_abs_deg": float(np.abs(diff).max())}


def opensim_ready(prog: str, osim_path: Path) -> bool:
    """True if opensim imports and the model file exists; otherwise says which is missing on stderr."""
    try:
        import opensim  # noqa: F401
    except ImportError as exc:
        print(f"{prog}: opensim not importable ({exc}); pip install opensim", file=sys.stderr)
        return False
    if not osim_path.exists():
        print(f"{prog}: {osim_path} not found (needs ../shared/reference)", file=sys.stderr)
        return False
    return True


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--duration", type=float, default=1.0, help="simulated seconds (both sides)")
    ap.add_argument("--reps", type=int, default=5, help="armrt repeats (median)")
    ap.add_argument("--osim-reps", type=int, default=3, help="OpenSim repeats per integrator (median)")
    ap.add_argument("--osim", type=Path, default=DEFAULT_OSIM)
    ap.add_argument("--json", type=Path, default=DEFAULT_JSON)
    ap.add_argument("--quick", action="store_true", help="0.1 s, one repeat (smoke test)")
    args = ap.parse_args(argv)
    if args.quick:
        args.duration, args.reps, args.osim_reps = 0.1, 1, 1
    if not opensim_ready("bench_opensim", args.osim):
        return 2
    model = model_file()
    dur = args.duration

    ours = {
        "armrt_ros2_1ms": run_armrt("ros2", 1e-3, dur, args.reps),
        "armrt_rk4_1ms_6substeps": run_armrt("rk4", 1e-3, dur, args.reps, substeps=6),
        "armrt_euler_0.1ms": run_armrt("euler", 1e-4, dur, args.reps),
        "armrt_cvode": run_armrt("cvode", 1e-3, dur, 1),
    }
    configs = {
        "opensim_rkm_default": ("default", None, None),
        "opensim_rkm_fixed_1ms": ("rkm", 1e-3, None),
    }
    theirs = {}
    for name, (method, fdt, acc) in configs.items():
        runs = []
        for _ in range(args.osim_reps):
            try:
                runs.append(run_opensim(args.osim, model, dur, method, fdt, acc))
            except Exception as exc:  # noqa: BLE001 - report and continue with the other integrators
                print(f"{name}: failed: {exc}", file=sys.stderr)
                break
            print(f"{name}: {runs[-1]['wall_s']:.2f} s wall for {dur} s, {runs[-1]['steps']} steps", file=sys.stderr)
        if runs:
            best = sorted(runs, key=lambda r: r["wall_s"])[len(runs) // 2]
            best["wall_all_s"] = [r["wall_s"] for r in runs]
            theirs[name] = best

    ref = ours["armrt_cvode"]
    out = {"duration_s": dur, "stimulation": STIM, "reps_armrt": args.reps, "reps_opensim": args.osim_reps,
           "machine": {"cpus": os.cpu_count(), "load_avg": os.getloadavg(), "note": "shared machine, 2 cores"},
           "opensim_model": next(iter(theirs.values()))["info"] if theirs else None, "runs": {}}
    for name, r in {**ours, **theirs}.items():
        entry = {"wall_s": r["wall_s"], "wall_all_s": r.get("wall_all_s"), "real_time_factor": r["rtf"],
                 "steps": r["steps"], "final_q_deg": np.degrees(r["q"][-1]).tolist(),
                 "vs_armrt_cvode": rms_deg(r["time"], r["q"], ref["time"], ref["q"], dur)}
        if name.startswith("opensim") and "opensim_rkm_default" in theirs:
            pass
        out["runs"][name] = entry
    # Same problem? RMS of joint angles between the two simulators (and OpenSim's two integrators).
    comp = {}
    if "opensim_rkm_default" in theirs:
        o = theirs["opensim_rkm_default"]
        for name, r in ours.items():
            comp[f"{name}_vs_opensim_rkm_default"] = rms_deg(r["time"], r["q"], o["time"], o["q"], dur)
        if "opensim_rkm_fixed_1ms" in theirs:
            f = theirs["opensim_rkm_fixed_1ms"]
            comp["opensim_fixed_1ms_vs_opensim_rkm_default"] = rms_deg(f["time"], f["q"], o["time"], o["q"], dur)
    out["trajectory_rms"] = comp
    ratios = {}
    for on, o in theirs.items():
        for an, a in ours.items():
            if an != "armrt_cvode":
                ratios[f"{on}/{an}"] = o["wall_s"] / a["wall_s"]
    out["speed_ratio"] = ratios
    # the joint-angle trajectories, 10 ms grid, degrees (small; for the plot)
    grid = np.linspace(0, dur, int(round(dur / 0.01)) + 1)
    out["trajectories_deg"] = {"time": grid.tolist(), **{
        name: np.degrees(np.column_stack([np.interp(grid, r["time"], r["q"][:, j]) for j in range(5)])).round(4).tolist()
        for name, r in {**ours, **theirs}.items()}}
    args.json.parent.mkdir(parents=True, exist_ok=True)
    args.json.write_text(json.dumps(out, indent=1) + "\n")
    print(markdown(out))
    print(f"\nwrote {args.json}")
    return 0


def markdown(out: dict) -> str:
    lines = [f"Simulated {out['duration_s']} s, excitations {out['stimulation']} (constant), from rest.", "",
             "| run | wall (s) | real-time factor | steps | RMS vs armrt CVODE (deg) |", "|---|---:|---:|---:|---:|"]
    for name, r in out["runs"].items():
        lines.append(f"| {name} | {r['wall_s']:.4g} | {r['real_time_factor']:.4g} | {r['steps']} | "
                     f"{r['vs_armrt_cvode']['rms_deg']:.3g} |")
    lines += ["", "| speed ratio (OpenSim wall / armrt wall) | |", "|---|---:|"]
    lines += [f"| {k} | {v:.0f} |" for k, v in out["speed_ratio"].items()]
    lines += ["", "| trajectory difference | RMS (deg) | max (deg) | per DOF GHy GHz GHyy ELx PSy (deg) |",
              "|---|---:|---:|---|"]
    for k, v in out["trajectory_rms"].items():
        lines.append(f"| {k} | {v['rms_deg']:.3g} | {v['max_abs_deg']:.3g} | "
                     f"{', '.join(f'{x:.2f}' for x in v['rms_deg_per_dof'])} |")
    return "\n".join(lines)


if __name__ == "__main__":
    sys.exit(main())
