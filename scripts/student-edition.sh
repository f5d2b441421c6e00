#!/usr/bin/env bash
# scripts/student-edition.sh [--with-reference] [--] OUT_DIR
#
# Writes what a course gives its students: the repository as of its last
# commit (HEAD; uncommitted changes are not in it) without any answer, as a
# fresh git repository with one commit in OUT_DIR, ready to push
# (docs/instructor.md, "A student edition"). Left out:
#   * the answers: each exercise unit's solution.glsl, mutants/ and
#     alternatives/ (correct solutions written differently), for the units
#     course/manifest.txt lists (a unit it leaves out is framework code, and
#     keeps its solution), and tests/portability/ (solutions with one
#     portability slip each);
#   * the model in every other language: the CPU reference's sources
#     (app/reference/, each unit's reference.cpp), the units' probes.cpp (the
#     expected values and the mistakes' formulas), the expert yardstick's
#     generator (app/bench/expert*.cpp), the textbook yardstick
#     (shaders/yardstick/textbook.frag) and the model variants' GLSL
#     (shaders/model_variants.glsl). In their place the edition gets what the
#     instructor's program records from them (`raylab course --record`): each
#     unit's probes.json (cases, expected values, tolerances, the mistakes'
#     values) and recorded/ (the check scenes' reference pictures, the
#     environment light's split-sum table), so `raylab check` gives the same
#     verdicts and hints. With --with-reference the reference and the probes'
#     sources stay in (the course's choice: students may then read the model
#     in C++); the yardsticks and the model variants are left out either way;
#   * every test that reads them (tests/CMakeLists.txt builds only the unit
#     suite where they are absent) and the instructor's scripts that need them
#     (docs/exercises/images/make-images.sh, scripts/judge-*.py);
# and the edition's README.md says what it is. Before the commit, every
# function body of the exercises' solutions is searched for in the edition's
# text files, app/ included (scripts/answer-leaks.py), and every function of
# its framework GLSL with an exercise function's types is run, renamed,
# against that exercise's probes (scripts/attack-leaks.py); a body found or a
# function that passes stops the export.
#
# The recording runs the instructor's program: $RAYLAB, else ./raylab (the
# build of the working tree: build it from the commit you export).
#
# OUT_DIR must not exist or be an empty folder, outside this repository (or
# in a folder of it that git ignores, such as build/), and may be named anything (-R, -; put -- before a name that is also an
# option): anything else is refused with one line and exit status 1. The
# edition is assembled in a new folder beside OUT_DIR and renamed into place
# at the end; on any failure nothing else is touched, and only that
# half-made folder, this run's own, is removed.
set -euo pipefail

usage="usage: scripts/student-edition.sh [--with-reference] [--] OUT_DIR"
with_reference=0
out=""
while [ "$#" -gt 0 ]; do
    case "$1" in
        -h|--help) sed -n '2,42p' "$0"; exit 0 ;;
        --with-reference) with_reference=1; shift ;;
        --) shift; [ "$#" -eq 1 ] && [ -z "$out" ] || { echo "$usage" >&2; exit 2; }; out="$1"; shift ;;
        *) [ -z "$out" ] || { echo "$usage" >&2; exit 2; }; out="$1"; shift ;;
    esac
done
if [ -z "$out" ]; then echo "$usage" >&2; exit 2; fi
here="$(cd "$(dirname "$0")/.." && pwd)"

fail() { echo "student-edition.sh: $*" >&2; exit 1; }

# OUT_DIR by its absolute path: ./-R and ./- are folders like any other.
case "$out" in /*) abs="$out" ;; *) abs="$PWD/$out" ;; esac
if [ -e "$abs" ] || [ -L "$abs" ]; then
    [ -d "$abs" ] && [ ! -L "$abs" ] || fail "$out: exists and is not a folder; name a new or empty folder"
    [ -z "$(ls -A -- "$abs")" ] || fail "$out: is not empty; name a new or empty folder"
fi
parent="$(dirname -- "$abs")"
[ -d "$parent" ] || fail "$parent: no such folder"
[ -w "$parent" ] || fail "$parent: not writable"
parent_real="$(cd -- "$parent" && pwd -P)"
here_real="$(cd -- "$here" && pwd -P)"
# Inside the repository only in a folder git ignores (build/): elsewhere the
# edition would be a second repository in the working tree.
case "$parent_real/" in
    "$here_real"/*)
        git -C "$here" check-ignore -q -- "$parent_real/$(basename -- "$abs")" ||
            fail "$out: is inside the repository $here_real, in a folder git does not ignore (the edition would be a second repository in its working tree); name a folder outside it" ;;
esac
# git's own words when it refuses (a repository owned by another user:
# "detected dubious ownership"), else the missing commit.
if ! git_error=$(git -C "$here" rev-parse --verify -q HEAD 2>&1 >/dev/null); then
    if [ -n "$git_error" ]; then
        fail "$here: git refuses to read the repository: $(printf '%s\n' "$git_error" | head -1)"
    fi
    fail "$here: no commit to export (git HEAD)"
fi
# The first word of each line: "11-environment optional" is the unit 11-environment.
exercises=$(sed -e 's/#.*//' "$here/course/manifest.txt" | awk 'NF { print $1 }')
raylab="${RAYLAB:-$here/raylab}"
if [ "$with_reference" -eq 0 ]; then
    [ -x "$raylab" ] || fail "$raylab: no instructor's program to record the reference with (build it, or set RAYLAB)"
