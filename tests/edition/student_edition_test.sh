#!/usr/bin/env bash
# The student edition as a course makes and uses it (issues 21, 35):
#   tests/edition/student_edition_test.sh SOURCE_ROOT RAYLAB SCRATCH
# scripts/student-edition.sh into SCRATCH, its refusals (a non-empty
# folder, a file, a folder inside the repository) and odd folder names (-R,
# -), its contents (no answer folder; no model in any language: no reference
# source, no probes.cpp, no yardstick, no model variants, but each unit's
# recorded probes.json and recorded/; no solution's function body in any
# text file, app/ included, by scripts/answer-leaks.py, which must also find
# one planted on purpose), then a fresh clone of it built and used as its
# README says: the quick start renders the stubs' picture (byte for byte the
# instructor's `raylab render --impl exercises`, not the solutions'),
# `--cpu` says it needs the reference, `bench` skips both yardsticks saying
# why, `raylab view` runs exercises/ and fills a partial folder with the
# shipped stubs, `raylab check` says NOT STARTED ten times with exit status
# 1, a solution copied in for one exercise passes on its probes with its
# images waiting, 08 alone fails with a hint naming 03 (which it calls), all
# ten copied in pass every check, images included, with exit status 0, and
# course mutants and alternatives get the instructor's verdicts and hints
# (tests/edition/same_verdicts.sh, a subset; RAYLAB_EDITION_ALL=1 for all).
# SCRATCH lies under the build folder, so that the clone's build folder is as
# deep below its source as the instructor's and ccache (CMakeLists.txt) finds
# the instructor's objects; RAYLAB is the instructor's binary.
set -euo pipefail
src="$1"; raylab="$2"; scratch="$3"
fail() { echo "FAIL: $*" >&2; exit 1; }
step() { echo "--- $* ($(date +%s) s)"; }

rm -rf -- "$scratch"  # this test's own folder, from an earlier run
mkdir -p "$scratch"
edition="$scratch/edition"

step "export"
RAYLAB="$raylab" "$src/scripts/student-edition.sh" "$edition" >"$scratch/export.log" 2>&1 || { cat "$scratch/export.log"; fail "export"; }
git -C "$edition" log --oneline | wc -l | grep -qx 1 || fail "the edition has not exactly one commit"
[ -z "$(git -C "$edition" status --porcelain)" ] || fail "the edition has uncommitted files"

step "refusals: a non-empty folder, a file"
if out=$("$src/scripts/student-edition.sh" "$edition" 2>&1); then fail "a non-empty OUT_DIR was accepted"; fi
[ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] && [[ "$out" == *"is not empty"* ]] || fail "refusal: $out"
touch "$scratch/a-file"
if out=$("$src/scripts/student-edition.sh" "$scratch/a-file" 2>&1); then fail "a file as OUT_DIR was accepted"; fi
[[ "$out" == *"not a folder"* ]] && [ -f "$scratch/a-file" ] || fail "refusal: $out"
[ -z "$(ls -A "$scratch" | grep '^\.student-edition-' || true)" ] || fail "a half-made folder was left beside OUT_DIR"
if out=$(RAYLAB="$raylab" "$src/scripts/student-edition.sh" "$src/docs/edition-inside" 2>&1); then fail "an OUT_DIR inside the repository was accepted"; fi
[ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] && [[ "$out" == *"is inside the repository"* ]] || fail "refusal: $out"
[ ! -e "$src/docs/edition-inside" ] || fail "a folder was made inside the repository"

step "odd folder names: -R (an empty folder), -"
mkdir -p "$scratch/odd/-R"
(cd "$scratch/odd" && RAYLAB="$raylab" "$src/scripts/student-edition.sh" -R >/dev/null 2>"$scratch/odd.log") || { cat "$scratch/odd.log"; fail "OUT_DIR -R"; }
[ -f "$scratch/odd/-R/README.md" ] || fail "the edition is not in -R"
(cd "$scratch/odd" && RAYLAB="$raylab" "$src/scripts/student-edition.sh" -- - >/dev/null 2>"$scratch/odd.log") || { cat "$scratch/odd.log"; fail "OUT_DIR -"; }
[ -f "$scratch/odd/-/README.md" ] || fail "the edition is not in -"
rm -rf -- "$scratch/odd"

step "no answers"
for answers in solutions tests/portability; do
    [ ! -e "$edition/$answers" ] || fail "$answers/ is in the edition"
