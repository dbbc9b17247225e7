"""docs/python.md's measurements of vr.study ("Studies: labelled arrays, all cores, a Dask
cluster"), medians of R runs (default 3) in one process:

1. one bem solve of the shipped examples/scenes/conveyor_idler.json (0 degC, 1 m/s, the auto
   method: the bem to 1% in d and chi);
2. the Dask path's overhead per task: N trivially cheap scenes (an elastic cylinder, the plane
   method on the half space) in chunks of 1, on a LocalCluster of W workers (processes, one
   thread each) against the same study on W local threads; the overhead is the difference of the
   wall times times W over the tasks: worker time per task;
3. the throughput (scenes/s) of one representative scene type, examples/python/
   conveyor_study.py's (the idler's eight-term Prony rubber on a bonded cover layer, the plane
   method to 1e-3; 2 thicknesses x 4 temperatures x 4 speeds = 32 scenes, chunk 4), locally on
   1 and 2 threads and on Dask with 1 and 2 workers;
4. the chunk that keeps the overhead under 5% of the solves of a task: chunk >= overhead /
   (0.05 t), t a solve's time.

usage: PYTHONPATH=<build>/python python3 python/bench/bench_study.py [--repeats R] [--tasks N]
"""
import argparse
import math
import os
import pathlib
import statistics
import time
import warnings

import numpy as np

import viscoroll as vr


def median_time(run, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        run()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), times


def cluster(workers):
    import distributed  # pylint: disable=import-outside-toplevel
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        local = distributed.LocalCluster(n_workers=workers, processes=True, threads_per_worker=1,
                                         dashboard_address=None)
    return local, distributed.Client(local)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--tasks", type=int, default=200)
    args = parser.parse_args()
    r = args.repeats
    root = pathlib.Path(__file__).resolve().parents[2]
    print(f"viscoroll {vr.__version__}, {os.cpu_count()} cores, load average at start "
          f"{' '.join(f'{x:.2f}' for x in os.getloadavg())}; medians of {r} runs")

    # 1. A bem solve of the shipped conveyor idler.
    idler = vr.Scene.from_json(root / "examples" / "scenes" / "conveyor_idler.json",
                               temperature=0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the leading edge's layer under a quarter cell
        bem, runs = median_time(lambda: vr.solve(idler, speed=1.0), r)
    print(f"bem solve, conveyor_idler.json at 0 degC, 1 m/s: {bem:.2f} s "
          f"({', '.join(f'{t:.2f}' for t in runs)})")

    # 2. The Dask path's overhead per task.
    cheap = vr.Scene(vr.Elastic(mu=1e6, nu=0.5), vr.Cylinder(radius=0.05), load=100.0)
    speeds = np.linspace(1.0, 2.0, args.tasks)
    for workers in (1, 2):
        local, _ = median_time(lambda: vr.study(cheap, speed=speeds, chunk=1, threads=workers,
                                                progress=False), r)
        lc, client = cluster(workers)
        with lc, client:
            vr.study(cheap, speed=speeds[:4], chunk=1, client=client, progress=False)  # warm
            dask, _ = median_time(lambda: vr.study(cheap, speed=speeds, chunk=1, client=client,
                                                   progress=False), r)
        if workers == 1:
            cheap_time = local / args.tasks  # a scene's wall time, its record included
        overhead = (dask - local) * workers / args.tasks
        print(f"overhead, {args.tasks} tasks of one plane solve, {workers} worker(s): Dask "
              f"{dask:.3f} s, local {local:.3f} s on {workers} thread(s): "
              f"{overhead * 1e3:.2f} ms of worker time per task")
    per_task = overhead  # 2 workers

    # 3. Throughput of the conveyor study's scene type.
    rubber = vr.Prony(g_inf=1.5e6, nu=0.5,
                      terms=[(2.0e8, 1e-7), (6.0e7, 1e-6), (1.8e7, 1e-5), (6.0e6, 1e-4),
                             (2.0e6, 1e-3), (8.0e5, 1e-2), (4.0e5, 1e-1), (2.0e5, 1.0)],
                      shift=vr.WLF(c1=8.86, c2=101.6, t_ref=0.0))
    cover = vr.Scene(rubber, vr.Cylinder(radius=0.0635), load=1500.0 / 0.37,
                     substrate={"model": "layer", "thickness": 0.006, "base": "bonded"})
    axes = {"thickness": [0.003, 0.012], "temperature": [-30.0, -10.0, 10.0, 30.0],
            "speed": [1.0, 3.0, 5.0, 8.0]}
    n = math.prod(len(v) for v in axes.values())

    def run(**options):
        return vr.study(cover, method="plane", tolerance=1e-3, chunk=4, progress=False,
                        **options, **axes)

    reference = run(threads=1)
    solve_time = float(reference["seconds"].median())
    rates = {}
    for threads in (1, 2):
        wall, _ = median_time(lambda: run(threads=threads), r)
        rates[f"local, {threads} thread(s)"] = n / wall
    for workers in (1, 2):
        lc, client = cluster(workers)
        with lc, client:
            run(client=client)  # warm: the workers import viscoroll
            wall, _ = median_time(lambda: run(client=client), r)
        rates[f"Dask, {workers} worker(s)"] = n / wall
    print(f"throughput, the conveyor cover ({n} scenes, plane on a bonded layer to 1e-3, median "
          f"solve {solve_time:.3f} s): " + ", ".join(f"{k} {v:.2f} scenes/s"
                                                    for k, v in rates.items()))

    # 4. The chunk that keeps the overhead under 5%.
    for name, t in (("bem (conveyor_idler.json)", bem), ("plane on a layer", solve_time),
                    ("plane on the half space (the overhead's scenes)", cheap_time)):
        print(f"chunk for < 5% overhead, {name} at {t:.3g} s a solve: "
              f"{max(1, math.ceil(per_task / (0.05 * t)))}")
    print(f"load average at end {' '.join(f'{x:.2f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
