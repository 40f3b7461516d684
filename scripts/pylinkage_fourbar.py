"""Rate of pylinkage (numba fast path) on the seed-001 four-bar.

A = (0, 0), D = (0.51, 0), AB = 0.12, BC = 0.48, DC = 0.38 m, 3600 steps of
0.1° per revolution, positions only (step_fast) and positions with
velocities and accelerations (step_fast_with_kinematics). Prints solves per
second; run by bench-vs-pylinkage.sh.
"""

import math
import time

from pylinkage.actuators import Crank
from pylinkage.components import Ground
from pylinkage.dyads import RRRDyad
from pylinkage.simulation import Linkage

N = 3600
A = Ground(0.0, 0.0, name="A")
D = Ground(0.51, 0.0, name="D")
crank = Crank(anchor=A, radius=0.12, angular_velocity=2 * math.pi / N, initial_angle=0.26)
rocker = RRRDyad(anchor1=crank.output, anchor2=D, distance1=0.48, distance2=0.38)
linkage = Linkage([A, D, crank, rocker], name="seed-001 four-bar")
linkage.set_input_velocity(crank, 900 * math.pi / 30)
linkage.compile()


def rate(fn, label):
    fn(N)  # compile and warm up
    best = float("inf")
    for _ in range(20):
        t = time.perf_counter()
        fn(N)
        best = min(best, time.perf_counter() - t)
    print(f"pylinkage {label}: {N / best / 1e6:.2f} million solves/s ({best / N * 1e9:.0f} ns per solve)")


rate(lambda n: linkage.step_fast(iterations=n), "positions only (step_fast)")
rate(lambda n: linkage.step_fast_with_kinematics(iterations=n), "positions, velocities, accelerations (step_fast_with_kinematics)")
