#!/usr/bin/env bash
# A stand-in for ssh that makes each host a folder on this machine: `ssh_to_folder.sh [options] HOST COMMAND...`
# runs COMMAND with bash in $SSH_TO_FOLDER_ROOT/HOST, which is also its HOME. GNU parallel takes it as its ssh
# ($PARALLEL_SSH), and so does the rsync it sends and fetches files with.
set -euo pipefail
while [[ ${1-} == -* ]]; do
  case $1 in
    -o | -p | -l | -i | -S) shift 2 ;;
    --) shift; break ;;
    *) shift ;;
  esac
done
host=${1:?a host}
shift
[ "${1-}" = -- ] && shift
home=${SSH_TO_FOLDER_ROOT:?the folder that holds the hosts}/$host
mkdir -p "$home"
cd "$home"
# sshd gives the command a login environment: HOME and SHELL (GNU parallel runs jobs with $SHELL).
HOME=$home SHELL=/bin/bash exec bash -c "$*"
