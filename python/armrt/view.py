"""Live 3D view of the arm in a browser page served on localhost (viser; its web client is bundled in
the PyPI package, nothing is downloaded at run time).

    armrt view                       # a demo simulation, http://localhost:8080
    armrt view --result run.npz      # replay a saved result
    armrt view --udp :9870           # the armrt-rt state stream on loopback (armrt-rt --state-to 127.0.0.1:9870
                                     # --excitations); bind another address explicitly, e.g. --udp 10.0.0.5:9870

    from armrt.view import serve, SimulationSource
    serve(SimulationSource(excitation=lambda t: {"elbow_flexors": 0.3}))

Data come from a *source*: any object with `start()`, `latest() -> Frame | None`, `close()` and the
attributes `model` (name) and `element_names`. Three are provided: `SimulationSource` (an `armrt.Arm`
stepped in real time in a thread), `ResultSource` (a saved `Result` replayed), `UdpSource` (the
armrt-rt UDP state stream, decoded with `armrt.realtime`).
"""
from __future__ import annotations

import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Protocol

import numpy as np

from .geometry import POINTS, ArmGeometry

BONE_COLOURS = {  # distinct, saturated: the browser test finds the arm by these colours
    "humerus": (255, 128, 0), "ulna": (0, 160, 255), "radius": (0, 90, 255), "hand": (200, 0, 200)}
STATIC_COLOUR = (120, 120, 120)
# A thorax-based model's moving girdle (ArmGeometry.girdle): clavicle, scapula blade and glenoid rim.
GIRDLE_COLOURS = {"clavicle_r": (0, 160, 96), "scapula_r": (140, 60, 20), "glenoid": (140, 60, 20)}
CONTACT_COLOUR = (212, 160, 0)   # TS, AI: the points held on the thorax ellipsoid
STAB_OK, STAB_BAD = (40, 180, 60), (230, 30, 30)


DOF_LABELS = {  # the model's coordinates (docs/conventions.md) with the names a lab uses
    "GHy": "plane of elevation", "GHz": "elevation", "GHyy": "axial rotation", "ELx": "elbow flexion",
    "PSy": "pronation-supination",
    # das3's girdle: DAS3's sterno-clavicular and acromio-clavicular rotations (y, z, x in that order)
    "SCy": "clavicle protraction", "SCz": "clavicle elevation", "SCx": "clavicle axial rotation",
    "ACy": "scapula protraction", "ACz": "scapula lateral rotation", "ACx": "scapula tilt"}
STAB_WINDOW_S = 10.0   # GHstab plot: the last seconds


@dataclass
class Frame:
    """One state to draw."""
    time: float
    q: np.ndarray                      # (n_dofs,) rad
    activation: np.ndarray | None      # (n,) or None
    gh_stab: float = float("nan")
    gh_rim_margin: float = float("nan")     # rad, how far the GH force can still turn towards the rim
    gh_rim_direction: float = float("nan")  # rad, where it leans: 0 superior, pi/2 anterior
    lag: float | None = None           # s behind wall time (real-time runner only)
    overrun: bool = False              # the runner overran since its previous state packet
    timed_out: bool = False            # the runner has no controller (excitation zero)
    kind: str = "activation"           # what `activation` holds: "activation" or "excitation received"


class Source(Protocol):
    model: str
    element_names: list

    def start(self) -> None: ...
    def latest(self) -> Frame | None: ...
    def close(self) -> None: ...


def demo_excitation(t: float) -> dict:
    """A slow, stable reaching-like pattern: elbow flexion and shoulder abduction cycles."""
    return {"rotator_cuff": 0.08,
            "elbow_flexors": 0.15 * (1 + np.sin(2 * np.pi * 0.3 * t)),
            "deltscap": 0.08 * (1 + np.sin(2 * np.pi * 0.2 * t - 1.0))}


