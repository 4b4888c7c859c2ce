"""A decoder's hand-velocity commands (LSL) -> joint targets for a running `armrt-rt --static-optimization`, by
differential inverse kinematics on the engine's hand Jacobian. docs/tasks.md#end-to-end.

Law, every 1/rate_hz s (dt), on the desired posture q_d (kinematic control: the runner's computed-torque loop makes
the arm follow q_d; the arm's measured q is not fed back here, the decoder closes the loop through the cursor):
    J = hand_jacobian(q_d)                                   (3 x ndof, m/rad, thorax frame)
    dq = J^T (J J^T + lambda^2 I)^-1 v dt                    damped least squares (Nakamura & Hanafusa 1986,
                                                             J Dyn Syst Meas Control 108:163; Wampler 1986,
                                                             IEEE Trans Syst Man Cybern 16:93)
    q_d <- clip(q_d + dq, dof_ranges)                        joint limits: a joint stops at its range
    send_target(q_d, qdot_d = (q_d_new - q_d_old) / dt, qddot_d = 0)
A silent decoder (no sample for hold_s) gives v = 0: the last posture is held.

    python -m armrt.endpoint_target_controller --decoder dec --runner 127.0.0.1:45100 [--rate 200] [--out c.npz]
"""
from __future__ import annotations

import argparse
import math
import signal
import sys
import threading
import time

import numpy as np

from . import checks


def dls_step(J, v, dt_s: float, damping: float) -> np.ndarray:
    """Damped-least-squares joint step (ndof,) rad for a hand velocity v (3,) m/s over dt_s s with Jacobian J
    (3, ndof) m/rad: dq = J^T (J J^T + damping^2 I)^-1 v dt (Nakamura & Hanafusa 1986; Wampler 1986). damping in
    m/rad (0: the Moore-Penrose pseudo-inverse step, J dq = v dt exactly for a full-rank J)."""
    J = np.asarray(J, dtype=float)
    v = checks.real_array(v, "hand velocity")
    if J.ndim != 2 or J.shape[0] != 3 or v.shape != (3,):
        raise ValueError(f"J must be (3, ndof) and v (3,), got {J.shape} and {v.shape}")
    if not (np.all(np.isfinite(v)) and np.all(np.isfinite(J))):
        raise ValueError("J and v must be finite")
    A = J @ J.T + float(damping) ** 2 * np.eye(3)
    return J.T @ np.linalg.solve(A, v * float(dt_s))


class TargetController:
    """decoder (lsl_bridge.LslEndpointDecoder or anything with command() -> (velocity (3,) m/s or None, _) and
    poll()) -> joint targets sent with client (realtime.UdpClient, joined to a --static-optimization runner) every
    step(). model: armrt.Model of the runner; q0 (ndof,) rad: the start posture (the runner's arm where it is).
    Records: .sent (seq, send time monotonic s), .applied_latency_s (per target: the first state packet whose
    last_applied_seq >= its seq, received - sent: an upper bound of send -> applied including the state packet's
    trip), .received_stamps (each decoder sample's LSL timestamp) and .decoder_latency_s (LSL receive time - stamp)."""

    def __init__(self, model, client, decoder, q0, rate_hz: float = 200.0, damping: float = 0.01):
        self.model, self.client, self.decoder = model, client, decoder
        self.dt_s = 1.0 / checks.real_scalar(rate_hz, "rate_hz")
        if not (math.isfinite(self.dt_s) and self.dt_s > 0):
            raise ValueError(f"rate_hz must be a finite number > 0, got {rate_hz}")
        self.damping = checks.real_scalar(damping, "damping")
        if not (math.isfinite(self.damping) and self.damping >= 0):
            raise ValueError(f"damping must be a finite number >= 0 m/rad, got {damping}")
        self.ranges = np.asarray(model.dof_ranges, dtype=float)
        q = checks.real_array(q0, "q0")
        if q.shape != (model.n_dofs,) or not np.all(np.isfinite(q)):
            raise ValueError(f"q0 must be {model.n_dofs} finite joint angles (rad), got {q!r}")
        self.q_d = np.clip(q, self.ranges[:, 0], self.ranges[:, 1])
        self._pending: dict[int, float] = {}
        self.sent: list[tuple[int, float]] = []
        self.applied_latency_s: list[float] = []
        self.received_stamps: list[float] = []
        self.decoder_latency_s: list[float] = []
        self.last_applied_seq = -1
        self.states = 0

    def _take_decoder(self):
        if self.decoder is None:
            return
        cmds = self.decoder.poll()
        if cmds:
            now = self.decoder.pylsl.local_clock() if hasattr(self.decoder, "pylsl") else math.nan
            for c in cmds:
                self.received_stamps.append(c.timestamp)
                self.decoder_latency_s.append(now - c.timestamp)

    def velocity(self) -> np.ndarray:
        """The decoder's newest velocity (3,) m/s, zero when it went silent for its hold_s (or there is none yet:
        decoder None)."""
        self._take_decoder()
        if self.decoder is None:
            return np.zeros(3)
        fresh = self.decoder._last is not None and time.perf_counter() - self.decoder._last <= self.decoder.hold_s
        v = self.decoder.velocity if (fresh and self.decoder.velocity is not None) else np.zeros(3)
        return np.asarray(v, dtype=float)

    def step(self) -> int:
        """One control period: decoder -> DLS step -> clipped target sent; state packets read. Returns the seq."""
        v = self.velocity()
        J, _ = self.model.hand_jacobian(self.q_d)
        q_new = np.clip(self.q_d + dls_step(J, v, self.dt_s, self.damping), self.ranges[:, 0], self.ranges[:, 1])
        qdot = (q_new - self.q_d) / self.dt_s
        self.q_d = q_new
        seq = self.client.send_target(q_new, qdot, np.zeros_like(q_new))
        t = time.monotonic()
        self._pending[seq] = t
        self.sent.append((seq, t))
        self.read_states()
        return seq

    def read_states(self) -> None:
        while self.client.poll(0.0):
            pass
        for st in self.client.take_states():
            self.states += 1
            a = int(st.last_applied_seq)
            if a > self.last_applied_seq:
                self.last_applied_seq = a
            for s in [s for s in self._pending if s <= a]:
                self.applied_latency_s.append(st.received_at - self._pending.pop(s))

    def run(self, duration_s: float = math.inf, stop=None) -> None:
        """step() every dt_s s (a late period runs at once) for duration_s s or until stop() is true."""
        t0 = time.perf_counter()
        k = 0
        while (stop is None or not stop()) and k * self.dt_s < duration_s:
            late = time.perf_counter() - t0 - k * self.dt_s
            if late < 0:
                time.sleep(-late)
            self.step()
            k += 1
        time.sleep(0.05)
        self.read_states()


