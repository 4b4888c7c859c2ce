"""`armrt model import` from the installed package, run in a folder outside the checkout with no path to
it -> the same model file, byte for byte, as the checkout's importer writes for the same input.

Skipped when the armrt that Python imports is this checkout (PYTHONPATH=python, an editable install): then
there is no installed copy to test. `pip install .` first.
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import DAS3, REFERENCE, ROOT

PARTICIPANT_A = REFERENCE / "participant_A" / "model_struct_A.mat"
DAS3_FREE = "SCy,SCz,SCx,ACy,ACz,ACx,GHy,GHz,GHyy,ELx,PSy"


def _outside_env() -> dict:
    """The environment without ARMRT_SOURCE_DIR and without PYTHONPATH entries inside the checkout."""
    env = {k: v for k, v in os.environ.items() if k not in ("ARMRT_SOURCE_DIR", "PYTHONPATH")}
    keep = [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep)
            if p and not Path(p).resolve().is_relative_to(ROOT)]
    if keep:
        env["PYTHONPATH"] = os.pathsep.join(keep)
    return env


def _run(args, cwd: Path, timeout=900):
    return subprocess.run([sys.executable, *args], cwd=cwd, env=_outside_env(), capture_output=True, text=True,
                          timeout=timeout)


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """(armrt package dir, generator package) of the installed armrt, seen from a folder outside the checkout."""
    where = tmp_path_factory.mktemp("outside")
    r = _run(["-c", "import armrt; print(armrt.__file__)"], where)
    if r.returncode != 0:
        pytest.skip(f"armrt is not installed for {sys.executable} ({r.stderr.strip().splitlines()[-1:]})")
    pkg = Path(r.stdout.strip()).resolve().parent
    if pkg.is_relative_to(ROOT):
        pytest.skip(f"the armrt Python imports is this checkout ({pkg}), not an installed copy: pip install . first")
    if not (pkg / "codegen_locator.py").is_file():
        pytest.skip(f"the armrt installed at {pkg} predates this checkout (no codegen_locator.py): pip install . first")
    r = _run(["-c", "from armrt.codegen_locator import codegen_package; print(codegen_package()[0])"], where)
    assert r.returncode == 0, f"installed armrt at {pkg}: its codegen locator failed: {r.stderr}"
    return pkg, r.stdout.strip()


def test_the_installed_armrt_uses_its_own_generator(installed):
    pkg, generator = installed
    assert generator == "armrt.codegen"
    for f in ("generate.py", "schema.py", "signatures.py", "importers/import_das3.py", "importers/glenoid.py"):
        assert (pkg / "codegen" / f).is_file(), f"the install rule did not ship codegen/{f}"


def _checkout_import(argv, out: Path) -> bytes:
    from codegen.importers.import_das3 import main
    assert main([*argv, "-o", str(out)]) == 0
    return out.read_bytes()


@pytest.mark.parametrize("argv", [
    # The default posture's equilibrium.mat is found from MAT (reference/das3 beside reference/participant_A),
    # not from where the importer's code sits (the checkout's ../shared).
    pytest.param([str(PARTICIPANT_A), "--free", "ELx,PSy", "--name", "participant_A"], id="participant_A"),
    pytest.param([str(PARTICIPANT_A), "--free", "ELx,PSy", "--name", "participant_A",
                  "--equilibrium", str(DAS3 / "equilibrium.mat")], id="participant_A-equilibrium"),
    # das3 reads its fitted paths from the package's models/das3_paths.json.
    pytest.param([str(DAS3 / "model_struct.mat"), "--free", DAS3_FREE], id="das3"),
])
def test_model_import_from_an_installed_package_in_any_folder(installed, argv, tmp_path):
    if not Path(argv[0]).is_file():
        pytest.skip(f"reference data absent: {argv[0]}")
    where = tmp_path / "elsewhere"
    where.mkdir()
    r = _run(["-m", "armrt.cli", "model", "import", *argv, "-o", "model.json"], where)
    assert r.returncode == 0, f"armrt model import failed outside the checkout:\n{r.stdout}\n{r.stderr}"
    assert sorted(p.name for p in where.iterdir()) == ["model.json"]
    expected = _checkout_import(argv, tmp_path / "checkout.json")
    assert (where / "model.json").read_bytes() == expected
