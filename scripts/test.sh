#!/usr/bin/env bash
# The whole test suite: installs what is missing (including Xvfb and
# Chromium for the window and report tests), builds, runs every CTest entry.
# Extra arguments go to ctest, e.g. scripts/test.sh -L unit
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh --window
ctest --preset default -j "$(nproc)" "$@"
