"""Refit das3's path-polynomial coefficients over the fit region plus das3's own simulated motions.

    python -m codegen.importers.das3_refit_simulated [--paths models/das3_paths.json] [--report docs/das3_path_accuracy.md]

codegen/importers/das3_fit.py chose each element's terms and coefficients over a kinematic stand-in for the girdle's
motion (codegen/importers/das3_rom.py), because the engine could not simulate das3 then. Simulated, das3's girdle
sits a few degrees outside that region (ACz and ACx below it, SCy and SCz at its edges;
codegen/importers/das3_simulated_poses.py), where the polynomials extrapolate badly. This keeps every element's
terms (exponents) and refits their coefficients by the same weighted least squares on lengths and moment
arms (codegen/importers/fit_paths.py, MA_WEIGHT) over the union of the fit's training poses and poses from das3's
simulations (training runs); it scores both on held-out poses of both kinds (the fit's test sample and
other simulated runs) and keeps, per element, whichever coefficients have the smaller worst error in
criteria over the two. Writes the chosen coefficients into the paths file, with the scores. Needs OpenSim.
"""
from __future__ import annotations

import json
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]


# (protocol level, random-run seeds) of each set of simulated runs; the three sets share no run
SIMULATED_SETS = {"train": (1.0, range(0, 6)), "test": (0.7, range(6, 12)), "valid": (0.85, range(12, 18))}
# every SIM_STRIDE-th simulated pose (10 ms apart, so 30 ms) enters the term selection: consecutive poses
# add little, and the selection's cost grows with the sample
SIM_STRIDE = 3


def simulated_poses(runs: str) -> np.ndarray:
    """Poses (n, 11) rad of das3's simulated motions, every 10 ms of 2 s runs from the settled arm: 'train'
    (the protocols at full level, random runs 0-5), 'valid' (85 %, runs 12-17) or 'test' (70 %, runs 6-11)."""
    import armrt

    from .das3_simulated_poses import PROTOCOLS, ramp, random_excitation, run_from_settled
    model = armrt.Model("das3")
    level, seeds = SIMULATED_SETS[runs]
    excitations = [(label, ramp(model, groups, level)) for label, groups in PROTOCOLS]
    excitations += [(f"random excitations (seed {1000 + seed})",
                     random_excitation(np.random.default_rng(1000 + seed), model.n_elements)) for seed in seeds]
    return np.concatenate([q for _, q in run_from_settled(excitations)])


def refit_coefficients(exponents, dof_idx, samples_list, bads, k):
    """Least-squares coefficients for fixed exponents of element k over several sample sets."""
    from . import fit_paths as fp
    A_parts, b_parts = [], []
    for s, bad in zip(samples_list, bads):
        ok = ~bad[:, k]
        q = s["q"][ok][:, dof_idx]
        P, dP = fp.design(q, exponents)
        L, ma = s["length"][ok][:, k], s["ma"][ok][:, k][:, dof_idx]
        A_parts.append(np.vstack([P] + [-fp.MA_WEIGHT * dP[j] for j in range(len(dof_idx))]))
        b_parts.append(np.concatenate([L] + [fp.MA_WEIGHT * ma[:, j] for j in range(len(dof_idx))]))
    A, b = np.vstack(A_parts), np.concatenate(b_parts)
    nrm = np.linalg.norm(A, axis=0)
    nrm[nrm == 0] = 1.0
    return np.linalg.lstsq(A / nrm, b, rcond=None)[0] / nrm


def merged(samples, bads, strides):
    """One sample set (q, length, ma, cross) and its wrap-jump mask from several, each taken every
    stride-th pose."""
    out = {k: np.concatenate([s[k][::st] for s, st in zip(samples, strides)]) for k in ("q", "length", "ma")}
    out["cross"] = samples[0]["cross"]
    return out, np.concatenate([b[::st] for b, st in zip(bads, strides)])


