"""The Python side of docs/python.md's overhead measurement: viscoroll.sweep of the line solver
over N speeds (default 100, V tau/a0 = 1e-2 ... 1e2 log-spaced, the paper's nondimensional scene,
grid 6, chunk 16), repeated R times (default 5); prints each wall time and the median. The C++
side, the same viscoroll::sweep call: python/bench/sweep_timing.cpp (target
viscoroll_python_bench_sweep, <build>/python/bench/sweep_timing).

usage: PYTHONPATH=<build>/python python3 python/bench/bench_sweep.py [--speeds N] [--repeats R]
       [--threads T]
"""
import argparse
import math
import statistics
import time

import viscoroll as vr

parser = argparse.ArgumentParser()
parser.add_argument("--speeds", type=int, default=100)
parser.add_argument("--repeats", type=int, default=5)
parser.add_argument("--threads", type=int, default=0)
args = parser.parse_args()

mat = vr.StandardLinearSolid(mu_d=1.0, nu=0.5, f=9.0, tau=1.0)
scene = vr.Scene(material=mat, roller=vr.Ellipsoid(c1=1.0, c2=(math.log(20) - 1) / 25),
                 load=1 * 5 / (3 * (1 + 9.0) * mat.instantaneous_compliance))
n = args.speeds
speeds = [10.0 ** (-2 + 4.0 * i / max(1, n - 1)) for i in range(n)]  # as sweep_timing.cpp
times, cpu = [], []
for r in range(args.repeats):
    t0, c0 = time.perf_counter(), time.process_time()
    s = vr.sweep(scene, speeds, method="line", grid=6, threads=args.threads)
    times.append(time.perf_counter() - t0)
    cpu.append(time.process_time() - c0)
    print(f"run {r + 1}: {times[-1]:.4f} s (cpu {cpu[-1]:.4f} s)")
print(f"Python sweep: {n} speeds, threads {args.threads}, chunk 16: median "
      f"{statistics.median(times):.4f} s (cpu {statistics.median(cpu):.4f} s), {int(s['converged'].sum())} converged")
