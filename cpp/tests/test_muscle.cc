// Hill-type muscle element (muscle.cc / muscle_kernel.h) and activation dynamics.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <limits>
#include <vector>

#include "armrt/engine.h"
#include "armrt/muscle_kernel.h"
#include "test_util.h"

using namespace armrt;
using armrt_test::das2;

namespace {

struct Fixture {
  Model m;
  Fixture() { model_init(m, das2()); }
};

// A Data of m at strength s for every element (data_apply_settings).
std::unique_ptr<Data> data_at_strength(const Model& m, double s) {
  auto d = std::make_unique<Data>();
  data_init(m, *d);
  for (int i = 0; i < m.num_elements; ++i) d->settings.strength_scale[i] = s;
  data_apply_settings(m, *d);
  return d;
}

// First element with zero optimal pennation.
int unpennated_element(const Model& m) {
  for (int i = 0; i < m.num_elements; ++i)
    if (m.def->elements[i].pennopt == 0.0) return i;
  return -1;
}
int pennated_element(const Model& m) {
  for (int i = 0; i < m.num_elements; ++i)
    if (m.def->elements[i].pennopt > 0.05) return i;
  return -1;
}

// SEE stretch s >= 0 at which k_see * s^2 = F (F >= 0).
double see_stretch_for_force(const ElementConstants& e, double F) { return std::sqrt(F / e.k_see); }

// PEE force at lce.
double pee_force(const ElementConstants& e, double lce) {
  const double s = lce - e.pee_slack;
  return s > 0 ? e.k_pee * s * s : 0.0;
}

// Unpennated element at lce = lceopt: muscle-tendon length at which the fibres carry force F.
double length_for_fibre_force(const ElementConstants& e, double F) {
  const double f_see = F + pee_force(e, e.lceopt);
  return e.lceopt + e.lslack + see_stretch_for_force(e, f_see);
}

}  // namespace

