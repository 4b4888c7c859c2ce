"""Target tasks for cursor/BCI control: cursor position each step (s, m) -> target state, events, and per-trial /
per-block metrics. Plain Python state machines, independent of the arm, so a scripted cursor with a known answer
tests each metric (tests/test_tasks.py). Formulas and sources: docs/tasks.md.

Tasks: centre_out_targets / fitts_targets build the target lists; TargetTask runs them (success radius, dwell,
timeout, inter-trial interval); PostureTask holds one target. SimulatedDecoder closes the loop without a person.
"""
from __future__ import annotations

import collections
import math
from dataclasses import dataclass, field
from typing import Callable, Optional

import numpy as np

from . import checks

# s: sample times are floats (i * dt); a dwell/timeout/ITI that ends within 1 ns of a sample ends on that sample.
TIME_TOLERANCE_S = 1e-9

EVENT_KINDS = ("trial_start", "target_shown", "target_entered", "target_left", "success", "timeout", "gh_unstable")


@dataclass(frozen=True)
class Event:
    """One task event: time_s (s, the task clock), kind (one of EVENT_KINDS), trial (0-based), target (index
    into the task's target list). marker() is the string form a marker stream (LSL) can publish unchanged."""
    time_s: float
    kind: str
    trial: int
    target: int

    def marker(self) -> str:
        return f"{self.kind} trial={self.trial} target={self.target}"


@dataclass(frozen=True)
class Target:
    """A target: position (3,) m in the thorax frame, radius_m (success radius, m), condition: a label grouping
    trials for Fitts throughput ((D, W) in m), None otherwise."""
    position: np.ndarray
    radius_m: float
    condition: Optional[tuple] = None


@dataclass
class TrialRecord:
    """What one trial recorded: times (n,) s, cursor (n, 3) m, the events, and the target."""
    trial: int
    target_index: int
    target: Target
    start_time_s: float
    times_s: list = field(default_factory=list)
    cursor_m: list = field(default_factory=list)
    events: list = field(default_factory=list)
    success: bool = False
    end_time_s: float = math.nan


def _vec3(v, what: str) -> np.ndarray:
    a = checks.real_array(v, what)
    if a.shape != (3,):
        raise ValueError(f"{what} must have shape (3,) (x, y, z in m, thorax frame), got {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{what} must be finite, got {a}")
    return a


def _positive(v, what: str, allow_zero: bool = False) -> float:
    x = checks.real_scalar(v, what)
    if not math.isfinite(x) or x < 0 or (x == 0 and not allow_zero):
        raise ValueError(f"{what} must be a finite number {'>=' if allow_zero else '>'} 0, got {x}")
    return x


def _plane_axes(centre, axis_u, axis_v):
    c = _vec3(centre, "centre")
    u = _vec3(axis_u, "axis_u")
    v = _vec3(axis_v, "axis_v")
    nu, nv = np.linalg.norm(u), np.linalg.norm(v)
    if nu == 0 or nv == 0:
        raise ValueError("axis_u and axis_v must be non-zero")
    u, v = u / nu, v / nv
    if abs(float(u @ v)) > 1e-9:
        raise ValueError(f"axis_u and axis_v must be orthogonal, got u.v = {float(u @ v):.3g}")
    return c, u, v


# Frontal plane of the thorax frame (OpenSim/DAS3 axes: x anterior, y up, z right): a vertical screen in front
# of the participant, as in BCI cursor tasks; the centre is given by the caller (reachable by the arm).
FRONTAL_U = (0.0, 0.0, 1.0)
FRONTAL_V = (0.0, 1.0, 0.0)


def centre_out_targets(centre, distance_m: float, radius_m: float, n_targets: int = 8, axis_u=FRONTAL_U,
                       axis_v=FRONTAL_V) -> list[Target]:
    """n_targets targets evenly spaced on a circle of distance_m (m) around centre (3,) m in the plane of
    axis_u, axis_v (orthogonal, thorax frame; default the frontal plane y-z), target k at angle 2 pi k / n
    from axis_u. Raises ValueError for non-positive sizes, non-orthogonal axes, a radius that reaches the centre
    (the cursor would start inside the target) or targets that overlap (each trial would start in the next one)."""
    c, u, v = _plane_axes(centre, axis_u, axis_v)
    d = _positive(distance_m, "distance_m")
    r = _positive(radius_m, "radius_m")
    n = checks.count(n_targets, "n_targets", minimum=1)
    if r >= d:
        raise ValueError(f"radius_m ({r} m) must be below distance_m ({d} m): the cursor would start inside the target")
    gap = 2 * d * math.sin(math.pi / n) if n > 1 else math.inf   # chord between neighbouring targets
    if 2 * r >= gap:
        raise ValueError(f"{n} targets of radius_m {r} m on a circle of {d} m overlap (neighbours {gap:.4g} m "
                         f"apart): fewer targets, a smaller radius or a larger distance")
    return [Target(c + d * (math.cos(2 * math.pi * k / n) * u + math.sin(2 * math.pi * k / n) * v), r)
            for k in range(n)]


