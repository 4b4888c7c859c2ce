"""GH stability as a signal for controllers (issue 24, item 4): the rim margin and rim direction beside
GHstab on every surface (Arm, Model, Result, ArmBatch, the state packet, LSL, the viewer), each checked
against an independent numpy computation from the GH force and the glenoid basis."""
import math
import os
import time

import numpy as np
import pytest

armrt = pytest.importorskip("armrt", reason="armrt is not built/installed (./run.sh setup)")

KEYS = ("gh_theta", "gh_phi", "gh_stab", "gh_rim_margin", "gh_rim_direction")


def numpy_rim(force, glenoid) -> dict:
    """The definition of docs/conventions.md written afresh in numpy: force (..., 3) N, scapula frame."""
    f = np.asarray(force, float)
    fn, fa, fb = (f @ np.asarray(glenoid[k]) for k in ("glenoid_normal", "glenoid_major_axis", "glenoid_minor_axis"))
    ta, pa = glenoid["rim_half_angle_major"], glenoid["rim_half_angle_minor"]
    theta, phi = np.arctan2(fa, fn), np.arctan2(fb, fn)
    rho = np.hypot(theta, phi)
    psi = np.where(rho > 0, np.arctan2(phi, theta), 0.0)
    rim = 1 / np.sqrt(np.cos(psi) ** 2 / ta**2 + np.sin(psi) ** 2 / pa**2)
    return {"gh_theta": theta, "gh_phi": phi, "gh_stab": (theta / ta) ** 2 + (phi / pa) ** 2,
            "gh_rim_margin": rim - rho, "gh_rim_direction": psi}


def assert_rim(got: dict, want: dict, atol=1e-12):
    for k in KEYS:
        np.testing.assert_allclose(got[k], want[k], rtol=1e-12, atol=atol, err_msg=k)


@pytest.fixture
def moving_arm():
    """A das2 arm 0.1 s into a deltoid contraction without the cuff (the paper's Fig. 2 situation):
    a GH force off the glenoid normal, past the superior rim."""
    arm = armrt.Arm(model="das2")
    arm.set_excitation({"deltoid": 0.3})
    arm.step(100)
    return arm


def test_minor_axis_is_anterior_for_the_right_scapula():
    # Scapula frame: x lateral, y superior, z posterior; +minor = normal x major must point anterior (-z).
    g = armrt.Model("das2").glenoid
    assert g["glenoid_normal"][0] < -0.9          # GH centre -> glenoid centre: medial
    assert g["glenoid_major_axis"][1] > 0.9       # superior
    assert g["glenoid_minor_axis"][2] < -0.9      # anterior
    np.testing.assert_allclose(np.cross(g["glenoid_normal"], g["glenoid_major_axis"]), g["glenoid_minor_axis"],
                               atol=1e-12)


def test_arm_properties_equal_numpy_of_the_gh_force(moving_arm):
    arm = moving_arm
    out = arm.outputs()
    want = numpy_rim(out["gh_force"], arm.model.glenoid)
    assert_rim({k: getattr(arm, k) for k in KEYS}, want)
    assert_rim({k: out[k] for k in KEYS}, want)
    # The deltoid alone shears the head beyond the superior rim (GHstab 1.25 here): a negative margin.
    assert arm.gh_stab > 1 and arm.gh_rim_margin < 0
    assert arm.gh_theta > 0 and arm.gh_phi != 0 and abs(arm.gh_rim_direction) < math.pi / 2  # superior


