"""OpenSim export: .mot joint angles and .sto activations (issue 7, part 3)."""
import numpy as np
import pytest

from conftest import DAS3

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
from armrt import opensim_io  # noqa: E402
from armrt.geometry import find_model_file  # noqa: E402

OSIM_COORDS = ["SC_y", "SC_z", "SC_x", "AC_y", "AC_z", "AC_x", "GH_y", "GH_z", "GH_yy", "EL_x", "PS_y"]


@pytest.fixture(scope="module")
def result():
    if find_model_file("das2") is None:
        pytest.skip("models/das2.json not found (girdle angles and OpenSim names come from it)")
    arm = armrt.Arm(model="das2", integrator="rk4", dt=1e-3)
    arm.reset()
    return arm.simulate(lambda t: {"elbow_flexors": 0.4, "rotator_cuff": 0.05, "deltscap": 0.2 if t > 0.1 else 0.0},
                        duration=0.3, record_every=10)


def test_mot_format(result, tmp_path):
    path = opensim_io.write_mot(result, tmp_path / "run.mot")
    text = path.read_text().splitlines()
    assert "inDegrees=no" in text
    k = text.index("endheader")
    assert text[k + 1].split("\t") == ["time"] + OSIM_COORDS
    header, labels, data = opensim_io.read_storage(path)
    assert int(header["nRows"]) == len(result.time) == data.shape[0]
    assert int(header["nColumns"]) == len(labels) == 12
    np.testing.assert_allclose(data[:, 0], result.time, atol=1e-9)
    np.testing.assert_allclose(data[:, 7:], result.q, atol=1e-8)
    desc = opensim_io.model_description("das2")
    girdle = [d["angle"] for d in desc["girdle"]["dofs"]]
    np.testing.assert_allclose(data[:, 1:7], np.tile(girdle, (len(result.time), 1)), atol=1e-9)


def test_sto_format(result, tmp_path):
    path = opensim_io.write_activation_sto(result, tmp_path / "act.sto")
    header, labels, data = opensim_io.read_storage(path)
    assert labels[0] == "time" and len(labels) == 1 + len(result.element_names)
    assert labels[1] == "delt_scap_1"          # OpenSim force names, not armrt names
    np.testing.assert_allclose(data[:, 1:], result.activation, atol=1e-9)
    path2 = opensim_io.write_activation_sto(result, tmp_path / "states.sto", state_paths=True)
    assert opensim_io.read_storage(path2)[1][1] == "/forceset/delt_scap_1/activation"


def test_rejects_bad_data(result, tmp_path):
    bad = armrt.Result(**{k: getattr(result, k) for k in armrt.Result.ARRAYS}, dof_names=result.dof_names,
                       element_names=result.element_names, model="das2")
    bad.q = bad.q.copy()
    bad.q[1, 2] = np.nan
    with pytest.raises(ValueError, match="NaN"):
        opensim_io.write_mot(bad, tmp_path / "bad.mot")


@pytest.mark.opensim
def test_mot_round_trip_in_opensim(result, tmp_path):
    opensim = pytest.importorskip("opensim", reason="the opensim package is not installed")
    osim = DAS3 / "das3.osim"
    if not osim.exists():
        pytest.skip(f"{osim} not found (needs ../shared beside the repository)")
    mot = opensim_io.write_mot(result, tmp_path / "run.mot")
    sto = opensim_io.write_activation_sto(result, tmp_path / "act.sto")

    storage = opensim.Storage(str(mot))
    labels = [storage.getColumnLabels().get(i) for i in range(storage.getColumnLabels().getSize())]
    assert labels == ["time"] + OSIM_COORDS
    assert not storage.isInDegrees()
    assert storage.getSize() == len(result.time)

    model = opensim.Model(str(osim))
    state = model.initSystem()
    coords = model.getCoordinateSet()
    assert sorted(coords.get(i).getName() for i in range(coords.getSize())) == sorted(OSIM_COORDS)
    for row in (0, storage.getSize() // 2, storage.getSize() - 1):
        sv = storage.getStateVector(row)
        values = sv.getData()
        t = sv.getTime()
        assert t == pytest.approx(result.time[row], abs=1e-9)
        for j, name in enumerate(OSIM_COORDS):
            v = values.get(j)
            expected = (opensim_io.model_description("das2")["girdle"]["dofs"][j]["angle"] if j < 6
                        else result.q[row, j - 6])
            assert v == pytest.approx(expected, abs=1e-8)
            coords.get(name).setValue(state, v, False)
        model.realizePosition(state)
        for j, name in enumerate(OSIM_COORDS):
            assert coords.get(name).getValue(state) == pytest.approx(values.get(j), abs=1e-9)
        # The hand lands where armrt puts it (thorax = OpenSim ground), within the path-fit tolerance of
        # the kinematics (same joint definitions, so closely).
        hand = model.getBodySet().get("hand_r")
        com = hand.getMassCenter()
        p = hand.findStationLocationInGround(state, com)
        assert np.allclose([p.get(0), p.get(1), p.get(2)], result.hand_position[row], atol=2e-3)

    act = opensim.Storage(str(sto))
    assert act.getColumnLabels().get(1) == "delt_scap_1"
    assert act.getSize() == len(result.time)
