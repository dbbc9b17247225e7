"""A Prony material from Python (docs/python.md, "Materials with a spectrum"): one relaxation
term equals the standard linear solid of its creep form in each method; a temperature is the
reference material with every time multiplied by a_T; the records carry temperature, a_T and
active_terms as the command line's; the line method takes a crowned roller on a spectrum; the
shipped prony scene agrees with viscoroll-solve."""

import json
import math
import subprocess

import pytest

import viscoroll as vr

MU_D, F, TAU = 3e6, 9.0, 0.01
# One relaxation term whose creep form is (F, TAU): G(t) = G_inf + g e^(-t/rho) with
# G_inf = mu_d/(1 + f), g = mu_d f/(1 + f), rho = tau/(1 + f) (docs/materials.md).
ONE_TERM = dict(g_inf=MU_D / (1 + F), nu=0.5, terms=[(MU_D * F / (1 + F), TAU / (1 + F))])
ROLLERS = {"plane": (vr.Cylinder(radius=0.05), 2000.0),
           "line": (vr.Ellipsoid(c1=20.0, c2=0.5), 100.0),
           "bem": (vr.Ellipsoid(c1=20.0, c2=0.5), 100.0)}
# plane and line hand one active term to the standard linear solid's solver: the same digits up
# to the creep conversion's rounding of tau (a few ulps), so 1e-12. The bem iteration stops at a
# relative residual of 1e-10, so an ulp in tau may move it by about that: 1e-9 (docs/cli.md).
TOLERANCE = {"plane": 1e-12, "line": 1e-12, "bem": 1e-9}


def relative(a, b):
    return abs(a - b) / max(abs(a), abs(b))


@pytest.mark.parametrize("method", ["plane", "line", "bem"])
def test_one_term_equals_the_standard_linear_solid(method):
    roller, load = ROLLERS[method]
    grid = None if method == "plane" else 4
    prony = vr.Scene(vr.Prony(**ONE_TERM), roller, load)
    sls = vr.Scene(vr.StandardLinearSolid(mu_d=MU_D, nu=0.5, f=F, tau=TAU), roller, load)
    for speed in (0.01, 1.0):
        a = vr.solve(prony, method=method, grid=grid, speed=speed)
        b = vr.solve(sls, method=method, grid=grid, speed=speed)
        assert a.converged and b.converged
        keys = ["a0", "b0", "chi", "a_long_term"] + (["l", "d"] if method != "plane" else [])
        for key in keys:
            assert relative(getattr(a, key), getattr(b, key)) <= TOLERANCE[method], (key, speed)
        fields = a.as_dict()
        assert "tau" not in fields and "vtau" not in fields
        assert math.isnan(fields["temperature"]) and fields["a_T"] == 1.0
        if method != "bem":
            assert fields["active_terms"] == 1


def test_a_temperature_is_the_reference_material_with_every_time_times_a_t():
    wlf = vr.WLF(c1=8.86, c2=101.6, t_ref=25.0)
    terms = [(3.0e7, 1e-4), (6.0e6, 1e-2), (1.0e6, 1.0)]
    at_zero = vr.Scene(vr.Prony(g_inf=2.5e6, nu=0.5, terms=terms, shift=wlf),
                       vr.Cylinder(radius=0.05), 2000.0, temperature=0.0)
    a_t = wlf.factor(0.0)
    assert a_t > 1  # colder: every time longer
    shifted = vr.Scene(vr.Prony(g_inf=2.5e6, nu=0.5, terms=[(g, rho * a_t) for g, rho in terms]),
                       vr.Cylinder(radius=0.05), 2000.0)
    for speed in (1e-3, 0.1):
        a = vr.solve(at_zero, method="plane", speed=speed)
        b = vr.solve(shifted, method="plane", speed=speed)
        assert a.temperature == 0.0 and a.a_T == a_t
        # the same material up to the rounding of rho a_T: 1e-13
        for key in ("a0", "b0", "chi", "pmax"):
            assert relative(getattr(a, key), getattr(b, key)) <= 1e-13, key
        assert a.active_terms >= 2


def test_the_line_method_gives_the_shape_not_the_pressure():
    scene = vr.Scene(vr.Prony(g_inf=2.5e6, nu=0.5, terms=[(3.0e7, 1e-4), (6.0e6, 1e-2)]),
                     vr.Ellipsoid(c1=20.0, c2=0.5), 100.0)
    r = vr.solve(scene, method="line", speed=0.01)
    assert r.converged and r.terms == 4  # a Prony material's default grid
    assert r.active_terms == 2
    assert r.a(0.0) == r.a0 and r.b(0.0) == r.b0 and r.f0(0.0) > 0
    with pytest.raises(AttributeError, match="gives no pmax"):
        r.pmax
    with pytest.raises(ValueError, match="pressure\\(x, y\\) is not available for the line "
                                         "method with a Prony material"):
        r.pressure(0.0, 0.0)
    s = vr.sweep(scene, speeds=[0.01, 0.1], method="line", threads=1)
    assert s["converged"].all() and list(s["active_terms"]) == [2, 2]
    assert s["a0"][0] == r.a0  # the sweep's first speed is a cold start, as solve()


