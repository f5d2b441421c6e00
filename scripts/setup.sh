#!/usr/bin/env bash
# Installs the Debian 12 packages raylab needs, only those missing. Run as root
# (or with sudo available). Safe to run again: does nothing when all are present.
#   scripts/setup.sh            build + headless + tests
#   scripts/setup.sh --window   also the window/report test tools (Xvfb, Chromium, ffmpeg)
#   scripts/setup.sh --slurm    also Slurm and MUNGE, for the test of the Slurm recipe (test extra)
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libglm-dev libegl-dev libgl-dev libgles-dev libosmesa6-dev
  libegl-mesa0 libgl1-mesa-dri mesa-utils-bin
  nlohmann-json3-dev libcli11-dev libstb-dev libgtest-dev
  libglfw3-dev libimgui-dev
  libzip-dev
  python3-jsonschema
)
# ffmpeg: `raylab record`'s MP4 and GIF (51 MB of packages without recommends).
window_packages=(xvfb xauth xdotool chromium fonts-dejavu-core imagemagick ffmpeg)
slurm_packages=(slurmctld slurmd slurm-client munge)

for arg in "$@"; do
  case "$arg" in
    --window) packages+=("${window_packages[@]}") ;;
    --slurm) packages+=("${slurm_packages[@]}") ;;
    --all) packages+=("${window_packages[@]}" "${slurm_packages[@]}") ;;
    -h|--help) sed -n '2,7p' "$0"; exit 0 ;;
    *) echo "setup.sh: unknown option '$arg'" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup.sh: installing ${missing[*]}" >&2
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq >&2
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
