"""The benchmarks find this tree's C++ tools, never the old commit bench_integrators builds under build/baseline
(on a fresh clone `./run.sh bench` built it after build/bench, and the das3 part ran the baseline's armrt_bench,
which has no --model)."""
import os
import time

from bench import bench_engine, bench_scaling


def _tool(path):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("#!/bin/sh\n")
    os.chmod(path, 0o755)
    return path


def test_the_baseline_build_is_never_picked_even_when_newest(tmp_path, monkeypatch):
    monkeypatch.setattr(bench_engine, "ROOT", tmp_path)
    monkeypatch.setattr(bench_scaling, "ROOT", tmp_path)
    dev = _tool(tmp_path / "build" / "dev" / "cpp" / "tools" / "armrt_bench")
    _tool(tmp_path / "build" / "dev" / "cpp" / "tools" / "armrt_bench_scaling")
    time.sleep(0.01)
    _tool(tmp_path / "build" / "baseline" / "build" / "bench" / "cpp" / "tools" / "armrt_bench")
    _tool(tmp_path / "build" / "baseline" / "build" / "bench" / "cpp" / "tools" / "armrt_bench_scaling")
    assert bench_engine.find_cpp_bench() == dev
    assert bench_scaling.newest("armrt_bench_scaling") == dev.parent / "armrt_bench_scaling"
    # build/bench's, what ./run.sh bench builds, is preferred over a newer one elsewhere.
    ours = _tool(tmp_path / "build" / "bench" / "cpp" / "tools" / "armrt_bench")
    time.sleep(0.01)
    _tool(tmp_path / "build" / "other" / "cpp" / "tools" / "armrt_bench")
    assert bench_engine.find_cpp_bench() == ours


def test_a_reduced_model_builds_against_the_shared_engine_and_runs():
    """bench_scaling's reduced models link the engine's one shared library (libarmrt.so under build/, which
    ./run.sh test and ./run.sh bench build); they looked for the static libarmrt_engine.a of before, found only
    build/baseline's, and every link failed (fresh-clone ./run.sh bench, 2026-12-07)."""
    import pytest

    if bench_scaling.newest("libarmrt.so") is None:
        pytest.skip("no libarmrt.so under build/ (cmake --build build/ctest)")
    rows = bench_scaling.measure_subsets(reps=200, sizes=(6,))
    assert len(rows) == 1 and rows[0]["n"] == 6
    assert rows[0]["muscle_paths_ns"] > 0 and rows[0]["rk4_step_ns"] > rows[0]["muscle_paths_ns"]
