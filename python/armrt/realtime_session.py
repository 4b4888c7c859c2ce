"""armrt-rt's options (keywords, or its argv) -> a running real-time loop, in this process or the armrt-rt runner.

RealtimeSession runs the model at a fixed rate on a C++ thread of this process (armrt._rt.RtLoop);
runner_path / runner_args / rt_main find and start the shipped armrt-rt runner (the console entry point).
"""
from __future__ import annotations

import json
import os
import shutil
import sys
import tempfile
import warnings
from pathlib import Path
from typing import Mapping

import numpy as np

from . import _rt
from .checks import hand_load, real_array, real_scalar
from .realtime_packets import _key_bytes


def _name_value_items(values, model: str, what: str = "max_activation", hi: float = 1.0) -> list[str]:
    """{name: value} or an array of one value per element -> the runner's "NAME=VALUE" items, each value
    in [0, hi] (max_activation: [0, 1]; strength: [0, inf), finite)."""
    if isinstance(values, Mapping):
        items = [(str(k), real_scalar(v, f"{what}[{k!r}]")) for k, v in values.items()]
    else:
        from . import _core
        names = [e["name"] for e in _core.model_info(model)["elements"]]
        arr = real_array(values, what).ravel()
        if arr.size != len(names):
            raise ValueError(f"{what} must have {len(names)} values (one per element), got {arr.size}")
        items = list(zip(names, arr.tolist()))
    bad = [f"{k}={v}" for k, v in items if not (0.0 <= v <= hi and np.isfinite(v))]
    if bad:
        raise ValueError(f"{what} must lie in [0, 1]: {bad[:5]}" if hi == 1.0 else
                         f"{what} must be finite and >= 0: {bad[:5]}")
    return [f"{k}={v!r}" for k, v in items]


def _max_activation_items(values, model: str) -> list[str]:
    """{name: value} or an array of one value per element -> the runner's "NAME=VALUE" items."""
    return _name_value_items(values, model)


# ---------------------------------------------------------------------------------------- session

# The options that are one number (s, Hz, us, 1/s^2, ...): bools refused (rate_hz=True was 1 Hz, so_kp=True a gain of
# 1, duration=True one second) and strings named, before the binding's conversion (its error for a string was a dump
# of the whole constructor signature).
_NUMBER_OPTIONS = ("rate_hz", "integration_step", "dt", "duration", "busy_wait_us", "max_lag", "state_rate_hz",
                   "input_timeout", "rx_budget_us", "settle", "resume_grace", "so_gh_stab_max", "so_kp", "so_kd",
                   "support")
_INTEGER_OPTIONS = ("priority", "cpu")
_OPTIONAL_OPTIONS = ("so_gh_stab_max", "so_kp", "so_kd")  # None: not given (the runner's own default)


def _check_numbers(config: dict) -> None:
    for name in _NUMBER_OPTIONS:
        if name in config and not (name in _OPTIONAL_OPTIONS and config[name] is None):
            config[name] = real_scalar(config[name], name, booleans=False)
    for name in _INTEGER_OPTIONS:
        if name in config:
            v = config[name]
            if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, np.integer)):
                raise TypeError(f"{name} must be an integer, got {type(v).__name__} {v!r}")
            config[name] = int(v)


