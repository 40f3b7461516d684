#!/bin/sh
# Times `tmm run` of the embedded default task on one core, the note and the
# sheets included (issue 12, item 8: under 3 s once built). Build first:
#   cargo build --release -p tmm-cli
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
tmm="${CARGO_TARGET_DIR:-$here/target}/release/tmm"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for i in 1 2 3; do
    start=$(date +%s.%N)
    taskset -c 0 "$tmm" run --out "$out/run" > /dev/null
    end=$(date +%s.%N)
    echo "run $i: $(echo "$end - $start" | bc) s"
done
ls "$out/run/note.pdf" > /dev/null
