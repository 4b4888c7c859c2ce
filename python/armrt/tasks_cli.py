"""`armrt task centre-out|fitts|posture`: args -> a task run offline with the simulated decoder driving a point
cursor, or with --arm MODEL the arm's hand through the endpoint controller; a metrics table on stdout, JSON/CSV
with --out."""
from __future__ import annotations

import argparse
import csv
import json
import math
import os
import signal
import time

from . import tasks

# s the LSL outlets stay open after the task: a recorder pulls the last markers before the outlet goes away (a
# closed outlet's unsent samples are lost; a LabRecorder test lost the final 'success' without it).
LSL_LINGER_S = 1.0

# A runner silent for longer than this (s) is reported: ten periods of its slowest useful state rate (10 Hz).
RUNNER_SILENCE_S = 1.0

TRIAL_COLUMNS = ("trial", "target", "success", "time_to_target_s", "acquisition_time_s", "dial_in_time_s",
                 "path_efficiency", "n_entries", "gh_unstable_events", "hold_rms_m")


def add_cli(sub, formatter) -> None:
    p = sub.add_parser("task", formatter_class=formatter,
                       help="run a target task offline (simulated decoder, point cursor) and print its metrics")
    p.add_argument("kind", choices=["centre-out", "fitts", "posture"], help="the task")
    p.add_argument("--runner-state", metavar="HOST:PORT", default=None,
                   help="the cursor is the hand of a running armrt-rt sending its state here (armrt-rt --state-to "
                        "HOST:PORT; ':PORT' is loopback): the arm is driven from outside the task, by a lab's "
                        "controller sending excitations or stimulation (UDP or the LSL bridge); the task measures "
                        "it in real time. Not with --arm or --decoder")
    p.add_argument("--runner-model", default="das2", help="with --runner-state: the runner's model")
    p.add_argument("--runner-wait", type=_seconds, default=5.0, help="with --runner-state: s to wait for its first state")
    p.add_argument("--decoder", default="simulated", type=_decoder_arg, metavar="simulated|lsl:NAME",
                   help="what drives the cursor (simulated: velocity towards the target + noise + lag; lsl:NAME: "
                        "the endpoint velocity/position commands of the LSL stream NAME on this host, channels "
                        "labelled hand_velocity_x.. / hand_position_x.., docs/lsl.md; runs in real time)")
    p.add_argument("--centre", type=float, nargs=3, default=None, metavar=("X", "Y", "Z"),
                   help="task centre, m, thorax frame (default: 0 0 0 for the point cursor; with --arm the hand "
                        "at --q-deg)")
    p.add_argument("--arm", metavar="MODEL", default=None,
                   help="drive this model's hand (e.g. das2) through the endpoint controller instead of a point "
                        "cursor (dt = 1 ms; --dt is ignored)")
    p.add_argument("--q-deg", type=float, nargs="+", default=[30, 60, 10, 60, 80], metavar="DEG",
                   help="with --arm: start posture, deg, one per DOF")
    p.add_argument("--targets", type=int, default=8, help="centre-out: number of targets")
    p.add_argument("--distance", type=float, default=0.1, help="centre-out: target distance from the centre, m")
    p.add_argument("--radius", type=float, default=0.015, help="centre-out/posture: success radius, m")
    p.add_argument("--fitts", nargs="+", default=["0.1:0.02", "0.2:0.02"], metavar="D:W",
                   help="fitts: conditions, distance:width in m")
    p.add_argument("--per-condition", type=int, default=9, help="fitts: targets per condition (odd)")
    p.add_argument("--trials", type=int, default=3, help="posture: number of holds")
    p.add_argument("--repeat", type=_blocks, default=1, metavar="N",
                   help="centre-out/fitts: run the target sequence N times in a row, one block each (a long "
                        "session); the metrics are given per block and over all trials")
    p.add_argument("--dwell", type=float, default=0.3, help="dwell (posture: hold) time, s")
    p.add_argument("--timeout", type=float, default=5.0, help="trial timeout, s")
    p.add_argument("--iti", type=float, default=0.2, help="inter-trial interval, s")
    p.add_argument("--gain", type=float, default=4.0, help="decoder gain, 1/s")
    p.add_argument("--noise-sd", type=float, default=0.01, help="decoder noise SD per axis, m/s")
    p.add_argument("--lag", type=float, default=0.05, help="decoder lag, s")
    p.add_argument("--dt", type=float, default=0.002, help="sample interval, s")
    p.add_argument("--seed", type=int, default=0, help="decoder noise seed")
    p.add_argument("--out", metavar="FILE.json|FILE.csv", type=_out_arg, help="write the metrics (JSON: trials + block; CSV: trials)")
    p.add_argument("--display", action="store_true",
                   help="run in real time with the participant display (chromium --kiosk URL) and the operator page")
    p.add_argument("--display-host", default="127.0.0.1", help="address the display pages are served on")
    p.add_argument("--display-port", type=int, default=8090, help="port of the display pages (0: a free one)")
    p.add_argument("--display-fps", type=_fps, default=60.0, help="states sent to the display per second")
    p.add_argument("--display-wait", type=_seconds, default=60.0,
                   help="with --display: s to wait for the participant page before the task starts (0: start at once)")
    p.add_argument("--hold", type=_seconds, default=2.0, help="with --display: s the last state stays up after the task")
    p.add_argument("--markers", nargs="?", const="armrt_task_markers", default=None, metavar="NAME",
                   help="publish the task events on an LSL marker stream (default name armrt_task_markers, "
                        "source_id armrt-task-markers); runs in real time")
    p.add_argument("--task-stream", nargs="?", const="armrt_task_state", default=None, metavar="NAME",
                   help="publish the task's state each sample on an LSL stream (default name armrt_task_state, "
                        "source_id armrt-task-state: time, cursor, target, target index, inside, GHstab); real time")
    p.add_argument("--lsl-source-id", default=None, metavar="ID",
                   help="with --decoder lsl:NAME: pin the decoder's stream by its source_id (when several share NAME)")
    p.add_argument("--lsl-wait", type=_seconds, default=10.0, help="with --decoder lsl:NAME: s to wait for the stream")
    p.set_defaults(func=cmd_task)


