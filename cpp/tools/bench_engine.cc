// armrt_bench: timing of the engine stages on one core (bench/README.md).
//
//   armrt_bench [--json PATH] [--reps N] [--batch B] [--no-pin]
//
// Each item is timed over many repetitions. With --batch 1 (default) every call is timed on its own with
// clock_gettime(CLOCK_MONOTONIC) (about 20-30 ns of the figure is the clock itself, reported as
// "clock_overhead"); with --batch B > 1, B consecutive calls are timed together and the per-call mean of
// each batch is one sample (hides the clock cost, smooths the tail). Reported: median, p99, max, mean (ns).
#include <sched.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <sys/stat.h>
#include <vector>

#include "armrt/cvode.h"
#include "armrt/clock.h"
#include "armrt/engine.h"
#include "armrt/arm.h"

using namespace armrt;

namespace {

struct Stats {
  std::string name;
  std::string note;
  long samples = 0;
  int batch = 1;
  double median = 0, p99 = 0, max = 0, mean = 0, min = 0;
};

Stats summarise(const std::string& name, std::vector<double>& t, int batch, const std::string& note) {
  Stats s;
  s.name = name;
  s.note = note;
  s.batch = batch;
  s.samples = static_cast<long>(t.size());
  std::sort(t.begin(), t.end());
  const size_t n = t.size();
  s.min = t.front();
  s.median = n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
  s.p99 = t[std::min(n - 1, static_cast<size_t>(std::ceil(0.99 * n)) - 1)];
  s.max = t.back();
  double sum = 0;
  for (double v : t) sum += v;
  s.mean = sum / n;
  return s;
}

// Times fn() reps times (after warmup calls), batch calls per sample.
Stats time_it(const std::string& name, long reps, int batch, const std::function<void()>& fn,
              const std::string& note = "") {
  for (int k = 0; k < 200; ++k) fn();
  const long samples = std::max(1L, reps / batch);
  std::vector<double> t(samples);
  for (long s = 0; s < samples; ++s) {
    const double t0 = now_ns();
    for (int b = 0; b < batch; ++b) fn();
    t[s] = (now_ns() - t0) / batch;
  }
  return summarise(name, t, batch, note);
}

bool pin_to_cpu(int cpu) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  return sched_setaffinity(0, sizeof set, &set) == 0;
}

void mkdirs(const std::string& path) {
  for (size_t p = path.find('/', 1); p != std::string::npos; p = path.find('/', p + 1))
    mkdir(path.substr(0, p).c_str(), 0755);
}

