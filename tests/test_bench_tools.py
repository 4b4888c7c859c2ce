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
