#pragma once
/// Contact between the body and a rigid analytic die (plane, sphere, cylinder) with prescribed
/// motion: frictionless (unilateral) or sticking.
#include <memory>
#include <vector>

#include "io/case.hpp"
#include "physics/dirichlet.hpp"
#include "physics/model_term.hpp"

namespace plisse {

/// The term for `die` (borrows `mesh`).
std::unique_ptr<ModelTerm> make_die_term(const Die& die, const Case& c, const Mesh& mesh,
                                         const std::vector<ConstrainedComponent>& constraints);

}  // namespace plisse
