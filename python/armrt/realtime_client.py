"""The runner's address + excitations (array or {name: value} via a mapping) -> excitation packets out, StatePackets in.

GroupMapping turns a controller's values (elements, muscles, groups or channels of the model) into the
packet the runner reads; UdpClient is a controller's end of the link (session join / release, the key,
the incoming state queue). The bytes themselves are armrt.realtime_packets'.
"""
from __future__ import annotations

import collections
import socket
import struct
import sys
import time
from dataclasses import dataclass, field
from typing import Mapping, Sequence

import numpy as np

from . import _rt
from .realtime_packets import (EXC_CHANNELS, EXC_ELEMENTS, EXC_GROUPS, EXC_MUSCLES, HELLO, OFFER, RELEASE,
                               SESSION_ENDED, STATE, STIMULATION, TARGET, PacketError, StatePacket, _key_bytes, decode_packet, encode_packet,
                               state_fields, state_packet_fields)

MAPPING_TYPES = {"elements": EXC_ELEMENTS, "muscles": EXC_MUSCLES, "groups": EXC_GROUPS, "channels": EXC_CHANNELS}

# Linux's SO_TIMESTAMPNS (= SCM_TIMESTAMPNS; asm-generic/socket.h, not in Python's socket module): each datagram's
# arrival time (CLOCK_REALTIME) in a recvmsg control message, so a packet read late keeps the time it came.
_SO_TIMESTAMPNS = 35 if sys.platform.startswith("linux") else None
_TIMESPEC = struct.Struct("qq")


def _arrival(ancillary) -> float:
    """time.monotonic() at which the kernel received the datagram (its SO_TIMESTAMPNS), else now."""
    now = time.monotonic()
    for level, kind, data in ancillary:
        if level == socket.SOL_SOCKET and kind == _SO_TIMESTAMPNS and len(data) >= _TIMESPEC.size:
            sec, nsec = _TIMESPEC.unpack_from(data)
            return min(now, now - (time.time() - (sec + 1e-9 * nsec)))
    return now


def parse_endpoint(endpoint: str, require_port: bool = False) -> tuple[str, int]:
    """'host:port' -> (numeric IPv4 host, port), exactly as armrt-rt reads it (an empty host or
    'localhost' is 127.0.0.1, never "any"). Raises ValueError naming the problem."""
    return tuple(_rt.parse_endpoint(str(endpoint), require_port))


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
        from .checks import real_array, real_scalar  # noqa: PLC0415 (as send_target imports them)
        n = len(self.names)
        if isinstance(excitation, Mapping):
            out = np.zeros(n)
            pos = {name: k for k, name in enumerate(self.names)}
            for name, v in excitation.items():
                # real_scalar: a string "0.3" is refused, as Arm.set_excitation refuses it (float() accepted it).
                v = real_scalar(v, f"excitation[{name!r}]", booleans=False)
                if name in pos:
                    out[pos[name]] = v
                elif self.kind != "elements":
                    raise KeyError(f"{name!r} is not a value of mapping {self.kind!r} (names: {self.names[:8]}...)")
            if self.kind == "elements":
                from . import _core
                return np.asarray(_core.excitations_from_names(self.model, [(str(k), float(v))
                                                                            for k, v in excitation.items()]))
            return out
        arr = real_array(excitation, "excitation", booleans=False)
        if arr.shape != (n,):  # (n, 1) too, as Arm.set_excitation: a column is not silently flattened
            raise ValueError(f"mapping {self.kind!r} needs {n} values, shape ({n},), got shape {arr.shape}")
        return arr

    def to_elements(self, values) -> np.ndarray:
        """The element excitations the runner applies for these values (for checks and plots)."""
        v = self.values(values)
        if self.kind == "elements":
            return np.clip(v, 0, 1)
        from . import _core  # the rule the runner applies (names.h)
        return np.asarray(_core.excitations_from_names(self.model, list(zip(self.names, np.clip(v, 0, 1).tolist()))))


