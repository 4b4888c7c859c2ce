// GH stability of a reaction force (gh_reaction.cc: gh_stability; docs/conventions.md).
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "armrt/engine.h"
#include "test_util.h"

using namespace armrt;
using armrt_test::das2;

namespace {

GHStability eval(const ModelDef& def, const double* f) { return gh_stability(def, f); }

// A tiny glenoid on das2's tables: the scapula axes as its basis (normal x, major y, minor z = x cross y) and
// rim half-angles of 0.4 rad (major) and 0.3 rad (minor), so that the cases below are worked by hand.
ModelDef tiny_glenoid() {
  ModelDef def = das2();
  const double n[3] = {1, 0, 0}, a[3] = {0, 1, 0}, b[3] = {0, 0, 1};
  for (int k = 0; k < 3; ++k) {
    def.glenoid_normal[k] = n[k];
    def.glenoid_major_axis[k] = a[k];
    def.glenoid_minor_axis[k] = b[k];
  }
  def.rim_half_angle_major = 0.4;
  def.rim_half_angle_minor = 0.3;
  return def;
}

// The force whose angles from the tiny glenoid's normal are theta (in the x-y plane) and phi (x-z), of
// normal component fn > 0.
void at_angles(double theta, double phi, double fn, double* f) {
  f[0] = fn;
  f[1] = fn * std::tan(theta);
  f[2] = fn * std::tan(phi);
}

// Force of magnitude `mag` tilted from the glenoid normal by `angle` toward `axis`.
void tilted(const ModelDef& def, const double* axis, double angle, double mag, double* f) {
  for (int k = 0; k < 3; ++k) f[k] = mag * (std::cos(angle) * def.glenoid_normal[k] + std::sin(angle) * axis[k]);
}

}  // namespace

