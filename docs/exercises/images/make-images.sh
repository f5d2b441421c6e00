#!/usr/bin/env bash
# Renders every picture of the exercise handouts (course/*/handout.md) into
# each unit's images/ folder (course/NN-name/images/NN-*.png), and the
# course's own pictures into docs/exercises/images/. Run it after a change to the model, the scenes or
# the solutions, and look at the pictures before you commit them.
#
#     docs/exercises/images/make-images.sh [RAYLAB]      (default: build/bin/raylab)
#
# Every picture comes from `raylab render`: with solutions/, with solutions/
# where one exercise is the shipped stub (what a student sees before starting
# it), or with solutions/ where one exercise is a mutant from course/*/mutants/
# (what a typical mistake looks like). ImageMagick's `convert` cuts the rows
# of spheres out of their scenes (scripts/setup.sh --window installs it).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
raylab=$(realpath "${1:-$root/build/bin/raylab}")
scenes=$here/scenes
work=$(mktemp -d)
out=$work/out  # sorted into the units' images/ folders at the end
mkdir -p "$out"
trap 'rm -rf "$work"' EXIT

command -v convert >/dev/null || { echo "make-images.sh: needs ImageMagick's convert" >&2; exit 2; }
[ -x "$raylab" ] || { echo "make-images.sh: no raylab at $raylab (build it first)" >&2; exit 2; }

# An implementation folder: solutions/ with one exercise file replaced.
#   with_file NAME FILE ID  -> prints the folder; FILE replaces exercise ID.
with_file() {
    local dir=$work/$1 file=$2 id=$3
    mkdir -p "$dir"
    cp "$root"/solutions/*.glsl "$dir"/
    cp "$file" "$dir/$id.glsl"
    echo "$dir"
}
unit_of() { basename "$(ls -d "$root"/course/"$1"-*/)"; }  # 05 -> 05-ggx
stub() { local id; id=$(unit_of "$1"); with_file "stub-$1" "$root/course/$id/stub.glsl" "$id"; }
mutant() { with_file "mutant-$1" "$root/course/${1%%--*}/mutants/${1#*--}.glsl" "${1%%--*}"; }

render() { "$raylab" render "$@" >/dev/null; }
lecture() { render "$root/scenes/lecture.json" --size 320x240 "$@"; }
# A row of six spheres (rough on the right, smooth on the left), cut out of
# the 640x480 scene: render_row SCENE OUT [render options]
render_row() {
    local scene=$1 png=$2
    shift 2
    render "$root/scenes/$scene.json" -o "$work/row.png" "$@"
    convert "$work/row.png" -crop 640x90+0+195 +repage "$png"
}

# ---- README and shared ------------------------------------------------------------
lecture -o "$out/lecture-final.png"
lecture -o "$out/readme-stubs.png" --impl "$root/exercises"

# ---- 01 camera ----------------------------------------------------------------------
lecture -o "$out/01-stub.png" --impl "$(stub 01)"
lecture -o "$out/01-mistake-aspect.png" --impl "$(mutant 01-camera--aspect-on-y)"
for spp in 1 16; do
    lecture -o "$work/spp$spp.png" --spp $spp
    convert "$work/spp$spp.png" -crop 80x60+40+70 +repage -filter point -resize 400% "$work/spp$spp-zoom.png"
done
convert "$work/spp1-zoom.png" "$work/spp16-zoom.png" +append "$out/01-spp.png"

# ---- 02 intersect -------------------------------------------------------------------
lecture -o "$out/02-stub.png" --impl "$(stub 02)"
lecture -o "$out/02-normals.png" --view normals
lecture -o "$out/02-mistake-textbook.png" --impl "$(mutant 02-intersect--textbook-quadratic)"
render "$scenes/far-sphere.json" -o "$work/far-right.png"
render "$scenes/far-sphere.json" -o "$work/far-textbook.png" --impl "$(mutant 02-intersect--textbook-quadratic)"
convert "$work/far-right.png" "$work/far-textbook.png" +append "$out/02-far-sphere.png"

# ---- 03 Lambert ---------------------------------------------------------------------
lecture -o "$out/03-stub.png" --impl "$(stub 03)"
lecture -o "$out/03-ndotl.png" --view ndotl
lecture -o "$out/03-mistake-missing-pi.png" --impl "$(mutant 03-lambert--missing-pi)"

# ---- 04 shadows ---------------------------------------------------------------------
lecture -o "$out/04-stub.png" --impl "$(stub 04)"
lecture -o "$out/04-shadow-view.png" --view shadow
lecture -o "$out/04-mistake-no-offset.png" --impl "$(mutant 04-shadows--no-offset)"
render "$scenes/lecture-scaled-1e-3.json" --size 320x240 -o "$out/04-relative-tiny.png"
render "$scenes/lecture-scaled-1e-3.json" --size 320x240 -o "$out/04-fixed-tiny.png" \
    --impl "$(mutant 04-shadows--fixed-offset)"
