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

#include "armrt/engine.h"
#include "armrt/stimulation.h"

namespace armrt {

namespace {

constexpr double kMaxSegment = 1e-3;  // s: the scheme's validated step (docs/fes.md "Numerics")

double* channel_state(Data& d, int k) { return d.stimulation_state.data() + k * kStimStateSize; }
const double* channel_state(const Data& d, int k) { return d.stimulation_state.data() + k * kStimStateSize; }


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
// (dt / (2 tau_c), dt / tau1) is below 0.1, where exp_neg_small is exact (the SIMD pass's channels).
struct SegmentParams {
  double tau1_s, tau2_s, km, inv_tau_c, inv_ref_tau, inv_tau_fat, rate_a, rate_tau1, rate_km;
};
[[gnu::always_inline]] inline double segment(const SegmentParams& c, bool fatigue, bool small, double dt, double R, double& S, double& CN,
                      double& f, double& A, double& T1, double& KM) {
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
  if (fatigue) {
    const double f_mean = 0.5 * (f0 + f1);
    const double A1 = A + dt * (-(A - 1.0) * c.inv_tau_fat + c.rate_a * f_mean);
    T1 += dt * (-(T1 - 1.0) * c.inv_tau_fat + c.rate_tau1 * f_mean);
    KM += dt * (-(KM - 1.0) * c.inv_tau_fat + c.rate_km * f_mean);
    A = A1 < 0.0 ? 0.0 : A1;  // A cannot change sign (Euler on a fully fatigued muscle)
  }
  return z;
}

SegmentParams segment_params(const StimChannel& ch) {
  const DingDerived& c = ch.derived;
  return {ch.ding.tau1_s, ch.ding.tau2_s, ch.ding.km, c.inv_tau_c, c.inv_ref_tau, c.inv_tau_fat,
          c.rate_a, c.rate_tau1, c.rate_km};
}

// Advances one channel's memory by a segment of length dt (< 0.2 tau_c, every segment: at most kMaxSegment) with
// no pulse inside it; returns dt / tau_eff.
double advance_segment(const StimChannel& ch, bool fatigue, double* st, double dt) {
  return segment(segment_params(ch), fatigue, false, dt, st[kStimRecruitment], st[kStimCalciumSum], st[kStimCalcium],
                 st[kStimForce], st[kStimFatigueA], st[kStimFatigueTau1], st[kStimFatigueKm]);
}

void pulse(const StimChannel& ch, const double* input, double* st, double t) {
  const DingParams& p = ch.ding;
  const double r0 = p.km * st[kStimFatigueKm] + p.r0_offset;  // R0 = Km(t) + 1.04 (Ding 2003)
  const double gap = t - st[kStimLastPulse];
  st[kStimCalciumSum] += 1.0 + (r0 - 1.0) * std::exp(-gap / p.tau_c_s);
  st[kStimLastPulse] = t;
  // The most recent pulse's recruitment scales A (as Ding et al. 2007 apply its pulse duration).
  st[kStimRecruitment] = recruitment_fraction(ch.recruitment, input[kStimPulseWidth], input[kStimAmplitude]);
}

// Time of the channel's next pulse at or after t if it may come before `horizon` (kNoPulse if none does): the
// earlier of its frequency train (1/f after the last pulse, at once if that is past) and its first queued pulse.
// Most steps have no pulse: a product tells that without the division 1/f (with a margin far above rounding, so
// every pulse that comes is found at its exact time).
double next_pulse(const double* input, const double* st, double t, double horizon) {
  double next = kNoPulse;
  const double f = input[kStimFrequency];
  if (f > 0.0 && (horizon - st[kStimLastPulse]) * f >= 1.0 - 1e-9) next = std::max(t, st[kStimLastPulse] + 1.0 / f);
  if (st[kStimQueued] > 0 && (next == kNoPulse || st[kStimQueue] < next)) next = std::max(t, st[kStimQueue]);
  return next;
}

void pop_queued(double* st, double t) {
  int n = static_cast<int>(st[kStimQueued]);
  int drop = 0;
  while (drop < n && st[kStimQueue + drop] <= t) ++drop;
  for (int i = drop; i < n; ++i) st[kStimQueue + i - drop] = st[kStimQueue + i];
  for (int i = n - drop; i < n; ++i) st[kStimQueue + i] = 0.0;
  st[kStimQueued] = n - drop;
}

}  // namespace

void stimulation_reset(Data& d) {
  const StimulationMap& map = d.stimulation_map;
  std::fill(d.stimulation_state.begin(), d.stimulation_state.end(), 0.0);
  for (int k = 0; k < map.num_channels; ++k) {
    double* st = channel_state(d, k);
    st[kStimFatigueA] = st[kStimFatigueTau1] = st[kStimFatigueKm] = 1.0;
    st[kStimLastPulse] = kNoPulse;
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
  for (int k = 0; k < installed.num_channels; ++k) {
    const SegmentParams c = segment_params(installed.channels[k]);
    StimulationMap::Lanes& l = installed.lanes;
    l.tau1_s[k] = c.tau1_s, l.tau2_s[k] = c.tau2_s, l.km[k] = c.km, l.inv_tau_c[k] = c.inv_tau_c;
    l.inv_ref_tau[k] = c.inv_ref_tau, l.inv_tau_fat[k] = c.inv_tau_fat;
    l.rate_a[k] = c.rate_a, l.rate_tau1[k] = c.rate_tau1, l.rate_km[k] = c.rate_km;
  }
  std::fill(d.stimulation.begin(), d.stimulation.end(), 0.0);
  stimulation_reset(d);
}

void stimulation_advance(const Model& m, Data& d, double h) {
  const StimulationMap& map = d.stimulation_map;
  if (map.num_channels == 0) return;
  const double t0 = d.time, t_end = d.time + h;
  double channel_z[kMaxChannels];  // each channel's force decay exponent over the step, sum of dt / tau_eff
  double channel_f[kMaxChannels];  // and its force level at the step's end
  // Most channels have no pulse inside the step (one every 25-50 steps at 20-40 Hz): their one segment of length h
  // runs below in SIMD lanes over channels; a channel with a pulse inside the step (or a step longer than
  // kMaxSegment) takes its segments here, one channel at a time.
  const int nc = map.num_channels;
  const StimulationMap::Lanes& l = map.lanes;
  // Which channels take the SIMD pass, decided in lanes too: no train pulse due before t_end ((t_end - t_last) f
  // below 1, with a margin far above rounding), nothing queued, a step within kMaxSegment, exponents below 0.1.
  unsigned char in_lanes[kMaxChannels];
  const bool short_step = t0 + kMaxSegment >= t_end;
#pragma omp simd
  for (int k = 0; k < nc; ++k) {
    const double* st = d.stimulation_state.data() + k * kStimStateSize;
    const double f = d.stimulation[k * kStimInputs + kStimFrequency];
    // What the step starts from (recorded with the step's start state).
    d.recruitment[k] = st[kStimRecruitment];
    d.fatigue[k] = 1.0 - st[kStimFatigueA];
    const bool train_due = f > 0.0 && (t_end - st[kStimLastPulse]) * f >= 1.0 - 1e-9;
    const bool small = 0.5 * h * l.inv_tau_c[k] < 0.1 && h < 0.1 * l.tau1_s[k] * st[kStimFatigueTau1];
    in_lanes[k] = short_step && !train_due && !(st[kStimQueued] > 0) && small;
  }
  int whole[kMaxChannels];
  int num_whole = 0;
  for (int k = 0; k < nc; ++k) {
    if (in_lanes[k]) {
      whole[num_whole++] = k;
      continue;
    }
    const StimChannel& ch = map.channels[k];
    const double* input = d.stimulation.data() + k * kStimInputs;
    double* st = channel_state(d, k);
    double t = t0, z = 0.0;
    while (t < t_end) {
      double stop = std::min(t_end, t + kMaxSegment);
      const double event = next_pulse(input, st, t, stop);
      if (event != kNoPulse && event <= t) {
        pulse(ch, input, st, t);
        pop_queued(st, t);
        continue;
      }
      if (event != kNoPulse && event < stop) stop = event;
      z += advance_segment(ch, map.fatigue, st, stop - t);
      t = (stop == t_end) ? t_end : stop;
    }
    channel_z[k] = z;
    channel_f[k] = st[kStimForce];  // (a SIMD-pass channel's is set there)
  }
  {
    // Gathered into lanes (the memory is stored per channel, as the snapshot has it), advanced, scattered back.
    double S[kMaxChannels], CN[kMaxChannels], f[kMaxChannels], A[kMaxChannels], T1[kMaxChannels], KM[kMaxChannels],
        R[kMaxChannels], z[kMaxChannels];
    for (int j = 0; j < num_whole; ++j) {
      const double* st = channel_state(d, whole[j]);
      S[j] = st[kStimCalciumSum], CN[j] = st[kStimCalcium], f[j] = st[kStimForce];
      A[j] = st[kStimFatigueA], T1[j] = st[kStimFatigueTau1], KM[j] = st[kStimFatigueKm], R[j] = st[kStimRecruitment];
    }
    auto params = [&](int k) {
      return SegmentParams{l.tau1_s[k], l.tau2_s[k], l.km[k], l.inv_tau_c[k], l.inv_ref_tau[k], l.inv_tau_fat[k],
                           l.rate_a[k], l.rate_tau1[k], l.rate_km[k]};
    };
    if (map.fatigue) {
#pragma omp simd
      for (int j = 0; j < num_whole; ++j)
        z[j] = segment(params(whole[j]), true, true, h, R[j], S[j], CN[j], f[j], A[j], T1[j], KM[j]);
    } else {
#pragma omp simd
      for (int j = 0; j < num_whole; ++j)
        z[j] = segment(params(whole[j]), false, true, h, R[j], S[j], CN[j], f[j], A[j], T1[j], KM[j]);
    }
    for (int j = 0; j < num_whole; ++j) {
      double* st = channel_state(d, whole[j]);
      st[kStimCalciumSum] = S[j], st[kStimCalcium] = CN[j], st[kStimForce] = f[j];
      st[kStimFatigueA] = A[j], st[kStimFatigueTau1] = T1[j], st[kStimFatigueKm] = KM[j];
      channel_z[whole[j]] = z[j];
      channel_f[whole[j]] = f[j];
    }
  }
  // The elements' activation targets: a first-order ODE da/dt = rate (target - a) that lands on the channels'
  // force level at t_end. Its decay exponent over the step is the reached channels' weighted mean exponent; any
  // decay in (0, 1) lands on the level, this one also follows the channels' shape within the step.
  const int n = m.num_elements;
  double level[kMaxElements], z_sum[kMaxElements];
  for (int i = 0; i < n; ++i) level[i] = z_sum[i] = 0.0;
  for (int e = 0; e < map.num_entries; ++e) {
    const StimEntry& en = map.entries[e];
    level[en.element] += en.weight * channel_f[en.channel];
    z_sum[en.element] += en.weight * channel_z[en.channel];
  }
  const double* a = d.x.data() + act_offset(m);
  const double* cap = d.muscles.max_activation.data();
  const double inv_h = 1.0 / h;
  // Branch-free over every element so that it runs in SIMD lanes (the divisions are the stage's cost); an element
  // no channel reaches has inv_weight_sum 0, hence z = 0, and its values are never read (muscles.cc: driven only).
  double z_max = 0.0;
#pragma omp simd reduction(max : z_max)
  for (int i = 0; i < n; ++i) {
    const double z = z_sum[i] * map.inv_weight_sum[i];
    z_max = std::max(z_max, z);
    const double decay = exp_neg_small(z);
    const double target_end = std::min(cap[i], level[i]);
    const double target = (target_end - a[i] * decay) / (1.0 - decay + (z == 0.0 ? 1.0 : 0.0));
    d.drive_target[i] = std::clamp(target, 0.0, cap[i]);
    d.drive_rate[i] = z * inv_h;  // 1/tau of that decay
  }
  if (z_max >= 0.1) {  // a long control step (h >= tau_eff / 10): the polynomial is not exact enough there
    for (int i = 0; i < n; ++i) {
      const double z = z_sum[i] * map.inv_weight_sum[i];
      if (z < 0.1) continue;
      const double decay = std::exp(-z);
      const double target = (std::min(cap[i], level[i]) - a[i] * decay) / (1.0 - decay);
      d.drive_target[i] = std::clamp(target, 0.0, cap[i]);
    }
  }
}

void stimulation_queue_pulses(const Model&, Data& d, int channel, const double* times, int count) {
  const StimulationMap& map = d.stimulation_map;
  if (channel < 0 || channel >= map.num_channels) throw std::invalid_argument("no stimulation channel " + std::to_string(channel));
  double* st = channel_state(d, channel);
  const int have = static_cast<int>(st[kStimQueued]);
  if (have + count > kMaxQueuedPulses)
    throw std::invalid_argument(std::string("channel '") + map.channels[channel].name + "': " +
                                std::to_string(have + count) + " queued pulses, more than the " +
                                std::to_string(kMaxQueuedPulses) + " a channel holds ahead (queue the rest later)");
  double prev = have > 0 ? st[kStimQueue + have - 1] : d.time;
  for (int i = 0; i < count; ++i) {
    if (!std::isfinite(times[i]) || times[i] < prev || (i == 0 && have == 0 && times[i] < d.time))
      throw std::invalid_argument(std::string("channel '") + map.channels[channel].name +
                                  "': pulse times must be finite, increasing and not before the arm's time " +
                                  std::to_string(d.time) + " s");
    prev = times[i];
  }
  for (int i = 0; i < count; ++i) st[kStimQueue + have + i] = times[i];
  st[kStimQueued] = have + count;
}

double channel_fatigue(const Data& d, int k) { return 1.0 - channel_state(d, k)[kStimFatigueA]; }

}  // namespace armrt
