#!/usr/bin/env bash
# Installs the Debian 12 packages raylab needs, only those missing. Run as root
# (or with sudo available). Safe to run again: does nothing when all are present.
#   scripts/setup.sh            build + headless + tests
#   scripts/setup.sh --window   also the window/report test tools (Xvfb, Chromium, ffmpeg)
#   scripts/setup.sh --slurm    also Slurm and MUNGE, for the test of the Slurm recipe (test extra)
#   scripts/setup.sh --web      also emscripten, Chromium and web/'s npm packages (CodeMirror,
#                               markdown-it, KaTeX, playwright-core) for the browser edition (scripts/build-web.sh)
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libglm-dev libegl-dev libgl-dev libgles-dev libosmesa6-dev
  libegl-mesa0 libgl1-mesa-dri mesa-utils-bin
  nlohmann-json3-dev libcli11-dev libstb-dev libgtest-dev
  libglfw3-dev libimgui-dev
  libzip-dev
  python3-jsonschema
  ccache
)
# ccache: the build uses it where it is installed (CMakeLists.txt): a second
# copy of the repository (a student edition's clone, a course with one more
# exercise, the tests that build them) compiles only what differs.
# ffmpeg: `raylab record`'s MP4 and GIF (51 MB of packages without recommends).
window_packages=(xvfb xauth xdotool chromium fonts-dejavu-core imagemagick ffmpeg)
slurm_packages=(slurmctld slurmd slurm-client munge)
web_packages=(emscripten chromium)
web=0

for arg in "$@"; do
  case "$arg" in
    --window) packages+=("${window_packages[@]}") ;;
    --slurm) packages+=("${slurm_packages[@]}") ;;
    --web) packages+=("${web_packages[@]}"); web=1 ;;
    --all) packages+=("${window_packages[@]}" "${slurm_packages[@]}" "${web_packages[@]}"); web=1 ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    *) echo "setup.sh: unknown option '$arg'" >&2; exit 2 ;;
  esac
done

# npm comes with Debian's nodejs as its own package (nodesource's nodejs has it built in).
if [ "$web" -eq 1 ] && ! command -v npm >/dev/null 2>&1; then packages+=(nodejs npm); fi

# web/'s npm packages, exactly as web/package-lock.json pins them (the one
# network step of the browser edition; the page itself never fetches anything).
install_web_modules() {
  [ "$web" -eq 1 ] || return 0
  local here
  here="$(cd "$(dirname "$0")/.." && pwd)"
  # The stamp: the lock file node_modules/ was installed from.
  if ! cmp -s "$here/web/package-lock.json" "$here/web/node_modules/.raylab-installed-lock" 2>/dev/null; then
    echo "setup.sh: npm ci in web/" >&2
    (cd "$here/web" && npm ci --no-audit --no-fund --loglevel=error >&2)
    cp "$here/web/package-lock.json" "$here/web/node_modules/.raylab-installed-lock"
  fi
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  install_web_modules
  exit 0
fi

echo "setup.sh: installing ${missing[*]}" >&2
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq >&2
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
install_web_modules