class SimulationSource:
    """An `armrt.Arm` stepped in a background thread, paced to wall-clock time x `speed`.

    excitation: f(t) -> anything `Arm.set_excitation` takes, or a constant; default demo_excitation.
    `set_manual({group: value})` overrides it (the viewer's excitation sliders; None: back to it);
    `set_paused(True)` holds the simulation. A diverged simulation restarts from the rest posture."""

    def __init__(self, arm=None, excitation: Callable | dict | None = None, model: str = "das2",
                 integrator: str | None = None, dt: float = 1e-3, speed: float = 1.0, chunk: float = 0.01):
        from .arm import DEFAULT_INTEGRATOR, Arm
        self.arm = arm if arm is not None else Arm(model=model, integrator=integrator or DEFAULT_INTEGRATOR, dt=dt)
        self.model = self.arm.model_name
        self.element_names = list(self.arm.element_names)
        self.excitation = demo_excitation if excitation is None else excitation
        self.speed = float(speed)
        self.steps_per_chunk = max(1, int(round(chunk / self.arm.dt)))
        self._frame: Frame | None = None
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self.restarts = 0
        self.error: BaseException | None = None
        self.manual: np.ndarray | None = None   # (n_elements,) held excitation, or None
        self._paused = threading.Event()

    @property
    def paused(self) -> bool:
        return self._paused.is_set()

    def set_paused(self, paused: bool) -> None:
        (self._paused.set if paused else self._paused.clear)()

    def set_manual(self, excitation: dict | None) -> None:
        """Excitations by group/muscle/element name held constant (None: back to the `excitation` source).
        An element in several named groups takes the largest of their values, as in the runner."""
        if excitation is None:
            self.manual = None
            return
        u = np.zeros(len(self.element_names))
        for name, v in excitation.items():
            ix = self.arm.indices(name)
            u[ix] = np.maximum(u[ix], float(v))
        self.manual = u

    def _snapshot(self) -> Frame:
        out = self.arm.outputs()
        return Frame(time=self.arm.time, q=self.arm.q.copy(), activation=self.arm.activation.copy(),
                     gh_stab=float(out["gh_stab"]), gh_rim_margin=float(out["gh_rim_margin"]),
                     gh_rim_direction=float(out["gh_rim_direction"]))

    def _run(self) -> None:
        from .arm import SimulationError
        try:
            t_wall0, t_sim0 = time.perf_counter(), self.arm.time
            while not self._stop.is_set():
                if self._paused.is_set():
                    self._stop.wait(0.02)
                    t_wall0, t_sim0 = time.perf_counter(), self.arm.time   # no catching up after a pause
                    continue
                if self.manual is not None:
                    u = self.manual
                else:
                    u = self.excitation(self.arm.time) if callable(self.excitation) else self.excitation
                self.arm.set_excitation(u)
                try:
                    self.arm.step(self.steps_per_chunk)
                except SimulationError:
                    self.restarts += 1
                    self.arm.reset()
                    t_wall0, t_sim0 = time.perf_counter(), self.arm.time
                self._frame = self._snapshot()
                lag = (self.arm.time - t_sim0) / self.speed - (time.perf_counter() - t_wall0)
                if lag > 0:
                    self._stop.wait(lag)
        except BaseException as exc:  # reported by latest(); the viewer keeps serving
            self.error = exc

    def start(self) -> None:
        if self._thread is None:
            self._frame = self._snapshot()
            self._thread = threading.Thread(target=self._run, name="armrt-sim", daemon=True)
            self._thread.start()

    def latest(self) -> Frame | None:
        if self.error is not None:
            raise RuntimeError(f"simulation source failed: {self.error}") from self.error
        return self._frame

    def close(self) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=2.0)


class ResultSource:
    """A saved `Result` replayed in real time x `speed`, looping; `set_paused`, `seek(t)` (the viewer's
    pause box and time slider)."""

    def __init__(self, result, speed: float = 1.0, loop: bool = True):
        if isinstance(result, (str, bytes)) or hasattr(result, "__fspath__"):
            from .arm import Result
            result = Result.load(result)
        self.result = result
        self.model = result.model or "das2"
        self.element_names = list(result.element_names)
        self.speed, self.loop = float(speed), loop
        self._t0 = None          # wall time at which playback (re)started
        self._pos0 = 0.0         # playback position (s after the first sample) at _t0
        self.paused = False

    @property
    def span(self) -> tuple[float, float]:
        return float(self.result.time[0]), float(self.result.time[-1])

    def start(self) -> None:
        self._t0 = time.perf_counter()

    def _position(self) -> float:
        span = self.span[1] - self.span[0]
        pos = self._pos0 if self.paused else self._pos0 + (time.perf_counter() - self._t0) * self.speed
        return pos % span if self.loop and span > 0 else min(pos, span)

    def set_paused(self, paused: bool) -> None:
        if self._t0 is None:
            self.start()
        self._pos0, self._t0 = self._position(), time.perf_counter()
        self.paused = bool(paused)

    def seek(self, t: float) -> None:
        """Shows the sample at time t (s, the result's clock); playback continues from there unless paused."""
        if self._t0 is None:
            self.start()
        lo, hi = self.span
        self._pos0, self._t0 = float(np.clip(t, lo, hi)) - lo, time.perf_counter()

    def latest(self) -> Frame | None:
        r = self.result
        if self._t0 is None or len(r.time) == 0:
            return None
        t = self._position() + float(r.time[0])
        k = int(np.clip(np.searchsorted(r.time, t, side="right") - 1, 0, len(r.time) - 1))
        act = np.asarray(r.activation[k])
        # A kinematic replay (a .mot) has no activations: NaN rows are shown as none.
        return Frame(time=float(r.time[k]), q=np.asarray(r.q[k]), activation=None if np.isnan(act).all() else act,
                     gh_stab=float(r.gh_stab[k]), gh_rim_margin=float(r.gh_rim_margin[k]),
                     gh_rim_direction=float(r.gh_rim_direction[k]))

    def close(self) -> None:
        pass


