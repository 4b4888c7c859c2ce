"""`armrt model import`: a DAS-format model_struct*.mat -> an armrt model file (codegen.import_das3).

The importer and the code generator live in the source checkout (`codegen/`, not in the wheel): the
command finds them on the path, in $ARMRT_SOURCE_DIR, in the current directory or beside the package.
"""
from __future__ import annotations

import os
import sys
from pathlib import Path


def codegen_module(name: str):
    """Import codegen.<name>, adding the source checkout to sys.path if needed."""
    import importlib
    try:
        return importlib.import_module(f"codegen.{name}")
    except ImportError:
        pass
    candidates = [os.environ.get("ARMRT_SOURCE_DIR"), os.getcwd(), str(Path(__file__).resolve().parents[2])]
    for c in candidates:
        if c and (Path(c) / "codegen" / "import_das3.py").exists():
            sys.path.insert(0, c)
            return importlib.import_module(f"codegen.{name}")
    raise FileNotFoundError("the model importer (codegen/) is part of the armrt source checkout, not of the "
                            "installed package: run this from the repository or set ARMRT_SOURCE_DIR to it")


def cmd_model_import(args) -> int:
    imp = codegen_module("import_das3")
    argv = [str(args.mat), "--free", args.free, "-o", str(args.out)]
    for p in args.posture:
        argv += ["--posture", p]
    for p in args.posture_deg:
        argv += ["--posture-deg", p]
    if args.equilibrium:
        argv += ["--equilibrium", str(args.equilibrium)]
    if args.name:
        argv += ["--name", args.name]
    if args.paths:
        argv += ["--paths", args.paths]
    return imp.main(argv, prog="armrt model import")


def add_cli(sub, formatter, msub=None) -> None:
    """Adds `armrt model import` to msub, the `armrt model` actions (cli.py also puts build and list
    there); without msub, creates `armrt model` in sub."""
    if msub is None:
        p = sub.add_parser("model", help="model files: import a DAS-format .mat", formatter_class=formatter)
        msub = p.add_subparsers(dest="model_command", required=True, metavar="MODEL_COMMAND",
                                help="import: a DAS-format .mat to a model file")
    q = msub.add_parser("import", formatter_class=formatter,
                        help="DAS-format model_struct*.mat -> model file with chosen free DOFs (docs/model_schema.md)")
    q.add_argument("mat", type=Path, help="DAS-format model_struct*.mat")
    q.add_argument("--free", required=True, help="comma-separated free DOFs, e.g. ELx,PSy (das2: GHy,GHz,GHyy,ELx,PSy; "
                        "das3: SCy,SCz,SCx,ACy,ACz,ACx,GHy,GHz,GHyy,ELx,PSy)")
    q.add_argument("--posture", action="append", default=[], metavar="NAME=RAD[,...]",
                   help="fixed DOF angles in rad (default: equilibrium.mat where it names every DOF, else the arm "
                        "hanging at the side)")
    q.add_argument("--posture-deg", action="append", default=[], metavar="NAME=DEG[,...]", help="the same in degrees")
    q.add_argument("--equilibrium", type=Path, default=None, help="equilibrium.mat for the default posture")
    q.add_argument("--name", default=None, help="model name (C identifier)")
    q.add_argument("--paths", choices=["opensim", "das3"], default=None, help="das2 only: how paths are made")
    q.add_argument("-o", "--out", type=Path, required=True, help="model file to write (.json)")
    q.set_defaults(func=cmd_model_import)
