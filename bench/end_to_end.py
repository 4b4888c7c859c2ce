"""End to end, measured (issue 29 item 6; not a test): the patient-in-the-loop chain in separate processes,
centre-out trials for --minutes, then every loss count, latency and task metric of the run.

    armrt-rt --static-optimization (1 kHz, state at 200 Hz) --UDP state--> armrt task centre-out --runner-state
    --task-stream --display (500 Hz task loop; the cursor is the runner's hand) --LSL task state--> python -m
    armrt.simulated_decoder_lsl --LSL hand velocity--> python -m armrt.endpoint_target_controller (200 Hz DLS IK)
    --UDP targets--> armrt-rt;  armrt task --WebSocket--> headless Chromium on the participant page (acks)

Counted: decoder commands pushed vs received by the controller (matched by their LSL timestamps: lost = pushed and
never received), task samples published vs read by the decoder, targets sent vs applied (the runner's
packets.targets_applied and the controller's last_applied_seq). Latencies (p50 / p90 / p99 / max): decoder push ->
controller poll (LSL clock, one machine; includes up to one controller period of polling), target sent -> applied
(the first state packet whose last_applied_seq covers it, received - sent, controller clock: an upper bound, it
includes the state packet's trip back and up to one state period), state published -> participant page frame
(the page's acks, armrt.display.ack_summary: an upper bound, it includes the ack's hop back). The runner's TET,
solve time and overruns (its --json), the task metrics per block (armrt task --repeat), the 1-min load average
before and after. The runner's own defaults are used for the static optimisation's gains (--so-kp, --so-kd: 0, pure
feedforward) unless --so-kp / --so-kd are given, and the decoder's defaults (docs/tasks.md); nothing is tuned.

    python -m bench.end_to_end [--minutes 10] [--distance 0.1] [--so-kp KP --so-kd KD] [--json bench/results/end_to_end.json]
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from bench._local import chromium, free_port

ROOT = Path(__file__).resolve().parents[1]
# das2's start posture, deg (GHy GHz GHyy ELx PSy): the one whose centre-out targets docs/tasks.md and
# tests/test_endpoint_control.py check for reachability.
Q0_DEG = [30, 60, 10, 60, 80]
STATE_RATE_HZ = 200     # runner -> task and controller
CONTROLLER_RATE_HZ = 200
SETTLE_S = 3.0          # s the controller holds the start posture before the task takes the hand as its centre
MIN_TRIAL_S = 0.5       # the shortest a trial can be: the task's default dwell 0.3 s + inter-trial interval 0.2 s


def percentiles_ms(x_s) -> dict:
    """p50 / p90 / p99 / max (ms) of latencies in s; n the count (None for each figure when there are none)."""
    x = np.asarray(x_s, dtype=float) * 1e3
    f = (lambda q: float(np.percentile(x, q))) if len(x) else (lambda q: None)
    return {"n": int(len(x)), "p50": f(50), "p90": f(90), "p99": f(99), "max": f(100)}


def _wait_for(path: Path, text: str, proc, timeout: float, what: str) -> None:
    """Waits until the log file path holds text; SystemExit naming what when proc exits first or timeout passes."""
    t_end = time.monotonic() + timeout
    while time.monotonic() < t_end:
        if path.exists() and text in path.read_text(errors="replace"):
            return
        if proc.poll() is not None:
            raise SystemExit(f"end_to_end: {what} exited (code {proc.returncode}) before '{text}':\n"
                             + path.read_text(errors="replace")[-2000:])
        time.sleep(0.1)
    raise SystemExit(f"end_to_end: no '{text}' from {what} within {timeout:g} s")


def _stop(proc, sig, timeout: float, what: str) -> int:
    if proc.poll() is None:
        proc.send_signal(sig)
    try:
        return proc.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()
        raise SystemExit(f"end_to_end: {what} did not stop within {timeout:g} s of {signal.Signals(sig).name}")


def run(minutes: float, distance: float, tmp: Path, so_kp: float | None = None, so_kd: float | None = None) -> dict:
    """Starts the chain in tmp, runs the task for minutes, stops every process cleanly and returns the figures.
    so_kp, so_kd: the runner's --so-kp / --so-kd (None: not passed, the runner's defaults)."""
    gains = [a for k, v in (("--so-kp", so_kp), ("--so-kd", so_kd)) if v is not None for a in (k, str(v))]
    py = sys.executable
    bindir = Path(py).parent
    P, S, H = free_port(socket.SOCK_DGRAM), free_port(socket.SOCK_DGRAM), free_port()
    uid = f"{os.getpid()}-{int(time.time())}"
    task_stream, dec_stream = f"e2e-task-{uid}", f"e2e-dec-{uid}"
    q0 = ",".join(f"{np.radians(d):.9f}" for d in Q0_DEG)
    env = dict(os.environ, PYTHONUNBUFFERED="1")
    logs = {k: tmp / f"{k}.log" for k in ("runner", "controller", "task", "decoder", "chromium")}
    procs = {}

    def start(name, cmd):
        fh = logs[name].open("w")
        procs[name] = subprocess.Popen(cmd, stdout=fh, stderr=subprocess.STDOUT, env=env)
        fh.close()
        return procs[name]

    # blocks of 8 asked of the task: more than fit in the run even if every trial were the shortest possible; the
    # bench ends the task after `minutes`
    repeat = int(np.ceil(minutes * 60 / (8 * MIN_TRIAL_S))) + 1
    load0 = os.getloadavg()
    t_start = time.time()
    try:
        runner = start("runner", [str(bindir / "armrt-rt"), "--listen", f"127.0.0.1:{P}", "--state-to",
                                  f"127.0.0.1:{S}", "--state-rate", str(STATE_RATE_HZ), "--q0", q0,
                                  "--static-optimization", *gains, "--no-mlock", "--timeout", "1",
                                  "--json", str(tmp / "runner.json"), "--quiet"])
        time.sleep(1.0)
        if runner.poll() is not None:
            raise SystemExit("end_to_end: armrt-rt exited at once:\n" + logs["runner"].read_text())
        ctl = start("controller", [py, "-m", "armrt.endpoint_target_controller", "--decoder", dec_stream,
                                   "--runner", f"127.0.0.1:{P}", "--q0-deg", *map(str, Q0_DEG),
                                   "--rate", str(CONTROLLER_RATE_HZ), "--wait", "180", "--out", str(tmp / "ctl.npz")])
        _wait_for(logs["controller"], "holding the start posture", ctl, 60, "the controller")
        time.sleep(SETTLE_S)
        task = start("task", [str(bindir / "armrt"), "task", "centre-out", "--runner-state", f"127.0.0.1:{S}",
                              "--distance", str(distance), "--repeat", str(repeat), "--task-stream", task_stream,
                              "--display", "--display-port", str(H), "--display-wait", "120", "--hold", "0",
                              "--out", str(tmp / "task.json")])
        dec = start("decoder", [py, "-m", "armrt.simulated_decoder_lsl", "--task-stream", task_stream, "--name",
                                dec_stream, "--source-id", dec_stream, "--wait", "120", "--out", str(tmp / "dec.npz")])
        _wait_for(logs["decoder"], "decoder: task stream", dec, 120, "the decoder")
        _wait_for(logs["controller"], "controller: decoder", ctl, 120, "the controller")
        _wait_for(logs["task"], "participant display:", task, 120, "the task")
        with tempfile.TemporaryDirectory() as profile:
            start("chromium", [chromium("end_to_end"), "--headless=new", "--no-sandbox", "--use-angle=swiftshader",
                               "--enable-unsafe-swiftshader", "--no-first-run", "--disable-extensions",
                               "--window-size=1280,800", f"--user-data-dir={profile}", f"http://127.0.0.1:{H}/"])
            _wait_for(logs["task"], "a participant page connected", task, 120, "the task")
            t0 = time.monotonic()
            while time.monotonic() - t0 < minutes * 60:
                for name, p in procs.items():
                    if p.poll() is not None:
                        raise SystemExit(f"end_to_end: {name} exited during the run (code {p.returncode}):\n"
                                         + logs[name].read_text(errors="replace")[-2000:])
                time.sleep(0.5)
            task_wall_s = time.monotonic() - t0
            task_rc = _stop(task, signal.SIGTERM, 60, "the task")   # 143: ended by the bench, trials reported
            time.sleep(1.0)                                        # the decoder's last commands reach the controller
            _stop(dec, signal.SIGTERM, 30, "the decoder")
            time.sleep(1.0)
            _stop(ctl, signal.SIGTERM, 30, "the controller")
            _stop(procs["chromium"], signal.SIGTERM, 30, "chromium")
        runner_rc = _stop(runner, signal.SIGINT, 30, "the runner")
    finally:
        for p in procs.values():
            if p.poll() is None:
                p.kill()
                p.wait()
    load1 = os.getloadavg()
    d, c = np.load(tmp / "dec.npz"), np.load(tmp / "ctl.npz")
    rs = json.loads((tmp / "runner.json").read_text())
    tk = json.loads((tmp / "task.json").read_text())
    pushed, received = d["sent_stamps"], c["received_stamps"]
    sent = c["sent"].reshape(-1, 2)
    so = rs.get("static_optimization") or {}
    blocks = tk.get("blocks", [])
    complete = [b for b in blocks if b["n_trials"] == 8]
    return {
        "minutes": minutes, "task_wall_s": task_wall_s, "distance_m": distance, "q0_deg": Q0_DEG,
        "state_rate_hz": STATE_RATE_HZ, "controller_rate_hz": CONTROLLER_RATE_HZ,
        "exit_codes": {"task": task_rc, "runner": runner_rc},
        "commands": {"decoder_pushed": int(len(pushed)), "controller_received": int(len(received)),
                     "lost": int(len(np.setdiff1d(pushed, received))),
                     "received_not_pushed": int(len(np.setdiff1d(received, pushed)))},
        "task_samples": {"published": (tk.get("real_time") or {}).get("task_stream_samples"),
                         "read_by_decoder": int(d["task_samples"]) if "task_samples" in d else None},
        "targets": {"sent": int(len(sent)), "runner_targets_applied": rs["packets"].get("targets_applied"),
                    "last_sent_seq": int(sent[-1, 0]) if len(sent) else None,
                    "controller_last_applied_seq": int(c["last_applied_seq"]),
                    "never_seen_applied": int(len(sent) - len(c["applied_latency_s"]))},
        "latency_ms": {
            "task_state_to_decoder": percentiles_ms(d["task_latency_s"]),
            "decoder_to_controller": percentiles_ms(c["decoder_latency_s"]),
            "target_sent_to_applied_upper_bound": percentiles_ms(c["applied_latency_s"]),
            "state_to_display_frame_upper_bound": tk.get("display"),
        },
        "runner": {"tet_ns": rs.get("tet_ns"), "cycle_ns": rs.get("cycle_ns"), "overruns": rs.get("overruns"),
                   "cycles": rs.get("cycles"), "missed_deadlines": rs.get("missed_deadlines"),
                   "wakeup_latency_ns": rs.get("latency_ns"), "scheduler": rs.get("scheduler"), "priority": rs.get("priority"),
                   "rt_note": rs.get("rt_note"), "stop_reason": rs.get("stop_reason"), "solve_ns": so.get("solve_ns"), "solves": so.get("solves"),
                   "infeasible": so.get("infeasible"), "not_converged": so.get("not_converged"),
                   "so_kp": so.get("kp"), "so_kd": so.get("kd"), "packets": rs.get("packets")},
        "task": {"all": tk.get("block"), "blocks": blocks, "complete_blocks": len(complete),
                 "runner_state": tk.get("runner_state"), "real_time": tk.get("real_time"),
                 "trials": tk.get("trials")},
        "load_avg_before": list(load0), "load_avg_after": list(load1), "cpus": os.cpu_count(),
        "machine": platform.node(), "started_utc": time.strftime("%Y-%m-%d %H:%M:%S", time.gmtime(t_start)),
        "logs": {k: v.read_text(errors="replace")[-3000:] for k, v in logs.items() if v.exists()},
    }


def _f(v, fmt="{:.1f}"):
    return "-" if v is None else fmt.format(v)


def markdown(r: dict, cmd: str) -> str:
    c, tg, L, ru, tk = r["commands"], r["targets"], r["latency_ms"], r["runner"], r["task"]
    disp = L["state_to_display_frame_upper_bound"] or {}
    dl = disp.get("latency_ms", {})

    def row(name, p, note):
        return (f"| {name} | {p.get('n', disp.get('drawn'))} | {_f(p.get('p50'))} | {_f(p.get('p90'))} | "
                f"{_f(p.get('p99'))} | {_f(p.get('max'))} | {note} |")
    tet = ru["tet_ns"] or {}
    sol = ru["solve_ns"] or {}
    lines = [
        f"# End to end, measured (`{cmd}`)", "",
        f"Started {r['started_utc']} UTC on {r['machine']} ({r['cpus']} CPUs shared with other work), "
        f"{r['task_wall_s']:.0f} s of centre-out trials (8 targets at {r['distance_m']:g} m, das2 from q0 = "
        f"{' '.join(map(str, r['q0_deg']))} deg). 1-min load average {r['load_avg_before'][0]:.2f} before, "
        f"{r['load_avg_after'][0]:.2f} after: a loaded machine. The runner's scheduler: {ru['scheduler']} at "
        + (f"priority {ru['priority']}" if ru.get("priority") else "its default priority (80, cpp/rt/rt_config.h)")
        + ", memory not locked (--no-mlock); the Python processes and Chromium at normal priority.",
        "",
        "## Losses", "",
        "| link | sent | received / applied | lost |", "|---|---|---|---|",
        f"| decoder -> controller (LSL commands, by timestamp) | {c['decoder_pushed']} | {c['controller_received']} | "
        f"{c['lost']} |",
        f"| task -> decoder (LSL task state samples) | {r['task_samples']['published']} | "
        f"{r['task_samples']['read_by_decoder']} | "
        f"{(r['task_samples']['published'] or 0) - (r['task_samples']['read_by_decoder'] or 0)} |",
        f"| controller -> runner (UDP targets) | {tg['sent']} | {tg['runner_targets_applied']} (last applied seq "
        f"{tg['controller_last_applied_seq']}, last sent {tg['last_sent_seq']}) | "
        f"{tg['sent'] - (tg['runner_targets_applied'] or 0)} |", "",
        "## Latencies (ms)", "",
        "| path | n | p50 | p90 | p99 | max | clock and what it includes |", "|---|---|---|---|---|---|---|",
        row("task state push -> decoder read", L["task_state_to_decoder"],
            "LSL clock (one machine); the decoder wakes on the first sample in"),
        row("decoder push -> controller poll", L["decoder_to_controller"],
            "LSL clock (one machine); includes up to one 5 ms controller period"),
        row("target sent -> applied (upper bound)", L["target_sent_to_applied_upper_bound"],
            "controller clock: first state packet with last_applied_seq >= seq; includes the state packet's trip "
            "back and up to one 5 ms state period"),
        row("state published -> participant frame (upper bound)", {"n": disp.get("drawn"), **dl},
            f"server clock, page acks; includes the ack's hop back; {disp.get('published')} states published, "
            f"{disp.get('drawn')} drawn, page {_f(disp.get('page_frames_per_s'))} frames/s (headless Chromium, "
            "SwiftShader)"), "",
        "## Runner", "",
        f"TET median {_f(tet.get('median', None) and tet['median'] / 1e3)} us, p99 "
        f"{_f(tet.get('p99', None) and tet['p99'] / 1e3)} us, max {_f(tet.get('max', None) and tet['max'] / 1e3)} us; "
        f"static optimisation solve median {_f(sol.get('median', None) and sol['median'] / 1e3)} us, p99 "
        f"{_f(sol.get('p99', None) and sol['p99'] / 1e3)} us, max {_f(sol.get('max', None) and sol['max'] / 1e3)} us "
        f"({ru['solves']} solves, {ru['infeasible']} infeasible); overruns {ru['overruns']} of {ru['cycles']} "
        f"cycles; gains so_kp {ru['so_kp']}, so_kd {ru['so_kd']}"
        + (" (the runner's defaults)." if "--so-k" not in cmd else " (given on the command line)."), "",
        "## Task metrics per block", "",
        f"Over all {tk['all']['n_trials']} finished trials: success rate {tk['all']['success_rate']:.3f}, "
        f"median time to target {_f(tk['all']['median_time_to_target_s'], '{:.3f}')} s, median path efficiency "
        f"{_f(tk['all']['median_path_efficiency'], '{:.3f}')}, median dial-in "
        f"{_f(tk['all']['median_dial_in_time_s'], '{:.3f}')} s, GH events {tk['all']['gh_unstable_events']}. Task "
        f"loop: largest lateness {_f((tk['real_time'] or {}).get('largest_lateness_ms'))} ms; runner state longest "
        f"gap {_f((tk['runner_state'] or {}).get('longest_gap_ms'))} ms.", "",
        "| block | trials | success rate | median time to target (s) | median acquisition (s) | median path "
        "efficiency | median dial-in (s) | GH events |", "|---|---|---|---|---|---|---|---|"]
    for k, b in enumerate(tk["blocks"]):
        lines.append(f"| {k} | {b['n_trials']} | {b['success_rate']:.3f} | {_f(b['median_time_to_target_s'], '{:.3f}')}"
                     f" | {_f(b['median_acquisition_time_s'], '{:.3f}')} | {_f(b['median_path_efficiency'], '{:.3f}')}"
                     f" | {_f(b['median_dial_in_time_s'], '{:.3f}')} | {b['gh_unstable_events']} |")
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m bench.end_to_end", description=__doc__.split("\n\n")[0])
    ap.add_argument("--minutes", type=float, default=10.0, help="minutes of centre-out trials")
    ap.add_argument("--distance", type=float, default=0.1, help="target distance from the start hand, m")
    ap.add_argument("--so-kp", type=float, default=None, help="the runner's --so-kp, 1/s^2 (default: not passed)")
    ap.add_argument("--so-kd", type=float, default=None, help="the runner's --so-kd, 1/s (default: not passed)")
    ap.add_argument("--json", default=str(ROOT / "bench" / "results" / "end_to_end.json"))
    ap.add_argument("--render", metavar="JSON", default=None,
                    help="do not run: write the markdown of a finished run's JSON beside it (and print it)")
    a = ap.parse_args(argv)
    if a.render:
        r = json.loads(Path(a.render).read_text())
        md = markdown(r, r["command"])
        Path(a.render).with_suffix(".md").write_text(md)
        print(md)
        return 0
    if not (a.minutes > 0 and a.distance > 0):
        raise SystemExit("end_to_end: --minutes and --distance must be > 0")
    with tempfile.TemporaryDirectory() as tmp:
        r = run(a.minutes, a.distance, Path(tmp), a.so_kp, a.so_kd)
    cmd = f"python -m bench.end_to_end --minutes {a.minutes:g} --distance {a.distance:g}" + "".join(
        f" --{k.replace('_', '-')} {v:g}" for k, v in (("so_kp", a.so_kp), ("so_kd", a.so_kd)) if v is not None) + (
        f" --json {a.json}" if Path(a.json).resolve() != (ROOT / "bench" / "results" / "end_to_end.json") else "")
    r["command"] = cmd
    out = Path(a.json)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(r, indent=1, default=str))
    md = markdown(r, cmd)
    out.with_suffix(".md").write_text(md)
    print(md)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
