#!/usr/bin/env bash
# Re-render the reference images tests/reference/NAME.png from tests/reference/NAME.pov with
# POV-Ray 3.7, single-threaded (+WT1) for determinism, at 160x120 without anti-aliasing.
# A scene line `// povray-options: +A0.3 +AM2 +R3 -J` replaces the default `-A` with those
# options (anti-aliasing: +A[threshold], +AM method, +R depth, +J[amount] / -J).
#
# usage: scripts/render-references.sh [--verbose] [NAME.pov ...]   (default: every scene)
#   --verbose  show POV-Ray's warnings and statistics instead of silencing them (-GA)
set -euo pipefail

WIDTH=160
HEIGHT=120
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here/tests/reference"

if ! command -v povray >/dev/null 2>&1; then
    echo "error: povray is not installed. Install POV-Ray 3.7 (on Debian/Ubuntu:" >&2
    echo "  sudo apt-get install povray povray-includes) and run this script again." >&2
    exit 1
fi

quiet=-GA
if [ "${1:-}" = --verbose ]; then
    quiet=
    shift
fi
if [ $# -eq 0 ]; then
    set -- *.pov
fi

log=$(mktemp)
trap 'rm -f "$log"' EXIT
failed=0
for scene in "$@"; do
    scene=$(basename "$scene")
    name=${scene%.pov}
    # Per-scene options from a `// povray-options:` line (word splitting intended).
    options=$(sed -n 's|^// povray-options:||p' "$scene" | head -n 1)
    options=${options:--A}
    start=$(date +%s%N)
    # shellcheck disable=SC2086
    if povray -D "+I$scene" "+O$name.png" "+W$WIDTH" "+H$HEIGHT" $options $quiet +WT1 >"$log" 2>&1; then
        milliseconds=$((($(date +%s%N) - start) / 1000000))
        printf '%-28s %6d ms %7d bytes\n' "$name" "$milliseconds" "$(stat -c %s "$name.png")"
        if [ -z "$quiet" ]; then
            sed -n '/Parse Warning\|Warning:/,+1p' "$log"
        fi
    else
        echo "FAILED: $scene" >&2
        # -GA hides the parse error; render again with messages on to show it.
        # shellcheck disable=SC2086
        povray -D "+I$scene" "+O/dev/null" "+W$WIDTH" "+H$HEIGHT" $options +WT1 2>&1 \
            | grep -A3 -i 'error' >&2 || true
        failed=1
    fi
done
exit $failed
