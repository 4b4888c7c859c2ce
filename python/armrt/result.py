"""Result: the time series a simulation records (Arm.simulate, ArmBatch, the real-time runner's log
replays), with its save/load (.npz), DataFrame and plot; and the row-size arithmetic simulate() uses
to refuse a Result that would not fit in memory."""
from __future__ import annotations

import re
from dataclasses import field, make_dataclass

import numpy as np

from . import _core
from .checks import known_model
from .model import Model

# The recorded channels, from the engine's table (armrt/layouts.h): (name, size rule, unit, stage,
# girdle_only, description), in recording order. Result's arrays are exactly these.
CHANNELS = tuple(_core.recorded_channels())
_WIDTH = {"one": lambda nd, ne, nc: 1, "two": lambda nd, ne, nc: 2, "three": lambda nd, ne, nc: 3,
          "dofs": lambda nd, ne, nc: nd, "elements": lambda nd, ne, nc: ne, "contact_points": lambda nd, ne, nc: nc}
# Channels of an arm's stimulation map (one value, or three, per channel): present only with a map.
_STIMULATION_RULES = ("channels", "channel_inputs")


def _optional(channel) -> bool:
    """Whether a recorded channel exists only for some arms: girdle channels (models whose scapula moves) and
    stimulation channels (arms with a stimulation map)."""
    return bool(channel[4]) or channel[1] in _STIMULATION_RULES


def _row_bytes(n_elements: int, n_dofs: int = 5, n_contact_points: int = 0, n_channels: int = 0) -> int:
    """Bytes of one recorded row of a Result (float64): the sum of the recorded channels' widths for a model
    of n_dofs DOFs, n_elements elements and n_contact_points girdle contact points (0: no girdle channels),
    and an arm of n_channels stimulation channels (0: no stimulation channels)."""
    width = dict(_WIDTH, channels=lambda nd, ne, nc: n_channels, channel_inputs=lambda nd, ne, nc: 3 * n_channels)
    return 8 * sum(width[rule](n_dofs, n_elements, n_contact_points)
                   for _name, rule, _unit, _stage, girdle_only, _doc in CHANNELS
                   if not girdle_only or n_contact_points > 0)


