"""Issue 11, item 7: the command line reports a person's mistakes in one line (no traceback), with
close matches for every unknown name at once; one unit convention; OpenSim names as aliases."""
import numpy as np
import pytest

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
from armrt.cli import build_parser, main  # noqa: E402


def run(capsys, *argv):
    rc = main(list(argv))
    out, err = capsys.readouterr()
    return rc, out, err


def one_line_error(err: str) -> str:
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert len(lines) == 1, err
    assert "Traceback" not in err
    return lines[0]


def test_unknown_names_all_at_once_with_close_matches(capsys):
    rc, out, err = run(capsys, "simulate", "bicbb=0.1", "tricepz=0.2", "deltscap=0.1", "--duration", "0.01")
    line = one_line_error(err)
    assert rc == 2 and out == ""
    assert line.startswith("armrt simulate: error: 2 unknown element, muscle or group names")
    assert "'bicbb' (did you mean 'bicb'" in line and "'tricepz' (did you mean 'triceps'" in line


def test_not_name_value(capsys):
    rc, _, err = run(capsys, "simulate", "bicb", "bicl=lots")
    line = one_line_error(err)
    assert rc == 2 and "'bicb' is not NAME=VALUE" in line and "'lots' is not a number" in line


@pytest.mark.parametrize("argv, message", [
    (["export", "missing.npz", "--mot", "x.mot"], "missing.npz: no such file"),
    (["animate", "missing.npz", "-o", "x.avi"], "unsupported format|gif or .mp4"),
    (["simulate", "-o", "run.txt"], "--out 'run.txt': unsupported format '.txt'; use .npz"),
    (["export", "r.npz", "--mot", "x.csv"], "--mot 'x.csv': unsupported format '.csv'"),
    (["export", "r.npz"], "give --mot FILE"),
    (["view", "--udp", "localhost:abc"], "bad port in 'localhost:abc'"),
    (["view", "--udp", "127.0.0.1:70000"], "bad port in '127.0.0.1:70000'"),
    (["view", "--udp", ":9870", "--key-file", "absent.key"], "absent.key"),
    (["info", "--model", "das9"], "unknown model 'das9'"),
])
def test_user_mistakes_are_one_line(capsys, tmp_path, monkeypatch, argv, message):
    monkeypatch.chdir(tmp_path)
    rc, _, err = run(capsys, *argv)
    assert rc == 2
    import re
    assert re.search(message, one_line_error(err)), err


def test_corrupt_and_crafted_results_are_one_line(capsys, tmp_path):
    bad = tmp_path / "bad.npz"
    bad.write_bytes(b"not a zip file at all")
    rc, _, err = run(capsys, "export", str(bad), "--mot", str(tmp_path / "x.mot"))
    assert rc == 2 and "not an armrt result" in one_line_error(err)
    other = tmp_path / "other.npz"
    np.savez(other, a=np.zeros(3))
    rc, _, err = run(capsys, "animate", str(other), "-o", str(tmp_path / "x.gif"))
    assert rc == 2 and "not an armrt result, missing arrays" in one_line_error(err)
    res = armrt.Arm().simulate(0.0, 0.01)
    res.model = "../../../../etc/passwd"
    res.save(tmp_path / "crafted.npz")
    rc, _, err = run(capsys, "export", str(tmp_path / "crafted.npz"), "--mot", str(tmp_path / "x.mot"))
    assert rc == 2 and "model field '../../../../etc/passwd' is not a known model" in one_line_error(err)
    assert not (tmp_path / "x.mot").exists()


def test_q_is_radians_q_deg_is_degrees(capsys, tmp_path):
    out = tmp_path / "r.npz"
    rc, _, err = run(capsys, "simulate", "--q-deg", "25", "28", "16", "40", "80", "--duration", "0", "-o", str(out))
    assert rc == 0, err
    np.testing.assert_allclose(armrt.Result.load(out).q[0], np.radians([25, 28, 16, 40, 80]))
    rc, _, err = run(capsys, "simulate", "--q", "0.43", "0.5", "0.27", "0.7", "1.4", "--duration", "0", "-o", str(out))
    assert rc == 0, err
    np.testing.assert_allclose(armrt.Result.load(out).q[0], [0.43, 0.5, 0.27, 0.7, 1.4])
    # Degrees given to the radian option: refused, naming the joint, with the hint.
    rc, _, err = run(capsys, "simulate", "--q", "25", "28", "16", "40", "80")
    line = one_line_error(err)
    assert rc == 2 and "q beyond the joint limits: GHy = 25 rad" in line and "look like degrees" in line


