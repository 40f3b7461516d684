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
# Three rounds, the two tools alternating, so that both see the machine in the
# same state; the ratio of the best of each is printed at the end.
cargo bench --quiet -p tmm-linkage --bench kinematics --no-run
best_py=1e9
best_tmm=1e9
for round in 1 2 3; do
    echo "== round $round: pylinkage 1.3 (numba)"
    py=$("$venv/bin/python" scripts/pylinkage_fourbar.py)
    echo "$py"
    # ns per solve of the full kinematics (positions, velocities, accelerations)
    ns=$(echo "$py" | grep step_fast_with_kinematics | sed -E 's/.*\(([0-9.]+) ns per solve\).*/\1/')
    best_py=$(python3 -c "print(min($best_py, $ns))")
    echo "== round $round: tmm (full solve: positions, velocities, accelerations of every point and link)"
    t=$(cargo bench --quiet -p tmm-linkage --bench kinematics -- fourbar_revolution 2>&1 | grep -A1 fourbar_revolution)
    echo "$t"
    # fastest sample for 3600 solves → ns per solve
    ns=$(echo "$t" | head -1 | python3 -c '
import re, sys
m = re.search(r"fourbar_revolution\s+([\d.]+)\s*(ns|µs|us|ms)", sys.stdin.read())
print(float(m.group(1)) * {"ns": 1, "µs": 1e3, "us": 1e3, "ms": 1e6}[m.group(2)] / 3600)')
    best_tmm=$(python3 -c "print(min($best_tmm, $ns))")
done
python3 -c "print(f'best of three: pylinkage {$best_py:.1f} ns, tmm {$best_tmm:.1f} ns per full solve: tmm is {$best_py / $best_tmm:.2f} × as fast')"
