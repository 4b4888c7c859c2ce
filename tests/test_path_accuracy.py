"""Muscle-path polynomials: the fitting routine on a known polynomial, and the model file against a
fresh OpenSim sample (paper II-C criterion)."""
import importlib.util
from pathlib import Path

import numpy as np
import pytest

from codegen import fit_paths as fp

ROOT = Path(__file__).resolve().parents[1]
REFERENCE = ROOT / ".." / "shared" / "reference"
MODEL = ROOT / "models" / "das2.json"

N_POSES = 256
# Bounds of the current fits (docs/path_accuracy.md: 59-62 of 102 elements meet the criterion at
# every pose; the deltoid/subscapularis sphere-wrap kinks, infraspinatus 4-6 and teres minor miss
# it on 3% of element-poses). They guard against regressions; they are not the paper's criterion.
MAX_OVER_FRACTION = 0.04   # element-poses over the criterion / scored element-poses
MAX_ERROR_RATIO = 11.0     # worst single moment-arm error / that element's criterion
LOA_P99_DEG = 25.0         # per element, 99th percentile line-of-action angle error
LOA_RMS_DEG = 6.0          # per element RMS


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
    from codegen import report_paths
    model = report_paths.load_model(MODEL)
    stats, _, _ = report_paths.evaluate_model(model, str(REFERENCE / "das3" / "das3.osim"),
                                              N_POSES, seed=987)
    assert len(stats) == 102
    n_over = sum(s["n_samples_over_criterion"] for s in stats.values())
    n_tot = sum(s["n_samples"] for s in stats.values())
    assert n_over <= MAX_OVER_FRACTION * n_tot, f"{n_over} of {n_tot} element-poses over criterion"
    ratio = {k: s["moment_arm_max_err_m"] / s["criterion_m"] for k, s in stats.items()}
    worst = max(ratio, key=ratio.get)
    assert ratio[worst] < MAX_ERROR_RATIO, f"{worst}: max error {ratio[worst]:.2f} x criterion"
    for k, s in stats.items():
        assert s["n_samples"] >= 0.9 * N_POSES, f"{k}: too many wrap-jump exclusions"
        if "direction_rms_deg" in s:
            assert s["direction_p99_deg"] < LOA_P99_DEG, k
            assert s["direction_rms_deg"] < LOA_RMS_DEG, k