fi
answers="$(mktemp -d)"
trap 'rm -rf -- "$answers"' EXIT
for id in $exercises; do
    [ -f "$here/course/$id/solution.glsl" ] || fail "$here: course/$id has no solution.glsl: this is already a student edition"
    cp "$here/course/$id/solution.glsl" "$answers/$id.glsl"
done

stage="$(mktemp -d "$parent/.student-edition-XXXXXX")"
[ -n "$stage" ] && [ -d "$stage" ] || fail "$parent: cannot make a folder there"
done_ok=0
cleanup() { rm -rf -- "$answers"; if [ "$done_ok" -eq 0 ]; then rm -rf -- "$stage"; fi; }
trap cleanup EXIT

git -C "$here" archive --format=tar HEAD | tar -x -C "$stage"

# The answers, the model, and what cannot work or would only mislead without them.
leave_out=(
    tests/portability
    tests/exercises tests/grading tests/gpu tests/accuracy tests/metamorphic tests/fuzz
    tests/walkthrough tests/window tests/browser tests/edition
    tests/bench/test_bench_cli.cpp tests/bench/test_specialisation.cpp  # its scenes stay: unit tests read them
    tests/bench/test_environment_sweep.cpp
    tests/unit/test_shipped_stubs.cpp tests/unit/test_loop_guard.cpp
    tests/unit/test_define_table.cpp tests/unit/defines.golden  # its implementations are the solutions and mutants
    tests/unit/test_select_tables.cpp  # the expert yardstick's generator
    shaders/yardstick/textbook.frag  # the model written out the plain way: every answer
    shaders/model_variants.glsl      # the model's lobes and their variants, line for line
    app/bench/expert.cpp app/bench/expert_scene.cpp app/bench/expert_scene.h  # writes the model fused into one shader
    docs/exercises/images/make-images.sh scripts/judge-kinds.py scripts/judge-hard-kinds.py
    scripts/student-edition.sh scripts/answer-leaks.py scripts/attack-leaks.py scripts/glsl_functions.py scripts/edition-readme.py
)
if [ "$with_reference" -eq 0 ]; then
    leave_out+=(
        app/reference/brdf_reference.cpp app/reference/cpu_reference.cpp app/reference/environment_reference.cpp
        app/reference/pixel_breakdown.cpp app/reference/split_sum.cpp app/reference/sphere_form_factor.cpp
        app/checks/probe_toolkit.h  # what the probes.cpp are written with
        tests/unit/test_cpu_reference.cpp tests/unit/test_environment.cpp tests/unit/test_sky_tiles.cpp
        tests/unit/test_probe_cases.cpp
    )
    for unit in "$stage"/course/*/; do
        id="$(basename "$unit")"
        leave_out+=("course/$id/probes.cpp" "course/$id/reference.cpp" "course/$id/reference.h")
    done
    # What the checker needs from the reference, recorded by the instructor's program.
    "$raylab" course --record "$stage" >&2 || fail "$raylab course --record: failed (lines above); nothing was written to $out"
fi
for id in $exercises; do
    leave_out+=("course/$id/solution.glsl" "course/$id/mutants" "course/$id/alternatives")
done
for path in "${leave_out[@]}"; do rm -rf -- "${stage:?}/$path"; done
# raytracer.glsl includes the model variants only for a scene that asks for
# one; in their place, a line that says so to such a scene.
cat >"$stage/shaders/model_variants.glsl" <<'GLSL'
// model_variants.glsl: a student edition leaves the shading-model variants
// out (their lobes are the model's, line for line; docs/instructor.md, "A
// student edition"). Only a scene with a "model" other than the reference
// includes this file.
#error a scene "model" other than the reference is not in this copy: a student edition renders the reference model only
GLSL

# The README says what this copy is (after its first paragraph, the title).
python3 "$here/scripts/edition-readme.py" "$stage/README.md" "$with_reference"

if ! python3 "$here/scripts/answer-leaks.py" "$answers" "$stage" >&2; then
    fail "the files above hold an answer; nothing was written to $out"
fi
# The attack: every framework GLSL function with an exercise function's
# types, renamed to it and run against its probes; one that passes is an answer.
if [ -x "$raylab" ]; then
    attack="$(mktemp -d)"
    if ! python3 "$here/scripts/attack-leaks.py" "$raylab" "$stage" "$attack" >&2; then
        rm -rf -- "$attack"
        fail "the functions above pass an exercise's probes; nothing was written to $out"
    fi
    rm -rf -- "$attack"
fi

source_commit="$(git -C "$here" rev-parse --short HEAD)"
git -C "$stage" init -q
git -C "$stage" add -A
# The instructor's git identity where one is set, else a neutral one.
identity=()
git -C "$here" config user.name >/dev/null || identity+=(-c "user.name=raylab student edition")
git -C "$here" config user.email >/dev/null || identity+=(-c "user.email=student-edition@raylab.invalid")
git -C "$stage" "${identity[@]}" commit -q -m "raylab student edition (from $source_commit)"

if [ -d "$abs" ]; then rmdir -- "$abs"; fi  # empty, checked above
mv -T -- "$stage" "$abs"
done_ok=1
echo "$(cd -- "$abs" && pwd)"