class RealtimeSession:
    """The real-time loop in-process: a C++ thread steps the model at rate_hz (SCHED_FIFO at
    `priority` when permitted, else normal scheduling with a note in stats()["rt_note"]; with
    require_rt=True start() raises instead). The loop never takes the GIL.

    Parameters are those of armrt-rt (docs/realtime.md): model, integrator, rate_hz, integration_step
    (the integrator's largest step, s; `dt`, its old name, is deprecated: dt is the control step, here
    1/rate_hz), q0, settle (s, finite and >= 0: first relax the arm with zero excitation, then start the loop at
    time 0, as Arm.settle; a simulation failure while settling raises RuntimeError), support (s, finite and >= 0:
    the joints held where the loop starts, at rest, for its first `support` s while the muscles respond as usual,
    the arm supported while stimulation builds up, as fes_control.run_offline(hold_s=...)), duration,
    realtime, priority, lock_memory (mlockall of the whole Python process; off by default), require_rt,
    cpu, busy_wait_us, max_lag, profile (a participant profile, as Arm.apply_profile takes it: a DAS-format .mat,
    an armrt model file or a model name such as "participant_A_FES"; resolved here with armrt.profile into one
    strength and max_activation value per element, the profile's name in stats()["profile"]; profile_reference: its
    reference=; strength / max_activation given too apply on top, as set after apply_profile), listen ("127.0.0.1:0" for an ephemeral port), state_to (one "host:port"
    or a list), allow (list of "host[:port]"), key (bytes >= 16), state_rate_hz, send_forces,
    send_excitation, input_timeout, channels, rx_budget_us, max_activation ({name: value} of elements,
    muscles or groups, or one value per element, in [0, 1]: paralysis and weakness; every excitation,
    and the excitations streamed with send_excitation, are capped at it), strength ({name: value} or one
    value per element, finite and >= 0: scales the elements' DAS3 fmax as Arm.strength does, 1 = intact),
    stimulation (a map: "per_muscle",
    "default" (the model's shipped map), a .json/.toml path or a dict, docs/fes.md; stimulation packets then drive its channels, a packet beyond
    a channel's limits refused whole and counted (stimulation_refused; the previous command held), zeroed when the
    session ends; state packets carry the applied stimulation and the
    fatigue), static_optimization (True: feedforward by the rigid-tendon static optimisation each cycle, the
    client sending targets with UdpClient.send_target; so_kp (1/s^2) and so_kd (1/s): computed-torque gains, the
    solve then at the arm's state; so_gh_stab_max: GHstab bound in the solve; docs/realtime.md; the solve-time
    statistics in stats()["static_optimization"]), hand_force (3,) N and hand_moment (3,) N m (a constant load at the
    hand from the start, thorax frame, as Arm.set_hand_load; the static optimisation accounts for it; recorded in
    stats()["hand_load"]). Bad values raise ValueError naming the option.
    """

    def __init__(self, **config):
        _check_numbers(config)
        if "dt" in config:
            if "integration_step" in config:
                raise ValueError("dt (deprecated) and integration_step both given; use integration_step")
            warnings.warn("RealtimeSession(dt=...) is deprecated: use integration_step (dt is the control step, "
                          "here 1/rate_hz)", DeprecationWarning, stacklevel=2)
            config["integration_step"] = config.pop("dt")
        if "model" in config and not isinstance(config["model"], str) or str(config.get("model", "")).endswith(".json"):
            from .model import Model
            config["model"] = Model(config["model"]).name  # a Model or a model file: loaded and registered
        if "q0" in config and config["q0"] is not None:
            config["q0"] = [float(x) for x in np.asarray(config["q0"], dtype=float).ravel()]
        elif "q0" in config:
            del config["q0"]
        if "channels" in config:
            config["channels"] = list(config["channels"] or [])
        profile, reference = config.pop("profile", None), config.pop("profile_reference", None)
        if profile is not None:
            # The runner does not read profiles (a .mat needs MATLAB's format): Arm.apply_profile resolves one
            # here, strength / max_activation given beside it apply on top (as setting them after apply_profile),
            # and the runner gets one value per element, the profile's name for its statistics.
            from .arm import Arm
            arm = Arm(config.get("model", "das2"))
            arm.apply_profile(profile, reference)
            for name in ("strength", "max_activation"):
                if config.get(name) is not None:
                    setattr(arm, name, config[name])
                config[name] = np.array(getattr(arm, name), dtype=float)
            config["profile"] = os.fspath(profile)
        elif reference is not None:
            raise ValueError("profile_reference without a profile")
        if config.get("max_activation") is not None:
            config["max_activation"] = _max_activation_items(config["max_activation"], config.get("model", "das2"))
        else:
            config.pop("max_activation", None)
        if config.get("strength") is not None:
            config["strength"] = _name_value_items(config["strength"], config.get("model", "das2"), "strength",
                                                   float("inf"))
        else:
            config.pop("strength", None)
        force, moment = config.pop("hand_force", None), config.pop("hand_moment", None)
        if force is not None or moment is not None:
            # checks.hand_load, Data.set_hand_load's rule: (3,) finite each, bools refused.
            none = (0.0, 0.0, 0.0)
            force, moment = hand_load(none if force is None else force, none if moment is None else moment)
            config["hand_force"], config["hand_moment"] = force.tolist(), moment.tolist()
        for name in ("state_to", "allow"):
            if isinstance(config.get(name), str):
                config[name] = [config[name]] if config[name] else []
            elif name in config:
                config[name] = list(config[name] or [])
        if "key" in config:
            config["key"] = _key_bytes(config["key"]) or b""
        self.config = dict(config)
        stim = config.pop("stimulation", None)
        if isinstance(stim, str) and stim == "default":  # the model's shipped map, as Arm(model, stimulation=...)
            from .stimulation import default_map_path
            stim = default_map_path(config.get("model", "das2"))
        if isinstance(stim, Mapping):  # the runner reads files: a dict goes through one, read at construction
            with tempfile.NamedTemporaryFile("w", suffix=".json") as f:
                try:
                    json.dump(stim, f)
                except TypeError as exc:
                    raise ValueError(f"stimulation map: not JSON-serialisable: {exc}") from None
                f.flush()
                try:
                    self._loop = _rt.RtLoop(stimulation=f.name, **config)
                except ValueError as exc:
                    raise ValueError(str(exc).replace(f.name, "the stimulation dict")) from None
        elif stim is not None:
            self._loop = _rt.RtLoop(stimulation=os.fspath(stim), **config)
        else:
            self._loop = _rt.RtLoop(**config)
        self._started = False

    @property
    def channel_names(self) -> list[str]:
        """The stimulation map's channels, in packet order ([] without stimulation)."""
        return list(self._loop.stimulation_channels)

    @property
    def port(self) -> int:
        """UDP port the loop listens on (0 without `listen`)."""
        return self._loop.port

    @property
    def running(self) -> bool:
        return self._loop.running

    @property
    def finished(self) -> bool:
        return self._loop.finished

    def start(self) -> "RealtimeSession":
        self._loop.start()
        self._started = True
        return self

    def wait(self, timeout: float | None = None) -> bool:
        """Waits for the loop to end by itself (duration, divergence); True if it has."""
        return self._loop.wait(-1.0 if timeout is None else float(timeout))

    def stop(self) -> dict:
        """Stops the loop (if running) and returns the final statistics."""
        self._loop.stop()
        return self.stats()

    def stats(self) -> dict:
        """TET, cycle time and wake-up latency percentiles (ns), overruns, packet counters, scheduler."""
        return self._loop.stats()

    def stats_json(self) -> str:
        return self._loop.stats_json()

    def __enter__(self):
        if not self._started:
            self.start()
        return self

    def __exit__(self, *exc):
        self.stop()


