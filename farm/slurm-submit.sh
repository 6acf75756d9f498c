#!/bin/sh
# Submits a split render to Slurm: an array job of N tiles, then a merge job that runs
# once all of them succeeded. Prints the merge job's id.
# Usage: farm/slurm-submit.sh SCENE N TILEDIR OUT [durer options]
#   farm/slurm-submit.sh scene.pov 16 tiles image.png +W1920 +H1080 +A0.3
# Run it from a folder every node sees (the jobs' logs are written there).
set -e
here=$(dirname "$0")
scene=$1 count=$2 dir=$3 out=$4
shift 4
tiles=$(sbatch --parsable --array=0-$((count - 1)) "$here/slurm-tiles.sbatch" \
    "$scene" "$count" "$dir" "$@")
sbatch --parsable --dependency="afterok:${tiles%%;*}" --kill-on-invalid-dep=yes \
    "$here/slurm-merge.sbatch" "$out" "$dir"
