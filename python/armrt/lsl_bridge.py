"""Lab Streaming Layer bridge: a process next to the real-time runner (docs/realtime.md).

It publishes the runner's state packets as an LSL stream (channel labels, units and types in the
stream description, a stable source_id) and forwards the samples of one LSL excitation stream to the
runner as UDP excitation packets, as the owner of the runner's session (armrt.realtime.UdpClient).
It only forwards new samples: when the LSL controller goes silent the runner's input timeout sets
the excitation to zero, as with a direct UDP controller. An excitation sample with a NaN, an infinity or a value
outside [0, 1] is not forwarded (counted in .refused, warned about once), as UdpClient.send refuses it.

With --mapping stimulation and the runner's --stimulation map, the input stream is a stimulator's: channels
labelled "<channel>/pulse_width" (s), "<channel>/amplitude" (A) and "<channel>/frequency" (Hz), any subset of
the map's channels (the others are off). A sample the Python API would refuse (NaN, negative, beyond a
channel's limits) is not forwarded (counted in .refused, warned about once): the runner holds the previous
command and, if nothing valid follows, its timeout sets every channel to zero. The state stream then also
carries the applied stimulation and each channel's fatigue.

    armrt-rt --listen 127.0.0.1:45100 --state-to 127.0.0.1:45101 &
    python -m armrt.lsl_bridge --runner 127.0.0.1:45100 --state-port 45101 --mapping groups \\
        --excitation-source-id my-controller

It also publishes a GH stability stream ("<source_id>-gh": GHstab, the GH force's direction, rim margin and
direction, units in its description) and a marker stream ("<source_id>-markers", type "Markers", one string
channel, irregular rate; LslBridge.push_marker(marker, timestamp)), all with the metadata LabRecorder records
(desc/acquisition/manufacturer, desc/channels/channel/label, unit, type). python -m armrt.lsl_record records
them to XDF (docs/lsl.md).

The excitation stream is pinned by --excitation-source-id, or else by its name on this host only
(--excitation-host to name another): never the first stream of that name anywhere on the network.
Its channels are matched to the mapping's names by label (a label the mapping does not know is an
error naming it). Looking for it happens on a separate thread, so the state stream never stalls.

Needs pylsl (pip install pylsl; its wheel bundles liblsl).
"""
from __future__ import annotations

import argparse
import select
import socket
import sys
import threading
import time
from dataclasses import dataclass

import numpy as np

from .realtime import GroupMapping, PacketError, StatePacket, UdpClient, decode_packet, parse_endpoint, state_packet_fields


def _stream_rows(model: str, forces: bool, excitations: bool, channels=()) -> list[dict]:
    """The rows of the state packet table (cpp/rt/packet.h) the stream carries: the ones always sent,
    then the runner's overrun flag (a channel of its own), then forces / excitations if asked for, then the
    stimulation and fatigue rows when the runner has a map with these channels."""
    rows = state_packet_fields(model, channels)
    fixed = [r for r in rows if r["flag"] == 0]
    flag = {"name": "overrun", "labels": ["overrun"], "unit": "1", "lsl_type": "flag", "size": 1, "flag": 0}
    optional = [r for r in rows if (r["name"] == "muscle_force" and forces) or (r["name"] == "excitation" and excitations)
                or (r["name"] in ("stimulation", "fatigue") and len(channels) > 0)]
    return fixed + [flag] + optional


def _row_units(r: dict) -> list[str]:
    # A row of several quantities ("s,A,Hz": pulse width, amplitude, frequency per channel) cycles its units.
    units = r["unit"].split(",")
    return [units[k % len(units)] for k in range(len(r["labels"]))]


def state_channels(model: str = "das2", forces: bool = False, excitations: bool = False,
                   channels=()) -> tuple[list[str], list[str], list[str]]:
    """Labels, units and types of the state stream's channels for `model`, read from the state packet
    table (armrt.realtime.state_packet_fields): time, one angle and one angular velocity per DOF
    (labelled by the DOF names), hand position, GHstab, the GH force's angles, rim margin and rim
    direction, last applied sequence number, lag, overruns, the overrun flag, then the muscle forces
    and excitations when the runner sends them, then with stimulation channels (the runner's --stimulation
    map, in order) "<channel>/pulse_width" (s), "/amplitude" (A), "/frequency" (Hz) and "<channel>/fatigue"."""
    rows = _stream_rows(model, forces, excitations, channels)
    labels = [lab for r in rows for lab in r["labels"]]
    units = [u for r in rows for u in _row_units(r)]
    types = [r["lsl_type"] for r in rows for _ in r["labels"]]
    return labels, units, types


