#!/usr/bin/env bash
# PeriStep's bond loop beside LAMMPS' peri/pmb and peri/lps on the same plate (102,400 points), both on
# two cores, medians of three runs each. Needs lmp and mpirun (Debian: lammps, openmpi-bin) and a built
# tree; prints one table. With a second build tree (an earlier version), also its rates ("before").
# Usage: bash bench/lammps/compare.sh [build dir] [runs] [earlier build dir]
set -euo pipefail
build=${1:-build}
runs=${2:-3}
before=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
command -v lmp >/dev/null || { echo "compare.sh: lmp (LAMMPS) is not installed" >&2; exit 1; }
mpi=(mpirun -n 2)
[ "$(id -u)" = 0 ] && mpi+=(--allow-run-as-root)
side=${PERISTEP_PLATE_SIDE:-320}  # points per side (the benchmark default)
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

# LAMMPS: bond-updates/s = bonds x steps / loop time.
lammps() {  # style ratio steps
  "${mpi[@]}" lmp -log none -in "$here/peri_plate.in" -var style "$1" -var side $side -var ratio "$2" -var steps "$3" |
    awk -v steps="$3" '/total # of bonds/ {b = $NF} /^Loop time/ {t = $4} END {printf "%.4e\n", b * steps / t}'
}
declare -A rate
for run in $(seq "$runs"); do
  for ratio in 4 8; do
    steps=$([ $ratio = 4 ] && echo 40 || echo 12)
    for style in pmb lps; do rate[lammps-$style-$ratio]+="$(lammps $style $ratio $steps) "; done
  done
  # PeriStep: the four rows of dynamics_throughput (eps/h 4, 8 tensile; 4, 8 hydrostatic).
  for version in peristep ${before:+before}; do
    tree=$([ $version = peristep ] && echo "$build" || echo "$before")
    while read -r ratio nu r; do
      rate[$version-$([ "$nu" = 0.25 ] && echo pmb || echo lps)-$ratio]+="$r "
    done < <(OMP_NUM_THREADS=2 "$tree/bench/dynamics_throughput" --side $side --repeats 1 |
             awk '$1 == 4 || $1 == 8 {print $1, $2, $8}')
  done
done
column() { tr ' ' '\n' <<< "${rate[$1]:-}" | grep . | median; }
printf "%-6s %-44s %12s %12s %12s %6s\n" "eps/h" "model" "LAMMPS" "before" "PeriStep" "ratio"
for ratio in 4 8; do
  for style in pmb lps; do
    l=$(column lammps-$style-$ratio)
    p=$(column peristep-$style-$ratio)
    b=$([ -n "$before" ] && column before-$style-$ratio || echo -)
    name=$([ $style = pmb ] && echo "peri/pmb vs tensile only (nu = 0.25)" || echo "peri/lps vs with hydrostatic term (nu = 0.22)")
    printf "%-6s %-44s %12.3e %12s %12.3e %6.1f\n" $ratio "$name" "$l" "$b" "$p" "$(awk -v a="$p" -v b="$l" 'BEGIN {print a / b}')"
  done
done
echo "(bond-updates/s, median of $runs runs; two MPI ranks for LAMMPS, two OpenMP threads for PeriStep; ratio = PeriStep / LAMMPS)"