def _seconds(text: str) -> float:
    """A wait or hold in s: a finite number >= 0."""
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number of seconds, got {text!r}") from None
    if not (math.isfinite(v) and v >= 0):
        raise argparse.ArgumentTypeError(f"expected a finite number of seconds >= 0, got {text!r}")
    return v


def _fps(text: str) -> float:
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected states per second, got {text!r}") from None
    if not (math.isfinite(v) and 1.0 <= v <= 1000.0):
        raise argparse.ArgumentTypeError(f"expected 1 to 1000 states per second, got {text!r}")
    return v


def _blocks(text: str) -> int:
    """--repeat: a whole number of blocks >= 1."""
    try:
        v = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number of blocks, got {text!r}") from None
    if v < 1:
        raise argparse.ArgumentTypeError(f"expected a number of blocks >= 1, got {text!r}")
    return v


def _out_arg(text: str) -> str:
    """--out: refused before the task runs (a session's metrics must not be lost at its end)."""
    if not (text.endswith(".csv") or text.endswith(".json")):
        raise argparse.ArgumentTypeError(f"must end in .json or .csv, got {text!r}")
    folder = os.path.dirname(os.path.abspath(text))
    if not os.path.isdir(folder):
        raise argparse.ArgumentTypeError(f"{text!r}: no folder {folder}")
    if not os.access(folder, os.W_OK) or (os.path.exists(text) and not os.access(text, os.W_OK)):
        raise argparse.ArgumentTypeError(f"{text!r}: not writable")
    return text


def _decoder_arg(text: str) -> str:
    if text == "simulated" or (text.startswith("lsl:") and len(text) > 4):
        return text
    import argparse
    raise argparse.ArgumentTypeError(f"--decoder takes 'simulated' or 'lsl:NAME' (an LSL stream name), got {text!r}")


