"""Real-time runner and patient-in-the-loop I/O (issues 5 and 12): loopback only, bounded in time."""
from __future__ import annotations

import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time

from pathlib import Path

import numpy as np
import pytest
from lsl_helpers import pylsl_or_skip

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
try:
    from armrt import realtime as rt
    from armrt import _rt  # noqa: F401
except ImportError as e:  # pragma: no cover
    pytest.skip(f"armrt._rt is not built: {e}", allow_module_level=True)


def runner():
    try:
        return rt.runner_path()
    except FileNotFoundError as e:
        pytest.skip(str(e))


def start_runner(*args, timeout=10.0):
    """Starts armrt-rt listening on an ephemeral port; returns (process, port)."""
    p = subprocess.Popen([runner(), "--listen", "127.0.0.1:0", *args], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    t_end = time.monotonic() + timeout
    while time.monotonic() < t_end:
        line = p.stdout.readline()
        if not line:
            break
        if "listening on udp port" in line:
            return p, int(line.split()[-1])
    p.kill()
    out, err = p.communicate()
    raise AssertionError(f"armrt-rt did not start: {out}\n{err}")


def stop_runner(p, sig=signal.SIGINT, timeout=10.0):
    p.send_signal(sig)
    out, err = p.communicate(timeout=timeout)
    return p.returncode, out, err


# ---------------------------------------------------------------------------------------- codec
def test_packet_round_trip_and_rejections():
    v = np.array([0.0, 0.25, 1.0])
    data = rt.encode_packet(rt.EXC_GROUPS, 7, v)
    assert data[:4] == b"ARMR" and len(data) == rt.HEADER_SIZE + 24
    p = rt.decode_packet(data)
    assert (p.type, p.seq, p.flags) == (rt.EXC_GROUPS, 7, 0)
    np.testing.assert_array_equal(p.values, v)
    with pytest.raises(rt.PacketError, match="magic"):
        rt.decode_packet(b"XRMR" + data[4:])
    with pytest.raises(rt.PacketError, match="version"):
        rt.decode_packet(data[:4] + b"\x01\x00" + data[6:])
    with pytest.raises(rt.PacketError, match="size"):
        rt.decode_packet(data[:-1])
    assert rt.encode_packet(1, 2**32 + 5, [0.0])[8:12] == (5).to_bytes(4, "little")  # seq wraps
    assert rt.decode_packet(rt.encode_packet(1, 1, [0.5], session=0xDEADBEEF)).session == 0xDEADBEEF
    # HMAC-SHA256 with a shared key: signed packets verify, unsigned / wrongly signed / altered ones do not.
    key = b"0123456789abcdef-lab"
    signed = rt.encode_packet(rt.EXC_GROUPS, 8, v, session=3, key=key)
    assert len(signed) == len(data) + rt.TAG_SIZE and rt.decode_packet(signed, key).session == 3
    with pytest.raises(rt.PacketError, match="unsigned"):
        rt.decode_packet(data, key)
    with pytest.raises(rt.PacketError, match="HMAC"):
        rt.decode_packet(signed, b"another key, 16+ bytes")
    altered = bytearray(signed)
    altered[rt.HEADER_SIZE] ^= 1
    with pytest.raises(rt.PacketError, match="HMAC"):
        rt.decode_packet(bytes(altered), key)
    with pytest.raises(ValueError, match="16 bytes"):
        rt.encode_packet(1, 1, [0.0], key=b"short")


def test_layout_comes_from_the_cpp_definition():
    from armrt import _rt
    assert rt.HEADER_SIZE == _rt.HEADER_SIZE == rt.HEADER.size
    assert [f[0] for f in rt.HEADER_FIELDS] == ["magic", "version", "type", "seq", "length", "count", "flags", "session"]
    assert rt.STATE_FIELDS[-2:] == ["lag", "overruns"] and rt.STATE_FIXED_VALUES == len(_rt.state_fields("das2"))
    assert rt.VERSION == _rt.VERSION == 3
    assert rt.parse_endpoint("localhost:9") == ("127.0.0.1", 9) == rt.parse_endpoint(":9")
    for bad in ("nohost", "1.2.3.4:70000", "example.org:5", "1.2.3.4:x"):
        with pytest.raises(ValueError):
            rt.parse_endpoint(bad)
    with pytest.raises(ValueError):
        rt.parse_endpoint("127.0.0.1:0", require_port=True)


def test_group_mapping():
    g = rt.GroupMapping.from_model("groups")
    arm = armrt.Arm()
    assert g.names == arm.group_names
    u = g.to_elements({"elbow_flexors": 0.4})
    assert u.shape == (arm.n_elements,)
    np.testing.assert_allclose(u[arm.indices("elbow_flexors")], 0.4)
    assert u.sum() == pytest.approx(0.4 * len(arm.indices("elbow_flexors")))
    c = rt.GroupMapping.from_model("channels", channels=["bicb", "triceps"])
    assert c.values({"triceps": 0.1}).tolist() == [0.0, 0.1]
    with pytest.raises(KeyError):
        rt.GroupMapping.from_model("channels", channels=["nope"])
    with pytest.raises(ValueError, match="needs 9 values"):
        g.values([0.1, 0.2])
    e = rt.GroupMapping.from_model("elements")
    assert e.values({"bicb": 0.3}).sum() == pytest.approx(0.3 * len(arm.indices("bicb")))
    # As Arm.set_excitation refuses them (a new user's trial found them sent): a column, bools.
    with pytest.raises(ValueError, match=r"needs 9 values, shape \(9,\), got shape \(9, 1\)"):
        g.values(np.full((9, 1), 0.1))
    with pytest.raises(TypeError, match=r"excitation\['deltoid'\] must be a number, got the bool True"):
        g.values({"deltoid": True})
    with pytest.raises(TypeError, match="excitation must be numbers, got an array of bools"):
        g.values(np.ones(9, bool))
    with pytest.raises(TypeError, match=r"must be a number, got the bool True"):
        arm.set_excitation({"bicb": True})


# ---------------------------------------------------------------------------------------- session
def test_session_runs_at_rate_and_reports_statistics():
    with rt.RealtimeSession(rate_hz=1000, duration=0.5) as s:
        assert s.wait(timeout=10)
    st = s.stats()
    assert st["cycles"] == 500 and st["stop_reason"] == "duration"
    for key in ("tet_ns", "cycle_ns", "latency_ns"):
        assert st[key]["count"] == 500
        assert 0 <= st[key]["min"] <= st[key]["median"] <= st[key]["p99"] <= st[key]["p999"] <= st[key]["max"]
    assert st["scheduler"] in ("SCHED_FIFO", "SCHED_OTHER")
    if st["scheduler"] == "SCHED_OTHER":
        assert st["rt_note"]  # says why
    assert st["elapsed_s"] == pytest.approx(0.5, abs=0.1)


def test_session_stop_and_normal_scheduling_on_request():
    s = rt.RealtimeSession(rate_hz=500, realtime=False).start()
    time.sleep(0.2)
    assert s.running
    st = s.stop()
    assert not s.running and st["stop_reason"] == "stop"
    assert st["scheduler"] == "SCHED_OTHER" and "not requested" in st["rt_note"]
    assert 60 <= st["cycles"] <= 200


def test_closed_loop_elbow_to_target_through_udp():
    """A Python controller (PD on the elbow angle, elbow flexors) drives the elbow to 70 deg."""
    target = np.radians(70.0)
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, input_timeout=0.2) as s, \
            rt.UdpClient(s.port, mapping="groups") as c:
        c.join()
        c.send({"rotator_cuff": 0.03})
        errors = []
        t_end = time.monotonic() + 3.0
        while time.monotonic() < t_end:
            st = c.latest_state(timeout=0.2)
            assert st is not None, "no state packet from the runner"
            assert not st.diverged
            el, eld = st.q[3], st.qdot[3]
            u = float(np.clip(0.05 + 0.6 * (target - el) - 0.05 * eld, 0.0, 0.3))
            c.send({"elbow_flexors": u, "rotator_cuff": 0.03})
            errors.append(abs(el - target))
        stats = s.stop()
    assert np.degrees(np.mean(errors[-20:])) < 8.0, np.degrees(errors[-20:])
    assert stats["packets"]["applied"] > 100
    assert stats["packets"]["timeouts"] == 0
    assert stats["error"] == ""


def test_silence_falls_to_zero_and_held_before():
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, input_timeout=0.15) as s, \
            rt.UdpClient(s.port, mapping="groups") as c:
        c.join()
        seq = c.send({"elbow_flexors": 0.1})
        st = c.latest_state(timeout=0.5)
        time.sleep(0.05)
        st = c.latest_state(timeout=0.5)
        assert st is not None and not st.timed_out and st.last_applied_seq == seq  # held
        time.sleep(0.3)
        # One last state packet says the session timed out; then nothing more goes to the ex-owner.
        states = []
        while (st := c.recv_state(timeout=0.1)) is not None:
            states.append(st)
        assert states and states[-1].timed_out and not any(x.timed_out for x in states[:-1])
        stats = s.stop()
    assert stats["packets"]["timeouts"] == 1


# ---------------------------------------------------------------------------------------- runner
def _last_state(sub):
    """The last state packet a subscriber socket holds (None if none)."""
    last = None
    sub.settimeout(0.3)
    try:
        while True:
            last = rt.StatePacket.from_packet(rt.decode_packet(sub.recv(65536)))
    except socket.timeout:
        pass
    return last


def _state_after(client, t_min: float, command=None, tries: int = 60):
    """Sends `command` (default: elbow flexors at zero) until a state packet past t_min s arrives; the last state
    received (None if none)."""
    st = None
    for _ in range(tries):
        client.send(command if command is not None else {"elbow_flexors": 0.0})
        st = client.latest_state(timeout=0.2) or st
        if st is not None and st.time > t_min:
            break
    return st


def _assert_streamed_like_offline(st, arm, intact):
    """The streamed state st is the offline `arm`'s stepped to st.time (q and muscle forces to 1e-9) and differs
    from the `intact` arm's: the settings reached the runner and changed what it simulates."""
    n = int(round(st.time / arm.dt))
    arm.step(n)
    intact.step(n)
    np.testing.assert_allclose(st.q, arm.q, atol=1e-9)
    np.testing.assert_allclose(st.muscle_force, arm.outputs()["muscle_force"], rtol=1e-9, atol=1e-9)
    assert np.abs(st.muscle_force - intact.outputs()["muscle_force"]).max() > 1e-6


def test_runner_signals_clean_shutdown_and_json(tmp_path):
    # SIGHUP (terminal / ssh session closed) and SIGQUIT end the run as SIGINT / SIGTERM do: statistics printed
    # and written, exit status 0, and a last state packet flagged stopped (their default actions killed the
    # runner with neither).
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP, signal.SIGQUIT):
        out_json = tmp_path / f"stats_{int(sig)}.json"
        sub = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        sub.bind(("127.0.0.1", 0))
        p, port = start_runner("--json", str(out_json), "--state-rate", "50",
                               "--state-to", f"127.0.0.1:{sub.getsockname()[1]}")
        time.sleep(0.5)
        rc, out, err = stop_runner(p, sig)
        final = _last_state(sub)
        sub.close()
        assert rc == 0, (sig, rc, err)
        st = json.loads(out_json.read_text())
        assert st["stop_reason"] == "signal"
        assert st["cycles"] > 300
        for key in ("min", "median", "p99", "p999", "max"):
            assert key in st["latency_ns"] and key in st["tet_ns"]
        assert "overruns" in st
        assert "p99.9" in out and "overruns" in out and "stopped (signal)" in out
        assert final is not None and final.stopped and not final.diverged, sig