done
for id in $(sed -e 's/#.*//' "$src/course/manifest.txt" | awk 'NF { print $1 }'); do  # each line's first word ("11-environment optional")
    for answers in solution.glsl mutants alternatives; do
        [ ! -e "$edition/course/$id/$answers" ] || fail "course/$id/$answers is in the edition"
    done
    [ -f "$edition/course/$id/stub.glsl" ] && [ -f "$edition/course/$id/handout.md" ] || fail "course/$id lost its stub or handout"
done
# No model in any language: the reference's sources, the probes' sources
# (each unit's expected values and mistakes' formulas), the yardsticks' and
# the model variants' code; in their place the recorded data.
for model in app/reference/brdf_reference.cpp app/reference/cpu_reference.cpp app/reference/environment_reference.cpp \
             app/reference/pixel_breakdown.cpp app/reference/split_sum.cpp app/reference/sphere_form_factor.cpp \
             app/checks/probe_toolkit.h \
             app/bench/expert.cpp app/bench/expert_scene.cpp shaders/yardstick/textbook.frag; do
    [ ! -e "$edition/$model" ] || fail "$model is in the edition"
done
if ls "$edition"/course/*/probes.cpp "$edition"/course/*/reference.cpp 2>/dev/null | grep .; then
    fail "a unit's probes.cpp or reference.cpp is in the edition (above)"
fi
grep -q "^#error" "$edition/shaders/model_variants.glsl" || fail "shaders/model_variants.glsl is not the edition's one #error line"
for id in $(sed -e 's/#.*//' "$src/course/manifest.txt" | awk 'NF { print $1 }'); do
    [ -s "$edition/course/$id/probes.json" ] || fail "course/$id/probes.json (the recorded probes) is missing"
done
[ "$(ls "$edition"/recorded/check-scenes/*.pfm | wc -l)" -eq 5 ] || fail "not 5 recorded check scenes"
# (the test files; a comment of tests/CMakeLists.txt names the folders, and
# tests/support/ keeps the GL helper of the suites left out, which no unit test calls)
if grep -rlE --include='test_*' --exclude-dir=support "solutionsDir\(\)|tests/(mutants|alternatives|portability)/" "$edition/tests"; then
    fail "a test of the edition reads an answer folder (files above)"
fi
python3 "$src/scripts/answer-leaks.py" "$src/solutions" "$edition" || fail "an answer is in the edition (lines above)"
# The search can fail: one solution's D_GGX quoted in a copy of its handout.
planted="$scratch/planted"
mkdir -p "$planted"
{ cat "$src/course/05-ggx/handout.md"; printf '\n```glsl\n'; cat "$src/solutions/05-ggx.glsl"; printf '```\n'; } \
    >"$planted/05-ggx.md"
if python3 "$src/scripts/answer-leaks.py" "$src/solutions" "$planted" >"$scratch/planted.log"; then
    fail "answer-leaks.py did not find a solution pasted into a handout"
fi
grep -q "05-ggx.md: the body of D_GGX" "$scratch/planted.log" || fail "planted: $(cat "$scratch/planted.log")"
# The attack finds no framework function that passes an exercise's probes in
# the edition, and finds one planted on purpose: 05's D_GGX renamed, in a
# framework file of its own.
python3 "$src/scripts/attack-leaks.py" "$raylab" "$edition" "$scratch/attack" || fail "a framework function passes an exercise's probes"
mkdir -p "$planted/shaders"
cp -r "$edition/course" "$planted/"
sed 's/D_GGX/myDistribution/' "$src/course/05-ggx/solution.glsl" >"$planted/shaders/extra.glsl"
if python3 "$src/scripts/attack-leaks.py" "$raylab" "$planted" "$scratch/attack-planted" >"$scratch/attack.log"; then
    fail "attack-leaks.py did not find a renamed solution in the framework"
fi
grep -q "shaders/extra.glsl: myDistribution passes all" "$scratch/attack.log" || fail "attack: $(cat "$scratch/attack.log")"
rm "$planted/shaders/extra.glsl"
{ printf '# notes\n\n```glsl\n'; sed 's/D_GGX/ggxLobe/' "$src/course/05-ggx/solution.glsl"; printf '```\n'; } >"$planted/notes.md"
if python3 "$src/scripts/attack-leaks.py" "$raylab" "$planted" "$scratch/attack-planted-md" >"$scratch/attack-md.log"; then
    fail "attack-leaks.py did not find a renamed solution in a document's GLSL block"
