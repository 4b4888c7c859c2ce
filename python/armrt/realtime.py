"""Real-time sessions and the patient-in-the-loop UDP protocol (docs/realtime.md).

RealtimeSession runs the model at a fixed rate on a C++ thread (SCHED_FIFO when permitted) without
the GIL; UdpClient is a controller's end of the UDP link: it sends excitations (102 element values,
or muscle / group / channel values through a named mapping) and receives state packets.

    with RealtimeSession(listen="127.0.0.1:0", duration=5) as s:
        with UdpClient(s.port, mapping="groups") as c:
            c.send({"elbow_flexors": 0.2})
            print(c.recv_state(timeout=0.1).q)
    print(s.stats()["latency_ns"])
"""
from __future__ import annotations

import os
import shutil
import socket
import struct
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Mapping, Sequence

import numpy as np

# ---------------------------------------------------------------------------------------- packets
MAGIC = b"ARMR"
VERSION = 1
HEADER = struct.Struct("<4sHHIIHHI")  # magic, version, type, seq, length, count, flags, reserved
HEADER_SIZE = HEADER.size             # 24
MAX_VALUES = 512

EXC_ELEMENTS, EXC_MUSCLES, EXC_GROUPS, EXC_CHANNELS, STATE = 1, 2, 3, 4, 16
FLAG_FORCES, FLAG_STOPPED, FLAG_ERROR, FLAG_TIMED_OUT = 1, 2, 4, 8
STATE_FIXED_VALUES = 16  # time, q[5], qdot[5], hand[3], gh_stab, last applied seq

MAPPING_TYPES = {"elements": EXC_ELEMENTS, "muscles": EXC_MUSCLES, "groups": EXC_GROUPS, "channels": EXC_CHANNELS}


class PacketError(ValueError):
    """A datagram that is not a valid armrt packet (the reason is in the message)."""


def encode_packet(ptype: int, seq: int, values, flags: int = 0) -> bytes:
    """Header + float64 values, little-endian (docs/realtime.md)."""
    v = np.ascontiguousarray(values, dtype="<f8").ravel()
    if v.size > MAX_VALUES:
        raise ValueError(f"at most {MAX_VALUES} values per packet, got {v.size}")
    length = HEADER_SIZE + 8 * v.size
    return HEADER.pack(MAGIC, VERSION, ptype, seq & 0xFFFFFFFF, length, v.size, flags, 0) + v.tobytes()


@dataclass
class Packet:
    type: int
    seq: int
    flags: int
    values: np.ndarray


def decode_packet(data: bytes) -> Packet:
    """Checks magic, version and lengths as the runner does; raises PacketError."""
    if len(data) < 4 or data[:4] != MAGIC:
        raise PacketError("bad magic")
    if len(data) < HEADER_SIZE:
        raise PacketError(f"short packet ({len(data)} bytes)")
    magic, version, ptype, seq, length, count, flags, _ = HEADER.unpack_from(data)
    if version != VERSION:
        raise PacketError(f"unsupported version {version} (this client speaks {VERSION})")
    if length != len(data) or HEADER_SIZE + 8 * count != len(data) or count > MAX_VALUES:
        raise PacketError(f"size mismatch: datagram {len(data)} bytes, length field {length}, count {count}")
    return Packet(ptype, seq, flags, np.frombuffer(data, dtype="<f8", count=count, offset=HEADER_SIZE).copy())


@dataclass
class State:
    """One state packet from the runner."""

    seq: int
    time: float                 # s, simulated
    q: np.ndarray               # (5,) rad
    qdot: np.ndarray            # (5,) rad/s
    hand_position: np.ndarray   # (3,) m, thorax frame
    gh_stab: float
    last_applied_seq: int       # sequence number of the last excitation applied (-1: none)
    flags: int
    muscle_force: np.ndarray | None = None  # (n,) N, if the runner sends forces
    received_at: float = 0.0    # time.monotonic() at reception

    @property
    def stopped(self) -> bool:
        return bool(self.flags & FLAG_STOPPED)

    @property
    def diverged(self) -> bool:
        return bool(self.flags & FLAG_ERROR)

    @property
    def timed_out(self) -> bool:
        return bool(self.flags & FLAG_TIMED_OUT)

    @classmethod
    def from_packet(cls, p: Packet) -> "State":
        if p.type != STATE:
            raise PacketError(f"not a state packet (type {p.type})")
        v = p.values
        if v.size < STATE_FIXED_VALUES:
            raise PacketError(f"state packet with {v.size} values, expected at least {STATE_FIXED_VALUES}")
        forces = v[STATE_FIXED_VALUES:].copy() if p.flags & FLAG_FORCES else None
        return cls(p.seq, float(v[0]), v[1:6].copy(), v[6:11].copy(), v[11:14].copy(), float(v[14]),
                   int(v[15]), p.flags, forces)


