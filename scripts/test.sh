#!/usr/bin/env bash
# The whole test suite: installs what is missing (including Xvfb and
# Chromium for the window and report tests, Slurm and MUNGE for the Slurm
# recipe's test), builds everything (the program and every test), runs every
# CTest entry.
# Extra arguments go to ctest, e.g. scripts/test.sh -L unit
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --window --slurm
cmake --preset default >/dev/null
cmake --build --preset default -j "$(nproc)"
ctest --preset default -j "$(nproc)" "$@"
