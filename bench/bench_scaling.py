"""Cost against the number of muscle elements and against the integrator.

    python -m bench.bench_scaling [--json bench/results/scaling.json] [--reps N] [--no-subsets] [--plot PNG]

Two measurements (see cpp/tools/bench_scaling.cc):
1. `armrt_bench_scaling` (built with the engine, ninja armrt_bench_scaling) on das2 restricted to its first
   n elements (n = 1 .. 102): the muscle loop of forward() alone, forward(), and Euler / RK4 steps. The
   path polynomials of all 102 elements still run there (a constant).
2. Reduced models: evenly spread subsets of the 102 elements written as model files, generated with
   `codegen.generate` into a temporary directory and compiled with bench_scaling.cc against the engine
   library (same flags as the engine). These give the real cost of a model with n elements, path
   polynomials included, against n and against the number of polynomial terms.
Least-squares lines (cost = a + b n) with R^2 say whether the growth is linear.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_JSON = ROOT / "bench" / "results" / "scaling.json"
SUBSETS = (6, 13, 26, 51, 77, 102)
ENGINE_FLAGS = ["-O3", "-DNDEBUG", "-std=c++17", "-march=native", "-fopenmp-simd", "-fno-math-errno",
                "-fno-trapping-math"]
SUNDIALS = ["-lsundials_cvode", "-lsundials_nvecserial", "-lsundials_sunlinsoldense", "-lsundials_sunmatrixdense"]


def newest(name: str) -> Path | None:
    """The newest `name` under build/, not build/baseline's (an old commit bench_integrators builds)."""
    build = ROOT / "build"
    found = sorted((p for p in build.rglob(name) if p.is_file() and build / "baseline" not in p.parents),
                   key=lambda p: p.stat().st_mtime, reverse=True) if build.is_dir() else []
    return found[0] if found else None


def run_tool(exe: Path, reps: int, sizes: str | None = None, runs: int = 3) -> dict:
    """Runs the tool `runs` times; each item's median is the median of the runs' medians (shared machine)."""
    results = []
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "s.json"
        cmd = [str(exe), "--json", str(out), "--reps", str(reps)] + (["--sizes", sizes] if sizes else [])
        for _ in range(runs):
            subprocess.run(cmd, check=True, capture_output=True, text=True)
            results.append(json.loads(out.read_text()))
    merged = results[0]
    for k, it in enumerate(merged["items"]):
        it["run_medians"] = [r["items"][k]["median"] for r in results]
        it["median"] = float(np.median(it["run_medians"]))
    merged["runs"] = runs
    return merged


def n_terms(el: dict) -> int:
    t = len(el["length_poly"]["coefs"])
    gd = el.get("gh_direction")
    if gd:
        t += sum(len(gd[k]["coefs"]) for k in gd if isinstance(gd[k], dict) and "coefs" in gd[k])
    return t


def subset_model(model: dict, n: int, name: str) -> dict:
    """The model with n of its elements, evenly spread over the DAS3 order (all muscles represented)."""
    els = model["elements"]
    idx = sorted(set(np.linspace(0, len(els) - 1, n).round().astype(int).tolist()))
    keep = [els[i] for i in idx]
    names = {e["name"] for e in keep}
    muscles = []
    for m in model["muscles"]:
        sub = [e for e in m["elements"] if e in names]
        if sub:
            muscles.append({**m, "elements": sub})
    present = {m["name"] for m in muscles}
    groups = {g: [m for m in ms if m in present] for g, ms in model["groups"].items()}
    groups = {g: ms for g, ms in groups.items() if ms}
    return {**model, "name": name, "elements": keep, "muscles": muscles, "groups": groups}


