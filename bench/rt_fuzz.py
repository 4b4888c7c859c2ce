"""Fuzz / soak run of the real-time runner on loopback (issue 12; bounded in time, loopback only).

Starts armrt-rt at 1 kHz, a legitimate controller (armrt.realtime.UdpClient, group excitations at
200 Hz, reading the 100 Hz state stream) that owns the session, and --senders fuzzing processes, each
on its own socket, sending datagrams drawn from a pool: random bytes, bit flips of valid packets,
valid-looking excitations with the real session id (a local attacker who sniffs it) and sequence
numbers ahead of the controller's, NaN / inf values, version 1 packets, unknown types, lying length
fields, hellos, releases, signed packets with a wrong key; and the controller itself sends junk that
can never be applied (random bytes, NaN, version 1, lying lengths, wrong session ids). Stops after --packets datagrams or
--duration s, whichever first, then prints and writes (--json) the runner's counters and timing and
what the controller saw: every excitation it sent should be applied, in one session.

    python -m bench.rt_fuzz --packets 1000000 --duration 120 [--senders 2] [--key] [--json out.json]
"""
from __future__ import annotations

import argparse
import json
import multiprocessing as mp
import os
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import numpy as np


OWNER_SAFE_KINDS = (0, 3, 4, 6, 10)  # junk the runner can never apply, whatever its seq and session


def fuzz_pool(rng: np.random.Generator, session: int, n: int = 2048, n_elements: int = 102,
              n_groups: int = 9, kinds=tuple(range(11))) -> list[bytes]:
    """n datagrams of the kinds listed in the module docstring (session: the sniffed session id)."""
    from armrt import realtime as rt
    good = rt.encode_packet(rt.EXC_ELEMENTS, 1, np.full(n_elements, 0.02), session=session)
    out = []
    for _ in range(n):
        kind = int(rng.choice(kinds))
        seq = int(rng.integers(0, 2**32))
        if kind == 0:
            data = rng.bytes(int(rng.integers(0, 1500)))
        elif kind == 1:  # bit flips in a valid packet
            b = bytearray(good)
            for _ in range(int(rng.integers(1, 6))):
                b[int(rng.integers(len(b)))] ^= 1 << int(rng.integers(8))
            data = bytes(b)
        elif kind == 2:  # valid with the sniffed session id, numbered ahead: a takeover attempt
            data = rt.encode_packet(rt.EXC_GROUPS, seq, np.full(n_groups, 0.9), session=session)
        elif kind == 3:
            v = np.full(n_elements, 0.02)
            v[int(rng.integers(n_elements))] = rng.choice([np.nan, np.inf, -np.inf])
            data = rt.encode_packet(rt.EXC_ELEMENTS, seq, v, session=session)
        elif kind == 4:
            data = good[:4] + bytes([1, 0]) + good[6:]  # version 1
        elif kind == 5:
            data = rt.encode_packet(int(rng.integers(0, 20)), seq, rng.random(int(rng.integers(0, 200))), session=session)
        elif kind == 6:
            data = good[:12] + int(rng.integers(0, 2**32)).to_bytes(4, "little") + good[16:]  # length lies
        elif kind == 7:
            data = rt.encode_packet(rt.HELLO, seq)
        elif kind == 8:
            data = rt.encode_packet(rt.RELEASE, seq, session=session)  # release someone else's session
        elif kind == 9:
            data = rt.encode_packet(rt.EXC_GROUPS, seq, np.full(n_groups, 0.9), session=session,
                                    key=b"not the lab's key, 16+ bytes")
        else:
            data = rt.encode_packet(rt.EXC_GROUPS, seq, np.full(n_groups, 0.9), session=int(rng.integers(1, 2**32)))
        out.append(data)
    return out


def _sender(port: int, session: int, seed: int, quota: int, t_end: float, sent) -> None:
    rng = np.random.default_rng(seed)
    pool = fuzz_pool(rng, session)
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    addr = ("127.0.0.1", port)
    n = 0
    k = 0
    while n < quota and time.monotonic() < t_end:
        for _ in range(256):
            try:
                s.sendto(pool[k], addr)
            except OSError:
                pass
            k = (k + 1) % len(pool)
        n += 256
        with sent.get_lock():
            sent.value += 256
    s.close()


def _controller(port: int, key, stop: threading.Event, counts: dict, ready: threading.Event) -> None:
    from armrt import realtime as rt
    with rt.UdpClient(port, mapping="groups", key=key) as c:
        counts["session"] = c.join(timeout=2.0)
        # A controller with bugs: from the owner's own socket, junk that must be decoded and refused.
        junk = fuzz_pool(np.random.default_rng(7), c.session, n=1024, kinds=OWNER_SAFE_KINDS)
        ready.set()
        t_next = time.monotonic()
        k = 0
        while not stop.is_set():
            st = None
            while (nxt := c.recv_state(timeout=0.0)) is not None:
                st = nxt
                counts["states"] += 1
            if st is not None:
                counts["last_el"] = float(st.q[3])
            c.send({"elbow_flexors": 0.05 + 0.05 * np.sin(2 * np.pi * 0.5 * k * 0.005), "rotator_cuff": 0.03})
            counts["sent"] += 1
            for j in range(4):
                c.send_raw(junk[(4 * k + j) % len(junk)])
            counts["owner_junk"] += 4
            if c.session != counts["session"]:
                counts["session_changes"] += 1
                counts["session"] = c.session
            k += 1
            t_next += 0.005
            time.sleep(max(0.0, t_next - time.monotonic()))
        counts["foreign_state"] = c.foreign_packets
        counts["bad_state"] = c.bad_packets


