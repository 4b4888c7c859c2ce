"""The participant display and operator page (issue 29 item 2): the task-plane projection, the server, and both
pages in real headless Chromium, where the target, the cursor and the arm are found by colour at the pixels the
task geometry predicts (computed here from the thorax-frame axes, not with the module's projection)."""
import json
import os
import threading
import time
from pathlib import Path
import urllib.error
import urllib.request

import numpy as np
import pytest

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
pytest.importorskip("websockets", reason="websockets is not installed (a viser dependency)")
from armrt import display  # noqa: E402
from chromium_helpers import chromium_page, free_port, needs_chromium  # noqa: E402


def test_plane_projection_is_the_frontal_plane():
    """Frontal plane (armrt.tasks): u = +z (right), v = +y (up); the anterior (x) offset does not show."""
    c = np.array([0.3, -0.2, 0.25])
    plane = display.TaskPlane(tuple(c), half_height_m=0.1)
    p = c + [0.07, 0.03, -0.02]          # 7 cm anterior, 3 cm up, 2 cm left
    np.testing.assert_allclose(plane.project(p), [-0.02, 0.03], atol=1e-15)
    # 1000 x 700 screen: 3500 px/m; right is +x pixels, up is -y pixels.
    np.testing.assert_allclose(plane.to_pixels([-0.02, 0.03], 1000, 700), [500 - 70, 350 - 105])
    tilted = display.TaskPlane(tuple(c), axis_u=(1, 0, 1), axis_v=(0, 1, 0))
    np.testing.assert_allclose(tilted.project(c + [1, 0, 1]), [np.sqrt(2), 0], atol=1e-12)
    with pytest.raises(ValueError, match="orthogonal"):
        display.TaskPlane(axis_u=(0, 1, 1))
    with pytest.raises(ValueError, match="half_height_m"):
        display.TaskPlane(half_height_m=0)
    with pytest.raises(ValueError, match="target_state"):
        display.display_state(plane, target=c, target_state="hit")


def test_fit_plane_holds_targets_and_shoulder():
    from armrt.tasks import centre_out_targets
    tg = centre_out_targets((0, 0, 0), 0.1, 0.02, 8)
    plane = display.fit_plane(tg, margin=1.25)
    assert plane.half_height_m == pytest.approx(1.25 * 0.12)
    plane = display.fit_plane(tg, points=[(0, 0.3, 0.0)], margin=1.1)
    assert plane.half_height_m == pytest.approx(0.33)


def test_server_serves_both_pages():
    with display.DisplayServer(port=0) as d:
        for url, marker in ((d.url, b"const PAGE = 'participant'"), (d.operator_url, b"const PAGE = 'operator'")):
            with urllib.request.urlopen(url, timeout=10) as r:
                assert r.headers["Content-Type"].startswith("text/html") and marker in r.read()
        with pytest.raises(urllib.error.HTTPError, match="404"):
            urllib.request.urlopen(d.url + "nothing", timeout=10)


def test_a_port_probe_prints_nothing_and_pages_are_announced(capsys):
    """A TCP connection closed without a request (a port scan, a browser's pre-connect) used to print websockets'
    25-line traceback into the session's terminal; a page coming and going is one line each (announce=True)."""
    import socket

    from websockets.sync.client import connect
    with display.DisplayServer(port=0, announce=True) as d:
        socket.create_connection(("127.0.0.1", d.port), timeout=5).close()
        with connect(f"ws://127.0.0.1:{d.port}/ws?page=participant"):
            assert d.wait_for_page("participant", 10)
        deadline = time.monotonic() + 10
        while d.connected["participant"] and time.monotonic() < deadline:
            time.sleep(0.02)
        time.sleep(0.2)   # the probe's handshake failure is logged on the server's thread
        cap = capsys.readouterr()
    assert "Traceback" not in cap.err and "handshake" not in cap.err, cap.err
    assert "a participant page connected" in cap.out
    assert "a participant page disconnected (0 still open): the participant sees nothing" in cap.out


