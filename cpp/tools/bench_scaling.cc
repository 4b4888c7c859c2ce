// armrt_bench_scaling: how the cost grows with the number of muscle elements (bench/bench_scaling.py).
//
//   armrt_bench_scaling [--json PATH] [--reps N] [--sizes 1,2,4,...] [--no-pin]
//
// Two kinds of figures, both wall-clock ns per call, median over samples of `batch` calls each:
//  * per-n items, n = each of --sizes (default 1 2 4 8 16 32 51 64 80 102): the model's first n elements
//    only (Model::num_elements = n, so the state is [q qd lce(n) act(n)]; the muscle loop, R^T F and
//    the integrator updates run over n elements). The generated path polynomials still evaluate every
//    element the model was generated with, so `forward`, `euler_step` and `rk4_step` carry a constant
//    path cost; `muscle_loop` (the activation + Hill-kernel loop of forward(), the same inline kernel
//    and compiler flags as the engine) does not.
//  * whole-model items: `muscle_paths`, `mass_matrix`, `dynamics` of the compiled model. To see the
//    path cost against the element count, bench/bench_scaling.py generates reduced models (subsets of
//    the elements) with codegen and builds this file against each (-DARMRT_SCALING_NS=<name>).
#include <sched.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "armrt/clock.h"
#include "armrt/engine.h"
#include "armrt/arm.h"

#ifdef ARMRT_SCALING_NS
#define ARMRT_STR2(x) #x
#define ARMRT_STR(x) ARMRT_STR2(x)
#include ARMRT_STR(ARMRT_SCALING_NS.h)
#endif

using namespace armrt;

namespace {

struct Item {
  std::string name;
  int n;
  int batch;
  long samples;
  double median, p10, p90, min;
};

Item summarise(const std::string& name, int n, int batch, std::vector<double>& t) {
  std::sort(t.begin(), t.end());
  const size_t k = t.size();
  auto at = [&](double f) { return t[std::min(k - 1, static_cast<size_t>(f * (k - 1) + 0.5))]; };
  return {name, n, batch, static_cast<long>(k), k % 2 ? t[k / 2] : 0.5 * (t[k / 2 - 1] + t[k / 2]), at(0.1), at(0.9),
          t.front()};
}

// Batch size so one sample lasts about 2 us or more (hides the ~30 ns clock pair).
int batch_for(double est_ns) { return std::max(1, static_cast<int>(std::ceil(2000.0 / std::max(est_ns, 1.0)))); }

Item time_it(const std::string& name, int n, long reps, const std::function<void()>& fn) {
  for (int k = 0; k < 100; ++k) fn();
  const double t0 = now_ns();
  for (int k = 0; k < 100; ++k) fn();
  const int batch = batch_for((now_ns() - t0) / 100);
  const long samples = std::max(50L, reps / batch);
  std::vector<double> t(samples);
  for (long s = 0; s < samples; ++s) {
    const double a = now_ns();
    for (int b = 0; b < batch; ++b) fn();
    t[s] = (now_ns() - a) / batch;
  }
  return summarise(name, n, batch, t);
}

void excite(Arm& sim) {
  const ModelDef& def = *sim.model.def;
  for (int g = 0; g < def.num_groups; ++g) {
    const double u = std::strcmp(def.groups[g].name, "rotator_cuff") == 0    ? 0.05
                     : std::strcmp(def.groups[g].name, "elbow_flexors") == 0 ? 0.3
                                                                             : -1;
    if (u < 0) continue;
    for (int k = 0; k < def.groups[g].num_elements; ++k) sim.data.excitation[def.groups[g].elements[k]] = u;
  }
  // Elements without a group excitation get a small one so every kernel branch is exercised.
  for (int i = 0; i < def.num_elements; ++i)
    if (sim.data.excitation[i] == 0) sim.data.excitation[i] = 0.02;
}

// A simulator restricted to the first n elements, stimulated, after `warm` steps.
// (The Model is immutable: the restriction is a copy of the ModelDef with n elements, kept for the process.)
std::unique_ptr<Arm> make_sim(const ModelDef& def, int n, Integrator integ, double dt, int warm) {
  static std::deque<ModelDef> restricted;
  ModelDef& first_n = restricted.emplace_back(def);
  first_n.num_elements = n;
  auto s = std::make_unique<Arm>(first_n, integ, dt);
  s->reset(nullptr, nullptr, nullptr);
  excite(*s);
  for (int k = 0; k < warm && s->step(); ++k) {
  }
  if (s->data.status != Status::kOk) s->reset(nullptr, nullptr, nullptr);
  return s;
}

// Steps over a 0.3 s window from rest, restarting at its end (and on divergence, outside the timing).
Item time_steps(const std::string& name, const ModelDef& def, int n, Integrator integ, double dt, long reps) {
  auto s = make_sim(def, n, integ, dt, 0);
  const long window = std::lround(0.3 / dt);
  const int batch = 10;
  const long samples = std::max(50L, reps / batch);
  std::vector<double> t;
  t.reserve(samples);
  long k = 0;
  for (long i = 0; i < samples + 20; ++i) {
    if (k + batch > window) {
      s->reset(nullptr, nullptr, nullptr);
      k = 0;
    }
    const double a = now_ns();
    bool ok = true;
    for (int b = 0; b < batch; ++b) ok &= s->step();
    const double el = (now_ns() - a) / batch;
    k += batch;
    if (!ok) {
      s->reset(nullptr, nullptr, nullptr);
      k = 0;
      continue;
    }
    if (i >= 20) t.push_back(el);  // the first 20 batches are warm-up
  }
  return summarise(name, n, batch, t);
}

}  // namespace

