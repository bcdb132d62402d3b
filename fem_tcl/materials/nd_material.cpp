#include "fem_tcl/materials/nd_material.hpp"