def test_q_from_a_mot_file(capsys, tmp_path):
    from armrt.geometry import find_model_file
    if find_model_file("das2") is None:
        pytest.skip("models/das2.json not found")
    from armrt.opensim_io import write_mot
    arm = armrt.Arm()
    arm.reset(q=[0.3, 0.5, 0.2, 1.2, 1.0])
    write_mot(arm.simulate(0.0, 0.02), tmp_path / "start.mot")
    rc, _, err = run(capsys, "simulate", "--q-mot", str(tmp_path / "start.mot"), "--duration", "0",
                     "-o", str(tmp_path / "r.npz"))
    assert rc == 0, err
    np.testing.assert_allclose(armrt.Result.load(tmp_path / "r.npz").q[0], [0.3, 0.5, 0.2, 1.2, 1.0], atol=1e-8)


def test_opensim_names_are_aliases(capsys, tmp_path, arm):
    from armrt.geometry import find_model_file
    arm.reset(q={"EL_x": 1.2, "PSy": 1.0})
    assert arm.q[3] == 1.2 and arm.q[4] == 1.0
    if find_model_file("das2") is None:
        pytest.skip("models/das2.json not found (OpenSim force names come from it)")
    assert arm.indices("delt_scap_1") == [arm.element_names.index("deltscap1")]
    assert sorted(arm.indices("delt_scap")) == sorted(arm.indices("deltscap"))
    arm.set_excitation({"tric_long": 0.3})
    assert np.all(arm.excitation[arm.indices("triclong")] == 0.3)
    rc, out, err = run(capsys, "simulate", "delt_scap=0.2", "--duration", "0.01")
    assert rc == 0, err


def test_version(capsys):
    with pytest.raises(SystemExit) as e:
        main(["--version"])
    assert e.value.code == 0 and capsys.readouterr().out.strip() == f"armrt {armrt.__version__}"


def test_every_option_has_help_with_default():
    ap = build_parser()
    subs = next(a for a in ap._actions if a.__class__.__name__ == "_SubParsersAction")
    for name, p in subs.choices.items():
        for a in p._actions:
            if a.dest == "help":
                continue
            assert a.help, f"armrt {name} {a.option_strings or a.dest} has no help"
        text = p.format_help()
        if name == "simulate":
            assert "control step, s (default: 0.001)" in " ".join(text.split())
            assert "--q-deg" in text and "rad" in text


def _all_parsers():
    """{"simulate": parser, ..., "model import": parser}: every armrt command, the model actions too."""
    def subparsers(p):
        return next((a.choices for a in p._actions if a.__class__.__name__ == "_SubParsersAction"), {})
    out = {}
    for name, p in subparsers(build_parser()).items():
        out[name] = p
        out.update({f"{name} {sub}": q for sub, q in subparsers(p).items()})
    return out


def test_help_says_each_default_once():
    """ArgumentDefaultsHelpFormatter added "(default: None)" after "(default: rest posture)", and "(default:
    True)" to --no-progress."""
    import re
    for name, p in _all_parsers().items():
        text = " ".join(p.format_help().split())
        for wrong in ("(default: None)", "(default: True)", "(default: False)", "(default: [])"):
            assert wrong not in text, f"armrt {name} --help: {wrong}"
        assert not re.search(r"default[^()]*\) \(default:", text), f"armrt {name} --help says a default twice"
    text = " ".join(_all_parsers()["simulate"].format_help().split())
    assert "rad (default: rest posture) --q-deg" in text and "control step, s (default: 0.001)" in text
    assert "--no-progress no progress bar (shown on a terminal for runs longer than 1 s) -o" in text


def test_runner_help_names_q0_as_a_list():
    import subprocess
    from armrt import realtime
    try:
        runner = realtime.runner_path()
    except FileNotFoundError as e:
        pytest.skip(str(e))
    text = subprocess.run([runner, "--help"], capture_output=True, text=True, timeout=20).stdout
    assert "--q0 Q,Q,..." in text and "--q0 FLOAT" not in text


def test_model_import_errors_in_the_usual_format(das3_dir, tmp_path, capsys):
    """The importer printed "import: --free: ..."; every armrt command says "armrt COMMAND: error: ..."."""
    rc, out, err = run(capsys, "model", "import", str(das3_dir / "model_struct.mat"), "--free", "ELX",
                       "-o", str(tmp_path / "m.json"))
    line = one_line_error(err)
    assert rc == 2 and line.startswith("armrt model import: error: --free: 'ELX' is not a DOF of model_struct.mat")
    with pytest.raises(ValueError, match="'ELX' is not a DOF"):
        main(["--traceback", "model", "import", str(das3_dir / "model_struct.mat"), "--free", "ELX",
              "-o", str(tmp_path / "m.json")])


def test_out_of_range_excitation_warns_in_one_line(capsys):
    rc, _, err = run(capsys, "simulate", "bicb=1.5", "--duration", "0.01")
    assert rc == 0
    lines = err.strip().splitlines()
    assert lines and all(ln.startswith("armrt simulate: warning: excitation outside [0.0, 1.0] clipped") for ln in lines)
