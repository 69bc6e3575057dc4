#pragma once
/// The table of the case file's `solver:` section (internal to src/case; case.cpp uses it).
#include "case/case.hpp"
#include "schema/table.hpp"

namespace plisse::case_detail {

using schema::Schema;

/// `solver:` with its nested `newton`, `newton.linear` and `stability` tables. Built anew on each
/// call; the case's schema keeps one.
Schema<SolverSettings> solver_schema();

}  // namespace plisse::case_detail
