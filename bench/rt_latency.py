"""Real-time runner latency measurement (issue 5; not a test).

Runs armrt-rt at 1 kHz with its default integrator (--integrator to choose) for --duration s (default 60) twice, with SCHED_FIFO (+ mlockall) and
with normal scheduling (--no-rt), while a UDP controller sends group excitations at 100 Hz and reads
the 100 Hz state stream (the patient-in-the-loop I/O is part of each cycle). Writes the runner's
statistics (TET, cycle time and wake-up latency: min, median, p99, p99.9, max in ns; overruns) to
bench/results/rt_latency.json and prints a markdown table.

    python -m bench.rt_latency [--duration 60] [--cpu 1] [--busy-wait 0] [--json bench/results/rt_latency.json]
    python -m bench.rt_latency --model das3 --json bench/results/rt_latency_das3.json   # the 11-DOF girdle model
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
import threading
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def controller(port: int, stop: threading.Event, counts: dict, model: str = "das2") -> None:
    from armrt import realtime as rt
    with rt.UdpClient(port, mapping="groups", model=model) as c:
        c.join()
        t_next = time.monotonic()
        k = 0
        while not stop.is_set():
            u = {"rotator_cuff": 0.03, "elbow_flexors": 0.05 + 0.05 * np.sin(2 * np.pi * 0.5 * k * 0.01)}
            c.send(u)
            while c.recv_state(timeout=0.0) is not None:
                counts["states"] += 1
            counts["sent"] += 1
            k += 1
            t_next += 0.01
            time.sleep(max(0.0, t_next - time.monotonic()))


def run_once(exe: str, duration: float, extra: list[str], out_json: Path, model: str = "das2") -> dict:
    args = [exe, "--rate", "1000", "--listen", "127.0.0.1:0", "--state-rate", "100",
            "--timeout", "0.2", "--duration", str(duration), "--json", str(out_json), "--model", model, *extra]
    p = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    port = None
    while port is None:
        line = p.stdout.readline()
        if not line:
            raise RuntimeError(f"armrt-rt did not start: {p.stderr.read()}")
        if "listening on udp port" in line:
            port = int(line.split()[-1])
    stop = threading.Event()
    counts = {"sent": 0, "states": 0}
    th = threading.Thread(target=controller, args=(port, stop, counts, model), daemon=True)
    th.start()
    try:
        out, err = p.communicate(timeout=duration + 60)
    except subprocess.TimeoutExpired:
        p.send_signal(signal.SIGINT)
        out, err = p.communicate(timeout=30)
    stop.set()
    th.join(timeout=5)
    sys.stdout.write(out)
    sys.stderr.write(err)
    st = json.loads(out_json.read_text())
    st["controller"] = counts
    st["command"] = " ".join(args[1:])
    return st


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--duration", type=float, default=60.0)
    ap.add_argument("--cpu", type=int, default=None, help="pin the loop thread (default: none)")
    ap.add_argument("--busy-wait", type=float, default=0.0, help="busy-wait tail in us")
    ap.add_argument("--priority", type=int, default=80)
    ap.add_argument("--integrator", default=None, help="default: the runner's default")
    ap.add_argument("--model", default="das2", help="registered model (das2, das3, ...)")
    ap.add_argument("--json", default=str(ROOT / "bench" / "results" / "rt_latency.json"))
    a = ap.parse_args(argv)
    from armrt import realtime as rt
    exe = rt.runner_path()
    common = ["--busy-wait", str(a.busy_wait)] + (["--cpu", str(a.cpu)] if a.cpu is not None else [])
    if a.integrator:
        common += ["--integrator", a.integrator]
    tmp = Path(a.json).with_suffix(".tmp")
    results = {}
    for name, extra in (("sched_fifo", ["--priority", str(a.priority)]), ("sched_other", ["--no-rt", "--no-mlock"])):
        print(f"== {name}: {a.model}, {a.duration:.0f} s at 1 kHz, integrator {a.integrator or 'default'}", flush=True)
        results[name] = run_once(exe, a.duration, common + extra, tmp, a.model)
    tmp.unlink(missing_ok=True)
    doc = {
        "what": "armrt-rt at 1 kHz (integrator and dt: runs.*.integrator / dt), UDP controller at 100 Hz (group "
                "excitations) and 100 Hz state stream on loopback; all times ns",
        "model": a.model,
        "duration_s": a.duration,
        "machine": {"host": socket.gethostname(), "cpus": os.cpu_count(), "kernel": platform.release(),
                    "processor": platform.processor() or platform.machine()},
        "date": time.strftime("%Y-%m-%d %H:%M:%S"),
        "runs": results,
    }
    Path(a.json).parent.mkdir(parents=True, exist_ok=True)
    Path(a.json).write_text(json.dumps(doc, indent=2) + "\n")
    print(f"\nwrote {a.json}\n")
    print("| run | quantity | min | median | p99 | p99.9 | max | overruns / cycles |")
    print("|---|---|---|---|---|---|---|---|")
    for name, st in results.items():
        for q in ("tet_ns", "cycle_ns", "latency_ns"):
            p = st[q]
            print(f"| {name} | {q[:-3]} (us) | {p['min']/1e3:.1f} | {p['median']/1e3:.1f} | {p['p99']/1e3:.1f} | "
                  f"{p['p999']/1e3:.1f} | {p['max']/1e3:.1f} | {st['overruns']} / {st['cycles']} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
