#include "mesh/generate.hpp"
