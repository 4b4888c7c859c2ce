// The interface between generated model code (cpp/generated/, written by `python -m codegen.generate`)
// and the engine. A ModelDef is immutable, static data: parameter tables plus straight-line functions.
// The generator fills it by member name (designated initialisers), so a field added here is never
// silently shifted into its neighbour's place. Sizes are the model's: n = num_dofs, E = num_elements.
// Arrays are row-major; frames and sign conventions are in docs/conventions.md.
#pragma once

#include "armrt/girdle_forces.h"

namespace armrt {

// Layout version of the structs below. A model library built on demand (cpp/src/registry.cc) reports the
// version it was compiled against and is refused if it differs: bump it whenever a field is added,
// removed, reordered or changes meaning. It is also part of the on-demand build cache key.
inline constexpr int kModelDefAbiVersion = 3;  // 3: muscle_paths writes moment arms by DOF

// Capacity of a model's muscle elements, and so the row stride of the moment arms by DOF that muscle_paths
// writes (below): a constant stride lets the engine's loops address every DOF's row from one pointer. It is
// compiled into every generated model (which static_asserts it), so changing it changes the layout: bump
// kModelDefAbiVersion with it, and codegen/generate.py's MAX_ELEMENTS.
inline constexpr int kMaxElements = 160;

// Capacity of GirdleDef's contact points (das3: TS and AI).
inline constexpr int kMaxContactPoints = 4;
// Capacity of the bodies moved by q (das3: clavicle, scapula, humerus, ulna, radius, hand).
inline constexpr int kMaxBodies = 8;

struct ElementParams {
  const char* name;        // DAS3 element name, e.g. "deltscap1"
  const char* muscle;      // parent muscle, e.g. "deltscap"
  const char* osim_name;   // OpenSim force name, e.g. "delt_scap_1" ("" if none): an alias (names.h)
  double fmax;             // N
  double lceopt;           // m
  double lslack;           // m, series elastic (tendon) slack length
  double pennopt;          // rad
  double vmax;             // lceopt/s
  double tact;             // s
  double tdeact;           // s
  double peeslack;         // x lceopt
  double mass;             // kg
  int crosses_gh;          // 0/1
  int dof_mask;            // bit j set if the element crosses DOF j
  double max_activation;   // [0, 1], the model's default cap on excitation and activation (1 = intact;
                           // a participant's `maxact`); Model::element[i].max_activation starts here
};

struct DofParams {
  const char* name;        // "GHy", ...
  const char* osim_name;   // "GH_y", ...
  double range_min;        // rad, fixed-scapula range of motion
  double range_max;        // rad
  double rest;             // rad, DAS3 equilibrium posture
};

struct GroupDef {
  const char* name;              // muscle or group name
  int num_elements;
  const int* elements;           // element indices
};

// The shoulder girdle's passive forces of a model whose clavicle and scapula move (das3; docs/das3.md):
// the scapula's contact points glide on the thorax ellipsoid, the conoid ligament ties the scapula to
// the clavicle. The base frame of such a model is the thorax, so all points are in thorax coordinates.
struct GirdleDef {
  ThoraxEllipsoid thorax;            // ellipsoid and contact penalty (girdle_forces.h)
  int num_contact_points;            // P (das3: 2)
  const char* const* contact_point_names;  // "TS", "AI"
  ConoidLigament conoid;             // slack length, stiffness, eps (its points are computed by points())
  // Positions p[(P + 2) * 3] (m, thorax frame) of the contact points, then the conoid's origin (clavicle)
  // and insertion (scapula), and their Jacobians J[(P + 2) * 3 * n] = dp/dq (m/rad), row-major.
  void (*points)(const double* q, double* p, double* J);
};

struct ModelDef {
  const char* name;              // "das2"
  const char* source_hash;       // SHA-256 of the model file it was generated from
  int num_dofs;                  // n (das2: 5), at most kMaxDofs
  int num_elements;              // E (das2: 102), at most kMaxElements
  const DofParams* dofs;
  const ElementParams* elements;
  int num_muscles;
  const GroupDef* muscles;       // the muscles (das2: 22)
  int num_groups;
  const GroupDef* groups;        // named groups (rotator_cuff, elbow_flexors, ...)

  // The base frame, fixed to the thorax, in which q = 0 and the chain start: the scapula for das2 (the
  // girdle fixed at the equilibrium.mat posture), the thorax itself for das3 (the girdle moves).
  const char* base_body;         // "scapula" or "thorax"
  double gravity_base[3];        // m/s^2, gravity in the base frame
  double base_rotation_in_thorax[9];  // columns = base axes in thorax coordinates
  double base_origin_in_thorax[3];    // m
  int num_bodies;                // bodies moved by q, proximal to distal (das2: 4, das3: 6)
  const char* const* body_names; // "clavicle", "scapula" (das3), "humerus", "ulna", "radius", "hand"
  int scapula_body;              // index of the scapula in body_poses; -1 when the scapula is the base
  int humerus_body;              // index of the humerus; the arm (GH reaction, arm_mass) is it and all after
  const GirdleDef* girdle;       // nullptr when the girdle is fixed
  double gh_centre[3];           // m, scapula frame
  double glenoid_normal[3];      // unit, scapula frame, GH centre -> glenoid centre
  double glenoid_major_axis[3];  // unit, superior-inferior axis of the glenoid ellipse
  double glenoid_minor_axis[3];  // unit, normal x major
  double rim_half_angle_major;   // rad
  double rim_half_angle_minor;   // rad
  double arm_mass;               // kg, humerus + ulna + radius + hand (the bodies the GH reaction holds)
  double passive_stiffness_inside;   // N m/rad
  double passive_stiffness_outside;  // N m/rad^2
  double passive_damping;            // N m s/rad

  // Dynamics: M(q) qdd = tau + bias_force(q, qd, g). Everything in the base frame.
  void (*mass_matrix)(const double* q, double* M);                       // M[n*n]
  void (*bias_force)(const double* q, const double* qd, const double* g_base,
                     double* b);                                         // b[n]: gravity and Coriolis/centrifugal generalised forces
  void (*dynamics)(const double* q, const double* qd, const double* g_base,
                   double* M, double* b);                                // both at once, sharing subexpressions
  void (*hand_position)(const double* q, double* p);                     // p[3], m, base frame
  void (*hand_jacobian)(const double* q, double* Jv, double* Jw);        // 3 x n each: hand point velocity, hand angular velocity
  void (*arm_momentum_rate)(const double* q, const double* qd,
                            double* A, double* c);                       // arm bodies: sum_b m_b a_b = A qdd + c; A[3*n], c[3]
  void (*body_poses)(const double* q, double* R, double* p);             // R[num_bodies*9], p[num_bodies*3] in the base frame
  // Muscle paths (polynomials): lengths, moment arms -dL/dq, lines of action at GH.
  void (*muscle_lengths)(const double* q, double* L);                    // L[E], m
  // L[E]; moment_arm by DOF, n rows of stride kMaxElements: moment_arm[j*kMaxElements + i] = -dL_i/dq_j (row j:
  // every element's moment arm about DOF j, zero for the elements that do not cross it), m; entries past E in
  // a row are unspecified (may be overwritten). By DOF so that the engine's loops over elements run eight elements per vector
  // operation (rosenbrock.cc, muscles.cc).
  void (*muscle_paths)(const double* q, double* L, double* moment_arm);
  void (*gh_directions)(const double* q, double* d);                     // d[E*3], unit, zero rows for non-GH elements
};

}  // namespace armrt
