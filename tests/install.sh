#!/usr/bin/env bash
# `cmake --install` puts the program, its man page, its completions and its documentation where GNUInstallDirs
# says, and the installed program renders an installed example.
# usage: tests/install.sh <build folder> <prefix to install into>
set -euo pipefail
build=$1 prefix=$2
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
status=0
for f in bin/raytrace share/man/man1/raytrace.1 share/bash-completion/completions/raytrace \
         share/zsh/vendor-completions/_raytrace share/doc/raytrace/README.md share/doc/raytrace/docs/output.md \
         share/doc/raytrace/examples/default.pov share/doc/raytrace/resources/default.png; do
  [[ -f $prefix/$f ]] || { echo "not installed: $f"; status=1; }
done
cd "$prefix"
bin/raytrace render share/doc/raytrace/examples/default.pov 32 24 -o check.png --quiet
[[ -s check.png ]] || { echo "the installed raytrace wrote no image"; status=1; }
exit $status
