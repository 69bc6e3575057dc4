#include "solver/stall_watch.hpp"

#include <cstdio>

namespace plisse {

void StallWatch::restart() {
  previous_ = -1.0;
  run_ = 0;
}

bool StallWatch::stalled(double norm) {
  if (previous_ >= 0.0) {
    if (norm > ratio_ * previous_) {
      if (run_ == 0) run_start_ = previous_;
      ++run_;
    } else {
      run_ = 0;
    }
  }
  previous_ = norm;
  return iterations_ > 0 && run_ >= iterations_;
}

std::string StallWatch::describe() const {
  char text[320];
  std::snprintf(text, sizeof text,
                "stalled: %d iterations in a row each left the residual above %.3g times the "
                "one before (from %.4g to %.4g; solver.newton.stall_iterations, stall_ratio)",
                run_, ratio_, run_start_, previous_);
  return text;
}

}  // namespace plisse
