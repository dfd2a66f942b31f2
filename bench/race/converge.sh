#!/usr/bin/env bash
# rodsea's largest converged time step on the race system: the collision rates and the mean
# squared velocities in the plane and along z at dt = 20 µs down to 0.625 µs, 4 seeds × 0.1 s
# each, and each dt against dt/4 (bench/race/converge_report.py). race.sh's
# RODSEA_DT is the largest step that passes in the observables LAMMPS reports too (the two mean
# squared velocities; converge_lammps.sh), the report's last line.
#
#   bench/race/converge.sh [OUT]        (default OUT: out/race-converge; about 3 min on 2 cores)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-$root/out/race-converge}
build=${RODSEA_BUILD:-$root/build}
cmake --build "$build" --target rodsea_race >/dev/null
mkdir -p "$out"
: >"$out/runs.txt"
for dt in 2e-5 1e-5 5e-6 2.5e-6 1.25e-6 6.25e-7; do
    for seed in 1 2 3 4; do
        echo "$dt $seed"
    done
done | xargs -n 2 -P "$(nproc)" sh -c \
    '"$0" --dt "$1" --seed "$2" --warmup 0.01 --time 0.1 | sed "s/^/seed=$2 /"' \
    "$build/bench/rodsea_race" >>"$out/runs.txt"
/usr/bin/python3 "$root/bench/race/converge_report.py" "$out/runs.txt" | tee "$out/converge.md"