# ---------------------------------------------------------------------------------------- mappings
@dataclass
class GroupMapping:
    """How a controller's values become the 102 element excitations.

    kind "elements": 102 values (dicts may name elements, muscles or groups);
    "muscles" / "groups": one value per muscle / group of the model, in the model's order;
    "channels": one value per configured name (element, muscle or group) - the runner must be started
    with the same names (armrt-rt --channels / RealtimeSession(channels=...)).
    An element in several groups or channels takes the largest of their values.
    """

    kind: str
    names: list = field(default_factory=list)
    element_names: list = field(default_factory=list)
    index: dict = field(default_factory=dict)

    @classmethod
    def from_model(cls, kind: str = "elements", model: str = "das2", channels: Sequence[str] | None = None):
        from . import _core
        info = _core.model_info(model)
        elements = [e["name"] for e in info["elements"]]
        index = {n: [i] for i, n in enumerate(elements)}
        index.update({m: list(ix) for m, ix in info["muscles"]})
        index.update({g: list(ix) for g, ix in info["groups"]})
        if kind == "elements":
            names = elements
        elif kind == "muscles":
            names = [m for m, _ in info["muscles"]]
        elif kind == "groups":
            names = [g for g, _ in info["groups"]]
        elif kind == "channels":
            if not channels:
                raise ValueError("mapping 'channels' needs the channel names")
            unknown = [c for c in channels if c not in index]
            if unknown:
                raise KeyError(f"unknown channel names {unknown} (element, muscle or group names)")
            names = list(channels)
        else:
            raise ValueError(f"unknown mapping {kind!r}; expected one of {list(MAPPING_TYPES)}")
        return cls(kind, names, elements, index)

    @property
    def packet_type(self) -> int:
        return MAPPING_TYPES[self.kind]

    def values(self, excitation) -> np.ndarray:
        """An array (one value per name) from an array or a {name: value} dict."""
        n = len(self.names)
        if isinstance(excitation, Mapping):
            out = np.zeros(n)
            pos = {name: k for k, name in enumerate(self.names)}
            for name, v in excitation.items():
                if name in pos:
                    out[pos[name]] = v
                elif self.kind == "elements" and name in self.index:
                    out[self.index[name]] = v
                else:
                    raise KeyError(f"{name!r} is not a value of mapping {self.kind!r} (names: {self.names[:8]}...)")
            return out
        arr = np.asarray(excitation, dtype=float).ravel()
        if arr.size != n:
            raise ValueError(f"mapping {self.kind!r} needs {n} values, got {arr.size}")
        return arr

    def to_elements(self, values) -> np.ndarray:
        """The 102 element excitations the runner applies for these values (for checks and plots)."""
        v = self.values(values)
        if self.kind == "elements":
            return np.clip(v, 0, 1)
        u = np.zeros(len(self.element_names))
        for name, x in zip(self.names, v):
            ix = self.index[name]
            u[ix] = np.maximum(u[ix], np.clip(x, 0, 1))
        return u


