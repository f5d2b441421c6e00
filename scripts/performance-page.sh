#!/usr/bin/env bash
# Regenerates the measured parts of docs/performance.md in one run of
# `raylab bench`: the "where it stands" table (between <!-- standing:begin -->
# and <!-- standing:end -->), the bench's table and comparisons (between
# <!-- bench:begin --> and <!-- bench:end -->, written by `raylab bench
# --markdown`) and the plot docs/images/bench-course.svg. Everything else on
# the page is left as it is.
#
#   scripts/performance-page.sh [--size WxH] [--frames N] [--sweeps LIST] [--doc FILE] [--no-environment]
#
# Then, where the page has <!-- bench-environment:begin --> ... :end --> lines,
# the environment sweep (issue 24) on the two environment scenes at 160x120
# into that section and docs/images/bench-environment.svg (about six minutes
# on 2 shared cores: the exact Monte Carlo references); --no-environment skips it.
#
# Defaults: 640x480, 9 timed frames, the `modes` sweep (both yardsticks and
# raylab's four programs), docs/performance.md; the binary is the one
# ./raylab runs (RAYLAB_BIN=/path/to/raylab overrides it). On 2 cores with llvmpipe the default run takes about two
# minutes. --doc FILE writes another copy of the page (its plot goes to
# images/ beside it); a FILE that does not exist yet gets both sections.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
size=640x480
frames=9
sweeps=modes
doc="$root/docs/performance.md"
environment=1
while [ $# -gt 0 ]; do
    case "$1" in
        --size) size=$2; shift 2 ;;
        --frames) frames=$2; shift 2 ;;
        --sweeps) sweeps=$2; shift 2 ;;
        --doc) doc=$2; shift 2 ;;
        --no-environment) environment=0; shift ;;
        *) echo "performance-page.sh: unknown option $1 (expected --size, --frames, --sweeps, --doc, --no-environment)" >&2; exit 2 ;;
    esac
done
raylab="$root/raylab"  # the wrapper: build/ or build-headless/, or RAYLAB_BIN
doc=$(cd "$(dirname "$doc")" && pwd)/$(basename "$doc")
plot="$(dirname "$doc")/images/bench-course.svg"
mkdir -p "$(dirname "$plot")" "$root/build"
csv="$root/build/bench-course.csv"
log="$root/build/bench-course.log"
fresh=0
if [ ! -e "$doc" ]; then
    fresh=1  # raylab bench --markdown writes it; the table goes on top
elif ! { grep -qx '<!-- standing:begin -->' "$doc" && grep -qx '<!-- standing:end -->' "$doc"; }; then
    echo "performance-page.sh: $doc has no <!-- standing:begin --> ... <!-- standing:end --> lines (not changed)" >&2
    exit 1
fi

