"""armrt.tasks: each metric against a scripted cursor with a known answer, events, bad input, and the simulated
decoder's noise SD and lag measured back from its output."""
import math

import numpy as np
import pytest

from armrt import tasks

C = np.array([0.3, -0.1, 0.2])  # any centre: the tasks do not know the arm
U = np.array(tasks.FRONTAL_U)
V = np.array(tasks.FRONTAL_V)
DT = 0.01


def run(task, cursor_fn, t_end, gh_fn=None):
    """Drive task with cursor_fn(t_in_trial, trial) at DT until done or t_end."""
    for i in range(int(round(t_end / DT)) + 1):
        t = i * DT
        rec = task.trials[-1] if task.trials and task.current_target() is not None else None
        tt = t - rec.start_time_s if rec is not None else 0.0
        trial = len(task.trials) - 1 if rec is not None else -1
        task.step(t, cursor_fn(tt, trial), None if gh_fn is None else gh_fn(t))
        if task.done:
            break
    return task


def straight(start, end, speed):
    start, end = np.asarray(start, float), np.asarray(end, float)
    d = np.linalg.norm(end - start)
    return lambda tt: start + (end - start) * min(tt * speed / d, 1.0)


def test_straight_cursor_known_times_and_efficiency_one():
    tg = C + 0.1 * U
    task = tasks.TargetTask([tasks.Target(tg, 0.0105)], dwell_s=0.2, timeout_s=5.0, iti_s=0.0)
    path = straight(C, tg, 0.1)  # 0.1 m/s: within 0.0105 m of the centre first at t = 0.9 s
    run(task, lambda tt, k: path(tt), 10)
    m = task.trial_metrics()[0]
    assert m["success"]
    assert m["time_to_target_s"] == pytest.approx(0.9)
    assert m["acquisition_time_s"] == pytest.approx(0.9)
    assert m["dial_in_time_s"] == pytest.approx(0.0)
    assert m["path_efficiency"] == pytest.approx(1.0, abs=1e-12)
    assert task.trials[0].end_time_s == pytest.approx(1.1)  # entry + dwell
    assert task.block_metrics()["success_rate"] == 1.0


def test_detour_known_efficiency():
    tg = C + 0.1 * U
    # a rectangular detour at 0.1 m/s: up 0.05 m (0.5 s), across 0.1 m (1 s), down towards the target; with a
    # 0.0105 m radius the first sample inside is 0.01 m above the target (0.4 s down the third leg):
    # efficiency = |0.1 U + 0.01 V| / (0.05 + 0.1 + 0.04)
    corners = [C, C + 0.05 * V, C + 0.05 * V + 0.1 * U, tg]

    def cursor(tt, k):
        for i, dur in enumerate((0.5, 1.0)):
            if tt <= dur:
                return corners[i] + (corners[i + 1] - corners[i]) * tt / dur
            tt -= dur
        return corners[2] + (tg - corners[2]) * min(tt / 0.5, 1.0)
    task = tasks.TargetTask([tasks.Target(tg, 0.0105)], dwell_s=0.1, timeout_s=5.0, iti_s=0.0)
    run(task, cursor, 10)
    m = task.trial_metrics()[0]
    assert m["time_to_target_s"] == pytest.approx(1.9)
    assert m["path_efficiency"] == pytest.approx(math.hypot(0.1, 0.01) / 0.19, rel=1e-9)


def test_success_rate_with_a_known_timeout():
    targets = tasks.centre_out_targets(C, 0.1, 0.01, n_targets=4)
    task = tasks.TargetTask(targets, dwell_s=0.1, timeout_s=2.0, iti_s=0.2)

    def cursor(tt, k):
        if k < 0 or k == 2:  # trial 2: the cursor stays at the centre -> timeout
            return C
        return straight(C, targets[k].position, 0.2)(tt)
    run(task, cursor, 60)
    rows = task.trial_metrics()
    assert [r["success"] for r in rows] == [True, True, False, True]
    assert task.block_metrics()["success_rate"] == 0.75
    timeout = [e for e in task.events if e.kind == "timeout"]
    assert len(timeout) == 1 and timeout[0].trial == 2
    assert timeout[0].time_s - task.trials[2].start_time_s == pytest.approx(2.0)
    assert math.isnan(rows[2]["time_to_target_s"]) and math.isnan(rows[2]["path_efficiency"])


