"""armrt._rt's packet layout (cpp/rt/packet.h) + values -> datagram bytes; datagram bytes -> Packet / StatePacket.

The packet codec of the armrt-rt UDP protocol (docs/realtime.md): the header struct, the packet types and
flags, the state packet table, the shared key and its HMAC-SHA256 tag. No sockets here (armrt.realtime_client).
"""
from __future__ import annotations

import hashlib
import hmac
import struct
from dataclasses import dataclass
from pathlib import Path

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
STIMULATION: int = TYPES["stimulation"]
SESSION_ENDED: int = TYPES["session_ended"]  # runner -> a timed-out owner: [reason (1 timeout), hold s, grace s]
TARGET: int = TYPES["target"]  # --static-optimization: desired q, qdot, qddot
FLAG_FORCES, FLAG_STOPPED, FLAG_ERROR, FLAG_TIMED_OUT = (FLAGS[k] for k in ("forces", "stopped", "error", "timed_out"))
FLAG_AUTH, FLAG_OVERRUN, FLAG_EXCITATION = (FLAGS[k] for k in ("auth", "overrun", "excitation"))
FLAG_STIMULATION: int = FLAGS["stimulation"]


def state_packet_fields(model: str = "das2", channels=()) -> list[dict]:
    """The state packet's table for `model` (cpp/rt/packet.h ARMRT_STATE_PACKET_FIELDS), in packet
    order: dicts of name, size, rule (one, dofs, three, elements, channels, channel_inputs), unit, flag (0: always
    sent, else the FLAGS bit that adds the row), integer, labels (one per value), lsl_type, description. channels:
    the runner's stimulation channel names (its --stimulation map, in order); they size the stimulation rows
    (labels "<channel>/pulse_width", "/amplitude", "/frequency", "<channel>/fatigue"). The decoder and the LSL
    bridge read it."""
    return [dict(r) for r in _rt.state_packet_fields(model, [str(c) for c in channels])]


def state_fields(model: str = "das2") -> list:
    """Labels of the values a state packet of `model` always carries, in order (they depend on its DOFs)."""
    return list(_rt.state_fields(model))


STATE_FIELDS: list = state_fields("das2")   # the default model's (das2: 22 values)
STATE_FIXED_VALUES = len(STATE_FIELDS)


def read_key_file(path) -> bytes:
    """The shared key in a file, as armrt-rt --key-file reads it (one trailing newline removed): the runner's own
    reader (cpp/rt/hmac.cc read_key_file, through armrt._rt), so both sides apply one set of rules.

    As ssh treats a private key: ValueError if the file is not a regular file (a device such as /dev/zero, a
    FIFO, a directory), is accessible by group or others (chmod 600 it), is larger than 4096 bytes or holds fewer
    than 16 bytes; OSError (FileNotFoundError, PermissionError, ...) if it cannot be opened."""
    import os
    return _rt.read_key_file(os.fsdecode(os.fspath(path)))


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
        size = {"one": 1, "three": 3, "dofs": n_dofs, "elements": n_el, "channels": 0, "channel_inputs": 0}
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
    # With a stimulation map (--stimulation): the applied command (channels, 3: pulse width s, amplitude A,
    # frequency Hz; after the runner's clamp to the channels' limits) and each channel's fatigue, 1 - A/A_rest.
    stimulation: np.ndarray | None = None
    fatigue: np.ndarray | None = None
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
        stim = [r for r in present if r["rule"] == "channel_inputs"]
        if v.size != expect and stim and stim[0]["size"] == 0:
            raise PacketError("the runner sends stimulation (armrt-rt --stimulation): decode with the map's channels, "
                              "state_packet_fields(model, channels) / UdpClient(stimulation=...)")
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
        if "stimulation" in values:
            values["stimulation"] = values["stimulation"].reshape(-1, 3)
        return cls(seq=p.seq, flags=p.flags, session=p.session, **values)
