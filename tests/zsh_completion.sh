#!/usr/bin/env bash
# The zsh completion written by raytrace_manual: valid zsh, and for each command the specifications of the
# options it takes (zsh's own _arguments, _describe and _files stood in for by functions that print them).
# Exits 77 (skipped) when zsh is not installed.
# usage: tests/zsh_completion.sh <_raytrace>
set -euo pipefail
script=$1
command -v zsh >/dev/null || { echo "zsh not installed: skipped"; exit 77; }
zsh -n "$script"
specs() {  # the words of `raytrace $1 ` as zsh would complete them
  zsh -fc '_arguments() { print -rl -- "$@"; }
           _describe() { print -rl -- "${(@P)${@[-1]}}"; }
           _files() { :; }
           words=(raytrace "$1" ""); CURRENT=$2; source "$0"' "$script" "$1" "${2:-3}"
}
status=0
check() {  # check COMMAND PATTERN present|absent
  if grep -qE -- "$2" <<<"$(specs "$1")"; then found=present; else found=absent; fi
  [[ $found == "$3" ]] || { echo "$1: '$2' $found, expected $3"; status=1; }
}
check render '^--threads\[' present
check render '^--display\[' present
check render '^--precision=-\[.*\(float double course auto\)$' present
check render '^-o\[.*:FILE:_files$' present
check sceneinfo '^--display\[' absent
check sceneinfo '^-o\[' absent
check sceneinfo '^\*:scene file:_files -g "\*\.\(pov\|cli\)"$' present
check merge '^\*:tile:_files -g "\*\.exr"$' present
check convert '^1:mesh file:_files -g "\*\.\(obj\|ply\)"$' present
[[ $(specs x 2 | head -1) == 'raycast:each pixel the colour of the first object its ray hits' ]] ||
  { echo "the commands are not described"; status=1; }
exit $status
