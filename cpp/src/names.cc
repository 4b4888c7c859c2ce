// Name lookups and close-match suggestions (names.h). Not in the hot path: they may allocate.
#include "armrt/names.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <cstring>
#include <tuple>

namespace armrt {

namespace {

std::string to_lower(const std::string& s) {
  std::string out = s;
  for (char& ch : out) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return out;
}

bool is_armrt_name(const ModelDef& def, const std::string& name) {
  for (int i = 0; i < def.num_elements; ++i)
    if (name == def.elements[i].name) return true;
  for (int k = 0; k < def.num_muscles; ++k)
    if (name == def.muscles[k].name) return true;
  for (int k = 0; k < def.num_groups; ++k)
    if (name == def.groups[k].name) return true;
  return false;
}

// The OpenSim muscle of a force name: without its element number and the separating underscore
// ("delt_scap_1", "delt_scap10" -> "delt_scap").
std::string osim_stem(const char* osim) {
  std::string s(osim);
  while (!s.empty() && s.back() >= '0' && s.back() <= '9') s.pop_back();
  while (!s.empty() && s.back() == '_') s.pop_back();
  return s;
}

// Every name find_elements accepts, in the order the Python API listed them (armrt names first).
std::vector<std::string> element_choices(const ModelDef& def) {
  std::vector<std::string> out;
  for (int i = 0; i < def.num_elements; ++i) out.emplace_back(def.elements[i].name);
  for (int k = 0; k < def.num_muscles; ++k) out.emplace_back(def.muscles[k].name);
  for (int k = 0; k < def.num_groups; ++k) out.emplace_back(def.groups[k].name);
  for (int i = 0; i < def.num_elements; ++i) {
    const char* osim = def.elements[i].osim_name;
    if (!osim || !*osim) continue;
    for (const std::string& alias : {std::string(osim), osim_stem(osim)})
      if (!alias.empty() && !is_armrt_name(def, alias) && std::find(out.begin(), out.end(), alias) == out.end())
        out.push_back(alias);
  }
  return out;
}

// difflib's longest matching block of a[alo:ahi] and b[blo:bhi]: the longest, then the earliest in
// a, then in b.
std::tuple<int, int, int> longest_match(const std::string& a, const std::string& b, int alo, int ahi, int blo, int bhi) {
  int besti = alo, bestj = blo, bestsize = 0;
  // prev[j + 1]: length of the match ending at (i - 1, j); cur likewise for row i.
  std::vector<int> prev(b.size() + 1, 0), cur(b.size() + 1, 0);
  for (int i = alo; i < ahi; ++i) {
    std::fill(cur.begin(), cur.end(), 0);
    for (int j = blo; j < bhi; ++j) {
      if (a[i] != b[j]) continue;
      const int len = prev[j] + 1;
      cur[j + 1] = len;
      if (len > bestsize) besti = i - len + 1, bestj = j - len + 1, bestsize = len;
    }
    std::swap(prev, cur);
  }
  return {besti, bestj, bestsize};
}

int matching_characters(const std::string& a, const std::string& b, int alo, int ahi, int blo, int bhi) {
  if (alo >= ahi || blo >= bhi) return 0;
  const auto [i, j, k] = longest_match(a, b, alo, ahi, blo, bhi);
  if (k == 0) return 0;
  return k + matching_characters(a, b, alo, i, blo, j) + matching_characters(a, b, i + k, ahi, j + k, bhi);
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

std::string join_quoted(const std::vector<std::string>& v, const char* sep) {
  std::string out;
  for (size_t k = 0; k < v.size(); ++k) out += (k ? sep : "") + quoted(v[k]);
  return out;
}

}  // namespace

double similarity(const std::string& a, const std::string& b) {
  const size_t total = a.size() + b.size();
  if (total == 0) return 1.0;
  const int m = matching_characters(a, b, 0, static_cast<int>(a.size()), 0, static_cast<int>(b.size()));
  return 2.0 * m / static_cast<double>(total);
}

bool find_elements(const ModelDef& def, const std::string& name, std::vector<int>& out) {
  NameLevel level;
  return find_elements(def, name, out, level);
}

bool find_elements(const ModelDef& def, const std::string& name, std::vector<int>& out, NameLevel& level) {
  for (int i = 0; i < def.num_elements; ++i)
    if (name == def.elements[i].name) {
      out.assign(1, i);
      level = NameLevel::kElement;
      return true;
    }
  for (const auto& [groups, count, lvl] : {std::tuple{def.muscles, def.num_muscles, NameLevel::kMuscle},
                                           std::tuple{def.groups, def.num_groups, NameLevel::kGroup}})
    for (int k = 0; k < count; ++k)
      if (name == groups[k].name) {
        out.assign(groups[k].elements, groups[k].elements + groups[k].num_elements);
        level = lvl;
        return true;
      }
  std::vector<int> found;
  bool force_name = false;
  for (int i = 0; i < def.num_elements; ++i) {
    const char* osim = def.elements[i].osim_name;
    if (!osim || !*osim) continue;
    if (name == osim) force_name = true;
    if (name == osim || name == osim_stem(osim)) found.push_back(i);
  }
  if (found.empty()) return false;
  level = force_name && found.size() == 1 ? NameLevel::kElement : NameLevel::kMuscle;
  out = std::move(found);
  return true;
}

NamedElements resolve_names(const ModelDef& def, const std::vector<std::string>& names) {
  NamedElements m;
  std::vector<std::string> unknown;
  std::vector<int> ix;
  for (const std::string& name : names) {
    NameLevel level;
    if (!find_elements(def, name, ix, level)) {
      unknown.push_back(name);
      continue;
    }
    m.names.push_back(name);
    m.elements.insert(m.elements.end(), ix.begin(), ix.end());
    m.offsets.push_back(static_cast<int>(m.elements.size()));
    m.levels.push_back(level);
  }
  if (!unknown.empty()) throw std::invalid_argument(unknown_names_message(def, unknown));
  return m;
}

void combine_named_values(const NamedElements& m, const double* values, int num_elements, double* out,
                          NameLevel* level) {
  for (int i = 0; i < num_elements; ++i) {
    out[i] = 0.0;
    level[i] = NameLevel::kUnnamed;
  }
  for (int k = 0; k < m.size(); ++k) {
    const double v = values[k];
    const NameLevel lk = m.levels[k];
    for (int j = m.offsets[k]; j < m.offsets[k + 1]; ++j) {
      const int i = m.elements[j];
      if (lk < level[i]) {
        out[i] = v;
        level[i] = lk;
      } else if (lk == level[i] && (v > out[i] || std::isnan(v))) {
        if (!std::isnan(out[i])) out[i] = v;
      }
    }
  }
}

std::vector<double> values_from_names(const ModelDef& def, const std::vector<std::pair<std::string, double>>& items,
                                      const double* unnamed) {
  std::vector<std::string> names;
  std::vector<double> values;
  for (const auto& [name, v] : items) {
    names.push_back(name);
    values.push_back(v);
  }
  const NamedElements m = resolve_names(def, names);
  std::vector<double> out(def.num_elements);
  std::vector<NameLevel> level(def.num_elements);
  combine_named_values(m, values.data(), def.num_elements, out.data(), level.data());
  if (unnamed)
    for (int i = 0; i < def.num_elements; ++i)
      if (level[i] == NameLevel::kUnnamed) out[i] = unnamed[i];
  return out;
}

std::vector<double> excitations_from_names(const ModelDef& def,
                                           const std::vector<std::pair<std::string, double>>& items) {
  return values_from_names(def, items, nullptr);
}

int find_dof(const ModelDef& def, const std::string& name) {
  for (int j = 0; j < def.num_dofs; ++j)
    if (name == def.dofs[j].name) return j;
  for (int j = 0; j < def.num_dofs; ++j)
    if (def.dofs[j].osim_name && name == def.dofs[j].osim_name) return j;
  return -1;
}

std::vector<std::string> close_matches(const ModelDef& def, const std::string& name, NameKind kind, int n) {
  std::vector<std::string> choices;
  if (kind == NameKind::kDofs) {
    for (int j = 0; j < def.num_dofs; ++j) choices.emplace_back(def.dofs[j].name);
    for (int j = 0; j < def.num_dofs; ++j)
      if (def.dofs[j].osim_name) choices.emplace_back(def.dofs[j].osim_name);
  } else {
    choices = element_choices(def);
  }
  // A name typed in another case ('BICB') first: difflib's ratio is case-sensitive and would find nothing.
  std::vector<std::string> out;
  const std::string lower = to_lower(name);
  for (const std::string& c : choices)
    if (static_cast<int>(out.size()) < n && to_lower(c) == lower && c != name &&
        std::find(out.begin(), out.end(), c) == out.end())
      out.push_back(c);
  // As difflib: the ratio of (choice, word), kept at >= 0.6, the n largest (score, choice) pairs.
  std::vector<std::pair<double, std::string>> scored;
  for (const std::string& c : choices) {
    const double r = similarity(c, name);
    if (r >= 0.6) scored.emplace_back(r, c);
  }
  std::sort(scored.begin(), scored.end(), [](const auto& x, const auto& y) { return x > y; });
  for (size_t k = 0; k < scored.size() && static_cast<int>(out.size()) < n; ++k)
    if (std::find(out.begin(), out.end(), scored[k].second) == out.end()) out.push_back(scored[k].second);
  return out;
}

std::string unknown_names_message(const ModelDef& def, const std::vector<std::string>& names) {
  std::vector<std::string> parts;
  for (const std::string& name : names) {
    const auto close = close_matches(def, name, NameKind::kElementsMusclesGroups);
    parts.push_back(quoted(name) + (close.empty() ? "" : " (did you mean " + join_quoted(close, ", ") + "?)"));
  }
  std::string joined;
  for (size_t k = 0; k < parts.size(); ++k) joined += (k ? "; " : "") + parts[k];
  if (names.size() == 1) return "unknown element, muscle or group name " + joined + "; `armrt info` lists them";
  return std::to_string(names.size()) + " unknown element, muscle or group names: " + joined +
         "; `armrt info` lists them";
}

std::string unknown_dof_message(const ModelDef& def, const std::string& name) {
  const auto close = close_matches(def, name, NameKind::kDofs);
  if (!close.empty()) return "unknown DOF " + quoted(name) + "; did you mean " + join_quoted(close, ", ") + "?";
  std::vector<std::string> names, osim;
  for (int j = 0; j < def.num_dofs; ++j) {
    names.emplace_back(def.dofs[j].name);
    osim.emplace_back(def.dofs[j].osim_name ? def.dofs[j].osim_name : "");
  }
  return "unknown DOF " + quoted(name) + "; DOFs are [" + join_quoted(names, ", ") + "] (OpenSim [" +
         join_quoted(osim, ", ") + "])";
}

}  // namespace armrt
