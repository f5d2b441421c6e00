#!/usr/bin/env bash
# The GPU table of docs/performance.md: on a machine with a GPU driver and a
# package made by scripts/gpu-package.sh, the bench's modes (both yardsticks
# and raylab's four programs) on the course's metal row, the course row with
# its ground, the lecture scene and 30 random spheres with 6 lights, at each
# size, then the live view's sweep (frames per second of its programs).
#
#   scripts/gpu-bench.sh PACKAGE OUT_DIR [SIZES [VIEW_SIZES]]
#
# SIZES defaults to "640x480 1920x1080 3840x2160", VIEW_SIZES to
# "1920x1080 3840x2160". Set GPU_BENCH_UNPACK_GL=1 to unpack the package's
# glvnd .debs into / first (a bare machine: the device README's recipe).
# Writes OUT_DIR/gpu.log (everything, in order), one CSV per size and one
# text table per view size: 8 files at most.
set -uo pipefail
pkg=$(cd "${1:?usage: scripts/gpu-bench.sh PACKAGE OUT_DIR [SIZES [VIEW_SIZES]]}" && pwd)
out=${2:?usage: scripts/gpu-bench.sh PACKAGE OUT_DIR [SIZES [VIEW_SIZES]]}
sizes=${3:-640x480 1920x1080 3840x2160}
viewSizes=${4:-1920x1080 3840x2160}
frames=${GPU_BENCH_FRAMES:-15}
mkdir -p "$out"
log="$out/gpu.log"
: > "$log"
say() { echo "$*" | tee -a "$log"; }

if [ "${GPU_BENCH_UNPACK_GL:-0}" = 1 ]; then
    for f in "$pkg"/gl/*.deb; do dpkg -x "$f" /; done
    ldconfig
fi
export LD_LIBRARY_PATH="$pkg/lib:/usr/local/nvidia/lib64${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export RAYLAB_ROOT="$pkg/root"
vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[ -f "$vendor" ] && export __EGL_VENDOR_LIBRARY_FILENAMES="$vendor"
raylab="$pkg/bin/raylab"
scenes="$RAYLAB_ROOT/scenes/metal-row.json $RAYLAB_ROOT/tests/bench/course-row-ground.json $RAYLAB_ROOT/scenes/lecture.json $RAYLAB_ROOT/tests/bench/random-30.json"

say "== $(date -u) $(uname -srm)"
(nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.sm,clocks.max.sm --format=csv 2>&1 || echo "no nvidia-smi") | tee -a "$log"
say "== nproc $(nproc), load $(cat /proc/loadavg 2>/dev/null)"
# What the loader will find (a first look when the GPU context fails).
{ ldd "$raylab" | grep -E "not found|EGL|GLdispatch|OSMesa"; ls /usr/local/nvidia/lib64 2>/dev/null | grep -i egl | head -5; } >>"$log" 2>&1
status=0
for size in $sizes; do
    cmd="raylab bench $scenes --sweeps modes --size $size --warmup 3 --frames $frames --reference-spp 1 --csv $out/bench-$size.csv"
    say "== $cmd"
    start=$(date +%s)
    "$raylab" bench $scenes --sweeps modes --size "$size" --warmup 3 --frames "$frames" --reference-spp 1 \
        --csv "$out/bench-$size.csv" >>"$log" 2>&1
    rc=$?; [ $rc = 0 ] || { status=1; say "== exit status $rc"; }
    say "== $size: $(( $(date +%s) - start )) s"
done
for size in $viewSizes; do
    say "== raylab bench $RAYLAB_ROOT/scenes/lecture.json --sweeps view --size $size --warmup 3 --frames $frames"
    start=$(date +%s)
    "$raylab" bench "$RAYLAB_ROOT/scenes/lecture.json" --sweeps view --size "$size" --warmup 3 --frames "$frames" \
        >"$out/view-$size.txt" 2>>"$log"
    rc=$?; [ $rc = 0 ] || { status=1; say "== exit status $rc"; }
    cat "$out/view-$size.txt" >>"$log"
    say "== view $size: $(( $(date +%s) - start )) s"
done
exit $status