def test_the_last_state_packet_after_a_signal_carries_zero_excitation_and_stimulation(tmp_path):
    """Stopped, the loop no longer lowers anything: the last command goes to zero before the last state packet, so
    that a stimulator driven from the state packets does not hold it (until 2026-12-07 the last packet carried the
    owner's last excitation, 0.5, and stimulation, 200 us / 15 mA / 30 Hz)."""
    m = tmp_path / "flexors.toml"
    m.write_text('[[channels]]\nname = "flexors"\nelements = ["bicl", "brachialis"]\n')
    for sig in (signal.SIGINT, signal.SIGTERM):
        # --timeout 2: the client is silent for 0.1 s below, which the default 0.1 s timeout raced (the session
        # could end first, zeroing the command the test means to see live).
        p, port = start_runner("--state-rate", "100", "--excitations", "--stimulation", str(m), "--timeout", "2")
        try:
            with rt.UdpClient(port, mapping="groups", stimulation=m) as c:
                c.join(timeout=5.0)
                c.send({"deltoid": 0.5})
                c.send_stimulation({"flexors": (200e-6, 0.015, 30.0)})
                time.sleep(0.1)
                live = c.latest_state(timeout=0.5)
                assert live.excitation.max() == 0.5 and live.stimulation[0][1] == 0.015 and not live.stopped
                rc, out, err = stop_runner(p, sig)
                final = c.latest_state(timeout=0.5)
        finally:
            if p.poll() is None:
                p.kill()
        assert rc == 0, err
        assert final is not None and final.stopped, sig
        assert np.all(final.excitation == 0.0) and np.all(final.stimulation == 0.0), (sig, final.excitation.max())


def test_runner_json_write_failure_exits_non_zero(tmp_path):
    # The statistics asked for and lost: exit status 4 with the reason, not 0 (a script would read a stale file).
    for path, reason in ((tmp_path / "absent_dir" / "stats.json", "No such file"), ("/dev/full", "No space")):
        if str(path) == "/dev/full" and not os.path.exists(path):
            continue
        r = subprocess.run([runner(), "--duration", "0.05", "--no-rt", "--no-mlock", "--json", str(path)],
                           capture_output=True, text=True, timeout=20)
        assert r.returncode == 4, (path, r.returncode, r.stderr)
        assert f"could not write the statistics to --json {path}" in r.stderr and reason in r.stderr, r.stderr
        assert "stopped (duration)" in r.stdout  # the printed statistics are still there


def test_runner_quiet_still_prints_the_port():
    p, port = start_runner("--quiet")  # start_runner reads the "listening on udp port" line
    try:
        with rt.UdpClient(port, mapping="groups") as c:
            c.join(timeout=5.0)
            assert c.session != 0
    finally:
        rc, out, err = stop_runner(p)
    assert rc == 0 and "stopped (signal)" in out


def test_runner_fuzzing_with_a_legitimate_controller():
    """Reduced bench/rt_fuzz.py: junk of every kind from two other processes, a controller alongside."""
    from bench.rt_fuzz import run
    # CI failed once with --timeout 0.1: two flooding processes starved the controller thread past it on 2 cores.
    r = run(packets=40000, duration=5.0, senders=2, timeout_s=1.0)
    st, c = r["runner"], r["controller"]
    k = st["packets"]
    assert r["returncode"] == 0, r["stderr"]
    assert r["fuzz"]["datagrams"] >= 1000
    assert k["received"] > 1000 and k["foreign"] > 1000
    # The owner's own junk is decoded and refused for its reason.
    assert c["owner_junk"] > 0 and k["bad_magic"] > 0 and k["bad_version"] > 0 and k["bad_size"] > 0
    assert k["non_finite"] > 0 and k["bad_session"] > 0
    # One session, never taken over, every excitation of the owner applied but those in flight at the end.
    assert k["sessions"] == 1 and k["owner_changes"] == 1 and k["timeouts"] == 0
    assert k["releases"] <= 1  # the controller's own, when it closes
    assert c["session_changes"] == 0
    assert k["applied"] >= 0.95 * c["sent"], (k, c)
    assert k["out_of_order"] == 0 and k["stale"] == 0
    assert st["stop_reason"] == "signal"


def test_fuzz_pool_covers_every_rejection():
    """Every kind of fuzz datagram is refused by the runner for the reason it was built for."""
    from bench.rt_fuzz import fuzz_pool
    pool = fuzz_pool(np.random.default_rng(3), session=0, n=400)
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=0) as s:
        sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        for d in pool:
            sock.sendto(d, ("127.0.0.1", s.port))
            time.sleep(0.0002)
        time.sleep(0.05)
        sock.close()
        st = s.stop()
    k = st["packets"]
    assert k["received"] == len(pool)
    assert k["applied"] == 0 and k["sessions"] == 0
    for name in ("bad_magic", "bad_version", "bad_size", "bad_type", "bad_session", "hellos"):
        assert k[name] > 0, (name, k)


def test_runner_refuses_an_explicit_step_unstable_at_rest_before_starting():
    """One RK4 step per 10 ms cycle is unstable for this model even at rest. The runner used to start, print its
    port, and stop in the first cycle with the engine's 'step too large' (and Python's substeps advice); it now
    refuses the option at start-up (exit 2), naming --integration-step and the stable bound, and sends nothing.
    The divergence path itself (last state packet flagged stopped + error) is cpp/rt/test_rt.cc's."""
    sub = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    sub.bind(("127.0.0.1", 0))
    sub.settimeout(0.5)
    r = subprocess.run([runner(), "--integrator", "rk4", "--rate", "100", "--integration-step", "0.01", "--state-rate",
                        "100", "--timeout", "0.5", "--state-to", f"127.0.0.1:{sub.getsockname()[1]}"],
                       capture_output=True, text=True, timeout=20)
    final = _last_state(sub)
    sub.close()
    assert r.returncode == 2, (r.returncode, r.stderr)
    assert "--integration-step 0.01 s is unstable for integrator 'rk4' even at rest" in r.stderr, r.stderr
    assert "substeps" not in r.stderr and final is None


def test_require_rt_without_privilege_fails_plainly():
    setpriv = shutil.which("setpriv")
    if os.geteuid() != 0 or not setpriv:
        pytest.skip("needs root and setpriv to drop CAP_SYS_NICE")
    drop = [setpriv, "--bounding-set", "-sys_nice,-ipc_lock", "--inh-caps", "-sys_nice,-ipc_lock"]
    r = subprocess.run([*drop, runner(), "--duration", "0.2", "--require-rt"], capture_output=True, text=True, timeout=20)
    assert r.returncode == 3
    assert "SCHED_FIFO" in r.stderr and "Operation not permitted" in r.stderr
    r = subprocess.run([*drop, runner(), "--duration", "0.2"], capture_output=True, text=True, timeout=20)
    assert r.returncode == 0
    assert "running with SCHED_OTHER" in r.stderr
    assert "stopped (duration) after 200 cycles" in r.stdout


def test_runner_rejects_bad_arguments():
    r = subprocess.run([runner(), "--integrator", "cvode"], capture_output=True, text=True, timeout=20)
    assert r.returncode == 2 and "not a real-time integrator" in r.stderr
    r = subprocess.run([runner(), "--channels", "bicb,nonsense", "--duration", "0.1"], capture_output=True, text=True, timeout=20)
    assert r.returncode == 2 and "nonsense" in r.stderr
    cases = [(["--timeout", "inf"], "--timeout"), (["--busy-wait", "nan"], "--busy-wait"),
             (["--integration-step", "nan"], "--integration-step"),
             (["--duration", "0.0004"], "--duration"), (["--rate", "1e5"], "--rate"), (["--integration-step", "0.002"], "fit"),
             (["--dt", "0.001", "--integration-step", "0.001"], "both given"),
             (["--state-rate", "300"], "333.333 and 250"), (["--priority", "80.5"], "--priority"),
             (["--timeout", "60"], "--timeout"), (["--q0", "0,0,nan,0,0"], "--q0"),
             # degrees, and a joint beyond its range: refused as Arm.set_state refuses them (issue 25)
             (["--q0", "25,28,16,40,80"], "look like degrees"), (["--q0", "0,0,0,4,0"], "q[ELx] = 4 rad"),
             (["--stat-rate", "100"], "did you mean --state-rate"), (["--listen", "1.2.3.4"], "HOST:PORT"),
             # the wildcards allow nobody: refused, not a session no controller can own
             (["--listen", "127.0.0.1:0", "--allow", "0.0.0.0"], "--allow: '0.0.0.0' matches no sender"),
             (["--listen", "127.0.0.1:0", "--allow", "::"], "IPv4 only"),
             (["--key-file", "/dev/zero"], "not a regular file")]
    for args, msg in cases:
        r = subprocess.run([runner(), *args, "--duration", "0.05", "--no-rt", "--no-mlock"] if args[0] != "--duration"
                           else [runner(), *args], capture_output=True, text=True, timeout=20)
        assert r.returncode == 2 and msg in r.stderr, (args, r.returncode, r.stderr)


def test_runner_day_long_run_locks_little_memory():
    """--duration 86400 starts at once with fixed-size records (it used to lock ~1 GB at start)."""
    p, port = start_runner("--duration", "86400", "--state-rate", "0")
    try:
        status = open(f"/proc/{p.pid}/status").read()
        rss_kb = int(next(line.split()[1] for line in status.splitlines() if line.startswith("VmRSS:")))
        assert rss_kb < 64 * 1024, status
    finally:
        rc, out, err = stop_runner(p)
    assert rc == 0 and "stopped (signal)" in out


def test_runner_warns_on_non_loopback_without_key(tmp_path):
    r = subprocess.run([runner(), "--listen", "0.0.0.0:0", "--duration", "0.05", "--no-rt", "--no-mlock"],
                       capture_output=True, text=True, timeout=20)
    assert r.returncode == 0 and "without a shared key" in r.stderr
    key = tmp_path / "key"
    key.write_bytes(b"a lab key of enough length\n")
    for mode in (0o644, 0o640):  # readable by others or the group: refused, as ssh refuses such a private key
        key.chmod(mode)
        r = subprocess.run([runner(), "--key-file", str(key), "--duration", "0.05"], capture_output=True, text=True,
                           timeout=20)
        assert r.returncode == 2 and "chmod 600" in r.stderr, r.stderr
        with pytest.raises(ValueError, match="chmod 600"):
            rt.read_key_file(key)  # the Python side reads key files by the same rules
    with pytest.raises(ValueError, match="not a regular file"):
        rt.read_key_file("/dev/zero")
    key.chmod(0o600)
    assert rt.read_key_file(key) == b"a lab key of enough length"
    r = subprocess.run([runner(), "--listen", "0.0.0.0:0", "--duration", "0.05", "--no-rt", "--no-mlock",
                        "--key-file", str(key)], capture_output=True, text=True, timeout=20)
    assert r.returncode == 0 and "without a shared key" not in r.stderr
    key.write_bytes(b"short\n")
    r = subprocess.run([runner(), "--key-file", str(key)], capture_output=True, text=True, timeout=20)
    assert r.returncode == 2 and "16 bytes" in r.stderr


# ---------------------------------------------------------------------------------------- sessions
def _drive(c, u, n, period=0.005):
    if c.session == 0:
        c.join()
    st = None
    for _ in range(n):
        c.send(u)
        st = c.latest_state(timeout=0.05) or st
        time.sleep(period)
    return st


def test_second_process_cannot_take_the_arm_over(tmp_path):
    """The measured fault: 60 packets numbered ahead from another process took the elbow 14 -> 141 deg."""
    out_json = tmp_path / "stats.json"
    p, port = start_runner("--state-rate", "200", "--timeout", "1.0", "--json", str(out_json))
    try:
        with rt.UdpClient(port, mapping="groups") as owner, rt.UdpClient(port, mapping="groups") as intruder:
            st = _drive(owner, {"rotator_cuff": 0.03}, 60)
            el0 = np.degrees(st.q[3])
            # The intruder sniffed the session id and numbers far ahead of the owner.
            with pytest.raises(TimeoutError):
                intruder.join(timeout=0.2)   # no offer while the session is owned
            intruder.session, intruder.seq = owner.session, owner.seq + 1000
            for _ in range(60):
                intruder.send({"elbow_flexors": 1.0})
                time.sleep(0.002)
            st = _drive(owner, {"rotator_cuff": 0.03}, 40)
            # Full elbow flexors would bend it past 100 deg; it hangs near its rest angle instead.
            assert np.degrees(st.q[3]) < 40.0, (el0, np.degrees(st.q[3]))
            assert intruder.recv_state(timeout=0.3) is None     # no state to the intruder
            assert st.last_applied_seq == owner.seq or st.last_applied_seq >= owner.seq - 3
    finally:
        rc, out, err = stop_runner(p)
    assert rc == 0
    k = json.loads(out_json.read_text())["packets"]
    assert k["foreign"] >= 60 and k["out_of_order"] == 0 and k["sessions"] == 1 and k["owner_changes"] == 1


