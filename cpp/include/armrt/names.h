// The name service of a model: elements, muscles, groups and DOFs by armrt or OpenSim name, and
// close-match suggestions for unknown names. The one implementation behind the Python API
// (armrt.Arm), the real-time runner (--max-activation, --channels), the LSL bridge and the viewer
// (through armrt.realtime.GroupMapping).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "armrt/model_def.h"

namespace armrt {

// Element indices named by `name`: an element, muscle or group (armrt names, e.g. "bicb1", "bicb",
// "elbow_flexors"), or an OpenSim force name ("bic_b_1") or OpenSim muscle ("bic_b": the force names
// without their element number). armrt names win over aliases. False (out untouched) if unknown.
bool find_elements(const ModelDef& def, const std::string& name, std::vector<int>& out);

// Overlapping names in one excitation command (a group, a muscle of it and an element of that
// muscle) resolve by specificity, whatever their order: an element's own name wins over its muscle's,
// a muscle's over a group's. Names of equal specificity that share elements (two groups; a name and
// its OpenSim alias) give those elements the largest of their values: a group's value is a demand,
// and 0 on one group must not silence the muscles another group drives. NaN propagates (callers refuse it).
enum class NameLevel : signed char { kElement = 0, kMuscle = 1, kGroup = 2, kUnnamed = 3 };
// find_elements plus the level of the name (an OpenSim force name is an element, an OpenSim muscle a muscle).
bool find_elements(const ModelDef& def, const std::string& name, std::vector<int>& out, NameLevel& level);

// Names resolved once (element lists in CSR form, with their levels), so that many commands can be
// combined without allocating (the real-time runner's packets).
struct NamedElements {
  std::vector<std::string> names;
  std::vector<int> offsets{0}, elements;
  std::vector<NameLevel> levels;
  int size() const { return static_cast<int>(levels.size()); }
};
// std::invalid_argument with unknown_names_message() naming every unknown name.
NamedElements resolve_names(const ModelDef& def, const std::vector<std::string>& names);
// values[k] for names.names[k] -> out[num_elements] by the rule above; elements no name covers get 0.
// level[num_elements] is scratch. No allocation.
void combine_named_values(const NamedElements& names, const double* values, int num_elements, double* out,
                          NameLevel* level);
// The rule in one call: {name: value} pairs -> one value per element (0 where no name covers it);
// std::invalid_argument naming every unknown name.
std::vector<double> excitations_from_names(const ModelDef& def,
                                           const std::vector<std::pair<std::string, double>>& items);
// The same rule for every per-element setting given by names (strength, maximum activation, activations): the
// elements no name covers keep unnamed[i] (num_elements values).
std::vector<double> values_from_names(const ModelDef& def, const std::vector<std::pair<std::string, double>>& items,
                                      const double* unnamed);

// Index of a DOF by armrt ("GHy") or OpenSim ("GH_y") name; -1 if unknown.
int find_dof(const ModelDef& def, const std::string& name);

enum class NameKind { kElementsMusclesGroups, kDofs };
// Up to n known names most similar to `name`, among element/muscle/group names and their OpenSim aliases,
// or DOF names: first those equal to it but for case ('BICB': 'bicb'), then difflib.get_close_matches's
// (Ratcliff-Obershelp ratio >= 0.6, best first).
std::vector<std::string> close_matches(const ModelDef& def, const std::string& name, NameKind kind, int n = 3);
// "unknown element, muscle or group name 'bicc' (did you mean 'bicb', 'bicl'?); `armrt info` lists
// them", or for several names "2 unknown element, muscle or group names: 'x'; 'y' (did you mean ...?); ...".
std::string unknown_names_message(const ModelDef& def, const std::vector<std::string>& names);
// "unknown DOF 'ELy'; did you mean 'ELx'?", or the list of DOFs when nothing is close.
std::string unknown_dof_message(const ModelDef& def, const std::string& name);
// difflib.SequenceMatcher(None, a, b).ratio() (no junk heuristics: names are short).
double similarity(const std::string& a, const std::string& b);

}  // namespace armrt
