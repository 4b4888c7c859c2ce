"""The reference FES controllers (armrt.fes_control; docs/control.md "Reference FES controllers"): their building
blocks cross-checked against the engine, and short versions of the papers' protocols against the published bounds."""
import copy
import math
import warnings

import numpy as np
import pytest

import armrt
from armrt import fes_control as fc
from armrt import fes_controllers_validation as v


@pytest.fixture(scope="module")
def setup():
    arm = v.weakened_arm()
    coding = fc.StimulationCoding.from_arm(arm)
    return arm, coding, fc.chain_time_constant(arm, coding)


# ------------------------------------------------------------------------------------------ building blocks
def test_coding_inverts_the_engines_recruitment(setup):
    """pulse_width(R) is the inverse of the engine's recruitment law (Arm.recruitment_fraction, computed in C++)."""
    arm, coding, _ = setup
    r = np.linspace(0.02, 1.0, len(coding.channel_names))
    pw = coding.pulse_width(r)
    engine = [arm.recruitment_fraction(c, pw[k], coding.amplitude_A) for k, c in enumerate(coding.channel_names)]
    np.testing.assert_allclose(engine, r, atol=1e-9)
    assert np.all(coding.pulse_width(np.zeros(len(r))) == 0.0)
    assert np.all(coding.pulse_width(np.ones(len(r))) <= coding.max_pulse_width_s)


def test_coded_level_is_the_force_level_the_engine_settles_to(setup):
    """command(level) gives, once the rested chain settles, the Ding force level asked for (0.1, 0.3, 0.6)."""
    arm, coding, _ = setup
    levels = np.resize([0.1, 0.3, 0.6], len(coding.channel_names)) * coding.fused / coding.fused.max()
    m = dict(arm.stimulation_map(), fatigue=False)
    probe = armrt.Arm("das2", stimulation=m)
    probe.set_stimulation(coding.command(levels))
    probe.step(700)
    got = np.zeros(len(levels))
    for _ in range(300):
        probe.step(1)
        got += [probe.force_level[c] for c in probe.channel_names]
    np.testing.assert_allclose(got / 300, levels, rtol=0.02, atol=2e-3)


def test_minimum_jerk_derivatives_match_finite_differences():
    t = np.linspace(-0.2, 1.4, 1601)
    q, qd, qdd = fc.minimum_jerk([0.1, 0.2], [0.5, -0.2], 0.0, 1.2, t)
    smooth = (np.abs(t) > 0.01) & (np.abs(t - 1.2) > 0.01)   # the jerk jumps at the ends
    np.testing.assert_allclose(np.gradient(q, t, axis=0)[smooth], qd[smooth], atol=1e-5)
    np.testing.assert_allclose(np.gradient(qd, t, axis=0)[smooth], qdd[smooth], atol=1e-4)
    assert np.allclose(q[t <= 0], [0.1, 0.2]) and np.allclose(q[t >= 1.2], [0.5, -0.2])
    with pytest.raises(ValueError, match="duration"):
        fc.minimum_jerk([0.0], [1.0], 0.0, 0.0, t)
    for bad in ({"t0": np.nan}, {"t0": np.inf}, {"duration": np.inf}, {"t": [0.0, np.nan]}, {"q1": [np.nan]}):
        args = {"q0": [0.0], "q1": [1.0], "t0": 0.0, "duration": 1.0, "t": t} | bad
        with pytest.raises(ValueError, match=next(iter(bad))):
            fc.minimum_jerk(**args)


def test_pole_placement_puts_the_four_poles_at_minus_one_over_four_lags():
    p = fc.PIDParams.pole_placement(0.1)
    roots = np.roots([0.1, 1.0, p.kd, p.kp, p.ki])   # tau s^4 + s^3 + kd s^2 + kp s + ki
    np.testing.assert_allclose(roots.real, -2.5, atol=2e-3 * 2.5 * 10)
    assert np.abs(roots.imag).max() < 0.05 and p.preview_s == 0.1
    with pytest.raises(ValueError, match="lag_s"):
        fc.PIDParams.pole_placement(0.0)
    # An infinite lag gave gains inf * 0 = NaN, reported as "kp must be finite and >= 0, got nan".
    with pytest.raises(ValueError, match="lag_s must be a finite time > 0 s, got inf"):
        fc.PIDParams.pole_placement(np.inf)
    with pytest.raises(ValueError, match="kp"):
        fc.PIDParams(kp=-1.0, ki=0.0, kd=0.0)


def test_channel_static_optimisation_balances_the_moments(setup):
    """The channel levels' element activations supply inverse dynamics' moments (the engine's muscle model)."""
    arm, coding, _ = setup
    model = fc.model_arm(arm)
    so = fc.ChannelStaticOptimizer(model, coding)
    q = arm.rest_posture.copy()
    q[arm.dof_index("ELx")] += math.radians(40)
    levels, res = so.solve_levels(q, np.zeros(arm.n_dofs), np.zeros(arm.n_dofs))
    assert res.feasible and np.abs(res.residual).max() < 1e-3
    assert np.all(levels >= 0) and np.all(levels <= so.level_max + 1e-12)
    # the activations the plant's stimulation stage gives those levels: min(max_activation, w level)
    np.testing.assert_allclose(res.activation, np.minimum(so.S @ levels, model.max_activation))


