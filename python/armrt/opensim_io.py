"""OpenSim export: joint angles to a `.mot`, activations to a `.sto` (OpenSim 4 storage format).

`.mot`: one column per coordinate of `das3.osim` (SC_y SC_z SC_x AC_y AC_z AC_x GH_y GH_z GH_yy EL_x
PS_y), radians (`inDegrees=no`), so a result plays on `das3.osim` in OpenSim (File > Load Motion, or
`opensim.Storage` + `Coordinate.setValue`). A fixed-scapula model (das2) holds the six girdle
coordinates at its fixed girdle posture (the model file's `girdle` block); a model with the girdle
free (das3) writes its own values of all eleven.

`.sto`: one column per muscle element, named with its OpenSim force name (`delt_scap_1`, ...), or
with `/forceset/<name>/activation` (`state_paths=True`) so it reads as an OpenSim states file.

Controls `.sto` (`write_excitation_sto`): the excitations the dynamics used (after clipping to [0, 1]
and capping at max_activation), one column per element with its OpenSim force name: an OpenSim
controls file.

Stimulation `.sto` (`write_stimulation_sto`): for an arm with a stimulation map, five columns per
channel, `<channel>/pulse_width` (s), `<channel>/amplitude` (A), `<channel>/frequency` (Hz) of the held
command, `<channel>/recruitment` and `<channel>/fatigue` (1 - A/A_rest), both fractions in [0, 1].

All: tab-separated, header ending in `endheader`, first column `time`.

Import: `read_motion(path)` reads a `.mot`/`.sto` of joint angles (OpenSim coordinate names or armrt
DOF names, `inDegrees=yes` converted to radians) into a `Motion`: a start posture for `Arm.reset`
(`motion.posture(t)`) or a kinematic replay (`motion.to_result()`, for `armrt animate` / `view`).
"""
from __future__ import annotations

import difflib
import json
import re
from pathlib import Path

import numpy as np

import warnings
from dataclasses import dataclass

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


def _table_row_by_row(path, text: list[str], k: int, labels: list[str]) -> np.ndarray:
    """(T, len(labels)) of the lines after text[k] (the labels), or ValueError naming the first line with the wrong
    number of values or a value that is not a number."""
    rows = []
    for lineno, line in enumerate(text[k + 1:], start=k + 2):
        if not line.strip():
            continue
        fields = line.split()
        if len(fields) != len(labels):
            raise ValueError(f"{path}:{lineno}: {len(fields)} values, expected {len(labels)}")
        try:
            rows.append([float(v) for v in fields])
        except ValueError:
            raise ValueError(f"{path}:{lineno}: not a number in {line[:60]!r}") from None
    return np.array(rows, dtype=float).reshape(-1, len(labels))


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
    k += 1
    while k < len(text) and not text[k].strip():  # blank lines before the labels (a trial's file had one)
        k += 1
    if k >= len(text):
        raise ValueError(f"{path}: no column labels after 'endheader'")
    labels = text[k].split()
    body = [line for line in text[k + 1:] if line.strip()]
    try:
        # numpy's parser (a 1e6-row file took 25 s row by row in Python); where it fails, the row-by-row one names the line
        table = np.loadtxt(body, dtype=float, ndmin=2, comments=None) if body else np.empty((0, len(labels)))
        if table.shape[1] != len(labels):
            raise ValueError("width")
    except ValueError:
        table = _table_row_by_row(path, text, k, labels)
    # OpenSim's Storage writes the table's size in the header: a file that disagrees was cut short or edited by
    # hand, and reading what is there would lose the rest without a word.
    for key, have, what in (("nRows", table.shape[0], "rows"), ("nColumns", len(labels), "columns (time included)")):
        if key in header:
            try:
                said = int(header[key])
            except ValueError:
                raise ValueError(f"{path}: the header's {key} must be an integer, got {header[key]!r}") from None
            if said != have:
                raise ValueError(f"{path}: the header says {key}={said} but the file has {have} {what}: cut short "
                                 f"or edited? Correct the header or the table")
    return header, labels, table