class UdpSource:
    """The armrt-rt UDP state stream (docs/realtime.md): run the runner with `--state-to HOST:PORT
    --excitations` (or `RealtimeSession(state_to=..., send_excitation=True)`) and view with
    `armrt view --udp :PORT`. Binds loopback unless another address is named (`HOST:PORT`, parsed as
    the runner does). Packets are decoded by `armrt.realtime`; with `key` (the runner's shared key)
    only signed packets are drawn. The activation panel shows the excitations the runner applied
    (present with --excitations); lag and the overrun flag come with every packet."""

    def __init__(self, host: str = "127.0.0.1", port: int = 9870, model: str = "das2", key: bytes | None = None):
        try:
            from . import realtime
        except ImportError as exc:
            raise RuntimeError("the UDP source needs armrt.realtime (the armrt-rt packet codec), which is "
                               "not available in this build") from exc
        self.model = model
        from . import _core
        self.element_names = [e["name"] for e in _core.model_info(model)["elements"]]
        self._listener = realtime.StateListener(host, port, model, key)
        self._sock = self._listener.sock
        self.port = self._listener.port
        self._sock.settimeout(0.2)
        self._frame: Frame | None = None
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    # Packet counts and why the last bad datagram was refused (e.g. a runner of another model): the listener's.
    packets = property(lambda self: self._listener.packets)
    bad_packets = property(lambda self: self._listener.bad_packets)
    last_error = property(lambda self: self._listener.last_error)

    def _run(self) -> None:
        while not self._stop.is_set():
            try:
                data, _ = self._sock.recvfrom(65536)
            except OSError:
                continue
            s = self._listener.decode(data)
            if s is not None:
                self._frame = Frame(time=s.time, q=np.asarray(s.q, dtype=float), activation=s.excitation,
                                    gh_stab=s.gh_stab, gh_rim_margin=s.gh_rim_margin,
                                    gh_rim_direction=s.gh_rim_direction, lag=s.lag, overrun=s.overrun, timed_out=s.timed_out,
                                    kind="excitation received")

    def start(self) -> None:
        if self._thread is None:
            self._thread = threading.Thread(target=self._run, name="armrt-udp", daemon=True)
            self._thread.start()

    def latest(self) -> Frame | None:
        return self._frame

    def close(self) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=1.0)
        self._sock.close()


def stab_colour(gh_stab: float) -> tuple[int, int, int]:
    """Green while GHstab <= 1 (force inside the glenoid rim), red above."""
    return STAB_BAD if (np.isfinite(gh_stab) and gh_stab > 1.0) else STAB_OK


# Where the GH force leans, by rim direction psi in 45-degree sectors from 0 (superior) through pi/2
# (+ minor axis: anterior for a right scapula, docs/conventions.md).
RIM_SECTORS = ("superior", "superior-anterior", "anterior", "inferior-anterior", "inferior",
               "inferior-posterior", "posterior", "superior-posterior")


def rim_text(margin: float, direction: float) -> str:
    """The status line's rim part: the margin in degrees and the side the force leans towards
    ("n/a" when unknown); a negative margin is how far beyond the rim the force points."""
    if not (np.isfinite(margin) and np.isfinite(direction)):
        return "rim margin n/a"
    side = RIM_SECTORS[int(np.round(direction / (np.pi / 4))) % 8]
    where = "to the rim" if margin >= 0 else "beyond the rim"
    return f"rim margin {np.degrees(abs(margin)):.1f}&deg; {where}, leaning {side} ({np.degrees(direction):.0f}&deg;)"


