"""Builds the generated model code with tests/gen_harness.cc into a shared library and wraps it with ctypes.

Independent of the armrt Python package, so the generator can be tested on its own.
"""
from __future__ import annotations

import ctypes
import json
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]
MODEL_PATH = ROOT / "models" / "das2.json"
GENERATED = ROOT / "cpp" / "generated"
INCLUDE = ROOT / "cpp" / "include"
HARNESS = Path(__file__).resolve().parent / "gen_harness.cc"

# The generator (codegen/) is run from the repository root and is not part of the installed package.
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

_D = ctypes.POINTER(ctypes.c_double)


def _ptr(a: np.ndarray):
    return a.ctypes.data_as(_D)


def build_library(gen_dir: Path, name: str, out_dir: Path) -> Path:
    cxx = shutil.which("g++") or shutil.which("c++")
    if cxx is None:
        pytest.skip("no C++ compiler (g++) on PATH")
    sources = sorted(str(p) for p in Path(gen_dir).glob(f"{name}*.cc"))
    lib = Path(out_dir) / f"lib{name}_harness.so"
    cmd = [cxx, "-O2", "-std=c++17", "-Wall", "-Wextra", "-Werror", "-shared", "-fPIC",
           f"-I{INCLUDE}", f"-I{gen_dir}", f"-DARMRT_MODEL_NS={name}", f"-DARMRT_MODEL_HEADER={name}.h",
           str(HARNESS), *sources, "-o", str(lib)]
    subprocess.run(cmd, check=True, capture_output=True, text=True)
    return lib


class GenModel:
    """numpy-facing view of the generated functions."""

    def __init__(self, lib_path: Path, model: dict):
        self.lib = ctypes.CDLL(str(lib_path))
        self.model = model
        for fn in ("h_name", "h_source_hash", "h_element_name", "h_muscle_name", "h_group_name"):
            getattr(self.lib, fn).restype = ctypes.c_char_p
        for fn in ("h_arm_mass", "h_element_fmax"):
            getattr(self.lib, fn).restype = ctypes.c_double
        self.ndof = self.lib.h_num_dofs()
        self.nel = self.lib.h_num_elements()

    def _q(self, q):
        return np.ascontiguousarray(q, dtype=float)

    def mass_matrix(self, q):
        M = np.zeros((5, 5))
        self.lib.h_mass_matrix(_ptr(self._q(q)), _ptr(M))
        return M

    def bias_force(self, q, qd, g):
        b = np.zeros(5)
        self.lib.h_bias_force(_ptr(self._q(q)), _ptr(self._q(qd)), _ptr(self._q(g)), _ptr(b))
        return b

    def hand_position(self, q):
        p = np.zeros(3)
        self.lib.h_hand_position(_ptr(self._q(q)), _ptr(p))
        return p

    def hand_jacobian(self, q):
        Jv, Jw = np.zeros((3, 5)), np.zeros((3, 5))
        self.lib.h_hand_jacobian(_ptr(self._q(q)), _ptr(Jv), _ptr(Jw))
        return Jv, Jw

    def arm_momentum_rate(self, q, qd):
        A, c = np.zeros((3, 5)), np.zeros(3)
        self.lib.h_arm_momentum_rate(_ptr(self._q(q)), _ptr(self._q(qd)), _ptr(A), _ptr(c))
        return A, c

    def body_poses(self, q):
        R, p = np.zeros((4, 3, 3)), np.zeros((4, 3))
        self.lib.h_body_poses(_ptr(self._q(q)), _ptr(R), _ptr(p))
        return R, p

    def muscle_lengths(self, q):
        L = np.zeros(self.nel)
        self.lib.h_muscle_lengths(_ptr(self._q(q)), _ptr(L))
        return L

    def muscle_paths(self, q):
        """(L (nel,), moment arms (nel, 5)): the generated code writes them by DOF, rows of MAX_ELEMENTS."""
        from codegen.generate import MAX_ELEMENTS
        L, r = np.zeros(self.nel), np.zeros((5, MAX_ELEMENTS))
        self.lib.h_muscle_paths(_ptr(self._q(q)), _ptr(L), _ptr(r))
        return L, np.ascontiguousarray(r[:, :self.nel].T)

    def gh_directions(self, q):
        d = np.zeros((self.nel, 3))
        self.lib.h_gh_directions(_ptr(self._q(q)), _ptr(d))
        return d

    def gravity_base(self):
        g = np.zeros(3)
        self.lib.h_gravity_base(_ptr(g))
        return g


@pytest.fixture(scope="session")
def gen_model(tmp_path_factory) -> GenModel:
    """The committed cpp/generated code for models/das2.json, compiled and loaded."""
    model = json.loads(MODEL_PATH.read_text())
    if not (GENERATED / f"{model['name']}_dynamics.cc").exists():
        pytest.fail(f"{GENERATED} holds no generated code for {model['name']}; run "
                    "python -m codegen.generate --model models/das2.json --out cpp/generated")
    lib = build_library(GENERATED, model["name"], tmp_path_factory.mktemp("genlib"))
    return GenModel(lib, model)