def test_controllers_check_their_inputs(setup):
    arm, coding, tau = setup
    t, q = v.movement_reference(arm, {"ELx": 10.0}, 1.0)
    ctl = fc.FeedforwardPID(fc.model_arm(arm), coding, (t, q), fc.PIDParams.pole_placement(tau))
    with pytest.raises(ValueError, match="shape"):
        ctl.update(0.0, np.zeros(3), np.zeros(5))
    with pytest.raises(ValueError, match="NaN"):
        ctl.update(0.0, np.full(5, np.nan), np.zeros(5))
    with pytest.raises(ValueError, match="without a stimulation map"):
        fc.FeedforwardPID(arm, coding, (t, q), fc.PIDParams.pole_placement(tau))
    with pytest.raises(ValueError, match="stimulation map"):
        fc.StimulationCoding.from_arm(armrt.Arm("das2"))
    with pytest.raises(ValueError, match="channels"):
        fc.run_offline(armrt.Arm("das2", stimulation={"channels": [{"name": "f", "elements": ["bicl"]}]}), ctl, 0.1)


def test_coding_refuses_non_finite_input_instead_of_coding_it_as_no_stimulation(setup):
    """A NaN level, activation or recruitment used to code as 0 s pulse width (a failed controller hidden as
    'no stimulation'); each now names the input and the channels or elements."""
    arm, coding, _ = setup
    C, n = len(coding.channel_names), arm.n_elements
    bad = np.zeros(C)
    bad[coding.channel_names.index("bicl")] = np.nan
    with pytest.raises(ValueError, match=r"levels contains NaN.*'bicl'"):
        coding.command(bad)
    with pytest.raises(ValueError, match="levels contains NaN"):
        coding.command(np.full(C, np.inf))
    with pytest.raises(ValueError, match=r"activation contains NaN.*'deltscap1'"):
        coding.levels(np.full(n, np.nan))
    with pytest.raises(ValueError, match="recruitment contains NaN"):
        coding.pulse_width(np.nan)
    with pytest.raises(ValueError, match="pulse_width_s contains NaN"):
        coding.recruitment(np.full(C, np.nan))
    with pytest.raises(ValueError, match=r"pulse_width_s must be >= 0"):
        coding.recruitment(-1e-4)
    with pytest.raises(ValueError, match=rf"levels must have shape \({C},\)"):
        coding.command(np.zeros((C, 1)))
    with pytest.raises(ValueError, match=rf"activation must have shape \({n},\)"):
        coding.levels(np.zeros(5))     # used to index past the end or read only the first elements
    with pytest.raises(TypeError, match="levels must be numbers"):
        coding.command("0.3")


def test_coding_warns_once_when_it_clips_out_of_range_input(setup):
    """Levels, activations and recruitments outside [0, 1] are clipped with one RuntimeWarning per call, as Arm
    clips excitations; the clipped command equals the command of the clipped values."""
    _, coding, _ = setup
    C = len(coding.channel_names)
    lv = np.full(C, 0.2)
    lv[0], lv[1] = -1.0, 5.0
    with pytest.warns(RuntimeWarning, match=r"levels outside \[0, 1\] clipped.*'deltscap', 'deltclav'") as rec:
        cmd = coding.command(lv)
    assert len(rec) == 1
    np.testing.assert_array_equal(cmd, coding.command(np.clip(lv, 0.0, 1.0)))
    with pytest.warns(RuntimeWarning, match=r"recruitment outside \[0, 1\]") as rec:
        coding.pulse_width(np.full(C, 2.0))
    assert len(rec) == 1
    a = np.zeros(len(coding.element_names))
    a[0] = 1.5
    with pytest.warns(RuntimeWarning, match=r"activation outside \[0, 1\] clipped.*'deltscap1'") as rec:
        got = coding.levels(a)
    assert len(rec) == 1
    np.testing.assert_allclose(got, coding.levels(np.minimum(a, 1.0)))
    with warnings.catch_warnings():
        warnings.simplefilter("error")       # in range: no warning
        coding.command(np.full(C, 0.5))


def test_feedforward_pid_needs_its_gains(setup):
    """params has no default: the documented gains come from the plant's lag (chain_time_constant), which the
    constructor's model (no map) and coding cannot measure; PIDParams() itself has no defaults to fall back on."""
    arm, coding, _ = setup
    t, q = v.movement_reference(arm, {"ELx": 10.0}, 1.0)
    with pytest.raises(TypeError, match="required positional argument: 'params'"):
        fc.FeedforwardPID(fc.model_arm(arm), coding, (t, q))
    with pytest.raises(TypeError, match="params must be PIDParams"):
        fc.FeedforwardPID(fc.model_arm(arm), coding, (t, q), None)
    with pytest.raises(TypeError, match="params must be PDParams"):
        fc.PDController(arm, coding, arm.rest_posture, fc.PIDParams(1.0, 0.0, 0.1))


def test_run_offline_checks_duration_and_hold_up_front(setup):
    arm, coding, _ = setup
    plant = armrt.Arm("das2", stimulation="per_muscle")
    pd = fc.PDController(plant, coding, plant.rest_posture, fc.PDParams(1.0, 0.3))
    for duration in (-1.0, 0.0, np.nan, np.inf):
        with pytest.raises(ValueError, match="duration must be finite and > 0 s"):
            fc.run_offline(plant, pd, duration)
    with pytest.raises(ValueError, match="shorter than one control interval"):
        fc.run_offline(plant, pd, 0.005)     # floor(0.5) = 0 updates: a run that does nothing
    with pytest.raises(TypeError, match="duration must be a number, got the string"):
        fc.run_offline(plant, pd, "1")
    for hold in (np.nan, -1.0, np.inf):
        with pytest.raises(ValueError, match="hold_s must be finite and >= 0 s"):
            fc.run_offline(plant, pd, 0.02, hold_s=hold)
    with pytest.raises(TypeError, match="hold_s must be a number, got the string"):
        fc.run_offline(plant, pd, 0.02, hold_s="1")
    with pytest.raises(TypeError, match="hand_load must be None or a callable"):
        fc.run_offline(plant, pd, 0.02, hand_load=(np.zeros(3), np.zeros(3)))
    assert plant.time == 0.0      # every refusal came before the first step
    # the hold is applied: with hold_s covering the run, the joints end where they started despite gravity
    q0 = plant.q.copy()
    run = fc.run_offline(plant, pd, 0.05, hold_s=0.05)
    np.testing.assert_array_equal(run.q[-1], q0)
    free = fc.run_offline(plant, pd, 0.05)
    assert np.abs(free.q[-1] - q0).max() > 1e-6


