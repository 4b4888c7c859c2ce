"""Muscle-path geometry of the 11-DOF das3 model from OpenSim, and the accuracy of path polynomials on it.

The 5-DOF sampler (`codegen/importers/opensim_geometry.py`) locks the girdle; here all 11 coordinates move, over the
girdle-and-arm region of `codegen/importers/das3_rom.py`, and all 138 DAS3 elements are sampled. Per pose and
element: length (`Muscle.getLength`), moment arm about every DOF the element crosses
(`GeometryPath.computeMomentArm`) and the central difference of OpenSim's own length (step FD_STEP),
which marks wrap-engagement jumps exactly as for das2 (`opensim_geometry.wrap_jumps`).

Crossed DOFs come from the bodies the path points and wrap surfaces sit on: the chain is serial (thorax,
clavicle, scapula, humerus, ulna, radius, hand), so an element crosses every joint between its most
proximal and most distal body.

`python -m codegen.importers.das3_paths --report FILE.md` scores the DAS3 release polynomials (model_struct.mat
`lparams`/`lcoefs`, the baseline to beat) with the paper's criterion; `codegen/importers/das3_fit.py` adds the
refitted ones to the same report.
"""
from __future__ import annotations

import hashlib
import json
import multiprocessing as mp
import os
import time
from pathlib import Path

import numpy as np

from . import opensim_geometry as og
from .das3_chain import DAS3_DOFS, OSIM_DOF

SEGMENT = {"ground": 0, "thorax": 0, "clavicle_1": 1, "clavicle_2": 1, "clavicle_r": 1, "scapula_1": 2,
           "scapula_2": 2, "scapula_r": 2, "humerus_1": 3, "humerus_2": 3, "humerus_r": 3, "ulna_r": 4,
           "radius_r": 5, "hand_r": 6}
# DOFs of the joint between segment s and s + 1 (the radius-hand joint is a weld)
JOINT_DOFS = [["SCy", "SCz", "SCx"], ["ACy", "ACz", "ACx"], ["GHy", "GHz", "GHyy"], ["ELx"], ["PSy"], []]
FD_STEP = og.FD_STEP
SAMPLE_VERSION = 1
CRIT_REL, CRIT_ABS = 0.10, 2e-3


def crossed_dofs(bodies) -> list[str]:
    segs = [SEGMENT[b] for b in bodies]
    return [d for s in range(min(segs), max(segs)) for d in JOINT_DOFS[s]]


def element_dofs(osim_path, osim_names):
    import opensim as osim
    osim.Logger.setLevelString("error")
    model = osim.Model(str(osim_path))
    model.initSystem()
    return [crossed_dofs(og._path_bodies(model, n)) for n in osim_names]


class Sampler:
    """One OpenSim model with all 11 coordinates free."""

    def __init__(self, osim_path, osim_names, cross):
        import opensim as osim
        osim.Logger.setLevelString("error")
        self.model = osim.Model(str(osim_path))
        self.state = self.model.initSystem()
        cs = self.model.getCoordinateSet()
        self.coords = [cs.get(OSIM_DOF[d]) for d in DAS3_DOFS]
        muscles = self.model.getMuscles()
        self.muscles = [muscles.get(n) for n in osim_names]
        self.paths = [m.getGeometryPath() for m in self.muscles]
        self.cross = np.asarray(cross, bool)

    def _set(self, q):
        for c, v in zip(self.coords, q):
            c.setValue(self.state, float(v), False)
        self.model.realizePosition(self.state)

    def _lengths(self):
        return np.array([m.getLength(self.state) for m in self.muscles])

    def sample(self, q):
        n_el, n = len(self.muscles), len(DAS3_DOFS)
        self._set(q)
        length = self._lengths()
        ma = np.full((n_el, n), np.nan)
        for j, c in enumerate(self.coords):
            for k in np.flatnonzero(self.cross[:, j]):
                ma[k, j] = self.paths[k].computeMomentArm(self.state, c)
        ma_fd = np.full((n_el, n), np.nan)
        for j in range(n):
            cols = self.cross[:, j]
            if not cols.any():
                continue
            qp = np.array(q, float)
            qp[j] += FD_STEP
            qm = np.array(q, float)
            qm[j] -= FD_STEP
            self._set(qp)
            lp = self._lengths()
            self._set(qm)
            lm = self._lengths()
            ma_fd[cols, j] = -(lp[cols] - lm[cols]) / (2 * FD_STEP)
        return length, ma, ma_fd