def test_dial_in_time_enter_leave_reenter():
    tg = C + 0.1 * U
    # inside at [1.0, 1.05), outside until 1.5, then inside for good: dial-in = 1.5 - 1.0
    def cursor(tt, k):
        if tt < 1.0:
            return C
        if tt < 1.05 or tt >= 1.5:
            return tg
        return C
    task = tasks.TargetTask([tasks.Target(tg, 0.01)], dwell_s=0.3, timeout_s=5.0, iti_s=0.0)
    run(task, cursor, 10)
    m = task.trial_metrics()[0]
    assert m["n_entries"] == 2
    assert m["time_to_target_s"] == pytest.approx(1.0)
    assert m["dial_in_time_s"] == pytest.approx(0.5)
    assert m["acquisition_time_s"] == pytest.approx(1.5)
    kinds = [e.kind for e in task.events]
    assert kinds == ["trial_start", "target_shown", "target_entered", "target_left", "target_entered", "success"]


def test_fitts_throughput_hand_computed():
    starts = np.zeros((3, 3))
    targets = np.tile([0.1, 0.0, 0.0], (3, 1))
    ends = np.array([[0.09, 0.01, 0], [0.10, -0.02, 0], [0.11, 0.0, 0]])  # off-axis parts do not count
    r = tasks.fitts_throughput(starts, ends, targets, [1.0, 1.2, 1.4])
    # dx = -0.01, 0, 0.01: SD (n-1) = 0.01; We = 4.133 * 0.01; De = 0.1; MT = 1.2
    assert r["We_m"] == pytest.approx(0.04133, rel=1e-4)
    assert r["De_m"] == pytest.approx(0.1)
    assert r["IDe_bits"] == pytest.approx(math.log2(0.1 / 0.04133 + 1), rel=1e-4)
    assert r["TP_bits_per_s"] == pytest.approx(math.log2(0.1 / 0.04133 + 1) / 1.2, rel=1e-4)
    with pytest.raises(ValueError, match="at least 2"):
        tasks.fitts_throughput(starts[:1], ends[:1], targets[:1], [1.0])


def test_fitts_task_block_throughput_matches_direct_formula():
    D, W = 0.2, 0.04
    targets = tasks.fitts_targets(C, [(D, W)], n_per_condition=5)
    # successive targets opposite-ish; the cursor jumps to each target with a known overshoot along the axis
    over = [0.004, -0.006, 0.0, 0.008, -0.002]
    task = tasks.TargetTask(targets, dwell_s=0.1, timeout_s=5.0, iti_s=0.0)
    prev = [C - 0.5 * D * U]  # between trials the cursor returns here (opposite target 0)

    def cursor(tt, k):
        if k < 0:
            return prev[0]
        s = task.trials[k].cursor_m[0] if task.trials[k].cursor_m else prev[0]
        g = targets[k].position
        u = (g - s) / np.linalg.norm(g - s)
        return s if tt < 0.5 + 0.1 * k else g + over[k] * u
    run(task, cursor, 60)
    rows = task.trial_metrics()
    assert all(r["success"] for r in rows)
    b = task.block_metrics()
    direct = tasks.fitts_throughput([r["start_m"] for r in rows], [r["endpoint_m"] for r in rows],
                                    [t.position for t in targets], [r["acquisition_time_s"] for r in rows])
    assert [r["acquisition_time_s"] for r in rows] == pytest.approx([0.5 + 0.1 * k for k in range(5)], abs=1.01 * DT)
    assert b["fitts_TP_bits_per_s"] == pytest.approx(direct["TP_bits_per_s"], rel=1e-9)
    assert direct["We_m"] == pytest.approx(4.133 * np.std(over, ddof=1), rel=1e-3)