def test_the_line_method_gives_the_pressure_where_at_most_one_term_is_active():
    """A spectrum with its fast term relaxed (V tau_1 <= sqrt(eps) a0) has one active term and
    the standard linear solid's strips, pressure included; with both relaxed, Hertz's:
    p(0, 0) = C1 a0 / (2 pi c (1 + F)) with the long-term compliance c (1 + F) = (1 - nu)/(2 pi
    g_inf), to rounding. At 1e-7 m/s the one active term moves it by O(V tau_2/a0) = 3e-7."""
    g_inf, c1 = 2.5e6, 20.0
    scene = vr.Scene(vr.Prony(g_inf=g_inf, nu=0.5, terms=[(3.0e7, 1e-4), (6.0e6, 1e-2)]),
                     vr.Ellipsoid(c1=c1, c2=0.5), 100.0)
    hertz = vr.solve(scene, method="line", speed=1e-9)
    assert hertz.converged and hertz.active_terms == 0
    long_term = 0.5 / (2 * math.pi * g_inf)
    p0 = c1 * hertz.a0 / (2 * math.pi * long_term)
    assert abs(hertz.pressure(0.0, 0.0) - p0) <= 1e-12 * p0
    one = vr.solve(scene, method="line", speed=1e-7)
    assert one.converged and one.active_terms == 1
    assert abs(one.pressure(one.b0, 0.0) - p0) <= 1e-5 * p0
    two = vr.solve(scene, method="line", speed=1e-3)
    assert two.active_terms == 2
    with pytest.raises(ValueError, match="active_terms is 2"):
        two.pressure(0.0, 0.0)


def test_the_line_method_solves_a_crowned_roller_on_a_spectrum(scenes_dir):
    """LineSolver<PronyRelaxation>::solve(LineProfileScene) from a scene file: the three terms
    active at every speed, the load's edge peak just past the flat part's ends (|y| = 25 mm)."""
    scene = vr.Scene.from_json(scenes_dir / "crowned_roller_prony_line.json")
    assert isinstance(scene.material, vr.Prony) and type(scene.roller) is vr.Crowned
    s = vr.sweep(scene, threads=1)
    assert s["converged"].all() and list(s["active_terms"]) == [3, 3, 3]
    r = vr.solve(scene, speed=1.0)
    assert r.converged and r.terms == 4 and r.y_plus == r.l
    assert 0.025 < abs(r.f0_max_y) < 0.04
    # f0(y) is the load per length times the long-term compliance: the peak's ratio holds at y = 0.
    assert r.f0(r.f0_max_y) > r.f0(0.0) > 0
    with pytest.raises(ValueError, match="pressure\\(x, y\\) is not available"):
        r.pressure(0.0, 0.0)


@pytest.mark.parametrize("method, grid, speeds", [("bem", None, [0.001, 0.01]), ("line", None, [0.01])])
def test_the_shipped_prony_scene_agrees_with_the_command_line(scenes_dir, viscoroll_solve, method,
                                                              grid, speeds):
    path = scenes_dir / "rubber_prony_bem.json"
    scene = vr.Scene.from_json(path, temperature=0.0)
    assert scene.temperature == 0.0 and isinstance(scene.material, vr.Prony)
    assert len(scene.material.terms) == 12 and isinstance(scene.material.shift, vr.WLF)
    # The same computation in two builds (the extension module and the program are compiled
    # apart, and their roundings differ): the BEM's and the plane's answers agree to rounding; the
    # spectrum's line equations are solved to the iteration's stopping step, eps^0.6 (1 + max|x|)
    # = 4e-10 (1 + max|x|) in the unknowns, and a(0) sums N + 1 = 5 of them: at this scene's root
    # (a residual 8e-10 at the stop) the two builds' a(0) differ by 4.7e-9.
    # The iteration's path (its count, its last residual and which stopping test ended it)
    # differs between the builds there: one stops on Levenberg-Marquardt's step test, the other at
    # the residual's floor (docs/line-solver.md).
    tolerance = 1e-8 if method == "line" else 1e-12
    skipped = {"seconds"} | ({"iterations", "residual", "reason"} if method == "line" else set())
    for speed in speeds:  # one run per speed: a cold start, as solve()
        args = [str(viscoroll_solve), "--scene", str(path), "--temperature", "0",
                "--method", method, "--speed", repr(speed)]
        if grid:
            args += ["--grid", str(grid)]
        done = subprocess.run(args, capture_output=True, text=True, check=False)
        assert done.returncode == 0, done.stderr
        (want,) = [json.loads(line) for line in done.stdout.splitlines()]
        got = vr.solve(scene, method=method, grid=grid, speed=speed).as_dict()
        assert list(got) == list(want), "the command line's fields in its order"
        for key, value in want.items():
            if key in skipped:
                continue
            if isinstance(value, float):
                assert relative(got[key], value) <= tolerance or got[key] == value, key
            else:
                assert got[key] == value, key
