// POV-Ray's internal functions, the ones functions.inc names `function { internal(N) }`
// (f_sphere, f_torus, f_rounded_box, f_noise3d, ...), with the parameters that file lists for
// each: x, y, z and the extra ones.
#pragma once

namespace rayset::tracer {

// The number of parameters internal(N) takes (x, y, z and the extra ones), or -1 when POV-Ray
// 3.7 has no internal function N.
int internal_function_arity(int number);
// Its name in functions.inc ("f_sphere"), or "" when there is none.
const char* internal_function_name(int number);
// Evaluates internal(N) at `args` (internal_function_arity(N) values). Returns false when
// the function is not implemented; the caller reports it as not supported.
bool evaluate_internal_function(int number, const double* args, double& result);

}  // namespace rayset::tracer