TEST_SUITE("gh") {

TEST_CASE("glenoid basis is orthonormal and right-handed") {
  const ModelDef& def = das2();
  const double* n = def.glenoid_normal;
  const double* a = def.glenoid_major_axis;
  const double* b = def.glenoid_minor_axis;
  auto dot = [](const double* x, const double* y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  CHECK(dot(n, n) == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(dot(a, a) == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(dot(b, b) == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(std::fabs(dot(n, a)) < 1e-12);
  CHECK(std::fabs(dot(n, b)) < 1e-12);
  CHECK(std::fabs(dot(a, b)) < 1e-12);
  const double c[3] = {n[1] * a[2] - n[2] * a[1], n[2] * a[0] - n[0] * a[2], n[0] * a[1] - n[1] * a[0]};
  for (int k = 0; k < 3; ++k) CHECK(c[k] == doctest::Approx(b[k]).epsilon(1e-12));
  CHECK(def.rim_half_angle_major == doctest::Approx(44.37 * M_PI / 180).epsilon(1e-9));
  CHECK(def.rim_half_angle_minor == doctest::Approx(38.55 * M_PI / 180).epsilon(1e-9));
}

TEST_CASE("force along the glenoid normal: stability 0") {
  const ModelDef& def = das2();
  for (double mag : {1.0, 250.0, 3000.0}) {
    double f[3];
    for (int k = 0; k < 3; ++k) f[k] = mag * def.glenoid_normal[k];
    const GHStability s = eval(def, f);
    CHECK(std::fabs(s.theta) < 1e-12);
    CHECK(std::fabs(s.phi) < 1e-12);
    CHECK(s.stab < 1e-20);
  }
}

TEST_CASE("force tilted by the rim half-angle: stability exactly 1; beyond: > 1") {
  const ModelDef& def = das2();
  const double ta = def.rim_half_angle_major, pa = def.rim_half_angle_minor;
  double minus_major[3], minus_minor[3];
  for (int k = 0; k < 3; ++k) minus_major[k] = -def.glenoid_major_axis[k], minus_minor[k] = -def.glenoid_minor_axis[k];
  struct Case {
    const double* axis;
    double half_angle;
    const char* what;
  } cases[] = {{def.glenoid_major_axis, ta, "+major"}, {minus_major, ta, "-major"},
               {def.glenoid_minor_axis, pa, "+minor"}, {minus_minor, pa, "-minor"}};
  for (const Case& c : cases) {
    CAPTURE(c.what);
    for (double mag : {10.0, 800.0}) {
      double f[3];
      tilted(def, c.axis, c.half_angle, mag, f);
      const GHStability s = eval(def, f);
      CHECK(s.stab == doctest::Approx(1.0).epsilon(1e-12));
      tilted(def, c.axis, 1.05 * c.half_angle, mag, f);
      CHECK(eval(def, f).stab > 1.0);
      tilted(def, c.axis, 0.95 * c.half_angle, mag, f);
      CHECK(eval(def, f).stab < 1.0);
      tilted(def, c.axis, 0.5 * c.half_angle, mag, f);
      CHECK(eval(def, f).stab == doctest::Approx(0.25).epsilon(1e-12));
    }
  }
  // A force pulling the head away from the glenoid (behind it) is far beyond the rim.
  double f[3];
  for (int k = 0; k < 3; ++k) f[k] = -def.glenoid_normal[k] + 0.1 * def.glenoid_major_axis[k];
  CHECK(eval(def, f).stab > 1.0);
}

TEST_CASE("forward() records the GH force and its stability consistently") {
  Arm sim(das2(), Integrator::kRos2, 1e-3);
  armrt_test::set_group_excitation(sim, "rotator_cuff", 0.2);
  for (int k = 0; k < 50; ++k) REQUIRE(sim.step());
  sim.evaluate_outputs();
  const GHStability s = eval(*sim.model.def, sim.data.gh_force.data());
  CHECK(sim.data.gh_stab == doctest::Approx(s.stab).epsilon(1e-14));
  CHECK(sim.data.gh_angles[0] == doctest::Approx(s.theta).epsilon(1e-14));
  CHECK(sim.data.gh_angles[1] == doctest::Approx(s.phi).epsilon(1e-14));
  CHECK(sim.data.gh_rim_direction == doctest::Approx(s.rim_direction).epsilon(1e-14));
  CHECK(sim.data.gh_rim_margin == doctest::Approx(s.rim_margin).epsilon(1e-14));
  CHECK(std::isfinite(sim.data.gh_stab));
}

TEST_CASE("rim margin and direction on a tiny glenoid, by hand") {
  const ModelDef def = tiny_glenoid();
  double f[3];

  SUBCASE("along the normal: margin theta_a, direction 0, stability 0") {
    at_angles(0, 0, 300, f);
    const GHStability s = eval(def, f);
    CHECK(s.stab == 0.0);
    CHECK(s.rim_direction == 0.0);
    CHECK(s.rim_margin == doctest::Approx(0.4).epsilon(1e-15));
    // The sign of a zero component must not turn the direction to pi (atan2(0, -0) = pi).
    const double g[3] = {300, -0.0, 0.0};
    CHECK(eval(def, g).rim_direction == 0.0);
    CHECK(eval(def, g).rim_margin == doctest::Approx(0.4).epsilon(1e-15));
  }
  SUBCASE("on the rim along +major (superior): margin 0, direction 0, stability 1") {
    at_angles(0.4, 0, 50, f);
    const GHStability s = eval(def, f);
    CHECK(s.stab == doctest::Approx(1.0).epsilon(1e-14));
    CHECK(s.rim_direction == 0.0);
    CHECK(std::fabs(s.rim_margin) < 1e-15);
  }
  SUBCASE("along -major, halfway: direction pi, margin theta_a / 2") {
    at_angles(-0.2, 0, 50, f);
    const GHStability s = eval(def, f);
    CHECK(s.rim_direction == doctest::Approx(M_PI).epsilon(1e-15));
    CHECK(s.rim_margin == doctest::Approx(0.2).epsilon(1e-14));
    CHECK(s.stab == doctest::Approx(0.25).epsilon(1e-14));
  }
  SUBCASE("along +minor and -minor: direction +-pi/2, margin phi_a - |phi|") {
    at_angles(0, 0.1, 50, f);
    GHStability s = eval(def, f);
    CHECK(s.rim_direction == doctest::Approx(M_PI / 2).epsilon(1e-15));
    CHECK(s.rim_margin == doctest::Approx(0.2).epsilon(1e-14));
    at_angles(0, -0.3, 50, f);
    s = eval(def, f);
    CHECK(s.rim_direction == doctest::Approx(-M_PI / 2).epsilon(1e-15));
    CHECK(std::fabs(s.rim_margin) < 1e-15);
    CHECK(s.stab == doctest::Approx(1.0).epsilon(1e-14));
  }
  SUBCASE("at psi = 45 deg: rim radius sqrt(2) theta_a phi_a / sqrt(theta_a^2 + phi_a^2) = 0.24 sqrt(2)") {
    // theta = phi = 0.2: rho = 0.2 sqrt(2), so the margin is 0.04 sqrt(2); GHstab = 0.25 + 0.4 / 0.9.
    at_angles(0.2, 0.2, 120, f);
    const GHStability s = eval(def, f);
    CHECK(s.rim_direction == doctest::Approx(M_PI / 4).epsilon(1e-15));
    CHECK(s.rim_margin == doctest::Approx(0.04 * std::sqrt(2.0)).epsilon(1e-13));
    CHECK(s.stab == doctest::Approx(0.25 + 0.04 / 0.09).epsilon(1e-14));
  }
  SUBCASE("outside the rim: negative margin by the excess along psi") {
    // theta = 0.6 along +major: 0.2 rad beyond the rim; (theta, phi) = (0.3, -0.3) at psi = -45 deg,
    // rho = 0.3 sqrt(2) against the rim's 0.24 sqrt(2).
    at_angles(0.6, 0, 10, f);
    GHStability s = eval(def, f);
    CHECK(s.rim_margin == doctest::Approx(-0.2).epsilon(1e-14));
    CHECK(s.stab == doctest::Approx(2.25).epsilon(1e-14));
    at_angles(0.3, -0.3, 10, f);
    s = eval(def, f);
    CHECK(s.rim_direction == doctest::Approx(-M_PI / 4).epsilon(1e-15));
    CHECK(s.rim_margin == doctest::Approx(-0.06 * std::sqrt(2.0)).epsilon(1e-13));
    // A force pulling the head off the glenoid (F.n < 0) is beyond the rim whichever way it leans.
    const double away[3] = {-1.0, 0.1, -0.05};
    s = eval(def, away);
    CHECK(s.rim_margin < -2.0);
    CHECK(s.stab > 1.0);
  }
}

TEST_CASE("the margin is zero exactly on the rim and has the sign of 1 - GHstab") {
  for (const ModelDef& def : {tiny_glenoid(), das2()}) {
    const double ta = def.rim_half_angle_major, pa = def.rim_half_angle_minor;
    // On the rim: (theta, phi) = (ta cos t, pa sin t) for any t.
    for (int k = 0; k < 24; ++k) {
      const double t = 2 * M_PI * k / 24.0;
      double f[3], local[3];
      at_angles(ta * std::cos(t), pa * std::sin(t), 200, local);
      for (int i = 0; i < 3; ++i)
        f[i] = local[0] * def.glenoid_normal[i] + local[1] * def.glenoid_major_axis[i] + local[2] * def.glenoid_minor_axis[i];
      const GHStability s = eval(def, f);
      CAPTURE(t);
      CHECK(s.stab == doctest::Approx(1.0).epsilon(1e-12));
      CHECK(std::fabs(s.rim_margin) < 1e-12);
    }
    // Random forces in every direction and magnitude.
    std::mt19937_64 rng(24);
    std::normal_distribution<double> gauss(0.0, 1.0);
    std::uniform_real_distribution<double> log_mag(-1.0, 3.5);
    int inside = 0, outside = 0;
    for (int k = 0; k < 20000; ++k) {
      const double mag = std::pow(10.0, log_mag(rng));
      const double f[3] = {mag * gauss(rng), mag * gauss(rng), mag * gauss(rng)};
      const GHStability s = eval(def, f);
      const double rho = std::hypot(s.theta, s.phi);
      CAPTURE(k);
      REQUIRE((s.rim_margin > 0) == (s.stab < 1));
      (s.stab < 1 ? inside : outside)++;
      // margin = rho (1 / sqrt(GHstab) - 1), the brief's closed form, where GHstab > 0.
      CHECK(s.rim_margin == doctest::Approx(rho * (1 / std::sqrt(s.stab) - 1)).epsilon(1e-9));
      CHECK(s.rim_direction == doctest::Approx(std::atan2(s.phi, s.theta)).epsilon(1e-15));
    }
    CHECK(inside > 500);  // both signs were exercised
    CHECK(outside > 500);
  }
}

}  // TEST_SUITE
