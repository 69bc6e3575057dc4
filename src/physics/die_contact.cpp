#include "physics/die_contact.hpp"

namespace plisse {

std::unique_ptr<ModelTerm> make_die_term(const Die& die, const Case&, const Mesh&,
                                         const std::vector<ConstrainedComponent>&) {
  throw InputError(die.place, "rigid dies are not implemented yet");
}

}  // namespace plisse
