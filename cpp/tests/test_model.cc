// Sanity of the generated model tables (cpp/generated, via find_model).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "armrt/registry.h"
#include "armrt/arm.h"
#include "test_util.h"

using namespace armrt;
using armrt_test::kDas2Dofs, armrt_test::kQ, armrt_test::kQd, armrt_test::kLce;

TEST_SUITE("model") {

TEST_CASE("sizes, names and DOF order") {
  const ModelDef& def = armrt_test::das2();
  CHECK(std::string(def.name) == "das2");
  CHECK(def.num_elements == 102);
  CHECK(def.num_dofs == 5);
  CHECK(def.num_dofs == kDas2Dofs);
  CHECK(def.num_muscles == 22);
  const char* dofs[] = {"GHy", "GHz", "GHyy", "ELx", "PSy"};
  for (int j = 0; j < 5; ++j) {
    CHECK(std::string(def.dofs[j].name) == dofs[j]);
    CHECK(def.dofs[j].range_min < def.dofs[j].range_max);
  }
  CHECK(std::string(def.elements[0].name) == "deltscap1");
  CHECK(std::string(def.elements[101].name) == "anconeus5");
  CHECK(find_model("nope") == nullptr);
  Model m;
  model_init(m, def);
  CHECK(m.num_elements == 102);
  CHECK(m.num_dofs == 5);
  CHECK(state_size(m) == 214);
  // The das2 layout constants of the tests are data.h's offsets for this model.
  CHECK(q_offset(m) == kQ);
  CHECK(qd_offset(m) == kQd);
  CHECK(lce_offset(m) == kLce);
  CHECK(act_offset(m) == kLce + 102);
}

TEST_CASE("a model larger than the engine's capacities is refused by name") {
  ModelDef big = armrt_test::das2();
  big.num_dofs = kMaxDofs + 1;
  Model m;
  CHECK_THROWS_WITH_AS(model_init(m, big), doctest::Contains("DOFs; the engine takes 1 to 16"), std::invalid_argument);
  big = armrt_test::das2();
  big.num_elements = kMaxElements + 1;
  CHECK_THROWS_WITH_AS(model_init(m, big), doctest::Contains("elements; the engine takes 1 to 160"), std::invalid_argument);
}

TEST_CASE("element parameters are physical") {
  const ModelDef& def = armrt_test::das2();
  std::set<std::string> names;
  for (int i = 0; i < def.num_elements; ++i) {
    const ElementParams& p = def.elements[i];
    CAPTURE(p.name);
    names.insert(p.name);
    CHECK(p.fmax > 0);
    CHECK(p.lceopt > 0);
    CHECK(p.lslack > 0);
    CHECK(p.pennopt >= 0);
    CHECK(p.pennopt < M_PI / 2);
    CHECK(p.vmax > 0);
    CHECK(p.tact > 0);
    CHECK(p.tdeact > 0);
    CHECK(p.dof_mask != 0);
    CHECK((p.dof_mask & ~31) == 0);
    CHECK(std::string(p.name).rfind(p.muscle, 0) == 0);  // element name starts with its muscle's
  }
  CHECK(names.size() == 102u);
}

TEST_CASE("muscles cover each element exactly once, in order") {
  const ModelDef& def = armrt_test::das2();
  std::vector<int> count(def.num_elements, 0);
  for (int k = 0; k < def.num_muscles; ++k) {
    const GroupDef& mu = def.muscles[k];
    CAPTURE(mu.name);
    for (int e = 0; e < mu.num_elements; ++e) {
      const int i = mu.elements[e];
      REQUIRE(i >= 0);
      REQUIRE(i < def.num_elements);
      ++count[i];
      CHECK(std::string(def.elements[i].muscle) == mu.name);
    }
  }
  for (int i = 0; i < def.num_elements; ++i) {
    CAPTURE(i);
    CHECK(count[i] == 1);
  }
}

TEST_CASE("rotator_cuff = infra + termin + supra + subscap") {
  const ModelDef& def = armrt_test::das2();
  const GroupDef* rc = armrt_test::find_group(def.groups, def.num_groups, "rotator_cuff");
  REQUIRE(rc != nullptr);
  std::set<int> expected;
  for (const char* name : {"infra", "termin", "supra", "subscap"}) {
    const GroupDef* mu = armrt_test::find_group(def.muscles, def.num_muscles, name);
    REQUIRE(mu != nullptr);
    expected.insert(mu->elements, mu->elements + mu->num_elements);
  }
  const std::set<int> got(rc->elements, rc->elements + rc->num_elements);
  CHECK(static_cast<int>(got.size()) == rc->num_elements);  // no duplicates
  CHECK(got == expected);
  // Every group's indices are valid and unique.
  for (int k = 0; k < def.num_groups; ++k) {
    const GroupDef& g = def.groups[k];
    CAPTURE(g.name);
    std::set<int> s(g.elements, g.elements + g.num_elements);
    CHECK(static_cast<int>(s.size()) == g.num_elements);
    CHECK(*s.begin() >= 0);
    CHECK(*s.rbegin() < def.num_elements);
  }
}

TEST_CASE("gravity magnitude 9.80665, scapula rotation orthonormal, gravity = R^T g_thorax") {
  const ModelDef& def = armrt_test::das2();
  const double* g = def.gravity_base;
  CHECK(std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]) == doctest::Approx(9.80665).epsilon(1e-12));
  const double* R = def.base_rotation_in_thorax;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += R[k * 3 + a] * R[k * 3 + b];
      CHECK(s == doctest::Approx(a == b ? 1.0 : 0.0).epsilon(1e-12));
    }
  // g_scapula = R^T (0, -9.80665, 0)
  for (int k = 0; k < 3; ++k) CHECK(g[k] == doctest::Approx(R[1 * 3 + k] * -9.80665).epsilon(1e-9));
  Model m;
  model_init(m, def);
  for (int k = 0; k < 3; ++k) CHECK(m.gravity_base[k] == g[k]);
}

