"""armrt.endpoint_target_controller: the decoder's hand velocity -> joint targets by damped least squares on the
engine's hand Jacobian, sent to a --static-optimization runner (docs/tasks.md#end-to-end). The IK step is checked
analytically (J dq = v dt with no damping; the damped step against its SVD form; a finite difference of the hand
position); the controller against a running RealtimeSession (the hand moves along the commanded velocity, a silent
decoder holds the posture, every target is applied)."""
from __future__ import annotations

import time

import numpy as np
import pytest

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
from armrt.endpoint_target_controller import TargetController, dls_step  # noqa: E402

Q = np.radians([30, 60, 10, 60, 80])
KP, KD = 100.0, 20.0   # docs/realtime.md: critically damped at 10 rad/s (kd = 2 sqrt(kp))


def test_dls_step_solves_j_dq_equals_v_dt_without_damping_and_matches_the_svd_form():
    m = armrt.Model("das2")
    J, _ = m.hand_jacobian(Q)
    v = np.array([0.05, -0.02, 0.03])
    dq = dls_step(J, v, 0.005, 0.0)
    np.testing.assert_allclose(J @ dq, v * 0.005, atol=1e-12)
    np.testing.assert_allclose(dq, np.linalg.pinv(J) @ v * 0.005, atol=1e-12)   # the minimum-norm solution
    lam = 0.05
    U, s, Vt = np.linalg.svd(J, full_matrices=False)     # DLS = sum_i s_i / (s_i^2 + lam^2) v_i u_i^T
    np.testing.assert_allclose(dls_step(J, v, 0.005, lam), Vt.T @ (s / (s**2 + lam**2) * (U.T @ v)) * 0.005,
                               atol=1e-12)
    # a small step moves the hand by v dt to first order (finite difference of the engine's kinematics)
    dx = m.hand_position(Q + dls_step(J, v, 1e-3, 0.01)) - m.hand_position(Q)
    np.testing.assert_allclose(dx, v * 1e-3, rtol=0.02, atol=1e-8)
    with pytest.raises(ValueError, match="finite"):
        dls_step(J, [np.nan, 0, 0], 0.005, 0.01)
    with pytest.raises(ValueError, match="3, ndof"):
        dls_step(J.T, v, 0.005, 0.01)


class _FakeDecoder:
    """LslEndpointDecoder's surface: poll(), velocity, _last (perf_counter of the newest sample), hold_s."""

    def __init__(self, v):
        self.velocity = np.asarray(v, dtype=float)
        self.hold_s = 0.5
        self._last = time.perf_counter()
        self.silent = False

    def poll(self):
        if not self.silent:
            self._last = time.perf_counter()
        return []


def test_controller_rejects_bad_input():
    m = armrt.Model("das2")
    with pytest.raises(ValueError, match="q0"):
        TargetController(m, None, _FakeDecoder([0, 0, 0]), Q[:3])
    with pytest.raises(ValueError, match="rate_hz"):
        TargetController(m, None, _FakeDecoder([0, 0, 0]), Q, rate_hz=-1.0)
    with pytest.raises(ValueError, match="damping"):
        TargetController(m, None, _FakeDecoder([0, 0, 0]), Q, damping=-1.0)


def test_controller_drives_a_running_session_and_holds_when_the_decoder_is_silent():
    from armrt import realtime as rt
    m = armrt.Model("das2")
    v = np.array([0.0, 0.03, 0.0])   # 3 cm/s up, thorax frame
    with rt.RealtimeSession(listen="127.0.0.1:0", q0=Q, static_optimization=True, so_kp=KP, so_kd=KD,
                            state_rate_hz=200) as s, rt.UdpClient(s.port) as c:
        c.join(timeout=2.0)
        dec = _FakeDecoder(v)
        ctl = TargetController(m, c, dec, Q, rate_hz=200.0)
        x0 = m.hand_position(Q)
        ctl.run(1.0)
        x_d1 = m.hand_position(ctl.q_d)
        dec.silent = True
        dec._last -= 1.0       # silent for longer than hold_s: v = 0, the last posture is held
        q_hold = ctl.q_d.copy()
        ctl.run(0.5)
        np.testing.assert_allclose(ctl.q_d, q_hold, atol=1e-12)
        x1 = np.asarray(c.latest_state(timeout=1.0).hand_position)
        stats = s.stop()
    # the desired hand moved v * 1 s (DLS with small damping: within 5 %), the arm's hand followed within 1 cm
    np.testing.assert_allclose(x_d1 - m.hand_position(Q), v * 1.0, atol=0.05 * 0.03)
    assert np.linalg.norm(x1 - x_d1) < 0.01, (x1, x_d1)
    assert x1[1] - x0[1] > 0.02
    n = len(ctl.sent)
    assert stats["packets"]["targets_applied"] == n
    assert ctl.last_applied_seq == ctl.sent[-1][0]
    assert len(ctl.applied_latency_s) == n and min(ctl.applied_latency_s) > 0


