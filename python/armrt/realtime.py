"""Real-time sessions and the patient-in-the-loop UDP protocol (docs/realtime.md).

RealtimeSession runs the model at a fixed rate on a C++ thread (SCHED_FIFO when permitted) without
the GIL; UdpClient is a controller's end of the UDP link: it sends excitations (one value per element,
or muscle / group / channel values through a named mapping) and receives state packets.

    with RealtimeSession(listen="127.0.0.1:0", duration=5) as s:
        with UdpClient(s.port, mapping="groups") as c:
            c.send({"elbow_flexors": 0.2})
            print(c.recv_state(timeout=0.1).q)
    print(s.stats()["latency_ns"])
"""
from __future__ import annotations

import collections
import hashlib
import hmac
import os
import shutil
import socket
import struct
import sys
import time
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import Mapping, Sequence

import numpy as np

from . import _rt

# ---------------------------------------------------------------------------------------- packets
# The layout is defined once, in cpp/rt/packet.h; armrt._rt exports it and the codec is built from it.
MAGIC: bytes = _rt.MAGIC
VERSION: int = _rt.VERSION
# The GH values a state packet carries beside gh_stab (cpp/rt/packet.h), and StatePacket's fields of those names.
GH_RIM_FIELDS = ("gh_theta", "gh_phi", "gh_rim_margin", "gh_rim_direction")
HEADER_SIZE: int = _rt.HEADER_SIZE
MAX_VALUES: int = _rt.MAX_VALUES
TAG_SIZE: int = _rt.TAG_SIZE
HEADER_FIELDS = [tuple(f) for f in _rt.HEADER_FIELDS]  # (name, offset, size)


def _header_struct(fields) -> struct.Struct:
    codes = {2: "H", 4: "I"}
    fmt, pos = "<", 0
    for name, offset, size in sorted(fields, key=lambda f: f[1]):
        if offset != pos:
            raise RuntimeError(f"armrt._rt header field {name} at offset {offset}, expected {pos}")
        fmt += "4s" if name == "magic" else codes[size]
        pos += size
    if pos != HEADER_SIZE:
        raise RuntimeError(f"armrt._rt header fields cover {pos} bytes, HEADER_SIZE is {HEADER_SIZE}")
    return struct.Struct(fmt)


HEADER = _header_struct(HEADER_FIELDS)
_HEADER_NAMES = [f[0] for f in sorted(HEADER_FIELDS, key=lambda f: f[1])]
TYPES: dict = dict(_rt.TYPES)
FLAGS: dict = dict(_rt.FLAGS)
EXC_ELEMENTS, EXC_MUSCLES, EXC_GROUPS, EXC_CHANNELS = (TYPES[k] for k in ("elements", "muscles", "groups", "channels"))
RELEASE, HELLO, STATE, OFFER = (TYPES[k] for k in ("release", "hello", "state", "offer"))
FLAG_FORCES, FLAG_STOPPED, FLAG_ERROR, FLAG_TIMED_OUT = (FLAGS[k] for k in ("forces", "stopped", "error", "timed_out"))
FLAG_AUTH, FLAG_OVERRUN, FLAG_EXCITATION = (FLAGS[k] for k in ("auth", "overrun", "excitation"))


def state_packet_fields(model: str = "das2") -> list[dict]:
    """The state packet's table for `model` (cpp/rt/packet.h ARMRT_STATE_PACKET_FIELDS), in packet
    order: dicts of name, size, rule (one, dofs, three, elements), unit, flag (0: always sent, else the FLAGS bit that adds the row),
    integer, labels (one per value), lsl_type, description. The decoder and the LSL bridge read it."""
    return [dict(r) for r in _rt.state_packet_fields(model)]


def state_fields(model: str = "das2") -> list:
    """Labels of the values a state packet of `model` always carries, in order (they depend on its DOFs)."""
    return list(_rt.state_fields(model))


STATE_FIELDS: list = state_fields("das2")   # the default model's (das2: 22 values)
STATE_FIXED_VALUES = len(STATE_FIELDS)

MAPPING_TYPES = {"elements": EXC_ELEMENTS, "muscles": EXC_MUSCLES, "groups": EXC_GROUPS, "channels": EXC_CHANNELS}


