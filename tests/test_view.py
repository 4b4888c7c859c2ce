"""Live view (issue 7, parts 1 and 4): geometry, data sources, the served page in headless Chromium."""
import os
import socket
import time
import urllib.request
from pathlib import Path

import numpy as np
import pytest

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
from armrt.geometry import POINTS, ArmGeometry  # noqa: E402
from chromium_helpers import chromium_page, free_port, needs_chromium  # noqa: E402


@pytest.fixture(scope="module")
def geom():
    return ArmGeometry("das2")


# ---------------------------------------------------------------- geometry (no browser)
def test_points_follow_the_engine(geom, arm):
    rng = np.random.default_rng(1)
    lo, hi = arm.dof_ranges.T
    for _ in range(5):
        q = rng.uniform(lo, hi)
        pts = geom.points(q)
        R, p = arm._sim.body_poses(q)
        np.testing.assert_allclose(pts[POINTS.index("elbow")], geom.to_thorax(p[1]), atol=1e-12)
        np.testing.assert_allclose(pts[POINTS.index("wrist")], geom.to_thorax(p[3]), atol=1e-12)
        arm.reset(q=q)
        np.testing.assert_allclose(pts[POINTS.index("hand")], arm.hand_position, atol=1e-9)


def test_segment_lengths_are_the_models(geom):
    L = geom.segment_lengths()
    bodies = {b["name"]: b for b in geom.model_json["bodies"]} if geom.model_json else None
    if bodies:
        assert L["humerus"] == pytest.approx(np.linalg.norm(np.subtract(bodies["ulna"]["joint"]["location_in_parent"],
                                                                        [0, 0, 0])), abs=1e-9)
        assert L["hand"] == pytest.approx(np.linalg.norm(geom.model_json["hand_point"]["point"]), abs=1e-9)
        axis = np.asarray(bodies["radius"]["joint"]["axes"][0])
        assert abs(np.dot(geom.ps_axis_in_ulna, axis)) == pytest.approx(1.0, abs=1e-9)
    # Rigid: lengths do not change with pose.
    for q in (geom.rest, geom.rest + 0.3):
        seg = ArmGeometry.segments(geom.points(q))
        np.testing.assert_allclose(np.linalg.norm(seg[:, 1] - seg[:, 0], axis=1),
                                   [L[s] for s in ("humerus", "ulna", "radius", "hand")], atol=1e-12)
    # The distal ulna stays next to the wrist through pronation-supination.
    for ps in (0.1, 1.5, 2.7):
        q = geom.rest.copy()
        q[4] = ps
        pts = geom.points(q)
        assert np.linalg.norm(pts[POINTS.index("ulna_distal")] - pts[POINTS.index("wrist")]) < 0.04


def test_static_girdle(geom):
    st = geom.static()
    assert {"clavicle_r", "scapula_r", "midline"} <= set(st)
    np.testing.assert_allclose(st["clavicle_r"][1], geom.info["base_origin_in_thorax"])
    gh = geom.to_thorax(geom.gh_centre_scapula)
    assert gh[0] > 0.1 and abs(gh[1]) < 0.1          # right shoulder, near IJ height
    seg, idx = geom.gh_lines_of_action(geom.rest)
    assert len(idx) == sum(e["crosses_gh"] for e in geom.info["elements"])
    np.testing.assert_allclose(np.linalg.norm(seg[:, 1] - seg[:, 0], axis=1), 0.06, atol=1e-9)


# ---------------------------------------------------------------- sources and server (no browser)
def test_result_source_replays(tmp_path, arm):
    from armrt.view import ResultSource
    arm.reset()
    res = arm.simulate({"elbow_flexors": 0.3}, duration=0.2, record_every=10)
    res.save(tmp_path / "r.npz")
    src = ResultSource(tmp_path / "r.npz", speed=1.0)
    src.start()
    f = src.latest()
    assert f.q.shape == (5,) and f.activation.shape == (arm.n_elements,)
    time.sleep(0.1)
    assert src.latest().time > f.time


