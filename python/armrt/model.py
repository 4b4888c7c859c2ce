"""armrt.Model: one arm model, immutable (like mjModel / pinocchio.Model), and the model registry.

    model = armrt.Model("das2")                 # a registered model (das2 is built in)
    model = armrt.Model.load("my_arm.json")     # a model file, built on demand and registered
    model.moment_arms(q)                        # (n, ndof) m at pose q (ndof,), or (k, n, ndof) for q (k, ndof)
    arm_a, arm_b = armrt.Arm(model), armrt.Arm(model)   # several arms (each with its own armrt.Data) share it
    armrt.models()                              # names of the registered models

Shapes: ndof = model.n_dofs, n = model.n_elements. Every function of a pose takes q of shape (ndof,)
(rad) and returns arrays as documented, or q of shape (k, ndof) and returns them with a leading k; a q
more than checks.STATE_MARGIN (the engine's physical domain, 0.35 rad) beyond the joint ranges is refused
(ValueError, with a hint when q looks like degrees): any state a simulation reaches is accepted.
"""
from __future__ import annotations

import json
import os
from pathlib import Path
from types import MappingProxyType

import numpy as np

from . import _core
from .checks import joint_range, joint_range_rows, real_array
from .control import inverse_dynamics as _inverse_dynamics
from .model_build import BuildResult, build, cached_library
from .model_files import LOADED as _LOADED
from .model_files import find_model_file
# One Model object per ModelDef (address), so `Model("x") is Model("x")` and loads are shared.
_MODELS: dict[int, "Model"] = {}

_PARAMETERS = ("fmax", "lceopt", "lslack", "pennopt", "vmax", "tact", "tdeact", "peeslack")


def models() -> list[str]:
    """Names of the models registered in this process: the built-in das2, das3, participant_A first, then
    models loaded from files (armrt.Model.load, Arm(model=path)) in load order."""
    return [d.name for d in _core.registered_models()]


def _readonly(a) -> np.ndarray:
    a = np.array(a, dtype=float)
    a.flags.writeable = False
    return a