def coordinate_table(result, model_desc: dict) -> tuple[list[str], np.ndarray]:
    """(OpenSim coordinate names, (T, 11) radians) for a Result: the model's fixed girdle coordinates
    (das2: the six SC and AC angles of its `girdle` block, constant), then its DOFs (das2: the five arm
    DOFs; das3: all eleven, girdle included, as simulated)."""
    girdle = [(d["osim_name"], float(d["angle"])) for d in model_desc.get("girdle", {}).get("dofs", [])]
    dofs = model_desc["dofs"]
    both = {n for n, _ in girdle} & {d["osim_name"] for d in dofs}
    if both:
        raise ValueError(f"coordinates {sorted(both)} are both fixed (girdle) and free (dofs) in the model file")
    if list(result.dof_names) and [d["name"] for d in dofs] != list(result.dof_names):
        raise ValueError(f"result DOFs {result.dof_names} do not match the model's {[d['name'] for d in dofs]}")
    T = len(result.time)
    labels = [n for n, _ in girdle] + [d["osim_name"] for d in dofs]
    data = np.column_stack([np.full(T, a) for _, a in girdle] + [np.asarray(result.q)[:, j] for j in range(len(dofs))])
    return labels, data


def write_mot(result, path, model: str | None = None, model_file=None) -> Path:
    """Joint angles of a Result to an OpenSim motion file (radians; a fixed girdle's coordinates filled
    in from the model file, a free girdle's from the result)."""
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


def write_excitation_sto(result, path, model: str | None = None, model_file=None) -> Path:
    """Excitations of a Result (those the dynamics used) to an OpenSim controls file, one column per
    element (OpenSim force names)."""
    desc = model_description(model or result.model or "das2", model_file)
    osim = {e["name"]: e.get("osim_name", e["name"]) for e in desc["elements"]}
    names = list(result.element_names) or [e["name"] for e in desc["elements"]]
    missing = [n for n in names if n not in osim]
    if missing:
        raise ValueError(f"elements {missing[:5]} are not in the model file")
    _write_storage(path, Path(path).stem, [osim[n] for n in names], result.time, np.asarray(result.excitation))
    return Path(path)


# Per channel, in this order: the command's three values, then what the chain made of it (docs/fes.md).
STIMULATION_COLUMNS = (("pulse_width", "s"), ("amplitude", "A"), ("frequency", "Hz"), ("recruitment", "1"),
                       ("fatigue", "1"))


def write_stimulation_sto(result, path, channel_names=None) -> Path:
    """The stimulation of a Result to an OpenSim storage file: per channel, in the map's order, columns
    `<channel>/pulse_width` (s), `/amplitude` (A), `/frequency` (Hz) from result.stimulation (T, channels, 3),
    `/recruitment` from result.recruitment (T, channels) and `/fatigue` (1 - A/A_rest) from result.fatigue
    (T, channels); the header states the units. Values are written to 10 significant digits.
    channel_names: the channels' names (default result.channel_names; needed for a result saved before
    results kept them). Returns the path. Raises ValueError if the result has no stimulation (an arm
    without a stimulation map), if the channel names are missing, repeated, contain whitespace (the format
    splits on it) or do not match the arrays' channel count, or if a value is NaN or infinite."""
    if result.stimulation is None or result.recruitment is None or result.fatigue is None:
        raise ValueError("the result has no stimulation (its arm had no stimulation map): simulate with "
                         "armrt.Arm(model, stimulation=...) to record pulse width, amplitude, frequency, "
                         "recruitment and fatigue")
    stim = np.asarray(result.stimulation, dtype=float)
    rec, fat = np.asarray(result.recruitment, dtype=float), np.asarray(result.fatigue, dtype=float)
    T = len(result.time)
    if stim.ndim != 3 or stim.shape[0] != T or stim.shape[2] != 3:
        raise ValueError(f"result.stimulation must have shape ({T}, channels, 3), got {stim.shape}")
    nc = stim.shape[1]
    for what, a in (("recruitment", rec), ("fatigue", fat)):
        if a.shape != (T, nc):
            raise ValueError(f"result.{what} must have shape ({T}, {nc}) (time, channels), got {a.shape}")
    names = list(result.channel_names if channel_names is None else channel_names)
    if not names:
        raise ValueError("the result does not name its stimulation channels (saved before results kept "
                         "channel_names): pass channel_names=arm.channel_names")
    if len(names) != nc:
        raise ValueError(f"{len(names)} channel names for {nc} stimulation channels")
    if len(set(names)) != nc:
        raise ValueError(f"repeated channel names: {sorted({n for n in names if names.count(n) > 1})}")
    spaced = [n for n in names if not n or any(c.isspace() for c in n)]
    if spaced:
        raise ValueError(f"channel names {spaced!r} are empty or contain whitespace, which a storage file's "
                         "columns cannot hold")
    labels = [f"{n}/{v}" for n in names for v, _ in STIMULATION_COLUMNS]
    data = np.concatenate([stim, rec[:, :, None], fat[:, :, None]], axis=2).reshape(T, 5 * nc)
    units = ", ".join(f"{v} {u}" for v, u in STIMULATION_COLUMNS)
    comment = (f"stimulation per channel ({nc} channels); units: {units} (1: a fraction); "
               "fatigue: 1 - A/A_rest of Ding et al. 2003 (armrt docs/fes.md)")
    _write_storage(path, Path(path).stem, labels, result.time, data, comment=comment)
    return Path(path)