def test_ownership_counters_release_and_no_state_after_timeout():
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, input_timeout=0.1, resume_grace=0.0) as s:
        with rt.UdpClient(s.port, mapping="groups") as a, rt.UdpClient(s.port, mapping="groups") as b:
            _drive(a, {"elbow_flexors": 0.1}, 10)
            b.session, b.seq = a.session, a.seq + 100
            for _ in range(60):
                b.send({"elbow_flexors": 0.9})
            _drive(a, {"elbow_flexors": 0.1}, 10)
            k = s.stats()["packets"]
            assert k["foreign"] >= 60 and k["out_of_order"] == 0 and k["sessions"] == 1
            # Silence: the session ends, state stops going to the ex-owner (no 100 packets/s forever).
            time.sleep(0.3)
            while a.recv_state(timeout=0.0) is not None:
                pass
            assert a.recv_state(timeout=0.3) is None
            assert s.stats()["packets"]["timeouts"] == 1
            # Another controller may own it after the hold (no grace here); release hands it back at once.
            b.join(timeout=s.stats()["session_hold_s"] + 2.0)
            st = _drive(b, {"elbow_flexors": 0.1}, 5)
            assert st is not None and not st.timed_out
            b.release()
            time.sleep(0.05)
            _drive(a, {"elbow_flexors": 0.1}, 5)
        k = s.stop()["packets"]
    assert k["sessions"] == 3 and k["owner_changes"] == 3 and k["releases"] >= 1


@pytest.mark.parametrize("option, value, exc, match", [
    ("rate_hz", True, TypeError, "rate_hz must be a number, got the bool True"),
    ("so_kp", True, TypeError, "so_kp must be a number, got the bool True"),
    ("input_timeout", True, TypeError, "input_timeout must be a number, got the bool True"),
    ("duration", np.bool_(True), TypeError, "duration must be a number, got the bool"),
    ("state_rate_hz", "100", TypeError, "state_rate_hz must be a number, got the string '100'"),
    ("cpu", True, TypeError, "cpu must be an integer, got bool True"),
    ("rate_hz", 10.0, ValueError, r"--timeout defaults to 0.1 s, shorter than two periods at --rate 10 Hz: give "
                                  r"--timeout in \[0.2, 10\] s"),
])
def test_session_options_refuse_bools_and_strings_and_name_the_default_timeout(option, value, exc, match):
    """A new user's trial: RealtimeSession took so_kp=True, input_timeout=True and duration=True as 1, a string gave
    pybind's dump of the whole signature, and rate_hz=10 failed on '--timeout ... got 0.1', an option never given."""
    kw = {"static_optimization": True} if option.startswith("so_") else {}
    with pytest.raises(exc, match=match):
        rt.RealtimeSession(listen="127.0.0.1:0", **kw, **{option: value})
    with pytest.raises(ValueError, match=r"--state-rate defaults to 100 Hz, above --rate 10 Hz: give --state-rate in "
                                         r"\[0, 10\] Hz"):
        rt.RealtimeSession(listen="127.0.0.1:0", rate_hz=10.0, input_timeout=0.5)
    with rt.RealtimeSession(listen="127.0.0.1:0", rate_hz=10.0, input_timeout=0.5, state_rate_hz=10.0, duration=0.2) as s:
        assert s.port > 0


def test_a_released_client_does_not_get_the_arm_back_without_join():
    """A new user's trial: after release(), a state packet sent before the runner read the release restored the old
    session id in the client, send() went out, the runner answered that stale packet with an offer of its new
    session, the client took it, and its next send() claimed the arm: a controller that had handed the arm over
    drove it again. Now only join() takes a session id, so send() raises until join()."""
    from armrt.realtime_packets import EXC_GROUPS, encode_packet
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=1000, input_timeout=2.0) as s, \
            rt.UdpClient(s.port, mapping="groups") as c:
        _drive(c, {"elbow_flexors": 0.5}, 5)
        old = c.session
        c.release()
        # The state packets in flight, and an offer: a packet of the released session (what the client would have
        # sent) makes the runner offer its new id.
        stale = np.zeros(len(c.mapping.names))
        c.send_raw(encode_packet(EXC_GROUPS, c.seq + 1, stale, session=old))
        for _ in range(20):
            c.latest_state(timeout=0.01)
            assert c.session == 0
            with pytest.raises(RuntimeError, match=r"call join\(timeout\) first"):
                c.send({"elbow_flexors": 0.5})
        k = s.stats()["packets"]
        assert k["releases"] == 1 and k["sessions"] == 1 and k["offers"] >= 2   # the offer came, and was not taken
        c.join()                                                                  # the explicit step still works
        assert c.session not in (0, old)
        _drive(c, {"elbow_flexors": 0.2}, 3)
        assert s.stats()["packets"]["sessions"] == 2


def test_one_packet_does_not_bring_the_state_stream_back_for_good():
    """The measured fault: after the safety timeout, one 96-byte packet brought back 100 state packets/s
    indefinitely. Now a packet that claims the session gets state only while its session lasts."""
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=100, input_timeout=0.1) as s, \
            rt.UdpClient(s.port, mapping="groups") as c:
        c.join()
        c.send({"rotator_cuff": 0.03})             # hello, offer, one excitation: a session of one packet
        time.sleep(0.5)
        got = []
        while (st := c.recv_state(timeout=0.0)) is not None:
            got.append(st)
        # At most the timeout's worth (0.1 s at 100 Hz, plus the last one flagged "no session").
        assert 1 <= len(got) <= 13 and got[-1].timed_out, len(got)
        assert c.recv_state(timeout=0.3) is None
        assert s.stats()["packets"]["timeouts"] == 1


def test_captured_packet_is_not_replayed_after_a_timeout():
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, input_timeout=0.1) as s, \
            rt.UdpClient(s.port, mapping="groups") as c:
        _drive(c, {"rotator_cuff": 0.03}, 5)
        captured = rt.encode_packet(rt.EXC_GROUPS, c.seq + 1, c.mapping.values({"elbow_flexors": 1.0}),
                                    session=c.session)
        c.send_raw(captured)                       # applied once, in its session
        time.sleep(0.3)                            # silence: the session ends
        applied = s.stats()["packets"]["applied"]
        for _ in range(20):
            c.send_raw(captured)                   # replayed from the very same source
            time.sleep(0.002)
        time.sleep(0.05)
        k = s.stats()["packets"]
        assert k["applied"] == applied and k["bad_session"] >= 20 and k["timeouts"] == 1
        st = c.latest_state(timeout=0.2)           # it learned the new session id from the offer
        assert st is None or st.timed_out
        c.join()
        _drive(c, {"rotator_cuff": 0.03}, 5)
        assert s.stats()["packets"]["sessions"] == 2


def test_client_rejects_forged_state_and_wrong_key():
    key = b"shared lab key, 32 bytes long!!!"
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, key=key) as s:
        assert s.stats()["authenticated"]
        with rt.UdpClient(s.port, mapping="groups", key=key) as c:
            st = _drive(c, {"rotator_cuff": 0.03}, 5)
            assert st is not None
            # Another process sends a state packet (signed with the right key even) to the client.
            forger = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
            fake = rt.encode_packet(rt.STATE, 1, np.zeros(rt.STATE_FIXED_VALUES), session=c.session, key=key)
            while c.recv_state(timeout=0.0) is not None:
                pass
            s.stop()  # nothing more from the runner
            while c.recv_state(timeout=0.05) is not None:
                pass
            forger.sendto(fake, ("127.0.0.1", c.local_port))
            assert c.recv_state(timeout=0.2) is None and c.foreign_packets == 1
            forger.close()
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, key=key) as s:
        with rt.UdpClient(s.port, mapping="groups", key=b"the wrong key, 16+ bytes") as bad:
            with pytest.raises(TimeoutError):
                bad.join(timeout=0.3)
        with rt.UdpClient(s.port, mapping="groups") as unsigned:
            with pytest.raises(TimeoutError):
                unsigned.join(timeout=0.3)
        k = s.stop()["packets"]
    assert k["bad_auth"] >= 2 and k["sessions"] == 0
    # A keyed client refuses the runner's state if the runner is unkeyed (unsigned state).
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200) as s:
        with rt.UdpClient(s.port, mapping="groups", key=key) as c:
            with pytest.raises(TimeoutError):
                c.join(timeout=0.3)
            assert c.bad_packets >= 1


def test_flood_from_another_process_does_not_starve_the_owner():
    """The measured fault: one process flooding junk cost the controller 77 % of its packets."""
    code = ("import socket,sys,time\n"
            "s=socket.socket(socket.AF_INET,socket.SOCK_DGRAM);a=('127.0.0.1',int(sys.argv[1]));d=b'ARMR'+bytes(900)\n"
            "t=time.monotonic()+float(sys.argv[2])\n"
            "while time.monotonic()<t:\n"
            " for _ in range(500):\n"
            "  try: s.sendto(d,a)\n"
            "  except OSError: pass\n")
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=100, input_timeout=0.2) as s, \
            rt.UdpClient(s.port, mapping="groups") as c:
        c.join()
        flood = subprocess.Popen([sys.executable, "-c", code, str(s.port), "3"])
        try:
            time.sleep(0.2)
            a0, sent = s.stats()["packets"]["applied"], 0
            t_end = time.monotonic() + 2.0
            while time.monotonic() < t_end:
                c.send({"rotator_cuff": 0.03})
                sent += 1
                time.sleep(0.004)
            time.sleep(0.02)
            k = s.stats()["packets"]
        finally:
            flood.kill()
            flood.wait()
    assert k["foreign"] > 10 * sent, k
    assert k["applied"] - a0 >= 0.95 * sent, (k["applied"] - a0, sent)
    assert k["timeouts"] == 0


def _subscriber():
    sub = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    sub.bind(("127.0.0.1", 0))
    sub.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 1 << 22)
    sub.setblocking(False)
    return sub


def _read_states(sub, table) -> list:
    out = []
    while True:
        try:
            p = rt.decode_packet(sub.recv(65536))
        except BlockingIOError:
            return out
        if p.type == rt.STATE:
            out.append(rt.StatePacket.from_packet(p, table))


def _drain(c) -> None:
    while c.poll(0.0):
        pass


