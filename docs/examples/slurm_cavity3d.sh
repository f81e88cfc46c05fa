#!/bin/bash
# An example SLURM batch script for a run of fddem on several MPI processes (issue 15;
# docs/parallel.md). Adapt the partition, the module lines and the paths to your cluster.
#
# What runs on several processes: any case, with no change to it (the bodies are held whole by
# every rank; docs/parallel.md says what is not split yet). The grid is split into Cartesian
# blocks, one per process (the layout with the least interface area). Every rank writes its
# pieces of the field frames and checkpoints; rank 0 writes the other files. No rank holds the
# whole grid (since the thirty-eighth session).
#
# Memory (docs/testing.md, "Memory estimate"; fddem prints at the start the whole run's
# estimate and, on several ranks, the largest block's and that of the ranks on each machine):
#   one process:   48 MiB + 850 B per cell in 2D, 1700 B per cell in 3D;
#   N processes:   each rank, rank 0 included, about 48 MiB + its block's cells at that rate
#                  (measured: the 96³ cube on 2 ranks peaked at 529 and 493 MiB, one process
#                  at 960 MiB; `bench/run.sh --no-base --mpi-memory 96`).
# Example: a 256³ cavity (16.8 M cells) on 64 ranks: fddem's estimate is about 0.55 GiB for the
# largest block, 17 GiB for the 32 ranks of a node; --mem below leaves room for the MPI
# library's buffers.
#
# Speed: not measured on a cluster. On one 2-core machine, 2 ranks ran a 128² cavity 3× slower
# than one process (docs/parallel.md); blocks of at least ~10⁵ cells per rank are advised until
# the scaling benchmarks say more.
#
#SBATCH --job-name=fddem-cavity3d
#SBATCH --nodes=2
#SBATCH --ntasks-per-node=32
#SBATCH --cpus-per-task=1
#SBATCH --mem=32G
#SBATCH --time=02:00:00
#SBATCH --output=fddem-%j.log

set -euo pipefail
# module load openmpi hypre fftw   # what your cluster calls them

export OMP_NUM_THREADS=${SLURM_CPUS_PER_TASK}
FDDEM=${FDDEM:-$HOME/fddem/build/release/app/fddem}
CASE=${CASE:-$HOME/fddem/docs/examples/cavity3d.toml}

# The lid-driven cube at Re 100, 256³ cells (docs/examples/cavity3d.toml), unchanged.
srun "$FDDEM" run "$CASE" -o "runs/cavity3d_${SLURM_JOB_ID}"

# A run continues on any number of processes from its last checkpoint:
#   srun "$FDDEM" run --restart "runs/cavity3d_<job id>" --set time.end=2.0
