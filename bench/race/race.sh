#!/usr/bin/env bash
# The race: rodsea against LAMMPS on the same system (2000 rigid rods of 7 spheres between
# vibrating plates, bench/race/race_system.hpp), each at its own time step, on 1 and on 2
# threads / MPI ranks. Prints simulated seconds per wall second for each and their ratio.
#
#   bench/race/race.sh [OUT]        (default OUT: out/race; needs scripts/install-deps.sh --race)
#
# Each code runs at its largest converged step on this system, judged the same way for both: the
# rods' mean squared velocity in the plane and along z agree with a quarter of the step within 2σ
# (converge.sh, converge_lammps.sh; docs/performance.md).
#
# Environment: RODSEA_BUILD (default build), RACE_WARMUP and RACE_TIME (simulated seconds before
# and during the timing; default 0.01 and 0.05), RODSEA_DT (default 5e-6: converge.sh),
# LAMMPS_DT (default 1.25e-6: 5 µs is the largest step LAMMPS keeps stable, but 5, 2.5 and 1.25 µs
# all fail against a quarter of themselves, so its converged step is smaller still and 1.25 µs
# favours LAMMPS), RACE_THREADS (default "1 2").
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-$root/out/race}
build=${RODSEA_BUILD:-$root/build}
warmup=${RACE_WARMUP:-0.01}
time=${RACE_TIME:-0.05}
rodsea_dt=${RODSEA_DT:-5e-6}
lammps_dt=${LAMMPS_DT:-1.25e-6}
threads_list=${RACE_THREADS:-1 2}

command -v lmp >/dev/null || { echo "race.sh: lmp not found: scripts/install-deps.sh --race" >&2; exit 2; }
command -v mpirun >/dev/null || { echo "race.sh: mpirun not found: scripts/install-deps.sh --race" >&2; exit 2; }
cmake --build "$build" --target rodsea_race >/dev/null
mkdir -p "$out"
race=$build/bench/rodsea_race
"$race" --write-lammps "$out/rods.data"

steps() { /usr/bin/python3 -c "print(round($1 / $2))"; }
nequil=$(steps "$warmup" "$lammps_dt")
nrun=$(steps "$time" "$lammps_dt")

printf '%-8s %-7s %-10s %-12s %-14s\n' code threads dt "steps/s" "sim s/wall s"
declare -A rodsea_rate lammps_rate
for t in $threads_list; do
    line=$("$race" --threads "$t" --dt "$rodsea_dt" --warmup "$warmup" --time "$time")
    echo "$line" >"$out/rodsea-$t.txt"
    rate=$(sed -n 's/.*sim_s_per_wall_s=\([^ ]*\).*/\1/p' <<<"$line")
    sps=$(sed -n 's/.* steps_per_s=\([^ ]*\) .*/\1/p' <<<"$line")
    rodsea_rate[$t]=$rate
    printf '%-8s %-7s %-10s %-12s %-14s\n' rodsea "$t" "$rodsea_dt" "$sps" "$rate"

    log=$out/lammps-$t.log
    OMP_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe -np "$t" lmp -nocite \
        -in "$root/bench/race/in.vibrods" -var data "$out/rods.data" -var dt "$lammps_dt" \
        -var nequil "$nequil" -var nrun "$nrun" -log none >"$log" 2>&1
    # The second "Loop time" is the timed run.
    loop=$(grep '^Loop time' "$log" | tail -1 | awk '{print $4}')
    rate=$(/usr/bin/python3 -c "print(f'{$time / $loop:.6g}')")
    lsps=$(/usr/bin/python3 -c "print(f'{$nrun / $loop:.1f}')")
    lammps_rate[$t]=$rate
    printf '%-8s %-7s %-10s %-12s %-14s\n' lammps "$t" "$lammps_dt" "$lsps" "$rate"
done
echo
for t in $threads_list; do
    ratio=$(/usr/bin/python3 -c "print(f'{${rodsea_rate[$t]} / ${lammps_rate[$t]}:.2f}')")
    echo "threads $t: rodsea / LAMMPS = $ratio (simulated seconds per wall second)"
done | tee "$out/ratio.txt"
