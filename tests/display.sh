#!/usr/bin/env bash
# --display under a virtual X server (Xvfb): what the window shows at the end is the image render writes, byte
# for byte (both as PNG). Without a display the render goes on with one message. Exits 77 (skipped) when
# xvfb-run is missing.
# usage: tests/display.sh <raytrace> <scene> <work folder>
set -euo pipefail
bin=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
command -v xvfb-run >/dev/null || { echo "xvfb-run not installed: skipped"; exit 77; }
status=0

# The window's last picture, read back from the window by SDL (RAYTRACE_DISPLAY_CAPTURE). In the sanitizer
# builds, the X and GL libraries SDL loads keep memory to the end of the process: no leak check of this run.
xvfb-run -a -s "-screen 0 800x600x24" env RAYTRACE_DISPLAY_CAPTURE="$PWD/window.png" \
  ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
  "$bin" render "$scene" 160 120 -ss=2 --display -o image.png 2>err.txt </dev/null
[[ -s err.txt ]] && { echo "unexpected messages:"; cat err.txt; status=1; }
cmp window.png image.png || { echo "the window does not show the image"; status=1; }

# No display: one line, and the same image all the same.
env -u DISPLAY -u WAYLAND_DISPLAY "$bin" render "$scene" 160 120 -ss=2 --display -o alone.png 2>err.txt </dev/null
expected="raytrace: warning: --display: no display to show the picture on (neither DISPLAY nor WAYLAND_DISPLAY is set); rendering on"
[[ $(cat err.txt) == "$expected" ]] || { echo "without a display it says: $(cat err.txt)"; status=1; }
cmp alone.png image.png || { echo "the image differs without a display"; status=1; }
exit $status
