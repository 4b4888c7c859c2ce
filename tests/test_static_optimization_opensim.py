"""armrt's static optimisation beside OpenSim's StaticOptimization on das2's problem (bench.static_optimization_opensim;
docs/control.md "OpenSim's StaticOptimization beside ours"): a short run of the benchmark, checking that both solve
the same problem (the same frames, activations of the same elements moving together)."""
from pathlib import Path

import pytest

from bench.bench_opensim import DEFAULT_OSIM


@pytest.mark.opensim
def test_static_optimization_beside_opensim_on_a_short_motion(tmp_path: Path):
    pytest.importorskip("opensim", reason="opensim (pip install opensim) is not installed")
    if not DEFAULT_OSIM.exists():
        pytest.skip(f"{DEFAULT_OSIM} not present (needs ../shared/reference/das3 beside the repository)")
    from bench.static_optimization_opensim import main

    out = main(["--quick", "--out", str(tmp_path / "so.json")])
    assert (tmp_path / "so.md").read_text().startswith("Static optimisation, armrt vs OpenSim")
    assert out["opensim"]["n_muscles"] == 102
    for tendon, r in out["armrt"].items():
        assert r["infeasible_frames"] == 0, tendon
        c = r["vs_opensim"]
        # Different muscle models and paths (Schutte1993 with wrapping vs DAS3 Hill with polynomials): the same
        # elements must still carry the load, rising and falling together.
        assert c["elements_compared"] > 50
        assert c["correlation_median"] > 0.5, (tendon, c["correlation_median"])
        assert 0.5 < c["sum_activation_ours"] / c["sum_activation_opensim"] < 2.0