# ---------------------------------------------------------------------------------------- UDP client
class UdpClient:
    """A controller's end of the link: send excitations, receive state packets (non-blocking socket
    with timeouts; never raises on a malformed incoming datagram, it is counted in .bad_packets)."""

    def __init__(self, port: int, host: str = "127.0.0.1", mapping: str | GroupMapping = "elements",
                 model: str = "das2", channels: Sequence[str] | None = None, bind_port: int = 0):
        self.address = (host, int(port))
        self.mapping = mapping if isinstance(mapping, GroupMapping) else GroupMapping.from_model(mapping, model, channels)
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind(("127.0.0.1" if host in ("127.0.0.1", "localhost") else "", bind_port))
        self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 1 << 20)
        self.seq = 0
        self.bad_packets = 0
        self.last_state: State | None = None

    @property
    def local_port(self) -> int:
        return self.sock.getsockname()[1]

    def send(self, excitation, seq: int | None = None) -> int:
        """Sends one excitation packet (array or dict through the mapping); returns its sequence number."""
        if seq is None:
            self.seq = (self.seq + 1) & 0xFFFFFFFF
            seq = self.seq
        self.sock.sendto(encode_packet(self.mapping.packet_type, seq, self.mapping.values(excitation)), self.address)
        return seq

    def send_raw(self, data: bytes) -> None:
        self.sock.sendto(data, self.address)

    def recv_state(self, timeout: float | None = 0.1) -> State | None:
        """The next state packet (None after timeout s)."""
        import time
        self.sock.settimeout(timeout)
        deadline = None if timeout is None else time.monotonic() + timeout
        while True:
            try:
                data = self.sock.recv(65536)
            except (socket.timeout, BlockingIOError):
                return None
            try:
                st = State.from_packet(decode_packet(data))
                st.received_at = time.monotonic()
                self.last_state = st
                return st
            except PacketError:
                self.bad_packets += 1
                if deadline is not None:
                    remaining = deadline - time.monotonic()
                    if remaining <= 0:
                        return None
                    self.sock.settimeout(remaining)

    def latest_state(self, timeout: float = 0.1) -> State | None:
        """Waits for a state packet, then drains the queue and returns the newest one."""
        st = self.recv_state(timeout)
        if st is None:
            return None
        while True:
            nxt = self.recv_state(0.0)
            if nxt is None:
                return st
            st = nxt

    def close(self) -> None:
        self.sock.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


# ---------------------------------------------------------------------------------------- session
class RealtimeSession:
    """The real-time loop in-process: a C++ thread steps the model at rate_hz (SCHED_FIFO at
    `priority` when permitted, else normal scheduling with a note in stats()["rt_note"]; with
    require_rt=True start() raises instead). The loop never takes the GIL.

    Parameters are those of armrt-rt (docs/realtime.md): model, integrator, rate_hz, dt, q0, duration,
    realtime, priority, lock_memory (mlockall of the whole Python process; off by default), require_rt,
    cpu, busy_wait_us, record_capacity, listen ("127.0.0.1:0" for an ephemeral port), state_to,
    state_rate_hz, send_forces, input_timeout, channels.
    """

    def __init__(self, **config):
        from . import _rt
        if "q0" in config and config["q0"] is not None:
            config["q0"] = [float(x) for x in np.asarray(config["q0"], dtype=float).ravel()]
        elif "q0" in config:
            del config["q0"]
        if "channels" in config:
            config["channels"] = list(config["channels"] or [])
        self.config = dict(config)
        self._loop = _rt.RtLoop(**config)
        self._started = False

    @property
    def port(self) -> int:
        """UDP port the loop listens on (0 without `listen`)."""
        return self._loop.port

    @property
    def running(self) -> bool:
        return self._loop.running

    @property
    def finished(self) -> bool:
        return self._loop.finished

    def start(self) -> "RealtimeSession":
        self._loop.start()
        self._started = True
        return self

    def wait(self, timeout: float | None = None) -> bool:
        """Waits for the loop to end by itself (duration, divergence); True if it has."""
        return self._loop.wait(-1.0 if timeout is None else float(timeout))

    def stop(self) -> dict:
        """Stops the loop (if running) and returns the final statistics."""
        self._loop.stop()
        return self.stats()

    def stats(self) -> dict:
        """TET, cycle time and wake-up latency percentiles (ns), overruns, packet counters, scheduler."""
        return self._loop.stats()

    def stats_json(self) -> str:
        return self._loop.stats_json()

    def __enter__(self):
        if not self._started:
            self.start()
        return self

    def __exit__(self, *exc):
        self.stop()


# ---------------------------------------------------------------------------------------- runner
def runner_path() -> str:
    """Path of the armrt-rt executable: shipped in the package (armrt/bin), on PATH, or in a build tree."""
    here = Path(__file__).resolve().parent
    candidates = [here / "bin" / "armrt-rt"]
    on_path = shutil.which("armrt-rt")
    if on_path:
        candidates.append(Path(on_path))
    root = here.parent.parent
    candidates += sorted((root / "build").glob("*/cpp/rt/armrt-rt"), key=lambda p: p.stat().st_mtime, reverse=True)
    for c in candidates:
        if c.is_file() and os.access(c, os.X_OK) and c.resolve() != Path(sys.argv[0]).resolve():
            return str(c)
    raise FileNotFoundError("armrt-rt not found: install armrt (pip install .) or build it with CMake (target armrt-rt)")


def rt_main() -> None:
    """Console entry point `armrt-rt`: runs the shipped C++ runner with the same arguments."""
    exe = runner_path()
    os.execv(exe, [exe, *sys.argv[1:]])


if __name__ == "__main__":
    rt_main()
