#!/usr/bin/env bash
# Record POV-Ray 3.7's answers to the probe scenes of durer's embedded include files:
# runs tests/stdlib/NAME.pov with povray (POV-Ray's own include files) in a scratch folder and
# keeps the probe.txt it writes as tests/stdlib/NAME.txt, which tests/integration/includes.rs
# compares with what durer's embedded files produce.
#
# usage: scripts/probe-stdlib.sh [NAME.pov ...]   (default: every probe scene)
set -euo pipefail

here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here/tests/stdlib"

if ! command -v povray >/dev/null 2>&1; then
    echo "error: povray is not installed (on Debian/Ubuntu: sudo apt-get install povray" >&2
    echo "  povray-includes)." >&2
    exit 1
fi
if [ $# -eq 0 ]; then
    set -- *.pov
fi

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for scene in "$@"; do
    name=$(basename "$scene" .pov)
    rm -f "$scratch"/*
    cp "$name.pov" "$scratch/"
    if ! (cd "$scratch" && povray "+I$name.pov" +W1 +H1 -F -D -GA >/dev/null 2>&1) \
        || [ ! -s "$scratch/probe.txt" ]; then
        echo "error: povray failed on $name.pov" >&2
        exit 1
    fi
    cp "$scratch/probe.txt" "$name.txt"
    echo "$name.txt: $(wc -l <"$name.txt") lines"
done