def test_parameters_times_and_durations_refuse_a_bool_as_endpoint_gains_do(setup):
    """True was taken as 1 (a gain of 1, a GH bound of 1, a 1 s run or hold, t = 1 s) where EndpointGains and
    StaticOptimizer raise a TypeError: the same check (checks.real_scalar(booleans=False)), naming the argument."""
    arm, coding, _ = setup
    for kw, name in (({"kp": True}, "kp"), ({"ki": np.bool_(False)}, "ki"), ({"kd": True}, "kd"),
                     ({"preview_s": True}, "preview_s"), ({"control_interval_s": True}, "control_interval_s"),
                     ({"gh_stab_max": True}, "gh_stab_max")):
        with pytest.raises(TypeError, match=f"{name} must be a number, got the bool"):
            fc.PIDParams(**({"kp": 1.0, "ki": 0.0, "kd": 0.1} | kw))
    with pytest.raises(TypeError, match="kp must be a number, got the bool True"):
        fc.PDParams(True, False)
    with pytest.raises(TypeError, match="kd must be a number, got the bool False"):
        fc.PDParams(1.0, False)
    with pytest.raises(TypeError, match="lag_s must be a number, got the bool True"):
        fc.PIDParams.pole_placement(True)
    plant = armrt.Arm("das2", stimulation="per_muscle")
    q = plant.rest_posture.copy()
    pd = fc.PDController(plant, coding, q, fc.PDParams(1.0, 0.3))
    with pytest.raises(TypeError, match="duration must be a number, got the bool True"):
        fc.run_offline(plant, pd, True)
    with pytest.raises(TypeError, match="hold_s must be a number, got the bool True"):
        fc.run_offline(plant, pd, 0.02, hold_s=True)
    assert plant.time == 0.0
    with pytest.raises(TypeError, match="t must be a number, got the bool True"):
        pd.update(True, q, np.zeros(5))
    t_ref, q_ref = v.movement_reference(arm, {"ELx": 10.0}, 1.0)
    ff = fc.FeedforwardPID(fc.model_arm(arm), coding, (t_ref, q_ref), fc.PIDParams(1.0, 0.0, 0.1))
    with pytest.raises(TypeError, match="t must be a number, got the bool True"):
        ff.update(True, q, np.zeros(5))
    assert ff.state.last_t is None


@pytest.mark.parametrize("bad, exc, match", [
    (np.inf, ValueError, "gh_stab_max must be None or a finite number > 0, got inf"),
    (np.nan, ValueError, "gh_stab_max must be None or a finite number > 0, got nan"),
    (0.0, ValueError, "gh_stab_max must be None or a finite number > 0"),
    ("0.1", TypeError, "gh_stab_max must be a number, got the string"),
])
def test_pid_params_refuse_a_bad_gh_stab_max_themselves(bad, exc, match):
    """The static optimiser's rule (control.check_gh_stab_max) where the bound is written: inf used to pass
    PIDParams and be refused only by FeedforwardPID's optimiser."""
    with pytest.raises(exc, match=match):
        fc.PIDParams(1.0, 0.0, 0.1, gh_stab_max=bad)


def test_pid_params_gh_stab_max_beyond_the_models_limit_is_refused_by_the_controller(setup):
    """The upper limit depends on the model's glenoid (das2: 3.51), which PIDParams does not know: FeedforwardPID
    refuses it when it builds its inverse model, with gh_polygon's message."""
    arm, coding, _ = setup
    p = fc.PIDParams(1.0, 0.0, 0.1, gh_stab_max=np.float32(5.0))
    assert p.gh_stab_max == 5.0 and type(p.gh_stab_max) is float
    t_ref, q_ref = v.movement_reference(arm, {"ELx": 10.0}, 1.0)
    with pytest.raises(ValueError, match=r"gh_stab_max = 5 puts the bound's ellipse beyond .*give gh_stab_max < 3.5"):
        fc.FeedforwardPID(fc.model_arm(arm), coding, (t_ref, q_ref), p)


def test_run_offline_hand_load_callable_returns_any_form_of_a_hand_load(setup):
    """hand_load(t) may return a force (3,), (force, moment), a (6,) [force, moment] or {"force", "moment"}, as
    every other hand_load (control._hand_load); a force alone failed with "too many values to unpack (expected 2)".
    A bad return is refused naming hand_load and t."""
    _, coding, _ = setup
    f, m = np.array([0.0, -9.81, 0.0]), np.array([0.0, 0.0, 0.2])

    def run(hand_load):
        plant = armrt.Arm("das2", stimulation="per_muscle")
        pd = fc.PDController(plant, coding, plant.rest_posture, fc.PDParams(1.0, 0.3))
        return fc.run_offline(plant, pd, 0.03, hand_load=hand_load).q

    unloaded = run(None)
    force_only = run(lambda t: list(f))
    np.testing.assert_array_equal(force_only, run(lambda t: (f, np.zeros(3))))
    assert np.abs(force_only[-1] - unloaded[-1]).max() > 1e-6     # the load was applied
    with_moment = run(lambda t: (f, m))
    for form in (lambda t: np.concatenate([f, m]), lambda t: {"force": f, "moment": m}, lambda t: [f, m]):
        np.testing.assert_array_equal(run(form), with_moment)
    for bad, exc, match in ((lambda t: [0.0, -9.81], ValueError, r"hand_load\(0\) returned .*got shape \(2,\)"),
                            (lambda t: (np.array([np.nan, 0, 0]), np.zeros(3)), ValueError,
                             r"hand_load\(0\) returned .*hand force contains NaN"),
                            (lambda t: None, TypeError, r"hand_load\(0\) returned None"),
                            (lambda t: "10 N", TypeError, r"hand_load\(0\) returned .*string")):
        with pytest.raises(exc, match=match):
            run(bad)