def _pylsl():
    try:
        import pylsl
    except Exception as e:  # ImportError or RuntimeError (liblsl not loadable)
        raise RuntimeError(f"the LSL bridge needs pylsl with a loadable liblsl (pip install pylsl): {e}") from e
    return pylsl


def check_state_rate(state_rate_hz: float, runner_rate_hz: float = 1000.0) -> int:
    """Cycles between state packets for a nominal LSL rate; ValueError unless the runner delivers it
    exactly (runner rate / an integer), naming the nearest rates that it does."""
    if not (np.isfinite(state_rate_hz) and 0 < state_rate_hz <= runner_rate_hz):
        raise ValueError(f"state rate {state_rate_hz} Hz must be in (0, {runner_rate_hz}] Hz")
    ratio = runner_rate_hz / state_rate_hz
    k = round(ratio)
    if k < 1 or abs(ratio - k) > 1e-9 * ratio:
        lo = max(1, int(np.floor(ratio)))
        raise ValueError(f"state rate {state_rate_hz:g} Hz is not the runner's {runner_rate_hz:g} Hz / an integer; "
                         f"the nearest are {runner_rate_hz / lo:g} and {runner_rate_hz / (lo + 1):g} Hz")
    return k


def _describe(desc, model: str, labels, units, types) -> None:
    """LabRecorder's (XDF meta-data) layout: desc/acquisition/manufacturer, desc/channels/channel/label, unit, type."""
    acq = desc.append_child("acquisition")
    acq.append_child_value("manufacturer", "armrt")
    acq.append_child_value("model", model)
    chans = desc.append_child("channels")
    for lab, unit, typ in zip(labels, units, types):
        c = chans.append_child("channel")
        c.append_child_value("label", lab)
        c.append_child_value("unit", unit)
        c.append_child_value("type", typ)


def state_stream_info(pylsl, name: str, source_id: str, rate_hz: float, forces: bool = False,
                      model: str = "das2", excitations: bool = False, channels=()):
    labels, units, types = state_channels(model, forces, excitations, channels)
    info = pylsl.StreamInfo(name, "ArmState", len(labels), rate_hz, pylsl.cf_double64, source_id)
    desc = info.desc()
    desc.append_child_value("model", model)
    desc.append_child_value("frames", "q: DAS3 generalised coordinates; hand: thorax frame (docs/conventions.md)")
    desc.append_child_value("resync", "skip: after an overrun the missed periods are not simulated; lag = "
                                      "simulated time behind the wall-clock schedule")
    _describe(desc, model, labels, units, types)
    return info


# The state packet's rows the GH stability stream carries (cpp/rt/packet.h: their units and meaning).
GH_ROWS = ("gh_stab", "gh_theta", "gh_phi", "gh_rim_margin", "gh_rim_direction")


def gh_channels(model: str = "das2") -> tuple[list[str], list[str], list[str]]:
    """Labels, units and types of the GH stability stream: GHstab (1; > 1 beyond the glenoid rim), the GH
    force's direction from the glenoid normal (gh_theta, gh_phi, rad), the rim margin and rim direction (rad),
    read from the state packet table (armrt.realtime.state_packet_fields)."""
    rows = {r["name"]: r for r in state_packet_fields(model)}
    missing = [n for n in GH_ROWS if n not in rows]
    if missing:
        raise RuntimeError(f"the state packet table has no rows {missing} for the GH stability stream")
    return ([rows[n]["labels"][0] for n in GH_ROWS], [rows[n]["unit"] for n in GH_ROWS],
            [rows[n]["lsl_type"] for n in GH_ROWS])


def gh_stream_info(pylsl, name: str, source_id: str, rate_hz: float, model: str = "das2"):
    """The GH stability stream (type "GHStability"): gh_channels(model), one sample per state packet, with the
    state stream's timestamp."""
    labels, units, types = gh_channels(model)
    info = pylsl.StreamInfo(name, "GHStability", len(labels), rate_hz, pylsl.cf_double64, source_id)
    desc = info.desc()
    desc.append_child_value("definition", "gh_stab = (theta/theta_a)^2 + (phi/phi_a)^2 of the GH joint reaction "
                                          "force's direction in the glenoid frame (theta_a, phi_a: the rim's "
                                          "half-angles); > 1 beyond the rim (docs/conventions.md, armrt/engine.h)")
    desc.append_child_value("frames", "gh_theta along the glenoid's major axis (+ superior), gh_phi along its minor "
                                      "axis (+ anterior)")
    _describe(desc, model, labels, units, types)
    return info