def test_stalled_owner_zero_held_then_the_waiting_controller_owns_after_hold_and_grace():
    """The measured fault: a local process waiting for the arm owned it 4 ms after a stalled owner's timeout (the
    zero lasted less than a deactivation time, the elbow never came down), and the old owner was locked out with no
    error. Now: zero for ln(100) deactivation time constants of the slowest element, then the old owner's grace,
    then the waiting one; the old owner is told (SessionEnded)."""
    grace = 0.3
    sub = _subscriber()
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, input_timeout=0.05, send_excitation=True,
                            resume_grace=grace, state_to=f"127.0.0.1:{sub.getsockname()[1]}") as s, \
            rt.UdpClient(s.port, mapping="groups") as a, rt.UdpClient(s.port, mapping="groups") as b:
        st0 = s.stats()
        tdeact = max(e["tdeact"] for e in armrt.Arm("das2").info["elements"])  # das2: deltoid, 83.5 ms
        hold = st0["session_hold_s"]
        assert hold == pytest.approx(np.log(100) * tdeact, abs=1e-3) and st0["resume_grace_s"] == pytest.approx(grace)
        a.join(timeout=5.0)
        for _ in range(40):
            a.send({"elbow_flexors": 1.0})
            time.sleep(0.005)
        # a stalls; b waits for the arm, asking again every 50 ms.
        failed = 0
        while True:
            try:
                b.join(timeout=0.05)
                break
            except TimeoutError:
                failed += 1
                assert failed < 400, "b never got the arm"
            _drain(a)
        b.seq = 10 ** 6  # b's packets recognisable in last_applied_seq
        for _ in range(10):
            b.send({"elbow_flexors": 0.5})
            time.sleep(0.005)
        time.sleep(0.03)
        _drain(a)
        assert a.session == 0 and a.session_end is not None and a.session_end.reason == "timeout"
        assert a.session_end.hold_s == pytest.approx(hold) and a.session_end.grace_s == pytest.approx(grace)
        with pytest.raises(rt.SessionEnded, match="ended this session"):
            a.send({"elbow_flexors": 1.0})
        k = s.stop()["packets"]
        states = _read_states(sub, b.state_table)
    sub.close()
    assert failed >= 5  # b asked during the hold and the grace and was refused
    # (the joins before the timeout were foreign: a still owned the arm)
    assert k["timeouts"] == 1 and k["session_ended"] >= 1 and k["held_off"] >= 5 and k["owner_changes"] == 2
    states.sort(key=lambda x: x.seq)
    i_a = next(i for i, x in enumerate(states) if not x.timed_out)            # a owns the arm
    i_out = next(i for i, x in enumerate(states) if i > i_a and x.timed_out)  # a's session ended
    i_b = next(i for i, x in enumerate(states) if x.last_applied_seq >= 10 ** 6)  # b's first packet applied
    assert states[i_out - 1].excitation.max() > 0.9                         # a's elbow flexors, full
    gap = states[i_b].time - states[i_out].time
    assert gap >= hold + grace - 0.011, (gap, hold, grace)                  # simulated time (cycles)
    for x in states[i_out:i_b]:
        assert x.excitation.max() == 0.0 and x.timed_out, x.time            # zero throughout
    elx = [d["name"] for d in armrt.Arm("das2").info["dofs"]].index("ELx")
    i_hold = next(i for i, x in enumerate(states) if x.time >= states[i_out].time + hold)
    assert states[i_hold].q[elx] < states[i_out].q[elx] - 0.05, (states[i_out].q, states[i_hold].q)  # it came down


def test_timed_out_owner_resumes_first_within_its_grace():
    """The old owner, back within the grace window, gets the arm again although another controller asks all the
    time; a release hands over at once (no hold: the owner's deliberate act)."""
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=100, input_timeout=0.05, resume_grace=5.0) as s, \
            rt.UdpClient(s.port, mapping="groups") as a, rt.UdpClient(s.port, mapping="groups") as b:
        hold = s.stats()["session_hold_s"]
        stop, b_got = threading.Event(), []

        def wait_for_the_arm():
            while not stop.is_set() and not b_got:
                try:
                    b_got.append(b.join(timeout=0.05))
                except TimeoutError:
                    pass

        a.join(timeout=5.0)
        _drive(a, {"elbow_flexors": 0.3}, 10)
        th = threading.Thread(target=wait_for_the_arm, daemon=True)
        th.start()
        t_end = time.monotonic() + 5.0
        while a.session_end is None and time.monotonic() < t_end:  # a stalls: it reads, sends nothing
            a.poll(0.01)
        assert a.session_end is not None
        a.join(timeout=hold + 5.0)  # after the hold, within the grace
        for _ in range(20):
            a.send({"elbow_flexors": 0.3})
            time.sleep(0.005)
        assert not b_got
        k = s.stats()["packets"]
        assert k["sessions"] == 2 and k["owner_changes"] == 1  # a, a again
        a.release()
        th.join(timeout=10.0)
        stop.set()
        assert b_got
        b.send({"elbow_flexors": 0.1})
        time.sleep(0.05)
        k = s.stop()["packets"]
    assert k["sessions"] == 3 and k["owner_changes"] == 2 and k["timeouts"] >= 1 and k["releases"] == 1


def test_hello_flood_from_one_process_does_not_starve_joins():
    """The measured fault: a hello flood from one unprivileged process, no session owned, blocked every join
    (0/10): the runner answered one hello per cycle, the flood's. Offers are now shared between sources (one per
    source per 10 ms, 4 per cycle). The bound: each of 10 joins within its 5 s timeout (generous: a join says
    hello every 50 ms, so 100 chances each), all 10 succeeding."""
    hello = rt.encode_packet(rt.HELLO, 1).hex()
    code = ("import socket,sys,time\n"
            "s=socket.socket(socket.AF_INET,socket.SOCK_DGRAM);a=('127.0.0.1',int(sys.argv[1]));d=bytes.fromhex(sys.argv[3])\n"
            "t=time.monotonic()+float(sys.argv[2])\n"
            "while time.monotonic()<t:\n"
            " for _ in range(500):\n"
            "  try: s.sendto(d,a)\n"
            "  except OSError: pass\n")
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=0, input_timeout=0.2) as s:
        flood = subprocess.Popen([sys.executable, "-c", code, str(s.port), "60", hello])
        try:
            t_end = time.monotonic() + 10.0
            while s.stats()["packets"]["hellos"] < 5000 and time.monotonic() < t_end:
                time.sleep(0.05)
            joined = 0
            for _ in range(10):
                with rt.UdpClient(s.port, mapping="groups") as c:
                    c.join(timeout=5.0)
                    # A controller streams its commands: 30 over about 30 ms stand for that stream here. A single
                    # one was dropped by the kernel for 5 of the 10 clients once in a full CI run on 2 cores
                    # (sessions 5 with kernel_drops > 0, 2026-12-06), the flood filling the shared queue.
                    for _ in range(30):
                        c.send({"rotator_cuff": 0.03})
                        time.sleep(0.001)
                    joined += 1
                    c.release()
            time.sleep(0.35)  # the last release read, or its session timed out (input_timeout 0.2 s) had it been dropped
            k = s.stats()["packets"]
        finally:
            flood.kill()
            flood.wait()
    assert joined == 10
    assert k["hellos"] > 5000 and k["replies_limited"] > 1000, k
    # Each client's stream claimed the arm, unless the flood filled the shared queue and the kernel dropped all of
    # it, which is then counted (nothing lost silently); every session ended by its release or, had the release been
    # dropped, its timeout.
    assert k["sessions"] == 10 or k["kernel_drops"] > 0, k
    assert k["sessions"] >= 8 and k["releases"] + k["timeouts"] == k["sessions"], k


def test_lag_and_overrun_reach_the_state_packets():
    """A period shorter than a step (0.1 ms, 500 substeps): every cycle overruns; skip and report."""
    with rt.RealtimeSession(listen="127.0.0.1:0", rate_hz=10000, integration_step=2e-7, state_rate_hz=10000,
                            input_timeout=10, realtime=False) as s, rt.UdpClient(s.port, mapping="groups") as c:
        c.join()
        c.send({"rotator_cuff": 0.03})
        st = c.recv_state(timeout=2.0)
        time.sleep(0.3)
        st = c.latest_state(timeout=2.0)
        stats = s.stop()
    assert st is not None and st.overrun and st.lag > 0 and st.overruns > 0
    assert stats["overruns"] > 0 and stats["lag_s"] == pytest.approx(stats["missed_deadlines"] * 1e-4)
    assert stats["resync"] == "skip"


# ---------------------------------------------------------------------------------------- LSL


def _exc_outlet(pylsl, name, source_id, labels, rate=100):
    info = pylsl.StreamInfo(name, "Excitation", len(labels), rate, pylsl.cf_double64, source_id)
    chans = info.desc().append_child("channels")
    for lab in labels:
        chans.append_child("channel").append_child_value("label", lab)
    return pylsl.StreamOutlet(info)


def _run_bridge(bridge):
    stop = threading.Event()
    errors = []

    def loop():
        try:
            bridge.run(stop)
        except Exception as e:  # noqa: BLE001 (handed to the test)
            errors.append(e)
    th = threading.Thread(target=loop, daemon=True)
    th.start()
    return stop, th, errors


def test_lsl_bridge_loopback():
    pylsl = pylsl_or_skip()
    from armrt.lsl_bridge import LslBridge, channel_labels, state_channels
    source = f"armrt-test-{os.getpid()}"
    bridge = LslBridge(runner_port=0, mapping="groups", source_id=source, excitation_name=f"exc-{source}",
                       state_rate_hz=200)
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, state_to=f"127.0.0.1:{bridge.state_port}") as s:
        bridge.runner_address = ("127.0.0.1", s.port)
        stop, th, errors = _run_bridge(bridge)
        try:
            # The controller's channels in another order than the mapping's: matched by label.
            labels = list(reversed(bridge.mapping.names))
            outlet = _exc_outlet(pylsl, f"exc-{source}", f"{source}-controller", labels)
            found = pylsl.resolve_byprop("source_id", f"{source}-state", timeout=10)
            assert found, "state stream not found on loopback"
            inlet = pylsl.StreamInlet(found[0])
            full = inlet.info(timeout=5)
            labels_out = channel_labels(full)
            assert labels_out == state_channels("das2")[0] and labels_out[-4:] == ["last_seq", "lag", "overruns", "overrun"]
            assert labels_out[1:6] == ["GHy", "GHz", "GHyy", "ELx", "PSy"]
            u = np.zeros(len(labels))
            u[labels.index("elbow_flexors")] = 0.15
            el0 = None
            t_end = time.monotonic() + 4
            el = None
            while time.monotonic() < t_end and not errors:
                outlet.push_sample(u.tolist())
                samples, _ = inlet.pull_chunk(timeout=0.05)
                if samples:
                    el = samples[-1][labels_out.index("ELx")]
                    if el0 is None:
                        el0 = el
                time.sleep(0.01)
            assert not errors, errors
            assert el0 is not None and el is not None, "no state samples over LSL"
            assert bridge.forwarded > 10, "no excitation samples forwarded from LSL"
            ef = bridge.mapping.names.index("elbow_flexors")
            assert bridge.last_values[ef] == 0.15 and bridge.last_values.sum() == pytest.approx(0.15)
            # Elbow flexors at 0.15 flex the elbow beyond 60 deg; unexcited it hangs near 13 deg.
            assert np.degrees(el) > 60, (np.degrees(el0), np.degrees(el), bridge.forwarded)
            assert [w for w in bridge.warnings if "overran" not in w] == [], bridge.warnings
        finally:
            stop.set()
            th.join(timeout=5)
            bridge.close()
        st = s.stop()
    assert st["packets"]["applied"] > 10 and st["packets"]["sessions"] == 1


def test_lsl_bridge_unknown_labels_are_an_error_naming_them():
    pylsl = pylsl_or_skip()
    from armrt.lsl_bridge import LslBridge
    source = f"armrt-test-lab-{os.getpid()}"
    bridge = LslBridge(runner_port=9, mapping="groups", source_id=source, excitation_source_id=f"{source}-ctl")
    try:
        _outlet = _exc_outlet(pylsl, "anything", f"{source}-ctl", ["elbow_flexors", "bicep_typo"])  # noqa: F841
        t_end = time.monotonic() + 10
        with pytest.raises(ValueError, match="bicep_typo"):
            while time.monotonic() < t_end:
                bridge.step()
    finally:
        bridge.close()