def test_controllers_refuse_a_joint_speed_beyond_the_arms_max_joint_speed(setup):
    """A new user's trial: a sensor glitch of qdot = 1e6 rad/s went through both controllers, and the PD's answer
    was its largest pulse widths. They refuse it now as static_optimization does (max_joint_speed, 100 rad/s)."""
    arm, coding, tau = setup
    q = arm.rest_posture.copy()
    fast = np.zeros(arm.n_dofs)
    fast[arm.dof_index("ELx")] = 1e6
    pd = fc.PDController(arm, coding, q, fc.PDParams(1.0, 0.3))
    t_ref, q_ref = v.movement_reference(arm, {"ELx": 10.0}, 1.0)
    ff = fc.FeedforwardPID(fc.model_arm(arm), coding, (t_ref, q_ref), fc.PIDParams.pole_placement(tau))
    for ctl in (pd, ff):
        with pytest.raises(ValueError, match=r"qdot\[ELx\] = 1e\+06 rad/s is beyond max_joint_speed 100 rad/s"):
            ctl.update(0.0, q, fast)
        fast_ok = np.zeros(arm.n_dofs)
        fast_ok[arm.dof_index("ELx")] = 99.0   # within the bound: answered
        assert np.all(np.isfinite(ctl.update(0.0, q, fast_ok)))


def test_controllers_refuse_a_non_finite_time_and_a_column_posture(setup):
    arm, coding, tau = setup
    q = arm.rest_posture.copy()
    z = np.zeros(arm.n_dofs)
    target = q.copy()
    target[arm.dof_index("ELx")] += 0.3
    pd = fc.PDController(arm, coding, q, fc.PDParams(1.0, 0.3), schedule=[(0.5, target)])
    for t in (np.nan, np.inf):
        with pytest.raises(ValueError, match="t must be a finite time"):
            pd.update(t, q, z)     # NaN <= 0.5 is false: the scheduled target would never take over
    assert len(pd.schedule) == 1
    with pytest.raises(ValueError, match=r"q must have shape \(5,\) \(GHy.*got \(5, 1\)"):
        pd.update(0.0, q[:, None], z)
    with pytest.raises(ValueError, match=r"qdot must have shape \(5,\)"):
        pd.update(0.0, q, z[:, None])
    with pytest.raises(ValueError, match="look like degrees"):
        pd.update(0.0, np.degrees(q), z)
    with pytest.raises(ValueError, match=r"target must have shape \(5,\)"):
        pd.set_target(q[:, None])
    with pytest.raises(ValueError, match="schedule time must be a finite time"):
        fc.PDController(arm, coding, q, fc.PDParams(1.0, 0.3), schedule=[(np.nan, target)])
    with pytest.raises(ValueError, match="schedule time must be >= 0 s"):
        fc.PDController(arm, coding, q, fc.PDParams(1.0, 0.3), schedule=[(-0.5, target)])
    # A bare posture, its time left out, was Python's 'too many values to unpack (expected 2)'.
    with pytest.raises(ValueError, match=r"a schedule entry must be a pair \(t s, target \(ndof,\) rad\)"):
        fc.PDController(arm, coding, q, fc.PDParams(1.0, 0.3), schedule=[target])
    t_ref, q_ref = v.movement_reference(arm, {"ELx": 10.0}, 1.0)
    with pytest.raises(ValueError, match=r"q_ref frame 0 \(t = 0 s\).*look like degrees"):
        fc.FeedforwardPID(fc.model_arm(arm), coding, (t_ref, np.degrees(q_ref)), fc.PIDParams.pole_placement(tau))
    ff = fc.FeedforwardPID(fc.model_arm(arm), coding, (t_ref, q_ref), fc.PIDParams.pole_placement(tau))
    with pytest.raises(ValueError, match="t must be a finite time"):
        ff.update(np.nan, q, z)
    with pytest.raises(ValueError, match=r"q must have shape \(5,\)"):
        ff.update(0.0, q[:, None], z)
    assert ff.state.last_t is None     # nothing of the refused updates was integrated


def test_udp_control_loop_sends_zero_stimulation_when_the_controller_fails(setup):
    """A state the controller refuses (NaN q) ends the loop with the error, after a zero command: the last
    non-zero command is not left applied until the runner's timeout."""
    from types import SimpleNamespace

    from armrt.fes_control_udp import control_loop

    arm, coding, _ = setup
    pd = fc.PDController(arm, coding, arm.rest_posture, fc.PDParams(3.0, 0.3))
    low = arm.rest_posture.copy()
    low[arm.dof_index("ELx")] -= 0.2       # below the target: the flexors are stimulated
    states = iter([low, np.full(arm.n_dofs, np.nan)])

    class Client:
        stimulation = SimpleNamespace(names=coding.channel_names)

        def __init__(self):
            self.sent = []

        def latest_state(self, timeout):
            return SimpleNamespace(time=0.0, q=next(states), qdot=np.zeros(arm.n_dofs), gh_stab=0.0,
                                   received_at=0.0, stopped=False)

        def send_stimulation(self, cmd):
            self.sent.append(np.array(cmd))

    client = Client()
    with pytest.raises(ValueError, match="contains NaN"):
        control_loop(pd, client, 1.0)
    assert len(client.sent) == 2 and client.sent[0][:, 0].max() > 0
    np.testing.assert_array_equal(client.sent[-1], 0.0)
    with pytest.raises(ValueError, match="until_s"):
        control_loop(pd, client, np.nan)


