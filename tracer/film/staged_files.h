// Output files that appear complete or not at all: each is written to a hidden temporary file
// beside its target, and all are renamed into place together by commit(). Destroying the set
// without commit() (an error was thrown) removes the temporary files and leaves the targets
// as they were.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rayset::tracer {

class StagedFiles {
public:
    StagedFiles() = default;
    ~StagedFiles();
    StagedFiles(const StagedFiles&) = delete;
    StagedFiles& operator=(const StagedFiles&) = delete;

    // Path to write the content of `target` to.
    std::string stage(const std::string& target);
    void commit();
    const std::vector<std::string>& targets() const { return targets_; }

private:
    std::vector<std::pair<std::string, std::string>> staged_;  // (temporary, target)
    std::vector<std::string> targets_;
    bool committed_ = false;
};

}  // namespace rayset::tracer