def test_lsl_bridge_pins_the_excitation_stream_by_source_id():
    pylsl = pylsl_or_skip()
    from armrt.lsl_bridge import LslBridge
    source = f"armrt-test-pin-{os.getpid()}"
    bridge = LslBridge(runner_port=0, mapping="groups", source_id=source, excitation_name=f"exc-{source}",
                       excitation_source_id=f"{source}-right")
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=100, state_to=f"127.0.0.1:{bridge.state_port}") as s:
        bridge.runner_address = ("127.0.0.1", s.port)
        names = list(bridge.mapping.names)
        wrong = _exc_outlet(pylsl, f"exc-{source}", f"{source}-wrong", names)  # same name, other source
        right = _exc_outlet(pylsl, f"exc-{source}", f"{source}-right", names)
        stop, th, errors = _run_bridge(bridge)
        try:
            t_end = time.monotonic() + 8
            while time.monotonic() < t_end and bridge.forwarded < 5 and not errors:
                wrong.push_sample([0.9] * len(names))
                right.push_sample([0.01] * len(names))
                time.sleep(0.01)
        finally:
            stop.set()
            th.join(timeout=5)
            bridge.close()
    assert not errors and bridge.forwarded >= 5
    np.testing.assert_allclose(bridge.last_values, 0.01)


def test_lsl_bridge_refuses_undeliverable_rate_and_unfilled_forces():
    pylsl = pylsl_or_skip()  # noqa: F841
    from armrt.lsl_bridge import LslBridge, check_state_rate
    with pytest.raises(ValueError, match="333.333 and 250"):
        check_state_rate(300, 1000)
    assert check_state_rate(250, 1000) == 4
    with pytest.raises(ValueError, match="300"):
        LslBridge(runner_port=9, state_rate_hz=300)
    source = f"armrt-test-forces-{os.getpid()}"
    bridge = LslBridge(runner_port=0, mapping="groups", source_id=source, forces=True,
                       excitation_source_id=f"{source}-none")
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=100, state_to=f"127.0.0.1:{bridge.state_port}") as s:
        bridge.runner_address = ("127.0.0.1", s.port)
        try:
            t_end = time.monotonic() + 5
            with pytest.raises(RuntimeError, match="--forces"):
                while time.monotonic() < t_end:
                    bridge.step()
        finally:
            bridge.close()


def test_lsl_bridge_warns_once_per_fault():
    pylsl_or_skip()
    from armrt.lsl_bridge import LslBridge
    source = f"armrt-test-warn-{os.getpid()}"
    bridge = LslBridge(runner_port=0, mapping="groups", source_id=source, excitation_source_id=f"{source}-none")
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, state_to=f"127.0.0.1:{bridge.state_port}") as s:
        bridge.runner_address = ("127.0.0.1", s.port)
        junk = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        try:
            for _ in range(50):
                junk.sendto(b"not a packet", ("127.0.0.1", bridge.state_port))
                bridge.step()
            # The runner sends state at 200 Hz, the bridge declared 100 Hz: one rate warning.
            t_end = time.monotonic() + 0.5
            while time.monotonic() < t_end:
                bridge.step()
        finally:
            junk.close()
            bridge.close()
    assert bridge.bad >= 50 and bridge.published > 10
    w = [x for x in bridge.warnings if "overran" not in x]  # an overrun on a busy machine is a fault of its own
    assert len(w) == 2 and w[0].startswith("dropped") and w[1].startswith("the runner sends state every 5.000 ms"), w


def test_lsl_bridge_never_blocks_on_resolving(monkeypatch):
    """Looking for a controller happens on a ContinuousResolver thread: step() never calls a blocking
    resolve (the old bridge published state in 200 ms lumps while it resolved), and every state
    packet is published as it arrives."""
    pylsl = pylsl_or_skip()

    def blocking(*a, **k):
        raise AssertionError("blocking LSL resolve called")
    for name in ("resolve_byprop", "resolve_stream", "resolve_streams", "resolve_bypred"):
        if hasattr(pylsl, name):
            monkeypatch.setattr(pylsl, name, blocking)
    from armrt.lsl_bridge import LslBridge
    source = f"armrt-test-burst-{os.getpid()}"
    bridge = LslBridge(runner_port=0, mapping="groups", source_id=source, excitation_source_id=f"{source}-absent",
                       state_rate_hz=200)
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, duration=0.5,
                            state_to=f"127.0.0.1:{bridge.state_port}") as s:
        bridge.runner_address = ("127.0.0.1", s.port)
        try:
            while not s.finished:
                bridge.step()
            for _ in range(20):
                bridge.step()
        finally:
            bridge.close()
        sent = s.stats()["packets"]["state_sent"]
    assert bridge.inlet is None and bridge.forwarded == 0
    assert bridge.published == sent and sent >= 90


# ---------------------------------------------------------------------------------------- paralysis (issue 11 item 3)
def test_paralysis_holds_in_the_real_time_loop():
    """Elbow flexors paralysed: a controller sending them 1.0 over UDP changes nothing, so the runner's
    trajectory is the offline one with zero excitation (same model, integrator and substeps), and the
    streamed excitation is the capped one the dynamics used."""
    import armrt
    arm = armrt.Arm()
    flexors = arm.indices("elbow_flexors")
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, input_timeout=1.0, integrator=arm.integrator,
                            send_excitation=True, max_activation={"elbow_flexors": 0.0, "triceps": 0.25}) as s, \
            rt.UdpClient(s.port, mapping="groups") as c:
        c.join()
        st = None
        for _ in range(40):
            c.send({"elbow_flexors": 1.0, "triceps": 0.0})
            st = c.latest_state(timeout=0.2) or st
            if st is not None and st.time > 0.3 and st.last_applied_seq >= 0:
                break
        c.send({"elbow_flexors": 1.0, "triceps": 1.0})
        capped = None
        for _ in range(40):
            got = c.latest_state(timeout=0.2)
            if got is not None and got.excitation is not None and got.excitation[arm.indices("triceps")].max() > 0:
                capped = got
                break
        stats = s.stop()
    assert stats["packets"]["applied"] > 0 and stats["error"] == ""
    assert st.excitation is not None and np.all(st.excitation[flexors] == 0.0)
    arm.step(int(round(st.time / arm.dt)))
    np.testing.assert_allclose(st.q, arm.q, atol=1e-9)
    assert capped is not None and np.all(capped.excitation[arm.indices("triceps")] == 0.25)
    assert np.all(capped.excitation[flexors] == 0.0)


def test_runner_strength_by_names_matches_arm_strength():
    """RealtimeSession(strength=) / --strength scales fmax through the names --max-activation uses (the muscle's
    value wins over its group's, in either order): with zero excitation the streamed state and muscle forces
    are the offline Arm's with the same Arm.strength, and not the intact arm's (passive forces scale with fmax)."""
    import armrt
    weak = {"bicb": 0.25, "elbow_flexors": 0.5}
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, input_timeout=1.0, send_forces=True,
                            strength=weak) as s, rt.UdpClient(s.port, mapping="groups") as c:
        c.join()
        st = _state_after(c, 0.3)
        stats = s.stop()
    assert stats["error"] == "" and st is not None and st.muscle_force is not None
    arm, intact = armrt.Arm(), armrt.Arm()
    arm.strength = weak
    assert np.all(arm.strength[arm.indices("bicb")] == 0.25)
    others = sorted(set(arm.indices("elbow_flexors")) - set(arm.indices("bicb")))
    assert others and np.all(arm.strength[others] == 0.5)
    _assert_streamed_like_offline(st, arm, intact)


def test_strength_bad_values_are_refused():
    with pytest.raises(ValueError, match=r"strength must be finite and >= 0"):
        rt.RealtimeSession(strength={"bicb": -0.5})
    with pytest.raises(ValueError, match=r"--strength: unknown element, muscle or group name 'bicbb' \(did you mean 'bicb'"):
        rt.RealtimeSession(strength={"bicbb": 0.5})
    for value in ("-1", "x", "inf", "nan"):
        r = subprocess.run([runner(), "--strength", f"bicb=0.3,triceps={value}", "--duration", "0.1"],
                           capture_output=True, text=True, timeout=20)
        assert r.returncode == 2 and "strength of 'triceps' must be a finite number >= 0" in r.stderr, r.stderr


def test_max_activation_bad_values_are_refused():
    with pytest.raises(ValueError, match=r"must lie in \[0, 1\]"):
        rt.RealtimeSession(max_activation={"bicb": 1.5})
    with pytest.raises(ValueError, match=r"--max-activation: unknown element, muscle or group name 'bicbb' \(did you mean 'bicb'"):
        rt.RealtimeSession(max_activation={"bicbb": 0.5})
    r = subprocess.run([runner(), "--max-activation", "bicb=0.3,triceps=x", "--duration", "0.1"],
                       capture_output=True, text=True, timeout=20)
    assert r.returncode == 2 and "max activation of 'triceps' must be a number in [0, 1]" in r.stderr


# ---------------------------------------------------------------------------------------- issue 25: one meaning per word
def test_dt_is_deprecated_for_the_integration_step():
    """dt is the control step (Arm.dt; 1/--rate here): the runner's integration step is --integration-step,
    and --dt / dt= still work with a warning on stderr / a DeprecationWarning."""
    r = subprocess.run([runner(), "--dt", "0.0005", "--duration", "0.05", "--no-rt", "--no-mlock"],
                       capture_output=True, text=True, timeout=20)
    assert r.returncode == 0, r.stderr
    assert "--dt is deprecated, use --integration-step" in r.stderr
    assert "integration step 0.0005 s" in r.stdout
    r = subprocess.run([runner(), "--integration-step", "0.0005", "--duration", "0.05", "--no-rt", "--no-mlock"],
                       capture_output=True, text=True, timeout=20)
    assert r.returncode == 0 and "deprecated" not in r.stderr and "integration step 0.0005 s" in r.stdout
    with pytest.warns(DeprecationWarning, match="integration_step"):
        s = rt.RealtimeSession(dt=0.0005, rate_hz=1000)
    assert s.stats()["integration_step"] == pytest.approx(0.0005) and s.stats()["control_step"] == pytest.approx(1e-3)
    with pytest.raises(ValueError, match="both"):
        rt.RealtimeSession(dt=0.0005, integration_step=0.0005)


def test_state_packet_class_is_statepacket_and_state_is_a_deprecated_alias():
    import armrt
    with pytest.warns(DeprecationWarning, match="StatePacket"):
        alias = rt.State
    assert alias is rt.StatePacket and rt.StatePacket is not armrt.State


GOLDEN_PACKET = Path(__file__).resolve().parent / "data" / "state_packet_v3_das2.hex"


def test_decoder_reads_every_row_of_the_packet_table_from_the_v3_capture():
    """The version-3 bytes captured before the table (cpp/rt/test_rt.cc checks the runner still writes
    them): the table-driven decoder yields every row, with the values in the table's order."""
    data = bytes.fromhex(GOLDEN_PACKET.read_text().strip())
    p = rt.decode_packet(data)
    # Every row the capture's flags carry (the stimulation rows came later, with their own flag).
    table = [r for r in rt.state_packet_fields("das2") if r["flag"] != rt.FLAG_STIMULATION]
    assert p.flags & rt.FLAG_FORCES and p.flags & rt.FLAG_EXCITATION and not p.flags & rt.FLAG_STIMULATION
    values = rt.StatePacket.decode_values(p, table)
    assert [r["name"] for r in table] == list(values)          # every row, in order
    st = rt.StatePacket.from_packet(p, "das2")
    k = 0
    for r in table:
        got = np.atleast_1d(getattr(st, r["name"]))
        assert got.size == r["size"] and len(r["labels"]) == r["size"], r["name"]
        np.testing.assert_array_equal(got, p.values[k:k + r["size"]])
        k += r["size"]
    assert k == p.values.size
    assert st.qdot.shape == (5,) and st.hand_position.shape == (3,) and isinstance(st.overruns, int)
    # max activation infra=0.2 in the capture: its streamed excitation is capped.
    from armrt import _core
    infra = list(_core.find_elements("das2", "infra"))
    assert st.excitation[infra].max() <= 0.2 + 1e-15 and st.excitation.max() > 0.2
    assert rt.state_fields("das2") == [lab for r in table if r["flag"] == 0 for lab in r["labels"]]


