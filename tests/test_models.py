"""Models as data: the registry, models built on demand (generator + compiler + cache + dlopen), and the
Model / Data / State API with snapshots and deepcopy (issue 13 items 2 and 6)."""
from __future__ import annotations

import copy
import json
import os
import stat
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import armrt
from armrt import model_build

ROOT = Path(__file__).resolve().parents[1]
DAS2_FILE = ROOT / "models" / "das2.json"
Q_TEST = np.radians([25, 28, 16, 40, 80])


def excitation(t):
    return {"elbow_flexors": 0.3 if t > 0.2 else 0.0, "rotator_cuff": 0.05, "deltoid": 0.1 * t}


def run(model, integrator="ros2", duration=0.6):
    arm = armrt.Arm(model, integrator=integrator)
    arm.reset(q=Q_TEST)
    arm.set_hand_load(force=(0.0, -5.0, 1.0))
    return arm.simulate(excitation, duration=duration)


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("ARMRT_CACHE_DIR", str(tmp_path / "cache"))
    return tmp_path / "cache"


def model_file(tmp_path, name="das2", edit=None) -> Path:
    doc = json.loads(DAS2_FILE.read_text())
    doc["name"] = name
    if edit:
        edit(doc)
    path = tmp_path / f"{name}.json"
    path.write_text(json.dumps(doc))
    return path


# ------------------------------------------------------------------------------------ registry
def test_registry_has_das2_built_in():
    assert armrt.models()[0] == "das2"
    m = armrt.Model("das2")
    assert m.builtin and m is armrt.Model() and m is armrt.Arm().model
    assert (m.n_dofs, m.n_elements, m.n_muscles) == (5, 102, 22)
    with pytest.raises(ValueError, match="unknown model 'das9'.*registered models: das2"):
        armrt.Model("das9")


# ------------------------------------------------------------------------------------ Model
def test_model_is_immutable_and_shared():
    m = armrt.Model("das2")
    with pytest.raises(AttributeError, match="immutable"):
        m.name = "x"
    for a in (m.dof_ranges, m.rest_posture, m.parameters["fmax"], m.crosses_gh, m.gravity_base):
        with pytest.raises(ValueError):
            a[0] = 0
    with pytest.raises(TypeError):
        m.muscles["bicb"] = (0,)
    assert copy.deepcopy(m) is m and copy.copy(m) is m
    # Weakening one arm leaves the Model and the other arms intact.
    a, b = armrt.Arm(m), armrt.Arm(m)
    a.strength = {"bicb": 0.2}
    assert np.all(b.strength == 1) and a.strength[m.muscles["bicb"][0]] == 0.2
    np.testing.assert_array_equal(m.parameters["fmax"], [e["fmax"] for e in m.info["elements"]])


def test_model_names_groups_parameters_provenance():
    m = armrt.Model("das2")
    arm = armrt.Arm()
    assert list(m.dof_names) == arm.dof_names and list(m.element_names) == arm.element_names
    assert list(m.muscle_names) == arm.muscle_names and list(m.group_names) == arm.group_names
    assert sorted(m.groups["elbow_flexors"]) == sorted(arm.indices("elbow_flexors"))
    assert m.muscles["bicb"] == tuple(arm.indices("bicb")) == m.indices("bicb")
    assert m.indices("delt_scap_1") == (m.element_names.index("deltscap1"),) and m.dof_index("EL_x") == 3
    with pytest.raises(KeyError, match="unknown element, muscle or group name 'bicp' .did you mean"):
        m.indices("bicp")
    assert m.parameters["fmax"].shape == (102,) and m.parameters["fmax"][0] == arm.info["elements"][0]["fmax"]
    assert m.dof_ranges.shape == (5, 2) and np.all(m.dof_ranges[:, 0] < m.dof_ranges[:, 1])
    # the passive joint law's constants are the model file's
    model_file = json.loads((Path(__file__).resolve().parents[1] / "models" / "das2.json").read_text())
    assert arm.info["passive_joint"] == model_file["passive_joint"]
    p = m.provenance
    assert p["builtin"] and p["source_hash"] == m.source_hash and len(m.source_hash) == 64
    if p["model_file"]:
        assert "DAS3" in json.dumps(p["source"]) or p["description"]


