// Temporary files renamed into place together (see staged_files.h).
#include "tracer/film/staged_files.h"

#include <cstdio>
#include <filesystem>

#include <fmt/format.h>
#include <unistd.h>

#include "core/error.h"

namespace rayset::tracer {

namespace fs = std::filesystem;

StagedFiles::~StagedFiles() {
    if (committed_) return;
    for (const auto& [temporary, target] : staged_) std::remove(temporary.c_str());
}

std::string StagedFiles::stage(const std::string& target) {
    const fs::path path(target);
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    if (!fs::is_directory(folder))
        throw Error(fmt::format("{}: the output folder does not exist", target));
    const std::string temporary =
        (folder / fmt::format(".{}.{}-{}.tmp", path.filename().string(), getpid(), staged_.size()))
            .string();
    staged_.emplace_back(temporary, target);
    targets_.push_back(target);
    return temporary;
}

void StagedFiles::commit() {
    for (const auto& [temporary, target] : staged_)
        if (std::rename(temporary.c_str(), target.c_str()) != 0)
            throw Error(fmt::format("{}: cannot move the finished file into place", target));
    committed_ = true;
}

}  // namespace rayset::tracer
