"""A target task run live: a task (armrt.tasks), a cursor driver (a point cursor, an arm's hand through the
endpoint controller, or the hand of a running armrt-rt driven from outside: RunnerDriver) and a decoder (simulated, or a decoder's LSL endpoint-command stream) -> the task paced to
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


class RunnerDriver:
    """The hand of a running armrt-rt as the cursor (its --state-to stream, docs/realtime.md): the arm is driven from
    outside the task (a lab's controller sending excitations or stimulation over UDP, or through the LSL bridge,
    issue 29 item 1(b)); the task only measures. Binds host:port (UDP; loopback unless another address is named)
    and waits up to wait_s s for the first state packet (RuntimeError naming the port when none comes). Each step
    takes the packets that arrived (non-blocking) and keeps the newest: cursor() is its hand_position (3,) m,
    thorax frame; gh_stab its GHstab. Datagrams that are not the model's state packets (or not signed with key) are
    counted in .bad_packets (.last_error says why), never drawn. stale_s is the longest gap between packets seen
    (s, the silence up to now included): a runner that stopped or a network that dropped packets shows there; a
    silence longer than max_silence_s (s) raises RunnerSilent from step(), so no trial is scored on a frozen hand.
    dt_s: the task's sample interval (s)."""

    def __init__(self, host: str = "127.0.0.1", port: int = 9870, model: str = "das2", key: bytes | None = None,
                 dt_s: float = 0.002, wait_s: float = 5.0, max_silence_s: float = 1.0):
        import socket

        from . import realtime
        from .geometry import ArmGeometry
        self.dt_s = checks.real_scalar(dt_s, "dt_s")
        if not (math.isfinite(self.dt_s) and self.dt_s > 0):
            raise ValueError(f"dt_s must be a finite number of seconds > 0, got {dt_s}")
        self.max_silence_s = checks.real_scalar(max_silence_s, "max_silence_s")
        if not self.max_silence_s > 0:
            raise ValueError(f"max_silence_s must be > 0 s, got {max_silence_s}")
        self.geometry = ArmGeometry(model)
        self._listener = realtime.StateListener(host, port, model, key)
        self._sock = self._listener.sock
        self.port = self._listener.port
        host = self._listener.host
        self.stale_s = 0.0
        self.packet = None
        self._last = None
        self._sock.settimeout(checks.real_scalar(wait_s, "wait_s"))
        try:
            while self.packet is None:
                self._take(self._sock.recv(65536))
        except (TimeoutError, socket.timeout):
            self._sock.close()
            why = f" ({self.bad_packets} datagrams refused: {self.last_error})" if self.bad_packets else ""
            raise RuntimeError(f"no armrt-rt state packet on {host}:{self.port} after {wait_s:g} s{why} "
                               f"(is the runner started with --state-to {host}:{self.port}?)") from None
        self._sock.setblocking(False)

    # Packet counts and the last refusal's reason are the listener's.
    packets = property(lambda self: self._listener.packets)
    bad_packets = property(lambda self: self._listener.bad_packets)
    last_error = property(lambda self: self._listener.last_error)

    def _take(self, data: bytes) -> None:
        pkt = self._listener.decode(data)
        if pkt is None:
            return
        now = time.perf_counter()
        if self._last is not None:
            self.stale_s = max(self.stale_s, now - self._last)
        self._last = now
        self.packet = pkt

    def poll(self) -> None:
        while True:
            try:
                data = self._sock.recv(65536)
            except (BlockingIOError, InterruptedError):
                return
            self._take(data)

    @property
    def gh_stab(self) -> float:
        return float(self.packet.gh_stab)

    def cursor(self) -> np.ndarray:
        return np.asarray(self.packet.hand_position, dtype=float)

    def gh_stable(self):
        return bool(self.packet.gh_stab <= 1.0)   # paper eq. 5, as run_task

    def step(self, target) -> None:
        self.poll()
        silence = time.perf_counter() - self._last
        if silence > self.max_silence_s:
            self.stale_s = max(self.stale_s, silence)
            raise RunnerSilent(f"the runner sent no state for {silence:.2f} s on port {self.port} (stopped, or its "
                               f"packets are lost): the task stops rather than score a frozen hand")

    def arm_points(self):
        from .display import arm_points
        return arm_points(self.geometry, np.asarray(self.packet.q, dtype=float))

    def shoulder(self) -> np.ndarray:
        return self.arm_points()[0]

    def close(self) -> None:
        if self._last is not None:
            self.stale_s = max(self.stale_s, time.perf_counter() - self._last)
        self._sock.close()


class RunnerSilent(RuntimeError):
    """RunnerDriver: the runner's state stopped coming for longer than max_silence_s."""


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


# Finished trials' rows sent with each state for the operator page: the newest this many. All of them would make every
# state of a long session (--repeat: hundreds of trials) larger and slower to build, at 60 states per second.
OPERATOR_ROWS = 50


def live_state(plane, task, driver, view: _TargetView, t: float) -> dict:
    """The display_state of a live task at task time t (s); metrics: the newest OPERATOR_ROWS finished trials."""
    from .display import display_state
    tg = view.target
    return display_state(plane, cursor=driver.cursor(), target=None if tg is None else tg.position,
                         target_radius_m=0.0 if tg is None else tg.radius_m, target_state=view.state,
                         arm_points=driver.arm_points(), time_s=t, gh_stab=driver.gh_stab,
                         trial=min(task._trial, len(task.targets) - 1), n_trials=len(task.targets),
                         phase="done" if task.done else task._phase, metrics=view.metrics[-OPERATOR_ROWS:])


def run_live(task, driver, display=None, plane=None, markers=None, fps: float = 60.0, max_time_s: float = 600.0,
             realtime: bool = True, hold_s: float = 1.0, on_event=None, task_stream=None, stats: dict | None = None):
    """Runs task with driver (CursorDriver / ArmDriver) one sample per driver.dt_s until the task is done or
    max_time_s passes, paced to wall-clock time when realtime (a late sample is run at once, never skipped:
    .lag_s in the returned stats is the largest lateness). Every 1/fps s of task time (rounded to whole samples)
    the state is published on display (armrt.display.DisplayServer) in plane; each task event is pushed on
    markers (lsl_bridge.MarkerOutlet) as Event.marker() at the LSL time of its sample (the loop's LSL start time
    + the event's task time) and handed to on_event; each sample's state goes on task_stream
    (lsl_bridge.TaskStateOutlet) at the same clock. After the task the last state stays on the display for
    hold_s (s). Returns dict(task, samples, lag_s, published, markers, streamed: samples pushed on task_stream): the
    dict stats if given, filled as the loop
    runs (so a caller has the figures of a loop stopped by an exception)."""
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
    stats = stats if stats is not None else {}
    stats.update({"task": task, "samples": 0, "lag_s": 0.0, "published": 0, "markers": 0, "streamed": 0})
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
                stats["streamed"] += 1
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