def test_fitts_targets_layout():
    tg = tasks.fitts_targets(C, [(0.2, 0.02)], n_per_condition=5)
    d01 = np.linalg.norm(tg[1].position - tg[0].position)
    assert d01 == pytest.approx(0.2 * math.sin(2 * math.pi * 3 / 5 / 2) * 1.0, rel=1e-9)  # chord of 3/5 turn
    assert all(t.radius_m == 0.01 and t.condition == (0.2, 0.02) for t in tg)
    for t in tg:
        assert np.linalg.norm(t.position - C) == pytest.approx(0.1)
        assert abs((t.position - C) @ np.array([1.0, 0, 0])) < 1e-12  # in the frontal plane


def test_centre_out_layout():
    tg = tasks.centre_out_targets(C, 0.1, 0.02)
    assert len(tg) == 8
    assert np.allclose(tg[0].position, C + 0.1 * U) and np.allclose(tg[2].position, C + 0.1 * V)


def test_posture_hold_rms_and_gh_events():
    P = C + 0.05 * V
    off = 0.003 * U
    seen = []
    task = tasks.PostureTask(P, 0.01, hold_s=0.5, timeout_s=3.0, n_trials=1, iti_s=0.0, on_event=seen.append)
    # GH stability lost twice during the hold: 2 events
    gh = lambda t: not (0.1 <= t < 0.2 or 0.3 <= t < 0.35)
    run(task, lambda tt, k: P + off, 10, gh_fn=gh)
    m = task.trial_metrics()[0]
    assert m["success"] and m["hold_rms_m"] == pytest.approx(0.003)
    assert m["gh_unstable_events"] == 2 and task.block_metrics()["gh_unstable_events"] == 2
    assert seen == task.events
    ev = [e for e in seen if e.kind == "success"][0]
    assert ev.marker() == "success trial=0 target=0"


def test_bad_input_refused():
    tg = [tasks.Target(C, 0.01)]
    with pytest.raises(ValueError, match="shorter than timeout"):
        tasks.TargetTask(tg, dwell_s=2.0, timeout_s=1.0)
    with pytest.raises(ValueError, match="at least one target"):
        tasks.TargetTask([])
    with pytest.raises(TypeError, match="Target"):
        tasks.TargetTask([C])
    with pytest.raises(TypeError, match="callable"):
        tasks.TargetTask(tg, on_event=3)
    task = tasks.TargetTask(tg)
    with pytest.raises(ValueError, match="shape"):
        task.step(0.0, [0.0, 0.0])
    with pytest.raises(ValueError, match="finite"):
        task.step(0.0, [np.nan, 0.0, 0.0])
    task.step(1.0, C)
    with pytest.raises(ValueError, match="decrease"):
        task.step(0.5, C)
    with pytest.raises(ValueError, match="odd"):
        tasks.fitts_targets(C, [(0.2, 0.02)], n_per_condition=4)
    with pytest.raises(ValueError, match="smaller than the distance"):
        tasks.fitts_targets(C, [(0.02, 0.2)])
    with pytest.raises(ValueError, match="orthogonal"):
        tasks.centre_out_targets(C, 0.1, 0.01, axis_u=(1, 0, 0), axis_v=(1, 1, 0))
    with pytest.raises(ValueError, match="noise_sd"):
        tasks.SimulatedDecoder(noise_sd_m_s=-1)