def activation_colours(a: np.ndarray) -> np.ndarray:
    """(k, 3) uint8: grey at 0 to red at 1."""
    a = np.clip(np.asarray(a, dtype=float), 0, 1)[:, None]
    return ((1 - a) * np.array([170, 170, 170]) + a * np.array([220, 20, 20])).astype(np.uint8)


def stab_plot_svg(t: np.ndarray, gh: np.ndarray, window: float = STAB_WINDOW_S, width: int = 260,
                  height: int = 96) -> str:
    """GHstab over the last `window` s as an inline SVG, with the 1 (rim: dislocation) and 0.5 lines."""
    t, gh = np.asarray(t, dtype=float), np.asarray(gh, dtype=float)
    ok = np.isfinite(gh)
    t, gh = t[ok], gh[ok]
    top = max(1.5, float(np.max(gh)) * 1.1) if gh.size else 1.5
    x0, x1, y0, y1 = 26, width - 4, 6, height - 16

    def y(v):
        return y1 - (y1 - y0) * np.clip(v, 0, top) / top
    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
             f'style="background:#fafafa;font:10px sans-serif" data-armrt="gh-stab-plot">']
    for level, colour, dash in ((1.0, "#d22", ""), (0.5, "#e90", ' stroke-dasharray="4 3"')):
        parts.append(f'<line x1="{x0}" x2="{x1}" y1="{y(level):.1f}" y2="{y(level):.1f}" stroke="{colour}"{dash}/>'
                     f'<text x="2" y="{y(level) + 3:.1f}" fill="{colour}">{level:g}</text>')
    if t.size >= 2:
        tx = x1 - (x1 - x0) * np.clip((t[-1] - t) / window, 0, 1)
        pts = " ".join(f"{a:.1f},{b:.1f}" for a, b in zip(tx, y(gh)))
        parts.append(f'<polyline points="{pts}" fill="none" stroke="#246" stroke-width="1.5"/>')
    parts.append(f'<text x="{x0}" y="{height - 3}" fill="#555">GHstab, last {window:g} s (1: force at the '
                 f'glenoid rim)</text></svg>')
    return "".join(parts)


def _polyline_segments(p: np.ndarray) -> np.ndarray:
    return np.stack([p[:-1], p[1:]], axis=1)


