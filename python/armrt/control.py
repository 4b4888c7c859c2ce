"""Inverse dynamics and static optimisation with a gleno-humeral stability bound (docs/control.md).

    tau = armrt.inverse_dynamics(arm, q, qdot, qddot, hand_load=None)      # (ndof,) N m the muscles must supply
    res = armrt.static_optimization(arm, q, gh_stab_max=0.5)               # activations (n,) in [0, max_activation]
    so = armrt.StaticOptimizer(arm, gh_stab_max=0.5); so.solve(q, ...)      # warm-started, for a loop
    armrt.static_optimization_motion(arm, "trial.mot")                      # activations per frame

The inverse dynamics is the engine's (inverse_dynamics.cc): forward()'s equation of motion solved for the muscles'
generalised forces. Static optimisation minimises the sum of (weighted) squared or cubed activations subject to
those moments, the activation bounds of the arm's settings and, optionally, GHstab <= gh_stab_max as a polygon of
linear constraints on the GH force; the muscle force as a function of activation is the engine's element at the
CE length where its fibre velocity equals the path's lengthening speed (elastic tendon, solved by sequential QP),
or the rigid-tendon approximation (linear, one QP). The QP solver is ProxQP (proxsuite, dense backend).

This module imports no other armrt module but checks, errors and _core: Arm and Model call into it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .checks import MAX_HAND_FORCE, MAX_HAND_MOMENT  # noqa: F401 (N, N m; re-exported)
from .checks import hand_load as _checked_hand_load
from .checks import (count, dof_vector, joint_acceleration_within, joint_range, joint_speed_within, real_array,
                     real_scalar)
from .errors import StaticOptimizationInfeasible

# Below |theta| tan|theta| = 1/2 (|theta| < 0.6533 rad), atan(u)^2 is convex in u = tan(theta), so the set of
# GH force directions with GHstab <= s is convex while both rim half-angles times sqrt(s) stay below it.
CONVEX_HALF_ANGLE = 0.6532711870  # rad, the root of x tan x = 1/2
# Beyond this (rad) the bound's ellipse approaches the glenoid plane (theta -> pi/2): refused.
MAX_BOUND_HALF_ANGLE = 1.45
POLYGON_SIDES = 24
MAX_POLYGON_SIDES = 64  # cpp/include/armrt/static_optimization.h kMaxGhPolygonSides: both backends take the same
MOMENT_TOLERANCE = 1e-7  # N m, the SQP's stop on the moment residual (|.|_inf), below the 1e-6 acceptance
_INF = 1e20


# ---------------------------------------------------------------------------------------------- inputs
def _target(arm_or_model):
    """(core arm with the settings to use, Model, hand load (force, moment) when None is given)."""
    sim = getattr(arm_or_model, "_sim", None)
    if sim is not None:  # armrt.Arm
        return sim, arm_or_model.model, (np.array(sim.hand_force), np.array(sim.hand_moment))
    d = getattr(arm_or_model, "_def", None)
    if d is None:
        raise TypeError(f"expected an armrt.Arm or armrt.Model, got {type(arm_or_model).__name__}")
    return _default_arm(arm_or_model), arm_or_model, (np.zeros(3), np.zeros(3))


_DEFAULT_ARMS: dict[int, object] = {}


def _default_arm(model):
    """A private engine arm of a Model with the default settings (intact strength, max_activation 1, the
    model's gravity): what a Model's static optimisation uses."""
    from . import _core  # noqa: PLC0415 (the extension, not an armrt module: no cycle)
    key = model._def.address
    if key not in _DEFAULT_ARMS:
        _DEFAULT_ARMS[key] = _core.Arm(model._def, "rk4", 1e-3)
    return _DEFAULT_ARMS[key]


def _dof_vector(model, v, what: str, allow_scalar_zero: bool = False) -> np.ndarray:
    nd = model.n_dofs
    # booleans=False: a posture, speed or acceleration is never a flag (q=[True, False, ...] was taken as 1 and 0 rad).
    if allow_scalar_zero and np.isscalar(v) and not isinstance(v, (str, bytes)):
        x = real_scalar(v, what, booleans=False)
        if x != 0:
            raise ValueError(f"{what}: a scalar must be 0 (for every DOF), got {x:g}; give an array of shape ({nd},) "
                             "otherwise")
        return np.zeros(nd)
    return np.ascontiguousarray(dof_vector(v, what, model.dof_names, booleans=False), dtype=float)


def _hand_load(hand_load, default) -> tuple[np.ndarray, np.ndarray]:
    """None -> default; a force (3,) N; (force (3,), moment (3,)) or [force, moment] (2, 3); a (6,) [force, moment];
    or {"force": (3,), "moment": (3,)} (either may be left out: zero), thorax frame. KeyError for another key (a
    misspelt "moment" would otherwise be a zero moment)."""
    if hand_load is None:
        return default
    if isinstance(hand_load, dict):
        unknown = [k for k in hand_load if k not in ("force", "moment")]
        if unknown:
            raise KeyError(f"hand_load: unknown key(s) {unknown}; a hand_load dict has 'force' (3,) N and 'moment' "
                           f"(3,) N m")
        return _checked_hand_load(hand_load.get("force", np.zeros(3)), hand_load.get("moment", np.zeros(3)))
    if isinstance(hand_load, tuple) and len(hand_load) == 2:
        return _checked_hand_load(*hand_load)
    a = real_array(hand_load, "hand_load", booleans=False)
    if a.shape == (3,):
        return _checked_hand_load(a, np.zeros(3))
    if a.shape == (6,):
        return _checked_hand_load(a[:3], a[3:])
    if a.shape == (2, 3):
        return _checked_hand_load(a[0], a[1])
    raise ValueError(f"hand_load must be a force (3,) N, (force, moment), a (6,) [force, moment] or "
                     f"{{'force': ..., 'moment': ...}} (thorax frame), got shape {a.shape}")


def _state(model, q, qdot, qddot, sim=None):
    """(q, qdot, qddot) checked; with sim (the engine arm), qdot within its max_joint_speed, the bound a step and
    set_state_vector hold (a faster joint is a diverged simulation, not a state to solve for)."""
    q = joint_range(_dof_vector(model, q, "q"), model.dof_names, model.dof_ranges, warn=False)
    qd = _dof_vector(model, qdot, "qdot", True)
    vmax = getattr(sim, "max_joint_speed", None)
    if vmax is not None:
        joint_speed_within(qd, model.dof_names, vmax, "the arm (the bound its step holds)")
    return q, qd, _dof_vector(model, qddot, "qddot", True)


# Beyond these a static optimisation is refused (ValueError), not attempted; the engine's constants
# (static_optimization.h), which armrt-rt holds its targets to as well. At a 1e16 N hand load ProxQP's closest-solution
# QPs ran for minutes (absolute tolerances below what doubles resolve), while up to 1e14 N they report the frame
# infeasible in about a second. The bounds are far above anything an arm bears or does (1e5 N is ten tonnes in the
# hand; a baseball pitch's shoulder reaches about 1e3-1e4 rad/s^2). The hand-load bounds hold for every hand load
# (checks.hand_load).
def _engine_max_joint_acceleration() -> float:
    from . import _core  # noqa: PLC0415 (the extension, not an armrt module: no cycle)
    return _core.STATIC_OPTIMIZATION_MAX_JOINT_ACCELERATION


MAX_JOINT_ACCELERATION = _engine_max_joint_acceleration()  # rad/s^2 (per DOF)


def _engine_min_gh_stab_max() -> float:
    from . import _core  # noqa: PLC0415 (the extension, not an armrt module: no cycle)
    return _core.STATIC_OPTIMIZATION_MIN_GH_STAB_MAX


# Smaller GH bounds are refused: a cone under 1 mrad about the glenoid normal, below what the solvers resolve
# (static_optimization.h kMinGhStabMax says why; armrt-rt refuses the same).
MIN_GH_STAB_MAX = _engine_min_gh_stab_max()


def check_on_infeasible(on_infeasible) -> None:
    """ValueError unless on_infeasible is "raise" or "return"."""
    if on_infeasible not in ("raise", "return"):
        raise ValueError(f"on_infeasible must be 'raise' or 'return', got {on_infeasible!r}")


# ---------------------------------------------------------------------------------------------- inverse dynamics
def inverse_dynamics(arm_or_model, q, qdot=0.0, qddot=0.0, hand_load=None, parts: bool = False):
    """The generalised forces tau_muscle (ndof,) N m the muscles must supply for the arm to have the joint
    accelerations qddot at (q, qdot): forward()'s M(q) qddot = tau_muscle + tau_passive + tau_ext + tau_girdle +
    b(q, qdot, g) solved for tau_muscle (cpp/src/inverse_dynamics.cc). Passive joint moments, gravity (the arm's
    setting, a Model's default), the hand load's generalised force and, for das3, the scapulothoracic contact and
    conoid forces are accounted for: they are not in tau_muscle. Every DOF is returned; in das2 and das3 every
    DOF is crossed by muscle elements, so each is actuated (das3's girdle DOFs by the trapezius, serratus,
    levator scapulae, rhomboids, pectoralis minor... together with its contact and ligament forces).

    q, qdot, qddot: (ndof,) rad, rad/s, rad/s^2 (qdot, qddot may be 0). hand_load: None (an Arm's present
    hand load, zero for a Model), a force (3,) N, (force, moment) or a (6,) [force, moment] in the thorax frame.
    parts=True returns a dict: tau_muscle, mass_times_qddot, bias (b), passive, external, girdle (ndof,) and
    gh_force_without_muscles (3,) N, scapula frame. ValueError for NaN, wrong shapes, q far beyond range or a result that
    overflows (inputs near the largest double); TypeError for q, qdot, qddot that are not numbers, bools included
    (q=[True, False, ...] would be 1 and 0 rad)."""
    sim, model, default_load = _target(arm_or_model)
    if not isinstance(parts, (bool, np.bool_)):
        raise TypeError(f"parts must be True or False, got {type(parts).__name__} {parts!r}")
    q, qd, qdd = _state(model, q, qdot, qddot, sim)
    f, m = _hand_load(hand_load, default_load)
    if hasattr(arm_or_model, "_sim"):
        out = sim.inverse_dynamics(q, qd, qdd, f, m)
    else:
        out = model._def.inverse_dynamics(q, qd, qdd, np.ascontiguousarray(model.gravity_base), f, m)
    # Finite inputs near the largest double (a 1.7e308 N hand force) overflow in M qddot or J^T F: a NaN or inf
    # answer is refused, not returned.
    bad = [name for name, v in out.items() if not np.all(np.isfinite(v))]
    if bad:
        raise ValueError(f"inverse dynamics overflowed ({', '.join(bad)} not finite): qddot (max |qddot| "
                         f"{float(np.max(np.abs(qdd))):.3g} rad/s^2) or the hand load (largest force component "
                         f"{float(np.max(np.abs(f))):.3g} N, moment component {float(np.max(np.abs(m))):.3g} N m) is beyond "
                         f"what doubles carry")
    return out if parts else out["tau_muscle"]


# ---------------------------------------------------------------------------------------------- GH polygon
def check_gh_stab_max(value) -> float | None:
    """gh_stab_max as a float, or None (no bound): the rule every holder of a GH bound applies where the bound is
    given (StaticOptimizer, gh_polygon, EndpointGains, fes_control.PIDParams). TypeError for a non-number or a bool
    (True would be a bound of 1), ValueError unless finite and > 0, and for a bound below MIN_GH_STAB_MAX (1e-6). The
    upper limit depends on the model's glenoid (the bound's ellipse within MAX_BOUND_HALF_ANGLE of its normal):
    gh_polygon checks it, where the model is known."""
    if value is None:
        return None
    v = real_scalar(value, "gh_stab_max", booleans=False)
    if not (v > 0 and math.isfinite(v)):
        raise ValueError(f"gh_stab_max must be None or a finite number > 0, got {v}")
    if v < MIN_GH_STAB_MAX:
        raise ValueError(f"gh_stab_max = {v:g} is below the smallest bound solved, {MIN_GH_STAB_MAX:g} (a cone under "
                         f"1 mrad about the glenoid normal, where the solvers' tolerances no longer resolve the bound)")
    return v


def gh_polygon(theta_a: float, phi_a: float, bound: float, sides: int = POLYGON_SIDES) -> np.ndarray:
    """Rows c (sides, 3) of linear constraints c . (F.normal, F.major, F.minor) <= 0 on a GH force F that
    imply GHstab(F) <= bound (paper eq. 5; F.normal >= 0 is a separate row), divided by sqrt(bound): the edges
    of a polygon inscribed in {(u, v) = (F.major, F.minor) / F.normal : (atan(u)/theta_a)^2 + (atan(v)/phi_a)^2 <= bound}.

    That set is convex while theta_a sqrt(bound) and phi_a sqrt(bound) stay below CONVEX_HALF_ANGLE, and the
    polygon of its boundary points is then inside it. Beyond that the set is still star-shaped about the
    origin (the function grows along every ray), so a polygon is inside it exactly when its edges are: the
    edges are checked at 64 points each and the polygon shrunk (its vertices' angles scaled by 0.99) until
    they are, which keeps the constraint conservative at the price of a bound tighter than asked
    (docs/control.md). ValueError for a bound <= 0, one whose ellipse reaches MAX_BOUND_HALF_ANGLE, or sides outside
    [3, MAX_POLYGON_SIDES]."""
    if isinstance(sides, (bool, np.bool_)) or not isinstance(sides, (int, np.integer)) or \
            not 3 <= sides <= MAX_POLYGON_SIDES:
        raise ValueError(f"polygon sides must be an integer in [3, {MAX_POLYGON_SIDES}], got {sides!r}")
    if bound is None:
        raise TypeError("gh_polygon needs a bound: a finite number > 0, got None")
    bound = check_gh_stab_max(bound)
    r = math.sqrt(bound)
    if max(theta_a, phi_a) * r >= MAX_BOUND_HALF_ANGLE:
        lim = (MAX_BOUND_HALF_ANGLE / max(theta_a, phi_a)) ** 2
        raise ValueError(f"gh_stab_max = {bound:g} puts the bound's ellipse beyond {MAX_BOUND_HALF_ANGLE} rad from "
                         f"the glenoid normal (towards the glenoid plane); give gh_stab_max < {lim:.3g}")
    psi = np.linspace(0.0, 2 * np.pi, sides, endpoint=False)
    t = np.linspace(0.0, 1.0, 64)
    scale = 1.0
    for _ in range(200):
        u = np.tan(theta_a * r * scale * np.cos(psi))
        v = np.tan(phi_a * r * scale * np.sin(psi))
        un, vn = np.roll(u, -1), np.roll(v, -1)
        eu = u[:, None] + (un - u)[:, None] * t
        ev = v[:, None] + (vn - v)[:, None] * t
        stab = (np.arctan(eu) / theta_a) ** 2 + (np.arctan(ev) / phi_a) ** 2
        # The vertices lie on the ellipse: rounding puts some 1e-16 above it, which must not shrink the polygon
        # (it did, by 1 %, at bounds such as 0.3, and differently in the engine's copy of this function).
        if stab.max() <= bound * (1 + 1e-12):
            break
        scale *= 0.99
    # Counter-clockwise vertices: the outward normal of edge k is (dv, -du); n . (u, v) <= n . p_k.
    nu, nv = vn - v, -(un - u)
    d = nu * u + nv * v
    # Divided by sqrt(bound): the edges, so the rows, shrink as sqrt(bound), and the solvers' tolerances are
    # absolute. Unscaled, |c| fell from 0.06 at a bound of 0.1 to 3e-4 at 3e-6, where ProxQP called a solution at
    # GHstab 3.5000001e-6 of a 3.5e-6 bound primal infeasible (4e-6 solved). Scaled, |c| is 0.17-0.24 for every
    # bound from 3e-6 to 0.5 (24 sides), near what the solvers were tuned on at 0.1.
    return np.column_stack([-d, nu, nv]) / r


# ---------------------------------------------------------------------------------------------- static optimisation
@dataclass
class StaticOptimizationResult:
    """One static optimisation. Arrays: activation, lce (m), force (N), by element (n,); moments (N m) by DOF
    (ndof,): tau_required (inverse dynamics), tau_muscle (R^T force of the muscle model at the activations),
    residual (tau_muscle - tau_required); gh_force (N, scapula frame) and gh_stab of those forces.
    For tendon="rigid", elastic_residual is what the same activations leave with the elastic element (its force
    at the CE length of the same fibre velocity): the rigid-tendon approximation's error. feasible False with
    report naming the DOFs with residual moments and the binding constraints."""
    activation: np.ndarray
    lce: np.ndarray
    force: np.ndarray
    tau_required: np.ndarray
    tau_muscle: np.ndarray
    residual: np.ndarray
    gh_force: np.ndarray
    gh_stab: float
    feasible: bool
    iterations: int
    objective: float
    criterion: str
    tendon: str
    gh_stab_max: float | None
    at_upper_bound: tuple[str, ...] = ()
    gh_bound_active: bool = False
    elastic_residual: np.ndarray | None = None
    report: str = ""
    fibre_velocity: np.ndarray | None = field(default=None, repr=False)

    def __repr__(self) -> str:
        return (f"StaticOptimizationResult(feasible={self.feasible}, criterion={self.criterion}, tendon={self.tendon}, "
                f"|residual|max={np.abs(self.residual).max():.2e} N m, gh_stab={self.gh_stab:.3f}, "
                f"iterations={self.iterations})")


# The largest ratio of static-optimisation weights accepted (StaticOptimizer's weight check). Measured, das2 rigid
# tendon, one weight raised: the Python path's activations are the C++ dual Newton's to 7.5e-7 at 1e6, 2.4e-5 at 1e7,
# 2.1e-4 at 1e8; at 1e11 its optimum was 1.6x the true one (ProxQP's tolerances are absolute).
MAX_WEIGHT_RATIO = 1e6


def _slack_qp(A, Cg, amax, w):
    """The closest-solution QP of the SQP's linearisation (moment rows A a' = b relaxed by free slacks s,
    (ndof,)): variables (a', s), objective |s|^2 + 1e-4 sum w a'^2, the GH rows Cg on a' only. Returns
    (H, g, A_, C_, lbox, ubox) for ProxQP."""
    nq, n = A.shape
    H = np.zeros((n + nq, n + nq))
    H[np.arange(n), np.arange(n)] = 2e-4 * w
    H[np.arange(n, n + nq), np.arange(n, n + nq)] = 2.0
    A_ = np.hstack([A, np.eye(nq)])
    C_ = np.hstack([Cg, np.zeros((Cg.shape[0], nq))])
    lbox = np.concatenate([np.zeros(n), -_INF * np.ones(nq)])
    ubox = np.concatenate([amax, _INF * np.ones(nq)])
    return H, np.zeros(n + nq), A_, C_, lbox, ubox


class StaticOptimizer:
    """Static optimisation of one arm (or a Model's default settings), keeping the ProxQP problem and the last
    activations between solves so that a controller's consecutive solves are warm started.

    criterion: "squared" (sum w_i a_i^2, Anderson & Pandy 2001) or "cubed" (sum w_i a_i^3, Crowninshield & Brand
    1981). tendon: "elastic" (the engine's element at the CE length where its fibre velocity equals the path's
    dL/dt, solved by sequential QP until the moments balance to MOMENT_TOLERANCE) or "rigid" (linear in a, one QP).
    gh_stab_max: None or a bound > 0 on GHstab (paper eq. 5) as gh_polygon's linear constraints on the GH force
    (check_gh_stab_max, then gh_polygon's model-dependent upper limit).
    weights: None (1) or (n,) > 0, largest / smallest at most MAX_WEIGHT_RATIO (1e6; ValueError; TypeError for bools,
    a mask is not weights). Bounds [0, max_activation] come from the arm's settings at each solve.
    backend: "auto" (the default: "cpp" for criterion="squared", either tendon, on an armrt Arm or Model; "python"
    for "cubed", which C++ does not solve, and for the elastic tendon with a max_iterations other than C++'s fixed
    50; bench.static_optimization_cpp: on das2's motion the elastic tendon 0.33 ms median from Python by C++
    against 2.7 ms by the Python SQP), "cpp" (the
    engine's cpp/src/static_optimization.cc: the same QPs solved in C++ by a dual projected Newton method with
    ProxQP as its fallback, for a 1 kHz loop; squared activations only and, for the elastic tendon, max_iterations
    50, ValueError otherwise; with the elastic
    tendon the same SQP and safeguards as here, and where it does not converge the Python path solves the frame
    again for its closest solution and report) or "python" (ProxQP from Python, as below). For the rigid tendon the
    two agree to the solvers' tolerance; the elastic problem is not convex, and near the damper floor's kink the two
    SQPs can stop at different local optima (objectives within 0.3 % on the bench motion:
    tests/test_static_optimization_cpp.py, docs/control.md)."""

    def __init__(self, arm_or_model, gh_stab_max=None, weights=None, criterion: str = "squared",
                 tendon: str = "elastic", polygon_sides: int = POLYGON_SIDES, max_iterations: int = 50,
                 backend: str = "auto"):
        self._sim, self.model, self._default_load = _target(arm_or_model)
        self._arm_or_model = arm_or_model
        n = self.model.n_elements
        if criterion not in ("squared", "cubed"):
            raise ValueError(f"criterion must be 'squared' or 'cubed', got {criterion!r}")
        if tendon not in ("elastic", "rigid"):
            raise ValueError(f"tendon must be 'elastic' or 'rigid', got {tendon!r}")
        self.criterion, self.tendon = criterion, tendon
        self.max_iterations = count(max_iterations, "max_iterations", minimum=1)
        if isinstance(polygon_sides, (bool, np.bool_)) or not isinstance(polygon_sides, (int, np.integer)) or \
                not 3 <= polygon_sides <= MAX_POLYGON_SIDES:
            # Fewer than 3 sides bound no area: the "polygon" would not keep GHstab under the bound at all.
            raise ValueError(f"polygon_sides must be an integer in [3, {MAX_POLYGON_SIDES}], got {polygon_sides!r}")
        if weights is None:
            self.weights = np.ones(n)
        else:
            w = real_array(weights, "weights", booleans=False)  # a bool mask is not weights (True = 1)
            if w.shape != (n,):
                raise ValueError(f"weights must have shape ({n},) (one per element), got {w.shape}")
            if not np.all(np.isfinite(w)) or np.any(w <= 0):
                raise ValueError("weights must be finite and > 0")
            ratio = float(w.max() / w.min())
            if ratio > MAX_WEIGHT_RATIO:
                # ProxQP's tolerances are absolute: with one weight 1e11 times the others the Python path returned a
                # balanced but far from optimal solution (sum of the others' a^2 1.6x the optimum; 1e10 is 0.1 % off).
                raise ValueError(f"weights span a ratio of {ratio:.3g} (largest / smallest); at most "
                                 f"{MAX_WEIGHT_RATIO:.0e} is accepted. To switch an element off, set its "
                                 f"max_activation to 0 (arm.max_activation = {{name: 0.0}}) instead of a huge weight")
            self.weights = np.ascontiguousarray(w, dtype=float)
        g = self.model.glenoid
        self._axes = np.array([g["glenoid_normal"], g["glenoid_major_axis"], g["glenoid_minor_axis"]])
        self.gh_stab_max = None
        self._gh_rows = np.zeros((0, 3))
        s = check_gh_stab_max(gh_stab_max)
        if s is not None:
            self._gh_rows = np.vstack([gh_polygon(g["rim_half_angle_major"], g["rim_half_angle_minor"], s, polygon_sides),
                                       [-1.0, 0.0, 0.0]])  # F.normal >= 0
            self.gh_stab_max = float(s)
        if backend not in ("auto", "cpp", "python"):
            raise ValueError(f"backend must be 'auto', 'cpp' or 'python', got {backend!r}")
        if backend == "cpp" and criterion != "squared":
            raise ValueError(f"backend='cpp' solves squared activations only (got criterion={criterion!r}); use "
                             f"backend='python' or 'auto'")
        from . import _core  # noqa: PLC0415 (the extension, not an armrt module: no cycle)
        # The C++ elastic SQP stops at its own fixed count of QPs: another max_iterations is the Python path's.
        cpp_iterations = tendon == "rigid" or self.max_iterations == _core.STATIC_OPTIMIZATION_MAX_SQP_ITERATIONS
        if backend == "cpp" and not cpp_iterations:
            raise ValueError(f"backend='cpp' runs the elastic tendon's SQP for at most "
                             f"{_core.STATIC_OPTIMIZATION_MAX_SQP_ITERATIONS} QPs (got max_iterations="
                             f"{self.max_iterations}); use backend='python' or 'auto' for another limit")
        cpp_able = criterion == "squared" and cpp_iterations  # what "auto" hands to C++
        engine_arm = isinstance(self._sim, _core.Arm)  # not a stand-in with the same methods (tests)
        if backend == "cpp" and not engine_arm:
            raise TypeError("backend='cpp' needs an armrt.Arm or armrt.Model (the engine's arm)")
        self.backend = "cpp" if backend == "cpp" or (backend == "auto" and cpp_able and engine_arm) else "python"
        self._cpp = None
        if self.backend == "cpp":
            self._cpp = _core.StaticOptimizationWorkspace(self._sim, 0.0 if self.gh_stab_max is None else self.gh_stab_max,
                                                          None if weights is None else self.weights, int(polygon_sides))
        self._qp = None
        self._qp_slack = None
        self._initialised = {}
        self._first_problem = {}  # (QP key, GH rows): the problem a QP object was first initialised with
        self.last_activation = None
        self._lce_guess = None
        self._last_L = None

    # -------------------------------------------------------------- the muscle model
    def _forces(self, L, v, a):
        """(lce, F, dF/da) of every element at activations a."""
        if self.tendon == "elastic":
            lce, F, dF = self._sim.steady_forces(L, v, a, self._lce_guess)
            self._lce_guess = lce
            return lce, F, dF
        lce, Fa, Fp = self._rigid
        return lce, Fa * a + Fp, Fa

    def _qp_object(self, slack: bool, n_in: int):
        from proxsuite import proxqp  # noqa: PLC0415 (a dependency, imported where the solver is built)
        n, nq = self.model.n_elements, self.model.n_dofs
        nv = n + (nq if slack else 0)
        key = "_qp_slack" if slack else "_qp"
        qp = getattr(self, key)
        if qp is None or qp.model.n_in != n_in:
            qp = proxqp.dense.QP(nv, nq, n_in, True)
            qp.settings.eps_abs = 1e-9
            # The closest-solution QP's residuals scale with the moments it cannot meet: an absolute 1e-9 alone is below
            # double precision once they pass 1e7 N m (a 1e16 N hand load spun ProxQP for minutes); relative 1e-15 is 1e-9
            # at 1e6 N m and leaves smaller problems alone.
            qp.settings.eps_rel = 1e-15 if slack else 0.0
            qp.settings.max_iter = 300 if slack else 1000
            qp.settings.verbose = False
            qp.settings.primal_infeasibility_solving = False
            qp.settings.initial_guess = proxqp.InitialGuess.WARM_START_WITH_PREVIOUS_RESULT
            self._initialised[key] = False
            setattr(self, key, qp)
        return qp

    # -------------------------------------------------------------- one solve
    def solve(self, q, qdot=0.0, qddot=0.0, hand_load=None, on_infeasible: str = "raise") -> StaticOptimizationResult:
        """Activations for the state (q, qdot, qddot) (ndof,) and hand load (as inverse_dynamics). Warm started
        from the previous solve's activations. on_infeasible: "raise" (StaticOptimizationInfeasible, with the
        result as .result) or "return" (the result with feasible False). ValueError for bad input."""
        check_on_infeasible(on_infeasible)
        model, sim = self.model, self._sim
        q, qd, qdd = _state(model, q, qdot, qddot, sim)
        f_hand, m_hand = _hand_load(hand_load, self._default_load if not hasattr(self._arm_or_model, "_sim") else
                                    (np.array(sim.hand_force), np.array(sim.hand_moment)))
        # Either backend's input; the hand load is held to MAX_HAND_FORCE, MAX_HAND_MOMENT by checks.hand_load.
        joint_acceleration_within(qdd, model.dof_names, MAX_JOINT_ACCELERATION, "static optimisation")
        if self._cpp is not None:
            res = self._solve_cpp(q, qd, qdd, f_hand, m_hand, on_infeasible)
            if res is not None:
                return res
            # The elastic SQP in C++ did not converge: the Python path's SQP, and its closest solution if that
            # does not either (C++ has no closest-solution QP for the elastic tendon).
        return self._solve_python(q, qd, qdd, f_hand, m_hand, on_infeasible)

    def _solve_python(self, q, qd, qdd, f_hand, m_hand, on_infeasible):
        """One solve by ProxQP from Python (backend "python")."""
        model, sim = self.model, self._sim
        if hasattr(self._arm_or_model, "_sim"):
            idyn = sim.inverse_dynamics(q, qd, qdd, f_hand, m_hand)
        else:
            idyn = model._def.inverse_dynamics(q, qd, qdd, np.ascontiguousarray(model.gravity_base), f_hand, m_hand)
        tau_req = idyn["tau_muscle"]
        L, R = sim.muscle_paths(q)          # (n,), (n, ndof)
        v = np.ascontiguousarray(-(R @ qd))  # dL/dt: moment arms are -dL/dq
        P = self._axes @ sim.gh_directions(q).T  # (3, n): GH force (normal, major, minor) per unit tendon force
        f0 = self._axes @ idyn["gh_force_without_muscles"]
        amax = sim.get_max_activation()
        self._rigid = sim.rigid_tendon_forces(L, v)
        # CE lengths to start the elastic element's Newton solves from: the last solve's if the paths moved
        # little since (a controller's next step), else the rigid tendon's.
        if self._lce_guess is None or self._last_L is None or np.abs(L - self._last_L).max() > 0.01:
            self._lce_guess = self._rigid[0].copy()
        self._last_L = L
        a0 = self.last_activation
        if a0 is None or a0.shape != amax.shape:
            a0 = np.minimum(0.05, amax)
        a0 = np.clip(a0, 0.0, amax)

        a, it, ok = self._sqp(a0, L, v, R, P, f0, tau_req, amax, slack=False)
        if not ok:
            a, it2, _ = self._sqp(a0, L, v, R, P, f0, tau_req, amax, slack=True)
            it += it2
        lce, F, _ = self._forces(L, v, a)
        # Feasible only if the forces returned balance the moments (the SQP's own test was on its last evaluation).
        ok = ok and float(np.abs(R.T @ F - tau_req).max()) < 1e-6
        res = self._result(a, lce, F, L, v, R, P, f0, tau_req, amax, it, feasible=ok)
        if ok:
            self.last_activation = a
        elif on_infeasible == "raise":
            raise StaticOptimizationInfeasible(res.report, res)
        return res

    def _solve_cpp(self, q, qd, qdd, f_hand, m_hand, on_infeasible):
        """One solve by the engine's static_optimization_rigid or _elastic (backend "cpp"): the result as _result
        builds it; None where the elastic SQP did not converge (the caller solves that frame in Python)."""
        sim, model = self._sim, self.model
        a, r = self._cpp.solve(sim, q, qd, qdd, f_hand, m_hand, self.tendon)
        feasible = bool(r["feasible"])
        elastic = self.tendon == "elastic"
        if elastic and not feasible:
            return None
        amax = sim.get_max_activation()
        L, R = sim.muscle_paths(q)
        names = model.element_names
        upper = tuple(names[i] for i in np.flatnonzero((amax > 0) & (a >= amax - 1e-6)))
        if elastic:
            it = r["qps"]  # the SQP's QPs, as the Python path counts them
            elastic_residual = None
            self._lce_guess, self._last_L = r["lce"], L
        else:
            it = 1 if r["solver"] == "dual_newton" else r["qps"]
            _, Fe, _ = sim.steady_forces(L, r["fibre_velocity"], a, r["lce"])
            elastic_residual = R.T @ Fe - r["tau_required"]
        res = StaticOptimizationResult(
            activation=a, lce=r["lce"], force=r["force"], tau_required=r["tau_required"], tau_muscle=r["tau_muscle"],
            residual=r["residual"], gh_force=r["gh_force"], gh_stab=float(r["gh_stab"]), feasible=feasible,
            iterations=int(it), objective=self._objective(a), criterion=self.criterion, tendon=self.tendon,
            gh_stab_max=self.gh_stab_max, at_upper_bound=upper, gh_bound_active=bool(r["gh_bound_active"]),
            elastic_residual=elastic_residual,
            report="" if feasible else self._report(r["residual"], int(it), R, amax, upper, bool(r["gh_bound_active"]),
                                                    float(r["gh_stab"])),
            fibre_velocity=r["fibre_velocity"])
        if feasible:
            self.last_activation = a
        elif on_infeasible == "raise":
            raise StaticOptimizationInfeasible(res.report, res)
        return res

    def _drop_qp(self, slack: bool) -> None:
        """Forget a QP object whose last solve did not succeed. ProxQP keeps its result and its proximal and
        penalty parameters (results.info.mu_eq, mu_in) from solve to solve, and warm starts from them: after an
        infeasible QP they held a later, feasible one from converging (the same state solved fresh converged; a
        StaticOptimizer with a GH bound stayed infeasible for good after a 3000 N load)."""
        setattr(self, "_qp_slack" if slack else "_qp", None)

    def _run_qp(self, qp, slack: bool, H, g, A, b, C, u, lbox, ubox) -> None:
        """qp.init on the QP object's first use (its preconditioner), qp.update after; then qp.solve(). A QP
        object made anew after a failed solve (_drop_qp) is initialised with the problem its predecessor was
        first initialised with, then updated to this one: the preconditioner (Ruiz scaling, kept by every
        update) is then the first problem's again. With the scaling of the problem after the failure instead,
        das2's bench motion with GHstab <= 0.1 had 3 failed QPs instead of 1 (2026-12-07,
        tests/test_static_optimization.py)."""
        n_in = C.shape[0]
        l_in = np.full(n_in, -_INF)
        key = "_qp_slack" if slack else "_qp"
        if not self._initialised[key]:
            first = self._first_problem.get((key, n_in))
            if first is None:
                qp.init(H, g, A, b, C if n_in else None, l_in if n_in else None, u if n_in else None, lbox, ubox)
                self._first_problem[(key, n_in)] = tuple(x.copy() for x in (H, g, A, b, C, u, lbox, ubox))
            else:
                H0, g0, A0, b0, C0, u0, lb0, ub0 = first
                qp.init(H0, g0, A0, b0, C0 if n_in else None, l_in if n_in else None, u0 if n_in else None, lb0, ub0)
                qp.update(H, g, A, b, C if n_in else None, l_in if n_in else None, u if n_in else None, lbox, ubox,
                          update_preconditioner=False)
            self._initialised[key] = True
        else:
            # ProxQP warm starts each solve from the last one's proximal parameters too. When a solve ends on
            # its cold restart (mu_in, mu_eq reset to 1/1.1 after the residuals stalled at mu_in <= 1e-5), every
            # later problem starts there: das2's bench motion with GHstab <= 0.1 went from 3 ProxQP iterations a
            # frame to 76-81 for the rest of the motion after one such frame, or not, by rounding-level changes
            # of q (1e-12 rad; tests/test_static_optimization.py). Proximal parameters above ProxQP's defaults are
            # put back to the defaults; the primal-dual warm start is kept.
            info, st = qp.results.info, qp.settings
            reset = info.mu_in > st.default_mu_in or info.mu_eq > st.default_mu_eq
            qp.update(H, g, A, b, C if n_in else None, l_in if n_in else None, u if n_in else None, lbox, ubox,
                      update_preconditioner=False, mu_eq=st.default_mu_eq if reset else None,
                      mu_in=st.default_mu_in if reset else None)
        qp.solve()

    def _objective(self, a):
        return float(self.weights @ (a ** 2 if self.criterion == "squared" else a ** 3))

    def _sqp(self, a, L, v, R, P, f0, tau_req, amax, slack: bool):
        """Sequential QP on the linearised muscle model; returns (a, iterations, converged). With slack the
        moment rows get free residuals s (ndof,) and the objective is |s|^2 + 1e-4 sum w a^2: about the
        closest the muscles can come (the infeasible case's report; the small activation term keeps the QP's
        conditioning at 1e4, a 1e12 ratio stalled ProxQP)."""
        n, nq = self.model.n_elements, self.model.n_dofs
        C_rows = self._gh_rows
        n_in = C_rows.shape[0]
        qp = self._qp_object(slack, n_in)
        # The optimum does not change with a common factor of the weights, but ProxQP's tolerances are absolute:
        # weights of 1e-8 (or m^3 muscle volumes) moved the answer by 0.02 and 1e9 failed a feasible problem. So the
        # QPs see the weights scaled to a mean of 1; the reported objective uses the user's (_objective).
        w = self.weights / self.weights.mean()
        a = a.copy()
        lin = self.tendon == "rigid" and self.criterion == "squared" and not slack
        converged = False
        squared_first = self.criterion == "cubed" and self.last_activation is None and not slack
        # The element's force is piecewise smooth in a: with the fibre moving, the damper's low-activation floor
        # (muscle.cc) puts a kink at a f(lce) = 0.02, where Newton's linearisation can cycle between its two
        # sides. Once the moment residual stops halving, the slopes are taken over +-1e-3 in activation (a
        # kink inside gets the mean of its sides); if it stalls again a proximal term mu sum w (a' - a)^2 is
        # added to the QP's objective, mu growing by 4 at each further stall. The linearisation still passes
        # through F(a), so a fixed point balances the moments exactly; these only change how it is reached.
        mu = 0.0
        stalls = 0
        last_resid = np.inf
        elastic_resid = np.inf  # the moment residual where the last elastic-mode step was taken
        step = np.inf
        qps = 0
        from proxsuite import proxqp  # noqa: PLC0415 (a dependency, imported where the solver runs)
        for _ in range(self.max_iterations + 1):
            lce, F, dF = self._forces(L, v, a)
            resid = float(np.abs(R.T @ F - tau_req).max())
            if slack:
                if step < 1e-9:
                    break
            elif lin and qps:
                converged = resid < 1e-6
                break
            elif not squared_first and resid < MOMENT_TOLERANCE and step < 1e-6:
                converged = True
                break
            if qps == self.max_iterations:
                break
            if qps > 1 and resid > MOMENT_TOLERANCE and resid > 0.5 * last_resid:
                stalls += 1
                if stalls > 1:
                    mu = 1.0 if mu == 0.0 else 4.0 * mu
            last_resid = resid
            if stalls and self.tendon == "elastic":
                # Slopes over +-1e-3 in activation (one-sided at a bound): a kink within that width gets the
                # mean of its two sides, so the iterates stop jumping across it.
                h = 1e-3
                lo_a, hi_a = np.maximum(a - h, 0.0), a + h
                guess = self._lce_guess
                _, F_hi, _ = self._sim.steady_forces(L, v, hi_a, lce)
                _, F_lo, _ = self._sim.steady_forces(L, v, lo_a, lce)
                self._lce_guess = guess
                wide = hi_a > lo_a
                dF = np.where(wide, (F_hi - F_lo) / np.where(wide, hi_a - lo_a, 1.0), dF)
            # Linearised moments: R^T (F + dF (a' - a)) = tau_req.
            A = R.T * dF                      # (ndof, n)
            b = tau_req - R.T @ F + A @ a
            # Linearised GH force (normal, major, minor) = f0 + P (F + dF (a' - a)).
            Cg = (C_rows @ P) * dF            # (n_in, n)
            ug = -(C_rows @ (f0 + P @ F - (P * dF) @ a))
            if slack:
                H, g, A_, C_, lbox, ubox = _slack_qp(A, Cg, amax, w)
            else:
                if self.criterion == "squared" or squared_first:
                    h = 2.0 * w
                    g = np.zeros(n)
                else:  # cubed: Newton's quadratic of sum w a^3 about a (its Hessian floored; fixed point unchanged)
                    h = 6.0 * w * np.maximum(a, 1e-3)
                    g = 3.0 * w * a ** 2 - h * a
                if mu:
                    h = h + 2.0 * mu * w
                    g = g - 2.0 * mu * w * a
                H = np.diag(h)
                A_, C_, lbox, ubox = A, Cg, np.zeros(n), amax
            self._run_qp(qp, slack, H, g, A_, b, C_, ug, lbox, ubox)
            qps += 1
            status = qp.results.info.status
            x_solved = qp.results.x.copy()
            if status != proxqp.PROXQP_SOLVED:
                self._drop_qp(slack)
                qp = self._qp_object(slack, n_in)
            if status == proxqp.PROXQP_PRIMAL_INFEASIBLE and not slack:
                if resid > 0.5 * elastic_resid:
                    # The last elastic step did not halve the moment residual: the closest moments of the
                    # linearisations do not approach a balance, the frame is out of reach from here (the force-velocity
                    # limit of a fast motion, tests/test_static_optimization.py). Stop, as SNOPT declares an elastic
                    # problem infeasible; without this a truly infeasible frame ran 80 QPs near their feasibility edge.
                    return a, qps, False
                elastic_resid = resid
                # The linearisation about a cannot balance the moments within the bounds, though the muscles may
                # (F(a) is not linear: its slope at a can understate what a' in [0, amax] reaches; das3 from the
                # previous frame's activations, bench.static_optimization). As SNOPT's elastic mode for an infeasible
                # QP subproblem (Gill, Murray & Saunders, SIAM J Optim 12:979, 2002; its l1 penalty here the
                # closest-solution QP's squared one): the step minimises the linearised moment residual, and the next
                # QP is linearised there. The fixed point is unchanged: convergence needs the moments balanced by F.
                qs = self._qp_object(True, n_in)
                Hs, gs, As, Cs, lbs, ubs = _slack_qp(A, Cg, amax, w)
                self._run_qp(qs, True, Hs, gs, As, b, Cs, ug, lbs, ubs)
                if qs.results.info.status != proxqp.PROXQP_SOLVED:
                    self._drop_qp(True)
                    return a, qps, False
                x_new = qs.results.x
            elif status != proxqp.PROXQP_SOLVED and not slack:
                return a, qps, False
            else:
                x_new = x_solved
            a_new = np.clip(x_new[:n], 0.0, amax)
            step = float(np.abs(a_new - a).max())
            a = a_new
            if squared_first:  # cubed from a cold start: the squared optimum first, then Newton on the cubes
                squared_first = False
                step = np.inf
        if not slack and not converged:
            _, F1, _ = self._forces(L, v, a)
            converged = float(np.abs(R.T @ F1 - tau_req).max()) < 1e-6
        it = qps
        return a, it, converged

    def _report(self, resid, it, R, amax, upper, gh_active, stab) -> str:
        """The infeasible solve's message: residual moment per DOF, DOFs no active element crosses, elements at
        their bound, whether the GH bound binds."""
        model = self.model
        bad = [(model.dof_names[j], resid[j]) for j in np.flatnonzero(np.abs(resid) > 1e-6)]
        lines = [f"static optimisation infeasible: the muscles cannot supply the required moments"
                 + (f" with GHstab <= {self.gh_stab_max:g}" if self.gh_stab_max is not None else "")
                 + f" (closest solution after {it} iterations):",
                 "  residual moment (achieved - required) per DOF: "
                 + (", ".join(f"{d} {r:+.4g} N m" for d, r in bad) or "none above 1e-6 N m")]
        paralysed_dofs = [model.dof_names[j] for j in range(model.n_dofs)
                          if not np.any((np.abs(R[:, j]) > 1e-9) & (amax > 0))]
        if paralysed_dofs:
            lines.append(f"  no active element crosses {', '.join(paralysed_dofs)} (all paralysed)")
        lines.append(f"  elements at their upper bound (max_activation): {len(upper)}"
                     + (f" ({', '.join(upper[:12])}{', ...' if len(upper) > 12 else ''})" if upper else ""))
        if self.gh_stab_max is not None:
            lines.append(f"  GH bound {'binding' if gh_active else 'not binding'} (GHstab of this solution {stab:.4g}, "
                         f"bound {self.gh_stab_max:g}"
                         + ("; this solution leaves the bound too: the closest-solution QP did not hold the GH rows "
                            "(no activations within their bounds bring the GH force inside it at this linearisation, "
                            "or the solver stopped short)" if stab > self.gh_stab_max + 1e-9 else "") + ")")
        return "\n".join(lines)

    def _result(self, a, lce, F, L, v, R, P, f0, tau_req, amax, it, feasible):
        model = self.model
        tau = R.T @ F
        resid = tau - tau_req
        gh_local = f0 + P @ F              # (normal, major, minor)
        gh_force = self._axes.T @ gh_local  # scapula frame (orthonormal axes)
        stab = float(model.gh_rim(gh_force)["gh_stab"])
        names = model.element_names
        upper = tuple(names[i] for i in np.flatnonzero((amax > 0) & (a >= amax - 1e-6)))
        gh_active = bool(self._gh_rows.shape[0] and np.max(self._gh_rows[:-1] @ gh_local) > -1e-6 * max(1.0, abs(gh_local[0])))
        elastic_resid = None
        if self.tendon == "rigid":
            _, Fe, _ = self._sim.steady_forces(L, v, a, self._rigid[0])
            elastic_resid = R.T @ Fe - tau_req
        report = "" if feasible else self._report(resid, it, R, amax, upper, gh_active, stab)
        return StaticOptimizationResult(
            activation=a, lce=np.asarray(lce), force=np.asarray(F), tau_required=tau_req, tau_muscle=tau,
            residual=resid, gh_force=gh_force, gh_stab=stab, feasible=feasible, iterations=it,
            objective=self._objective(a), criterion=self.criterion, tendon=self.tendon, gh_stab_max=self.gh_stab_max,
            at_upper_bound=upper, gh_bound_active=gh_active, elastic_residual=elastic_resid, report=report,
            fibre_velocity=v)


def static_optimization(arm_or_model, q, qdot=0.0, qddot=0.0, hand_load=None, gh_stab_max=None, weights=None,
                        criterion: str = "squared", tendon: str = "elastic", on_infeasible: str = "raise",
                        backend: str = "auto"):
    """Per-element activations (n,) in [0, max_activation] whose muscle forces supply the inverse dynamics'
    moments at (q, qdot, qddot) with the hand load, minimising sum w_i a_i^2 (criterion="cubed": sum w_i a_i^3),
    with GHstab <= gh_stab_max if given (StaticOptimizer has the details and a warm-started loop).

    Returns a StaticOptimizationResult (activation, lce, force, moments, residual, gh_stab...). Raises
    StaticOptimizationInfeasible (a ValueError, .result holds the closest solution and .report names the DOFs
    with residual moments and the binding constraints) when no activations within the bounds supply the moments,
    unless on_infeasible="return". ValueError for NaN or wrongly shaped q/qdot/qddot, gh_stab_max <= 0, bad
    weights. backend: as StaticOptimizer's. Sources: docs/control.md."""
    so = StaticOptimizer(arm_or_model, gh_stab_max=gh_stab_max, weights=weights, criterion=criterion, tendon=tendon,
                         backend=backend)
    return so.solve(q, qdot, qddot, hand_load, on_infeasible=on_infeasible)