def test_stop_closes_open_pages_so_the_process_can_end():
    """websockets runs each connection on a non-daemon thread: an open kiosk page must not keep the session alive."""
    import threading
    from websockets.exceptions import ConnectionClosed
    from websockets.sync.client import connect
    before = {t for t in threading.enumerate() if not t.daemon}
    d = display.DisplayServer(port=0).start()
    with connect(f"ws://127.0.0.1:{d.port}/ws?page=participant") as page:
        assert d.wait_for_page("participant", 10) and d.connected["participant"] == 1
        seq = d.publish(display.display_state(d.plane, cursor=(0.01, 0.0, 0.02)))
        msg = json.loads(page.recv(timeout=10))
        assert msg["seq"] == seq and msg["cursor"] == [0.02, 0.0]
        d.stop()
        with pytest.raises(ConnectionClosed):
            page.recv(timeout=10)
    deadline = time.monotonic() + 10
    while d.connected["participant"] and time.monotonic() < deadline:
        time.sleep(0.02)
    assert d.connected["participant"] == 0
    left = {t for t in threading.enumerate() if not t.daemon} - before
    assert not [t for t in left if t.is_alive()], left


@pytest.fixture(scope="module")
def scene():
    """das2's arm at the CLI's start posture, the hand as cursor, a target 8 cm right and 3 cm up of it."""
    from armrt.geometry import POINTS, ArmGeometry
    geom = ArmGeometry("das2")
    q = np.radians([30, 60, 10, 60, 80])
    pts = geom.points(q)
    hand, elbow = pts[POINTS.index("hand")], pts[POINTS.index("elbow")]
    target = hand + np.array([0.0, 0.03, 0.08])
    centre = hand + np.array([0.0, 0.05, 0.0])
    plane = display.TaskPlane(tuple(centre), half_height_m=0.25)
    return dict(plane=plane, centre=centre, hand=hand, elbow=elbow, target=target, radius=0.02,
                arm=display.arm_points(geom, q))


def _predicted_px(p, centre, half_height, shape):
    """Thorax-frame point -> pixel of a screenshot (h, w): frontal plane, z to the right, y up."""
    h, w = shape[:2]
    s = min(w, h) / (2 * half_height)
    d = np.asarray(p) - centre
    return np.array([w / 2 + s * d[2], h / 2 - s * d[1]])


def _colour_centroid(img, rgb, tol=30):
    m = (np.abs(img.astype(int) - np.array(rgb)).max(axis=2) <= tol)
    ys, xs = np.nonzero(m)
    return (np.array([xs.mean(), ys.mean()]) if len(xs) else None), int(m.sum())


def _out_dir(tmp_path) -> Path:
    d = Path(os.environ.get("ARMRT_SCREENSHOT_DIR", tmp_path))
    d.mkdir(parents=True, exist_ok=True)
    return d


def _state(sc, target_state, **kw):
    return display.display_state(sc["plane"], cursor=sc["hand"], target=sc["target"], target_radius_m=sc["radius"],
                                 target_state=target_state, arm_points=sc["arm"], **kw)


