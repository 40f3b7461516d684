#!/usr/bin/env bash
# tmm against pylinkage 1.3 (numba) on the same four-bar (seed 001), measured
# side by side in one run: installs pylinkage and numba into a throw-away
# virtual environment from PyPI, builds tmm-linkage's `ratios` benchmark,
# then alternates the two tools round by round (scripts/pylinkage_fourbar.py)
# and prints each round's rates and ratio, each tool's median and the median
# of the rounds' ratios. On a shared machine absolute rates swing by a factor
# of two or more; the ratio of two measurements taken a second apart does not.
#
# Usage: scripts/bench-vs-pylinkage.sh [ROUNDS]   (default 7)
set -euo pipefail
cd "$(dirname "$0")/.."
venv=$(mktemp -d)/venv
trap 'rm -rf "$(dirname "$venv")"' EXIT
python3 -m venv "$venv"
"$venv/bin/pip" install --quiet "pylinkage==1.3.0" numba
bin=$(cargo bench --quiet -p tmm-linkage --bench ratios --no-run --message-format=json \
    | python3 -c 'import json, sys
for line in sys.stdin:
    m = json.loads(line)
    if m.get("reason") == "compiler-artifact" and m["target"]["name"] == "ratios" and m.get("executable"):
        print(m["executable"])')
"$venv/bin/python" scripts/pylinkage_fourbar.py "$bin" "${1:-7}"
