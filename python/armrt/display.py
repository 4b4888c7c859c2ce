"""Participant display and operator page for the target tasks (issue 29 item 2): task state (cursor, target, arm
pose) -> JSON over a WebSocket -> a full-screen canvas in the browser. docs/tasks.md#participant-display.

    from armrt.display import DisplayServer, TaskPlane, display_state
    plane = TaskPlane(centre=(0.3, -0.2, 0.25))          # the frontal plane through the task centre
    with DisplayServer(plane, port=8090) as d:           # http://127.0.0.1:8090/ and .../operator
        d.publish(display_state(plane, cursor=hand, target=target_position, target_radius_m=0.015,
                                target_state="shown"))   # hand, target_position: (3,) m, thorax frame

    chromium --kiosk http://127.0.0.1:8090/             # the participant's screen

The participant page draws only what a BCI participant needs, on black for contrast: the targets, a large white
cursor and the arm (thorax-frame points projected orthogonally into the task plane, seen from behind the
participant: +axis_u to the right, +axis_v up), no text. The operator page (/operator) draws the same scene small
beside the engineering panel: GHstab, task state, per-trial metrics so far. Both are fed by whatever calls
publish(): the Python task loop (armrt task ... --display) or the armrt-rt state stream (UdpSource frames through
display_state).

The server is websockets' threaded server (a maintained RFC 6455 implementation that viser already depends on, so
nothing new is installed): one port serves both pages over plain HTTP and the state stream at /ws. Each state
carries a sequence number; after drawing it the page answers at its next animation frame with the number, so the
server measures state-to-frame latency on its own clock (DisplayServer.acks; bench/display_latency.py).
"""
from __future__ import annotations

import json
import logging
import math
import sys
import threading
import time
from dataclasses import dataclass
from http import HTTPStatus

import numpy as np

from . import checks

# Colours (RGB): saturated and distinct so a browser test finds each by colour; success green and timeout red as
# a participant reads them, the cursor white on black (highest contrast).
BACKGROUND = (0, 0, 0)
CURSOR_COLOUR = (255, 255, 255)
ARM_COLOUR = (150, 150, 150)
TARGET_COLOURS = {"shown": (255, 190, 0), "entered": (0, 150, 255), "success": (0, 220, 60), "timeout": (230, 30, 30)}
TARGET_STATES = tuple(TARGET_COLOURS)
ARM_POINTS = ("gh", "elbow", "wrist", "hand")   # the polyline drawn: upper arm, forearm, hand (armrt.geometry.POINTS)
CURSOR_RADIUS_M = 0.006   # drawn cursor radius (m in the task plane; at least CURSOR_MIN_PX pixels)
CURSOR_MIN_PX = 10
ARM_WIDTH_PX = 9


@dataclass(frozen=True)
class TaskPlane:
    """The plane the display shows: centre (3,) m in the thorax frame at the middle of the screen, axis_u to the
    right and axis_v up (unit, orthogonal; default the frontal plane of armrt.tasks: u = +z, right, v = +y, up),
    half_height_m: the distance from the centre to the screen's nearer edges (the scale is
    min(width, height) / (2 half_height_m) px/m). ValueError for non-orthogonal axes or a bad size."""
    centre: tuple = (0.0, 0.0, 0.0)
    axis_u: tuple = (0.0, 0.0, 1.0)
    axis_v: tuple = (0.0, 1.0, 0.0)
    half_height_m: float = 0.15

    def __post_init__(self):
        from .tasks import _plane_axes, _positive
        c, u, v = _plane_axes(self.centre, self.axis_u, self.axis_v)
        object.__setattr__(self, "centre", tuple(float(x) for x in c))
        object.__setattr__(self, "axis_u", tuple(float(x) for x in u))
        object.__setattr__(self, "axis_v", tuple(float(x) for x in v))
        object.__setattr__(self, "half_height_m", _positive(self.half_height_m, "half_height_m"))

    def project(self, points) -> np.ndarray:
        """(..., 3) thorax-frame points, m -> (..., 2) plane coordinates (u, v), m: orthogonal projection."""
        p = checks.real_array(points, "points")
        if p.shape[-1:] != (3,):
            raise ValueError(f"points must have shape (..., 3) (m, thorax frame), got {p.shape}")
        d = p - np.asarray(self.centre)
        return np.stack([d @ np.asarray(self.axis_u), d @ np.asarray(self.axis_v)], axis=-1)

    def to_pixels(self, uv, width: float, height: float) -> np.ndarray:
        """(..., 2) plane coordinates, m -> (..., 2) pixel (x right, y down) in a width x height screen; the
        page draws with the same mapping (PAGE_JS: px)."""
        uv = np.asarray(uv, dtype=float)
        s = min(width, height) / (2 * self.half_height_m)
        return np.stack([width / 2 + s * uv[..., 0], height / 2 - s * uv[..., 1]], axis=-1)

    def as_dict(self) -> dict:
        return {"half_height_m": self.half_height_m}


