#!/usr/bin/env bash
# Renders one image on a Slurm cluster: an array job of tiles (render-tiles.sbatch), then a merge job
# (merge.sbatch) that starts when all of them have succeeded (--dependency=afterok). The image is byte for
# byte the one `raytrace render` makes on one machine. With --frames, an animation's frames, whole or as tiles.
#
#   tools/slurm/submit.sh -n N -o OUT [--cpus C] [--wait] [--sbatch "OPTIONS"] SCENE WIDTH HEIGHT [render options]
#   tools/slurm/submit.sh --frames FIRST-LAST [-n K] [--cpus C] [--wait] [--sbatch "OPTIONS"] -- POV-RAY SWITCHES
#
#   -n N            tiles, one array task each
#   -o OUT          the merged image (.png, .hdr or .exr), on a folder the nodes share
#   --cpus C        CPUs per task (sbatch --cpus-per-task; default 1)
#   --wait          return once the merge job (or the frames' job) has ended, with its exit status
#   --sbatch OPTS   more sbatch options for both jobs, e.g. "--partition=render --time=1:00:00"
#   --frames F-L    an animation instead, from the scene's folder (which every node sees): one task per frame
#                   (render-frames.sbatch), or with -n K one per frame and tile, then a merge task per frame
#                   once they have all succeeded (afterok); stamps and logs as render-frames.sbatch says
#
# The tiles, the scene's copy and the logs go to OUT.tiles, which every node must see. Submitting again
# resumes: a task keeps its tile if it is of this very render (the contents of the scene and of every file it
# reads, size, options, program version) and renders a missing, unreadable or stale one again, its log
# (tile-I.log) saying which; the merge job checks every tile against the request. $RAYTRACE names the executable on the nodes (default: raytrace
# on their PATH).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
tiles="" output="" cpus=1 wait=() extra=() frames=""
die() { echo "submit.sh: error: $*" >&2; exit 2; }
while (($#)); do
  case $1 in
    -n) tiles=${2:?}; shift 2 ;;
    -o) output=${2:?}; shift 2 ;;
    --cpus) cpus=${2:?}; shift 2 ;;
    --wait) wait=(--wait); shift ;;
    --sbatch) read -r -a extra <<<"${2:?}"; shift 2 ;;
    --frames) frames=${2:?}; shift 2 ;;
    --) shift; break ;;
    -h | --help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) die "unknown option '$1' (see tools/slurm/submit.sh --help)" ;;
    *) break ;;
  esac
done
if [ -n "$frames" ]; then
  [[ $frames =~ ^([0-9]{1,6})-([0-9]{1,6})$ ]] || die "--frames must be FIRST-LAST, found '${frames:0:40}'"
  first=${BASH_REMATCH[1]} last=${BASH_REMATCH[2]}
  ((first <= last)) || die "--frames $frames: the first frame is after the last"
  [ -z "$output" ] || die "--frames writes the images the switches name (+O): -o is for one image"
  [ -z "$tiles" ] || [[ $tiles =~ ^[1-9][0-9]{0,4}$ ]] || die "-n must be a whole number of tiles from 1 to 32768"
  (($#)) || die "give the POV-Ray switches after --frames (see --help)"
  options=("${extra[@]}" --cpus-per-task="$cpus")
  if [ -z "$tiles" ]; then
    job=$(sbatch --parsable "${options[@]}" "${wait[@]}" --array="$first-$last" "$here/render-frames.sbatch" "$@")
    echo "submit.sh: frames $first-$last (current ones kept): job ${job%%;*}"
    exit 0
  fi
  # Task t of the tiles' array is tile t mod K of frame t div K.
  job=$(sbatch --parsable "${options[@]}" --array="$((first * tiles))-$(((last + 1) * tiles - 1))" \
    --output=frame-tiles-%a.log "$here/render-frames.sbatch" --tiles "$tiles" "$@")
  job=${job%%;*}
  echo "submit.sh: frames $first-$last, $tiles tiles each (current ones kept): job $job"
  merge=$(sbatch --parsable "${options[@]}" --dependency=afterok:"$job" --kill-on-invalid-dep=yes "${wait[@]}" \
    --array="$first-$last" "$here/render-frames.sbatch" --merge "$tiles" "$@")
  echo "submit.sh: a merge per frame: job ${merge%%;*}"
  exit 0
fi
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