def parse_endpoint(endpoint: str, require_port: bool = False) -> tuple[str, int]:
    """'host:port' -> (numeric IPv4 host, port), exactly as armrt-rt reads it (an empty host or
    'localhost' is 127.0.0.1, never "any"). Raises ValueError naming the problem."""
    return tuple(_rt.parse_endpoint(str(endpoint), require_port))


def read_key_file(path) -> bytes:
    """The shared key in a file, as armrt-rt --key-file reads it (one trailing newline removed);
    ValueError if shorter than 16 bytes."""
    key = Path(path).read_bytes()
    if key.endswith(b"\n"):
        key = key[:-1]
    if key.endswith(b"\r"):
        key = key[:-1]
    if len(key) < 16:
        raise ValueError(f"the key in {str(path)!r} is shorter than 16 bytes")
    return key


def _key_bytes(key) -> bytes | None:
    if key is None or key == b"" or key == "":
        return None
    k = key.encode() if isinstance(key, str) else bytes(key)
    if len(k) < 16:
        raise ValueError(f"the shared key must be at least 16 bytes (got {len(k)})")
    return k


class PacketError(ValueError):
    """A datagram that is not a valid armrt packet (the reason is in the message)."""


def encode_packet(ptype: int, seq: int, values=(), flags: int = 0, session: int = 0, key: bytes | None = None) -> bytes:
    """Header + float64 values, little-endian (docs/realtime.md); with key, the HMAC-SHA256 tag."""
    v = np.ascontiguousarray(values, dtype="<f8").ravel()
    if v.size > MAX_VALUES:
        raise ValueError(f"at most {MAX_VALUES} values per packet, got {v.size}")
    key = _key_bytes(key)
    if key is not None:
        flags |= FLAG_AUTH
    length = HEADER_SIZE + 8 * v.size + (TAG_SIZE if flags & FLAG_AUTH else 0)
    fields = {"magic": MAGIC, "version": VERSION, "type": ptype, "seq": seq & 0xFFFFFFFF, "length": length,
              "count": v.size, "flags": flags, "session": session & 0xFFFFFFFF}
    body = HEADER.pack(*(fields[n] for n in _HEADER_NAMES)) + v.tobytes()
    if key is not None:
        body += hmac.new(key, body, hashlib.sha256).digest()
    return body


@dataclass
class Packet:
    type: int
    seq: int
    flags: int
    values: np.ndarray
    session: int = 0


def decode_packet(data: bytes, key: bytes | None = None) -> Packet:
    """Checks magic, version and lengths as the runner does, and with key the HMAC tag; raises PacketError."""
    if len(data) < 4 or data[:4] != MAGIC:
        raise PacketError("bad magic")
    if len(data) < HEADER_SIZE:
        raise PacketError(f"short packet ({len(data)} bytes)")
    h = dict(zip(_HEADER_NAMES, HEADER.unpack_from(data)))
    if h["version"] != VERSION:
        raise PacketError(f"unsupported version {h['version']} (this client speaks {VERSION})")
    count, flags = h["count"], h["flags"]
    tag = TAG_SIZE if flags & FLAG_AUTH else 0
    if h["length"] != len(data) or HEADER_SIZE + 8 * count + tag != len(data) or count > MAX_VALUES:
        raise PacketError(f"size mismatch: datagram {len(data)} bytes, length field {h['length']}, count {count}")
    key = _key_bytes(key)
    if key is not None:
        if not tag:
            raise PacketError("unsigned packet (a shared key is in use)")
        if not hmac.compare_digest(hmac.new(key, data[:-TAG_SIZE], hashlib.sha256).digest(), data[-TAG_SIZE:]):
            raise PacketError("bad HMAC tag (wrong key or forged packet)")
    values = np.frombuffer(data, dtype="<f8", count=count, offset=HEADER_SIZE).copy()
    return Packet(h["type"], h["seq"], flags, values, h["session"])


_TABLES: dict = {}


def _table(table, n_elements: int | None = None) -> list[dict]:
    """A state packet table from a model name (cached), a table, or None (das2). A list of
    state_fields() labels (the older argument) gives the table of that many DOFs and n_elements."""
    if table is None or isinstance(table, str):
        name = table or "das2"
        if name not in _TABLES:
            _TABLES[name] = state_packet_fields(name)
        return _TABLES[name]
    rows = list(table)
    if rows and isinstance(rows[0], str):
        template = _table("das2")
        n_fixed_one = sum(r["size"] for r in template if r["flag"] == 0 and r["rule"] != "dofs")
        n_dofs = (len(rows) - n_fixed_one) // 2
        n_el = n_elements if n_elements is not None else next(r["size"] for r in template if r["rule"] == "elements")
        size = {"one": 1, "three": 3, "dofs": n_dofs, "elements": n_el}
        return [dict(r, size=size[r["rule"]]) for r in template]
    return rows