def run(packets: int = 1_000_000, duration: float = 120.0, senders: int = 2, use_key: bool = False,
        extra: list[str] | None = None, timeout_s: float = 0.1) -> dict:
    """Runs the fuzz; returns {"runner": the runner's statistics, "controller": ..., "fuzz": ...}.

    timeout_s is the runner's --timeout: 0.1 s (the bench's default) asks the controller thread to send every
    5 ms through the flood; a test on a loaded 2-core machine gives it longer so that the senders' CPU
    starving a Python thread is not mistaken for the runner taking the arm away."""
    from armrt import realtime as rt
    exe = rt.runner_path()
    with tempfile.TemporaryDirectory() as tmp:
        out_json = Path(tmp) / "stats.json"
        args = [exe, "--listen", "127.0.0.1:0", "--state-rate", "100", "--timeout", str(timeout_s), "--json", str(out_json),
                *(extra or [])]
        key = None
        if use_key:
            key = os.urandom(32).hex().encode()
            (Path(tmp) / "key").write_bytes(key + b"\n")
            args += ["--key-file", str(Path(tmp) / "key")]
        p = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        port = None
        while port is None:
            line = p.stdout.readline()
            if not line:
                raise RuntimeError(f"armrt-rt did not start: {p.stderr.read()}")
            if "listening on udp port" in line:
                port = int(line.split()[-1])
        stop, ready = threading.Event(), threading.Event()
        counts = {"sent": 0, "states": 0, "session": 0, "session_changes": 0, "last_el": 0.0, "owner_junk": 0}
        th = threading.Thread(target=_controller, args=(port, key, stop, counts, ready), daemon=True)
        th.start()
        if not ready.wait(5.0):
            p.kill()
            raise RuntimeError("the controller got no session")
        ctx = mp.get_context("spawn")  # no fork of a process with threads
        sent = ctx.Value("q", 0)
        t0 = time.monotonic()
        t_end = t0 + duration
        procs = [ctx.Process(target=_sender, args=(port, counts["session"], 1000 + i, -(-packets // senders), t_end, sent))
                 for i in range(senders)]
        for q in procs:
            q.start()
        for q in procs:
            q.join()
        fuzz_time = time.monotonic() - t0
        time.sleep(0.3)  # the controller keeps going alone for a moment
        stop.set()
        th.join(timeout=5)
        p.send_signal(signal.SIGINT)
        out, err = p.communicate(timeout=30)
        stats = json.loads(out_json.read_text())
    return {"runner": stats, "controller": counts,
            "fuzz": {"datagrams": int(sent.value), "seconds": fuzz_time, "senders": senders, "key": use_key},
            "returncode": p.returncode, "stderr": err}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m bench.rt_fuzz", description=__doc__.split("\n\n")[0])
    ap.add_argument("--packets", type=int, default=1_000_000)
    ap.add_argument("--duration", type=float, default=120.0, help="upper bound, s")
    ap.add_argument("--senders", type=int, default=2)
    ap.add_argument("--key", action="store_true", help="run the runner and the controller with a shared key")
    ap.add_argument("--json", default=None)
    a = ap.parse_args(argv)
    r = run(a.packets, a.duration, a.senders, a.key)
    st, c, f = r["runner"], r["controller"], r["fuzz"]
    k = st["packets"]
    print(f"fuzz: {f['datagrams']} datagrams from {f['senders']} processes in {f['seconds']:.1f} s "
          f"({f['datagrams'] / f['seconds']:.0f}/s), key {f['key']}")
    print(f"runner: received {k['received']}, applied {k['applied']}, dropped {k['dropped']} (foreign {k['foreign']}, "
          f"bad_magic {k['bad_magic']}, bad_version {k['bad_version']}, bad_size {k['bad_size']}, bad_session "
          f"{k['bad_session']}, bad_auth {k['bad_auth']}), sessions {k['sessions']}, owner changes "
          f"{k['owner_changes']}, timeouts {k['timeouts']}, rx budget hits {k['rx_budget_hits']}")
    print(f"controller: sent {c['sent']}, applied {k['applied']} ({100 * k['applied'] / max(1, c['sent']):.2f} %), "
          f"states {c['states']}, session changes {c['session_changes']}, junk from its own socket {c['owner_junk']} "
          f"(non_finite {k['non_finite']}), elbow {np.degrees(c['last_el']):.1f} deg")
    print(f"timing: {st['cycles']} cycles in {st['elapsed_s']:.1f} s, overruns {st['overruns']}, lag {st['lag_s']:.3f} s, "
          f"{st['scheduler']}; cycle p99 {st['cycle_ns']['p99'] / 1e3:.1f} us, max {st['cycle_ns']['max'] / 1e3:.1f} us; "
          f"latency p99 {st['latency_ns']['p99'] / 1e3:.1f} us, max {st['latency_ns']['max'] / 1e3:.1f} us")
    print(f"runner exit status {r['returncode']}")
    if a.json:
        Path(a.json).write_text(json.dumps(r, indent=2))
    return 0 if r["returncode"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