class Viewer:
    """The viser scene and the update loop; `serve()` is the one-call entry point."""

    def __init__(self, source, host: str = "127.0.0.1", port: int = 8080, fps: float = 30.0,
                 lines_of_action: bool = True, verbose: bool = True):
        import viser
        self.source = source
        self.geom = ArmGeometry(source.model)
        self.fps = float(fps)
        self.server = viser.ViserServer(host=host, port=port, verbose=False)
        self.host, self.port = host, self.server.get_port()
        self.url = f"http://{'localhost' if host in ('0.0.0.0', '127.0.0.1') else host}:{self.port}"
        self.frames_drawn = 0
        self.last_frame: Frame | None = None
        import collections
        self._stab_history: collections.deque = collections.deque(maxlen=int(self.fps * STAB_WINDOW_S * 2) + 10)
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self._lines_of_action = lines_of_action
        names = list(source.element_names)
        info = self.geom.info
        self._muscles = [(m, np.array(ix)) for m, ix in info["muscles"]] if names == [
            e["name"] for e in info["elements"]] else []
        self._build_scene()
        if verbose:
            print(f"armrt view: {self.url}  (Ctrl-C to stop)", flush=True)

    # -------------------------------------------------------------- scene
    def _build_scene(self) -> None:
        sc, g = self.server.scene, self.geom
        sc.set_up_direction("+y")
        sc.configure_environment_map(hdri=None)   # the default HDRI would be fetched from the internet
        sc.add_light_ambient("/lights/ambient", intensity=1.2)
        sc.add_light_directional("/lights/key", intensity=1.5, position=(0.5, 1.0, -1.0))
        static = g.static()
        segs = np.concatenate([_polyline_segments(p) for p in static.values()])
        sc.add_line_segments("/thorax/girdle", segs.astype(np.float32), STATIC_COLOUR, thickness=0.006)
        sc.add_icosphere("/thorax/ij", radius=0.01, color=STATIC_COLOUR, position=(0.0, 0.0, 0.0))
        rest = g.points(g.rest)
        self._head_radius = 0.024
        if g.model_json is not None:
            glen = np.asarray(g.model_json["glenoid"]["glenoid_centre"]) - g.gh_centre_scapula
            self._head_radius = float(np.linalg.norm(glen))   # humeral head touches the glenoid
        self._bones = sc.add_line_segments("/arm/bones", self._bone_segments(rest), self._bone_colours(),
                                           thickness=0.016)
        self._head = sc.add_icosphere("/arm/humeral_head", radius=self._head_radius, color=STAB_OK,
                                      position=tuple(rest[0]))
        self._joints = {n: sc.add_icosphere(f"/arm/{n}", radius=0.014, color=(230, 230, 230), position=tuple(rest[i]))
                        for i, n in enumerate(POINTS) if n in ("elbow", "wrist", "hand")}
        # A moving girdle (das3): clavicle, scapula and glenoid redrawn from the body poses every frame.
        girdle = g.girdle(g.rest)
        self._girdle = self._contacts = None
        if girdle:
            segs, cols = self._girdle_segments(girdle)
            self._girdle = sc.add_line_segments("/girdle/bones", segs, cols, thickness=0.01)
            self._contacts = [sc.add_icosphere(f"/girdle/contact_{k}", radius=0.008, color=CONTACT_COLOUR,
                                               position=tuple(x)) for k, x in enumerate(girdle.get("contact_points", []))]
        if self._lines_of_action:
            seg, self._loa_idx = g.gh_lines_of_action(g.rest)
            self._loa = sc.add_line_segments("/arm/gh_lines_of_action", seg.astype(np.float32),
                                             np.repeat(activation_colours(np.zeros(len(seg)))[:, None], 2, axis=1),
                                             thickness=0.002)
        gui = self.server.gui
        gui.configure_theme(control_width="medium")
        self._status = gui.add_markdown("starting...")
        self._stab_bar = gui.add_progress_bar(0.0, color="green")
        self.controls: dict = {}
        self._add_controls(gui)
        self._stab_plot = gui.add_html(stab_plot_svg([], []))
        self._angles = gui.add_html(self._angles_html(None))
        self._bars = gui.add_html(self._activation_html(None))

        @self.server.on_client_connect
        def _(client) -> None:
            # Anterior view from the subject's front right, framing the shoulder and the arm at rest
            # (shoulder to hand about 0.6 m) so that they fill most of the view's height.
            centre = np.array([0.13, -0.27, 0.0])
            client.camera.up_direction = (0.0, 1.0, 0.0)
            client.camera.position = tuple(centre + np.array([0.2, 0.08, -0.55]))
            client.camera.look_at = tuple(centre)

    def _add_controls(self, gui) -> None:
        """Offline sources: pause; a time slider for a saved result; excitation sliders per group for a
        simulation. (The real-time runner is driven by its controller, not from the page.)"""
        src = self.source
        if hasattr(src, "set_paused"):
            pause = gui.add_checkbox("pause", initial_value=False)
            pause.on_update(lambda _: src.set_paused(pause.value))
            self.controls["pause"] = pause
        if hasattr(src, "seek"):
            lo, hi = src.span
            scrub = gui.add_slider("time (s)", min=lo, max=max(hi, lo + 1e-3), step=max((hi - lo) / 1000, 1e-4),
                                   initial_value=lo)

            def _seek(_) -> None:
                src.seek(scrub.value)
                if "pause" in self.controls and not self.controls["pause"].value:
                    self.controls["pause"].value = True   # scrubbing holds the frame
            scrub.on_update(_seek)
            self.controls["time"] = scrub
        if hasattr(src, "set_manual"):
            with gui.add_folder("excitation (manual)", expand_by_default=False):
                manual = gui.add_checkbox("use sliders", initial_value=False)
                sliders = {g: gui.add_slider(g, min=0.0, max=1.0, step=0.01, initial_value=0.0)
                           for g, _ in self.geom.info["groups"]}

            def _apply(_) -> None:
                src.set_manual({g: h.value for g, h in sliders.items()} if manual.value else None)
            manual.on_update(_apply)
            for h in sliders.values():
                h.on_update(_apply)
            self.controls["manual"] = manual
            self.controls.update({f"excitation:{g}": h for g, h in sliders.items()})

    @staticmethod
    def _girdle_segments(girdle: dict) -> tuple[np.ndarray, np.ndarray]:
        """(segments (k, 2, 3) float32, colours (k, 2, 3) uint8) of the girdle's polylines."""
        parts = [(_polyline_segments(girdle[n]), c) for n, c in GIRDLE_COLOURS.items() if n in girdle]
        segs = np.concatenate([seg for seg, _ in parts]).astype(np.float32)
        cols = np.concatenate([np.tile(np.array(c, dtype=np.uint8), (len(seg), 2, 1)) for seg, c in parts])
        return segs, cols

    def _bone_segments(self, pts: np.ndarray) -> np.ndarray:
        return ArmGeometry.segments(pts).astype(np.float32)

    @staticmethod
    def _bone_colours() -> np.ndarray:
        return np.repeat(np.array(list(BONE_COLOURS.values()), dtype=np.uint8)[:, None], 2, axis=1)

    def _angles_html(self, q: np.ndarray | None) -> str:
        rows = []
        for k, name in enumerate(self.geom.dof_names):
            v = "" if q is None else f"{np.degrees(q[k]):7.1f}&deg;"
            rows.append(f'<tr><td>{DOF_LABELS.get(name, name)}</td><td style="color:#777">{name}</td>'
                        f'<td style="text-align:right">{v}</td></tr>')
        return ('<div style="font:11px monospace"><b style="font:12px sans-serif">joint angles</b>'
                '<table style="border-spacing:6px 0">' + "".join(rows) + "</table></div>")

    def _activation_html(self, act: np.ndarray | None, kind: str = "activation", note: str = "") -> str:
        rows = []
        for m, ix in self._muscles:
            a = 0.0 if act is None else float(np.mean(act[ix]))
            w = int(round(100 * min(max(a, 0.0), 1.0)))
            rows.append(f'<div style="display:flex;align-items:center;font:11px monospace;height:13px">'
                        f'<span style="width:70px">{m}</span><span style="flex:1;background:#eee;height:9px">'
                        f'<span style="display:block;width:{w}%;height:9px;background:#d33"></span></span>'
                        f'<span style="width:34px;text-align:right">{a:.2f}</span></div>')
        head = f'<b style="font:12px sans-serif">muscle {kind} (mean of elements)</b>'
        if note:
            head += f'<div style="font:11px sans-serif;color:#a50">{note}</div>'
        return "<div>" + head + "".join(rows) + "</div>"

    # -------------------------------------------------------------- updates
    def draw(self, f: Frame) -> None:
        pts = self.geom.points(f.q)
        colour = stab_colour(f.gh_stab)
        with self.server.atomic():
            self._bones.points = self._bone_segments(pts)
            self._head.position = tuple(pts[0])
            self._head.color = colour
            for i, n in enumerate(POINTS):
                if n in self._joints:
                    self._joints[n].position = tuple(pts[i])
            if self._girdle is not None:
                girdle = self.geom.girdle(f.q)
                self._girdle.points = self._girdle_segments(girdle)[0]
                for handle, x in zip(self._contacts, girdle.get("contact_points", [])):
                    handle.position = tuple(x)
            if self._lines_of_action and f.activation is not None:
                seg, idx = self.geom.gh_lines_of_action(f.q)
                if len(idx) == len(self._loa_idx):
                    self._loa.points = seg.astype(np.float32)
                    self._loa.colors = np.repeat(activation_colours(f.activation[idx])[:, None], 2, axis=1)
            stab = f"{f.gh_stab:.2f}" if np.isfinite(f.gh_stab) else "n/a"
            flag = " **above 1: force outside the glenoid rim**" if colour == STAB_BAD else ""
            rt_line = ""
            if f.lag is not None:
                rt_line = f"  \nlag behind wall time {f.lag * 1e3:.0f} ms" + (
                    "  \n**OVERRUN** (the runner missed a deadline)" if f.overrun else "") + (
                    "  \nno controller: excitation zero" if f.timed_out else "")
            self._status.content = (f"**t = {f.time:7.2f} s**  \nGHstab = {stab}{flag}  \n"
                                    f"{rim_text(f.gh_rim_margin, f.gh_rim_direction)}{rt_line}")
            self._stab_bar.value = float(np.clip(50 * f.gh_stab, 0, 100)) if np.isfinite(f.gh_stab) else 0.0
            self._stab_bar.color = "red" if colour == STAB_BAD else "green"
            self._stab_history.append((f.time, f.gh_stab))
            if self.frames_drawn % 3 == 0:
                h = np.array(self._stab_history)
                recent = h[h[:, 0] >= h[-1, 0] - STAB_WINDOW_S]
                self._stab_plot.content = stab_plot_svg(recent[:, 0], recent[:, 1])
                self._angles.content = self._angles_html(f.q)
                if self._muscles:
                    note = ""
                    if f.activation is None and f.kind == "excitation received":
                        note = "state packets carry no excitations: start armrt-rt with --excitations"
                    self._bars.content = self._activation_html(f.activation, f.kind, note)
        self.frames_drawn += 1

    def _loop(self) -> None:
        period = 1.0 / self.fps
        next_t = time.perf_counter()
        while not self._stop.is_set():
            f = self.source.latest()
            if f is not None and f is not self.last_frame:
                try:
                    self.draw(f)
                except ValueError as exc:
                    # A pose the geometry refuses (q far beyond the joint ranges: degrees, a runner of another
                    # model) must not end this loop, which would freeze the page without a word: it says why.
                    self._status.content = f"**cannot draw t = {f.time:.2f} s:** {exc}"
                self.last_frame = f
            next_t += period
            delay = next_t - time.perf_counter()
            if delay > 0:
                self._stop.wait(delay)
            else:
                next_t = time.perf_counter()

    def start(self) -> "Viewer":
        self.source.start()
        self._thread = threading.Thread(target=self._loop, name="armrt-view", daemon=True)
        self._thread.start()
        return self

    def stop(self) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=2.0)
        self.source.close()
        self.server.stop()