def test_every_table_row_is_an_lsl_channel():
    from armrt.lsl_bridge import state_channels
    labels, units, types = state_channels("das2", forces=True, excitations=True)
    for r in rt.state_packet_fields("das2"):
        for lab in r["labels"]:
            k = labels.index(lab)
            assert units[k] == r["unit"] and types[k] == r["lsl_type"], lab
    assert len(labels) == len(set(labels)) == sum(r["size"] for r in rt.state_packet_fields("das2")) + 1  # + overrun flag


# ---------------------------------------------------------------------------------------- issue 25: overlapping names
def _cuff(model="das2"):
    from armrt import _core
    return list(_core.find_elements(model, "infra")), list(_core.find_elements(model, "supra"))


def test_udp_overlapping_channels_most_specific_wins_in_either_order():
    infra, supra = _cuff()
    for channels in (["rotator_cuff", "infra"], ["infra", "rotator_cuff"]):
        with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=100, send_excitation=True, channels=channels,
                                input_timeout=1.0) as s, \
                rt.UdpClient(s.port, mapping="channels", channels=channels) as c:
            c.join()
            u = {"rotator_cuff": 0.3, "infra": 0.05}
            assert np.allclose(c.mapping.to_elements(u)[infra], 0.05)
            st = None
            t_end = time.monotonic() + 3
            while time.monotonic() < t_end:
                c.send(u)
                st = c.latest_state(timeout=0.1) or st
                if st is not None and st.last_applied_seq >= 0 and st.excitation[supra[0]] > 0:
                    break
            assert st is not None and st.excitation is not None
            np.testing.assert_allclose(st.excitation[infra], 0.05)   # the old maximum gave 0.3
            np.testing.assert_allclose(st.excitation[supra], 0.3)


def test_udp_elements_mapping_dict_uses_the_same_rule():
    infra, supra = _cuff()
    m = rt.GroupMapping.from_model("elements")
    a = m.values({"rotator_cuff": 0.05, "infra": 0.3})
    b = m.values({"infra": 0.3, "rotator_cuff": 0.05})
    np.testing.assert_array_equal(a, b)
    assert a[infra[0]] == 0.3 and a[supra[0]] == 0.05


def test_lsl_overlapping_channels_most_specific_wins_in_either_order():
    """An LSL controller whose channels are a group and one of its muscles: the runner applies the one
    rule (the muscle's value for its elements), whichever order the channels come in."""
    pylsl = pylsl_or_skip()
    from armrt.lsl_bridge import LslBridge, state_channels
    infra, supra = _cuff()
    for order, channels in enumerate((["rotator_cuff", "infra"], ["infra", "rotator_cuff"])):
        source = f"armrt-test-ovl{order}-{os.getpid()}"
        bridge = LslBridge(runner_port=0, mapping="channels", channels=channels, source_id=source,
                           excitation_source_id=f"{source}-ctl", state_rate_hz=100, excitations=True)
        with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=100, send_excitation=True, channels=channels,
                                state_to=f"127.0.0.1:{bridge.state_port}", input_timeout=1.0) as s:
            bridge.runner_address = ("127.0.0.1", s.port)
            stop, th, errors = _run_bridge(bridge)
            try:
                labels = ["rotator_cuff", "infra"]
                outlet = _exc_outlet(pylsl, f"exc-{source}", f"{source}-ctl", labels)
                found = pylsl.resolve_byprop("source_id", f"{source}-state", timeout=10)
                assert found
                inlet = pylsl.StreamInlet(found[0])
                names = state_channels("das2", excitations=True)[0]
                ki, ks = names.index(f"excitation_{_elname(infra[0])}"), names.index(f"excitation_{_elname(supra[0])}")
                got = None
                t_end = time.monotonic() + 5
                while time.monotonic() < t_end and not errors:
                    outlet.push_sample([0.3, 0.05])
                    samples, _ = inlet.pull_chunk(timeout=0.05)
                    if samples and samples[-1][ks] > 0:
                        got = samples[-1]
                        break
                    time.sleep(0.01)
                assert not errors, errors
                assert got is not None, "no excited state over LSL"
                assert got[ki] == pytest.approx(0.05) and got[ks] == pytest.approx(0.3), channels
            finally:
                stop.set()
                th.join(timeout=5)
                bridge.close()


def _elname(i, model="das2"):
    from armrt import _core
    return _core.model_info(model)["elements"][i]["name"]


def test_docs_list_every_row_of_the_packet_table():
    doc = (Path(__file__).resolve().parents[1] / "docs" / "realtime.md").read_text()
    table = doc.split("| row | values | unit | sent | label | meaning |", 1)[1].split("\n\n", 1)[0]
    for r in rt.state_packet_fields("das2"):
        row = next((line for line in table.splitlines() if line.startswith(f"| `{r['name']}` |")), None)
        assert row is not None, f"docs/realtime.md lacks the row {r['name']}"
        assert f"| {r['unit']} |" in row, (r["name"], r["unit"], row)


def test_runner_max_activation_overlapping_names_most_specific_wins_in_either_order():
    """--max-activation by names that overlap (a group and one of its muscles) follows the engine's one rule
    as Arm.max_activation does: the muscle's value wins over the group's, whatever the order."""
    infra, supra = _cuff()
    for cap in ({"rotator_cuff": 0.3, "infra": 0.05}, {"infra": 0.05, "rotator_cuff": 0.3}):
        with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, input_timeout=1.0, send_excitation=True,
                                max_activation=cap) as s, \
                rt.UdpClient(s.port, mapping="groups") as c:
            c.join()
            st = None
            t_end = time.monotonic() + 3
            while time.monotonic() < t_end:
                c.send({"rotator_cuff": 1.0})
                got = c.latest_state(timeout=0.1)
                if got is not None and got.excitation is not None and got.excitation[supra[0]] > 0:
                    st = got
                    break
            s.stop()
        assert st is not None
        np.testing.assert_array_equal(st.excitation[infra], 0.05)
        np.testing.assert_array_equal(st.excitation[supra], 0.3)


# ---------------------------------------------------------------------------------------- stimulation
def test_stimulation_through_udp_flexes_the_elbow_fatigues_and_times_out_to_zero():
    """A stimulation map drives the runner over UDP: the elbow flexors' channels flex the elbow, the state
    packets carry the applied command and the fatigue, the client refuses what Arm.set_stimulation refuses,
    and silence sets every channel to zero."""
    flexors = {"bicl": (250e-6, 0.020, 30.0), "bicb": (250e-6, 0.020, 30.0), "brachialis": (250e-6, 0.020, 30.0)}
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, input_timeout=0.2,
                            stimulation="per_muscle") as s, \
            rt.UdpClient(s.port, stimulation="per_muscle") as c:
        c.join()
        names = s.channel_names
        assert names == c.stimulation.names and set(flexors) <= set(names)
        # What the Python API refuses is refused before it is sent (the message names the channel).
        with pytest.raises(ValueError, match="exceeds its limit"):
            c.send_stimulation({next(iter(flexors)): (250e-6, 0.030, 30.0)})
        with pytest.raises(ValueError, match="not finite"):
            c.send_stimulation({next(iter(flexors)): (np.nan, 0.01, 30.0)})
        with pytest.raises(ValueError, match="unknown stimulation channel"):
            c.send_stimulation({"bicepz": (250e-6, 0.01, 30.0)})
        el0 = None
        t_end = time.monotonic() + 2.0
        while time.monotonic() < t_end:
            c.send_stimulation(flexors)
            st = c.latest_state(timeout=0.2)
            assert st is not None and not st.diverged
            el0 = st.q[3] if el0 is None else el0
        assert st.stimulation.shape == (len(names), 3)
        k = names.index(next(iter(flexors)))
        np.testing.assert_array_equal(st.stimulation[k], flexors[names[k]])
        assert st.fatigue[k] > 0 and st.fatigue[names.index("anconeus")] == 0  # stimulated / never pulsed
        assert np.degrees(st.q[3] - el0) > 20, (np.degrees(el0), np.degrees(st.q[3]))
        # A raw packet beyond the limits (a client that does not check; 15 is mA written for A): refused by the
        # runner as Arm.set_stimulation refuses it, the previous command held, not clamped to the channel's maximum.
        raw = np.zeros((len(names), 3))
        raw[k] = (200e-6, 15.0, 30.0)
        c.send_raw(rt.encode_packet(rt.STIMULATION, c._next_seq(), raw.ravel(), session=c.session))
        time.sleep(0.05)
        st = c.latest_state(timeout=0.2)
        np.testing.assert_array_equal(st.stimulation[k], flexors[names[k]])
        time.sleep(0.4)  # silence: the session ends and every channel falls to zero
        stats = s.stop()
    assert stats["packets"]["stimulation_refused"] == 1
    assert stats["packets"]["stimulation_applied"] > 20
    assert stats["packets"]["timeouts"] == 1


def test_runner_stimulation_option_and_its_errors(tmp_path):
    m = tmp_path / "map.toml"
    m.write_text('[[channels]]\nname = "flexors"\nelements = ["bicl", "brachialis"]\n')
    with rt.RealtimeSession(listen="127.0.0.1:0", stimulation=m) as s:
        assert s.channel_names == ["flexors"]
    with rt.RealtimeSession(listen="127.0.0.1:0", stimulation={"channels": [{"name": "f", "elements": ["bicl"]}]}) as s:
        assert s.channel_names == ["f"]
    with pytest.raises(ValueError, match="--stimulation.*bicepz"):
        rt.RealtimeSession(stimulation={"channels": [{"name": "f", "elements": ["bicepz"]}]})
    bad = tmp_path / "bad.toml"
    bad.write_text('[[channels]]\nname = "f"\nelements = []\n')
    r = subprocess.run([runner(), "--stimulation", str(bad), "--duration", "0.01", "--no-rt", "--no-mlock"],
                       capture_output=True, text=True, timeout=30)
    assert r.returncode == 2 and "--stimulation" in r.stderr, r.stderr
    p, port = start_runner("--stimulation", str(m), "--no-rt", "--no-mlock", "--timeout", "0.2")
    try:
        with rt.UdpClient(port, stimulation=m) as c:
            c.join()
            c.send_stimulation({"flexors": (200e-6, 0.015, 25.0)})
            time.sleep(0.05)
    finally:
        code, out, err = stop_runner(p)
    assert code == 0, err
    assert "stimulation: 1 channels, packets applied 1, refused beyond the channels' limits 0" in out, out


def test_lsl_stimulator_stream_by_label_drives_the_runner():
    """A stimulator on LSL (channels labelled "<channel>/pulse_width", "/amplitude", "/frequency", a subset of
    the map's, in any order): forwarded as stimulation packets; a sample beyond the limits is not forwarded; the
    state stream carries the applied stimulation and the fatigue by channel."""
    pylsl = pylsl_or_skip()
    from armrt.lsl_bridge import LslBridge, channel_labels
    source = f"armrt-test-stim-{os.getpid()}"
    bridge = LslBridge(runner_port=0, mapping="stimulation", stimulation="per_muscle", source_id=source,
                       excitation_source_id=f"{source}-stimulator", state_rate_hz=200)
    assert bridge.excitation_name == "armrt_stimulation"
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, stimulation="per_muscle",
                            state_to=f"127.0.0.1:{bridge.state_port}") as s:
        bridge.runner_address = ("127.0.0.1", s.port)
        stop, th, errors = _run_bridge(bridge)
        try:
            labels = ["brachialis/amplitude", "brachialis/pulse_width", "brachialis/frequency",
                      "bicl/frequency", "bicl/pulse_width", "bicl/amplitude"]
            outlet = _exc_outlet(pylsl, "stimulator", f"{source}-stimulator", labels)
            good = [0.020, 250e-6, 30.0, 30.0, 250e-6, 0.020]
            found = pylsl.resolve_byprop("source_id", f"{source}-state", timeout=10)
            assert found, "state stream not found on loopback"
            inlet = pylsl.StreamInlet(found[0])
            out_labels = channel_labels(inlet.info(timeout=5))
            assert "bicl/pulse_width" in out_labels and "bicl/fatigue" in out_labels
            el0 = el = None
            t_end = time.monotonic() + 3
            while time.monotonic() < t_end and not errors:
                outlet.push_sample(good)
                samples, _ = inlet.pull_chunk(timeout=0.05)
                if samples:
                    el = samples[-1][out_labels.index("ELx")]
                    el0 = el if el0 is None else el0
                    last = samples[-1]
                time.sleep(0.01)
            assert not errors, errors
            assert el is not None and np.degrees(el - el0) > 15, (el0, el)
            assert last[out_labels.index("bicl/amplitude")] == 0.020
            assert last[out_labels.index("bicl/fatigue")] > 0
            assert last[out_labels.index("triclong/amplitude")] == 0.0
            forwarded = bridge.forwarded
            bad = list(good)
            bad[0] = 0.5  # 500 mA on an intramuscular channel: never sent
            for _ in range(5):
                outlet.push_sample(bad)
                time.sleep(0.02)
            t_end = time.monotonic() + 2
            while bridge.refused == 0 and time.monotonic() < t_end:
                time.sleep(0.01)
            assert bridge.refused >= 1 and bridge.forwarded == forwarded
            assert any("refused" in w and "brachialis" in w for w in bridge.warnings), bridge.warnings
        finally:
            stop.set()
            th.join(timeout=5)
            bridge.close()
        st = s.stop()
    assert st["packets"]["stimulation_applied"] > 10 and st["packets"]["stimulation_refused"] == 0


