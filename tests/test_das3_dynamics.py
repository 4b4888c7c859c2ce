"""The 11-DOF DAS3 chain (codegen/eom_chain.py): generated C++ against its Python twin, physics
(Lagrange's equations by finite differences), and OpenSim 4.6's own mass matrix and inverse dynamics."""
from __future__ import annotations

import ctypes
import shutil
import subprocess

import numpy as np
import pytest

from conftest import DAS3, ROOT
from codegen.importers.das3_chain import BASE, DAS3_DOFS, OSIM_DOF, das3_bodies, girdle_points
from codegen.eom_chain import NumericChain, generate_source

RTOL = 1e-9
N = len(DAS3_DOFS)
G = np.array([0.0, -9.80665, 0.0])
OSIM_PATH = DAS3 / "das3.osim"
HARNESS = """
#include "das3_dynamics.h"
namespace d = armrt::generated::das3;
extern "C" {
void h_mass_matrix(const double* q, double* M) { d::mass_matrix(q, M); }
void h_bias_force(const double* q, const double* qd, const double* g, double* b) { d::bias_force(q, qd, g, b); }
void h_dynamics(const double* q, const double* qd, const double* g, double* M, double* b) { d::dynamics(q, qd, g, M, b); }
void h_body_poses(const double* q, double* R, double* p) { d::body_poses(q, R, p); }
void h_points(const double* q, double* p, double* J) { d::points(q, p, J); }
}
"""


