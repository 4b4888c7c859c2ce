// Per-solve cost of the C++ static optimisation (static_optimization.cc) along bench/static_optimization.py's
// das2 motion (its motion()): q0 + 0.3 rad (1 - cos(pi t / T)) / 2, sign alternating by DOF, T = frames ms, from
// q0 = (20, 40, 0, 60, 60) deg with a 1 kg weight in the hand, one solve per millisecond, warm started. Prints JSON: wall time per solve (ns; the machine's load
// is the caller's to record), ProxQP iterations, the largest moment residual and GHstab, the infeasible count.
//   armrt_bench_static_optimization [--gh-stab-max S] [--frames N] [--repeat R] [--cold] [--diagonal]
//       [--backend 0|1|2] [--eps E] [--proxqp] [--no-fallback] [--elastic]   (StaticOptimizationOptions' solver choices)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "armrt/arm.h"
#include "armrt/static_optimization.h"

using namespace armrt;

int main(int argc, char** argv) {
  double gh = 0;
  int frames = 400, repeat = 1;
  bool cold = false, elastic = false;
  StaticOptimizationOptions o;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--gh-stab-max" && k + 1 < argc) gh = std::atof(argv[++k]);
    else if (a == "--frames" && k + 1 < argc) frames = std::atoi(argv[++k]);
    else if (a == "--repeat" && k + 1 < argc) repeat = std::atoi(argv[++k]);
    else if (a == "--cold") cold = true;
    else if (a == "--diagonal") o.diagonal_hessian = true;
    else if (a == "--proxqp") o.dual_newton = false;
    else if (a == "--no-fallback") o.proxqp_fallback = false;
    else if (a == "--elastic") elastic = true;
    else if (a == "--backend" && k + 1 < argc) o.dense_backend = std::atoi(argv[++k]);
    else if (a == "--eps" && k + 1 < argc) o.eps_abs = std::atof(argv[++k]);
    else { std::fprintf(stderr, "unknown argument %s\n", a.c_str()); return 2; }
  }
  const ModelDef* def = find_model("das2");
  Arm arm(*def, Integrator::kRos2, 1e-3);
  o.gh_stab_max = gh;
  StaticOptimizationWorkspace w;
  static_optimization_setup(arm.model, o, w);
  const int nq = def->num_dofs;
  const double q0deg[5] = {20, 40, 0, 60, 60};
  const double hand[3] = {0, -9.81, 0}, zero[3] = {};
  const double T = frames * 1e-3, amp = 0.3, pi = 3.141592653589793;
  std::vector<double> times;
  double worst_res = 0, worst_stab = 0;
  int infeasible = 0, iters_max = 0;
  std::vector<int> iters, newton;
  int proxqp = 0, qps_max = 0;
  double a[kMaxElements];
  StaticOptimizationReport rep;
  for (int r = 0; r < repeat; ++r) {
    static_optimization_reset(w);
    for (int f = 0; f < frames; ++f) {
      const double t = f * 1e-3;
      const double wt = pi / T, s = 0.5 * (1 - std::cos(wt * t)), sd = 0.5 * wt * std::sin(wt * t),
                   sdd = 0.5 * wt * wt * std::cos(wt * t);
      double q[kMaxDofs], qd[kMaxDofs], qdd[kMaxDofs];
      for (int j = 0; j < nq; ++j) {
        const double sign = j % 2 == 0 ? 1.0 : -1.0;
        q[j] = q0deg[j] * pi / 180 + sign * amp * s;
        qd[j] = sign * amp * sd;
        qdd[j] = sign * amp * sdd;
      }
      if (cold) static_optimization_reset(w);
      const auto t0 = std::chrono::steady_clock::now();
      if (elastic) static_optimization_elastic(arm.model, arm.data, w, q, qd, qdd, hand, zero, a, &rep);
      else static_optimization_rigid(arm.model, arm.data, w, q, qd, qdd, hand, zero, a, &rep);
      const auto t1 = std::chrono::steady_clock::now();
      times.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count());
      iters.push_back(rep.qp_iterations);
      newton.push_back(rep.newton_iterations);
      qps_max = std::max(qps_max, rep.qps);
      if (rep.solver == StaticOptimizationSolverUsed::kProxQP) ++proxqp;
      if (std::getenv("ARMRT_SO_TRACE"))
        std::fprintf(stderr, "frame %d: %.0f ns, %d ProxQP iterations, %d QPs\n", f, times.back(), rep.qp_iterations, rep.qps);
      iters_max = std::max(iters_max, rep.qp_iterations);
      if (!rep.feasible) ++infeasible;
      else {
        worst_res = std::max(worst_res, rep.residual_max);
        worst_stab = std::max(worst_stab, rep.gh_stab);
      }
    }
  }
  std::vector<double> s = times;
  std::sort(s.begin(), s.end());
  std::vector<int> it = iters;
  std::sort(it.begin(), it.end());
  auto pct = [&](double p) { return s[std::min<std::size_t>(s.size() - 1, static_cast<std::size_t>(p * s.size()))]; };
  std::printf("{\"solves\": %zu, \"gh_stab_max\": %g, \"cold\": %s, \"median_ns\": %.0f, \"p99_ns\": %.0f, "
              "\"max_ns\": %.0f, \"min_ns\": %.0f, \"qp_iterations_median\": %d, \"qp_iterations_max\": %d, "
              "\"newton_iterations_max\": %d, \"proxqp_solves\": %d, \"elastic\": %s, \"qps_max\": %d, \"dual_newton\": %s, \"diagonal\": %s, \"backend\": %d, \"eps_abs\": %g, \"infeasible\": %d, \"residual_max\": %.3g, \"gh_stab_max_seen\": %.4g}\n",
              s.size(), gh, cold ? "true" : "false", pct(0.5), pct(0.99), s.back(), s.front(), it[it.size() / 2],
              iters_max, *std::max_element(newton.begin(), newton.end()), proxqp, elastic ? "true" : "false", qps_max, o.dual_newton ? "true" : "false", o.diagonal_hessian ? "true" : "false", o.dense_backend, o.eps_abs, infeasible, worst_res, worst_stab);
  return 0;
}
