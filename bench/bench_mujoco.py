"""MuJoCo / MyoSuite muscle models next to armrt: steps per second, cost per muscle per step, real-time factor.

    python -m bench.bench_mujoco [--json bench/results/mujoco.json] [--seconds 2] [--reps 5]

Models (all from PyPI wheels, nothing downloaded at run time):
- myoArm: `myosuite` 3.0.0's envs/myo/assets/arm/myoarm.xml (the wheel's own top-level file; installed
  with `pip install --no-deps myosuite`), whose meshes and scene come from the `myo-sim` wheel. The file
  refers to them as ../myo_sim, so it is copied with the arm assets into a temporary directory beside a
  symlink myo_sim -> <site-packages>/myo_sim/models.
- myoElbow: `myo-sim` 0.2.3's models/legacy/elbow/myoelbow_2dof6muscles.xml (2 DOF, 6 muscles) and
  myoelbow_1dof6muscles.xml.
Each model runs with its own timestep and integrator (as shipped), constant controls of 0.3 on every
muscle actuator, from the default pose; mj_step in a Python loop and, as the fair figure, mujoco's
C rollout (mujoco.rollout) which steps without Python in between. armrt: RK4 at 1 ms and Euler at
0.1 ms, Arm.step(n) (loop in C++).

What limits the comparison (also in docs/benchmarks.md): MuJoCo's muscles have rigid tendons and no
contraction state (the force is an algebraic function of actuator length, velocity and activation; the
only muscle state is activation), the tendon paths are geometric (sites and wrapping) rather than
polynomials, the myoArm has more DOF (hand and fingers) and contact geometry, and the integrators
differ (semi-implicit Euler at the model's timestep versus explicit RK4 / Euler). Cost per muscle per
step divides the whole step by the number of muscles, so it includes the skeleton.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_JSON = ROOT / "bench" / "results" / "mujoco.json"


def make_arm(integrator: str, dt: float, substeps: int | None = 1):
    """armrt.Arm with an explicit number of substeps (1: one step of dt, the paper's setting); None: Arm's default."""
    import armrt
    try:
        return armrt.Arm(integrator=integrator, dt=dt, substeps=substeps)
    except TypeError:  # an armrt without substeps
        return armrt.Arm(integrator=integrator, dt=dt)


def model_paths(tmp: Path) -> dict:
    """name -> xml path, for the models whose packages are installed."""
    import importlib.util

    out = {}
    spec = importlib.util.find_spec("myo_sim")
    if spec is None:
        return out
    myo_sim = Path(spec.origin).parent / "models"
    ms = importlib.util.find_spec("myosuite")
    if ms is not None:
        arm_dir = Path(ms.origin).parent / "envs" / "myo" / "assets" / "arm"
        if (arm_dir / "myoarm.xml").exists():
            shutil.copytree(arm_dir, tmp / "arm")
            (tmp / "myo_sim").symlink_to(myo_sim, target_is_directory=True)
            out["myoArm"] = tmp / "arm" / "myoarm.xml"
    for name, f in (("myoElbow_2dof6muscles", "myoelbow_2dof6muscles.xml"), ("myoElbow_1dof6muscles", "myoelbow_1dof6muscles.xml")):
        p = myo_sim / "legacy" / "elbow" / f
        if p.exists():
            out[name] = p
    return out


def bench_mujoco(path: Path, seconds: float, reps: int) -> dict:
    import mujoco

    m = mujoco.MjModel.from_xml_path(str(path))
    d = mujoco.MjData(m)
    muscles = [i for i in range(m.nu) if m.actuator_dyntype[i] == mujoco.mjtDyn.mjDYN_MUSCLE
               or m.actuator_gaintype[i] == mujoco.mjtGain.mjGAIN_MUSCLE]
    nsteps = int(round(seconds / m.opt.timestep))
    ctrl = np.zeros(m.nu)
    ctrl[muscles] = 0.3

    def reset():
        mujoco.mj_resetData(m, d)
        d.ctrl[:] = ctrl
        mujoco.mj_forward(m, d)

    # Python loop of mj_step.
    walls = []
    for _ in range(reps):
        reset()
        t0 = time.perf_counter()
        for _ in range(nsteps):
            mujoco.mj_step(m, d)
        walls.append(time.perf_counter() - t0)
    py_wall = float(np.median(walls))
    # C rollout (no Python between steps), if available.
    c_wall = None
    try:
        from mujoco import rollout

        reset()
        state0 = np.empty(mujoco.mj_stateSize(m, mujoco.mjtState.mjSTATE_FULLPHYSICS))
        mujoco.mj_getState(m, d, state0, mujoco.mjtState.mjSTATE_FULLPHYSICS)
        controls = np.tile(ctrl, (nsteps, 1))[None]
        cw = []
        for _ in range(reps):
            t0 = time.perf_counter()
            rollout.rollout(m, d, state0[None], controls)
            cw.append(time.perf_counter() - t0)
        c_wall = float(np.median(cw))
    except Exception as exc:  # noqa: BLE001
        print(f"  rollout unavailable for {path.name}: {exc}", file=sys.stderr)
    wall = c_wall if c_wall is not None else py_wall
    n_mus = max(1, len(muscles))
    step_ns = wall / nsteps * 1e9
    return {"file": str(path.name), "nq": m.nq, "nv": m.nv, "nu": m.nu, "muscles": len(muscles),
            "tendons": m.ntendon, "na": m.na, "ngeom": m.ngeom, "neq": m.neq, "timestep": m.opt.timestep,
            "integrator": mujoco.mjtIntegrator(m.opt.integrator).name, "sim_s": seconds, "steps": nsteps,
            "wall_python_loop_s": py_wall, "wall_rollout_s": c_wall, "step_ns": step_ns,
            "steps_per_s": nsteps / wall, "ns_per_muscle_step": step_ns / n_mus, "real_time_factor": seconds / wall,
            "mujoco": mujoco.__version__}


def bench_armrt(seconds: float, reps: int) -> dict:
    import armrt

    out = {}
    # RK4 in its 6 validated substeps per 1 ms: one 1 ms RK4 step is refused (unstable even at rest).
    for integ, dt, substeps in (("ros2", 1e-3, 1), ("rk4", 1e-3, 6), ("euler", 1e-4, 1)):
        arm = make_arm(integ, dt, substeps)
        n = int(round(seconds / dt))
        walls = []
        for _ in range(reps):
            arm.reset()
            arm.set_excitation({"rotator_cuff": 0.05, "elbow_flexors": 0.3})
            t0 = time.perf_counter()
            arm.step(n)
            walls.append(time.perf_counter() - t0)
        wall = float(np.median(walls))
        step_ns = wall / n * 1e9
        out[f"armrt_{integ}"] = {"muscles": arm.n_elements, "nq": 5, "timestep": dt, "integrator": integ.upper(),
                                 "sim_s": seconds, "steps": n, "step_ns": step_ns, "steps_per_s": n / wall,
                                 "ns_per_muscle_step": step_ns / arm.n_elements, "real_time_factor": seconds / wall,
                                 "substeps": substeps,
                                 "ns_per_muscle_derivative": step_ns / arm.n_elements / ({"rk4": 4, "ros2": 2}.get(integ, 1) * substeps)}
    return out


def markdown(out: dict) -> str:
    lines = ["| model | DOF (nq) | muscles | integrator, dt | steps/s | ns per step | ns per muscle per step | real-time factor |",
             "|---|---:|---:|---|---:|---:|---:|---:|"]
    for name, r in out["models"].items():
        lines.append(f"| {name} | {r['nq']} | {r['muscles']} | {r['integrator']}, {r['timestep'] * 1e3:g} ms | "
                     f"{r['steps_per_s']:.0f} | {r['step_ns']:.0f} | {r['ns_per_muscle_step']:.1f} | {r['real_time_factor']:.0f} |")
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--json", type=Path, default=DEFAULT_JSON)
    ap.add_argument("--seconds", type=float, default=2.0, help="simulated seconds per run")
    ap.add_argument("--reps", type=int, default=5)
    args = ap.parse_args(argv)
    out = {"machine": {"cpus": os.cpu_count(), "load_avg": os.getloadavg(), "note": "shared machine"}, "models": {}}
    try:
        import mujoco  # noqa: F401
    except ImportError as exc:
        out["error"] = f"mujoco not importable: {exc} (pip install mujoco myo-sim; pip install --no-deps myosuite)"
        print(out["error"], file=sys.stderr)
    else:
        with tempfile.TemporaryDirectory() as tmp:
            paths = model_paths(Path(tmp))
            if not paths:
                out["error"] = "myo-sim not installed (pip install myo-sim): no MyoSuite models"
                print(out["error"], file=sys.stderr)
            for name, p in paths.items():
                try:
                    out["models"][name] = bench_mujoco(p, args.seconds, args.reps)
                except Exception as exc:  # noqa: BLE001
                    out.setdefault("failed", {})[name] = str(exc)
                    print(f"{name}: {exc}", file=sys.stderr)
    out["models"].update(bench_armrt(args.seconds, args.reps))
    out["limits"] = ("MuJoCo muscles: rigid tendons, no contraction (fibre-length) state, force algebraic in actuator "
                     "length/velocity/activation; geometric tendon paths (sites, wrapping) instead of polynomials; "
                     "myoArm has more DOF (hand, fingers) and contact geometry; semi-implicit Euler at the model "
                     "timestep vs explicit RK4/Euler. Cost per muscle divides the whole step, skeleton included.")
    args.json.parent.mkdir(parents=True, exist_ok=True)
    args.json.write_text(json.dumps(out, indent=1) + "\n")
    print(markdown(out))
    print(f"\nwrote {args.json}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