def test_model_geometry_at_any_pose_matches_the_arm():
    m = armrt.Model("das2")
    arm = armrt.Arm(m)
    q = Q_TEST
    np.testing.assert_array_equal(m.moment_arms(q), arm.moment_arms(q))
    np.testing.assert_array_equal(m.muscle_lengths(q), arm.muscle_lengths(q))
    np.testing.assert_array_equal(m.gh_directions(q), arm.gh_directions(q))
    np.testing.assert_array_equal(m.mass_matrix(q), arm.mass_matrix(q))
    # Hand position (thorax frame) is the engine's output at that pose.
    arm.reset(q=q)
    np.testing.assert_allclose(m.hand_position(q), arm.hand_position, rtol=0, atol=1e-15)
    # The humerus origin is the GH centre, fixed in the scapula.
    R, p = m.body_poses(q, frame="scapula")
    np.testing.assert_allclose(p[0], m.glenoid["gh_centre"], atol=1e-12)
    Rt, pt = m.body_poses(q)
    np.testing.assert_allclose(pt[0], m.base_rotation_in_thorax @ p[0] + m.base_origin_in_thorax, atol=1e-15)
    np.testing.assert_allclose(Rt[3].T @ Rt[3], np.eye(3), atol=1e-12)
    # Hand Jacobian against a finite difference of the hand position.
    Jv, _ = m.hand_jacobian(q)
    h = 1e-6
    fd = np.stack([(m.hand_position(q + h * e) - m.hand_position(q - h * e)) / (2 * h) for e in np.eye(5)], axis=1)
    np.testing.assert_allclose(Jv, fd, atol=1e-8)


def test_model_functions_take_many_poses():
    m = armrt.Model("das2")
    Q = np.stack([Q_TEST, m.rest_posture, Q_TEST + 0.1])
    assert m.moment_arms(Q).shape == (3, 102, 5)
    assert m.muscle_lengths(Q).shape == (3, 102)
    assert m.gh_directions(Q).shape == (3, 102, 3)
    assert m.mass_matrix(Q).shape == (3, 5, 5)
    assert m.hand_position(Q).shape == (3, 3)
    R, p = m.body_poses(Q)
    assert R.shape == (3, 4, 3, 3) and p.shape == (3, 4, 3)
    for k in range(3):
        np.testing.assert_array_equal(m.moment_arms(Q)[k], m.moment_arms(Q[k]))
        np.testing.assert_array_equal(m.body_poses(Q)[1][k], m.body_poses(Q[k])[1])
    with pytest.raises(ValueError, match=r"shape \(5,\).*or \(k, 5\), got \(4,\)"):
        m.moment_arms(np.zeros(4))
    with pytest.raises(ValueError, match="NaN"):
        m.mass_matrix(np.full(5, np.nan))
    with pytest.raises(TypeError):
        m.muscle_lengths("rest")
    with pytest.raises(ValueError, match="frame"):
        m.hand_position(Q_TEST, frame="world")


# ------------------------------------------------------------------------------------ Data, State
def test_several_data_per_model_are_independent():
    m = armrt.Model("das2")
    d1, d2 = armrt.Data(m), armrt.Data(m)
    assert d1.model is d2.model is m
    a = armrt.Arm(m)
    a.set_excitation({"biceps": 0.5})
    a.step(20)
    assert d1.time == 0 and np.array_equal(d1.q, m.rest_posture) and np.array_equal(d1.q, d2.q)
    assert a.data.time == pytest.approx(0.02) and a.data.q is a.q
    assert a.data.state.shape == (2 * 5 + 2 * 102,)
    with pytest.raises(ValueError):
        a.data.q[0] = 1.0  # read-only views
    out = a.data.outputs()
    assert out["moment_arm"].shape == (102, 5) and np.isfinite(out["gh_stab"])
    # The outputs' moment arms are the polynomials' at the state they describe (computed from its q).
    np.testing.assert_array_equal(out["moment_arm"], a.moment_arms(a.q))
    d3 = copy.deepcopy(a.data)
    assert d3.get_state() == a.data.get_state() and d3.model is m
    a.step(5)
    assert d3.time == pytest.approx(0.02)


