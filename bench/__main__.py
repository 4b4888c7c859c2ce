"""Benchmark harness: one command for every comparison, results under bench/results/.

    python -m bench all [--quick]     # engine, integrators, das3, OpenSim (das2, das3), MuJoCo/MyoSuite,
                                      # scaling, batch, then the report
    python -m bench engine|integrators|das3|opensim|opensim-das3|mujoco|scaling|batch|guard|report

Needs `armrt` importable (pip install ., or PYTHONPATH=python with _core*.so copied there), the C++
tools built (ninja armrt_bench armrt_bench_scaling) for the engine and scaling figures, opensim and
../shared/reference for the OpenSim comparison, mujoco + myo-sim (+ myosuite --no-deps) for MuJoCo.
A part whose requirements are missing is skipped with a message; the report uses whatever JSON exists.

Writes bench/results/{engine,opensim,opensim_das3,mujoco,scaling}.json (+ opensim_das3.npz), summary.json,
summary.md (the markdown tables), opensim.png and opensim_das3.png (joint-angle trajectories, armrt against
OpenSim) and scaling.png.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
RESULTS = ROOT / "bench" / "results"


def _load(name: str) -> dict | None:
    p = RESULTS / f"{name}.json"
    try:
        return json.loads(p.read_text()) if p.exists() else None
    except json.JSONDecodeError:
        return None


def plot_opensim(osr: dict, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    tr = osr["trajectories_deg"]
    t = tr["time"]
    dofs = ["GHy", "GHz", "GHyy", "ELx", "PSy"]
    fig, axes = plt.subplots(1, 5, figsize=(15, 3.2), sharex=True)
    style = {"armrt_ros2_1ms": "-", "armrt_rk4_1ms_6substeps": "-", "armrt_euler_0.1ms": ":", "armrt_cvode": "--", "opensim_rkm_default": "-",
             "opensim_rkm_fixed_1ms": "-."}
    for name, q in tr.items():
        if name == "time":
            continue
        for j, ax in enumerate(axes):
            ax.plot(t, [row[j] for row in q], style.get(name, "-"), lw=1.4 if "opensim" in name else 1.0,
                    label=name if j == 0 else None)
    for j, ax in enumerate(axes):
        ax.set_title(dofs[j])
        ax.set_xlabel("t (s)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("angle (deg)")
    fig.legend(loc="upper center", ncol=5, fontsize=8, bbox_to_anchor=(0.5, 1.02))
    fig.tight_layout(rect=(0, 0, 1, 0.9))
    fig.savefig(path, dpi=80)
    plt.close(fig)


def plot_opensim_das3(npz_path: Path, path: Path) -> None:
    """The 11 das3 coordinates: OpenSim (default integrator) and armrt, from opensim_das3.npz."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    d = np.load(npz_path)
    names = [str(n) for n in d["coordinates"]]
    fig, axes = plt.subplots(3, 4, figsize=(14, 8), sharex=True)
    for j, ax in enumerate(axes.flat):
        if j >= len(names):
            ax.axis("off")
            continue
        ax.plot(d["opensim_default_t"], np.degrees(d["opensim_default_q"][:, j]), "-", lw=1.4,
                label="OpenSim 4.6 (RKM default)")
        if "armrt_q" in d and d["armrt_q"].shape[1] == len(names):
            ax.plot(d["armrt_t"], np.degrees(d["armrt_q"][:, j]), "--", lw=1.0, label="armrt das3")
        ax.set_title(names[j])
        ax.grid(alpha=0.3)
    for ax in axes[-1]:
        ax.set_xlabel("t (s)")
    axes[0, 0].set_ylabel("angle (deg)")
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="upper center", ncol=2)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    fig.savefig(path, dpi=80)
    plt.close(fig)


