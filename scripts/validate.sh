#!/usr/bin/env bash
# The validate tier: every measurement behind docs/validation.md and docs/model.md's choice of
# gap and time step, and of the error bars and the drift control, regenerated from scratch. Not part
# of CI: about 75 minutes on 2 cores.
#
#   scripts/validate.sh [OUT [PART...]]     (default OUT: out/validate; PART: all of
#                                            gap dt dt-fine epsilon apolar-rod bead mixture
#                                            replicates medium-drift reproduction)
#
# Parts already in OUT are kept, so a tier can be completed part by part; the report uses
# whatever parts OUT holds.
# Environment: RODSEA_BUILD (build directory, default build), RODSEA_THREADS (default: all
# cores), RODSEA_PYTHON (default /usr/bin/python3, with numpy and matplotlib).
# Writes OUT/<part>/ for each part, OUT/validation.md (the tables) and OUT/*.png (the plots), and
# OUT/epsilon/calibration.csv: a quick 16 × 3 s check of the committed data/calibration.csv,
# which comes from two independent 8 × 10 s sets (data/reproduction/noise-calibration/).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/out/validate}
shift || true
parts=("$@")
all_parts=(gap dt dt-fine epsilon apolar-rod bead mixture replicates medium-drift reproduction)
[[ ${#parts[@]} -gt 0 ]] || parts=("${all_parts[@]}")
for part in "${parts[@]}"; do
    if [[ " ${all_parts[*]} " != *" $part "* ]]; then
        echo "validate.sh: unknown part '$part' (parts: ${all_parts[*]})" >&2
        exit 2
    fi
done
build=${RODSEA_BUILD:-$root/build}
threads=${RODSEA_THREADS:-$(nproc)}
python=${RODSEA_PYTHON:-/usr/bin/python3}
rodsea=$build/rodsea

if [[ ! -f $build/build.ninja && ! -f $build/Makefile ]]; then
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" --target rodsea
mkdir -p "$out"

started=$SECONDS
stamp() { printf '[validate %4d s] %s\n' $((SECONDS - started)) "$*"; }

# Runs the (config, output directory) pairs of a NUL-separated jobs file: independent
# single-threaded runs, $threads at a time.
run_jobs() {
    xargs -0 -n 2 -P "$threads" sh -c '"$0" run "$1" --out "$2" --overwrite --quiet' "$rodsea" \
        <"$1"
    rm -f "$1"
}

# One config of validate/ run for each seed for `duration` s, then analysed (automatic window).
#   run_seeds PART DURATION OBSERVABLES SEED...
run_seeds() {
    local part=$1 duration=$2 observables=$3
    shift 3
    mkdir -p "$out/$part"
    local jobs_file=$out/$part/jobs
    : >"$jobs_file"
    for seed in "$@"; do
        local config=$out/$part/seed$seed.toml
        {
            cat "$root/validate/$part.toml"
            printf '\n[time]\nduration = %s  # s\n\n[run]\nseed = %s\n' "$duration" "$seed"
        } >"$config"
        printf '%s\0%s\0' "$config" "$out/$part/seed$seed" >>"$jobs_file"
    done
    stamp "$part: $# seeds of ${duration} s, $threads at a time"
    run_jobs "$jobs_file"
    for seed in "$@"; do
        "$rodsea" analyze "$out/$part/seed$seed" --observables "$observables" --quiet
    done
}

# The dense mixture at dt, dt/2 and dt/4 of the default (1.25 µs), several seeds each.
run_mixture() {
    mixture_dts=(1.25e-6 6.25e-7 3.125e-7)
    mixture_seeds=(1 2 3 4 5 6 7 8)
    mixture_duration=0.2  # s
    mkdir -p "$out/mixture"
    jobs_file=$out/mixture/jobs
    : >"$jobs_file"
    for dt in "${mixture_dts[@]}"; do
        for seed in "${mixture_seeds[@]}"; do
            name=dt${dt}_seed${seed}
            config=$out/mixture/$name.toml
            {
                cat "$root/validate/mixture.toml"
                printf '\n[time]\ndt = %s  # s\nduration = %s  # s\n\n[run]\nseed = %s\n' \
                    "$dt" "$mixture_duration" "$seed"
            } >"$config"
            printf '%s\0%s\0' "$config" "$out/mixture/$name" >>"$jobs_file"
        done
    done
    stamp "mixture: ${#mixture_dts[@]} time steps × ${#mixture_seeds[@]} seeds, $threads at a time"
    run_jobs "$jobs_file"
}

for part in "${parts[@]}"; do
    if [[ $part == mixture ]]; then
        run_mixture
    elif [[ $part == replicates ]]; then
        # 8 seeds of 20 s (400 frames each): ~25 core-minutes.
        run_seeds replicates 20 order,flocks,drift 1 2 3 4 5 6 7 8
    elif [[ $part == reproduction ]]; then
        # The reproduction's first row (Fig. 1c / 3a) end to end, tiny: its campaign in a 50 mm box (--scale 0.2) for
        # 2 s per point (~10 core-minutes), collected, and its runs' series binned as
        # data/reproduction/ keeps them.
        campaign=$root/data/reproduction/fig1c-phi_p0.05-small.toml
        stamp "reproduction: $campaign at --scale 0.2 for 2 s, $threads at a time"
        "$rodsea" campaign run "$campaign" --scale 0.2 --duration 2 --out "$out/reproduction" \
            --jobs "$threads" --quiet
        "$rodsea" campaign collect "$campaign" --scale 0.2 --duration 2 \
            --out "$out/reproduction" --quiet
        "$python" "$root/scripts/reproduction_series.py" "$out"/reproduction/runs/*/seed1 \
            --out "$out/reproduction/series"
    elif [[ $part == medium-drift ]]; then
        # 2 seeds of 20 s (2000 frames each): ~10 core-minutes.
        run_seeds medium-drift 20 order,drift 1 2
    else
        # Single bodies: one `rodsea calibrate`, each point's copies spread over the threads.
        stamp "calibrate validate/$part.toml"
        "$rodsea" calibrate "$root/validate/$part.toml" --out "$out/$part" --threads "$threads" \
            --quiet
    fi
done

stamp "report"
"$python" "$root/scripts/validation_report.py" "$out"
stamp "done: $out/validation.md"
