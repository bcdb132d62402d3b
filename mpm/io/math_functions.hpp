#pragma once
// CB-Geo's math functions (the deck's `math_functions` array, include/functions/): functions of time that
// scale a load (base_acceleration, concentrated_nodal_forces, particle_surface_traction). Both of CB-Geo's
// types are read: "Linear" (a table of points) and "Sin".
#include <map>

#include "mpm/problem/math_function.hpp"

namespace mpm::io {

class StrictObject;


/// Reads `math_functions` from the root object (absent or []: none): each entry {"id", "type": "Linear",
/// "xvalues": [...], "fxvalues": [...]} or {"id", "type": "Sin", "a", "x0", <"xrange": [min, max]>}.
/// Errors name the entry and key: an unknown type, arrays of different lengths or of non-numbers, x not
/// strictly increasing, an xrange that is not 2 increasing numbers (CB-Geo ignores it), a duplicate id.
std::map<unsigned, MathFunction> read_math_functions(StrictObject& root);

/// The function `math_function_id` of `functions` (the key read from `entry`); fails naming the key when
/// there is no such function.
const MathFunction& math_function_of(StrictObject& entry, const std::map<unsigned, MathFunction>& functions);

}  // namespace mpm::io
