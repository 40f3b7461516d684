"""pylinkage (numba fast path) against tmm on the seed-001 four-bar, side by side.

A = (0, 0), D = (0.51, 0), AB = 0.12, BC = 0.48, DC = 0.38 m, 3600 steps of
0.1° per revolution; the full solve: positions, velocities and
accelerations (pylinkage's step_fast_with_kinematics; tmm's sweep).

Usage: python pylinkage_fourbar.py TMM_RATIOS_BINARY [ROUNDS]

Each round measures pylinkage (the fastest of 20 sweeps) and then tmm (the
fastest of 20 sweeps, by `ratios fourbar 20`, the tmm-linkage benchmark
binary), so that both see the machine in the same state; the end gives each
tool's median over the rounds and the median of the rounds' ratios. Run by
bench-vs-pylinkage.sh, which installs pylinkage into a throw-away venv.
"""

import math
import statistics
import subprocess
import sys
import time

from pylinkage.actuators import Crank
from pylinkage.components import Ground
from pylinkage.dyads import RRRDyad
from pylinkage.simulation import Linkage

N = 3600
SWEEPS = 20
A = Ground(0.0, 0.0, name="A")
D = Ground(0.51, 0.0, name="D")
crank = Crank(anchor=A, radius=0.12, angular_velocity=2 * math.pi / N, initial_angle=0.26)
rocker = RRRDyad(anchor1=crank.output, anchor2=D, distance1=0.48, distance2=0.38)
linkage = Linkage([A, D, crank, rocker], name="seed-001 four-bar")
linkage.set_input_velocity(crank, 900 * math.pi / 30)
linkage.compile()


def pylinkage_ns(fn):
    """ns per solve of the fastest of SWEEPS sweeps of N steps."""
    best = float("inf")
    for _ in range(SWEEPS):
        t = time.perf_counter()
        fn(N)
        best = min(best, time.perf_counter() - t)
    return best / N * 1e9


def tmm_ns(binary):
    out = subprocess.run([binary, "fourbar", str(SWEEPS)], check=True, capture_output=True, text=True).stdout
    return float(next(line.split()[1] for line in out.splitlines() if line.startswith("ns_per_solve ")))


def main():
    binary = sys.argv[1]
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 7
    full = lambda n: linkage.step_fast_with_kinematics(iterations=n)  # noqa: E731
    positions = lambda n: linkage.step_fast(iterations=n)  # noqa: E731
    full(N)  # compile and warm up
    positions(N)
    print(f"pylinkage positions only (step_fast): {pylinkage_ns(positions):.0f} ns per solve (for reference)")
    py, tmm = [], []
    for r in range(1, rounds + 1):
        p = pylinkage_ns(full)
        t = tmm_ns(binary)
        py.append(p)
        tmm.append(t)
        print(
            f"round {r}: pylinkage {p:7.1f} ns ({1e3 / p:5.2f} M solves/s), tmm {t:6.1f} ns ({1e3 / t:5.1f} M solves/s):"
            f" tmm {p / t:5.1f} × as fast"
        )
    ratios = [p / t for p, t in zip(py, tmm)]
    mp, mt = statistics.median(py), statistics.median(tmm)
    print(
        f"median of {rounds} rounds: pylinkage {mp:.1f} ns ({1e3 / mp:.2f} M solves/s), tmm {mt:.1f} ns"
        f" ({1e3 / mt:.1f} M solves/s) per full solve; median ratio: tmm {statistics.median(ratios):.1f} × as fast"
        f" (rounds: {min(ratios):.1f} … {max(ratios):.1f})"
    )


if __name__ == "__main__":
    main()
