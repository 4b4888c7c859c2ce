"""Weakness profiles: per-element strength and maximum activation from a participant file.

A profile is what a DAS-format participant file (`model_struct_A_FES.mat`, its `fmax` and `maxact`)
or an armrt model file (`models/participant_A_FES.json`: `fmax`, `max_activation`) says about each
element, by element name. `Arm.apply_profile` sets, for every element the arm and the profile share,

    strength       = fmax(profile) / fmax(reference)
    max_activation = maxact(profile)

where the reference is the participant's intact file: given as `reference=`, or found beside the
profile (the same name without its last `_suffix`: `model_struct_A_FES.mat` -> `model_struct_A.mat`,
`participant_A_FES.json` -> `participant_A.json`). Without one, the profile's fmax are taken as
absolute: strength = fmax(profile) / fmax(arm's model), so the arm gets the file's forces as given.
The weakness of a participant thus moves onto any arm (das2 included) that names the same elements.
"""
from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .model_files import find_model_file


@dataclass
class ProfileElements:
    source: str                                  # path read
    fmax: dict[str, float]                       # N, by element name
    max_activation: dict[str, float]             # [0, 1], by element name
    osim_names: dict[str, str] = field(default_factory=dict)   # element name -> OpenSim force name


@dataclass
class ProfileReport:
    """What `Arm.apply_profile` did. `unmatched` are profile elements the arm does not have (by
    element or OpenSim name); `untouched` are arm elements the profile does not name (left as they
    were)."""
    profile: str
    reference: str                               # intact file, or "absolute: ..." when none was found
    applied: list[str]
    unmatched: list[str]
    untouched: list[str]
    strength: dict[str, float]
    max_activation: dict[str, float]

    def __str__(self) -> str:
        lines = [f"profile {self.profile}: {len(self.applied)} elements set (strength relative to {self.reference})"]
        lines.append("unmatched profile elements (not in this arm): " + (", ".join(self.unmatched) or "none"))
        lines.append(f"arm elements not in the profile, left unchanged: {len(self.untouched)}"
                     + (f" ({', '.join(self.untouched[:8])}{', ...' if len(self.untouched) > 8 else ''})"
                        if self.untouched else ""))
        return "\n".join(lines)

    __repr__ = __str__


def _read_mat(path: Path) -> ProfileElements:
    import scipy.io as sio
    try:
        mat = sio.loadmat(path, squeeze_me=True, struct_as_record=False)
    except Exception as exc:  # scipy raises several types for corrupt files
        raise ValueError(f"{path}: not a readable MATLAB file ({exc})") from None
    if "model" not in mat or not hasattr(mat["model"], "muscles"):
        raise ValueError(f"{path}: no DAS-format 'model' struct with 'muscles'")
    fmax, maxact, osim = {}, {}, {}
    for k, mu in enumerate(np.atleast_1d(mat["model"].muscles)):
        name = getattr(mu, "name", None)
        if not isinstance(name, str):
            raise ValueError(f"{path}: model.muscles[{k}] has no 'name'")
        try:
            f = float(mu.fmax)
            a = float(getattr(mu, "maxact", 1.0))
        except (AttributeError, TypeError, ValueError):
            raise ValueError(f"{path}: model.muscles[{k}] ('{name}'): 'fmax' or 'maxact' is not a number") from None
        fmax[name], maxact[name] = f, a
        osim[name] = str(getattr(mu, "osim_name", name))
    return ProfileElements(str(path), fmax, maxact, osim)


def _read_json(path: Path) -> ProfileElements:
    try:
        model = json.loads(path.read_text())
        els = model["elements"]
        fmax = {e["name"]: float(e["fmax"]) for e in els}
        maxact = {e["name"]: float(e.get("max_activation", 1.0)) for e in els}
        osim = {e["name"]: e.get("osim_name", e["name"]) for e in els}
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise ValueError(f"{path}: not an armrt model file with elements' fmax ({exc})") from None
    return ProfileElements(str(path), fmax, maxact, osim)


