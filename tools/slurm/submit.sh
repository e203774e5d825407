#!/usr/bin/env bash
# Renders one image on a Slurm cluster: an array job of tiles (render-tiles.sbatch), then a merge job
# (merge.sbatch) that starts when all of them have succeeded (--dependency=afterok). The image is byte for
# byte the one `raytrace render` makes on one machine.
#
#   tools/slurm/submit.sh -n N -o OUT [--cpus C] [--wait] [--sbatch "OPTIONS"] SCENE WIDTH HEIGHT [render options]
#
#   -n N            tiles, one array task each
#   -o OUT          the merged image (.png, .hdr or .exr), on a folder the nodes share
#   --cpus C        CPUs per task (sbatch --cpus-per-task; default 1)
#   --wait          return once the merge job has ended, with its exit status
#   --sbatch OPTS   more sbatch options for both jobs, e.g. "--partition=render --time=1:00:00"
#
# The tiles, the scene's copy and the logs go to OUT.tiles, which every node must see. Submitting again
# resumes: a task keeps its tile if it is of this very render (the contents of the scene and of every file it
# reads, size, options, program version) and renders a missing, unreadable or stale one again, its log
# (tile-I.log) saying which; the merge job checks every tile against the request. $RAYTRACE names the executable on the nodes (default: raytrace
# on their PATH).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
tiles="" output="" cpus=1 wait=() extra=()
die() { echo "submit.sh: error: $*" >&2; exit 2; }
while (($#)); do
  case $1 in
    -n) tiles=${2:?}; shift 2 ;;
    -o) output=${2:?}; shift 2 ;;
    --cpus) cpus=${2:?}; shift 2 ;;
    --wait) wait=(--wait); shift ;;
    --sbatch) read -r -a extra <<<"${2:?}"; shift 2 ;;
    -h | --help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) die "unknown option '$1' (see tools/slurm/submit.sh --help)" ;;
    *) break ;;
  esac
done
(($# >= 3)) || die "give the scene, width and height (see --help)"
[[ $tiles =~ ^[1-9][0-9]{0,4}$ ]] || die "-n must be a whole number of tiles from 1 to 32768"
[ -n "$output" ] || die "give the merged image's name with -o"
scene=$1 width=$2 height=$3
shift 3
[ -f "$scene" ] || die "cannot read '$scene'"

case $output in /*) ;; *) output=$PWD/$output ;; esac
# The tasks read the scene's copy beside the tiles: the files it includes or reads are found in its own folder.
set -- -L "$(cd "$(dirname -- "$scene")" && pwd)" "$@"
dir=$output.tiles
mkdir -p "$dir"
name=$(basename -- "$scene")
cmp -s "$scene" "$dir/$name" 2>/dev/null || cp -- "$scene" "$dir/$name"
[[ $name == -* ]] && name=./$name  # not an option to raytrace
cd "$dir"

job=$(sbatch --parsable "${extra[@]}" --array="0-$((tiles - 1))" --cpus-per-task="$cpus" \
  "$here/render-tiles.sbatch" "$tiles" "$name" "$width" "$height" "$@")
job=${job%%;*}
echo "submit.sh: tiles 0-$((tiles - 1)) of $tiles (current ones kept): job $job"
merge=$(sbatch --parsable "${extra[@]}" --dependency=afterok:"$job" "${wait[@]}" "$here/merge.sbatch" "$tiles" \
  "$output" "$name" "$width" "$height" "$@")
echo "submit.sh: merge into $output: job ${merge%%;*}"
