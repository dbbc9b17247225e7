"""The rollers of finite length built in Python (Crowned, Logarithmic, Table, and Roller(profile,
**keys)) are a scene file's: the scene reader's checks and messages naming the parameter, and the
same numbers by the line and bem methods, tilted or not. Every result carries the rolling
resistance F = chi W, the power chi W V and the energy per revolution chi W 2 pi R after chi
(docs/cli.md, "Output")."""

import json

import numpy as np
import pytest

import viscoroll as vr

# crowned_roller_line.json's roller and material.
CROWNED = dict(radius=0.05, flat_length=0.05, crown_radius=1.0, length=0.16)


def material():
    return vr.StandardLinearSolid(mu_d=2.0e6, nu=0.5, f=4.0, tau=0.005)


@pytest.mark.parametrize("method,grid", [("line", None), ("bem", 8)])
@pytest.mark.parametrize("tilt", [None, 0.002])
def test_a_crowned_roller_built_in_python_solves_as_the_scene_files(scenes_dir, tmp_path, method,
                                                                    grid, tilt):
    """Bit for bit: the same library profile, scene and solver from either front door."""
    document = json.loads((scenes_dir / "crowned_roller_line.json").read_text())
    if tilt is not None:
        document["roller"]["tilt"] = tilt
    path = tmp_path / "crowned.json"
    path.write_text(json.dumps(document))
    expected = vr.solve(vr.Scene.from_json(path), method=method, grid=grid, speed=0.1).as_dict()
    assert expected["converged"] and expected["method"] == method
    built = (vr.Crowned(**CROWNED, tilt=tilt), vr.Roller(profile="crowned", **CROWNED, tilt=tilt))
    for roller in built:
        got = vr.solve(vr.Scene(material(), roller, load=100.0), method=method, grid=grid,
                       speed=0.1).as_dict()
        assert list(got) == list(expected)
        for key, value in expected.items():
            if key != "seconds":
                assert got[key] == value, f"{roller!r} {method}: {key}"
    if tilt is not None:  # the tilted contact is asymmetric in both methods
        assert expected["y_minus"] + expected["y_plus"] < 0


def test_every_profile_solves_by_line_and_bem():
    """Logarithmic and Table, as Crowned: a converged contact inside the roller by both methods,
    and a sweep of the bem method."""
    y = [-0.08, -0.06, -0.04, 0.0, 0.04, 0.06, 0.08]
    h = [2.0e-3, 5.0e-4, 0.0, 0.0, 0.0, 5.0e-4, 2.0e-3]
    for roller in (vr.Logarithmic(radius=0.05, length=0.16, scale=5.0e-4),
                   vr.Table(radius=0.05, y=y, h=h, tilt=0.001)):
        scene = vr.Scene(material(), roller, load=100.0)
        for method, grid in (("line", None), ("bem", 8)):
            r = vr.solve(scene, method=method, grid=grid, speed=0.1)
            assert r.converged, (roller, method, r.reason)
            assert -0.08 < r.y_minus < r.y_plus < 0.08
        s = vr.sweep(scene, speeds=[0.1, 1.0], method="bem", grid=8, threads=1)
        assert s["converged"].all()


@pytest.mark.parametrize("make,message", [
    (lambda: vr.Crowned(radius=-1.0, flat_length=0.05, crown_radius=1.0),
     "viscoroll: radius = -1 is outside the valid range radius > 0"),
    (lambda: vr.Crowned(radius=0.05, flat_length=-0.01, crown_radius=1.0), "flat_length = -0.01"),
    (lambda: vr.Crowned(radius=0.05, flat_length=0.05, crown_radius=0.0), "crown_radius = 0"),
    (lambda: vr.Crowned(radius=0.05, flat_length=0.05, crown_radius=1.0, length=0.04),
     "length = 0.04 is outside the valid range length > flat_length"),
    (lambda: vr.Crowned(**CROWNED, tilt=0.2), "tilt = 0.2 is outside the valid range |tilt| < 0.1"),
    (lambda: vr.Crowned(radius="5 cm", flat_length=0.05, crown_radius=1.0),
     "radius must be a number, got string"),
    (lambda: vr.Logarithmic(radius=0.05, length=0.0, scale=2.0e-5), "length = 0"),
    (lambda: vr.Logarithmic(radius=0.05, length=0.16, scale=-1.0), "scale = -1"),
    (lambda: vr.Logarithmic(radius=0.05, length=0.16, scale=2.0e-5, end_drop=0.0), "end_drop = 0"),
    (lambda: vr.Table(radius=0.05, y=[-1.0, 0.0, 1.0], h=[0.0, 0.0, 0.0]), "y has 3 values"),
    (lambda: vr.Table(radius=0.05, y=[-2.0, -1.0, 1.0, 2.0], h=[0.0, 0.0, 0.0]), "h has 3 values"),
    (lambda: vr.Table(radius=0.05, y=[-2.0, 1.0, -1.0, 2.0], h=[0.0] * 4), "y[2] = -1"),
    (lambda: vr.Roller(profile="crowned", radius=0.05), "missing key flat_length"),
    (lambda: vr.Roller(profile="crowned", **CROWNED, camber=1.0), "unknown key camber"),
    (lambda: vr.Roller(profile="spline", radius=0.05), "profile = 'spline' is not one of"),
    (lambda: vr.Roller(profile="ellipsoid", c1=1.0, c2=0.1), "Ellipsoid(c1, c2)"),
])
def test_bad_roller_parameters_raise_value_error_naming_them(make, message):
    with pytest.raises(ValueError) as error:
        make()
    assert message in str(error.value)


def rolling_radius(roller):
    return roller.radius if hasattr(roller, "radius") else 1 / roller.c1


@pytest.mark.parametrize("file,method,grid", [("paper.json", None, None),
                                              ("rubber_ball.json", None, None),
                                              ("polyamide_cylinder.json", None, None),
                                              ("crowned_roller_line.json", "bem", 8),
                                              ("press_roll.json", None, None)])
def test_results_carry_force_power_and_energy_per_revolution(scenes_dir, file, method, grid):
    """F = chi W, P = chi W V, E = chi W 2 pi R (R the roller's radius, an ellipsoid's 1/c1),
    the fields after chi. Each is the same products of the same doubles, rounded in the order of
    evaluation: at most four roundings of eps/2 each, so two orders differ by under 2 eps; the
    test allows 4 eps."""
    scene = vr.Scene.from_json(scenes_dir / file)
    s = vr.sweep(scene, method=method, grid=grid, threads=1, with_results=True)
    assert s["converged"].all()
    load, radius, speed, chi = scene.load, rolling_radius(scene.roller), s["speed"], s["chi"]
    tolerance = 4 * np.finfo(float).eps
    for key, expected in (("rolling_resistance", chi * load),
                          ("power_loss", chi * load * speed),
                          ("energy_per_revolution", chi * load * 2 * np.pi * radius)):
        assert s[key].dtype == np.float64
        assert np.all(np.abs(s[key] - expected) <= tolerance * np.abs(expected)), key
        assert all(getattr(r, key) == s[key][i] for i, r in enumerate(s["results"]))
    keys = list(s["results"][0].as_dict())
    at = keys.index("chi")
    assert keys[at + 1:at + 4] == ["rolling_resistance", "power_loss", "energy_per_revolution"]
