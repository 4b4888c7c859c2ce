"""Scapulothoracic contact and conoid ligament laws (cpp/include/armrt/girdle_forces.h): forces against
their potentials and the derivation in docs/das3.md, analytic derivatives against finite differences, and
the values at the DAS3 resting posture."""
from __future__ import annotations

import ctypes
import shutil
import subprocess

import numpy as np
import pytest

from conftest import DAS3, ROOT

HARNESS = r"""
#include "armrt/girdle_forces.h"
using namespace armrt;
static ThoraxEllipsoid ell(const double* c, const double* r, double k, double eps) {
  return ThoraxEllipsoid{{c[0], c[1], c[2]}, {r[0], r[1], r[2]}, k, eps};
}
static ConoidLigament con(double L0, double k, double eps) {
  return ConoidLigament{{0, 0, 0}, {0, 0, 0}, L0, k, eps};
}
extern "C" {
double h_contact(const double* c, const double* r, double k, double eps, const double* p, double* F, double* dF,
                 int with_jacobian) {
  return scapulothoracic_contact(ell(c, r, k, eps), p, F, with_jacobian ? dF : nullptr);
}
double h_contact_potential(const double* c, const double* r, double k, double eps, const double* p) {
  return scapulothoracic_potential(ell(c, r, k, eps), p);
}
double h_tension(double L0, double k, double eps, double L, double* dT) { return conoid_tension(con(L0, k, eps), L, dT); }
double h_conoid_potential(double L0, double k, double eps, double L) { return conoid_potential(con(L0, k, eps), L); }
double h_conoid_force(double L0, double k, double eps, const double* xo, const double* xi, double* F, double* dF) {
  return conoid_force(con(L0, k, eps), xo, xi, F, dF);
}
}
"""

D = ctypes.c_double
P = ctypes.POINTER(ctypes.c_double)
# DAS3 release values (model_struct.mat), so the tests run without ../shared too; test_das3_parameters
# checks them against the file when it is there.
CENTRE = np.array([0.0, -0.1486, 0.0591])
RADII = np.array([0.147, 0.2079, 0.0944])
K_CONTACT, EPS_CONTACT = 20000.0, 0.01
L0, K_CONOID, EPS_CONOID = 0.0174, 80000.0, 0.001


def _p(a):
    return np.ascontiguousarray(a, float).ctypes.data_as(P)


class Lib:
    def __init__(self, path):
        self.lib = ctypes.CDLL(str(path))
        for fn in ("h_contact", "h_contact_potential", "h_tension", "h_conoid_potential", "h_conoid_force"):
            getattr(self.lib, fn).restype = D

    def contact(self, p, k=K_CONTACT, eps=EPS_CONTACT):
        F, dF = np.zeros(3), np.zeros(9)
        f = self.lib.h_contact(_p(CENTRE), _p(RADII), D(k), D(eps), _p(p), F.ctypes.data_as(P), dF.ctypes.data_as(P), 1)
        return f, F, dF.reshape(3, 3)

    def contact_potential(self, p):
        return self.lib.h_contact_potential(_p(CENTRE), _p(RADII), D(K_CONTACT), D(EPS_CONTACT), _p(p))

    def tension(self, L):
        dT = D()
        T = self.lib.h_tension(D(L0), D(K_CONOID), D(EPS_CONOID), D(L), ctypes.byref(dT))
        return T, dT.value

    def conoid_potential(self, L):
        return self.lib.h_conoid_potential(D(L0), D(K_CONOID), D(EPS_CONOID), D(L))

    def conoid_force(self, xo, xi):
        F, dF = np.zeros(3), np.zeros(9)
        L = self.lib.h_conoid_force(D(L0), D(K_CONOID), D(EPS_CONOID), _p(xo), _p(xi), F.ctypes.data_as(P),
                                    dF.ctypes.data_as(P))
        return L, F, dF.reshape(3, 3)


def build_harness(out) -> Lib:
    """HARNESS compiled into folder out (a shared library over girdle_forces.h) and loaded; skips the
    test without a C++ compiler."""
    cxx = shutil.which("g++") or shutil.which("c++")
    if cxx is None:
        pytest.skip("no C++ compiler (g++) on PATH")
    (out / "h.cc").write_text(HARNESS)
    so = out / "libgirdle.so"
    subprocess.run([cxx, "-O2", "-std=c++17", "-Wall", "-Wextra", "-Werror", "-shared", "-fPIC",
                    f"-I{ROOT / 'cpp' / 'include'}", str(out / "h.cc"), "-o", str(so)], check=True)
    return Lib(so)


