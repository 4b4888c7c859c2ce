"""LQR posture holding: das2 held at a posture with some co-contraction against a push at the hand, by discrete
linear-quadratic feedback on Arm.linearize()'s (A, B) (docs/control.md "Linearised dynamics").

    python examples/lqr_posture.py                      # prints the deviations with and without feedback
    python examples/lqr_posture.py --push 40 --push-duration 0.1

1. Baseline excitation u0 holding the posture: the moment balance R^T F(u) + tau_passive + b(q, 0, g) = 0 at the
   posture with each element's isometric force linear in activation between its passive (a = 0) and full (a = 1)
   force at its equilibrium fibre length, solved by scipy.optimize.lsq_linear with every u in [cocontraction, 0.6]
   (the lower bound is the co-contraction: it keeps every muscle active, so the controller can push both ways).
   The linear force model is then corrected with the engine's own acceleration at the posture (a few lsq_linear
   steps) until the posture is an equilibrium of forward(): qdot = 0, fibres in equilibrium, qdd ~ 0. That is x0.
2. Open loop the posture is unstable at this co-contraction (dfdx has eigenvalues with positive real part): the
   arm drifts off it even without a push.
3. A, B = arm.linearize() at (x0, u0); K from the discrete algebraic Riccati equation (scipy.linalg.
   solve_discrete_are) with Q on the joint angles and velocities and a little on the CE lengths and activations
   (so that Q's null space is stable), R = r I: u = u0 - K (x - x0), clipped to [0, 1] (Anderson & Moore, Optimal
   Control: Linear Quadratic Methods, Prentice Hall 1990, ch. 2-3: the discrete-time regulator).
4. A hand-force pulse (Arm.set_hand_load) with and without the feedback: the largest hand and joint deviations
   from x0 during and after the push.
"""
from __future__ import annotations

import argparse
import warnings

import numpy as np
import scipy.linalg
import scipy.optimize

import armrt
from armrt import StatePart

POSTURE = {"GHy": 0.4, "GHz": 0.6, "GHyy": 0.3, "ELx": 1.2, "PSy": 1.4}  # rad: arm forward, elbow flexed


U_MAX = 0.6  # the baseline's largest excitation


def baseline_excitation(arm: armrt.Arm, q: np.ndarray, cocontraction: float, u_max: float = U_MAX) -> np.ndarray:
    """u (n_elements,) in [cocontraction, u_max] whose isometric forces balance gravity and the passive joint moments
    at q (least squares on the moment balance, scipy.optimize.lsq_linear)."""
    n = arm.n_elements
    L, R = arm._sim.muscle_paths(q)            # R: (n, ndof) m
    f_pass, f_full = np.zeros(n), np.zeros(n)
    for i in range(n):
        for a, out in ((0.0, f_pass), (1.0, f_full)):
            lce = arm._sim.muscle_equilibrium_lce(i, L[i], a)
            out[i] = arm._sim.muscle_element(i, L[i], lce, a)[0]
    tau_p = arm._sim.passive_joint_torque(q, np.zeros(arm.n_dofs))
    bias = arm._sim.bias_force(q, np.zeros(arm.n_dofs))  # M qdd = tau + b
    # R^T (f_pass + a (f_full - f_pass)) + tau_p + b = 0  ->  (R^T diag(df)) a = -(R^T f_pass + tau_p + b)
    G = R.T * (f_full - f_pass)
    u = scipy.optimize.lsq_linear(G, -(R.T @ f_pass + tau_p + bias), bounds=(cocontraction, u_max)).x
    # The forces are not linear in activation (the fibre's force-length curve moves with the tendon's stretch):
    # correct u with the engine's own imbalance M qdd at the state reset() gives (qdot 0, fibres in equilibrium),
    # G as the slope, until the posture's acceleration is below 1e-6 rad/s^2 or 20 corrections.
    probe = armrt.Arm(arm.model)
    M = arm.mass_matrix(q)
    for corrections in range(21):
        probe.set_excitation(u)
        probe.reset(q=q, activation=u)
        qdd = probe._sim.state_derivative()[arm.n_dofs:2 * arm.n_dofs]  # of the u returned, the last one included
        if np.abs(qdd).max() < 1e-6 or corrections == 20:
            break
        u = scipy.optimize.lsq_linear(G, G @ u - M @ qdd, bounds=(cocontraction, u_max)).x
    if np.abs(qdd).max() >= 1e-6:
        # An LQR about a point that is no equilibrium regulates towards a moving state: said, not printed only (a
        # fourth trial's posture stopped at |qdd| 0.15 rad/s^2 and the script went on).
        warnings.warn(f"the baseline excitation is no equilibrium of this posture: |qdd| = {np.abs(qdd).max():.2g} "
                      f"rad/s^2 after 20 corrections (excitations within [{cocontraction:g}, {u_max:g}]); the LQR is "
                      f"designed about a point the arm accelerates from", RuntimeWarning, stacklevel=2)
    return u