_worker = None


def _init_worker(args):
    global _worker
    _worker = Sampler(*args)


def _run_chunk(qs):
    out = [_worker.sample(q) for q in qs]
    return [np.array([o[i] for o in out]) for i in range(3)]


def sample_poses(osim_path, elements, poses, processes=2):
    """OpenSim geometry at poses (n, 11) for elements [{name, osim_name}]: dict of arrays."""
    names = [e["osim_name"] for e in elements]
    dofs = element_dofs(osim_path, names)
    cross = np.array([[d in ds for d in DAS3_DOFS] for ds in dofs])
    args = (str(osim_path), names, cross)
    poses = np.asarray(poses, float)
    chunks = np.array_split(poses, max(1, min(len(poses), 8 * processes)))
    if mp.parent_process() is not None:
        processes = 1
    if processes > 1:
        with mp.get_context("spawn").Pool(processes, _init_worker, (args,)) as pool:
            parts = pool.map(_run_chunk, chunks)
    else:
        _init_worker(args)
        parts = [_run_chunk(c) for c in chunks]
    length, ma, ma_fd = [np.concatenate([p[i] for p in parts]) for i in range(3)]
    return {"q": poses, "length": length, "ma": ma, "ma_fd": ma_fd, "cross": cross,
            "names": np.array([e["name"] for e in elements])}


def cached_sample(osim_path, elements, poses, cache_dir, tag, processes=2):
    key = json.dumps({"osim": og._file_hash(osim_path), "elements": [(e["name"], e["osim_name"]) for e in elements],
                      "poses": hashlib.sha256(np.ascontiguousarray(poses).tobytes()).hexdigest(),
                      "fd": FD_STEP, "v": SAMPLE_VERSION})
    path = Path(cache_dir) / f"das3_samples_{tag}_{hashlib.sha256(key.encode()).hexdigest()[:16]}.npz"
    if path.exists():
        with np.load(path, allow_pickle=False) as z:
            return {k: z[k] for k in z.files}
    s = sample_poses(osim_path, elements, poses, processes)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(f".tmp{os.getpid()}.npz")
    np.savez(tmp, **s)
    os.replace(tmp, path)
    return s


def polynomial_moment_arms(exponents, coefs, poly_dofs, q):
    """-dL/dq (n, 11) of a polynomial in the DOFs poly_dofs at poses q (n, 11); zero for other DOFs."""
    from ..polynomial import gradient
    idx = [DAS3_DOFS.index(d) for d in poly_dofs]
    out = np.zeros((len(q), len(DAS3_DOFS)))
    out[:, idx] = -gradient(exponents, coefs, q[:, idx])
    return out


def score(samples, predicted_ma, bad):
    """Per element: the paper's criterion on the crossed DOFs, poses in `bad` excluded."""
    stats = []
    for k, name in enumerate(samples["names"]):
        cols = samples["cross"][k]
        ok = ~bad[:, k]
        ref = samples["ma"][ok][:, k][:, cols]
        err = np.abs(predicted_ma[k][ok][:, cols] - ref)
        peak = float(np.abs(ref).max())
        crit = max(CRIT_REL * peak, CRIT_ABS)
        worst = err.max(axis=1)
        stats.append({"name": str(name), "dofs": [d for d, c in zip(DAS3_DOFS, cols) if c],
                      "peak_m": peak, "criterion_m": crit, "max_err_m": float(worst.max()),
                      "p99_err_m": float(np.percentile(worst, 99)), "n_over": int((worst >= crit).sum()),
                      "n_scored": int(ok.sum()), "n_wrap_jumps": int((~ok).sum()),
                      "pass": bool(worst.max() < crit),
                      "worst_dof": [d for d, c in zip(DAS3_DOFS, cols) if c][int(np.argmax(err.max(axis=0)))]})
    return stats


