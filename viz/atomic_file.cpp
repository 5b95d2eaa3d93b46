#include "viz/atomic_file.h"

#include "converters/error.h"

#include <filesystem>
#include <system_error>

namespace rayset::viz {

void write_atomically(const std::string& path, const std::function<bool(const std::string&)>& write) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    // Same extension, so writers that look at it (none of VTK's XML ones do) still agree.
    const fs::path temporary = target.parent_path() / ("." + target.stem().string() + ".partial" + target.extension().string());
    std::error_code ignored;
    if (!write(temporary.string()) || !fs::exists(temporary)) {
        fs::remove(temporary, ignored);
        throw Error(path + ": cannot write");
    }
    std::error_code error;
    fs::rename(temporary, target, error);
    if (error) {
        fs::remove(temporary, ignored);
        throw Error(path + ": cannot write: " + error.message());
    }
}

}  // namespace rayset::viz
