#!/usr/bin/env bash
# Course files an instructor writes, each with one mistake, configured
# (cmake -P cmake/course.cmake, what every build runs first, on a copy of
# course/): each stops with one line that names the file and the field (and
# the line where there is one), never an internal error later (issue 35).
#   tests/course/course_mistakes_test.sh SOURCE_ROOT CMAKE SCRATCH
set -euo pipefail
src="$1"; cmake="$2"; scratch="$3"
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf -- "$scratch"; mkdir -p "$scratch"

fresh() {  # a copy of the course's files that the configure step reads
    rm -rf -- "$scratch/root"; mkdir -p "$scratch/root/course"
    cp "$src/course/manifest.txt" "$src/course/unit.schema.json" "$scratch/root/course/"
    for unit in "$src"/course/*/; do
        id="$(basename "$unit")"; mkdir -p "$scratch/root/course/$id"
        cp "$unit/unit.json" "$unit/stub.glsl" "$scratch/root/course/$id/"
        [ ! -f "$unit/solution.glsl" ] || cp "$unit/solution.glsl" "$scratch/root/course/$id/"
    done
}
configure() { "$cmake" -DRAYLAB_ROOT_DIR="$scratch/root" -DRAYLAB_GENERATED_DIR="$scratch/gen" -P "$src/cmake/course.cmake" 2>&1; }
json_edit() {  # json_edit UNIT PYTHON-EXPRESSION-ON-d
    python3 - "$scratch/root/course/$1/unit.json" "$2" <<'PY'
import json, sys
path, edit = sys.argv[1], sys.argv[2]
d = json.load(open(path))
exec(edit)
open(path, 'w').write(json.dumps(d, indent=2) + '\n')
PY
}
count=0
# expect NAME WANT...: configure fails, its message is one line, holding every WANT.
expect() {
    local name="$1"; shift
    local out status=0
    out=$(configure) && status=0 || status=$?
    [ "$status" -ne 0 ] || fail "$name: configured without a word"
    # CMake's message: "CMake Error at ...:" then the text, indented.
    local text; text=$(printf '%s\n' "$out" | grep '^  ' | sed 's/^ *//')
    [ "$(printf '%s\n' "$text" | grep -c .)" -eq 1 ] || fail "$name: not one line: $out"
    for want in "$@"; do [[ "$text" == *"$want"* ]] || fail "$name: \"$want\" not in: $text"; done
    [[ "$text" != *"internal error"* && "$text" != *"exception"* ]] || fail "$name: $text"
    echo "ok  $name: $text"
    count=$((count + 1))
}

fresh; out=$(configure) || fail "the course as shipped does not configure: $out"