def das3_release_elements(das3_dir):
    import scipy.io as sio

    from .das3_source import read_model_struct
    struct = read_model_struct(Path(das3_dir) / "model_struct.mat")
    return struct.elements


def _summary(stats, label):
    n_pass = sum(s["pass"] for s in stats)
    over = sum(s["n_over"] for s in stats)
    scored = sum(s["n_scored"] for s in stats)
    worst = sorted(stats, key=lambda s: -s["max_err_m"] / s["criterion_m"])[:8]
    return [f"- {label}: {n_pass} of {len(stats)} elements meet the criterion at every scored pose; "
            f"element-poses over the criterion {over} of {scored} ({100 * over / max(scored, 1):.1f}%); worst "
            "(max error / criterion, DOF): " + ", ".join(
                f"{s['name']} {1e3 * s['max_err_m']:.1f} / {1e3 * s['criterion_m']:.1f} mm ({s['worst_dof']})"
                for s in worst) + "."]


def write_report(release, rom_desc, n_poses, seed, md_path, command, fitted=None, fit_info=None):
    """Markdown report: the DAS3 release polynomials (baseline) and, if given, the refitted ones."""
    jumps = sum(s["n_wrap_jumps"] for s in release)
    title = "das3 muscle paths: polynomials against OpenSim over the girdle-and-arm region"
    lines = [
        f"# {title}", "",
        f"Generated by `{command}`:",
        f"length polynomials against a fresh OpenSim 4.6 sample of {n_poses} poses (seed {seed}) of das3.osim",
        "with all 11 DOFs free, over the girdle-and-arm region of `codegen/importers/das3_rom.py` (below). Baseline: the",
        "DAS3 release polynomials (model_struct.mat `lparams`, `lcoefs`, in the DOFs each polynomial uses).",
    ]
    if fitted is not None:
        lines += ["Refitted: `codegen/importers/das3_fit.py` (the das2 method, `codegen/fit_paths.fit_length`, in the DOFs each",
                  f"element crosses in das3.osim) on separate samples: {fit_info}."]
    lines += [
        "", "Criterion (paper II-C, as in docs/path_accuracy.md): for every DOF the element crosses in das3.osim,",
        "|moment-arm error| < max(10% of the element's peak |moment arm| over its DOFs and the sample, 2 mm).",
        "Reference moment arms are OpenSim `computeMomentArm`; poses where it disagrees with the central",
        "difference of OpenSim's length by more than max(2 mm, 10% of peak) are wrap-engagement jumps, excluded",
        "and counted. A DOF the element crosses in OpenSim but a polynomial lacks counts with a moment arm of 0.",
        "", "## Region sampled", "",
        f"Arm DOFs (Sobol): {', '.join(f'{d} [{lo:.3f}, {hi:.3f}]' for d, (lo, hi) in rom_desc['arm_range'].items())} rad.",
        f"Girdle DOFs: the scapulohumeral rhythm path ({rom_desc['rhythm']} rad of scapular upward rotation per rad of",
        "GHz, minimum-norm girdle motion keeping the TS/AI contact state of the resting posture) plus normal",
        f"scatter of {rom_desc['scatter_rad']} rad per DOF projected to keep TS/AI on the thorax, clipped to these limits (rad):",
        ", ".join(f"{d} [{lo:.3f}, {hi:.3f}]" for d, (lo, hi) in rom_desc["girdle_range"].items()) + ".",
        "Path (rad) at six elevations:", "",
        "| GHz | SCy | SCz | SCx | ACy | ACz | ACx | f(TS) | f(AI) |", "|---|---|---|---|---|---|---|---|---|"]
    for r in rom_desc["path"]:
        lines.append("| " + " | ".join(f"{r[k]:.3f}" for k in ["GHz", "SCy", "SCz", "SCx", "ACy", "ACz", "ACx"])
                     + f" | {r['f_TS_AI'][0]:.4f} | {r['f_TS_AI'][1]:.4f} |")
    lines += ["", "This kinematic rule was the first fit's whole region (the engine could not simulate das3 then; see",
              "`codegen/importers/das3_rom.py`). das3's own simulated motions were added to it afterwards: the last two sections.", "",
              "## Summary", ""]
    if fitted is not None:
        lines += _summary(fitted, "Refitted")
    lines += _summary(release, "DAS3 release")
    lines += [f"- Wrap-jump poses excluded: {jumps} element-poses.", "", "## Per element", ""]
    head = "| element | DOFs crossed | peak (mm) | criterion (mm) | wrap jumps |"
    sep = "|---|---|---|---|---|"
    for lab in (["refit"] if fitted is not None else []) + ["DAS3"]:
        head += f" {lab} terms | {lab} max err (mm) | {lab} p99 (mm) | {lab} poses over | {lab} pass |"
        sep += "---|---|---|---|---|"
    lines += [head, sep]
    for i, s in enumerate(release):
        row = (f"| {s['name']} | {' '.join(s['dofs'])} | {1e3 * s['peak_m']:.1f} | {1e3 * s['criterion_m']:.1f} | "
               f"{s['n_wrap_jumps']} |")
        for st in ([fitted[i]] if fitted is not None else []) + [s]:
            row += (f" {st.get('n_terms', '-')} | {1e3 * st['max_err_m']:.2f} | {1e3 * st['p99_err_m']:.2f} | "
                    f"{st['n_over']} | {'yes' if st['pass'] else 'NO'} |")
        lines.append(row)
    Path(md_path).write_text("\n".join(lines) + "\n")


