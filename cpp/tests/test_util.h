// Shared helpers of the C++ tests.
#pragma once

#include <cstring>
#include <stdexcept>
#include <string>

#include "armrt/arm.h"

namespace armrt_test {

inline const armrt::ModelDef& das2() {
  const armrt::ModelDef* def = armrt::find_model("das2");
  if (!def) throw std::runtime_error("model das2 not compiled in");
  return *def;
}

// das2's sizes and state layout, for the tests written for das2 (the engine takes them from the model;
// test_model.cc checks these against data.h's offsets).
inline constexpr int kDas2Dofs = 5;
inline constexpr int kDas2Elements = 102;
inline constexpr int kQ = 0, kQd = kDas2Dofs, kLce = 2 * kDas2Dofs;

inline int element_index(const armrt::ModelDef& def, const char* name) {
  for (int i = 0; i < def.num_elements; ++i)
    if (std::strcmp(def.elements[i].name, name) == 0) return i;
  return -1;
}

inline const armrt::GroupDef* find_group(const armrt::GroupDef* groups, int n, const char* name) {
  for (int k = 0; k < n; ++k)
    if (std::strcmp(groups[k].name, name) == 0) return &groups[k];
  return nullptr;
}

// Sets the excitation of every element of a group (or muscle) name.
inline void set_group_excitation(armrt::Arm& sim, const char* name, double u) {
  const armrt::ModelDef& def = *sim.model.def;
  const armrt::GroupDef* g = find_group(def.groups, def.num_groups, name);
  if (!g) g = find_group(def.muscles, def.num_muscles, name);
  if (!g) throw std::runtime_error(std::string("no group ") + name);
  for (int k = 0; k < g->num_elements; ++k) sim.data.excitation[g->elements[k]] = u;
}

}  // namespace armrt_test