@dataclass
class StatePacket:
    """One state packet from the runner: one attribute per row of the packet table
    (state_packet_fields(); the optional rows are None when the packet does not carry them)."""

    seq: int
    time: float                 # s, simulated
    q: np.ndarray               # (n_dofs,) rad
    qdot: np.ndarray            # (n_dofs,) rad/s
    hand_position: np.ndarray   # (3,) m, thorax frame
    gh_stab: float              # 1, (theta/theta_a)^2 + (phi/phi_a)^2; > 1 beyond the rim
    last_applied_seq: int       # sequence number of the last excitation applied in this session (-1: none)
    flags: int
    lag: float = 0.0            # s, simulated time behind the wall-clock schedule (skipped periods)
    overruns: int = 0           # overrun cycles since the runner started
    muscle_force: np.ndarray | None = None  # (n,) N, if the runner sends forces (--forces)
    excitation: np.ndarray | None = None    # (n,) applied element excitations (--excitations)
    session: int = 0
    received_at: float = 0.0    # time.monotonic() at reception
    # The GH force where GHstab is (armrt.Arm.gh_rim, docs/conventions.md).
    gh_theta: float = float("nan")          # rad, from the glenoid normal along the major axis (+ superior)
    gh_phi: float = float("nan")            # rad, along the minor axis (+ anterior)
    gh_rim_margin: float = float("nan")     # rad, how far it can still turn towards the rim; < 0 beyond it
    gh_rim_direction: float = float("nan")  # rad, atan2(phi, theta): 0 superior, pi/2 anterior

    @property
    def stopped(self) -> bool:
        return bool(self.flags & FLAG_STOPPED)

    @property
    def diverged(self) -> bool:
        return bool(self.flags & FLAG_ERROR)

    @property
    def timed_out(self) -> bool:
        """No session: the excitation is zero (silence, release, or never claimed)."""
        return bool(self.flags & FLAG_TIMED_OUT)

    @property
    def overrun(self) -> bool:
        """At least one cycle overran since the previous state packet."""
        return bool(self.flags & FLAG_OVERRUN)

    @staticmethod
    def decode_values(p: Packet, table=None) -> dict:
        """{row name: value} of every row the packet carries (state_packet_fields(); a float or int
        for one-value rows, an array otherwise). PacketError if the packet's size does not fit the
        table: a runner of another model (das2's 22 fixed values, das3's 34) is refused, not decoded
        into wrong angles."""
        if p.type != STATE:
            raise PacketError(f"not a state packet (type {p.type})")
        rows = _table(table)
        present = [r for r in rows if r["flag"] == 0 or p.flags & r["flag"]]
        expect = sum(r["size"] for r in present)
        v = p.values
        if v.size != expect:
            raise PacketError(f"state packet with {v.size} values where this model's has {expect}: is the runner "
                              f"running another model (armrt-rt --model)?")
        out, k = {}, 0
        for r in present:
            n = r["size"]
            if r["rule"] == "one":
                out[r["name"]] = int(v[k]) if r["integer"] else float(v[k])
            else:
                out[r["name"]] = v[k:k + n].copy()
            k += n
        return out

    @classmethod
    def from_packet(cls, p: Packet, table=None, n_elements: int | None = None) -> "StatePacket":
        """table: the model's state_packet_fields() or its name (default das2). n_elements, if given,
        must agree with the table (kept for callers that pass it)."""
        rows = _table(table, n_elements)
        if n_elements is not None:
            sizes = {r["name"]: r["size"] for r in rows}
            if sizes.get("muscle_force", n_elements) != n_elements:
                raise PacketError(f"the table has {sizes['muscle_force']} elements, n_elements is {n_elements}")
        values = cls.decode_values(p, rows)
        return cls(seq=p.seq, flags=p.flags, session=p.session, **values)