cd "$root"
# A student's files beside the course's: the solutions with a comment line
# added at the top of each (folder "commented"), and a complete submission
# written differently, every exercise's first alternative where it has one
# (folder "alternatives"): the bench's rows specialised:commented and
# specialised:alternatives, the same program path as the course's files.
students=$(mktemp -d)
trap 'rm -rf "$students"' EXIT
mkdir -p "$students/commented" "$students/alternatives"
for unit in course/*/; do
    [ -f "$unit/solution.glsl" ] || continue
    name=$(basename "$unit").glsl
    { echo "// my own copy of the solution, with this comment"; cat "$unit/solution.glsl"; } > "$students/commented/$name"
    alternative=""
    [ -d "$unit/alternatives" ] && alternative=$(find "$unit/alternatives" -name '*.glsl' | sort | head -1)
    cp "${alternative:-$students/commented/$name}" "$students/alternatives/$name"
done
scenes="scenes/metal-row.json tests/bench/course-row-ground.json scenes/lecture.json tests/bench/random-30.json"
rel() { python3 -c 'import os,sys; print(os.path.relpath(sys.argv[1]))' "$1"; }
# shellcheck disable=SC2086
"$raylab" bench $scenes --sweeps "$sweeps" --size "$size" --clock cpu --frames "$frames" \
    --also-impl "$students/commented" --also-impl "$students/alternatives" \
    --csv "$(rel "$csv")" --plot "$(rel "$plot")" --markdown "$(rel "$doc")" 2> >(tee "$log" >&2)
wait
context=$(sed -n 's/^bench: \(EGL\|OSMesa\|GLFW\)/\1/p' "$log" | head -1)

python3 - "$csv" "$doc" "$context" "$size" "$fresh" <<'EOF'
import csv, datetime, os, sys
path, doc, context, size, fresh = sys.argv[1:6]
rows = [r for r in csv.DictReader(open(path)) if r["sweep"] == "modes" and r["skipped"] == "0"]
scenes = []
for r in rows:
    if r["scene"] not in scenes:
        scenes.append(r["scene"])
def row(scene, variant):
    return next((r for r in rows if r["scene"] == scene and r["variant"] == variant), None)
columns = [("expert", "expert (strongest yardstick)"), ("textbook", "textbook (straightforward yardstick)"),
           ("specialised", "raylab `render`, the course's files"),
           ("specialised:commented", "the same with a comment added"),
           ("specialised:alternatives", "a submission written differently (the alternatives)"),
           ("generic", "raylab `--generic`")]
load = ""
try:
    load = open("/proc/loadavg").read().split()[0]
except OSError:
    pass
out = ["<!-- written by scripts/performance-page.sh from its bench run: run it again, do not edit -->", ""]
out.append("| scene | " + " | ".join(title for _, title in columns) + " |")
out.append("|---" * (len(columns) + 1) + "|")
for scene in scenes:
    strongest = min((r for r in (row(scene, "expert"), row(scene, "textbook")) if r), key=lambda r: float(r["ms_median"]),
                    default=None)
    cells = []
    for variant, _ in columns:
        r = row(scene, variant)
        if not r:
            cells.append("-")
            continue
        ms = float(r["ms_median"])
        ratio = float(strongest["ms_median"]) / ms if strongest and ms > 0 else 0
        err = "%.3f LSB, %.3f%% off" % (float(r["err_mean_lsb"]), 100 * float(r["off_frac"]))
        speed = "" if r is strongest else ", **%.2fx**" % ratio if variant.startswith("specialised") else ", %.2fx" % ratio
        cells.append("%.2f ms%s; %s" % (ms, speed, err))
    out.append("| %s | %s |" % (scene, " | ".join(cells)))
out.append("")
out.append("%s, %s, process CPU time per frame (`--clock cpu`, median of the bench's frames), mean error "
           "against the CPU reference in 8-bit steps and pixels off by more than 1/255; the ratio is the strongest "
           "yardstick's time over the row's, in the same run (above 1: faster than it). %s%s." % (
               size, context or "context unknown",
               datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
               ", load average " + load + " after the run" if load else ""))
text = open(doc).read()
if fresh == "1":
    text = "# Performance\n\n<!-- standing:begin -->\n<!-- standing:end -->\n\n" + text
begin, end = "<!-- standing:begin -->\n", "<!-- standing:end -->"
a = text.index(begin) + len(begin)
b = text.index(end, a)
tmp = doc + ".tmp"
open(tmp, "w").write(text[:a] + "\n".join(out) + "\n" + text[b:])
os.replace(tmp, doc)
EOF
if [ "$environment" = 1 ] && grep -qx '<!-- bench-environment:begin -->' "$doc" && grep -qx '<!-- bench-environment:end -->' "$doc"; then
    envplot="$(dirname "$doc")/images/bench-environment.svg"
    "$raylab" bench scenes/environments/sky-spheres.json scenes/environments/studio-spheres.json --size 160x120 \
        --sweeps environment --clock cpu --frames "$frames" --plot "$(rel "$envplot")" --markdown "$(rel "$doc")" \
        2> >(tee "$root/build/bench-environment.log" >&2)
    wait
fi
echo "$doc"