# ---------------------------------------------------------------------------------------- runner
def runner_path() -> str:
    """Path of the armrt-rt executable: shipped in the package (armrt/bin), on PATH, or in a build tree."""
    here = Path(__file__).resolve().parent
    candidates = [here / "bin" / "armrt-rt"]
    on_path = shutil.which("armrt-rt")
    if on_path:
        candidates.append(Path(on_path))
    root = here.parent.parent
    candidates += sorted((root / "build").glob("*/cpp/rt/armrt-rt"), key=lambda p: p.stat().st_mtime, reverse=True)
    for c in candidates:
        if c.is_file() and os.access(c, os.X_OK) and c.resolve() != Path(sys.argv[0]).resolve():
            return str(c)
    raise FileNotFoundError("armrt-rt not found: install armrt (pip install .) or build it with CMake (target armrt-rt)")


def _option_value(argv: list[str], k: int, name: str) -> tuple[str | None, int]:
    """(value, arguments it takes) of `--name VALUE` or `--name=VALUE` at argv[k]; (None, 0) for anything else."""
    a = argv[k]
    if a.startswith(f"--{name}="):
        return a.split("=", 1)[1], 1
    if a == f"--{name}" and k + 1 < len(argv):
        return argv[k + 1], 2
    return None, 0


def _profile_items(model: str, profile: str, strength: list[str], max_activation: list[str]) -> list[str]:
    """`--profile NAME|FILE` (with the --strength / --max-activation items given beside it, applied on top, as set
    after Arm.apply_profile) -> the runner's --strength, --max-activation (one value per element) and
    --profile-name arguments. ValueError / FileNotFoundError as Arm.apply_profile and the runner word them."""
    from .arm import Arm
    arm = Arm(model)
    arm.apply_profile(profile)
    for name, items, lo_hi in (("strength", strength, "a finite number >= 0"),
                               ("max_activation", max_activation, "a number in [0, 1]")):
        given = {}
        for item in (x for arg in items for x in arg.split(",") if x):
            key, eq, text = item.partition("=")
            what = name.replace("_", " ")
            if not eq:
                raise ValueError(f"{what} '{item}' is not NAME=VALUE")
            try:
                v = float(text)
            except ValueError:
                v = float("nan")
            hi = 1.0 if name == "max_activation" else float("inf")
            if not (np.isfinite(v) and 0.0 <= v <= hi):
                raise ValueError(f"{what} of '{key}' must be {lo_hi}, got '{text}'")
            given[key] = v
        if given:
            setattr(arm, name, given)
    out = []
    for option, values in (("--strength", arm.strength), ("--max-activation", arm.max_activation)):
        out += [option, ",".join(f"{n}={float(v)!r}" for n, v in zip(arm.element_names, values))]
    return out + ["--profile-name", os.fspath(profile)]


