#!/bin/sh
# Copies the projector-layout screenshots that docs/lecture.md shows
# (ProjectorLayout.NothingOverlaps*, tests/window/test_view_layout.cpp) to
# docs/images/lecture/, halved to at most 640 pixels wide.
# Usage: tests/window/update-layout-images.sh [BUILD_DIR]   (default: build)
set -eu
build=${1:-build}
RAYLAB_UPDATE_DOC_IMAGES=1 "$build/bin/window_tests" --gtest_filter='ProjectorLayout.NothingOverlaps*'
