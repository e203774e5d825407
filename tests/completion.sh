#!/usr/bin/env bash
# The bash completion written by raytrace_manual: commands, a command's options, an option's values and scene
# files, each completed as a user's Tab would.
# usage: tests/completion.sh <raytrace.bash> <work folder>
set -euo pipefail
script=$1 work=$2
rm -rf "$work" && mkdir -p "$work/sub" && cd "$work" && touch a.pov b.cli c.txt t.exr m.obj m.ply m.inc
# shellcheck source=/dev/null
source "$script"
status=0
expect() {  # expect "WORDS" "COMPLETIONS"
  read -r -a COMP_WORDS <<<"$1"
  [[ $1 == *' ' ]] && COMP_WORDS+=("")
  COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMPREPLY=()
  _raytrace || true  # its status is that of its last test, not a failure
  # The order compgen lists files in is the folder's: compare sorted.
  local found
  found=$(printf '%s\n' "${COMPREPLY[@]}" | sort | xargs)
  if [[ $found != "$(printf '%s\n' $2 | sort | xargs)" ]]; then
    echo "'$1' completes to '$found', expected '$2'"
    status=1
  fi
}
expect "raytrace ren" "render"
expect "raytrace help pixelc" "pixelcolor"
expect "raytrace render --thr" "--threads"
expect "raytrace render --thread" "--threads"
expect "raytrace render --dis" "--display"
expect "raytrace sceneinfo --dis" ""
expect "raytrace raycast --ou" "--output"
expect "raytrace render --hierarchy = a" "auto always"
expect "raytrace render " "sub a.pov b.cli"
expect "raytrace render a.pov -o " "sub a.pov b.cli c.txt t.exr m.obj m.ply m.inc"
expect "raytrace merge " "sub t.exr"
expect "raytrace merge --" "--output --threads --help"
expect "raytrace convert " "sub m.obj m.ply m.inc"
expect "raytrace convert --" "--name --help"
exit $status
