#include "material/gent.hpp"

#include <sstream>

#include "material/inadmissible_deformation.hpp"

namespace plisse {

void Gent::throw_past_limit(double I1bar) const {
  std::ostringstream msg;
  msg << "inadmissible deformation for the gent model: Ī1 - 3 = " << I1bar - 3.0
      << " reached the chain-extensibility limit jm = " << jm << " (energy is infinite there)";
  throw InadmissibleDeformation(msg.str());
}

}  // namespace plisse