def marker_stream_info(pylsl, name: str = "armrt_markers", source_id: str = "armrt-markers", model: str = "das2"):
    """A marker stream as LabRecorder expects one: type "Markers", one string channel, irregular rate."""
    info = pylsl.StreamInfo(name, "Markers", 1, pylsl.IRREGULAR_RATE, pylsl.cf_string, source_id)
    desc = info.desc()
    desc.append_child_value("content", "task events (armrt.tasks TaskEvent.marker()), at the simulated event's "
                                       "LSL time")
    _describe(desc, model, ["marker"], ["none"], ["Marker"])
    return info


class MarkerOutlet:
    """An LSL marker outlet: push(marker, timestamp) publishes one string at an LSL timestamp (pylsl.local_clock()
    seconds; None: now). A marker that is not a non-empty str, or a timestamp that is not finite, is a
    ValueError (never published)."""

    def __init__(self, name: str = "armrt_markers", source_id: str = "armrt-markers", model: str = "das2"):
        self.pylsl = _pylsl()
        self.source_id = source_id
        self.outlet = self.pylsl.StreamOutlet(marker_stream_info(self.pylsl, name, source_id, model))
        self.pushed = 0

    def push(self, marker: str, timestamp: float | None = None) -> float:
        """Publishes `marker` at `timestamp` (s, LSL clock); returns the timestamp used."""
        if not isinstance(marker, str) or not marker:
            raise ValueError(f"a marker must be a non-empty str, got {marker!r}")
        t = self.pylsl.local_clock() if timestamp is None else float(timestamp)
        if not np.isfinite(t):
            raise ValueError(f"marker {marker!r}: timestamp {timestamp!r} is not finite")
        self.outlet.push_sample([marker], t)
        self.pushed += 1
        return t


# The live task's state stream (armrt task ... --task-stream; task_live.run_live): one sample per task sample.
TASK_STATE_CHANNELS = (("time", "s", "time"), ("cursor_x", "m", "position"), ("cursor_y", "m", "position"),
                       ("cursor_z", "m", "position"), ("target_x", "m", "position"), ("target_y", "m", "position"),
                       ("target_z", "m", "position"), ("target_index", "1", "index"), ("inside", "1", "flag"),
                       ("gh_stab", "1", "stability"))


class TaskStateOutlet:
    """An LSL outlet of a live task's state (type "TaskState", float64, rate 1/dt_s): TASK_STATE_CHANNELS, i.e. the
    task time (s), the cursor (m, thorax frame), the shown target (m; NaN between trials), its index (-1 between
    trials), whether the cursor is inside it (0/1) and GHstab (NaN without an arm). push(values, timestamp)."""

    def __init__(self, name: str = "armrt_task_state", source_id: str = "armrt-task-state", rate_hz: float = 500.0,
                 model: str = "cursor"):
        self.pylsl = _pylsl()
        labels, units, types = (list(c) for c in zip(*TASK_STATE_CHANNELS))
        info = self.pylsl.StreamInfo(name, "TaskState", len(labels), float(rate_hz), self.pylsl.cf_double64,
                                     source_id)
        info.desc().append_child_value("frames", "cursor and target in the thorax frame (docs/conventions.md)")
        _describe(info.desc(), model, labels, units, types)
        self.outlet = self.pylsl.StreamOutlet(info)
        self.source_id = source_id
        self.pushed = 0

    def push(self, values, timestamp: float) -> None:
        self.outlet.push_sample([float(v) for v in values], float(timestamp))
        self.pushed += 1


def channel_labels(info) -> list[str]:
    """Channel labels from a full StreamInfo (desc/channels/channel/label), [] if none."""
    labels = []
    ch = info.desc().child("channels").child("channel")
    while not ch.empty():
        labels.append(ch.child_value("label"))
        ch = ch.next_sibling()
    return labels


def match_labels(labels: list[str], names: list[str], stream: str = "") -> np.ndarray:
    """Index of each stream channel in the mapping's names; ValueError naming unknown, duplicate or
    missing labels (a stream without labels cannot be matched)."""
    where = f" of stream {stream!r}" if stream else ""
    if not labels or all(not lab for lab in labels):
        raise ValueError(f"the channels{where} have no labels; label them with the mapping's names ({names[:5]}...)")
    unknown = [lab for lab in labels if lab not in names]
    if unknown:
        raise ValueError(f"unknown channel labels{where}: {unknown} (the mapping's names are {names})")
    dup = sorted({lab for lab in labels if labels.count(lab) > 1})
    if dup:
        raise ValueError(f"duplicate channel labels{where}: {dup}")
    pos = {n: k for k, n in enumerate(names)}
    return np.array([pos[lab] for lab in labels], dtype=int)


