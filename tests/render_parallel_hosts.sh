#!/usr/bin/env bash
# tools/render-parallel on two other hosts over ssh, the hosts being folders on this machine
# (tests/support/ssh_to_folder.sh stands in for ssh): each gets the scene and renders tiles, the tiles come back
# and nothing is left on the hosts, and the merged image is the one-machine render's bytes.
#   tests/render_parallel_hosts.sh <raytrace> <scene> <empty work directory>
set -euo pipefail
raytrace=$(realpath "$1") scene=$(realpath "$2") work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work/hosts" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
export PARALLEL_SSH=$here/support/ssh_to_folder.sh SSH_TO_FOLDER_ROOT=$work/hosts
size=(160 120) flags=(-ss=2)

"$raytrace" render "$scene" "${size[@]}" "${flags[@]}" --quiet -o one.png
"$here/../tools/render-parallel" --raytrace "$raytrace" --sshlogin alpha --sshlogin beta -n 6 -o six.png \
  "$scene" "${size[@]}" "${flags[@]}"
cmp one.png six.png || fail "6 tiles rendered on two hosts differ from the one-machine render"
for host in alpha beta; do
  ran=$(awk -F'\t' -v h="$host" '$2 == h && $7 == 0' six.png.tiles/joblog | wc -l)
  ((ran >= 1)) || fail "no tile ran on $host"
  [ -z "$(ls -A "hosts/$host")" ] || fail "left behind on $host: $(ls -A "hosts/$host")"
  echo "render-parallel: $ran of 6 tiles rendered on $host"
done
echo "render-parallel: two hosts over ssh give the one-machine bytes"

# Resumed over ssh with one tile gone: the hosts get the other tiles, keep them, and render that one alone.
rm six.png.tiles/tile-2.exr
"$here/../tools/render-parallel" --raytrace "$raytrace" --sshlogin alpha --sshlogin beta -n 6 -o six.png --resume \
  "$scene" "${size[@]}" "${flags[@]}" >resumed.log 2>&1 || { cat resumed.log; fail "the resumed render failed"; }
cmp one.png six.png || fail "the resumed render on two hosts differs from the one-machine render"
kept=$(grep -c "is already this tile: kept" resumed.log || true)
[ "$kept" = 5 ] || { cat resumed.log; fail "$kept of 5 tiles kept"; }
grep -q "'tile-2.exr' is missing: rendering it" resumed.log || { cat resumed.log; fail "tile 2 not rendered again"; }
for host in alpha beta; do [ -z "$(ls -A "hosts/$host")" ] || fail "left behind on $host: $(ls -A "hosts/$host")"; done
echo "render-parallel: resumed on two hosts, 5 tiles kept and the missing one rendered again"
