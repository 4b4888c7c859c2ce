// Stimulation: what an FES stimulator sends, per channel (electrode), to the arm's muscle elements.
//   channels     pulse width (s), amplitude (A), frequency (Hz) or queued pulse times per channel
//   recruitment  (pulse width, amplitude) -> recruited fraction R in [0, 1]: a strength-duration
//                threshold-saturation ramp per electrode kind (docs/fes.md)
//   frequency    pulse train -> normalised force level f of the fibres a channel recruits: Ding et al. 2003's
//                calcium (CN) and force (F) dynamics, the pulse sum carried recursively (no pulse history)
//   fatigue      f -> A, tau1, Km drift and recover (Ding et al. 2003), per channel
//   elements     a_e = min(max_activation_e, sum_k w_ek f_k): the activation each reached element follows
// Equations, parameters and their sources: docs/fes.md. Fixed-size: a map of up to kMaxChannels channels and
// kMaxStimEntries (channel, element, weight) entries lives in Data; a control step costs O(channels + entries)
// and never allocates.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "armrt/model.h"

namespace armrt {

inline constexpr int kMaxChannels = 64;
inline constexpr int kMaxStimEntries = 512;
inline constexpr int kMaxQueuedPulses = 16;  // explicit pulse times a channel holds ahead
inline constexpr int kChannelNameSize = 48;

// Electrode kinds, each with its recruitment parameters and default limits (stimulation.cc kKinds).
enum class ElectrodeKind { kSurface = 0, kIntramuscular = 1, kEpimysial = 2, kNerveCuff = 3, kCount = 4 };

// Recruitment: an effective current I_eff = I (1 + chronaxie/pw_ref) / (1 + chronaxie/pw) (the Weiss-Lapicque
// strength-duration law referred to pulse width pw_ref), then R = clip((I_eff - I_thr)/(I_sat - I_thr), 0, 1)
// (Veltink et al. 1992's threshold-saturation ramp).
struct RecruitmentParams {
  double threshold_A;            // A, current at pw_ref where the first fibres are recruited
  double saturation_A;           // A, current at pw_ref where all the electrode reaches are recruited
  double reference_pulse_width_s;  // s, pw_ref
  double chronaxie_s;            // s, strength-duration time constant of motor axons
};

// Ding et al. 2003 (J Electromyogr Kinesiol 13:575) in SI units, force normalised by F_ref = A_rest (tau1 + tau2)
// (the rested muscle's steady force under saturated calcium): docs/fes.md.
struct DingParams {
  double tau_c_s;       // s, calcium time constant
  double tau1_s;        // s, rested force decay time constant tau1
  double tau2_s;        // s, force decay added by bound cross-bridges
  double km;            // rested Km (sensitivity of strongly bound cross-bridges to CN)
  double r0_offset;     // R0 = Km + r0_offset (Ding 2003: 1.04)
  double tau_fat_s;     // s, recovery time constant of A, tau1, Km
  double alpha_a;       // 1/s^2, dA/dt per N of force (Ding 2003 alpha_A, SI)
  double alpha_tau1;    // 1/N, dtau1/dt per N of force
  double alpha_km;      // 1/(s N), dKm/dt per N of force
  double a_rest_N_per_s;  // N/s, Ding 2003's rested A: sets how fatigue rates scale with the normalised force
};

// A channel's safety limits: commands beyond them are refused (Python) or clamped and counted (armrt-rt).
struct ChannelLimits {
  double max_pulse_width_s;
  double max_amplitude_A;
  double max_frequency_Hz;
  double max_charge_C;  // per phase: amplitude x pulse width
};

// What the stage needs of DingParams per step, computed once when a map is made (stimulation_derive).
struct DingDerived {
  double inv_tau_c;      // 1/s
  double inv_ref_tau;    // 1/s, 1 / (tau1_r + tau2)
  double inv_tau_fat;    // 1/s
  double rate_a;         // 1/s per unit f: alpha_A F_ref / A_rest = alpha_A (tau1_r + tau2)
  double rate_tau1;      // 1/s per unit f: alpha_tau1 F_ref / tau1_r
  double rate_km;        // 1/s per unit f: alpha_Km F_ref / Km_r
};

struct StimChannel {
  char name[kChannelNameSize];
  ElectrodeKind kind;
  RecruitmentParams recruitment;
  DingParams ding;
  DingDerived derived;
  ChannelLimits limits;
  int entry_begin, entry_end;  // its entries in StimulationMap::entries
};

struct StimEntry {
  int channel, element;
  double weight;  // (0, 1]: the fraction of the element the channel recruits at saturation (spill-over < 1)
};

struct StimulationMap {
  int num_channels = 0;
  int num_entries = 0;
  bool fatigue = true;  // whether A, tau1, Km drift under stimulation (false: a fresh muscle forever)
  std::array<StimChannel, kMaxChannels> channels{};
  std::array<StimEntry, kMaxStimEntries> entries{};  // sorted by channel
  // 1.0: an element some channel reaches (stimulation drives it), else 0.0 (a double, so that the muscles stage
  // selects on it in SIMD lanes).
  std::array<double, kMaxElements> driven{};
  std::array<double, kMaxElements> inv_weight_sum{};  // 1 / the element's summed weights (data_set_stimulation_map)
  // The channels' parameters the stage reads, one array per parameter so that it reads them in SIMD lanes
  // (data_set_stimulation_map fills them from channels[k].ding and .derived): s, s, 1, 1/s, 1/s, 1/s, and the
  // fatigue rates (1/s per unit f). A map with fatigue off has inv_tau_fat and the rates zero.
  struct Lanes {
    std::array<double, kMaxChannels> tau1_s, tau2_s, km, inv_tau_c, inv_ref_tau, inv_tau_fat, rate_a, rate_tau1,
        rate_km;
  } lanes{};
};

// Per-channel values of Data::stimulation (the inputs, held over the steps): kStimInputs per channel.
enum StimInput { kStimPulseWidth = 0, kStimAmplitude = 1, kStimFrequency = 2, kStimInputs = 3 };
// The columns of Data::stimulation_state (the chain's memory, part of the snapshot). It is stored by column:
// column c of channel k at stim_state_index(c, k, num_channels), every channel's value of a column contiguous, so
// that the stage reads a column over channels in SIMD lanes. The snapshot holds it per channel (snapshot.cc).
enum StimState {
  kStimCalciumSum = 0,  // S = sum_i R_i exp(-(t - t_i)/tau_c) over past pulses (carried recursively)
  kStimCalcium,         // CN
  kStimForce,           // f = F / F_ref
  kStimFatigueA,        // A / A_rest
  kStimFatigueTau1,     // tau1 / tau1_rest
  kStimFatigueKm,       // Km / Km_rest
  kStimLastPulse,       // s, time of the last pulse (kNoPulse: none yet)
  kStimRecruitment,     // R of the last pulse
  kStimQueued,          // explicit pulse times queued (0..kMaxQueuedPulses)
  kStimQueue,           // kMaxQueuedPulses times (s), earliest first
  kStimStateSize = kStimQueue + kMaxQueuedPulses
};
inline constexpr double kNoPulse = -1e9;  // a time long before any simulation
inline constexpr int stim_state_index(int column, int channel, int num_channels) {
  return column * num_channels + channel;
}

// The map from a JSON text (docs/fes.md "Stimulation maps"): channels with names, kinds, elements by
// element, muscle, group or OpenSim names with weights, limits and model parameters. Throws
// std::invalid_argument naming the field for anything wrong: an unknown key, name or kind, a weight outside
// (0, 1], a limit beyond the kind's device limits, a channel that reaches no element, a map with no channel.
StimulationMap stimulation_map_from_json(const ModelDef& def, const std::string& json_text);
// The same from a file: .json, or .toml (converted by toml++). Errors name the file.
StimulationMap stimulation_map_from_file(const ModelDef& def, const std::string& path);
// One intramuscular channel per muscle, named after it, reaching all its elements with weight 1.
StimulationMap stimulation_map_per_muscle(const ModelDef& def);
// The map as JSON (every default made explicit), readable by stimulation_map_from_json.
std::string stimulation_map_to_json(const ModelDef& def, const StimulationMap& map);

// Fills ch.derived from ch.ding (every map the engine makes has it; call it after changing ding by hand).
void stimulation_derive(StimChannel& ch);

const char* electrode_kind_name(ElectrodeKind kind);
RecruitmentParams default_recruitment(ElectrodeKind kind);
ChannelLimits default_limits(ElectrodeKind kind);
DingParams default_ding_params();

// Recruited fraction for one pulse (0 for a zero pulse width or amplitude).
double recruitment_fraction(const RecruitmentParams& p, double pulse_width_s, double amplitude_A);

// Whether a channel command is accepted: finite, >= 0 and within the channel's limits (pulse width, amplitude,
// frequency, charge per phase). No allocation: the real-time runner checks each stimulation packet with it.
bool stimulation_command_allowed(const StimChannel& ch, double pulse_width_s, double amplitude_A, double frequency_Hz);
// Why a channel command is refused ("" if stimulation_command_allowed): the value and the limit it breaks.
std::string stimulation_command_error(const StimChannel& ch, double pulse_width_s, double amplitude_A,
                                      double frequency_Hz);

}  // namespace armrt
