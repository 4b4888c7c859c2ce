// Stage: girdle forces, for models whose clavicle and scapula move (das3; a fixed girdle has none).
// q -> tau_girdle (N m): the scapulothoracic contact of the scapula's contact points (TS, AI) on the
// thorax ellipsoid and the conoid ligament from clavicle to scapula (force laws in girdle_forces.h,
// derived in docs/das3.md), as generalised forces J^T F; with a Jacobian also their stiffness
// d tau / dq = J^T (dF/dp) J (N m/rad; the small term from dJ/dq is left out, as for the moment arms).
#include <cmath>

#include "armrt/engine.h"

namespace armrt {

void girdle_forces(const Model& m, const double* q, double* tau, double* stiffness, GirdleState* state) {
  const int nq = m.num_dofs;
  for (int j = 0; j < nq; ++j) tau[j] = 0.0;
  if (stiffness)
    for (int k = 0; k < nq * nq; ++k) stiffness[k] = 0.0;
  const GirdleDef* g = m.def->girdle;
  if (g == nullptr) return;
  const int P = g->num_contact_points;
  double p[(kMaxContactPoints + 2) * 3];
  double J[(kMaxContactPoints + 2) * 3 * kMaxDofs];
  g->points(q, p, J);

  // Adds J^T F to tau and J^T dF J to the stiffness, for a force F (N) at a point with Jacobian J (3 x nq).
  auto apply = [&](const double* Jp, const double* F, const double* dF) {
    for (int j = 0; j < nq; ++j) tau[j] += Jp[j] * F[0] + Jp[nq + j] * F[1] + Jp[2 * nq + j] * F[2];
    if (!stiffness) return;
    double dFJ[3 * kMaxDofs];  // dF/dp J
    for (int r = 0; r < 3; ++r)
      for (int j = 0; j < nq; ++j) dFJ[r * nq + j] = dF[3 * r] * Jp[j] + dF[3 * r + 1] * Jp[nq + j] + dF[3 * r + 2] * Jp[2 * nq + j];
    for (int a = 0; a < nq; ++a)
      for (int b = 0; b < nq; ++b)
        stiffness[a * nq + b] += Jp[a] * dFJ[b] + Jp[nq + a] * dFJ[nq + b] + Jp[2 * nq + a] * dFJ[2 * nq + b];
  };

  for (int k = 0; k < P; ++k) {
    double F[3], dF[9];
    scapulothoracic_contact(g->thorax, p + 3 * k, F, stiffness ? dF : nullptr);
    apply(J + 3 * nq * k, F, dF);
    if (state) {
      state->contact_distance[k] = thorax_signed_distance(g->thorax, p + 3 * k);
      state->contact_force[k] = std::sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]);
    }
  }
  // Conoid: the force F on the insertion, -F on the origin; it depends on their difference only, so
  // both enter through J_insertion - J_origin.
  const double* xo = p + 3 * P;
  const double* xi = p + 3 * (P + 1);
  double Jd[3 * kMaxDofs];
  for (int k = 0; k < 3 * nq; ++k) Jd[k] = J[3 * nq * (P + 1) + k] - J[3 * nq * P + k];
  double F[3], dF[9];
  const double L = conoid_force(g->conoid, xo, xi, F, stiffness ? dF : nullptr);
  apply(Jd, F, dF);
  if (state) {
    state->conoid_length = L;
    state->conoid_tension = std::sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]);
  }
}

}  // namespace armrt
