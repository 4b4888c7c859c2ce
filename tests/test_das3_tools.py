"""das3 (the 11-DOF shoulder girdle) through the tools around the engine (issue 15 item 5): the
geometry, animation and live view draw the moving clavicle and scapula; .mot export carries all
eleven das3.osim coordinates; armrt-rt runs it over UDP and LSL; weakness profiles, ArmBatch and the
Gymnasium environments take it. das2's behaviour is covered by the tests of each tool."""
from __future__ import annotations

import json
import os
import subprocess
import time

import numpy as np
import pytest
from lsl_helpers import pylsl_or_skip

from conftest import DAS3

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")
if "das3" not in armrt.models():
    pytest.skip("das3 is not built into this armrt", allow_module_level=True)
from armrt import opensim_io  # noqa: E402
from armrt.geometry import BONES, POINTS, ArmGeometry  # noqa: E402

OSIM_COORDS = ["SC_y", "SC_z", "SC_x", "AC_y", "AC_z", "AC_x", "GH_y", "GH_z", "GH_yy", "EL_x", "PS_y"]
GIRDLE_MOVE = {"serratus_anterior": 0.3, "trapezius": 0.2, "deltoid": 0.2, "rotator_cuff": 0.1}


@pytest.fixture(scope="module")
def model():
    return armrt.Model("das3")


@pytest.fixture(scope="module")
def geom():
    g = ArmGeometry("das3")
    if g.model_json is None:
        pytest.skip("models/das3.json not found (scapula landmarks and contact points come from it)")
    return g


@pytest.fixture(scope="module")
def result():
    """0.4 s of das3 with the scapular muscles on: the girdle moves (SCz about +10 deg)."""
    arm = armrt.Arm(model="das3")
    return arm.simulate(GIRDLE_MOVE, duration=0.4, record_every=10)


def _poses(rng, model, k):
    """k poses: the girdle within 0.1 rad of rest (kinematics only), the arm anywhere in its ranges."""
    lo, hi = model.dof_ranges.T
    q = rng.uniform(lo, hi, size=(k, model.n_dofs))
    g = list(model.girdle_dofs)
    q[:, g] = model.rest_posture[g] + rng.uniform(-0.1, 0.1, size=(k, len(g)))
    return q


# ---------------------------------------------------------------- geometry
def test_girdle_dofs_are_sc_and_ac(model):
    assert [model.dof_names[j] for j in model.girdle_dofs] == ["SCy", "SCz", "SCx", "ACy", "ACz", "ACx"]
    assert armrt.Model("das2").girdle_dofs == ()
    assert model.body_names == ("clavicle", "scapula", *BONES) and model.base_body == "thorax"


def test_model_scapula_frame_moves_with_the_girdle(model):
    rng = np.random.default_rng(5)
    Q = _poses(rng, model, 4)
    R, p = model.body_poses(Q, frame="scapula")
    for k in range(len(Q)):
        np.testing.assert_allclose(R[k, 1], np.eye(3), atol=1e-12)                  # the scapula itself
        np.testing.assert_allclose(p[k, 2], model.glenoid["gh_centre"], atol=1e-12)  # GH, fixed in it
    Rt, pt = model.body_poses(Q)
    h_s = model.hand_position(Q, frame="scapula")
    np.testing.assert_allclose(np.einsum("kij,kj->ki", Rt[:, 1], h_s) + pt[:, 1], model.hand_position(Q), atol=1e-12)
    with pytest.raises(ValueError, match="thorax frame only"):
        model.hand_jacobian(Q[0], frame="scapula")