# The endpoint-command input's channels (thorax frame, docs/conventions.md): a desired hand velocity and/or
# position, each as a complete x, y, z triple.
ENDPOINT_VELOCITY = ("hand_velocity_x", "hand_velocity_y", "hand_velocity_z")   # m/s
ENDPOINT_POSITION = ("hand_position_x", "hand_position_y", "hand_position_z")   # m
ENDPOINT_LABELS = ENDPOINT_VELOCITY + ENDPOINT_POSITION


@dataclass(frozen=True)
class EndpointCommand:
    """One sample of a decoder's endpoint-command stream: its LSL timestamp (s, as the inlet delivers it), the
    desired hand velocity (3,) m/s and position (3,) m in the thorax frame, each None when the stream has no
    such channels."""
    timestamp: float
    hand_velocity: np.ndarray | None
    hand_position: np.ndarray | None


def endpoint_layout(labels: list[str], stream: str = "") -> tuple[bool, bool]:
    """(has velocity, has position) of an endpoint-command stream's channel labels; ValueError naming unknown or
    duplicate labels (match_labels) or an incomplete x, y, z triple."""
    match_labels(labels, list(ENDPOINT_LABELS), stream)
    where = f" of stream {stream!r}" if stream else ""
    present = []
    for triple in (ENDPOINT_VELOCITY, ENDPOINT_POSITION):
        have = [lab for lab in triple if lab in labels]
        if have and len(have) != 3:
            raise ValueError(f"endpoint command{where}: {sorted(set(triple) - set(have))} missing "
                             f"(a velocity or position comes as x, y and z)")
        present.append(bool(have))
    return present[0], present[1]


def endpoint_commands(samples, stamps, channel_index, has) -> tuple[list[EndpointCommand], int]:
    """An inlet's chunk of endpoint-command samples (channels in the stream's order; channel_index: their places
    in ENDPOINT_LABELS, from match_labels; has: endpoint_layout's (velocity, position)) -> (the EndpointCommands in
    order, the number refused: a used channel NaN or infinite)."""
    have_v, have_p = has
    out, refused = [], 0
    for sample, t in zip(samples, stamps):
        x = np.full(len(ENDPOINT_LABELS), np.nan)
        x[channel_index] = np.asarray(sample, dtype=float)
        used = np.concatenate([x[:3]] * have_v + [x[3:]] * have_p)
        if not np.all(np.isfinite(used)):
            refused += 1
            continue
        out.append(EndpointCommand(float(t), x[:3].copy() if have_v else None, x[3:].copy() if have_p else None))
    return out, refused


def endpoint_stream_info(pylsl, name: str, source_id: str, rate_hz: float, labels=ENDPOINT_LABELS):
    """A decoder's endpoint-command stream as the bridge matches it (type "EndpointCommand", float64): channels
    labelled from ENDPOINT_LABELS (complete triples), units m/s and m, thorax frame."""
    labels = list(labels)
    endpoint_layout(labels)
    info = pylsl.StreamInfo(name, "EndpointCommand", len(labels), rate_hz, pylsl.cf_double64, source_id)
    desc = info.desc()
    desc.append_child_value("frames", "hand velocity and position in the thorax frame (docs/conventions.md)")
    units = ["m/s" if lab in ENDPOINT_VELOCITY else "m" for lab in labels]
    types = ["velocity" if lab in ENDPOINT_VELOCITY else "position" for lab in labels]
    _describe(desc, "decoder", labels, units, types)
    return info


