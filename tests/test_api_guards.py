"""Guards of the Python API that cannot be sidestepped (issue 25, B2 and B4): arm.data goes through the
Arm's one-thread guard, armrt.ConcurrentUseError is exported, the control step and substep count are
bounded, set_state checks q as reset does, and masked arrays are refused wherever arrays come in."""
from __future__ import annotations

import copy
import dataclasses
import threading

import numpy as np
import pytest

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")


# ------------------------------------------------------------------------------------ B2: one thread
def test_concurrent_use_error_is_exported():
    """The README names armrt.ConcurrentUseError; it is the class the guard raises."""
    assert armrt.ConcurrentUseError is armrt.arm.ConcurrentUseError
    assert "ConcurrentUseError" in armrt.__all__ and issubclass(armrt.ConcurrentUseError, RuntimeError)


def _while_simulating(arm, calls):
    """Runs each call on this thread while another thread is inside arm.simulate(); returns what each
    raised (None if it returned), and the run's Result."""
    inside, release = threading.Event(), threading.Event()
    out = {}

    def excitation(t):
        if t == 0.0:
            inside.set()
            release.wait(5.0)
        return {"bicb": 0.3}

    worker = threading.Thread(target=lambda: out.setdefault("res", arm.simulate(excitation, 0.02)))
    worker.start()
    assert inside.wait(5.0)
    raised = []
    try:
        for call in calls:
            try:
                call()
                raised.append(None)
            except Exception as exc:  # noqa: BLE001 (what each raised is the result)
                raised.append(exc)
    finally:
        release.set()
        worker.join()
    return raised, out["res"]


def test_arm_data_goes_through_the_arms_guard():
    """arm.data.outputs() evaluates into the workspace the stepping thread is using and set_state
    writes its state: from a second thread they raise ConcurrentUseError, as the Arm's own methods do,
    and the run finishes undisturbed."""
    arm = armrt.Arm(integrator="rk4")
    state = arm.get_state()
    d = arm.data
    calls = [d.outputs, d.get_state, lambda: d.set_state(state), lambda: copy.deepcopy(d), lambda: d.excitation,
             lambda: d.hand_force, lambda: d.hand_moment, lambda: d.time]
    raised, res = _while_simulating(arm, calls)
    for call, exc in zip(["outputs", "get_state", "set_state", "deepcopy", "excitation", "hand_force",
                          "hand_moment", "time"], raised):
        assert isinstance(exc, armrt.ConcurrentUseError), f"arm.data.{call} from a second thread: {exc!r}"
        assert "another thread" in str(exc)
    ref = armrt.Arm(integrator="rk4").simulate({"bicb": 0.3}, 0.02)
    assert np.array_equal(res.q, ref.q)


def test_data_on_the_stepping_thread_is_not_refused():
    """The guard is per thread: a callback of simulate() may read arm.data (re-entrant)."""
    arm = armrt.Arm(integrator="rk4")
    seen = []

    def excitation(t):
        seen.append(arm.data.get_state().time)
        arm.data.outputs()
        return 0.1
    arm.simulate(excitation, 0.005)
    assert len(seen) == 5
