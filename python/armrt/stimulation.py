"""Stimulation: an FES stimulator's channels driving the arm's muscle elements (cpp/include/armrt/stimulation.h;
equations, parameters and sources in docs/fes.md).

A stimulation map says which elements each channel (electrode) reaches, with what weight, its electrode kind and
its limits. Maps are files a lab writes (JSON or TOML), Python dicts of the same shape, or "per_muscle" (one
intramuscular channel per muscle, named after it) or "default" (the map the model ships beside its model file,
models/<model>.stimulation.toml):

    arm = armrt.Arm("das2", stimulation="per_muscle")
    arm.set_stimulation({"bicl": (200e-6, 0.020, 30.0)})   # pulse width s, amplitude A, frequency Hz
    arm.step(1000); arm.fatigue["bicl"]

The engine validates maps and commands (errors name the field or channel); the Python API only reshapes.
"""
from __future__ import annotations

import json
import os
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from . import _core
from .model_files import find_model_file
from .checks import real_array

#: Columns of Arm.stimulation_state (the chain's memory per channel, stimulation.h StimState).
STATE_COLUMNS = dict(_core.STIM_STATE_COLUMNS)
STATE_SIZE = int(_core.STIM_STATE_SIZE)


def default_map_path(model_name: str) -> Path:
    """The map a model ships, models/<model>.stimulation.toml beside its model file (docs/fes.md
    "participant_A_FES: the default map and maxact"). ValueError naming the model when it ships none."""
    model_file = find_model_file(model_name)
    path = model_file.with_name(f"{model_name}.stimulation.toml") if model_file is not None else None
    if path is None or not path.exists():
        where = f" (no {path})" if path is not None else " (it has no model file beside which to look)"
        raise ValueError(f"model {model_name!r} ships no default stimulation map{where}; pass a map file, a dict "
                         "or 'per_muscle'")
    return path


def install_map(sim, stimulation, model_name: str | None = None) -> None:
    """stimulation: None (no map: excitation drives every element), "per_muscle", "default" (the map the
    model ships, default_map_path(model_name)), a path to a .json or .toml map, or a dict of the map's shape
    (docs/fes.md "Stimulation maps"). ValueError naming the field for a map the engine refuses, or the model
    for "default" on a model without one; FileNotFoundError for a missing file."""
    if stimulation is None:
        sim.clear_stimulation_map()
    elif isinstance(stimulation, str) and stimulation == "per_muscle":
        sim.set_stimulation_map_per_muscle()
    elif isinstance(stimulation, str) and stimulation == "default":
        if model_name is None:
            raise ValueError("stimulation='default' needs the arm's model name")
        sim.set_stimulation_map_file(os.fspath(default_map_path(model_name)))
    elif isinstance(stimulation, (str, os.PathLike)):
        path = os.fspath(stimulation)
        if not os.path.exists(path):
            raise FileNotFoundError(f"stimulation map {path!r} does not exist "
                                    "(or pass stimulation='per_muscle' for one channel per muscle)")
        sim.set_stimulation_map_file(path)
    elif isinstance(stimulation, Mapping):
        try:
            text = json.dumps(stimulation)
        except TypeError as exc:
            raise ValueError(f"stimulation map: not JSON-serialisable: {exc}") from None
        sim.set_stimulation_map_json(text)
    else:
        raise TypeError("stimulation must be None, 'per_muscle', 'default', a map file path or a dict, "
                        f"got {type(stimulation).__name__}")


def commands(sim, values, current: np.ndarray) -> np.ndarray:
    """{channel name: (pulse_width_s, amplitude_A, frequency_Hz)} (channels not named keep their command) or a
    (channels, 3) array -> the (channels, 3) command array. ValueError for an unknown channel or a bad shape;
    the engine refuses values beyond a channel's limits."""
    names = list(sim.channel_names)
    if not names:
        raise ValueError("this arm has no stimulation map: create it with Arm(model, stimulation=...) or call "
                         "arm.set_stimulation_map(...)")
    out = np.array(current, dtype=float).reshape(len(names), 3)
    if isinstance(values, Mapping):
        for name, v in values.items():
            if name not in names:
                import difflib
                near = difflib.get_close_matches(str(name), names, n=3)
                hint = f" (did you mean {', '.join(map(repr, near))}?)" if near else ""
                raise ValueError(f"unknown stimulation channel {name!r}{hint}; channels: {', '.join(names)}")
            a = real_array(v, f"stimulation[{name!r}]", booleans=False)  # strings were converted by float()
            if a.shape != (3,):
                raise ValueError(f"channel {name!r}: expected (pulse_width_s, amplitude_A, frequency_Hz), got {v!r}")
            out[names.index(name)] = a
    else:
        a = real_array(values, "stimulation", booleans=False)
        if a.shape != (len(names), 3):
            raise ValueError(f"stimulation must be a {{channel: (pulse_width_s, amplitude_A, frequency_Hz)}} dict "
                             f"or an array of shape ({len(names)}, 3), got shape {a.shape}")
        out = a.copy()
    return out
