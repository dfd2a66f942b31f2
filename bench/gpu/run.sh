#!/usr/bin/env bash
# The GPU backend on a GPU machine, in one command: checks and timings.
#
#   bench/gpu/run.sh              on the device machine, from the repository root
#
# Binaries: those of .gpu-prebuilt/ where it holds them (bench/gpu/prebuild.sh makes them on a
# machine with nvcc and GoogleTest; carry the folder with the device tool's `carry`), else built
# here from source: the machine needs CUDA, CMake, ninja and a C++ compiler, nothing of Debian
# (RODSEA_ENGINE_ONLY); the tests then need GoogleTest's .deb, fetched by bench/gpu/fetch-debs.sh
# into .gpu-debs/ (carried likewise), and are skipped without it.
#
# Each part has a time limit, so that one slow part cannot eat the lease:
#   TESTS=0|1 (1), TESTS_LIMIT (180 s)  VALIDATE=0|quick|full (full), VALIDATE_LIMIT (330 s)
#   BENCH_SECONDS (3), BENCH_ONLY (all systems), BENCH_LIMIT (300 s)
#   PROFILE=0|1 (1: per-kernel times of a few steps of the paper's largest rod system, with ncu),
#   PROFILE_LIMIT (120 s)
#
# Writes to $OUT (the device tool's folder) or bench/gpu/out: device.txt (nvidia-smi),
# tests.txt (the physics tests on the GPU, the device's per-element physics), validate.md (the
# GPU against the CPU on the validation tier's measurements), bench.csv (steps/s and stage times,
# GPU beside all the CPU's cores), bench.log (determinism, the device), kernels.csv (ncu).
set -uo pipefail
cd "$(dirname "$0")/../.."
out=${OUT:-bench/gpu/out}
mkdir -p "$out"
status=0
started=$SECONDS
stamp() { echo "--- $1 ($((SECONDS - started)) s)"; }

(nvidia-smi || true) >"$out/device.txt" 2>&1
head -12 "$out/device.txt"

if [ -x .gpu-prebuilt/rodsea_gpu_bench ]; then
  bin=.gpu-prebuilt
  export LD_LIBRARY_PATH="$PWD/.gpu-prebuilt${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  echo "prebuilt binaries of $(tr '\n' ' ' <.gpu-prebuilt/commit)"
  tests_built=$([ -x "$bin/rodsea_engine_tests" ] && echo ON || echo OFF)
else
  build=build-gpu
  prefix=()
  tests_built=OFF
  if compgen -G ".gpu-debs/*.deb" >/dev/null; then
    mkdir -p .gpu-debs/root
    for f in .gpu-debs/*.deb; do dpkg -x "$f" .gpu-debs/root; done
    prefix=(-DCMAKE_PREFIX_PATH="$PWD/.gpu-debs/root/usr;$PWD/.gpu-debs/root/usr/lib/x86_64-linux-gnu/cmake")
    tests_built=ON
  fi
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRODSEA_ENGINE_ONLY=ON \
    -DRODSEA_CUDA=ON -DRODSEA_BUILD_TESTS="$tests_built" -DRODSEA_BUILD_BENCHMARKS=ON "${prefix[@]}" \
    >"$out/configure.log" 2>&1 || { cat "$out/configure.log"; exit 1; }
  targets=(rodsea_gpu_bench rodsea_gpu_validate)
  [ "$tests_built" = ON ] && targets+=(rodsea_engine_tests rodsea_cuda_tests)
  cmake --build "$build" --target "${targets[@]}" 2>&1 | tail -3
  mkdir -p "$build/all"
  for t in bench/gpu/rodsea_gpu_bench bench/gpu/rodsea_gpu_validate tests/rodsea_engine_tests \
    tests/rodsea_cuda_tests; do [ -x "$build/$t" ] && cp "$build/$t" "$build/all/"; done
  bin=$build/all
  stamp built
fi

# In order of what matters most should the lease run out: the device's own operations (seconds),
# the timings, the physics tests, the comparison with the CPU, the per-kernel profile.
tests_wanted=$([ "${TESTS:-1}" = 1 ] && [ "$tests_built" = ON ] && echo yes)
[ "${TESTS:-1}" = 1 ] && [ "$tests_built" != ON ] &&
  echo "no GoogleTest (.gpu-prebuilt or .gpu-debs): the tests are skipped" | tee "$out/tests.txt"
if [ -n "$tests_wanted" ]; then
  stamp "device operations"
  timeout 60 "$bin/rodsea_cuda_tests" >"$out/tests.txt" 2>&1 || status=1
  grep -E "^\[  (PASSED|FAILED) |^\[  FAILED  \]|Failure" "$out/tests.txt" | head -20
fi

stamp bench
only=()
[ -n "${BENCH_ONLY:-}" ] && only=(--only "$BENCH_ONLY")
timeout "${BENCH_LIMIT:-300}" "$bin/rodsea_gpu_bench" --seconds "${BENCH_SECONDS:-3}" "${only[@]}" \
  >"$out/bench.csv" 2>"$out/bench.log" || status=1
cat "$out/bench.csv" "$out/bench.log"

if [ -n "$tests_wanted" ]; then
  stamp tests
  # Every physics test with an analytic answer on the GPU backend, and its equivalence with the
  # CPU (the contact list to the bit, the trajectory, ensembles, runs of steps).
  timeout "${TESTS_LIMIT:-180}" "$bin/rodsea_engine_tests" --gtest_filter='Backends/*/gpu:GpuBackend.*' \
    >>"$out/tests.txt" 2>&1 || status=1
  grep -E "^\[  (PASSED|FAILED) |^\[  FAILED  \]|measured|Failure" "$out/tests.txt" | head -40
fi

# The table prints row by row, should its time limit cut it; but its first rows wait for the lone
# rods on both backends, most of the whole (254 s in all on the H100 machine, no row before 150).
case "${VALIDATE:-full}" in
  0) ;;
  quick | full)
    stamp validate
    flag=$([ "${VALIDATE:-full}" = quick ] && echo --quick)
    timeout "${VALIDATE_LIMIT:-330}" "$bin/rodsea_gpu_validate" $flag >"$out/validate.md" 2>&1 ||
      status=1
    cat "$out/validate.md"
    ;;
esac

if [ "${PROFILE:-1}" = 1 ]; then
  stamp profile
  ncu=$(command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | head -1)
  if [ -n "$ncu" ]; then
    # Ten steps of the largest rod system, every kernel launched singly (no graph replays, which
    # ncu does not count as launches): 2000 steps of settling and the timing's first run of 1024,
    # 6 launches a step, come to ~18 100 launches before the steps timed. Each kernel's duration
    # (bench/gpu/kernel_table.py makes the table).
    RODSEA_GPU_GRAPHS=0 timeout "${PROFILE_LIMIT:-120}" "$ncu" --clock-control none \
      --metrics gpu__time_duration.sum --csv --launch-skip "${PROFILE_SKIP:-20000}" \
      --launch-count "${PROFILE_COUNT:-60}" \
      "$bin/rodsea_gpu_bench" --only paper-rods --skip-cpu --seconds 0.5 --launches-only \
      --settle-steps 2000 \
      >"$out/kernels.csv" 2>"$out/ncu.log" || echo "ncu failed: $(tail -3 "$out/ncu.log")"
    wc -l "$out/kernels.csv"
  else
    echo "no ncu on this machine"
  fi
fi
stamp done
exit $status
