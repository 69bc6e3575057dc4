#include "mesh/gmsh_io.hpp"