# ------------------------------------------------------------------------------------------ (a) Blana 2009
def test_blana_feedforward_pid_tracks_within_4_deg_ideal_and_10_deg_fatigued(setup):
    """Blana, Kirsch & Chadwick 2009: < 4 deg in ideal conditions, < 10 deg with fatigue; the PID does the work the
    feedforward alone cannot under fatigue."""
    mv = v.BLANA_MOVEMENTS[-1]   # shoulder and elbow together
    ideal = v.blana_trial(mv, setup=setup)
    assert ideal["rms_deg"] < 4.0 and ideal["max_deg"] < 4.0
    fatigued = v.blana_trial(mv, fatigue_s=10.0, setup=setup)
    assert 0.2 < fatigued["fatigue"] < 0.4          # the fatigue is there (1 - A/A_rest)
    assert fatigued["rms_deg"] < 10.0 and fatigued["max_deg"] < 10.0
    open_loop = v.blana_trial(mv, fatigue_s=10.0, gains="feedforward", setup=setup)
    assert open_loop["rms_deg"] > 1.2 * fatigued["rms_deg"]


def test_blana_disturbance_is_corrected(setup):
    mv = v.BLANA_MOVEMENTS[0]
    r = v.blana_trial(mv, disturbance_N=2.0, setup=setup)
    assert r["rms_deg"] < 10.0
    # after the pulse (0.5 s from the movement's middle) the error falls to less than half its peak by the end
    run = r["run"]
    assert np.abs(np.degrees(run.q[-1] - run.q_ref[-1])).max() < 0.5 * r["max_deg"]


@pytest.mark.slow
def test_blana_full_protocol_table():
    rows = v.blana(None)
    for r in rows:
        if r["condition"] == "ideal":
            assert r["rms_deg"] < 4.0, r["movement"]
        if r["condition"] in ("fatigue 10 s", "disturbance 2 N", "disturbance 5 N"):
            assert r["rms_deg"] < 10.0, (r["condition"], r["movement"])