def report() -> int:
    eng, osr, mj, sc = _load("engine"), _load("opensim"), _load("mujoco"), _load("scaling")
    summary: dict = {"timestamp": time.strftime("%Y-%m-%dT%H:%M:%S"), "cpus": os.cpu_count(),
                     "load_avg": os.getloadavg(), "note": "shared machine (2 cores, other builds running): medians over repeats"}
    md = ["# armrt benchmark summary", "",
          f"Compiled {summary['timestamp']} by `python -m bench report` (which every `python -m bench ...` run ends "
          "with) from the bench/results JSON files: each section is from the last run of its own bench (`python -m "
          f"bench all` runs them all), on a shared {os.cpu_count()}-core machine (other engineers' builds running); "
          "every figure is a median over repeats; expect 10-30 % noise.", ""]
    if eng and eng.get("cpp"):
        c = eng["cpp"]
        summary["engine"] = {k: c[k]["median"] for k in ("forward", "ros2_step", "rk4_step", "euler_step") if k in c}
        md += ["## Engine (C++, median ns)", "", "| item | median | p99 | max |", "|---|---:|---:|---:|"]
        md += [f"| {k} | {c[k]['median']:.0f} | {c[k]['p99']:.0f} | {c[k]['max']:.0f} |"
               for k in ("forward", "forward_record", "muscle_paths", "mass_matrix", "euler_step", "rk4_step", "ros2_step") if k in c]
        md.append("")
    integ = _load("integrators")
    if integ:
        from bench.bench_integrators import markdown as integ_md

        summary["integrators"] = {k: integ[k] for k in ("cost", "tasks", "forward_vs_baseline") if k in integ}
        if "random" in integ:
            summary["integrators"]["random"] = integ["random"]["summary"]
        md += integ_md(integ).replace("# Integrators side by side", "## Integrators side by side").replace("\n## ", "\n### ").splitlines()
        md.append("")
    if osr:
        from bench.bench_opensim import markdown as os_md

        summary["opensim"] = {"duration_s": osr["duration_s"], "speed_ratio": osr["speed_ratio"],
                              "real_time_factor": {k: v["real_time_factor"] for k, v in osr["runs"].items()},
                              "trajectory_rms_deg": {k: v["rms_deg"] for k, v in osr["trajectory_rms"].items()}}
        md += ["## Against OpenSim 4.6 (das3.osim reduced to the same 5-DOF, 102-element problem)", "", os_md(osr), ""]
        try:
            plot_opensim(osr, RESULTS / "opensim.png")
            md += ["![trajectories](opensim.png)", ""]
        except Exception as exc:  # noqa: BLE001
            print(f"plot failed: {exc}", file=sys.stderr)
    osd3 = _load("opensim_das3")
    if osd3:
        from bench.bench_opensim_das3 import markdown as osd3_md

        summary["opensim_das3"] = {"duration_s": osd3["duration_s"],
                                   "real_time_factor": {k: v["real_time_factor"] for k, v in osd3["runs"].items()},
                                   "armrt": {k: v for k, v in (osd3.get("armrt") or {}).items()
                                             if k in ("armrt_model", "speed_ratio", "max_abs_deg", "error")}}
        md += ["## das3 against OpenSim 4.6 (das3.osim, girdle free, conoid and scapulothoracic contact added)", "",
               osd3_md(osd3), ""]
        try:
            plot_opensim_das3(RESULTS / "opensim_das3.npz", RESULTS / "opensim_das3.png")
            md += ["![das3 trajectories](opensim_das3.png)", ""]
        except Exception as exc:  # noqa: BLE001
            print(f"das3 plot failed: {exc}", file=sys.stderr)
    if mj:
        from bench.bench_mujoco import markdown as mj_md

        summary["mujoco"] = {k: {"steps_per_s": v["steps_per_s"], "ns_per_muscle_step": v["ns_per_muscle_step"],
                                 "real_time_factor": v["real_time_factor"]} for k, v in mj["models"].items()}
        md += ["## Against MuJoCo / MyoSuite", "", mj_md(mj), "", f"Limits: {mj.get('limits', '')}", ""]
        if mj.get("error"):
            md += [f"MuJoCo part incomplete: {mj['error']}", ""]
    if sc:
        from bench.bench_scaling import markdown as sc_md

        summary["scaling_fits"] = sc.get("fits")
        md += ["## Scaling with elements and integrator", "", sc_md(sc), "", "![scaling](scaling.png)", ""]
    (RESULTS / "summary.json").write_text(json.dumps(summary, indent=1) + "\n")
    (RESULTS / "summary.md").write_text("\n".join(md) + "\n")
    print("\n".join(md))
    print(f"\nwrote {RESULTS / 'summary.md'} and summary.json")
    return 0


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m bench", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=["all", "engine", "integrators", "das3", "opensim", "opensim-das3", "mujoco",
                                     "scaling", "batch", "guard", "report"])
    ap.add_argument("--quick", action="store_true", help="shorter runs (smoke test; figures noisier)")
    args = ap.parse_args(argv)
    if str(ROOT) not in sys.path:
        sys.path.insert(0, str(ROOT))
    RESULTS.mkdir(parents=True, exist_ok=True)
    q = args.quick
    steps = {
        "engine": lambda: __import__("bench.bench_engine", fromlist=["main"]).main(["--reps", "2000" if q else "20000"]),
        "opensim": lambda: __import__("bench.bench_opensim", fromlist=["main"]).main(["--quick"] if q else []),
        "opensim-das3": lambda: __import__("bench.bench_opensim_das3", fromlist=["main"]).main(["--quick"] if q else []),
        "mujoco": lambda: __import__("bench.bench_mujoco", fromlist=["main"]).main(["--reps", "2" if q else "5"]),
        "scaling": lambda: __import__("bench.bench_scaling", fromlist=["main"]).main(
            ["--reps", "3000" if q else "20000"] + (["--no-subsets"] if q else [])),
        "batch": lambda: __import__("bench.bench_batch", fromlist=["main"]).main(["--quick"] if q else []),
        "guard": lambda: __import__("bench.ci_guard", fromlist=["main"]).main([]),
        "integrators": lambda: __import__("bench.bench_integrators", fromlist=["main"]).main(
            ["--quick"] if q else []),
        "das3": lambda: __import__("bench.bench_das3", fromlist=["main"]).main(
            ["--reps", "2000", "--duration", "2"] if q else []),
    }
    if args.what == "report":
        return report()
    names = (["engine", "integrators", "das3", "opensim", "opensim-das3", "mujoco", "scaling", "batch"]
             if args.what == "all" else [args.what])
    rc = 0
    for name in names:
        print(f"\n=== {name} ===", flush=True)
        try:
            r = steps[name]()
        except Exception as exc:  # noqa: BLE001 - one failing part must not lose the others
            print(f"{name}: failed: {type(exc).__name__}: {exc}", file=sys.stderr)
            r = 1
        rc = rc or (r or 0)
    if args.what in ("all", "engine", "integrators", "opensim", "opensim-das3", "mujoco", "scaling"):
        print("\n=== report ===")
        report()
    return rc


if __name__ == "__main__":
    sys.exit(main())
