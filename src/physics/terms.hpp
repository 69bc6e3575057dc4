#pragma once
/// The model terms a case asks for: its loads, cavities and dies.
#include <memory>
#include <vector>

#include "io/case.hpp"
#include "physics/dirichlet.hpp"
#include "physics/model_term.hpp"

namespace plisse {

/// One term per load, then per cavity, then per die, in the case's order. Borrows `mesh`.
std::vector<std::unique_ptr<ModelTerm>> make_terms(const Case& c, const Mesh& mesh,
                                                   const std::vector<ConstrainedComponent>& constraints);

}  // namespace plisse