# ------------------------------------------------------------------------------------------ real time over UDP
def _udp_example():
    import importlib.util
    from pathlib import Path
    path = Path(__file__).resolve().parents[1] / "examples" / "fes_controllers_udp.py"
    spec = importlib.util.spec_from_file_location("fes_controllers_udp", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.mark.slow
@pytest.mark.parametrize("kind", ["blana", "jagodnik", "posture"])
def test_controller_runs_as_a_separate_process_against_the_realtime_runner(kind):
    """The controller process joins armrt-rt over UDP and controls the arm; its loop times are reported (not bounded:
    wall clock on a shared machine) and the runner applied its stimulation packets."""
    mod = _udp_example()
    out = mod.main(["--controller", kind])
    assert out["cycles"] > 100 and out["runner"]["stimulation_applied"] > 100
    assert {"p50", "p90", "p99", "max"} <= set(out["compute_us"]) and out["compute_us"]["p50"] > 0
    if kind == "blana":
        # RMS within Blana's 10 deg: the loop's late and irregular updates on a shared machine act as a disturbance
        assert max(out["rms_deg"].values()) < 10.0
    elif kind == "jagodnik":
        assert max(out["final_deg"][d] for d in ("GHy", "ELx")) < 5.0     # arrived (Jagodnik's 5 deg criterion)
    else:
        # below the unconstrained (unloaded) hold's 0.038: the bound lowers GHstab; over UDP, with late updates and
        # no supported start, it is not kept exactly (0.034 against 0.03 measured, docs/control.md)
        assert out["gh_stab_max"] < 0.038 and max(out["max_deg"].values()) < 5.0


# ------------------------------------------------------------------------------------------ (b) Jagodnik 2010
def test_pd_structure_maps_errors_to_agonists(setup):
    """A positive elbow error stimulates the elbow flexors and no triceps; a negative one the reverse."""
    arm, coding, _ = setup
    q = arm.rest_posture.copy()
    ctl = fc.PDController(arm, coding, q, fc.PDParams(3.0, 0.3))
    el = arm.dof_index("ELx")
    names = coding.channel_names
    for sign, agonists, antagonists in ((+1, ["bicl", "brachialis"], ["triclat", "tricmed"]),
                                        (-1, ["triclat", "tricmed"], ["bicl", "brachialis"])):
        dq = np.zeros(arm.n_dofs)
        dq[el] = -sign * 0.1     # the arm below (sign +1) or above the target
        cmd = ctl.update(0.0, q + dq, np.zeros(arm.n_dofs))
        assert all(cmd[names.index(m), 0] > 0 for m in agonists), sign
        assert all(cmd[names.index(m), 0] == 0 for m in antagonists), sign
    with pytest.raises(ValueError, match="kp"):
        fc.PDParams(-1.0, 0.1)


def test_saved_pd_gains_are_the_optimisers_improvement(setup):
    """The saved gains (optimise-pd's result) lower the training cost below the search's start."""
    saved = v.saved_pd_gains()
    moves = v.pd_movements(6, 1, setup[0].rest_posture)
    assert v.pd_cost(saved, moves, setup) < v.pd_cost(v.PD_START_GAINS, moves, setup) - 0.1
    assert saved[0] > 0 and saved[1] > 0


def test_pd_tracks_with_doubled_forearm_weight_and_weakened_muscles(setup):
    """Jagodnik 2010: generality error 5.50 deg and doubled mass 6.18 deg for their 2-gain PD; ours on three test
    movements, nominal and with the elbow's gravity moment doubled and every muscle weakened to 0.5-1 x."""
    arm = setup[0]
    kp, kd = v.saved_pd_gains()
    moves = v.pd_movements(3, 2, arm.rest_posture)
    nominal = [v.pd_trial(kp, kd, mv, setup) for mv in moves]
    assert np.mean([r["error_deg"] for r in nominal]) < 5.50 and not any(r["failed"] for r in nominal)
    load = v.elbow_weight_load(arm, moves[0][0])
    # the load doubles the forearm and hand's gravitational elbow moment (independent: inverse dynamics with it)
    j = arm.dof_index("ELx")
    t0 = arm.inverse_dynamics(moves[0][0], hand_load=((0, 0, 0), (0, 0, 0)))
    t1 = arm.inverse_dynamics(moves[0][0], hand_load=(tuple(load), (0, 0, 0)))
    t0, t1 = (np.asarray(x["tau_muscle"] if isinstance(x, dict) else x)[j] for x in (t0, t1))
    assert t1 == pytest.approx(2 * t0, rel=1e-6)
    rng = np.random.default_rng(0)
    heavy = []
    for mv in moves:
        scale = np.ones(arm.n_elements)
        for name in arm.muscle_names:
            scale[arm.indices(name)] = rng.uniform(*v.WEAKEN_RANGE)
        heavy.append(v.pd_trial(kp, kd, mv, setup, hand_force=v.elbow_weight_load(arm, mv[0]), strength_scale=scale))
    err = np.mean([r["error_deg"] for r in heavy])
    assert err < 10.0                                   # still tracking: within 10 deg on average over 2 s
    assert err > np.mean([r["error_deg"] for r in nominal])   # and the load and weakness cost accuracy


def _free_fall_with_friction(friction_Nm, dofs, steps=200, model="das2"):
    """The arm unstimulated from rest at an elevated, flexed posture (gravity's moment about GHy and ELx well above
    1 N m), its joints under joint_friction: the arm, and per step (a, qdot after the step)."""
    arm = armrt.Arm(model)
    q0 = arm.rest_posture.copy()
    q0[arm.dof_index("GHy")], q0[arm.dof_index("ELx")] = 0.8, 1.2
    arm.reset(q=q0)
    friction = v.joint_friction(arm, friction_Nm, dofs)
    log = []
    for _ in range(steps):
        arm.set_applied_moment(0)  # the moments besides friction, as run_offline holds them while it is called
        a = friction(arm.time, arm.q, arm.qdot)
        arm.set_applied_moment(a)
        arm.step()
        log.append((a, arm.qdot.copy()))
    return arm, q0, log


def test_joint_friction_sticks_below_its_bound_and_slides_against_it_above():
    """joint_friction's time-stepping Coulomb law (Stewart & Trinkle 1996; MuJoCo's frictionloss): with a bound no
    moment reaches, every joint sticks; with 1 N m against gravity's larger moments, the joints slide, each moment at
    the bound against its joint's velocity, and friction never adds energy."""
    arm = armrt.Arm("das2")
    stuck, q0, log = _free_fall_with_friction(1e3, arm.dof_names)
    assert np.abs(stuck.q - q0).max() < 1e-6                    # held where it was: nothing reached 1000 N m
    assert max(np.abs(a).max() for a, _ in log) < 1e3          # and no moment sat at the bound
    free, _, _ = _free_fall_with_friction(0.0, v.PD_DOFS)
    sliding, _, log = _free_fall_with_friction(1.0, v.PD_DOFS)
    cols = [arm.dof_index(d) for d in v.PD_DOFS]
    moving = [(a[cols], qd[cols]) for a, qd in log if np.all(np.abs(qd[cols]) > 0.05)]
    assert len(moving) > 100
    for a, qd in moving:
        np.testing.assert_allclose(a, -np.sign(qd), rtol=0, atol=1e-9)   # sliding: the bound, against the motion
    assert all(a @ qd <= 1e-12 for a, qd in log)         # dissipative at every step: a opposes the velocity it leaves
    # the friction slows the fall but does not stop it (gravity's moments exceed 1 N m)
    fell, fell_free = (q0 - sliding.q)[cols], (q0 - free.q)[cols]
    assert np.all(fell > 0.02) and np.all(fell < fell_free)


def test_joint_friction_follows_a_stiff_implicit_step_and_refuses_a_negative_bound():
    """das3 (its girdle stiff under ROS2's implicit step): a joint that sticks ends each step at rest to 1e-5 rad/s
    (3.7e-7 measured; 4e-3 without the re-centring) and no step's friction pushes along the velocity it leaves (the
    moments are solved on the arm's own step, not on an explicit prediction qdot + h qddot, which on das3 gave
    moments along the motion, adding 1.2e-3 J in 300 steps)."""
    arm, q0, log = _free_fall_with_friction(1e3, ["GHy", "ELx"], steps=100, model="das3")
    cols = [arm.dof_index(d) for d in ("GHy", "ELx")]
    assert max(np.abs(qd[cols]).max() for _, qd in log) < 1e-5
    # within a step a stuck joint still moves while the girdle settles (velocity-level friction holds the step's
    # end): 3e-4 rad in 100 steps, against 0.06 and 0.11 rad of the free fall
    assert np.abs(arm.q[cols] - q0[cols]).max() < 1e-3
    _, _, log = _free_fall_with_friction(1.0, ["GHy", "ELx"], steps=100, model="das3")
    assert all(a @ qd <= 1e-12 for a, qd in log)
    for bad in (-1.0, np.nan, np.inf):
        with pytest.raises(ValueError, match="friction_Nm must be finite and >= 0"):
            v.joint_friction(arm, bad)


def test_run_offline_adds_the_joint_moment_to_the_plants_own_and_restores_it(setup):
    """joint_moment is added to the moment the plant holds (an exoskeleton's, say), the callable sees copies of
    q and qdot and the plant without its previous output, and the plant's own moment is back after the run."""
    arm, coding, _ = setup
    plant = copy.deepcopy(arm)
    plant.reset()
    own = np.zeros(plant.n_dofs)
    own[plant.dof_index("ELx")] = 0.4
    plant.set_applied_moment(own)
    ctl = fc.PDController(arm, coding, plant.q.copy(), fc.PDParams(1.0, 0.1))
    seen = []

    def extra(t, q, qdot):
        seen.append(plant.applied_moment)
        q[:] = 99.0  # a copy: the plant is not touched
        out = np.zeros(plant.n_dofs)
        out[plant.dof_index("GHy")] = -0.25
        return out
    run = fc.run_offline(plant, ctl, 0.05, joint_moment=extra)
    assert len(seen) == round(0.05 / plant.dt) and all(np.array_equal(s, own) for s in seen)
    assert np.all(np.abs(run.q) < 10.0)
    assert np.array_equal(plant.applied_moment, own)
    with pytest.raises(ValueError, match="joint_moment.*NaN"):
        fc.run_offline(plant, ctl, 0.01, joint_moment=lambda t, q, qd: np.full(plant.n_dofs, np.nan))
    assert np.array_equal(plant.applied_moment, own)   # restored after a refused moment too


def test_pd_tracks_with_added_joint_friction(setup):
    """Jagodnik 2010 Table 4: 1.0 N m of added friction raised their 2-gain PD's error to 6.08 deg (SS 4.06 deg, 14
    of 1000 failed). Ours on three test movements: still tracking, every trial arriving; its final posture within
    the dead band 1 N m opens in this PD's loop (a static 1 N m moves the PD-held elbow 1.6-1.8 deg,
    docs/control.md) of the friction-free one."""
    arm = setup[0]
    kp, kd = v.saved_pd_gains()
    moves = v.pd_movements(3, 2, arm.rest_posture)
    cols = [arm.dof_index(d) for d in v.PD_DOFS]
    for mv in moves:
        plain = v.pd_trial(kp, kd, mv, setup)
        rough = v.pd_trial(kp, kd, mv, setup, friction_Nm=v.JAGODNIK_FRICTION_NM)
        assert not rough["failed"] and rough["error_deg"] < 6.08
        gap = np.degrees(np.abs(rough["run"].q[-1, cols] - plain["run"].q[-1, cols]))
        assert gap.max() < 2.0
        assert np.any(rough["run"].q[-1, cols] != plain["run"].q[-1, cols])  # the friction acted


# ------------------------------------------------------------------------------------------ (c) posture, GH limit
def test_posture_holding_keeps_simulated_ghstab_under_the_limit(setup):
    free = v.posture_trial(None, duration=2.0, setup=setup)
    held = v.posture_trial(0.06, duration=2.0, setup=setup)
    assert free["gh_stab_max"] > 0.08                    # without the limit the hold's GHstab is above it
    assert held["model_gh_stab_max"] <= 0.06 + 1e-6      # the inverse model keeps its bound
    assert held["gh_stab_max"] <= 0.06 * 1.02            # and the simulated arm (the engine's GHstab) follows
    assert held["max_deg"] < 2.0 and held["infeasible"] == 0


@pytest.mark.slow
def test_posture_full_protocol_under_fatigue():
    rows = v.posture(None)
    for r in rows[1:]:
        # the inverse model holds the bound; the simulated arm's lagged forces go up to 2.5 % over (docs/control.md)
        assert r["model_gh_stab_max"] <= r["limit"] + 1e-6, r["limit"]
        assert r["gh_stab_max"] <= r["limit"] * 1.03 and r["max_deg"] < 5.0, r["limit"]


@pytest.mark.slow
def test_pd_full_test_set():
    conds = v.jagodnik(None)
    assert conds["generality"]["error_deg"] < 5.50 and conds["generality"]["failed"] == 0
    assert conds["doubled mass + weakened"]["error_deg"] < 10.0


def test_control_loop_drives_the_realtime_runner_over_udp(setup):
    """The cheap default-run check of the UDP path: the PD (a cheap update) holds the rest posture through
    fes_control_udp.control_loop against an in-process RealtimeSession for 1 s of simulated time."""
    from armrt.fes_control_udp import control_loop, first_state
    from armrt.realtime import RealtimeSession, UdpClient
    arm, coding, _ = setup
    kp, kd = v.saved_pd_gains()
    ctl = fc.PDController(arm, coding, arm.rest_posture, fc.PDParams(kp, kd))
    with RealtimeSession(model="das2", profile="participant_A_FES", stimulation="per_muscle", listen="127.0.0.1:0",
                         state_rate_hz=1000, input_timeout=5.0, q0=arm.rest_posture) as s:
        with UdpClient(s.port, stimulation="per_muscle") as c:
            c.join(timeout=5.0)
            t0 = first_state(c).time
            r = control_loop(ctl, c, t0 + 1.0)
        stats = s.stop()
    assert r["time"].size > 20 and stats["packets"]["stimulation_applied"] >= r["time"].size
    assert np.all(np.diff(r["time"]) > 0) and r["time"][-1] >= t0 + 1.0
    assert {"p50", "p90", "p99", "max"} <= set(r["compute_us"]) and r["period_s"].size == r["time"].size - 1
    # held near rest: unstimulated, the arm drops 30 deg at the elbow and 10 deg at GHz in the same 1 s
    assert np.degrees(np.abs(r["q"][-1] - arm.rest_posture)).max() < 5.0


@pytest.mark.slow
def test_optimise_pd_reproduces_the_saved_gains():
    """optimise-pd rerun (not saved) finds the gains in fes_pd_gains.json: the PD trials are deterministic (no QP)."""
    out = v.optimise_pd(save=None)
    kp, kd = v.saved_pd_gains()
    assert out["kp_per_rad"] == pytest.approx(kp, rel=1e-6) and out["kd_s_per_rad"] == pytest.approx(kd, rel=1e-6)


def test_run_offline_joint_moment_takes_opensim_coordinate_names():
    """A joint_moment callable may name DOFs as set_applied_moment does (EL_x for ELx): the same run as the array
    form, and the plant's own moment restored after."""
    runs = []
    for form in ({"EL_x": 0.5}, np.array([0, 0, 0, 0.5, 0])):
        plant = armrt.Arm("das2", stimulation="per_muscle")
        coding = fc.StimulationCoding.from_arm(plant)
        pd = fc.PDController(plant, coding, plant.model.rest_posture, fc.PDParams(1.0, 0.3))
        runs.append(fc.run_offline(plant, pd, 0.03, joint_moment=lambda t, q, qdot, f=form: f).q)
        np.testing.assert_array_equal(plant.applied_moment, np.zeros(plant.n_dofs))
    np.testing.assert_array_equal(runs[0], runs[1])


def test_controllers_refuse_a_wrong_coding_reference_or_argument_order_with_a_clear_error(setup, tmp_path):
    """From a fresh-user trial: a None coding, a .mot path as the reference and run_offline's arguments swapped
    ended in AttributeErrors or 'takes 4 positional arguments but 12 were given'; time running backwards in one
    trial left the integral silently unadvanced."""
    from types import SimpleNamespace

    from armrt.opensim_io import write_mot

    arm, coding, tau = setup
    params = fc.PIDParams.pole_placement(tau)
    t_ref, q_ref = v.movement_reference(arm, {"ELx": 10.0}, 1.0)
    with pytest.raises(TypeError, match="coding must be a StimulationCoding"):
        fc.FeedforwardPID(fc.model_arm(arm), None, (t_ref, q_ref), params)
    with pytest.raises(TypeError, match="coding must be a StimulationCoding"):
        fc.PDController(arm, None, arm.rest_posture, fc.PDParams(1.0, 0.3))
    with pytest.raises(TypeError, match="reference must be a Reference"):
        fc.FeedforwardPID(fc.model_arm(arm), coding, q_ref, params)
    # A .mot is a reference: the same samples as the arrays it was written from (radians, OpenSim names).
    mot = write_mot(SimpleNamespace(time=t_ref, q=q_ref, dof_names=list(arm.dof_names), model=arm.model_name),
                    tmp_path / "ref.mot")
    from_file = fc.FeedforwardPID(fc.model_arm(arm), coding, mot, params)
    np.testing.assert_allclose(from_file.reference(0.4)[0], fc.Reference(t_ref, q_ref, arm.model)(0.4)[0], atol=1e-9)
    ff = fc.FeedforwardPID(fc.model_arm(arm), coding, (t_ref, q_ref), params)
    with pytest.raises(TypeError, match=r"run_offline\(plant, controller, duration\): plant must be an armrt.Arm"):
        fc.run_offline(ff, arm, 0.1)
    with pytest.raises(TypeError, match="controller must be a FeedforwardPID"):
        fc.run_offline(arm, arm, 0.1)
    q, z = arm.q.copy(), np.zeros(arm.n_dofs)
    ff.update(0.5, q, z)
    with pytest.raises(ValueError, match="before the last update's 0.5 s.*reset"):
        ff.update(0.2, q, z)
    ff.reset()
    ff.update(0.2, q, z)


def test_an_infeasible_inverse_model_is_marked_in_the_run_and_warned(setup):
    """A 0.15 s shoulder movement on the weakened arm: the inverse model cannot give what it asks on some
    updates (the closest levels are sent). ControlRun.feasible marks those rows and run_offline warns, instead
    of a finished run whose only trace was the controller's state (a fresh-user trial)."""
    arm, coding, tau = setup
    plant = v.weakened_arm()
    q0 = plant.q.copy()
    q1 = q0.copy()
    q1[plant.dof_index("GHy")], q1[plant.dof_index("GHz")] = np.radians(55), np.radians(80)
    t = np.linspace(0, 3, 301)
    q_ref = fc.minimum_jerk(q0, q1, 0.2, 0.15, t)[0]
    ff = fc.FeedforwardPID(fc.model_arm(plant), coding, (t, q_ref), fc.PIDParams.pole_placement(tau))
    with pytest.warns(RuntimeWarning, match=r"updates found no stimulation.*ControlRun.feasible"):
        run = fc.run_offline(plant, ff, 0.5)
    assert run.feasible.shape == run.time.shape and run.feasible[0]
    assert run.infeasible_updates == ff.state.infeasible_updates > 0
    # A feasible run has every row marked and no warning.
    easy = v.weakened_arm()
    pd = fc.PDController(easy, coding, easy.rest_posture, fc.PDParams(1.0, 0.3))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        quiet = fc.run_offline(easy, pd, 0.05)
    assert quiet.feasible.all() and quiet.infeasible_updates == 0
