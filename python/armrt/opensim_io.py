"""OpenSim export: joint angles to a `.mot`, activations to a `.sto` (OpenSim 4 storage format).

`.mot`: one column per coordinate of `das3.osim` (SC_y SC_z SC_x AC_y AC_z AC_x GH_y GH_z GH_yy EL_x
PS_y), the six girdle coordinates held at the model's fixed girdle posture, radians
(`inDegrees=no`), so a result plays on `das3.osim` in OpenSim (File > Load Motion, or
`opensim.Storage` + `Coordinate.setValue`).

`.sto`: one column per muscle element, named with its OpenSim force name (`delt_scap_1`, ...), or
with `/forceset/<name>/activation` (`state_paths=True`) so it reads as an OpenSim states file.

Both: tab-separated, header ending in `endheader`, first column `time`.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from .geometry import find_model_file

GIRDLE_OSIM = ("SC_y", "SC_z", "SC_x", "AC_y", "AC_z", "AC_x")


def model_description(model: str = "das2", model_file: str | Path | None = None) -> dict:
    """The model file (models/<model>.json) as a dict; it holds the girdle angles and OpenSim names."""
    path = Path(model_file) if model_file is not None else find_model_file(model)
    if path is None or not Path(path).exists():
        raise FileNotFoundError(
            f"model file for {model!r} not found (looked for models/{model}.json beside the package and in the "
            f"source checkout, and $ARMRT_MODEL_DIR); pass model_file=")
    return json.loads(Path(path).read_text())


def _write_storage(path, name: str, labels: list[str], time: np.ndarray, data: np.ndarray,
                   in_degrees: bool = False, comment: str = "") -> None:
    time = np.asarray(time, dtype=float).reshape(-1)
    data = np.asarray(data, dtype=float)
    if data.ndim != 2 or data.shape[0] != time.size or data.shape[1] != len(labels):
        raise ValueError(f"data must have shape ({time.size}, {len(labels)}), got {data.shape}")
    if not np.all(np.isfinite(data)) or not np.all(np.isfinite(time)):
        raise ValueError("storage data contain NaN or infinite values")
    if time.size > 1 and np.any(np.diff(time) <= 0):
        raise ValueError("time must be strictly increasing")
    lines = [name, "version=1", f"nRows={time.size}", f"nColumns={len(labels) + 1}",
             f"inDegrees={'yes' if in_degrees else 'no'}"]
    if comment:
        lines += [c for c in comment.splitlines() if "=" not in c and c.strip() != "endheader"]
    lines.append("endheader")
    lines.append("\t".join(["time", *labels]))
    table = np.column_stack([time, data])
    body = "\n".join("\t".join(f"{v:.10g}" for v in row) for row in table)
    Path(path).write_text("\n".join(lines) + "\n" + body + "\n")


def read_storage(path) -> tuple[dict, list[str], np.ndarray]:
    """(header {key: value}, labels including 'time', data (T, ncols)) of a .mot/.sto written here."""
    text = Path(path).read_text().splitlines()
    header: dict[str, str] = {}
    for k, line in enumerate(text):
        if line.strip() == "endheader":
            break
        if "=" in line:
            key, _, value = line.partition("=")
            header[key.strip()] = value.strip()
    else:
        raise ValueError(f"{path}: no 'endheader' line")
    labels = text[k + 1].split("\t")
    rows = [list(map(float, line.split("\t"))) for line in text[k + 2:] if line.strip()]
    return header, labels, np.array(rows).reshape(-1, len(labels))


def coordinate_table(result, model_desc: dict) -> tuple[list[str], np.ndarray]:
    """(OpenSim coordinate names, (T, 11) radians) for a Result: fixed girdle then the five arm DOFs."""
    girdle = [(d["osim_name"], float(d["angle"])) for d in model_desc["girdle"]["dofs"]]
    dofs = model_desc["dofs"]
    if list(result.dof_names) and [d["name"] for d in dofs] != list(result.dof_names):
        raise ValueError(f"result DOFs {result.dof_names} do not match the model's {[d['name'] for d in dofs]}")
    T = len(result.time)
    labels = [n for n, _ in girdle] + [d["osim_name"] for d in dofs]
    data = np.column_stack([np.full(T, a) for _, a in girdle] + [np.asarray(result.q)[:, j] for j in range(len(dofs))])
    return labels, data


def write_mot(result, path, model: str | None = None, model_file=None) -> Path:
    """Joint angles of a Result to an OpenSim motion file (radians, girdle coordinates filled in)."""
    desc = model_description(model or result.model or "das2", model_file)
    labels, data = coordinate_table(result, desc)
    _write_storage(path, Path(path).stem, labels, result.time, data, in_degrees=False)
    return Path(path)


def write_activation_sto(result, path, model: str | None = None, model_file=None,
                         state_paths: bool = False) -> Path:
    """Activations of a Result to an OpenSim storage file, one column per element (OpenSim names)."""
    desc = model_description(model or result.model or "das2", model_file)
    osim = {e["name"]: e.get("osim_name", e["name"]) for e in desc["elements"]}
    names = list(result.element_names) or [e["name"] for e in desc["elements"]]
    missing = [n for n in names if n not in osim]
    if missing:
        raise ValueError(f"elements {missing[:5]} are not in the model file")
    act = np.asarray(result.activation)
    if act.shape[1] != len(names):
        raise ValueError(f"activation has {act.shape[1]} columns, expected {len(names)}")
    labels = [f"/forceset/{osim[n]}/activation" if state_paths else osim[n] for n in names]
    _write_storage(path, Path(path).stem, labels, result.time, act, in_degrees=False)
    return Path(path)


def export(result, mot_path=None, sto_path=None, model_file=None, state_paths: bool = False) -> list[Path]:
    """Both files; returns the paths written."""
    out = []
    if mot_path is not None:
        out.append(write_mot(result, mot_path, model_file=model_file))
    if sto_path is not None:
        out.append(write_activation_sto(result, sto_path, model_file=model_file, state_paths=state_paths))
    return out
