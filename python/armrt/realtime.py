"""Real-time sessions and the patient-in-the-loop UDP protocol (docs/realtime.md).

RealtimeSession runs the model at a fixed rate on a C++ thread (SCHED_FIFO when permitted) without
the GIL; UdpClient is a controller's end of the UDP link: it sends excitations (one value per element,
or muscle / group / channel values through a named mapping) and receives state packets.

    with RealtimeSession(listen="127.0.0.1:0", duration=5) as s:
        with UdpClient(s.port, mapping="groups") as c:
            c.join(timeout=1.0)  # explicit: send() never waits for a session
            c.send({"elbow_flexors": 0.2})
            print(c.recv_state(timeout=0.1).q)
    print(s.stats()["latency_ns"])

The jobs live in three modules; this one re-exports their public names (import from here):
armrt.realtime_packets (the codec: layout, encode/decode, StatePacket), armrt.realtime_client
(GroupMapping, UdpClient) and armrt.realtime_session (RealtimeSession, the armrt-rt runner).
"""
from __future__ import annotations

import warnings

from .realtime_packets import (  # noqa: F401 (armrt.realtime's names, as before the split)
    EXC_CHANNELS, EXC_ELEMENTS, EXC_GROUPS, EXC_MUSCLES, FLAG_AUTH, FLAG_ERROR, FLAG_EXCITATION, FLAG_FORCES,
    FLAG_OVERRUN, FLAG_STIMULATION, FLAG_STOPPED, FLAG_TIMED_OUT, FLAGS, GH_RIM_FIELDS, HEADER, HEADER_FIELDS, HEADER_SIZE, HELLO,
    MAGIC, MAX_VALUES, OFFER, RELEASE, SESSION_ENDED, STATE, STATE_FIELDS, STIMULATION, STATE_FIXED_VALUES, TAG_SIZE, TYPES, VERSION, Packet,
    PacketError, StatePacket, decode_packet, encode_packet, read_key_file, state_fields, state_packet_fields)
from .realtime_client import (MAPPING_TYPES, GroupMapping, SessionEnd, SessionEnded, StimulationChannels,  # noqa: F401
                              StateListener, UdpClient, parse_endpoint)
from .realtime_session import RealtimeSession, rt_main, runner_args, runner_path  # noqa: F401


def __getattr__(name):
    # The packet class was State, which is also the engine's snapshot (armrt.State).
    if name == "State":
        warnings.warn("armrt.realtime.State is deprecated: use armrt.realtime.StatePacket (armrt.State is the "
                      "engine's snapshot)", DeprecationWarning, stacklevel=2)
        return StatePacket
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


if __name__ == "__main__":
    rt_main()
