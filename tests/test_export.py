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


# ------------------------------------------------------------------ stimulation .sto (issue 27)
@pytest.fixture(scope="module")
def stim_result():
    arm = armrt.Arm(model="das2", stimulation="per_muscle")
    arm.set_stimulation({"bicl": (200e-6, 0.012, 30.0), "triclat": (150e-6, 0.020, 50.0)})
    return arm.simulate(np.zeros(arm.n_elements), 0.5, record_every=10)


def _printed(a):
    """The values as the file prints them (10 significant digits)."""
    return np.vectorize(lambda v: float(f"{v:.10g}"))(np.asarray(a, dtype=float))


def test_stimulation_sto_round_trip(stim_result, tmp_path):
    r = stim_result
    path = opensim_io.write_stimulation_sto(r, tmp_path / "stim.sto")
    header, labels, data = opensim_io.read_storage(path)
    names = r.channel_names
    assert names == armrt.Arm(model="das2", stimulation="per_muscle").channel_names
    assert labels[:6] == ["time", f"{names[0]}/pulse_width", f"{names[0]}/amplitude", f"{names[0]}/frequency",
                          f"{names[0]}/recruitment", f"{names[0]}/fatigue"]
    assert len(labels) == 1 + 5 * len(names) and int(header["nColumns"]) == len(labels)
    text = path.read_text()
    assert "units: pulse_width s, amplitude A, frequency Hz" in text.split("endheader")[0]
    col = {n: k for k, n in enumerate(labels)}
    assert np.array_equal(data[:, 0], _printed(r.time))
    for k, n in enumerate(names):
        assert np.array_equal(data[:, [col[f"{n}/{v}"] for v in ("pulse_width", "amplitude", "frequency")]],
                              _printed(r.stimulation[:, k]))
        assert np.array_equal(data[:, col[f"{n}/recruitment"]], _printed(r.recruitment[:, k]))
        assert np.array_equal(data[:, col[f"{n}/fatigue"]], _printed(r.fatigue[:, k]))
    # Not a table of zeros: the two stimulated channels recruit and fatigue.
    assert data[1, col["bicl/amplitude"]] == 0.012 and data[1, col["triclat/frequency"]] == 50.0
    assert data[-1, col["bicl/recruitment"]] > 0 and data[-1, col["bicl/fatigue"]] > 0
    assert np.all(data[:, col["deltscap/recruitment"]] == 0)


def test_stimulation_sto_kept_through_save_and_bad_input(stim_result, result, tmp_path):
    stim_result.save(tmp_path / "r.npz")
    back = armrt.Result.load(tmp_path / "r.npz")
    assert back.channel_names == stim_result.channel_names
    a = opensim_io.write_stimulation_sto(back, tmp_path / "a.sto").read_text().splitlines()
    b = opensim_io.write_stimulation_sto(stim_result, tmp_path / "b.sto").read_text().splitlines()
    assert a[1:] == b[1:]       # the first line is the file's name
    with pytest.raises(ValueError, match="the result has no stimulation"):
        opensim_io.write_stimulation_sto(result, tmp_path / "none.sto")
    with pytest.raises(ValueError, match="the result has no stimulation"):
        opensim_io.export(result, stimulation_path=tmp_path / "none.sto")
    assert not (tmp_path / "none.sto").exists()
    unnamed = armrt.Result.load(tmp_path / "r.npz")
    unnamed.channel_names = []          # a result saved before results kept the names
    with pytest.raises(ValueError, match="does not name its stimulation channels"):
        opensim_io.write_stimulation_sto(unnamed, tmp_path / "c.sto")
    names = list(stim_result.channel_names)
    opensim_io.write_stimulation_sto(unnamed, tmp_path / "c.sto", channel_names=names)
    with pytest.raises(ValueError, match="3 channel names for 22"):
        opensim_io.write_stimulation_sto(unnamed, tmp_path / "d.sto", channel_names=names[:3])
    with pytest.raises(ValueError, match="whitespace"):
        opensim_io.write_stimulation_sto(unnamed, tmp_path / "d.sto", channel_names=["bi cl"] + names[1:])
    with pytest.raises(ValueError, match="repeated channel names: \\['bicl'\\]"):
        opensim_io.write_stimulation_sto(unnamed, tmp_path / "d.sto", channel_names=["bicl"] + names[1:])


def test_export_command_writes_the_stimulation(stim_result, result, tmp_path, capsys):
    from armrt.cli import main
    stim_result.save(tmp_path / "s.npz")
    assert main(["export", str(tmp_path / "s.npz"), "--stimulation", str(tmp_path / "s.sto")]) == 0
    assert opensim_io.read_storage(tmp_path / "s.sto")[1][1] == "deltscap/pulse_width"
    result.save(tmp_path / "e.npz")
    capsys.readouterr()
    rc = main(["export", str(tmp_path / "e.npz"), "--mot", str(tmp_path / "e.mot"), "--stimulation",
               str(tmp_path / "e.sto")])
    err = capsys.readouterr().err
    assert rc == 2 and "has no stimulation" in err and "Traceback" not in err
    assert not (tmp_path / "e.mot").exists()     # refused before anything is written


@pytest.mark.opensim
def test_stimulation_sto_reads_in_opensim(stim_result, tmp_path):
    opensim = pytest.importorskip("opensim", reason="the opensim package is not installed")
    path = str(opensim_io.write_stimulation_sto(stim_result, tmp_path / "stim.sto"))
    _, labels, data = opensim_io.read_storage(path)
    storage = opensim.Storage(path)
    got = [storage.getColumnLabels().get(i) for i in range(storage.getColumnLabels().getSize())]
    assert got == labels and storage.getSize() == len(stim_result.time)
    table = opensim.TimeSeriesTable(path)
    assert list(table.getColumnLabels()) == labels[1:]
    assert table.getNumRows() == len(stim_result.time)
    k = labels.index("bicl/amplitude") - 1
    column = table.getDependentColumnAtIndex(k)
    assert [column[i] for i in range(table.getNumRows())] == list(data[:, k + 1])
    assert list(table.getIndependentColumn()) == list(data[:, 0])
