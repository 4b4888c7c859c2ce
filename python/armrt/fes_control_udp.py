"""A reference FES controller as a UDP client of armrt-rt: state packets in -> controller.update -> stimulation
packets out, at the controller's own rate, with its loop time measured (docs/control.md "Reference FES controllers",
examples/fes_controllers_udp.py runs it as a separate process against a RealtimeSession).
"""
from __future__ import annotations

import math
import time

import numpy as np

from .checks import real_scalar

PERCENTILES = (50, 90, 99, 100)


def percentiles_us(values) -> dict:
    """{"p50": .., "p90": .., "p99": .., "max": ..} of values (s) in microseconds."""
    a = np.asarray(values, float) * 1e6
    if a.size == 0:
        return {}
    return {("max" if p == 100 else f"p{p}"): float(np.percentile(a, p)) for p in PERCENTILES}


def first_state(client, tries: int = 50):
    """Sends zero stimulation until the runner answers with a state packet (the runner streams state to a client
    that has sent); the state, or RuntimeError."""
    zeros = np.zeros((len(client.stimulation.names), 3))
    for _ in range(tries):
        client.send_stimulation(zeros)
        st = client.latest_state(timeout=0.1)
        if st is not None:
            return st
    raise RuntimeError(f"no state packet from the runner after {tries} zero stimulation packets")


def _send_zero(client) -> None:
    """Best effort: zero pulse width, amplitude and frequency on every channel (a failure to send is left to the
    runner's timeout, and must not hide the error being raised)."""
    try:
        client.send_stimulation(np.zeros((len(client.stimulation.names), 3)))
    except Exception:  # noqa: BLE001 (the caller re-raises its own error)
        pass


def control_loop(controller, client, until_s: float, reference=None) -> dict:
    """Runs `controller` through `client` (an armrt.realtime.UdpClient that has joined the runner, with the
    runner's stimulation map) until the simulated time passes until_s s.
    Each cycle takes the newest state packet, calls controller.update(t, q, qdot) and sends the command
    (UdpClient.send_stimulation); it then sleeps to the next multiple of controller.params.control_interval_s of
    wall-clock time. Returns time (K,) s simulated, q, q_ref (K, ndof) rad, gh_stab (K,), compute_s (K,) (update and
    send, wall clock), age_s (K,) (how old the state was when its command left: reception to send), period_s (K-1,)
    (wall-clock time between sends), and their percentiles in microseconds. RuntimeError if no state arrives;
    an error of controller.update (e.g. its ValueError for a NaN state) or of send_stimulation is raised after a
    zero stimulation packet has been sent (best effort; the runner's timeout zeros it otherwise). ValueError for a
    NaN until_s, TypeError for a non-number."""
    until_s = real_scalar(until_s, "until_s")
    if math.isnan(until_s):   # no time passes NaN: the loop would never end
        raise ValueError("until_s must be a time in s (inf: until the runner stops), got nan")
    h = controller.params.control_interval_s
    if reference is None:
        reference = (lambda t: controller.reference(t)[0]) if hasattr(controller, "reference") else \
            (lambda t: controller.state.target)
    rec = {k: [] for k in ("time", "q", "q_ref", "gh_stab", "compute_s", "age_s", "sent_at")}
    next_wake = time.monotonic()
    while True:
        st = client.latest_state(timeout=1.0)
        if st is None:
            raise RuntimeError("no state packet from the runner within 1 s")
        t0 = time.monotonic()
        try:
            cmd = controller.update(st.time, st.q, st.qdot)
            client.send_stimulation(cmd)
        except BaseException:
            # A controller that refuses its input (a NaN state) or fails, or a command the client refuses, must not
            # leave the last command applied until the runner's timeout: zero stimulation goes out, then the error.
            _send_zero(client)
            raise
        t1 = time.monotonic()
        rec["time"].append(st.time)
        rec["q"].append(np.array(st.q))
        rec["q_ref"].append(reference(st.time))
        rec["gh_stab"].append(st.gh_stab)
        rec["compute_s"].append(t1 - t0)
        rec["age_s"].append(t1 - st.received_at)
        rec["sent_at"].append(t1)
        if st.time >= until_s or st.stopped:
            break
        next_wake += h
        pause = next_wake - time.monotonic()
        if pause > 0:
            time.sleep(pause)
        else:
            next_wake = time.monotonic()   # late: restart the schedule, do not burst
    out = {k: np.asarray(v) for k, v in rec.items()}
    out["period_s"] = np.diff(out.pop("sent_at"))
    out["compute_us"] = percentiles_us(out["compute_s"])
    out["age_us"] = percentiles_us(out["age_s"])
    out["period_us"] = percentiles_us(out["period_s"])
    return out