@pytest.fixture(scope="module")
def lib(tmp_path_factory):
    return build_harness(tmp_path_factory.mktemp("girdle"))


def surface_point(direction, f):
    """The point along `direction` from the centre where the ellipsoid function equals f."""
    d = np.asarray(direction, float)
    s = np.sqrt((1.0 + f) / np.sum((d / RADII) ** 2))
    return CENTRE + s * d


DIRECTIONS = [[1.0, 0.2, 0.9], [0.3, 1.0, 0.8], [0.6, -0.5, 1.0], [-0.2, 0.1, 1.0]]
FS = [-0.3, -0.05, -0.012, -1e-3, 0.0, 1e-3, 0.012, 0.05, 0.3]


def test_contact_is_the_derived_law(lib):
    """f is the ellipsoid function; F = -K m(f) grad f, K = k sum(r^2)/2, m = (f - sqrt(f^2+eps^2))/2."""
    K = K_CONTACT * np.sum(RADII ** 2) / 2
    for d in DIRECTIONS:
        for f in FS:
            p = surface_point(d, f)
            fc, F, _ = lib.contact(p)
            assert fc == pytest.approx(f, abs=1e-14)
            grad = 2 * (p - CENTRE) / RADII ** 2
            m = 0.5 * (f - np.sqrt(f * f + EPS_CONTACT ** 2))
            np.testing.assert_allclose(F, -K * m * grad, rtol=1e-12, atol=1e-12)
            # outward along the surface normal, never pulling
            assert F @ grad > 0
            assert abs(F @ grad) == pytest.approx(np.linalg.norm(F) * np.linalg.norm(grad), rel=1e-12)


def test_contact_penetration_stiffness_and_release(lib):
    """Deep inside: linear in f with slope K |grad f|; outside: fades like K eps^2 / (4 f) |grad f|."""
    K = K_CONTACT * np.sum(RADII ** 2) / 2
    p_in = surface_point(DIRECTIONS[0], -0.3)
    g_in = np.linalg.norm(2 * (p_in - CENTRE) / RADII ** 2)
    assert np.linalg.norm(lib.contact(p_in)[1]) == pytest.approx(K * 0.3 * g_in, rel=2e-3)
    p_out = surface_point(DIRECTIONS[0], 0.3)
    g_out = np.linalg.norm(2 * (p_out - CENTRE) / RADII ** 2)
    assert np.linalg.norm(lib.contact(p_out)[1]) == pytest.approx(K * EPS_CONTACT ** 2 / (4 * 0.3) * g_out, rel=1e-3)
    # far outside: no cancellation to zero or NaN, still the asymptote eps^2 / (4 f)
    p_far = surface_point(DIRECTIONS[0], 1e9)
    g_far = np.linalg.norm(2 * (p_far - CENTRE) / RADII ** 2)
    assert np.linalg.norm(lib.contact(p_far)[1]) == pytest.approx(K * EPS_CONTACT ** 2 / (4 * 1e9) * g_far, rel=1e-6)


def test_contact_jacobian_and_potential_by_finite_differences(lib):
    h = 1e-7
    for d in DIRECTIONS:
        for f in FS:
            p = surface_point(d, f)
            _, F, J = lib.contact(p)
            Jfd = np.array([(lib.contact(p + h * e)[1] - lib.contact(p - h * e)[1]) / (2 * h) for e in np.eye(3)]).T
            np.testing.assert_allclose(J, Jfd, rtol=1e-6, atol=1e-6 * np.abs(J).max())
            np.testing.assert_allclose(J, J.T, rtol=1e-14, atol=0)   # conservative
            gradV = np.array([(lib.contact_potential(p + h * e) - lib.contact_potential(p - h * e)) / (2 * h)
                              for e in np.eye(3)])
            np.testing.assert_allclose(-gradV, F, rtol=1e-6, atol=1e-6 * max(np.abs(F).max(), 1e-3))
    assert abs(lib.contact_potential(surface_point(DIRECTIONS[1], 0.0))) < 1e-12   # f = 0 up to rounding