fresh; mkdir "$scratch/root/course/helpers"; cp "$src/course/05-ggx/unit.json" "$src/course/05-ggx/stub.glsl" "$scratch/root/course/helpers/"
expect "a folder named helpers" "course/helpers: a unit folder is named NN-name"
fresh; mkdir "$scratch/root/course/12 my unit"
expect "a folder with a space" "course/12 my unit: a unit folder is named NN-name"
fresh; mkdir "$scratch/root/course/12-q\"x"
expect "a folder with a quote" "a unit folder is named NN-name" '"12-q\"x"'
fresh; mkdir "$scratch/root/course/12-a;b"
expect "a folder with a semicolon" "course/12-a;b: a unit folder is named NN-name"
fresh; mkdir "$scratch/root/course/12-empty"
expect "a unit without unit.json" "course/12-empty/unit.json is missing"
fresh; rm "$scratch/root/course/07-fresnel/stub.glsl"
expect "a unit without stub.glsl" "course/07-fresnel/stub.glsl is missing"
fresh; json_edit 02-intersect 'd["functions"][0]["geometry"] = "yes"'
expect '"geometry": "yes"' "course/02-intersect/unit.json:" "functions[0].geometry" "must be true or false"
fresh; json_edit 05-ggx 'd["weight"] = 1e10'
expect '"weight": 1e10' "course/05-ggx/unit.json:" "weight" "must be"
fresh; json_edit 05-ggx 'd["weight"] = -3'
expect '"weight": -3' "course/05-ggx/unit.json:" "weight" "must be at least 0"
fresh; json_edit 06-geometry 'd["functions"][1]["neeeds"] = ["G1_SchlickGGX"]'
expect "an unknown field" "course/06-geometry/unit.json:" "functions[1].neeeds: unknown field"
fresh; json_edit 06-geometry 'del d["title"]'
expect "no title" "course/06-geometry/unit.json:" "title: missing"
fresh; json_edit 06-geometry 'del d["functions"][1]["probe"]'
expect "a function without its probe" "course/06-geometry/unit.json:" "functions[1].probe: missing"
fresh; json_edit 06-geometry 'd["functions"][0]["needs"] = ["G2_Nothing"]'
expect "needs a function no unit has" "course/06-geometry/unit.json: functions[0].needs: G2_Nothing"
fresh; json_edit 07-fresnel 'd["functions"][0]["name"] = "D_GGX"; d["functions"][0]["signature"] = "float D_GGX(vec3 n)"'
expect "a function two units define" "functions[0].name: D_GGX is a function of course/"
fresh; json_edit 07-fresnel 'd["functions"][0]["signature"] = "vec3 F_Schlik(vec3 F0, float VoH)"'
expect "a signature of another name" "course/07-fresnel/unit.json: functions[0].signature: does not declare F_Schlick"
fresh; printf '\n}garbage\n' >>"$scratch/root/course/03-lambert/unit.json"
expect "trailing garbage" "course/03-lambert/unit.json:" "text after the JSON value"
fresh; printf '\xef\xbb\xbf' | cat - "$src/course/03-lambert/unit.json" >"$scratch/root/course/03-lambert/unit.json"
expect "a unit.json with a byte-order mark" "course/03-lambert/unit.json:1: starts with a byte-order mark"
fresh; python3 -c "import sys; open(sys.argv[1], 'w').write('{\"title\": \"x\", \"functions\": ' + '[' * 1000 + ']' * 1000 + '}')" "$scratch/root/course/03-lambert/unit.json"
expect "values nested 1000 deep" "course/03-lambert/unit.json:1: values nest more than 64 deep"
fresh; python3 -c "
import sys; p=sys.argv[1]; t=open(p).read(); open(p,'w').write(t.replace('\"title\"', '\"title\": \"x\", \"title\"', 1))" "$scratch/root/course/03-lambert/unit.json"
expect "a repeated key" "course/03-lambert/unit.json: the key \"title\" appears twice"
fresh; mkdir "$scratch/root/course/05-other"; cp "$src/course/05-ggx/stub.glsl" "$scratch/root/course/05-other/"
printf '{"title": "x", "functions": [{"name": "otherFn", "signature": "float otherFn()", "neutral": "return 0.0;", "probe": "r.x = otherFn();"}]}\n' >"$scratch/root/course/05-other/unit.json"
expect "two units with one number" "has the number 05 of course/"
fresh; { printf '\xef\xbb\xbf'; cat "$src/course/manifest.txt"; } >"$scratch/root/course/manifest.txt"
expect "a manifest with a byte-order mark" "course/manifest.txt:1: starts with a byte-order mark"
fresh; printf '01-camera\n02-intersect optionl\n' >"$scratch/root/course/manifest.txt"
expect "a manifest's unknown word" "course/manifest.txt:2:" "\"optionl\"" "only \"optional\" may follow"
fresh; printf '01-camera\n01-camera\n' >"$scratch/root/course/manifest.txt"
expect "a unit listed twice" "course/manifest.txt:2: 01-camera is listed twice"
fresh; printf '01-camera\n12-nothing\n' >"$scratch/root/course/manifest.txt"
expect "a manifest line naming no unit" "course/manifest.txt:2: no unit 12-nothing"
fresh; printf '01-camera\n02-intersect\x01\n' >"$scratch/root/course/manifest.txt"
expect "a control character in the manifest" "course/manifest.txt:2: holds the control or invisible character U+0001"
echo "PASS: $count course mistakes, one line each"
