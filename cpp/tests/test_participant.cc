// Participant A's elbow-forearm model (models/participant_A.json, built in next to das2) and the
// per-element maximum activation a model file carries (the participant's `maxact`).
#include <doctest/doctest.h>

#include <array>
#include <cstring>

#include "armrt/engine.h"
#include "armrt/simulator.h"

using namespace armrt;

TEST_CASE("participant_A is built in: 2 DOFs, 42 elements, intact maximum activations") {
  const ModelDef* def = find_model("participant_A");
  REQUIRE(def != nullptr);
  CHECK(def->num_dofs == 2);
  CHECK(def->num_elements == 42);
  CHECK(std::strcmp(def->dofs[0].name, "ELx") == 0);
  CHECK(std::strcmp(def->dofs[1].name, "PSy") == 0);
  Model m;
  model_init(m, *def);
  for (int i = 0; i < m.num_elements; ++i) CHECK(m.element[i].max_activation == 1.0);
}

TEST_CASE("model_init starts each element's maximum activation at the model's value") {
  const ModelDef& base = *find_model("participant_A");
  // A copy of the model whose elements carry reduced maximum activations (as participant_A_FES.json does).
  std::array<ElementParams, 42> els{};
  for (int i = 0; i < base.num_elements; ++i) {
    els[i] = base.elements[i];
    els[i].max_activation = 0.01 * i;
  }
  ModelDef def = base;
  def.elements = els.data();
  Model m;
  model_init(m, def);
  for (int i = 0; i < m.num_elements; ++i) {
    CHECK(m.element[i].max_activation == doctest::Approx(0.01 * i));
    CHECK(m.muscles.max_activation[i] == doctest::Approx(0.01 * i));
  }
  // The cap holds in the dynamics: at full excitation the activation of element 3 (max 0.03) settles there.
  Simulator sim(def, Integrator::kRos2, 1e-3, 1);
  sim.reset(nullptr, nullptr, nullptr);
  for (int i = 0; i < m.num_elements; ++i) sim.data.excitation[i] = 1.0;
  for (int k = 0; k < 500; ++k) REQUIRE(sim.step());
  CHECK(sim.data.x[act_offset(sim.model) + 3] == doctest::Approx(0.03).epsilon(1e-6));
}