def rel_err(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    return float(np.max(np.abs(a - b)) / max(np.max(np.abs(b)), 1e-300))


@pytest.fixture(scope="module")
def bodies():
    if not OSIM_PATH.exists():
        pytest.skip(f"{OSIM_PATH} not present (needs ../shared/reference/das3 beside the repository)")
    return das3_bodies(OSIM_PATH)


@pytest.fixture(scope="module")
def ref(bodies):
    return NumericChain(DAS3_DOFS, bodies, BASE)


@pytest.fixture(scope="module")
def ranges():
    import scipy.io as sio
    ms = sio.loadmat(DAS3 / "model_struct.mat", squeeze_me=True, struct_as_record=False)["model"]
    r = {str(d.name): np.asarray(d.range, float) for d in np.atleast_1d(ms.dofs)}
    return np.array([r[d] for d in DAS3_DOFS])


def random_states(ranges, n, seed):
    rng = np.random.default_rng(seed)
    for _ in range(n):
        yield (rng.uniform(ranges[:, 0], ranges[:, 1]), rng.uniform(-4.0, 4.0, N), rng.uniform(-20.0, 20.0, N),
               rng.normal(0.0, 10.0, 3))


class Lib:
    def __init__(self, path):
        self.lib = ctypes.CDLL(str(path))

    @staticmethod
    def _p(a):
        return a.ctypes.data_as(ctypes.POINTER(ctypes.c_double))

    def mass_matrix(self, q):
        M = np.zeros((N, N))
        self.lib.h_mass_matrix(self._p(np.ascontiguousarray(q, float)), self._p(M))
        return M

    def bias_force(self, q, qd, g):
        b = np.zeros(N)
        self.lib.h_bias_force(*(self._p(np.ascontiguousarray(x, float)) for x in (q, qd, g)), self._p(b))
        return b

    def dynamics(self, q, qd, g):
        M, b = np.zeros((N, N)), np.zeros(N)
        self.lib.h_dynamics(*(self._p(np.ascontiguousarray(x, float)) for x in (q, qd, g)), self._p(M), self._p(b))
        return M, b

    def points(self, q):
        p, J = np.zeros((4, 3)), np.zeros((4, 3, N))
        self.lib.h_points(self._p(np.ascontiguousarray(q, float)), self._p(p), self._p(J))
        return p, J

    def body_poses(self, q):
        R, p = np.zeros((6, 3, 3)), np.zeros((6, 3))
        self.lib.h_body_poses(self._p(np.ascontiguousarray(q, float)), self._p(R), self._p(p))
        return R, p


@pytest.fixture(scope="module")
def gen(bodies, tmp_path_factory):
    cxx = shutil.which("g++") or shutil.which("c++")
    if cxx is None:
        pytest.skip("no C++ compiler (g++) on PATH")
    out = tmp_path_factory.mktemp("das3_dynamics")
    header, source, _ = generate_source(DAS3_DOFS, bodies, BASE, "das3", points=girdle_points(DAS3 / "model_struct.mat"))
    (out / "das3_dynamics.h").write_text(header)
    (out / "das3_dynamics.cc").write_text(source)
    (out / "harness.cc").write_text(HARNESS)
    lib = out / "libdas3_dynamics.so"
    subprocess.run([cxx, "-O2", "-std=c++17", "-Wall", "-Wextra", "-Werror", "-shared", "-fPIC",
                    f"-I{ROOT / 'cpp' / 'include'}", f"-I{out}", str(out / "harness.cc"), str(out / "das3_dynamics.cc"),
                    "-o", str(lib)], check=True, capture_output=True, text=True)
    return Lib(lib)


def test_chain_reads_the_eleven_dofs_in_osim_order(bodies):
    assert [b["name"] for b in bodies] == ["clavicle", "scapula", "humerus", "ulna", "radius", "hand"]
    assert [d for b in bodies for d in b["joint"]["dofs"]] == DAS3_DOFS
    # SC, AC and GH turn about the body-fixed y, z, x (SC, AC) and y, z, y (GH) axes of das3.osim
    ax = {d: a for b in bodies for a, d in zip(b["joint"]["axes"], b["joint"]["dofs"])}
    for d, a in [("SCy", [0, 1, 0]), ("SCz", [0, 0, 1]), ("SCx", [1, 0, 0]), ("ACy", [0, 1, 0]), ("ACz", [0, 0, 1]),
                 ("ACx", [1, 0, 0]), ("GHy", [0, 1, 0]), ("GHz", [0, 0, 1]), ("GHyy", [0, 1, 0])]:
        np.testing.assert_array_equal(ax[d], a)
    assert sum(b["mass"] for b in bodies) == pytest.approx(0.156 + 0.7054 + 2.0519 + 0.5464 + 0.5464 + 0.525)


def test_generated_code_matches_its_python_twin(gen, ref, ranges):
    for q, qd, _, g in random_states(ranges, 10, 1):
        M = gen.mass_matrix(q)
        assert rel_err(M, ref.mass_matrix(q)) < 1e-13
        assert rel_err(gen.bias_force(q, qd, g), ref.bias_force(q, qd, g)) < 1e-13
        M2, b2 = gen.dynamics(q, qd, g)
        assert rel_err(M2, M) < 1e-15 and rel_err(b2, gen.bias_force(q, qd, g)) < 1e-15
        R, p = gen.body_poses(q)
        for k, name in enumerate(["clavicle", "scapula", "humerus", "ulna", "radius", "hand"]):
            Rr, pr = ref.body_pose(q, name)
            np.testing.assert_allclose(R[k], Rr, atol=1e-14)
            np.testing.assert_allclose(p[k], pr, atol=1e-14)


def test_girdle_points_and_jacobians(gen, ref, ranges):
    """TS, AI, conoid origin and insertion: positions against the twin, dp/dq against central differences."""
    pts = girdle_points(DAS3 / "model_struct.mat")
    assert [(label, body) for label, body, _ in pts] == [("TS", "scapula"), ("AI", "scapula"),
                                                         ("conoid_origin", "clavicle"), ("conoid_insertion", "scapula")]
    h = 1e-7
    for q, *_ in random_states(ranges, 5, 6):
        p, J = gen.points(q)
        for k, (_, body, x) in enumerate(pts):
            pr, Jr = ref.point(q, body, x)
            np.testing.assert_allclose(p[k], pr, atol=1e-14)
            np.testing.assert_allclose(J[k], Jr, atol=1e-14)
            Jfd = np.array([(ref.point(q + h * e, body, x)[0] - ref.point(q - h * e, body, x)[0]) / (2 * h)
                            for e in np.eye(N)]).T
            np.testing.assert_allclose(J[k], Jfd, atol=1e-8)
            # only the DOFs above the body move the point
            above = 3 if body == "clavicle" else 6
            assert np.all(J[k][:, above:] == 0)


def test_mass_matrix_symmetric_positive_definite(gen, ranges):
    for q, *_ in random_states(ranges, 20, 2):
        M = gen.mass_matrix(q)
        np.testing.assert_array_equal(M, M.T)
        assert np.linalg.eigvalsh(M).min() > 0


def test_bias_is_lagrange_equations(ref, bodies, ranges):
    """Independent of the algorithms: b = -(dM/dt qd - 1/2 d(qd'M qd)/dq) - dV/dq, by central differences."""
    h = 1e-6
    com = {b["name"]: np.array(b["com"]) for b in bodies}
    mass = {b["name"]: b["mass"] for b in bodies}

    def potential(q):
        return -sum(mass[n] * G @ (lambda Rp: Rp[1] + Rp[0] @ com[n])(ref.body_pose(q, n)) for n in mass)

    for q, qd, _, _ in random_states(ranges, 4, 3):
        Mdot = (ref.mass_matrix(q + h * qd) - ref.mass_matrix(q - h * qd)) / (2 * h)
        dT = np.array([(qd @ ref.mass_matrix(q + h * e) @ qd - qd @ ref.mass_matrix(q - h * e) @ qd) / (2 * h)
                       for e in np.eye(N)])
        dV = np.array([(potential(q + h * e) - potential(q - h * e)) / (2 * h) for e in np.eye(N)])
        expected = -(Mdot @ qd - 0.5 * dT) - dV
        assert rel_err(ref.bias_force(q, qd, G), expected) < 1e-7


# ----------------------------------------------------------------------------------------------
# OpenSim 4.6 on das3.osim, the dynamics oracle

@pytest.fixture(scope="module")
def osim_model(bodies):
    osim = pytest.importorskip("opensim", reason="opensim (pip install opensim) is not installed")
    osim.Logger.setLevelString("error")
    model = osim.Model(str(OSIM_PATH))
    model.updForceSet().clearAndDestroy()     # muscles and all other forces off: gravity and inertia only
    state = model.initSystem()
    coords = [model.getCoordinateSet().get(OSIM_DOF[d]) for d in DAS3_DOFS]
    for i, c in enumerate(coords):
        c.setSpeedValue(state, 10.0 + i)
    U = state.getU()
    u = np.array([U.get(k) for k in range(U.size())])
    assert u.size == N, "das3.osim should have exactly the 11 mobilities SC..PS (thorax welded)"
    uidx = [int(np.flatnonzero(u == 10.0 + i)[0]) for i in range(N)]
    g = model.getGravity()
    return osim, model, state, coords, uidx, np.array([g.get(k) for k in range(3)])


@pytest.mark.opensim
def test_mass_matrix_and_inverse_dynamics_vs_opensim(gen, osim_model, ranges):
    osim, model, state, coords, uidx, g = osim_model
    np.testing.assert_array_equal(g, G)
    solver = osim.InverseDynamicsSolver(model)
    worst = {"M": 0.0, "tau": 0.0}
    for q, qd, qdd, _ in random_states(ranges, 20, 11):
        for i, c in enumerate(coords):
            c.setValue(state, float(q[i]), False)
            c.setSpeedValue(state, float(qd[i]))
        model.realizeVelocity(state)
        Mo = osim.Matrix()
        model.getMatterSubsystem().calcM(state, Mo)
        Mosim = np.array([[Mo.get(i, j) for j in range(N)] for i in range(N)])[np.ix_(uidx, uidx)]
        udot = np.zeros(N)
        udot[uidx] = qdd
        t = solver.solve(state, osim.Vector.createFromMat(udot))
        tau_osim = np.array([t.get(k) for k in range(N)])[uidx]
        M, b = gen.dynamics(q, qd, g)
        worst["M"] = max(worst["M"], rel_err(M, Mosim))
        worst["tau"] = max(worst["tau"], rel_err(M @ qdd - b, tau_osim))
    print(f"max relative error vs OpenSim: {worst}")
    assert worst["M"] < RTOL and worst["tau"] < RTOL


@pytest.mark.opensim
def test_body_poses_vs_opensim(gen, osim_model, ranges):
    osim, model, state, coords, _, _ = osim_model
    bs = model.getBodySet()
    for q, *_ in random_states(ranges, 10, 12):
        for i, c in enumerate(coords):
            c.setValue(state, float(q[i]), False)
        model.realizePosition(state)
        R, p = gen.body_poses(q)
        for k, name in enumerate(["clavicle_r", "scapula_r", "humerus_r", "ulna_r", "radius_r", "hand_r"]):
            T = bs.get(name).getTransformInGround(state)
            np.testing.assert_allclose(R[k], [[T.R().get(i, j) for j in range(3)] for i in range(3)], atol=1e-12)
            np.testing.assert_allclose(p[k], [T.p().get(i) for i in range(3)], atol=1e-12)


def test_symbolic_baseline_agrees_on_the_forearm_subchain(bodies, ref):
    """The sympy route timed against the recursive one (`--symbolic`) computes the same M and b (on the
    elbow-forearm subchain: lambdify of the larger unsimplified expressions takes minutes)."""
    import sympy as sp

    from codegen.eom_chain import _distal_subchain, symbolic_dynamics
    dofs, sub, base = _distal_subchain(bodies, DAS3_DOFS, 2)
    assert dofs == ["ELx", "PSy"] and base == "humerus"
    q, qd, g, M, b = symbolic_dynamics(dofs, sub, base)
    f = sp.lambdify([q, qd, g], [M, b], "numpy")
    arm = NumericChain(dofs, sub, base)
    rng = np.random.default_rng(5)
    for _ in range(3):
        qq, vv, gg = rng.uniform(-1, 1, 2), rng.uniform(-3, 3, 2), rng.normal(0, 10, 3)
        Ms, bs = f(qq, vv, gg)
        Ms = np.triu(Ms) + np.triu(Ms, 1).T        # symbolic_dynamics fills both triangles
        assert rel_err(Ms, arm.mass_matrix(qq)) < 1e-12
        assert rel_err(np.ravel(bs), arm.bias_force(qq, vv, gg)) < 1e-12
