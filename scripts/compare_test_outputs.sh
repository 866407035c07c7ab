#!/usr/bin/env bash
# Byte-for-byte comparison of the test outputs of two builds (doc/testing.md, "Refactoring
# without changing results").
#   scripts/compare_test_outputs.sh snapshot BUILD_DIR DEST   copy BUILD_DIR/tests/**/output to DEST
#   scripts/compare_test_outputs.sh compare DEST BUILD_DIR    cmp each copy with BUILD_DIR's output
# 'compare' exits 1 if an output differs or is missing.
set -euo pipefail
case "${1:-}" in
  snapshot)
    build=$2 dest=$3
    rm -rf "$dest" && mkdir -p "$dest"
    (cd "$build/tests" && find . -name output -type f) | while read -r f; do
      mkdir -p "$dest/$(dirname "$f")" && cp "$build/tests/$f" "$dest/$f"
    done
    echo "$(find "$dest" -name output | wc -l) outputs in $dest" ;;
  compare)
    snapshot=$2 build=$3 bad=0 n=0
    while read -r f; do
      n=$((n + 1))
      if [ ! -f "$build/tests/$f" ]; then echo "missing: $f"; bad=1
      elif ! cmp -s "$snapshot/$f" "$build/tests/$f"; then echo "differs: $f"; bad=1; fi
    done < <(cd "$snapshot" && find . -name output -type f | sort)
    [ $bad = 0 ] && echo "all $n outputs byte for byte equal"
    exit $bad ;;
  *) echo "usage: $0 snapshot BUILD_DIR DEST | compare DEST BUILD_DIR" >&2; exit 2 ;;
esac