def fit_plane(targets, centre=None, points=(), margin: float = 1.25, axis_u=(0.0, 0.0, 1.0),
              axis_v=(0.0, 1.0, 0.0)) -> TaskPlane:
    """A TaskPlane centred on centre (default: the targets' mean) whose half-height holds every target (with its
    radius) and every extra point (e.g. the shoulder, so the arm is on screen) x margin."""
    pos = np.array([t.position for t in targets], dtype=float).reshape(-1, 3)
    c = pos.mean(axis=0) if centre is None else np.asarray(centre, dtype=float)
    plane = TaskPlane(tuple(c), axis_u, axis_v, 1.0)
    reach = [np.abs(plane.project(t.position)).max() + t.radius_m for t in targets]
    if len(points):
        reach.append(float(np.abs(plane.project(np.asarray(points, dtype=float))).max()))
    return TaskPlane(tuple(c), axis_u, axis_v, margin * max(max(reach), 0.01))


def display_state(plane: TaskPlane, cursor=None, target=None, target_radius_m: float = 0.0,
                  target_state: str | None = None, arm_points=None, time_s: float = math.nan,
                  gh_stab: float = math.nan, trial: int = -1, n_trials: int = 0, phase: str = "",
                  metrics=None) -> dict:
    """One state for the pages (the JSON publish() sends): cursor (3,) m, target (3,) m with target_radius_m (m)
    and target_state (one of TARGET_STATES; None: no target), arm_points (k, 3) m (the ARM_POINTS of
    ArmGeometry.points) all in the thorax frame, projected here into the plane; time_s (the task clock), gh_stab,
    trial/n_trials, phase and metrics (rows of TargetTask.trial_metrics so far) for the operator page.
    ValueError for an unknown target_state."""
    if target_state is not None and target_state not in TARGET_STATES:
        raise ValueError(f"target_state must be one of {TARGET_STATES} or None, got {target_state!r}")
    out = {"plane": plane.as_dict(), "time_s": _num(time_s), "gh_stab": _num(gh_stab), "trial": int(trial),
           "n_trials": int(n_trials), "phase": str(phase)}
    if cursor is not None:
        out["cursor"] = plane.project(cursor).tolist()
        out["cursor_radius_m"] = CURSOR_RADIUS_M
    if target is not None and target_state is not None:
        out["target"] = {"uv": plane.project(target).tolist(), "radius_m": float(target_radius_m),
                         "state": target_state, "rgb": list(TARGET_COLOURS[target_state])}
    if arm_points is not None:
        out["arm"] = plane.project(np.asarray(arm_points, dtype=float).reshape(-1, 3)).tolist()
    if metrics is not None:
        out["metrics"] = [{k: _jsonable(v) for k, v in row.items() if k in OPERATOR_COLUMNS} for row in metrics]
    return out


OPERATOR_COLUMNS = ("trial", "target", "success", "time_to_target_s", "acquisition_time_s", "path_efficiency",
                    "n_entries", "gh_unstable_events")


def _num(x):
    x = float(x)
    return x if math.isfinite(x) else None


def _jsonable(v):
    if isinstance(v, (bool, int, str)) or v is None:
        return v
    if isinstance(v, float):
        return _num(v)
    return str(v)


def arm_points(geometry, q) -> np.ndarray:
    """(4, 3) thorax-frame ARM_POINTS of an armrt.geometry.ArmGeometry at pose q (rad)."""
    from .geometry import POINTS
    pts = geometry.points(q)
    return pts[[POINTS.index(n) for n in ARM_POINTS]]