@needs_chromium
def test_participant_page_draws_target_cursor_and_arm_where_the_geometry_says(scene, tmp_path):
    sc = scene
    with display.DisplayServer(sc["plane"], port=free_port()) as d, chromium_page(d.url, tmp_path) as page:
        page.wait_for("window.armrtFrames !== undefined", "the participant page did not load")
        seq = d.publish(_state(sc, "shown"))
        page.wait_for(f"window.armrtState && window.armrtState.seq === {seq}", "the state was never drawn")
        time.sleep(0.3)
        img, png = page.screenshot()
        (_out_dir(tmp_path) / "participant_shown.png").write_bytes(png)
        text = page.eval("document.body.innerText")
        seq = d.publish(_state(sc, "success"))
        page.wait_for(f"window.armrtState && window.armrtState.seq === {seq}", "the success state was never drawn")
        time.sleep(0.3)
        img2, png2 = page.screenshot()
        (_out_dir(tmp_path) / "participant_success.png").write_bytes(png2)
        deadline = time.monotonic() + 5
        while len(d.acks) < 2 and time.monotonic() < deadline:
            time.sleep(0.05)
        acks = list(d.acks)
    hh, c = sc["plane"].half_height_m, sc["centre"]
    s = min(img.shape[:2]) / (2 * hh)                    # px per m
    assert text.strip() == "", f"the participant page shows text: {text!r}"
    # The target (amber while shown) is a disc of the target's radius at the predicted pixel.
    at, n = _colour_centroid(img, display.TARGET_COLOURS["shown"])
    assert at is not None, "no target-coloured pixels"
    np.testing.assert_allclose(at, _predicted_px(sc["target"], c, hh, img.shape), atol=2.0)
    assert n == pytest.approx(np.pi * (sc["radius"] * s) ** 2, rel=0.1)
    # The cursor (white) is centred on the hand.
    at, n = _colour_centroid(img, display.CURSOR_COLOUR, tol=10)
    assert at is not None and n > 100, n
    np.testing.assert_allclose(at, _predicted_px(sc["hand"], c, hh, img.shape), atol=2.0)
    # The arm (grey) passes through the projected elbow.
    ex, ey = np.round(_predicted_px(sc["elbow"], c, hh, img.shape)).astype(int)
    patch = img[ey - 2:ey + 3, ex - 2:ex + 3].astype(int)
    assert (np.abs(patch - display.ARM_COLOUR).max(axis=2) <= 30).any(), patch[2, 2]
    # Success: the same disc turns green, no amber left.
    at, n = _colour_centroid(img2, display.TARGET_COLOURS["success"])
    assert at is not None
    np.testing.assert_allclose(at, _predicted_px(sc["target"], c, hh, img.shape), atol=2.0)
    assert _colour_centroid(img2, display.TARGET_COLOURS["shown"])[1] == 0
    # Each drawn state was acknowledged by the page (state-to-frame latency on the server's clock).
    assert {a.seq for a in acks} >= {seq - 1, seq} and all(a.latency_s > 0 and a.page == "participant" for a in acks)


@needs_chromium
def test_operator_page_shows_the_panel_and_metrics(scene, tmp_path):
    sc = scene
    rows = [{"trial": 0, "target": 0, "success": True, "time_to_target_s": 0.61, "acquisition_time_s": 0.7,
             "path_efficiency": 0.93, "n_entries": 1, "gh_unstable_events": 0, "hold_rms_m": 0.004}]
    with display.DisplayServer(sc["plane"], port=free_port()) as d, chromium_page(d.operator_url, tmp_path) as page:
        page.wait_for("window.armrtFrames !== undefined", "the operator page did not load")
        seq = d.publish(_state(sc, "entered", time_s=3.25, gh_stab=1.3, trial=1, n_trials=8, phase="target",
                               metrics=rows))
        page.wait_for(f"window.armrtState && window.armrtState.seq === {seq}", "the state was never drawn")
        text = page.eval("document.body.innerText")
        img, png = page.screenshot()
        (_out_dir(tmp_path) / "operator.png").write_bytes(png)
    assert "t = 3.25 s" in text and "GHstab = 1.30" in text and "outside the glenoid rim" in text
    assert "trial 2 of 8" in text and "target entered" in text
    assert "path_efficiency" in text and "0.930" in text and "yes" in text
    assert _colour_centroid(img, display.TARGET_COLOURS["entered"])[1] > 50   # the scene is drawn beside it


def test_frame_feed_draws_the_runner_state_stream(arm):
    """armrt-rt's UDP state packets (UdpSource) -> the display: the cursor is the engine's hand at the packet's q."""
    realtime = pytest.importorskip("armrt.realtime", reason="armrt.realtime (the armrt-rt codec) is not built")
    import socket
    from armrt.view import UdpSource

    class Recorder:
        plane = display.TaskPlane((0.2, -0.3, 0.3), half_height_m=0.4)
        states = []

        def publish(self, st):
            self.states.append(st)

    src = UdpSource("127.0.0.1", 0)
    rec = Recorder()
    feed = display.FrameFeed(src, rec, fps=100).start()
    try:
        q = arm.dof_ranges.mean(axis=1)
        values = np.concatenate([[1.25], q, np.zeros(5), np.zeros(3), [0.8, 0.5, -0.6, -0.1, -0.87, -1, 0.004, 0]])
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as tx:
            tx.sendto(realtime.encode_packet(realtime.STATE, 7, values), ("127.0.0.1", src.port))
            deadline = time.monotonic() + 5
            while not rec.states and time.monotonic() < deadline:
                time.sleep(0.02)
    finally:
        feed.stop()
    assert rec.states, "no state drawn"
    st = rec.states[-1]
    arm.reset(q=q)
    np.testing.assert_allclose(st["cursor"], rec.plane.project(arm.hand_position), atol=1e-9)
    np.testing.assert_allclose(st["arm"][-1], st["cursor"])
    assert st["time_s"] == 1.25 and st["gh_stab"] == 0.8 and "target" not in st


