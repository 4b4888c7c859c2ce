"""A target task run live: a task (armrt.tasks), a cursor driver (a point cursor or an arm's hand through the
endpoint controller) and a decoder (simulated, or a decoder's LSL endpoint-command stream) -> the task paced to
wall-clock time, its state on the participant display (armrt.display), its events on an LSL marker stream.
docs/tasks.md#participant-display.

    with DisplayServer(plane) as d:
        run_live(task, CursorDriver(start, SimulatedDecoder(dt_s=0.002), 0.002), display=d, markers=MarkerOutlet())
"""
from __future__ import annotations

import math
import time

import numpy as np

from . import checks
from .tasks import _vec3, trial_metrics


def _command(decoder, cursor, target):
    """(velocity (3,) m/s or None, position (3,) m or None) from a decoder: one with command(cursor, target)
    (LslEndpointDecoder) gives both; one with step(cursor, target) (tasks.SimulatedDecoder) a velocity."""
    if hasattr(decoder, "command"):
        return decoder.command(cursor, target)
    return decoder.step(cursor, target), None


class CursorDriver:
    """A point cursor at start (3,) m: each step a decoder's position command sets it and its velocity command
    (m/s) integrates it (explicit Euler, dt_s), as tasks.run_cursor_task. No arm: arm_points() is None."""

    def __init__(self, start, decoder, dt_s: float):
        self.p = _vec3(start, "start").copy()
        self.decoder = decoder
        self.dt_s = checks.real_scalar(dt_s, "dt_s")
        self.gh_stab = math.nan

    def cursor(self) -> np.ndarray:
        return self.p

    def gh_stable(self):
        return None

    def step(self, target) -> None:
        v, x = _command(self.decoder, self.p, target)
        if x is not None:
            self.p = _vec3(x, "position command").copy()
        if v is not None:
            self.p = self.p + self.dt_s * _vec3(v, "velocity command")

    def arm_points(self):
        return None


class ArmDriver:
    """An arm's hand through an EndpointController (armrt.endpoint_control), as run_task: decoder None commands
    the target position; else the decoder's position and/or velocity commands. dt_s is the arm's dt."""

    def __init__(self, controller, decoder=None):
        from .geometry import ArmGeometry
        self.controller = controller
        self.arm = controller.arm
        self.decoder = decoder
        self.dt_s = self.arm.dt
        self.geometry = ArmGeometry(self.arm.model_name)

    @property
    def gh_stab(self) -> float:
        return float(self.arm.gh_stab)

    def cursor(self) -> np.ndarray:
        return self.controller.hand_position()

    def gh_stable(self):
        return bool(self.arm.gh_stab <= 1.0)   # paper eq. 5, as run_task

    def step(self, target) -> None:
        if self.decoder is None:
            if target is not None:
                self.controller.command_position(target)
        else:
            v, x = _command(self.decoder, self.cursor(), target)
            if x is not None:
                self.controller.command_position(x)
            if v is not None:
                self.controller.command_velocity(v)
        self.controller.step()

    def arm_points(self):
        from .display import arm_points
        return arm_points(self.geometry, self.arm.q)

    def shoulder(self) -> np.ndarray:
        return self.arm_points()[0]


class _TargetView:
    """The target's display state from the task's events: shown -> entered <-> shown -> success / timeout, the
    finished trial's colour held through the inter-trial interval; the finished trials' metrics, each computed
    once when its trial ends (not every published state: a long block would make that grow)."""

    def __init__(self, task):
        self.task = task
        self.state = None
        self.target = None
        self.metrics = []

    def on_event(self, ev) -> None:
        tg = self.task.targets[ev.target]
        if ev.kind == "target_shown":
            self.state, self.target = "shown", tg
        elif ev.kind == "target_entered":
            self.state = "entered"
        elif ev.kind == "target_left":
            self.state = "shown"
        elif ev.kind in ("success", "timeout"):
            self.state = ev.kind
            self.metrics.append(trial_metrics(self.task.trials[ev.trial], self.task.dwell_s))


def live_state(plane, task, driver, view: _TargetView, t: float) -> dict:
    """The display_state of a live task at task time t (s)."""
    from .display import display_state
    tg = view.target
    return display_state(plane, cursor=driver.cursor(), target=None if tg is None else tg.position,
                         target_radius_m=0.0 if tg is None else tg.radius_m, target_state=view.state,
                         arm_points=driver.arm_points(), time_s=t, gh_stab=driver.gh_stab,
                         trial=min(task._trial, len(task.targets) - 1), n_trials=len(task.targets),
                         phase="done" if task.done else task._phase, metrics=view.metrics)


def run_live(task, driver, display=None, plane=None, markers=None, fps: float = 60.0, max_time_s: float = 600.0,
             realtime: bool = True, hold_s: float = 1.0, on_event=None, task_stream=None):
    """Runs task with driver (CursorDriver / ArmDriver) one sample per driver.dt_s until the task is done or
    max_time_s passes, paced to wall-clock time when realtime (a late sample is run at once, never skipped:
    .lag_s in the returned stats is the largest lateness). Every 1/fps s of task time (rounded to whole samples)
    the state is published on display (armrt.display.DisplayServer) in plane; each task event is pushed on
    markers (lsl_bridge.MarkerOutlet) as Event.marker() at the LSL time of its sample (the loop's LSL start time
    + the event's task time) and handed to on_event; each sample's state goes on task_stream
    (lsl_bridge.TaskStateOutlet) at the same clock. After the task the last state stays on the display for
    hold_s (s). Returns dict(task, samples, lag_s, published, markers)."""
    dt = float(driver.dt_s)
    fps = checks.real_scalar(fps, "fps")
    if not (math.isfinite(fps) and fps > 0):
        raise ValueError(f"fps must be a finite number > 0, got {fps}")
    every = max(1, int(round(1.0 / (fps * dt))))
    if display is not None and plane is None:
        plane = display.plane
    view = _TargetView(task)
    clock = markers if markers is not None else task_stream
    lsl_t0 = clock.pylsl.local_clock() if clock is not None else 0.0
    stats = {"task": task, "samples": 0, "lag_s": 0.0, "published": 0, "markers": 0}
    user = task.on_event

    def events(ev):
        view.on_event(ev)
        if markers is not None:
            markers.push(ev.marker(), lsl_t0 + ev.time_s)
            stats["markers"] += 1
        for f in (user, on_event):
            if f is not None:
                f(ev)

    task.on_event = events
    wall0 = time.perf_counter()
    t = 0.0
    try:
        for i in range(int(math.ceil(max_time_s / dt))):
            t = i * dt
            if realtime:
                late = time.perf_counter() - wall0 - t
                if late < 0:
                    time.sleep(-late)
                stats["lag_s"] = max(stats["lag_s"], late)
            cursor = driver.cursor()
            st = task.step(t, cursor, gh_stable=driver.gh_stable())
            if task_stream is not None:
                tp = st.target_position if st.target_position is not None else (math.nan,) * 3
                task_stream.push([t, *cursor, *tp, st.target_index, float(st.inside), driver.gh_stab], lsl_t0 + t)
            if display is not None and (i % every == 0 or task.done):
                display.publish(live_state(plane, task, driver, view, t))
                stats["published"] += 1
            stats["samples"] += 1
            if task.done:
                break
            tg = task.current_target()
            driver.step(None if tg is None else tg.position)
    finally:
        task.on_event = user
    if display is not None and hold_s > 0 and realtime:
        time.sleep(hold_s)
    return stats
