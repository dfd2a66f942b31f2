#!/usr/bin/env bash
# Installs every build, test and plotting dependency of rodsea from Debian 12's archive.
# Nothing is downloaded from anywhere else. Safe to run again: apt skips what is present.
#
#   scripts/install-deps.sh           # build, tests, plots
#   scripts/install-deps.sh --race    # also LAMMPS and Open MPI, for bench/race/race.sh
set -euo pipefail

packages=(
    g++ cmake make ninja-build          # C++20 compiler and build system
    libgtest-dev libgmock-dev           # GoogleTest, through ctest
    libbenchmark-dev                    # Google Benchmark
    clang-format                        # the committed .clang-format
    libtomlplusplus-dev                 # TOML config files (toml++)
    libhdf5-dev                         # HDF5 trajectories and checkpoints (H5MD layout)
    libfftw3-dev                        # FFTW: C(t) by FFT in the analysis
    nlohmann-json3-dev                  # analysis.json
    libcli11-dev                        # CLI11: every command's options, help and checks
    pkg-config libcairo2-dev libpng-dev fonts-dejavu-core  # `rodsea render`: Cairo, PNG, text
    ffmpeg                              # `rodsea movie`: H.264 MP4 (and ffprobe for its test)
    python3 python3-numpy python3-matplotlib  # `rodsea plot` (scripts/rodsea_plots/)
    python3-h5py python3-scipy          # reading trajectories from Python; cross-checks
    python3-mdanalysis python3-sklearn  # MDAnalysis reads trajectory and export (tested)
    pybind11-dev python3-dev python3-pytest  # `import rodsea` (python/) and its pytest suite
    python3-gsd                         # `rodsea export --format gsd` (scripts/rodsea_gsd.py)
    slurmctld slurmd slurm-client munge # `rodsea campaign submit`'s test: a one-node cluster
)

for arg in "$@"; do
    case $arg in
        --race) packages+=(lammps openmpi-bin) ;;  # the peer code of the speed race
        *) echo "install-deps: unknown option '$arg' (allowed: --race)" >&2; exit 2 ;;
    esac
done

if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#packages[@]} packages already installed"
    exit 0
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
