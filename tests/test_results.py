"""Issue 11, item 5: results that fit in memory (estimate, limit with the record_every hint,
`--record-every`), and a Result that is easy to look at (short repr, DataFrame, plot)."""
import re

import numpy as np
import pytest

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
from armrt.arm import RESULT_MEMORY_LIMIT  # noqa: E402


def test_an_hour_at_1_ms_is_refused_with_the_record_every_that_fits(arm):
    """The issue's example: simulate(duration=3600) would record 15 GB."""
    rows = 3_600_001
    assert arm.result_bytes(3600) == rows * 8 * (5 * 102 + 26)          # 15.44 GB
    with pytest.raises(MemoryError, match=r"would record 3600001 rows = 15.4 GB") as err:
        arm.simulate({"bicb": 0.1}, 3600)
    k = int(re.search(r"record_every=(\d+)", str(err.value)).group(1))
    assert arm.result_bytes(3600, record_every=k) <= RESULT_MEMORY_LIMIT < arm.result_bytes(3600, record_every=k - 1)
    assert arm.time == 0.0, "refused before stepping"


def test_result_rows_match_the_estimate(arm):
    for duration, every in ((0.05, 1), (0.05, 7), (0.05, 10), (0.0, 3)):
        arm.reset()
        res = arm.simulate(0.05, duration, record_every=every)
        assert sum(getattr(res, k).nbytes for k in armrt.Result.ARRAYS) == arm.result_bytes(duration, every)


def test_blocks_give_the_same_result_as_one_loop(arm, monkeypatch):
    """simulate() runs in blocks of C++ steps; the joins must not show (rows, times, values)."""
    u = lambda t: {"elbow_flexors": 0.3 if t > 0.02 else 0.0, "rotator_cuff": 0.05}  # noqa: E731
    one = arm.simulate(u, 0.1, record_every=3)
    monkeypatch.setattr(armrt.arm, "SIMULATE_BLOCK_STEPS", 7)
    arm.reset()
    blocks = arm.simulate(u, 0.1, record_every=3)
    for k in armrt.Result.ARRAYS:
        if k != "tet_ns":
            np.testing.assert_array_equal(getattr(blocks, k), getattr(one, k), err_msg=k)
    np.testing.assert_allclose(one.time, np.arange(0, 0.1 + 1e-9, 0.003)[:len(one.time)], atol=1e-12)


def test_max_bytes_lets_a_big_run_through(arm):
    with pytest.raises(MemoryError):
        arm.simulate(0.0, 0.1, max_bytes=1000)
    res = arm.simulate(0.0, 0.1, max_bytes=10**9)
    assert len(res.time) == 101


def test_cli_record_every(tmp_path, capsys):
    from armrt.cli import main
    out = tmp_path / "r.npz"
    assert main(["simulate", "bicb=0.2", "--duration", "0.1", "--record-every", "10", "-o", str(out)]) == 0
    res = armrt.Result.load(out)
    assert len(res.time) == 11 and res.time[1] == pytest.approx(0.01)
    assert main(["simulate", "--duration", "3600"]) == 2
    assert "record_every=8" in capsys.readouterr().err


def test_short_repr(arm):
    res = arm.simulate({"bicb": 0.3}, 0.05, record_every=10)
    text = repr(res)
    assert "\n" not in text and len(text) < 300
    assert text.startswith("Result(das2, rk4 dt=1 ms x6 substeps: 6 rows, every 10 steps, t = 0 to 0.05 s")
    q_end = np.degrees(res.q[-1])
    assert f"{q_end[3]:.1f}" in text


def test_to_dataframe(arm):
    pd = pytest.importorskip("pandas")
    res = arm.simulate({"bicb": 0.3}, 0.02, record_every=5)
    df = res.to_dataframe()
    assert isinstance(df, pd.DataFrame) and df.shape == (5, 535)
    np.testing.assert_array_equal(df.index.to_numpy(), res.time)
    np.testing.assert_array_equal(df["q.ELx"].to_numpy(), res.q[:, 3])
    np.testing.assert_array_equal(df["activation.bicb1"].to_numpy(), res.activation[:, res.element_names.index("bicb1")])
    np.testing.assert_array_equal(df["thorax_humerus.elevation"].to_numpy(), res.thorax_humerus[:, 1])
    assert list(res.to_dataframe(["gh_stab"]).columns) == ["gh_stab"]
    with pytest.raises(ValueError, match="unknown channels \\['forces'\\]"):
        res.to_dataframe(["forces"])


def test_to_dataframe_without_pandas(arm, monkeypatch):
    import sys
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError, match="pip install pandas"):
        arm.simulate(0.0, 0.01).to_dataframe()


def test_plot(arm):
    pytest.importorskip("matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    res = arm.simulate({"bicb": 0.3}, 0.02)
    fig = res.plot(("q", "gh_stab", "activation"), names=["ELx", "bicb1"])
    axes = fig.get_axes()
    assert [a.get_ylabel() for a in axes] == ["q (deg)", "GHstab", "activation"]
    np.testing.assert_allclose(axes[0].lines[0].get_ydata(), np.degrees(res.q[:, 3]))
    assert len(axes[2].lines) == 1
    with pytest.raises(ValueError, match="unknown channels"):
        res.plot(["nope"])


@pytest.mark.parametrize("make, message", [
    (lambda p, r: p.write_bytes(b"PK\x03\x04 truncated zip"), "not an armrt result"),
    (lambda p, r: np.save(p, np.zeros(3)), "not an armrt result"),
    (lambda p, r: np.savez(p, a=np.zeros(3)), "missing arrays"),
    (lambda p, r: np.savez(p, **{**{k: getattr(r, k) for k in armrt.Result.ARRAYS}, "dof_names": r.dof_names,
                                 "element_names": r.element_names, "model": "/etc/passwd"}), "'/etc/passwd' is not a known model"),
    (lambda p, r: np.savez(p, **{**{k: getattr(r, k) for k in armrt.Result.ARRAYS}, "q": np.array([None, 1], dtype=object),
                                 "dof_names": r.dof_names, "element_names": r.element_names, "model": "das2"}), "corrupt"),
    (lambda p, r: np.savez(p, **{**{k: getattr(r, k) for k in armrt.Result.ARRAYS}, "q": r.q[:-1],
                                 "dof_names": r.dof_names, "element_names": r.element_names, "model": "das2"}),
     r"arrays \['q'\] do not have one row per time"),
])
def test_result_load_refuses_in_one_line(arm, tmp_path, make, message):
    """Issue 11 item 6: corrupt, non-result or crafted files give one ValueError line naming the file."""
    res = arm.simulate(0.0, 0.005)
    path = tmp_path / "r.npz"
    make(path, res)
    if not path.exists():                    # np.save appends .npy
        path = tmp_path / "r.npz.npy"
    with pytest.raises(ValueError, match=message) as err:
        armrt.Result.load(path)
    assert "\n" not in str(err.value) and str(path) in str(err.value)
    with pytest.raises(FileNotFoundError, match="no such file"):
        armrt.Result.load(tmp_path / "absent.npz")
