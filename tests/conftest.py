import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
REFERENCE = (ROOT / ".." / "shared" / "reference").resolve()
DAS3 = REFERENCE / "das3"
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))


@pytest.fixture(scope="session")
def das3_dir():
    if not (DAS3 / "model_struct.mat").exists():
        pytest.skip(f"DAS3 reference data not found at {DAS3} (needs ../shared beside the repository)")
    return DAS3


@pytest.fixture
def arm():
    armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
    return armrt.Arm(model="das2", integrator="rk4", dt=1e-3)