@pytest.mark.parametrize("integrator", ["ros2", "rk4", "euler"])
def test_set_state_continues_bit_for_bit(integrator):
    arm = armrt.Arm(integrator=integrator)
    arm.reset(q=Q_TEST)
    arm.set_excitation({"elbow_flexors": 0.4, "rotator_cuff": 0.1})
    arm.set_hand_load(force=(1.0, -9.81, 0.5), moment=(0.0, 0.1, 0.0))
    arm.step(30)
    s = arm.get_state()
    assert s.time == arm.time and np.array_equal(s.activation, arm.activation)
    assert np.array_equal(s.excitation, arm.excitation) and s.hand_force[1] == -9.81 and s.hand_moment[1] == 0.1
    with pytest.raises(ValueError):
        s.q[0] = 0  # snapshots are read-only copies
    first = arm.simulate(excitation, duration=0.1)
    # Change everything the State holds, then restore it.
    arm.set_excitation(0.0)
    arm.set_hand_load()
    arm.reset(q=arm.rest_posture, time=5.0)
    arm.set_state(s)
    assert arm.get_state() == s
    again = arm.simulate(excitation, duration=0.1)
    for k in ("q", "qdot", "lce", "activation", "muscle_force", "time"):
        np.testing.assert_array_equal(getattr(first, k), getattr(again, k), err_msg=k)