def test_cli_display_serves_the_pages(capsys):
    pytest.importorskip("armrt.realtime", reason="armrt.realtime is not built")
    from armrt.cli import main
    assert main(["display", "--udp", "127.0.0.1:0", "--port", "0", "--duration", "0.3"]) == 0
    out = capsys.readouterr().out
    assert "chromium --kiosk http://127.0.0.1:" in out and "/operator" in out and "drew 0 states" in out


def test_urls_of_wildcard_and_ipv6_hosts():
    import socket
    d = display.DisplayServer(host="0.0.0.0", port=8123)
    assert d.url == f"http://{socket.gethostname()}:8123/"
    assert display.DisplayServer(host="::1", port=8123).operator_url == "http://[::1]:8123/operator"


def _ipv6_loopback():
    import socket
    try:
        with socket.socket(socket.AF_INET6) as s:
            s.bind(("::1", 0))
        return True
    except OSError:
        return False


def _page_status(url_host, port):
    with urllib.request.urlopen(f"http://{url_host}:{port}/", timeout=10) as r:
        return r.status, r.headers["Content-Type"]


def test_wildcard_ipv4_host_binds_and_serves():
    with display.DisplayServer(host="0.0.0.0", port=0) as d:
        assert d._server.socket.getsockname()[0] == "0.0.0.0"
        assert _page_status("127.0.0.1", d.port) == (200, "text/html; charset=utf-8")


@pytest.mark.skipif(not _ipv6_loopback(), reason="this machine cannot bind ::1 (no IPv6 loopback)")
def test_ipv6_hosts_bind_and_serve():
    """websockets' serve took IPv4 as the family of any host: '::1' and '::' failed to bind ("Address family for
    hostname not supported"). '::1' serves on IPv6 loopback; '::' on IPv6, and on IPv4 too where dual stack is."""
    import socket
    with display.DisplayServer(host="::1", port=0) as d:
        assert d.url == f"http://[::1]:{d.port}/"
        assert _page_status("[::1]", d.port) == (200, "text/html; charset=utf-8")
    with display.DisplayServer(host="::", port=0) as d:
        assert d.url == f"http://{socket.gethostname()}:{d.port}/"
        assert _page_status("[::1]", d.port)[0] == 200
        if socket.has_dualstack_ipv6():
            assert _page_status("127.0.0.1", d.port)[0] == 200


@pytest.mark.skipif(not _ipv6_loopback(), reason="this machine cannot bind ::1 (no IPv6 loopback)")
def test_cli_task_display_on_an_ipv6_host_prints_a_url_a_browser_opens(capsys):
    from armrt.cli import main
    assert main(["task", "posture", "--trials", "1", "--dwell", "0.05", "--display", "--display-host", "::1",
                 "--display-port", "0", "--display-wait", "0", "--hold", "0"]) == 0
    out = capsys.readouterr().out
    assert "chromium --kiosk http://[::1]:" in out and "operator page: http://[::1]:" in out


def test_ack_summary_percentiles_of_hand_made_acks():
    """Latencies 1..100 ms on the participant page (linear-interpolation percentiles: p50 50.5, p90 90.1, p99 99.01,
    max 100), draw -> next frame 5 ms (to draw: 45.5 at p50), one frame per 40 ms on the page's clock (25 frames/s);
    the operator page's acks are not counted; no acks: counts only."""
    from armrt.display import Ack, ack_summary
    acks = [Ack(k + 1, (k + 1) / 1e3, 0.005, "participant", k, 40.0 * k) for k in range(100)]
    acks += [Ack(k + 1, 9.0, 0.005, "operator", k, 40.0 * k) for k in range(10)]
    s = ack_summary(acks, published=150)
    assert s["published"] == 150 and s["drawn"] == 100
    assert s["latency_ms"] == pytest.approx({"p50": 50.5, "p90": 90.1, "p99": 99.01, "max": 100.0})
    assert s["to_draw_ms"]["p50"] == pytest.approx(45.5)
    assert s["page_frames_per_s"] == pytest.approx(25.0)
    empty = ack_summary([], published=7)
    assert empty["drawn"] == 0 and empty["latency_ms"]["p50"] is None and empty["page_frames_per_s"] is None


