"""Models built on demand: build time (first, cached) and the step cost of an on-demand das2 against the
built-in one (same generated code, same flags: the same speed is expected).

    python -m bench.bench_models [--model models/das2.json] [--steps 5000] [--out bench/results/models.json]

The model file is copied under another name (so it does not coincide with the built-in das2) and built
into a fresh temporary cache (ARMRT_CACHE_DIR), so the first build is a real one. Then: build() again
(the cache lookup), Model.load in a new process (the load a user sees in a new session), and TET of
`steps` control steps of ROS2 (elbow flexors 0.2, rotator cuff 0.05), built-in and on-demand arms in
turn, three rounds each; min and median of the per-step TET. Prints the numbers and writes JSON.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def tet_of(model, steps: int) -> np.ndarray:
    import armrt
    arm = armrt.Arm(model)
    arm.set_excitation({"elbow_flexors": 0.2, "rotator_cuff": 0.05})
    arm.step(200)
    res = arm.simulate(arm.excitation, duration=steps * arm.dt)
    return res.tet_ns[:-1]


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--model", default=str(ROOT / "models" / "das2.json"), help="model file to build")
    ap.add_argument("--steps", type=int, default=5000, help="control steps per TET round")
    ap.add_argument("--out", default=str(ROOT / "bench" / "results" / "models.json"), help="JSON output")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="armrt-bench-models-") as tmp:
        os.environ["ARMRT_CACHE_DIR"] = str(Path(tmp) / "cache")
        import armrt
        from armrt.model_build import build
        doc = json.loads(Path(args.model).read_text())
        base = doc["name"]
        doc["name"] = f"{base}_on_demand"
        path = Path(tmp) / f"{doc['name']}.json"
        path.write_text(json.dumps(doc))
        load0 = os.getloadavg()[0]
        first = build(path)
        cached = min(build(path).seconds for _ in range(5))
        code = ("import time, armrt; t = time.perf_counter(); armrt.Model.load(%r); print(time.perf_counter() - t)"
                % str(path))
        new_process = min(float(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                                               check=True, env=os.environ).stdout) for _ in range(3))
        m = armrt.Model.load(path)
        tets = {"built_in": [], "on_demand": []}
        for _ in range(3):
            tets["built_in"].append(tet_of(base, args.steps))
            tets["on_demand"].append(tet_of(m, args.steps))
        load1 = os.getloadavg()[0]
    out = {"command": " ".join(["python -m bench.bench_models", *(argv if argv is not None else sys.argv[1:])]),
           "model_file": os.path.relpath(args.model, ROOT), "n_dofs": m.n_dofs, "n_elements": m.n_elements,
           "first_build_s": round(first.seconds, 2), "cached_build_s": round(cached, 4),
           "cached_load_new_process_s": round(new_process, 4),
           "tet_us": {k: {"min": round(float(np.min(np.concatenate(v))) / 1e3, 2),
                          "median": round(float(np.median(np.concatenate(v))) / 1e3, 2)} for k, v in tets.items()},
           "steps": args.steps, "rounds": 3, "load_average": [round(load0, 1), round(load1, 1)],
           "cpus": os.cpu_count(), "time": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}
    print(f"{m.name}: {m.n_dofs} DOF, {m.n_elements} elements; first build {out['first_build_s']} s, cached "
          f"{out['cached_build_s'] * 1e3:.1f} ms, Model.load in a new process {out['cached_load_new_process_s'] * 1e3:.1f} ms")
    for k, v in out["tet_us"].items():
        print(f"  TET {k:9s} min {v['min']:.2f} us, median {v['median']:.2f} us")
    print(f"  load average {out['load_average'][0]} -> {out['load_average'][1]} on {out['cpus']} CPUs")
    Path(args.out).parent.mkdir(parents=True, exist_ok=True)
    Path(args.out).write_text(json.dumps(out, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
