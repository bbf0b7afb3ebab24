// The Ceres solver options every optimizer of cyclide_optim starts from
// (private to lib/optim: Ceres never appears in a public header).
#pragma once

#include <ceres/ceres.h>

namespace cyclide {
inline namespace v0 {
namespace optim {

// Dense QR (the problems have a handful of unknowns), silent, one thread
// (results do not depend on scheduling, and callers run optimizers on
// their own threads), the iteration budget and the three stopping
// tolerances of Ceres' trust-region minimizer.
inline ceres::Solver::Options quiet_dense_options(int max_iterations, double function_tolerance,
                                                  double gradient_tolerance,
                                                  double parameter_tolerance) {
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.logging_type = ceres::SILENT;
  so.minimizer_progress_to_stdout = false;
  so.num_threads = 1;
  so.max_num_iterations = max_iterations;
  so.function_tolerance = function_tolerance;
  so.gradient_tolerance = gradient_tolerance;
  so.parameter_tolerance = parameter_tolerance;
  return so;
}

}  // namespace optim
}  // namespace v0
}  // namespace cyclide
