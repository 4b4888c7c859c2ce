"""The LSL bridge's outputs: the GH stability and marker streams, read with a pylsl inlet."""
import time

import numpy as np
import pytest


def _pylsl():
    try:
        import pylsl
        pylsl.library_version()
        return pylsl
    except Exception as e:  # ImportError, or RuntimeError when liblsl cannot load
        pytest.skip(f"pylsl/liblsl cannot load: {type(e).__name__}: {e}")


def _uid():
    return f"t{time.monotonic_ns() % 10**9}"


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
    pylsl = _pylsl()
    from armrt.lsl_bridge import MarkerOutlet
    uid = _uid()
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
    pylsl = _pylsl()
    from armrt.lsl_bridge import GH_ROWS, LslBridge, gh_channels
    labels, units, types = gh_channels("das2")
    assert labels == list(GH_ROWS) and units == ["1", "rad", "rad", "rad", "rad"]
    uid = _uid()
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
