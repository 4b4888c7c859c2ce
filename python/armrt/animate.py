"""Offline animation of a saved result: `armrt animate run.npz -o arm.mp4` (or .gif).

Front and side views of the arm (same geometry as the live view, armrt.geometry; a thorax-based
model's clavicle, scapula, glenoid and scapulothoracic contact points move with it, over the thorax
ellipsoid's outline), the GH stability trace (red above 1) and per-muscle activation bars. Frames go to the encoder as they are drawn, so
memory does not grow with the length of the video: .gif through StreamingGifWriter (Pillow, one frame
in memory; matplotlib's PillowWriter keeps every frame: 1.3 GB for 600), .mp4 through ffmpeg's pipe
(Debian package `ffmpeg`). The frames' rows (FrameRows) and each frame's geometry are computed when the
frame is drawn, not for the whole video first (a 19 KB result spanning a long time reached 2 GB in 30 s
before its first frame), and a video of more than MAX_FRAMES frames is refused before any work unless
max_frames bounds it.
"""
from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np

from .geometry import POINTS, SEGMENTS, ArmGeometry

BONE_COLOURS = {"humerus": "#ff8000", "ulna": "#00a0ff", "radius": "#005aff", "hand": "#c800c8"}
# The moving girdle of a thorax-based model (das3): ArmGeometry.girdle parts.
GIRDLE_STYLE = {"clavicle_r": dict(color="#00a060", lw=4, solid_capstyle="round"),
                "scapula_r": dict(color="#a05a2c", lw=2.5),
                "glenoid": dict(color="#a05a2c", lw=1.2),
                "contact_points": dict(color="#d4a000", ls="none", marker="s", ms=5)}


# An hour of video at 30 frames/s (encoding it takes hours here): longer asks for max_frames or a higher speed.
MAX_FRAMES = 108_000


class FrameRows:
    """The rows of a result shown at `fps` frames per second of wall time, `speed` x real time, as a lazy
    sequence (len, [k], iteration): frame k shows the first row at or after time[0] + k * speed / fps, the rows
    frame_indices lists, without an array of every frame. max_frames: keep only the first ones.
    ValueError as frame_indices."""

    def __init__(self, time, fps: float, speed: float = 1.0, max_frames: int | None = None):
        self.time = np.asarray(time, dtype=float)
        if self.time.size == 0:
            raise ValueError("the result has no rows")
        if not (np.isfinite(fps) and np.isfinite(speed)) or fps <= 0 or speed <= 0:
            raise ValueError("fps and speed must be positive")
        if not np.all(np.isfinite(self.time)) or np.any(np.diff(self.time) < 0):
            raise ValueError("the result's time must be finite and non-decreasing")
        self.step = speed / fps
        # As np.arange(time[0], time[-1] + 1e-12, step) counts them.
        self.n = max(1, int(np.ceil((self.time[-1] + 1e-12 - self.time[0]) / self.step)))
        if max_frames is not None:
            self.n = min(self.n, int(max_frames))

    def __len__(self) -> int:
        return self.n

    def __getitem__(self, k):
        if isinstance(k, slice):
            return [self[j] for j in range(*k.indices(self.n))]
        k = int(k)
        if k < 0:
            k += self.n
        if not 0 <= k < self.n:
            raise IndexError(f"frame {k} of {self.n}")
        r = int(np.searchsorted(self.time, self.time[0] + k * self.step, side="left"))
        return min(r, self.time.size - 1)

    def __iter__(self):
        return (self[k] for k in range(self.n))


def frame_indices(time: np.ndarray, fps: float, speed: float = 1.0) -> np.ndarray:
    """Rows of a result shown at `fps` frames per second of wall time, `speed` x real time."""
    time = np.asarray(time, dtype=float)
    if time.size == 0:
        raise ValueError("the result has no rows")
    if fps <= 0 or speed <= 0:
        raise ValueError("fps and speed must be positive")
    t = np.arange(time[0], time[-1] + 1e-12, speed / fps)
    return np.clip(np.searchsorted(time, t, side="left"), 0, time.size - 1)


