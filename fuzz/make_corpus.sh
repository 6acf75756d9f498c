#!/usr/bin/env bash
# Builds fuzz/corpus/ (the seed corpus) from every .pov file under tests/ and examples/:
# one file per distinct content, named by its hash, files over 64 KiB left out (AFL++ runs
# slowly on large inputs). With afl-cmin available (`cargo afl cmin`), pass --min to also
# keep only the seeds that add coverage for a target: ./make_corpus.sh --min eval
set -euo pipefail
cd "$(dirname "$0")"
rm -rf corpus
mkdir -p corpus
find ../tests ../examples -name '*.pov' -size -64k -print0 | sort -z \
  | while IFS= read -r -d '' scene; do
      cp "$scene" "corpus/$(sha1sum "$scene" | cut -c1-16).pov"
    done
echo "fuzz/corpus: $(ls corpus | wc -l) seeds"
if [ "${1:-}" = "--min" ]; then
  target="${2:-eval}"
  rm -rf "corpus-$target"
  AFL_SKIP_BIN_CHECK=1 cargo afl cmin -i corpus -o "corpus-$target" -t 5000 \
    -- "target/release/$target"
  echo "fuzz/corpus-$target: $(ls "corpus-$target" | wc -l) seeds"
fi