def _conditions(texts):
    out = []
    for s in texts:
        try:
            d, w = (float(x) for x in s.split(":"))
        except ValueError:
            raise ValueError(f"--fitts takes D:W in m (e.g. 0.2:0.02), got {s!r}") from None
        out.append((d, w))
    return out


def _fmt(v):
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, float):
        return "-" if math.isnan(v) else f"{v:.3f}"
    return str(v)


def _make_task(args):
    """The task of the options; --repeat N: the target sequence N times (block k: trials k*n .. (k+1)*n - 1)."""
    repeat = getattr(args, "repeat", 1)
    if args.kind == "centre-out":
        targets = tasks.centre_out_targets(args.centre, args.distance, args.radius, args.targets)
        return tasks.TargetTask(targets * repeat, args.dwell, args.timeout, args.iti)
    if args.kind == "fitts":
        targets = tasks.fitts_targets(args.centre, _conditions(args.fitts), args.per_condition)
        return tasks.TargetTask(targets * repeat, args.dwell, args.timeout, args.iti)
    if repeat != 1:
        raise ValueError("--repeat is for centre-out and fitts: a posture block's length is --trials")
    return tasks.PostureTask(args.centre, args.radius, args.dwell, args.timeout, args.trials, args.iti)


def _block_size(args, task) -> int:
    """Trials per block: the whole target sequence once (--repeat 1: every trial)."""
    return len(task.targets) // getattr(args, "repeat", 1)


def _cmd_task_runner(args) -> int:
    """--runner-state: the task over the hand of a running armrt-rt (task_live.RunnerDriver)."""
    import sys
    from . import task_live
    from .realtime import parse_endpoint
    if args.arm is not None or args.decoder != "simulated":
        raise ValueError("--runner-state measures a runner's arm driven from outside: it takes neither --arm nor "
                         "--decoder (drive the runner with your controller, e.g. through the LSL bridge)")
    host, port = parse_endpoint(args.runner_state)
    driver = task_live.RunnerDriver(host, port, model=args.runner_model, dt_s=args.dt, wait_s=args.runner_wait,
                                    max_silence_s=RUNNER_SILENCE_S)
    stopped = 0
    record = {}
    try:
        if args.centre is None:
            args.centre = driver.cursor().tolist()   # the hand where the runner's arm is now
        try:
            task = _make_task(args)
        except ValueError as exc:
            raise _option_error(exc) from None
        max_time = len(task.targets) * (args.timeout + args.iti) + 1.0
        try:
            _run_live_with(args, task, driver, [driver.shoulder()], max_time, record)
        except task_live.RunnerSilent as exc:
            print(f"armrt task: error: {exc}", file=sys.stderr)
            stopped = 1
        except KeyboardInterrupt:
            stopped = 130
        except _Stopped:
            stopped = 143
    finally:
        driver.close()
    print(f"armrt task {args.kind} --runner-state {args.runner_state}: the {args.runner_model} hand of a running "
          f"armrt-rt, {driver.packets} state packets ({driver.bad_packets} refused), longest gap "
          f"{driver.stale_s * 1e3:.1f} ms, dt {args.dt} s (real time)")
    if driver.bad_packets:
        print(f"armrt task: warning: {driver.bad_packets} datagrams refused: {driver.last_error}", file=sys.stderr)
    record["runner_state"] = {"packets": driver.packets, "refused": driver.bad_packets,
                              "longest_gap_ms": driver.stale_s * 1e3}
    return _finish(args, task, stopped, record)


# What the task functions call their parameters, as the options a user typed (errors name the option).
_OPTION_NAMES = {"radius_m": "--radius", "distance_m": "--distance", "n_targets": "--targets",
                 "n_per_condition": "--per-condition", "dwell_s": "--dwell", "timeout_s": "--timeout",
                 "iti_s": "--iti", "n_trials": "--trials", "gain_per_s": "--gain", "noise_sd": "--noise-sd",
                 "lag_s": "--lag", "dt_s": "--dt"}


