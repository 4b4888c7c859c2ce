"""Lab Streaming Layer bridge: a process next to the real-time runner (docs/realtime.md).

It publishes the runner's state packets as an LSL stream (channel labels, units and types in the
stream description, a stable source_id) and forwards the samples of an LSL excitation stream to the
runner as UDP excitation packets. It only forwards new samples: when the LSL controller goes silent
the runner's input timeout sets the excitation to zero, as with a direct UDP controller.

    armrt-rt --listen 127.0.0.1:45100 --state-to 127.0.0.1:45101 &
    python -m armrt.lsl_bridge --runner 127.0.0.1:45100 --state-port 45101 --mapping groups

Needs pylsl (pip install pylsl; its wheel bundles liblsl).
"""
from __future__ import annotations

import argparse
import select
import socket
import sys
import threading
import time

import numpy as np

from .realtime import GroupMapping, PacketError, State, decode_packet, encode_packet

DOFS = ["GHy", "GHz", "GHyy", "ELx", "PSy"]
STATE_LABELS = (["time"] + DOFS + [f"{d}_dot" for d in DOFS] + ["hand_x", "hand_y", "hand_z", "gh_stab"])
STATE_UNITS = ["s"] + ["rad"] * 5 + ["rad/s"] * 5 + ["m"] * 3 + ["1"]
STATE_TYPES = ["time"] + ["angle"] * 5 + ["angular_velocity"] * 5 + ["position"] * 3 + ["stability"]


def _pylsl():
    try:
        import pylsl
    except Exception as e:  # ImportError or RuntimeError (liblsl not loadable)
        raise RuntimeError(f"the LSL bridge needs pylsl with a loadable liblsl (pip install pylsl): {e}") from e
    return pylsl


def state_stream_info(pylsl, name: str, source_id: str, rate_hz: float, forces: list[str] | None = None,
                      model: str = "das2"):
    labels, units, types = list(STATE_LABELS), list(STATE_UNITS), list(STATE_TYPES)
    for f in forces or []:
        labels.append(f"force_{f}")
        units.append("N")
        types.append("force")
    info = pylsl.StreamInfo(name, "ArmState", len(labels), rate_hz, pylsl.cf_double64, source_id)
    desc = info.desc()
    desc.append_child_value("model", model)
    desc.append_child_value("frames", "q: DAS3 generalised coordinates; hand: thorax frame (docs/conventions.md)")
    chans = desc.append_child("channels")
    for lab, unit, typ in zip(labels, units, types):
        c = chans.append_child("channel")
        c.append_child_value("label", lab)
        c.append_child_value("unit", unit)
        c.append_child_value("type", typ)
    return info


