"""Loading models cannot be fooled (issue 25, B1 and B3): a corrupted cached library is rebuilt or
refused before dlopen, and a model file is refused, before anything is compiled, for a name that
clashes with a registered model, a name too long or unsafe for a file or C symbol, a file that is
not UTF-8, or masses, inertias and lengths no arm has.

Loads of a damaged library run in a subprocess: dlopen of a truncated .so dies of SIGBUS or SIGSEGV,
which must fail the test, not kill pytest."""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

import armrt
from armrt import model_build

ROOT = Path(__file__).resolve().parents[1]
PENDULUM = ROOT / "tests" / "data" / "pendulum2.json"


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("ARMRT_CACHE_DIR", str(tmp_path / "cache"))
    return tmp_path / "cache"


def load_in_subprocess(code: str, cache: Path) -> subprocess.CompletedProcess:
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600,
                       env={**os.environ, "ARMRT_CACHE_DIR": str(cache)})
    if p.returncode < 0:
        pytest.fail(f"the load died of {signal.Signals(-p.returncode).name}: {p.stderr[-2000:]}")
    return p


def pendulum(tmp_path: Path, name: str = "pendulum2", edit=None) -> Path:
    doc = json.loads(PENDULUM.read_text())
    doc["name"] = name
    if edit:
        edit(doc)
    path = tmp_path / "model.json"
    path.write_text(json.dumps(doc))
    return path


# ------------------------------------------------------------------------------------ B1: the cache
def _damage(lib: Path, how: str) -> None:
    data = lib.read_bytes()
    if how == "truncate":
        lib.write_bytes(data[:len(data) // 3])
    else:  # flip bytes all through the file, the ELF header's magic excepted
        b = bytearray(data)
        for i in range(0x40, len(b), 97):
            b[i] ^= 0xFF
        lib.write_bytes(bytes(b))


@pytest.mark.parametrize("how", ["truncate", "flip"])
def test_a_corrupted_cached_library_is_rebuilt_not_loaded(tmp_path, cache, how):
    """Model.load of a file whose cached library was damaged afterwards (a full disk, a crash while
    copying, bit rot) rebuilds it, with a warning, and runs; before, dlopen died of SIGBUS/SIGSEGV."""
    path = pendulum(tmp_path)
    code = (f"import armrt, warnings; warnings.simplefilter('always'); m = armrt.Model.load({str(path)!r}); "
            f"a = armrt.Arm(m); a.step(10); print('ran', m.name, a.time)")
    first = load_in_subprocess(code, cache)
    assert first.returncode == 0 and first.stdout.split()[:2] == ["ran", "pendulum2"], first.stderr
    libs = list(cache.glob("models/*/libarmrt_model.so"))
    assert len(libs) == 1
    assert (libs[0].parent / "libarmrt_model.so.sha256").is_file()
    _damage(libs[0], how)
    again = load_in_subprocess(code, cache)
    assert again.returncode == 0 and again.stdout.split()[:2] == ["ran", "pendulum2"], again.stderr
    assert "does not match its checksum" in again.stderr and "rebuilding" in again.stderr
    assert model_build.library_intact(libs[0])


def test_a_corrupted_library_that_cannot_be_rebuilt_is_refused_clearly(tmp_path, cache):
    """A saved Result reopens its model from the cache (no model file to rebuild from): a damaged
    library there is refused with a message naming it, instead of a crash in dlopen."""
    path = pendulum(tmp_path)
    out = tmp_path / "run.npz"
    made = load_in_subprocess(f"import armrt; a = armrt.Arm(armrt.Model.load({str(path)!r})); "
                              f"a.simulate(0.1, 0.01).save({str(out)!r})", cache)
    assert made.returncode == 0, made.stderr
    lib = next(cache.glob("models/*/libarmrt_model.so"))
    _damage(lib, "truncate")
    p = load_in_subprocess(f"import armrt; armrt.Result.load({str(out)!r})", cache)
    assert p.returncode != 0
    assert "ModelBuildError" in p.stderr and str(lib) in p.stderr and "does not match its checksum" in p.stderr
    assert "armrt.Model.load" in p.stderr  # what to do: load the model file, which rebuilds it
