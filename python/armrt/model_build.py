"""Models built on demand: a model file (docs/model_schema.md) -> the code generator -> the C++ compiler
-> a shared library in the user's cache -> the engine's model registry.

    lib = build("my_arm.json")          # BuildResult: library path, model name, seconds, cached?
    armrt.Model.load("my_arm.json")     # the same, then loads the library (armrt/model.py)

The generator (`python -m codegen.generate --entry-point`, the one path from a model file to C++) and
the compiler run once per model file: the library is cached under cache_dir() by a key made of the
file's SHA-256, the engine's ModelDef layout version, the armrt version, the generator's sources, the
compiler and its flags (and the CPU when the flags say -march=native), so a second build or load of the
same file only hashes it. The compiler and flags are those the installed engine compiled das2 with
(armrt/build_config.json, written by CMake), so an on-demand das2 runs bit for bit like the built-in one.
"""
from __future__ import annotations

import contextlib
import hashlib
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

from .codegen_locator import CodegenNotFoundError, codegen_module_name, import_codegen

HERE = Path(__file__).resolve().parent
# Checkout layout (PYTHONPATH=python or pytest from the repository root): python/armrt/../../{cpp,codegen}.
REPO = HERE.parents[1]
LIBRARY_NAME = "libarmrt_model.so"


class ModelBuildError(RuntimeError):
    """Generating or compiling a model failed; `log` is the path of the build log."""

    def __init__(self, message: str, log: Path | None = None):
        super().__init__(message)
        self.log = log


class CompilerNotFoundError(ModelBuildError):
    """No C++ compiler to build a model with."""


class ModelFileError(ValueError):
    """A model file that does not follow docs/model_schema.md; the message names the field (and the
    element, DOF, muscle or body by name)."""


@dataclass(frozen=True)
class BuildResult:
    library: Path       # the shared library (in the cache)
    name: str           # the model's name
    source_hash: str    # SHA-256 of the model file
    model_file: Path
    seconds: float      # wall time of this call
    cached: bool        # True: the library was already built
    log: Path           # build log (written when it was built)


# ------------------------------------------------------------------------------------ locations
def cache_dir() -> Path:
    """Where built models are kept: $ARMRT_CACHE_DIR, else the platform's user cache folder
    ($XDG_CACHE_HOME/armrt or ~/.cache/armrt on Linux, ~/Library/Caches/armrt on macOS)."""
    if os.environ.get("ARMRT_CACHE_DIR"):
        return Path(os.environ["ARMRT_CACHE_DIR"]).expanduser()
    if sys.platform == "darwin":
        return Path.home() / "Library" / "Caches" / "armrt"
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base).expanduser() / "armrt"


def include_dir() -> Path:
    """The engine headers the generated code includes (armrt/model_def.h, ...): installed with the
    package (armrt/include) or, in a source checkout, cpp/include."""
    for d in (HERE / "include", REPO / "cpp" / "include"):
        if (d / "armrt" / "model_def.h").is_file():
            return d
    raise ModelBuildError(f"the engine headers (armrt/model_def.h) are not in {HERE / 'include'} nor "
                          f"{REPO / 'cpp' / 'include'}: reinstall armrt (pip install .)")


def generator() -> tuple[str, Path]:
    """(module to run with python -m, the sys.path entry it needs): the checkout's codegen/ when running
    from a checkout, else the generator installed with the package (armrt.codegen; codegen_locator.py)."""
    try:
        return codegen_module_name("generate")
    except CodegenNotFoundError as exc:
        raise ModelBuildError(str(exc)) from None


def build_config() -> dict:
    """How the engine's generated code was compiled (armrt/build_config.json, written by CMake). In a
    source checkout without an installed config: the system compiler and the engine's Release flags."""
    from . import _core
    for path in (HERE / "build_config.json",):
        if path.is_file():
            cfg = json.loads(path.read_text())
            break
    else:
        cfg = {"abi_version": _core.MODEL_ABI_VERSION, "cxx": "", "cxx_id": "",
               "flags": "-O3 -DNDEBUG -std=gnu++17 -fPIC -Wall -Wextra -O3 -fopenmp-simd -fno-math-errno "
                        "-fno-trapping-math", "dynamics_flags": "-Os"}
    if cfg.get("abi_version") != _core.MODEL_ABI_VERSION:
        raise ModelBuildError(f"{HERE / 'build_config.json'} is for ModelDef layout {cfg.get('abi_version')} but the "
                              f"engine has {_core.MODEL_ABI_VERSION}: reinstall armrt (pip install .)")
    return cfg