def serve(source=None, host: str = "127.0.0.1", port: int = 8080, fps: float = 30.0,
          lines_of_action: bool = True, block: bool = True, duration: float | None = None) -> Viewer:
    """Serves the live view of `source` (default: the demo SimulationSource) at http://host:port.
    block=True runs until Ctrl-C (or `duration` seconds) and then stops; block=False returns the running
    Viewer (call .stop())."""
    viewer = Viewer(source if source is not None else SimulationSource(), host=host, port=port, fps=fps,
                    lines_of_action=lines_of_action).start()
    if not block:
        return viewer
    try:
        t_end = None if duration is None else time.monotonic() + duration
        while t_end is None or time.monotonic() < t_end:
            time.sleep(0.2)
    except KeyboardInterrupt:
        pass
    finally:
        viewer.stop()
    return viewer


# ------------------------------------------------------------------ command line
def load_replay(path, model: str = "das2"):
    """A saved Result (.npz) or an OpenSim motion (.mot/.sto of joint angles, kinematics only)."""
    from .arm import Result
    if Path(path).suffix.lower() in (".mot", ".sto"):
        from .opensim_io import read_motion
        return read_motion(path, model=model).to_result()
    return Result.load(path)


def _cmd_view(args) -> int:
    if args.result:
        source = ResultSource(load_replay(args.result, args.model), speed=args.speed)
    elif args.udp:
        from .realtime import parse_endpoint, read_key_file
        # A bad address or key file raises ValueError/OSError: one line from armrt's main().
        host, port = parse_endpoint(args.udp)
        key = read_key_file(args.key_file) if args.key_file else None
        source = UdpSource(host, port, model=args.model, key=key)
    else:
        source = SimulationSource(model=args.model, integrator=args.integrator, dt=args.dt, speed=args.speed)
    serve(source, host=args.host, port=args.port, fps=args.fps, lines_of_action=not args.no_lines,
          duration=args.duration)
    return 0


