#!/usr/bin/env bash
# Downloads what bench/gpu/run.sh needs on a GPU machine that has no Debian packages (GoogleTest,
# for the tests) into .gpu-debs/, which .gitignore names; carry that folder to the device:
#   run(command="bench/gpu/run.sh", carry=[".gpu-debs"])
set -euo pipefail
cd "$(dirname "$0")/../.."
mkdir -p .gpu-debs
(cd .gpu-debs && apt-get download libgtest-dev 2>&1 | grep -v "unsandboxed" || true)
ls -la .gpu-debs