int main(int argc, char** argv) {
  std::string json = "bench/results/scaling_cpp.json";
  long reps = 20000;
  bool pin = true;
  std::vector<int> sizes = {1, 2, 4, 8, 16, 32, 51, 64, 80, 102};
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--json" && k + 1 < argc) json = argv[++k];
    else if (a == "--reps" && k + 1 < argc) reps = std::atol(argv[++k]);
    else if (a == "--no-pin") pin = false;
    else if (a == "--sizes" && k + 1 < argc) {
      sizes.clear();
      std::stringstream ss(argv[++k]);
      for (std::string tok; std::getline(ss, tok, ',');) sizes.push_back(std::atoi(tok.c_str()));
    } else {
      std::fprintf(stderr, "usage: %s [--json PATH] [--reps N] [--sizes 1,2,...] [--no-pin]\n", argv[0]);
      return a == "-h" || a == "--help" ? 0 : 2;
    }
  }
  const long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
  const int cpu = ncpu > 1 ? 1 : 0;
  bool pinned = false;
  if (pin) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cpu, &set);
    pinned = sched_setaffinity(0, sizeof set, &set) == 0;
  }
#ifdef ARMRT_SCALING_NS
  const ModelDef* def = &armrt::generated::ARMRT_SCALING_NS::model_def();
#else
  const ModelDef* def = find_model("das2");
#endif
  const int nmax = def->num_elements;
  std::vector<Item> items;
  volatile double sink = 0;

  // Whole-model items.
  {
    auto s = make_sim(*def, nmax, Integrator::kRk4, 1e-3 / 6, 200);
    const double* q = s->data.x.data();
    double L[kMaxElements], R[kMaxElements * kMaxDofs], M[kMaxDofs * kMaxDofs], b[kMaxDofs];
    items.push_back(time_it("muscle_paths", nmax, reps, [&] { def->muscle_paths(q, L, R); sink = L[0] + R[0]; }));
    items.push_back(time_it("muscle_lengths", nmax, reps, [&] { def->muscle_lengths(q, L); sink = L[0]; }));
    items.push_back(time_it("mass_matrix", nmax, reps, [&] { def->mass_matrix(q, M); sink = M[6]; }));
    items.push_back(time_it("dynamics", nmax, reps, [&] {
      def->dynamics(q, q + qd_offset(s->model), s->data.settings.gravity.data(), M, b);
      sink = M[6] + b[2];
    }));
  }

  for (int n : sizes) {
    if (n < 1 || n > nmax) continue;
    auto s = make_sim(*def, n, Integrator::kRk4, 1e-3 / 6, 200);
    const Model& m = s->model;
    Data& d = s->data;
    auto x = std::make_unique<StateVec>(d.x);
    auto xdot = std::make_unique<StateVec>();
    double L[kMaxElements], R[kMaxElements * kMaxDofs];
    def->muscle_paths(x->data(), L, R);
    const int ia = act_offset(m);
    // The muscle stage of forward() (activation dynamics + Hill kernel + R^T F), over n elements.
    auto loop = [&] {
      double force[kMaxElements], tau[kMaxDofs];
      muscle_dynamics(m, d.muscles, d.excitation.data(), L, R, x->data() + ia, x->data() + lce_offset(m), xdot->data() + ia,
                      xdot->data() + lce_offset(m), force, tau);
      sink = tau[0] + tau[3];
    };
    items.push_back(time_it("muscle_loop", n, reps, loop));
    items.push_back(time_it("forward", n, reps, [&] { forward(m, d, x->data(), xdot->data(), false); sink = (*xdot)[3]; }));
    items.push_back(time_it("forward_record", n, reps, [&] { forward(m, d, x->data(), xdot->data(), true); sink = d.gh_stab; }));
    items.push_back(time_steps("euler_step", *def, n, Integrator::kEuler, 1e-4, reps));
    items.push_back(time_steps("rk4_step", *def, n, Integrator::kRk4, 1e-3 / 6, reps));
  }
  (void)sink;

  std::printf("armrt_bench_scaling: model %s (%d elements), cpu %s\n", def->name, nmax,
              pinned ? std::to_string(cpu).c_str() : "not pinned");
  std::printf("%-16s %5s %11s %11s %11s %6s\n", "item", "n", "median_ns", "p10_ns", "p90_ns", "batch");
  for (const Item& it : items)
    std::printf("%-16s %5d %11.1f %11.1f %11.1f %6d\n", it.name.c_str(), it.n, it.median, it.p10, it.p90, it.batch);

  FILE* f = std::fopen(json.c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "cannot write %s: %s\n", json.c_str(), std::strerror(errno));
    return 1;
  }
  std::fprintf(f, "{\n  \"tool\": \"armrt_bench_scaling\",\n  \"model\": \"%s\",\n  \"num_elements\": %d,\n", def->name, nmax);
  std::fprintf(f, "  \"pinned_cpu\": %d,\n  \"unit\": \"ns\",\n  \"items\": [\n", pinned ? cpu : -1);
  for (size_t i = 0; i < items.size(); ++i) {
    const Item& it = items[i];
    std::fprintf(f,
                 "    {\"name\": \"%s\", \"n\": %d, \"median\": %.2f, \"p10\": %.2f, \"p90\": %.2f, \"min\": %.2f, "
                 "\"batch\": %d, \"samples\": %ld}%s\n",
                 it.name.c_str(), it.n, it.median, it.p10, it.p90, it.min, it.batch, it.samples,
                 i + 1 < items.size() ? "," : "");
  }
  std::fprintf(f, "  ]\n}\n");
  std::fclose(f);
  std::printf("wrote %s\n", json.c_str());
  return 0;
}
