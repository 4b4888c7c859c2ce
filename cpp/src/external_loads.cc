// Stage: external loads. (q, hand force (N) and moment (N m) in the thorax frame) -> the load in the
// scapula frame and its generalised forces tau_ext = Jv^T F + Jw^T M (N m) at the hand.
#include <charconv>
#include <cmath>
#include <string>

#include "armrt/engine.h"

namespace armrt {

namespace {
std::string shortest(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}
}  // namespace

std::string hand_load_error(const char* what, const double* v, bool moment) {
  const double size = std::hypot(v[0], v[1], v[2]);
  const double limit = moment ? kMaxHandMoment : kMaxHandForce;
  if (!(size > limit)) return "";
  const char* unit = moment ? "N m" : "N";
  return std::string(what) + " of " + shortest(size) + " " + unit + " is beyond " + shortest(limit) + " " + unit +
         ", more than any arm bears (check the units)";
}

bool external_load(const Model& m, const double* q, const double* hand_force, const double* hand_moment,
                   double* f_ext, double* t_ext, double* tau_ext) {
  const ModelDef& def = *m.def;
  const int nq = m.num_dofs;
  const double* Rs = def.base_rotation_in_thorax;  // columns = scapula axes in thorax
  for (int k = 0; k < 3; ++k) {
    f_ext[k] = Rs[0 * 3 + k] * hand_force[0] + Rs[1 * 3 + k] * hand_force[1] + Rs[2 * 3 + k] * hand_force[2];
    t_ext[k] = Rs[0 * 3 + k] * hand_moment[0] + Rs[1 * 3 + k] * hand_moment[1] + Rs[2 * 3 + k] * hand_moment[2];
  }
  for (int j = 0; j < nq; ++j) tau_ext[j] = 0.0;
  const bool loaded = f_ext[0] != 0 || f_ext[1] != 0 || f_ext[2] != 0 || t_ext[0] != 0 || t_ext[1] != 0 || t_ext[2] != 0;
  if (!loaded) return false;
  double Jv[3 * kMaxDofs], Jw[3 * kMaxDofs];
  def.hand_jacobian(q, Jv, Jw);
  for (int j = 0; j < nq; ++j)
    for (int k = 0; k < 3; ++k) tau_ext[j] += Jv[k * nq + j] * f_ext[k] + Jw[k * nq + j] * t_ext[k];
  return true;
}

void hand_position_in_thorax(const Model& m, const double* q, double* p_thorax) {
  const ModelDef& def = *m.def;
  const double* Rs = def.base_rotation_in_thorax;
  double p[3];
  def.hand_position(q, p);
  for (int k = 0; k < 3; ++k)
    p_thorax[k] = def.base_origin_in_thorax[k] + Rs[k * 3 + 0] * p[0] + Rs[k * 3 + 1] * p[1] + Rs[k * 3 + 2] * p[2];
}

}  // namespace armrt
