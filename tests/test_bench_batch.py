"""bench/bench_batch.py runs end to end (its --quick smoke size) and writes every section."""
import json

import pytest

pytest.importorskip("gymnasium", reason="needs gymnasium (pip install gymnasium)")
pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")


def test_bench_batch_quick_writes_json_and_markdown(tmp_path):
    from bench import bench_batch
    js, md = tmp_path / "batch.json", tmp_path / "batch.md"
    assert bench_batch.main(["--quick", "--json", str(js), "--md", str(md)]) == 0
    res = json.loads(js.read_text())
    runs = res["armrt"]["runs"]
    assert set(runs) == {f"n{n}_t{t}" for n in bench_batch.NS for t in bench_batch.THREADS}
    assert all(r["arm_steps_per_s"] > 0 for r in runs.values())
    assert "scaling_efficiency" in runs["n512_t2"]
    assert {"sync_n8", "vector_n8_t1", "vector_n8_t2"} <= set(res["vector_env"]["runs"])
    assert "runs" in res["mujoco"] or "skipped" in res["mujoco"]
    text = md.read_text()
    assert "python -m bench.bench_batch --quick" in text and "| 512 |" in text
