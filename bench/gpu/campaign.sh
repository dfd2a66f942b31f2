#!/usr/bin/env bash
# A campaign's runs stepped on the device machine's GPU as one ensemble, for as long as a lease
# allows, with the whole `rodsea` command that `bench/gpu/prebuild.sh --cli` (or --cli-only) put in
# .gpu-prebuilt/:
#
#   bench/gpu/campaign.sh CAMPAIGN [campaign run options: --scale F --duration T ...]
#   run(command="bench/gpu/campaign.sh ...", carry=[".gpu-prebuilt"])
#
# The runs are stopped after CAMPAIGN_LIMIT seconds (default 240) with SIGINT, which makes every
# run write its checkpoint (exit 124 from timeout, then), and their record comes back in $OUT
# (or bench/gpu/out) in two files (three with ANALYZE), as the device returns eight at most:
# campaign.log (the plan, the progress with the ensemble's steps/s, and `campaign status` at the
# end) and runs.tar.gz
# (every run's config.toml, progress.txt, timeseries.csv and checkpoint.h5). A large box's
# trajectory is far over what comes back and stays on the device, which keeps nothing: the same
# command again, while the machine is still warm, continues every run in place; after that, a
# run goes on from its checkpoint alone (a few MB), in a later lease or on the CPU, with
# `rodsea run --continue RUN/checkpoint.h5 --out DIR` (docs/running.md), its earlier frames lost.
# Where the checkpoints would take runs.tar.gz over 15 MB they stay behind, as the log says.
# The prebuilt rodsea must be this tree's
# (`campaign status` takes the directory's --scale and --duration since 027b470).
#
# ANALYZE="OPTIONS[|OPTIONS...]" then analyses every run on the device, where its trajectory is,
# once per '|'-separated set of `rodsea analyze` options (newlines count as spaces), into
# RUN/analysis-1, -2, ... (all at once, one process each); their tables and analysis.json come
# back in analysis.tar.gz (analysis.h5 too, where under 8 MB), and a failed analysis makes the
# script exit 1 after everything else is done, e.g.
#   ANALYZE="--observables medium_velocity --from 1|--observables medium_velocity --from 1 --param medium_velocity.lag=10"
#
# BACKEND=cpu runs the same on the host's cores (to check the script where no GPU is).
set -uo pipefail
cd "$(dirname "$0")/../.." || exit 2
[ $# -ge 1 ] || { sed -n 2,30p "$0"; exit 2; }
campaign=$1
shift
out=${OUT:-bench/gpu/out}
mkdir -p "$out"
[ -x .gpu-prebuilt/rodsea ] || {
  echo "no .gpu-prebuilt/rodsea: run bench/gpu/prebuild.sh --cli-only here and carry .gpu-prebuilt" >&2
  exit 2
}
export LD_LIBRARY_PATH="$PWD/.gpu-prebuilt/lib:$PWD/.gpu-prebuilt${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
rodsea=.gpu-prebuilt/rodsea
[ -f .gpu-prebuilt/fonts/fonts.conf ] && export FONTCONFIG_FILE="$PWD/.gpu-prebuilt/fonts/fonts.conf"
dir=${CAMPAIGN_DIR:-out/device-campaign}
log=$out/campaign.log
echo "prebuilt rodsea of $(tr '\n' ' ' <.gpu-prebuilt/commit)" | tee "$log"

"$rodsea" campaign plan "$campaign" "$@" --out "$dir" --ensemble --no-measure 2>&1 | tail -5 | tee -a "$log"
# SIGINT is Ctrl-C's: the campaign checkpoints every run and exits with 130. -k: should a
# checkpoint hang, the lease must still come back with what is under $OUT.
timeout -s INT -k 60 "${CAMPAIGN_LIMIT:-240}" "$rodsea" campaign run "$campaign" "$@" --out "$dir" \
  --ensemble --backend "${BACKEND:-gpu}" --threads "${THREADS:-16}" >>"$log" 2>&1
status=$?
# timeout says 124 for a campaign it stopped, which has then checkpointed every run as on Ctrl-C.
echo "campaign run exited with $status (124: stopped at CAMPAIGN_LIMIT, checkpoints written; 0: done)" |
  tee -a "$log"
tail -4 "$log"

"$rodsea" campaign status "$campaign" --out "$dir" 2>&1 | tee -a "$log"

files=()
for run in "$dir"/runs/*/*/; do
  for f in config.toml progress.txt timeseries.csv; do
    [ -f "$run$f" ] && files+=("$run$f")
  done
done
if [ ${#files[@]} -gt 0 ]; then
  checkpoints=()
  for run in "$dir"/runs/*/*/; do
    [ -f "${run}checkpoint.h5" ] && checkpoints+=("${run}checkpoint.h5")
  done
  tar -czf "$out/runs.tar.gz" "${files[@]}" "${checkpoints[@]}"
  # The device returns files of 16 MiB at most.
  if [ "$(stat -c %s "$out/runs.tar.gz")" -gt 15000000 ]; then
    echo "runs.tar.gz without the checkpoints: with them it is over 15 MB" | tee -a "$log"
    tar -czf "$out/runs.tar.gz" "${files[@]}"
  fi
  ls -la "$out/runs.tar.gz"
fi

analyses_failed=0
if [ -n "${ANALYZE:-}" ]; then
  # read stops at a newline: a value written over several lines is one line of options.
  IFS='|' read -r -a analyses <<<"${ANALYZE//$'\n'/ }"
  # All at once: each is one process, and the device has 16 cores.
  intos=()
  for run in "$dir"/runs/*/*/; do
    [ -f "${run}trajectory.h5" ] || continue
    for k in "${!analyses[@]}"; do
      into="${run}analysis-$((k + 1))"
      intos+=("$into")
      echo "rodsea analyze $run ${analyses[$k]} --out $into" | tee -a "$log"
      # Word splitting of the options is wanted: each set is a command line's tail.
      # shellcheck disable=SC2086
      { "$rodsea" analyze "$run" ${analyses[$k]} --out "$into" --quiet >"$into.log" 2>&1 ||
        echo "analysis failed: exit $?" >>"$into.log"; } &
    done
  done
  wait
  tables=()
  for into in "${intos[@]}"; do
    [ -s "$into.log" ] && { echo "$into:"; cat "$into.log"; } | tee -a "$log"
    grep -q "^analysis failed" "$into.log" 2>/dev/null && analyses_failed=1
    for f in "$into"/*; do
      case "$f" in
      *.h5) [ "$(stat -c %s "$f")" -lt 8000000 ] && tables+=("$f") ;;
      *) [ -f "$f" ] && tables+=("$f") ;;
      esac
    done
  done
  [ ${#tables[@]} -gt 0 ] && tar -czf "$out/analysis.tar.gz" "${tables[@]}" &&
    ls -la "$out/analysis.tar.gz"
fi

[ "$analyses_failed" = 0 ] || exit 1
[ "$status" = 0 ] || [ "$status" = 124 ]
