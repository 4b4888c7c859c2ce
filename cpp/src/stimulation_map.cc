// stimulation_map.cc: a lab's stimulation map (JSON or TOML text) -> StimulationMap, validated field by field;
// the electrode kinds' defaults (docs/fes.md gives every value's source).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <toml++/toml.h>

#include "armrt/names.h"
#include "armrt/stimulation.h"
#include "fmt.h"

namespace armrt {

using detail::fmt;

namespace {

using nlohmann::json;

struct KindDefaults {
  const char* name;
  RecruitmentParams recruitment;
  ChannelLimits limits;
};

// Recruitment: threshold and saturation currents at a reference pulse width, and the motor axons' strength-
// duration time constant (Mogyoros, Kiernan & Burke 1996, Brain 119:439: about 0.4-0.5 ms). Limits: the device
// a kind is used with. Sources and what is an assumption: docs/fes.md "Electrode kinds".
constexpr double kChronaxie = 0.45e-3;
const KindDefaults kKinds[] = {
    // Surface: Veltink et al. 1992 (IEEE TBME 39:368) threshold 20 mA and saturation 60 mA; limits of a
    // clinical surface stimulator (RehaStim 2: 130 mA, 500 us, 100 Hz).
    {"surface", {20e-3, 60e-3, 300e-6, kChronaxie}, {500e-6, 130e-3, 100.0, 130e-3 * 500e-6}},
    // Intramuscular: NNP pulse generator (COSMIIC PG4: 0-20 mA, 1-255 us, 1-50 Hz); threshold 5 mA (Leitch
    // et al. 2017: 5-7 mA in tibialis anterior), saturation at the generator's 20 mA at 200 us.
    {"intramuscular", {5e-3, 20e-3, 200e-6, kChronaxie}, {255e-6, 20e-3, 50.0, 20e-3 * 255e-6}},
    // Epimysial: the same pulse generator and, in want of data of its own, the intramuscular ramp.
    {"epimysial", {5e-3, 20e-3, 200e-6, kChronaxie}, {255e-6, 20e-3, 50.0, 20e-3 * 255e-6}},
    // Nerve cuff: thresholds of about 0.1-2 mA at 10-250 us; the same pulse generator's limits.
    {"nerve_cuff", {0.2e-3, 2e-3, 100e-6, kChronaxie}, {255e-6, 20e-3, 50.0, 20e-3 * 255e-6}},
};
static_assert(sizeof kKinds / sizeof kKinds[0] == static_cast<int>(ElectrodeKind::kCount), "one row per kind");

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw std::invalid_argument("stimulation map: " + where + ": " + what);
}

double number(const json& j, const std::string& where) {
  if (!j.is_number() || j.is_boolean()) fail(where, "expected a number, got " + j.dump());
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(where, "must be finite");
  return v;
}

double positive(const json& obj, const char* key, double fallback, const std::string& where) {
  if (!obj.contains(key)) return fallback;
  const double v = number(obj.at(key), where + "." + key);
  if (!(v > 0)) fail(where + "." + key, "must be > 0, got " + fmt(v));
  return v;
}

void only_keys(const json& obj, std::initializer_list<const char*> keys, const std::string& where) {
  if (!obj.is_object()) fail(where, "expected a table (object), got " + obj.dump());
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    if (std::none_of(keys.begin(), keys.end(), [&](const char* k) { return it.key() == k; })) {
      std::string known;
      for (const char* k : keys) known += std::string(known.empty() ? "" : ", ") + k;
      fail(where, "unknown key '" + it.key() + "' (known: " + known + ")");
    }
  }
}

ElectrodeKind parse_kind(const json& j, const std::string& where) {
  if (!j.is_string()) fail(where, "expected a kind name, got " + j.dump());
  const std::string s = j.get<std::string>();
  for (int k = 0; k < static_cast<int>(ElectrodeKind::kCount); ++k)
    if (s == kKinds[k].name) return static_cast<ElectrodeKind>(k);
  fail(where, "unknown electrode kind '" + s + "' (surface, intramuscular, epimysial, nerve_cuff)");
}

}  // namespace

