"""The redesign of issue 25 keeps the physics: every golden run of tests/golden_runs.py (das2 and das3,
ROS2, RK4 and Euler, recorded states and outputs, a weakened arm, a batch) comes out bit for bit."""
import numpy as np
import pytest

from tests.golden_runs import FILE, runs


@pytest.fixture(scope="module")
def fresh():
    return runs()


def test_golden_runs_bit_for_bit(fresh):
    saved = np.load(FILE)
    assert sorted(saved.files) == sorted(fresh), "the golden runs record other arrays than the saved file"
    differing = [k for k in saved.files if not np.array_equal(saved[k], fresh[k], equal_nan=True)]
    worst = {k: float(np.nanmax(np.abs(saved[k] - fresh[k]))) for k in differing[:5]}
    assert not differing, f"{len(differing)} arrays differ from {FILE.name}, e.g. {worst}"