def test_state_carries_ros2_history(tmp_path):
    """ROS2 evaluates the paths at one step in three and extrapolates them from the last two evaluations
    (docs/engine.md): the State keeps their q so that a restore continues bit for bit, whichever step of the
    three it stops at; without them the continuation differs by the extrapolation's error only."""
    arm = armrt.Arm()
    s0 = arm.get_state()
    assert s0.path_anchors is None and s0.path_anchor_steps == (0, 0) and s0.previous_step == 0.0  # no step yet
    arm.set_excitation({"elbow_flexors": 0.4, "deltoid": 0.2})
    before = arm.q.copy()
    arm.step(1)
    s = arm.get_state()
    np.testing.assert_array_equal(s.path_anchors, before[None, :])  # the first step's evaluation only
    assert s.path_anchor_steps == (0, 1) and s.previous_step == 1e-3
    seen = set()
    for _ in range(3):
        arm.step(1)
        s = arm.get_state()
        assert s.path_anchors.shape == (2, 5)
        seen.add(s.path_anchor_steps[1])
        ahead = arm.simulate(arm.excitation, duration=0.05)
        bare = armrt.State(**{**s.as_dict(), "path_anchors": None, "path_anchor_steps": (0, 0), "previous_step": 0.0})
        assert bare != s
        for state, exact in ((s, True), (bare, False)):
            arm.set_state(state)
            again = arm.simulate(arm.excitation, duration=0.05)
            diff = np.abs(again.q - ahead.q).max()
            assert (diff == 0.0) if exact else (0.0 < diff < 1e-5), diff
        arm.set_state(s)
    assert seen == {1, 2, 3}
    with pytest.raises(ValueError, match=r"path_anchors must have shape \(1, 5\) or \(2, 5\)"):
        arm.set_state(armrt.State(**{**s.as_dict(), "path_anchors": np.zeros(3)}))
    with pytest.raises(ValueError, match=r"ROS2 memory .*step size h must be >= 0 s, got -1"):
        arm.set_state(armrt.State(**{**s.as_dict(), "previous_step": -1.0}))
    with pytest.raises(ValueError, match="path_anchor_steps must be two whole numbers"):
        armrt.State(**{**s.as_dict(), "path_anchor_steps": (1.5, 1)})
    with pytest.raises(ValueError, match=r"ROS2 memory .*steps since the newest anchor must be 1 to 3 with 2 anchor\(s\), got 7"):
        arm.set_state(armrt.State(**{**s.as_dict(), "path_anchor_steps": (3, 7)}))
    before_refusal = arm.get_state()
    with pytest.raises(ValueError, match=r"ROS2 memory .*anchor spacing 2 with 2 anchors"):
        arm.set_state(armrt.State(**{**s.as_dict(), "path_anchor_steps": (2, 1),
                                     "q": s.q + 0.01}))  # no run leaves it
    assert arm.get_state() == before_refusal  # refused before anything was written
    with pytest.raises(ValueError, match=r"ROS2 memory .*must be 1 to 1 with 1 anchor"):
        arm.set_state(armrt.State(**{**s.as_dict(), "path_anchors": s.path_anchors[1:], "path_anchor_steps": (0, 2)}))
    with pytest.raises(ValueError, match=r"ROS2 memory .*step size h must be > 0 s with anchors"):
        arm.set_state(armrt.State(**{**s.as_dict(), "previous_step": 0.0}))
    with pytest.raises(ValueError, match=r"path_anchor_steps must be \(0, 0\) without path_anchors"):
        armrt.State(**{**s.as_dict(), "path_anchors": None})
    with pytest.raises(ValueError, match="path_anchor_steps must be two whole numbers"):
        armrt.State(**{**s.as_dict(), "path_anchor_steps": ("3", "x")})
    # A State saved by an older armrt (previous_q, no anchors): read back with a warning, restored without memory.
    old = {k: v for k, v in bare.as_dict().items() if not k.startswith("path_anchor")}
    with pytest.warns(UserWarning, match="previous_q .* is no longer ROS2's memory"):
        legacy = armrt.State(**old, previous_q=s.q)
    assert legacy == bare
    # An Arm pickled by an older armrt carried (previous_q, step) as its ROS2 memory: unpickled without it.
    func, (cls, model, settings, raw, extras) = arm.__reduce__()
    old_raw = (arm.data.state.copy(), arm.excitation, arm.data.hand_force, arm.data.hand_moment, arm.time, (arm.q.copy(), 1e-3))
    older = func(cls, model, settings, old_raw, extras)
    assert older.get_state().path_anchors is None and np.array_equal(older.q, arm.q)
    far = s.path_anchors.copy()
    far[-1] = s.q + np.array([0.3, 0, 0, 0, 0]) * s.path_anchor_steps[1]
    with pytest.raises(ValueError, match=r"ROS2 memory .*the newest anchor is not \d step\(s\) of 0.001 s before q: "
                                         "GHy would have moved at 300 rad/s"):
        arm.set_state(armrt.State(**{**s.as_dict(), "path_anchors": far}))
    # Through a file and back (State.as_dict's documented use), with and without the memory.
    for state in (s, bare):
        path = tmp_path / "state.npz"
        np.savez(path, **state.as_dict())
        with np.load(path) as f:  # no pickled objects in it
            back = armrt.State(**f)
        assert back == state and back.model == "das2" and isinstance(back.source_hash, str)
    # Another integrator has no such memory.
    rk4 = armrt.Arm(integrator="rk4")
    rk4.step(3)
    assert rk4.get_state().path_anchors is None


def test_set_state_refuses_another_model_and_bad_values(tmp_path):
    arm = armrt.Arm()
    s = arm.get_state()
    other = armrt.State(**{**s.as_dict(), "model": "other", "source_hash": "0" * 64})
    with pytest.raises(ValueError, match="model 'other'"):
        arm.set_state(other)
    with pytest.raises(ValueError, match="State.q must have shape"):
        arm.set_state(armrt.State(**{**s.as_dict(), "q": np.zeros(4)}))
    with pytest.raises(ValueError, match=r"State.lce\[deltscap1\] is not finite"):
        arm.set_state(armrt.State(**{**s.as_dict(), "lce": np.full(102, np.nan)}))
    with pytest.raises(TypeError, match="armrt.State"):
        arm.set_state(s.as_dict())


def test_cvode_restore_is_repeatable():
    arm = armrt.Arm(integrator="cvode")
    arm.set_excitation({"elbow_flexors": 0.3})
    arm.step(10)
    s = arm.get_state()
    runs = []
    for _ in range(2):
        arm.set_state(s)
        arm.step(50)
        runs.append(arm.q.copy())
    np.testing.assert_array_equal(runs[0], runs[1])


