#!/usr/bin/env bash
# The GPU backend on a GPU machine, in one command: build, checks, timings.
#
#   bench/gpu/run.sh              on the device machine, from the repository root
#
# The machine needs CUDA, CMake, ninja and a C++ compiler, nothing of Debian: the engine and the
# builder build alone (RODSEA_ENGINE_ONLY). The tests need GoogleTest: fetch its .deb here first
# (bench/gpu/fetch-debs.sh puts it in .gpu-debs/, which git ignores) and carry that folder to the
# device (the device tool's `carry`); without it the tests are skipped, saying so.
#
# Writes to $OUT (the device tool's folder) or bench/gpu/out: device.txt (nvidia-smi),
# tests.txt (the physics tests on the GPU, the device's per-element physics), validate.md (the
# GPU against the CPU on the validation tier's measurements, rodsea_gpu_validate), bench.csv
# (steps/s and stage times, GPU beside all the CPU's cores), bench.log (determinism, the device).
set -uo pipefail
cd "$(dirname "$0")/../.."
out=${OUT:-bench/gpu/out}
mkdir -p "$out"
: >"$out/tests.txt"
build=build-gpu
status=0

prefix=()
if compgen -G ".gpu-debs/*.deb" >/dev/null; then
  mkdir -p .gpu-debs/root
  for f in .gpu-debs/*.deb; do dpkg -x "$f" .gpu-debs/root; done
  prefix=(-DCMAKE_PREFIX_PATH="$PWD/.gpu-debs/root/usr;$PWD/.gpu-debs/root/usr/lib/x86_64-linux-gnu/cmake")
  tests=ON
else
  echo "no .gpu-debs/*.deb (GoogleTest): the tests are skipped, only the benchmark runs" | tee "$out/tests.txt"
  tests=OFF
fi

(nvidia-smi || true) >"$out/device.txt" 2>&1
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRODSEA_ENGINE_ONLY=ON \
  -DRODSEA_CUDA=ON -DRODSEA_BUILD_TESTS="$tests" -DRODSEA_BUILD_BENCHMARKS=ON "${prefix[@]}" \
  >"$out/configure.log" 2>&1 || { cat "$out/configure.log"; exit 1; }
targets=(rodsea_gpu_bench rodsea_gpu_validate)
[ "$tests" = ON ] && targets+=(rodsea_engine_tests rodsea_cuda_tests)
cmake --build "$build" --target "${targets[@]}" 2>&1 | tail -5

if [ "$tests" = ON ]; then
  {
    "$build/tests/rodsea_cuda_tests" || status=1
    # Every physics test with an analytic answer on the GPU backend, and its equivalence with
    # the CPU (the contact list to the bit, the trajectory, ensembles).
    "$build/tests/rodsea_engine_tests" --gtest_filter='Backends/*/gpu' || status=1
  } 2>&1 | tee -a "$out/tests.txt"
fi

"$build/bench/gpu/rodsea_gpu_validate" >"$out/validate.md" 2>&1 || status=1
cat "$out/validate.md"

"$build/bench/gpu/rodsea_gpu_bench" --seconds "${BENCH_SECONDS:-5}" \
  >"$out/bench.csv" 2>"$out/bench.log" || status=1
cat "$out/bench.csv" "$out/bench.log"
exit $status
