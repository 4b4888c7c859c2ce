"""Issue 11, item 3: paralysis and weakness hold at every entry point, the logged excitation is what
the dynamics used, and OpenSim files go both ways (controls .sto out, .mot in)."""
import warnings

import numpy as np
import pytest

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
from armrt import opensim_io  # noqa: E402
from armrt.geometry import find_model_file  # noqa: E402

needs_model_file = pytest.mark.skipif(find_model_file("das2") is None, reason="models/das2.json not found")


def test_logged_excitation_is_what_the_dynamics_used(arm):
    """The issue's example: max_activation={"bicb": 0.3} logged 1.0 while activation sat at 0.3."""
    arm.max_activation = {"bicb": 0.3}
    ib = arm.indices("bicb")
    for excitation in ({"bicb": 1.0}, np.ones(102), lambda t: {"bicb": 1.0}, np.ones((500, 102))):
        arm.reset()
        res = arm.simulate(excitation, 0.5)
        assert np.all(res.excitation[:, ib] == 0.3)
        assert res.activation[-1, ib].max() == pytest.approx(0.3, abs=1e-4)
        assert res.activation[:, ib].max() <= 0.3 + 1e-12
        others = np.setdiff1d(np.arange(102), ib)
        if isinstance(excitation, np.ndarray):
            assert np.all(res.excitation[:, others] == 1.0)
    arm.set_excitation(1.0)
    assert np.all(arm.excitation[ib] == 0.3) and arm.excitation[0] == 1.0


def test_lowering_max_activation_caps_the_held_excitation(arm):
    arm.set_excitation({"triceps": 0.8})
    arm.max_activation = {"triceps": 0.0}
    assert np.all(arm.excitation[arm.indices("triceps")] == 0.0)
    res = arm.simulate(arm.excitation, 0.05)
    assert np.all(res.excitation[:, arm.indices("triceps")] == 0.0)


def test_reset_activation_is_capped(arm):
    arm.max_activation = {"brachialis": 0.0, "bicb": 0.25}
    with pytest.warns(RuntimeWarning, match="above max_activation capped"):
        arm.reset(activation={"brachialis": 0.6, "bicb": 0.6, "triceps": 0.6})
    assert np.all(arm.activation[arm.indices("brachialis")] == 0.0)
    assert np.all(arm.activation[arm.indices("bicb")] == 0.25)
    assert np.all(arm.activation[arm.indices("triceps")] == 0.6)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        arm.reset(activation={"bicb": 0.2})      # within the bound: no warning


@needs_model_file
def test_controls_sto_holds_the_used_excitation(arm, tmp_path):
    arm.max_activation = {"bicb": 0.3}
    res = arm.simulate({"bicb": 1.0, "triceps": 0.4}, 0.05, record_every=10)
    path = opensim_io.write_excitation_sto(res, tmp_path / "controls.sto")
    _, labels, data = opensim_io.read_storage(path)
    assert labels[:2] == ["time", "delt_scap_1"]
    desc = opensim_io.model_description("das2")
    osim = {e["name"]: e["osim_name"] for e in desc["elements"]}
    k = labels.index(osim[arm.element_names[arm.indices("bicb")[0]]])
    assert np.all(data[:, k] == 0.3)
    np.testing.assert_allclose(data[:, 1:], res.excitation, atol=1e-10)


@needs_model_file
@pytest.mark.parametrize("in_degrees", [False, True])
def test_mot_round_trip_sets_the_start_posture(arm, tmp_path, in_degrees):
    arm.reset(q=[0.3, 0.5, 0.2, 1.2, 1.0])
    res = arm.simulate({"elbow_flexors": 0.3}, 0.2, record_every=20)
    path = opensim_io.write_mot(res, tmp_path / "run.mot")
    if in_degrees:   # the same motion as OpenSim GUI writes it: degrees, flagged in the header
        header, labels, data = opensim_io.read_storage(path)
        data[:, 1:] = np.degrees(data[:, 1:])
        opensim_io._write_storage(path, "run", labels[1:], data[:, 0], data[:, 1:], in_degrees=True)
    motion = opensim_io.read_motion(path)
    np.testing.assert_allclose(motion.q, res.q, atol=1e-8)
    np.testing.assert_allclose(motion.time, res.time, atol=1e-9)
    fresh = armrt.Arm()
    fresh.reset(q=motion.posture())
    np.testing.assert_allclose(fresh.q, [0.3, 0.5, 0.2, 1.2, 1.0], atol=1e-8)
    mid = motion.posture(0.1)
    np.testing.assert_allclose(mid, res.q[np.searchsorted(res.time, 0.1 - 1e-9)], atol=1e-8)