@dataclass(frozen=True)
class Ack:
    """A page's answer for one drawn state: seq (publish()'s number); latency_s = ack received - publish() on the
    server's clock (state to the animation frame after the one that drew it, plus one loopback hop back: an upper
    bound of state-to-frame latency); draw_to_frame_s: draw -> that next frame on the page's clock; page
    ("participant" or "operator"); ticks: the page's animation frames so far and page_time_ms its clock then (the
    page's frame rate from two acks)."""
    seq: int
    latency_s: float
    draw_to_frame_s: float
    page: str
    ticks: int
    page_time_ms: float


def ack_summary(acks, published: int, page: str = "participant") -> dict:
    """State -> display latency of a session from its acknowledgements (DisplayServer.acks; Ack above) of one page:
    published (states sent, DisplayServer.published), drawn (acks of that page), latency_ms p50 / p90 / p99 / max
    (ack received - published, server clock: an upper bound, it includes the ack's loopback hop back),
    to_draw_ms p50 / p99 (the same minus the page's draw -> next-frame interval: state published -> drawn) and
    page_frames_per_s (animation frames between the first and last ack, page clock). Empty acks: the counts, and
    None for every figure (nothing was drawn)."""
    mine = [a for a in acks if a.page == page]
    lat = np.array([a.latency_s for a in mine], dtype=float) * 1e3
    to_draw = lat - np.array([a.draw_to_frame_s for a in mine], dtype=float) * 1e3

    def pct(x, q):
        return float(np.percentile(x, q)) if len(x) else None
    span_s = (mine[-1].page_time_ms - mine[0].page_time_ms) / 1e3 if len(mine) > 1 else 0.0
    return {"page": page, "published": int(published), "drawn": len(mine),
            "latency_ms": {"p50": pct(lat, 50), "p90": pct(lat, 90), "p99": pct(lat, 99), "max": pct(lat, 100)},
            "to_draw_ms": {"p50": pct(to_draw, 50), "p99": pct(to_draw, 99)},
            "page_frames_per_s": (mine[-1].ticks - mine[0].ticks) / span_s if span_s > 0 else None,
            "note": "latency: state published -> the page's next animation frame after drawing it, acknowledged "
                    "back over the WebSocket (server clock; an upper bound: includes that loopback hop)"}


# s a page gets to answer the close handshake when the session ends (it is closed without the answer after that).
CLOSE_TIMEOUT_S = 0.5


class _OneLine(logging.Handler):
    """websockets' log records as one line on stderr, without their tracebacks; a connection that closed before
    sending a request (a port probe) is not worth a line."""

    def emit(self, record) -> None:
        msg = record.getMessage()
        exc = record.exc_info[1] if record.exc_info else None
        if exc is not None and "did not receive a valid HTTP request" in f"{exc} {exc.__cause__}":
            return
        if record.levelno >= logging.WARNING:
            extra = f": {exc}" if exc is not None else ""
            print(f"armrt display: {msg}{extra}", file=sys.stderr, flush=True)


def _one_line_logger() -> logging.Logger:
    log = logging.getLogger("armrt.display.server")
    if not log.handlers:
        log.addHandler(_OneLine())
        log.propagate = False
        log.setLevel(logging.INFO)
    return log