const char* electrode_kind_name(ElectrodeKind kind) { return kKinds[static_cast<int>(kind)].name; }
RecruitmentParams default_recruitment(ElectrodeKind kind) { return kKinds[static_cast<int>(kind)].recruitment; }
ChannelLimits default_limits(ElectrodeKind kind) { return kKinds[static_cast<int>(kind)].limits; }

DingParams default_ding_params() {
  // Ding et al. 2003 (J Electromyogr Kinesiol 13:575) in SI units; tau2 0.060 s and R0 = Km + 1.04 as
  // cocofest's Ding 2003 model uses them (docs/fes.md).
  DingParams p;
  p.tau_c_s = 0.020;
  p.tau1_s = 0.050957;
  p.tau2_s = 0.060;
  p.km = 0.103;
  p.r0_offset = 1.04;
  p.tau_fat_s = 127.0;
  p.alpha_a = -0.4;
  p.alpha_tau1 = 2.1e-5;
  p.alpha_km = 1.9e-5;
  p.a_rest_N_per_s = 3009.0;
  return p;
}

StimulationMap stimulation_map_from_json(const ModelDef& def, const std::string& json_text) {
  json root;
  try {
    root = json::parse(json_text);
  } catch (const json::parse_error& e) {
    fail("text", std::string("not JSON: ") + e.what());
  }
  only_keys(root, {"fatigue", "channels", "description"}, "map");
  StimulationMap map;
  if (root.contains("fatigue")) {
    if (!root.at("fatigue").is_boolean()) fail("fatigue", "expected true or false");
    map.fatigue = root.at("fatigue").get<bool>();
  }
  if (!root.contains("channels")) fail("map", "no 'channels' (a list of channels)");
  const json& chans = root.at("channels");
  if (!chans.is_array() || chans.empty()) fail("channels", "expected a non-empty list of channels");
  if (chans.size() > static_cast<size_t>(kMaxChannels))
    fail("channels", std::to_string(chans.size()) + " channels, more than the " + std::to_string(kMaxChannels) +
                         " an arm holds");
  std::vector<std::string> names;
  for (size_t k = 0; k < chans.size(); ++k) {
    const json& c = chans[k];
    std::string where = "channels[" + std::to_string(k) + "]";
    only_keys(c, {"name", "kind", "elements", "limits", "recruitment", "ding"}, where);
    if (!c.contains("name") || !c.at("name").is_string() || c.at("name").get<std::string>().empty())
      fail(where + ".name", "each channel needs a name (a non-empty string)");
    const std::string name = c.at("name").get<std::string>();
    if (name.size() >= static_cast<size_t>(kChannelNameSize))
      fail(where + ".name", "'" + name + "' is longer than " + std::to_string(kChannelNameSize - 1) + " characters");
    if (std::find(names.begin(), names.end(), name) != names.end()) fail(where + ".name", "'" + name + "' repeats");
    names.push_back(name);
    where = "channel '" + name + "'";
    StimChannel& ch = map.channels[k];
    std::memset(ch.name, 0, sizeof ch.name);
    std::memcpy(ch.name, name.data(), name.size());
    ch.kind = c.contains("kind") ? parse_kind(c.at("kind"), where + ".kind") : ElectrodeKind::kIntramuscular;
    const ChannelLimits device = default_limits(ch.kind);
    ch.limits = device;
    if (c.contains("limits")) {
      const json& l = c.at("limits");
      only_keys(l, {"max_pulse_width_s", "max_amplitude_A", "max_frequency_Hz", "max_charge_C"}, where + ".limits");
      ch.limits.max_pulse_width_s = positive(l, "max_pulse_width_s", device.max_pulse_width_s, where + ".limits");
      ch.limits.max_amplitude_A = positive(l, "max_amplitude_A", device.max_amplitude_A, where + ".limits");
      ch.limits.max_frequency_Hz = positive(l, "max_frequency_Hz", device.max_frequency_Hz, where + ".limits");
      ch.limits.max_charge_C = positive(l, "max_charge_C", device.max_charge_C, where + ".limits");
      // A lab may narrow what the device allows, never widen it.
      const std::pair<const char*, std::pair<double, double>> checks[] = {
          {"max_pulse_width_s", {ch.limits.max_pulse_width_s, device.max_pulse_width_s}},
          {"max_amplitude_A", {ch.limits.max_amplitude_A, device.max_amplitude_A}},
          {"max_frequency_Hz", {ch.limits.max_frequency_Hz, device.max_frequency_Hz}},
          {"max_charge_C", {ch.limits.max_charge_C, device.max_charge_C}}};
      for (const auto& [key, v] : checks)
        if (v.first > v.second * (1 + 1e-12))
          fail(where + ".limits." + key, fmt(v.first) + " exceeds the " + electrode_kind_name(ch.kind) +
                                             " device limit " + fmt(v.second));
    }
    ch.recruitment = default_recruitment(ch.kind);
    if (c.contains("recruitment")) {
      const json& r = c.at("recruitment");
      only_keys(r, {"threshold_A", "saturation_A", "reference_pulse_width_s", "chronaxie_s"}, where + ".recruitment");
      RecruitmentParams& p = ch.recruitment;
      p.threshold_A = positive(r, "threshold_A", p.threshold_A, where + ".recruitment");
      p.saturation_A = positive(r, "saturation_A", p.saturation_A, where + ".recruitment");
      p.reference_pulse_width_s = positive(r, "reference_pulse_width_s", p.reference_pulse_width_s, where + ".recruitment");
      p.chronaxie_s = positive(r, "chronaxie_s", p.chronaxie_s, where + ".recruitment");
      if (!(p.saturation_A > p.threshold_A))
        fail(where + ".recruitment", "saturation_A " + fmt(p.saturation_A) + " must exceed threshold_A " +
                                         fmt(p.threshold_A));
    }
    ch.ding = default_ding_params();
    if (c.contains("ding")) {
      const json& dj = c.at("ding");
      only_keys(dj, {"tau_c_s", "tau1_s", "tau2_s", "km", "r0_offset", "tau_fat_s", "alpha_a", "alpha_tau1",
                     "alpha_km", "a_rest_N_per_s"},
                where + ".ding");
      DingParams& p = ch.ding;
      const std::string w = where + ".ding";
      p.tau_c_s = positive(dj, "tau_c_s", p.tau_c_s, w);
      p.tau1_s = positive(dj, "tau1_s", p.tau1_s, w);
      p.tau2_s = positive(dj, "tau2_s", p.tau2_s, w);
      p.km = positive(dj, "km", p.km, w);
      p.r0_offset = positive(dj, "r0_offset", p.r0_offset, w);
      p.tau_fat_s = positive(dj, "tau_fat_s", p.tau_fat_s, w);
      p.a_rest_N_per_s = positive(dj, "a_rest_N_per_s", p.a_rest_N_per_s, w);
      if (dj.contains("alpha_a")) {
        p.alpha_a = number(dj.at("alpha_a"), w + ".alpha_a");
        if (p.alpha_a > 0) fail(w + ".alpha_a", "must be <= 0 (A falls under stimulation), got " + fmt(p.alpha_a));
      }
      if (dj.contains("alpha_tau1")) {
        p.alpha_tau1 = number(dj.at("alpha_tau1"), w + ".alpha_tau1");
        if (p.alpha_tau1 < 0) fail(w + ".alpha_tau1", "must be >= 0, got " + fmt(p.alpha_tau1));
      }
      if (dj.contains("alpha_km")) {
        p.alpha_km = number(dj.at("alpha_km"), w + ".alpha_km");
        if (p.alpha_km < 0) fail(w + ".alpha_km", "must be >= 0, got " + fmt(p.alpha_km));
      }
    }
    stimulation_derive(ch);
    // Elements: {name: weight} (a list of names means weight 1 each), by the name service's rule.
    if (!c.contains("elements")) fail(where, "no 'elements' (the elements, muscles or groups it reaches)");
    std::vector<std::pair<std::string, double>> items;
    const json& el = c.at("elements");
    if (el.is_array()) {
      for (const json& n : el) {
        if (!n.is_string()) fail(where + ".elements", "expected names, got " + n.dump());
        items.emplace_back(n.get<std::string>(), 1.0);
      }
    } else if (el.is_object()) {
      for (auto it = el.begin(); it != el.end(); ++it) {
        const double w = number(it.value(), where + ".elements." + it.key());
        if (!(w > 0 && w <= 1))
          fail(where + ".elements." + it.key(), "weight must lie in (0, 1] (the fraction recruited at saturation), got " + fmt(w));
        items.emplace_back(it.key(), w);
      }
    } else {
      fail(where + ".elements", "expected a list of names or a table {name: weight}");
    }
    if (items.empty()) fail(where + ".elements", "reaches no element");
    std::vector<double> weight;
    try {
      weight = excitations_from_names(def, items);
    } catch (const std::invalid_argument& e) {
      fail(where + ".elements", e.what());
    }
    ch.entry_begin = map.num_entries;
    for (int i = 0; i < def.num_elements; ++i) {
      if (!(weight[i] > 0)) continue;
      if (map.num_entries >= kMaxStimEntries)
        fail(where + ".elements", "the map reaches more than " + std::to_string(kMaxStimEntries) +
                                      " (channel, element) pairs");
      map.entries[map.num_entries++] = {static_cast<int>(k), i, weight[i]};
      map.driven[i] = 1.0;
    }
    ch.entry_end = map.num_entries;
    map.num_channels = static_cast<int>(k) + 1;
  }
  return map;
}

