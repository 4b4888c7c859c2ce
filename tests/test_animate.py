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