def test_state_channels_with_stimulation_have_units_per_value():
    from armrt.lsl_bridge import state_channels
    labels, units, types = state_channels("das2", channels=["flexors", "extensors"])
    for c in ("flexors", "extensors"):
        for v, u in (("pulse_width", "s"), ("amplitude", "A"), ("frequency", "Hz"), ("fatigue", "1")):
            assert units[labels.index(f"{c}/{v}")] == u
    assert labels[-1] == "extensors/fatigue" and len(labels) == len(state_channels("das2")[0]) + 8


def test_client_refuses_nan_and_out_of_range_excitation_before_sending():
    """UdpClient.send refuses what the runner would drop or clip, naming the values; nothing reaches the runner."""
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=100) as s, rt.UdpClient(s.port, mapping="groups") as c:
        for bad, shown in (({"elbow_flexors": float("nan")}, "elbow_flexors=nan"),
                           ({"elbow_flexors": 1.5}, "elbow_flexors=1.5"),
                           ({"rotator_cuff": -0.1}, "rotator_cuff=-0.1"),
                           ({"deltoid": float("inf")}, "deltoid=inf")):
            with pytest.raises(ValueError, match=shown):
                c.send(bad)
        # A string is refused as Arm.set_excitation refuses it (float("0.3") took it until 2026-12-07).
        with pytest.raises(TypeError, match="string"):
            c.send({"elbow_flexors": "0.3"})
        with pytest.raises(TypeError, match="string"):
            c.send(["0.3"] * len(c.mapping.names))
        assert c.session == 0  # refused before joining: no hello, no packet
        time.sleep(0.02)
        stats = s.stop()
    assert stats["packets"]["received"] == 0


def test_runner_takes_the_models_default_map_as_the_python_api_does():
    """stimulation="default" means the model's shipped map in the runner too (RealtimeSession and the armrt-rt
    entry point), with the Python API's error for a model without one."""
    model_file = Path(__file__).resolve().parents[1] / "models" / "participant_A_FES.json"
    expected = armrt.Arm(str(model_file), stimulation="default").channel_names
    with rt.RealtimeSession(model=str(model_file), stimulation="default") as s:
        assert s.channel_names == expected
    args = rt.runner_args(["--model", str(model_file), "--stimulation", "default", "--no-rt"])
    i = args.index("--stimulation")
    assert args[i + 1].endswith("participant_A_FES.stimulation.toml") and args[-1] == "--no-rt"
    assert rt.runner_args(["--model=das2", "--stimulation=x.toml"]) == ["--model=das2", "--stimulation=x.toml"]
    with pytest.raises(ValueError, match="ships no default stimulation map"):
        rt.RealtimeSession(stimulation="default")
    with pytest.raises(ValueError, match="ships no default stimulation map"):
        rt.runner_args(["--stimulation", "default"])


def test_runner_refuses_a_start_pose_as_arm_reset_does_with_its_words():
    """--q0 between Arm.reset's bound (0.2 rad beyond a range) and the domain's (0.35) used to start the runner where
    Arm.reset refuses; now both refuse with the same description (snapshot.h start_pose_error, checks.joint_range),
    and both accept a pose within the bound."""
    import re
    import warnings

    import armrt
    arm = armrt.Arm()
    lo, hi = arm.model.dof_ranges[:, 0], arm.model.dof_ranges[:, 1]
    q = arm.model.rest_posture.copy()
    q[3] = hi[3] + 0.3  # ELx 0.3 rad beyond: inside the physical domain, outside reset's bound
    q[1] = lo[1] - 0.25  # GHz too
    with pytest.raises(ValueError) as py_error:
        arm.reset(q=q)
    r = subprocess.run([runner(), "--q0", ",".join(repr(float(v)) for v in q), "--duration", "0.05", "--no-rt",
                        "--no-mlock"], capture_output=True, text=True, timeout=20)
    assert r.returncode == 2, (r.returncode, r.stderr)
    desc = re.search(r"q beyond the joint limits: (.*? deg)\.(?: |$)", str(py_error.value)).group(1)
    assert "GHz" in desc and "ELx" in desc
    assert f"--q0 (rad): q beyond the joint limits: {desc}" in r.stderr, (desc, r.stderr)
    # Within the bound: Arm.reset warns and starts, so does the runner.
    q_ok = arm.model.rest_posture.copy()
    q_ok[3] = hi[3] + 0.1
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        arm.reset(q=q_ok)
    r = subprocess.run([runner(), "--q0", ",".join(repr(float(v)) for v in q_ok), "--duration", "0.05", "--no-rt",
                        "--no-mlock"], capture_output=True, text=True, timeout=20)
    assert r.returncode == 0, r.stderr


def test_client_send_never_waits_for_a_session():
    """UdpClient.send used to join on its first call, blocking up to 1 s (a second client in the same loop silenced
    the owner that long): without a session it now raises at once, naming join(), and sends nothing."""
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=100) as s, rt.UdpClient(s.port, mapping="groups") as c:
        for send in (lambda: c.send({"rotator_cuff": 0.03}),
                     lambda: c.send(np.zeros(len(c.mapping.names)))):
            with pytest.raises(RuntimeError, match=r"join\(timeout\)"):
                send()
        time.sleep(0.05)
        assert s.stats()["packets"]["applied"] == 0
        c.join()
        c.send({"rotator_cuff": 0.03})
        time.sleep(0.05)
        assert s.stats()["packets"]["applied"] == 1


def test_statistics_name_the_model_and_profile(tmp_path):
    """The model's name and the profile (None when none is given) are in RealtimeSession's result and in --json:
    one field of RtStats (rt_stats.cc), not written anywhere else."""
    s = rt.RealtimeSession(model="das2", duration=0.02, realtime=False)
    s.start()
    assert s.wait(10.0)
    stats = s.stop()
    assert stats["model"] == "das2" and stats["profile"] is None
    path = tmp_path / "stats.json"
    r = subprocess.run([runner(), "--model", "das2", "--duration", "0.02", "--no-rt", "--no-mlock", "--json",
                        str(path)], capture_output=True, text=True, timeout=20)
    assert r.returncode == 0, r.stderr
    saved = json.loads(path.read_text())
    assert saved["model"] == "das2" and saved["profile"] is None
    assert "das2 stopped (duration)" in r.stdout


def test_runner_settle_starts_from_the_relaxed_arm():
    """RealtimeSession(settle=S) / --settle S: the arm first relaxes S s with zero excitation (Arm.settle's engine
    path, Arm::settle), the loop then starts at time 0: the streamed state at time t is the offline arm's after
    S + t s of zero excitation, stepped without settle()."""
    weak = {"elbow_flexors": 0.5}
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, input_timeout=1.0, strength=weak,
                            settle=0.3) as s, rt.UdpClient(s.port, mapping="groups") as c:
        c.join()
        st = _state_after(c, 0.05)
        stats = s.stop()
    assert stats["error"] == "" and st is not None and st.time < 0.3 + 0.2
    arm = armrt.Arm()
    arm.strength = weak
    arm.step(300 + int(round(st.time / arm.dt)))
    np.testing.assert_allclose(st.q, arm.q, atol=1e-9)
    unsettled = armrt.Arm()
    unsettled.strength = weak
    unsettled.step(int(round(st.time / arm.dt)))
    assert np.abs(st.q - unsettled.q).max() > 1e-6
    # Arm.settle goes through the same engine path: its state is the stepped arm's, the clock back at 0.
    a, b = armrt.Arm(), armrt.Arm()
    a.set_excitation(0.2)
    a.settle(0.1)
    b.step(100)
    assert a.time == 0.0 and np.all(a.excitation == 0.2)
    np.testing.assert_allclose(a.q, b.q, atol=1e-12)


def test_runner_support_holds_the_joints_until_s_after_the_first_command():
    """RealtimeSession(support=S) / --support S: the joints stay where the loop started, at rest, while no controller
    has commanded anything and for S s after its first command; then the arm moves (das2's rest posture with zero
    excitation is no equilibrium). The C++ test checks the muscles go on meanwhile."""
    arm = armrt.Arm()
    watcher = rt.StateListener("127.0.0.1", 0, "das2")   # a --state-to subscriber sees the arm before any command
    watcher.sock.settimeout(2.0)
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, input_timeout=1.0, support=0.3,
                            state_to=f"127.0.0.1:{watcher.port}") as s, \
            rt.UdpClient(s.port, mapping="groups") as c:
        time.sleep(0.4)                                # longer than S, and nothing sent yet: held
        waiting = None
        while waiting is None or waiting.time < 0.35:
            waiting = watcher.decode(watcher.sock.recv(65536)) or waiting
        watcher.close()
        c.join()
        first = _state_after(c, waiting.time)          # the first commands
        during = _state_after(c, first.time + 0.15)
        after = _state_after(c, first.time + 0.6)
        stats = s.stop()
    assert stats["error"] == "" and stats["support_s"] == pytest.approx(0.3)
    for st in (waiting, first, during):
        np.testing.assert_array_equal(st.q, arm.rest_posture)
        np.testing.assert_array_equal(st.qdot, np.zeros(arm.n_dofs))
    assert np.abs(after.q - arm.rest_posture).max() > 1e-4


def test_settle_bad_values_are_refused():
    for bad in (-1.0, float("nan"), float("inf"), 1e308):  # 1e308 overflowed the cycle count
        with pytest.raises(ValueError, match=r"--settle must be a finite number of seconds >= 0"):
            rt.RealtimeSession(settle=bad)
    r = subprocess.run([runner(), "--settle", "-0.5", "--duration", "0.1"], capture_output=True, text=True, timeout=20)
    assert r.returncode == 2 and "--settle must be a finite number of seconds >= 0 (at most 1e7), got -0.5" in r.stderr, r.stderr
    for bad in (-1.0, float("nan"), float("inf"), 1e308):
        with pytest.raises(ValueError, match=r"--support must be a finite number of seconds >= 0"):
            rt.RealtimeSession(support=bad)
    r = subprocess.run([runner(), "--support", "-0.5", "--duration", "0.1"], capture_output=True, text=True, timeout=20)
    assert r.returncode == 2 and "--support must be a finite number of seconds >= 0 (at most 1e7), got -0.5" in r.stderr, r.stderr
    r = subprocess.run([runner(), "--support", "1e308", "--duration", "0.1"], capture_output=True, text=True, timeout=20)
    assert r.returncode == 2 and "at most 1e7), got 1e+308" in r.stderr, r.stderr