TEST_CASE("element runs: blocks of eight in order, each crossing exactly its DOF range") {
  // Model::element_runs lets the ROS2 step skip moment-arm rows that are zero: a run must cover its blocks'
  // crossed DOFs (else a nonzero moment arm would be dropped) and nothing else is assumed.
  std::mt19937_64 rng(3);
  for (const ModelDef* def : registered_models()) {
    Model m;
    model_init(m, *def);
    const int n = m.num_elements, nq = m.num_dofs;
    CAPTURE(def->name);
    int expected_begin = 0;
    for (int r = 0; r < m.num_element_runs; ++r) {
      const Model::ElementRun& run = m.element_runs[r];
      CHECK(run.begin == expected_begin);
      CHECK(run.end > run.begin);
      CHECK(run.end % 8 == 0);
      const bool range_ok = 0 <= run.dof_lo && run.dof_lo <= run.dof_hi && run.dof_hi < nq;
      CHECK(range_ok);
      const bool differs = r == 0 || run.dof_lo != m.element_runs[r - 1].dof_lo ||
                           run.dof_hi != m.element_runs[r - 1].dof_hi;
      CHECK(differs);
      for (int b = run.begin; b < run.end; b += 8) {
        unsigned crossed = 0;
        for (int i = b; i < std::min(b + 8, n); ++i) crossed |= static_cast<unsigned>(def->elements[i].dof_mask);
        const unsigned in_range = ((2u << run.dof_hi) - 1u) & ~((1u << run.dof_lo) - 1u);
        const bool ends_crossed = (crossed >> run.dof_lo & 1u) && (crossed >> run.dof_hi & 1u);
        CHECK(ends_crossed);
        CHECK((crossed & ~in_range) == 0u);
      }
      expected_begin = run.end;
    }
    CHECK(expected_begin == (n + 7) / 8 * 8);  // the last block's ghost lanes included
    // The polynomials agree: zero moment arms outside each run's range, at random postures in range.
    std::vector<double> q(nq), L(n), R(static_cast<size_t>(nq) * kMaxElements);
    for (int trial = 0; trial < 20; ++trial) {
      for (int j = 0; j < nq; ++j)
        q[j] = std::uniform_real_distribution<double>(def->dofs[j].range_min, def->dofs[j].range_max)(rng);
      def->muscle_paths(q.data(), L.data(), R.data());
      for (int r = 0; r < m.num_element_runs; ++r) {
        const Model::ElementRun& run = m.element_runs[r];
        for (int j = 0; j < nq; ++j) {
          if (j >= run.dof_lo && j <= run.dof_hi) continue;
          for (int i = run.begin; i < std::min(run.end, n); ++i) CHECK(R[j * kMaxElements + i] == 0.0);
        }
      }
    }
  }
}

TEST_CASE("mass matrix symmetric positive definite; moment arms = -dL/dq") {
  const ModelDef& def = armrt_test::das2();
  double q[5];
  for (int j = 0; j < 5; ++j) q[j] = def.dofs[j].rest;
  double M[25];
  def.mass_matrix(q, M);
  for (int a = 0; a < 5; ++a) {
    CHECK(M[a * 5 + a] > 0);
    for (int b = 0; b < 5; ++b) CHECK(M[a * 5 + b] == doctest::Approx(M[b * 5 + a]).epsilon(1e-12));
  }
  double L[102], R[5 * kMaxElements], Lp[102], Lm[102];
  def.muscle_paths(q, L, R);
  const double h = 1e-6;
  for (int j = 0; j < 5; ++j) {
    double qp[5], qm[5];
    for (int k = 0; k < 5; ++k) qp[k] = qm[k] = q[k];
    qp[j] += h, qm[j] -= h;
    def.muscle_lengths(qp, Lp);
    def.muscle_lengths(qm, Lm);
    for (int i = 0; i < 102; ++i) {
      CAPTURE(i);
      CAPTURE(j);
      CHECK(R[j * kMaxElements + i] == doctest::Approx(-(Lp[i] - Lm[i]) / (2 * h)).epsilon(1e-5).scale(1e-3));  // by DOF
      if (!(def.elements[i].dof_mask & (1 << j))) CHECK(R[j * kMaxElements + i] == 0.0);
    }
  }
}

}  // TEST_SUITE
