#include <cmath>

#include "armrt/engine.h"

namespace armrt {

void thorax_humerus_angles(const Model& m, const double* q, double* angles) {
  double Rb[kMaxBodies * 9], pb[kMaxBodies * 3];
  m.def->body_poses(q, Rb, pb);
  const double* Rs = m.def->base_rotation_in_thorax;
  const double* Rh = Rb + 9 * m.def->humerus_body;
  double R[9];  // humerus in thorax = R_base * R_humerus_in_base
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      R[r * 3 + c] = Rs[r * 3 + 0] * Rh[0 * 3 + c] + Rs[r * 3 + 1] * Rh[1 * 3 + c] + Rs[r * 3 + 2] * Rh[2 * 3 + c];
  // R = Ry(plane) Rz(elevation) Ry(axial): R[1][1] = cos(elevation), R[0][1] = -cos(plane) sin(elev),
  // R[2][1] = sin(plane) sin(elev), R[1][0] = sin(elev) cos(axial), R[1][2] = sin(elev) sin(axial).
  angles[1] = std::acos(std::fmax(-1.0, std::fmin(1.0, R[1 * 3 + 1])));
  angles[0] = std::atan2(R[2 * 3 + 1], -R[0 * 3 + 1]);
  angles[2] = std::atan2(R[1 * 3 + 2], R[1 * 3 + 0]);
}

}  // namespace armrt