def test_runner_profile_is_arm_apply_profile():
    """RealtimeSession(profile=) resolves a participant profile with Arm.apply_profile (the runner reads no .mat):
    the runner gets its strength and max_activation element by element, strength= given beside it applies on top,
    and the statistics name the profile. With zero excitation the streamed state and muscle forces are the offline
    arm's with the same profile (passive forces scale with fmax); full excitation is streamed capped at its
    max_activation."""
    mat = Path(__file__).resolve().parents[1].parent / "shared" / "reference" / "participant_A" / "model_struct_A_FES.mat"
    if not mat.exists():
        pytest.skip(f"participant data not found at {mat} (needs ../shared beside the repository)")
    arm, intact = armrt.Arm(), armrt.Arm()
    report = arm.apply_profile(mat)
    arm.strength = {"deltscap": 0.3}
    assert len(report.applied) == 42 and np.any(arm.max_activation[arm.indices("elbow_flexors")] < 1)
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, input_timeout=1.0, send_excitation=True,
                            send_forces=True, profile=mat, strength={"deltscap": 0.3}) as s, \
            rt.UdpClient(s.port, mapping="groups") as c:
        c.join()
        capped = None
        st = _state_after(c, 0.2)
        for _ in range(60):
            c.send({"elbow_flexors": 1.0})
            got = c.latest_state(timeout=0.2)
            if got is not None and got.excitation is not None and got.excitation.max() > 0:
                capped = got
                break
        stats = s.stop()
    assert stats["error"] == "" and stats["profile"] == str(mat) and st is not None and capped is not None
    _assert_streamed_like_offline(st, arm, intact)
    u = np.zeros(arm.n_elements)
    u[arm.indices("elbow_flexors")] = 1.0
    np.testing.assert_array_equal(capped.excitation, np.minimum(u, arm.max_activation))
    with pytest.raises(FileNotFoundError, match="no profile named 'participant_Z'"):
        rt.RealtimeSession(profile="participant_Z")
    with pytest.raises(ValueError, match="profile_reference without a profile"):
        rt.RealtimeSession(profile_reference=mat)


def test_runner_profile_by_model_name():
    """A profile named as a model file (models/participant_A_FES.json, as Arm.apply_profile takes it): resolved
    without ../shared, its name in the statistics, its max_activation the offline arm's."""
    s = rt.RealtimeSession(profile="participant_A_FES", send_excitation=True)
    assert s.stats()["profile"] == "participant_A_FES"
    arm = armrt.Arm()
    arm.apply_profile("participant_A_FES")
    assert np.any(arm.max_activation < 1) or np.any(arm.strength != 1)
    assert s.config["profile"] == "participant_A_FES"


def test_console_script_resolves_profile(tmp_path):
    """`armrt-rt --profile NAME|FILE` (the console script, python -m armrt.realtime): resolved with Arm.apply_profile
    into one --strength and --max-activation value per element, --strength given beside it on top, the name in
    --json; the bare runner refuses --profile with the reason, and an unknown profile exits 2."""
    args = rt.runner_args(["--no-rt", "--profile", "participant_A_FES", "--strength", "deltscap=0.3"])
    arm = armrt.Arm()
    arm.apply_profile("participant_A_FES")
    arm.strength = {"deltscap": 0.3}
    got = dict(zip(args[1::2], args[2::2]))
    assert args[0] == "--no-rt" and got["--profile-name"] == "participant_A_FES"
    assert args.count("--strength") == 1 and args.count("--max-activation") == 1
    for option, values in (("--strength", arm.strength), ("--max-activation", arm.max_activation)):
        items = dict(x.split("=") for x in got[option].split(","))
        assert list(items) == arm.element_names
        np.testing.assert_array_equal([float(v) for v in items.values()], values)
    with pytest.raises(ValueError, match="strength of 'bicb' must be a finite number >= 0, got 'x'"):
        rt.runner_args(["--profile", "participant_A_FES", "--strength=bicb=x"])
    path = tmp_path / "stats.json"
    r = subprocess.run([sys.executable, "-m", "armrt.realtime", "--profile", "participant_A_FES", "--duration", "0.02",
                        "--no-rt", "--no-mlock", "--json", str(path)], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    assert json.loads(path.read_text())["profile"] == "participant_A_FES"
    assert "profile participant_A_FES stopped (duration)" in r.stdout
    r = subprocess.run([sys.executable, "-m", "armrt.realtime", "--profile", "participant_Z"], capture_output=True,
                       text=True, timeout=60)
    assert r.returncode == 2 and "no profile named 'participant_Z'" in r.stderr, r.stderr
    r = subprocess.run([runner(), "--profile", "participant_A_FES"], capture_output=True, text=True, timeout=20)
    assert r.returncode == 2 and "profiles are resolved in Python by the armrt-rt console script" in r.stderr


def test_statistics_report_receive_buffers_and_kernel_drops():
    """The receive queues' sizes (the owner's as the shared one's) and the kernel drops reach RealtimeSession's
    statistics; the C++ tests force drops deterministically (cpp/rt/test_rt.cc, "receive queues")."""
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=0) as s:
        st = s.stats()
    assert st["owner_rcvbuf_bytes"] == st["rcvbuf_bytes"] > 2 * 212992
    assert st["packets"]["kernel_drops"] == 0
    for key in ("replies_limited", "held_off", "session_ended"):
        assert st["packets"][key] == 0


def test_read_key_file_is_the_runners_reader(tmp_path):
    """One implementation of the key-file rules: Python's read_key_file is the runner's (armrt._rt), an unopenable
    file still an OSError naming it."""
    assert rt.read_key_file.__module__ == "armrt.realtime_packets"
    with pytest.raises(FileNotFoundError) as e:
        rt.read_key_file(tmp_path / "absent")
    assert e.value.filename == str(tmp_path / "absent")
    short = tmp_path / "short"
    short.write_bytes(b"too short\n")
    short.chmod(0o600)
    with pytest.raises(ValueError, match="shorter than 16 bytes"):
        rt.read_key_file(short)
    with pytest.raises(ValueError, match="not a regular file"):
        rt.read_key_file(tmp_path)


def test_runner_hand_load_matches_arm_set_hand_load(tmp_path):
    """RealtimeSession(hand_force=, hand_moment=) / --hand-force, --hand-moment: a constant load at the hand, as
    Arm.set_hand_load (the runner had no hand load at all): the streamed state is the offline arm's with the same
    load, not the unloaded arm's; the statistics record the load."""
    import armrt
    force, moment = (0.0, -9.81, 0.0), (0.0, 0.0, 0.2)
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=200, input_timeout=1.0, send_forces=True,
                            hand_force=force, hand_moment=moment) as s, rt.UdpClient(s.port, mapping="groups") as c:
        c.join()
        st = _state_after(c, 0.3)
        stats = s.stop()
    assert stats["error"] == "" and st is not None
    assert stats["hand_load"] == {"force_N": list(force), "moment_N_m": list(moment)}
    arm, unloaded = armrt.Arm(), armrt.Arm()
    arm.set_hand_load(force, moment)
    _assert_streamed_like_offline(st, arm, unloaded)
    # The command line, the same numbers: the JSON statistics carry them; without the options, zeros.
    out_json = tmp_path / "stats.json"
    r = subprocess.run([runner(), "--hand-force", "0,-9.81,0", "--hand-moment", "0,0,0.2", "--duration", "0.05",
                        "--json", str(out_json)], capture_output=True, text=True, timeout=20)
    assert r.returncode == 0, r.stderr
    assert json.loads(out_json.read_text())["hand_load"] == {"force_N": list(force), "moment_N_m": list(moment)}
    with rt.RealtimeSession(duration=0.01) as s:
        assert s.stop()["hand_load"] == {"force_N": [0.0] * 3, "moment_N_m": [0.0] * 3}


@pytest.mark.parametrize("kwargs, error, message", [
    ({"hand_force": (0.0, -9.81)}, ValueError, r"hand force must have shape \(3,\), got \(2,\)"),
    ({"hand_moment": (0.0, np.nan, 0.0)}, ValueError, "hand moment contains NaN or infinite values"),
    ({"hand_force": (True, False, False)}, TypeError, "bool"),
    ({"hand_force": "0,-9.81,0"}, TypeError, "hand force"),
    ({"hand_force": (0.0, -2e5, 0.0)}, ValueError, r"hand force of 2e\+05 N is beyond 1e\+05 N"),
    ({"hand_moment": (0.0, 0.0, 2e4)}, ValueError, r"hand moment of 20000 N m is beyond 10000 N m"),
])
def test_hand_load_bad_values_are_refused(kwargs, error, message):
    with pytest.raises(error, match=message):
        rt.RealtimeSession(**kwargs)


@pytest.mark.parametrize("args, message", [
    (["--hand-force", "0,-9.81"], "--hand-force needs 3 values (x lateral, y up, z posterior; thorax frame), got 2"),
    (["--hand-force", "0,-9.81,0,1"], "--hand-force needs 3 values"),
    (["--hand-moment", "0,inf,0"], "--hand-moment contains NaN or infinite values"),
    (["--hand-force", "0,nan,0"], "--hand-force contains NaN or infinite values"),
    # Arm.set_hand_load's bound (checks.hand_load): 1e7 N was accepted and diverged in the first cycle.
    (["--hand-force", "0,-1e7,0"], "--hand-force of 1e+07 N is beyond 1e+05 N, more than any arm bears"),
    (["--hand-moment", "3e4,0,0"], "--hand-moment of 30000 N m is beyond 10000 N m"),
    # One rule with the Python API's to the last bit (a fifth trial: the runner's plain sqrt and Python's scaled norm
    # disagreed one ulp from the bound, 11103 of 200000 directions); the excess shown in full.
    (["--hand-force", "0,-100000.00000000001,0"], "--hand-force of 100000.00000000001 N is beyond 1e+05 N"),
])
def test_runner_hand_load_bad_values_are_refused(args, message):
    r = subprocess.run([runner(), *args, "--duration", "0.05"], capture_output=True, text=True, timeout=20)
    assert r.returncode == 2 and message in r.stderr, (r.returncode, r.stderr)


def test_latest_state_after_a_stall_is_not_the_stale_queue():
    """A third trial's controller stalled 1.5 s and 3 s at a 1 kHz state rate: the 2 MB receive buffer fills in
    about 0.9 s, the kernel drops what comes after, and latest_state() returned a state seconds old that still
    showed the stimulation on after the session's timeout (the runner sends a timed-out owner nothing more, and
    its session-ended notice was lost). Now a newest state older than the wait is counted and not returned: after
    1.5 s (the session alive) the newest is a fresh one, packets arriving while the queue drains; after the
    timeout, none, and the next send learns that the session ended."""
    from armrt.realtime_client import SessionEnded
    with rt.RealtimeSession(listen="127.0.0.1:0", state_rate_hz=1000, input_timeout=2.0, send_forces=True) as s, \
            rt.UdpClient(s.port) as c:
        c.join()
        c.send({"bicb": 0.2})
        t0 = c.latest_state(timeout=0.5).time
        time.sleep(1.5)  # the buffer is full after about 0.9 s; the session (--timeout 2 s) still runs, and the
        st = c.latest_state(timeout=0.5)  # packets that come while the queue drains are fresh: that one is newest
        assert st is not None and st.time > t0 + 1.4 and time.monotonic() - st.received_at < 0.1, (t0, st.time)
        assert c.stale_states == 0 and not st.timed_out
        c.send({"bicb": 0.2})
        time.sleep(3.0)  # the buffer full again before the timeout; then no state is sent, the notice is lost
        assert c.latest_state(timeout=0.3) is None and c.stale_states == 1
        assert c.last_state is not None and c.last_state.time < st.time + 2.5
        c.send({"bicb": 0.2})  # goes out (the client cannot know yet); the runner refuses it and says why
        for _ in range(20):
            c.poll(0.05)
        assert c.session_end is not None
        with pytest.raises(SessionEnded):
            c.send({"bicb": 0.2})
        s.stop()