def _cmd_animate(args) -> int:
    from .animate import animate, check_output
    check_output(args.out)
    out = animate(load_replay(args.result, args.model), args.out, fps=args.fps, speed=args.speed, dpi=args.dpi,
                  lines_of_action=not args.no_lines, max_frames=args.max_frames,
                  progress=None if args.progress else False)
    print(f"wrote {out}")
    return 0


def _cmd_export(args) -> int:
    from .arm import Result
    from .cli_common import CliError, check_suffix
    from .opensim_io import write_activation_sto, write_excitation_sto, write_mot, write_stimulation_sto
    if not (args.mot or args.sto or args.controls or args.stimulation):
        raise CliError("give --mot FILE, --sto FILE, --controls FILE and/or --stimulation FILE")
    check_suffix(args.mot, (".mot",), "--mot")
    check_suffix(args.sto, (".sto",), "--sto")
    check_suffix(args.controls, (".sto",), "--controls")
    check_suffix(args.stimulation, (".sto",), "--stimulation")
    res = Result.load(args.result)
    if args.stimulation and res.stimulation is None:   # before any file is written
        raise CliError(f"--stimulation: {args.result} has no stimulation (its arm had no stimulation map)")
    if args.mot:
        print(f"wrote {write_mot(res, args.mot, model_file=args.model_file)}")
    if args.sto:
        print(f"wrote {write_activation_sto(res, args.sto, model_file=args.model_file, state_paths=args.state_paths)}")
    if args.controls:
        print(f"wrote {write_excitation_sto(res, args.controls, model_file=args.model_file)}")
    if args.stimulation:
        print(f"wrote {write_stimulation_sto(res, args.stimulation)}")
    return 0