StimulationMap stimulation_map_from_file(const ModelDef& def, const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("stimulation map " + path + ": cannot read it");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const bool is_toml = path.size() > 5 && path.compare(path.size() - 5, 5, ".toml") == 0;
  try {
    if (is_toml) {
      std::ostringstream js;
      try {
        js << toml::json_formatter{toml::parse(text, path)};
      } catch (const toml::parse_error& e) {
        throw std::invalid_argument(std::string("not TOML: ") + std::string(e.description()) + " at line " +
                                    std::to_string(e.source().begin.line));
      }
      text = js.str();
    }
    return stimulation_map_from_json(def, text);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(path + ": " + e.what());
  }
}

StimulationMap stimulation_map_per_muscle(const ModelDef& def) {
  json chans = json::array();
  for (int k = 0; k < def.num_muscles; ++k)
    chans.push_back({{"name", def.muscles[k].name}, {"kind", "intramuscular"}, {"elements", {def.muscles[k].name}}});
  return stimulation_map_from_json(def, json{{"channels", chans}}.dump());
}

std::string stimulation_map_to_json(const ModelDef& def, const StimulationMap& map) {
  json chans = json::array();
  for (int k = 0; k < map.num_channels; ++k) {
    const StimChannel& ch = map.channels[k];
    json el = json::object();
    for (int e = ch.entry_begin; e < ch.entry_end; ++e) el[def.elements[map.entries[e].element].name] = map.entries[e].weight;
    const DingParams& d = ch.ding;
    chans.push_back({{"name", ch.name},
                     {"kind", electrode_kind_name(ch.kind)},
                     {"elements", el},
                     {"limits",
                      {{"max_pulse_width_s", ch.limits.max_pulse_width_s},
                       {"max_amplitude_A", ch.limits.max_amplitude_A},
                       {"max_frequency_Hz", ch.limits.max_frequency_Hz},
                       {"max_charge_C", ch.limits.max_charge_C}}},
                     {"recruitment",
                      {{"threshold_A", ch.recruitment.threshold_A},
                       {"saturation_A", ch.recruitment.saturation_A},
                       {"reference_pulse_width_s", ch.recruitment.reference_pulse_width_s},
                       {"chronaxie_s", ch.recruitment.chronaxie_s}}},
                     {"ding",
                      {{"tau_c_s", d.tau_c_s}, {"tau1_s", d.tau1_s}, {"tau2_s", d.tau2_s}, {"km", d.km},
                       {"r0_offset", d.r0_offset}, {"tau_fat_s", d.tau_fat_s}, {"alpha_a", d.alpha_a},
                       {"alpha_tau1", d.alpha_tau1}, {"alpha_km", d.alpha_km}, {"a_rest_N_per_s", d.a_rest_N_per_s}}}});
  }
  return json{{"fatigue", map.fatigue}, {"channels", chans}}.dump(2);
}

