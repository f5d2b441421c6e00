#!/usr/bin/env bash
# The student edition checks as the instructor's repository does:
#   tests/edition/same_verdicts.sh SOURCE_ROOT INSTRUCTOR_RAYLAB EDITION_ROOT SCRATCH [all]
# For course files (the units' mutants, alternatives and stubs), `raylab
# check --impl S --file F -e ID`, S a folder of every solution, run by the
# instructor's program (SOURCE_ROOT's build) and by the edition's
# (EDITION_ROOT/raylab, which has no reference: its probes and check
# pictures are the recorded ones), must give the same verdict line and the
# same hint. Without `all`, a representative subset (each unit's first
# mutant and every third alternative: 15 files, about 15 s on 2 cores); with
# it, every mutant, alternative and stub of the course (98 files, 65 s): the
# command docs/instructor.md gives. Exit status 1 with the
# differing files named.
set -euo pipefail
src="$1"; instructor="$2"; edition="$3"; scratch="$4"; which="${5:-subset}"
mkdir -p "$scratch/solutions"
cp "$src"/solutions/*.glsl "$scratch/solutions/"
files=()
k=0
for id in $(sed -e 's/#.*//' "$src/course/manifest.txt" | awk 'NF { print $1 }'); do
    unit="$src/course/$id"
    if [ "$which" = all ]; then
        for f in "$unit"/mutants/*.glsl "$unit"/alternatives/*.glsl "$unit/stub.glsl"; do
            [ -f "$f" ] && files+=("$id:$f")
        done
    else
        first=$(ls "$unit"/mutants/*.glsl 2>/dev/null | head -1)
        [ -n "$first" ] && files+=("$id:$first")
        for f in "$unit"/alternatives/*.glsl; do
            [ -f "$f" ] || continue
            k=$((k + 1))
            [ $((k % 3)) -eq 1 ] && files+=("$id:$f")
        done
    fi
done
# The verdict line without its time, and the hint.
verdict() { grep -E "^[0-9][0-9]-[a-z0-9-]+ |^    hint:" | sed -E 's/ \([0-9]+ s\)$//'; }
differ=0
for entry in "${files[@]}"; do
    id="${entry%%:*}"; file="${entry#*:}"
    a=$("$instructor" check --impl "$scratch/solutions" --file "$file" -e "$id" --output "$scratch/out-a" 2>&1 | verdict || true)
    b=$(cd "$edition" && ./raylab check --impl "$scratch/solutions" --file "$file" -e "$id" --output "$scratch/out-b" 2>&1 | verdict || true)
    if [ "$a" != "$b" ]; then
        echo "DIFFERENT: ${file#$src/}"
        echo "  instructor: $a"
        echo "  edition:    $b"
        differ=1
    fi
done
echo "${#files[@]} course files checked by both"
exit "$differ"