def export(result, mot_path=None, sto_path=None, model_file=None, state_paths: bool = False,
           controls_path=None, stimulation_path=None) -> list[Path]:
    """The files asked for (.mot angles, .sto activations, controls .sto excitations, stimulation .sto); the
    paths written. ValueError from write_stimulation_sto for a result without stimulation."""
    out = []
    if mot_path is not None:
        out.append(write_mot(result, mot_path, model_file=model_file))
    if sto_path is not None:
        out.append(write_activation_sto(result, sto_path, model_file=model_file, state_paths=state_paths))
    if controls_path is not None:
        out.append(write_excitation_sto(result, controls_path, model_file=model_file))
    if stimulation_path is not None:
        out.append(write_stimulation_sto(result, stimulation_path))
    return out


# ------------------------------------------------------------------ import
@dataclass
class Motion:
    """Joint angles read from an OpenSim motion file: time (T,) s, q (T, ndof) rad in the model's DOF
    order (das2: 5, das3: 11)."""

    time: np.ndarray
    q: np.ndarray
    dof_names: list
    model: str = "das2"
    source: str = ""

    def posture(self, t: float | None = None) -> np.ndarray:
        """(ndof,) rad: the first row, or the angles at time t (linear interpolation, t inside the file)."""
        if t is None:
            return self.q[0].copy()
        t = float(t)
        if not (self.time[0] <= t <= self.time[-1]):
            raise ValueError(f"t = {t} s is outside the motion ({self.time[0]} to {self.time[-1]} s)")
        return np.array([np.interp(t, self.time, self.q[:, j]) for j in range(self.q.shape[1])])

    def to_result(self):
        """A kinematics-only Result for replay (animate, view): q and qdot from the file, the
        thorax-humerus angles computed; muscle channels, forces and GH stability are NaN (unknown)."""
        from .arm import Arm, Result
        arm = Arm(model=self.model)
        T, n = len(self.time), arm.n_elements
        nan = lambda *shape: np.full((T, *shape), np.nan)  # noqa: E731
        qdot = np.gradient(self.q, self.time, axis=0) if T > 1 else np.zeros_like(self.q)
        from .result import CHANNELS, _optional
        width = {"one": (), "two": (2,), "three": (3,), "dofs": (arm.n_dofs,), "elements": (n,)}
        # Every recorded channel the file does not give is unknown (NaN), whatever the engine's table holds.
        known = {"time": self.time.copy(), "q": self.q.copy(), "qdot": qdot, "tet_ns": np.zeros(T),
                 "thorax_humerus": np.array([arm.thorax_humerus_angles(q) for q in self.q])}
        arrays = {name: known[name] if name in known else nan(*width[rule])
                  for name, rule, *_ in (c for c in CHANNELS if not _optional(c))}
        return Result(**arrays, dof_names=list(arm.dof_names), element_names=list(arm.element_names),
                      integrator="", dt=float(np.median(np.diff(self.time))) if T > 1 else 0.0, model=self.model)


