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
# SHA-256 of the library, written beside it when it is built and checked before every dlopen: a
# truncated or damaged .so (a full disk, an interrupted copy, bit rot) kills the process in dlopen
# with SIGBUS or SIGSEGV, before any message could be printed.
CHECKSUM_NAME = LIBRARY_NAME + ".sha256"


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
    from ._version import __version__
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


def _file_sha256(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def library_problem(library: Path) -> str | None:
    """Why the cached library must not be dlopened (None: its SHA-256 matches the checksum written
    when it was built)."""
    checksum = library.parent / CHECKSUM_NAME
    try:
        expected = checksum.read_text().split()[0]
    except (OSError, IndexError):
        return f"{library} has no checksum ({checksum}: built by an older armrt, or its build was interrupted)"
    try:
        actual = _file_sha256(library)
    except OSError as exc:
        return f"{library} cannot be read: {exc}"
    if actual != expected:
        return f"{library} does not match its checksum (sha256 {actual[:12]}..., built as {expected[:12]}...): damaged"
    return None


def library_intact(library: Path) -> bool:
    """True if the library's SHA-256 matches the checksum written when it was built."""
    return library_problem(library) is None


def cached_library(name: str, source_hash: str) -> Path | None:
    """The library already built for the model file of that name and SHA-256 with this configuration,
    or None. Used to reopen a result's model without its file; builds nothing. ModelBuildError if the
    library is there but fails its checksum: without the model file it cannot be rebuilt here."""
    entry = cache_entry(source_hash)
    try:
        meta = json.loads((entry / "model.json").read_text())
    except (OSError, ValueError):
        return None
    ok = meta.get("name") == name and meta.get("source_hash") == source_hash
    library = entry / LIBRARY_NAME
    if not (ok and library.is_file()):
        return None
    problem = library_problem(library)
    if problem:
        raise ModelBuildError(f"the cached library of model {name!r} is not loaded: {problem}. Load its model file "
                              f"with armrt.Model.load({meta.get('model_file', 'FILE.json')!r}), which rebuilds it")
    return library


# ------------------------------------------------------------------------------------ validation
_LISTS = {"elements": "element", "dofs": "DOF", "muscles": "muscle", "bodies": "body"}

# Names: at most 64 characters. The longest name in das2/das3/participant_A is 17 (OpenSim's and DAS3's
# are of that order); a model name becomes a file name (with the generator's suffixes, under the 255
# bytes of common file systems), a C symbol and a column of every table and message, so a 100 000
# character name is a mistake, not a model. A model name is also a C identifier and a file name, and
# find_model_file takes it as one: ASCII letters, digits and '_', not starting with a digit.
MAX_NAME_LENGTH = 64
MODEL_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
# Physical ranges (SI) of what the file gives, with the extremes of das2/das3/participant_A beside
# them: the bounds are a factor of 10 or more beyond any human arm, so only non-physical values (a
# mass of 1e-300 kg, a 10 km bone) fail. Body mass: 1 g to 100 kg (DAS3: clavicle 0.156 kg to humerus
# 2.05 kg). Principal moments of inertia: 1e-9 kg m^2 (1 g at a 1 mm radius of gyration) to 10 kg m^2
# (100 kg at 0.3 m) (DAS3: 1.3e-6 to 0.013). Lengths of the skeleton (centres of mass, joint
# locations, the hand point): each coordinate within 1 m (DAS3: at most 0.29 m). Muscle elements:
# fmax 0.01 N to 10 kN (DAS3 16-510 N, participant A's weakest 3.5 N; the largest human muscles give
# a few kN), lceopt and lslack 1 mm to 1 m (DAS3 0.02-0.34 m and 0.004-0.23 m).
BODY_MASS_RANGE = (1e-3, 1e2)                 # kg
INERTIA_RANGE = (1e-9, 1e1)                   # kg m^2, principal moments
SKELETON_COORDINATE_LIMIT = 1.0               # m
ELEMENT_RANGES = {"fmax": ((1e-2, 1e4), "N"), "lceopt": ((1e-3, 1.0), "m"), "lslack": ((1e-3, 1.0), "m")}


def _number(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def check_model_document(path, data: bytes) -> dict:
    """The model file's JSON after the checks armrt makes before the generator sees it (the generator's
    schema checks follow in validate_file): UTF-8, valid JSON, names of at most MAX_NAME_LENGTH
    characters (the model's an identifier, MODEL_NAME), and masses, inertias, lengths and element
    parameters within the physical ranges above. ModelFileError naming the file, the field and the
    item; what is missing or of the wrong type is left to the generator to report."""
    path = Path(path)

    def fail(msg: str):
        raise ModelFileError(f"{path}: {_name_the_item(path, msg, doc)}")
    doc = None
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise ModelFileError(f"{path}: not UTF-8 (byte {exc.start}: {exc.reason}); a model file must be UTF-8 "
                             f"encoded JSON (docs/model_schema.md): re-save it as UTF-8") from None
    try:
        doc = json.loads(text)
    except json.JSONDecodeError as exc:
        raise ModelFileError(f"{path}: not valid JSON ({exc})") from None
    except RecursionError:
        raise ModelFileError(f"{path}: nested too deeply to be a model file") from None
    if not isinstance(doc, dict):
        raise ModelFileError(f"{path}: a model file is a JSON object, got {type(doc).__name__}")
    name = doc.get("name")
    if isinstance(name, str):
        if len(name) > MAX_NAME_LENGTH:
            fail(f"field 'name' is {len(name)} characters long, more than {MAX_NAME_LENGTH} ({name[:40]!r}...)")
        if not (name.isascii() and MODEL_NAME.fullmatch(name)):
            fail(f"field 'name' {name!r} must be ASCII letters, digits and '_', not starting with a digit (it "
                 f"becomes a file name and a C symbol)")

    def items(key):
        v = doc.get(key)
        return list(enumerate(v)) if isinstance(v, list) else []
    for key in ("dofs", "bodies", "muscles", "elements"):
        for i, item in items(key):
            n = item.get("name") if isinstance(item, dict) else None
            if isinstance(n, str) and len(n) > MAX_NAME_LENGTH:
                fail(f"field '{key}[{i}].name' is {len(n)} characters long, more than {MAX_NAME_LENGTH} ({n[:40]!r}...)")
    groups = doc.get("groups")
    if isinstance(groups, dict):
        for g in groups:
            if len(g) > MAX_NAME_LENGTH:
                fail(f"group name in 'groups' is {len(g)} characters long, more than {MAX_NAME_LENGTH} ({g[:40]!r}...)")

    def in_range(field: str, v, lo: float, hi: float, unit: str):
        if _number(v) and not (lo <= v <= hi):
            fail(f"field '{field}' = {v:g} {unit} is outside [{lo:g}, {hi:g}] {unit}, the physical range armrt "
                 f"accepts (armrt.model_build: a factor of 10 or more beyond any human arm)")

    def coordinates(field: str, v):
        if isinstance(v, list):
            for c in v:
                if _number(c) and abs(c) > SKELETON_COORDINATE_LIMIT:
                    fail(f"field '{field}' has a coordinate of {c:g} m, beyond +-{SKELETON_COORDINATE_LIMIT:g} m "
                         f"(an arm's segments are under 0.4 m)")
    for i, b in items("bodies"):
        if not isinstance(b, dict):
            continue
        in_range(f"bodies[{i}].mass", b.get("mass"), *BODY_MASS_RANGE, "kg")
        inertia = b.get("inertia")
        if (isinstance(inertia, list) and len(inertia) == 3 and all(isinstance(r, list) and len(r) == 3 and
                                                                      all(_number(x) for x in r) for r in inertia)):
            import numpy as np
            moments = np.linalg.eigvalsh(0.5 * (np.array(inertia, dtype=float) + np.array(inertia, dtype=float).T))
            lo, hi = INERTIA_RANGE
            if not np.all(np.isfinite(moments)) or moments.min() < lo or moments.max() > hi:
                fail(f"field 'bodies[{i}].inertia' has principal moments {', '.join(f'{m:.3g}' for m in moments)} "
                     f"kg m^2, outside [{lo:g}, {hi:g}] kg m^2, the physical range armrt accepts")
        coordinates(f"bodies[{i}].com", b.get("com"))
        joint = b.get("joint")
        if isinstance(joint, dict):
            coordinates(f"bodies[{i}].joint.location_in_parent", joint.get("location_in_parent"))
    hand = doc.get("hand_point")
    if isinstance(hand, dict):
        coordinates("hand_point.point", hand.get("point"))
    for i, e in items("elements"):
        if isinstance(e, dict):
            for k, ((lo, hi), unit) in ELEMENT_RANGES.items():
                in_range(f"elements[{i}].{k}", e.get(k), lo, hi, unit)
    return doc


def refuse_name_clash(path, name, source_hash: str) -> None:
    """ValueError, before anything is built, if a different model (another file hash) of the file's
    name is registered: names identify models in results, the real-time runner and the viewer."""
    from . import _core
    known = _core.find_model(name) if isinstance(name, str) else None
    if known is not None and known.source_hash != source_hash:
        raise ValueError(f"{path}: a different model named {name!r} is already registered (model file sha256 "
                         f"{known.source_hash[:12]}...): give this model file another 'name'")


def validate_file(path) -> tuple[dict, str]:
    """(model, SHA-256 of the file) after the generator's checks (codegen.schema.load_model:
    schema and sense checks). ModelFileError naming the file, the field, and the element (DOF, muscle,
    body) by name when the field is inside one; FileNotFoundError for a missing file."""
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(2, "no such model file", str(path))
    check_model_document(path, path.read_bytes())
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


def _name_the_item(path: Path, message: str, doc: dict | None = None) -> str:
    """'... field 'elements[3].fmax' ...' -> '... (element 'deltscap4')' when the file (or `doc`, the file
    already parsed) says so."""
    m = re.search(r"'(elements|dofs|muscles|bodies)\[(\d+)\]", message)
    if not m:
        return message
    try:
        item = (doc if doc is not None else json.loads(path.read_bytes()))[m.group(1)][int(m.group(2))]
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
    # Before the cache and the compiler: a file armrt refuses is refused in milliseconds, not after a build.
    doc = check_model_document(path, data)
    refuse_name_clash(path, doc.get("name"), source_hash)
    cfg = build_config()
    gen = generator()
    entry = cache_entry(source_hash, cfg, gen)
    library, meta_path, log_path = entry / LIBRARY_NAME, entry / "model.json", entry / "build.log"

    warned: list[str] = []

    def cached() -> BuildResult | None:
        if force or not library.is_file() or not meta_path.is_file():
            return None
        problem = library_problem(library)
        if problem:
            if not warned:  # once, though cached() is asked again under the lock
                warned.append(problem)
                import warnings
                warnings.warn(f"{problem}; rebuilding it", RuntimeWarning, stacklevel=3)
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
            # The checksum first: a crash before the library is in place leaves a mismatch (a rebuild),
            # never a library without its checksum.
            (entry / CHECKSUM_NAME).write_text(f"{_file_sha256(out)}  {LIBRARY_NAME}\n")
            os.replace(out, library)
            meta = {"name": model["name"], "model_file": str(path.resolve()), "source_hash": source_hash,
                    "built": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()), "compiler": compiler,
                    "flags": cfg["flags"], "dynamics_flags": cfg["dynamics_flags"],
                    "seconds": round(time.perf_counter() - t0, 2)}
            meta_path.write_text(json.dumps(meta, indent=1) + "\n")
            log.write(f"built in {time.perf_counter() - t0:.1f} s\n")
        shutil.rmtree(work, ignore_errors=True)
    return BuildResult(library, model["name"], source_hash, path, time.perf_counter() - t0, False, log_path)