def test_simulated_decoder_noise_sd_and_lag_measured_back():
    dt, lag, sd = 0.001, 0.037, 0.02
    dec = tasks.SimulatedDecoder(gain_per_s=3.0, noise_sd_m_s=sd, lag_s=lag, dt_s=dt, seed=7)
    t = np.arange(20000) * dt
    cursor = C + 0.05 * np.outer(np.sin(2 * np.pi * 0.7 * t), U) + 0.03 * np.outer(np.cos(2 * np.pi * 1.3 * t), V)
    target = C + 0.1 * U
    out = np.array([dec.step(p, target) for p in cursor])
    ideal = np.array([dec.intended(p, target) for p in cursor])
    shifts = range(0, 80)
    mse = [np.mean((out[k:] - ideal[:len(ideal) - k]) ** 2) for k in shifts]
    k = int(np.argmin(mse))
    assert k * dt == pytest.approx(lag, abs=0.5 * dt)
    resid = out[k:] - ideal[:len(ideal) - k]
    assert np.std(resid) == pytest.approx(sd, rel=0.02)  # 60k samples: SD of the SD estimate ~0.3 %
    again = tasks.SimulatedDecoder(gain_per_s=3.0, noise_sd_m_s=sd, lag_s=lag, dt_s=dt, seed=7)
    assert np.array_equal(np.array([again.step(p, target) for p in cursor[:100]]), out[:100])
    other = tasks.SimulatedDecoder(gain_per_s=3.0, noise_sd_m_s=sd, lag_s=lag, dt_s=dt, seed=8)
    assert not np.array_equal(np.array([other.step(p, target) for p in cursor[:100]]), out[:100])


def test_held_cursor_spread_from_decoder_noise_is_the_ar1_answer():
    """docs/tasks.md "What widths the decoder's noise allows": without lag, a point cursor held at a target by the
    decoder is x_k+1 = (1 - g dt) x_k + dt n_k, whose stationary variance per axis is dt sd^2 / (g (2 - g dt))
    (AR(1)); the 50 ms lag makes the spread larger, not smaller."""
    g, sd, dt = 4.0, 0.05, 0.002
    exact = math.sqrt(dt * sd ** 2 / (g * (2 - g * dt)))
    spread = {}
    for lag in (0.0, 0.05):
        dec = tasks.SimulatedDecoder(gain_per_s=g, noise_sd_m_s=sd, lag_s=lag, dt_s=dt, seed=4)
        p, xs = C.copy(), []
        for _ in range(75000):   # 150 s; the first 5 s (20 time constants) dropped
            p = p + dt * dec.step(p, C)
            xs.append(p - C)
        spread[lag] = float(np.std(np.array(xs[2500:])))   # pooled over the 3 axes
    assert spread[0.0] == pytest.approx(exact, rel=0.08)   # ~900 correlation times: SD estimate within ~3 %
    assert spread[0.05] > 1.05 * spread[0.0]


def test_simulated_decoder_closes_a_centre_out_block():
    targets = tasks.centre_out_targets(C, 0.1, 0.015, n_targets=8)
    task = tasks.TargetTask(targets, dwell_s=0.3, timeout_s=5.0, iti_s=0.2)
    dec = tasks.SimulatedDecoder(gain_per_s=4.0, noise_sd_m_s=0.01, lag_s=0.05, dt_s=0.002, seed=1)
    tasks.run_cursor_task(task, dec, C, max_time_s=60)
    b = task.block_metrics()
    assert task.done and b["n_trials"] == 8 and b["success_rate"] == 1.0
    assert 0 < b["mean_path_efficiency"] <= 1.0


