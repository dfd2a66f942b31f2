#!/usr/bin/env bash
# Builds the GPU programs here (where nvcc and GoogleTest are) and puts them, with the OpenMP
# runtime they link, in .gpu-prebuilt/ (git ignores it), so that a device call spends its minutes
# measuring rather than compiling:
#   bench/gpu/prebuild.sh && run(command="bench/gpu/run.sh", carry=[".gpu-prebuilt"])
# The binaries need only glibc, libstdc++ and libgomp (the CUDA runtime is linked statically), so
# a machine with a glibc as new as this one's runs them. Debian 12's: 2.36.
#
#   bench/gpu/prebuild.sh --cli     also the whole `rodsea` command (from build/, configured with
#                                   CUDA found) and the Debian libraries it links (HDF5, FFTW,
#                                   Cairo, toml++ and theirs; ~35 MB) in .gpu-prebuilt/lib, and
#                                   the DejaVu fonts its pictures need in .gpu-prebuilt/fonts
#                                   (there: FONTCONFIG_FILE=.gpu-prebuilt/fonts/fonts.conf), for
#                                   runs and campaigns on the device:
#   run(command="LD_LIBRARY_PATH=.gpu-prebuilt/lib .gpu-prebuilt/rodsea campaign run ... --backend gpu",
#       carry=[".gpu-prebuilt"])
#   bench/gpu/prebuild.sh --cli-only  the `rodsea` command and its libraries alone: a lease that only
#                                   runs campaigns (bench/gpu/campaign.sh) needs neither the tests
#                                   nor the benchmarks, whose CUDA build takes a 2-core machine
#                                   tens of minutes (this takes seconds where build/ is current)
set -euo pipefail
cd "$(dirname "$0")/../.."
mode=${1:-}
case "$mode" in "" | --cli | --cli-only) ;; *) sed -n 2,20p "$0" >&2; exit 2 ;; esac
# Everything is built before the old .gpu-prebuilt/ goes: a failed build leaves it as it was.
if [ "$mode" != --cli-only ]; then
  cmake -S . -B build-gpu -G Ninja -DCMAKE_BUILD_TYPE=Release -DRODSEA_ENGINE_ONLY=ON \
    -DRODSEA_CUDA=ON -DRODSEA_BUILD_TESTS=ON -DRODSEA_BUILD_BENCHMARKS=ON >/dev/null
  cmake --build build-gpu --target rodsea_gpu_bench rodsea_gpu_validate rodsea_engine_tests \
    rodsea_cuda_tests
fi
if [ -n "$mode" ]; then
  cmake --build build --target rodsea
  [ -f build/src/librodsea_gpu.a ] ||
    { echo "build/ has no CUDA: configure it where nvcc is found" >&2; exit 1; }
fi
rm -rf .gpu-prebuilt
mkdir -p .gpu-prebuilt
if [ "$mode" != --cli-only ]; then
  cp build-gpu/bench/gpu/rodsea_gpu_bench build-gpu/bench/gpu/rodsea_gpu_validate \
    build-gpu/tests/rodsea_engine_tests build-gpu/tests/rodsea_cuda_tests .gpu-prebuilt/
  cp "$(ldd build-gpu/bench/gpu/rodsea_gpu_bench | awk '/libgomp/ {print $3}')" .gpu-prebuilt/
fi
if [ -n "$mode" ]; then
  cp build/rodsea .gpu-prebuilt/
  mkdir -p .gpu-prebuilt/lib
  # Every library it links but the C and C++ runtimes, which the device's own system provides
  # (newer than these: they keep the old symbols).
  ldd build/rodsea | awk '$3 ~ /^\// {print $3}' |
    grep -vE "/(libc|libm|libstdc\+\+|libgcc_s|ld-linux[^/]*|libpthread|libdl|librt|libresolv)\.so" |
    while read -r lib; do cp -L "$lib" .gpu-prebuilt/lib/; done
  # The device has no fonts and no fontconfig setup: without these a picture made there
  # (`rodsea render`, `movie`) writes its φ and σ as empty boxes.
  # FONTCONFIG_FILE=.gpu-prebuilt/fonts/fonts.conf there (campaign.sh sets it).
  mkdir -p .gpu-prebuilt/fonts
  # fonts-dejavu-core, which scripts/install-deps.sh installs for `rodsea render`.
  cp /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf \
    /usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf .gpu-prebuilt/fonts/
  cat >.gpu-prebuilt/fonts/fonts.conf <<'CONF'
<?xml version="1.0"?>
<!DOCTYPE fontconfig SYSTEM "urn:fontconfig:fonts.dtd">
<fontconfig>
  <dir prefix="relative">.</dir>
  <cachedir>/tmp/rodsea-fontconfig</cachedir>
</fontconfig>
CONF
fi
git rev-parse HEAD >.gpu-prebuilt/commit
git diff --quiet HEAD || echo "(with uncommitted changes)" >>.gpu-prebuilt/commit
du -sh .gpu-prebuilt
