#!/bin/bash
# One render across the nodes of a Slurm cluster: each MPI rank renders its share of the
# passes, rank 0 combines them and writes the outputs and the checkpoint. The result equals a
# one-process render of the same passes up to the order of floating-point sums, and is the
# same bits for a given number of ranks.
#
#   sbatch examples/slurm_render.sh scene.pov out/scene.exr 256
#
# Give each rank a node's cores (--threads), so the job runs one rank per node. rayset is
# built with Open MPI (scripts/install-deps.sh); the scene, its include files and ray files
# must be readable on every node (a shared file system), the output folder on the first.
#SBATCH --job-name=raytrace
#SBATCH --nodes=4
#SBATCH --ntasks-per-node=1
#SBATCH --cpus-per-task=32
#SBATCH --time=02:00:00
#SBATCH --output=raytrace-%j.log
set -euo pipefail
scene=${1:?usage: sbatch slurm_render.sh SCENE.pov OUT.exr PASSES}
output=${2:?usage: sbatch slurm_render.sh SCENE.pov OUT.exr PASSES}
passes=${3:-256}
raytrace=${RAYTRACE:-build/tracer/raytrace}

# srun starts one raytrace per task; with Open MPI, mpirun inside the allocation does the same
# (mpirun -n "$SLURM_NTASKS" ...). A resubmitted job continues from the checkpoint (--resume),
# so a job that hit its time limit is resumed rather than repeated.
resume=()
[ -f "${output%.exr}.checkpoint" ] && resume=(--resume)
srun --mpi=pmix "$raytrace" "$scene" -o "$output" --passes "$passes" \
  --threads "$SLURM_CPUS_PER_TASK" --checkpoint-interval 300 "${resume[@]}"