def test_mot_with_armrt_names_and_errors(tmp_path):
    p = tmp_path / "m.mot"
    p.write_text("m\nversion=1\nnRows=2\nnColumns=6\ninDegrees=yes\nendheader\n"
                 "time GHy GHz GHyy ELx PSy\n0 10 20 30 90 45\n0.5 10 20 30 80 45\n")
    m = opensim_io.read_motion(p)
    np.testing.assert_allclose(m.q[0], np.radians([10, 20, 30, 90, 45]))
    p.write_text("m\ninDegrees=no\nendheader\ntime\tGH_y\tEL_x\n0\t0.1\t0.2\n")
    with pytest.raises(ValueError, match=r"no column for coordinates \['GH_z', 'GH_yy', 'PS_y'\]"):
        opensim_io.read_motion(p)
    p.write_text("m\ninDegrees=no\nendheader\ntime GH_y GH_z GH_yy EL_x PS_y\n0 0.1 0.2 x 1 1\n")
    with pytest.raises(ValueError, match="not a number"):
        opensim_io.read_motion(p)


@pytest.mark.parametrize("in_degrees", [False, True])
def test_mot_whose_values_contradict_its_inDegrees_header_is_refused(tmp_path, in_degrees):
    # das2's rest posture written in the unit the header does not say: read as the header says, GH_z is outside
    # its range (0.5 rad read as degrees is below 14 deg); read in the other unit every angle fits. Before, the
    # radian file marked inDegrees=yes was read as angles 1/57 of the intended, without a word.
    rest = np.array([d["rest"] for d in armrt._core.model_info("das2")["dofs"]])
    values = rest if in_degrees else np.degrees(rest)
    p = tmp_path / "m.mot"
    p.write_text(f"m\ninDegrees={'yes' if in_degrees else 'no'}\nendheader\ntime GH_y GH_z GH_yy EL_x PS_y\n"
                 + "".join(f"{t} " + " ".join(f"{v:.8f}" for v in values) + "\n" for t in (0, 0.5)))
    said, meant = ("yes", "radians") if in_degrees else ("no", "degrees")
    with pytest.raises(ValueError, match=f"inDegrees={said}, but the angles look like {meant}"):
        opensim_io.read_motion(p)
    # The header corrected, the same values read as the posture.
    p.write_text(p.read_text().replace(f"inDegrees={said}", f"inDegrees={'no' if in_degrees else 'yes'}"))
    np.testing.assert_allclose(opensim_io.read_motion(p).q[0], rest, atol=1e-8)
    # One sample of the mislabelled file outside its range in the right unit too (GH_z 0.05 rad below its 0.25):
    # the rule counts, so it still fires (a second trial's: 'every value fits' let the whole file through).
    low = rest.copy()
    low[1] = 0.2
    rows = [rest, low, rest]
    values = [r if in_degrees else np.degrees(r) for r in rows]
    p.write_text(f"m\ninDegrees={said}\nendheader\ntime GH_y GH_z GH_yy EL_x PS_y\n"
                 + "".join(f"{t} " + " ".join(f"{v:.8f}" for v in r) + "\n" for t, r in zip((0, 0.5, 1), values)))
    with pytest.raises(ValueError, match=f"inDegrees={said}, but the angles look like {meant}"):
        opensim_io.read_motion(p)


