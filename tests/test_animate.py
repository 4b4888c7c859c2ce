"""Offline animation and saved results (issue 7, part 2), and the view/animate/export subcommands."""
import argparse
import shutil

import numpy as np
import pytest

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
pytest.importorskip("matplotlib", reason="matplotlib is not installed")
from armrt.animate import animate, frame_indices  # noqa: E402


@pytest.fixture(scope="module")
def saved(tmp_path_factory):
    arm = armrt.Arm(model="das2", integrator="rk4", dt=1e-3)
    arm.reset()
    res = arm.simulate(lambda t: {"rotator_cuff": 0.08, "elbow_flexors": 0.5, "deltscap": 0.15},
                       duration=0.5, record_every=5)
    path = tmp_path_factory.mktemp("res") / "run.npz"
    res.save(path)
    return res, path


def test_save_load_round_trip(saved):
    res, path = saved
    back = armrt.Result.load(path)
    for k in armrt.Result.ARRAYS:
        np.testing.assert_array_equal(getattr(back, k), getattr(res, k))
    assert back.element_names == res.element_names and back.model == "das2"


def test_frame_indices():
    t = np.linspace(0, 1, 101)
    ix = frame_indices(t, fps=10)
    assert len(ix) == 11 and ix[0] == 0 and ix[-1] == 100
    assert len(frame_indices(t, fps=10, speed=2)) == 6
    with pytest.raises(ValueError):
        frame_indices(t, fps=0)


def test_gif(saved, tmp_path):
    from PIL import Image
    _, path = saved
    out = animate(path, tmp_path / "arm.gif", fps=10, dpi=40, max_frames=5)
    im = Image.open(out)
    assert im.n_frames == 5
    frames = []
    for k in (0, 4):
        im.seek(k)
        frames.append(np.asarray(im.convert("RGB"), dtype=int))
    assert frames[0].shape[0] > 200
    assert np.abs(frames[0] - frames[1]).sum(axis=2).astype(bool).sum() > 50   # the arm moved


@pytest.mark.skipif(shutil.which("ffmpeg") is None, reason="ffmpeg is not installed (Debian package 'ffmpeg')")
def test_mp4(saved, tmp_path):
    res, _ = saved
    out = animate(res, tmp_path / "arm.mp4", fps=10, dpi=40, max_frames=4)
    assert out.stat().st_size > 1000 and out.read_bytes()[4:8] == b"ftyp"


def test_bad_suffix(saved, tmp_path):
    with pytest.raises(ValueError, match="gif or .mp4"):
        animate(saved[0], tmp_path / "arm.avi")


def test_cli_subcommands(saved, tmp_path, capsys):
    from armrt.view import add_cli
    _, path = saved
    ap = argparse.ArgumentParser(prog="armrt")
    add_cli(ap.add_subparsers(dest="command", required=True))
    args = ap.parse_args(["animate", str(path), "-o", str(tmp_path / "a.gif"), "--fps", "5", "--dpi", "30"])
    assert args.func(args) == 0 and (tmp_path / "a.gif").exists()
    from armrt.geometry import find_model_file
    if find_model_file("das2") is not None:
        args = ap.parse_args(["export", str(path), "--mot", str(tmp_path / "a.mot"), "--sto", str(tmp_path / "a.sto")])
        assert args.func(args) == 0
        assert (tmp_path / "a.mot").read_text().count("endheader") == 1
    args = ap.parse_args(["view", "--result", str(path), "--port", "0", "--duration", "0"])
    assert args.result == str(path) and args.func is not None


def test_gif_frames_go_to_the_file_as_drawn(saved, tmp_path):
    """Issue 11 item 5: each grabbed frame is encoded into the file at once (matplotlib's PillowWriter
    kept every frame until the end: 1.3 GB for 600 frames)."""
    import matplotlib
    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    from PIL import Image

    from armrt.animate import StreamingGifWriter
    fig, ax = plt.subplots(figsize=(2, 1.5), dpi=50)
    writer = StreamingGifWriter(fps=10)
    out = tmp_path / "s.gif"
    sizes, drawn = [], []
    with writer.saving(fig, str(out), 50):
        for k in range(4):
            ax.clear()
            ax.plot([0, 1], [0, k], color="tab:red")
            writer.grab_frame()
            drawn.append(np.asarray(fig.canvas.buffer_rgba())[..., :3].astype(int))
            sizes.append(out.stat().st_size)
    assert all(b > a for a, b in zip(sizes, sizes[1:])), sizes
    assert not hasattr(writer, "_frames")
    im = Image.open(out)
    assert im.n_frames == 4 and im.info["duration"] == 100 and im.info["loop"] == 0
    # Frames after the first hold only what changed; decoded, each is the figure as drawn.
    for k in range(4):
        im.seek(k)
        shown = np.asarray(im.convert("RGB"), dtype=int)
        assert shown.shape == drawn[k].shape
        assert np.abs(shown - drawn[k]).mean() < 2.0, k
    plt.close(fig)