def measure_subsets(reps: int, sizes=SUBSETS) -> list[dict]:
    sys.path.insert(0, str(ROOT))
    from codegen.generate import generate

    # The engine is one shared library, libarmrt.so (CMakeLists.txt: every tool links it); the reduced models'
    # generated code is compiled into each tool beside it. (Before it was a static libarmrt_engine.a: looking for
    # that found only build/baseline's, an old commit whose engine lacks today's symbols, and every link failed.)
    lib = newest("libarmrt.so")
    cxx = shutil.which("g++") or shutil.which("c++")
    if lib is None or cxx is None:
        print("bench_scaling: no libarmrt.so under build/ or no g++: reduced models skipped", file=sys.stderr)
        return []
    model = json.loads((ROOT / "models" / "das2.json").read_text())
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in sizes:
            name = f"sub{n}"
            sub = subset_model(model, n, name) if n < len(model["elements"]) else {**model, "name": name}
            d = Path(tmp) / name
            d.mkdir()
            mpath = d / f"{name}.json"
            mpath.write_text(json.dumps(sub))
            t0 = time.perf_counter()
            generate(mpath, d)
            t_gen = time.perf_counter() - t0
            exe = d / "bench"
            t0 = time.perf_counter()
            cmd = [cxx, *ENGINE_FLAGS, f"-I{ROOT / 'cpp' / 'include'}", f"-I{ROOT / 'cpp' / 'generated'}", f"-I{d}",
                   "-isystem", "/usr/include/eigen3", f"-DARMRT_SCALING_NS={name}",
                   str(ROOT / "cpp" / "tools" / "bench_scaling.cc"), *sorted(str(p) for p in d.glob(f"{name}_*.cc")),
                   str(lib), f"-Wl,-rpath,{lib.parent}", *SUNDIALS, "-o", str(exe)]
            proc = subprocess.run(cmd, capture_output=True, text=True)
            if proc.returncode != 0:
                print(f"bench_scaling: building {name} failed:\n{proc.stderr[-2000:]}", file=sys.stderr)
                continue
            t_build = time.perf_counter() - t0
            res = run_tool(exe, reps, sizes=str(len(sub["elements"])))
            items = {it["name"]: it["median"] for it in res["items"]}
            rows.append({"n": len(sub["elements"]), "terms": sum(n_terms(e) for e in sub["elements"]),
                         "length_terms": sum(len(e["length_poly"]["coefs"]) for e in sub["elements"]),
                         "crosses_gh": sum(bool(e["crosses_gh"]) for e in sub["elements"]),
                         "generate_s": t_gen, "build_s": t_build, **{f"{k}_ns": v for k, v in items.items()}})
            print(f"  reduced model n={rows[-1]['n']}: paths {items['muscle_paths']:.0f} ns, "
                  f"rk4 {items['rk4_step']:.0f} ns, euler {items['euler_step']:.0f} ns", file=sys.stderr)
    return rows


def linfit(x, y) -> dict:
    x, y = np.asarray(x, float), np.asarray(y, float)
    A = np.column_stack([np.ones_like(x), x])
    (a, b), *_ = np.linalg.lstsq(A, y, rcond=None)
    pred = a + b * x
    ss = ((y - y.mean()) ** 2).sum()
    r2 = 1 - ((y - pred) ** 2).sum() / ss if ss > 0 else 1.0
    return {"intercept_ns": float(a), "slope_ns": float(b), "r2": float(r2),
            "max_rel_residual": float(np.max(np.abs(y - pred) / y))}


def analyse(tool: dict | None, subsets: list[dict]) -> dict:
    fits = {}
    if tool:
        by = {}
        for it in tool["items"]:
            by.setdefault(it["name"], []).append((it["n"], it["median"]))
        for name in ("muscle_loop", "forward", "euler_step", "rk4_step"):
            pts = sorted(by.get(name, []))
            if len(pts) >= 3:
                fits[f"first_n/{name}"] = {"x": "elements", **linfit([p[0] for p in pts], [p[1] for p in pts])}
    if len(subsets) >= 3:
        n = [r["n"] for r in subsets]
        for k in ("muscle_paths_ns", "forward_ns", "rk4_step_ns", "euler_step_ns"):
            fits[f"reduced/{k[:-3]}"] = {"x": "elements", **linfit(n, [r[k] for r in subsets])}
        fits["reduced/muscle_paths_vs_terms"] = {"x": "polynomial terms",
                                                 **linfit([r["terms"] for r in subsets], [r["muscle_paths_ns"] for r in subsets])}
    return fits


def plot(result: dict, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    ax = axes[0]
    tool = result.get("first_n")
    if tool:
        by = {}
        for it in tool["items"]:
            by.setdefault(it["name"], []).append((it["n"], it["median"] / 1000))
        for name in ("rk4_step", "euler_step", "forward", "muscle_loop"):
            pts = sorted(by.get(name, []))
            ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", ms=3, label=f"{name} (first n)")
    subs = result.get("reduced_models") or []
    if subs:
        n = [r["n"] for r in subs]
        ax.plot(n, [r["rk4_step_ns"] / 1000 for r in subs], "s--", ms=4, label="rk4_step (reduced model)")
        ax.plot(n, [r["muscle_paths_ns"] / 1000 for r in subs], "s--", ms=4, label="muscle_paths (reduced model)")
    ax.set_xlabel("muscle elements n")
    ax.set_ylabel("median cost per call (us)")
    ax.set_title("cost against elements")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    ax = axes[1]
    if subs:
        ax.plot([r["terms"] for r in subs], [r["muscle_paths_ns"] for r in subs], "o-")
        for r in subs:
            ax.annotate(f"n={r['n']}", (r["terms"], r["muscle_paths_ns"]), fontsize=7)
        ax.set_xlabel("polynomial terms (lengths + GH directions)")
        ax.set_ylabel("muscle_paths median (ns)")
        ax.set_title("path polynomials against terms (reduced models)")
        ax.grid(alpha=0.3)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=90)
    plt.close(fig)


