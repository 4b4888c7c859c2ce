"""The LSL bridge's endpoint-command input: a decoder's stream matched by channel label, each sample handed to a
consumer (a fake endpoint controller here) with its timestamp, the consumer's excitation forwarded."""
import time

import numpy as np
import pytest
from lsl_helpers import pylsl_or_skip, unique_id




def _step_until(bridge, cond, seconds=10.0):
    t_end = time.monotonic() + seconds
    while time.monotonic() < t_end and not cond():
        bridge.step()
    return cond()


def test_endpoint_layout_by_label():
    from armrt.lsl_bridge import endpoint_layout
    assert endpoint_layout(["hand_position_z", "hand_velocity_x", "hand_velocity_y", "hand_velocity_z",
                            "hand_position_x", "hand_position_y"]) == (True, True)
    assert endpoint_layout(["hand_velocity_z", "hand_velocity_y", "hand_velocity_x"]) == (True, False)
    with pytest.raises(ValueError, match=r"\['hand_velocity_z'\] missing"):
        endpoint_layout(["hand_velocity_x", "hand_velocity_y"])
    with pytest.raises(ValueError, match="unknown channel labels.*hand_speed"):
        endpoint_layout(["hand_speed"])
    with pytest.raises(ValueError, match="duplicate"):
        endpoint_layout(["hand_position_x", "hand_position_x", "hand_position_y", "hand_position_z"])


def test_endpoint_command_stream_reaches_the_consumer_by_label(monkeypatch):
    pylsl = pylsl_or_skip()
    from armrt.lsl_bridge import LslBridge, endpoint_stream_info
    uid = unique_id("e")
    # A reordered stream: position first, velocity's channels shuffled.
    labels = ["hand_position_x", "hand_position_y", "hand_position_z", "hand_velocity_z", "hand_velocity_x",
              "hand_velocity_y"]
    decoder = pylsl.StreamOutlet(endpoint_stream_info(pylsl, f"dec-{uid}", f"{uid}-decoder", 50, labels))
    got = []
    excitation = None  # what the fake controller asks for at its 4th command: set below, one value per group

    def consumer(cmd):
        got.append(cmd)
        return excitation if len(got) == 4 else None

    sent = []
    bridge = LslBridge(runner_port=9, source_id=uid, excitation_source_id=f"{uid}-decoder",
                       endpoint_consumer=consumer)
    n_names = len(bridge.client.mapping.names)
    excitation = np.full(n_names, 0.25)
    monkeypatch.setattr(bridge.client, "join", lambda timeout=1.0: 1)
    monkeypatch.setattr(bridge.client, "send", lambda v, seq=None: sent.append(np.array(v)) or len(sent))
    try:
        assert _step_until(bridge, lambda: bridge.inlet is not None), "decoder stream not matched"
        assert bridge.endpoint_has == (True, True)
        t0 = pylsl.local_clock()
        pushed = []
        for k in range(4):
            pos, vel = np.array([0.1, 0.2, 0.3]) + 0.01 * k, np.array([-0.05, 0.0, 0.05]) * k
            decoder.push_sample([pos[0], pos[1], pos[2], vel[2], vel[0], vel[1]], t0 + 0.02 * k)
            pushed.append((t0 + 0.02 * k, vel, pos))
        decoder.push_sample([np.nan, 0, 0, 0, 0, 0], t0 + 0.1)  # refused, never reaches the consumer
        assert _step_until(bridge, lambda: len(got) >= 4 and bridge.refused >= 1), f"got {len(got)} commands"
    finally:
        bridge.close()
    assert len(got) == 4 and bridge.refused == 1
    for cmd, (t, vel, pos) in zip(got, pushed):
        assert cmd.timestamp == pytest.approx(t, abs=1e-6)  # same host: LSL's time correction is ~0
        np.testing.assert_allclose(cmd.hand_velocity, vel)
        np.testing.assert_allclose(cmd.hand_position, pos)
    assert len(sent) == 1 and bridge.forwarded == 1
    np.testing.assert_array_equal(sent[0], excitation)


def test_endpoint_consumer_refuses_a_stimulation_mapping_and_non_callables():
    pylsl_or_skip()
    from armrt.lsl_bridge import LslBridge
    with pytest.raises(ValueError, match="not 'stimulation'"):
        LslBridge(runner_port=9, mapping="stimulation", stimulation="per_muscle", endpoint_consumer=print)
    with pytest.raises(ValueError, match="must be callable"):
        LslBridge(runner_port=9, endpoint_consumer=3)


def test_endpoint_command_over_lsl_reaches_the_arm():
    """Decoder (LSL, endpoint labels) -> bridge -> fake endpoint controller -> UDP -> armrt-rt: the arm moves."""
    pylsl = pylsl_or_skip()
    try:
        from armrt import _rt  # noqa: F401
        from armrt import realtime as rt
    except ImportError as e:
        pytest.skip(f"armrt._rt is not built: {e}")
    from armrt.lsl_bridge import LslBridge, channel_labels, endpoint_stream_info
    uid = unique_id("e")
    names = []

    def controller(cmd):
        # A stand-in for the endpoint controller: "hand up" (velocity z > 0) -> elbow flexors at 0.15.
        u = np.zeros(len(names))
        if cmd.hand_velocity[2] > 0:
            u[names.index("elbow_flexors")] = 0.15
        return u

    bridge = LslBridge(runner_port=0, mapping="groups", source_id=uid, excitation_source_id=f"{uid}-decoder",
                       state_rate_hz=200, endpoint_consumer=controller)
    names += bridge.mapping.names
    labels = ["hand_velocity_z", "hand_velocity_y", "hand_velocity_x"]
    decoder = pylsl.StreamOutlet(endpoint_stream_info(pylsl, f"dec-{uid}", f"{uid}-decoder", 100, labels))
    try:
        with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200,
                                state_to=f"127.0.0.1:{bridge.state_port}") as s:
            bridge.runner_address = ("127.0.0.1", s.port)
            found = pylsl.resolve_byprop("source_id", f"{uid}-state", timeout=10)
            assert found, "state stream not found on loopback"
            inlet = pylsl.StreamInlet(found[0])
            labels_out = channel_labels(inlet.info(timeout=5))
            el = None
            t_end = time.monotonic() + 4
            while time.monotonic() < t_end:
                decoder.push_sample([0.1, 0.0, 0.0])  # hand_velocity_z = 0.1 m/s up
                bridge.step()
                samples, _ = inlet.pull_chunk(timeout=0.0)
                if samples:
                    el = samples[-1][labels_out.index("ELx")]
                time.sleep(0.005)
            st = s.stop()
    finally:
        bridge.close()
    assert bridge.forwarded > 10, "no excitation forwarded from the endpoint commands"
    assert st["packets"]["applied"] > 10 and st["packets"]["sessions"] == 1
    # Elbow flexors at 0.15 flex the elbow beyond 60 deg; unexcited it hangs near 13 deg (test_realtime.py).
    assert el is not None and np.degrees(el) > 60, el
