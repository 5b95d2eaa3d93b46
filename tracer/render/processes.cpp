// MPI behind Processes (processes.h).
#include "tracer/render/processes.h"

#include <cstdlib>

#include <mpi.h>

#include "core/error.h"

namespace rayset::tracer {

namespace {

Processes& mutable_world() {
    static Processes world;
    return world;
}

// Each launcher says so in the environment of the processes it starts: Open MPI's mpirun,
// MPICH's and Intel's Hydra (PMI), PMIx (Open MPI 4+, Slurm's srun --mpi=pmix).
bool started_by_mpi_launcher() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
        if (std::getenv(name)) return true;
    return false;
}

void check(int code, const char* what) {
    if (code != MPI_SUCCESS) throw Error(std::string("MPI: ") + what + " failed");
}

}  // namespace

const Processes& Processes::world() { return mutable_world(); }

void Processes::broadcast(std::vector<int64_t>& values) const {
    if (size_ == 1) return;
    check(MPI_Bcast(values.data(), int(values.size()), MPI_INT64_T, 0, MPI_COMM_WORLD),
          "broadcast");
}

void Processes::broadcast(std::vector<double>& values) const {
    if (size_ == 1) return;
    int64_t count = int64_t(values.size());
    check(MPI_Bcast(&count, 1, MPI_INT64_T, 0, MPI_COMM_WORLD), "broadcast");
    values.resize(size_t(count));
    check(MPI_Bcast(values.data(), int(count), MPI_DOUBLE, 0, MPI_COMM_WORLD), "broadcast");
}

bool Processes::all(bool value) const {
    if (size_ == 1) return value;
    int local = value ? 1 : 0, result = 0;
    check(MPI_Allreduce(&local, &result, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD), "reduction");
    return result == 1;
}

void Processes::sum_at_root(std::vector<double>& values) const {
    constexpr int kTag = 1;
    std::vector<double> received(size_ > 1 ? values.size() : 0);
    for (int step = 1; step < size_; step *= 2) {
        if (rank_ % (2 * step) == step) {
            check(MPI_Send(values.data(), int(values.size()), MPI_DOUBLE, rank_ - step, kTag,
                           MPI_COMM_WORLD),
                  "send");
            return;
        }
        if (rank_ + step < size_) {
            check(MPI_Recv(received.data(), int(received.size()), MPI_DOUBLE, rank_ + step, kTag,
                           MPI_COMM_WORLD, MPI_STATUS_IGNORE),
                  "receive");
            for (size_t i = 0; i < values.size(); ++i) values[i] += received[i];
        }
    }
}

void Processes::abort(int exit_code) const {
    if (size_ > 1) MPI_Abort(MPI_COMM_WORLD, exit_code);
    std::exit(exit_code);
}

MpiSession::MpiSession(int* argc, char*** argv) {
    if (!started_by_mpi_launcher()) return;
    int provided = 0;
    check(MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided), "initialisation");
    initialised_ = true;
    Processes& world = mutable_world();
    MPI_Comm_rank(MPI_COMM_WORLD, &world.rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &world.size_);
}

MpiSession::~MpiSession() {
    if (initialised_) MPI_Finalize();
}

}  // namespace rayset::tracer
