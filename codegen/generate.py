"""Model file (docs/model_schema.md) -> the C++ model sources (cpp/generated/): the generator's driver.

    python -m codegen.generate --model models/das2.json --out cpp/generated

Writes <name>.h (codegen/signatures.py), <name>_model.cc (parameter tables, ModelDef;
codegen/model_emitter.py), <name>_dynamics.cc (equations of motion, kinematics; codegen/dynamics_emitter.py)
and <name>_paths.cc (muscle path polynomials; codegen/paths_emitter.py), after the checks of
codegen/schema.py. Output depends only on the bytes of the model file, so regenerating from the same file
gives byte-identical sources.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from .dynamics_emitter import dynamics_source
from .model_emitter import model_source
from .paths_emitter import paths_source
# The schema's API, named from here by its users since the generator was one module (docs/models.md).
from .schema import MAX_ELEMENTS, ModelFileError, check_sense, load_model, validate
from .signatures import entry_source, header_source

__all__ = ["generate", "main", "load_model", "validate", "check_sense", "ModelFileError", "MAX_ELEMENTS"]


def _banner(model_file: str, digest: str, command: str | None = None) -> str:
    command = command or f"python -m codegen.generate --model models/{model_file} --out cpp/generated"
    return (f"// GENERATED FILE - DO NOT EDIT BY HAND.\n"
            f"// Written by `{command}`\n"
            f"// from the model file {model_file} (sha256 {digest}).\n"
            f"// Change the model file or the generator and regenerate instead.\n")


def generate(model_path, out_dir, verbose=False, command: str | None = None, entry_point=False) -> dict:
    """Write the generated sources for the model file into out_dir; returns {file name: bytes written}.
    command: the command line the banner names (default: the das2 one, models/NAME -> cpp/generated).
    entry_point: also write <name>_entry.cc, the entry point of a model library built on demand."""
    t0 = time.perf_counter()
    model, digest = load_model(model_path)
    ns = model["name"]
    banner = _banner(Path(model_path).name, digest, command)
    dyn, stats = dynamics_source(model, ns)
    files = {
        f"{ns}.h": banner + header_source(ns),
        f"{ns}_model.cc": banner + "\n" + model_source(model, ns, digest),
        f"{ns}_dynamics.cc": banner + "\n" + dyn,
        f"{ns}_paths.cc": banner + "\n" + paths_source(model, ns),
    }
    if entry_point:
        files[f"{ns}_entry.cc"] = banner + "\n" + entry_source(ns)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    written = {}
    for fname, text in files.items():
        data = text.encode("utf-8")
        path = out / fname
        # Leave an identical file untouched so that build systems do not recompile it.
        if not path.exists() or path.read_bytes() != data:
            path.write_bytes(data)
        written[fname] = len(data)
    if verbose:
        print(f"generated {', '.join(f'{k} ({v} bytes)' for k, v in written.items())} in {out} "
              f"in {time.perf_counter() - t0:.1f} s; CSE temporaries: {stats}")
    return written


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--model", required=True, help="model file, e.g. models/das2.json")
    ap.add_argument("--out", required=True, help="output directory, e.g. cpp/generated")
    ap.add_argument("--entry-point", action="store_true",
                    help="also write <name>_entry.cc, the extern \"C\" entry point of a model library "
                         "built on demand (armrt model build)")
    args = ap.parse_args(argv)
    try:
        # The banner names the standard command for the project's models (whatever paths were typed, so
        # regeneration stays byte-identical), and the command as typed for any other model file or an
        # on-demand build (--entry-point).
        root = Path(__file__).resolve().parents[1]
        in_models = Path(args.model).resolve().parent == root / "models"
        command = f"python -m codegen.generate --model {args.model} --out {args.out}"
        if in_models and not args.entry_point:
            # cpp/generated or cpp/tests/generated, named from the root whatever the working directory;
            # elsewhere (a scratch directory) the standard cpp/generated one.
            out = Path(args.out).resolve()
            command = (f"python -m codegen.generate --model models/{Path(args.model).name} --out {out.relative_to(root)}"
                       if out.is_relative_to(root) else None)
        elif args.entry_point:
            command += " --entry-point"
        generate(args.model, args.out, verbose=True, command=command, entry_point=args.entry_point)
    except ModelFileError as exc:
        print(f"codegen.generate: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
