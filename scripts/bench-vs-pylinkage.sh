#!/usr/bin/env bash
# Compare tmm with pylinkage 1.3 (numba) on the same four-bar (seed 001):
# installs pylinkage and numba into a throw-away virtual environment from PyPI,
# then measures both tools side by side in one run and prints the ratio of
# their times per full solve (positions, velocities, accelerations).
#
# On a shared machine absolute rates swing by a factor of two or more; the
# ratio of two measurements taken seconds apart does not. Three rounds
# alternate the two tools; each round prints its own ratio, and the end
# gives the ratio of the best of each tool and the median of the rounds'
# ratios, next to tmm's median sample.
set -euo pipefail
cd "$(dirname "$0")/.."
venv=$(mktemp -d)/venv
trap 'rm -rf "$(dirname "$venv")"' EXIT
python3 -m venv "$venv"
"$venv/bin/pip" install --quiet "pylinkage==1.3.0" numba
cargo bench --quiet -p tmm-linkage --bench kinematics --no-run
py_all=()
tmm_all=()
tmm_med_all=()
for round in 1 2 3; do
    echo "== round $round: pylinkage 1.3 (numba)"
    py=$("$venv/bin/python" scripts/pylinkage_fourbar.py)
    echo "$py"
    # ns per solve of the full kinematics (best of 20 sweeps of 3600 solves)
    ns_py=$(echo "$py" | grep step_fast_with_kinematics | sed -E 's/.*\(([0-9.]+) ns per solve\).*/\1/')
    echo "== round $round: tmm (full solve: positions, velocities, accelerations of every point and link)"
    t=$(cargo bench --quiet -p tmm-linkage --bench kinematics -- fourbar_revolution 2>&1 | grep -A1 fourbar_revolution)
    echo "$t"
    # fastest and median samples of 3600 solves → ns per solve
    read -r ns_tmm ns_tmm_med < <(echo "$t" | head -1 | python3 -c '
import re, sys
u = {"ns": 1, "µs": 1e3, "us": 1e3, "ms": 1e6}
v = re.findall(r"([\d.]+)\s*(ns|µs|us|ms)", sys.stdin.read())
print(float(v[0][0]) * u[v[0][1]] / 3600, float(v[2][0]) * u[v[2][1]] / 3600)')
    python3 -c "print(f'round $round: pylinkage {$ns_py:.1f} ns, tmm {$ns_tmm:.1f} ns (median {$ns_tmm_med:.1f} ns) per full solve: tmm/pylinkage time = {$ns_tmm / $ns_py:.3f} (tmm {$ns_py / $ns_tmm:.2f} × as fast)')"
    py_all+=("$ns_py")
    tmm_all+=("$ns_tmm")
    tmm_med_all+=("$ns_tmm_med")
done
python3 - "${py_all[*]}" "${tmm_all[*]}" "${tmm_med_all[*]}" <<'PY'
import statistics, sys
py, tmm, tmm_med = ([float(x) for x in a.split()] for a in sys.argv[1:4])
ratios = [t / p for p, t in zip(py, tmm)]
print(f"best of three: pylinkage {min(py):.1f} ns, tmm {min(tmm):.1f} ns per full solve:"
      f" tmm/pylinkage time = {min(tmm) / min(py):.3f} (tmm {min(py) / min(tmm):.2f} × as fast)")
print(f"median of the rounds: pylinkage {statistics.median(py):.1f} ns, tmm {statistics.median(tmm):.1f} ns"
      f" (tmm's median sample {statistics.median(tmm_med):.1f} ns); median per-round ratio tmm/pylinkage"
      f" = {statistics.median(ratios):.3f} (tmm {1 / statistics.median(ratios):.2f} × as fast)")
PY