class DisplayServer:
    """Serves the participant page at http://host:port/, the operator page at /operator and the state stream at
    /ws (port 0: a free one, see .port). publish(state) hands the newest state (a display_state dict) to every
    page; a page that is slower than the states skips to the newest (nothing queues). Each page acknowledges the
    frame that drew a state: .acks holds an Ack per drawn state. Use as a context manager or start()/stop()."""

    def __init__(self, plane: TaskPlane | None = None, host: str = "127.0.0.1", port: int = 8090,
                 keep_acks: int = 100000, announce: bool = False):
        self.plane = plane if plane is not None else TaskPlane()
        self.announce = bool(announce)   # a line on stdout when a page connects or goes away
        self.host = host
        self._port = checks.count(port, "port")
        self._cond = threading.Condition()
        self._seq = 0
        self._message = None     # the newest state, JSON text
        self._stamps: dict[int, float] = {}   # seq -> publish time (perf_counter s), the newest keep_acks
        self.keep_acks = checks.count(keep_acks, "keep_acks", minimum=1)
        self.acks: list[tuple] = []
        self.connected = {"participant": 0, "operator": 0}   # pages open now
        self._connections = set()
        self._server = None
        self._thread = None
        self._closed = False

    @property
    def port(self) -> int:
        return self._server.socket.getsockname()[1] if self._server is not None else self._port

    @property
    def url(self) -> str:
        return f"http://{self._url_host()}:{self.port}/"

    @property
    def operator_url(self) -> str:
        return f"http://{self._url_host()}:{self.port}/operator"

    def _url_host(self) -> str:
        """The host as a browser on another machine types it: a wildcard bind is reached by this machine's name,
        an IPv6 address in brackets (RFC 3986)."""
        if self.host in ("0.0.0.0", "::", ""):
            import socket
            return socket.gethostname()
        return f"[{self.host}]" if ":" in self.host else self.host

    def start(self) -> "DisplayServer":
        from websockets.sync.server import serve
        # close_timeout: a page that stopped reading must not hold stop() up for websockets' default 10 s per page;
        # the logger turns the server's tracebacks (a port probe without a request, a page gone mid-handshake) into
        # one line each instead of 25 in the session's terminal.
        # websockets hands host and port to socket.create_server, whose family defaults to IPv4: an IPv6 host
        # ('::1', '::') failed with "Address family for hostname not supported". '::' is bound dual stack where
        # the system can, so IPv4 browsers reach it too (as '0.0.0.0' would).
        import socket
        family = {}
        if ":" in self.host:
            family["family"] = socket.AF_INET6
            if self.host == "::" and socket.has_dualstack_ipv6():
                family["dualstack_ipv6"] = True
        self._server = serve(self._handle, self.host, self._port, process_request=self._http,
                             compression=None, close_timeout=CLOSE_TIMEOUT_S, logger=_one_line_logger(), **family)
        self._thread = threading.Thread(target=self._server.serve_forever, name="armrt-display", daemon=True)
        self._thread.start()
        return self

    def stop(self) -> None:
        """Stops serving and closes the open pages' connections (their screens go black): websockets runs each
        connection on a non-daemon thread, which an open kiosk page would otherwise keep alive past the end."""
        with self._cond:
            self._closed = True
            self._cond.notify_all()
            conns = list(self._connections)
        if self._server is not None:
            self._server.shutdown()
            self._thread.join(timeout=2.0)
        for c in conns:
            c.close()

    def __enter__(self):
        return self.start()

    def __exit__(self, *exc):
        self.stop()

    def wait_for_page(self, page: str = "participant", timeout_s: float | None = None) -> bool:
        """Blocks until a `page` ("participant" or "operator") is connected or timeout_s passes (None: forever);
        returns whether one is."""
        with self._cond:
            return self._cond.wait_for(lambda: self.connected.get(page, 0) > 0 or self._closed, timeout=timeout_s) \
                and not self._closed

    @property
    def published(self) -> int:
        """States published so far (the newest sequence number)."""
        with self._cond:
            return self._seq

    def publish(self, state: dict) -> int:
        """Sends state (display_state) to the pages; returns its sequence number."""
        with self._cond:
            self._seq += 1
            seq = self._seq
            self._stamps[seq] = time.perf_counter()
            self._stamps.pop(seq - self.keep_acks, None)
            self._message = json.dumps({"seq": seq, **state})
            self._cond.notify_all()
        return seq

    # ------------------------------------------------------------ connection handling (server threads)
    def _http(self, connection, request):
        path = request.path.split("?")[0]
        if path == "/ws":
            return None   # the WebSocket handshake goes on
        page = {"/": PARTICIPANT_HTML, "/operator": OPERATOR_HTML}.get(path)
        if page is None:
            return connection.respond(HTTPStatus.NOT_FOUND, "not found: / (participant) or /operator\n")
        r = connection.respond(HTTPStatus.OK, page)
        del r.headers["Content-Type"]
        r.headers["Content-Type"] = "text/html; charset=utf-8"
        r.headers["Cache-Control"] = "no-store"
        return r

    def _handle(self, ws) -> None:
        stop = threading.Event()
        page = "operator" if "page=operator" in ws.request.path else "participant"

        def sender():
            sent = 0
            try:
                while not stop.is_set():
                    with self._cond:
                        self._cond.wait_for(lambda: self._seq != sent or self._closed or stop.is_set(), timeout=0.5)
                        if self._closed:
                            return
                        msg, seq = self._message, self._seq
                    if msg is not None and seq != sent:
                        ws.send(msg)
                        sent = seq
            except Exception:   # the page went away: the receive loop below ends too
                stop.set()

        th = threading.Thread(target=sender, daemon=True)
        with self._cond:
            if self._closed:
                return
            self.connected[page] = self.connected.get(page, 0) + 1
            self._connections.add(ws)
            self._cond.notify_all()
        if self.announce:
            print(f"armrt display: a {page} page connected", flush=True)
        th.start()
        try:
            for text in ws:
                a = json.loads(text)
                t_recv = time.perf_counter()
                t_pub = self._stamps.get(int(a["seq"]))
                if t_pub is not None:
                    self.acks.append(Ack(int(a["seq"]), t_recv - t_pub, float(a["next_frame_ms"] - a["draw_ms"]) / 1e3,
                                         page, int(a["ticks"]), float(a["next_frame_ms"])))
                    del self.acks[:-self.keep_acks]
        except Exception:
            pass
        finally:
            stop.set()
            th.join(timeout=1.0)
            with self._cond:
                self.connected[page] -= 1
                self._connections.discard(ws)
                left, closed = self.connected[page], self._closed
            if self.announce and not closed:
                print(f"armrt display: a {page} page disconnected ({left} still open)"
                      + (": the participant sees nothing until it reconnects" if page == "participant" and not left
                         else ""), flush=True)


