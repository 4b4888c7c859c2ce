"""examples/fes_elbow_hold_pi.py: two minutes of PI pulse-width control holding participant_A_FES's elbow at
90 deg by stimulating its flexors. Its claims (docs/fes.md "Holding the elbow at 90 deg for two minutes"):
the pulse width rises as the fibres fatigue, recruitment saturates within the two minutes, and until then
the elbow stays within 2 deg of the target."""
import importlib.util
from pathlib import Path

import numpy as np
import pytest

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "fes_elbow_hold_pi.py"


@pytest.fixture(scope="module")
def example():
    spec = importlib.util.spec_from_file_location("fes_elbow_hold_pi", EXAMPLE)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.fixture(scope="module")
def two_minutes(example):
    return example.run(120.0)


def test_pulse_width_rises_with_fatigue_until_recruitment_saturates(example, two_minutes):
    r, s = two_minutes, example.summary(two_minutes)
    t = r["t"]
    # 10 s means of the pulse width rise from window to window, as the fatigue of every channel does.
    means = [r["pulse_width"][(t > a) & (t <= a + 10)].mean() for a in range(10, 110, 10)]
    assert np.all(np.diff(means) > 0)
    assert np.all(np.diff(r["fatigue"][::100], axis=0) > 0)
    # Saturation comes, but only after the first minute (Ding 2003's fatigue, tau_fat 127 s).
    assert s["saturation_s"] is not None and 60.0 < s["saturation_s"] < 120.0
    # Holding while not saturated: within the 2 deg that summary() calls lost (1.2 deg at worst, in the last
    # seconds before saturation), and within 1 deg over the first 100 s. The error grows as the pulse width
    # ramps up: a PI lags a ramp by (ramp rate) / KI.
    assert s["max_error_unsaturated_deg"] < 2.0
    early = (t > 3) & (t < 100)
    assert np.degrees(np.abs(r["target"] - r["elbow"][early])).max() < 1.0
    assert s["lost_s"] is not None and s["lost_s"] > s["saturation_s"]


def test_without_fatigue_the_same_controller_holds_at_a_constant_pulse_width(example):
    r = example.run(40.0, fatigue=False)
    t, pw = r["t"], r["pulse_width"]
    late = pw[t > 10]
    assert late.max() - late.min() < 2e-6          # s: nothing to compensate for
    assert np.degrees(np.abs(r["target"] - r["elbow"][t > 10])).max() < 0.5


def test_main_writes_the_figure(example, tmp_path):
    example.main(["--duration", "25", "--out", str(tmp_path / "hold")])
    assert (tmp_path / "hold.png").stat().st_size > 10_000
