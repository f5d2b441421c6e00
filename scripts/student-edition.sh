#!/usr/bin/env bash
# scripts/student-edition.sh OUT_DIR
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
#   * every test that reads them (tests/CMakeLists.txt builds only the unit
#     suite where they are absent) and the instructor's scripts that need them
#     (docs/exercises/images/make-images.sh, scripts/judge-kinds.py);
# and the edition's README.md says what it is. Before the commit, every
# function body of the exercises' solutions is searched for in the edition's text files
# (scripts/answer-leaks.py); one found stops the export.
#
# OUT_DIR must not exist or be an empty folder: anything else is refused
# with one line and exit status 1. The edition is assembled in a new folder
# beside OUT_DIR and renamed into place at the end; on any failure nothing
# else is touched, and only that half-made folder, this run's own, is
# removed.
set -euo pipefail

usage="usage: scripts/student-edition.sh OUT_DIR"
if [ "$#" -ne 1 ] || [ -z "$1" ]; then echo "$usage" >&2; exit 2; fi
case "$1" in -h|--help) sed -n '2,22p' "$0"; exit 0 ;; esac
out="$1"
here="$(cd "$(dirname "$0")/.." && pwd)"

fail() { echo "student-edition.sh: $*" >&2; exit 1; }

if [ -e "$out" ] || [ -L "$out" ]; then
    [ -d "$out" ] && [ ! -L "$out" ] || fail "$out: exists and is not a folder; name a new or empty folder"
    [ -z "$(ls -A "$out")" ] || fail "$out: is not empty; name a new or empty folder"
fi
parent="$(dirname "$out")"
[ -d "$parent" ] || fail "$parent: no such folder"
[ -w "$parent" ] || fail "$parent: not writable"
git -C "$here" rev-parse --verify -q HEAD >/dev/null || fail "$here: no commit to export (git HEAD)"
# The first word of each line: "11-environment optional" is the unit 11-environment.
exercises=$(sed -e 's/#.*//' "$here/course/manifest.txt" | awk 'NF { print $1 }')
answers="$(mktemp -d)"
trap 'rm -rf -- "$answers"' EXIT
for id in $exercises; do
    [ -f "$here/course/$id/solution.glsl" ] || fail "$here: course/$id has no solution.glsl: this is already a student edition"
    cp "$here/course/$id/solution.glsl" "$answers/$id.glsl"
done

stage="$(mktemp -d "$parent/.student-edition-XXXXXX")"
done_ok=0
cleanup() { rm -rf -- "$answers"; if [ "$done_ok" -eq 0 ]; then rm -rf -- "$stage"; fi; }
trap cleanup EXIT

git -C "$here" archive --format=tar HEAD | tar -x -C "$stage"

# The answers, and what cannot work or would only mislead without them.
leave_out=(
    tests/portability
    tests/exercises tests/grading tests/gpu tests/accuracy tests/metamorphic tests/fuzz
    tests/walkthrough tests/window tests/browser tests/edition
    tests/bench/test_bench_cli.cpp tests/bench/test_specialisation.cpp  # its scenes stay: unit tests read them
    tests/bench/test_environment_sweep.cpp
    tests/unit/test_shipped_stubs.cpp tests/unit/test_loop_guard.cpp
    tests/unit/test_define_table.cpp tests/unit/defines.golden  # its implementations are the solutions and mutants
    shaders/yardstick/textbook.frag  # the model written out the plain way: every answer
    docs/exercises/images/make-images.sh scripts/judge-kinds.py
    scripts/student-edition.sh scripts/answer-leaks.py
)
for id in $exercises; do
    leave_out+=("course/$id/solution.glsl" "course/$id/mutants" "course/$id/alternatives")
done
for path in "${leave_out[@]}"; do rm -rf -- "${stage:?}/$path"; done

# The README says what this copy is (after its first paragraph, the title).
python3 - "$stage/README.md" <<'EOF'
import sys
path = sys.argv[1]
text = open(path, encoding='utf-8').read()
note = """> **Student edition.** This copy of raylab has no answers: no exercise's
> `solution.glsl`, `mutants/` or `alternatives/` in `course/`, no `solutions/`,
> and only the `unit` tests. `./raylab render`, `view`, `record` and `bench` run
> your files in `exercises/` (in `view`, a file missing from an `--impl`
> folder is the shipped stub), and `./raylab check` checks each exercise with your own
> files for the others: its image step waits until every exercise passes its
> probes ([docs/exercises/README.md](docs/exercises/README.md)). Documents
> that mention `solutions/`, the solutions or the mutants describe the instructor's
> repository, where grading runs.

"""
title_end = text.index('\n\n') + 2
open(path, 'w', encoding='utf-8').write(text[:title_end] + note + text[title_end:])
EOF

if ! python3 "$here/scripts/answer-leaks.py" "$answers" "$stage" >&2; then
    fail "the files above hold an answer; nothing was written to $out"
fi

source_commit="$(git -C "$here" rev-parse --short HEAD)"
git -C "$stage" init -q
git -C "$stage" add -A
# The instructor's git identity where one is set, else a neutral one.
identity=()
git -C "$here" config user.name >/dev/null || identity+=(-c "user.name=raylab student edition")
git -C "$here" config user.email >/dev/null || identity+=(-c "user.email=student-edition@raylab.invalid")
git -C "$stage" "${identity[@]}" commit -q -m "raylab student edition (from $source_commit)"

if [ -d "$out" ]; then rmdir -- "$out"; fi  # empty, checked above
mv -T -- "$stage" "$out"
done_ok=1
echo "$(cd "$out" && pwd)"
