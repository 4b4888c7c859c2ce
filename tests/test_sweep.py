"""armrt.sweep: results in item order, gathered as arrays, locally and as Ray tasks on a local Ray
(2 CPUs, no dashboard, bounded in time); the Fig. 3 cuff grid runs the same on both backends."""
import signal
from contextlib import contextmanager

import numpy as np
import pytest

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
from armrt.sweeps import gather, sweep  # noqa: E402

RAY_BUDGET_S = 240   # the whole Ray part: start, tasks, shutdown


def settle_elbow(level):
    """A whole (short) simulation per item."""
    arm = armrt.Arm()
    arm.set_excitation({"elbow_flexors": level})
    arm.step(100)
    return {"q": np.array(arm.q), "gh_stab": arm.gh_stab}


def fails_on_two(x):
    if x == 2:
        raise ValueError("item two is bad")
    return x


def test_local_keeps_order_and_gathers_arrays():
    out = sweep(settle_elbow, [0.4, 0.0, 0.2], progress=False)
    assert out["q"].shape == (3, len(armrt.Arm().dof_names)) and out["gh_stab"].shape == (3,)
    for k, level in enumerate([0.4, 0.0, 0.2]):
        one = settle_elbow(level)
        assert np.array_equal(out["q"][k], one["q"]) and out["gh_stab"][k] == one["gh_stab"]
    elbow = armrt.Arm().dof_names.index("ELx")
    assert out["q"][0, elbow] > out["q"][2, elbow] > out["q"][1, elbow]   # more flexor drive, more elbow flexion


def test_gather_and_errors():
    assert gather([1, 2, 3]).tolist() == [1, 2, 3]
    assert gather([np.zeros(2), np.zeros(3)])[1].shape == (3,)            # ragged: left as a list
    assert sweep(str, [1, 2], progress=False, stack=False) == ["1", "2"]
    with pytest.raises(ValueError, match="unknown backend"):
        sweep(str, [1], backend="dask")
    with pytest.raises(ValueError, match="item two"):
        sweep(fails_on_two, [1, 2, 3], progress=False)


@contextmanager
def time_limit(seconds):
    def on_alarm(signum, frame):
        raise TimeoutError(f"Ray part of the test took longer than {seconds} s")
    old = signal.signal(signal.SIGALRM, on_alarm)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


@pytest.fixture(scope="module")
def local_ray():
    ray = pytest.importorskip("ray", reason="needs ray (pip install ray)")
    with time_limit(RAY_BUDGET_S):
        ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
        try:
            yield ray
        finally:
            ray.shutdown()


def test_ray_matches_local_in_order_and_propagates_errors(local_ray):
    items = [0.3, 0.0, 0.1, 0.2]
    remote = sweep(settle_elbow, items, backend="ray", progress=False)
    local = sweep(settle_elbow, items, backend="local", progress=False)
    assert np.array_equal(remote["q"], local["q"]) and np.array_equal(remote["gh_stab"], local["gh_stab"])
    with pytest.raises(ValueError, match="item two"):
        sweep(fails_on_two, [1, 2, 3], backend="ray", progress=False)


def test_fig3_cuff_grid_on_ray_equals_local(local_ray):
    from armrt.cuff_grid import cuff_grid, grid_setup
    setup = grid_setup()
    kw = dict(levels=[0.149], boosts=[0.0, 0.2], setup=setup, progress=False)
    remote = cuff_grid(backend="ray", **kw)
    local = cuff_grid(backend="local", **kw)
    assert remote["gh_stab_max"].shape == (1, 2)
    assert np.array_equal(remote["gh_stab_max"], local["gh_stab_max"])
    assert np.array_equal(remote["elevation_deg"], local["elevation_deg"])
    assert np.all(remote["elevation_deg"] > 20)   # the deltoid really elevates the arm


def test_progress_bar_only_on_a_terminal_unless_asked(monkeypatch):
    """README: progress bars appear only on a terminal; sweep drew one into pipes and logs (progress
    defaulted to True, tqdm's disable=False). It now uses armrt.progress.bar like every other loop."""
    pytest.importorskip("tqdm")
    import io
    import sys
    plain = io.StringIO()
    monkeypatch.setattr(sys, "stderr", plain)
    assert sweep(str, [1, 2], stack=False) == ["1", "2"]
    assert plain.getvalue() == ""
    sweep(str, [1, 2], progress=True, stack=False)
    assert "sweep" in plain.getvalue()