def resolve(path_or_name) -> Path:
    """A profile path, or a model name looked up like the model files (models/<name>.json)."""
    p = Path(os.fspath(path_or_name))
    if p.suffix in (".mat", ".json") or p.exists():
        if not p.exists():
            raise FileNotFoundError(f"profile file {p} does not exist")
        return p
    found = find_model_file(str(path_or_name))
    if found is None:
        raise FileNotFoundError(f"no profile named {str(path_or_name)!r}: not a file, and no model file "
                                f"models/{path_or_name}.json")
    return found


def read_profile(path_or_name) -> ProfileElements:
    p = resolve(path_or_name)
    prof = _read_mat(p) if p.suffix == ".mat" else _read_json(p)
    for name, v in list(prof.fmax.items()):
        if not (np.isfinite(v) and v >= 0):
            raise ValueError(f"{p}: element '{name}': fmax {v} must be a finite non-negative force")
        a = prof.max_activation[name]
        if not (np.isfinite(a) and 0.0 <= a <= 1.0):
            raise ValueError(f"{p}: element '{name}': maximum activation {a} must lie in [0, 1]")
    return prof


def sibling_reference(path: Path) -> Path | None:
    """The intact file beside a variant: the same name without its last `_suffix`, if it exists."""
    stem = path.stem
    if "_" not in stem:
        return None
    cand = path.with_name(stem.rsplit("_", 1)[0] + path.suffix)
    return cand if cand.exists() and cand != path else None


def profile_values(arm, path_or_name, reference=None):
    """(strength array, max_activation array, ProfileReport) for `arm` without changing it."""
    p = resolve(path_or_name)
    prof = read_profile(p)
    ref_path = resolve(reference) if reference is not None else sibling_reference(p)
    ref = read_profile(ref_path) if ref_path is not None else None
    arm_fmax = np.array([e["fmax"] for e in arm.info["elements"]], dtype=float)
    strength = np.array(arm.strength, dtype=float)
    max_act = np.array(arm.max_activation, dtype=float)
    pos = {n: i for i, n in enumerate(arm.element_names)}

    def by_osim_name(osim: str):
        """The one arm element an OpenSim force name names (the engine's name service), else None."""
        try:
            ix = list(arm.indices(osim))
        except KeyError:
            return None
        return ix[0] if len(ix) == 1 else None
    applied, unmatched, s_out, a_out = [], [], {}, {}
    for name, f in prof.fmax.items():
        i = pos.get(name)
        if i is None and prof.osim_names.get(name):
            i = by_osim_name(prof.osim_names[name])
        if i is None:
            unmatched.append(name)
            continue
        if ref is not None:
            # The same element in the reference: by the profile's name, the arm's, or the OpenSim name.
            key = next((k for k in (name, arm.element_names[i]) if k in ref.fmax), None)
            if key is None:
                key = next((k for k, o in ref.osim_names.items() if o == prof.osim_names.get(name)), None)
            if key is None:
                raise ValueError(f"reference {ref.source} has no element '{name}' (named by the profile {p})")
            f_ref = ref.fmax[key]
        else:
            f_ref = arm_fmax[i]
        if f_ref <= 0:
            raise ValueError(f"reference fmax of '{name}' is {f_ref}: no strength ratio")
        strength[i] = f / f_ref
        max_act[i] = prof.max_activation[name]
        applied.append(arm.element_names[i])
        s_out[arm.element_names[i]], a_out[arm.element_names[i]] = float(strength[i]), float(max_act[i])
    done = set(applied)
    report = ProfileReport(
        profile=str(p), reference=str(ref_path) if ref is not None else f"absolute: fmax of {arm.model_name} (no intact file beside {p.name})",
        applied=applied, unmatched=unmatched, untouched=[n for n in arm.element_names if n not in done],
        strength=s_out, max_activation=a_out)
    return strength, max_act, report
