"""GH lines of action of the das3 elements that cross the gleno-humeral joint, in the moving scapula frame.

For the GH stability measure the engine needs, per GH-crossing element, the direction of the force the
muscle exerts on the arm at GH, in the scapula frame. With the girdle free the scapula frame moves, so the
direction is sampled at each pose as in das2 (`opensim_geometry._Sampler._direction`: the first path
segment from an arm-side to a scapula-side point, wrap tangent points included) but rotated into the
scapula frame of that pose. Three polynomials (x, y, z) sharing one set of monomials are fitted in the
DOFs the element crosses (`codegen/fit_paths.fit_direction`, das2's settings) and the engine normalises
their value, so errors are angles after normalisation. Poses excluded as wrap jumps for the element's
length are excluded here too.

`python -m codegen.importers.das3_directions` adds `gh_direction` to every GH-crossing element of
models/das3_paths.json and a line-of-action section to docs/das3_path_accuracy.md. With `--with-simulated`
the region is that of the length polynomials after codegen/importers/das3_refit_simulated.py: the kinematic samples plus
das3's own simulated motions (every SIM_STRIDE-th pose of the training runs in the fit, of the validation runs
in its stopping test), and the fits are scored on the held-out simulated runs as well.
"""
from __future__ import annotations

import hashlib
import json
import multiprocessing as mp
import os
import time
from pathlib import Path

import numpy as np

from . import das3_paths as dp
from . import fit_paths as fp
from . import opensim_geometry as og
from .das3_chain import DAS3_DOFS, OSIM_DOF

DIRECTION_VERSION = 1


class DirectionSampler:
    def __init__(self, osim_path, osim_names):
        import opensim as osim
        osim.Logger.setLevelString("error")
        self.model = osim.Model(str(osim_path))
        self.state = self.model.initSystem()
        cs = self.model.getCoordinateSet()
        self.coords = [cs.get(OSIM_DOF[d]) for d in DAS3_DOFS]
        muscles = self.model.getMuscles()
        self.paths = [muscles.get(n).getGeometryPath() for n in osim_names]
        self.scapula = self.model.getBodySet().get("scapula_r")

    def sample(self, q):
        for c, v in zip(self.coords, q):
            c.setValue(self.state, float(v), False)
        self.model.realizePosition(self.state)
        T = self.scapula.getTransformInGround(self.state).R()
        R = np.array([[T.get(i, j) for j in range(3)] for i in range(3)])
        out = np.full((len(self.paths), 3), np.nan)
        for k, gp in enumerate(self.paths):
            path = gp.getCurrentPath(self.state)
            pts = []
            for i in range(path.getSize()):
                p = path.get(i)
                g = p.getLocationInGround(self.state)
                pts.append((p.getParentFrame().getName() in og.SCAPULA_SIDE, np.array([g.get(0), g.get(1), g.get(2)])))
            for (sa, pa), (sb, pb) in zip(pts[:-1], pts[1:]):
                if sa != sb:
                    arm, scap = (pb, pa) if sa else (pa, pb)
                    d = R.T @ (scap - arm)
                    out[k] = d / np.linalg.norm(d)
                    break
        return out


_worker = None


def _init(args):
    global _worker
    _worker = DirectionSampler(*args)


def _chunk(qs):
    return np.array([_worker.sample(q) for q in qs])


def sample_directions(osim_path, osim_names, poses, cache_dir, tag, processes=2):
    """(n_poses, n_elements, 3) unit directions, cached by model file, elements and poses."""
    key = json.dumps({"osim": og._file_hash(osim_path), "elements": list(osim_names),
                      "poses": hashlib.sha256(np.ascontiguousarray(poses).tobytes()).hexdigest(),
                      "v": DIRECTION_VERSION})
    path = Path(cache_dir) / f"das3_directions_{tag}_{hashlib.sha256(key.encode()).hexdigest()[:16]}.npy"
    if path.exists():
        return np.load(path)
    args = (str(osim_path), list(osim_names))
    chunks = np.array_split(np.asarray(poses, float), max(1, min(len(poses), 8 * processes)))
    if processes > 1 and mp.parent_process() is None:
        with mp.get_context("spawn").Pool(processes, _init, (args,)) as pool:
            d = np.concatenate(pool.map(_chunk, chunks))
    else:
        _init(args)
        d = np.concatenate([_chunk(c) for c in chunks])
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(f".tmp{os.getpid()}.npy")
    np.save(tmp, d)
    os.replace(tmp, path)
    return d