def test_geometry_follows_the_engine_bodies(geom, model):
    """Bones, clavicle, scapula, contact points and GH lines of action come from the body poses of
    each pose: humerus origin = GH, clavicle from the SC to the AC joint, the scapula carried rigidly."""
    rng = np.random.default_rng(3)
    body = {n: i for i, n in enumerate(model.body_names)}
    contact = {c["name"]: np.asarray(c["point"]) for c in geom.model_json["girdle_forces"]["contact"]["points"]}
    shapes = []
    for q in _poses(rng, model, 6):
        R, p = model.body_poses(q)
        pts = geom.points(q)
        for name, b in (("gh", "humerus"), ("elbow", "ulna"), ("radius_proximal", "radius"), ("wrist", "hand")):
            np.testing.assert_allclose(pts[POINTS.index(name)], p[body[b]], atol=1e-12)
        np.testing.assert_allclose(pts[POINTS.index("hand")], model.hand_position(q), atol=1e-12)
        gir = geom.girdle(q)
        np.testing.assert_allclose(gir["clavicle_r"], [p[body["clavicle"]], p[body["scapula"]]], atol=1e-12)
        Rs, os_ = R[body["scapula"]], p[body["scapula"]]
        np.testing.assert_allclose(gir["contact_points"], [Rs @ contact["TS"] + os_, Rs @ contact["AI"] + os_],
                                   atol=1e-12)
        # The blade closes on AA (the scapula origin) through GH, the humerus origin.
        scap = gir["scapula_r"]
        np.testing.assert_allclose(scap[0], os_, atol=1e-12)
        np.testing.assert_allclose(scap[-1], os_, atol=1e-12)
        np.testing.assert_allclose(scap[3], p[body["humerus"]], atol=1e-12)
        shapes.append(np.linalg.norm(scap[:, None] - scap[None], axis=2))
        # Lines of action start at GH and turn with the scapula.
        seg, idx = geom.gh_lines_of_action(q)
        np.testing.assert_allclose(seg[:, 0], np.broadcast_to(p[body["humerus"]], seg[:, 0].shape), atol=1e-12)
        d = model.gh_directions(q)[idx]
        np.testing.assert_allclose((seg[:, 1] - seg[:, 0]) / 0.06, d @ Rs.T, atol=1e-12)
    for s in shapes[1:]:
        np.testing.assert_allclose(s, shapes[0], atol=1e-12)        # rigid


def test_girdle_moves_with_the_girdle_dofs_only(geom):
    q = geom.rest.copy()
    g0, a0 = geom.girdle(q), geom.points(q)
    q_gh = q.copy()
    q_gh[geom.dof_names.index("GHz")] += 0.4
    for k, v in geom.girdle(q_gh).items():
        np.testing.assert_allclose(v, g0[k], atol=1e-15)             # arm motion leaves the girdle alone
    assert np.linalg.norm(geom.points(q_gh)[1] - a0[1]) > 0.05
    q_sc = q.copy()
    q_sc[geom.dof_names.index("SCz")] += 0.2                         # clavicle elevation
    g1 = geom.girdle(q_sc)
    assert g1["clavicle_r"][1, 1] - g0["clavicle_r"][1, 1] > 0.02    # AC rises by centimetres
    assert np.all(np.linalg.norm(g1["scapula_r"] - g0["scapula_r"], axis=1) > 0.01)
    assert geom.points(q_sc)[0, 1] - a0[0, 1] > 0.02                 # and carries the arm with it


def test_static_parts_of_das3_and_das2(geom):
    st = geom.static()
    assert {"thorax_frontal", "thorax_sagittal", "thorax_transverse", "clavicle_l", "scapula_l", "midline"} == set(st)
    gf = geom.info["girdle"]
    c, r = np.asarray(gf["thorax_centre"]), np.asarray(gf["thorax_radii"])
    for poly in (st["thorax_frontal"], st["thorax_sagittal"], st["thorax_transverse"]):
        np.testing.assert_allclose((((poly - c) / r) ** 2).sum(axis=1), 1.0, atol=1e-12)   # on the ellipsoid
    np.testing.assert_allclose(st["clavicle_l"], geom.girdle(geom.rest)["clavicle_r"] * [-1, 1, 1])
    # das2: the girdle is fixed and static, as before; nothing moves and no thorax surface.
    g2 = ArmGeometry("das2")
    assert g2.girdle(g2.rest + 0.1) == {}
    assert set(g2.static()) >= {"clavicle_r", "scapula_r", "clavicle_l", "scapula_l", "midline"}
    assert not any(k.startswith("thorax") for k in g2.static())


