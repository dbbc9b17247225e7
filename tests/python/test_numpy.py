"""NumPy in and out: shapes, dtypes, broadcasting, scalars."""

import math

import numpy as np
import pytest

import viscoroll as vr

MATERIAL = vr.StandardLinearSolid(mu_d=1.0, nu=0.5, f=9.0, tau=1.0)
LOAD = 5 / (3 * 10 * MATERIAL.instantaneous_compliance)
SCENE = vr.Scene(material=MATERIAL, roller=vr.Ellipsoid(c1=1.0, c2=(math.log(20) - 1) / 25),
                 load=LOAD, speeds=[0.1, 1.0, 10.0])


@pytest.fixture(scope="module", params=["line", "plane", "bem"])
def result(request):
    return vr.solve(SCENE, method=request.param, speed=1.0, grid=6 if request.param == "bem"
                    else None)


def test_scalars_in_scalars_out(result):
    assert isinstance(result.pressure(0.0, 0.0), float)
    assert isinstance(result.a0, float) and isinstance(result.converged, bool)
    assert isinstance(result.iterations, int) and isinstance(result.reason if
                                                             result.method != "plane" else "",
                                                             str)
    if result.method != "bem":
        for f in (result.a, result.b, result.f0):
            assert isinstance(f(0.0), float)


def test_broadcasting(result):
    x = np.linspace(-1.5, 1.5, 7)
    y = np.linspace(-0.5, 0.5, 3)
    p = result.pressure(x[np.newaxis, :], y[:, np.newaxis])
    assert p.shape == (3, 7) and p.dtype == np.float64
    assert np.all(p >= 0) and p.max() > 0
    assert result.pressure(x, 0.0).shape == (7,)
    assert result.pressure([0.0, 0.1], [0.0]).shape == (2,)
    assert np.array_equal(result.pressure(x, 0.0), [result.pressure(float(v), 0.0) for v in x])
    assert result.pressure(np.arange(3, dtype=np.int64), 0).dtype == np.float64
    if result.method != "bem":
        for f in (result.a, result.b, result.f0):
            out = f(y.reshape(3, 1))
            assert out.shape == (3, 1) and out.dtype == np.float64
        assert result.a(0.0) == pytest.approx(result.a0, rel=1e-15)
        assert result.b(0.0) == pytest.approx(result.b0, rel=1e-15)


def test_the_peak(result):
    if result.method == "bem":
        return
    assert result.pressure(result.pmax_x, 0.0) == pytest.approx(result.pmax, rel=1e-12)


def test_sweep_columns():
    s = vr.sweep(SCENE, method="line", threads=1)
    assert "method" not in s
    for key in ("tau", "speed", "vtau", "a0", "b0", "l", "d", "chi", "pmax", "pmax_x", "residual",
                "seconds"):
        assert s[key].dtype == np.float64 and s[key].shape == (3,), key
    for key in ("iterations", "terms"):
        assert s[key].dtype == np.int64 and s[key].shape == (3,), key
    for key in ("converged", "root"):
        assert s[key].dtype == np.bool_ and s[key].shape == (3,), key
    assert isinstance(s["reason"], list) and all(isinstance(r, str) for r in s["reason"])
    assert isinstance(s["warnings"], list) and all(isinstance(w, list) for w in s["warnings"])
    assert [len(c) for c in s["warning_codes"]] == [len(w) for w in s["warnings"]]
    assert np.array_equal(s["speed"], SCENE.speeds)
    plane = vr.sweep(SCENE, method="plane", speeds=np.array([0.5, 2.0]))
    assert plane["chi"].shape == (2,) and "l" not in plane
    assert plane["code"] == ["converged", "converged"] and plane["reason"] == ["", ""]
    with_results = vr.sweep(SCENE, method="line", threads=1, with_results=True)
    assert [r.chi for r in with_results["results"]] == list(s["chi"])


def test_sweep_equals_serial_solves_within_a_chunk():
    """Within a chunk each speed continues from the previous one: solve(start=) does the same."""
    s = vr.sweep(SCENE, threads=1)
    previous = None
    for i, v in enumerate(SCENE.speeds):
        r = vr.solve(SCENE, speed=float(v), start=previous)
        assert r.chi == s["chi"][i] and r.a0 == s["a0"][i]
        previous = r if r.converged and r.iterations > 0 else None


def test_help_is_readable():
    for f in (vr.solve, vr.sweep, vr.Scene, vr.Scene.from_json, vr.Result, vr.Result.pressure,
              vr.StandardLinearSolid, vr.Elastic, vr.Ellipsoid, vr.Cylinder):
        assert f.__doc__ and len(f.__doc__) > 40, f
    assert "method" in vr.solve.__doc__ and "ValueError" in vr.solve.__doc__
    assert vr.Result.chi.__doc__
