#!/usr/bin/env bash
# Re-render the animation references tests/animation/NAME/reference/NAMEnn.png with POV-Ray
# 3.7: for each folder holding NAME.ini (POV-Ray's own example animation, copied with its
# licence header) and frames.txt (the frames to check), `povray NAME.ini` renders each frame
# at 80x60 without jitter, single-threaded, with an empty default INI so the machine's
# povray.ini cannot change the result. tests/integration/povray_cli.rs renders the same
# command with durer and compares (at most 2% of pixels over 24/255).
#
# usage: scripts/render-animation-references.sh
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
if ! command -v povray >/dev/null 2>&1; then
    echo "error: povray is not installed (apt-get install povray povray-includes)" >&2
    exit 1
fi
empty=$(mktemp --suffix=.ini)
trap 'rm -f "$empty"' EXIT
for folder in "$here"/tests/animation/*/; do
    name=$(basename "$folder")
    [ -f "$folder/$name.ini" ] && [ -f "$folder/frames.txt" ] || continue
    rm -rf "${folder}reference"
    mkdir -p "${folder}reference"
    for frame in $(cat "$folder/frames.txt"); do
        (cd "$folder" && POVINI=$empty povray -D -GA "$name.ini" +W80 +H60 "+SF$frame" \
            "+EF$frame" -J +WT1 +L/usr/share/povray-3.7/include "+O${folder}reference/" >/dev/null 2>&1) || echo "povray failed: $name frame $frame" >&2
    done
    echo "$name: $(ls "${folder}reference" | tr '\n' ' ')"
done