TEST_SUITE("muscle") {

TEST_CASE("constants derived from the DAS3 parameters") {
  Fixture f;
  for (int i = 0; i < f.m.num_elements; ++i) {
    const ElementParams& p = f.m.def->elements[i];
    const ElementConstants& e = f.m.element[i];
    CHECK(e.fmax == p.fmax);
    CHECK(e.c2 == doctest::Approx(1.0 / p.tdeact).epsilon(1e-14));
    CHECK(e.c1 == doctest::Approx(1.0 / p.tact - 1.0 / p.tdeact).epsilon(1e-12));
    CHECK(e.k_see == doctest::Approx(p.fmax / std::pow(kTendonStrainAtFmax * p.lslack, 2)).epsilon(1e-12));
    CHECK(e.vmax == doctest::Approx(p.vmax * p.lceopt).epsilon(1e-14));
  }
}

TEST_CASE("isometric force at optimal fibre length equals a * Fmax") {
  Fixture f;
  const int i = unpennated_element(f.m);
  REQUIRE(i >= 0);
  const ElementConstants& e = f.m.element[i];
  CAPTURE(f.m.def->elements[i].name);
  for (double a : {0.05, 0.3, 0.7, 1.0}) {
    CAPTURE(a);
    const double L = length_for_fibre_force(e, a * e.fmax);
    const double lce = muscle_equilibrium_lce(e, f.m.fibre_damping, L, a);
    CHECK(std::fabs(lce - e.lceopt) <= 1e-6 * e.lceopt);
    const MuscleOut out = muscle_element(e, f.m.fibre_damping, L, e.lceopt, a);
    // PEE at lceopt: peeslack >= 1 leaves only the (non-positive) linear term.
    const double expected = a * e.fmax + pee_force(e, e.lceopt);
    CHECK(std::fabs(out.force - expected) <= 1e-6 * e.fmax);
    CHECK(std::fabs(out.fibre_velocity) <= 1e-9 * e.vmax);
    // The force at the equilibrium lce (as found) is the same within the tolerance.
    CHECK(std::fabs(muscle_element(e, f.m.fibre_damping, L, lce, a).force - expected) <= 1e-6 * e.fmax);
  }
}

TEST_CASE("force-velocity: lengthening velocity grows monotonically with the force imbalance") {
  Fixture f;
  const double b = f.m.fibre_damping;
  for (int i : {unpennated_element(f.m), pennated_element(f.m)}) {
    REQUIRE(i >= 0);
    const ElementConstants& e = f.m.element[i];
    CAPTURE(f.m.def->elements[i].name);
    for (double a : {0.0, 0.01, 0.2, 1.0}) {
      CAPTURE(a);
      const double lce = e.lceopt;
      double prev = -std::numeric_limits<double>::infinity();
      // Tendon from slack to 2x its stretch at Fmax.
      const double L0 = lce * std::sqrt(1.0 - std::pow(e.thickness / lce, 2)) + e.lslack;
      for (int k = 0; k <= 400; ++k) {
        const double L = L0 + (k / 400.0) * 2.0 * kTendonStrainAtFmax * e.lslack;
        const MuscleOut out = muscle_element(e, b, L, lce, a);
        REQUIRE(std::isfinite(out.fibre_velocity));
        CHECK(out.fibre_velocity > prev);
        prev = out.fibre_velocity;
      }
    }
  }
}

TEST_CASE("force-velocity: concentric force tends to 0 at v -> -vmax, eccentric plateau < 1.5 a Fmax") {
  Fixture f;
  const double b = f.m.fibre_damping;
  const int i = unpennated_element(f.m);
  const ElementConstants& e = f.m.element[i];
  const double a = 0.5, F0 = a * e.fmax;  // lce = lceopt: force-length factor 1
  // Concentric: fibre force F from F0 down to 0; CE force F - b v, its ratio to F0 is g(v).
  double prev_v = 1.0;
  for (double frac : {0.9, 0.5, 0.2, 0.05, 0.01, 0.0}) {
    const double F = frac * F0;
    const MuscleOut out = muscle_element(e, b, length_for_fibre_force(e, F), e.lceopt, a);
    const double v = out.fibre_velocity;
    CAPTURE(frac);
    CHECK(v < 0);
    CHECK(v > -e.vmax);
    CHECK(v < prev_v);
    prev_v = v;
    const double g = (F - b * v) / F0;
    CHECK(g == doctest::Approx((e.vmax + v) / (e.vmax - v / kHillA)).epsilon(1e-9));
  }
  // At zero fibre force the CE carries only what the damper takes back, g = b |v| / F0 (small).
  const double g0 = (0.0 - b * prev_v) / F0;
  CHECK(g0 < 0.06);
  // Concentric limit: as the damper vanishes, zero fibre force means v -> -vmax (g(v) -> 0).
  for (double tiny_b : {1e-3, 1e-6}) {
    const double v = muscle_element(e, tiny_b, length_for_fibre_force(e, 0.0), e.lceopt, a).fibre_velocity;
    CHECK(v == doctest::Approx(-e.vmax).epsilon(10 * tiny_b));
  }
  // And at 5% of F0 the shortening velocity is already beyond 3/4 vmax.
  {
    const double v = muscle_element(e, 1e-9, length_for_fibre_force(e, 0.05 * F0), e.lceopt, a).fibre_velocity;
    CHECK(v < -0.75 * e.vmax);
  }

  // Eccentric: F above F0; the CE force F - b v stays below 1.5 F0 and approaches it.
  double prev_g = 1.0;
  for (double frac : {1.01, 1.1, 1.3, 1.45, 1.6, 2.0, 5.0, 20.0}) {
    const double F = frac * F0;
    const MuscleOut out = muscle_element(e, b, length_for_fibre_force(e, F), e.lceopt, a);
    const double v = out.fibre_velocity;
    CAPTURE(frac);
    CHECK(v > 0);
    const double g = (F - b * v) / F0;
    CHECK(g > prev_g);
    CHECK(g < kEccentricFmax);
    CHECK(g == doctest::Approx((kEccentricFmax * v + e.ecc_c) / (v + e.ecc_c)).epsilon(1e-9));
    prev_g = g;
  }
  CHECK(prev_g > 1.4);
}

TEST_CASE("force-velocity: dF/dv continuous at v = 0") {
  Fixture f;
  const double b = f.m.fibre_damping;
  for (int i = 0; i < f.m.num_elements; ++i) {
    const ElementConstants& e = f.m.element[i];
    if (e.thickness != 0) continue;
    CAPTURE(f.m.def->elements[i].name);
    const double a = 0.4, F0 = a * e.fmax;
    const double dF = 1e-6 * F0;
    const double v_minus = muscle_element(e, b, length_for_fibre_force(e, F0 - dF), e.lceopt, a).fibre_velocity;
    const double v_plus = muscle_element(e, b, length_for_fibre_force(e, F0 + dF), e.lceopt, a).fibre_velocity;
    REQUIRE(v_minus < 0);
    REQUIRE(v_plus > 0);
    const double slope_c = -dF / v_minus, slope_e = dF / v_plus;
    CHECK(slope_c == doctest::Approx(slope_e).epsilon(1e-4));
    // And both equal the analytic concentric slope F0 (1 + A)/(A vmax) + b.
    CHECK(slope_c == doctest::Approx(F0 * (1 + kHillA) / (kHillA * e.vmax) + b).epsilon(1e-4));
  }
}

TEST_CASE("tendon: SEE force at 4% strain of lslack is Fmax, zero when slack") {
  Fixture f;
  for (int i = 0; i < f.m.num_elements; ++i) {
    const ElementConstants& e = f.m.element[i];
    CAPTURE(f.m.def->elements[i].name);
    for (double lce : {0.8 * e.lceopt, e.lceopt, 1.2 * e.lceopt}) {
      const double cos_pen = std::sqrt(1.0 - std::pow(e.thickness / lce, 2));
      const double stretch = kTendonStrainAtFmax * e.lslack;
      const double L = lce * cos_pen + e.lslack + stretch;
      const MuscleOut out = muscle_element(e, f.m.fibre_damping, L, lce, 0.3);
      CHECK(out.force == doctest::Approx(e.fmax).epsilon(1e-10));
      // Slack tendon: a tendon cannot push.
      const MuscleOut slack = muscle_element(e, f.m.fibre_damping, L - 2 * stretch, lce, 0.3);
      CHECK(slack.force == 0.0);
    }
  }
}

TEST_CASE("a tendon cannot push: the tendon force is never negative (every element, slack to stretched)") {
  Fixture f;
  int checked = 0;
  for (int i = 0; i < f.m.num_elements; ++i) {
    const ElementConstants& e = f.m.element[i];
    CAPTURE(f.m.def->elements[i].name);
    for (double lf : {0.3, 0.6, 1.0, 1.4, 2.0})
      for (double Lf : {0.2, 0.6, 0.9, 1.0, 1.1, 1.3})
        for (double a : {0.0, 0.5, 1.0}) {
          const MuscleOut out = muscle_element(e, f.m.fibre_damping, Lf * (e.lceopt + e.lslack), lf * e.lceopt, a);
          CHECK(out.force >= 0.0);
          ++checked;
        }
  }
  CHECK(checked == f.m.num_elements * 90);
}

TEST_CASE("strength 0.5 halves the isometric force exactly, active and passive alike") {
  Model full;
  model_init(full, armrt_test::das2());
  const auto weak = data_at_strength(full, 0.5);
  const double b = full.fibre_damping;
  for (int i = 0; i < full.num_elements; ++i) {
    const ElementConstants &e = full.element[i], h = data_element(full, *weak, i);
    CHECK(h.fmax == 0.5 * e.fmax);
    CHECK(weak->muscles.fmax[i] == h.fmax);
    CAPTURE(full.def->elements[i].name);
    for (double Lf : {0.95, 1.0, 1.03, 1.1}) {
      const double L = Lf * (e.lceopt + e.lslack);
      const double passive_full = muscle_element(e, b, L, muscle_equilibrium_lce(e, b, L, 0.0), 0.0).force;
      const double passive_half = muscle_element(h, b, L, muscle_equilibrium_lce(h, b, L, 0.0), 0.0).force;
      CHECK(passive_half == doctest::Approx(0.5 * passive_full).epsilon(1e-9).scale(1e-9 * e.fmax));
      for (double a : {0.3, 1.0}) {
        const double total_full = muscle_element(e, b, L, muscle_equilibrium_lce(e, b, L, a), a).force;
        const double total_half = muscle_element(h, b, L, muscle_equilibrium_lce(h, b, L, a), a).force;
        CHECK((total_half - passive_half) == doctest::Approx(0.5 * (total_full - passive_full)).epsilon(1e-8));
      }
    }
  }
}

TEST_CASE("fibre compressive element: zero above its onset, 4 fmax at min_lce, velocity F/b when relaxed") {
  Fixture f;
  const double b0 = f.m.fibre_damping;
  for (int i = 0; i < f.m.num_elements; ++i) {
    const ElementConstants& e = f.m.element[i];
    CAPTURE(f.m.def->elements[i].name);
    CHECK(e.compress_length >= kCompressOnset * e.lceopt);
    CHECK(e.compress_length >= e.min_lce + kCompressMinSpan * e.lceopt - 1e-15);
    // Slack tendon and PEE, a = 0: the damper alone (b0 plus the full floor) carries the compressive force.
    const double L = 0.5 * e.lslack;
    const double b = b0 + e.damping_slope * kLowActivation;
    CHECK(muscle_element(e, b0, L, e.min_lce, 0.0).fibre_velocity ==
          doctest::Approx(kCompressForceAtMin * e.fmax / b).epsilon(1e-12));
    const double mid = 0.5 * (e.min_lce + e.compress_length);
    CHECK(muscle_element(e, b0, L, mid, 0.0).fibre_velocity ==
          doctest::Approx(0.25 * kCompressForceAtMin * e.fmax / b).epsilon(1e-12));
    // Above the onset a whole slack unit carries nothing and its relaxed fibre keeps its length.
    if (e.pee_slack > e.compress_length * 1.01) {
      CHECK(muscle_element(e, b0, L, e.compress_length * 1.001, 0.0).fibre_velocity == 0.0);
      CHECK(muscle_element(e, b0, L, 0.5 * (e.compress_length + e.pee_slack), 0.0).fibre_velocity == 0.0);
    }
    // Fully active and unloaded, the fibre still lengthens at min_lce: it cannot reach it.
    CHECK(muscle_element(e, b0, L, e.min_lce, 1.0).fibre_velocity > 0.0);
    // It comes to rest where the compressive force balances the active isometric force.
    const double lce_eq = muscle_equilibrium_lce(e, b0, L, 1.0);
    CHECK(lce_eq > e.min_lce);
    CHECK(lce_eq < e.compress_length);
    const double x = (lce_eq / e.lceopt - 1.0) / kForceLengthWidth;
    CHECK(e.k_compress * (e.compress_length - lce_eq) * (e.compress_length - lce_eq) ==
          doctest::Approx(e.fmax * std::exp(-x * x)).epsilon(1e-9));
  }
}

TEST_CASE("zero-activation equilibrium of a slack unit: the fibre has taken up all but 0.2 % of the slack") {
  Fixture f;
  const double b0 = f.m.fibre_damping;
  int slack_cases = 0;
  for (int i = 0; i < f.m.num_elements; ++i) {
    const ElementConstants& e = f.m.element[i];
    CAPTURE(f.m.def->elements[i].name);
    // A unit slack by 10 % of its tendon's slack length with the fibre at its PEE slack length: the fibre
    // rests shorter, inside the unit, where the tendon is slack by 0.2 % of lslack.
    const double along_pee = std::sqrt(e.pee_slack * e.pee_slack - e.thickness * e.thickness);
    const double L = along_pee + 0.9 * e.lslack;
    const double lce_eq = muscle_equilibrium_lce(e, b0, L, 0.0);
    const double along_eq = std::sqrt(lce_eq * lce_eq - e.thickness * e.thickness);
    if (along_eq > std::sqrt(e.compress_length * e.compress_length - e.thickness * e.thickness) * (1 + 1e-12)) {
      CHECK(L - along_eq == doctest::Approx((1.0 - kRestTendonSlack) * e.lslack).epsilon(1e-9));
      ++slack_cases;
    }
    CHECK(along_eq < L);  // never longer than the whole unit
    CHECK(lce_eq <= e.pee_slack);
    CHECK(muscle_element(e, b0, L, lce_eq, 0.0).force == 0.0);
    CHECK(muscle_element(e, b0, L, lce_eq, 0.0).fibre_velocity == 0.0);
    // A unit taut with the fibre at its PEE slack length: the tendon pulls the fibre beyond it until
    // the PEE balances (a unique rest length).
    const double L_taut = along_pee + 1.01 * e.lslack;
    const double lce_taut = muscle_equilibrium_lce(e, b0, L_taut, 0.0);
    CHECK(lce_taut > e.pee_slack);
    CHECK(std::fabs(muscle_element(e, b0, L_taut, lce_taut, 0.0).fibre_velocity) < 1e-9 * e.vmax);
  }
  CHECK(slack_cases > f.m.num_elements / 2);
}

TEST_CASE("finite CE velocity at zero activation over a range of lengths") {
  Fixture f;
  const double b = f.m.fibre_damping;
  int checked = 0;
  for (int i = 0; i < f.m.num_elements; ++i) {
    const ElementConstants& e = f.m.element[i];
    CAPTURE(f.m.def->elements[i].name);
    for (double lf : {0.0, 0.05, 0.3, 0.6, 0.9, 1.0, 1.2, 1.6, 2.0, 3.0}) {
      const double lce = lf * e.lceopt;  // 0: below min_lce, clamped
      for (double Lf : {0.3, 0.7, 0.9, 1.0, 1.05, 1.2, 1.5}) {
        const double L = Lf * (e.lceopt + e.lslack);
        const MuscleOut out = muscle_element(e, b, L, lce, 0.0);
        CHECK(std::isfinite(out.force));
        CHECK(std::isfinite(out.fibre_velocity));
        ++checked;
      }
    }
    // Equilibrium at a = 0 exists and is a rest point.
    const double L = e.lceopt + e.lslack;
    const double lce_eq = muscle_equilibrium_lce(e, b, L, 0.0);
    CHECK(std::isfinite(lce_eq));
    CHECK(std::fabs(muscle_element(e, b, L, lce_eq, 0.0).fibre_velocity) < 1e-8);
  }
  CHECK(checked == f.m.num_elements * 70);
}

TEST_CASE("activation dynamics: da/dt = (c1 u + c2)(u - a), time constants tact and tdeact") {
  Fixture f;
  Data d;
  data_init(f.m, d);
  const int n = f.m.num_elements, ia = act_offset(f.m);
  // Element i gets excitation / activation chosen per case.
  const double us[] = {1.0, 0.0, 0.5, 0.5, 0.2};
  const double as[] = {0.0, 1.0, 0.1, 0.9, 0.2};
  for (int i = 0; i < n; ++i) {
    d.excitation[i] = us[i % 5];
    d.x[ia + i] = as[i % 5];
  }
  StateVec xdot{};
  forward(f.m, d, d.x.data(), xdot.data(), false);
  for (int i = 0; i < n; ++i) {
    const ElementParams& p = f.m.def->elements[i];
    const double u = us[i % 5], a = as[i % 5];
    const double c2 = 1.0 / p.tdeact, c1 = 1.0 / p.tact - c2;
    CAPTURE(p.name);
    CHECK(xdot[ia + i] == doctest::Approx((c1 * u + c2) * (u - a)).epsilon(1e-12));
    if (u > a) CHECK(xdot[ia + i] > 0);
    if (u < a) CHECK(xdot[ia + i] < 0);
    if (u == a) CHECK(xdot[ia + i] == 0);
    if (u == 1.0 && a == 0.0) CHECK(xdot[ia + i] == doctest::Approx(1.0 / p.tact).epsilon(1e-12));
    if (u == 0.0 && a == 1.0) CHECK(xdot[ia + i] == doctest::Approx(-1.0 / p.tdeact).epsilon(1e-12));
  }
}

TEST_CASE("activation dynamics: excitation capped at max_activation, clipped to [0, 1]") {
  Fixture f;
  const int i = 0;
  Data d;
  data_init(f.m, d);
  d.settings.max_activation[i] = 0.4;
  data_apply_settings(f.m, d);
  d.excitation[i] = 1.0;
  d.excitation[1] = -0.5;
  StateVec xdot{};
  forward(f.m, d, d.x.data(), xdot.data(), false);
  const int ia = act_offset(f.m);
  const ElementConstants e = data_element(f.m, d, i);
  CHECK(xdot[ia + i] == doctest::Approx((e.c1 * 0.4 + e.c2) * 0.4).epsilon(1e-12));
  CHECK(xdot[ia + 1] == 0.0);  // u clipped to 0, a = 0
}

TEST_CASE("exp_nonpositive: relative error below 1e-15") {
  double worst = 0;
  for (int k = 0; k <= 200000; ++k) {
    const double x = -700.0 * k / 200000.0;
    const double ref = std::exp(x);
    worst = std::fmax(worst, std::fabs(exp_nonpositive(x) - ref) / ref);
  }
  CHECK(worst < 1e-15);
  CHECK(exp_nonpositive(0.0) == 1.0);
  CHECK(exp_nonpositive(-1e6) >= 0.0);
}

TEST_CASE("sin_cos (generated dynamics): within 2.5e-16 of the C library over +-4 pi, exact quadrant signs") {
  double worst = 0;
  for (int k = -400000; k <= 400000; ++k) {
    const double x = 4.0 * M_PI * k / 400000.0 + 1e-7 * (k % 7);
    double s, c;
    sin_cos(x, &s, &c);
    worst = std::fmax(worst, std::fmax(std::fabs(s - std::sin(x)), std::fabs(c - std::cos(x))));
  }
  CHECK(worst < 2.5e-16);
  double s, c;
  sin_cos(0.0, &s, &c);
  CHECK(s == 0.0);
  CHECK(c == 1.0);
  sin_cos(M_PI / 2, &s, &c);
  CHECK(s == doctest::Approx(1.0).epsilon(1e-16));
  CHECK(std::fabs(c) < 1e-16);
}

}  // TEST_SUITE
