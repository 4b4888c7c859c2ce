"""`armrt model import`: a DAS-format model_struct*.mat -> an armrt model file (codegen.importers.import_das3).

The importers go with the generator: the checkout's codegen/ when armrt runs from a source checkout, else
armrt.codegen installed with the package (codegen_locator.py), so the command works in any folder.
"""
from __future__ import annotations

from pathlib import Path

try:
    from .codegen_locator import import_codegen
except ImportError:
    # Loaded as a lone file (tests/test_import_das3_girdle.py runs this file's command), not as armrt.model_cli:
    # the locator beside it, which then finds the checkout this file is in.
    import importlib.util as _util
    _spec = _util.spec_from_file_location("armrt_codegen_locator", Path(__file__).with_name("codegen_locator.py"))
    _locator = _util.module_from_spec(_spec)
    _spec.loader.exec_module(_locator)
    import_codegen = _locator.import_codegen


def codegen_module(name: str):
    """codegen.<name> (e.g. 'importers.import_das3') of the generator this armrt goes with."""
    return import_codegen(name)


def cmd_model_import(args) -> int:
    imp = codegen_module("importers.import_das3")
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
    return imp.main(argv, prog="armrt model import", raise_errors=True)


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
