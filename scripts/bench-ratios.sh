#!/usr/bin/env bash
# Kinetostatics against kinematics of the seed-003 six-bar (3600 positions),
# measured side by side in one run: tmm-linkage's `ratios` benchmark runs the
# kinematics alone, the kinetostatics from stored solutions and both in one
# loop in interleaved rounds (each round runs all three, in a turning order)
# and prints the fastest and median time of each and the median of the
# rounds' ratios to the kinematics: a busy machine slows all three alike.
#
# Usage: scripts/bench-ratios.sh [ROUNDS]   (default 301)
set -euo pipefail
cd "$(dirname "$0")/.."
cargo bench --quiet -p tmm-linkage --bench ratios -- sixbar "${1:-301}"
