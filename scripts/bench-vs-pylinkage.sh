#!/usr/bin/env bash
# Compare tmm with pylinkage 1.3 (numba) on the same four-bar (seed 001):
# installs pylinkage and numba into a throw-away virtual environment from PyPI,
# then prints both tools' rates in one run.
set -euo pipefail
cd "$(dirname "$0")/.."
venv=$(mktemp -d)/venv
trap 'rm -rf "$(dirname "$venv")"' EXIT
python3 -m venv "$venv"
"$venv/bin/pip" install --quiet "pylinkage==1.3.0" numba
echo "== pylinkage 1.3 (numba)"
"$venv/bin/python" scripts/pylinkage_fourbar.py
echo "== tmm (full solve: positions, velocities, accelerations of every point and link)"
cargo bench --quiet -p tmm-linkage --bench kinematics -- fourbar_revolution 2>&1 | grep -A1 fourbar_revolution
