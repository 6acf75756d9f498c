#!/bin/sh
# Renders N tiles with GNU parallel (tile number from PARALLEL_SEQ) and merges them.
# Usage: farm/parallel.sh SCENE N TILEDIR OUT [parallel options] [-- durer options]
#   local cores:  farm/parallel.sh scene.pov 16 tiles image.png
#   other hosts:  farm/parallel.sh scene.pov 16 tiles image.png --sshlogin 4/host1,4/host2,:
# With --sshlogin the scene, its include files, TILEDIR and durer must be at the same
# paths on every host (a shared file system); DURER names the binary (default: durer).
set -e
scene=$1 count=$2 dir=$3 out=$4
shift 4
popts=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do popts="$popts $1"; shift; done
[ "$1" = "--" ] && shift
mkdir -p "$dir"
durer=${DURER:-durer}
# shellcheck disable=SC2086
seq 1 "$count" | parallel --will-cite --halt now,fail=1 $popts \
    "$durer" render "$scene" --tile "auto/$count" -o "$dir/tile-{}" --quiet "$@"
exec "$durer" merge "$out" "$dir"/tile-*.tile.png