class LslBridge:
    """State packets (UDP, from the runner) -> LSL outlet; LSL excitation inlet -> UDP packets.

    runner_port: the runner's --listen port (runner_address may be set later); state_port: where the
    runner sends state (--state-to); 0 picks a free port (see .state_port). source_id is stable
    (default "armrt-<model>"): the state stream is "<source_id>-state".
    """

    def __init__(self, runner_port: int, runner_host: str = "127.0.0.1", state_port: int = 0,
                 mapping: str = "groups", model: str = "das2", channels=None, source_id: str | None = None,
                 state_name: str = "armrt_state", excitation_name: str = "armrt_excitation",
                 state_rate_hz: float = 100.0, forces: bool = False):
        self.pylsl = _pylsl()
        self.runner_address = (runner_host, int(runner_port))
        self.mapping = GroupMapping.from_model(mapping, model, channels)
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind(("127.0.0.1" if runner_host in ("127.0.0.1", "localhost") else "", state_port))
        self.sock.setblocking(False)
        self.state_port = self.sock.getsockname()[1]
        self.source_id = source_id or f"armrt-{model}"
        self.excitation_name = excitation_name
        force_names = self.mapping.element_names if forces else None
        self.outlet = self.pylsl.StreamOutlet(
            state_stream_info(self.pylsl, state_name, f"{self.source_id}-state", state_rate_hz, force_names, model))
        self.inlet = None
        self.seq = 0
        self.forwarded = 0
        self.published = 0
        self.bad = 0

    def _connect_inlet(self) -> None:
        found = self.pylsl.resolve_byprop("name", self.excitation_name, timeout=0.2)
        if not found:
            return
        n = found[0].channel_count()
        if n != len(self.mapping.names):
            print(f"lsl_bridge: stream {self.excitation_name!r} has {n} channels; mapping {self.mapping.kind!r} "
                  f"needs {len(self.mapping.names)}; ignored", file=sys.stderr)
            return
        self.inlet = self.pylsl.StreamInlet(found[0], max_buflen=1, recover=True)

    def step(self) -> None:
        """One pass: forward pending excitation samples, publish pending state packets."""
        if self.inlet is None:
            self._connect_inlet()
        if self.inlet is not None:
            samples, _ = self.inlet.pull_chunk(timeout=0.0)
            if samples:  # only the newest matters
                self.seq = (self.seq + 1) & 0xFFFFFFFF
                v = np.asarray(samples[-1], dtype=float)
                self.sock.sendto(encode_packet(self.mapping.packet_type, self.seq, v), self.runner_address)
                self.forwarded += 1
        select.select([self.sock], [], [], 0.002)  # the pace of the bridge: at most 2 ms idle
        while True:  # drain what is pending, without waiting
            try:
                data = self.sock.recv(65536)
            except (BlockingIOError, InterruptedError):
                break
            try:
                st = State.from_packet(decode_packet(data))
            except PacketError:
                self.bad += 1
                continue
            sample = [st.time, *st.q, *st.qdot, *st.hand_position, st.gh_stab]
            if st.muscle_force is not None and self.outlet.channel_count > len(sample):
                sample += list(st.muscle_force)
            if len(sample) == self.outlet.channel_count:
                self.outlet.push_sample(sample, self.pylsl.local_clock())
                self.published += 1

    def run(self, stop: threading.Event | None = None, duration: float | None = None) -> None:
        t_end = None if duration is None else time.monotonic() + duration
        while not (stop is not None and stop.is_set()) and (t_end is None or time.monotonic() < t_end):
            self.step()

    def close(self) -> None:
        self.sock.close()


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m armrt.lsl_bridge", description=__doc__.split("\n\n")[0])
    ap.add_argument("--runner", default="127.0.0.1:45100", help="the runner's --listen HOST:PORT")
    ap.add_argument("--state-port", type=int, default=45101, help="UDP port the runner sends state to (--state-to)")
    ap.add_argument("--mapping", default="groups", choices=["elements", "muscles", "groups", "channels"])
    ap.add_argument("--channels", default="", help="comma-separated names for --mapping channels")
    ap.add_argument("--source-id", default=None)
    ap.add_argument("--state-name", default="armrt_state")
    ap.add_argument("--excitation-name", default="armrt_excitation")
    ap.add_argument("--rate", type=float, default=100.0, help="nominal state rate (the runner's --state-rate)")
    ap.add_argument("--forces", action="store_true", help="the runner sends forces (--forces)")
    ap.add_argument("--duration", type=float, default=None)
    a = ap.parse_args(argv)
    host, _, port = a.runner.rpartition(":")
    bridge = LslBridge(int(port), host or "127.0.0.1", a.state_port, a.mapping,
                       channels=[c for c in a.channels.split(",") if c], source_id=a.source_id,
                       state_name=a.state_name, excitation_name=a.excitation_name, state_rate_hz=a.rate,
                       forces=a.forces)
    print(f"lsl_bridge: state stream {a.state_name!r} (source_id {bridge.source_id}-state), "
          f"excitation stream {a.excitation_name!r} -> udp {a.runner}", flush=True)
    try:
        bridge.run(duration=a.duration)
    except KeyboardInterrupt:
        pass
    finally:
        bridge.close()
    print(f"lsl_bridge: forwarded {bridge.forwarded} excitation samples, published {bridge.published} states")
    return 0


if __name__ == "__main__":
    sys.exit(main())