class FrameFeed:
    """Feeds a DisplayServer from an armrt.view source (UdpSource: the armrt-rt UDP state stream; ResultSource,
    SimulationSource): a thread draws each new Frame's arm (ArmGeometry.points at frame.q) with the hand as the
    cursor, GHstab and time for the operator page, at most fps times a second. No target: the state stream does
    not carry the task's (a task loop publishes its own states, task_live.run_live)."""

    def __init__(self, source, server: DisplayServer, fps: float = 60.0):
        from .geometry import ArmGeometry
        self.source, self.server = source, server
        self.fps = checks.real_scalar(fps, "fps")
        if not (math.isfinite(self.fps) and self.fps > 0):
            raise ValueError(f"fps must be a finite number > 0, got {fps}")
        self.geometry = ArmGeometry(source.model)
        self.frames = 0
        self.error = ""          # why the last frame could not be drawn (e.g. a pose in degrees)
        self._stop = threading.Event()
        self._thread = None

    def state(self, f) -> dict:
        pts = arm_points(self.geometry, f.q)
        return display_state(self.server.plane, cursor=pts[-1], arm_points=pts, time_s=f.time, gh_stab=f.gh_stab,
                             phase="armrt-rt state stream")

    def _run(self) -> None:
        last = None
        while not self._stop.is_set():
            f = self.source.latest()
            if f is not None and f is not last:
                try:
                    self.server.publish(self.state(f))
                    self.frames += 1
                except ValueError as exc:   # a pose the geometry refuses: said, and the feed goes on
                    self.error = str(exc)
                last = f
            self._stop.wait(1.0 / self.fps)

    def start(self) -> "FrameFeed":
        self.source.start()
        self._thread = threading.Thread(target=self._run, name="armrt-display-feed", daemon=True)
        self._thread.start()
        return self

    def stop(self) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=2.0)
        self.source.close()