def _check_angle_unit(path, q: np.ndarray, raw: np.ndarray, in_degrees: bool, dofs) -> None:
    """ValueError when the inDegrees header contradicts the values: the angles q (frames, ndof) rad leave the model's
    joint ranges at more samples than the file's raw values taken in the other unit do (a radian file marked
    inDegrees=yes gave angles 1/57 of the intended, read without a word). A motion within the ranges is never
    questioned; one slightly beyond them at a few samples is not either, as the other unit puts most of it far out."""
    lo = np.array([d["range"][0] for d in dofs])
    hi = np.array([d["range"][1] for d in dofs])
    outside = (q < lo) | (q > hi)
    if not outside.any():
        return
    other = raw if in_degrees else np.radians(raw)
    # Counted, not 'all within': one sample of a radian file 0.05 rad below a range must not let the other 5000
    # be read at 1/57 (a second trial's).
    if np.count_nonzero((other < lo) | (other > hi)) >= np.count_nonzero(outside):
        return
    r, j = np.argwhere(outside)[0]
    said, meant = ("yes", "radians") if in_degrees else ("no", "degrees")
    raise ValueError(f"{path}: the header says inDegrees={said}, but the angles look like {meant}: read so, "
                     f"{dofs[j]['osim_name']} = {np.degrees(q[r, j]):.3g} deg (row {r}) is outside its range "
                     f"[{np.degrees(lo[j]):.1f}, {np.degrees(hi[j]):.1f}] deg ({np.count_nonzero(outside)} of {q.size} "
                     f"values outside the model's ranges; read as {meant}, {np.count_nonzero((other < lo) | (other > hi))}). "
                     f"Correct the header's inDegrees line.")


# The coordinates of the DAS3 OpenSim model (das3.osim's CoordinateSet): columns of a DAS3 motion any armrt model
# may read, the girdle's ignored by das2 (which fixes it).
_DAS3_COORDINATES = ("SC_y", "SC_z", "SC_x", "AC_y", "AC_z", "AC_x", "GH_y", "GH_z", "GH_yy", "EL_x", "PS_y")
# An OpenSim 4 states file's coordinate columns: /jointset/<joint>/<coordinate>/value (and .../speed).
_STATE_VALUE = re.compile(r"^/?jointset/[^/]+/([^/]+)/value$")


def _coordinate_label(label: str) -> str:
    """The coordinate a storage column holds: its label, or <coordinate> for an OpenSim 4 state path
    /jointset/<joint>/<coordinate>/value; other labels as they are."""
    label = label.strip()
    match = _STATE_VALUE.match(label)
    return match.group(1) if match else label


# An OpenSim 3 states file's muscle state columns: <muscle>.<state>.
_OPENSIM3_FORCE_STATES = ("activation", "fiber_length", "fiber_velocity", "excitation")


def _known_column(label: str, names) -> bool:
    """Whether a storage column is one armrt knows and may ignore: a coordinate of the model (names) or of DAS3, an
    OpenSim 4 state path (/jointset/.../speed, /forceset/...), or an OpenSim 3 states file's speed (<coordinate>_u)
    or force state (<muscle>.activation, <muscle>.fiber_length)."""
    if label in names or label in _DAS3_COORDINATES or label.startswith("/"):
        return True
    if label.endswith("_u") and (label[:-2] in names or label[:-2] in _DAS3_COORDINATES):
        return True
    return "." in label and label.rsplit(".", 1)[1] in _OPENSIM3_FORCE_STATES


def _resembles(name: str, candidates) -> str | None:
    """The candidate `name` most resembles, ignoring case (difflib's ratio at least 0.6), or None."""
    lower = {c.lower(): c for c in candidates}
    close = difflib.get_close_matches(name.lower(), list(lower), n=1, cutoff=0.6)
    return lower[close[0]] if close else None


