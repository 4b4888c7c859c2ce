"""Where this armrt runs from -> the code generator and model importers it goes with: the checkout's
codegen/ when armrt runs from a source checkout (python/armrt beside codegen/), else the copy
installed with the package (armrt.codegen, CMakeLists.txt's install rule), which matches this engine.

The one locator for `armrt model build`/`armrt.Model.load` (model_build.py) and `armrt model import`
(model_cli.py). Imports nothing from armrt, so any module may use it.
"""
from __future__ import annotations

import importlib
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
# Checkout layout: <repo>/python/armrt/codegen_locator.py and <repo>/codegen/generate.py.
REPO = HERE.parents[1]


class CodegenNotFoundError(FileNotFoundError):
    """Neither a checkout's codegen/ nor an installed armrt/codegen is beside this armrt."""


def running_from_checkout() -> bool:
    return HERE == REPO / "python" / "armrt" and (REPO / "codegen" / "generate.py").is_file()


def codegen_package() -> tuple[str, Path]:
    """(the generator's package name, the sys.path entry that imports it by that name)."""
    if running_from_checkout():
        return "codegen", REPO
    if (HERE / "codegen" / "generate.py").is_file():
        return "armrt.codegen", HERE.parent
    raise CodegenNotFoundError(f"the code generator and model importers are neither installed with armrt "
                               f"({HERE / 'codegen'}) nor in a source checkout ({REPO / 'codegen'}): "
                               f"reinstall armrt (pip install .)")


def codegen_module_name(module: str) -> tuple[str, Path]:
    """('<package>.<module>', sys.path entry) for `python -m`, e.g. module 'generate'."""
    package, root = codegen_package()
    return f"{package}.{module}", root


def import_codegen(module: str):
    """Import <package>.<module> (e.g. 'generate', 'importers.import_das3') from where codegen_package()
    says, putting its sys.path entry first if it is missing."""
    name, root = codegen_module_name(module)
    if str(root) not in sys.path:
        sys.path.insert(0, str(root))
    mod = importlib.import_module(name)
    if not Path(mod.__file__).resolve().is_relative_to(root):
        # Another `codegen` earlier on sys.path (a second checkout as the working directory, say).
        raise CodegenNotFoundError(f"{name} was imported from {mod.__file__}, not from {root}: remove the other "
                                   f"'codegen' from the Python path")
    return mod