def test_task_cli_records_the_pages_acks(tmp_path, capsys):
    """armrt task --display --out: the participant page's acknowledgements become the state -> display latency in
    the JSON and the summary. A Python WebSocket client stands in for the page (acks every state it receives, as the
    page does after drawing it); the latencies must be positive and below the whole run's wall time."""
    import json
    websocket = pytest.importorskip("websocket", reason="websocket-client is not installed")
    from armrt.cli import main
    port, out = free_port(), tmp_path / "m.json"
    rc = {}
    args = ["task", "centre-out", "--targets", "2", "--display", "--display-port", str(port), "--display-wait", "30",
            "--hold", "0", "--out", str(out)]
    th = threading.Thread(target=lambda: rc.setdefault("rc", main(args)), daemon=True)
    t0 = time.perf_counter()
    th.start()
    deadline = time.monotonic() + 30
    while True:
        try:
            ws = websocket.create_connection(f"ws://127.0.0.1:{port}/ws?page=participant", timeout=5)
            break
        except OSError:
            assert time.monotonic() < deadline, "the display server did not start"
            time.sleep(0.1)
    n = 0
    try:
        while th.is_alive():
            try:
                msg = json.loads(ws.recv())
            except Exception:   # the server closed the page at the end
                break
            n += 1
            ws.send(json.dumps({"seq": msg["seq"], "draw_ms": 10.0 * n, "next_frame_ms": 10.0 * n + 4.0, "ticks": n}))
    finally:
        ws.close()
    th.join(timeout=30)
    wall_ms = (time.perf_counter() - t0) * 1e3
    assert rc.get("rc") == 0
    d = json.loads(out.read_text())["display"]
    assert d["page"] == "participant" and 0 < d["drawn"] <= n and d["drawn"] <= d["published"]
    L = d["latency_ms"]
    assert 0 < L["p50"] <= L["p90"] <= L["p99"] <= L["max"] < wall_ms
    assert d["to_draw_ms"]["p50"] == pytest.approx(L["p50"] - 4.0, abs=1.0)   # the stand-in's 4 ms draw -> frame
    assert d["page_frames_per_s"] == pytest.approx(100.0)                      # 10 ms per tick on its clock
    assert f"display: {d['published']} states published, {d['drawn']} drawn" in capsys.readouterr().out


@pytest.mark.slow
@needs_chromium
def test_task_cli_records_a_real_pages_acks(tmp_path, capsys):
    """The same with the participant page in headless Chromium: every state it drew is acknowledged from its
    animation frames, and the task's JSON and summary give the latency percentiles of a real page."""
    from armrt.cli import main
    port, out = free_port(), tmp_path / "m.json"
    rc = {}
    args = ["task", "centre-out", "--targets", "2", "--display", "--display-port", str(port), "--display-wait", "60",
            "--hold", "0", "--out", str(out)]
    th = threading.Thread(target=lambda: rc.setdefault("rc", main(args)), daemon=True)
    th.start()
    deadline = time.monotonic() + 30
    while True:   # the server is up when its page answers
        try:
            urllib.request.urlopen(f"http://127.0.0.1:{port}/", timeout=2).close()
            break
        except OSError:
            assert time.monotonic() < deadline, "the display server did not start"
            time.sleep(0.1)
    with chromium_page(f"http://127.0.0.1:{port}/", tmp_path) as page:
        page.wait_for("window.armrtTicks !== undefined", "the participant page did not load")
        th.join(timeout=120)
    assert not th.is_alive() and rc.get("rc") == 0
    d = json.loads(out.read_text())["display"]
    assert d["drawn"] > 10 and d["published"] >= d["drawn"]
    L = d["latency_ms"]
    assert 0 < L["p50"] <= L["p90"] <= L["p99"] <= L["max"]
    assert d["page_frames_per_s"] > 1
    assert "state -> frame latency p50" in capsys.readouterr().out
