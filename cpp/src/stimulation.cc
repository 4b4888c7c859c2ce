// Stage: stimulation, once per control step before the integrator. (the channels' pulse width, amplitude,
// frequency and queued pulses over [t, t + h], the chain's memory) -> the memory at t + h, and for every element a
// channel reaches the activation ODE's target and rate over the step (Data::drive_target, drive_rate), so that
// the element's activation arrives at a_e = min(max_activation_e, sum_k w_ek f_k(t + h)).
//
// Per channel (Ding et al. 2003, J Electromyogr Kinesiol 13:575; SI units, force normalised, docs/fes.md):
//   dCN/dt = (S - CN)/tau_c,  S = sum_i R_i exp(-(t - t_i)/tau_c),  R_i = 1 + (R0 - 1) exp(-(t_i - t_{i-1})/tau_c)
//   df/dt  = R A_hat x / (tau1_r + tau2) - f / (tau1 + tau2 x),     x = CN / (Km + CN)
//   dA_hat/dt = -(A_hat - 1)/tau_fat + alpha_A F_ref/A_rest f,  likewise tau1/tau1_r and Km/Km_r
// Every term of S decays with the same tau_c, so S itself is one state: S <- S e^{-d/tau_c}, S += R_i at a pulse
// (exact, no pulse history). Between events CN is exact: CN(s) = e^{-s/tau_c} (CN0 + S0 s/tau_c). f takes an
// exponential-Euler step with x averaged by Simpson's rule over the segment; the fatigue states an Euler step on
// the segment's mean f. Segments end at pulses and are at most kMaxSegment long.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "armrt/engine.h"
#include "armrt/stimulation.h"