class StreamingGifWriter:
    """A matplotlib movie writer (setup / grab_frame / finish, or `saving`) that encodes each frame
    into the .gif as soon as it is grabbed: one frame (and the previous one, to find what changed) in
    memory at a time. Each frame is the rectangle that changed, with its own 256-colour palette
    (Pillow's median-cut quantiser); the file loops forever."""

    def __init__(self, fps: float = 30):
        self.fps = fps
        self.frames = 0
        self._fp = None
        self._prev = None  # the last frame (RGB), to write only what changed

    def setup(self, fig, outfile, dpi=None) -> None:
        self.fig, self.dpi = fig, dpi if dpi is not None else fig.dpi
        self._fp = open(outfile, "wb")
        self.frames = 0
        self._prev = None

    def grab_frame(self, **savefig_kwargs) -> None:
        from PIL import GifImagePlugin, Image
        self.fig.set_dpi(self.dpi)
        self.fig.canvas.draw()
        rgb = np.asarray(self.fig.canvas.buffer_rgba())[..., :3]
        duration_ms = 1000.0 / self.fps
        # After the first frame only the rectangle that changed is written (kept in place by disposal
        # 1, "do not dispose"), as Pillow's own multi-frame writer does: the arm moves, the axes do not.
        x0 = y0 = 0
        region = rgb
        if self._prev is not None and self._prev.shape == rgb.shape:
            changed = np.any(rgb != self._prev, axis=2)
            rows, cols = np.flatnonzero(changed.any(axis=1)), np.flatnonzero(changed.any(axis=0))
            if rows.size == 0:
                rows, cols = np.array([0]), np.array([0])  # nothing moved: a 1-pixel frame keeps the timing
            y0, x0 = int(rows[0]), int(cols[0])
            region = rgb[y0:rows[-1] + 1, x0:cols[-1] + 1]
        self._prev = rgb.copy()
        im = Image.fromarray(np.ascontiguousarray(region)).quantize(colors=256, method=Image.Quantize.MEDIANCUT)
        if self.frames == 0:
            header, _ = GifImagePlugin.getheader(im, None, {"loop": 0, "duration": duration_ms})
            self._fp.write(b"".join(header))
        for chunk in GifImagePlugin.getdata(im, offset=(x0, y0), duration=duration_ms, disposal=1,
                                            include_color_table=True):
            self._fp.write(chunk)
        self._fp.flush()
        self.frames += 1

    def finish(self) -> None:
        if self._fp is not None:
            self._fp.write(b";")  # GIF trailer
            self._fp.close()
            self._fp = None

    def saving(self, fig, outfile, dpi):
        from contextlib import contextmanager

        @contextmanager
        def ctx():
            self.setup(fig, outfile, dpi)
            try:
                yield self
            finally:
                self.finish()
        return ctx()


def check_output(out) -> Path:
    """`out` if its format can be written here; ValueError/RuntimeError saying why not (before any work)."""
    out = Path(out)
    suffix = out.suffix.lower()
    if suffix == ".mp4":
        import matplotlib
        if shutil.which(matplotlib.rcParams["animation.ffmpeg_path"]) is None:
            raise RuntimeError("writing .mp4 needs ffmpeg (Debian: apt-get install ffmpeg); use a .gif instead")
    elif suffix != ".gif":
        raise ValueError(f"output must end in .gif or .mp4, got {out.name!r}")
    return out


