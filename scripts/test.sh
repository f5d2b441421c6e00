#!/usr/bin/env bash
# The whole test suite: installs what is missing (including Xvfb and
# Chromium for the window and report tests, Slurm and MUNGE for the Slurm
# recipe's test, emscripten and web/'s npm packages for the browser edition's
# tests, label browser, which build the page themselves), builds everything
# (the program and every test), runs every CTest entry, then builds raylab and
# the GL tests without EGL and OSMesa (build-glfw/, the hidden GLFW window under
# Xvfb) and runs their GL suites there, then builds raylab, the unit and the fuzz tests again with
# AddressSanitizer and UndefinedBehaviorSanitizer (build-asan/) and runs those
# two labels there.
# Extra arguments go to ctest, e.g. scripts/test.sh -L unit (and then the
# extra builds are left out: a subset is a quick check, not CI).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --window --slurm --web
cmake --preset default >/dev/null
cmake --build --preset default -j "$(nproc)"
ctest --preset default -j "$(nproc)" "$@"
if [ "$#" -eq 0 ]; then
    # Without EGL and OSMesa, as on macOS and Windows: the hidden GLFW window
    # is the only backend, on a private Xvfb (build-glfw/: raylab and the GL
    # tests only; their GL suites and the check of the ten solutions).
    cmake --preset glfw-only >/dev/null
    cmake --build --preset glfw-only -j "$(nproc)"
    xvfb-run -a ctest --preset glfw-only -j "$(nproc)"
    cmake --preset asan >/dev/null
    cmake --build --preset asan -j "$(nproc)"
    ctest --preset asan -j "$(nproc)"
fi