def __getattr__(name):
    # The packet class was State, which is also the engine's snapshot (armrt.State).
    if name == "State":
        warnings.warn("armrt.realtime.State is deprecated: use armrt.realtime.StatePacket (armrt.State is the "
                      "engine's snapshot)", DeprecationWarning, stacklevel=2)
        return StatePacket
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


# ---------------------------------------------------------------------------------------- mappings
@dataclass
class GroupMapping:
    """How a controller's values become the model's element excitations (das2: 102).

    kind "elements": one value per element (dicts may name elements, muscles or groups);
    "muscles" / "groups": one value per muscle / group of the model, in the model's order;
    "channels": one value per configured name (element, muscle or group) - the runner must be started
    with the same names (armrt-rt --channels / RealtimeSession(channels=...)).
    Overlapping names (a group, a muscle of it, one of its elements) follow the engine's one rule
    (armrt._core.excitations_from_names, cpp/src/names.cc): the most specific name wins, in any
    order; names of equal specificity take the largest of their values.
    """

    kind: str
    names: list = field(default_factory=list)
    element_names: list = field(default_factory=list)
    index: dict = field(default_factory=dict)
    model: str = "das2"

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
            unknown = [c for c in channels if not _core.is_name(model, c)]
            if unknown:
                raise KeyError("channels: " + _core.unknown_names_message(model, list(unknown)))
            names = list(channels)
            # Aliases (OpenSim names) resolve through the engine's name service, as the runner does.
            index.update({c: list(_core.find_elements(model, c)) for c in names if c not in index})
        else:
            raise ValueError(f"unknown mapping {kind!r}; expected one of {list(MAPPING_TYPES)}")
        return cls(kind, names, elements, index, model)

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
                elif self.kind != "elements":
                    raise KeyError(f"{name!r} is not a value of mapping {self.kind!r} (names: {self.names[:8]}...)")
            if self.kind == "elements":
                from . import _core
                return np.asarray(_core.excitations_from_names(self.model, [(str(k), float(v))
                                                                            for k, v in excitation.items()]))
            return out
        arr = np.asarray(excitation, dtype=float).ravel()
        if arr.size != n:
            raise ValueError(f"mapping {self.kind!r} needs {n} values, got {arr.size}")
        return arr

    def to_elements(self, values) -> np.ndarray:
        """The element excitations the runner applies for these values (for checks and plots)."""
        v = self.values(values)
        if self.kind == "elements":
            return np.clip(v, 0, 1)
        from . import _core  # the rule the runner applies (names.h)
        return np.asarray(_core.excitations_from_names(self.model, list(zip(self.names, np.clip(v, 0, 1).tolist()))))