def _option_error(exc: ValueError) -> ValueError:
    text = str(exc)
    for name, opt in _OPTION_NAMES.items():
        text = text.replace(name, opt)
    return ValueError(text)


class _Stopped(Exception):
    """SIGTERM during a task, turned into an exception so the finished trials are still reported."""


def _on_sigterm(signum, frame):
    raise _Stopped()


def cmd_task(args) -> int:
    """Runs the task; on Ctrl-C (exit 130) or SIGTERM (143) the trials finished so far are still printed and
    written to --out."""
    import threading
    if threading.current_thread() is not threading.main_thread():   # signals reach the main thread only
        return _cmd_task(args)
    previous = signal.signal(signal.SIGTERM, _on_sigterm)
    try:
        return _cmd_task(args)
    finally:
        signal.signal(signal.SIGTERM, previous)


def _cmd_task(args) -> int:
    if args.runner_state is not None:
        return _cmd_task_runner(args)
    arm = None
    if args.arm is not None:
        import numpy as np
        from .arm import Arm
        from .endpoint_control import start_at_rest
        arm = Arm(args.arm)
        q0 = np.radians(args.q_deg)
        start_at_rest(arm, q0)   # held at q0 from the first step, not falling until the muscles activate
        args.dt = arm.dt
        if args.centre is None:
            args.centre = arm.model.hand_position(q0).tolist()
    if args.centre is None:
        args.centre = [0.0, 0.0, 0.0]
    try:
        task = _make_task(args)
    except ValueError as exc:
        raise _option_error(exc) from None
    start = list(args.centre)
    if args.kind == "posture":  # start away from the held target so there is something to reach
        start[1] += 0.05
    max_time = len(task.targets) * (args.timeout + args.iti) + 1.0
    live = args.display or args.markers is not None or args.task_stream is not None or args.decoder != "simulated"
    decoder = None
    stopped = 0
    record = {}
    try:
        if args.decoder == "simulated":
            try:
                dec = tasks.SimulatedDecoder(args.gain, args.noise_sd, args.lag, args.dt, seed=args.seed)
            except ValueError as exc:
                raise _option_error(exc) from None
            how = f"gain {args.gain} 1/s, noise SD {args.noise_sd} m/s, lag {args.lag} s"
        else:
            from .lsl_bridge import LslEndpointDecoder
            dec = decoder = LslEndpointDecoder(args.decoder[4:], source_id=args.lsl_source_id, wait_s=args.lsl_wait)
            how = (f"LSL stream {decoder.name!r} ({decoder.source_id}): "
                   + " and ".join(k for k, h in zip(("velocity", "position"), decoder.has) if h) + " commands")
        try:
            if not live:
                if arm is None:
                    tasks.run_cursor_task(task, dec, start, max_time_s=max_time)
                else:
                    from .endpoint_control import EndpointController, run_task
                    ctl = EndpointController(arm)  # posture: hold the hand where it starts, against gravity
                    run_task(task, ctl, dec, max_time_s=max_time)
            else:
                _run_live(args, task, arm, dec, start, max_time, record)
        except KeyboardInterrupt:
            stopped = 130
        except _Stopped:
            stopped = 143
    finally:
        if decoder is not None:
            decoder.close()
    what = f"the {args.arm} hand (endpoint controller)" if arm is not None else "a point cursor"
    print(f"armrt task {args.kind} --decoder {args.decoder} driving {what}: {how}, dt {args.dt} s, seed {args.seed}"
          + (" (real time)" if live else ""))
    if decoder is not None:
        _decoder_summary(decoder)
    return _finish(args, task, stopped, record)


