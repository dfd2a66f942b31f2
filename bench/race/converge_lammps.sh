#!/usr/bin/env bash
# LAMMPS's largest converged time step on the race system, judged the way converge.sh judges
# rodsea's: the rods' mean squared centre-of-mass velocity in the plane and along z
# (bench/race/in.observe) at dt = 10 µs down to 0.3125 µs, 4 starting states × 0.1 s each, and
# each dt against dt/4 (converge_report.py). race.sh's LAMMPS_DT comes from here.
#
#   bench/race/converge_lammps.sh [OUT]   (default OUT: out/race-converge-lammps; ~25 min on 2
#                                          cores; needs scripts/install-deps.sh --race)
# Environment: RODSEA_BUILD (default build), CONVERGE_DTS (default
# "1e-5 5e-6 2.5e-6 1.25e-6 6.25e-7 3.125e-7").
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-$root/out/race-converge-lammps}
build=${RODSEA_BUILD:-$root/build}
dts=${CONVERGE_DTS:-1e-5 5e-6 2.5e-6 1.25e-6 6.25e-7 3.125e-7}
command -v lmp >/dev/null || { echo "converge_lammps.sh: lmp not found: scripts/install-deps.sh --race" >&2; exit 2; }
cmake --build "$build" --target rodsea_race >/dev/null
mkdir -p "$out"
for seed in 1 2 3 4; do
    "$build/bench/rodsea_race" --seed "$seed" --write-lammps "$out/rods-$seed.data" >/dev/null
done

# One LAMMPS run: 0.01 s of warm-up and 0.1 s observed, as converge.sh gives rodsea. Prints the
# run's key=value line; a run that loses atoms or blows up prints nothing and is reported.
one() {
    local dt=$1 seed=$2 log
    log="$out/lammps-$dt-$seed.log"
    local nequil nrun
    nequil=$(/usr/bin/python3 -c "print(round(0.01 / $dt))")
    nrun=$(/usr/bin/python3 -c "print(round(0.1 / $dt))")
    if ! OMP_NUM_THREADS=1 lmp -nocite -in "$root/bench/race/in.vibrods" \
        -var data "$out/rods-$seed.data" -var dt "$dt" -var nequil "$nequil" -var nrun "$nrun" \
        -var observe 1 -var racedir "$root/bench/race" -log none >"$log" 2>&1; then
        echo "converge_lammps.sh: dt=$dt seed=$seed failed, see $log" >&2
        return 0
    fi
    # The last thermo line of the observed run: step time atoms ke zmin zmax <v_xy²> <v_z²>.
    awk -v dt="$dt" -v seed="$seed" '/^Loop time/ {n++} n == 1 && NF == 8 && $1 ~ /^[0-9]+$/ {last = $0}
        END {split(last, f); printf "lammps seed=%s dt=%s in_plane_speed2=%s vertical_speed2=%s\n", seed, dt, f[7], f[8]}' "$log"
}
export -f one
export out root
: >"$out/runs.txt"
for dt in $dts; do
    for seed in 1 2 3 4; do
        echo "$dt $seed"
    done
done | xargs -n 2 -P "$(nproc)" bash -c 'one "$0" "$1"' >>"$out/runs.txt"
/usr/bin/python3 "$root/bench/race/converge_report.py" "$out/runs.txt" | tee "$out/converge.md"
