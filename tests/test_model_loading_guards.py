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


# ------------------------------------------------------------------------------------ B3: the model file
@pytest.fixture
def no_compiling(tmp_path, monkeypatch):
    """CXX is a compiler that records being run: a refusal must come before it is."""
    marker = tmp_path / "compiler-ran"
    fake = tmp_path / "recording-c++"
    fake.write_text(f"#!/bin/sh\ntouch {marker}\nexit 1\n")
    fake.chmod(0o755)
    monkeypatch.setenv("CXX", str(fake))
    return marker


def test_a_name_clash_is_refused_before_compiling(tmp_path, cache, no_compiling):
    """A file named like a registered model (das2, built in) but with other contents: refused by
    Model.load, by model_build.build and by `armrt model build`, and nothing is generated or compiled
    (before, the CLI compiled for 15 s first and build() compiled it without a word)."""
    from armrt.cli import main
    path = pendulum(tmp_path, "das2")
    with pytest.raises(ValueError, match="different model named 'das2' is already registered"):
        armrt.Model.load(path)
    with pytest.raises(ValueError, match="different model named 'das2' is already registered"):
        model_build.build(path)
    assert main(["model", "build", str(path)]) == 2
    assert not no_compiling.exists() and not list(cache.glob("models/*/*.so"))
    assert not list(cache.glob("models/*/build.log")), "the generator was not run either"


@pytest.mark.parametrize("name, message", [
    ("a" * 100_000, r"field 'name' is 100000 characters long, more than 64"),
    ("a" * 65, r"field 'name' is 65 characters long, more than 64"),
    ("pend-ulum", r"field 'name' 'pend-ulum' must be ASCII letters, digits and '_'"),
    ("../../etc/x", r"must be ASCII letters, digits and '_'"),
    ("2arm", r"not starting with a digit"),
    ("p\u00e9ndulum", r"must be ASCII letters"),
])
def test_model_names_are_short_and_safe(tmp_path, cache, no_compiling, name, message):
    with pytest.raises(armrt.ModelFileError, match=message):
        armrt.Model.load(pendulum(tmp_path, name))
    assert not no_compiling.exists()


@pytest.mark.parametrize("where, message", [
    (lambda d: d["dofs"][0].__setitem__("name", "E" * 5000), r"'dofs\[0\]\.name' is 5000 characters.*\(DOF 'E"),
    (lambda d: d["elements"][2].__setitem__("name", "x" * 101), r"'elements\[2\]\.name' is 101 characters"),
    (lambda d: d["muscles"][1].__setitem__("name", "m" * 65), r"'muscles\[1\]\.name' is 65 characters"),
    (lambda d: d["groups"].__setitem__("g" * 200, []), r"group name in 'groups' is 200 characters"),
], ids=["dof", "element", "muscle", "group"])
def test_item_names_are_limited(tmp_path, cache, no_compiling, where, message):
    with pytest.raises(armrt.ModelFileError, match=message):
        model_build.validate_file(pendulum(tmp_path, "pendulum2", where))
    assert armrt.model_build.MAX_NAME_LENGTH == 64


def test_a_file_that_is_not_utf8_names_the_file(tmp_path, cache):
    path = tmp_path / "latin1.json"
    doc = json.loads(PENDULUM.read_text())
    doc["description"] = "mod\u00e9le"
    path.write_bytes(json.dumps(doc, ensure_ascii=False).encode("latin-1"))
    for load in (armrt.Model.load, model_build.validate_file):
        with pytest.raises(armrt.ModelFileError, match=r"latin1\.json: not UTF-8 \(byte \d+: .*\); a model file must "
                                                       r"be UTF-8 encoded JSON"):
            load(path)


@pytest.mark.parametrize("edit, message", [
    (lambda d: d["bodies"][1].__setitem__("mass", 1e-300),
     r"'bodies\[1\]\.mass' = 1e-300 kg is outside \[0\.001, 100\] kg.*\(body 'ulna'\)"),
    (lambda d: d["bodies"][0].__setitem__("mass", 5e3), r"'bodies\[0\]\.mass' = 5000 kg"),
    (lambda d: d["bodies"][2].__setitem__("inertia", [[1e-300, 0, 0], [0, 1e-300, 0], [0, 0, 1e-300]]),
     r"'bodies\[2\]\.inertia' has principal moments .* outside \[1e-09, 10\] kg m\^2.*\(body 'radius'\)"),
    (lambda d: d["bodies"][1]["joint"].__setitem__("location_in_parent", [0, -1e6, 0]),
     r"'bodies\[1\]\.joint\.location_in_parent' has a coordinate of -1e\+06 m"),
    (lambda d: d["bodies"][3].__setitem__("com", [0, 5.0, 0]), r"'bodies\[3\]\.com' has a coordinate of 5 m"),
    (lambda d: d["hand_point"].__setitem__("point", [0, -2.0, 0]), r"'hand_point\.point' has a coordinate of -2 m"),
    (lambda d: d["elements"][0].__setitem__("fmax", 1e-300), r"'elements\[0\]\.fmax' = 1e-300 N"),
    (lambda d: d["elements"][4].__setitem__("lceopt", 50.0), r"'elements\[4\]\.lceopt' = 50 m"),
    (lambda d: d["elements"][1].__setitem__("lslack", 1e-9), r"'elements\[1\]\.lslack' = 1e-09 m"),
], ids=["tiny_mass", "huge_mass", "inertia", "joint_offset", "com", "hand_point", "fmax", "lceopt", "lslack"])
def test_non_physical_values_are_refused_by_field(tmp_path, cache, no_compiling, edit, message):
    with pytest.raises(armrt.ModelFileError, match=message):
        armrt.Model.load(pendulum(tmp_path, "pendulum2", edit))
    assert not no_compiling.exists()


def test_the_shipped_models_pass_the_checks():
    """The bounds leave every real model in: das2, das3, participant A's variants, the test pendulum."""
    files = [p for p in sorted((ROOT / "models").glob("*.json")) if "bodies" in json.loads(p.read_text())]
    assert len(files) >= 6
    for p in [*files, PENDULUM]:
        model_build.check_model_document(p, p.read_bytes())
