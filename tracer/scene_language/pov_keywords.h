// POV-Ray 3.7's reserved words, so that a keyword outside our subset is reported as
// "not supported" rather than as an unknown identifier, and cannot be #declared.
#pragma once

#include <string>

namespace rayset::tracer {

bool is_pov_keyword(const std::string& word);
// The keywords this parser understands somewhere (a subset keyword in the wrong place is a
// syntax error, not a missing feature).
bool is_subset_keyword(const std::string& word);

}  // namespace rayset::tracer
