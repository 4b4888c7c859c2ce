"""Snapshots by signature: the engine's snapshot table (cpp/include/armrt/layouts.h ARMRT_SNAPSHOT, snapshot.h)
as armrt.StatePart flags, as MuJoCo's mjtState names the parts mj_getState copies.

    x = arm.get_state_vector(armrt.StatePart.PHYSICS)   # (2 ndof + 2 n,) q, qdot, lce, activation
    arm.set_state_vector(x, armrt.StatePart.PHYSICS)    # checked in the engine (snapshot_error)

Parts, in vector order (one bit each): TIME (s), Q (rad), QDOT (rad/s), LCE (m), ACTIVATION, EXCITATION (the
held excitation, capped at max_activation), HAND_FORCE (N), HAND_MOMENT (N m), APPLIED_MOMENT (N m per DOF),
STIMULATION, STIMULATION_STATE, ROS2_PATH_HISTORY (ROS2's memory, 4 + 2 ndof values). Groups: PHYSICS (the state vector), INPUTS, INTEGRATOR, FULL (everything: what armrt.State
holds).
"""
from __future__ import annotations

import enum

from . import _core

# (name, size rule, unit, stage, girdle_only, description) per part, in vector order; part k is bit 1 << k.
ROWS = tuple(_core.snapshot_rows())
PART_NAMES = tuple(row[0] for row in ROWS)


def _state_part() -> type:
    members = {name.upper(): 1 << k for k, name in enumerate(PART_NAMES)}
    members.update(PHYSICS=_core.SNAPSHOT_PHYSICS, INPUTS=_core.SNAPSHOT_INPUTS,
                   INTEGRATOR=_core.SNAPSHOT_INTEGRATOR, FULL=_core.SNAPSHOT_FULL)
    # STIMULATION_STATE is one part already (the stimulation chain's memory): no group of the same name.
    flag = enum.IntFlag("StatePart", members, module=__name__)
    flag.__doc__ = ("The parts of a state vector (Arm.get_state_vector), one bit each, OR-able: "
                    + ", ".join(f"{row[0].upper()} ({row[5]})" for row in ROWS)
                    + "; PHYSICS, INPUTS, INTEGRATOR and FULL group them.")
    return flag


StatePart = _state_part()


def signature(parts) -> int:
    """parts (a StatePart, an int of its bits, or a part name such as "physics") -> the engine's signature;
    ValueError for a name or bits no part has."""
    if isinstance(parts, str):
        try:
            return int(StatePart[parts.upper()])
        except KeyError:
            raise ValueError(f"unknown state part {parts!r}; parts: {', '.join(PART_NAMES)}, "
                             "or the groups physics, inputs, integrator, full") from None
    if isinstance(parts, bool) or not isinstance(parts, int):
        raise TypeError(f"parts must be an armrt.StatePart, its int value or a part name, got {type(parts).__name__}")
    if parts <= 0 or parts & ~int(StatePart.FULL):
        raise ValueError(f"parts {parts!r} selects no part or bits beyond StatePart.FULL ({int(StatePart.FULL)})")
    return int(parts)


def part_slices(sim, parts) -> dict:
    """{part name: slice} of the vector of `parts` for the engine arm `sim` (its sizes from the engine)."""
    sig, out, offset = signature(parts), {}, 0
    for k, name in enumerate(PART_NAMES):
        if sig & (1 << k):
            n = sim.snapshot_size(1 << k)
            out[name] = slice(offset, offset + n)
            offset += n
    return out
