// Signal handling and checkpoint schedule of raytrace (see raytrace_resume.h).
#include "tracer/raytrace_resume.h"

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <utility>

#include <unistd.h>

#include "core/error.h"

namespace rayset::tracer {

namespace {

// A signal handler may only touch lock-free atomics.
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free);
std::atomic<bool> stop_flag{false};
std::atomic<int> received_signal{0};
struct sigaction previous_int, previous_term;

extern "C" void on_interrupt(int number) {
    received_signal.store(number);
    stop_flag.store(true);
    static const char message[] =
        "\nraytrace: stopping: writing the last completed pass and the checkpoint (again to quit "
        "at once)\n";
    const ssize_t ignored = write(STDERR_FILENO, message, sizeof message - 1);
    (void)ignored;
}

}  // namespace

InterruptSignals::InterruptSignals() {
    stop_flag = false;
    received_signal = 0;
    struct sigaction action = {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART | SA_RESETHAND;
    sigaction(SIGINT, &action, &previous_int);
    sigaction(SIGTERM, &action, &previous_term);
    // A signal the caller ignores stays ignored (the shell's background jobs ignore SIGINT).
    if (previous_int.sa_handler == SIG_IGN) sigaction(SIGINT, &previous_int, nullptr);
    if (previous_term.sa_handler == SIG_IGN) sigaction(SIGTERM, &previous_term, nullptr);
}

InterruptSignals::~InterruptSignals() {
    sigaction(SIGINT, &previous_int, nullptr);
    sigaction(SIGTERM, &previous_term, nullptr);
}

const std::atomic<bool>& InterruptSignals::flag() const { return stop_flag; }
int InterruptSignals::signal() const { return received_signal.load(); }
const char* InterruptSignals::signal_name() const {
    return signal() == SIGINT ? "SIGINT" : signal() == SIGTERM ? "SIGTERM" : "no signal";
}

CheckpointSchedule::CheckpointSchedule(std::string path, CheckpointIdentity identity,
                                       double interval, int passes_on_disk)
    : path_(std::move(path)),
      identity_(std::move(identity)),
      interval_(interval),
      passes_on_disk_(passes_on_disk),
      last_write_(std::chrono::steady_clock::now()) {}

bool CheckpointSchedule::due() const {
    const double since =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - last_write_).count();
    return passes_on_disk_ == 0 || since >= interval_;
}

void CheckpointSchedule::after_pass(const RenderResult& state) {
    if (!due()) return;
    try {
        write(state);
    } catch (const Error& e) {
        std::fprintf(stderr,
                     "raytrace: warning: %s (the render goes on; retried after the next pass)\n",
                     e.what());
    }
}

void CheckpointSchedule::write(const RenderResult& state) {
    if (state.passes == passes_on_disk_) return;
    write_checkpoint(path_, identity_, state);
    passes_on_disk_ = state.passes;
    last_write_ = std::chrono::steady_clock::now();
}

void CheckpointSchedule::remove() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
    passes_on_disk_ = 0;
}

}  // namespace rayset::tracer
