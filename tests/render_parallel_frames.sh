#!/usr/bin/env bash
# tools/render-parallel --frames: a 4-frame animation, one job per frame, gives byte for byte the 4 files of the
# animation rendered on one machine in one run; resumed, it keeps every frame, and renders again each one whose
# scene or include changed or whose image was deleted or truncated. Then the same as frames x tiles (-n 3).
#   tests/render_parallel_frames.sh <raytrace> <empty work directory>
set -euo pipefail
raytrace=$(realpath "$1") work=$2
tool=$(cd "$(dirname "$0")/.." && pwd)/tools/render-parallel
rm -rf "$work" && mkdir -p "$work/one" "$work/par" "$work/tiled" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
cat > spin.pov <<'POV'
#version 3.7;
camera { location <0, 2, -5> look_at 0 }
light_source { <3, 5, -4> rgb 1 }
#include "spin.inc"
sphere { <2 * sin(clock * 2 * pi), 0.5, 2 * cos(clock * 2 * pi)>, 0.5 pigment { Orange } }
plane { y, 0 pigment { checker rgb 1 rgb 0.3 } }
POV
echo '#declare Orange = rgb <1, 0.4, 0.2>;' > spin.inc
switches=(+Ispin.pov +W48 +H36 +KFI0 +KFF3)

"$raytrace" "${switches[@]}" +Oone/spin
"$tool" --raytrace "$raytrace" --frames 0-3 -j 2 -- "${switches[@]}" +Opar/spin
for f in 0 1 2 3; do cmp "one/spin$f.png" "par/spin$f.png" || fail "frame $f differs from the one-machine animation's"; done
echo "render-parallel --frames: 4 frames, the one-machine animation's bytes"

"$tool" --raytrace "$raytrace" --frames 0-3 --resume -- "${switches[@]}" +Opar/spin | tee kept.log
[ "$(grep -c 'is already this render: kept' kept.log)" = 4 ] || fail "a current frame was rendered again"
resume() { "$tool" --raytrace "$raytrace" --frames 0-3 --resume "$@" -- "${switches[@]}" +Opar/spin | tee "$log"; }
log=changed.log
echo "// changed" >> spin.pov
resume
[ "$(grep -c "is stale: 'spin.pov' has changed: rendering it" changed.log)" = 4 ] || fail "a frame of the old scene was kept"
log=include.log
echo '#declare Orange = rgb <1, 0.5, 0.2>;' > spin.inc
resume
[ "$(grep -c "is stale: 'spin.inc' has changed: rendering it" include.log)" = 4 ] || fail "a frame of the old include was kept"
"$raytrace" "${switches[@]}" +Oone/spin
for f in 0 1 2 3; do cmp "one/spin$f.png" "par/spin$f.png" || fail "frame $f is not the new include's"; done
log=image.log
rm par/spin1.png
head -c 100 par/spin2.png > cut && mv cut par/spin2.png
resume
grep -q "^render-parallel: frame 1 is stale: 'par/spin1.png' is missing: rendering it$" image.log || fail "frame 1's message"
grep -q "^render-parallel: frame 2 is stale: 'par/spin2.png' has changed: rendering it$" image.log || fail "frame 2's message"
[ "$(grep -c 'kept' image.log)" = 2 ] || fail "frames 0 and 3 were not kept"
for f in 0 1 2 3; do cmp "one/spin$f.png" "par/spin$f.png" || fail "frame $f is not restored"; done
echo "render-parallel --frames: resumed, current frames kept; an edited scene or include, a deleted or truncated image rendered again"

# Frames x tiles: each frame as 3 tiles, merged into the frame's own name; resumed, a frame whose image is gone
# is merged again from its tiles, kept as they are current.
"$tool" --raytrace "$raytrace" --frames 0-3 -n 3 -j 2 --tiles-dir tiled.stamps -- "${switches[@]}" +Otiled/spin
for f in 0 1 2 3; do cmp "one/spin$f.png" "tiled/spin$f.png" || fail "frame $f of 3 tiles differs"; done
[ "$(ls tiled.stamps/frame-2)" = "$(printf 'tile-0.exr\ntile-1.exr\ntile-2.exr')" ] || fail "frame 2's tiles"
rm tiled/spin3.png
"$tool" --raytrace "$raytrace" --frames 0-3 -n 3 --resume --tiles-dir tiled.stamps -- "${switches[@]}" +Otiled/spin \
  > tiled.log 2>&1
grep -q "^render-parallel: frame 3 is stale: 'tiled/spin3.png' is missing: rendering it$" tiled.log || fail "frame 3"
[ "$(grep -c "is already this tile: kept" tiled.log)" = 3 ] || { cat tiled.log; fail "frame 3's tiles were not kept"; }
cmp one/spin3.png tiled/spin3.png || fail "frame 3 merged again differs"
echo "render-parallel --frames -n 3: 4 frames of 3 tiles each, the one-machine animation's bytes; resumed"

expect_error() {
  local message=$1
  shift
  ! "$tool" --raytrace "$raytrace" "$@" > log 2>&1 || fail "render-parallel $*: no error"
  [ "$(cat log)" = "render-parallel: error: $message" ] || { cat log; fail "render-parallel $*: the message"; }
}
expect_error "--frames must be FIRST-LAST, found '3'" --frames 3 -- "${switches[@]}"
expect_error "--frames 3-1: the first frame is after the last" --frames 3-1 -- "${switches[@]}"
expect_error "--frames writes the images the switches name (+O): -o is for one image" --frames 0-3 -o x.png -- "${switches[@]}"
expect_error "-n must be a whole number of tiles from 1 to 32768, found '0'" --frames 0-3 -n 0 -- "${switches[@]}"
expect_error "give the POV-Ray switches after --frames (see tools/render-parallel --help)" --frames 0-3
echo "render-parallel --frames: bad requests, each one message"
