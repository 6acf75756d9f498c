#!/bin/sh
# Writes docs/reference-results.md: every reference scene of tests/reference/ with its
# measured difference from POV-Ray's render (the reference-image test's own comparison).
# Usage: scripts/reference-report.sh [OUTPUT]   (default docs/reference-results.md)
set -eu
cd "$(dirname "$0")/.."
out="${1:-docs/reference-results.md}"
table="$(mktemp)"
trap 'rm -f "$table"' EXIT
# The test fails when a scene does not match; the table is written either way.
DURER_REFERENCE_REPORT="$table" cargo test --release --quiet --test integration \
    reference_images_match_povray || true
{
    echo "# Reference images: measured difference from POV-Ray 3.7"
    echo
    echo "Every scene of \`tests/reference/\` rendered by durer at 160x120 and compared with"
    echo "POV-Ray 3.7's render of it (the reference-image test's comparison). A scene matches"
    echo "when at most 2% of its pixels differ by more than 24/255 in a channel (some scenes"
    echo "allow more, and say why). *Block diff* is the mean difference of 4x4-block means"
    echo "(0-255), *max diff* the largest channel difference. Regenerate with"
    echo "\`scripts/reference-report.sh\`."
    echo
    total=$(($(wc -l < "$table") - 2))
    matched=$(grep -c '| match |$' "$table" || true)
    echo "$matched of $total scenes match."
    echo
    cat "$table"
} > "$out"
echo "wrote $out"