def add_cli(subparsers, formatter_class=None) -> None:
    """Registers `view`, `animate` and `export` on an argparse subparsers object (each sets func)."""
    from .integrators import DEFAULT_INTEGRATOR, INTEGRATORS
    kw = {"formatter_class": formatter_class} if formatter_class else {}
    p = subparsers.add_parser("view", help="live 3D view in the browser (demo simulation, a saved result, or UDP)",
                              **kw)
    src = p.add_mutually_exclusive_group()
    src.add_argument("--result", metavar="FILE", help="replay a saved result (.npz) or a motion (.mot, angles only)")
    src.add_argument("--udp", metavar="HOST:PORT", help="listen to the armrt-rt state stream (':PORT': loopback)")
    p.add_argument("--key-file", help="the runner's --key-file (draw only signed state packets)")
    p.add_argument("--model", default="das2", help="compiled-in model name")
    p.add_argument("--integrator", default=DEFAULT_INTEGRATOR, choices=list(INTEGRATORS),
                   help="integration method of the demo simulation (ros2: one linearly implicit step per 1 ms)")
    p.add_argument("--dt", type=float, default=1e-3, help="control step, s (demo)")
    p.add_argument("--speed", type=float, default=1.0, help="simulated seconds per wall-clock second")
    p.add_argument("--host", default="127.0.0.1", help="address the web page is served on")
    p.add_argument("--port", type=int, default=8080, help="port the web page is served on")
    p.add_argument("--fps", type=float, default=30.0, help="page updates per second")
    p.add_argument("--duration", type=float, default=None, help="stop after this many seconds (default: Ctrl-C)")
    p.add_argument("--no-lines", action="store_true", help="hide the GH lines of action")
    p.set_defaults(func=_cmd_view)

    p = subparsers.add_parser("animate", help="render a saved result (or a .mot motion) to .mp4 (ffmpeg) or .gif",
                              **kw)
    p.add_argument("result", help="saved result (.npz) or OpenSim motion (.mot, angles only)")
    p.add_argument("-o", "--out", default="arm.gif", help="output .mp4 or .gif")
    p.add_argument("--model", default="das2", help="model of a .mot input")
    p.add_argument("--fps", type=int, default=30, help="frames per second of the video")
    p.add_argument("--speed", type=float, default=1.0, help="simulated seconds per video second")
    p.add_argument("--dpi", type=int, default=80, help="resolution, dots per inch (figure 10 x 6.4 in)")
    p.add_argument("--no-lines", action="store_true", help="hide the GH lines of action")
    p.add_argument("--max-frames", type=int, default=None,
                   help="only the first N frames (needed beyond an hour of video at 30 frames/s)")
    p.add_argument("--no-progress", dest="progress", action="store_false", help="no progress bar on a terminal")
    p.set_defaults(func=_cmd_animate)

    p = subparsers.add_parser("export", help="OpenSim files: joint angles (.mot), activations, excitations and stimulation (.sto)",
                              **kw)
    p.add_argument("result", help="saved result (.npz)")
    p.add_argument("--mot", metavar="FILE.mot", help="joint angles, OpenSim motion file (rad)")
    p.add_argument("--sto", metavar="FILE.sto", help="activations, OpenSim storage file (force names)")
    p.add_argument("--controls", metavar="FILE.sto",
                   help="excitations the dynamics used (capped at max_activation), OpenSim controls file")
    p.add_argument("--stimulation", metavar="FILE.sto",
                   help="per stimulation channel: pulse width (s), amplitude (A), frequency (Hz), recruitment and "
                        "fatigue, OpenSim storage file (a result of an arm with a stimulation map)")
    p.add_argument("--state-paths", action="store_true", help="name .sto columns /forceset/<muscle>/activation")
    p.add_argument("--model-file", help="models/<name>.json (default: found beside the package)")
    p.set_defaults(func=_cmd_export)
