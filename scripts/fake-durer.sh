#!/usr/bin/env bash
# A stand-in for the durer binary, for testing the harness without durer:
#   FAKE_DURER=povray  (default) renders with POV-Ray instead, so every scene matches
#   FAKE_DURER=fail    prints an error and exits 1, so every scene is an error
#   FAKE_DURER=blank   writes a black image by rendering an empty scene, so scenes differ
#   FAKE_DURER=hang    sleeps for an hour, to test timeouts
# Understands the subset of durer's CLI the harness uses:
#   fake-durer.sh render SCENE -o OUT --width W --height H [-L DIR]... [--threads N] [--quiet]
set -u
mode=${FAKE_DURER:-povray}
[ "${1:-}" = render ] || { echo "usage: $0 render SCENE [-o OUT] ..." >&2; exit 2; }
shift
scene="" out="" width=320 height=240 libs=()
while [ $# -gt 0 ]; do
    case $1 in
        -o) out=$2; shift 2 ;;
        --width) width=$2; shift 2 ;;
        --height) height=$2; shift 2 ;;
        -L) libs+=("+L$2"); shift 2 ;;
        --threads) shift 2 ;;
        --quiet) shift ;;
        -*) echo "error: unknown option $1" >&2; exit 2 ;;
        *) scene=$1; shift ;;
    esac
done
[ -n "$scene" ] || { echo "error: no scene given" >&2; exit 2; }
[ -n "$out" ] || out="${scene%.pov}.png"
case $mode in
    fail)
        echo "error: fake durer refuses to render $scene" >&2
        echo "  (second line that the harness should not show)" >&2
        exit 1 ;;
    hang)
        sleep 3600 ;;
    blank)
        empty=$(mktemp --suffix=.pov)
        echo 'background { rgb 0 }' > "$empty"
        povray -D "+I$empty" "+O$out" "+W$width" "+H$height" -GA +WT1 2>/dev/null
        code=$?
        rm -f "$empty"
        exit $code ;;
    *)
        povray -D "+I$scene" "+O$out" "+W$width" "+H$height" -GA +WT1 "${libs[@]}" "+L$(pwd)" \
            2>/dev/null || { echo "error: povray failed on $scene" >&2; exit 1; } ;;
esac
