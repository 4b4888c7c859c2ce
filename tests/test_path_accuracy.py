"""Muscle-path polynomials: the fitting routine on a known polynomial, and the model file against a
fresh OpenSim sample (paper II-C criterion)."""
import importlib.util
from pathlib import Path

import numpy as np
import pytest

from codegen.importers import fit_paths as fp

ROOT = Path(__file__).resolve().parents[1]
REFERENCE = ROOT / ".." / "shared" / "reference"
MODEL = ROOT / "models" / "das2.json"

N_POSES = 256
# Bounds of the current fits. Achieved on this sample (seed 987, 256 poses): 92 of 102 elements
# meet the criterion at every pose (docs/path_accuracy.md, 1024 poses: 93), 0.62% of
# element-poses over it, worst error 7.5 x criterion (deltscap2, whose path flips over the humeral
# head near GHz 1.05-1.25), line of action worst element p99 17.4 deg / RMS 5.9 deg (deltscap2),
# overall RMS 2.05 deg; infraspinatus 4/5 lose up to 15% of the poses to wrap-jump exclusion at
# high elevation. The bounds guard against regressions (about 1.3-1.5x the achieved values, 2
# elements of slack); the paper's criterion itself is the per-element pass.
MIN_PASSING = 90           # elements meeting the criterion at every scored pose
MAX_OVER_FRACTION = 0.0093 # element-poses over the criterion / scored element-poses
MAX_ERROR_RATIO = 10.0     # worst single moment-arm error / that element's criterion
LOA_P99_DEG = 22.0         # per element, 99th percentile line-of-action angle error
LOA_RMS_DEG = 7.5          # per element RMS
LOA_RMS_ALL_DEG = 2.6      # RMS over all GH-crossing elements
MIN_SCORED_FRACTION = 0.8  # per element, poses not excluded as wrap jumps
# Size of the polynomials (the real-time engine evaluates every path 4x per RK4 step).
MAX_LENGTH_TERMS = 1480    # achieved 1408
MAX_LOA_TERMS = 1000       # achieved 912 (x, y, z components counted separately)


def test_fit_length_recovers_known_polynomial():
    rng = np.random.default_rng(3)
    exps = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (0, 2, 1), (2, 0, 0), (1, 1, 1)]
    coefs = np.array([0.2, -0.03, 0.02, 0.015, 0.01, -0.004, 0.006, 0.003])
    poly = {"exponents": exps, "coefs": coefs}
    q_tr = rng.uniform(-1, 1.5, (600, 3))
    q_va = rng.uniform(-1, 1.5, (300, 3))
    L_tr, g_tr = fp.eval_poly(poly, q_tr)
    L_va, g_va = fp.eval_poly(poly, q_va)
    peak = np.abs(g_tr).max()
    got_e, got_c = fp.fit_length(q_tr, L_tr, -g_tr, q_va, L_va, -g_va, fp.criterion(peak))
    _, g = fp.eval_poly({"exponents": got_e, "coefs": got_c}, q_va)
    assert np.abs(g - g_va).max() < fp.criterion(peak)
    assert len(got_c) <= 12
    # Run to all candidate terms, the known coefficients come back exactly.
    big_e, big_c = fp.fit_length(q_tr, L_tr, -g_tr, q_va, L_va, -g_va, 1e-12)
    full = {tuple(e): c for e, c in zip(big_e, big_c)}
    for e, c in zip(exps, coefs):
        assert full[e] == pytest.approx(c, abs=1e-8)


def test_monomial_derivatives_match_finite_difference():
    rng = np.random.default_rng(0)
    exps = fp.monomials(3, 4)
    q = rng.uniform(-1, 2, (20, 3))
    P, dP = fp.design(q, exps)
    h = 1e-6
    for j in range(3):
        dq = np.zeros(3); dq[j] = h
        fd = (fp.design(q + dq, exps)[0] - fp.design(q - dq, exps)[0]) / (2 * h)
        np.testing.assert_allclose(dP[j], fd, rtol=1e-6, atol=1e-6)


@pytest.mark.skipif(not MODEL.exists(), reason=f"{MODEL} absent (run python -m codegen.import_das3)")
def test_model_path_polynomial_sizes():
    import json
    els = json.loads(MODEL.read_text())["elements"]
    assert len(els) == 102
    n_len = sum(len(e["length_poly"]["coefs"]) for e in els)
    n_loa = sum(3 * len(e["gh_direction"]["x"]["coefs"]) for e in els if e.get("gh_direction"))
    assert n_len <= MAX_LENGTH_TERMS, n_len
    assert n_loa <= MAX_LOA_TERMS, n_loa
    for e in els:
        assert len(e["length_poly"]["coefs"]) <= max(fp.EXT_TERMS.values()), e["name"]
        if e.get("gh_direction"):
            assert len(e["gh_direction"]["x"]["coefs"]) <= fp.DIR_MAX_TERMS, e["name"]
            assert max(sum(x) for x in e["gh_direction"]["x"]["exponents"]) <= fp.DIR_MAX_DEGREE


def _skip_reason():
    if importlib.util.find_spec("opensim") is None:
        return "opensim is not importable"
    if not (REFERENCE / "das3" / "das3.osim").exists():
        return f"reference data absent ({REFERENCE.resolve()})"
    if not MODEL.exists():
        return f"{MODEL} absent (run python -m codegen.import_das3)"
    return None


@pytest.mark.opensim
@pytest.mark.skipif(_skip_reason() is not None, reason=str(_skip_reason()))
def test_model_paths_match_fresh_opensim_sample():
    from codegen.importers import report_paths
    model = report_paths.load_model(MODEL)
    stats, _, _ = report_paths.evaluate_model(model, str(REFERENCE / "das3" / "das3.osim"),
                                              N_POSES, seed=987)
    assert len(stats) == 102
    n_pass = sum(s["meets_criterion"] for s in stats.values())
    assert n_pass >= MIN_PASSING, f"only {n_pass} elements meet the criterion"
    n_over = sum(s["n_samples_over_criterion"] for s in stats.values())
    n_tot = sum(s["n_samples"] for s in stats.values())
    assert n_over <= MAX_OVER_FRACTION * n_tot, f"{n_over} of {n_tot} element-poses over criterion"
    ratio = {k: s["moment_arm_max_err_m"] / s["criterion_m"] for k, s in stats.items()}
    worst = max(ratio, key=ratio.get)
    assert ratio[worst] < MAX_ERROR_RATIO, f"{worst}: max error {ratio[worst]:.2f} x criterion"
    for k, s in stats.items():
        assert s["n_samples"] >= MIN_SCORED_FRACTION * N_POSES, f"{k}: too many wrap-jump exclusions"
        if "direction_rms_deg" in s:
            assert s["direction_p99_deg"] < LOA_P99_DEG, k
            assert s["direction_rms_deg"] < LOA_RMS_DEG, k
    gh = [s["direction_rms_deg"] for s in stats.values() if "direction_rms_deg" in s]
    assert len(gh) == 67
    assert np.sqrt(np.mean(np.square(gh))) < LOA_RMS_ALL_DEG