def test_result_source_pause_and_seek(tmp_path, arm):
    from armrt.view import ResultSource
    arm.reset()
    res = arm.simulate({"elbow_flexors": 0.3}, duration=0.3, record_every=5)
    src = ResultSource(res)
    src.start()
    src.set_paused(True)
    src.seek(0.2)
    f0 = src.latest()
    time.sleep(0.1)
    f1 = src.latest()
    assert f0.time == f1.time == pytest.approx(0.2, abs=0.006)
    src.set_paused(False)
    time.sleep(0.05)
    assert src.latest().time != f1.time


def test_viewer_offline_controls(arm):
    pytest.importorskip("viser", reason="viser is not installed (pip install viser)")
    from armrt.view import ResultSource, SimulationSource, serve
    arm.reset()
    res = arm.simulate({"elbow_flexors": 0.3}, duration=0.3, record_every=5)
    v = serve(ResultSource(res), host="127.0.0.1", port=free_port(), block=False)
    try:
        v.controls["time"].value = 0.1          # scrubbing holds the frame there
        assert v.controls["pause"].value and v.source.paused
        assert v.source.latest().time == pytest.approx(0.1, abs=0.006)
    finally:
        v.stop()
    v = serve(SimulationSource(), host="127.0.0.1", port=free_port(), block=False)
    try:
        ef = arm.indices("elbow_flexors")
        v.controls["manual"].value = True
        v.controls["excitation:elbow_flexors"].value = 0.4
        assert (v.source.manual[ef] == 0.4).all() and v.source.manual.sum() == pytest.approx(0.4 * len(ef))
        deadline = time.monotonic() + 5
        while not np.allclose(v.source.arm.excitation[ef], 0.4) and time.monotonic() < deadline:
            time.sleep(0.02)
        np.testing.assert_allclose(v.source.arm.excitation[ef], 0.4)
        v.controls["pause"].value = True
        time.sleep(0.1)
        t0 = v.source.latest().time
        time.sleep(0.2)
        assert v.source.latest().time == t0
        v.controls["manual"].value = False
        assert v.source.manual is None
    finally:
        v.stop()


def test_viewer_says_why_it_cannot_draw_a_frame():
    """A pose the geometry refuses (degrees from a runner) is reported on the page; the loop goes on."""
    pytest.importorskip("viser", reason="viser is not installed (pip install viser)")
    from armrt.view import Frame, serve

    class Degrees:
        model, element_names = "das2", []

        def __init__(self):
            self.frame = Frame(time=0.5, q=np.array([25, 28, 16, 40, 80.0]), activation=None)

        def start(self):
            pass

        def latest(self):
            return self.frame

        def close(self):
            pass

    v = serve(Degrees(), host="127.0.0.1", port=free_port(), block=False)
    try:
        deadline = time.monotonic() + 5
        while v.last_frame is None and time.monotonic() < deadline:
            time.sleep(0.02)
        assert "cannot draw t = 0.50 s" in v._status.content and "look like degrees" in v._status.content
        v.source.frame = Frame(time=0.6, q=armrt.Model("das2").rest_posture.copy(), activation=None)
        while v.frames_drawn == 0 and time.monotonic() < deadline:
            time.sleep(0.02)
        assert v.frames_drawn == 1 and v._thread.is_alive()
    finally:
        v.stop()


def test_udp_source_decodes_state_packets(geom):
    realtime = pytest.importorskip("armrt.realtime", reason="armrt.realtime (the armrt-rt codec) is not built")
    from armrt.view import UdpSource
    src = UdpSource("127.0.0.1", 0)
    src.start()
    try:
        q = geom.rest + 0.1
        exc = np.linspace(0, 1, len(src.element_names))
        # ..., gh_stab, gh_theta, gh_phi, gh_rim_margin, gh_rim_direction, last_seq, lag, overruns
        values = np.concatenate([[1.25], q, np.zeros(5), np.zeros(3), [1.7, 0.5, -0.6, -0.1, -0.87, -1, 0.004, 2], exc])
        assert len(values) == realtime.STATE_FIXED_VALUES + len(exc)
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as tx:
            tx.sendto(b"not a packet", ("127.0.0.1", src.port))
            tx.sendto(realtime.encode_packet(realtime.STATE, 7, values, flags=realtime.FLAG_EXCITATION |
                                             realtime.FLAG_OVERRUN), ("127.0.0.1", src.port))
            deadline = time.monotonic() + 5
            while src.latest() is None and time.monotonic() < deadline:
                time.sleep(0.02)
        f = src.latest()
        assert f is not None, "no state decoded"
        assert f.time == 1.25 and f.gh_stab == 1.7 and f.lag == 0.004 and f.overrun
        assert f.gh_rim_margin == -0.1 and f.gh_rim_direction == -0.87
        assert f.kind == "excitation received"
        np.testing.assert_allclose(f.activation, exc)
        np.testing.assert_allclose(f.q, q)
        assert src.bad_packets == 1
    finally:
        src.close()