def test_cli_task_writes_json_and_csv(tmp_path, capsys):
    import csv
    import json
    from armrt.cli import main
    out = tmp_path / "m.json"
    assert main(["task", "centre-out", "--decoder", "simulated", "--targets", "4", "--out", str(out)]) == 0
    data = json.loads(out.read_text())
    assert len(data["trials"]) == 4 and data["block"]["success_rate"] == 1.0
    assert "success_rate" in capsys.readouterr().out
    out = tmp_path / "m.csv"
    assert main(["task", "posture", "--trials", "2", "--out", str(out)]) == 0
    rows = list(csv.DictReader(out.open()))
    assert len(rows) == 2 and rows[0]["success"] == "True"
    with pytest.raises(SystemExit):   # refused before the task runs, not after it
        main(["task", "fitts", "--fitts", "0.2:0.03", "--per-condition", "3", "--out", str(tmp_path / "x.txt")])
    assert "argument --out: must end in .json or .csv" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main(["task", "centre-out", "--out", str(tmp_path / "no" / "such" / "m.csv")])
    assert "no folder" in capsys.readouterr().err
    assert main(["task", "fitts", "--fitts", "0.2"]) == 2


def test_cli_task_drives_the_arm(tmp_path, capsys):
    pytest.importorskip("proxsuite", reason="proxsuite (pip install proxsuite) is not installed")
    import json
    from armrt.cli import main
    out = tmp_path / "arm.json"
    assert main(["task", "centre-out", "--arm", "das2", "--targets", "2", "--distance", "0.05", "--out",
                 str(out)]) == 0
    assert "das2 hand" in capsys.readouterr().out
    data = json.loads(out.read_text())
    assert len(data["trials"]) == 2 and data["block"]["success_rate"] == 1.0