def build_figure(result, rows: np.ndarray, dpi: int = 80, lines_of_action: bool = True):
    """The animation's figure for the rows `rows` of a result (anything with time, q, gh_stab,
    activation, element_names and model): returns (fig, draw, views), draw(k) drawing frame k
    (row rows[k]) and views the [(axes, projection of thorax-frame points)] of the two arm views.
    Also used by armrt.gym's render()."""
    import matplotlib.pyplot as plt

    geom = ArmGeometry(result.model or "das2")
    # rows: an array or a lazy FrameRows. Each frame's geometry is computed when it is drawn; the axes' extent
    # from the rows the frames span, in chunks, so memory does not grow with the number of frames.
    r_first, r_last = int(rows[0]), int(rows[len(rows) - 1])
    static = geom.static()
    ix = {n: i for i, n in enumerate(POINTS)}
    info = geom.info
    muscles = [(m, np.array(e)) for m, e in info["muscles"]]
    same_elements = list(result.element_names) == [e["name"] for e in info["elements"]]

    fig = plt.figure(figsize=(10, 6.4), dpi=dpi)
    gs = fig.add_gridspec(2, 3, height_ratios=[3, 1], width_ratios=[1, 1, 0.8])
    ax_front, ax_side = fig.add_subplot(gs[0, 0]), fig.add_subplot(gs[0, 1])
    ax_act, ax_stab = fig.add_subplot(gs[:, 2]), fig.add_subplot(gs[1, :2])
    # Views: front (from anterior: the subject's right, +x, on the viewer's left) and right side
    # (anterior, -z, to the right). Thorax frame: x lateral, y up, z posterior.
    views = [(ax_front, lambda p: (-p[..., 0], p[..., 1]), "front (thorax x to the left)"),
             (ax_side, lambda p: (-p[..., 2], p[..., 1]), "right side (anterior to the right)")]
    lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
    for p in static.values():
        lo, hi = np.minimum(lo, p.min(axis=0)), np.maximum(hi, p.max(axis=0))
    lo_r, hi_r = min(r_first, r_last), max(r_first, r_last)
    for c0 in range(lo_r, hi_r + 1, 1000):
        q = result.q[c0:min(c0 + 1000, hi_r + 1)]
        for p in [geom.points_series(q)] + list(geom.girdle_series(q).values()):
            p = p.reshape(-1, 3)
            lo, hi = np.minimum(lo, p.min(axis=0)), np.maximum(hi, p.max(axis=0))
    corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
    artists = []
    for ax, proj, title in views:
        h, v = proj(corners)
        pad = 0.05
        ax.set_xlim(h.min() - pad, h.max() + pad)
        ax.set_ylim(v.min() - pad, v.max() + pad)
        ax.set_aspect("equal")
        ax.set_title(title, fontsize=9)
        ax.tick_params(labelsize=7)
        for name, poly in static.items():
            ax.plot(*proj(poly), color="0.75" if name.startswith("thorax") else "0.55",
                    lw=1.0 if name.startswith("thorax") else 1.5)
        moving = {name: ax.plot([], [], **GIRDLE_STYLE[name])[0] for name in geom.girdle(result.q[r_first])}
        bones = {name: ax.plot([], [], color=BONE_COLOURS[name], lw=5, solid_capstyle="round")[0]
                 for name, _, _ in SEGMENTS}
        head = ax.plot([], [], "o", ms=9, color="tab:green")[0]
        loa = ax.plot([], [], color="tab:red", lw=0.6, alpha=0.8)[0] if lines_of_action else None
        artists.append((proj, bones, head, loa, moving))

    ax_stab.plot(result.time, result.gh_stab, color="0.3", lw=1)
    ax_stab.axhline(1.0, color="tab:red", ls="--", lw=0.8)
    ax_stab.set_ylabel("GHstab", fontsize=8)
    ax_stab.set_xlabel("time (s)", fontsize=8)
    ax_stab.tick_params(labelsize=7)
    cursor = ax_stab.axvline(result.time[0], color="tab:blue")
    stab_text = ax_stab.text(0.01, 0.85, "", transform=ax_stab.transAxes, fontsize=9)

    names = [m for m, _ in muscles] if same_elements else ["all elements"]
    bars = ax_act.barh(np.arange(len(names)), np.zeros(len(names)), color="tab:red")
    ax_act.set_yticks(np.arange(len(names)), names, fontsize=7)
    ax_act.invert_yaxis()
    ax_act.set_xlim(0, 1)
    ax_act.set_title("activation (mean of elements)", fontsize=9)
    ax_act.tick_params(axis="x", labelsize=7)
    title = fig.suptitle("", fontsize=10)
    fig.tight_layout()

    def draw(k: int):
        r = int(rows[k])
        p = geom.points(result.q[r])
        girdle = geom.girdle(result.q[r])
        stab = float(result.gh_stab[r])
        colour = "tab:red" if stab > 1 else "tab:green"
        loa_xyz = None
        if lines_of_action:
            seg, idx = geom.gh_lines_of_action(result.q[r])
            active = np.nan_to_num(np.asarray(result.activation[r])[idx]) > 0.02
            seg = seg[active]
            loa_xyz = np.concatenate([np.concatenate([s, np.full((1, 3), np.nan)]) for s in seg]) if len(seg) else None
        for proj, bones, head, loa, moving in artists:
            for name, a, b in SEGMENTS:
                bones[name].set_data(*proj(np.array([p[ix[a]], p[ix[b]]])))
            for name, line in moving.items():
                line.set_data(*proj(girdle[name]))
            head.set_data(*proj(p[ix["gh"]][None]))
            head.set_color(colour)
            if loa is not None:
                loa.set_data(*(proj(loa_xyz) if loa_xyz is not None else ([], [])))
        cursor.set_xdata([result.time[r]])
        stab_text.set_text("GHstab unknown (kinematics only)" if np.isnan(stab) else
                           f"GHstab {stab:.2f}" + ("  > 1: outside the rim" if stab > 1 else ""))
        stab_text.set_color(colour)
        act = np.asarray(result.activation[r])
        values = [act[e].mean() for _, e in muscles] if same_elements else [act.mean()]
        for b, v in zip(bars, values):
            b.set_width(0.0 if np.isnan(v) else v)
        title.set_text(f"{result.model or 'armrt'}  t = {result.time[r]:.2f} s  "
                       f"q = {np.array2string(np.degrees(result.q[r]), precision=0, separator=', ')} deg")
        return []

    return fig, draw, [(ax, proj) for ax, proj, _ in views]


