#!/bin/bash
# An example SLURM batch script for a run of fddem on several MPI processes (issue 15;
# docs/parallel.md). Adapt the partition, the module lines and the paths to your cluster.
#
# What runs on several processes today: cases without bodies (a case with bodies is refused
# with exit status 2). The grid is split into Cartesian blocks, one per process (the layout
# with the least interface area). Rank 0 writes every output file, gathered from the blocks.
#
# Memory (docs/testing.md, "Memory estimate"; the estimate fddem prints at the start):
#   one process:   48 MiB + 850 B per cell in 2D, 1700 B per cell in 3D;
#   N processes:   each rank about 48 MiB + its block's cells at that rate, and rank 0 in
#                  addition the whole run's state (a one-process mirror it writes the outputs
#                  from): about 1700 B per cell of the whole grid in 3D.
# Example: a 256³ cavity (16.8 M cells) on 64 ranks: ~0.5 GiB per rank, ~28 GiB more on
# rank 0. That extra is why rank 0 asks for a node of its own below (--mem per node).
#
# Speed: not measured on a cluster. On one 2-core machine, 2 ranks ran a 128² cavity 3× slower
# than one process (docs/parallel.md); blocks of at least ~10⁵ cells per rank are advised until
# the scaling benchmarks say more.
#
#SBATCH --job-name=fddem-cavity3d
#SBATCH --nodes=2
#SBATCH --ntasks-per-node=32
#SBATCH --cpus-per-task=1
#SBATCH --mem=120G
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
