// A progress bar on stderr for long work, drawn only when stderr is a terminal and at most
// ten times a second, so it costs nothing in pipelines and tests.
#pragma once

#include <chrono>
#include <string>

namespace rayset {

class ProgressBar {
public:
    explicit ProgressBar(std::string label, bool enabled = true);
    ~ProgressBar();
    void update(double fraction);  // 0..1
    void done();

private:
    std::string label_;
    bool enabled_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace rayset
