// Model: the immutable description of one arm model (like mjModel / pinocchio::Model), built once per
// generated ModelDef (shared_model() in registry.h) and shared by every arm of it. What may differ between
// arms of one model (strength, maximum activation, gravity, the divergence bound) is in Data::settings
// (data.h), with the muscle constants scaled by it.
#pragma once

#include <array>

#include "armrt/model_def.h"

namespace armrt {

// Capacities, not sizes: a model's own sizes are ModelDef::num_dofs and num_elements (das2: 5 and 102;
// the full shoulder girdle: 11 and 138). Model and Data reserve room for the largest, so one build runs
// any generated model and stepping never allocates.
inline constexpr int kMaxDofs = 16;
// kMaxElements: model_def.h (the row stride of muscle_paths' moment arms).
inline constexpr int kMaxState = 2 * kMaxDofs + 2 * kMaxElements;

// Hill-type muscle constants (McLean et al. 2003, as used by the DAS3 real-time code).
inline constexpr double kHillA = 0.25;             // Hill a/Fmax (concentric curvature)
inline constexpr double kEccentricFmax = 1.5;      // eccentric force limit, x isometric force
inline constexpr double kForceLengthWidth = 0.56;  // width of the Gaussian force-length curve (x lceopt)
inline constexpr double kTendonStrainAtFmax = 0.04;
// Fibre compressive element (muscle.cc): zero above kCompressOnset lceopt (or kCompressMinSpan lceopt above
// the geometric minimum min_lce, whichever is longer), quadratic below, kCompressForceAtMin fmax at min_lce.
inline constexpr double kCompressOnset = 0.3;
inline constexpr double kCompressMinSpan = 0.1;
inline constexpr double kCompressForceAtMin = 4.0;
// Physical domain checked after every step (integrate.cc check_state): CE length in [min_lce, max_lce]
// with max_lce where the PEE alone would carry kMaxPeeForce fmax; activation in [0, 1] (with
// kActivationTolerance for round-off); joints at most kJointRangeMargin beyond their range of motion,
// where the passive joint moment is already 5000 N m/rad^2 * 0.35^2 = 610 N m.
inline constexpr double kMaxPeeForce = 9.0;
// A relaxed slack fibre at rest (muscle_equilibrium_lce) leaves its tendon slack by this fraction of lslack.
inline constexpr double kRestTendonSlack = 0.002;
inline constexpr double kActivationTolerance = 1e-6;
inline constexpr double kJointRangeMargin = 0.35;  // rad (20 deg)
// A start pose (Arm.reset, armrt-rt --q0) is refused more than this beyond a joint's range (rad, ~11 deg): a state
// may end there (the passive limits are springs), a start so far out is a mistake (often degrees for radians).
inline constexpr double kStartRangeMargin = 0.2;
// A scapula contact point (TS, AI) 2 cm inside the thorax ellipsoid carries about 3 kN of contact force
// (das3; docs/das3.md): no physiological load gets there, so the state is refused as out of domain.
inline constexpr double kMaxContactPenetration = 0.02;  // m
inline constexpr double kFibreDamping = 10.0;      // N/(m/s), parallel to the contractile element
inline constexpr double kLowActivation = 0.02;     // below it the damper adds the CE damping that is lost

struct ElementConstants {
  double fmax;          // N, after strength scaling
  double lceopt;        // m
  double inv_lceopt;    // 1/m
  double min_lce;       // m, shortest CE length the pennation geometry allows
  double max_lce;       // m, longest CE length accepted by the domain check (PEE at kMaxPeeForce fmax)
  double compress_length;  // m, below it the fibre compressive element pushes
  double k_compress;    // N/m^2, its quadratic stiffness
  double lslack;        // m
  double thickness;     // m, lceopt * sin(pennopt): constant for a constant-volume pennate muscle
  double vmax;          // m/s (vmax * lceopt)
  double k_see;         // N/m^2, quadratic SEE: fmax at 4% strain
  double k_pee;         // N/m^2, quadratic PEE: fmax at (peeslack + width) * lceopt
  double pee_slack;     // m
  double c1, c2;        // activation dynamics: da/dt = (c1 u + c2)(u - a)
  double ecc_c;         // m/s, eccentric F-V constant matching the concentric slope at zero velocity
  double damping_slope; // N s/m per unit activation: the CE's force-velocity damping at v = 0, fmax (1+A)/(A vmax)
  double max_activation;  // [0, 1]
  double strength_scale;  // multiplies DAS3 fmax (1 = intact)
};
// The constants of one element (DAS3 parameters p) at a strength scale (x fmax) and maximum activation.
ElementConstants element_constants(const ElementParams& p, double strength_scale, double max_activation);

// The same constants as structure-of-arrays, for the vectorised muscle loop in forward().
struct MuscleArrays {
  std::array<double, kMaxElements> fmax, inv_lceopt, lslack, thickness, min_lce, vmax, k_see, k_pee,
      pee_slack, compress_length, k_compress, ecc_c, damping_slope, c1, c2, max_activation;
  // Reciprocals for the ROS2 overshoot limiter's loop (fibre_limiter.cc), where divisions dominated:
  std::array<double, kMaxElements> inv_k_see;        // 1/k_see, m^2/N
  std::array<double, kMaxElements> inv_taut_stretch; // 1/m, 1 / (a tenth of the tendon's stretch at fmax)
  std::array<double, kMaxElements> max_lce;          // m, the physical domain's upper CE length (check_state)
};

// The bound on joint speed (rad/s) beyond which a simulation counts as diverged, unless an arm sets its own.
inline constexpr double kDefaultMaxJointSpeed = 100.0;

struct Model {
  const ModelDef* def = nullptr;
  int num_dofs = 0;       // generalised coordinates (<= kMaxDofs)
  int num_elements = 0;   // muscle elements (<= kMaxElements)
  // The intact model's element constants (strength 1, the model file's maximum activation): what
  // Data::settings scales per arm (data_apply_settings).
  std::array<ElementConstants, kMaxElements> element{};
  std::array<double, 3> gravity_base{};     // m/s^2, the model file's gravity (an arm may set its own)
  double fibre_damping = kFibreDamping;     // N/(m/s)
  // For each DOF, the elements [begin, end) that span those crossing it (by their dof_mask): the moment arms
  // about it are zero outside, so R^T F sums each row over that range only (das3: SC is crossed within
  // elements 0-100, GH within 36-102, the elbow within 82-137; muscles.cc generalised_force).
  std::array<int, kMaxDofs> dof_elements_begin{}, dof_elements_end{};
  // The elements in blocks of eight (the engine's vector width, lanes.h) as runs of consecutive blocks that
  // cross the same range of DOFs: a run's moment arms are zero outside [dof_lo, dof_hi] (the lowest and highest
  // DOF any of its elements crosses). Loops over moment-arm pairs skip the zero rows with them (das3: 10 runs
  // over 18 blocks; its R^T diag(k) R needs 320 eight-wide multiply-adds instead of 791 by dof_elements_*).
  // The last block may end past num_elements (at the next multiple of 8): the engine's per-element arrays
  // (Data, StepJacobian, PathHistory) are zero there, so its ghost lanes add zeros.
  struct ElementRun {
    int begin, end;       // elements [begin, end), multiples of 8
    int dof_lo, dof_hi;   // DOFs crossed, inclusive
  };
  static_assert(kMaxElements % 8 == 0, "per-element arrays hold whole blocks of eight");
  std::array<ElementRun, kMaxElements / 8> element_runs{};
  int num_element_runs = 0;
};

// Builds a Model from generated tables. Never allocates; throws std::invalid_argument if the model's
// sizes exceed the capacities above. Most code wants the one shared Model of a ModelDef (shared_model).
void model_init(Model& m, const ModelDef& def);

}  // namespace armrt
