#pragma once
/// A fluid-filled cavity bounded by a tagged surface (closed, or closed by symmetry planes through
/// the origin): volume control or an ideal gas, with the cavity pressure as a global unknown.
#include <memory>
#include <vector>

#include "io/case.hpp"
#include "physics/dirichlet.hpp"
#include "physics/model_term.hpp"

namespace plisse {

/// The term for `cavity` (borrows `mesh`).
std::unique_ptr<ModelTerm> make_cavity_term(const Cavity& cavity, const Mesh& mesh,
                                            const std::vector<ConstrainedComponent>& constraints);

}  // namespace plisse
