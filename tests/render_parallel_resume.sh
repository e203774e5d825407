#!/usr/bin/env bash
# tools/render-parallel --resume after the request or the tiles changed: a new size or new options,
# an edited scene, a tile deleted or truncated. Each time only the tiles that are not of the new request are
# rendered again, each tile's line says why, and the image is the one-machine render's bytes.
#   tests/render_parallel_resume.sh <raytrace> <scene> <empty work directory>
set -euo pipefail
raytrace=$(realpath "$1") work=$3
tool=$(cd "$(dirname "$0")/.." && pwd)/tools/render-parallel
rm -rf "$work" && mkdir -p "$work" && cp "$2" "$work/scene.pov" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
tiles=out.png.tiles

# Renders with the tool into out.png, its messages in log, and checks the bytes against one machine's.
run() {
  local resume=()
  [ "$1" = --resume ] && resume=(--resume) && shift
  "$tool" --raytrace "$raytrace" -n 4 -o out.png "${resume[@]}" "$@" >log 2>&1 || { cat log; fail "render-parallel $*"; }
  "$raytrace" render "$@" --quiet -o one.png
  cmp one.png out.png || { cat log; fail "render-parallel $* differs from the one-machine render"; }
}
# The number of lines of the last run saying `what`.
said() { grep -c -- "$1" log || true; }

run scene.pov 61 43
run --resume scene.pov 61 43
(($(said "is already this tile: kept") == 4)) || { cat log; fail "a current tile was rendered again"; }
echo "render-parallel --resume: 4 current tiles kept"

run --resume scene.pov 80 60 -ss=3
(($(said "is stale (its raytrace.options is '', not '-ss=3')") == 4)) || { cat log; fail "new options not seen"; }
echo "render-parallel --resume: new size and options, 4 stale tiles rendered again"

echo "// edited" >>scene.pov
run --resume scene.pov 80 60 -ss=3
(($(said "is stale (its raytrace.sceneHash is") == 4)) || { cat log; fail "the edited scene not seen"; }
echo "render-parallel --resume: edited scene, 4 stale tiles rendered again"

rm "$tiles/tile-1.exr"
head -c 100 "$tiles/tile-2.exr" >"$tiles/cut" && mv "$tiles/cut" "$tiles/tile-2.exr"
run --resume scene.pov 80 60 -ss=3
(($(said "'tile-1.exr' is missing: rendering it") == 1)) || { cat log; fail "the deleted tile not seen"; }
(($(said "'tile-2.exr' is unreadable (") == 1)) || { cat log; fail "the truncated tile not seen"; }
(($(said "is already this tile: kept") == 2)) || { cat log; fail "the other tiles not kept"; }
echo "render-parallel --resume: a deleted and a truncated tile rendered again, the other two kept"

# A stale tile put back by hand is refused by merge, which checks every tile against the request.
cp "$tiles/tile-3.exr" keep.exr
"$raytrace" render scene.pov 80 60 --quiet --tile 3/4 -o "$tiles/tile-3.exr"
"$raytrace" merge -o late.png "$tiles"/tile-{0,1,2,3}.exr --for "$tiles/scene.pov" 80 60 -ss=3 2>err &&
  fail "merge took a stale tile"
grep -qF "is not a tile of the render asked for: its raytrace.options is '', not '-ss=3'" err || { cat err; fail "merge's message"; }
[ ! -e late.png ] || fail "merge wrote an image from a stale tile"
echo "render-parallel: merge --for refuses a stale tile"

# Mistakes found before any tile is rendered: an absurd tile count, more tiles than rows, an image
# merge cannot write; and a scene whose name starts with '-' is a scene, not an option.
expect_error() {
  local message=$1
  shift
  "$tool" --raytrace "$raytrace" "$@" >log 2>&1 && fail "render-parallel $* succeeded"
  [ "$(cat log)" = "render-parallel: error: $message" ] || { cat log; fail "render-parallel $*: the message"; }
}
expect_error "-n must be a whole number of tiles from 1 to 32768, found '99999999999999999999'" \
  -n 99999999999999999999 -o x.png scene.pov 8 6
expect_error "-n 7 is more tiles than the 6 rows" -n 7 -o x.png scene.pov 8 6
expect_error "the merged image must be .png, .hdr or .exr, found 'x.jpg'" -n 2 -o x.jpg scene.pov 8 6
[ ! -e x.png.tiles ] && [ ! -e x.jpg.tiles ] || fail "a refused render left a tiles folder"
mkdir mine && echo precious >mine/tile-0.exr
expect_error "the tiles' folder 'mine' holds other files, which tiles would replace: name a new or empty one" \
  -n 2 -o x.png --tiles-dir mine scene.pov 8 6
[ "$(cat mine/tile-0.exr)" = precious ] && [ "$(ls -A mine)" = tile-0.exr ] || fail "a folder of other files was written"
cp scene.pov ./-x.pov
"$tool" --raytrace "$raytrace" -n 2 -o dash.png -- -x.pov 8 6 >log 2>&1 || { cat log; fail "a scene named -x.pov"; }
"$raytrace" render ./-x.pov 8 6 --quiet -o one.png
cmp one.png dash.png || fail "the scene named -x.pov differs from the one-machine render"
echo "render-parallel: bad tile counts, image names and a folder of other files refused at once; a scene named -x.pov rendered"

# A POV-Ray scene that includes a file of its own folder: the tiles find it, and an edited include makes
# every tile stale, as an edited scene does.
mkdir inc && cd inc
echo '#declare Tint = rgb <1, 0.2, 0.2>;' >tint.inc
printf '%s\n' '#version 3.7;' '#include "tint.inc"' 'camera { location <0, 0, -4> look_at 0 }' \
  'light_source { <5, 5, -5> rgb 1 }' 'sphere { 0, 1 pigment { Tint } }' >lit.pov
run lit.pov 40 30
echo '#declare Tint = rgb <0.2, 0.2, 1>;' >tint.inc
run --resume lit.pov 40 30
(($(said "is stale (its raytrace.sceneHash is") == 4)) || { cat log; fail "the edited include not seen"; }
echo "render-parallel: a scene's include found by the tiles; an edited include makes every tile stale"