def test_mot_slightly_beyond_a_range_is_read_and_a_bad_header_or_second_time_column_refused(tmp_path):
    """A correct radian file with one sample 0.05 rad below GH_z's range is read (its values are what the file
    means; the consumers warn or refuse by their own rules); inDegrees must be yes or no ('true' was read as
    no); two time columns are ambiguous (the last was taken)."""
    rest = np.array([d["rest"] for d in armrt._core.model_info("das2")["dofs"]])
    low = rest.copy()
    low[1] = 0.2
    p = tmp_path / "m.mot"
    body = "".join(f"{t} " + " ".join(f"{v:.8f}" for v in r) + "\n" for t, r in zip((0, 0.5, 1), [rest, low, rest]))
    p.write_text("m\ninDegrees=no\nendheader\ntime GH_y GH_z GH_yy EL_x PS_y\n" + body)
    np.testing.assert_allclose(opensim_io.read_motion(p).q[1], low, atol=1e-8)
    p.write_text("m\ninDegrees=true\nendheader\ntime GH_y GH_z GH_yy EL_x PS_y\n" + body)
    with pytest.raises(ValueError, match="inDegrees must be yes or no, got 'true'"):
        opensim_io.read_motion(p)
    p.write_text("m\ninDegrees=no\nendheader\ntime GH_y GH_z GH_yy EL_x PS_y time\n"
                 + "".join(f"{t} " + " ".join(f"{v:.8f}" for v in rest) + f" {t}\n" for t in (0, 0.5)))
    with pytest.raises(ValueError, match="2 'time' columns; keep one"):
        opensim_io.read_motion(p)


@pytest.mark.parametrize("second", ["ELx", "EL_x"])
def test_mot_with_two_columns_for_one_coordinate_is_refused(tmp_path, second):
    # OpenSim's and armrt's name of one coordinate (EL_x and ELx), or one name twice: which to take is the
    # user's call. Before, EL_x was used and the other column dropped silently.
    p = tmp_path / "m.mot"
    p.write_text(f"m\ninDegrees=no\nendheader\ntime GH_y GH_z GH_yy EL_x PS_y {second}\n"
                 "0 0.43 0.5 0.27 0.66 1.42 2.0\n")
    with pytest.raises(ValueError, match=r"coordinate EL_x has 2 columns \(EL_x, " + ("ELx" if second == "ELx" else "EL_x")):
        opensim_io.read_motion(p)


@needs_model_file
def test_motion_replays_as_a_kinematic_result(arm, tmp_path):
    res = arm.simulate({"elbow_flexors": 0.3}, 0.1, record_every=10)
    motion = opensim_io.read_motion(opensim_io.write_mot(res, tmp_path / "run.mot"))
    replay = motion.to_result()
    np.testing.assert_allclose(replay.q, res.q, atol=1e-8)
    np.testing.assert_allclose(replay.thorax_humerus, res.thorax_humerus, atol=1e-7)
    assert np.all(np.isnan(replay.gh_stab)) and np.all(np.isnan(replay.activation))


def _rest_rows(labels_extra="", values_extra="", times=(0, 0.5)):
    rest = np.array([d["rest"] for d in armrt._core.model_info("das2")["dofs"]])
    body = "".join(f"{t} " + " ".join(f"{v:.8f}" for v in rest) + (f" {values_extra}" if values_extra else "") + "\n"
                   for t in times)
    return rest, "time GH_y GH_z GH_yy EL_x PS_y" + (f" {labels_extra}" if labels_extra else "") + "\n" + body


def test_mot_column_that_is_no_coordinate_is_named_and_a_misspelt_one_hinted(tmp_path):
    # A typo beside the right column (EL_X_typo beside EL_x) was dropped without a word; now a RuntimeWarning
    # names it and the coordinate it resembles. Without the right column the missing-column error points at it.
    rest, table = _rest_rows("EL_X_typo", "9.0")
    p = tmp_path / "m.mot"
    p.write_text("m\ninDegrees=no\nendheader\n" + table)
    with pytest.warns(RuntimeWarning, match=r"columns EL_X_typo \(like EL_x\) are not coordinates of das2; ignored"):
        m = opensim_io.read_motion(p)
    np.testing.assert_allclose(m.q[0], rest, atol=1e-8)
    p.write_text("m\ninDegrees=no\nendheader\n" + table.replace(" EL_x ", " ELbow_x ", 1))
    with pytest.raises(ValueError, match=r"no column for coordinates \['EL_x'\].*perhaps misspelt: EL_x \(a column "
                                         r"'ELbow_x'\?\)"):
        opensim_io.read_motion(p)