class LslEndpointDecoder:
    """A decoder's LSL endpoint-command stream as a task decoder (armrt task --decoder lsl:NAME; task_live):
    the stream named `name` on this host (host= another; or pinned by source_id), waited for up to wait_s s
    (RuntimeError naming it when absent or ambiguous), its channels matched by label (ENDPOINT_LABELS, complete
    x, y, z triples: ValueError otherwise). command(cursor, target) pulls what arrived and returns (velocity (3,)
    m/s or None, position (3,) m or None): the newest sample's, the position held; a velocity older than
    hold_s s (the decoder went silent) is zero, so the hand stops instead of drifting (as the runner's input
    timeout zeroes the excitation). Samples with a NaN or an infinity in a used channel are refused (counted
    in .refused). received counts the samples taken, stale_s the longest silence seen (s)."""

    def __init__(self, name: str | None = None, source_id: str | None = None, host: str | None = None,
                 wait_s: float = 10.0, hold_s: float = 0.5):
        if not name and not source_id:
            raise ValueError("name the decoder's endpoint stream (lsl:NAME) or pin its source_id")
        pylsl = self.pylsl = _pylsl()
        self.host = host or socket.gethostname()
        self.hold_s = float(hold_s)
        what = f"source_id {source_id!r}" if source_id else f"stream {name!r} on {self.host}"
        resolver = (pylsl.ContinuousResolver(prop="source_id", value=source_id) if source_id
                    else pylsl.ContinuousResolver(prop="name", value=name))
        t_end = time.monotonic() + float(wait_s)
        found = []
        while True:
            found = [r for r in resolver.results() if source_id or r.hostname() == self.host]
            if len(found) > 1:
                who = [f"{f.name()}@{f.hostname()} ({f.source_id()})" for f in found]
                raise RuntimeError(f"{len(found)} endpoint-command streams match {what}: {who}; pin one by source_id")
            if found or time.monotonic() > t_end:
                break
            time.sleep(0.05)
        if not found:
            raise RuntimeError(f"no LSL endpoint-command {what} after {wait_s:g} s (is the decoder running?)")
        self.inlet = pylsl.StreamInlet(found[0], max_buflen=1, recover=True)
        full = self.inlet.info(timeout=5.0)
        where = f"{full.name()}@{full.hostname()}"
        if full.channel_format() == pylsl.cf_string:
            self.inlet.close_stream()
            raise ValueError(f"the endpoint-command stream {where} carries strings: its channels must be numbers "
                             "(float32, float64 or integers)")
        labels = channel_labels(full)
        self.channel_index = match_labels(labels, list(ENDPOINT_LABELS), where)
        self.has = endpoint_layout(labels, where)
        self.name, self.source_id = full.name(), full.source_id()
        self.inlet.open_stream(timeout=5.0)
        self.velocity = np.zeros(3) if self.has[0] else None
        self.position = None
        self.received = 0
        self.refused = 0
        self.stale_s = 0.0
        self._last = None   # perf_counter of the newest sample

    def poll(self) -> list[EndpointCommand]:
        """Takes the samples that arrived; returns them (in order)."""
        samples, stamps = self.inlet.pull_chunk(timeout=0.0)
        cmds, refused = endpoint_commands(samples, stamps, self.channel_index, self.has)
        self.refused += refused
        now = time.perf_counter()
        if cmds:
            if self._last is not None:
                self.stale_s = max(self.stale_s, now - self._last)
            self._last = now
            self.received += len(cmds)
            if self.has[0]:
                self.velocity = cmds[-1].hand_velocity
            if self.has[1]:
                self.position = cmds[-1].hand_position
        return cmds

    def command(self, cursor=None, target=None):
        """(velocity or None, position or None) to command now; cursor and target are not used (the decoder
        outside sees the participant's screen)."""
        self.poll()
        v = None
        if self.has[0]:
            fresh = self._last is not None and time.perf_counter() - self._last <= self.hold_s
            v = self.velocity if fresh else np.zeros(3)
        return v, self.position

    def close(self) -> None:
        self.inlet.close_stream()