def find_compiler(cfg: dict) -> list[str]:
    """The compiler command: $CXX if set, else the one the engine was built with, else c++, g++ or
    clang++ on PATH. CompilerNotFoundError naming what was tried otherwise."""
    tried = []
    if os.environ.get("CXX"):
        cmd = shlex.split(os.environ["CXX"])
        if cmd and shutil.which(cmd[0]):
            return [shutil.which(cmd[0]), *cmd[1:]]
        raise CompilerNotFoundError(f"no C++ compiler: $CXX is {os.environ['CXX']!r}, which is not an executable; "
                                    f"install g++ (Debian: apt-get install g++) or set CXX to a C++17 compiler")
    candidates = ([cfg["cxx"]] if cfg.get("cxx") else []) + ["c++", "g++", "clang++"]
    for c in candidates:
        tried.append(c)
        found = shutil.which(c)
        if found:
            return [found]
    raise CompilerNotFoundError(f"no C++ compiler found (tried {', '.join(tried)}); building a model needs one: "
                                f"install g++ (Debian: apt-get install g++) or set CXX")


def _cpu_identity() -> str:
    """The CPU's feature flags, for -march=native libraries (a cache shared between machines must not
    hand one CPU's instructions to another)."""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith(("flags", "Features")):
                return line
    except OSError:
        pass
    import platform
    return platform.processor() or platform.machine()


def _generator_hash(gen_root: Path, module: str) -> str:
    pkg = gen_root.joinpath(*module.split(".")[:-1])
    h = hashlib.sha256()
    for p in sorted(pkg.glob("*.py")):
        h.update(p.name.encode() + b"\0" + p.read_bytes())
    return h.hexdigest()


def cache_key(source_hash: str, cfg: dict, compiler: list[str], gen: tuple[str, Path]) -> str:
    from . import __version__
    parts = {"model": source_hash, "abi": cfg["abi_version"], "armrt": __version__, "cxx": compiler,
             "cxx_id": cfg.get("cxx_id", ""), "flags": cfg["flags"], "dynamics_flags": cfg["dynamics_flags"],
             "generator": _generator_hash(gen[1], gen[0])}
    if "-march=native" in cfg["flags"] or "-mcpu=native" in cfg["flags"]:
        parts["cpu"] = _cpu_identity()
    return hashlib.sha256(json.dumps(parts, sort_keys=True).encode()).hexdigest()


def cache_entry(source_hash: str, cfg: dict | None = None, gen: tuple[str, Path] | None = None) -> Path:
    """The cache folder of the model file with that SHA-256 for this engine, generator and compiler
    configuration (the compiler as configured, not looked up: a cached library loads without any)."""
    cfg = cfg or build_config()
    gen = gen or generator()
    configured = shlex.split(os.environ["CXX"]) if os.environ.get("CXX") else [cfg.get("cxx") or "c++"]
    return cache_dir() / "models" / cache_key(source_hash, cfg, configured, gen)[:24]


def cached_library(name: str, source_hash: str) -> Path | None:
    """The library already built for the model file of that name and SHA-256 with this configuration,
    or None. Used to reopen a result's model without its file; builds nothing."""
    entry = cache_entry(source_hash)
    try:
        meta = json.loads((entry / "model.json").read_text())
    except (OSError, ValueError):
        return None
    ok = meta.get("name") == name and meta.get("source_hash") == source_hash
    return entry / LIBRARY_NAME if ok and (entry / LIBRARY_NAME).is_file() else None


# ------------------------------------------------------------------------------------ validation
_LISTS = {"elements": "element", "dofs": "DOF", "muscles": "muscle", "bodies": "body"}


def validate_file(path) -> tuple[dict, str]:
    """(model, SHA-256 of the file) after the generator's checks (codegen.schema.load_model:
    schema and sense checks). ModelFileError naming the file, the field, and the element (DOF, muscle,
    body) by name when the field is inside one; FileNotFoundError for a missing file."""
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(2, "no such model file", str(path))
    try:
        gen = import_codegen("generate")
    except CodegenNotFoundError as exc:
        raise ModelBuildError(str(exc)) from None
    except ModuleNotFoundError as exc:
        raise ModelBuildError(f"building a model needs the code generator's dependency {exc.name!r}: "
                              f"pip install {exc.name}") from None
    try:
        return gen.load_model(path)
    except gen.ModelFileError as exc:
        raise ModelFileError(f"{path}: {_name_the_item(path, str(exc))}") from None


def _name_the_item(path: Path, message: str) -> str:
    """'... field 'elements[3].fmax' ...' -> '... (element 'deltscap4')' when the file says so."""
    m = re.search(r"'(elements|dofs|muscles|bodies)\[(\d+)\]", message)
    if not m:
        return message
    try:
        item = json.loads(path.read_bytes())[m.group(1)][int(m.group(2))]
        name = item.get("name") if isinstance(item, dict) else None
    except (OSError, ValueError, KeyError, IndexError, TypeError, RecursionError):
        name = None
    return f"{message} ({_LISTS[m.group(1)]} {name!r})" if isinstance(name, str) else message


