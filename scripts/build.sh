#!/usr/bin/env bash
# Installs what is missing (scripts/setup.sh), configures and builds raylab
# into build/ (binary: build/bin/raylab). Extra arguments go to setup.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh "$@"
cmake --preset default >/dev/null
cmake --build --preset default -j "$(nproc)"
