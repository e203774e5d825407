#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, started in a private folder, that runs the tile array job and the
# merge job of submit.sh end to end on a scene, checks the image against the one-machine render byte for byte,
# then the frames array job (render-frames.sbatch) on a 4-frame animation of its own against the one-machine
# animation, then the same animation as frames × tiles (submit.sh --frames 0-3 -n 2), and stops the cluster. Needs Debian's slurm-wlm and munge; runs as root (Slurm's daemons then run as
# root too) or as any user who may run munged and slurmd.
#
#   tools/slurm/local-cluster.sh [--tiles N] [--keep DIR] RAYTRACE SCENE WIDTH HEIGHT [render options]
#
# Its own munge key and socket, its own ports (16817, 16818) and state under DIR (default: a fresh temporary
# folder, removed at the end unless --keep names one), so a cluster already on the machine is left alone.
set -euo pipefail

tiles=4 keep=""
while (($#)); do
  case $1 in
    --tiles) tiles=${2:?}; shift 2 ;;
    --keep) keep=${2:?}; shift 2 ;;
    *) break ;;
  esac
done
(($# >= 4)) || { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 2; }
raytrace=$(realpath "$1") scene=$(realpath "$2") width=$3 height=$4
shift 4
here=$(cd "$(dirname "$0")" && pwd)
for tool in munged slurmctld slurmd sbatch sinfo; do
  command -v "$tool" >/dev/null || [ -x "/usr/sbin/$tool" ] ||
    { echo "local-cluster: $tool is missing (apt-get install slurm-wlm munge)" >&2; exit 2; }
done
export PATH=$PATH:/usr/sbin

dir=${keep:-$(mktemp -d /tmp/raytrace-slurm-XXXXXX)}
mkdir -p "$dir"/{munge,state,spool,log,work}
chmod 700 "$dir/munge"
stop() {
  for pid in "$dir"/slurmd.pid "$dir"/slurmctld.pid "$dir"/munge/munged.pid; do
    [ -s "$pid" ] && kill "$(cat "$pid")" 2>/dev/null || true
  done
  sleep 1
  [ -n "$keep" ] || rm -rf "$dir"
}
trap stop EXIT
start=$SECONDS

# munge: a fresh key, a socket of our own.
dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$dir/munge/munge.key"
munged --force --key-file="$dir/munge/munge.key" --socket="$dir/munge/socket" \
  --pid-file="$dir/munge/munged.pid" --log-file="$dir/log/munged.log" --seed-file="$dir/munge/seed"

node=$(hostname -s)
cpus=$(nproc)
memory=$(($(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 / 2))
user=$(id -un)
cat >"$dir/slurm.conf" <<CONF
ClusterName=raytrace-local
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=16817
SlurmdPort=16818
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
AuthInfo=socket=$dir/munge/socket
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool/%n
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$dir/slurm.conf
slurmctld -i
slurmd
for _ in $(seq 120); do
  sinfo -h -o %T 2>/dev/null | grep -q '^idle' && break
  sleep 0.5
done
sinfo -h -o %T | grep -q '^idle' || { echo "local-cluster: the node did not come up" >&2; tail "$dir"/log/*.log >&2; exit 1; }
echo "local-cluster: one-node cluster up in $((SECONDS - start)) s ($node, $cpus CPUs)"
sinfo

cd "$dir/work"
cp "$scene" scene.pov  # a copy, edited below, which finds the files the scene includes in the scene's folder
set -- -L "$(dirname "$scene")" "$@"
scene=$dir/work/scene.pov
"$raytrace" render "$scene" "$width" "$height" "$@" --quiet -o one.png
RAYTRACE=$raytrace "$here/submit.sh" -n "$tiles" -o "$dir/work/slurm.png" --wait "$scene" "$width" "$height" "$@"
cmp one.png slurm.png
echo "local-cluster: $tiles array tasks and the merge job give the one-machine bytes"
# Resuming: with the image and the first tile gone (as if its task had failed), submitting again renders that
# tile alone and merges the same bytes.
rm slurm.png slurm.png.tiles/tile-0.exr
RAYTRACE=$raytrace "$here/submit.sh" -n "$tiles" -o "$dir/work/slurm.png" --wait "$scene" "$width" "$height" "$@"
cmp one.png slurm.png
echo "local-cluster: resubmitted, tile 0 alone rendered again; the same bytes ($((SECONDS - start)) s in all)"
# Resuming after the request changed: a new height, then an edited scene, then a truncated tile. Each time
# the stale or unreadable tiles alone are rendered again (their logs say why) and the bytes are right.
submit() { RAYTRACE=$raytrace "$here/submit.sh" -n "$tiles" -o "$dir/work/slurm.png" --wait "$scene" "$@"; }
check() {
  "$raytrace" render "$scene" "$@" --quiet -o one.png
  cmp one.png slurm.png
  grep -h "raytrace: 'tile-" slurm.png.tiles/tile-*.log | sort | uniq -c
}
submit "$width" $((height + 2)) "$@"
check "$width" $((height + 2)) "$@"
[ "$(cat slurm.png.tiles/tile-*.log | grep -c 'is stale')" = "$tiles" ] || { echo "local-cluster: stale tiles kept" >&2; exit 1; }
echo "// edited" >>"$scene"
submit "$width" "$height" "$@"
check "$width" "$height" "$@"
[ "$(cat slurm.png.tiles/tile-*.log | grep -c 'raytrace.sceneHash')" = "$tiles" ] || { echo "local-cluster: the edit not seen" >&2; exit 1; }
head -c 100 slurm.png.tiles/tile-1.exr >cut && mv cut slurm.png.tiles/tile-1.exr
submit "$width" "$height" "$@"
check "$width" "$height" "$@"
grep -q "'tile-1.exr' is unreadable" slurm.png.tiles/tile-1.log || { echo "local-cluster: tile 1 not redone" >&2; exit 1; }
[ "$(cat slurm.png.tiles/tile-*.log | grep -c 'kept')" = $((tiles - 1)) ] || { echo "local-cluster: not kept" >&2; exit 1; }
echo "local-cluster: resubmitted after a new size, an edited scene and a truncated tile; the same bytes as one machine ($((SECONDS - start)) s in all)"

# The frames recipe: a 4-frame animation whose scene includes a file, one array task per frame, in a folder of
# its own (the scene's, which the tasks work in); then resubmitted after a frame's image is deleted (that frame
# alone is rendered again) and after the include is edited (every frame is).
mkdir -p "$dir/frames/one" "$dir/frames/slurm"
cd "$dir/frames"
cat >spin.pov <<'POV'
#version 3.7;
camera { location <0, 2, -5> look_at 0 }
light_source { <3, 5, -4> rgb 1 }
#include "spin.inc"
sphere { <2 * sin(clock * 2 * pi), 0.5, 2 * cos(clock * 2 * pi)>, 0.5 pigment { Orange } }
plane { y, 0 pigment { checker rgb 1 rgb 0.3 } }
POV
echo '#declare Orange = rgb <1, 0.4, 0.2>;' >spin.inc
switches=(+Ispin.pov +W"$width" +H"$height" +KFI0 +KFF3)
# Submits the animation into folder $1 by the command after it, renders it on one machine, compares every
# frame and shows the tasks' logs.
animation() {
  local out=$1
  shift
  rm -f frame-*.log
  RAYTRACE=$raytrace "$@" "${switches[@]}" +O"$out"/spin >/dev/null
  "$raytrace" "${switches[@]}" +Oone/spin
  for f in 0 1 2 3; do cmp "one/spin$f.png" "$out/spin$f.png"; done
  cat frame-*.log
}
frames() { animation slurm sbatch --wait --array=0-3 "$here/render-frames.sbatch"; }
said() {
  [ "$(cat frame-*.log | grep -c "$1")" = "$2" ] || { echo "local-cluster: not $2 frames $1" >&2; exit 1; }
}
frames
said "is not rendered yet: rendering it" 4
echo "local-cluster: 4 frame tasks give the one-machine animation's bytes"
rm slurm/spin2.png
frames
grep -qx "frame 2 is stale: 'slurm/spin2.png' is missing: rendering it" frame-2.log ||
  { echo "local-cluster: frame 2 not redone" >&2; exit 1; }
said "is already this render: kept" 3
echo '#declare Orange = rgb <1, 0.5, 0.2>;' >spin.inc
frames
said "is stale: 'spin.inc' has changed: rendering it" 4
echo "local-cluster: frames resubmitted after a deleted frame and an edited include; the one-machine bytes ($((SECONDS - start)) s in all)"

# Frames × tiles: the same animation, 2 tiles a frame (8 tasks), then a merge task per frame; resubmitted after
# a frame's image is deleted (that frame alone is merged again, its tiles kept) and after the include is edited.
# A fresh start: the stamps of the frames above are of other switches.
rm -rf frames.stamps
mkdir -p tiled
tiled() { animation tiled "$here/submit.sh" --frames 0-3 -n 2 --wait --; }
tiled
said "is not rendered yet: rendering its tile" 8
said "is not rendered yet: merging its tiles" 4
echo "local-cluster: 4 frames of 2 tile tasks each and a merge task per frame give the one-machine animation's bytes"
rm tiled/spin1.png
tiled
grep -qx "frame 1 is stale: 'tiled/spin1.png' is missing: merging its tiles" frame-1.log ||
  { echo "local-cluster: frame 1 not merged again" >&2; exit 1; }
said "is already this tile: kept" 2
said "is already this render: kept" 9
echo '#declare Orange = rgb <1, 0.3, 0.2>;' >spin.inc
tiled
said "is stale: 'spin.inc' has changed: rendering its tile" 8
said "is stale: 'spin.inc' has changed: merging its tiles" 4
echo "local-cluster: frames × tiles resubmitted after a deleted frame and an edited include; the one-machine bytes ($((SECONDS - start)) s in all)"