// Runs the fixed-step stimulation used by every stepping item: rotator cuff 0.05, elbow flexors 0.3.
void excite(Arm& sim) {
  const ModelDef& def = *sim.model.def;
  for (int g = 0; g < def.num_groups; ++g) {
    const double u = std::strcmp(def.groups[g].name, "rotator_cuff") == 0    ? 0.05
                     : std::strcmp(def.groups[g].name, "elbow_flexors") == 0 ? 0.3
                                                                             : -1;
    if (u < 0) continue;
    for (int k = 0; k < def.groups[g].num_elements; ++k) sim.data.excitation[def.groups[g].elements[k]] = u;
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string model_name = "das2";
  std::string json = "bench/results/engine.json";
  long reps = 20000;
  int batch = 1;
  bool pin = true;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--json" && k + 1 < argc) json = argv[++k];
    else if (a == "--reps" && k + 1 < argc) reps = std::atol(argv[++k]);
    else if (a == "--batch" && k + 1 < argc) batch = std::max(1, std::atoi(argv[++k]));
    else if (a == "--no-pin") pin = false;
    else if (a == "--model" && k + 1 < argc) model_name = argv[++k];
    else {
      std::fprintf(stderr, "usage: %s [--model NAME] [--json PATH] [--reps N] [--batch B] [--no-pin]\n", argv[0]);
      return a == "-h" || a == "--help" ? 0 : 2;
    }
  }
  const long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
  const int cpu = ncpu > 1 ? 1 : 0;
  const bool pinned = pin && pin_to_cpu(cpu);

  const ModelDef* def = find_model(model_name);
  if (!def) {
    std::fprintf(stderr, "model %s not compiled in\n", model_name.c_str());
    return 1;
  }
  std::vector<Stats> results;

  // Clock overhead: an empty timed call.
  results.push_back(time_it("clock_overhead", reps, 1, [] {}, "empty timed region (clock_gettime pair)"));

  // Derivative and its parts, at a stimulated, moving state (after 300 ms of ROS2 at 1 ms).
  auto sim = std::make_unique<Arm>(*def, Integrator::kRos2, 1e-3);
  excite(*sim);
  for (int k = 0; k < 300; ++k) sim->step();
  const Model& m = sim->model;
  Data& d = sim->data;
  auto x = std::make_unique<StateVec>(d.x);
  auto xdot = std::make_unique<StateVec>();
  volatile double sink = 0;
  results.push_back(time_it("forward", reps, batch, [&] { forward(m, d, x->data(), xdot->data(), false); sink = (*xdot)[3]; },
                            "state derivative, record=false (one RK4 stage)"));
  results.push_back(time_it("forward_record", reps, batch, [&] { forward(m, d, x->data(), xdot->data(), true); sink = d.gh_stab; },
                            "state derivative, record=true (+ outputs, GH force/stability)"));
  double L[kMaxElements], R[kMaxElements * kMaxDofs], M[kMaxDofs * kMaxDofs];
  results.push_back(time_it("muscle_paths", reps, batch, [&] { def->muscle_paths(x->data(), L, R); sink = L[0] + R[0]; },
                            "path lengths + moment arms of every element (polynomials)"));
  results.push_back(time_it("mass_matrix", reps, batch, [&] { def->mass_matrix(x->data(), M); sink = M[6]; },
                            "M(q), generated"));
  // The stages of forward() (forward.cc) one by one, for the cost split.
  {
    const int iq = q_offset(m), iqd = qd_offset(m), il = lce_offset(m), ia = act_offset(m);
    double b[kMaxDofs], force[kMaxElements], tau[kMaxDofs], tau2[kMaxDofs], K[kMaxDofs * kMaxDofs];
    auto* xd = xdot->data();
    def->muscle_paths(x->data() + iq, L, R);
    results.push_back(time_it("stage_muscles", reps, batch, [&] {
      muscle_dynamics(m, d.muscles, d.excitation.data(), L, R, x->data() + ia, x->data() + il, xd + ia, xd + il, force, tau);
      sink = tau[0]; }, "muscles.cc: activation and CE dynamics, tendon forces, R^T F"));
    results.push_back(time_it("stage_passive_joints", reps, batch, [&] {
      passive_joint_torque(*def, x->data() + iq, x->data() + iqd, tau2); sink = tau2[0]; }, "passive_joints.cc"));
    results.push_back(time_it("stage_girdle", reps, batch, [&] {
      girdle_forces(m, x->data() + iq, tau2, nullptr, nullptr); sink = tau2[0]; },
      def->girdle ? "girdle.cc: scapulothoracic contact and conoid, J^T F" : "girdle.cc: fixed girdle, nothing to do"));
    results.push_back(time_it("stage_girdle_jacobian", reps, batch, [&] {
      girdle_forces(m, x->data() + iq, tau2, K, nullptr); sink = K[0]; }, "girdle.cc with its stiffness J^T dF/dp J"));
    results.push_back(time_it("stage_skeleton", reps, batch, [&] {
      skeleton_dynamics(m, d.settings.gravity.data(), x->data() + iq, x->data() + iqd, tau, M, b); sink = b[0]; },
      "skeleton.cc: M(q), b(q, qd), Cholesky solve"));
  }

  // Steps: keep stepping from the stimulated state; reset when the 2 s window is over so the state
  // stays physiological (reset is outside the timed region only when batch == 1; it is rare anyway).
  // min_batch: steps timed together at least (ROS2 evaluates the path polynomials at one step in
  // kRos2PathPeriod, so its steps are timed in such runs: a single step's median would be one kind's).
  auto step_item = [&](const char* name, Integrator integ, double dt, const char* note, int min_batch) {
    const int step_batch = std::max(batch, min_batch);
    auto s = std::make_unique<Arm>(*def, integ, dt);
    excite(*s);
    const long steps_per_window = static_cast<long>(std::lround(2.0 / dt));
    long k = 0, diverged = 0;
    std::vector<double> t;
    const long samples = std::max(1L, reps / step_batch);
    t.reserve(samples);
    for (int w = 0; w < 200; ++w) s->step();
    for (long i = 0; i < samples; ++i) {
      if ((k += step_batch) > steps_per_window) {
        s->reset(nullptr, nullptr, nullptr);
        k = 0;
      }
      const double t0 = now_ns();
      bool ok = true;
      for (int b = 0; b < step_batch; ++b) ok &= s->step();
      const double el = (now_ns() - t0) / step_batch;
      if (!ok && s->data.status == Status::kUnstableStep) {
        // Refused before stepping (das3's stiffest resting fibre needs shorter explicit steps): say so once.
        std::fprintf(stderr, "%s: %s (not timed)\n", name, s->error_message().c_str());
        t.clear();
        break;
      }
      if (!ok) {  // a diverged step is not a representative sample: drop it, restart the window
        ++diverged;
        std::fprintf(stderr, "%s: %s (restarting)\n", name, s->error_message().c_str());
        s->reset(nullptr, nullptr, nullptr);
        k = 0;
        continue;
      }
      t.push_back(el);
    }
    if (t.empty()) return;
    std::string n = note;
    if (diverged) n += "; diverged " + std::to_string(diverged) + "x (samples dropped)";
    results.push_back(summarise(name, t, step_batch, n));
  };
  step_item("euler_step", Integrator::kEuler, 1e-4, "Arm::step, Euler, dt = 0.1 ms (1 derivative)", 1);
  // One RK4 step costs the same at any step size; 1/6 ms is the default substep (1 ms is refused: unstable).
  step_item("rk4_step", Integrator::kRk4, 1e-3 / 6, "Arm::step, RK4, dt = 1/6 ms (4 derivatives)", 1);
  const std::string period = std::to_string(kRos2PathPeriod);
  step_item("ros2_step", Integrator::kRos2, 1e-3,
            ("Arm::step, ROS2, dt = 1 ms (2 derivatives, Jacobian, n x n Schur LU; per step of runs of " +
             period + ": the paths are evaluated at one step in " + period + ")").c_str(),
            kRos2PathPeriod);
  {
    // CVODE: 1 ms advances over a 2 s stimulation (elbow flexors switched on at 0.5 s: one restart).
    const long cv_reps = std::min<long>(reps, 2000);
    auto s = std::make_unique<Arm>(*def, Integrator::kCvode, 1e-3);
    const ModelDef& dd = *def;
    for (int g = 0; g < dd.num_groups; ++g)
      if (std::strcmp(dd.groups[g].name, "rotator_cuff") == 0)
        for (int k = 0; k < dd.groups[g].num_elements; ++k) s->data.excitation[dd.groups[g].elements[k]] = 0.05;
    std::vector<double> t;
    for (long i = 0; i < cv_reps; ++i) {
      if (i % 2000 == 500) excite(*s);
      if (i > 0 && i % 2000 == 0) {
        s->reset(nullptr, nullptr, nullptr);
        for (int k = 0; k < kMaxElements; ++k) s->data.excitation[k] = 0;
      }
      const double t0 = now_ns();
      s->step();
      t.push_back(now_ns() - t0);
    }
    if (s->data.status != Status::kOk) std::fprintf(stderr, "cvode: %s\n", s->error_message().c_str());
    results.push_back(summarise("cvode_advance_1ms", t, 1, "CVODE (BDF, rtol 1e-8) advance by 1 ms, 2 s stimulation"));
  }
  (void)sink;

  // Table.
  std::printf("armrt engine benchmark: model %s, %d elements, cpu %s, batch %d\n", def->name, def->num_elements,
              pinned ? std::to_string(cpu).c_str() : "not pinned", batch);
  std::printf("%-20s %10s %10s %10s %10s %9s\n", "item", "median_ns", "p99_ns", "max_ns", "mean_ns", "samples");
  for (const Stats& s : results)
    std::printf("%-20s %10.0f %10.0f %10.0f %10.0f %9ld\n", s.name.c_str(), s.median, s.p99, s.max, s.mean, s.samples);

  // JSON.
  mkdirs(json);
  FILE* f = std::fopen(json.c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "cannot write %s: %s\n", json.c_str(), std::strerror(errno));
    return 1;
  }
  std::fprintf(f, "{\n  \"tool\": \"armrt_bench\",\n  \"model\": \"%s\",\n  \"num_elements\": %d,\n", def->name,
               def->num_elements);
  std::fprintf(f, "  \"pinned_cpu\": %d,\n  \"batch\": %d,\n  \"unit\": \"ns\",\n  \"cpp\": {\n", pinned ? cpu : -1, batch);
  for (size_t i = 0; i < results.size(); ++i) {
    const Stats& s = results[i];
    std::fprintf(f,
                 "    \"%s\": {\"median\": %.1f, \"p99\": %.1f, \"max\": %.1f, \"mean\": %.1f, \"min\": %.1f, "
                 "\"samples\": %ld, \"batch\": %d, \"what\": \"%s\"}%s\n",
                 s.name.c_str(), s.median, s.p99, s.max, s.mean, s.min, s.samples, s.batch, s.note.c_str(),
                 i + 1 < results.size() ? "," : "");
  }
  std::fprintf(f, "  }\n}\n");
  std::fclose(f);
  std::printf("wrote %s\n", json.c_str());
  return 0;
}
