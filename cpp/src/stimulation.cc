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


// exp(-z) for z >= 0: by its Taylor polynomial of degree 7 below 0.1 (relative error < 3e-13), where every
// exponent of a 1 ms step lies (h/tau_c = 0.05, h/tau <= 0.02), else std::exp. Half of the chain's cost
// was std::exp.
inline double exp_neg(double z) {
  if (z >= 0.1) return std::exp(-z);
  return 1.0 + -z * (1.0 + -z * (1.0 / 2 + -z * (1.0 / 6 + -z * (1.0 / 24 + -z * (1.0 / 120 + -z * (1.0 / 720 + -z / 5040))))));
}

// Advances one channel's memory by a segment of length dt with no pulse inside it; returns tau_eff at its end (s).
double advance_segment(const StimChannel& ch, bool fatigue, double* st, double dt) {
  const DingParams& p = ch.ding;
  const DingDerived& c = ch.derived;
  const double S0 = st[kStimCalciumSum], CN0 = st[kStimCalcium], f0 = st[kStimForce];
  const double A = st[kStimFatigueA], tau1 = st[kStimFatigueTau1] * p.tau1_s, Km = st[kStimFatigueKm] * p.km;
  const double e_half = exp_neg(0.5 * dt * c.inv_tau_c), e_end = e_half * e_half;
  const double cn_mid = e_half * (CN0 + S0 * 0.5 * dt * c.inv_tau_c), cn_end = e_end * (CN0 + S0 * dt * c.inv_tau_c);
  const double x_end = cn_end / (Km + cn_end);
  const double x_mean = (CN0 / (Km + CN0) + 4.0 * cn_mid / (Km + cn_mid) + x_end) * (1.0 / 6.0);
  const double tau_eff = tau1 + p.tau2_s * x_mean;
  const double decay = exp_neg(dt / tau_eff);
  const double drive = st[kStimRecruitment] * A * x_mean * c.inv_ref_tau;
  const double f1 = f0 * decay + drive * tau_eff * (1.0 - decay);
  st[kStimCalciumSum] = S0 * e_end;
  st[kStimCalcium] = cn_end;
  st[kStimForce] = f1;
  if (fatigue) {
    const double f_mean = 0.5 * (f0 + f1);
    st[kStimFatigueA] += dt * (-(A - 1.0) * c.inv_tau_fat + c.rate_a * f_mean);
    st[kStimFatigueTau1] += dt * (-(st[kStimFatigueTau1] - 1.0) * c.inv_tau_fat + c.rate_tau1 * f_mean);
    st[kStimFatigueKm] += dt * (-(st[kStimFatigueKm] - 1.0) * c.inv_tau_fat + c.rate_km * f_mean);
    if (st[kStimFatigueA] < 0.0) st[kStimFatigueA] = 0.0;  // A cannot change sign (Euler on a fully fatigued muscle)
  }
  return p.tau1_s * st[kStimFatigueTau1] + p.tau2_s * x_end;
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

// Time of the channel's next pulse at or after t (kNoPulse if none): the earlier of its frequency train
// (1/f after the last pulse, at once if that is past) and its first queued pulse.
double next_pulse(const double* input, const double* st, double t) {
  double next = kNoPulse;
  const double f = input[kStimFrequency];
  if (f > 0.0) next = std::max(t, st[kStimLastPulse] + 1.0 / f);
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

// -log(e) for e in (0, 1]: its series in u = 1 - e below u = 0.1 (relative error < 2e-7, which moves a
// step's end activation by < 1e-9), else std::log.
inline double minus_log(double e) {
  const double u = 1.0 - e;
  if (u >= 0.1) return -std::log(e);
  return u * (1.0 + u * (1.0 / 2 + u * (1.0 / 3 + u * (1.0 / 4 + u * (1.0 / 5 + u / 6)))));
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
  std::fill(d.stimulation.begin(), d.stimulation.end(), 0.0);
  stimulation_reset(d);
}

void stimulation_advance(const Model& m, Data& d, double h) {
  const StimulationMap& map = d.stimulation_map;
  if (map.num_channels == 0) return;
  const double t0 = d.time, t_end = d.time + h;
  double channel_decay[kMaxChannels];  // each channel's force decay over the step, at its end state
  for (int k = 0; k < map.num_channels; ++k) {
    const StimChannel& ch = map.channels[k];
    const double* input = d.stimulation.data() + k * kStimInputs;
    double* st = channel_state(d, k);
    // What the step starts from (recorded with the step's start state).
    d.recruitment[k] = st[kStimRecruitment];
    d.fatigue[k] = 1.0 - st[kStimFatigueA];
    double t = t0;
    double tau_end = ch.ding.tau1_s * st[kStimFatigueTau1];
    while (t < t_end) {
      double event = next_pulse(input, st, t);
      if (event != kNoPulse && event <= t) {
        pulse(ch, input, st, t);
        pop_queued(st, t);
        continue;
      }
      double stop = std::min(t_end, t + kMaxSegment);
      if (event != kNoPulse && event < stop) stop = event;
      tau_end = advance_segment(ch, map.fatigue, st, stop - t);
      t = (stop == t_end) ? t_end : stop;
    }
    channel_decay[k] = exp_neg(h / tau_end);
  }
  // The elements' activation targets: a first-order ODE da/dt = rate (target - a) that lands on the channels'
  // force level at t_end. Its decay over the step is the reached channels' (weighted) force decay; any decay in
  // (0, 1) lands on the level, this one also follows the channels' shape within the step.
  const int n = m.num_elements;
  double level[kMaxElements], decay_sum[kMaxElements], w_sum[kMaxElements];
  for (int i = 0; i < n; ++i) level[i] = decay_sum[i] = w_sum[i] = 0.0;
  for (int e = 0; e < map.num_entries; ++e) {
    const StimEntry& en = map.entries[e];
    level[en.element] += en.weight * channel_state(d, en.channel)[kStimForce];
    decay_sum[en.element] += en.weight * channel_decay[en.channel];
    w_sum[en.element] += en.weight;
  }
  const double* a = d.x.data() + act_offset(m);
  for (int i = 0; i < n; ++i) {
    if (!map.driven[i]) continue;
    const double cap = d.muscles.max_activation[i];
    const double target_end = std::min(cap, level[i]);
    const double decay = decay_sum[i] / w_sum[i];
    const double target = (target_end - a[i] * decay) / (1.0 - decay);
    d.drive_target[i] = std::clamp(target, 0.0, cap);
    d.drive_rate[i] = minus_log(decay) / h;  // 1/tau of that decay
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