def main(argv=None) -> int:
    from . import realtime
    from .lsl_bridge import LslEndpointDecoder
    from .model import Model
    ap = argparse.ArgumentParser(prog="python -m armrt.endpoint_target_controller", description=__doc__.split("\n\n")[0])
    ap.add_argument("--decoder", required=True, help="name of the decoder's LSL endpoint-command stream")
    ap.add_argument("--runner", required=True, metavar="HOST:PORT", help="the runner's --listen address")
    ap.add_argument("--model", default="das2")
    ap.add_argument("--q0-deg", type=float, nargs="+", required=True, metavar="DEG",
                    help="the start posture: the runner's --q0, deg, one per DOF")
    ap.add_argument("--rate", type=float, default=200.0, help="targets sent per second")
    ap.add_argument("--damping", type=float, default=0.01, help="DLS damping, m/rad")
    ap.add_argument("--hold", type=float, default=0.5, help="s without a decoder sample before v = 0")
    ap.add_argument("--wait", type=float, default=30.0, help="s to wait for the decoder stream")
    ap.add_argument("--duration", type=float, default=math.inf, help="s (default: until SIGINT/SIGTERM)")
    ap.add_argument("--out", default=None, help=".npz of the records (sent, latencies, decoder stamps)")
    a = ap.parse_args(argv)
    host, port = realtime.parse_endpoint(a.runner)
    model = Model(a.model)
    stop = []
    signal.signal(signal.SIGTERM, lambda *_: stop.append(1))
    client = realtime.UdpClient(port, host, model=a.model)
    client.join(timeout=5.0)
    ctl = TargetController(model, client, None, np.radians(a.q0_deg), a.rate, a.damping)
    # The start posture is held (targets sent, v = 0) while the decoder's stream is looked for: a silent owner's
    # session ends after the runner's --timeout and its excitation falls to zero, so the arm would drop before the
    # task (whose centre is the hand where the arm is) and the decoder start.
    found = {}

    def resolve():
        try:
            found["decoder"] = LslEndpointDecoder(a.decoder, wait_s=a.wait, hold_s=a.hold)
        except Exception as exc:   # raised below, in the main thread
            found["error"] = exc
    threading.Thread(target=resolve, daemon=True).start()
    print(f"controller: holding the start posture, waiting up to {a.wait:g} s for the decoder {a.decoder!r}",
          flush=True)
    try:
        ctl.run(a.wait + 5.0, stop=lambda: bool(found) or bool(stop))
        if "error" in found:
            raise SystemExit(f"endpoint_target_controller: {found['error']}")
        if "decoder" not in found:
            raise SystemExit(f"endpoint_target_controller: no decoder stream {a.decoder!r} after {a.wait:g} s")
        dec = ctl.decoder = found["decoder"]
        if not dec.has[0]:
            raise SystemExit(f"endpoint_target_controller: the stream {a.decoder!r} has no hand_velocity channels")
        print(f"controller: decoder {a.decoder!r} -> targets to {a.runner} at {a.rate:g} Hz", flush=True)
        ctl.run(a.duration, stop=lambda: bool(stop))
    except KeyboardInterrupt:
        pass
    if a.out:
        np.savez(a.out, sent=np.array(ctl.sent), applied_latency_s=np.array(ctl.applied_latency_s),
                 received_stamps=np.array(ctl.received_stamps), decoder_latency_s=np.array(ctl.decoder_latency_s),
                 last_applied_seq=ctl.last_applied_seq, states=ctl.states)
    print(f"controller: {len(ctl.received_stamps)} decoder samples, {len(ctl.sent)} targets sent, last applied "
          f"seq {ctl.last_applied_seq}, {len(ctl._pending)} never seen applied", flush=True)
    client.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