# ---------------------------------------------------------------- animation and live view
def test_animation_draws_the_girdle_moving(result, tmp_path):
    pytest.importorskip("matplotlib")
    from armrt.animate import GIRDLE_STYLE, animate, build_figure
    rows = np.array([0, len(result.time) - 1])
    fig, draw, views = build_figure(result, rows)
    try:
        ax = views[0][0]
        clav = [ln for ln in ax.lines if ln.get_color() == GIRDLE_STYLE["clavicle_r"]["color"]]
        scap = [ln for ln in ax.lines if ln.get_color() == GIRDLE_STYLE["scapula_r"]["color"] and ln.get_linewidth() == 2.5]
        assert len(clav) == 1 and len(scap) == 1
        draw(0)
        c0, s0 = np.array(clav[0].get_xydata()), np.array(scap[0].get_xydata())
        draw(1)
        c1, s1 = np.array(clav[0].get_xydata()), np.array(scap[0].get_xydata())
        geom = ArmGeometry("das3")
        front = -geom.girdle(result.q[-1])["clavicle_r"][:, 0]
        np.testing.assert_allclose(c1[:, 0], front, atol=1e-12)
        assert np.abs(c1 - c0).max() > 0.005 and np.abs(s1 - s0).max() > 0.005
    finally:
        import matplotlib.pyplot as plt
        plt.close(fig)
    out = animate(result, tmp_path / "das3.gif", fps=10, max_frames=3, progress=False)
    from PIL import Image
    with Image.open(out) as im:
        assert im.n_frames == 3


def test_viewer_moves_the_girdle(result):
    pytest.importorskip("viser", reason="viser is not installed (pip install viser)")
    from armrt.view import Frame, ResultSource, Viewer
    import socket
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    v = Viewer(ResultSource(result), host="127.0.0.1", port=port, verbose=False)
    try:
        assert v._girdle is not None and len(v._contacts) == 2
        v.draw(Frame(time=0.0, q=result.q[0], activation=result.activation[0], gh_stab=1.0))
        p0 = np.array(v._girdle.points)
        v.draw(Frame(time=0.4, q=result.q[-1], activation=result.activation[-1], gh_stab=1.0))
        p1 = np.array(v._girdle.points)
        clav = v.geom.girdle(result.q[-1])["clavicle_r"]
        np.testing.assert_allclose(p1[0], clav, atol=1e-6)          # the first segment: SC to AC
        assert np.abs(p1 - p0).max() > 0.005
        np.testing.assert_allclose(v._contacts[0].position, v.geom.girdle(result.q[-1])["contact_points"][0],
                                   atol=1e-6)
        html = v._angles_html(result.q[-1])
        assert "clavicle elevation" in html and "scapula lateral rotation" in html
    finally:
        v.server.stop()


def test_live_page_shows_the_girdle_moving(tmp_path):
    """The served page in headless Chromium: the girdle's pixels (the difference between the page with
    the girdle shown and hidden, the simulation paused) are there, and elsewhere a second later."""
    import chromium_helpers as tv
    if tv.chromium() is None:
        pytest.skip("chromium is not installed (Debian package 'chromium')")
    pytest.importorskip("viser", reason="viser is not installed (pip install viser)")
    from armrt.view import SimulationSource, serve

    def excitation(t):
        return {"serratus_anterior": 0.25 * (1 + np.sin(2 * np.pi * 0.5 * t)), "trapezius": 0.15,
                "rotator_cuff": 0.08, "deltoid": 0.1}
    v = serve(SimulationSource(model="das3", excitation=excitation), host="127.0.0.1", port=tv.free_port(),
              fps=30, block=False)
    out_dir = tmp_path / "shots"
    out_dir.mkdir()

    def girdle_pixels(page, k):
        v.source.set_paused(True)
        time.sleep(0.6)
        shown, png = page.screenshot()
        (out_dir / f"das3_{k}.png").write_bytes(png)
        v._girdle.visible = False
        for c in v._contacts:
            c.visible = False
        time.sleep(0.6)
        hidden, _ = page.screenshot()
        v._girdle.visible = True
        for c in v._contacts:
            c.visible = True
        v.source.set_paused(False)
        h, w, _ = shown.shape
        region = (slice(int(0.15 * h), h), slice(0, int(0.64 * w)))   # the 3D view, not the panel
        return np.abs(shown[region].astype(int) - hidden[region].astype(int)).max(axis=2) > 40
    try:
        with tv.chromium_page(v.url, tmp_path) as page:
            deadline = time.monotonic() + 30
            while not page.eval("!!document.querySelector('canvas') && document.body.innerText.includes('GHstab')"):
                assert time.monotonic() < deadline, "the page never showed the scene and the GHstab panel"
                time.sleep(0.3)
            time.sleep(1.5)
            m0 = girdle_pixels(page, 0)
            time.sleep(1.0)
            m1 = girdle_pixels(page, 1)
            assert "clavicle elevation" in page.eval("document.body.innerText")
    finally:
        v.stop()
    assert v.source.restarts == 0 and v.source.error is None
    assert m0.sum() > 300 and m1.sum() > 300, (m0.sum(), m1.sum())
    assert (m0 ^ m1).sum() > 50, "the girdle did not move between the two screenshots"