fi
grep -q "notes.md: ggxLobe passes all" "$scratch/attack-md.log" || fail "attack: $(cat "$scratch/attack-md.log")"

step "a fresh clone, built as its README says (scripts/build.sh)"
clone="$scratch/clone"
git clone -q "$edition" "$clone"
# The clone's build goes through ccache as every build does where it is
# installed (CMakeLists.txt, RAYLAB_CCACHE): it hits the instructor's objects.
start=$(date +%s)
(cd "$clone" && scripts/build.sh) >"$scratch/build.log" 2>&1 || { tail -30 "$scratch/build.log"; fail "scripts/build.sh"; }
echo "build of the clone: $(( $(date +%s) - start )) s"

step "quick start: ./raylab render -o raylab.png shows the stubs"
(cd "$clone" && ./raylab render -o raylab.png) || fail "./raylab render -o raylab.png"
"$raylab" render --impl "$src/exercises" -o "$scratch/stubs.png" >/dev/null
"$raylab" render -o "$scratch/solutions.png" >/dev/null
cmp -s "$clone/raylab.png" "$scratch/stubs.png" || fail "the edition's picture is not the stubs' picture"
! cmp -s "$clone/raylab.png" "$scratch/solutions.png" || fail "the edition renders the solutions' picture"

step "no reference: --cpu says so in one line, exit status 1"
status=0; out=$(cd "$clone" && ./raylab render --cpu -o cpu.png 2>&1) || status=$?
[ "$status" -eq 1 ] && [ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] && [[ "$out" == *"not in this copy"* ]] || fail "--cpu: $out"
# A scene with a model variant: the edition renders the reference model only, and says so.
printf '{"spheres": [{"center": [0, 0, -3], "radius": 1}], "lights": [{"position": [2, 2, 0], "intensity": 10}], "model": {"distribution": "beckmann"}}\n' >"$scratch/variant.json"
status=0; out=$(cd "$clone" && ./raylab render "$scratch/variant.json" -o variant.png 2>&1) || status=$?
[ "$status" -eq 1 ] && [[ "$out" == *"is not in this copy"* ]] && [[ "$out" != *"the cause is in an exercise"* ]] ||
    fail "a model variant: $out"

step "no yardstick in the edition: ./raylab bench says why its textbook and expert rows are skipped"
[ ! -e "$clone/shaders/yardstick/textbook.frag" ] || fail "the edition ships shaders/yardstick/textbook.frag"
(cd "$clone" && ./raylab bench --sweeps modes --size 16x12 --warmup 0 --frames 1 --reference-spp 1) >"$scratch/bench.txt" 2>&1 ||
    { cat "$scratch/bench.txt"; fail "bench"; }
grep -q "not in this copy: a student edition leaves shaders/yardstick/textbook.frag out" "$scratch/bench.txt" ||
    { cat "$scratch/bench.txt"; fail "bench does not say why the textbook row is skipped"; }
grep -q "not in this copy: a student edition leaves the expert yardstick out" "$scratch/bench.txt" ||
    { cat "$scratch/bench.txt"; fail "bench does not say why the expert row is skipped"; }
! grep -q "not found" "$scratch/bench.txt" || { cat "$scratch/bench.txt"; fail "bench looks for a file the edition lacks"; }

step "./raylab view (Xvfb): exercises/ by default, the shipped stubs beside a partial folder"
mkdir -p "$scratch/partial"
cp "$src/solutions/01-camera.glsl" "$src/solutions/02-intersect.glsl" "$scratch/partial/"
(cd "$clone" && xvfb-run -a ./raylab view --frames 2 --size 64x48) >"$scratch/view.txt" 2>&1 || { cat "$scratch/view.txt"; fail "view"; }
grep -q "(exercises)" "$scratch/view.txt" || fail "view: $(cat "$scratch/view.txt")"
(cd "$clone" && xvfb-run -a ./raylab view --impl "$scratch/partial" --frames 2 --size 64x48) >"$scratch/view-partial.txt" 2>&1 ||
    { cat "$scratch/view-partial.txt"; fail "view --impl partial"; }
grep -q "(+ shipped stubs)" "$scratch/view-partial.txt" || fail "view --impl partial: $(cat "$scratch/view-partial.txt")"