def direction_stats(gd, q, target):
    """Angle errors (deg) of a fitted gh_direction at full poses q (n, 11) against unit targets."""
    idx = [DAS3_DOFS.index(d) for d in gd["dofs"]]
    v = np.stack([fp.eval_poly(gd[c], q[:, idx])[0] for c in "xyz"], axis=1)
    a = fp.angle_deg(v / np.linalg.norm(v, axis=1, keepdims=True), target)
    return {"rms_deg": float(np.sqrt(np.mean(a ** 2))), "max_deg": float(a.max()),
            "p99_deg": float(np.percentile(a, 99)), "n_terms": len(gd["x"]["coefs"])}


def main(argv=None):
    import argparse
    root = Path(__file__).resolve().parents[2]
    ap = argparse.ArgumentParser(prog="python -m codegen.importers.das3_directions", description=__doc__.split("\n\n")[0])
    ap.add_argument("--das3", default=str(root / ".." / "shared" / "reference" / "das3"))
    ap.add_argument("--paths", default=str(root / "models" / "das3_paths.json"))
    ap.add_argument("--report", default=str(root / "docs" / "das3_path_accuracy.md"))
    ap.add_argument("--cache", default=str(root / "build"))
    ap.add_argument("--processes", type=int, default=2)
    ap.add_argument("--with-simulated", action="store_true",
                    help="fit over the kinematic samples plus das3's simulated motions and score on both "
                         "(as codegen.importers.das3_refit_simulated does for the lengths)")
    a = ap.parse_args(argv)
    from .das3_rom import Das3Rom
    t0 = time.time()
    paths = json.loads(Path(a.paths).read_text())
    smp = paths["sampling"]
    rom = Das3Rom(a.das3)
    gh = [e for e in paths["elements"] if "GHy" in e["dofs"]]
    all_els = [{"name": e["name"], "osim_name": e["osim_name"]} for e in paths["elements"]]
    osim_path = f"{a.das3}/das3.osim"
    sets = {}
    # the poses and cache tags of codegen/importers/das3_fit.py, whose (cached) length samples give the wrap-jump exclusions
    for tag, cache_tag, n, seed in (("train", f"train{smp['seed']}", smp["train"], smp["seed"]),
                                    ("valid", f"valid{smp['seed']}", smp["valid"], smp["seed"] + 7919),
                                    ("eval", f"eval{smp['test_seed']}", smp["test"], smp["test_seed"])):
        poses = rom.sample(n, seed)
        s = dp.cached_sample(osim_path, all_els, poses, a.cache, cache_tag, a.processes)
        bad = og.wrap_jumps(s)
        d = sample_directions(osim_path, [e["osim_name"] for e in gh], poses, a.cache, cache_tag, a.processes)
        sets[tag] = (s["q"], bad, d)
    if a.with_simulated:
        from .das3_refit_simulated import SIM_STRIDE, simulated_poses
        for tag, runs in (("sim_train", "train"), ("sim_valid", "valid"), ("sim_test", "test")):
            poses = simulated_poses(runs)
            s = dp.cached_sample(osim_path, all_els, poses, a.cache, f"sim{runs}", a.processes)
            d = sample_directions(osim_path, [e["osim_name"] for e in gh], poses, a.cache, f"sim{runs}", a.processes)
            stride = 1 if tag == "sim_test" else SIM_STRIDE
            sets[tag] = (s["q"][::stride], og.wrap_jumps(s)[::stride], d[::stride])
        for tag in ("train", "valid"):
            sets[tag] = tuple(np.concatenate([x, y]) for x, y in zip(sets[tag], sets[f"sim_{tag}"]))
    t_sample = time.time() - t0
    names = [e["name"] for e in paths["elements"]]
    stats = []
    for k, e in enumerate(gh):
        col = names.index(e["name"])
        idx = [DAS3_DOFS.index(x) for x in e["dofs"]]
        (q_tr, b_tr, d_tr), (q_va, b_va, d_va), (q_te, b_te, d_te) = sets["train"], sets["valid"], sets["eval"]
        tr, va, te = ~b_tr[:, col], ~b_va[:, col], ~b_te[:, col]
        before = None
        if a.with_simulated and e.get("gh_direction"):
            q_si, b_si, d_si = sets["sim_test"]
            before = direction_stats(e["gh_direction"], q_si[~b_si[:, col]], d_si[~b_si[:, col], k])
        fit = fp.fit_direction(q_tr[tr][:, idx], d_tr[tr, k], q_va[va][:, idx], d_va[va, k])
        e["gh_direction"] = {"dofs": e["dofs"], **fit}
        st = {"name": e["name"], **direction_stats(e["gh_direction"], q_te[te], d_te[te, k])}
        if a.with_simulated:
            q_si, b_si, d_si = sets["sim_test"]
            si = ~b_si[:, col]
            st["simulated"] = direction_stats(e["gh_direction"], q_si[si], d_si[si, k])
            st["simulated_before"] = before
        e["fit"]["direction"] = st
        stats.append(st)
    paths["gh_direction_command"] = "python -m codegen.importers.das3_directions" + (" --with-simulated" if a.with_simulated else "")
    Path(a.paths).write_text(json.dumps(paths, indent=1) + "\n")
    dt = time.time() - t0
    all_rms = float(np.sqrt(np.mean([s["rms_deg"] ** 2 for s in stats])))
    worst = sorted(stats, key=lambda s: -s["p99_deg"])[:6]
    cmd = paths["gh_direction_command"]
    region = ("the same training and validation poses as the lengths, das3's simulated motions included (every "
              f"{SIM_STRIDE}rd pose of the training and validation runs)" if a.with_simulated else
              "the same training and validation poses")
    lines = ["## GH line of action (scapula frame)", "",
             f"`{cmd}` ({dt:.0f} s, {t_sample:.0f} s of it sampling): for the {len(stats)}",
             "GH-crossing elements, the direction of the force on the arm at GH in the scapula frame of each pose,",
             f"fitted as x, y, z polynomials in the element's DOFs (das2's method and settings) on {region},",
             f"scored on the fit's {smp['test']} test poses" + (f" and on {len(sets['sim_test'][0])} poses of the held-out "
                                                               "simulated runs" if a.with_simulated else "")
             + " (wrap-jump poses excluded); angle after normalisation.", "",
             f"- Overall RMS {all_rms:.2f} deg on the test poses; worst elements by 99th percentile: " + ", ".join(
                 f"{s['name']} p99 {s['p99_deg']:.1f} / max {s['max_deg']:.1f} deg" for s in worst) + "."]
    if a.with_simulated:
        sim_rms = float(np.sqrt(np.mean([s["simulated"]["rms_deg"] ** 2 for s in stats])))
        worst_s = sorted(stats, key=lambda s: -s["simulated"]["p99_deg"])[:6]
        had = [s["simulated_before"] for s in stats if s.get("simulated_before")]
        before_rms = float(np.sqrt(np.mean([b["rms_deg"] ** 2 for b in had]))) if len(had) == len(stats) else None
        lines += [f"- On the held-out simulated motions: overall RMS {sim_rms:.2f} deg"
                  + (f" (the polynomials fitted over the kinematic region alone: {before_rms:.2f} deg, p99 up to "
                     f"{max(b['p99_deg'] for b in had):.1f} deg)" if before_rms is not None else "")
                  + "; worst by 99th percentile: "
                  + ", ".join(f"{s['name']} p99 {s['simulated']['p99_deg']:.1f} / max {s['simulated']['max_deg']:.1f} deg"
                              for s in worst_s) + "."]
    lines += ["", "| element | terms | RMS (deg) | p99 (deg) | max (deg) |"
              + (" simulated RMS (deg) | simulated p99 (deg) | simulated max (deg) |" if a.with_simulated else ""),
              "|---|---|---|---|---|" + ("---|---|---|" if a.with_simulated else "")]
    lines += [f"| {s['name']} | {s['n_terms']} | {s['rms_deg']:.2f} | {s['p99_deg']:.1f} | {s['max_deg']:.1f} |"
              + (f" {s['simulated']['rms_deg']:.2f} | {s['simulated']['p99_deg']:.1f} | {s['simulated']['max_deg']:.1f} |"
                 if a.with_simulated else "") for s in stats]
    from .das3_simulated_poses import replace_section
    replace_section(Path(a.report), "## GH line of action (scapula frame)", "\n".join(lines) + "\n")
    print(f"das3_directions: {len(stats)} GH-crossing elements in {dt:.0f} s; overall RMS {all_rms:.2f} deg")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