# ---------------------------------------------------------------------------------------- UDP client
class UdpClient:
    """A controller's end of the link: owns a session of the runner, sends excitations, receives state.

    port, host: the runner's --listen address. key: the runner's shared key (bytes, >= 16; see
    read_key_file), or None. The first send() asks for the session (hello -> offer, join()); packets
    carry the session id and, with a key, an HMAC-SHA256 tag. Incoming datagrams are accepted only
    from the runner's address and, with a key, only with a valid tag: anything else is dropped and
    counted (.foreign_packets, .bad_packets), never raised. When a session ends (silence longer than
    the runner's --timeout) the runner offers a new id on the next packet, and the client adopts it
    as soon as it reads the offer (recv_state / latest_state / join()).
    """

    def __init__(self, port: int, host: str = "127.0.0.1", mapping: str | GroupMapping = "elements",
                 model: str = "das2", channels: Sequence[str] | None = None, bind_port: int = 0,
                 key: bytes | str | None = None):
        self.address = parse_endpoint(f"{host}:{int(port)}")
        self.state_fields = state_fields(model)
        self.state_table = state_packet_fields(model)
        self.mapping = mapping if isinstance(mapping, GroupMapping) else GroupMapping.from_model(mapping, model, channels)
        self.key = _key_bytes(key)
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind(("127.0.0.1" if self.address[0].startswith("127.") else "", bind_port))
        self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 1 << 20)
        self.seq = 0
        self.session = 0
        self.bad_packets = 0       # malformed, unsigned or wrongly signed datagrams
        self.foreign_packets = 0   # datagrams from anyone but the runner
        self.last_state: StatePacket | None = None
        self.last_error = ""       # why the last bad datagram was refused
        self._states: collections.deque = collections.deque(maxlen=4096)

    @property
    def local_port(self) -> int:
        return self.sock.getsockname()[1]

    def _next_seq(self) -> int:
        self.seq = (self.seq + 1) & 0xFFFFFFFF
        return self.seq

    def _pump(self, timeout: float | None) -> bool:
        """Reads one datagram (waiting up to timeout s; None: forever); True if one was read."""
        self.sock.settimeout(timeout)
        try:
            data, src = self.sock.recvfrom(65536)
        except (socket.timeout, BlockingIOError):
            return False
        if (src[0], src[1]) != self.address:
            self.foreign_packets += 1
            return True
        try:
            p = decode_packet(data, self.key)
            if p.type == OFFER:
                self.session = p.session
            elif p.type == STATE:
                st = StatePacket.from_packet(p, self.state_table)
                st.received_at = time.monotonic()
                if not st.timed_out:
                    self.session = st.session
                self._states.append(st)
            else:
                self.bad_packets += 1
        except PacketError as exc:
            self.bad_packets += 1
            self.last_error = str(exc)
        return True

    def poll(self, timeout: float | None = 0.0) -> bool:
        """Reads one datagram if one comes within timeout s (offers update .session, state packets are
        queued for recv_state / take_states); True if one was read."""
        return self._pump(timeout)

    def take_states(self) -> list[StatePacket]:
        """The state packets read so far and not yet returned, oldest first."""
        out = list(self._states)
        self._states.clear()
        if out:
            self.last_state = out[-1]
        return out

    def join(self, timeout: float = 1.0) -> int:
        """Asks the runner for its session id and waits for the offer; returns it. TimeoutError if
        none comes (the runner is not there, another controller owns the session, --allow or the key
        refuses this one)."""
        self.session = 0
        t_end = time.monotonic() + timeout
        next_hello = 0.0
        while self.session == 0:
            now = time.monotonic()
            if now >= t_end:
                raise TimeoutError(f"no session offer from {self.address[0]}:{self.address[1]} within {timeout} s "
                                   "(runner not listening, session owned by another controller, or refused by "
                                   "--allow / the key)")
            if now >= next_hello:
                self.sock.sendto(encode_packet(HELLO, self._next_seq(), key=self.key), self.address)
                next_hello = now + 0.05
            self._pump(min(0.01, t_end - now))
        return self.session

    def send(self, excitation, seq: int | None = None) -> int:
        """Sends one excitation packet (array or dict through the mapping); returns its sequence number.
        Joins the session first if none is known (TimeoutError if that fails)."""
        if self.session == 0:
            self.join()
        if seq is None:
            seq = self._next_seq()
        data = encode_packet(self.mapping.packet_type, seq, self.mapping.values(excitation),
                             session=self.session, key=self.key)
        self.sock.sendto(data, self.address)
        return seq

    def send_raw(self, data: bytes) -> None:
        self.sock.sendto(data, self.address)

    def release(self) -> None:
        """Ends the session (the runner sets the excitation to zero at once and accepts a new owner)."""
        if self.session:
            self.sock.sendto(encode_packet(RELEASE, self._next_seq(), session=self.session, key=self.key), self.address)
            self.session = 0

    def recv_state(self, timeout: float | None = 0.1) -> StatePacket | None:
        """The next state packet from the runner (None after timeout s)."""
        deadline = None if timeout is None else time.monotonic() + timeout
        while not self._states:
            remaining = None if deadline is None else deadline - time.monotonic()
            if remaining is not None and remaining <= 0:
                self._pump(0.0)
                if not self._states:
                    return None
                break
            self._pump(remaining)
        st = self._states.popleft()
        self.last_state = st
        return st

    def latest_state(self, timeout: float = 0.1) -> StatePacket | None:
        """Waits for a state packet, then drains the queue and returns the newest one."""
        st = self.recv_state(timeout)
        if st is None:
            return None
        while self._pump(0.0):
            pass
        while self._states:
            st = self._states.popleft()
        self.last_state = st
        return st

    def close(self) -> None:
        try:
            self.release()
        except OSError:
            pass
        self.sock.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def _max_activation_items(values, model: str) -> list[str]:
    """{name: value} or an array of one value per element -> the runner's "NAME=VALUE" items."""
    from .arm import real_array, real_scalar
    if isinstance(values, Mapping):
        items = [(str(k), real_scalar(v, f"max_activation[{k!r}]")) for k, v in values.items()]
    else:
        from . import _core
        names = [e["name"] for e in _core.model_info(model)["elements"]]
        arr = real_array(values, "max_activation").ravel()
        if arr.size != len(names):
            raise ValueError(f"max_activation must have {len(names)} values (one per element), got {arr.size}")
        items = list(zip(names, arr.tolist()))
    bad = [f"{k}={v}" for k, v in items if not 0.0 <= v <= 1.0]
    if bad:
        raise ValueError(f"max_activation must lie in [0, 1]: {bad[:5]}")
    return [f"{k}={v!r}" for k, v in items]