step "./raylab check: NOT STARTED ten times, exit status 1"
status=0; (cd "$clone" && ./raylab check) >"$scratch/check-stubs.txt" 2>&1 || status=$?
cat "$scratch/check-stubs.txt"
[ "$status" -eq 1 ] || fail "exit status $status, expected 1"
# A verdict line for every unit of the manifest: ten, and the optional ones
# (11-environment, 12-sky-shadows: counted apart in the summary).
units="$(sed -e 's/#.*//' "$src/course/manifest.txt" | awk 'NF' | wc -l)"
[ "$(grep -cE "^[0-9][0-9]-[a-z0-9-]+ +NOT STARTED" "$scratch/check-stubs.txt")" -eq "$units" ] || fail "not $units units NOT STARTED"
grep -q "^0 of 10 exercises pass; optional 11-environment: NOT STARTED" "$scratch/check-stubs.txt" ||
    fail "no '0 of 10 exercises pass; optional 11-environment: NOT STARTED'"

step "one exercise done: PASS on its probes, images waiting"
cp "$src/solutions/03-lambert.glsl" "$clone/exercises/"
status=0; (cd "$clone" && ./raylab check) >"$scratch/check-03.txt" 2>&1 || status=$?
cat "$scratch/check-03.txt"
[ "$status" -eq 1 ] || fail "exit status $status, expected 1"
grep -qE "^03-lambert +PASS .*images waiting for exercise 01-camera" "$scratch/check-03.txt" || fail "03-lambert"

step "08 alone: FAIL, and the hint names the exercise it calls that is not done"
git -C "$clone" checkout -q -- exercises
cp "$src/solutions/08-cook-torrance.glsl" "$clone/exercises/"
status=0; (cd "$clone" && ./raylab check -e 8) >"$scratch/check-08.txt" 2>&1 || status=$?
head -3 "$scratch/check-08.txt"
[ "$status" -eq 1 ] || fail "exit status $status, expected 1"
grep -qE "^08-cook-torrance +FAIL" "$scratch/check-08.txt" || fail "08-cook-torrance is not FAIL"
grep -q "hint: it calls exercise 03-lambert, whose probes do not pass yet" "$scratch/check-08.txt" || fail "08's hint"

step "hints follow the call graph: 03 (calls nothing) names no other exercise, 09 names 02 (through the framework)"
git -C "$clone" checkout -q -- exercises
cp "$src/course/03-lambert/mutants/missing-pi.glsl" "$clone/exercises/03-lambert.glsl"
status=0; (cd "$clone" && ./raylab check -e 3) >"$scratch/check-03-mutant.txt" 2>&1 || status=$?
head -2 "$scratch/check-03-mutant.txt"
grep -qE "^03-lambert +FAIL" "$scratch/check-03-mutant.txt" || fail "03's mutant is not FAIL"
! grep -q "make that one pass first" "$scratch/check-03-mutant.txt" || fail "03, which calls no exercise, was sent to another"
git -C "$clone" checkout -q -- exercises
cp "$src/solutions/09-reflections.glsl" "$clone/exercises/"
status=0; (cd "$clone" && ./raylab check -e 9) >"$scratch/check-09.txt" 2>&1 || status=$?
grep -q "hint: it calls exercise 02-intersect (through the framework), whose probes do not pass yet" "$scratch/check-09.txt" ||
    { head -3 "$scratch/check-09.txt"; fail "09's hint"; }
git -C "$clone" checkout -q -- exercises

step "all ten done: every check passes, images included, exit status 0"
cp "$src"/solutions/*.glsl "$clone/exercises/"
status=0; (cd "$clone" && ./raylab check) >"$scratch/check-all.txt" 2>&1 || status=$?
cat "$scratch/check-all.txt"
[ "$status" -eq 0 ] || fail "exit status $status, expected 0"
[ "$(grep -cE "PASS +[0-9]+ probe cases, [1-9][0-9]* images" "$scratch/check-all.txt")" -eq "$units" ] || fail "not $units units PASS with images"
grep -q "^10 of 10 exercises pass; optional 11-environment: PASS" "$scratch/check-all.txt" || fail "no '10 of 10 exercises pass; optional ...: PASS'"
step "course mutants and alternatives: the instructor's verdicts and hints"
bash "$src/tests/edition/same_verdicts.sh" "$src" "$raylab" "$clone" "$scratch/verdicts" \
    "$([ "${RAYLAB_EDITION_ALL:-0}" = 1 ] && echo all || echo subset)" || fail "the edition's verdicts differ (above)"
echo "PASS"