def test_task_sample_to_cursor_target_reads_the_task_state_channels():
    from armrt.simulated_decoder_lsl import task_sample_to_cursor_target
    c, t = task_sample_to_cursor_target([0.5, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 2, 0, 0.1])
    assert np.allclose(c, [0.1, 0.2, 0.3]) and np.allclose(t, [0.4, 0.5, 0.6])
    c, t = task_sample_to_cursor_target([0.5, 0.1, 0.2, 0.3, np.nan, np.nan, np.nan, -1, 0, 0.1])
    assert t is None
    with pytest.raises(ValueError, match="channels"):
        task_sample_to_cursor_target([0.0] * 3)


def test_decoder_process_pushes_velocities_towards_the_target_over_lsl():
    """The decoder process closes the loop over LSL: task state in (cursor at 0, target at +10 cm x), the simulated
    decoder's velocity (gain 4/s x 0.1 m = 0.4 m/s along x, no noise, no lag) out, one command per task sample."""
    from lsl_helpers import pylsl_or_skip, unique_id
    pylsl_or_skip()
    from armrt import tasks
    from armrt.lsl_bridge import LslEndpointDecoder, TaskStateOutlet
    from armrt.simulated_decoder_lsl import DecoderProcess
    uid = unique_id("d")
    outlet = TaskStateOutlet(f"ts-{uid}", f"{uid}-ts", 100.0)
    dec = DecoderProcess(tasks.SimulatedDecoder(4.0, 0.0, 0.0, 0.01), f"ts-{uid}", f"dec-{uid}", f"{uid}-dec",
                         wait_s=10)
    rx = LslEndpointDecoder(f"dec-{uid}", source_id=f"{uid}-dec", wait_s=10)
    try:
        import time
        got = []
        deadline = time.monotonic() + 10
        while len(got) < 20 and time.monotonic() < deadline:
            outlet.push([0.0, 0.0, 0.0, 0.0, 0.1, 0.0, 0.0, 0, 0, np.nan], outlet.pylsl.local_clock())
            dec.step(0.05)
            got += rx.poll()
        assert len(got) >= 20 and dec.task_samples == len(dec.sent_stamps) >= 20
        v = np.array([c.hand_velocity for c in got])
        assert np.allclose(v, [0.4, 0.0, 0.0], atol=1e-9)
    finally:
        rx.close()


def test_controller_without_a_decoder_yet_holds_the_start_posture():
    """decoder None (the process waiting for the decoder's stream): v = 0, so the target stays the start posture,
    and it is sent every period (the runner's session does not time out and every target is applied)."""
    from armrt import realtime as rt
    m = armrt.Model("das2")
    with rt.RealtimeSession(listen="127.0.0.1:0", q0=Q, static_optimization=True, so_kp=KP, so_kd=KD,
                            state_rate_hz=200, input_timeout=0.2) as s, rt.UdpClient(s.port) as c:
        c.join(timeout=2.0)
        ctl = TargetController(m, c, None, Q, rate_hz=200.0)
        ctl.run(0.6)     # three times the runner's input timeout
        stats = s.stop()
    np.testing.assert_array_equal(ctl.q_d, Q)
    assert len(ctl.sent) > 50 and stats["packets"]["targets_applied"] == len(ctl.sent)
    assert stats["packets"]["timeouts"] == 0 and ctl.received_stamps == []
