"""sweep() releases the GIL while it works, and its numbers do not depend on the thread count."""

import math
import threading
import time

import numpy as np

import viscoroll as vr

MATERIAL = vr.StandardLinearSolid(mu_d=1.0, nu=0.5, f=9.0, tau=1.0)
SCENE = vr.Scene(material=MATERIAL, roller=vr.Ellipsoid(c1=1.0, c2=(math.log(20) - 1) / 25),
                 load=5 / (3 * 10 * MATERIAL.instantaneous_compliance))
SPEEDS = np.logspace(-2, 2, 40)


def test_the_gil_is_released_during_a_sweep():
    count = 0
    stop = threading.Event()

    def spin():
        nonlocal count
        while not stop.is_set():
            count += 1

    worker = threading.Thread(target=spin)
    worker.start()
    try:
        time.sleep(0.05)
        before = count
        t0 = time.perf_counter()
        vr.sweep(SCENE, speeds=SPEEDS[:16], threads=1)  # about 0.15 s
        elapsed = time.perf_counter() - t0
        during = count - before
    finally:
        stop.set()
        worker.join()
    # Held, the GIL would stop the counter for the whole sweep (it never yields in C++): a few
    # iterations at most. Released, the counter runs on: about 1e6-1e7 iterations per second.
    assert elapsed > 0.02, "a sweep long enough to measure"
    assert during > 10000, f"{during} iterations of the other thread during a {elapsed:.3f} s sweep"
    print(f"{during} iterations of the other thread during a {elapsed:.3f} s sweep")


def test_solve_releases_the_gil_too():
    count = 0
    stop = threading.Event()

    def spin():
        nonlocal count
        while not stop.is_set():
            count += 1

    worker = threading.Thread(target=spin)
    worker.start()
    try:
        time.sleep(0.05)
        before = count
        vr.solve(SCENE, method="bem", grid=12, speed=1.0)
        during = count - before
    finally:
        stop.set()
        worker.join()
    assert during > 1000


def test_two_threads_equal_one_exactly():
    one = vr.sweep(SCENE, speeds=SPEEDS, threads=1)
    two = vr.sweep(SCENE, speeds=SPEEDS, threads=2)
    every = vr.sweep(SCENE, speeds=SPEEDS)  # all cores
    assert one.keys() == two.keys() == every.keys()
    for key in one:
        if key == "seconds":
            continue
        if isinstance(one[key], np.ndarray):
            assert np.array_equal(one[key], two[key], equal_nan=one[key].dtype == np.float64), key
            assert np.array_equal(one[key], every[key], equal_nan=one[key].dtype == np.float64), key
        else:
            assert one[key] == two[key] == every[key], key