namespace armrt {

namespace {

constexpr double kMaxSegment = 1e-3;  // s: the scheme's validated step (docs/fes.md "Numerics")

// The chain's memory by column (stimulation.h stim_state_index): one pointer per column, indexed by channel.
struct Memory {
  double *S, *CN, *f, *A, *T1, *KM, *last, *R, *queued, *queue;  // queue: kMaxQueuedPulses columns
  int nc;
  double& queue_at(int i, int k) const { return queue[i * nc + k]; }
};
Memory memory(Data& d) {
  const int nc = d.stimulation_map.num_channels;
  double* base = d.stimulation_state.data();
  auto col = [&](int c) { return base + stim_state_index(c, 0, nc); };
  return {col(kStimCalciumSum), col(kStimCalcium), col(kStimForce), col(kStimFatigueA), col(kStimFatigueTau1),
          col(kStimFatigueKm), col(kStimLastPulse), col(kStimRecruitment), col(kStimQueued), col(kStimQueue), nc};
}

// Whether a frequency train's next pulse (1/f after the last) may come before `horizon`: a product, not the
// division 1/f, with a margin far above rounding, so that every pulse that comes is found at its exact time.
// Bitwise and, so that it runs in SIMD lanes too.
[[gnu::always_inline]] inline bool train_pulse_due(double f, double last_pulse, double horizon) {
  return (f > 0.0) & ((horizon - last_pulse) * f >= 1.0 - 1e-9);
}

// exp(-z) by its Taylor polynomial of degree 7, for 0 <= z < 0.1 (relative error < 3e-13). Constants as products:
// a division by 5040 is a division (the compiler may not turn it into a product), and divisions are what cost.
inline double exp_neg_small(double z) {
  const double y = -z;
  return 1.0 + y * (1.0 + y * (1.0 / 2 + y * (1.0 / 6 + y * (1.0 / 24 + y * (1.0 / 120 + y * (1.0 / 720 + y * (1.0 / 5040)))))));
}

// exp(-z) for z >= 0: by its Taylor polynomial of degree 7 below 0.1 (relative error < 3e-13), where every
// exponent of a 1 ms step lies (h/tau_c = 0.05, h/tau <= 0.02), else std::exp. Half of the chain's cost
// was std::exp.
inline double exp_neg(double z) {
  if (z >= 0.1) return std::exp(-z);
  return exp_neg_small(z);
}

// One segment of length dt with no pulse inside it, on plain values (so that the same lines run per channel and
// in SIMD lanes over channels): the memory (S, CN, f, A_hat, tau1_hat, Km_hat) in place; returns the exponent of
// the force's decay over it, dt / tau_eff (dimensionless). R: the last pulse's recruitment. small: every exponent
// (dt / (2 tau_c), dt / tau1) is below 0.1, where exp_neg_small is exact (the SIMD pass's channels). A map
// without fatigue has zero fatigue rates (data_set_stimulation_map), so that A_hat, tau1_hat and Km_hat stay
// exactly 1 with no branch.
struct SegmentParams {
  double tau1_s, tau2_s, km, inv_tau_c, inv_ref_tau, inv_tau_fat, rate_a, rate_tau1, rate_km;
};
[[gnu::always_inline]] inline double segment(const SegmentParams& c, bool small, double dt, double R, double& S,
                                             double& CN, double& f, double& A, double& T1, double& KM) {
  const double S0 = S, CN0 = CN, f0 = f;
  const double tau1 = T1 * c.tau1_s, Km = KM * c.km;
  const double half = 0.5 * dt * c.inv_tau_c;
  const double e_half = small ? exp_neg_small(half) : exp_neg(half), e_end = e_half * e_half;
  const double cn_mid = e_half * (CN0 + S0 * 0.5 * dt * c.inv_tau_c), cn_end = e_end * (CN0 + S0 * dt * c.inv_tau_c);
  // x = CN / (Km + CN) at the segment's start, middle and end with one division: the chain's cost is its divisions.
  const double d0 = Km + CN0, d1 = Km + cn_mid, d2 = Km + cn_end;
  const double d01 = d0 * d1, inv = 1.0 / (d01 * d2);
  const double x_end = cn_end * d01 * inv;
  const double x_mean = (CN0 * d1 + 4.0 * cn_mid * d0) * d2 * inv * (1.0 / 6.0) + x_end * (1.0 / 6.0);
  const double tau_eff = tau1 + c.tau2_s * x_mean;
  const double z = dt / tau_eff;
  const double decay = small ? exp_neg_small(z) : exp_neg(z);
  const double drive = R * A * x_mean * c.inv_ref_tau;
  const double f1 = f0 * decay + drive * tau_eff * (1.0 - decay);
  S = S0 * e_end;
  CN = cn_end;
  f = f1;
  const double f_mean = 0.5 * (f0 + f1);
  const double A1 = A + dt * (-(A - 1.0) * c.inv_tau_fat + c.rate_a * f_mean);
  T1 += dt * (-(T1 - 1.0) * c.inv_tau_fat + c.rate_tau1 * f_mean);
  KM += dt * (-(KM - 1.0) * c.inv_tau_fat + c.rate_km * f_mean);
  A = A1 < 0.0 ? 0.0 : A1;  // A cannot change sign (Euler on a fully fatigued muscle)
  return z;
}

// Channel k's segment parameters, from the map's lanes (data_set_stimulation_map).
[[gnu::always_inline]] inline SegmentParams segment_params(const StimulationMap::Lanes& l, int k) {
  return {l.tau1_s[k], l.tau2_s[k], l.km[k], l.inv_tau_c[k], l.inv_ref_tau[k], l.inv_tau_fat[k],
          l.rate_a[k], l.rate_tau1[k], l.rate_km[k]};
}

// Advances channel k's memory by a segment of length dt (< 0.2 tau_c, every segment: at most kMaxSegment) with
// no pulse inside it; returns dt / tau_eff.
double advance_segment(const StimulationMap& map, const Memory& mem, int k, double dt) {
  return segment(segment_params(map.lanes, k), false, dt, mem.R[k], mem.S[k], mem.CN[k], mem.f[k], mem.A[k],
                 mem.T1[k], mem.KM[k]);
}

void pulse(const StimChannel& ch, const double* input, const Memory& mem, int k, double t) {
  const DingParams& p = ch.ding;
  const double r0 = p.km * mem.KM[k] + p.r0_offset;  // R0 = Km(t) + 1.04 (Ding 2003)
  const double gap = t - mem.last[k];
  mem.S[k] += 1.0 + (r0 - 1.0) * std::exp(-gap / p.tau_c_s);
  mem.last[k] = t;
  // The most recent pulse's recruitment scales A (as Ding et al. 2007 apply its pulse duration).
  mem.R[k] = recruitment_fraction(ch.recruitment, input[kStimPulseWidth], input[kStimAmplitude]);
}

// Time of channel k's next pulse at or after t if it may come before `horizon` (kNoPulse if none does): the
// earlier of its frequency train (1/f after the last pulse, at once if that is past) and its first queued pulse.
double next_pulse(const double* input, const Memory& mem, int k, double t, double horizon) {
  double next = kNoPulse;
  const double f = input[kStimFrequency];
  if (train_pulse_due(f, mem.last[k], horizon)) next = std::max(t, mem.last[k] + 1.0 / f);
  if (mem.queued[k] > 0 && (next == kNoPulse || mem.queue_at(0, k) < next)) next = std::max(t, mem.queue_at(0, k));
  return next;
}

void pop_queued(const Memory& mem, int k, double t) {
  const int n = static_cast<int>(mem.queued[k]);
  int drop = 0;
  while (drop < n && mem.queue_at(drop, k) <= t) ++drop;
  for (int i = drop; i < n; ++i) mem.queue_at(i - drop, k) = mem.queue_at(i, k);
  for (int i = n - drop; i < n; ++i) mem.queue_at(i, k) = 0.0;
  mem.queued[k] = n - drop;
}

}  // namespace

void stimulation_reset(Data& d) {
  std::fill(d.stimulation_state.begin(), d.stimulation_state.end(), 0.0);
  const Memory mem = memory(d);
  for (int k = 0; k < mem.nc; ++k) {
    mem.A[k] = mem.T1[k] = mem.KM[k] = 1.0;
    mem.last[k] = kNoPulse;
  }
  std::fill(d.recruitment.begin(), d.recruitment.end(), 0.0);
  std::fill(d.fatigue.begin(), d.fatigue.end(), 0.0);
}

void data_set_stimulation_map(const Model& m, Data& d, const StimulationMap& map) {
  for (int e = 0; e < map.num_entries; ++e)
    if (map.entries[e].element < 0 || map.entries[e].element >= m.num_elements)
      throw std::invalid_argument("stimulation map: element index out of range for model " + std::string(m.def->name));
  d.stimulation_map = map;
  StimulationMap& installed = d.stimulation_map;
  std::array<double, kMaxElements> w_sum{};
  for (int e = 0; e < installed.num_entries; ++e) w_sum[installed.entries[e].element] += installed.entries[e].weight;
  for (int i = 0; i < kMaxElements; ++i) installed.inv_weight_sum[i] = w_sum[i] > 0 ? 1.0 / w_sum[i] : 0.0;
  const double on = installed.fatigue ? 1.0 : 0.0;  // without fatigue: no drift and no recovery
  StimulationMap::Lanes& l = installed.lanes;
  for (int k = 0; k < installed.num_channels; ++k) {
    const StimChannel& ch = installed.channels[k];
    l.tau1_s[k] = ch.ding.tau1_s, l.tau2_s[k] = ch.ding.tau2_s, l.km[k] = ch.ding.km;
    l.inv_tau_c[k] = ch.derived.inv_tau_c, l.inv_ref_tau[k] = ch.derived.inv_ref_tau;
    l.inv_tau_fat[k] = on * ch.derived.inv_tau_fat;
    l.rate_a[k] = on * ch.derived.rate_a, l.rate_tau1[k] = on * ch.derived.rate_tau1, l.rate_km[k] = on * ch.derived.rate_km;
  }
  std::fill(d.stimulation.begin(), d.stimulation.end(), 0.0);
  stimulation_reset(d);
}

void stimulation_advance(const Model& m, Data& d, double h) {
  const StimulationMap& map = d.stimulation_map;
  if (map.num_channels == 0) return;
  const double t0 = d.time, t_end = d.time + h;
  const int nc = map.num_channels;
  const Memory mem = memory(d);
  const StimulationMap::Lanes& l = map.lanes;
  // Each channel's force level at the step's end and its force's decay exponent over the step (the sum of
  // dt / tau_eff) side by side: an entry reads both from one cache line.
  double channel_fz[2 * kMaxChannels];
  // 1 where the lanes pass below advanced the channel (64 bits wide, as the doubles beside it in the lanes)
  std::int64_t whole_step[kMaxChannels];
  // Most channels have no pulse inside the step (one every 25-50 steps at 20-40 Hz): one segment of length h
  // advances them, in SIMD lanes over every channel (the memory is stored by column for this). The segment is
  // computed for every channel and kept where it is the whole step: no train pulse due before t_end, nothing
  // queued, a step within kMaxSegment and exponents below 0.1. A channel with a pulse inside the step takes its segments one at a time in the loop after.
  // The exponents' bound, and none for a step longer than kMaxSegment (a number, not a bool: the lanes' tests are
  // bitwise ands of comparisons, which the vectoriser takes where it refuses a branch on a bool).
  const double small_z = t0 + kMaxSegment >= t_end ? 0.1 : -1.0;
#pragma omp simd
  for (int k = 0; k < nc; ++k) {
    const double S0 = mem.S[k], CN0 = mem.CN[k], f0 = mem.f[k], A0 = mem.A[k], T10 = mem.T1[k], KM0 = mem.KM[k];
    const double R = mem.R[k];
    // What the step starts from (recorded with the step's start state).
    d.recruitment[k] = R;
    d.fatigue[k] = 1.0 - A0;
    const double freq = d.stimulation[k * kStimInputs + kStimFrequency];
    const bool train_due = train_pulse_due(freq, mem.last[k], t_end);
    const bool small = (0.5 * h * l.inv_tau_c[k] < small_z) & (h < small_z * l.tau1_s[k] * T10);
    const bool keep = !train_due & !(mem.queued[k] > 0) & small;
    double S = S0, CN = CN0, f = f0, A = A0, T1 = T10, KM = KM0;
    const double z = segment(segment_params(l, k), true, h, R, S, CN, f, A, T1, KM);
    mem.S[k] = keep ? S : S0, mem.CN[k] = keep ? CN : CN0, mem.f[k] = keep ? f : f0;
    mem.A[k] = keep ? A : A0, mem.T1[k] = keep ? T1 : T10, mem.KM[k] = keep ? KM : KM0;
    channel_fz[2 * k] = f, channel_fz[2 * k + 1] = z;
    whole_step[k] = keep;
  }
  int pulsing[kMaxChannels];  // the channels the lanes pass left, listed without a branch per channel
  int num_pulsing = 0;
  for (int k = 0; k < nc; ++k) {
    pulsing[num_pulsing] = k;
    num_pulsing += 1 - static_cast<int>(whole_step[k]);
  }
  for (int j = 0; j < num_pulsing; ++j) {
    const int k = pulsing[j];
    const StimChannel& ch = map.channels[k];
    const double* input = d.stimulation.data() + k * kStimInputs;
    double t = t0, z = 0.0;
    while (t < t_end) {
      double stop = std::min(t_end, t + kMaxSegment);
      const double event = next_pulse(input, mem, k, t, stop);
      if (event != kNoPulse && event <= t) {
        pulse(ch, input, mem, k, t);
        pop_queued(mem, k, t);
        continue;
      }
      if (event != kNoPulse && event < stop) stop = event;
      z += advance_segment(map, mem, k, stop - t);
      t = (stop == t_end) ? t_end : stop;
    }
    channel_fz[2 * k] = mem.f[k], channel_fz[2 * k + 1] = z;
  }
  // The elements' activation targets: a first-order ODE da/dt = rate (target - a) that lands on the channels'
  // force level at t_end. Its decay exponent over the step is the reached channels' weighted mean exponent; any
  // decay in (0, 1) lands on the level, this one also follows the channels' shape within the step.
  const int n = m.num_elements;
  double level_z[2 * kMaxElements];  // per element: sum_k w_ek f_k and sum_k w_ek z_k, side by side
  std::fill(level_z, level_z + 2 * n, 0.0);
  for (int e = 0; e < map.num_entries; ++e) {
    const StimEntry& en = map.entries[e];
    double* sums = level_z + 2 * static_cast<std::size_t>(en.element);  // (no int arithmetic per index)
    const double* fz = channel_fz + 2 * static_cast<std::size_t>(en.channel);
    sums[0] += en.weight * fz[0];
    sums[1] += en.weight * fz[1];
  }
  const double* a = d.x.data() + act_offset(m);
  const double* cap = d.muscles.max_activation.data();
  const double inv_h = 1.0 / h;
  // Branch-free over every element so that it runs in SIMD lanes (the divisions are the stage's cost); an element
  // no channel reaches has inv_weight_sum 0, hence z = 0, and its values are never read (muscles.cc: driven only).
  double z_max = 0.0;
#pragma omp simd reduction(max : z_max)
  for (int i = 0; i < n; ++i) {
    // (Ternaries, not std::min, max or clamp: those return references, and the vectoriser gives up on them.)
    const double level = level_z[2 * i], z = level_z[2 * i + 1] * map.inv_weight_sum[i];
    z_max = z > z_max ? z : z_max;
    const double decay = exp_neg_small(z);
    const double target_end = level < cap[i] ? level : cap[i];
    const double target = (target_end - a[i] * decay) / (1.0 - decay + (z == 0.0 ? 1.0 : 0.0));
    const double above_zero = target > 0.0 ? target : 0.0;
    d.drive_target[i] = above_zero < cap[i] ? above_zero : cap[i];
    d.drive_rate[i] = z * inv_h;  // 1/tau of that decay
  }
  if (z_max >= 0.1) {  // a long control step (h >= tau_eff / 10): the polynomial is not exact enough there
    for (int i = 0; i < n; ++i) {
      const double z = level_z[2 * i + 1] * map.inv_weight_sum[i];
      if (z < 0.1) continue;
      const double decay = std::exp(-z);
      const double target = (std::min(cap[i], level_z[2 * i]) - a[i] * decay) / (1.0 - decay);
      d.drive_target[i] = std::min(std::max(target, 0.0), cap[i]);
    }
  }
}

void stimulation_queue_pulses(const Model&, Data& d, int channel, const double* times, int count) {
  const StimulationMap& map = d.stimulation_map;
  if (channel < 0 || channel >= map.num_channels) throw std::invalid_argument("no stimulation channel " + std::to_string(channel));
  const Memory mem = memory(d);
  const int have = static_cast<int>(mem.queued[channel]);
  if (have + count > kMaxQueuedPulses)
    throw std::invalid_argument(std::string("channel '") + map.channels[channel].name + "': " +
                                std::to_string(have + count) + " queued pulses, more than the " +
                                std::to_string(kMaxQueuedPulses) + " a channel holds ahead (queue the rest later)");
  double prev = have > 0 ? mem.queue_at(have - 1, channel) : d.time;
  for (int i = 0; i < count; ++i) {
    if (!std::isfinite(times[i]) || times[i] < prev || (i == 0 && have == 0 && times[i] < d.time))
      throw std::invalid_argument(std::string("channel '") + map.channels[channel].name +
                                  "': pulse times must be finite, increasing and not before the arm's time " +
                                  std::to_string(d.time) + " s");
    prev = times[i];
  }
  for (int i = 0; i < count; ++i) mem.queue_at(have + i, channel) = times[i];
  mem.queued[channel] = have + count;
}

double channel_fatigue(const Data& d, int k) {
  return 1.0 - d.stimulation_state[stim_state_index(kStimFatigueA, k, d.stimulation_map.num_channels)];
}

void stimulation_state_by_channel(const Data& d, double* out) {
  const int nc = d.stimulation_map.num_channels;
  for (int k = 0; k < nc; ++k)
    for (int c = 0; c < kStimStateSize; ++c) out[k * kStimStateSize + c] = d.stimulation_state[stim_state_index(c, k, nc)];
}

void set_stimulation_state_by_channel(Data& d, const double* in) {
  const int nc = d.stimulation_map.num_channels;
  for (int k = 0; k < nc; ++k)
    for (int c = 0; c < kStimStateSize; ++c) d.stimulation_state[stim_state_index(c, k, nc)] = in[k * kStimStateSize + c];
}

}  // namespace armrt
