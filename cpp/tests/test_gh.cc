// GH stability of a reaction force (forward.cc: gh_stability; docs/conventions.md).
#include <doctest/doctest.h>

#include <cmath>

#include "armrt/engine.h"
#include "test_util.h"

using namespace armrt;
using armrt_test::das2;

namespace {

struct Stab {
  double theta, phi, stab;
};

Stab eval(const ModelDef& def, const double* f) {
  Stab s{};
  gh_stability(def, f, &s.theta, &s.phi, &s.stab);
  return s;
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
    const Stab s = eval(def, f);
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
      const Stab s = eval(def, f);
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
  Simulator sim(das2(), Integrator::kRos2, 1e-3);
  armrt_test::set_group_excitation(sim, "rotator_cuff", 0.2);
  for (int k = 0; k < 50; ++k) REQUIRE(sim.step());
  sim.evaluate_outputs();
  const Stab s = eval(*sim.model.def, sim.data.gh_force.data());
  CHECK(sim.data.gh_stab == doctest::Approx(s.stab).epsilon(1e-14));
  CHECK(sim.data.gh_theta == doctest::Approx(s.theta).epsilon(1e-14));
  CHECK(std::isfinite(sim.data.gh_stab));
}

}  // TEST_SUITE
