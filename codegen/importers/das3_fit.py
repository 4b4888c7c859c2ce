"""Length polynomials of the 138 das3 elements fitted to OpenSim over the girdle-and-arm region.

Same method as the das2 fits (`codegen/fit_paths.fit_length`: joint least squares of length and moment
arms, forward selection of monomials, stopping when the paper's criterion holds with margin on a
held-out validation sample), on samples of das3.osim with all 11 DOFs free over `codegen/importers/das3_rom.py`,
in the DOFs each element crosses in das3.osim (`codegen/das3_paths.element_dofs`). Girdle-crossing
elements cross 3 (trapezius clavicular part: SC), 6 (thorax-scapula muscles, clavicular deltoid:
SC+AC or AC+GH) or 9 DOFs (latissimus, pectoralis major: SC+AC+GH); their degree and term budgets are
added below (the das2 table stops at 5 DOFs). Scored on the separate sample of `codegen/importers/das3_paths.py`
against the DAS3 release polynomials (the baseline).

`python -m codegen.importers.das3_fit [--elements NAMES] [--train N --valid N] --out build/das3_fits.json`
"""
from __future__ import annotations

import json
import time
from pathlib import Path

import numpy as np

from . import das3_paths as dp
from . import fit_paths as fp
from . import opensim_geometry as og
from .das3_chain import DAS3_DOFS

# degree / term budgets for the girdle-crossing DOF counts (das2's table covers 1-5 DOFs)
EXTRA_MAX_DEGREE = {6: 3, 7: 3, 8: 3, 9: 3, 10: 2, 11: 2}
EXTRA_MAX_TERMS = {6: 40, 7: 40, 8: 45, 9: 45, 10: 45, 11: 45}
EXTRA_EXT_TERMS = {6: 60, 7: 60, 8: 70, 9: 70, 10: 70, 11: 70}
for _table, _extra in ((fp.MAX_DEGREE, EXTRA_MAX_DEGREE), (fp.MAX_TERMS, EXTRA_MAX_TERMS),
                       (fp.EXT_TERMS, EXTRA_EXT_TERMS)):
    for _k, _v in _extra.items():
        _table.setdefault(_k, _v)


def fit_element(k, samples_tr, samples_va, bad_tr, bad_va):
    """Fitted {dofs, exponents, coefs} of element k from training/validation samples."""
    cols = samples_tr["cross"][k]
    dofs = [d for d, c in zip(DAS3_DOFS, cols) if c]
    idx = [DAS3_DOFS.index(d) for d in dofs]
    tr, va = ~bad_tr[:, k], ~bad_va[:, k]
    q_tr, q_va = samples_tr["q"][tr][:, idx], samples_va["q"][va][:, idx]
    ma_tr, ma_va = samples_tr["ma"][tr][:, k, idx], samples_va["ma"][va][:, k, idx]
    L_tr, L_va = samples_tr["length"][tr][:, k], samples_va["length"][va][:, k]
    crit = fp.criterion(max(np.abs(ma_tr).max(), np.abs(ma_va).max()))
    exps, coefs = fp.fit_length(q_tr, L_tr, ma_tr, q_va, L_va, ma_va, crit)
    return {"dofs": dofs, "exponents": exps, "coefs": coefs.tolist()}


_FIT_ARGS = None


def _fit_one(k):
    t = time.time()
    return fit_element(k, *_FIT_ARGS), time.time() - t


def fit_all(elements, samples_tr, samples_va, bad_tr, bad_va, processes, names):
    """fit_element for the element indices `elements` (or 0..elements-1 for an int) on `processes` forked
    workers (numpy only), in order; names[i] labels the progress line of the i-th."""
    import multiprocessing as mp
    global _FIT_ARGS
    _FIT_ARGS = (samples_tr, samples_va, bad_tr, bad_va)
    ks = list(range(elements)) if isinstance(elements, int) else list(elements)
    if processes > 1 and mp.parent_process() is None:
        with mp.get_context("fork").Pool(processes) as pool:
            results = []
            for k, r in enumerate(pool.imap(_fit_one, ks)):
                print(f"{names[k]}: {len(r[0]['dofs'])} DOFs, {len(r[0]['coefs'])} terms, {r[1]:.1f} s", flush=True)
                results.append(r)
    else:
        results = []
        for k, kk in enumerate(ks):
            results.append(_fit_one(kk))
            print(f"{names[k]}: {len(results[-1][0]['dofs'])} DOFs, {len(results[-1][0]['coefs'])} terms, "
                  f"{results[-1][1]:.1f} s", flush=True)
    return [r[0] for r in results], [r[1] for r in results]