def test_deepcopy_is_an_independent_arm():
    arm = armrt.Arm(integrator="rk4")
    arm.strength = {"deltscap": 0.3}
    arm.max_activation = {"triceps": 0.0}
    arm.set_excitation({"elbow_flexors": 0.3, "triceps": 0.5})
    arm.set_hand_load(force=(0, -2.0, 0))
    arm.step(25)
    arm.note = {"trial": [1, 2]}
    twin = copy.deepcopy(arm)
    assert twin is not arm and twin.data is not arm.data and twin.model is arm.model
    assert twin.get_state() == arm.get_state()
    assert (twin.integrator, twin.dt, twin.substeps) == (arm.integrator, arm.dt, arm.substeps)
    np.testing.assert_array_equal(twin.strength, arm.strength)
    np.testing.assert_array_equal(twin.max_activation, arm.max_activation)
    assert twin.note == arm.note and twin.note is not arm.note
    # Same steps, same trajectory; stepping one leaves the other alone.
    twin.step(40)
    assert arm.time < twin.time
    arm.step(40)
    assert twin.get_state() == arm.get_state()
    twin.set_excitation(0.0)
    assert arm.excitation.max() > 0
    assert copy.copy(arm).data is not arm.data


# ------------------------------------------------------------------------------------ model files
def test_a_model_file_error_names_the_field_and_element(tmp_path, cache):
    def bad_fmax(doc):
        doc["elements"][3]["fmax"] = -5.0
    path = model_file(tmp_path, "bad", bad_fmax)
    with pytest.raises(armrt.ModelFileError, match=r"bad\.json: .*'elements\[3\]\.fmax'.*\(element 'deltscap4'\)"):
        armrt.Model.load(path)

    def no_range(doc):
        del doc["dofs"][3]["range"]
    with pytest.raises(armrt.ModelFileError, match=r"dofs\[3\]\.range.*\(DOF 'ELx'\)"):
        armrt.Model.load(model_file(tmp_path, "bad2", no_range))
    with pytest.raises(FileNotFoundError):
        armrt.Model.load(tmp_path / "absent.json")
    assert not (cache / "models").exists() or not list((cache / "models").glob("*/*.so"))


def test_a_different_model_under_a_registered_name_is_refused(tmp_path, cache):
    def stronger(doc):
        doc["elements"][0]["fmax"] *= 2
    with pytest.raises(ValueError, match="different model named 'das2' is already registered"):
        armrt.Model.load(model_file(tmp_path, "das2", stronger))


def test_no_compiler_is_a_clear_error(tmp_path, cache, monkeypatch):
    monkeypatch.setenv("CXX", str(tmp_path / "no-such-compiler"))
    with pytest.raises(armrt.CompilerNotFoundError, match="no C.. compiler.*apt-get install g\\+\\+"):
        armrt.Model.load(model_file(tmp_path, "nocxx"))


def test_a_compile_failure_names_the_build_log(tmp_path, cache, monkeypatch):
    fake = tmp_path / "broken-c++"
    fake.write_text("#!/bin/sh\necho 'broken-c++: internal error: out of luck' >&2\nexit 1\n")
    fake.chmod(fake.stat().st_mode | stat.S_IEXEC)
    monkeypatch.setenv("CXX", str(fake))
    with pytest.raises(armrt.ModelBuildError, match="compiling model 'broken' failed.*build log: ") as e:
        armrt.Model.load(model_file(tmp_path, "broken"))
    log = e.value.log
    assert str(log) in str(e.value) and log.is_file() and "out of luck" in log.read_text()
    assert not list(cache.glob("models/*/*.so"))  # nothing half-built is left where a load would find it