void stimulation_derive(StimChannel& ch) {
  const DingParams& p = ch.ding;
  const double ref_tau = p.tau1_s + p.tau2_s, f_ref = p.a_rest_N_per_s * ref_tau;
  ch.derived = {1.0 / p.tau_c_s, 1.0 / ref_tau, 1.0 / p.tau_fat_s, p.alpha_a * ref_tau, p.alpha_tau1 * f_ref / p.tau1_s,
                p.alpha_km * f_ref / p.km};
}

double recruitment_fraction(const RecruitmentParams& p, double pulse_width_s, double amplitude_A) {
  if (!(pulse_width_s > 0) || !(amplitude_A > 0)) return 0.0;
  const double eff = amplitude_A * (1.0 + p.chronaxie_s / p.reference_pulse_width_s) / (1.0 + p.chronaxie_s / pulse_width_s);
  const double r = (eff - p.threshold_A) / (p.saturation_A - p.threshold_A);
  return r < 0 ? 0.0 : (r > 1 ? 1.0 : r);
}

// The charge limit's relative tolerance: a command at exactly the limit, written as pulse width and amplitude, may
// round above it.
constexpr double kChargeTolerance = 1e-12;

namespace {

// The rules a channel command keeps, in the order a refusal names them.
enum class StimRule { kNone, kFinite, kNonNegative, kPulseWidth, kAmplitude, kFrequency, kCharge };

// The first rule (pw, amp, freq) breaks (kNone: none), and for kFinite / kNonNegative which value (0 pulse width,
// 1 amplitude, 2 frequency). No allocation: the real-time runner checks each stimulation packet with it.
StimRule broken_rule(const StimChannel& ch, double pw, double amp, double freq, int* which) {
  const double v[3] = {pw, amp, freq};
  for (int k = 0; k < 3; ++k) {
    *which = k;
    if (!std::isfinite(v[k])) return StimRule::kFinite;
    if (v[k] < 0) return StimRule::kNonNegative;
  }
  const ChannelLimits& l = ch.limits;
  if (pw > l.max_pulse_width_s) return StimRule::kPulseWidth;
  if (amp > l.max_amplitude_A) return StimRule::kAmplitude;
  if (freq > l.max_frequency_Hz) return StimRule::kFrequency;
  if (pw * amp > l.max_charge_C * (1 + kChargeTolerance)) return StimRule::kCharge;
  return StimRule::kNone;
}

}  // namespace

