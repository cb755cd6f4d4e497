#!/usr/bin/env bash
# Resume on another number of MPI ranks, at full size: the check of
# tests/checkpoint_rank_change.sh (saved on 1 rank and resumed on 2, and
# the other way round, against the uninterrupted run on 1 rank; it prints
# the largest relative difference per statistics.csv column) on a shipped
# parameter file with its own number of steps.
# Usage: benchmarks/checkpoint_ranks.sh [build dir] [prm file]
#   default: the quarter circle at h = 2^-7 (parameter_files/willmore_flow)
set -euo pipefail
build=${1:-build}; shift || true
here=$(cd "$(dirname "$0")/.." && pwd)
prm=${1:-$here/parameter_files/willmore_flow/quarter_circle_h7.prm}
n_steps=$(sed -n 's/^ *set Number of steps *= *\([0-9]*\).*/\1/p' "$prm")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sh "$here/tests/checkpoint_rank_change.sh" mpirun "$build/willmore_flow" \
  "$prm" "$n_steps" "$work/runs"
