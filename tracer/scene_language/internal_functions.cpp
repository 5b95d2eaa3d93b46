// Placeholder until the internal-function table lands: no internal function is known.
#include "tracer/scene_language/internal_functions.h"

namespace rayset::tracer {

int internal_function_arity(int) { return -1; }
const char* internal_function_name(int) { return ""; }
bool evaluate_internal_function(int, const double*, double&) { return false; }

}  // namespace rayset::tracer