class Model:
    """An arm model: names, sizes, ranges, parameters, groups and provenance (all read-only), and its
    geometry and dynamics at any pose. Immutable: weakness and paralysis are per arm (Arm.strength,
    Arm.max_activation), gravity per arm too. Model(name_or_path): a registered model's name ("das2"),
    or a model file path (built on demand, see Model.load). Raises ValueError for an unknown name (with
    the registered ones), and what Model.load raises for a file."""

    def __new__(cls, model="das2"):
        if isinstance(model, Model):
            return model
        if isinstance(model, _core.ModelDef):
            return cls._of(model)
        if isinstance(model, os.PathLike) or (isinstance(model, str) and (
                model.endswith(".json") or os.sep in model) and _core.find_model(model) is None):
            return cls.load(model)
        if not isinstance(model, str):
            raise ValueError(f"model must be a model name, a model file path or an armrt.Model, "
                             f"got {type(model).__name__}")
        d = _core.find_model(model)
        if d is None:
            try:
                shipped = find_model_file(model)
            except ValueError:
                shipped = None
            hint = (f"; a model file of that name ships at {shipped}: Arm({str(shipped)!r}) builds it"
                    if shipped is not None else "")
            raise ValueError(f"unknown model {model!r} (registered models: {', '.join(models())}; "
                             f"or give a model file path, e.g. models/das2.json){hint}")
        return cls._of(d)

    @classmethod
    def _of(cls, d, file: Path | None = None, library: Path | None = None) -> "Model":
        m = _MODELS.get(d.address)
        if m is not None:
            return m
        m = object.__new__(cls)
        object.__setattr__(m, "_def", d)
        object.__setattr__(m, "_info", _core.model_info(d))
        object.__setattr__(m, "_file", file)
        object.__setattr__(m, "_library", library)
        _MODELS[d.address] = m
        return m

    @classmethod
    def load(cls, path, rebuild: bool = False) -> "Model":
        """The model of a model file (JSON, docs/model_schema.md): validated, generated, compiled into a
        shared library cached by the file's hash in the user cache folder (armrt.model_build.cache_dir();
        a second load of the same file, in this or any later process, skips generation and compilation),
        loaded and registered under its name (armrt.models()). rebuild: ignore the cache.

        Raises FileNotFoundError, armrt.ModelFileError (the field and element that fail validation),
        armrt.CompilerNotFoundError, armrt.ModelBuildError (with the build log's path), ValueError if a
        different model of the same name is already registered (checked before anything is built)."""
        res: BuildResult = build(path, force=rebuild)
        d = _core.load_model_library(str(res.library))
        _LOADED.setdefault(res.name, (Path(path).resolve(), res.library))
        m = cls._of(d, Path(path).resolve(), res.library)
        return m

    @classmethod
    def from_cache(cls, name: str, source_hash: str) -> "Model | None":
        """The registered model of that name and hash, else the one already built into the cache from
        such a model file (loaded and registered), else None. Builds nothing and reads no model file:
        how a saved Result reopens a model built on demand in an earlier session."""
        d = _core.find_model(name)
        if d is not None:
            return cls._of(d) if d.source_hash == source_hash else None
        lib = cached_library(name, source_hash)
        if lib is None:
            return None
        d = _core.load_model_library(str(lib))
        meta = json.loads((lib.parent / "model.json").read_text())
        return cls._of(d, Path(meta["model_file"]) if Path(meta["model_file"]).is_file() else None, lib)

    def __setattr__(self, name, value):
        raise AttributeError(f"armrt.Model is immutable (set {name!r} on an Arm: strength, max_activation, gravity)")

    def __delattr__(self, name):
        raise AttributeError("armrt.Model is immutable")

    def __copy__(self):
        return self

    def __deepcopy__(self, memo):
        return self

    def __reduce__(self):
        return (Model, (str(self._file) if self._file is not None else self.name,))

    def __repr__(self) -> str:
        where = f", file {self._file}" if self._file else ", built in" if self.builtin else ""
        return (f"Model({self.name!r}: {self.n_dofs} DOF, {self.n_muscles} muscles, {self.n_elements} elements"
                f"{where})")

    # ------------------------------------------------------------------ names and sizes
    @property
    def name(self) -> str:
        return self._info["name"]

    @property
    def source_hash(self) -> str:
        """SHA-256 of the model file the model was generated from."""
        return self._info["source_hash"]

    @property
    def builtin(self) -> bool:
        """Compiled into the engine (das2), as opposed to loaded from a model library."""
        return self._library is None

    @property
    def n_dofs(self) -> int:
        return len(self._info["dofs"])

    @property
    def n_elements(self) -> int:
        return len(self._info["elements"])

    @property
    def n_muscles(self) -> int:
        return len(self._info["muscles"])

    @property
    def state_layout(self) -> MappingProxyType:
        """{"q", "qdot", "lce", "activation": (offset, size)} in the engine's state vector (Data.state)."""
        return MappingProxyType({k: tuple(v) for k, v in self._info["state_layout"].items()})

    @property
    def dof_names(self) -> tuple[str, ...]:
        return tuple(d["name"] for d in self._info["dofs"])

    @property
    def dof_osim_names(self) -> tuple[str, ...]:
        """OpenSim coordinate names (GH_y, ...)."""
        return tuple(d["osim_name"] for d in self._info["dofs"])

    @property
    def dof_ranges(self) -> np.ndarray:
        """(ndof, 2) rad: range of motion, also where the passive joint limits start."""
        return _readonly([d["range"] for d in self._info["dofs"]])

    @property
    def rest_posture(self) -> np.ndarray:
        """(ndof,) rad: the default posture of reset()."""
        return _readonly([d["rest"] for d in self._info["dofs"]])

    @property
    def element_names(self) -> tuple[str, ...]:
        return tuple(e["name"] for e in self._info["elements"])

    @property
    def element_muscles(self) -> tuple[str, ...]:
        """The muscle of each element."""
        return tuple(e["muscle"] for e in self._info["elements"])

    @property
    def element_dofs(self) -> tuple[tuple[int, ...], ...]:
        """Indices of the DOFs each element crosses."""
        return tuple(tuple(e["dofs"]) for e in self._info["elements"])

    @property
    def crosses_gh(self) -> np.ndarray:
        """(n,) bool: the element crosses the gleno-humeral joint."""
        a = np.array([e["crosses_gh"] for e in self._info["elements"]], dtype=bool)
        a.flags.writeable = False
        return a

    @property
    def muscle_names(self) -> tuple[str, ...]:
        return tuple(m for m, _ in self._info["muscles"])

    @property
    def group_names(self) -> tuple[str, ...]:
        return tuple(g for g, _ in self._info["groups"])

    @property
    def muscles(self) -> MappingProxyType:
        """{muscle name: element indices (tuple)}."""
        return MappingProxyType({m: tuple(ix) for m, ix in self._info["muscles"]})

    @property
    def groups(self) -> MappingProxyType:
        """{group name: element indices (tuple)} (rotator_cuff, elbow_flexors, ...)."""
        return MappingProxyType({g: tuple(ix) for g, ix in self._info["groups"]})

    @property
    def parameters(self) -> MappingProxyType:
        """Hill-type parameters per element, (n,) read-only arrays: fmax (N, intact), lceopt (m),
        lslack (m), pennopt (rad), vmax (lceopt/s), tact, tdeact (s), peeslack (x lceopt)."""
        return MappingProxyType({k: _readonly([e[k] for e in self._info["elements"]]) for k in _PARAMETERS})

    @property
    def arm_mass(self) -> float:
        """kg, humerus + ulna + radius + hand."""
        return float(self._info["arm_mass"])

    @property
    def gravity_base(self) -> np.ndarray:
        """(3,) m/s^2, gravity in the base frame (das2: the fixed scapula; das3: the thorax; an Arm may
        change its own)."""
        return _readonly(self._info["gravity_base"])

    @property
    def base_rotation_in_thorax(self) -> np.ndarray:
        """(3, 3): columns are the base frame's axes (das2: the fixed scapula; das3: the thorax, identity)
        in thorax coordinates."""
        return _readonly(np.reshape(self._info["base_rotation_in_thorax"], (3, 3)))

    @property
    def base_origin_in_thorax(self) -> np.ndarray:
        """(3,) m."""
        return _readonly(self._info["base_origin_in_thorax"])

    @property
    def glenoid(self) -> MappingProxyType:
        """GH centre (m), glenoid normal, major and minor axes (unit, scapula frame, moving with q in
        das3), rim half-angles (rad)."""
        keys = ("gh_centre", "glenoid_normal", "glenoid_major_axis", "glenoid_minor_axis")
        out = {k: _readonly(self._info[k]) for k in keys}
        out.update(rim_half_angle_major=self._info["rim_half_angle_major"],
                   rim_half_angle_minor=self._info["rim_half_angle_minor"])
        return MappingProxyType(out)

    @property
    def model_file(self) -> Path | None:
        """The model file: the one loaded, or for a built-in model the shipped models/<name>.json if found."""
        if self._file is not None:
            return self._file
        return find_model_file(self.name)

    @property
    def provenance(self) -> MappingProxyType:
        """Where the model comes from: name, source_hash (SHA-256 of the model file), builtin, model_file,
        library (the shared library of a model built on demand), and the model file's own description
        and source (input files with hashes, importer command) when the file is found."""
        out = {"name": self.name, "source_hash": self.source_hash, "builtin": self.builtin,
               "model_file": str(self.model_file) if self.model_file else None,
               "library": str(self._library) if self._library else None}
        path = self.model_file
        if path is not None:
            try:
                doc = json.loads(Path(path).read_text())
                out.update(description=doc.get("description"), source=doc.get("source"))
            except (OSError, ValueError):
                pass
        return MappingProxyType(out)

    @property
    def info(self) -> dict:
        """The engine's description of the model (what Arm.info holds): a fresh dict."""
        return _core.model_info(self._def)

    # ------------------------------------------------------------------ names (the C++ name service)
    def indices(self, name: str) -> tuple[int, ...]:
        """Element indices of an element, muscle or group name, or an OpenSim force or muscle name
        (delt_scap_1, delt_scap); KeyError with close matches otherwise."""
        if not isinstance(name, str):
            raise KeyError(f"element, muscle or group names must be strings, got {name!r}")
        return tuple(_core.find_elements(self.name, name))

    def dof_index(self, name: str) -> int:
        """Index of a DOF by armrt name (GHy) or OpenSim coordinate name (GH_y); KeyError with close matches."""
        return _core.find_dof(self.name, str(name))

    # ------------------------------------------------------------------ functions of a pose
    def _q(self, q, what: str = "q") -> np.ndarray:
        a = np.ascontiguousarray(real_array(q, what))
        nd = self.n_dofs
        if a.shape[-1:] != (nd,) or a.ndim not in (1, 2):
            raise ValueError(f"{what} must have shape ({nd},) ({', '.join(self.dof_names)}) or (k, {nd}), "
                             f"got {a.shape}")
        if not np.all(np.isfinite(a)):
            raise ValueError(f"{what} contains NaN or infinite values")
        # The paths are polynomials fitted over the joint ranges: far outside (degrees given as radians)
        # they return moment arms of kilometres, not an error. No warning closer in: a simulated state
        # may be slightly beyond its range.
        if a.ndim == 1:
            return joint_range(a, self.dof_names, self.dof_ranges, warn=False)
        return joint_range_rows(a, self.dof_names, self.dof_ranges, lambda r: f"{what} row {r}", warn=False)

    def muscle_lengths(self, q) -> np.ndarray:
        """(n,) m: muscle-tendon lengths at pose q (ndof,) rad; (k, n) for q (k, ndof)."""
        return self._def.muscle_lengths(self._q(q))

    def moment_arms(self, q) -> np.ndarray:
        """(n, ndof) m: moment arms -dL/dq of the path polynomials at pose q; (k, n, ndof) for q (k, ndof)."""
        return self._def.muscle_paths(self._q(q))[1]

    def gh_directions(self, q) -> np.ndarray:
        """(n, 3) unit lines of action at GH (scapula frame), zero rows for elements not crossing GH;
        (k, n, 3) for q (k, ndof)."""
        return self._def.gh_directions(self._q(q))

    def mass_matrix(self, q) -> np.ndarray:
        """(ndof, ndof) kg m^2 (symmetric positive definite); (k, ndof, ndof) for q (k, ndof)."""
        return self._def.mass_matrix(self._q(q))

    def inverse_dynamics(self, q, qdot=0.0, qddot=0.0, hand_load=None, parts: bool = False):
        """(ndof,) N m the muscles must supply for accelerations qddot at (q, qdot) with the model's default
        gravity and hand_load (None: none); armrt.inverse_dynamics has the details."""
        return _inverse_dynamics(self, q, qdot, qddot, hand_load, parts)

    # Keys of gh_rim, in the order the engine's gh_stability returns them; the names of the Arm properties.
    GH_RIM_KEYS = ("gh_theta", "gh_phi", "gh_stab", "gh_rim_margin", "gh_rim_direction")

    def gh_rim(self, force) -> dict:
        """Where forces of the humeral head on the glenoid point (the engine's gh_stability, the one
        definition; docs/conventions.md). force: (3,) or (k, 3) N, scapula frame. Returns a dict of arrays
        of shape () or (k,): gh_theta, gh_phi (rad, from the glenoid normal along the major (+ superior)
        and minor (+ anterior) axes), gh_stab (1, the paper's eq. (5); > 1 beyond the rim), gh_rim_margin
        (rad, how far the force can still turn towards gh_rim_direction before it reaches the rim; < 0
        beyond it; theta_a for a force along the normal) and gh_rim_direction (rad, psi = atan2(phi, theta)
        in (-pi, pi]: 0 superior, pi/2 anterior, +-pi inferior, -pi/2 posterior). ValueError for another
        shape or a non-finite force, TypeError for a complex or non-numeric one."""
        f = np.ascontiguousarray(real_array(force, "force"))
        if f.ndim not in (1, 2) or f.shape[-1:] != (3,):
            raise ValueError(f"force must have shape (3,) or (k, 3) (N, scapula frame), got {f.shape}")
        if not np.all(np.isfinite(f)):
            raise ValueError("force contains NaN or infinite values")
        return dict(zip(self.GH_RIM_KEYS, self._def.gh_stability(f)))

    @property
    def body_names(self) -> tuple[str, ...]:
        """The moving bodies body_poses returns, in order: das2 humerus, ulna, radius, hand; das3
        clavicle, scapula, humerus, ulna, radius, hand."""
        return tuple(self._info["body_names"])

    @property
    def base_body(self) -> str:
        """The engine's base frame (fixed to the thorax): "scapula" (das2) or "thorax" (das3)."""
        return self._info["base_body"]

    @property
    def girdle_dofs(self) -> tuple[int, ...]:
        """Indices of the DOFs that move the scapula (das3: SCy SCz SCx ACy ACz ACx; das2: none), found
        from the engine's body poses: a DOF is a girdle DOF if turning it alone moves the scapula."""
        k = self._info["scapula_body"]
        if k < 0:
            return ()
        q0 = np.asarray(self.rest_posture, dtype=float)
        Q = q0 + 0.1 * np.eye(self.n_dofs)
        R, p = self._def.body_poses(np.ascontiguousarray(np.vstack([q0, Q])))
        moved = (np.abs(R[1:, k] - R[0, k]).max(axis=(1, 2)) > 1e-9) | (np.abs(p[1:, k] - p[0, k]).max(axis=1) > 1e-12)
        return tuple(int(j) for j in np.flatnonzero(moved))

    def _scapula_in_base(self, q) -> tuple[np.ndarray, np.ndarray]:
        """(R (..., 3, 3), o (..., 3)): the moving scapula's pose in the base frame at q."""
        R, p = self._def.body_poses(q)
        k = self._info["scapula_body"]
        return R[..., k, :, :], p[..., k, :]

    def body_poses(self, q, frame: str = "thorax") -> tuple[np.ndarray, np.ndarray]:
        """(R (nb, 3, 3), p (nb, 3) m) of the bodies in body_names (das2: humerus, ulna, radius, hand,
        whose origins are GH, elbow, proximal radius, wrist; das3 adds clavicle and scapula first, at the
        SC and AC joints) in the thorax frame (frame="scapula": the scapula frame, which moves with q in
        das3); (k, nb, 3, 3), (k, nb, 3) for q (k, ndof)."""
        q = self._q(q)
        R, p = self._def.body_poses(q)
        if self._frame(frame) == "scapula":
            if self._info["scapula_body"] < 0:
                return R, p
            Rs, os_ = self._scapula_in_base(q)
            return (np.einsum("...ji,...bjk->...bik", Rs, R),
                    np.einsum("...ji,...bj->...bi", Rs, p - os_[..., None, :]))
        Rs, os_ = self.base_rotation_in_thorax, self.base_origin_in_thorax
        return np.einsum("ij,...bjk->...bik", Rs, R), p @ Rs.T + os_

    def hand_position(self, q, frame: str = "thorax") -> np.ndarray:
        """(3,) m: the hand point (where Arm.hand_position is reported) in the thorax frame (or
        frame="scapula", moving with q in das3); (k, 3) for q (k, ndof)."""
        q = self._q(q)
        p = self._def.hand_position(q)
        if self._frame(frame) == "scapula":
            if self._info["scapula_body"] < 0:
                return p
            Rs, os_ = self._scapula_in_base(q)
            return np.einsum("...ji,...j->...i", Rs, p - os_)
        return p @ self.base_rotation_in_thorax.T + self.base_origin_in_thorax

    def hand_jacobian(self, q, frame: str = "thorax") -> tuple[np.ndarray, np.ndarray]:
        """(Jv (3, ndof) m/rad, Jw (3, ndof) 1): hand point velocity and hand angular velocity per joint
        velocity, thorax frame (or frame="scapula" for a model whose scapula is fixed; ValueError for
        das3, whose scapula frame moves); with a leading k for q (k, ndof)."""
        if self._frame(frame) == "scapula" and self._info["scapula_body"] >= 0:
            raise ValueError(f"model {self.name}: the scapula moves with q, so the hand Jacobian is given in "
                             f"the thorax frame only (frame='thorax')")
        Jv, Jw = self._def.hand_jacobian(self._q(q))
        if self._frame(frame) == "scapula":
            return Jv, Jw
        Rs = self.base_rotation_in_thorax
        return np.einsum("ij,...jk->...ik", Rs, Jv), np.einsum("ij,...jk->...ik", Rs, Jw)

    @staticmethod
    def _frame(frame: str) -> str:
        if frame not in ("thorax", "scapula"):
            raise ValueError(f"frame must be 'thorax' or 'scapula', got {frame!r}")
        return frame