def test_udp_source_binds_loopback_by_default():
    pytest.importorskip("armrt.realtime", reason="armrt.realtime is not built")
    from armrt.view import UdpSource
    src = UdpSource(port=0)
    try:
        assert src._sock.getsockname()[0] == "127.0.0.1"
    finally:
        src.close()
    src = UdpSource("", 0)          # ":PORT" on the command line
    try:
        assert src._sock.getsockname()[0] == "127.0.0.1"
    finally:
        src.close()


def test_stab_plot_has_the_reference_lines():
    from armrt.view import stab_plot_svg
    t = np.linspace(0, 20, 200)
    svg = stab_plot_svg(t, 0.7 + 0.2 * np.sin(t))
    assert svg.count("<line") == 2 and ">1</text>" in svg and ">0.5</text>" in svg
    pts = svg.split('points="')[1].split('"')[0].split()
    assert len(pts) == 200
    xs = np.array([float(p.split(",")[0]) for p in pts])
    assert (xs[t < 10] == xs.min()).all()   # older than the window: pinned at the left edge


def test_udp_source_with_the_runner():
    realtime = pytest.importorskip("armrt.realtime", reason="armrt.realtime is not built")
    try:
        from armrt import _rt  # noqa: F401
    except ImportError:
        pytest.skip("the real-time loop bindings (armrt._rt) are not built")
    from armrt.view import UdpSource
    src = UdpSource("127.0.0.1", 0)
    src.start()
    try:
        with realtime.RealtimeSession(state_to=f"127.0.0.1:{src.port}", state_rate_hz=100, duration=1.0,
                                      send_excitation=True):
            deadline = time.monotonic() + 5
            while src.packets < 20 and time.monotonic() < deadline:
                time.sleep(0.05)
        assert src.packets >= 20 and src.latest().q.shape == (5,)
        assert src.latest().activation.shape == (len(src.element_names),) and src.latest().lag is not None
    finally:
        src.close()


@pytest.fixture
def viewer():
    pytest.importorskip("viser", reason="viser is not installed (pip install viser)")
    from armrt.view import SimulationSource, serve
    v = serve(SimulationSource(), host="127.0.0.1", port=free_port(), fps=30, block=False)
    yield v
    v.stop()


def test_server_draws_30_fps(viewer):
    with urllib.request.urlopen(viewer.url, timeout=10) as r:
        assert b"<html" in r.read(2000).lower()
    time.sleep(0.5)
    n0, t0 = viewer.frames_drawn, time.perf_counter()
    time.sleep(2.0)
    rate = (viewer.frames_drawn - n0) / (time.perf_counter() - t0)
    assert rate >= 27, f"viewer drew {rate:.1f} frames/s"
    assert viewer.source.restarts == 0


# ---------------------------------------------------------------- the page in headless Chromium
def _arm_mask(img: np.ndarray) -> np.ndarray:
    """Saturated (coloured) pixels of the 3D view: the bones (orange, blue, magenta) and the humeral head;
    the girdle is grey, the background white. Crops away the GUI panel, the notification and the axes."""
    h, w, _ = img.shape
    region = img[int(0.22 * h):int(0.9 * h), int(0.08 * w):int(0.64 * w)].astype(int)
    sat = region.max(axis=2) - region.min(axis=2)
    return sat > 80