def test_cli_fitts_drives_the_arm_and_reports_effective_throughput(tmp_path, capsys):
    """armrt task fitts --arm das2 (docs/tasks.md "The Fitts task with the arm"): 3 targets of 20 mm 8 cm apart
    through the simulated decoder and the endpoint controller are acquired without GH events (before velocity
    mode no trial of such a block succeeded), and the block prints and writes the condition's effective-width
    throughput, consistent with its own IDe / MT."""
    pytest.importorskip("proxsuite", reason="proxsuite (pip install proxsuite) is not installed")
    import json
    from armrt.cli import main
    out = tmp_path / "fitts.json"
    assert main(["task", "fitts", "--arm", "das2", "--fitts", "0.08:0.02", "--per-condition", "3",
                 "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "das2 hand" in printed and "fitts D=0.08 W=0.02: We_m" in printed
    block = json.loads(out.read_text())["block"]
    assert block["success_rate"] == 1.0 and block["gh_unstable_events"] == 0
    r = block["fitts"]["D=0.08 W=0.02"]
    assert r["TP_bits_per_s"] == pytest.approx(r["IDe_bits"] / r["MT_s"])
    assert r["IDe_bits"] == pytest.approx(math.log2(r["De_m"] / r["We_m"] + 1))
    assert block["fitts_TP_bits_per_s"] == pytest.approx(r["TP_bits_per_s"])


def test_cli_task_json_is_strict_and_bad_geometry_names_the_option(tmp_path, capsys):
    import json

    from armrt.cli import main
    out = tmp_path / "m.json"
    # A posture hold that cannot succeed (the decoder does not move): undefined metrics are null, not NaN.
    assert main(["task", "posture", "--trials", "1", "--gain", "0", "--noise-sd", "0", "--timeout", "0.5",
                 "--out", str(out)]) == 0
    data = json.loads(out.read_text(), parse_constant=lambda c: pytest.fail(f"{c} in JSON"))
    assert data["trials"][0]["success"] is False and data["trials"][0]["path_efficiency"] is None
    capsys.readouterr()
    assert main(["task", "centre-out", "--radius", "0.2", "--distance", "0.1"]) == 2
    assert "--radius (0.2 m) must be below --distance" in capsys.readouterr().err
    assert main(["task", "centre-out", "--radius", "0.05", "--distance", "0.1", "--targets", "8"]) == 2
    assert "overlap" in capsys.readouterr().err
    for bad in (["--lsl-wait", "nan"], ["--hold", "-1"], ["--display-wait", "inf"], ["--display-fps", "1e-6"]):
        with pytest.raises(SystemExit):
            main(["task", "centre-out", *bad])
        assert "expected" in capsys.readouterr().err


def test_cli_task_interrupted_reports_the_finished_trials(tmp_path, capsys, monkeypatch):
    import csv

    from armrt.cli import main
    calls = {"n": 0}
    step = tasks.SimulatedDecoder.step

    def interrupting(self, cursor, target):
        calls["n"] += 1
        if calls["n"] == 1500:   # 3 s of 2 ms samples: a few centre-out trials done (each ~0.4 s + dwell + iti)
            raise KeyboardInterrupt
        return step(self, cursor, target)
    monkeypatch.setattr(tasks.SimulatedDecoder, "step", interrupting)
    out = tmp_path / "m.csv"
    assert main(["task", "centre-out", "--out", str(out)]) == 130
    captured = capsys.readouterr()
    rows = list(csv.DictReader(out.open()))
    assert 0 < len(rows) < 8 and all(r["success"] == "True" for r in rows)
    assert f"interrupted: the {len(rows)} trials finished so far" in captured.err


def test_cli_task_sigterm_reports_the_finished_trials(tmp_path):
    import csv
    import signal
    import subprocess
    import sys
    out = tmp_path / "m.csv"
    code = "import sys; from armrt.cli import main; raise SystemExit(main(sys.argv[1:]))"
    p = subprocess.Popen([sys.executable, "-c", code, "task", "centre-out", "--display", "--display-port", "0",
                          "--display-wait", "0", "--dwell", "0.3", "--out", str(out)],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        for line in p.stdout:   # the task has started once the display is up
            if "operator page" in line:
                break
        import time
        time.sleep(2.5)
        p.send_signal(signal.SIGTERM)
        stdout, stderr = p.communicate(timeout=30)
    finally:
        p.kill()
    assert p.returncode == 143, stderr
    assert "terminated: the" in stderr
    rows = list(csv.DictReader(out.open()))
    assert 0 < len(rows) < 8


def test_cli_task_repeat_runs_blocks_and_gives_metrics_per_block(tmp_path, capsys):
    """--repeat N: the target sequence N times; each block's metrics are block_metrics of its own trials (computed
    here again from the trial rows), and the overall block is over every trial."""
    import csv
    import json
    from armrt.cli import main
    out = tmp_path / "m.json"
    assert main(["task", "centre-out", "--targets", "4", "--repeat", "3", "--out", str(out)]) == 0
    data = json.loads(out.read_text())
    rows = data["trials"]
    assert len(rows) == 12 and [r["target"] for r in rows] == [0, 1, 2, 3] * 3
    assert [r["block"] for r in rows] == [0] * 4 + [1] * 4 + [2] * 4
    assert len(data["blocks"]) == 3 and data["block"]["n_trials"] == 12
    for k, b in enumerate(data["blocks"]):
        mine = [r for r in rows if r["block"] == k]
        assert b["n_trials"] == 4
        assert b["median_time_to_target_s"] == pytest.approx(np.median([r["time_to_target_s"] for r in mine]))
    text = capsys.readouterr().out
    assert "block 2: n_trials 4" in text and "all blocks:" in text
    csv_out = tmp_path / "m.csv"
    assert main(["task", "centre-out", "--targets", "2", "--repeat", "2", "--out", str(csv_out)]) == 0
    assert [r["block"] for r in csv.DictReader(csv_out.open())] == ["0", "0", "1", "1"]
    capsys.readouterr()
    for bad in ("0", "-2", "1.5", "x"):
        with pytest.raises(SystemExit):
            main(["task", "centre-out", "--repeat", bad])
        assert "--repeat: expected a" in capsys.readouterr().err
    assert main(["task", "posture", "--repeat", "2"]) == 2
    assert "--repeat is for centre-out and fitts" in capsys.readouterr().err
