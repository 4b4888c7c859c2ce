"""The redesign of issue 25 keeps the physics: every golden run of tests/golden_runs.py (das2 and das3,
ROS2, RK4 and Euler, recorded states and outputs, a weakened arm, a batch) comes out bit for bit.

The golden file was written by an AVX2 build (-march=native on Zen 3); a build with -march=znver3 reproduces the
whole file exactly, and is held to it (armrt._core.BUILD says the target). A native build for another target rounds
differently wherever the compiler vectorises differently: an AVX-512 build on Zen 4 sums the glenohumeral reaction
eight lanes at a time instead of four (GH outputs about 6.5 ulps of their largest value off, states exact); on an
Intel Xeon whose gcc 12 -march=native is icelake-client (2026-12-06), 66 of the 110 arrays moved, the states too, by
at most 1.9e-13 of each array's largest value (muscle forces; qdot 2.0e-14). Such builds are held to
RELATIVE_ROUNDING of each array's largest value: 50 times that, and far below any change of the physics (the check
below: a 1e-9 change fails). gcc 12's -march=native on a Zen 4 defines __znver3__ (it knows no znver4) with AVX-512:
BUILD's avx512f tells that build from a -march=znver3 one (the fresh-clone CI on such a machine, 2026-12-07, held it
bit for bit and failed 36 arrays off by at most 6.8e-13 N in gh_force)."""
import numpy as np
import pytest

from armrt import _core
from tests.golden_runs import FILE, runs

RELATIVE_ROUNDING = 1e-11
# gcc 12 names a Zen 4 "znver3" under -march=native (it has no znver4) and defines __znver3__ with AVX-512 on: that
# build is not the reference's (a -march=znver3 build has no AVX-512; Zen 3 has none), and is held to rounding.
REFERENCE_BUILD = bool(_core.BUILD["march_znver3"]) and not bool(_core.BUILD["avx512f"])


@pytest.fixture(scope="module")
def fresh():
    return runs()


def _differences(saved, fresh, reference_build=REFERENCE_BUILD):
    off = {}
    for k in saved.files:
        a, b = saved[k], fresh[k]
        if np.array_equal(a, b, equal_nan=True):
            continue
        if a.shape == b.shape and np.array_equal(np.isnan(a), np.isnan(b)) and not reference_build:
            scale = float(np.nanmax(np.abs(a))) if a.size else 0.0
            worst = float(np.nanmax(np.abs(a - b)))
            if worst <= RELATIVE_ROUNDING * scale:
                continue
        off[k] = float(np.nanmax(np.abs(a - b))) if a.shape == b.shape else "shape"
    return off


def test_golden_runs_bit_for_bit(fresh):
    saved = np.load(FILE)
    assert sorted(saved.files) == sorted(fresh), "the golden runs record other arrays than the saved file"
    off = _differences(saved, fresh)
    assert not off, f"{len(off)} arrays differ from {FILE.name}, e.g. {dict(list(off.items())[:5])}"


def test_golden_comparison_catches_a_changed_state_and_a_gh_output_beyond_rounding():
    saved = np.load(FILE)
    same = {k: saved[k] for k in saved.files}
    assert not _differences(saved, same, True) and not _differences(saved, same, False)
    state_key = next(k for k in saved.files if k.endswith("/final_x"))
    gh_key = next(k for k in saved.files if k.endswith("/gh_force"))
    ulp = dict(same)
    ulp[state_key] = np.nextafter(same[state_key], np.inf)  # one ulp on a state is a change for the reference build
    ulp[gh_key] = np.nextafter(same[gh_key], np.inf)
    assert set(_differences(saved, ulp, True)) == {state_key, gh_key}
    assert not _differences(saved, ulp, False)  # rounding, for another target
    changed = dict(same)
    changed[state_key] = same[state_key] * (1 + 1e-9)  # no rounding on any target
    changed[gh_key] = same[gh_key] * (1 + 1e-9)
    assert set(_differences(saved, changed, False)) == {state_key, gh_key}