@needs_chromium
def test_live_page_in_headless_chromium(viewer, tmp_path):
    out_dir = Path(os.environ.get("ARMRT_SCREENSHOT_DIR", tmp_path))
    out_dir.mkdir(parents=True, exist_ok=True)
    with chromium_page(viewer.url, tmp_path) as page:
        deadline = time.monotonic() + 30
        while not page.eval("!!document.querySelector('canvas') && document.body.innerText.includes('GHstab')"):
            assert time.monotonic() < deadline, "the page never showed the scene and the GHstab panel"
            time.sleep(0.3)
        time.sleep(1.5)   # first frames rendered
        text0 = page.eval("document.body.innerText")
        img0, png0 = page.screenshot()
        time.sleep(0.8)
        text1 = page.eval("document.body.innerText")
        img1, png1 = page.screenshot()
        (out_dir / "view_0.png").write_bytes(png0)
        (out_dir / "view_1.png").write_bytes(png1)
    # The panel shows live values: the time advanced between the two screenshots, activations listed.
    t = [float(s.split("t =")[1].split("s")[0]) for s in (text0, text1)]
    assert t[1] > t[0], (t, "the page did not update")
    assert "GHstab" in text1 and "bicb" in text1
    assert "pause" in text1 and "excitation (manual)" in text1 and "elbow flexion" in text1
    # The arm is drawn: coloured bone pixels, including the hand's magenta.
    m0, m1 = _arm_mask(img0), _arm_mask(img1)
    assert m0.sum() > 500 and m1.sum() > 500, (m0.sum(), m1.sum())
    magenta = (img0[..., 0] > 150) & (img0[..., 2] > 150) & (img0[..., 1] < 90)
    assert magenta.sum() > 30
    # ... and it moves: its pixels differ between the frames.
    changed = (m0 ^ m1).sum()
    assert changed > 100, f"only {changed} arm pixels changed between frames"


def _panel_value(text: str, name: str) -> float:
    """The number after a muscle's name in the activation panel's text."""
    lines = [ln for ln in text.splitlines() if ln.strip()]
    k = next(i for i, ln in enumerate(lines) if ln.strip() == name or ln.strip().startswith(name + " "))
    for ln in lines[k:k + 3]:
        for tok in ln.split():
            try:
                return float(tok)
            except ValueError:
                pass
    raise AssertionError(f"no value for {name} in the panel: {lines[k:k + 3]}")


@needs_chromium
def test_realtime_page_in_headless_chromium(tmp_path):
    """A lab's view of the runner: excitations received, GHstab plot with the 1 and 0.5 lines, labelled
    joint angles in degrees, lag visible, the arm framed large, moving when an excitation is sent."""
    pytest.importorskip("viser", reason="viser is not installed (pip install viser)")
    realtime = pytest.importorskip("armrt.realtime", reason="armrt.realtime is not built")
    import threading
    from armrt.view import UdpSource, serve
    src = UdpSource(port=0)
    v = serve(src, host="127.0.0.1", port=free_port(), fps=30, block=False)
    out_dir = Path(os.environ.get("ARMRT_SCREENSHOT_DIR", tmp_path))
    out_dir.mkdir(parents=True, exist_ok=True)
    stop = threading.Event()
    level = {"elbow_flexors": 0.0}
    try:
        with realtime.RealtimeSession(listen="127.0.0.1:0", state_to=f"127.0.0.1:{src.port}", state_rate_hz=100,
                                      send_excitation=True, input_timeout=0.5, realtime=False) as s, \
                realtime.UdpClient(s.port, mapping="groups") as c:
            c.join()
            def control():
                while not stop.is_set():
                    c.send({"rotator_cuff": 0.03, **level})
                    c.latest_state(timeout=0.02)
                    time.sleep(0.01)
            th = threading.Thread(target=control, daemon=True)
            th.start()
            with chromium_page(v.url, tmp_path) as page:
                deadline = time.monotonic() + 30
                while not page.eval("!!document.querySelector('canvas') && "
                                    "document.body.innerText.includes('excitation received')"):
                    assert time.monotonic() < deadline, "the page never showed the received excitations"
                    time.sleep(0.3)
                time.sleep(1.5)
                text0 = page.eval("document.body.innerText")
                img0, png0 = page.screenshot()
                level["elbow_flexors"] = 0.3        # the controller flexes the elbow
                time.sleep(2.0)
                text1 = page.eval("document.body.innerText")
                img1, png1 = page.screenshot()
                plot = page.eval("(() => { const s = document.querySelector('svg[data-armrt=gh-stab-plot]');"
                                 " return s ? [s.querySelectorAll('line').length, "
                                 "s.querySelectorAll('polyline').length, s.textContent] : null })()")
            stop.set()
            th.join(timeout=2)
        (out_dir / "view_rt_0.png").write_bytes(png0)
        (out_dir / "view_rt_1.png").write_bytes(png1)
    finally:
        stop.set()
        v.stop()
    assert _panel_value(text0, "bicb") == 0.0
    assert _panel_value(text1, "bicb") > 0.2, text1       # the excitation sent is shown
    for label in ("plane of elevation", "elevation", "axial rotation", "elbow flexion", "pronation-supination",
                  "lag behind wall time"):
        assert label in text1, label
    assert "\u00b0" in text1                              # degrees
    assert plot is not None and plot[0] == 2 and plot[1] == 1 and "0.5" in plot[2], plot
    # The arm is framed at a useful size and it moved.
    m0, m1 = _arm_mask(img0), _arm_mask(img1)
    rows = np.where(m1.any(axis=1))[0]
    assert rows.size and (rows[-1] - rows[0]) > 0.3 * img1.shape[0], "the arm fills too little of the view"
    assert (m0 ^ m1).sum() > 300