def _recorded_rows(n_steps: int, record_every: int) -> int:
    """Rows simulate() records: steps 0, k, 2k, ... and the final state when it falls on the grid."""
    return -(-n_steps // record_every) + (1 if n_steps % record_every == 0 else 0)


def _other_columns() -> dict:
    """Column names (to_dataframe) of the channels that are neither per DOF nor per element: x, y, z for three
    values unless named here, None for one value."""
    named = {"gh_angles": ("theta", "phi"), "thorax_humerus": ("plane_of_elevation", "elevation", "axial_rotation"),
             "contact_distance": ("TS", "AI")}
    default = {"one": None, "two": ("0", "1"), "three": ("x", "y", "z"), "contact_points": ("TS", "AI")}
    return {name: named.get(name, default.get(rule)) for name, rule, *_ in CHANNELS if rule not in ("dofs", "elements")}


_SHAPES = {"one": "(T,)", "two": "(T, 2)", "three": "(T, 3)", "dofs": "(T, ndof)", "elements": "(T, n)",
           "contact_points": "(T, P)", "channels": "(T, channels)", "channel_inputs": "(T, channels, 3)"}


class _ResultMethods:
    """Time series of a simulation; row k is the state at time[k] and the outputs at that state.

    repr() is one line; to_dataframe() gives a pandas DataFrame (pandas optional), plot() a figure.
    Arrays (the engine's recorded channels, armrt/layouts.h; ndof DOFs, n elements, P girdle contact points):
    {arrays}
    The optional arrays ({optional}) are None where they do not apply: the girdle arrays exist for models
    whose scapula moves (das3), the stimulation arrays for arms with a stimulation map (stimulation: pulse
    width s, amplitude A, frequency Hz per channel; recruitment and fatigue per channel).
    Metadata: dof_names, element_names, channel_names (the stimulation map's channels in the order of the
    stimulation arrays' second axis; [] without a map, or for a result saved before they were kept),
    integrator, dt (control step, s), substeps, model, model_hash (SHA-256 of the model file: reopens a model
    built on demand from the cache)."""

    ARRAYS = tuple(c[0] for c in CHANNELS if not _optional(c))
    OPTIONAL_ARRAYS = tuple(c[0] for c in CHANNELS if _optional(c))
    # Arrays added after the first file format: a file without them gets them from its own recorded
    # gh_angles through the engine (gh_rim), so that older results load whole.
    _DERIVED_FROM_GH_ANGLES = ("gh_rim_margin", "gh_rim_direction")

    @property
    def q_deg(self) -> np.ndarray:
        return np.degrees(self.q)

    # Per-DOF and per-element channels (by the table's size rule), and the column names of the others
    # (to_dataframe): x, y, z for three values unless named here.
    _DOF_CHANNELS = tuple(c[0] for c in CHANNELS if c[1] == "dofs")
    _ELEMENT_CHANNELS = tuple(c[0] for c in CHANNELS if c[1] == "elements")
    _OTHER_COLUMNS = _other_columns()

    def channels(self) -> list[str]:
        """The time-series names this Result has besides time: ARRAYS, and the optional arrays when present."""
        return [k for k in self.ARRAYS if k != "time"] + [k for k in self.OPTIONAL_ARRAYS if getattr(self, k) is not None]

    def __repr__(self) -> str:
        T = len(self.time)
        if T == 0:
            return f"Result({self.model or '?'}, empty)"
        step = f"dt={self.dt * 1e3:g} ms" + (f" x{self.substeps} substeps" if self.substeps > 1 else "")
        every = ""
        if T > 1 and self.dt > 0:
            k = int(round((self.time[1] - self.time[0]) / self.dt))
            every = f", every {k} steps" if k > 1 else ""
        q_end = np.array2string(np.degrees(self.q[-1]), precision=1, separator=", ", suppress_small=True)
        stab = np.nanmax(self.gh_stab) if np.any(np.isfinite(self.gh_stab)) else float("nan")
        mb = sum(getattr(self, k).nbytes for k in self.ARRAYS) / 1e6
        return (f"Result({self.model or '?'}, {self.integrator or 'replay'} {step}: {T} rows{every}, "
                f"t = {self.time[0]:g} to {self.time[-1]:g} s, {len(self.element_names)} elements; "
                f"final q = {q_end} deg; GHstab max {stab:.3g}; {mb:.1f} MB)")

    def to_dataframe(self, channels=None):
        """A pandas DataFrame indexed by time (s), one column per value: 'q.GHy', 'activation.deltscap1',
        'gh_force.x', 'gh_stab', ... in the Result's units (radians). channels: names from ARRAYS
        (default all). Raises ImportError with the install command if pandas is absent, ValueError
        for an unknown channel."""
        try:
            import pandas as pd
        except ImportError:
            raise ImportError("Result.to_dataframe needs pandas: pip install pandas "
                              "(or pip install 'armrt[dataframe]')") from None
        names = self.channels() if channels is None else list(channels)
        unknown = [c for c in names if c not in self.channels()]
        if unknown:
            raise ValueError(f"unknown channels {unknown}; expected some of {self.channels()}")
        cols = {}
        for c in names:
            a = np.asarray(getattr(self, c))
            if c in self._DOF_CHANNELS:
                labels = self.dof_names or [str(j) for j in range(a.shape[1])]
            elif c in self._ELEMENT_CHANNELS:
                labels = self.element_names or [str(i) for i in range(a.shape[1])]
            else:
                labels = self._OTHER_COLUMNS[c]
            if a.ndim == 3:  # stimulation (T, channels, 3): one column per channel and value
                labels = [f"{k}.{v}" for k in range(a.shape[1]) for v in ("pulse_width", "amplitude", "frequency")]
                a = a.reshape(len(a), -1)
            elif labels is None and a.ndim == 2:  # per stimulation channel, by channel index
                labels = [str(k) for k in range(a.shape[1])]
            if labels is None:
                cols[c] = a
            else:
                cols.update({f"{c}.{n}": a[:, j] for j, n in enumerate(labels)})
        return pd.DataFrame(cols, index=pd.Index(np.asarray(self.time), name="time"))

    def plot(self, channels=("q", "gh_stab"), names=None, fig=None):
        """A matplotlib figure with one panel per channel against time: joint angles in degrees (the
        label says so), GH stability with its limit of 1, other channels in their SI units. names:
        the DOFs / elements to draw (default all DOFs, and for element channels the muscle means).
        Returns the figure (call .savefig or plt.show())."""
        import matplotlib.pyplot as plt
        unknown = [c for c in channels if c not in self.channels()]
        if unknown:
            raise ValueError(f"unknown channels {unknown}; expected some of {self.channels()}")
        fig = fig or plt.figure(figsize=(8, 2.2 * len(channels)))
        axes = fig.subplots(len(channels), 1, sharex=True, squeeze=False)[:, 0]
        for ax, c in zip(axes, channels):
            a = np.asarray(getattr(self, c))
            if c in self._DOF_CHANNELS:
                scale, unit = (np.degrees(1.0), "deg" if c == "q" else "deg/s")
                for j, n in enumerate(self.dof_names):
                    if names is None or n in names:
                        ax.plot(self.time, scale * a[:, j], label=n)
                ax.set_ylabel(f"{c} ({unit})")
            elif c in self._ELEMENT_CHANNELS:
                pick = [i for i, n in enumerate(self.element_names) if names is None or n in names]
                for i in pick[:12]:
                    ax.plot(self.time, a[:, i], label=self.element_names[i], lw=0.8)
                if len(pick) > 12:
                    ax.plot(self.time, a[:, pick].mean(axis=1), "k", lw=1.5, label=f"mean of {len(pick)}")
                ax.set_ylabel(c)
            elif c == "contact_distance":
                for j, n in enumerate(self._OTHER_COLUMNS[c][:a.shape[1]]):
                    ax.plot(self.time, 1e3 * a[:, j], label=n)
                ax.axhline(0.0, color="0.5", lw=0.8)
                ax.set_ylabel("contact distance (mm)")
            elif c == "gh_stab":
                ax.plot(self.time, a, color="0.3")
                ax.axhline(1.0, color="tab:red", ls="--", lw=0.8, label="rim (1)")
                ax.set_ylabel("GHstab")
            else:
                ax.plot(self.time, a)
                ax.set_ylabel(c)
            if ax.get_legend_handles_labels()[0]:
                ax.legend(fontsize=7, ncol=3, loc="best")
        axes[-1].set_xlabel("time (s)")
        fig.tight_layout()
        return fig

    def save(self, path) -> None:
        """Saves to a compressed .npz (load with Result.load)."""
        np.savez_compressed(path, **{k: getattr(self, k) for k in self.ARRAYS},
                            **{k: getattr(self, k) for k in self.OPTIONAL_ARRAYS if getattr(self, k) is not None},
                            dof_names=np.array(self.dof_names), element_names=np.array(self.element_names),
                            channel_names=np.array(self.channel_names, dtype=str), integrator=self.integrator, dt=self.dt, substeps=self.substeps, model=self.model,
                            model_hash=self.model_hash)

    @classmethod
    def load(cls, path) -> "Result":
        """A Result saved with save(). ValueError (one line, naming the file) for a file that is not
        a readable .npz, lacks the result arrays, has arrays of the wrong shape, or names a model that
        is not registered (load its model file first: armrt.Model.load); FileNotFoundError if absent."""
        import zipfile
        path = str(path)
        try:
            z = np.load(path, allow_pickle=False)
        except FileNotFoundError:
            raise FileNotFoundError(f"{path}: no such file") from None
        except (OSError, ValueError, zipfile.BadZipFile, EOFError) as exc:
            raise ValueError(f"{path}: not an armrt result (.npz written by Result.save): {exc}") from None
        if not hasattr(z, "files"):
            raise ValueError(f"{path}: not an armrt result (a single .npy array, not an .npz)")
        with z:
            missing = [k for k in (*cls.ARRAYS, "dof_names", "element_names", "model")
                       if k not in z.files and k not in cls._DERIVED_FROM_GH_ANGLES]
            if missing:
                raise ValueError(f"{path}: not an armrt result, missing arrays {missing}")
            try:
                fields = {k: np.asarray(z[k], dtype=float) for k in cls.ARRAYS if k in z.files}
                fields.update({k: np.asarray(z[k], dtype=float) for k in cls.OPTIONAL_ARRAYS if k in z.files})
                meta = dict(dof_names=[str(s) for s in z["dof_names"]],
                            element_names=[str(s) for s in z["element_names"]],
                            channel_names=([str(s) for s in z["channel_names"]] if "channel_names" in z.files
                                           else []),
                            integrator=str(z["integrator"]) if "integrator" in z.files else "",
                            dt=float(z["dt"]) if "dt" in z.files else 0.0,
                            substeps=int(z["substeps"]) if "substeps" in z.files else 1, model=str(z["model"]),
                            model_hash=str(z["model_hash"]) if "model_hash" in z.files else "")
            except (OSError, ValueError, TypeError, zipfile.BadZipFile, EOFError) as exc:
                raise ValueError(f"{path}: corrupt armrt result: {exc}") from None
        try:
            known_model(meta["model"])
        except ValueError:
            # A model built on demand in an earlier session: reopened from the cache (never rebuilt
            # from a path: a result file names a model, it does not point at code to compile).
            reopened = (Model.from_cache(meta["model"], meta["model_hash"])
                        if re.fullmatch(r"[0-9a-f]{64}", meta["model_hash"]) else None)
        else:
            reopened = True
        if reopened is None:
            raise ValueError(f"{path}: the result's model field {meta['model'][:80]!r} is not a known model "
                             f"(registered: {_core.model_names()}; a model built on demand: armrt.Model.load(its file) "
                             f"first)") from None
        absent = [k for k in cls._DERIVED_FROM_GH_ANGLES if k not in fields]
        if absent:
            fields.update(_rim_of_recorded_angles(meta["model"], fields["gh_angles"], path, absent))
        T = fields["time"].shape[0] if fields["time"].ndim == 1 else -1
        bad = [k for k, v in fields.items() if v.ndim == 0 or v.shape[0] != T]
        if T < 0 or bad:
            raise ValueError(f"{path}: corrupt armrt result: arrays {bad or ['time']} do not have one row per time")
        return cls(**fields, **meta)


def _rim_of_recorded_angles(model: str, gh_angles: np.ndarray, path: str, keys) -> dict:
    """`keys` (gh_rim_margin, gh_rim_direction) of a result's own recorded gh_angles (T, 2) (theta, phi,
    rad) on the model's rim (the engine's gh_rim): the file's angles, not its gh_force through today's
    glenoid basis, which may not be the one it was recorded with. NaN where the row is NaN (a replay)."""
    if gh_angles.ndim != 2 or gh_angles.shape[1] != 2:
        raise ValueError(f"{path}: corrupt armrt result: gh_angles has shape {gh_angles.shape}, expected (T, 2)")
    ok = np.all(np.isfinite(gh_angles), axis=1)
    out = {k: np.full(len(gh_angles), np.nan) for k in keys}
    if ok.any():
        margin, direction = Model(model)._def.gh_rim_of_angles(np.ascontiguousarray(gh_angles[ok], dtype=float))
        rim = {"gh_rim_margin": margin, "gh_rim_direction": direction}
        for k in keys:
            out[k][ok] = rim[k]
    return out


# Result: the methods above, and one field per recorded channel (a new channel in the engine's table is a new
# array here without a change to this file), then the metadata.
Result = make_dataclass(
    "Result",
    [(c[0], np.ndarray) for c in CHANNELS if not _optional(c)]
    + [("dof_names", list, field(default_factory=list)), ("element_names", list, field(default_factory=list)),
       ("channel_names", list, field(default_factory=list)),
       ("integrator", str, field(default="")), ("dt", float, field(default=0.0)), ("substeps", int, field(default=1)),
       ("model", str, field(default="")), ("model_hash", str, field(default=""))]
    + [(c[0], "np.ndarray | None", field(default=None)) for c in CHANNELS if _optional(c)],
    bases=(_ResultMethods,), repr=False, namespace={"__module__": __name__})
Result.__doc__ = _ResultMethods.__doc__.format(
    arrays="\n    ".join(f"{c[0]} {_SHAPES[c[1]]} {c[2]}: {c[5]}" for c in CHANNELS),
    optional=", ".join(_ResultMethods.OPTIONAL_ARRAYS))
