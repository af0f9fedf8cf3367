#!/usr/bin/env bash
# A campaign spread over MPI ranks (task farm): run i goes to rank i mod K, each
# rank runs its runs one after the other in its own process; rank 0
# post-processes when all are done. Finished runs are skipped with --resume, so
# the same command continues a campaign after a kill or a time limit.
#
#   workflows/mpi/run_campaign.sh configs/collapse_table51.yaml runs 4
#
# Inside a Slurm allocation, `srun grainflow campaign ...` works the same way.
set -euo pipefail
config=${1:?usage: run_campaign.sh CAMPAIGN.yaml [OUT_DIR] [RANKS]}
out=${2:-runs}
ranks=${3:-2}
here=$(cd "$(dirname "$0")/../.." && pwd)
grainflow=${GRAINFLOW:-$here/build/grainflow}
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}   # one core per rank
mpirun -n "$ranks" "$grainflow" campaign "$config" -o "$out" --resume