def test_viewer_replays_a_mot_motion(tmp_path, arm):
    """Issue 11 item 3: an OpenSim motion (angles only: no activations, GHstab unknown) plays in the view."""
    pytest.importorskip("viser", reason="viser is not installed (pip install viser)")
    from armrt.geometry import find_model_file
    if find_model_file("das2") is None:
        pytest.skip("models/das2.json not found")
    from armrt.opensim_io import write_mot
    from armrt.view import ResultSource, load_replay, serve
    write_mot(arm.simulate({"elbow_flexors": 0.3}, 0.2, record_every=10), tmp_path / "m.mot")
    src = ResultSource(load_replay(tmp_path / "m.mot"))
    v = serve(src, host="127.0.0.1", port=free_port(), fps=30, block=False)
    try:
        deadline = time.monotonic() + 10
        while v.frames_drawn < 5 and time.monotonic() < deadline:
            time.sleep(0.05)
        assert v.frames_drawn >= 5
        f = src.latest()
        assert f.activation is None and np.isnan(f.gh_stab)
    finally:
        v.stop()


def test_state_listener_refuses_what_is_not_its_models_state_and_names_a_taken_port():
    # The one decoder behind UdpSource, display --udp and task --runner-state (armrt.realtime.StateListener).
    realtime = pytest.importorskip("armrt.realtime", reason="armrt.realtime (the armrt-rt codec) is not built")
    fixed = np.concatenate([[0.5], np.zeros(5), np.zeros(5), np.zeros(3), [0.2, 0, 0, 0.3, 0, 3, 0.0, 0]])
    assert len(fixed) == realtime.STATE_FIXED_VALUES
    good = realtime.encode_packet(realtime.STATE, 2, np.concatenate([fixed, np.zeros(102)]),
                                  flags=realtime.FLAG_EXCITATION, key=b"k" * 16)
    other_model = realtime.encode_packet(realtime.STATE, 3, np.concatenate([fixed, np.zeros(50)]),
                                         flags=realtime.FLAG_EXCITATION, key=b"k" * 16)
    unsigned = realtime.encode_packet(realtime.STATE, 4, np.concatenate([fixed, np.zeros(102)]),
                                      flags=realtime.FLAG_EXCITATION)
    listener = realtime.StateListener("127.0.0.1", 0, "das2", key=b"k" * 16)
    try:
        assert listener.decode(b"junk") is None and listener.bad_packets == 1 and listener.last_error
        assert listener.decode(other_model) is None and listener.bad_packets == 2
        assert listener.decode(unsigned) is None and listener.bad_packets == 3
        assert listener.packets == 0
        pkt = listener.decode(good)
        assert pkt.time == 0.5 and pkt.gh_stab == 0.2 and listener.packets == 1 and listener.bad_packets == 3
        with pytest.raises(OSError, match=rf"127\.0\.0\.1:{listener.port}"):
            realtime.StateListener("127.0.0.1", listener.port, "das2")
    finally:
        listener.close()