def test_gh_rim_of_any_forces_arrays_in_arrays_out(arm):
    g = arm.model.glenoid
    rng = np.random.default_rng(7)
    F = rng.normal(size=(200, 3)) * 10 ** rng.uniform(-1, 3.5, size=(200, 1))
    got = arm.gh_rim(F)
    assert all(got[k].shape == (200,) for k in KEYS)
    assert_rim(got, numpy_rim(F, g))
    assert np.all(np.sign(got["gh_rim_margin"]) == np.sign(1 - got["gh_stab"]))
    one = arm.gh_rim(F[3])
    assert all(np.shape(one[k]) == () for k in KEYS)
    assert tuple(float(one[k]) for k in KEYS[:3]) == pytest.approx(arm.gh_stability(F[3]), rel=1e-15)
    # On the rim along +minor (anterior): margin 0, psi pi/2.
    n, b = np.asarray(g["glenoid_normal"]), np.asarray(g["glenoid_minor_axis"])
    pa = g["rim_half_angle_minor"]
    # Along the normal (to rounding) the direction is that of the rounding and the margin is the rim's
    # radius that way, between phi_a and theta_a (exactly theta_a with psi 0 only at rho = 0: cpp/tests/test_gh.cc).
    centre = arm.gh_rim(250 * n)
    assert np.hypot(centre["gh_theta"], centre["gh_phi"]) < 1e-15
    assert pa - 1e-15 <= centre["gh_rim_margin"] <= g["rim_half_angle_major"] + 1e-15
    rim = arm.gh_rim(math.cos(pa) * n + math.sin(pa) * b)
    assert abs(rim["gh_rim_margin"]) < 1e-12 and rim["gh_rim_direction"] == pytest.approx(math.pi / 2)
    for bad in ([1.0, 2.0], np.zeros((2, 4)), np.zeros((2, 2, 3))):
        with pytest.raises(ValueError, match="shape"):
            arm.gh_rim(bad)
    with pytest.raises(ValueError, match="NaN"):
        arm.gh_rim([1.0, np.inf, 0.0])
    with pytest.raises(TypeError):
        arm.gh_rim([1j, 0, 0])


def test_result_records_margin_and_direction(tmp_path, moving_arm):
    arm = moving_arm
    res = arm.simulate({"deltoid": 0.4, "rotator_cuff": 0.02}, duration=0.3, record_every=3)
    assert res.gh_rim_margin.shape == res.gh_rim_direction.shape == res.time.shape
    want = numpy_rim(res.gh_force, arm.model.glenoid)
    assert_rim({"gh_theta": res.gh_angles[:, 0], "gh_phi": res.gh_angles[:, 1], "gh_stab": res.gh_stab,
                "gh_rim_margin": res.gh_rim_margin, "gh_rim_direction": res.gh_rim_direction}, want)
    assert sum(getattr(res, k).nbytes for k in armrt.Result.ARRAYS) == arm.result_bytes(0.3, 3)
    df = res.to_dataframe(["gh_stab", "gh_rim_margin", "gh_rim_direction"])
    np.testing.assert_array_equal(df["gh_rim_margin"].to_numpy(), res.gh_rim_margin)
    np.testing.assert_array_equal(df["gh_rim_direction"].to_numpy(), res.gh_rim_direction)
    res.save(tmp_path / "r.npz")
    back = armrt.Result.load(tmp_path / "r.npz")
    np.testing.assert_array_equal(back.gh_rim_margin, res.gh_rim_margin)
    np.testing.assert_array_equal(back.gh_rim_direction, res.gh_rim_direction)


def test_result_file_from_before_the_rim_arrays_loads_them_from_its_own_angles(tmp_path, moving_arm):
    """A file saved before the rim arrays existed gets them from its recorded gh_angles, which are right
    for the glenoid it was recorded with, even when today's model file has another glenoid basis (as
    every file from before issue 24: there recomputing from gh_force would mix the two)."""
    res = moving_arm.simulate({"deltoid": 0.3}, duration=0.05)
    res.gh_angles[2] = np.nan         # a row without angles (as a replay's) stays NaN
    res.save(tmp_path / "new.npz")
    with np.load(tmp_path / "new.npz") as z:
        old = {k: z[k] for k in z.files if k not in ("gh_rim_margin", "gh_rim_direction")}
    # Another glenoid's record: the force turned 15 deg about the minor axis, its angles left as recorded.
    R = np.array([[1, 0, 0], [0, math.cos(0.26), -math.sin(0.26)], [0, math.sin(0.26), math.cos(0.26)]])
    old["gh_force"] = old["gh_force"] @ R.T
    np.savez_compressed(tmp_path / "old.npz", **old)
    back = armrt.Result.load(tmp_path / "old.npz")
    ok = np.isfinite(res.gh_angles).all(axis=1)
    np.testing.assert_allclose(back.gh_rim_margin[ok], res.gh_rim_margin[ok], rtol=1e-14, atol=1e-15)
    np.testing.assert_allclose(back.gh_rim_direction[ok], res.gh_rim_direction[ok], rtol=1e-14, atol=1e-15)
    assert np.isnan(back.gh_rim_margin[2]) and np.isnan(back.gh_rim_direction[2])
    assert np.all(np.sign(back.gh_rim_margin[ok]) == np.sign(1 - back.gh_stab[ok]))


