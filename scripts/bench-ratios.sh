#!/usr/bin/env bash
# Kinetostatics against kinematics of the seed-003 six-bar (3600 positions),
# measured side by side in one run of one benchmark binary, printed as ratios:
# on a busy machine absolute times swing by a factor of two or more, while
# the ratio of two measurements taken minutes apart in the same process does
# not. Each ratio is given for the fastest sample (the least disturbed) and
# for the median.
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(cargo bench --quiet -p tmm-linkage --bench forces 2>&1)
echo "$out" | grep -E "_3600_positions"
echo "$out" | python3 -c '
import re, sys
unit = {"ns": 1e-9, "µs": 1e-6, "us": 1e-6, "ms": 1e-3, "s": 1.0}
t = {}
for line in sys.stdin:
    m = re.search(r"(\w+_3600_positions)\s+([\d.]+)\s*(ns|µs|us|ms|s)\s+│\s+[\d.]+\s*\S+\s+│\s+([\d.]+)\s*(ns|µs|us|ms|s)", line)
    if m:
        t[m.group(1)] = (float(m.group(2)) * unit[m.group(3)], float(m.group(4)) * unit[m.group(5)])
k, kr, r = t["kinematics_3600_positions"], t["kinematics_and_reactions_3600_positions"], t["reactions_3600_positions"]
for i, what in enumerate(["fastest", "median"]):
    print(f"{what}: kinematics {k[i]*1e3:.3f} ms; kinematics + kinetostatics {kr[i]*1e3:.3f} ms = {kr[i]/k[i]:.2f} × kinematics;"
          f" kinetostatics alone (stored solutions) {r[i]*1e3:.3f} ms = {r[i]/k[i]:.2f} × kinematics;"
          f" kinetostatics in the loop (the difference) {(kr[i]-k[i])*1e3:.3f} ms = {(kr[i]-k[i])/k[i]:.2f} × kinematics")
print(f"target: kinetostatics of 3600 positions < 1 ms; fastest {r[0]*1e3:.3f} ms alone, {kr[0]*1e3:.3f} ms with the kinematics")
'
