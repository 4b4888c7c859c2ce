"""das3 (11 DOF, 138 elements, moving girdle) beside das2 (5 DOF, 102 elements) in one run: the cost of
one ROS2 step at 1 ms and of each forward() stage (armrt_bench --model, C++, pinned), and the
real-time factor of Arm.simulate (Python, recording every step and every 10th); and das3's settling from
equilibrium.mat and ROS2 at 1 ms against CVODE on four protocols from the settled arm.

    python -m bench.bench_das3 [--reps 20000] [--duration 10]

Writes bench/results/das3.json and das3.md. The excitation is armrt_bench's (rotator cuff 0.05, elbow
flexors 0.3) for the C++ items and, for Arm.simulate, the same held from the settled arm (das3 settles
from equilibrium.mat for 3 s first, so that the run is not its settling transient).
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

import numpy as np

from .bench_engine import run_cpp

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "bench" / "results"
MODELS = ("das2", "das3")
STAGES = [("muscle_paths", "paths (polynomials)"), ("stage_muscles", "muscles"),
          ("stage_passive_joints", "passive joints"), ("stage_girdle", "girdle contact + conoid"),
          ("stage_skeleton", "skeleton (M, b, Cholesky)"), ("forward", "forward() total")]


def cpp_costs(model: str, reps: int) -> dict | None:
    data = run_cpp(reps, model)
    return data["cpp"] if data else None


def simulate_rtf(model: str, duration: float) -> dict:
    import armrt
    out = {}
    for every in (1, 10):
        walls = []
        for _ in range(3):
            arm = armrt.Arm(model=model)
            if model == "das3":
                arm.simulate(np.zeros(arm.model.n_elements), 3.0, record_every=1000)
            t0 = time.perf_counter()
            arm.simulate({"rotator_cuff": 0.05, "elbow_flexors": 0.3}, duration, record_every=every)
            walls.append(time.perf_counter() - t0)
        out[f"record_every_{every}"] = duration / min(walls)
    return out


ACCURACY_PROTOCOLS = {
    "deltoid 0.3 + rotator cuff 0.2": {"deltoid": 0.3, "rotator_cuff": 0.2},
    "elbow flexors 0.4": {"elbow_flexors": 0.4},
    "serratus anterior + trapezius 0.3": {"serratus_anterior": 0.3, "trapezius": 0.3},
    "all 138 elements 0.2": {"all": 0.2},
}


def das3_accuracy(duration: float = 1.0) -> dict:
    """Settling (CVODE, 3 s from equilibrium.mat) and ROS2 1 ms against CVODE from the settled arm."""
    import armrt
    arm = armrt.Arm(model="das3", integrator="cvode")
    r = arm.simulate(np.zeros(arm.model.n_elements), 3.0, record_every=10)
    state = arm.get_state()
    out = {"settled_minus_rest_deg": dict(zip(arm.model.dof_names, np.degrees(r.q[-1] - r.q[0]).round(3).tolist())),
           "settling_contact_distance_mm": {"min": float(r.contact_distance.min() * 1e3),
                                            "max": float(r.contact_distance.max() * 1e3)},
           "settling_conoid_tension_N": {"min": float(r.conoid_tension.min()),
                                         "after_0.5s": [float(r.conoid_tension[r.time >= 0.5].min()),
                                                        float(r.conoid_tension[r.time >= 0.5].max())]},
           "protocols": {}, "hand_loads": {}}
    for name, groups in ACCURACY_PROTOCOLS.items():
        res = {}
        for integ in ("ros2", "cvode"):
            a = armrt.Arm(model="das3", integrator=integ)
            a.set_state(state)
            u = np.zeros(a.model.n_elements)
            for g, v in groups.items():
                u[list(range(a.model.n_elements)) if g == "all" else list(a.model.indices(g))] = v
            res[integ] = a.simulate(u, duration)
        diff = np.degrees(np.abs(res["ros2"].q - res["cvode"].q)).max(0)
        cd = res["cvode"].contact_distance
        out["protocols"][name] = {"max_diff_deg": float(diff.max()), "worst_dof": a.model.dof_names[int(diff.argmax())],
                                  "girdle_motion_deg": float(np.degrees(np.abs(res["cvode"].q[-1, :6] - res["cvode"].q[0, :6])).max()),
                                  "contact_distance_mm": [float(cd.min() * 1e3), float(cd.max() * 1e3)]}
    # The girdle ranges are a box: how much of it puts the scapula into the thorax (girdle uniform in its
    # ranges, the arm at rest, seed 0).
    rng = np.random.default_rng(0)
    lo, hi = arm.model.dof_ranges.T
    qs = np.tile(arm.model.rest_posture, (3000, 1))
    qs[:, :6] = lo[:6] + rng.random((3000, 6)) * (hi[:6] - lo[:6])
    depth = np.array([arm.girdle_forces(q)["contact_distance"].min() for q in qs])
    out["girdle_box_sample"] = {"postures": 3000, "deeper_than_20mm": int((depth < -0.02).sum()),
                                "within_5mm": int((np.abs(depth) <= 0.005).sum())}
    # Hand loads that pull the scapula off the thorax (0.5 s from the settled arm): ROS2 with 1, 2, 4 substeps.
    for load in HAND_LOADS:
        res = {}
        for integ, sub in (("cvode", 1), ("ros2", 1), ("ros2", 2), ("ros2", 4)):
            a = armrt.Arm(model="das3", integrator=integ, substeps=sub) if integ == "ros2" else armrt.Arm(
                model="das3", integrator=integ)
            a.set_state(state)
            a.set_hand_load(force=load)
            res[(integ, sub)] = a.simulate(np.zeros(a.model.n_elements), 0.5)
        ref = res[("cvode", 1)]
        out["hand_loads"][str(list(load))] = {
            "lift_off_mm": float(max(0.0, ref.contact_distance.max()) * 1e3),
            "max_diff_deg": {f"ros2_x{sub}": float(np.degrees(np.abs(res[("ros2", sub)].q - ref.q)).max())
                             for sub in (1, 2, 4)}}
    return out


HAND_LOADS = [(0.0, 100.0, 0.0), (0.0, 0.0, 100.0), (0.0, 0.0, 300.0)]   # N, thorax frame (y up, z lateral)


def markdown(d: dict) -> str:
    lines = [f"das3 beside das2 (`python -m bench.bench_das3`, {d['date']}, {d['cpus']} CPUs, load "
             f"{d['load_avg'][0]:.1f}); C++ medians in ns, one call each.", "",
             "| item | das2 | das3 | das3 / das2 |", "|---|---|---|---|"]
    c2, c3 = d["models"]["das2"].get("cpp"), d["models"]["das3"].get("cpp")
    if c2 and c3:
        for key, label in STAGES + [("ros2_step", "ROS2 step, 1 ms (two forward() + Jacobian + solves)")]:
            a, b = c2[key]["median"], c3[key]["median"]
            lines.append(f"| {label} | {a:.0f} | {b:.0f} | {b / a:.2f} |" if a > 50 else f"| {label} | {a:.0f} | {b:.0f} | |")
        for m in MODELS:
            c = d["models"][m]["cpp"]
            d["models"][m]["ros2_real_time_factor"] = 1e6 / c["ros2_step"]["median"]
        lines.append(f"| real-time factor of the ROS2 step (1 ms / median) | "
                     f"{d['models']['das2']['ros2_real_time_factor']:.0f}x | "
                     f"{d['models']['das3']['ros2_real_time_factor']:.0f}x | |")
    r2, r3 = d["models"]["das2"]["simulate"], d["models"]["das3"]["simulate"]
    lines.append(f"| Arm.simulate real-time factor, every step recorded | {r2['record_every_1']:.0f}x | "
                 f"{r3['record_every_1']:.0f}x | |")
    lines.append(f"| Arm.simulate real-time factor, every 10th step recorded | {r2['record_every_10']:.0f}x | "
                 f"{r3['record_every_10']:.0f}x | |")
    acc = d.get("das3_accuracy")
    if acc:
        lines += ["", "das3 settled (CVODE, 3 s from equilibrium.mat) minus equilibrium.mat, deg:", "",
                  "| " + " | ".join(acc["settled_minus_rest_deg"]) + " |",
                  "|" + "---|" * len(acc["settled_minus_rest_deg"]),
                  "| " + " | ".join(f"{v:+.1f}" for v in acc["settled_minus_rest_deg"].values()) + " |", "",
                  f"TS/AI signed distance from the thorax while settling: {acc['settling_contact_distance_mm']['min']:.2f} "
                  f"to {acc['settling_contact_distance_mm']['max']:.2f} mm.", "",
                  "ROS2 at 1 ms against CVODE from the settled arm, 1 s each:", "",
                  "| protocol | max difference (deg) | at | girdle motion (deg) | TS/AI distance (mm) |",
                  "|---|---|---|---|---|"]
        for name, p in acc["protocols"].items():
            lines.append(f"| {name} | {p['max_diff_deg']:.3f} | {p['worst_dof']} | {p['girdle_motion_deg']:.1f} | "
                         f"{p['contact_distance_mm'][0]:.2f} to {p['contact_distance_mm'][1]:.2f} |")
        bx = acc["girdle_box_sample"]
        lines += ["", f"Girdle uniform in its ranges (arm at rest, {bx['postures']} postures, seed 0): "
                  f"{bx['deeper_than_20mm']} put TS or AI more than 20 mm inside the thorax, {bx['within_5mm']} "
                  "have the deeper of the two within 5 mm of the surface."]
        c = acc["settling_conoid_tension_N"]
        lines += ["", f"Conoid tension while settling: {c['min']:.0f} N at its lowest, {c['after_0.5s'][0]:.0f}-"
                  f"{c['after_0.5s'][1]:.0f} N after 0.5 s.", "",
                  "Hand loads pulling the scapula off the thorax, 0.5 s from the settled arm, max difference from "
                  "CVODE (deg):", "", "| hand load (N, thorax frame) | lift-off (mm, CVODE) | ROS2 x1 | x2 | x4 |",
                  "|---|---|---|---|---|"]
        for load, h in acc["hand_loads"].items():
            d = h["max_diff_deg"]
            lines.append(f"| {load} | {h['lift_off_mm']:.0f} | {d['ros2_x1']:.2f} | {d['ros2_x2']:.2f} | "
                         f"{d['ros2_x4']:.2f} |")
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m bench.bench_das3", description=__doc__.splitlines()[0])
    ap.add_argument("--reps", type=int, default=20000)
    ap.add_argument("--duration", type=float, default=10.0, help="simulated seconds per Arm.simulate run")
    args = ap.parse_args(argv)
    data = {"date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "cpus": os.cpu_count(),
            "load_avg": os.getloadavg(), "models": {}}
    for m in MODELS:
        data["models"][m] = {"cpp": cpp_costs(m, args.reps), "simulate": simulate_rtf(m, args.duration)}
        print(f"{m}: Arm.simulate {data['models'][m]['simulate']['record_every_1']:.0f}x real time", flush=True)
    data["das3_accuracy"] = das3_accuracy()
    md = markdown(data)
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "das3.json").write_text(json.dumps(data, indent=1) + "\n")
    (RESULTS / "das3.md").write_text(md)
    print(md)
    return 0


if __name__ == "__main__":
    sys.exit(main())
