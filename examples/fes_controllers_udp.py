"""A reference FES controller in its own process driving armrt-rt over UDP in real time (docs/control.md
"Reference FES controllers"): this process runs the real-time loop (armrt.RealtimeSession: das2, participant A's FES
profile, one intramuscular channel per muscle) and starts the controller as a second Python process, which joins
over UDP, reads state packets, calls controller.update(t, q, qdot) and sends stimulation packets at 100 Hz.
Printed: the tracking error and the controller's loop time (compute per cycle, the state's age when its command
left, the period between commands) as percentiles, and the runner's own statistics (overruns, lag).

    python examples/fes_controllers_udp.py --controller blana      # (a) feedforward + PID, a shoulder + elbow movement
    python examples/fes_controllers_udp.py --controller jagodnik   # (b) PD with the optimised gains, a step target
    python examples/fes_controllers_udp.py --controller posture    # (c) posture holding with GHstab <= the limit
    python examples/fes_controllers_udp.py --json out.json         # the same numbers as JSON

The machine's load changes the loop times: the printout records the 1-min load average before and after.
"""
import argparse
import json
import os
import subprocess
import sys

import numpy as np

POSTURE_LIMIT = 0.03   # (c)'s GHstab bound over UDP: below the unloaded hold's 0.038, so that it binds
# s of simulated time the controller first holds the start posture; the runner supports the arm meanwhile
# (--support: the joints held until LEAD_S after the first command), as the offline runs hold it (run_offline hold_s).
LEAD_S = 2.0


def build_controller(kind: str, t_start: float, setup):
    """(controller, dofs whose error is reported, t from which it is reported, t_end) for a trial starting at
    t_start s; setup: fes_controllers_validation._setup() (made before joining: the runner ends a silent session)."""
    from armrt import fes_control as fc
    from armrt import fes_controllers_validation as v
    arm, coding, tau = setup
    if kind == "blana":
        name, amp, dur = v.BLANA_MOVEMENTS[-1]
        t, q = v.movement_reference(arm, amp, dur)
        t = t + t_start + LEAD_S - v.HOLD_S
        t = np.concatenate([[t_start], t])
        q = np.vstack([q[:1], q])
        return fc.FeedforwardPID(fc.model_arm(arm), coding, (t, q), fc.PIDParams.pole_placement(tau)), \
            list(amp), t_start + LEAD_S, float(t[-1])
    if kind == "jagodnik":
        return v.jagodnik_udp_controller(arm, coding, t_start, LEAD_S)
    if kind == "posture":
        return v.posture_udp_controller(arm, coding, tau, t_start, LEAD_S, limit=POSTURE_LIMIT)
    raise ValueError(f"unknown controller {kind!r}")


class Shifted:
    """controller on the runner's clock: update(t, ...) calls controller.update(t - offset, ...)."""

    def __init__(self, controller, offset: float):
        self.controller, self.offset, self.params = controller, offset, controller.params

    def update(self, t, q, qdot):
        return self.controller.update(t - self.offset, q, qdot)

    def reference(self, t):
        if hasattr(self.controller, "reference"):
            return self.controller.reference(t - self.offset)
        return (self.controller.state.target,)


def client(port: int, kind: str) -> dict:
    """The controller process: joins, builds the controller from the first state's time, runs it, returns numbers."""
    from armrt.fes_control_udp import control_loop, first_state
    from armrt import fes_controllers_validation as v
    from armrt.realtime import UdpClient
    setup = v._setup()
    # Built before joining, on a time axis starting at 0, and shifted to the runner's clock once its first state
    # arrives: building takes longer than the runner's input timeout on a loaded machine.
    ctl, dofs, t_from, t_end = build_controller(kind, 0.0, setup)
    with UdpClient(port, stimulation="per_muscle") as c:
        c.join(timeout=10.0)
        st = first_state(c)
        shifted = Shifted(ctl, float(st.time))
        r = control_loop(shifted, c, t_end + shifted.offset)
    t_from += shifted.offset
    import armrt
    arm = armrt.Arm("das2")
    sel = r["time"] >= t_from
    err = {d: np.degrees(r["q"][sel, arm.dof_index(d)] - r["q_ref"][sel, arm.dof_index(d)]) for d in arm.dof_names}
    return {"controller": kind, "cycles": int(r["time"].size),
            "rms_deg": {d: float(np.sqrt(np.mean(e ** 2))) for d, e in err.items()},
            "max_deg": {d: float(np.abs(e).max()) for d, e in err.items()},
            "final_deg": {d: float(abs(e[-1])) for d, e in err.items()},
            "gh_stab_max": float(np.max(r["gh_stab"][sel])),
            "compute_us": r["compute_us"], "age_us": r["age_us"], "period_us": r["period_us"]}


def main(argv=None) -> dict:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--controller", default="blana", choices=["blana", "jagodnik", "posture"])
    p.add_argument("--json", default=None, help="write the numbers to this file")
    p.add_argument("--client", type=int, default=None, help=argparse.SUPPRESS)  # the controller process: port
    a = p.parse_args(argv)
    if a.client is not None:
        print(json.dumps(client(a.client, a.controller)))
        return {}
    import armrt
    from armrt.realtime import RealtimeSession
    load0 = os.getloadavg()[0]
    from armrt import fes_controllers_validation as v
    arm = armrt.Arm("das2")
    q0 = arm.rest_posture.copy()   # (a) and (b) start at rest; (c) is supported at the posture it holds, as offline
    if a.controller == "posture":
        q0[arm.dof_index("GHy")] += v.POSTURE_GHY_RAD
    with RealtimeSession(model="das2", profile="participant_A_FES", stimulation="per_muscle", listen="127.0.0.1:0",
                         state_rate_hz=1000, input_timeout=5.0, q0=q0, support=LEAD_S) as s:
        proc = subprocess.run([sys.executable, os.path.abspath(__file__), "--controller", a.controller,
                               "--client", str(s.port)], capture_output=True, text=True, timeout=600)
        stats = s.stop()
    if proc.returncode != 0:
        raise RuntimeError(f"the controller process failed:\n{proc.stderr}")
    out = json.loads(proc.stdout.strip().splitlines()[-1])
    out["load_average_1min"] = [load0, os.getloadavg()[0]]
    out["runner"] = {"cycles": stats.get("cycles"), "overruns": stats.get("overruns"),
                     "missed_deadlines": stats.get("missed_deadlines"), "scheduler": stats.get("scheduler"),
                     "tet_p99_us": stats.get("tet_ns", {}).get("p99", float("nan")) / 1e3,
                     "stimulation_applied": stats.get("packets", {}).get("stimulation_applied")}
    print(f"controller {out['controller']} in its own process over UDP, {out['cycles']} cycles at 100 Hz "
          f"(1-min load average {load0:.1f} before, {out['load_average_1min'][1]:.1f} after):")
    print("  error (deg) RMS / max / at the end: " + ", ".join(
        f"{d} {out['rms_deg'][d]:.2f} / {out['max_deg'][d]:.2f} / {out['final_deg'][d]:.2f}" for d in out["rms_deg"]))
    print(f"  largest GHstab {out['gh_stab_max']:.3f}")
    for k, label in (("compute_us", "update + send"), ("age_us", "state received -> command sent"),
                     ("period_us", "period between commands")):
        q = out[k]
        print(f"  {label} (us): p50 {q['p50']:.0f}, p90 {q['p90']:.0f}, p99 {q['p99']:.0f}, max {q['max']:.0f}")
    print(f"  runner: {json.dumps(out['runner'])[:300]}")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(out, f, indent=1)
    return out


if __name__ == "__main__":
    main()