# ---------------------------------------------------------------- the pages
# px(uv): TaskPlane.to_pixels. The page answers each drawn state at its next animation frame (the frame with the
# draw has been produced by then): {seq, draw_ms, next_frame_ms} on the page's performance.now() clock.
PAGE_JS = r"""
const canvas = document.getElementById('scene');
const ctx = canvas.getContext('2d');
let state = null, dirty = false, pendingAck = null;
window.armrtFrames = 0;
function px(uv, W, H, hh) { const s = Math.min(W, H) / (2 * hh); return [W / 2 + s * uv[0], H / 2 - s * uv[1], s]; }
function draw(st) {
  const W = canvas.width, H = canvas.height, hh = st.plane.half_height_m;
  ctx.fillStyle = 'rgb(0,0,0)'; ctx.fillRect(0, 0, W, H);
  const s = Math.min(W, H) / (2 * hh);
  if (st.target) {
    const [x, y] = px(st.target.uv, W, H, hh);
    ctx.fillStyle = `rgb(${st.target.rgb.join(',')})`;
    ctx.beginPath(); ctx.arc(x, y, Math.max(st.target.radius_m * s, 4), 0, 2 * Math.PI); ctx.fill();
  }
  if (st.arm) {
    ctx.strokeStyle = 'rgb(150,150,150)'; ctx.lineWidth = ARM_WIDTH * devicePixelRatio;
    ctx.lineCap = 'round'; ctx.lineJoin = 'round'; ctx.beginPath();
    st.arm.forEach((p, k) => { const [x, y] = px(p, W, H, hh); if (k) ctx.lineTo(x, y); else ctx.moveTo(x, y); });
    ctx.stroke();
  }
  if (st.cursor) {
    const [x, y] = px(st.cursor, W, H, hh);
    ctx.fillStyle = 'rgb(255,255,255)';
    ctx.beginPath(); ctx.arc(x, y, Math.max(st.cursor_radius_m * s, CURSOR_MIN * devicePixelRatio), 0, 2 * Math.PI);
    ctx.fill();
  }
}
function resize() {
  canvas.width = Math.round(canvas.clientWidth * devicePixelRatio);
  canvas.height = Math.round(canvas.clientHeight * devicePixelRatio);
  dirty = state !== null;
}
window.addEventListener('resize', resize);
resize();
const ws = new WebSocket(`ws://${location.host}/ws?page=${PAGE}`);
ws.onmessage = (e) => { state = JSON.parse(e.data); dirty = true; };
ws.onclose = () => { state = null; ctx.fillStyle = 'rgb(0,0,0)'; ctx.fillRect(0, 0, canvas.width, canvas.height); };
window.armrtTicks = 0;
function frame() {
  const now = performance.now();
  window.armrtTicks += 1;
  if (pendingAck !== null && ws.readyState === 1) {
    ws.send(JSON.stringify({seq: pendingAck.seq, draw_ms: pendingAck.t, next_frame_ms: now,
                            ticks: window.armrtTicks}));
  }
  pendingAck = null;
  if (dirty && state) {
    draw(state); dirty = false; window.armrtFrames += 1; window.armrtState = state;
    if (typeof panel === 'function') panel(state);
    pendingAck = {seq: state.seq, t: performance.now()};
  }
  requestAnimationFrame(frame);
}
requestAnimationFrame(frame);
""".replace("ARM_WIDTH", str(ARM_WIDTH_PX)).replace("CURSOR_MIN", str(CURSOR_MIN_PX))

PARTICIPANT_HTML = """<!doctype html>
<html><head><meta charset="utf-8"><title>armrt</title>
<style>html,body{margin:0;height:100%;background:#000;overflow:hidden;cursor:none}
#scene{display:block;width:100vw;height:100vh}</style></head>
<body><canvas id="scene"></canvas><script>const PAGE = 'participant';
""" + PAGE_JS + "</script></body></html>\n"