def test_batch_views_equal_lone_arms():
    n = 3
    batch = armrt.ArmBatch(n, threads=1)
    rng = np.random.default_rng(3)
    U = rng.uniform(0, 0.3, size=(n, batch.n_elements))
    batch.set_excitation(U)
    assert not len(batch.step(40))
    for name in ("gh_rim_margin", "gh_rim_direction"):
        v = getattr(batch, name)
        assert v.shape == (n,) and not v.flags.writeable
    want = numpy_rim(batch.gh_force, armrt.Model("das2").glenoid)
    assert_rim({k: getattr(batch, k) for k in KEYS}, want)
    outs = batch.outputs()
    for i in range(n):
        lone = armrt.Arm(model="das2")
        lone.set_excitation(U[i])
        lone.step(40)
        for k in KEYS:
            assert getattr(lone, k) == getattr(batch, k)[i] == outs[k][i], (k, i)


def test_state_packet_carries_the_gh_values():
    rt = pytest.importorskip("armrt.realtime", reason="armrt.realtime (the armrt-rt codec) is not built")
    from armrt import _rt
    fields = _rt.state_fields("das2")
    k = fields.index("gh_stab")
    assert fields[k:k + 5] == ["gh_stab", *rt.GH_RIM_FIELDS] and rt.VERSION == 3
    with rt.RealtimeSession(listen="127.0.0.1:0", rate_hz=1000, state_rate_hz=200) as s:
        with rt.UdpClient(s.port, mapping="groups") as c:
            c.join()
            t_end = time.monotonic() + 3
            st = None
            while time.monotonic() < t_end and (st is None or st.time < 0.2):
                c.send({"deltoid": 0.3, "rotator_cuff": 0.05})
                st = c.latest_state(timeout=0.1) or st
    assert st is not None, "no state packet"
    g = armrt.Model("das2").glenoid
    ta, pa = g["rim_half_angle_major"], g["rim_half_angle_minor"]
    assert st.gh_theta != 0 and np.isfinite([st.gh_rim_margin, st.gh_rim_direction]).all()
    # The packet has no force: its values must be those of its own theta and phi.
    assert st.gh_stab == pytest.approx((st.gh_theta / ta) ** 2 + (st.gh_phi / pa) ** 2, rel=1e-12)
    assert st.gh_rim_direction == pytest.approx(math.atan2(st.gh_phi, st.gh_theta), rel=1e-12)
    rho = math.hypot(st.gh_theta, st.gh_phi)
    assert st.gh_rim_margin == pytest.approx(rho / math.sqrt(st.gh_stab) - rho, rel=1e-10)