# ---------------------------------------------------------------- .mot export
def test_mot_exports_all_eleven_coordinates(result, tmp_path):
    path = opensim_io.write_mot(result, tmp_path / "das3.mot")
    header, labels, data = opensim_io.read_storage(path)
    assert labels == ["time"] + OSIM_COORDS
    np.testing.assert_allclose(data[:, 1:], result.q, atol=1e-8)
    assert np.ptp(data[:, 1:7], axis=0).max() > 0.05                 # the girdle columns move
    motion = opensim_io.read_motion(path, model="das3")
    np.testing.assert_allclose(motion.q, result.q, atol=1e-8)
    assert motion.to_result().q.shape == result.q.shape
    sto = opensim_io.write_activation_sto(result, tmp_path / "das3.sto")
    assert opensim_io.read_storage(sto)[1][1] == "trap_scap_1"


@pytest.mark.opensim
def test_mot_plays_on_das3_osim(result, model, tmp_path):
    opensim = pytest.importorskip("opensim", reason="the opensim package is not installed")
    osim = DAS3 / "das3.osim"
    if not osim.exists():
        pytest.skip(f"{osim} not found (needs ../shared beside the repository)")
    storage = opensim.Storage(str(opensim_io.write_mot(result, tmp_path / "das3.mot")))
    labels = [storage.getColumnLabels().get(i) for i in range(storage.getColumnLabels().getSize())]
    assert labels == ["time"] + OSIM_COORDS and not storage.isInDegrees()
    m = opensim.Model(str(osim))
    state = m.initSystem()
    coords = m.getCoordinateSet()
    assert sorted(coords.get(i).getName() for i in range(coords.getSize())) == sorted(OSIM_COORDS)
    for row in (0, storage.getSize() - 1):
        values = storage.getStateVector(row).getData()
        for j, name in enumerate(OSIM_COORDS):
            coords.get(name).setValue(state, values.get(j), False)
        m.realizePosition(state)
        # The file's angles put OpenSim's scapula and humerus where armrt has them (thorax = ground).
        _, p = model.body_poses(result.q[row])
        for k, body in ((1, "scapula_r"), (2, "humerus_r")):
            o = m.getBodySet().get(body).getPositionInGround(state)
            np.testing.assert_allclose([o.get(0), o.get(1), o.get(2)], p[k], atol=1e-6)