def write_outputs(out, report, paths_out, source):
    """The markdown report (fitted beside DAS3 release) and the compact polynomial file from a fit result."""
    smp = out["sampling"]
    fitted, release = [], []
    terms = None
    if any("n_terms" not in e["release"] for e in out["elements"]):   # results written before n_terms was kept
        root = Path(__file__).resolve().parents[2]
        terms = {e.name: len(e.lcoefs) for e in dp.das3_release_elements(root / ".." / "shared" / "reference" / "das3")}
    for e in out["elements"]:
        fitted.append({**e["fit"], "n_terms": len(e["length_poly"]["coefs"])})
        release.append({**e["release"], "n_terms": e["release"].get("n_terms", terms and terms[e["name"]])})
    cmd = (f"python -m codegen.importers.das3_fit --train {smp['train']} --valid {smp['valid']} --test {smp['test']} "
           f"--seed {smp['seed']} --test-seed {smp['test_seed']}")
    info = (f"{smp['train']} training and {smp['valid']} validation poses (seeds {smp['seed']}, {smp['seed'] + 7919}); "
            f"sampling {smp['seconds_sampling'] / 60:.0f} min, fitting {smp['seconds_fitting'] / 60:.0f} min of worker "
            f"time, on the shared 2-core machine (load 7-9)")
    if report:
        dp.write_report(release, out["rom"], smp["test"], smp["test_seed"], report, cmd + f" --report {report}",
                        fitted=fitted, fit_info=info)
    if paths_out:
        write_paths(out, paths_out, cmd + f" --paths-out {paths_out}")


def report_from_paths(paths_file, report, das3_dir, cache, processes):
    """Rewrites the head of the accuracy report (everything before its "## GH line of action" section) for the
    polynomials now in `paths_file`: their scores on the fit's test sample (each element's `fit` entry, which
    codegen.importers.das3_refit_simulated keeps current) beside the DAS3 release polynomials scored on the same poses."""
    from .das3_rom import Das3Rom
    paths = json.loads(Path(paths_file).read_text())
    smp = paths["sampling"]
    rom = Das3Rom(das3_dir)
    release = dp.das3_release_elements(das3_dir)
    s_te = dp.cached_sample(f"{das3_dir}/das3.osim", [{"name": e.name, "osim_name": e.osim_name} for e in release],
                            rom.sample(smp["test"], smp["test_seed"]), cache, f"eval{smp['test_seed']}", processes)
    bad = og.wrap_jumps(s_te)
    st_rel = dp.score(s_te, [dp.polynomial_moment_arms(e.lparams, e.lcoefs, e.dof_names, s_te["q"]) for e in release], bad)
    for st, e in zip(st_rel, release):
        st["n_terms"] = len(e.lcoefs)
    by_name = {e["name"]: e for e in paths["elements"]}
    fitted = [{**{k: v for k, v in by_name[e.name]["fit"].items() if k != "simulated"},
               "n_terms": len(by_name[e.name]["length_poly"]["coefs"])} for e in release]
    n_reselected = sum(1 for e in paths["elements"] if e["fit"].get("simulated", {}).get("reselected"))
    info = (f"{smp['train']} training and {smp['valid']} validation poses (seeds {smp['seed']}, {smp['seed'] + 7919}); "
            "then refitted over this region plus das3's own simulated motions (the last two sections), "
            f"{n_reselected} elements with their terms selected afresh")
    cmd = f"python -m codegen.importers.das3_fit --from-paths {paths_file} --report {report}"
    old = Path(report).read_text() if Path(report).exists() else ""
    dp.write_report(st_rel, paths["rom"], smp["test"], smp["test_seed"], report, cmd, fitted=fitted, fit_info=info)
    cut = old.find("## GH line of action")
    if cut >= 0:
        Path(report).write_text(Path(report).read_text().rstrip("\n") + "\n\n" + old[cut:])


def write_paths(out, path, command):
    """Fitted polynomials in the model schema's `length_poly` form (docs/model_schema.md), per element, with
    the fit statistics; not a model file: the das3 importer (after issue 13) will take its paths from here."""
    data = {"schema": "armrt-das3-paths", "schema_version": 1, "command": command,
            "dofs": DAS3_DOFS, "rom": out["rom"], "sampling": out["sampling"],
            "elements": [{"name": e["name"], "osim_name": e["osim_name"], "dofs": e["length_poly"]["dofs"],
                          "length_poly": e["length_poly"], "fit": e["fit"]} for e in out["elements"]]}
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    Path(path).write_text(json.dumps(data, indent=1) + "\n")


