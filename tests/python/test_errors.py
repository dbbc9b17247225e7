"""Invalid input raises ValueError with the library's (or the scene reader's) message naming the
parameter; non-convergence is on the result, not an exception."""

import json

import numpy as np
import pytest

import viscoroll as vr


def sls(**kw):
    args = dict(mu_d=1.0, nu=0.5, f=9.0, tau=1.0)
    args.update(kw)
    return vr.StandardLinearSolid(**args)


def scene(**kw):
    args = dict(material=sls(), roller=vr.Ellipsoid(c1=1.0, c2=0.08), load=0.06)
    args.update(kw)
    return vr.Scene(**args)


@pytest.mark.parametrize("make,name", [
    (lambda: sls(mu_d=-1.0), "mu_d"),
    (lambda: sls(mu_d=float("nan")), "mu_d"),
    (lambda: sls(nu=0.7), "nu"),
    (lambda: sls(f=-1.0), "f ="),
    (lambda: sls(tau=-1.0), "tau"),
    (lambda: sls(tau=float("inf")), "tau"),
    (lambda: vr.Elastic(mu=0.0, nu=0.3), "mu ="),
    (lambda: vr.Elastic(mu=1.0, nu=-1.0), "nu"),
    (lambda: vr.Ellipsoid(c1=0.0, c2=1.0), "c1"),
    (lambda: vr.Ellipsoid(c1=1.0, c2=-1.0), "c2"),
    (lambda: vr.Cylinder(radius=-1.0), "radius"),
    (lambda: scene(load=0.0), "load"),
    (lambda: scene(speeds=[1.0, -1.0]), "speed"),
    (lambda: scene(speeds=[[1.0]]), "speeds"),
])
def test_constructors_name_the_parameter(make, name):
    with pytest.raises(ValueError, match=name) as error:
        make()
    assert "outside the valid range" in str(error.value) or "speeds" in str(error.value)


@pytest.mark.parametrize("call,name", [
    (lambda: vr.solve(scene(roller=vr.Ellipsoid(c1=1.0, c2=0.5)), method="line", speed=1.0),
     "c2"),
    (lambda: vr.solve(scene(roller=vr.Cylinder(radius=1.0)), method="line", speed=1.0),
     "cylinder"),
    (lambda: vr.solve(scene(), speed=-1.0), "speed"),
    (lambda: vr.solve(scene(), method="line", speed=1.0, grid=0), "grid"),
    (lambda: vr.solve(scene(), method="line", speed=1.0, grid=65), "grid"),
    (lambda: vr.solve(scene(), method="bem", speed=1.0, grid=1), "grid"),
    (lambda: vr.solve(scene(), method="spline", speed=1.0), "method"),
    (lambda: vr.solve(scene()), "speed"),
    (lambda: vr.sweep(scene()), "speed"),
    (lambda: vr.sweep(scene(), speeds=[1.0, float("nan")]), "speed"),
    (lambda: vr.sweep(scene(), speeds=[1.0], threads=-1), "threads"),
    (lambda: vr.sweep(scene(), speeds=[1.0], chunk=0), "chunk"),
    (lambda: vr.solve(scene(), speed=1.0, start=vr.solve(scene(), method="plane", speed=1.0)),
     "start"),
    (lambda: vr.solve(scene(), speed=1.0, setting="quick"), "setting"),
    (lambda: vr.solve(scene(), method="bem", speed=1.0, setting="fast"), "setting"),
    (lambda: vr.sweep(scene(), speeds=[1.0], method="plane", setting="fast"), "setting"),
    # A result of the fast setting does not seed the default one (another solver).
    (lambda: vr.solve(scene(), speed=1.0,
                      start=vr.solve(scene(), speed=1.1, setting="fast")), "start"),
])
def test_solve_and_sweep_name_the_parameter(call, name):
    with pytest.raises(ValueError, match=name):
        call()


def test_bem_results_have_no_strip_functions():
    r = vr.solve(scene(), method="bem", grid=4, speed=1.0)
    with pytest.raises(ValueError, match="bem"):
        r.a(0.0)
    with pytest.raises(AttributeError, match="root"):
        r.root
    x, y, p = r.cell_pressures()
    assert p.shape == (y.size, x.size) and p.dtype == np.float64


def write(tmp_path, document):
    path = tmp_path / "s.json"
    path.write_text(document if isinstance(document, str) else json.dumps(document))
    return path


GOOD = {"material": {"model": "standard_linear_solid", "mu_d": 3e6, "nu": 0.5, "f": 9,
                     "tau": 0.01},
        "roller": {"profile": "ellipsoid", "c1": 20.0, "c2": 1.6}, "load": 20.0,
        "speeds": [0.1, 1.0], "method": "line"}


