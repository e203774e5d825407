#!/usr/bin/env bash
# The output file through the real executable: a signal during a render ends it with the shell's 130 or 143,
# leaving the previous image and no temporary file; a 251-character name is written; a symbolic link planted
# at the temporary name the program used to use is not followed.
#   tests/output_safety.sh <raytrace> <scene> <empty work directory>
set -euo pipefail
raytrace=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
set -m  # background jobs keep SIGINT: without job control, bash starts them with it ignored

for sig in TERM INT; do
  echo "the previous picture" > output.png
  "$raytrace" render "$scene" 2000 2000 -ss=8 --quiet &
  pid=$!
  sleep 1
  kill -"$sig" "$pid"
  status=0
  wait "$pid" || status=$?
  want=$((128 + $(kill -l "$sig")))
  [ "$status" = "$want" ] || fail "SIG$sig: exit $status, expected $want"
  [ "$(cat output.png)" = "the previous picture" ] || fail "SIG$sig: output.png changed"
  [ "$(ls -A)" = "output.png" ] || fail "SIG$sig: left $(ls -A)"
done
rm output.png

name=$(printf 'n%.0s' $(seq 247)).png
"$raytrace" render "$scene" 8 6 -o "$name"
[ "$(ls -A)" = "$name" ] || fail "long name: found $(ls -A)"
rm "$name"

echo "keep me" > victim.txt
sh -c 'ln -s victim.txt output.png.tmp$$ && exec "$0" render "$1" 8 6' "$raytrace" "$scene"
[ "$(cat victim.txt)" = "keep me" ] || fail "the planted link was followed"
[ "$(ls -A | wc -l)" = 3 ] || fail "planted link: found $(ls -A)"
echo "output safety: ok"