# ---------------------------------------------------------------------------------------- session
class RealtimeSession:
    """The real-time loop in-process: a C++ thread steps the model at rate_hz (SCHED_FIFO at
    `priority` when permitted, else normal scheduling with a note in stats()["rt_note"]; with
    require_rt=True start() raises instead). The loop never takes the GIL.

    Parameters are those of armrt-rt (docs/realtime.md): model, integrator, rate_hz, integration_step
    (the integrator's largest step, s; `dt`, its old name, is deprecated: dt is the control step, here
    1/rate_hz), q0, duration,
    realtime, priority, lock_memory (mlockall of the whole Python process; off by default), require_rt,
    cpu, busy_wait_us, max_lag, listen ("127.0.0.1:0" for an ephemeral port), state_to (one "host:port"
    or a list), allow (list of "host[:port]"), key (bytes >= 16), state_rate_hz, send_forces,
    send_excitation, input_timeout, channels, rx_budget_us, max_activation ({name: value} of elements,
    muscles or groups, or one value per element, in [0, 1]: paralysis and weakness; every excitation,
    and the excitations streamed with send_excitation, are capped at it). Bad values raise ValueError
    naming the option.
    """

    def __init__(self, **config):
        from . import _rt
        if "dt" in config:
            if "integration_step" in config:
                raise ValueError("dt (deprecated) and integration_step both given; use integration_step")
            warnings.warn("RealtimeSession(dt=...) is deprecated: use integration_step (dt is the control step, "
                          "here 1/rate_hz)", DeprecationWarning, stacklevel=2)
            config["integration_step"] = config.pop("dt")
        if "model" in config and not isinstance(config["model"], str) or str(config.get("model", "")).endswith(".json"):
            from .model import Model
            config["model"] = Model(config["model"]).name  # a Model or a model file: loaded and registered
        if "q0" in config and config["q0"] is not None:
            config["q0"] = [float(x) for x in np.asarray(config["q0"], dtype=float).ravel()]
        elif "q0" in config:
            del config["q0"]
        if "channels" in config:
            config["channels"] = list(config["channels"] or [])
        if config.get("max_activation") is not None:
            config["max_activation"] = _max_activation_items(config["max_activation"], config.get("model", "das2"))
        else:
            config.pop("max_activation", None)
        for name in ("state_to", "allow"):
            if isinstance(config.get(name), str):
                config[name] = [config[name]] if config[name] else []
            elif name in config:
                config[name] = list(config[name] or [])
        if "key" in config:
            config["key"] = _key_bytes(config["key"]) or b""
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


def runner_args(argv: list[str]) -> list[str]:
    """The runner's arguments: `--model FILE.json` (or --model=FILE.json) becomes the model built on demand
    (armrt.Model.load, cached) as `--model-library LIB --model NAME`; everything else is passed as is."""
    out, k = [], 0
    while k < len(argv):
        a = argv[k]
        value = a.split("=", 1)[1] if a.startswith("--model=") else argv[k + 1] if a == "--model" and k + 1 < len(argv) else None
        if value is not None and (value.endswith(".json") or os.sep in value):
            from .model_build import build
            res = build(value)
            out += ["--model-library", str(res.library), "--model", res.name]
            k += 1 if a.startswith("--model=") else 2
            continue
        out.append(a)
        k += 1
    return out


def rt_main() -> None:
    """Console entry point `armrt-rt`: runs the shipped C++ runner with the same arguments (a model file
    given to --model is built on demand first)."""
    exe = runner_path()
    try:
        args = runner_args(sys.argv[1:])
    except (OSError, ValueError, RuntimeError) as exc:
        print(f"armrt-rt: {exc}", file=sys.stderr)
        sys.exit(2)
    os.execv(exe, [exe, *args])


if __name__ == "__main__":
    rt_main()