class LslBridge:
    """State packets (UDP, from the runner) -> LSL outlet; LSL excitation inlet -> UDP packets.

    runner_port: the runner's --listen port (runner_address may be set later, before the first
    excitation); state_port: where the runner sends state (--state-to); 0 picks a free port (see
    .state_port). source_id is stable (default "armrt-<model>"): the state stream is "<source_id>-state".
    excitation_source_id pins the excitation stream; without it, the stream named excitation_name on
    excitation_host (default: this host). state_rate_hz must be runner_rate_hz / an integer (ValueError).
    key: the runner's shared key, if any. mapping "stimulation" with stimulation= (the runner's --stimulation
    map): the input stream carries "<channel>/pulse_width", "/amplitude", "/frequency" (SI) by label, forwarded
    as stimulation packets (excitation_name defaults to "armrt_stimulation"). Faults (bad packets, rate
    mismatch, refused stimulation samples) are counted and warned about once each (.warnings); a stream that
    cannot be matched, or a declared channel set the runner does not fill (forces), raises from step() / run().
    Besides the state stream it publishes the GH stability stream "<source_id>-gh" (gh_name; gh_channels(), each
    with its state sample's timestamp) and the marker stream "<source_id>-markers" (marker_name; push_marker()).
    endpoint_consumer: a callable(EndpointCommand) -> excitation (the mapping's names, or None): the input
    stream is then a decoder's endpoint command (channels labelled from ENDPOINT_LABELS, matched by label, default
    name "armrt_endpoint"); every sample reaches the consumer in order (a sample with a NaN or an infinity is
    refused, counted in .refused), and the last excitation it returns in a pass is forwarded to the runner.
    """

    def __init__(self, runner_port: int, runner_host: str = "127.0.0.1", state_port: int = 0,
                 mapping: str = "groups", model: str = "das2", channels=None, source_id: str | None = None,
                 state_name: str = "armrt_state", excitation_name: str = "armrt_excitation",
                 state_rate_hz: float = 100.0, forces: bool = False, excitation_source_id: str | None = None,
                 excitation_host: str | None = None, runner_rate_hz: float = 1000.0, key: bytes | None = None,
                 excitations: bool = False, stimulation=None, gh_name: str = "armrt_gh",
                 marker_name: str = "armrt_markers", endpoint_consumer=None):
        self.pylsl = _pylsl()
        if endpoint_consumer is not None and mapping == "stimulation":
            raise ValueError("an endpoint consumer returns excitations: use an excitation mapping, not 'stimulation'")
        if endpoint_consumer is not None and not callable(endpoint_consumer):
            raise ValueError(f"endpoint_consumer must be callable(EndpointCommand), got {endpoint_consumer!r}")
        self.endpoint_consumer = endpoint_consumer
        if endpoint_consumer is not None and excitation_name == "armrt_excitation":
            excitation_name = "armrt_endpoint"
        self.state_every = check_state_rate(state_rate_hz, runner_rate_hz)
        self.state_period = self.state_every / runner_rate_hz
        self.stimulating = mapping == "stimulation"
        if self.stimulating and stimulation is None:
            raise ValueError("mapping 'stimulation' needs the runner's stimulation map (stimulation=, --stimulation)")
        if self.stimulating and excitation_name == "armrt_excitation":
            excitation_name = "armrt_stimulation"
        self.client = UdpClient(runner_port, runner_host, "groups" if self.stimulating else mapping, model, channels,
                                bind_port=state_port, key=key, stimulation=stimulation)
        channel_names = self.client.stimulation.names if self.client.stimulation else []
        # What the input stream's labels are matched against: the mapping's names, or the stimulation labels.
        self.mapping = self.client.stimulation if self.stimulating else self.client.mapping
        self.input_names = list(self.mapping.labels if self.stimulating else self.mapping.names)
        if endpoint_consumer is not None:
            self.input_names = list(ENDPOINT_LABELS)
        self.endpoint_has = (False, False)  # (velocity, position) channels of the matched endpoint stream
        self.refused = 0  # input samples not forwarded (the Python API would refuse them)
        self.state_port = self.client.local_port
        self.source_id = source_id or f"armrt-{model}"
        self.excitation_name = excitation_name
        self.excitation_source_id = excitation_source_id
        self.excitation_host = excitation_host or socket.gethostname()
        self.forces = forces
        self.excitations = excitations
        self.stream_rows = _stream_rows(model, forces, excitations, channel_names)
        self.outlet = self.pylsl.StreamOutlet(
            state_stream_info(self.pylsl, state_name, f"{self.source_id}-state", state_rate_hz, forces, model,
                              excitations, channel_names))
        self.gh_outlet = self.pylsl.StreamOutlet(
            gh_stream_info(self.pylsl, gh_name, f"{self.source_id}-gh", state_rate_hz, model))
        self.markers = MarkerOutlet(marker_name, f"{self.source_id}-markers", model)
        self.inlet = None
        self.channel_index: np.ndarray | None = None
        self.last_values: np.ndarray | None = None   # the last forwarded excitation, in the mapping's order
        self.forwarded = 0
        self.published = 0
        self.bad = 0
        self.warnings: list[str] = []
        self._warned: set = set()
        self._error: BaseException | None = None
        self._last_time: float | None = None
        self._stop = threading.Event()
        self._connector = threading.Thread(target=self._connect, name="armrt-lsl-resolve", daemon=True)
        self._connector.start()

    @property
    def runner_address(self):
        return self.client.address

    @runner_address.setter
    def runner_address(self, addr) -> None:
        self.client.address = parse_endpoint(f"{addr[0]}:{int(addr[1])}")

    def warn(self, fault: str, message: str) -> None:
        """Prints message once per fault (not once per cycle)."""
        if fault not in self._warned:
            self._warned.add(fault)
            self.warnings.append(message)
            print(f"lsl_bridge: {message}", file=sys.stderr, flush=True)

    # ---------------------------------------------------------------- excitation stream (own thread)
    def _candidates(self, results) -> list:
        if self.excitation_source_id:
            return [r for r in results if r.source_id() == self.excitation_source_id]
        return [r for r in results if r.name() == self.excitation_name and r.hostname() == self.excitation_host]

    def _connect(self) -> None:
        pylsl = self.pylsl
        try:
            if self.excitation_source_id:
                resolver = pylsl.ContinuousResolver(prop="source_id", value=self.excitation_source_id)
            else:
                resolver = pylsl.ContinuousResolver(prop="name", value=self.excitation_name)
            while not self._stop.is_set():
                found = self._candidates(resolver.results())
                if len(found) > 1:
                    who = [f"{f.name()}@{f.hostname()} ({f.source_id()})" for f in found]
                    self.warn("ambiguous", f"{len(found)} excitation streams match, none used: {who}; "
                                           "pin one with --excitation-source-id")
                elif found:
                    inlet = pylsl.StreamInlet(found[0], max_buflen=1, recover=True)
                    full = inlet.info(timeout=5.0)
                    labels = channel_labels(full)
                    self.channel_index = match_labels(labels, self.input_names, f"{full.name()}@{full.hostname()}")
                    if self.endpoint_consumer is not None:  # the same label match, then complete triples
                        self.endpoint_has = endpoint_layout(labels, f"{full.name()}@{full.hostname()}")
                    inlet.open_stream(timeout=5.0)  # subscribed from here on: no sample after this is lost
                    self.inlet = inlet
                    print(f"lsl_bridge: excitation stream {full.name()!r} ({full.source_id()}) on "
                          f"{full.hostname()}: channels matched by label", file=sys.stderr, flush=True)
                    return
                self._stop.wait(0.1)
        except BaseException as e:  # reported by step() on the bridge's own thread
            self._error = e

    # ---------------------------------------------------------------- one pass
    def step(self) -> None:
        """One pass: forward pending excitation samples, publish pending state packets. Raises the
        stream-matching error of the resolver thread, and RuntimeError if the runner does not fill
        the declared channels."""
        if self._error is not None:
            raise self._error
        if self.inlet is not None:
            samples, stamps = self.inlet.pull_chunk(timeout=0.0)
            if samples and self.endpoint_consumer is not None:
                self._forward(self._consume_endpoint(samples, stamps))
            elif samples:  # only the newest matters
                v = np.zeros(len(self.input_names))
                v[self.channel_index] = np.asarray(samples[-1], dtype=float)
                self._forward(v)
        bad0 = self.client.bad_packets + self.client.foreign_packets
        if self.client.poll(0.002):  # the bridge's pace: at most 2 ms idle, then drain without waiting
            while self.client.poll(0.0):
                pass
        bad = self.client.bad_packets + self.client.foreign_packets - bad0
        if bad:
            self.bad += bad
            self.warn("bad-packets", "dropped datagrams on the state port that are not the runner's valid "
                                     "state packets (counted in .bad)")
        for st in self.client.take_states():
            self._publish(st)

    def _forward(self, v) -> None:
        """Sends one input sample (the mapping's order) to the runner as the session's owner; None sends nothing."""
        if v is None:
            return
        try:
            if self.client.session == 0:  # the bridge's own, timed claim (UdpClient.send never waits)
                self.client.join()
            if self.stimulating:
                self.client.send_stimulation(v.reshape(-1, 3))
            else:
                self.client.send(v)
            self.last_values = v
            self.forwarded += 1
        except TimeoutError as e:
            self.warn("no-session", f"the runner gives this bridge no session: {e}")
        except ValueError as e:  # NaN, out of range, beyond a channel's limits: never sent
            self.refused += 1
            kind = "stimulation" if self.stimulating else "excitation"
            self.warn("refused", f"{kind} samples refused, not forwarded (counted in .refused): {e}")

    def _consume_endpoint(self, samples, stamps):
        """Each endpoint-command sample, in order, to the consumer; returns the last excitation it returned."""
        out = None
        commands, refused = endpoint_commands(samples, stamps, self.channel_index, self.endpoint_has)
        if refused:
            self.refused += refused
            self.warn("refused-endpoint", "endpoint command samples with NaN or infinity refused, not given to "
                                          "the consumer (counted in .refused)")
        for cmd in commands:
            r = self.endpoint_consumer(cmd)
            if r is not None:
                out = np.asarray(r, dtype=float)
        return out

    def _publish(self, st: StatePacket) -> None:
        if self.forces and st.muscle_force is None:
            raise RuntimeError("the state stream declares muscle forces but the runner sends none: start "
                               "armrt-rt with --forces, or the bridge without --forces")
        if self.excitations and st.excitation is None:
            raise RuntimeError("the state stream declares excitations but the runner sends none: start "
                               "armrt-rt with --excitations, or the bridge without --excitations")
        if self.client.stimulation is not None and st.stimulation is None:
            raise RuntimeError("the state stream declares stimulation channels but the runner sends none: start "
                               "armrt-rt with the same --stimulation map")
        if self._last_time is not None and not st.stopped:
            dt = st.time - self._last_time
            if dt > 0 and abs(dt - self.state_period) > 1e-6:
                self.warn("rate", f"the runner sends state every {dt * 1e3:.3f} ms of simulated time, the stream "
                                  f"declares {1 / self.state_period:g} Hz: set armrt-rt --state-rate and "
                                  "--rate here to the same value")
        self._last_time = st.time
        if st.overrun:
            self.warn("overrun", f"the runner overran (lag {st.lag:.3f} s): see the lag and overrun channels")
        sample = []
        for r in self.stream_rows:  # the table's rows, in the stream's order
            v = float(st.overrun) if r["name"] == "overrun" else getattr(st, r["name"])
            sample += np.asarray(v, dtype=float).ravel().tolist()
        now = self.pylsl.local_clock()
        self.outlet.push_sample(sample, now)
        self.gh_outlet.push_sample([float(getattr(st, n)) for n in GH_ROWS], now)
        self.published += 1

    def push_marker(self, marker: str, timestamp: float | None = None) -> float:
        """Publishes a task event's marker string on the marker stream ("<source_id>-markers") at `timestamp`
        (LSL clock s; None: now); see MarkerOutlet.push."""
        return self.markers.push(marker, timestamp)

    def run(self, stop: threading.Event | None = None, duration: float | None = None) -> None:
        t_end = None if duration is None else time.monotonic() + duration
        while not (stop is not None and stop.is_set()) and (t_end is None or time.monotonic() < t_end):
            self.step()

    def close(self) -> None:
        self._stop.set()
        self._connector.join(timeout=1.0)
        self.client.close()


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m armrt.lsl_bridge", description=__doc__.split("\n\n")[0])
    ap.add_argument("--runner", default="127.0.0.1:45100", help="the runner's --listen HOST:PORT")
    ap.add_argument("--state-port", type=int, default=45101, help="UDP port the runner sends state to (--state-to)")
    ap.add_argument("--mapping", default="groups", choices=["elements", "muscles", "groups", "channels", "stimulation"])
    ap.add_argument("--stimulation", default=None, help="the runner's --stimulation map (FILE or per_muscle): with "
                                                        "--mapping stimulation, and for the state stream's "
                                                        "stimulation and fatigue channels")
    ap.add_argument("--model", default="das2", help="the runner's --model (names of the state channels and the mapping)")
    ap.add_argument("--channels", default="", help="comma-separated names for --mapping channels")
    ap.add_argument("--source-id", default=None)
    ap.add_argument("--state-name", default="armrt_state")
    ap.add_argument("--gh-name", default="armrt_gh", help="the GH stability stream's name")
    ap.add_argument("--marker-name", default="armrt_markers", help="the marker stream's name")
    ap.add_argument("--excitation-name", default="armrt_excitation",
                    help="the input stream's name (with --mapping stimulation: default armrt_stimulation)")
    ap.add_argument("--excitation-source-id", default=None, help="pin the excitation stream by its source_id")
    ap.add_argument("--excitation-host", default=None, help="host of the excitation stream (default: this one)")
    ap.add_argument("--rate", type=float, default=100.0, help="state rate: the runner's --state-rate")
    ap.add_argument("--runner-rate", type=float, default=1000.0, help="the runner's --rate")
    ap.add_argument("--forces", action="store_true", help="the runner sends forces (--forces)")
    ap.add_argument("--excitations", action="store_true", help="the runner sends excitations (--excitations)")
    ap.add_argument("--key-file", default=None, help="the runner's --key-file")
    ap.add_argument("--duration", type=float, default=None)
    a = ap.parse_args(argv)
    from .realtime import read_key_file
    try:
        host, port = parse_endpoint(a.runner, require_port=True)
        bridge = LslBridge(port, host, a.state_port, a.mapping, channels=[c for c in a.channels.split(",") if c],
                           source_id=a.source_id, state_name=a.state_name, excitation_name=a.excitation_name,
                           state_rate_hz=a.rate, forces=a.forces, excitation_source_id=a.excitation_source_id,
                           excitation_host=a.excitation_host, runner_rate_hz=a.runner_rate,
                           key=read_key_file(a.key_file) if a.key_file else None, model=a.model,
                           excitations=a.excitations, stimulation=a.stimulation, gh_name=a.gh_name,
                           marker_name=a.marker_name)
    except (ValueError, RuntimeError, OSError) as e:
        print(f"lsl_bridge: {e}", file=sys.stderr)
        return 2
    pin = a.excitation_source_id or f"{a.excitation_name} on {bridge.excitation_host}"
    print(f"lsl_bridge: state stream {a.state_name!r} (source_id {bridge.source_id}-state), "
          f"excitation stream {pin} -> udp {a.runner}", flush=True)
    rc = 0
    try:
        bridge.run(duration=a.duration)
    except KeyboardInterrupt:
        pass
    except (ValueError, RuntimeError) as e:
        print(f"lsl_bridge: {e}", file=sys.stderr)
        rc = 2
    finally:
        bridge.close()
    print(f"lsl_bridge: forwarded {bridge.forwarded} excitation samples, published {bridge.published} states")
    return rc


if __name__ == "__main__":
    sys.exit(main())
