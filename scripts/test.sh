#!/usr/bin/env bash
# The whole test suite: installs what is missing (including Xvfb and
# Chromium for the window and report tests, Slurm and MUNGE for the Slurm
# recipe's test), builds, runs every CTest entry.
# Extra arguments go to ctest, e.g. scripts/test.sh -L unit
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh --window --slurm
ctest --preset default -j "$(nproc)" "$@"