def fitts_targets(centre, conditions, n_per_condition: int = 9, axis_u=FRONTAL_U, axis_v=FRONTAL_V) -> list[Target]:
    """ISO 9241-9 multidirectional sequence: for each (D, W) in conditions (m: distance between opposite targets,
    target width = 2 x success radius), n_per_condition (odd) targets on a circle of diameter D visited in the
    order 0, (n+1)/2, 1, (n+1)/2 + 1, ... so successive targets are (nearly) opposite. Each target's condition
    is (D, W). Raises ValueError for an even or small n, or W >= D."""
    c, u, v = _plane_axes(centre, axis_u, axis_v)
    n = checks.count(n_per_condition, "n_per_condition", minimum=3)
    if n % 2 == 0:
        raise ValueError(f"n_per_condition must be odd (ISO 9241-9 circle), got {n}")
    out = []
    for D, W in conditions:
        D = _positive(D, "Fitts distance D")
        W = _positive(W, "Fitts width W")
        if W >= D:
            raise ValueError(f"Fitts width W ({W}) must be smaller than the distance D ({D})")
        half = (n + 1) // 2
        order = [(i // 2) if i % 2 == 0 else (i // 2 + half) for i in range(n)]
        for k in order:
            a = 2 * math.pi * k / n
            out.append(Target(c + 0.5 * D * (math.cos(a) * u + math.sin(a) * v), W / 2, (D, W)))
    return out


@dataclass(frozen=True)
class TaskState:
    """What step() returns: target index (-1 between trials), its position (3,) m or None, radius m, whether the
    cursor is inside, the trial index, and done (all trials finished)."""
    target_index: int
    target_position: Optional[np.ndarray]
    radius_m: float
    inside: bool
    trial: int
    done: bool


class TargetTask:
    """Runs targets in order: inter-trial interval (iti_s, no target), then the target is shown; success when the
    cursor stays within the target's radius for dwell_s (continuously); timeout when timeout_s passes since the
    target was shown. Call step(t, cursor) once per sample with increasing t (s) and cursor (3,) m; gh_stable
    (bool or None) reports the arm's glenohumeral stability so a loss emits a 'gh_unstable' event.
    on_event(Event) is called for each event. Raises ValueError for bad settings or input."""

    def __init__(self, targets, dwell_s: float = 0.5, timeout_s: float = 10.0, iti_s: float = 0.5,
                 on_event: Callable[[Event], None] | None = None):
        self.targets = list(targets)
        if not self.targets:
            raise ValueError("the task needs at least one target")
        for k, tg in enumerate(self.targets):
            if not isinstance(tg, Target):
                raise TypeError(f"target {k} must be an armrt.tasks.Target, got {type(tg).__name__}")
        self.dwell_s = _positive(dwell_s, "dwell_s", allow_zero=True)
        self.timeout_s = _positive(timeout_s, "timeout_s")
        self.iti_s = _positive(iti_s, "iti_s", allow_zero=True)
        if self.dwell_s >= self.timeout_s:
            raise ValueError(f"dwell_s ({self.dwell_s}) must be shorter than timeout_s ({self.timeout_s})")
        if on_event is not None and not callable(on_event):
            raise TypeError("on_event must be callable (Event) -> None")
        self.on_event = on_event
        self.events: list[Event] = []
        self.trials: list[TrialRecord] = []
        self._trial = 0
        self._phase = "iti"
        self._phase_start = None
        self._inside = False
        self._enter_time = None
        self._gh_stable = True
        self._last_t = None
        self.done = False

    def _emit(self, t, kind, record=None):
        ev = Event(float(t), kind, self._trial, self._trial_target())
        self.events.append(ev)
        if record is not None:
            record.events.append(ev)
        if self.on_event is not None:
            self.on_event(ev)

    def _trial_target(self) -> int:
        return min(self._trial, len(self.targets) - 1)

    def step(self, t, cursor, gh_stable: bool | None = None) -> TaskState:
        t = checks.real_scalar(t, "t")
        if not math.isfinite(t):
            raise ValueError(f"t must be finite, got {t}")
        if self._last_t is not None and t < self._last_t:
            raise ValueError(f"t must not decrease: {t} after {self._last_t}")
        self._last_t = t
        p = _vec3(cursor, "cursor")
        if self.done:
            return TaskState(-1, None, 0.0, False, self._trial, True)
        if self._phase_start is None:
            self._phase_start = t
        rec = self.trials[-1] if self._phase == "target" else None
        if gh_stable is not None:
            if self._gh_stable and not gh_stable:
                self._emit(t, "gh_unstable", rec)
            self._gh_stable = bool(gh_stable)
        if self._phase == "iti" and t - self._phase_start >= self.iti_s - TIME_TOLERANCE_S:
            self._phase, self._phase_start = "target", t
            rec = TrialRecord(self._trial, self._trial, self.targets[self._trial], t)
            self.trials.append(rec)
            self._inside, self._enter_time = False, None
            self._emit(t, "trial_start", rec)
            self._emit(t, "target_shown", rec)
        if self._phase != "target":
            return TaskState(-1, None, 0.0, False, self._trial, False)
        tg = rec.target
        rec.times_s.append(t)
        rec.cursor_m.append(p)
        inside = float(np.linalg.norm(p - tg.position)) <= tg.radius_m
        if inside and not self._inside:
            self._emit(t, "target_entered", rec)
            self._enter_time = t
        elif self._inside and not inside:
            self._emit(t, "target_left", rec)
            self._enter_time = None
        self._inside = inside
        state_trial = self._trial
        if inside and t - self._enter_time >= self.dwell_s - TIME_TOLERANCE_S:
            rec.success, rec.end_time_s = True, t
            self._emit(t, "success", rec)
            self._end_trial(t)
        elif t - rec.start_time_s >= self.timeout_s - TIME_TOLERANCE_S:
            rec.end_time_s = t
            self._emit(t, "timeout", rec)
            self._end_trial(t)
        return TaskState(state_trial, tg.position, tg.radius_m, inside, state_trial, self.done)

    def _end_trial(self, t):
        self._trial += 1
        self._phase, self._phase_start = "iti", t
        if self._trial >= len(self.targets):
            self.done = True

    def current_target(self) -> Optional[Target]:
        """The shown target, or None between trials / when done."""
        return self.trials[-1].target if self._phase == "target" and not self.done else None

    def trial_metrics(self) -> list[dict]:
        """Per-trial metrics (see trial_metrics)."""
        return [trial_metrics(r, self.dwell_s) for r in self.trials]

    def block_metrics(self) -> dict:
        """Per-block metrics (see block_metrics)."""
        return block_metrics(self.trial_metrics())


class PostureTask(TargetTask):
    """Posture holding: hold the cursor within radius_m of position (3,) m for hold_s (the dwell) within
    timeout_s, n_trials times. Metrics add the RMS distance from the target over the hold (m)."""

    def __init__(self, position, radius_m: float, hold_s: float = 2.0, timeout_s: float = 10.0, n_trials: int = 1,
                 iti_s: float = 0.5, on_event=None):
        tg = Target(_vec3(position, "position"), _positive(radius_m, "radius_m"))
        n = checks.count(n_trials, "n_trials", minimum=1)
        super().__init__([tg] * n, dwell_s=hold_s, timeout_s=timeout_s, iti_s=iti_s, on_event=on_event)


def _first_time(rec: TrialRecord, kind: str):
    for ev in rec.events:
        if ev.kind == kind:
            return ev.time_s
    return None


def _last_entry_time(rec: TrialRecord):
    t = None
    for ev in rec.events:
        if ev.kind == "target_entered":
            t = ev.time_s
    return t


def trial_metrics(rec: TrialRecord, dwell_s: float) -> dict:
    """One trial's metrics (docs/tasks.md):
    success (bool); time_to_target_s: target shown -> first entry (NaN if never entered);
    acquisition_time_s: target shown -> start of the successful dwell (success only);
    dial_in_time_s: first entry -> start of the successful dwell (0 when the first entry holds; success only);
    path_efficiency: straight-line distance / path length, both from the cursor at trial start to the cursor at
    the final target entry (success only; 1 for a straight path, <= 1 always; the dwell is excluded so hold
    jitter does not count);
    n_entries; gh_unstable_events; hold_rms_m: RMS distance to the target over the successful dwell;
    endpoint_m (3,): cursor at selection; start_m (3,): cursor at trial start; target_m (3,)."""
    times = np.asarray(rec.times_s, float)
    cur = np.asarray(rec.cursor_m, float).reshape(-1, 3)
    tg = rec.target
    first = _first_time(rec, "target_entered")
    out = {"trial": rec.trial, "target": rec.target_index, "success": bool(rec.success),
           "time_to_target_s": (first - rec.start_time_s) if first is not None else math.nan,
           "acquisition_time_s": math.nan, "dial_in_time_s": math.nan, "path_efficiency": math.nan,
           "n_entries": sum(ev.kind == "target_entered" for ev in rec.events),
           "gh_unstable_events": sum(ev.kind == "gh_unstable" for ev in rec.events),
           "hold_rms_m": math.nan, "start_m": cur[0].tolist() if len(cur) else None,
           "endpoint_m": cur[-1].tolist() if len(cur) else None, "target_m": tg.position.tolist(),
           "condition": tg.condition}
    if rec.success:
        last = _last_entry_time(rec)
        out["acquisition_time_s"] = last - rec.start_time_s
        out["dial_in_time_s"] = last - first
        k = int(np.searchsorted(times, last))
        seg = cur[:k + 1]
        length = float(np.sum(np.linalg.norm(np.diff(seg, axis=0), axis=1)))
        ideal = float(np.linalg.norm(seg[-1] - seg[0]))
        out["path_efficiency"] = ideal / length if length > 0 else math.nan
        hold = cur[k:]
        out["hold_rms_m"] = float(np.sqrt(np.mean(np.sum((hold - tg.position) ** 2, axis=1))))
    return out


# ISO 9241-9 effective width factor: We = sqrt(2 pi e) SD = 4.133 SD (Soukoreff & MacKenzie 2004).
EFFECTIVE_WIDTH_FACTOR = math.sqrt(2 * math.pi * math.e)


def fitts_throughput(starts, endpoints, targets, movement_times_s) -> dict:
    """ISO 9241-9 effective throughput of one (D, W) condition (Soukoreff & MacKenzie 2004, Int J Hum-Comput
    Stud 61:751): for each trial, the endpoint's distance along the start->target axis, a = (end - start).u;
    dx = a - |target - start|; We = 4.133 SD(dx) (sample SD, ddof=1); De = mean(a); IDe = log2(De/We + 1) bits;
    MT = mean movement time (s); TP = IDe / MT (bits/s). starts, endpoints, targets (n, 3) m, movement_times_s (n,)
    s, n >= 2. Returns dict(We_m, De_m, IDe_bits, MT_s, TP_bits_per_s). Raises ValueError for n < 2 or SD 0."""
    s = checks.real_array(starts, "starts").reshape(-1, 3)
    e = checks.real_array(endpoints, "endpoints").reshape(-1, 3)
    g = checks.real_array(targets, "targets").reshape(-1, 3)
    mt = checks.real_array(movement_times_s, "movement_times_s").ravel()
    n = len(mt)
    if not (len(s) == len(e) == len(g) == n):
        raise ValueError(f"starts, endpoints, targets and movement_times_s must have the same length, got "
                         f"{len(s)}, {len(e)}, {len(g)}, {n}")
    if n < 2:
        raise ValueError(f"Fitts throughput needs at least 2 trials per condition, got {n}")
    dist = np.linalg.norm(g - s, axis=1)
    if np.any(dist == 0):
        raise ValueError("a Fitts trial starts at its target: the task axis is undefined")
    u = (g - s) / dist[:, None]
    a = np.sum((e - s) * u, axis=1)
    sd = float(np.std(a - dist, ddof=1))
    if sd == 0:
        raise ValueError("the endpoint spread is 0: the effective width is undefined")
    We = EFFECTIVE_WIDTH_FACTOR * sd
    De = float(np.mean(a))
    IDe = math.log2(De / We + 1)
    MT = float(np.mean(mt))
    return {"We_m": We, "De_m": De, "IDe_bits": IDe, "MT_s": MT, "TP_bits_per_s": IDe / MT}


def block_metrics(trials: list[dict]) -> dict:
    """Per-block metrics from trial_metrics rows: n_trials, success_rate (successes / trials), mean and median of
    time_to_target_s, acquisition_time_s, dial_in_time_s, path_efficiency (over the trials where defined),
    gh_unstable_events (sum), and, where trials carry Fitts conditions, per-condition fitts_throughput over the
    successful trials (start = cursor at trial start, endpoint = cursor at selection, MT = acquisition time) and
    their mean TP_bits_per_s (the mean of means, Soukoreff & MacKenzie 2004)."""
    n = len(trials)
    out = {"n_trials": n, "success_rate": (sum(t["success"] for t in trials) / n) if n else math.nan,
           "gh_unstable_events": int(sum(t["gh_unstable_events"] for t in trials))}
    for key in ("time_to_target_s", "acquisition_time_s", "dial_in_time_s", "path_efficiency"):
        vals = np.array([t[key] for t in trials], float)
        vals = vals[np.isfinite(vals)]
        out[f"mean_{key}"] = float(np.mean(vals)) if len(vals) else math.nan
        out[f"median_{key}"] = float(np.median(vals)) if len(vals) else math.nan
    conds = {}
    for t in trials:
        if t["condition"] is not None and t["success"]:
            conds.setdefault(tuple(t["condition"]), []).append(t)
    if conds:
        per = {}
        for c, rows in conds.items():
            if len(rows) < 2:
                continue
            try:
                per[c] = fitts_throughput([r["start_m"] for r in rows], [r["endpoint_m"] for r in rows],
                                          [r["target_m"] for r in rows],
                                          [r["acquisition_time_s"] for r in rows])
            except ValueError:
                continue
        out["fitts"] = {f"D={c[0]:g} W={c[1]:g}": v for c, v in per.items()}
        tps = [v["TP_bits_per_s"] for v in per.values()]
        out["fitts_TP_bits_per_s"] = float(np.mean(tps)) if tps else math.nan
    return out


@dataclass
class SimulatedDecoder:
    """A simulated velocity decoder (the standard closed-loop BCI simulation form: an intended velocity towards the
    target, plus Gaussian noise, delivered after a lag; cf. Cunningham et al. 2011, J Neurophysiol 105:1932):
        v_int(t) = gain_per_s * (target - cursor(t)), its norm clipped to max_speed_m_s;
        v_out(t) = v_int(t - lag_s) + noise,  noise ~ N(0, noise_sd_m_s^2) per axis, seeded.
    gain_per_s (1/s), noise_sd_m_s (m/s per axis), lag_s (s, rounded to whole dt_s samples), dt_s (s), seed.
    step(cursor, target) -> velocity (3,) m/s; target None (between trials) -> intended velocity 0."""
    gain_per_s: float = 4.0
    noise_sd_m_s: float = 0.02
    lag_s: float = 0.05
    dt_s: float = 0.001
    max_speed_m_s: float = 0.5
    seed: int = 0

    def __post_init__(self):
        self.gain_per_s = _positive(self.gain_per_s, "gain_per_s", allow_zero=True)
        self.noise_sd_m_s = _positive(self.noise_sd_m_s, "noise_sd_m_s", allow_zero=True)
        self.lag_s = _positive(self.lag_s, "lag_s", allow_zero=True)
        self.dt_s = _positive(self.dt_s, "dt_s")
        self.max_speed_m_s = _positive(self.max_speed_m_s, "max_speed_m_s")
        self.seed = checks.count(self.seed, "seed")
        self.lag_samples = int(round(self.lag_s / self.dt_s))
        self.reset()

    def reset(self):
        """Empty the lag line and restart the noise sequence from the seed."""
        self._rng = np.random.default_rng(self.seed)
        self._line = collections.deque([np.zeros(3)] * self.lag_samples)

    def intended(self, cursor, target) -> np.ndarray:
        """The noise-free, undelayed velocity (3,) m/s."""
        if target is None:
            return np.zeros(3)
        v = self.gain_per_s * (_vec3(target, "target") - _vec3(cursor, "cursor"))
        s = float(np.linalg.norm(v))
        return v * (self.max_speed_m_s / s) if s > self.max_speed_m_s else v

    def step(self, cursor, target) -> np.ndarray:
        self._line.append(self.intended(cursor, target))
        v = self._line.popleft()
        return v + self._rng.normal(0.0, self.noise_sd_m_s, 3)


def run_cursor_task(task: TargetTask, decoder: SimulatedDecoder, start, max_time_s: float = 600.0) -> TargetTask:
    """Close the loop without an arm: a point cursor integrates the decoder's velocity (explicit Euler, dt_s) from
    start (3,) m until the task is done or max_time_s passes. Returns the task (its trials, events, metrics)."""
    p = _vec3(start, "start").copy()
    t = 0.0
    n = int(math.ceil(_positive(max_time_s, "max_time_s") / decoder.dt_s))
    for i in range(n):
        t = i * decoder.dt_s
        task.step(t, p)
        if task.done:
            break
        tg = task.current_target()
        p = p + decoder.dt_s * decoder.step(p, None if tg is None else tg.position)
    return task