def test_conoid_tension_law(lib):
    for L in [0.0, 0.010, 0.0164, 0.0174, 0.0184, 0.025, 0.05]:
        d = L - L0
        T, dT = lib.tension(L)
        assert T == pytest.approx(K_CONOID * 0.5 * (d + np.sqrt(d * d + EPS_CONOID ** 2)), rel=1e-12)
        assert T > 0
        h = 1e-8
        assert dT == pytest.approx((lib.tension(L + h)[0] - lib.tension(L - h)[0]) / (2 * h), rel=1e-6)
        assert T == pytest.approx((lib.conoid_potential(L + h) - lib.conoid_potential(L - h)) / (2 * h), rel=1e-6)
    assert lib.tension(L0)[0] == pytest.approx(K_CONOID * EPS_CONOID / 2)          # 40 N at the slack length
    assert lib.tension(L0 + 0.01)[0] == pytest.approx(K_CONOID * 0.01, rel=3e-3)    # taut: linear
    assert lib.tension(L0 - 0.01)[0] < 2.0                                           # slack: fades
    assert lib.tension(-1e6)[0] > 0 and np.isfinite(lib.tension(-1e6)[0])           # no cancellation
    assert lib.conoid_potential(L0) == 0.0


def test_conoid_force_vector_and_jacobian(lib):
    rng = np.random.default_rng(4)
    for _ in range(10):
        xo = rng.normal(0, 0.05, 3)
        xi = xo + rng.normal(0, 1, 3) / np.sqrt(3) * rng.uniform(0.008, 0.04)
        L, F, J = lib.conoid_force(xo, xi)
        u = (xi - xo) / np.linalg.norm(xi - xo)
        assert L == pytest.approx(np.linalg.norm(xi - xo), rel=1e-15)
        np.testing.assert_allclose(F, -lib.tension(L)[0] * u, rtol=1e-13)
        h = 1e-8
        Jfd = np.array([(lib.conoid_force(xo, xi + h * e)[1] - lib.conoid_force(xo, xi - h * e)[1]) / (2 * h)
                        for e in np.eye(3)]).T
        np.testing.assert_allclose(J, Jfd, rtol=1e-5, atol=1e-5 * np.abs(J).max())
        np.testing.assert_allclose(J, J.T, atol=1e-9 * np.abs(J).max())


def test_das3_parameters_and_resting_posture(lib):
    """The constants above are DAS3's; at equilibrium.mat TS and AI are on the thorax within 2 mm."""
    if not (DAS3 / "model_struct.mat").exists():
        pytest.skip(f"DAS3 reference data not found at {DAS3}")
    import scipy.io as sio

    from codegen.importers.das3_chain import BASE, DAS3_DOFS, das3_bodies
    from codegen.eom_chain import NumericChain
    m = sio.loadmat(DAS3 / "model_struct.mat", squeeze_me=True, struct_as_record=False)["model"]
    np.testing.assert_array_equal(np.ravel(m.thorax_center), CENTRE)
    np.testing.assert_array_equal(np.ravel(m.thorax_radii), RADII)
    assert (m.scap_thorax_k, m.scap_thorax_eps) == (K_CONTACT, EPS_CONTACT)
    assert (m.conoid_length, m.conoid_stiffness, m.conoid_eps) == (L0, K_CONOID, EPS_CONOID)
    q = sio.loadmat(DAS3 / "equilibrium.mat", squeeze_me=True)["x"][:11]
    chain = NumericChain(DAS3_DOFS, das3_bodies(DAS3 / "das3.osim"), BASE)
    Rs, ps = chain.body_pose(q, "scapula")
    Rc, pc = chain.body_pose(q, "clavicle")
    for name in ("TSprojection", "AIprojection"):
        p = ps + Rs @ np.ravel(getattr(m, name))
        f, F, J = lib.contact(p)
        depth = -f / np.linalg.norm(2 * (p - CENTRE) / RADII ** 2)       # first-order distance inside (m)
        n = 2 * (p - CENTRE) / RADII ** 2
        n /= np.linalg.norm(n)
        print(f"{name}: f = {f:.4f}, depth {depth * 1e3:.2f} mm, |F| = {np.linalg.norm(F):.1f} N, "
              f"normal stiffness {-(n @ J @ n):.0f} N/m")
        assert 0 < depth < 2e-3
    L = np.linalg.norm((ps + Rs @ np.ravel(m.conoid_insertion)) - (pc + Rc @ np.ravel(m.conoid_origin)))
    print(f"conoid: length {L * 1e3:.1f} mm (slack {L0 * 1e3:.1f} mm), tension {lib.tension(L)[0]:.0f} N")
    assert L > L0