OPERATOR_HTML = """<!doctype html>
<html><head><meta charset="utf-8"><title>armrt operator</title>
<style>html,body{margin:0;height:100%;font:13px sans-serif;background:#fff}
#wrap{display:flex;height:100vh}#scene{display:block;width:40vw;height:40vw;max-height:100vh;flex:none}
#panel{flex:1;padding:8px;overflow:auto;font-size:12px}td,th{padding:1px 4px;text-align:right;font-size:11px}
.bad{color:#c00;font-weight:bold}.ok{color:#080}</style></head>
<body><div id="wrap"><canvas id="scene"></canvas><div id="panel">
<div id="status">waiting for the session...</div><table id="metrics"></table></div></div>
<script>const PAGE = 'operator';
const COLUMNS = COLUMNS_JSON;
function fmt(v) { return v === null || v === undefined ? '-' : (typeof v === 'number' && !Number.isInteger(v))
  ? v.toFixed(3) : (v === true ? 'yes' : (v === false ? 'no' : String(v))); }
function panel(st) {
  const gh = st.gh_stab === null ? 'n/a' : st.gh_stab.toFixed(2);
  const cls = st.gh_stab !== null && st.gh_stab > 1 ? 'bad' : 'ok';
  const tgt = st.target ? st.target.state : 'none';
  document.getElementById('status').innerHTML =
    `<b>t = ${st.time_s === null ? '-' : st.time_s.toFixed(2)} s</b><br>` +
    `GHstab = <span class="${cls}">${gh}</span>${cls === 'bad' ? ' (above 1: force outside the glenoid rim)' : ''}<br>` +
    `task: ${st.phase}, trial ${st.trial + 1} of ${st.n_trials}, target ${tgt}`;
  const rows = (st.metrics || []).map(r => '<tr>' + COLUMNS.map(c => `<td>${fmt(r[c])}</td>`).join('') + '</tr>');
  document.getElementById('metrics').innerHTML =
    '<tr>' + COLUMNS.map(c => `<th>${c}</th>`).join('') + '</tr>' + rows.join('');
}
""".replace("COLUMNS_JSON", json.dumps(list(OPERATOR_COLUMNS))) + PAGE_JS + "</script></body></html>\n"


# ------------------------------------------------------------------ command line
def _cmd_display(args) -> int:
    from .geometry import ArmGeometry
    from .realtime import parse_endpoint, read_key_file
    from .view import UdpSource
    host, port = parse_endpoint(args.udp)
    key = read_key_file(args.key_file) if args.key_file else None
    geom = ArmGeometry(args.model)
    pts = arm_points(geom, geom.rest)
    centre = np.asarray(args.centre, dtype=float) if args.centre else pts[-1]
    plane = TaskPlane(tuple(centre), half_height_m=args.half_height or
                      1.25 * float(np.abs(TaskPlane(tuple(centre)).project(pts)).max()))
    source = UdpSource(host, port, model=args.model, key=key)
    with DisplayServer(plane, host=args.host, port=args.port) as server:
        feed = FrameFeed(source, server, fps=args.fps).start()
        print(f"participant display: chromium --kiosk {server.url}\noperator page: {server.operator_url}\n"
              f"drawing the armrt-rt state stream on udp {host or '127.0.0.1'}:{source.port}", flush=True)
        try:
            t_end = None if args.duration is None else time.monotonic() + args.duration
            while t_end is None or time.monotonic() < t_end:
                time.sleep(0.2)
        except KeyboardInterrupt:
            pass
        finally:
            feed.stop()
    print(f"drew {feed.frames} states ({source.packets} packets, {source.bad_packets} refused)"
          + (f"; last refused pose: {feed.error}" if feed.error else ""))
    if source.bad_packets:   # e.g. a runner of another model, or another key: say why, not only how many
        print(f"armrt display: refused datagrams: {source.last_error}", file=sys.stderr)
    return 0


def add_cli(sub, formatter=None) -> None:
    """Registers `display`: the participant display and operator page fed by the armrt-rt UDP state stream."""
    kw = {"formatter_class": formatter} if formatter else {}
    p = sub.add_parser("display", help="participant display (kiosk) + operator page of the armrt-rt state stream",
                       **kw)
    p.add_argument("--udp", default=":9870", metavar="HOST:PORT",
                   help="where armrt-rt sends state (--state-to; ':PORT': loopback)")
    p.add_argument("--key-file", help="the runner's --key-file (draw only signed state packets)")
    p.add_argument("--model", default="das2", help="the runner's --model")
    p.add_argument("--centre", type=float, nargs=3, default=None, metavar=("X", "Y", "Z"),
                   help="screen centre, m, thorax frame (default: the hand at the model's rest posture)")
    p.add_argument("--half-height", type=float, default=None,
                   help="m from the centre to the screen's nearer edges (default: the arm fits)")
    p.add_argument("--host", default="127.0.0.1", help="address the pages are served on")
    p.add_argument("--port", type=int, default=8090, help="port the pages are served on")
    p.add_argument("--fps", type=float, default=60.0, help="states sent to the pages per second")
    p.add_argument("--duration", type=float, default=None, help="stop after this many seconds (default: Ctrl-C)")
    p.set_defaults(func=_cmd_display)
