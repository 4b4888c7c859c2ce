"""Issue 11, item 8: progress on long work, on a terminal only (tqdm)."""
import io

import pytest

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
pytest.importorskip("tqdm")
from armrt import progress  # noqa: E402


class Terminal(io.StringIO):
    def isatty(self):
        return True


@pytest.fixture
def terminal(monkeypatch):
    """stderr as a terminal. Patched through a property of the test's own body: pytest re-installs
    its capture of sys.stderr between fixture set-up and the test call."""
    import sys
    t = Terminal()
    t.install = lambda: monkeypatch.setattr(sys, "stderr", t)
    return t


def test_simulate_and_step_show_a_bar_on_request(arm, terminal):
    terminal.install()
    arm.simulate(0.0, 0.2, progress=True)
    text = terminal.getvalue()
    assert "simulate:" in text and "/0.2 [" in text
    arm.step(2500, progress=True)
    assert "step:" in terminal.getvalue() and "/2500 [" in terminal.getvalue()
    assert arm.time == pytest.approx(2.7)


def test_no_bar_off_a_terminal_or_when_disabled(arm, capsys, terminal):
    terminal.install()
    arm.simulate(0.0, 0.2, progress=False)
    arm.step(2500, progress=False)
    assert terminal.getvalue() == ""


def test_no_bar_when_not_a_terminal(arm, monkeypatch):
    import sys
    plain = io.StringIO()
    monkeypatch.setattr(sys, "stderr", plain)
    with progress.bar(10, "x", delay=0.0) as b:   # enabled=None: only on a terminal
        b.update(10)
    assert plain.getvalue() == ""


def test_quiet_silences_automatic_bars(terminal):
    terminal.install()
    with progress.quiet():
        with progress.bar(10, "inner", delay=0.0) as b:
            b.update(10)
        assert isinstance(b, progress._Silent)
    with progress.bar(10, "outer", delay=0.0) as b:
        b.update(10)
    assert "outer" in terminal.getvalue() and "inner" not in terminal.getvalue()


def test_experiment_stages_are_announced_when_they_start(capsys):
    from armrt.experiments import Progress
    p = Progress(total=2)                 # pytest's stderr is not a terminal: plain lines
    p.start("CVODE references")
    assert capsys.readouterr().err.startswith("[1/2] CVODE references ...")
    p.tick("dt = 0.1 ms")                 # terminal only
    p.step("CVODE references")
    assert capsys.readouterr().err.startswith("[1/2] CVODE references done")
    p.close()


def test_experiment_bar_names_the_running_stage(terminal):
    terminal.install()
    from armrt.experiments import Progress
    p = Progress(total=3)
    p.start("Fig. 2")
    p.tick("dt = 0.1 ms, fig2")
    p.step("Fig. 2")
    p.close()
    text = terminal.getvalue()
    assert "Fig. 2" in text and "1/3" in text and "dt = 0.1 ms, fig2" in text


def test_animate_counts_frames(terminal, tmp_path, arm):
    pytest.importorskip("matplotlib")
    terminal.install()
    from armrt.animate import animate
    res = arm.simulate(0.0, 0.2, record_every=10)
    animate(res, tmp_path / "a.gif", fps=10, dpi=20, progress=True)
    assert "animate a.gif:" in terminal.getvalue() and "/3 [" in terminal.getvalue()
