#!/usr/bin/env bash
# Builds the GPU programs here (where nvcc and GoogleTest are) and puts them, with the OpenMP
# runtime they link, in .gpu-prebuilt/ (git ignores it), so that a device call spends its minutes
# measuring rather than compiling:
#   bench/gpu/prebuild.sh && run(command="bench/gpu/run.sh", carry=[".gpu-prebuilt"])
# The binaries need only glibc, libstdc++ and libgomp (the CUDA runtime is linked statically), so
# a machine with a glibc as new as this one's runs them. Debian 12's: 2.36.
set -euo pipefail
cd "$(dirname "$0")/../.."
cmake -S . -B build-gpu -G Ninja -DCMAKE_BUILD_TYPE=Release -DRODSEA_ENGINE_ONLY=ON \
  -DRODSEA_CUDA=ON -DRODSEA_BUILD_TESTS=ON -DRODSEA_BUILD_BENCHMARKS=ON >/dev/null
cmake --build build-gpu --target rodsea_gpu_bench rodsea_gpu_validate rodsea_engine_tests \
  rodsea_cuda_tests
rm -rf .gpu-prebuilt
mkdir -p .gpu-prebuilt
cp build-gpu/bench/gpu/rodsea_gpu_bench build-gpu/bench/gpu/rodsea_gpu_validate \
  build-gpu/tests/rodsea_engine_tests build-gpu/tests/rodsea_cuda_tests .gpu-prebuilt/
cp "$(ldd build-gpu/bench/gpu/rodsea_gpu_bench | awk '/libgomp/ {print $3}')" .gpu-prebuilt/
git rev-parse HEAD >.gpu-prebuilt/commit
git diff --quiet HEAD || echo "(with uncommitted changes)" >>.gpu-prebuilt/commit
du -sh .gpu-prebuilt