def test_animate_plays_a_mot_motion(saved, tmp_path, capsys):
    from armrt.cli import main
    from armrt.geometry import find_model_file
    from armrt.opensim_io import write_mot
    if find_model_file("das2") is None:
        pytest.skip("models/das2.json not found")
    res, _ = saved
    write_mot(res, tmp_path / "m.mot")
    assert main(["animate", str(tmp_path / "m.mot"), "-o", str(tmp_path / "m.gif"), "--fps", "5", "--dpi", "30"]) == 0
    from PIL import Image
    assert Image.open(tmp_path / "m.gif").n_frames == len(frame_indices(res.time, 5))


def test_frame_rows_are_frame_indices_without_the_array():
    from armrt.animate import FrameRows
    rng = np.random.default_rng(4)
    for _ in range(20):
        t = np.sort(rng.uniform(0, 3, rng.integers(1, 60)))
        fps, speed = float(rng.choice([5, 10, 30])), float(rng.choice([0.5, 1.0, 2.0]))
        rows = FrameRows(t, fps, speed)
        np.testing.assert_array_equal(list(rows), frame_indices(t, fps, speed))
        assert len(FrameRows(t, fps, speed, max_frames=3)) == min(3, len(rows))
    with pytest.raises(ValueError, match="non-decreasing"):
        FrameRows(np.array([0.0, 2.0, 1.0]), 10)


def _stretched(res, factor):
    import copy
    long = copy.copy(res)
    long.time = res.time * factor
    return long


def test_animate_memory_does_not_grow_with_the_video(saved, tmp_path):
    """The measured fault: a 19 KB result file reached 2 GB in 30 s (the geometry of every frame computed before the
    first was drawn). The same result stretched 10^5 times in time: 10^6 frames at 20 frames/s. The animation's
    figure for all of them (FrameRows, drawn lazily) peaks, in tracemalloc, within 2 MB of the figure for 3 frames
    (before: the geometry of the 10^6 frames first, > 144 MB), and draws its last frame; the whole video is refused
    before any work without max_frames, naming the frame count."""
    import tracemalloc

    import matplotlib
    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    from armrt.animate import FrameRows, build_figure
    res, _ = saved
    long = _stretched(res, 1e5)
    peaks = []
    for max_frames in (3, None):
        rows = FrameRows(long.time, 20, 1.0, max_frames)
        tracemalloc.start()
        fig, draw, _ = build_figure(long, rows, dpi=20)
        for k in (0, len(rows) // 2, len(rows) - 1):
            draw(k)
        peaks.append(tracemalloc.get_traced_memory()[1])
        tracemalloc.stop()
        plt.close(fig)
    assert len(FrameRows(long.time, 20)) == 10 ** 6 + 1  # 0 .. 50 000 s every 0.05 s
    assert peaks[1] < peaks[0] + 2e6, peaks
    with pytest.raises(ValueError, match="1000001 frames .* more than"):
        animate(long, tmp_path / "refused.gif", fps=20, dpi=20, progress=False)
    assert not (tmp_path / "refused.gif").exists()
    out = animate(long, tmp_path / "bounded.gif", fps=20, dpi=20, max_frames=3, progress=False)
    from PIL import Image
    assert Image.open(out).n_frames == 3


def test_animate_frames_show_their_rows(saved, tmp_path):
    """Drawn one at a time, frame k still shows row rows[k]: each decoded frame matches the figure drawn for it."""
    import matplotlib
    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    from PIL import Image

    from armrt.animate import FrameRows, build_figure
    res, _ = saved
    out = animate(res, tmp_path / "f.gif", fps=10, dpi=30, max_frames=4, progress=False)
    im = Image.open(out)
    rows = FrameRows(res.time, 10, 1.0, 4)
    fig, draw, _ = build_figure(res, rows, dpi=30)
    for k in range(4):
        draw(k)
        fig.canvas.draw()
        drawn = np.asarray(fig.canvas.buffer_rgba())[..., :3].astype(int)
        im.seek(k)
        shown = np.asarray(im.convert("RGB"), dtype=int)
        assert shown.shape == drawn.shape and np.abs(shown - drawn).mean() < 2.0, k
    plt.close(fig)
