#!/usr/bin/env bash
# raytrace.1 formats without a warning and lists every command and option that `raytrace --help` lists.
# usage: tests/man_page.sh <raytrace> <raytrace.1>
set -euo pipefail
bin=$1 page=$2
warnings=$(MANWIDTH=200 man --warnings -l "$page" 2>&1 >/dev/null)
[[ -z $warnings ]] || { echo "man warns: $warnings"; exit 1; }
text=$(MANWIDTH=200 man -l "$page" 2>/dev/null)
status=0
# The options' labels ("  --depth=N   deepest..." or a label alone on its line) and the usage lines.
while IFS= read -r label; do
  grep -qF -- "$label" <<<"$text" || { echo "raytrace.1 lacks '$label'"; status=1; }
done < <("$bin" --help | sed -nE 's/^  ((-|raytrace )[^ ]*( [^ ]+)*)( {2,}.*)?$/\1/p')
exit $status