class StimulationChannels:
    """The runner's stimulation map on the controller's side: its channels in order, and the engine's own check
    of a command against each channel's limits (armrt.Arm.set_stimulation's), so a client refuses what the
    Python API refuses before it is sent; the runner refuses (and counts, stimulation_refused) whatever still
    arrives beyond them, holding the previous command.

    model: the runner's --model; stimulation: the same map as its --stimulation ("per_muscle", a .json/.toml
    path or a dict). ValueError / FileNotFoundError as Arm(model, stimulation=...)."""

    def __init__(self, model: str, stimulation):
        from .arm import Arm  # one reader of maps: the engine's (cpp/src/stimulation_map.cc)
        self._arm = Arm(model, stimulation=stimulation)
        self.names: list[str] = list(self._arm.channel_names)
        #: The labels of a stimulation stream's channels (LSL), in packet order: "<channel>/pulse_width", ... (the
        #: packet table's stimulation row, cpp/rt/packet.h, which labels the state packets' values the same way).
        self.labels: list[str] = next(r["labels"] for r in state_packet_fields(model, self.names)
                                      if r["name"] == "stimulation")

    def values(self, stimulation) -> np.ndarray:
        """{channel: (pulse_width_s, amplitude_A, frequency_Hz)} (channels not named: 0, off) or a (channels, 3)
        array -> the packet's 3 * channels values. ValueError naming the channel for an unknown name, a NaN, a
        negative value or one beyond the channel's limits (pulse width, amplitude, frequency, charge per phase)."""
        from . import stimulation as _stimulation
        cmd = _stimulation.commands(self._arm._sim, stimulation, np.zeros((len(self.names), 3)))
        err = self._arm._sim.stimulation_command_error(cmd.ravel())
        if err:
            raise ValueError(err)
        return cmd.ravel()


# ---------------------------------------------------------------------------------------- UDP client
@dataclass
class SessionEnd:
    """The runner's notice that this client's session ended (packet type 18, docs/realtime.md "Sessions").

    reason: "timeout" (no valid packet for longer than the runner's --timeout); hold_s: the excitation is held at
    zero that long (simulated s) and nobody may own the arm meanwhile; grace_s: then, for that long, only this
    client (the timed-out owner) may claim it again with join(); session: the ended session's id; received_at:
    time.monotonic() when the notice came."""

    reason: str
    hold_s: float
    grace_s: float
    session: int
    received_at: float


class SessionEnded(RuntimeError):
    """send() / send_stimulation() after the runner ended this client's session (the notice is .end, a
    SessionEnd): the excitation is zero; join(timeout) again to resume (first in line within the grace window)."""

    def __init__(self, end: SessionEnd, address):
        self.end = end
        super().__init__(f"the runner at {address[0]}:{address[1]} ended this session ({end.reason}: no valid packet "
                         f"for longer than its --timeout); the excitation is zero and held for {end.hold_s:g} s, then "
                         f"this controller alone may claim the arm for {end.grace_s:g} s: call join(timeout) again "
                         f"(docs/realtime.md, Sessions)")


