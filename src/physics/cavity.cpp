#include "physics/cavity.hpp"

namespace plisse {

std::unique_ptr<ModelTerm> make_cavity_term(const Cavity& cavity, const Mesh&,
                                            const std::vector<ConstrainedComponent>&) {
  throw InputError(cavity.place, "cavities are not implemented yet");
}

}  // namespace plisse