render "$scenes/lecture-scaled-1e3.json" --size 320x240 -o "$out/04-fixed-huge.png" \
    --impl "$(mutant 04-shadows--fixed-offset)"

# ---- 05 GGX D (a stub 05, 06 or 07 gives the same picture: 05-stub.png) -------------
lecture -o "$out/05-stub.png" --impl "$(stub 05)"
lecture -o "$out/05-d-view.png" --view d
render_row metal-row "$out/05-d-view-row.png" --view d
render_row metal-row "$work/metal-final.png"
render_row metal-row "$work/metal-d-nopi.png" --impl "$(mutant 05-ggx--missing-pi)"
convert "$work/metal-final.png" "$work/metal-d-nopi.png" -append "$out/05-mistake-missing-pi-row.png"

# ---- 06 G ---------------------------------------------------------------------------
render_row metal-row "$out/06-g-view-row.png" --view g

# ---- 07 F ---------------------------------------------------------------------------
render "$scenes/fresnel-frontlit.json" -o "$out/07-frontlit-f.png" --view f
render "$scenes/fresnel-backlit.json" -o "$out/07-backlit-f.png" --view f
render "$scenes/fresnel-frontlit.json" -o "$out/07-frontlit.png"
render "$scenes/fresnel-backlit.json" -o "$out/07-backlit.png"
render "$scenes/fresnel-backlit.json" -o "$out/07-stub-backlit.png" --impl "$(stub 07)"
render "$scenes/fresnel-backlit.json" -o "$out/07-mistake-power-on-voh.png" \
    --impl "$(mutant 07-fresnel--power-on-voh)"

# ---- 08 Cook-Torrance ---------------------------------------------------------------
lecture -o "$out/08-stub.png" --impl "$(stub 08)"
lecture -o "$out/08-diffuse.png" --view diffuse
lecture -o "$out/08-specular.png" --view specular
render_row metal-row "$out/08-metal-row.png"
render_row dielectric-row "$out/08-dielectric-row.png"
render_row metal-row "$out/08-mistake-alpha-row.png" --impl "$(mutant 08-cook-torrance--alpha-is-roughness)"
render_row metal-row "$out/08-mistake-metals-diffuse-row.png" --impl "$(mutant 08-cook-torrance--metals-diffuse)"

# ---- 09 reflections -----------------------------------------------------------------
lecture -o "$out/09-stub.png" --impl "$(stub 09)"
for k in 0 1 2; do lecture -o "$out/09-bounce$k.png" --view bounce$k; done
lecture -o "$out/09-mistake-full-strength.png" --impl "$(mutant 09-reflections--full-strength-bounces)"
lecture -o "$out/09-mistake-reflect-swapped.png" --impl "$(mutant 09-reflections--reflect-swapped)"

# ---- 10 display ---------------------------------------------------------------------
lecture -o "$out/10-stub.png" --impl "$(stub 10)"
variant() {  # variant NAME SED-EXPRESSION: the lecture scene with one render setting changed
    sed "$2" "$root/scenes/lecture.json" >"$work/lecture-$1.json"
    render "$work/lecture-$1.json" --size 320x240 -o "$out/10-$1.png"
}
variant exponential 's/"tonemap": "reinhard"/"tonemap": "exponential"/'
variant none 's/"tonemap": "reinhard"/"tonemap": "none"/'
variant gamma-1 's/"gamma": 2.2/"gamma": 1.0/'
variant exposure-4 's/"exposure": 1.0/"exposure": 4.0/'
variant exposure-4-none 's/"exposure": 1.0, "tonemap": "reinhard"/"exposure": 4.0, "tonemap": "none"/'
lecture -o "$out/10-mistake-pow-gamma.png" --impl "$(mutant 10-display--pow-gamma)"
lecture -o "$out/10-mistake-gamma-first.png" --impl "$(mutant 10-display--gamma-before-tonemap)"

# ---- 11 environment (optional) ---------------------------------------------------------
sky() { render "$root/scenes/environments/sky-spheres.json" "$@"; }
sky -o "$out/11-final.png"
sky -o "$out/11-stub.png" --impl "$(stub 11)"
sky -o "$out/11-reference.png" --cpu
sky -o "$out/11-mistake-level-unmapped.png" --impl "$(mutant 11-environment--level-unmapped)"

echo "make-images.sh: $(ls "$out"/*.png | wc -l) pictures in $out"

# Each picture to its place: NN-*.png into its unit's images/, the rest here.
for picture in "$out"/*.png; do
    name=$(basename "$picture")
    case "$name" in
        [0-9][0-9]-*) dest="$root/course/$(unit_of "${name:0:2}")/images" ;;
        *) dest="$here" ;;
    esac
    mkdir -p "$dest"
    mv -f "$picture" "$dest/$name"
done