def test_mot_of_das3_and_opensim_states_paths_read_without_warnings(tmp_path):
    # The DAS3 girdle's columns are known (das2 fixes them); an OpenSim 4 states file names coordinates by path
    # (/jointset/<joint>/<coordinate>/value) and also holds speeds and muscle states, which are ignored.
    import warnings
    rest = np.array([d["rest"] for d in armrt._core.model_info("das2")["dofs"]])
    names = ["GH_y", "GH_z", "GH_yy", "EL_x", "PS_y"]
    labels = ["time"] + [f"/jointset/j{k}/{n}/value" for k, n in enumerate(names)] + \
        [f"/jointset/j{k}/{n}/speed" for k, n in enumerate(names)] + ["/forceset/bic_l/activation"]
    p = tmp_path / "states.sto"
    p.write_text("states\nversion=1\nnRows=2\nnColumns=12\ninDegrees=no\nendheader\n" + "\t".join(labels) + "\n"
                 + "".join("\t".join(map(str, [t, *rest, *np.zeros(5), 0.1])) + "\n" for t in (0, 0.01)))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        m = opensim_io.read_motion(p)
    np.testing.assert_allclose(m.q[1], rest, atol=1e-12)
    # A path and a plain name for one coordinate are two columns for it.
    p.write_text(p.read_text().replace("/forceset/bic_l/activation", "EL_x"))
    with pytest.raises(ValueError, match=r"coordinate EL_x has 2 columns \(/jointset/j3/EL_x/value, EL_x\)"):
        opensim_io.read_motion(p)


@pytest.mark.parametrize("header, message", [
    ("nRows=3", r"the header says nRows=3 but the file has 2 rows: cut short"),
    ("nColumns=5", r"the header says nColumns=5 but the file has 6 columns \(time included\)"),
    ("nRows=two", r"the header's nRows must be an integer, got 'two'"),
])
def test_storage_whose_header_contradicts_its_table_is_refused(tmp_path, header, message):
    # A file cut short (nRows says more than there are) was read as the shorter motion without a word.
    _, table = _rest_rows()
    p = tmp_path / "m.mot"
    p.write_text(f"m\n{header}\ninDegrees=no\nendheader\n" + table)
    with pytest.raises(ValueError, match=message):
        opensim_io.read_motion(p)
    p.write_text("m\nnRows=2\nnColumns=6\ninDegrees=no\nendheader\n" + table)
    assert opensim_io.read_motion(p).q.shape == (2, 5)


def test_opensim3_states_columns_are_known_and_messages_name_the_columns_not_read(tmp_path):
    """A fifth trial: an OpenSim 3 states file (bare names, <coordinate>_u speeds, <muscle>.activation) gave a
    3620-character warning hinting GH_y_u as a misspelling of GH_y; a states path without its leading slash got no
    hint; a missing coordinate's error listed the first 12 columns (speeds), not the ones not read; a blank line
    before the labels gave '12 values, expected 0'."""
    import warnings
    rest = np.array([d["rest"] for d in armrt._core.model_info("das2")["dofs"]])
    names = ["GH_y", "GH_z", "GH_yy", "EL_x", "PS_y"]
    labels = ["time", *names, *[f"{n}_u" for n in names], *[f"m{i}.activation" for i in range(40)]]
    row = lambda t: "\t".join(map(str, [t, *rest, *np.zeros(5), *np.full(40, 0.1)]))  # noqa: E731
    p = tmp_path / "states3.sto"
    p.write_text("states\ninDegrees=no\nendheader\n\n" + "\t".join(labels) + "\n" + row(0) + "\n" + row(0.01) + "\n")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        np.testing.assert_allclose(opensim_io.read_motion(p).q[1], rest, atol=1e-12)
    p.write_text(p.read_text().replace("\tEL_x\t", "\tjointset/hu/EL_x/value\t", 1))
    np.testing.assert_allclose(opensim_io.read_motion(p).q[0], rest, atol=1e-12)
    p.write_text(p.read_text().replace("jointset/hu/EL_x/value", "jointset/hu/EL_X/value", 1))
    with pytest.raises(ValueError, match=r"columns not read: \['jointset/hu/EL_X/value'\]\); perhaps misspelt: EL_x "
                                         r"\(a column 'jointset/hu/EL_X/value'\?\)"):
        opensim_io.read_motion(p)
    many = ["time", *names, *[f"extra{i}" for i in range(20)]]
    p.write_text("m\ninDegrees=no\nendheader\n" + " ".join(many) + "\n"
                 + " ".join(map(str, [0, *rest, *np.zeros(20)])) + "\n")
    with pytest.warns(RuntimeWarning, match=r"columns extra0, .*, extra7 and 12 more are not coordinates"):
        opensim_io.read_motion(p)