def lqr_gain(lin, q_weight: float, qd_weight: float, r_weight: float) -> np.ndarray:
    """K (n_elements, ns) of the discrete LQR on (A, B): Q on q (1/rad^2) and qdot (s^2/rad^2), 1e-3 of that scale
    on lce (per lceopt-sized 1e-2 m) and activations, R = r_weight I (Anderson & Moore 1990, the discrete regulator)."""
    ns = lin.A.shape[0]
    Q = np.zeros(ns)
    Q[lin.slices["q"]] = q_weight
    Q[lin.slices["qdot"]] = qd_weight
    Q[lin.slices["lce"]] = 1e-3 * q_weight / 1e-4
    Q[lin.slices["activation"]] = 1e-3 * q_weight
    Q = np.diag(Q)
    R = r_weight * np.eye(lin.B.shape[1])
    P = scipy.linalg.solve_discrete_are(lin.A, lin.B, Q, R)
    return np.linalg.solve(R + lin.B.T @ P @ lin.B, lin.B.T @ P @ lin.A)


def lin_slice(arm) -> slice:
    """The qdot block of forward()'s dx/dt (its qdd)."""
    o, n = arm.model.state_layout["qdot"]
    return slice(o, o + n)


def run(arm0: armrt.Arm, x0, u0, K, push_N, push_start, push_duration, duration):
    """Copies arm0, starts at x0, applies the push (N, thorax frame) over [push_start, push_start + push_duration]
    and u = u0 - K (x - x0) clipped to [0, 1] (K None: u0 open loop). Returns time, q, hand position, u."""
    arm = arm0.__deepcopy__({})
    arm.set_state_vector(x0, StatePart.PHYSICS)
    arm.set_hand_load((0.0, 0.0, 0.0))
    n = int(round(duration / arm.dt))
    t, qs, hand, us = np.arange(n) * arm.dt, np.zeros((n, arm.n_dofs)), np.zeros((n, 3)), np.zeros((n, arm.n_elements))
    for k in range(n):
        on = push_start <= t[k] < push_start + push_duration
        arm.set_hand_load(push_N if on else (0.0, 0.0, 0.0))
        x = arm.get_state_vector(StatePart.PHYSICS)
        u = u0 if K is None else np.clip(u0 - K @ (x - x0), 0.0, 1.0)
        arm.set_excitation(u)
        qs[k], hand[k], us[k] = arm.q, arm.hand_position, u
        arm.step(1)
    return t, qs, hand, us


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--push", type=float, default=30.0, help="push force (N), forward (+x of the thorax frame)")
    p.add_argument("--push-duration", type=float, default=0.1, help="s")
    p.add_argument("--cocontraction", type=float, default=0.05, help="lowest baseline excitation")
    p.add_argument("--duration", type=float, default=1.5, help="s after settling")
    p.add_argument("--q-weight", type=float, default=1e4)
    p.add_argument("--qd-weight", type=float, default=1e2)
    p.add_argument("--r-weight", type=float, default=1.0)
    args = p.parse_args(argv)
    if not 0.0 <= args.cocontraction < U_MAX:  # lsq_linear needs lower < upper bounds; a negative one is no excitation
        p.error(f"--cocontraction must be in [0, {U_MAX:g}) (the baseline's excitations lie in [cocontraction, "
                f"{U_MAX:g}]), got {args.cocontraction:g}")

    arm = armrt.Arm("das2")
    q = np.array([POSTURE[d] for d in arm.dof_names])
    u0 = baseline_excitation(arm, q, args.cocontraction)
    arm.set_excitation(u0)
    arm.reset(q=q, activation=u0)
    x0 = arm.get_state_vector(StatePart.PHYSICS)
    qdd0 = np.abs(arm._sim.state_derivative()[lin_slice(arm)]).max()
    lin = arm.linearize()
    growth = np.linalg.eigvals(arm.linearize(continuous=True).dfdx).real.max()
    K = lqr_gain(lin, args.q_weight, args.qd_weight, args.r_weight)
    rho = np.abs(np.linalg.eigvals(lin.A - lin.B @ K)).max()
    push = (args.push, 0.0, 0.0)
    hand0 = arm.hand_position.copy()
    out = {}
    for name, gain, f in (("open loop, no push", None, 0.0), ("open loop", None, args.push), ("LQR", K, args.push)):
        t, qs, hand, us = run(arm, x0, u0, gain, (f, 0.0, 0.0), 0.2, args.push_duration, args.duration)
        out[name] = {"t": t, "q": qs, "hand": hand, "u": us,
                     "hand_dev_mm": 1e3 * np.linalg.norm(hand - hand0, axis=1).max(),
                     "joint_dev_deg": np.degrees(np.abs(qs - x0[lin.slices["q"]]).max()),
                     "final_hand_mm": 1e3 * np.linalg.norm(hand[-1] - hand0),
                     "u_range": (float(us.min()), float(us.max()))}
    print(f"posture {np.round(np.degrees(q), 1)} deg; baseline excitation {u0.min():.3f}-{u0.max():.3f} "
          f"(mean {u0.mean():.3f}); |qdd| there {qdd0:.1e} rad/s^2; fastest open-loop growth rate {growth:.2f} 1/s")
    print(f"LQR: spectral radius of A - B K {rho:.4f}; push {args.push:g} N for {args.push_duration * 1e3:g} ms")
    for name, r in out.items():
        print(f"  {name:18s}: largest hand deviation {r['hand_dev_mm']:6.1f} mm, joints {r['joint_dev_deg']:5.2f} deg, "
              f"hand {r['final_hand_mm']:5.1f} mm off at the end; u in [{r['u_range'][0]:.3f}, {r['u_range'][1]:.3f}]")
    return {"rho": rho, "growth": growth, "qdd0": qdd0, "runs": out, "u0": u0, "x0": x0, "K": K}


if __name__ == "__main__":
    main()
