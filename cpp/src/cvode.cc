#include "armrt/cvode.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <ctime>
#include <stdexcept>
#include <string>

#include "armrt/engine.h"

namespace armrt {
namespace {

struct RhsContext {
  const Model* m;
  Data* d;
};

int rhs(sunrealtype, N_Vector y, N_Vector ydot, void* user) {
  auto* c = static_cast<RhsContext*>(user);
  forward(*c->m, *c->d, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), false);
  return 0;
}

}  // namespace

CvodeIntegrator::CvodeIntegrator(const Model& m, Data& d, double rtol, double atol) : m_(m), d_(d) {
  SUNContext ctx;
  if (SUNContext_Create(nullptr, &ctx) != 0) throw std::runtime_error("CVODE: SUNContext_Create failed");
  ctx_ = ctx;
  const int n = state_size(m);
  N_Vector y = N_VNew_Serial(n, ctx);
  y_ = y;
  for (int k = 0; k < n; ++k) NV_Ith_S(y, k) = d.x[k];
  mem_ = CVodeCreate(CV_BDF, ctx);
  if (!mem_ || CVodeInit(mem_, rhs, d.time, y) != CV_SUCCESS)
    throw std::runtime_error("CVODE: initialisation failed");
  CVodeSStolerances(mem_, rtol, atol);
  SUNMatrix A = SUNDenseMatrix(n, n, ctx);
  A_ = A;
  SUNLinearSolver ls = SUNLinSol_Dense(y, A, ctx);
  ls_ = ls;
  if (CVodeSetLinearSolver(mem_, ls, A) != CV_SUCCESS) throw std::runtime_error("CVODE: linear solver setup failed");
  CVodeSetMaxNumSteps(mem_, 100000);
  user_ = new RhsContext{&m_, &d_};
  CVodeSetUserData(mem_, user_);
}

CvodeIntegrator::~CvodeIntegrator() {
  if (mem_) CVodeFree(&mem_);
  delete static_cast<RhsContext*>(user_);
  if (ls_) SUNLinSolFree(static_cast<SUNLinearSolver>(ls_));
  if (A_) SUNMatDestroy(static_cast<SUNMatrix>(A_));
  if (y_) N_VDestroy(static_cast<N_Vector>(y_));
  if (ctx_) {
    SUNContext c = static_cast<SUNContext>(ctx_);
    SUNContext_Free(&c);
  }
}

void CvodeIntegrator::reinit() {
  N_Vector y = static_cast<N_Vector>(y_);
  for (int k = 0; k < state_size(m_); ++k) NV_Ith_S(y, k) = d_.x[k];
  CVodeReInit(mem_, d_.time, y);
}

bool CvodeIntegrator::advance(double dt) {
  forward(m_, d_, d_.x.data(), xdot_scratch_, true);
  N_Vector y = static_cast<N_Vector>(y_);
  // Inputs are piecewise constant per interval: restart when they jump so the BDF history does not
  // straddle a discontinuity, and keep the history (and large steps) while they are constant.
  bool inputs_changed = !have_inputs_;
  for (int i = 0; i < m_.num_elements; ++i) inputs_changed |= d_.excitation[i] != last_excitation_[i];
  // A stimulation map's drive changes at every step: each step is its own initial-value problem then.
  inputs_changed |= d_.stimulation_map.num_channels > 0;
  for (int k = 0; k < 3; ++k)
    inputs_changed |= d_.hand_force[k] != last_load_[k] || d_.hand_moment[k] != last_load_[3 + k];
  for (int j = 0; j < m_.num_dofs; ++j) inputs_changed |= d_.applied_moment[j] != last_load_[6 + j];
  if (inputs_changed) {
    for (int i = 0; i < m_.num_elements; ++i) last_excitation_[i] = d_.excitation[i];
    for (int k = 0; k < 3; ++k) last_load_[k] = d_.hand_force[k], last_load_[3 + k] = d_.hand_moment[k];
    for (int j = 0; j < m_.num_dofs; ++j) last_load_[6 + j] = d_.applied_moment[j];
    have_inputs_ = true;
    reinit();
  }
  sunrealtype tret = d_.time;
  const int flag = CVode(mem_, d_.time + dt, y, &tret, CV_NORMAL);
  for (int k = 0; k < state_size(m_); ++k) d_.x[k] = NV_Ith_S(y, k);
  d_.time = tret;
  if (flag < 0) {
    d_.status = Status::kCvodeFailed;
    d_.bad_time = d_.time;
    return false;
  }
  return check_state(m_, d_);
}

long CvodeIntegrator::num_steps() const {
  long n = 0;
  CVodeGetNumSteps(mem_, &n);
  return n;
}

}  // namespace armrt
