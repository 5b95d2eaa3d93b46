// The processes a render is shared among: one, or the ranks of an MPI job (`mpirun -n N
// raytrace ...`, `srun raytrace ...`). Only the pass driver and raytrace's main speak to it;
// every call is made by every process in the same order, from one thread.
//
// Rank 0 is the root: it decides (budget, checkpoints, stop), writes and prints. With one
// process every operation is the identity and no MPI call is made.
#pragma once

#include <cstdint>
#include <vector>

namespace rayset::tracer {

class Processes {
public:
    // The processes of this run: MPI's world when the process was started by an MPI launcher
    // (mpirun, mpiexec, srun; MpiSession initialised it), else this process alone.
    static const Processes& world();

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool is_root() const { return rank_ == 0; }

    // The root's values, on every process.
    void broadcast(std::vector<int64_t>& values) const;
    void broadcast(std::vector<double>& values) const;
    // True on every process when `value` is true on all.
    bool all(bool value) const;
    // The element-wise sum of every process's `values` (of one length on all) into the root's:
    // a binomial tree, each process sending once and the root receiving log2(size) times,
    // summed in one fixed order, so the same bits for a given number of processes. Other
    // processes' values are left partial.
    void sum_at_root(std::vector<double>& values) const;
    // Ends every process of the job (after an error on some of them, which would otherwise
    // leave the others waiting in a collective).
    [[noreturn]] void abort(int exit_code) const;

private:
    friend class MpiSession;
    int rank_ = 0, size_ = 1;
};

// MPI for the life of main: initialised (MPI_THREAD_FUNNELED) when an MPI launcher started
// the process, finalised at the end; nothing otherwise.
class MpiSession {
public:
    MpiSession(int* argc, char*** argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

private:
    bool initialised_ = false;
};

}  // namespace rayset::tracer
