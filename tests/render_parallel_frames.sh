#!/usr/bin/env bash
# tools/render-parallel --frames: a 4-frame animation, one job per frame, gives byte for byte the 4 files of the
# animation rendered on one machine in one run; resumed, it keeps every frame, and after the scene changes it renders them all again.
#   tests/render_parallel_frames.sh <raytrace> <empty work directory>
set -euo pipefail
raytrace=$(realpath "$1") work=$2
tool=$(cd "$(dirname "$0")/.." && pwd)/tools/render-parallel
rm -rf "$work" && mkdir -p "$work/one" "$work/par" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
cat > spin.pov <<'POV'
#version 3.7;
camera { location <0, 2, -5> look_at 0 }
light_source { <3, 5, -4> rgb 1 }
sphere { <2 * sin(clock * 2 * pi), 0.5, 2 * cos(clock * 2 * pi)>, 0.5 pigment { rgb <1, 0.4, 0.2> } }
plane { y, 0 pigment { checker rgb 1 rgb 0.3 } }
POV
switches=(+Ispin.pov +W48 +H36 +KFI0 +KFF3)

"$raytrace" "${switches[@]}" +Oone/spin
"$tool" --raytrace "$raytrace" --frames 0-3 -j 2 -- "${switches[@]}" +Opar/spin
for f in 0 1 2 3; do cmp "one/spin$f.png" "par/spin$f.png" || fail "frame $f differs from the one-machine animation's"; done
echo "render-parallel --frames: 4 frames, the one-machine animation's bytes"

"$tool" --raytrace "$raytrace" --frames 0-3 --resume -- "${switches[@]}" +Opar/spin | tee kept.log
[ "$(grep -c 'is already this render: kept' kept.log)" = 4 ] || fail "a current frame was rendered again"
echo "// changed" >> spin.pov
"$tool" --raytrace "$raytrace" --frames 0-3 --resume -- "${switches[@]}" +Opar/spin | tee changed.log
! grep -q 'kept' changed.log || fail "a frame of the old scene was kept"
echo "render-parallel --frames: resumed, current frames kept, changed ones rendered again"
