#include "mesh/quality.hpp"