class UdpClient:
    """A controller's end of the link: owns a session of the runner, sends excitations, receives state.

    port, host: the runner's --listen address. key: the runner's shared key (bytes, >= 16; see
    read_key_file), or None. join(timeout) asks for the session (hello -> offer) before the first send(),
    which never waits for one (RuntimeError without a session); packets carry the session id and, with a key, an HMAC-SHA256 tag. Incoming datagrams are accepted only
    from the runner's address and, with a key, only with a valid tag: anything else is dropped and
    counted (.foreign_packets, .bad_packets), never raised. When the runner ends the session (silence
    longer than its --timeout) it says so (a session-ended packet, read by poll / recv_state / latest_state):
    .session becomes 0, .session_end holds the notice (SessionEnd) and send() raises SessionEnded until
    join() succeeds again; the runner holds the excitation at zero for the notice's hold_s, then lets this
    client alone claim the arm for grace_s (docs/realtime.md, Sessions).
    """

    def __init__(self, port: int, host: str = "127.0.0.1", mapping: str | GroupMapping = "elements",
                 model: str = "das2", channels: Sequence[str] | None = None, bind_port: int = 0,
                 key: bytes | str | None = None, stimulation=None):
        self.address = parse_endpoint(f"{host}:{int(port)}")
        self.state_fields = state_fields(model)
        #: The runner's stimulation channels (its --stimulation map, given here as stimulation=), or None.
        self.stimulation = None if stimulation is None else StimulationChannels(model, stimulation)
        self.state_table = state_packet_fields(model, self.stimulation.names if self.stimulation else ())
        self.mapping = mapping if isinstance(mapping, GroupMapping) else GroupMapping.from_model(mapping, model, channels)
        self.key = _key_bytes(key)
        self.model = model
        self._model = None  # armrt.Model, loaded by the first send_target (its DOF names and ranges)
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind(("127.0.0.1" if self.address[0].startswith("127.") else "", bind_port))
        self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 1 << 20)
        self._timestamps = False
        if _SO_TIMESTAMPNS is not None:
            try:
                self.sock.setsockopt(socket.SOL_SOCKET, _SO_TIMESTAMPNS, 1)
                self._timestamps = True
            except OSError:
                pass
        self.seq = 0
        self.session = 0
        self._joining = False      # only join() takes a session id: an offer or a state packet elsewhere is not one
        self.bad_packets = 0       # malformed, unsigned or wrongly signed datagrams
        self.foreign_packets = 0   # datagrams from anyone but the runner
        self.last_state: StatePacket | None = None
        self.last_error = ""       # why the last bad datagram was refused
        self.session_end: SessionEnd | None = None  # the runner's notice that this session ended (None: none)
        self._states: collections.deque = collections.deque(maxlen=4096)
        self._state_interval = 0.0  # s between the last two state packets' arrivals
        self._last_arrival = None
        #: latest_state() calls whose newest queued state was stale (older than timeout and two state intervals:
        #: after a stall the kernel had dropped the newer ones, or the runner had stopped sending) and so not returned.
        self.stale_states = 0

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
            if self._timestamps:
                data, ancillary, _, src = self.sock.recvmsg(65536, socket.CMSG_SPACE(_TIMESPEC.size))
                arrival = _arrival(ancillary)
            else:
                data, src = self.sock.recvfrom(65536)
                arrival = time.monotonic()
        except (socket.timeout, BlockingIOError):
            return False
        if (src[0], src[1]) != self.address:
            self.foreign_packets += 1
            return True
        try:
            p = decode_packet(data, self.key)
            if p.type == OFFER:
                # Only while join() asks. The runner offers its id to any packet of a wrong session; taken at any
                # time, that made a client released (or never joined) own the arm again at its next send().
                if self._joining:
                    self.session = p.session
            elif p.type == SESSION_ENDED:
                if self.session != 0 and p.session == self.session:  # a late notice of an older session: ignored
                    v = p.values
                    self.session_end = SessionEnd("timeout" if len(v) and v[0] == 1 else f"reason {v[0] if len(v) else '?'}",
                                                  float(v[1]) if len(v) > 1 else 0.0,
                                                  float(v[2]) if len(v) > 2 else 0.0, p.session, time.monotonic())
                    self.session = 0
            elif p.type == STATE:
                st = StatePacket.from_packet(p, self.state_table)
                st.received_at = arrival
                if self._last_arrival is not None and arrival > self._last_arrival:
                    self._state_interval = arrival - self._last_arrival
                self._last_arrival = arrival
                # The session id is not taken from state packets: one sent before the runner read this client's
                # release restored the old id, and the runner's offer to the send() that followed claimed the
                # arm again without join() (a new user's trial). Subscribers get state packets too.
                self._states.append(st)
            else:
                self.bad_packets += 1
        except PacketError as exc:
            self.bad_packets += 1
            self.last_error = str(exc)
        return True

    def poll(self, timeout: float | None = 0.0) -> bool:
        """Reads one datagram if one comes within timeout s (an offer sets .session only inside join(); state
        packets are queued for recv_state / take_states); True if one was read."""
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
        none comes (the runner is not there, another controller owns the session, the runner holds the arm at
        zero after an owner timed out and then keeps it for that owner's grace window, --allow or the key
        refuses this one). After a SessionEnded, a timeout of session_end.hold_s + 1 s covers the hold."""
        self.session = 0
        self.session_end = None
        t_end = time.monotonic() + timeout
        self._joining = True
        try:
            return self._join_until(t_end, timeout)
        finally:
            self._joining = False

    def _join_until(self, t_end: float, timeout: float) -> int:
        next_hello = 0.0
        while self.session == 0:
            now = time.monotonic()
            if now >= t_end:
                raise TimeoutError(f"no session offer from {self.address[0]}:{self.address[1]} within {timeout} s "
                                   "(runner not listening, session owned by another controller, the zero held after "
                                   "an owner timed out and that owner's grace window, or refused by --allow / the "
                                   "key)")
            if now >= next_hello:
                self.sock.sendto(encode_packet(HELLO, self._next_seq(), key=self.key), self.address)
                next_hello = now + 0.05
            self._pump(min(0.01, t_end - now))
        return self.session

    def _require_session(self) -> None:
        # The first send used to join, blocking up to a second inside a caller's control loop (a second client in
        # the loop silenced the owner that long): joining is the caller's explicit, timed step.
        if self.session == 0 and self.session_end is not None:
            raise SessionEnded(self.session_end, self.address)
        if self.session == 0:
            raise RuntimeError(f"no session with the runner at {self.address[0]}:{self.address[1]}: call "
                               "join(timeout) first (send never waits; after release() or a session that ended, "
                               "join again)")

    def send(self, excitation, seq: int | None = None) -> int:
        """Sends one excitation packet (array or dict through the mapping); returns its sequence number.
        ValueError (nothing sent) for a NaN, an infinity or a value outside [0, 1], naming the values: the runner
        would drop or clip them, and a controller that computes them has a bug the lab should see. RuntimeError
        without a session (join(timeout) first): send never waits for the runner, so a control loop never stalls on
        it; SessionEnded (a RuntimeError) once the runner said the session ended (join again)."""
        values = self.mapping.values(excitation)
        bad = ~np.isfinite(values) | (values < 0.0) | (values > 1.0)
        if bad.any():
            which = [f"{self.mapping.names[k]}={float(values[k])!r}" for k in np.flatnonzero(bad)[:5]]
            raise ValueError(f"excitation must be finite and in [0, 1]; got {', '.join(which)}"
                             f"{' ...' if bad.sum() > 5 else ''} (nothing sent)")
        self._require_session()
        if seq is None:
            seq = self._next_seq()
        data = encode_packet(self.mapping.packet_type, seq, values, session=self.session, key=self.key)
        self.sock.sendto(data, self.address)
        return seq

    def send_stimulation(self, stimulation, seq: int | None = None) -> int:
        """Sends one stimulation packet: {channel: (pulse_width_s, amplitude_A, frequency_Hz)} (channels not
        named are off) or a (channels, 3) array, in the map's channel order; returns its sequence number.
        ValueError (nothing sent) for a value the Python API refuses: NaN, negative, beyond a channel's limits;
        RuntimeError without stimulation= (the runner's map) or without a session (join(timeout) first)."""
        if self.stimulation is None:
            raise RuntimeError("this client has no stimulation map: UdpClient(..., stimulation=<the runner's "
                               "--stimulation map>)")
        values = self.stimulation.values(stimulation)
        self._require_session()
        if seq is None:
            seq = self._next_seq()
        self.sock.sendto(encode_packet(STIMULATION, seq, values, session=self.session, key=self.key), self.address)
        return seq

    def send_target(self, q, qdot=0.0, qddot=0.0, seq: int | None = None) -> int:
        """Sends one target to a runner started with --static-optimization (RealtimeSession(static_optimization=
        True)): the desired joint angles q (ndof,) rad, velocities qdot (rad/s) and accelerations qddot (rad/s^2)
        (each may be 0), in the model's DOF order; the runner solves the static optimisation for them every cycle
        and applies the activations. Returns the sequence number. ValueError (nothing sent) for what
        StaticOptimizer.solve refuses: NaN, wrong shapes, q beyond the joint ranges by more than the engine's
        margin (with a hint when it looks like degrees), |qdot| beyond max_joint_speed (100 rad/s), |qddot| beyond
        1e5 rad/s^2; RuntimeError without a session (join(timeout) first)."""
        from .checks import (dof_vector, joint_acceleration_within, joint_range,  # noqa: PLC0415 (light: numpy only)
                             joint_speed_within, real_scalar)
        if self._model is None:
            from .model import Model  # noqa: PLC0415 (the model's DOF names and ranges, once)
            self._model = Model(self.model)
        m = self._model

        def vec(v, what):
            if np.isscalar(v) and not isinstance(v, (str, bytes)):
                if real_scalar(v, what, booleans=False) != 0:  # True was "a scalar must be 0", not named a bool
                    raise ValueError(f"{what}: a scalar must be 0 (for every DOF); give an array of shape ({m.n_dofs},)")
                return np.zeros(m.n_dofs)
            return np.asarray(dof_vector(v, what, m.dof_names), dtype=float)

        q = joint_range(vec(q, "q"), m.dof_names, m.dof_ranges, warn=False)
        qd = vec(qdot, "qdot")
        qdd = vec(qddot, "qddot")
        from . import _core  # noqa: PLC0415 (the extension: the static optimisation's bounds)
        # The runner's arm's max_joint_speed (its default).
        joint_speed_within(qd, m.dof_names, _core.DEFAULT_MAX_JOINT_SPEED, "the runner, as StaticOptimizer.solve,")
        joint_acceleration_within(qdd, m.dof_names, _core.STATIC_OPTIMIZATION_MAX_JOINT_ACCELERATION,
                                  "the runner, as StaticOptimizer.solve,")
        values = np.concatenate([q, qd, qdd])
        self._require_session()
        if seq is None:
            seq = self._next_seq()
        self.sock.sendto(encode_packet(TARGET, seq, values, session=self.session, key=self.key), self.address)
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
                # Everything already queued, up to the first state packet (an offer or a session-ended notice
                # ahead of it is read on the way, not taken for "nothing there").
                while not self._states and self._pump(0.0):
                    pass
                if not self._states:
                    return None
                break
            self._pump(remaining)
        st = self._states.popleft()
        self.last_state = st
        return st

    def latest_state(self, timeout: float = 0.1) -> StatePacket | None:
        """Waits up to timeout s for a state packet, then drains the queue and returns the newest one; None if none
        comes. A newest queued state that arrived longer ago than timeout and two state intervals is not returned:
        after a controller stalled longer than the receive buffer holds (1 MB asked: about 0.9 s of 1 kHz state)
        the kernel dropped the newer packets, the runner's session-ended notice among them, so the queue held a state
        seconds old that still showed the stimulation on. Then the wait starts again for a state that arrives
        after the drain (None if none comes: a timed-out owner is sent none), the stale one counted in
        .stale_states and kept in .last_state. received_at is the kernel's arrival time (Linux SO_TIMESTAMPNS)."""
        st = self._newest(timeout)
        if st is None:
            return None
        if time.monotonic() - st.received_at > max(timeout, 2.0 * self._state_interval):
            self.stale_states += 1
            st = self._newest(timeout)
        return st

    def _newest(self, timeout: float) -> StatePacket | None:
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


class StateListener:
    """The receiving end of an armrt-rt --state-to stream (docs/realtime.md "State packets"), for whoever only
    watches the arm (armrt view / display --udp, armrt task --runner-state). Binds host:port (UDP; host parsed as
    the runner parses it, loopback unless another address is named; port 0 picks one, then .port says which).
    decode(datagram) -> StatePacket of the model, or None for a datagram that is not one (another model's runner,
    unsigned or wrongly signed when key is set, junk): counted in .bad_packets with the reason in .last_error, so
    nothing refused is drawn or scored and nothing is silently lost. Raises OSError naming host:port when it
    cannot bind, ValueError for a bad host or port."""

    def __init__(self, host: str = "127.0.0.1", port: int = 9870, model: str = "das2", key: bytes | None = None):
        host, port = parse_endpoint(f"{host}:{int(port)}")
        self.model = model
        self.fields = state_packet_fields(model)
        self.key = key
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        try:
            self.sock.bind((host, port))
        except OSError as exc:
            self.sock.close()
            raise OSError(f"cannot listen for the runner's state on {host}:{port}: {exc.strerror}") from None
        self.host, self.port = host, self.sock.getsockname()[1]
        self.packets = self.bad_packets = 0
        self.last_error = ""

    def decode(self, data: bytes) -> StatePacket | None:
        try:
            pkt = StatePacket.from_packet(decode_packet(data, self.key), self.fields)
        except Exception as exc:  # a datagram from the network may be malformed any way: refused, reason kept
            self.bad_packets += 1
            self.last_error = str(exc)
            return None
        self.packets += 1
        return pkt

    def close(self) -> None:
        self.sock.close()
