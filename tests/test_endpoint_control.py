"""armrt.endpoint_control: the controller reaches 8 centre-out targets on das2 within the task's success radius and
timeout (position commands), follows the simulated decoder's velocity commands, and refuses bad input."""
import numpy as np
import pytest

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
pytest.importorskip("proxsuite", reason="proxsuite (pip install proxsuite) is not installed")
from armrt import tasks  # noqa: E402
from armrt.endpoint_control import EndpointController, EndpointGains, run_task  # noqa: E402

# das2 posture: humerus elevated 60 deg, elbow 60 deg flexed; the hand ~0.3 m below and in front of the shoulder.
Q0 = np.radians([30, 60, 10, 60, 80])


def reach(arm, ctl, task, command, max_steps):
    for _ in range(max_steps):
        x = ctl.hand_position()
        task.step(arm.time, x)
        if task.done:
            break
        command(task, x)
        ctl.step()


def test_reaches_8_centre_out_targets_on_das2():
    arm = armrt.Arm("das2")
    arm.reset(q=Q0)
    centre = arm.model.hand_position(Q0)
    targets = tasks.centre_out_targets(centre, 0.05, 0.015, n_targets=8)  # frontal plane (y-z)
    for k, tg in enumerate(targets):
        arm.reset(q=Q0)
        ctl = EndpointController(arm)
        task = tasks.TargetTask([tg], dwell_s=0.2, timeout_s=3.0, iti_s=0.0)
        reach(arm, ctl, task, lambda t, x: ctl.command_position(tg.position), 3500)
        m = task.trial_metrics()[0]
        assert m["success"], f"target {k} not reached: {np.linalg.norm(ctl.hand_position() - tg.position)} m"
        assert m["time_to_target_s"] < 3.0


def test_follows_simulated_decoder_velocity():
    arm = armrt.Arm("das2")
    arm.reset(q=Q0)
    ctl = EndpointController(arm)
    centre = ctl.hand_position()
    tg = tasks.centre_out_targets(centre, 0.05, 0.015, n_targets=4)[1]  # upwards
    task = tasks.TargetTask([tg], dwell_s=0.2, timeout_s=3.0, iti_s=0.0)
    dec = tasks.SimulatedDecoder(gain_per_s=3.0, noise_sd_m_s=0.005, lag_s=0.05, dt_s=arm.dt, seed=3)
    reach(arm, ctl, task, lambda t, x: ctl.command_velocity(dec.step(x, tg.position)), 3500)
    assert task.trial_metrics()[0]["success"]


def test_run_task_position_mode_two_targets_with_events():
    arm = armrt.Arm("das2")
    arm.reset(q=Q0)
    ctl = EndpointController(arm)
    targets = tasks.centre_out_targets(ctl.hand_position(), 0.05, 0.015, n_targets=4)[:2]
    seen = []
    task = tasks.TargetTask(targets, dwell_s=0.2, timeout_s=3.0, iti_s=0.1, on_event=seen.append)
    run_task(task, ctl, max_time_s=8.0)
    assert task.done and task.block_metrics()["success_rate"] == 1.0
    assert [e.kind for e in seen if e.kind == "success"] == ["success", "success"]
    with pytest.raises(ValueError, match="dt_s"):
        run_task(task, ctl, tasks.SimulatedDecoder(dt_s=0.002))


def test_bad_input_refused():
    arm = armrt.Arm("das2")
    ctl = EndpointController(arm)
    with pytest.raises(ValueError, match="position command"):
        ctl.command_position([0.1, 0.2])
    with pytest.raises(ValueError, match="velocity command"):
        ctl.command_velocity([np.nan, 0, 0])
    with pytest.raises(ValueError, match="kp"):
        EndpointGains(kp=-1)
    with pytest.raises(ValueError, match="solve_every"):
        EndpointGains(solve_every=0)
    with pytest.raises(TypeError, match="EndpointGains"):
        EndpointController(arm, gains={"kp": 1})