def markdown(result: dict) -> str:
    lines = []
    tool = result.get("first_n")
    if tool:
        by = {}
        for it in tool["items"]:
            by.setdefault(it["n"], {})[it["name"]] = it["median"]
        lines += ["First n elements of das2 (path polynomials of all 102 still evaluated), median ns:", "",
                  "| n | muscle_loop | forward | euler_step | rk4_step |", "|---:|---:|---:|---:|---:|"]
        for n in sorted(k for k in by if "muscle_loop" in by[k]):
            r = by[n]
            lines.append(f"| {n} | {r['muscle_loop']:.0f} | {r['forward']:.0f} | {r['euler_step']:.0f} | {r['rk4_step']:.0f} |")
        whole = {it["name"]: it["median"] for it in tool["items"] if it["name"] in ("muscle_paths", "muscle_lengths", "mass_matrix", "dynamics")}
        lines += ["", "Whole das2 model: " + ", ".join(f"{k} {v:.0f} ns" for k, v in whole.items()), ""]
    subs = result.get("reduced_models") or []
    if subs:
        lines += ["Reduced models (generated with n evenly spread elements), median ns:", "",
                  "| n | polynomial terms | muscle_paths | forward | euler_step | rk4_step |", "|---:|---:|---:|---:|---:|---:|"]
        for r in subs:
            lines.append(f"| {r['n']} | {r['terms']} | {r['muscle_paths_ns']:.0f} | {r['forward_ns']:.0f} | "
                         f"{r['euler_step_ns']:.0f} | {r['rk4_step_ns']:.0f} |")
        lines.append("")
    lines += ["Linear fits cost = a + b x:", "", "| series | x | a (ns) | b (ns per unit) | R^2 | max rel. residual |",
              "|---|---|---:|---:|---:|---:|"]
    for k, f in result.get("fits", {}).items():
        lines.append(f"| {k} | {f['x']} | {f['intercept_ns']:.0f} | {f['slope_ns']:.2f} | {f['r2']:.4f} | {f['max_rel_residual']:.3f} |")
    integ = result.get("integrators")
    if integ:
        lines += ["", "Integrators on the full model (cost per simulated second = steps per second x step cost):", "",
                  "| integrator | dt | step median (us) | derivative evaluations / step | cost per simulated s (ms) | real-time factor (engine only) |",
                  "|---|---:|---:|---:|---:|---:|"]
        for k, v in integ.items():
            lines.append(f"| {k} | {v['dt']:g} | {v['step_us']:.2f} | {v['evals']} | {v['ms_per_sim_s']:.2f} | {v['rtf']:.0f} |")
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--json", type=Path, default=DEFAULT_JSON)
    ap.add_argument("--plot", type=Path, default=None, help="PNG (default: beside the JSON, scaling.png)")
    ap.add_argument("--reps", type=int, default=20000)
    ap.add_argument("--no-subsets", action="store_true", help="skip the generated reduced models")
    args = ap.parse_args(argv)
    result: dict = {"machine": {"cpus": os.cpu_count(), "load_avg": os.getloadavg(), "note": "shared machine"}}
    exe = newest("armrt_bench_scaling")
    if exe is None:
        print("bench_scaling: armrt_bench_scaling not built (ninja -C build/... armrt_bench_scaling)", file=sys.stderr)
    else:
        result["first_n"] = run_tool(exe, args.reps)
        result["first_n"]["binary"] = str(exe.relative_to(ROOT)) if exe.is_relative_to(ROOT) else str(exe)
    if not args.no_subsets:
        result["reduced_models"] = measure_subsets(max(2000, args.reps // 4))
    result["fits"] = analyse(result.get("first_n"), result.get("reduced_models") or [])
    if result.get("first_n"):
        full = {it["name"]: it["median"] for it in result["first_n"]["items"] if it["n"] == result["first_n"]["num_elements"]}
        result["integrators"] = {}
        # One step each at the validated sizes (armrt_bench_scaling times RK4 at 1/6 ms).
        for name, dt, evals in (("euler", 1e-4, 1), ("rk4", 1e-3 / 6, 4)):
            ns = full.get(f"{name}_step")
            if ns:
                result["integrators"][name] = {"dt": dt, "step_us": ns / 1000, "evals": evals,
                                               "ms_per_sim_s": ns * (1 / dt) / 1e6, "rtf": dt / (ns * 1e-9)}
    args.json.parent.mkdir(parents=True, exist_ok=True)
    args.json.write_text(json.dumps(result, indent=1) + "\n")
    png = args.plot or args.json.with_suffix(".png")
    try:
        plot(result, png)
        result["plot"] = str(png)
    except Exception as exc:  # noqa: BLE001
        print(f"bench_scaling: plot failed: {exc}", file=sys.stderr)
    print(markdown(result))
    print(f"\nwrote {args.json} and {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