def animate(result, out, fps: int = 30, speed: float = 1.0, dpi: int = 80, lines_of_action: bool = True,
            max_frames: int | None = None, progress: bool | None = None) -> Path:
    """Renders a Result (or a path to a saved .npz) to `out` (.gif or .mp4). Returns the path.
    progress: a frame counter on stderr (None: only on a terminal). Memory does not grow with the number of frames
    (each is computed, drawn and encoded in turn); ValueError before any work for more than MAX_FRAMES frames
    without max_frames (a long result: raise speed, or give max_frames)."""
    import matplotlib
    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    from matplotlib import animation

    from .arm import Result
    from .progress import bar
    out = check_output(out)
    if not isinstance(result, Result):
        result = Result.load(result)
    if out.suffix.lower() == ".gif":
        writer = StreamingGifWriter(fps=fps)
    else:
        writer = animation.FFMpegWriter(fps=fps, codec="libx264", extra_args=["-pix_fmt", "yuv420p"])

    rows = FrameRows(result.time, fps, speed, max_frames)
    if max_frames is None and len(rows) > MAX_FRAMES:
        raise ValueError(f"{len(rows)} frames ({result.time[-1] - result.time[0]:.6g} s of result at {fps} frames/s, "
                         f"speed {speed}): more than {MAX_FRAMES} (an hour at 30 frames/s); raise the speed or give "
                         "max_frames (--max-frames)")
    fig, draw, _ = build_figure(result, rows, dpi, lines_of_action)
    out.parent.mkdir(parents=True, exist_ok=True)
    try:
        # One draw per frame (FuncAnimation.save draws twice).
        with writer.saving(fig, str(out), dpi), bar(len(rows), f"animate {out.name}", unit="frame",
                                                     enabled=progress, delay=0.0 if progress else 0.5) as pbar:
            for k in range(len(rows)):
                draw(k)
                writer.grab_frame()
                pbar.update(1)
    finally:
        plt.close(fig)
    return out
