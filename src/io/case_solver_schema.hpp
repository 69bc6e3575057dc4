#pragma once
/// The table of the case file's `solver:` section (internal to src/io; case.cpp uses it).
#include "io/case.hpp"
#include "io/case_schema.hpp"

namespace plisse::case_detail {

/// `solver:` with its nested `newton`, `newton.linear` and `stability` tables. Built anew on each
/// call; the case's schema keeps one.
Schema<SolverSettings> solver_schema();

}  // namespace plisse::case_detail