bool stimulation_command_allowed(const StimChannel& ch, double pw, double amp, double freq) {
  int which = 0;
  return broken_rule(ch, pw, amp, freq, &which) == StimRule::kNone;
}

std::string stimulation_command_error(const StimChannel& ch, double pw, double amp, double freq) {
  int which = 0;
  const StimRule rule = broken_rule(ch, pw, amp, freq, &which);
  if (rule == StimRule::kNone) return "";
  const std::string where = std::string("channel '") + ch.name + "': ";
  const char* names[3] = {"pulse width", "amplitude", "frequency"};
  const double values[3] = {pw, amp, freq};
  const ChannelLimits& l = ch.limits;
  switch (rule) {
    case StimRule::kFinite: return where + names[which] + " is not finite";
    case StimRule::kNonNegative: return where + names[which] + " " + fmt(values[which]) + " is negative";
    case StimRule::kPulseWidth:
      return where + "pulse width " + fmt(pw * 1e6) + " us exceeds its limit " + fmt(l.max_pulse_width_s * 1e6) + " us";
    case StimRule::kAmplitude:
      return where + "amplitude " + fmt(amp * 1e3) + " mA exceeds its limit " + fmt(l.max_amplitude_A * 1e3) + " mA";
    case StimRule::kFrequency:
      return where + "frequency " + fmt(freq) + " Hz exceeds its limit " + fmt(l.max_frequency_Hz) + " Hz";
    case StimRule::kCharge:
      return where + "charge per phase " + fmt(pw * amp * 1e6) + " uC (pulse width x amplitude) exceeds its limit " +
             fmt(l.max_charge_C * 1e6) + " uC";
    case StimRule::kNone: break;
  }
  return "";
}

}  // namespace armrt