# ------------------------------------------------------------------------------------ building
@contextlib.contextmanager
def _locked(directory: Path):
    """One builder per cache entry across processes (a second waits, then finds the library)."""
    import fcntl
    directory.mkdir(parents=True, exist_ok=True)
    with open(directory / ".lock", "w") as f:
        fcntl.flock(f, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(f, fcntl.LOCK_UN)


def _run(cmd: list[str], log, env=None, cwd=None) -> int:
    log.write("$ " + shlex.join(str(c) for c in cmd) + "\n")
    p = subprocess.run([str(c) for c in cmd], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       env=env, cwd=cwd)
    log.write(p.stdout)
    log.write(f"[exit status {p.returncode}]\n")
    log.flush()
    return p.returncode


def build(path, force: bool = False, jobs: int | None = None) -> BuildResult:
    """Builds (or finds in the cache) the shared library of a model file; see the module docstring.

    path: a model file (JSON, docs/model_schema.md). force: rebuild even if cached. jobs: compiler
    processes at once (default 2, or fewer cores). Raises FileNotFoundError (no file), ModelFileError
    (fails validation: the field and element), CompilerNotFoundError (no C++ compiler),
    ModelBuildError (the generator or compiler failed: the message gives the build log's path)."""
    t0 = time.perf_counter()
    path = Path(path)
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        raise FileNotFoundError(2, "no such model file", str(path)) from None
    source_hash = hashlib.sha256(data).hexdigest()
    cfg = build_config()
    gen = generator()
    entry = cache_entry(source_hash, cfg, gen)
    library, meta_path, log_path = entry / LIBRARY_NAME, entry / "model.json", entry / "build.log"

    def cached() -> BuildResult | None:
        if force or not library.is_file() or not meta_path.is_file():
            return None
        meta = json.loads(meta_path.read_text())
        return BuildResult(library, meta["name"], source_hash, path, time.perf_counter() - t0, True, log_path)

    hit = cached()
    if hit is not None:
        return hit
    model, _ = validate_file(path)  # a broken file is the first thing to fix, compiler or not
    compiler = find_compiler(cfg)
    with _locked(entry):
        hit = cached()  # another process may have built it while we waited
        if hit is not None:
            return hit
        work = Path(tempfile.mkdtemp(prefix="build-", dir=entry))
        src = work / "src"
        with open(log_path, "w") as log:
            log.write(f"armrt model build {path} (sha256 {source_hash}) -> {library}\n")
            env = dict(os.environ)
            env["PYTHONPATH"] = os.pathsep.join([str(gen[1])] + ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else []))
            if _run([sys.executable, "-m", gen[0], "--model", path.resolve(), "--out", src, "--entry-point"],
                    log, env=env) != 0:
                raise ModelBuildError(f"generating the C++ code of model {model['name']!r} failed; "
                                      f"build log: {log_path}", log_path)
            sources = sorted(src.glob("*.cc"))
            flags = shlex.split(cfg["flags"])
            inc = include_dir()

            def compile_one(cc: Path) -> tuple[Path, int, str]:
                extra = shlex.split(cfg["dynamics_flags"]) if cc.name.endswith("_dynamics.cc") else []
                obj = cc.with_suffix(".o")
                cmd = [*compiler, f"-I{inc}", f"-I{src}", *flags, *extra, "-fvisibility=hidden",
                       "-o", str(obj), "-c", str(cc)]
                p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
                return obj, p.returncode, "$ " + shlex.join(cmd) + "\n" + p.stdout + f"[exit status {p.returncode}]\n"

            n_jobs = jobs or max(1, min(2, os.cpu_count() or 1))
            with ThreadPoolExecutor(n_jobs) as pool:
                results = list(pool.map(compile_one, sources))
            for _, _, text in results:
                log.write(text)
            log.flush()
            failed = [obj.with_suffix(".cc").name for obj, rc, _ in results if rc != 0]
            if failed:
                raise ModelBuildError(f"compiling model {model['name']!r} failed ({', '.join(failed)}); "
                                      f"compiler output in the build log: {log_path}", log_path)
            out = work / LIBRARY_NAME
            if _run([*compiler, *flags, "-shared", "-o", out, *[obj for obj, _, _ in results]], log) != 0:
                raise ModelBuildError(f"linking model {model['name']!r} failed; build log: {log_path}", log_path)
            os.replace(out, library)
            meta = {"name": model["name"], "model_file": str(path.resolve()), "source_hash": source_hash,
                    "built": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()), "compiler": compiler,
                    "flags": cfg["flags"], "dynamics_flags": cfg["dynamics_flags"],
                    "seconds": round(time.perf_counter() - t0, 2)}
            meta_path.write_text(json.dumps(meta, indent=1) + "\n")
            log.write(f"built in {time.perf_counter() - t0:.1f} s\n")
        shutil.rmtree(work, ignore_errors=True)
    return BuildResult(library, model["name"], source_hash, path, time.perf_counter() - t0, False, log_path)