def main(argv=None) -> int:
    import argparse

    from . import das3_paths as dp
    from . import opensim_geometry as og
    from .das3_chain import DAS3_DOFS
    from .das3_rom import Das3Rom
    from .das3_simulated_poses import replace_section
    ap = argparse.ArgumentParser(prog="python -m codegen.importers.das3_refit_simulated", description=__doc__.split("\n\n")[0])
    ap.add_argument("--das3", default=str(ROOT / ".." / "shared" / "reference" / "das3"))
    ap.add_argument("--paths", default=str(ROOT / "models" / "das3_paths.json"))
    ap.add_argument("--report", help="append (or replace) the section in this markdown file")
    ap.add_argument("--cache", default=str(ROOT / "build"))
    ap.add_argument("--processes", type=int, default=2)
    ap.add_argument("--reselect", action="store_true",
                    help="for elements still missing the criterion after the coefficient refit, also select "
                         "their terms afresh (codegen/importers/das3_fit.py's forward selection) over the fit's region "
                         "plus das3's simulated motions, and keep them where the worst error falls")
    ap.add_argument("--reselect-elements", nargs="*", metavar="NAME",
                    help="with --reselect: only these elements (default: every one still missing the criterion)")
    a = ap.parse_args(argv)
    t0 = time.time()
    paths = json.loads(Path(a.paths).read_text())
    sampling = paths["sampling"]
    els = [{"name": e["name"], "osim_name": e["osim_name"]} for e in paths["elements"]]
    osim = f"{a.das3}/das3.osim"
    rom = Das3Rom(a.das3)
    sets = {
        "fit_train": dp.cached_sample(osim, els, rom.sample(sampling["train"], sampling["seed"]), a.cache,
                                      f"train{sampling['seed']}", a.processes),
        "fit_test": dp.cached_sample(osim, els, rom.sample(sampling["test"], sampling["test_seed"]), a.cache,
                                     f"eval{sampling['test_seed']}", a.processes),
        "sim_train": dp.cached_sample(osim, els, simulated_poses("train"), a.cache, "simtrain", a.processes),
        "sim_test": dp.cached_sample(osim, els, simulated_poses("test"), a.cache, "simtest", a.processes),
    }
    # Poses simulated by earlier versions of the model (an earlier run of this refit changed the paths, so
    # the model moves elsewhere now): kept in training, so that repeated runs approach a fixed point.
    earlier = []
    for f in sorted(Path(a.cache).glob("das3_samples_simtrain_*.npz")):
        with np.load(f, allow_pickle=False) as z:
            s_old = {k: z[k] for k in z.files}
        if len(s_old["q"]) and not np.array_equal(s_old["q"], sets["sim_train"]["q"]):
            earlier.append(s_old)
    if a.reselect:
        sets["fit_valid"] = dp.cached_sample(osim, els, rom.sample(sampling["valid"], sampling["seed"] + 7919),
                                             a.cache, f"valid{sampling['seed']}", a.processes)
        sets["sim_valid"] = dp.cached_sample(osim, els, simulated_poses("valid"), a.cache, "simvalid", a.processes)
    bad = {k: og.wrap_jumps(s) for k, s in sets.items()}
    bad_earlier = [og.wrap_jumps(s) for s in earlier]
    t_sample = time.time() - t0

    def worst_ratio(e, coefs, key, exponents=None):
        pred = dp.polynomial_moment_arms(exponents or e["length_poly"]["exponents"], coefs, e["length_poly"]["dofs"],
                                         sets[key]["q"])
        k = [x["name"] for x in paths["elements"]].index(e["name"])
        st = dp.score(_one(sets[key], k), [pred], bad[key][:, [k]])[0]
        return st

    changed, rows = 0, []
    for k, e in enumerate(paths["elements"]):
        lp = e["length_poly"]
        idx = [DAS3_DOFS.index(d) for d in lp["dofs"]]
        new = refit_coefficients(lp["exponents"], idx, [sets["fit_train"], sets["sim_train"], *earlier],
                                 [bad["fit_train"], bad["sim_train"], *bad_earlier], k).tolist()
        old_st = {key: worst_ratio(e, lp["coefs"], key) for key in ("fit_test", "sim_test")}
        new_st = {key: worst_ratio(e, new, key) for key in ("fit_test", "sim_test")}
        r_old = max(s["max_err_m"] / s["criterion_m"] for s in old_st.values())
        r_new = max(s["max_err_m"] / s["criterion_m"] for s in new_st.values())
        use_new = r_new < r_old
        if use_new:
            lp["coefs"] = new
            changed += 1
        chosen = new_st if use_new else old_st
        was = e["fit"].get("simulated", {})
        # e["fit"] scores the polynomial as it now is on the fit's test sample (the report's per-element table)
        e["fit"].update(chosen["fit_test"])
        e["fit"]["simulated"] = {"refit": use_new or was.get("refit", False), "reselected": was.get("reselected", False),
                                 "fit_test": chosen["fit_test"], "sim_test": chosen["sim_test"]}
        rows.append((e["name"], old_st, new_st, use_new))
    reselected, n_tried, t_select = 0, 0, 0.0
    if a.reselect:
        from . import das3_fit
        todo = [k for k, (_, o, n, u) in enumerate(rows)
                if not ((n if u else o)["fit_test"]["pass"] and (n if u else o)["sim_test"]["pass"])]
        if a.reselect_elements:
            names = [r[0] for r in rows]
            unknown = sorted(set(a.reselect_elements) - set(names))
            if unknown:
                ap.error(f"unknown elements {unknown}")
            todo = [k for k in todo if names[k] in a.reselect_elements]
        n_tried = len(todo)
        tr, bad_tr = merged([sets["fit_train"], sets["sim_train"], *earlier],
                            [bad["fit_train"], bad["sim_train"], *bad_earlier], [1] + [SIM_STRIDE] * (1 + len(earlier)))
        va, bad_va = merged([sets["fit_valid"], sets["sim_valid"]], [bad["fit_valid"], bad["sim_valid"]], [1, SIM_STRIDE])
        t1 = time.time()
        fits, _ = das3_fit.fit_all(todo, tr, va, bad_tr, bad_va, a.processes, [rows[k][0] for k in todo])
        t_select = time.time() - t1
        for k, f in zip(todo, fits):
            e, (name, o, n, u) = paths["elements"][k], rows[k]
            cur = n if u else o
            sel_st = {key: worst_ratio(e, f["coefs"], key, f["exponents"]) for key in ("fit_test", "sim_test")}
            r_cur = max(s["max_err_m"] / s["criterion_m"] for s in cur.values())
            r_sel = max(s["max_err_m"] / s["criterion_m"] for s in sel_st.values())
            if r_sel < r_cur:
                e["length_poly"]["exponents"], e["length_poly"]["coefs"] = f["exponents"], f["coefs"]
                e["fit"].update(sel_st["fit_test"])
                e["fit"]["simulated"] = {"refit": True, "reselected": True, **sel_st}
                rows[k] = (name, o, sel_st, True)
                reselected += 1
    paths["refit_simulated_command"] = "python -m codegen.importers.das3_refit_simulated" + (" --reselect" if a.reselect else "")
    Path(a.paths).write_text(json.dumps(paths, indent=1) + "\n")

    def count(which, key):
        return sum(1 for _, o, n, u in rows if ((n if (u if which == "chosen" else which == "new") else o)[key]["pass"]))
    summary = {key: {"before": count("old", key), "after": count("chosen", key)} for key in ("fit_test", "sim_test")}
    both_before = sum(1 for _, o, n, u in rows if o["fit_test"]["pass"] and o["sim_test"]["pass"])
    both_after = sum(1 for _, o, n, u in rows if (n if u else o)["fit_test"]["pass"] and (n if u else o)["sim_test"]["pass"])
    fails = [(name, (n if u else o)) for name, o, n, u in rows
             if not ((n if u else o)["fit_test"]["pass"] and (n if u else o)["sim_test"]["pass"])]
    fails.sort(key=lambda x: -max(s["max_err_m"] / s["criterion_m"] for s in x[1].values()))
    lines = ["## Refit over das3's own simulated motions", "",
             f"`python -m codegen.importers.das3_refit_simulated{' --reselect' if a.reselect else ''}` ({time.time() - t0:.0f} s, "
             f"{t_sample:.0f} s of it sampling "
             "OpenSim): every element keeps its terms; the coefficients are refitted over the fit's "
             f"{len(sets['fit_train']['q'])} training poses plus {len(sets['sim_train']['q'])} poses of das3's "
             "simulated motions (the protocols above at full level and six seeded random runs, every 10 ms)"
             + (f" and {sum(len(e['q']) for e in earlier)} poses simulated by the model before earlier runs of this "
                f"refit ({len(earlier)}; a refit moves the model, so it is run until the scores settle)"
                if earlier else "") + ", and "
             f"kept where that lowers the element's worst error over the two held-out samples: the fit's "
             f"{len(sets['fit_test']['q'])} test poses and {len(sets['sim_test']['q'])} poses of other simulated "
             f"runs (the protocols at 70 %, six other random runs). Refitted: {changed} of {len(rows)} elements."
             + (f" Then the {n_tried} elements still missing the criterion had their terms selected afresh "
                f"(codegen/importers/das3_fit.py's forward selection, {t_select / 60:.0f} min) over the fit's training poses "
                f"plus every {SIM_STRIDE}rd simulated training pose, stopping on the fit's "
                f"{len(sets['fit_valid']['q'])} validation poses plus every {SIM_STRIDE}rd of "
                f"{len(sets['sim_valid']['q'])} poses of a third set of simulated runs (the protocols at 85 %, "
                f"six more random runs); kept for {reselected} of them, where the worst held-out error fell."
                if a.reselect else ""), "",
             "| elements meeting the criterion at every pose | before | after |", "|---|---|---|",
             f"| on the fit's test sample | {summary['fit_test']['before']} | {summary['fit_test']['after']} |",
             f"| on the held-out simulated motions | {summary['sim_test']['before']} | {summary['sim_test']['after']} |",
             f"| on both | {both_before} | {both_after} |", "",
             "Still missing (worst error / criterion over both samples, DOF): " + (", ".join(
                 f"{name} {max(s['max_err_m'] / s['criterion_m'] for s in st.values()):.1f}x "
                 f"({max(st.values(), key=lambda s: s['max_err_m'] / s['criterion_m'])['worst_dof']})"
                 for name, st in fails) or "none") + ".", ""]
    text = "\n".join(lines)
    print(text)
    if a.report:
        replace_section(Path(a.report), "## Refit over das3's own simulated motions", text)
    return 0


def _one(s, k):
    """The sample set s restricted to element k (the form das3_paths.score takes)."""
    return {"names": s["names"][[k]], "cross": s["cross"][[k]], "ma": s["ma"][:, [k]], "q": s["q"]}


if __name__ == "__main__":
    raise SystemExit(main())
