#!/bin/sh
# Runs chosen runs of a campaign directory one after another, in the order given, exactly as
# `rodsea campaign run` would (same config, same directory, resumed where a checkpoint is), so
# that a later `rodsea campaign run`/`collect` counts them as done. For running the runs that
# decide something first, at low priority beside development work.
#
#   run-queue.sh RODSEA CAMPAIGN_DIR POINT/SEED [POINT/SEED ...]
#   (POINT/SEED as in CAMPAIGN_DIR/runs/, e.g. "medium.mass=0.2,...,mode=add/seed1")
set -u
rodsea=$1; dir=$2; shift 2
for run in "$@"; do
    out="$dir/runs/$run"
    if grep -q '^state *= *"\?done' "$out/progress.txt" 2>/dev/null; then
        echo "done already: $run"; continue
    fi
    if [ -f "$out/checkpoint.h5" ]; then
        nice -n 19 "$rodsea" run --resume "$out" --threads 1 >>"$out.log" 2>&1
    else
        nice -n 19 "$rodsea" run "$out.toml" --out "$out" --overwrite --threads 1 >>"$out.log" 2>&1
    fi
    echo "$run: exit $?"
done
