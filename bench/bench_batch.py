"""Many arms at once: ArmBatch throughput and thread scaling, the vector env against Gymnasium's
SyncVectorEnv, and MuJoCo's myoArm batch rollout, all in one run (about 1-2 minutes).

    python -m bench.bench_batch [--json bench/results/batch.json] [--md bench/results/batch.md] [--quick]

armrt: ArmBatch(n) with Arm's default integrator, dt and substeps, held excitations (rotator cuff
0.05, elbow flexors 0.3, as the other benchmarks), n = 1, 8, 64, 512 arms on 1 and 2 threads; each
figure is the best of `reps` runs of about `arm_steps` arm-steps from rest. arm-steps/s counts
control steps (dt of simulated time each) summed over arms; each run lasts about 0.3 s. Scaling efficiency = (2-thread rate /
1-thread rate) / 2 (threads are capped at the number of arms, so n = 1 runs on one thread either
way); CPU-time efficiency: arm-steps per CPU-second of the process, 2 threads over 1. Per core: simulated seconds per wall second divided by the threads used.

Vector env: armrt/Reach-v0 as ArmVectorEnv (the batch, threads 1 and 2) and as SyncVectorEnv over
single ArmEnvs, random actions; env-steps/s = num_envs x vector steps per wall second.

MuJoCo: myosuite's myoArm (as bench/bench_mujoco.py finds it, from PyPI wheels) at its native
2 ms step, mujoco.rollout of `nbatch` trajectories with constant 0.3 on every muscle, one MjData
per thread (1 and 2 threads). Skipped with a message when mujoco/myo-sim/myosuite are missing
(pip install mujoco myo-sim; pip install --no-deps myosuite).

The machine may be shared: figures are noisy; the JSON records the load average, the command and, per run, the
cores other processes kept busy (bench/_contention.py): a 2-thread speed-up measured while they took more than a
quarter of a core is marked contended, not reported as scaling.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from bench._contention import CONTENDED_CORES, Window, contended

ROOT = Path(__file__).resolve().parent.parent
RESULTS = ROOT / "bench" / "results"
NS = (1, 8, 64, 512)
THREADS = (1, 2)


def bench_armrt(ns, threads, seconds: float, reps: int) -> dict:
    """Each run lasts about `seconds` on one thread (steps per arm calibrated on a short run)."""
    from armrt import ArmBatch

    out = {}
    for n in ns:
        batch = ArmBatch(n)
        batch.threads = 1
        batch.set_excitation({"rotator_cuff": 0.05, "elbow_flexors": 0.3})
        k0 = max(1, 2000 // n)
        t0 = time.perf_counter()
        batch.step(k0, outputs=False)
        per_step = (time.perf_counter() - t0) / k0
        k = max(1, int(round(seconds / per_step)))
        for t in threads:
            batch.threads = t
            walls, cpus, others = [], [], []
            for _ in range(reps):
                batch.reset()
                batch.set_excitation({"rotator_cuff": 0.05, "elbow_flexors": 0.3})
                c0 = time.process_time()
                with Window() as w:
                    batch.step(k, outputs=False)
                walls.append(w.wall_s)
                cpus.append(time.process_time() - c0)
                others.append(w.other_cores)
            if batch.diverged.any():
                raise RuntimeError(f"arms diverged in the benchmark: {batch.errors}")
            best = int(np.argmin(walls))
            wall, cpu = walls[best], cpus[best]
            rate = n * k / wall
            out[f"n{n}_t{t}"] = {"n": n, "threads": t, "steps_per_arm": k, "wall_s": wall, "cpu_s": cpu,
                                 "arm_steps_per_s": rate, "arm_steps_per_cpu_s": n * k / cpu,
                                 "sim_s_per_wall_s_per_core": rate * batch.dt / t,
                                 "other_processes_cores": others[best]}
        meta = {"integrator": batch.integrator, "dt": batch.dt, "substeps": batch.substeps,
                "elements": batch.n_elements, "dofs": batch.n_dofs}
    for n in ns:
        if all(f"n{n}_t{t}" in out for t in (1, 2)):
            r1, r2 = out[f"n{n}_t1"]["arm_steps_per_s"], out[f"n{n}_t2"]["arm_steps_per_s"]
            out[f"n{n}_t2"]["speedup"] = r2 / r1
            out[f"n{n}_t2"]["scaling_efficiency"] = r2 / r1 / 2
            out[f"n{n}_t2"]["contended"] = contended(out[f"n{n}_t1"]["other_processes_cores"],
                                                     out[f"n{n}_t2"]["other_processes_cores"])
            # Robust to other processes taking a core: work per CPU-second of this process (threads
            # spinning at barriers count as CPU time, so parallel overhead still shows).
            out[f"n{n}_t2"]["cpu_time_efficiency"] = out[f"n{n}_t2"]["arm_steps_per_cpu_s"] / out[f"n{n}_t1"]["arm_steps_per_cpu_s"]
    return {"runs": out, **meta}


def bench_vector_env(ns, threads, vector_steps: int) -> dict:
    import gymnasium as gym  # noqa: F401
    from gymnasium.vector import SyncVectorEnv

    import armrt.gym as ag

    def timed(env, n, steps):
        env.reset(seed=0)
        rng = np.random.default_rng(0)
        actions = rng.uniform(0, 1, (steps, n) + env.single_action_space.shape).astype(np.float32)
        env.step(actions[0])  # warm-up
        t0 = time.perf_counter()
        for a in actions[1:]:
            env.step(a)
        return n * (steps - 1) / (time.perf_counter() - t0)

    out = {}
    for n in ns:
        sync = SyncVectorEnv([lambda: ag.ReachEnv() for _ in range(n)])
        out[f"sync_n{n}"] = {"n": n, "env": "SyncVectorEnv(ArmEnv)", "env_steps_per_s": timed(sync, n, vector_steps)}
        sync.close()
        for t in threads:
            vec = ag.ReachVectorEnv(n, threads=t)
            rate = timed(vec, n, vector_steps)
            out[f"vector_n{n}_t{t}"] = {"n": n, "threads": t, "env": "ArmVectorEnv", "env_steps_per_s": rate,
                                        "vs_sync": rate / out[f"sync_n{n}"]["env_steps_per_s"]}
    env = ag.ReachEnv()
    return {"runs": out, "env_dt": env.task.env_dt, "frame_skip": env.task.frame_skip, "task": "armrt/Reach-v0"}


def bench_myoarm(nbatch: int, sim_s: float, threads, reps: int) -> dict:
    try:
        import mujoco
        from mujoco import rollout
    except ImportError as exc:
        return {"skipped": f"mujoco not importable ({exc}): pip install mujoco myo-sim; pip install --no-deps myosuite"}
    from bench.bench_mujoco import model_paths

    with tempfile.TemporaryDirectory() as tmp:
        path = model_paths(Path(tmp)).get("myoArm")
        if path is None:
            return {"skipped": "myoArm not found (pip install myo-sim; pip install --no-deps myosuite)"}
        m = mujoco.MjModel.from_xml_path(str(path))
    muscles = [i for i in range(m.nu) if m.actuator_dyntype[i] == mujoco.mjtDyn.mjDYN_MUSCLE
               or m.actuator_gaintype[i] == mujoco.mjtGain.mjGAIN_MUSCLE]
    d = mujoco.MjData(m)
    mujoco.mj_resetData(m, d)
    mujoco.mj_forward(m, d)
    state0 = np.empty(mujoco.mj_stateSize(m, mujoco.mjtState.mjSTATE_FULLPHYSICS))
    mujoco.mj_getState(m, d, state0, mujoco.mjtState.mjSTATE_FULLPHYSICS)
    nstep = int(round(sim_s / m.opt.timestep))
    ctrl = np.zeros(m.nu)
    ctrl[muscles] = 0.3
    control = np.tile(ctrl, (nbatch, nstep, 1))
    initial = np.tile(state0, (nbatch, 1))
    out = {"model": "myoArm", "file": path.name, "nq": m.nq, "muscles": len(muscles), "timestep": m.opt.timestep,
           "integrator": mujoco.mjtIntegrator(m.opt.integrator).name, "nbatch": nbatch, "nstep": nstep,
           "mujoco": mujoco.__version__, "runs": {}}
    for t in threads:
        datas = [mujoco.MjData(m) for _ in range(t)]
        walls, others = [], []
        for _ in range(reps):
            with Window() as w:
                rollout.rollout(m, datas, initial, control)
            walls.append(w.wall_s)
            others.append(w.other_cores)
        best = int(np.argmin(walls))
        wall = walls[best]
        steps = nbatch * nstep
        out["runs"][f"t{t}"] = {"threads": t, "wall_s": wall, "steps_per_s": steps / wall,
                                "sim_s_per_wall_s_per_core": nbatch * sim_s / wall / t,
                                "other_processes_cores": others[best]}
    if "t1" in out["runs"] and "t2" in out["runs"]:
        out["runs"]["t2"]["scaling_efficiency"] = out["runs"]["t2"]["steps_per_s"] / out["runs"]["t1"]["steps_per_s"] / 2
        out["runs"]["t2"]["contended"] = contended(out["runs"]["t1"]["other_processes_cores"],
                                                   out["runs"]["t2"]["other_processes_cores"])
    return out


def _cores(run: dict) -> str:
    c = run.get("other_processes_cores")
    return "?" if c is None else f"{c:.2f}"


def markdown(res: dict) -> str:
    a = res["armrt"]
    lines = [f"Command: `{res['command']}` ({res['date']}, load average {res['load_avg'][0]:.2f} on "
             f"{res['cpus']} CPUs: a shared machine, figures are noisy).", "",
             f"### ArmBatch: arm-steps per second ({a['integrator']}, dt {a['dt'] * 1e3:g} ms, {a['substeps']} substeps, "
             f"{a['elements']} elements)", "",
             "| arms | 1 thread | 2 threads | speed-up | scaling efficiency | CPU-time efficiency | sim s / wall s per core (2 threads) | other processes (cores, 1 / 2 threads) |",
             "|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for n in NS:
        r1, r2 = a["runs"].get(f"n{n}_t1"), a["runs"].get(f"n{n}_t2")
        if r1 and r2:
            # A run that shared its cores is no scaling figure: the speed-up is withheld, not printed low.
            speedup, eff = (("contended", "-") if r2.get("contended")
                            else (f"{r2['speedup']:.2f}x", f"{r2['scaling_efficiency']:.0%}"))
            lines.append(f"| {n} | {r1['arm_steps_per_s']:.0f} | {r2['arm_steps_per_s']:.0f} | {speedup} | "
                         f"{eff} | {r2['cpu_time_efficiency']:.0%} | {r2['sim_s_per_wall_s_per_core']:.1f} | "
                         f"{_cores(r1)} / {_cores(r2)} |")
    lines += ["", "Scaling efficiency = (2-thread rate / 1-thread rate) / 2, by the wall clock. CPU-time efficiency = "
                  "arm-steps per CPU-second of this process at 2 threads / at 1 thread: it does not suffer when another "
                  "process takes a core, but still counts threads spinning at barriers. Other processes: the cores the "
                  "rest of the machine kept busy during the run (/proc/stat less this process, bench/_contention.py); "
                  f"above {CONTENDED_CORES} in either run the speed-up is marked contended and is no scaling figure."]
    v = res.get("vector_env")
    if v:
        lines += ["", f"### Vector env ({v['task']}, env_dt {v['env_dt'] * 1e3:g} ms = {v['frame_skip']} arm steps): "
                      "env-steps per second", "",
                  "| envs | SyncVectorEnv | ArmVectorEnv 1 thread | ArmVectorEnv 2 threads | ratio (2 threads / sync) |",
                  "|---:|---:|---:|---:|---:|"]
        for key, r in v["runs"].items():
            if key.startswith("sync_n"):
                n = r["n"]
                v1, v2 = v["runs"].get(f"vector_n{n}_t1"), v["runs"].get(f"vector_n{n}_t2")
                lines.append(f"| {n} | {r['env_steps_per_s']:.0f} | {v1['env_steps_per_s']:.0f} | "
                             f"{v2['env_steps_per_s']:.0f} | {v2['vs_sync']:.2f}x |")
    m = res.get("mujoco", {})
    lines += ["", "### Per core against MuJoCo myoArm (batch rollout)", ""]
    if m.get("runs", {}).get("t2", {}).get("contended"):
        lines += ["MuJoCo's 2-thread run shared its cores with other processes "
                  f"({_cores(m['runs']['t1'])} / {_cores(m['runs']['t2'])} cores): its per-core figure is not a scaling figure.", ""]
    if "skipped" in m:
        lines.append(f"MuJoCo skipped: {m['skipped']}")
    else:
        lines += ["| simulator | threads | steps/s | sim s / wall s per core |", "|---|---:|---:|---:|"]
        big = a["runs"].get(f"n{NS[-1]}_t2") or a["runs"].get(f"n{NS[-1]}_t1")
        for t in THREADS:
            r = m["runs"].get(f"t{t}")
            if r:
                lines.append(f"| MuJoCo {m['mujoco']} myoArm ({m['nq']} DOF, {m['muscles']} muscles, {m['integrator']} "
                             f"{m['timestep'] * 1e3:g} ms), {m['nbatch']} rollouts | {t} | {r['steps_per_s']:.0f} | "
                             f"{r['sim_s_per_wall_s_per_core']:.1f} |")
            ra = a["runs"].get(f"n{NS[-1]}_t{t}")
            if ra:
                lines.append(f"| armrt ArmBatch({NS[-1]}) ({a['dofs']} DOF, {a['elements']} elements, {a['integrator']} "
                             f"{a['dt'] * 1e3:g} ms x {a['substeps']}) | {t} | {ra['arm_steps_per_s']:.0f} | "
                             f"{ra['sim_s_per_wall_s_per_core']:.1f} |")
        ratios = res.get("ratio_to_mujoco_per_core", {})
        if big and ratios:
            shown = ", ".join(f"**{r:.2f}x** on {k[1:]} thread{'s' if k != 't1' else ''}" for k, r in ratios.items())
            lines += ["", f"Ratio armrt ArmBatch({NS[-1]}) / myoArm rollout, simulated seconds per wall second per core: "
                          f"{shown}. "
                          f"The models differ: myoArm has {m['nq']} DOF (shoulder girdle, hand, fingers), {m['muscles']} "
                          "muscles with rigid tendons and no fibre-length state, geometric tendon paths (sites, "
                          f"wrapping) and contacts, {m['integrator']} at {m['timestep'] * 1e3:g} ms; armrt has "
                          f"{a['dofs']} DOF, {a['elements']} Hill elements with elastic tendons (a fibre-length state each) and polynomial "
                          f"paths, no contacts, integrated by {a['integrator']} ({a['substeps']} step(s) per {a['dt'] * 1e3:g} ms)."]
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--json", type=Path, default=RESULTS / "batch.json")
    ap.add_argument("--md", type=Path, default=RESULTS / "batch.md")
    ap.add_argument("--quick", action="store_true", help="fewer steps (a smoke run, not for the record)")
    args = ap.parse_args(argv)
    run_s, reps, vsteps, nbatch, sim_s = (0.01, 1, 4, 8, 0.1) if args.quick else (0.3, 5, 21, 64, 0.5)
    t_start = time.perf_counter()
    res = {"command": "python -m bench.bench_batch" + (" --quick" if args.quick else ""),
           "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "cpus": os.cpu_count(),
           "load_avg": os.getloadavg()}
    print("armrt batch ...", file=sys.stderr)
    res["armrt"] = bench_armrt(NS, THREADS, run_s, reps)
    print("vector env ...", file=sys.stderr)
    res["vector_env"] = bench_vector_env((8, 64), THREADS, vsteps)
    print("MuJoCo myoArm rollout ...", file=sys.stderr)
    res["mujoco"] = bench_myoarm(nbatch, sim_s, THREADS, reps)
    m = res["mujoco"]
    if "runs" in m:
        a = res["armrt"]["runs"]
        res["ratio_to_mujoco_per_core"] = {
            f"t{t}": a[f"n{NS[-1]}_t{t}"]["sim_s_per_wall_s_per_core"] / m["runs"][f"t{t}"]["sim_s_per_wall_s_per_core"]
            for t in THREADS if f"t{t}" in m["runs"] and f"n{NS[-1]}_t{t}" in a}
    res["wall_s"] = time.perf_counter() - t_start
    md = markdown(res)
    args.json.parent.mkdir(parents=True, exist_ok=True)
    args.json.write_text(json.dumps(res, indent=1) + "\n")
    args.md.write_text(md)
    print(md)
    print(f"wrote {args.json} and {args.md} ({res['wall_s']:.0f} s)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