def test_lsl_state_channels_and_samples_carry_the_gh_values():
    from armrt.lsl_bridge import state_channels
    labels, units, types = state_channels("das2")
    k = labels.index("gh_stab")
    assert labels[k:k + 5] == ["gh_stab", "gh_theta", "gh_phi", "gh_rim_margin", "gh_rim_direction"]
    assert units[k:k + 5] == ["1", "rad", "rad", "rad", "rad"] and len(units) == len(types) == len(labels)
    pylsl = pytest.importorskip("pylsl", reason="pylsl is not installed")
    del pylsl
    from armrt.lsl_bridge import LslBridge
    from armrt.realtime import StatePacket as State
    bridge = LslBridge(runner_port=0, mapping="groups", source_id=f"armrt-test-rim-{os.getpid()}",
                       excitation_source_id="none")
    pushed = []
    try:
        bridge.outlet = type("Outlet", (), {"push_sample": lambda self, s, t: pushed.append(s)})()
        st = State(seq=1, time=0.5, q=np.arange(5.0), qdot=np.zeros(5), hand_position=np.zeros(3), gh_stab=0.4,
                   last_applied_seq=0, flags=0, gh_theta=0.1, gh_phi=-0.2, gh_rim_margin=0.3, gh_rim_direction=-1.1)
        bridge._publish(st)
    finally:
        bridge.close()
    sample = dict(zip(labels, pushed[0]))
    assert len(pushed[0]) == len(labels)
    assert [sample[n] for n in labels[k:k + 5]] == [0.4, 0.1, -0.2, 0.3, -1.1]


def test_viewer_shows_margin_and_direction_beside_ghstab(moving_arm):
    from armrt.view import RIM_SECTORS, ResultSource, SimulationSource, rim_text
    assert rim_text(math.radians(12.34), 0.0) == "rim margin 12.3&deg; to the rim, leaning superior (0&deg;)"
    assert "leaning anterior (90&deg;)" in rim_text(0.1, math.pi / 2)
    assert "leaning posterior (-90&deg;)" in rim_text(0.1, -math.pi / 2)
    assert "leaning inferior" in rim_text(0.1, -math.pi) and "leaning inferior" in rim_text(0.1, math.pi)
    assert "0.6&deg; beyond the rim" in rim_text(-0.01, 0.3) and RIM_SECTORS[1] == "superior-anterior"
    assert rim_text(float("nan"), float("nan")) == "rim margin n/a"
    res = moving_arm.simulate({"deltoid": 0.3}, duration=0.05)
    src = ResultSource(res)
    src.start()
    f = src.latest()
    k = int(np.searchsorted(res.time, f.time))
    assert (f.gh_rim_margin, f.gh_rim_direction) == (res.gh_rim_margin[k], res.gh_rim_direction[k])
    sim = SimulationSource(arm=moving_arm)
    f = sim._snapshot()
    assert (f.gh_rim_margin, f.gh_rim_direction) == (sim.arm.gh_rim_margin, sim.arm.gh_rim_direction)


def test_das3_formula_differs_as_docs_say():
    """The numbers of docs/conventions.md's DAS3 table (tests/das3_ghstab.py)."""
    from tests.das3_ghstab import CASES, PA, TA, das3_ghstab, glenoid_axis_error_deg, paper_ghstab, tilted
    # Both are 0 along the normal and grow with the angle, but DAS3 reaches 1 at tan(theta_a) rad.
    assert paper_ghstab(tilted(0, 0)) == das3_ghstab(tilted(0, 0)) == 0
    assert paper_ghstab(tilted(44.37, 0)) == pytest.approx(1.0)
    assert das3_ghstab(tilted(44.37, 0)) == pytest.approx((TA / math.tan(TA)) ** 2)  # 0.627
    assert das3_ghstab(tilted(math.degrees(math.tan(TA)), 0)) == pytest.approx(1.0)
    assert das3_ghstab(tilted(0, 38.55)) == pytest.approx((PA / math.tan(PA)) ** 2)
    # A force pulling the head off is far beyond the rim by eq. (5); DAS3's arcsines cannot tell it from
    # its mirror pressing in.
    away = dict(CASES)["20 deg superior, pulling the head off"]
    assert paper_ghstab(away) > 30 and das3_ghstab(away) == pytest.approx(das3_ghstab(tilted(20, 0)))
    # The engine agrees with this file's eq. (5) in the engine's own glenoid basis.
    g = armrt.Model("das2").glenoid
    basis = np.array([g["glenoid_normal"], g["glenoid_major_axis"], g["glenoid_minor_axis"]])
    for _, f in CASES:
        assert armrt.Model("das2").gh_rim(f @ basis)["gh_stab"] == pytest.approx(paper_ghstab(f), rel=1e-12)
    assert glenoid_axis_error_deg() == pytest.approx(9.05, abs=0.01)