def test_model_built_on_demand_runs_like_the_built_in_one(tmp_path, cache, capsys):
    """End to end: `armrt model build` on a copy of das2.json under another name (generator, compiler,
    cache), then the loaded library gives the built-in das2's trajectories bit for bit, by Model, by
    name, in an ArmBatch and from the cache in a new process."""
    from armrt.cli import main
    path = model_file(tmp_path, "das2_on_demand")
    t0 = time.perf_counter()
    assert main(["model", "build", str(path)]) == 0
    first = time.perf_counter() - t0
    out = capsys.readouterr().out
    assert "model das2_on_demand: 5 DOF, 22 muscles, 102 elements; built in" in out
    libs = list(cache.glob("models/*/libarmrt_model.so"))
    assert len(libs) == 1
    assert main(["model", "build", str(path)]) == 0
    assert "found in the cache" in capsys.readouterr().out
    assert "das2_on_demand" in armrt.models()
    assert main(["model", "list"]) == 0
    listed = capsys.readouterr().out
    assert f"das2_on_demand: {path}" in listed and "for another armrt" not in listed
    assert main(["info", "--model", str(path)]) == 0
    assert capsys.readouterr().out.startswith("model das2_on_demand: 5 DOF, 22 muscles, 102 elements")

    m = armrt.Model.load(path)
    assert not m.builtin and m.name == "das2_on_demand" and m.provenance["library"] == str(libs[0])
    assert m.model_file == path.resolve() and m is armrt.Model("das2_on_demand")
    for integrator in ("ros2", "rk4"):
        ref, got = run("das2", integrator), run(m, integrator)
        for k in ("q", "qdot", "lce", "activation", "muscle_force", "gh_stab", "hand_position"):
            np.testing.assert_array_equal(getattr(ref, k), getattr(got, k), err_msg=f"{integrator} {k}")
    got = run("das2_on_demand")  # by name, through the registry
    np.testing.assert_array_equal(got.q, run("das2").q)
    np.testing.assert_array_equal(m.moment_arms(Q_TEST), armrt.Model("das2").moment_arms(Q_TEST))

    batch = armrt.ArmBatch(2, model="das2_on_demand", threads=1)
    batch.set_excitation(np.full((2, 102), 0.2))
    ref_batch = armrt.ArmBatch(2, model="das2", threads=1)
    ref_batch.set_excitation(np.full((2, 102), 0.2))
    batch.step(50), ref_batch.step(50)
    np.testing.assert_array_equal(batch.q, ref_batch.q)

    # The real-time runner: `armrt-rt --model FILE.json` loads the cached library, then runs it by name.
    from armrt.realtime import RealtimeSession, runner_args, runner_path
    args = runner_args(["--rate", "1000", "--model", str(path)])
    assert args == ["--rate", "1000", "--model-library", str(libs[0]), "--model", "das2_on_demand"]
    rt = subprocess.run([runner_path(), *args, "--duration", "0.05", "--no-rt", "--no-mlock"],
                        capture_output=True, text=True, timeout=60)
    assert rt.returncode == 0 and "das2_on_demand" in rt.stdout, rt.stderr
    assert RealtimeSession(model=m, duration=0.05).config["model"] == "das2_on_demand"
    # The runner checks a library against its checksum before dlopen, as Model.load does: a damaged copy is
    # refused with a message instead of killing the runner inside dlopen.
    import shutil
    lib_dir = tmp_path / "libcopy"
    lib_dir.mkdir()
    copied = lib_dir / libs[0].name
    shutil.copy(libs[0], copied)
    for checksum, expect in ((None, "no checksum"), ("0" * 64, "does not match its checksum")):
        sidecar = copied.with_name(copied.name + ".sha256")
        if checksum is None:
            sidecar.unlink(missing_ok=True)
        else:
            sidecar.write_text(f"{checksum}  {copied.name}\n")
        bad = subprocess.run([runner_path(), "--model-library", str(copied), "--model", "das2_on_demand",
                              "--duration", "0.05", "--no-rt", "--no-mlock"], capture_output=True, text=True, timeout=60)
        assert bad.returncode == 2 and expect in bad.stderr, bad.stderr

    # A new process finds it in the cache: nothing is generated, compiled or rewritten.
    stamps = {p: p.stat().st_mtime_ns for p in libs[0].parent.iterdir()}
    code = (f"import time, armrt; t = time.perf_counter(); m = armrt.Model.load({str(path)!r}); "
            f"print(m.name, time.perf_counter() - t)")
    env = {**os.environ, "ARMRT_CACHE_DIR": str(cache)}
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True)
    name, seconds = p.stdout.split()
    assert name == "das2_on_demand"
    assert {p: p.stat().st_mtime_ns for p in libs[0].parent.iterdir()} == stamps
    print(f"on-demand build of das2 under another name: first {first:.1f} s, cached load {float(seconds) * 1e3:.1f} ms")