def runner_args(argv: list[str]) -> list[str]:
    """The runner's arguments: `--model FILE.json` (or --model=FILE.json) becomes the model built on demand
    (armrt.Model.load, cached) as `--model-library LIB --model NAME`; `--stimulation default` becomes the map the
    model ships (armrt.stimulation.default_map_path, as Arm(model, stimulation="default"); ValueError for a model
    without one); `--profile NAME|FILE` is resolved with Arm.apply_profile (the runner reads no .mat) into one
    --strength and --max-activation value per element (the --strength / --max-activation given applied on top)
    and --profile-name for the statistics; everything else is passed as is."""
    out, k, model, stimulation_at = [], 0, "das2", None
    profile, strength, max_activation = None, [], []
    while k < len(argv):
        got = False
        for name, store in (("strength", strength), ("max-activation", max_activation)):
            value, taken = _option_value(argv, k, name)
            if value is not None:
                store.append(value)
                out += argv[k:k + taken]  # kept as given unless a profile comes (then merged below)
                k += taken
                got = True
                break
        if got:
            continue
        value, taken = _option_value(argv, k, "profile")
        if value is not None:
            profile = value
            k += taken
            continue
        value, taken = _option_value(argv, k, "model")
        if value is not None:
            model = value
            if value.endswith(".json") or os.sep in value:
                from .model_build import build
                res = build(value)
                model = res.name
                out += ["--model-library", str(res.library), "--model", res.name]
                k += taken
                continue
        value, taken = _option_value(argv, k, "stimulation")
        if value == "default":
            stimulation_at = len(out)
            out += ["--stimulation", "default"]
            k += taken
            continue
        out.append(argv[k])
        k += 1
    if stimulation_at is not None:
        from .stimulation import default_map_path
        out[stimulation_at + 1] = str(default_map_path(model))
    if profile is not None:
        kept, j = [], 0
        while j < len(out):  # the --strength / --max-activation items are merged into the profile's
            if out[j] in ("--strength", "--max-activation") and j + 1 < len(out):
                j += 2
            elif out[j].startswith(("--strength=", "--max-activation=")):
                j += 1
            else:
                kept.append(out[j])
                j += 1
        out = kept + _profile_items(model, profile, strength, max_activation)
    return out


def rt_main() -> None:
    """Console entry point `armrt-rt`: runs the shipped C++ runner with the same arguments (a model file
    given to --model is built on demand first)."""
    exe = runner_path()
    try:
        args = runner_args(sys.argv[1:])
    except (OSError, ValueError, KeyError, RuntimeError) as exc:
        print(f"armrt-rt: {exc.args[0] if isinstance(exc, KeyError) and exc.args else exc}", file=sys.stderr)
        sys.exit(2)
    os.execv(exe, [exe, *args])
