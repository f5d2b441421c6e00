#!/usr/bin/env bash
# Installs what is missing (scripts/setup.sh), configures and builds the
# program, only the `raylab` target, into build/ (binary: build/bin/raylab; run
# it as ./raylab). scripts/test.sh builds everything else (the tests).
# Extra arguments go to setup.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh "$@"
cmake --preset default >/dev/null
cmake --build --preset default --target raylab -j "$(nproc)"