def test_a_model_of_another_size_builds_and_runs(cache, tmp_path):
    """tests/data/pendulum2.json (2 DOF, 5 elements, constant moment arms): built on demand, then the
    whole API on it: geometry from the file, Arm, snapshots, copies, a batch, shapes in errors."""
    path = ROOT / "tests" / "data" / "pendulum2.json"
    m = armrt.Model.load(path)
    assert (m.name, m.n_dofs, m.n_elements, m.n_muscles) == ("pendulum2", 2, 5, 4)
    assert m.dof_names == ("ELx", "PSy") and "pendulum2" in armrt.models()
    doc = json.loads(path.read_text())
    expected = np.zeros((5, 2))
    for i, e in enumerate(doc["elements"]):
        poly = e["length_poly"]
        for exps, c in zip(poly["exponents"], poly["coefs"]):
            if sum(exps) == 1:  # L = c0 + c1 q: moment arm -c1 on that DOF
                expected[i, m.dof_names.index(poly["dofs"][exps.index(1)])] = -c
    for q in (m.rest_posture, np.array([0.7, -0.4])):
        np.testing.assert_allclose(m.moment_arms(q), expected, atol=1e-15)
    M = m.mass_matrix(np.array([0.3, 0.2]))
    assert M.shape == (2, 2) and np.allclose(M, M.T) and np.all(np.linalg.eigvalsh(M) > 0)
    with pytest.raises(ValueError, match=r"shape \(2,\)"):
        m.moment_arms(np.zeros(5))

    arm = armrt.Arm(m)
    with pytest.raises(ValueError, match=r"q must have shape \(2,\) \(ELx, PSy\)"):
        arm.reset(q=np.zeros(5))
    arm.reset(q=[0.5, 0.1])
    arm.set_excitation({"flexor": 0.3, "pronator": 0.2})
    arm.step(100)
    res = arm.simulate({"extensor": 0.4}, duration=0.2)
    assert res.q.shape == (201, 2) and res.activation.shape == (201, 5) and np.all(np.isfinite(res.q))
    assert res.model == "pendulum2" and res.model_hash == m.source_hash
    # A later session reopens the result's model from the cache (by name and hash; nothing is built).
    res.save(tmp_path / "run.npz")
    code = (f"import armrt; r = armrt.Result.load({str(tmp_path / 'run.npz')!r}); "
            f"print(r.model, armrt.Model(r.model).n_dofs, armrt.models())")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                       env={**os.environ, "ARMRT_CACHE_DIR": str(cache)})
    assert p.stdout.split()[:2] == ["pendulum2", "2"], p.stderr
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       env={**os.environ, "ARMRT_CACHE_DIR": str(tmp_path / "empty-cache")})
    assert p.returncode != 0 and "not a known model" in p.stderr
    s = arm.get_state()
    twin = copy.deepcopy(arm)
    arm.step(150)
    twin.step(150)
    assert twin.get_state() == arm.get_state()
    arm.set_state(s)
    arm.step(150)
    assert twin.get_state() == arm.get_state()
    import pickle
    back = pickle.loads(pickle.dumps(arm))  # the model travels as its file: found in the cache
    assert back.model is m and back.get_state() == arm.get_state()
    batch = armrt.ArmBatch(2, model="pendulum2", threads=1)
    batch.step(5)
    assert batch.q.shape == (2, 2)
    assert armrt.ArmBatch(1, model=m, threads=1).model is m and armrt.ArmBatch(1, model=path).model is m


