#!/usr/bin/env bash
# tools/render-parallel on this machine: 4 tiles merged give the one-machine render's bytes; a run interrupted
# after two tiles leaves only whole tiles, and resumed renders only the rest and gives the same bytes again.
#   tests/render_parallel.sh <raytrace> <scene> <empty work directory>
set -euo pipefail
raytrace=$(realpath "$1") scene=$(realpath "$2") work=$3
tool=$(cd "$(dirname "$0")/.." && pwd)/tools/render-parallel
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
size=(320 240) flags=(-ss=4)

"$raytrace" render "$scene" "${size[@]}" "${flags[@]}" --quiet -o one.png
"$tool" --raytrace "$raytrace" -n 4 -o four.png "$scene" "${size[@]}" "${flags[@]}"
cmp one.png four.png || fail "4 tiles merged differ from the one-machine render"
echo "render-parallel: 4 tiles give the one-machine bytes"

# One tile at a time; stopped (the whole process group, as a Ctrl-C would) once two tiles are done.
setsid "$tool" --raytrace "$raytrace" -j 1 -n 4 -o resumed.png "$scene" "${size[@]}" "${flags[@]}" &
pid=$!
for _ in $(seq 600); do
  (($(ls resumed.png.tiles/tile-*.exr 2>/dev/null | wc -l) >= 2)) && break
  sleep 0.1
done
kill -TERM -- -"$pid"
wait "$pid" && fail "the interrupted run succeeded"
# setsid made the run a session of its own: a job GNU parallel started at the instant of the signal may still
# finish its tile, so the tiles are counted once nothing of the session is left.
for _ in $(seq 600); do pgrep -s "$pid" >/dev/null || break; sleep 0.1; done
! pgrep -s "$pid" >/dev/null || fail "still running a minute after the interrupted run returned: $(pgrep -a -s "$pid")"
done=$(ls resumed.png.tiles/tile-*.exr | wc -l)
((done >= 2 && done < 4)) || fail "$done tiles done when interrupted"
[ ! -e resumed.png ] || fail "the interrupted run wrote its image"
[ -z "$(ls -A resumed.png.tiles | grep -v -e '^tile-[0-3]\.exr$' -e '^joblog$' -e '\.pov$' -e '^\.render-parallel$')" ] ||
  fail "left behind: $(ls -A resumed.png.tiles)"
echo "render-parallel: interrupted with $done of 4 tiles done"

"$tool" --raytrace "$raytrace" -j 1 -n 4 -o resumed.png --resume "$scene" "${size[@]}" "${flags[@]}" 2>&1 |
  tee resumed.log
cmp one.png resumed.png || fail "the resumed render differs from the one-machine render"
# Each finished tile was kept: only the interrupted and the unstarted ones were rendered again.
kept=$(grep -c "is already this tile: kept" resumed.log || true)
[ "$kept" = "$done" ] || fail "$kept of the $done finished tiles kept"
echo "render-parallel: resumed, the same bytes; finished tiles not rendered again"
