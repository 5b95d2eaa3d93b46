// VTK writers take a file name, so outputs go through a temporary name beside the target that
// is renamed into place only when the writer succeeded (the project's AtomicOutput rule).
#pragma once

#include <functional>
#include <string>

namespace rayset::viz {

// `write` gets the temporary path and returns whether it succeeded; throws rayset::Error naming
// `path` otherwise, leaving whatever was at `path` untouched.
void write_atomically(const std::string& path, const std::function<bool(const std::string&)>& write);

}  // namespace rayset::viz