def _decoder_summary(decoder) -> None:
    """The LSL decoder's samples taken, refused and its longest silence; a warning when it gave nothing usable."""
    import sys
    print(f"decoder {decoder.name!r}: {decoder.received} samples used, {decoder.refused} refused (NaN or "
          f"infinite), longest silence {decoder.stale_s * 1e3:.0f} ms", flush=True)
    if decoder.received == 0:
        print(f"armrt task: warning: the decoder {decoder.name!r} sent "
              + ("only refused samples" if decoder.refused else "nothing") + ": the cursor did not move by its "
              "commands", file=sys.stderr)


def _finish(args, task, stopped: int, record=None) -> int:
    """The report of a run (stopped: 0, or the exit code of an interrupted one: only its finished trials); record:
    the live run's figures (real_time, display, runner_state), printed and written to a JSON --out."""
    import sys
    if stopped:
        task.trials = [r for r in task.trials if math.isfinite(r.end_time_s)]
        how = {130: "interrupted", 143: "terminated"}.get(stopped, "stopped")
        print(f"armrt task: {how}: the {len(task.trials)} trials finished so far", file=sys.stderr, flush=True)
    _report(args, task, record or {})
    return stopped


def _json_ready(v):
    if isinstance(v, dict):
        return {k: _json_ready(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [_json_ready(x) for x in v]
    if hasattr(v, "tolist") and not isinstance(v, str):
        return _json_ready(v.tolist())
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v


def _report(args, task, record=None) -> None:
    """The metrics table on stdout, and --out (JSON: with the live run's record)."""
    record = record or {}
    rows, block = task.trial_metrics(), task.block_metrics()
    columns, blocks = TRIAL_COLUMNS, None
    if getattr(args, "repeat", 1) > 1:   # a long session: which block each trial is in, and each block's metrics
        n = _block_size(args, task)
        for r in rows:   # target: its place in the sequence (the task itself numbers the repeated list's entries)
            r["block"], r["target"] = r["trial"] // n, r["target"] % n
        columns = ("block",) + TRIAL_COLUMNS
        blocks = [tasks.block_metrics(rows[k:k + n]) for k in range(0, len(rows), n)]
    print("  ".join(columns))
    for r in rows:
        print("  ".join(f"{_fmt(r[c]):>{len(c)}}" for c in columns))
    if blocks is not None:
        print(f"blocks ({_block_size(args, task)} trials each; the last may be unfinished):")
        for k, b in enumerate(blocks):
            print(f"  block {k}: n_trials {b['n_trials']}, success_rate {_fmt(b['success_rate'])}, "
                  f"median_time_to_target_s {_fmt(b['median_time_to_target_s'])}, median_path_efficiency "
                  f"{_fmt(b['median_path_efficiency'])}, median_dial_in_time_s {_fmt(b['median_dial_in_time_s'])}")
        print("all blocks:")
    else:
        print("block:")
    disp = record.get("display")
    for k, v in block.items():
        if k == "fitts":
            for cond, res in v.items():
                print(f"  fitts {cond}: " + ", ".join(f"{a} {_fmt(b)}" for a, b in res.items()))
        else:
            print(f"  {k}: {_fmt(v)}")
    if disp is not None:
        L = disp["latency_ms"]
        figures = ("no state was drawn" if L["p50"] is None else
                   "state -> frame latency p50 {:.1f}, p90 {:.1f}, p99 {:.1f}, max {:.1f} ms (upper bound: includes "
                   "the ack's hop back)".format(L["p50"], L["p90"], L["p99"], L["max"]))
        print(f"display: {disp['published']} states published, {disp['drawn']} drawn by the {disp['page']} page; "
              + figures)
    if args.out:
        if args.out.endswith(".csv"):
            with open(args.out, "w", newline="") as fh:
                w = csv.writer(fh)
                w.writerow(columns)
                for r in rows:
                    w.writerow([r[c] for c in columns])
        elif args.out.endswith(".json"):
            with open(args.out, "w") as fh:   # strict JSON: undefined metrics (NaN) are null
                doc = {"trials": rows, "block": block} | ({"blocks": blocks} if blocks is not None else {}) | record
                json.dump(_json_ready(doc), fh, indent=1, default=str, allow_nan=False)
        else:
            raise ValueError(f"--out must end in .json or .csv, got {args.out!r}")
        print(f"wrote {args.out}")


def _run_live(args, task, arm, dec, start, max_time, record=None) -> dict:
    """The task in real time: the display pages (--display), the marker stream (--markers)."""
    from . import task_live
    if arm is None:
        driver = task_live.CursorDriver(start, dec, args.dt)
        extra = [start]   # the cursor starts on the screen (posture: 5 cm off the held target)
    else:
        from .endpoint_control import EndpointController
        driver = task_live.ArmDriver(EndpointController(arm), dec)
        extra = [driver.shoulder(), driver.cursor()]
    return _run_live_with(args, task, driver, extra, max_time, record)


# s the display's acknowledgements of the last states get to arrive before the latencies are summed up (a page
# answers at its next animation frame: tens of ms on a loaded machine).
ACK_WAIT_S = 0.3


def _run_live_with(args, task, driver, extra, max_time, record=None) -> dict:
    """task paced in real time with driver: the display pages (--display), the LSL outlets (--markers,
    --task-stream); extra: points the display plane must hold besides the targets (the shoulder). record (dict):
    filled with real_time (samples, largest lateness) and, with --display, display (display.ack_summary of the
    participant page), also when the run is stopped by an exception (Ctrl-C, SIGTERM, a silent runner)."""
    record = record if record is not None else {}
    stats = {}
    from . import task_live
    model = args.arm or (args.runner_model if args.runner_state is not None else "cursor")
    server = markers = stream = None
    try:
        if args.task_stream is not None:
            from .lsl_bridge import TaskStateOutlet
            stream = TaskStateOutlet(args.task_stream, "armrt-task-state", 1.0 / driver.dt_s, model)
            print(f"task state: LSL stream {args.task_stream!r} (type TaskState, source_id armrt-task-state)",
                  flush=True)
        if args.markers is not None:
            from .lsl_bridge import MarkerOutlet
            markers = MarkerOutlet(args.markers, "armrt-task-markers", model)
            print(f"markers: LSL stream {args.markers!r} (type Markers, source_id armrt-task-markers)", flush=True)
        if args.display:
            from .display import DisplayServer, fit_plane
            plane = fit_plane(task.targets, centre=args.centre, points=extra)
            server = DisplayServer(plane, host=args.display_host, port=args.display_port, announce=True).start()
            print(f"participant display: chromium --kiosk {server.url}\noperator page: {server.operator_url}",
                  flush=True)
            if args.display_wait > 0:
                print(f"waiting up to {args.display_wait:g} s for the participant page...", flush=True)
                if not server.wait_for_page("participant", args.display_wait):
                    print("no participant page connected: the task starts anyway", flush=True)
        if hasattr(driver, "poll"):   # a runner's state: what queued while the page was awaited is not a gap
            driver.poll()
            driver.stale_s = 0.0
        task_live.run_live(task, driver, display=server, markers=markers, task_stream=stream,
                           fps=args.display_fps, max_time_s=max_time,
                           hold_s=args.hold if server is not None else 0.0, stats=stats)
        if markers is not None or stream is not None:
            time.sleep(LSL_LINGER_S)
    finally:
        if stats:
            record["real_time"] = {"samples": stats["samples"], "dt_s": driver.dt_s,
                                   "largest_lateness_ms": stats["lag_s"] * 1e3, "markers": stats["markers"],
                                   "task_stream_samples": stats["streamed"]}
        if server is not None:
            from .display import ack_summary
            if server.published:
                time.sleep(ACK_WAIT_S)
            record["display"] = ack_summary(list(server.acks), server.published)
            server.stop()
    print(f"real time: {stats['samples']} samples, largest lateness {stats['lag_s'] * 1e3:.1f} ms, "
          f"{stats['published']} display states, {stats['markers']} markers", flush=True)
    return stats