# ---------------------------------------------------------------- real time
def test_runner_runs_das3_over_udp_and_fails_safe(tmp_path):
    from armrt import realtime as rt
    try:
        exe = rt.runner_path()
    except FileNotFoundError as e:
        pytest.skip(str(e))
    out_json = tmp_path / "rt.json"
    p = subprocess.Popen([exe, "--model", "das3", "--listen", "127.0.0.1:0", "--state-rate", "200", "--excitations",
                          "--timeout", "0.1", "--duration", "30", "--json", str(out_json)],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        port, head = None, ""
        t_end = time.monotonic() + 10
        while port is None and time.monotonic() < t_end:
            line = p.stdout.readline()
            head += line
            if "listening on udp port" in line:
                port = int(line.split()[-1])
        assert port is not None, "armrt-rt --model das3 did not start"
        m = armrt.Model("das3")
        serrant = list(m.indices("serratus_anterior"))
        with rt.UdpClient(port, mapping="groups", model="das3") as c:
            c.join()
            states = []
            t_end = time.monotonic() + 1.0
            while time.monotonic() < t_end:
                c.send(GIRDLE_MOVE)
                st = c.latest_state(timeout=0.5)
                assert st is not None, "no state packet from the runner"
                states.append(st)
                time.sleep(0.005)
            last = states[-1]
            assert last.q.shape == (11,) and last.qdot.shape == (11,) and last.excitation.shape == (138,)
            assert not last.diverged
            np.testing.assert_allclose(last.excitation[serrant], 0.3)
            # The runner's q is das3's: the scapular muscles moved the girdle from rest.
            assert np.abs(last.q[:6] - m.rest_posture[:6]).max() > 0.01
            # Silence: the session times out and the excitation falls to zero (fail safe).
            time.sleep(0.4)
            tail = []
            while (st := c.recv_state(timeout=0.1)) is not None:
                tail.append(st)
            assert tail and tail[-1].timed_out and tail[-1].excitation.max() == 0.0
        p.send_signal(2)
        out, err = p.communicate(timeout=10)
    finally:
        if p.poll() is None:
            p.kill()
    assert p.returncode == 0, err
    assert "das3" in head and "TET" in out
    stats = json.loads(out_json.read_text())
    assert stats["error"] == "" and stats["packets"]["timeouts"] >= 1 and stats["packets"]["applied"] > 20
    assert 0 < stats["tet_ns"]["mean"] <= stats["tet_ns"]["max"]


def test_state_packets_of_another_model_are_refused_not_misread():
    """A das2 client (or viewer) on a das3 runner, and the reverse, counts the packets as bad with the
    reason, instead of decoding das3's 34 values as das2's 22 (wrong angles, silently)."""
    from armrt import realtime as rt
    n3, n2 = armrt.Model("das3").n_elements, armrt.Model("das2").n_elements
    f2, f3 = rt.state_fields("das2"), rt.state_fields("das3")
    plain3 = rt.decode_packet(rt.encode_packet(rt.STATE, 1, np.zeros(len(f3))))
    with_exc3 = rt.decode_packet(rt.encode_packet(rt.STATE, 1, np.zeros(len(f3) + n3), flags=rt.FLAG_EXCITATION))
    with_exc2 = rt.decode_packet(rt.encode_packet(rt.STATE, 1, np.zeros(len(f2) + n2), flags=rt.FLAG_EXCITATION))
    assert rt.StatePacket.from_packet(plain3, f3, n3).q.shape == (11,)
    assert rt.StatePacket.from_packet(with_exc3, f3, n3).excitation.shape == (n3,)
    for packet, fields, n in ((plain3, f2, n2), (with_exc3, f2, n2), (with_exc2, f3, n3)):
        with pytest.raises(rt.PacketError, match="another model"):
            rt.StatePacket.from_packet(packet, fields, n)
    with rt.RealtimeSession(listen="127.0.0.1:0", model="das3", state_rate_hz=200) as s, \
            rt.UdpClient(s.port, mapping="elements", model="das2") as c:
        c.join()
        c.sock.sendto(rt.encode_packet(rt.EXC_ELEMENTS, 99, np.zeros(n3), session=c.session), c.address)
        assert c.recv_state(timeout=0.3) is None
        assert c.bad_packets > 0 and "another model" in c.last_error
        s.stop()


def test_lsl_state_stream_names_das3_coordinates():
    pytest.importorskip("pylsl", reason="pylsl is not installed")
    from armrt.lsl_bridge import state_channels
    labels, _, _ = state_channels("das3")
    assert labels[1:12] == ["SCy", "SCz", "SCx", "ACy", "ACz", "ACx", "GHy", "GHz", "GHyy", "ELx", "PSy"]
    assert labels[12] == "SCy_dot" and len(labels) == len(set(labels))


def test_lsl_bridge_loopback_with_das3():
    """The LSL bridge between an excitation outlet and a das3 session: das3's state channels come back,
    the scapular channel is forwarded and moves the girdle."""
    import test_realtime as tr
    pylsl = pylsl_or_skip()
    from armrt import realtime as rt
    from armrt.lsl_bridge import LslBridge, channel_labels, state_channels
    source = f"armrt-test-das3-{os.getpid()}"
    bridge = LslBridge(runner_port=0, mapping="groups", model="das3", source_id=source,
                       excitation_name=f"exc-{source}", state_rate_hz=200)
    with rt.RealtimeSession(listen="127.0.0.1:0", model="das3", state_rate_hz=200,
                            state_to=f"127.0.0.1:{bridge.state_port}") as s:
        bridge.runner_address = ("127.0.0.1", s.port)
        stop, th, errors = tr._run_bridge(bridge)
        try:
            labels = list(bridge.mapping.names)
            assert "serratus_anterior" in labels and len(labels) == 15
            outlet = tr._exc_outlet(pylsl, f"exc-{source}", f"{source}-controller", labels)
            found = pylsl.resolve_byprop("source_id", f"{source}-state", timeout=10)
            assert found, "state stream not found on loopback"
            inlet = pylsl.StreamInlet(found[0])
            labels_out = channel_labels(inlet.info(timeout=5))
            assert labels_out == state_channels("das3")[0]
            u = np.zeros(len(labels))
            u[labels.index("serratus_anterior")] = 0.3
            first = last = None
            t_end = time.monotonic() + 2.5
            while time.monotonic() < t_end and not errors:
                outlet.push_sample(u.tolist())
                samples, _ = inlet.pull_chunk(timeout=0.05)
                if samples:
                    first = samples[0] if first is None else first
                    last = samples[-1]
                time.sleep(0.01)
            assert not errors, errors
            assert first is not None and bridge.forwarded > 10
            assert bridge.last_values[labels.index("serratus_anterior")] == 0.3
            girdle = [labels_out.index(n) for n in ("SCy", "SCz", "SCx", "ACy", "ACz", "ACx")]
            assert np.abs(np.subtract(last, first)[girdle]).max() > 0.01
        finally:
            stop.set()
            th.join(timeout=5)
            bridge.close()
        st = s.stop()
    assert st["packets"]["applied"] > 10 and st["error"] == ""


def test_lsl_bridge_command_takes_the_model(monkeypatch, capsys):
    from armrt import lsl_bridge
    seen = {}

    def fake(*args, **kwargs):
        seen.update(kwargs)
        raise ValueError("stopped here by the test")
    monkeypatch.setattr(lsl_bridge, "LslBridge", fake)
    assert lsl_bridge.main(["--model", "das3", "--runner", "127.0.0.1:45100"]) == 2
    assert seen["model"] == "das3" and "stopped here" in capsys.readouterr().err


# ---------------------------------------------------------------- profiles, batch, gym
def test_weakness_profile_on_das3_matches_das2_element_by_element():
    a2, a3 = armrt.Arm(model="das2"), armrt.Arm(model="das3")
    r2, r3 = a2.apply_profile("participant_A_FES"), a3.apply_profile("participant_A_FES")
    assert r3.unmatched == [] and r3.applied == r2.applied
    ix3 = {n: i for i, n in enumerate(a3.element_names)}
    for i, n in enumerate(a2.element_names):
        assert a3.strength[ix3[n]] == a2.strength[i] and a3.max_activation[ix3[n]] == a2.max_activation[i]
    only3 = [ix3[n] for n in a3.element_names if n not in set(a2.element_names)]
    assert len(only3) == 36 and np.all(a3.strength[only3] == 1.0) and np.all(a3.max_activation[only3] == 1.0)


def test_batch_of_das3_arms_matches_a_lone_arm():
    batch = armrt.ArmBatch(2, model="das3", threads=1)
    arm = armrt.Arm(model="das3")
    u = np.zeros(arm.n_elements)
    u[list(arm.indices("serratus_anterior"))] = 0.3
    batch.reset()
    batch.set_excitation(np.stack([u, np.zeros_like(u)]))
    arm.set_excitation(u)
    assert list(batch.step(30)) == []
    arm.step(30)
    assert batch.q.shape == (2, 11)
    np.testing.assert_array_equal(batch.q[0], arm.q)
    np.testing.assert_array_equal(batch.hand_position[0], arm.hand_position)
    # the girdle's outputs, as the lone arm's
    out_b, out_a = batch.outputs(), arm.outputs()
    for k in ("girdle_torque", "contact_distance", "contact_force", "conoid_length", "conoid_tension"):
        assert out_b[k].shape == (2,) + np.shape(out_a[k]), k
        np.testing.assert_array_equal(out_b[k][0], out_a[k], err_msg=k)
    assert np.all(out_b["conoid_tension"] > 0) and np.all(np.abs(out_b["contact_distance"]) < 0.02)
    for k in ("girdle_torque", "contact_distance", "contact_force", "conoid_length", "conoid_tension"):
        np.testing.assert_array_equal(getattr(batch, k), out_b[k], err_msg=k)   # the live view, same values
    # a model with a fixed girdle has none, and says why
    das2 = armrt.ArmBatch(1, threads=1)
    assert "contact_distance" not in das2.outputs()
    with pytest.raises(AttributeError, match="model das2 has no moving girdle"):
        das2.contact_distance


def test_gym_envs_run_das3_with_the_girdle_at_rest_to_start():
    gym = pytest.importorskip("gymnasium", reason="needs gymnasium (pip install gymnasium)")
    import armrt.gym  # noqa: F401
    from gymnasium.utils.env_checker import check_env
    env = gym.make("armrt/Reach-v0", model="das3").unwrapped
    check_env(env, skip_render_check=True)
    m = armrt.Model("das3")
    g = list(m.girdle_dofs)
    for seed in range(3):
        obs, _ = env.reset(seed=seed)
        np.testing.assert_array_equal(obs[g], m.rest_posture[g].astype(np.float32))
        assert np.abs(obs[6:11] - m.rest_posture[6:11]).max() > 0       # the arm's start is still drawn
    obs, _ = env.reset(seed=0)
    for _ in range(10):
        obs, reward, terminated, truncated, info = env.step(np.full(env.action_space.shape, 0.05, np.float32))
        assert not info["diverged"]
    env = gym.make("armrt/FESElbow-v0", model="das3").unwrapped
    env.reset(seed=0)
    for _ in range(10):
        obs, reward, terminated, truncated, info = env.step(np.full(env.action_space.shape, 0.2, np.float32))
        assert not info["diverged"] and np.isfinite(reward)


def test_cli_info_and_simulate_das3(tmp_path, capsys):
    from armrt.cli import main
    assert main(["info", "--model", "das3"]) == 0
    out = capsys.readouterr().out
    assert "model das3: 11 DOF, 28 muscles, 138 elements" in out and "SC_y" in out
    npz = tmp_path / "run.npz"
    assert main(["simulate", "--model", "das3", "--duration", "0.05", "--no-progress", "-o", str(npz),
                 "serratus_anterior=0.3"]) == 0
    res = armrt.Result.load(npz)
    assert res.model == "das3" and res.q.shape[1] == 11
    mot = tmp_path / "run.mot"
    assert main(["export", str(npz), "--mot", str(mot)]) == 0
    assert opensim_io.read_storage(mot)[1] == ["time"] + OSIM_COORDS


def test_cli_simulate_settle_starts_from_the_relaxed_arm(capsys):
    """`armrt simulate --settle` starts from Arm.settle()'s state: no start-up jolt from equilibrium.mat."""
    from armrt.cli import main
    # the excitation after --settle is not taken as its duration
    assert main(["simulate", "--model", "das3", "--duration", "0.05", "--no-progress", "--settle",
                 "elbow_flexors=0.0", "--settle-duration", "0.5"]) == 0
    out = capsys.readouterr().out
    assert "settled for 0.5 s with no excitation" in out
    arm = armrt.Arm(model="das3")
    rest = dict(zip(arm.dof_names, np.degrees(arm.q)))
    arm.settle(0.5)
    settled = dict(zip(arm.dof_names, np.degrees(arm.q)))
    start = {ln.split()[0]: float(ln.split()[1]) for ln in out.splitlines() if ln.split() and ln.split()[0] in settled}
    assert len(start) == 11 and all(abs(start[k] - settled[k]) < 0.01 for k in start)
    assert abs(start["ELx"] - rest["ELx"]) > 1.0  # the elbow's sag from equilibrium.mat has begun


@pytest.mark.parametrize("value", ["-1", "nan", "inf"])
def test_cli_settle_duration_errors_name_the_option(value, capsys):
    from armrt.cli import main
    assert main(["simulate", "--model", "das3", "--settle", "--settle-duration", value, "--no-progress"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--settle-duration must be a finite number of seconds >= 0" in err[0], err