@pytest.mark.parametrize("edit,message", [
    (lambda d: d["material"].update(f=-1), "material.f = -1 is outside the valid range f >= 0"),
    (lambda d: d.update(speeds=[0.1, "x"]), "speeds[1] must be a number, got string"),
    (lambda d: d["roller"].update(radius=1), "unknown key roller.radius"),
    (lambda d: d["roller"].update(c2=40.0), "roller.c2 = 40 is outside the valid range"),
    (lambda d: d.update(method="spline"), "method"),
    (lambda d: d.pop("load"), "missing key load"),
])
def test_from_json_names_the_key_with_its_path(tmp_path, edit, message):
    document = json.loads(json.dumps(GOOD))
    edit(document)
    path = write(tmp_path, document)
    with pytest.raises(ValueError) as error:
        vr.Scene.from_json(path)
    assert message in str(error.value)
    assert str(error.value).startswith(str(path) + ": "), "the file first, as the command line"


def test_from_json_file_errors(tmp_path):
    with pytest.raises(ValueError, match="no such file"):
        vr.Scene.from_json(tmp_path / "missing.json")
    with pytest.raises(ValueError, match="not valid JSON"):
        vr.Scene.from_json(write(tmp_path, "{"))


@pytest.mark.parametrize("method", [None, "plane", "line", "bem"])
def test_from_json_of_a_prony_scene_with_several_temperatures_asks_for_one(tmp_path, method):
    """A Scene holds one temperature: a file with several raises ValueError naming the file and
    temperature, whatever the method; temperature= picks one."""
    document = json.loads(json.dumps(GOOD))
    document["material"] = {"model": "prony", "nu": 0.5, "g_inf": 1.0e6,
                            "terms": [{"g": 2.0e6, "tau": 1e-3}, {"g": 5.0e5, "tau": 1e-1}],
                            "shift": {"law": "wlf", "c1": 8.86, "c2": 101.6, "t_ref": 25}}
    document["temperature"] = [0, 25]
    if method is None:
        document.pop("method")
    else:
        document["method"] = method
    path = write(tmp_path, document)
    with pytest.raises(ValueError) as error:
        vr.Scene.from_json(path)
    message = str(error.value)
    assert message.startswith(str(path) + ": temperature: the file gives 2 temperatures")
    assert "Scene.from_json(path, temperature=T)" in message
    assert vr.Scene.from_json(path, temperature=0).temperature == 0


def test_temperature_errors_name_the_parameter():
    prony = vr.Prony(g_inf=1e6, nu=0.5, terms=[(2e6, 1e-3)], shift=vr.WLF(8.86, 101.6, 25))
    roller = vr.Ellipsoid(c1=20.0, c2=0.5)
    with pytest.raises(ValueError, match=r"temperature = -80 is outside the valid range "
                                         r"temperature > t_ref - c2 = -76.6"):
        vr.Scene(prony, roller, 100.0, temperature=-80)
    with pytest.raises(ValueError, match="temperature is valid only with a Prony material with "
                                         "a shift law"):
        vr.Scene(vr.Elastic(mu=1e6, nu=0.5), roller, 100.0, temperature=20)
    with pytest.raises(ValueError, match="temperature is valid only with a Prony material with "
                                         "a shift law"):
        vr.Scene(vr.Prony(g_inf=1e6, nu=0.5, terms=[(2e6, 1e-3)]), roller, 100.0, temperature=20)
    with pytest.raises(ValueError, match=r"g_inf = -1 is outside the valid range"):
        vr.Prony(g_inf=-1, nu=0.5, terms=[(2e6, 1e-3)])
    with pytest.raises(ValueError, match=r"rho\[1\] = 0 is outside the valid range"):
        vr.Prony(g_inf=1e6, nu=0.5, terms=[(2e6, 1e-3), (1e6, 0.0)])
    with pytest.raises(ValueError, match=r"c2 = 0 is outside the valid range"):
        vr.WLF(8.86, 0.0, 25)
    with pytest.raises(ValueError, match=r"activation_energy = -1 is outside the valid range"):
        vr.Arrhenius(-1.0, 25)


def test_non_convergence_is_on_the_result():
    # Every result says whether it converged and why it stopped; nothing raises.
    r = vr.solve(scene(), speed=1.0)
    assert isinstance(r.converged, bool) and isinstance(r.reason, str)
    s = vr.sweep(scene(), speeds=[0.1, 1.0, 10.0])
    assert s["converged"].dtype == np.bool_ and len(s["reason"]) == 3