def main(argv=None):
    import argparse
    root = Path(__file__).resolve().parents[2]
    ap = argparse.ArgumentParser(prog="python -m codegen.importers.das3_paths", description=__doc__.split("\n\n")[0])
    ap.add_argument("--das3", default=str(root / ".." / "shared" / "reference" / "das3"))
    ap.add_argument("--poses", type=int, default=512)
    ap.add_argument("--seed", type=int, default=20240601)
    ap.add_argument("--elements", nargs="*", help="element names (default: all 138)")
    ap.add_argument("--processes", type=int, default=2)
    ap.add_argument("--cache", default=str(root / "build"))
    ap.add_argument("--report", help="write the markdown accuracy report of the DAS3 release polynomials here")
    ap.add_argument("--json", help="write the per-element statistics here")
    a = ap.parse_args(argv)
    from .das3_rom import Das3Rom
    t0 = time.time()
    rom = Das3Rom(a.das3)
    elements = das3_release_elements(a.das3)
    if a.elements:
        unknown = set(a.elements) - {e.name for e in elements}
        if unknown:
            ap.error(f"unknown elements {sorted(unknown)}")
        elements = [e for e in elements if e.name in a.elements]
    poses = rom.sample(a.poses, a.seed)
    samples = cached_sample(f"{a.das3}/das3.osim", [{"name": e.name, "osim_name": e.osim_name} for e in elements],
                            poses, a.cache, f"eval{a.seed}", a.processes)
    bad = og.wrap_jumps(samples)
    pred = [polynomial_moment_arms(e.lparams, e.lcoefs, e.dof_names, samples["q"]) for e in elements]
    stats = score(samples, pred, bad)
    for st, e in zip(stats, elements):
        st["n_terms"] = len(e.lcoefs)
    dt = time.time() - t0
    n_pass = sum(s["pass"] for s in stats)
    print(f"das3_paths: {len(stats)} elements, {a.poses} poses, {dt:.0f} s; DAS3 release polynomials: "
          f"{n_pass}/{len(stats)} meet the criterion")
    if a.json:
        Path(a.json).write_text(json.dumps(stats, indent=1))
    if a.report:
        cmd = "python -m codegen.importers.das3_paths " + " ".join(
            x for x in [f"--poses {a.poses}", f"--seed {a.seed}", f"--report {a.report}"])
        write_report(stats, rom.describe(), a.poses, a.seed, a.report, cmd)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