def test_the_package_carries_what_a_build_needs():
    """An installed armrt finds the engine headers, the generator and the build flags beside itself (a
    checkout run with PYTHONPATH=python uses cpp/include and codegen/)."""
    inc = model_build.include_dir()
    assert (inc / "armrt" / "model_def.h").is_file() and (inc / "armrt" / "fast_math.h").is_file()
    module, root = model_build.generator()
    assert (root.joinpath(*module.split(".")[:-1]) / "generate.py").is_file()
    cfg = model_build.build_config()
    assert cfg["abi_version"] == armrt._core.MODEL_ABI_VERSION and "-O" in cfg["flags"]
    installed = model_build.HERE != ROOT / "python" / "armrt"
    if installed:
        assert inc == model_build.HERE / "include" and module == "armrt.codegen.generate"
        assert (model_build.HERE / "build_config.json").is_file()


def test_an_arm_pickles_with_its_settings_and_state():
    import pickle
    arm = armrt.Arm(integrator="rk4")
    arm.strength = {"bicb": 0.4}
    arm.set_excitation({"elbow_flexors": 0.3})
    arm.set_hand_load(force=(0.0, -3.0, 0.0))
    arm.step(20)
    arm.label = "subject 7"
    back = pickle.loads(pickle.dumps(arm))
    assert back.get_state() == arm.get_state() and back.label == "subject 7" and back.model is arm.model
    np.testing.assert_array_equal(back.strength, arm.strength)
    back.step(30)
    arm.step(30)
    assert back.get_state() == arm.get_state()
    s = pickle.loads(pickle.dumps(arm.get_state()))
    assert s == arm.get_state()


@pytest.mark.slow
def test_das2_json_itself_built_on_demand_equals_the_built_in_das2(cache):
    """models/das2.json as it is (same name and hash as the built-in model): the registry keeps the
    built-in das2 under the name, the loaded Model runs the library's code, and the two agree bit for
    bit. (The CI test above builds a renamed copy, which also exercises lookups by name.)"""
    m = armrt.Model.load(DAS2_FILE)
    assert not m.builtin and m.name == "das2" and m is not armrt.Model("das2")
    assert m.source_hash == armrt.Model("das2").source_hash and armrt.models().count("das2") == 1
    for integrator in ("ros2", "rk4", "euler"):
        ref, got = run("das2", integrator, 0.3), run(m, integrator, 0.3)
        for k in ("q", "qdot", "lce", "activation", "muscle_force"):
            np.testing.assert_array_equal(getattr(ref, k), getattr(got, k), err_msg=f"{integrator} {k}")


def test_two_processes_building_one_model_build_it_once(cache):
    path = ROOT / "tests" / "data" / "pendulum2.json"
    env = {**os.environ, "ARMRT_CACHE_DIR": str(cache)}
    cmd = [sys.executable, "-m", "armrt.cli", "model", "build", str(path)]
    procs = [subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env) for _ in range(2)]
    outs = [p.communicate(timeout=300) for p in procs]
    assert [p.returncode for p in procs] == [0, 0], outs
    said = sorted("found in the cache" in out for out, _ in outs)
    assert said == [False, True], outs  # one built it, the other waited for the lock and found it
    assert len(list(cache.glob("models/*/libarmrt_model.so"))) == 1


def test_one_registry_for_every_extension(tmp_path):
    """libarmrt is the one engine of the process (issue 25): a model loaded through armrt._core is known to the
    batch and real-time extensions without registering it there, and they share the one shared library."""
    import armrt
    from armrt import _batch, _core, _rt
    src = Path(__file__).resolve().parent / "data" / "pendulum2.json"
    model = armrt.Model.load(src)
    assert model.name in armrt.models()
    batch = _batch.Batch(model.name, 2, "ros2", 1e-3, 1)  # by name, no second registration
    assert batch.state.shape[0] == 2
    assert "load_model_library" not in dir(_batch) and "load_model_library" not in dir(_rt)
    linked = [_linked_libraries(ext.__file__) for ext in (_core, _batch, _rt)]
    assert all(len(libs) == 1 for libs in linked), linked
    assert len({Path(libs[0]).resolve() for libs in linked}) == 1, linked  # the same file


def _linked_libraries(path):
    import subprocess
    out = subprocess.run(["ldd", path], capture_output=True, text=True, check=True).stdout
    return [line.split("=>")[1].split()[0] for line in out.splitlines() if "=>" in line and "libarmrt" in line]
