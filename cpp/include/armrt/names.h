// The name service of a model: elements, muscles, groups and DOFs by armrt or OpenSim name, and
// close-match suggestions for unknown names. The one implementation behind the Python API
// (armrt.Arm), the real-time runner (--max-activation, --channels), the LSL bridge and the viewer
// (through armrt.realtime.GroupMapping).
#pragma once

#include <string>
#include <vector>

#include "armrt/model_def.h"

namespace armrt {

// Element indices named by `name`: an element, muscle or group (armrt names, e.g. "bicb1", "bicb",
// "elbow_flexors"), or an OpenSim force name ("bic_b_1") or OpenSim muscle ("bic_b": the force names
// without their element number). armrt names win over aliases. False (out untouched) if unknown.
bool find_elements(const ModelDef& def, const std::string& name, std::vector<int>& out);
// Index of a DOF by armrt ("GHy") or OpenSim ("GH_y") name; -1 if unknown.
int find_dof(const ModelDef& def, const std::string& name);

enum class NameKind { kElementsMusclesGroups, kDofs };
// Up to n known names most similar to `name` (Python difflib.get_close_matches: Ratcliff-Obershelp
// ratio >= 0.6, best first), among element/muscle/group names and their OpenSim aliases, or DOF names.
std::vector<std::string> close_matches(const ModelDef& def, const std::string& name, NameKind kind, int n = 3);
// "unknown element, muscle or group name 'bicc' (did you mean 'bicb', 'bicl'?); `armrt info` lists
// them", or for several names "... 2 names: 'x'; 'y' (did you mean ...?); ...".
std::string unknown_names_message(const ModelDef& def, const std::vector<std::string>& names);
// "unknown DOF 'ELy'; did you mean 'ELx'?", or the list of DOFs when nothing is close.
std::string unknown_dof_message(const ModelDef& def, const std::string& name);
// difflib.SequenceMatcher(None, a, b).ratio() (no junk heuristics: names are short).
double similarity(const std::string& a, const std::string& b);

}  // namespace armrt