def read_motion(path, model: str = "das2") -> Motion:
    """A .mot/.sto of joint angles as a Motion (radians). Columns: the model's DOFs by OpenSim
    coordinate name (GH_y, ..., PS_y; das3 also SC_y ... AC_x), armrt name (GHy, ...) or OpenSim 4 state path
    (/jointset/<joint>/GH_y/value, as a states .sto holds them). das2's fixed girdle (SC_*, AC_*) is ignored, with a
    RuntimeWarning if it differs from the model's; other state paths (speeds, /forceset/...) are ignored; any
    other column is ignored with a RuntimeWarning naming it (and the coordinate it resembles). `inDegrees=yes`
    is honoured. Raises ValueError naming missing columns (and a column that looks like a misspelling of one), a
    coordinate with two columns (GH_y and GHy), two time columns, a header nRows or nColumns the table contradicts,
    non-numeric rows, a bad time column, an inDegrees other than yes or no, or an inDegrees header the
    values contradict (angles outside the model's ranges at more samples than in the other unit)."""
    from . import _core
    from .arm import known_model
    known_model(model)
    info = _core.model_info(model)
    try:
        header, labels, data = read_storage(path)
    except ValueError as exc:
        raise ValueError(f"{path}: not a readable OpenSim storage file ({exc})") from None
    flag = header.get("inDegrees", "no").strip().lower()
    if flag not in ("yes", "no"):  # OpenSim writes yes or no; 'true' was read as no
        raise ValueError(f"{path}: the header's inDegrees must be yes or no, got {header['inDegrees'].strip()!r}")
    deg = flag == "yes"
    raw_labels = [label.strip() for label in labels]
    labels = [_coordinate_label(label) for label in raw_labels]
    col = {name: k for k, name in enumerate(labels)}
    if "time" not in col:
        raise ValueError(f"{path}: no 'time' column")
    time_columns = sum(label.strip() == "time" for label in labels)
    if time_columns > 1:
        raise ValueError(f"{path}: {time_columns} 'time' columns; keep one")
    idx, missing = [], []
    for d in info["dofs"]:
        # One column per coordinate: a name twice, or OpenSim's and armrt's name both (GH_y and GHy), is
        # ambiguous; before, one of them was taken silently.
        both = [raw for raw, label in zip(raw_labels, labels) if label in (d["osim_name"], d["name"])]
        if len(both) > 1:
            raise ValueError(f"{path}: coordinate {d['osim_name']} has {len(both)} columns ({', '.join(both)}); "
                             f"keep one")
        k = col.get(d["osim_name"], col.get(d["name"]))
        (missing if k is None else idx).append(d["osim_name"] if k is None else k)
    girdle = [(g["osim_name"], g["angle"]) for g in model_description(model).get("girdle", {}).get("dofs", [])] \
        if find_model_file(model) is not None else []
    names = [n for d in info["dofs"] for n in (d["osim_name"], d["name"])]
    # Columns that are no coordinate armrt knows: a typo (EL_X_typo beside EL_x) or another model's coordinate was
    # dropped without a word. OpenSim states files' other columns (speeds, /forceset/...) are ignored silently.
    raw_of = dict(zip(labels, raw_labels))
    unknown = [label for label in labels if label != "time" and not _known_column(label, names)]
    if missing:
        hints = [f"{m} (a column {raw_of[close]!r}?)" for m in missing if (close := _resembles(m, unknown))]
        shown = [raw_of[u] for u in unknown] or raw_labels
        raise ValueError(f"{path}: no column for coordinates {missing} ("
                         + (f"columns not read: {shown[:12]}" if unknown else f"columns: {shown[:12]}")
                         + (f" and {len(shown) - 12} more" if len(shown) > 12 else "") + ")"
                         + (f"; perhaps misspelt: {', '.join(hints)}" if hints else ""))
    if unknown:
        hints = {u: close for u in unknown if (close := _resembles(u, names))}
        said = ", ".join(f"{raw_of[u]} (like {hints[u]})" if u in hints else raw_of[u] for u in unknown[:8])
        more = f" and {len(unknown) - 8} more" if len(unknown) > 8 else ""
        warnings.warn(f"{path}: columns {said}{more} are not coordinates of {model}; ignored", RuntimeWarning,
                      stacklevel=2)
    if data.shape[0] == 0:
        raise ValueError(f"{path}: no rows")
    time = data[:, col["time"]]
    q = data[:, idx]
    if deg:
        q = np.radians(q)
    if not (np.all(np.isfinite(q)) and np.all(np.isfinite(time))):
        raise ValueError(f"{path}: NaN or infinite values")
    if time.size > 1 and np.any(np.diff(time) <= 0):
        raise ValueError(f"{path}: time must be strictly increasing")
    _check_angle_unit(path, q, data[:, idx], deg, info["dofs"])
    if girdle:
        off = [name for name, a in girdle if name in col and
               np.max(np.abs((np.radians(data[:, col[name]]) if deg else data[:, col[name]]) - a)) > 1e-3]
        if off:
            warnings.warn(f"{path}: girdle coordinates {off} differ from the model's fixed girdle; armrt "
                          f"ignores them (the scapula is fixed)", RuntimeWarning, stacklevel=2)
    return Motion(time=time, q=q, dof_names=[d["name"] for d in info["dofs"]], model=model, source=str(path))
