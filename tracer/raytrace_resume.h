// raytrace's stop and resume machinery: the SIGINT/SIGTERM handlers that ask the renderer to
// stop, and the schedule of checkpoints written while it renders (film/checkpoint.h).
#pragma once

#include <atomic>
#include <chrono>
#include <string>

#include "tracer/film/checkpoint.h"

namespace rayset::tracer {

// While alive, SIGINT and SIGTERM (unless ignored when it began) set flag() and say on stderr
// that the render is stopping; the handler then resets itself, so a second signal ends the
// process at once. One at a time.
class InterruptSignals {
public:
    InterruptSignals();
    ~InterruptSignals();
    InterruptSignals(const InterruptSignals&) = delete;
    InterruptSignals& operator=(const InterruptSignals&) = delete;

    const std::atomic<bool>& flag() const;
    int signal() const;  // the signal received, 0 for none
    const char* signal_name() const;
    int exit_code() const { return 128 + signal(); }  // the shell's convention: 130, 143
};

// Writes the checkpoint after a pass when the file holds no pass yet or `interval` seconds
// have passed since the last write; write() on demand (interruption, --keep-checkpoint).
class CheckpointSchedule {
public:
    // `passes_on_disk`: the passes of the checkpoint already at `path` that this render
    // continues (0 for a fresh render, whose file is replaced at its first pass).
    CheckpointSchedule(std::string path, CheckpointIdentity identity, double interval,
                       int passes_on_disk);
    // Whether after_pass would write now.
    bool due() const;
    // A failed write here is reported on stderr and retried at the next pass: the render goes on.
    void after_pass(const RenderResult& state);
    void write(const RenderResult& state);  // unless the file already holds this state; throws
    void remove();

private:
    std::string path_;
    CheckpointIdentity identity_;
    double interval_;
    int passes_on_disk_;
    std::chrono::steady_clock::time_point last_write_;
};

}  // namespace rayset::tracer