def main(argv=None):
    import argparse
    root = Path(__file__).resolve().parents[2]
    ap = argparse.ArgumentParser(prog="python -m codegen.importers.das3_fit", description=__doc__.split("\n\n")[0])
    ap.add_argument("--das3", default=str(root / ".." / "shared" / "reference" / "das3"))
    ap.add_argument("--elements", nargs="*", help="element names (default: all 138)")
    ap.add_argument("--train", type=int, default=1024)
    ap.add_argument("--valid", type=int, default=512)
    ap.add_argument("--test", type=int, default=512, help="poses of the scoring sample (das3_paths --poses)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--test-seed", type=int, default=20240601)
    ap.add_argument("--processes", type=int, default=2)
    ap.add_argument("--cache", default=str(root / "build"))
    ap.add_argument("--out", default=str(root / "build" / "das3_fits.json"))
    ap.add_argument("--report", help="also write the accuracy report (markdown) here")
    ap.add_argument("--paths-out", help="also write the fitted length polynomials (JSON, see write_paths) here")
    ap.add_argument("--from-json", help="skip sampling and fitting: write --report/--paths-out from this --out file")
    ap.add_argument("--from-paths", help="skip sampling and fitting: write --report's summary and per-element "
                    "table for the polynomials of this paths file as they now are (after codegen.importers.das3_refit_simulated), "
                    "keeping the report's later sections")
    a = ap.parse_args(argv)
    if a.from_json:
        write_outputs(json.loads(Path(a.from_json).read_text()), a.report, a.paths_out, a.from_json)
        return 0
    if a.from_paths:
        if not a.report:
            ap.error("--from-paths needs --report")
        report_from_paths(a.from_paths, a.report, a.das3, a.cache, a.processes)
        return 0
    from .das3_rom import Das3Rom
    t0 = time.time()
    rom = Das3Rom(a.das3)
    release = dp.das3_release_elements(a.das3)
    if a.elements:
        unknown = set(a.elements) - {e.name for e in release}
        if unknown:
            ap.error(f"unknown elements {sorted(unknown)}")
        release = [e for e in release if e.name in a.elements]
    els = [{"name": e.name, "osim_name": e.osim_name} for e in release]
    osim_path = f"{a.das3}/das3.osim"
    s_tr = dp.cached_sample(osim_path, els, rom.sample(a.train, a.seed), a.cache, f"train{a.seed}", a.processes)
    s_va = dp.cached_sample(osim_path, els, rom.sample(a.valid, a.seed + 7919), a.cache, f"valid{a.seed}", a.processes)
    s_te = dp.cached_sample(osim_path, els, rom.sample(a.test, a.test_seed), a.cache, f"eval{a.test_seed}", a.processes)
    t_sample = time.time() - t0
    bad_tr, bad_va, bad_te = og.wrap_jumps(s_tr), og.wrap_jumps(s_va), og.wrap_jumps(s_te)
    fits, times = fit_all(len(release), s_tr, s_va, bad_tr, bad_va, a.processes, [e.name for e in release])
    pred_fit = [dp.polynomial_moment_arms(f["exponents"], f["coefs"], f["dofs"], s_te["q"]) for f in fits]
    pred_rel = [dp.polynomial_moment_arms(e.lparams, e.lcoefs, e.dof_names, s_te["q"]) for e in release]
    st_fit, st_rel = dp.score(s_te, pred_fit, bad_te), dp.score(s_te, pred_rel, bad_te)
    for st, e in zip(st_rel, release):
        st["n_terms"] = len(e.lcoefs)
    out = {"sampling": {"train": a.train, "valid": a.valid, "test": a.test, "seed": a.seed, "test_seed": a.test_seed,
                        "seconds_sampling": t_sample, "seconds_fitting": float(sum(times))},
           "rom": rom.describe(),
           "elements": [{"name": e.name, "osim_name": e.osim_name, "length_poly": f, "fit": sf, "release": sr,
                         "seconds": t} for e, f, sf, sr, t in zip(release, fits, st_fit, st_rel, times)]}
    Path(a.out).parent.mkdir(parents=True, exist_ok=True)
    Path(a.out).write_text(json.dumps(out, indent=1))
    write_outputs(out, a.report, a.paths_out, a.out)
    print(f"das3_fit: {len(fits)} elements in {time.time() - t0:.0f} s (sampling {t_sample:.0f} s, fitting "
          f"{sum(times):.0f} s); criterion met on the test sample: fitted {sum(s['pass'] for s in st_fit)}, "
          f"DAS3 release {sum(s['pass'] for s in st_rel)} of {len(fits)}; wrote {a.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
