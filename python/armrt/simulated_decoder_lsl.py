"""The simulated decoder as its own process: a live task's LSL state stream (cursor, target) -> tasks.SimulatedDecoder
-> an LSL endpoint-command stream of hand velocities (lsl_bridge.endpoint_stream_info, velocity channels), one
sample per task-state sample, stamped with the LSL clock at its push (so a receiver counts losses and measures
latency on the same clock on one machine). docs/tasks.md#end-to-end.

    python -m armrt.simulated_decoder_lsl --task-stream armrt_task_state --name dec [--out dec.npz]
"""
from __future__ import annotations

import argparse
import math
import signal
import sys
import time

import numpy as np

from . import lsl_bridge, tasks
from .lsl_bridge import TASK_STATE_CHANNELS

_COL = {name: k for k, (name, _, _) in enumerate(TASK_STATE_CHANNELS)}


def task_sample_to_cursor_target(sample) -> tuple[np.ndarray, np.ndarray | None]:
    """One TaskState sample (TASK_STATE_CHANNELS order) -> (cursor (3,) m, target (3,) m or None between trials)."""
    x = np.asarray(sample, dtype=float)
    if x.shape != (len(TASK_STATE_CHANNELS),):
        raise ValueError(f"a task-state sample has {len(TASK_STATE_CHANNELS)} channels, got shape {x.shape}")
    cursor = x[[_COL["cursor_x"], _COL["cursor_y"], _COL["cursor_z"]]]
    target = x[[_COL["target_x"], _COL["target_y"], _COL["target_z"]]]
    return cursor, (target if np.all(np.isfinite(target)) else None)


class DecoderProcess:
    """Reads the task-state stream named task_stream (waits up to wait_s s: RuntimeError naming it), runs decoder
    (tasks.SimulatedDecoder) on each sample and pushes its velocity (3,) m/s on the endpoint stream `name`
    (source_id). .sent_stamps holds every pushed sample's LSL timestamp (s), .task_samples the samples read and
    .task_latency_s each one's delay from its task-state timestamp to its read (s, LSL clock: one machine)."""

    def __init__(self, decoder, task_stream: str = "armrt_task_state", name: str = "dec",
                 source_id: str = "armrt-simulated-decoder", wait_s: float = 30.0):
        self.pylsl = pylsl = lsl_bridge._pylsl()
        found = pylsl.resolve_byprop("name", task_stream, 1, float(wait_s))
        if not found:
            raise RuntimeError(f"no LSL task-state stream {task_stream!r} after {wait_s:g} s "
                               "(is `armrt task ... --task-stream` running?)")
        self.inlet = pylsl.StreamInlet(found[0], max_buflen=10, recover=True)
        if self.inlet.info(timeout=5.0).channel_count() != len(TASK_STATE_CHANNELS):
            raise ValueError(f"stream {task_stream!r} is not a TaskState stream ({len(TASK_STATE_CHANNELS)} channels)")
        self.inlet.open_stream(timeout=5.0)
        info = lsl_bridge.endpoint_stream_info(pylsl, name, source_id, 1.0 / decoder.dt_s,
                                               labels=lsl_bridge.ENDPOINT_VELOCITY)
        self.outlet = pylsl.StreamOutlet(info)
        self.decoder = decoder
        self.sent_stamps: list[float] = []
        self.task_samples = 0
        self.task_latency_s: list[float] = []

    def step(self, timeout: float = 0.1) -> int:
        """Takes the task samples that arrived (waiting up to timeout s for the first); pushes one command each."""
        # min_samples=1: return as soon as one sample is there. pylsl's default waits until max_samples (1024) are
        # in or the timeout passes (its pull_chunk docstring), which would batch the task state by up to timeout s
        # and delay every command by as much.
        samples, stamps = self.inlet.pull_chunk(timeout=timeout, min_samples=1)
        if samples:
            now = self.pylsl.local_clock()
            self.task_latency_s.extend(now - t for t in stamps)
        for s in samples:
            cursor, target = task_sample_to_cursor_target(s)
            v = self.decoder.step(cursor, target)
            t = self.pylsl.local_clock()
            self.outlet.push_sample([float(a) for a in v], t)
            self.sent_stamps.append(t)
        self.task_samples += len(samples)
        return len(samples)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m armrt.simulated_decoder_lsl", description=__doc__.split("\n\n")[0])
    ap.add_argument("--task-stream", default="armrt_task_state", help="the task's LSL state stream (armrt task --task-stream)")
    ap.add_argument("--name", default="dec", help="name of the endpoint-command stream pushed")
    ap.add_argument("--source-id", default="armrt-simulated-decoder")
    ap.add_argument("--gain", type=float, default=4.0, help="1/s")
    ap.add_argument("--noise-sd", type=float, default=0.01, help="m/s per axis")
    ap.add_argument("--lag", type=float, default=0.05, help="s")
    ap.add_argument("--dt", type=float, default=0.002, help="the task's sample interval, s")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--wait", type=float, default=30.0, help="s to wait for the task stream")
    ap.add_argument("--duration", type=float, default=math.inf, help="s to run (default: until SIGINT/SIGTERM)")
    ap.add_argument("--out", default=None, help="write the pushed samples' LSL timestamps and the task samples' "
                                                "read latencies (.npz: sent_stamps, task_samples, task_latency_s)")
    a = ap.parse_args(argv)
    dec = tasks.SimulatedDecoder(a.gain, a.noise_sd, a.lag, a.dt, seed=a.seed)
    stop = []
    signal.signal(signal.SIGTERM, lambda *_: stop.append(1))
    proc = DecoderProcess(dec, a.task_stream, a.name, a.source_id, a.wait)
    print(f"decoder: task stream {a.task_stream!r} -> endpoint stream {a.name!r} ({a.source_id})", flush=True)
    t_end = time.monotonic() + a.duration
    try:
        while not stop and time.monotonic() < t_end:
            proc.step(0.1)
    except KeyboardInterrupt:
        pass
    if a.out:
        np.savez(a.out, sent_stamps=np.array(proc.sent_stamps), task_samples=proc.task_samples,
                 task_latency_s=np.array(proc.task_latency_s))
    print(f"decoder: {proc.task_samples} task samples read, {len(proc.sent_stamps)} commands pushed", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
