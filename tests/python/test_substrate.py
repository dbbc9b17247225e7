"""Scene(substrate=...): the roller on a layer of the rubber bonded to or lying on a rigid base,
or on the belt-conveyor spring bed; the bem method's body (docs/bem.md, B15-B19), the plane
method's for a cylinder (PlaneSubstrateSolver, docs/plane-substrate.md), the auto method's choice
of them, the line method's refusal, and the scene file's key."""

import json
import subprocess

import pytest

import viscoroll as vr

RUBBER = vr.StandardLinearSolid(mu_d=3.0e6, nu=0.5, f=4.0, tau=0.002)
IDLER = vr.Ellipsoid(c1=15.748, c2=0.5)
CYLINDER = vr.Cylinder(radius=0.0635)


def scene(substrate=None):
    return vr.Scene(RUBBER, IDLER, load=500.0, substrate=substrate)


def cylinder(substrate=None):
    """The idler as the plane method's cylinder, 1000 N per metre."""
    return vr.Scene(RUBBER, CYLINDER, load=1000.0, substrate=substrate)


def test_a_cover_is_stiffer_than_the_half_space_and_d_is_from_its_base():
    half = vr.solve(scene(), method="bem", speed=2.0, grid=12)
    cover = vr.solve(scene({"model": "layer", "thickness": 0.004}), method="bem", speed=2.0,
                     grid=12)
    assert half.converged and cover.converged
    assert cover.d < half.d and cover.a0 < half.a0
    # The same layer 1e4 contacts thick is the half space in chi and the contact's size, to 1e-6
    # (docs/bem.md, "The half space as h -> inf").
    thick = vr.solve(scene({"model": "layer", "thickness": 1e4 * half.a_long_term}),
                     method="bem", speed=2.0, grid=12)
    assert abs(thick.chi / half.chi - 1) <= 1e-6
    assert abs(thick.a0 / half.a0 - 1) <= 1e-6


def test_the_auto_method_answers_a_layer_by_the_bem_and_says_why():
    s = scene({"model": "spring_bed", "thickness": 0.004})
    r = vr.solve(s, speed=2.0)
    assert r.method == "bem" and r.converged
    assert r.method_reason == ("auto: bem (the substrate is a spring_bed (thickness 0.004 m); "
                               "the line theory is the half space's)")


def test_the_line_method_refuses_a_layer_naming_the_bem():
    s = scene({"model": "layer", "thickness": 0.004, "base": "frictionless"})
    with pytest.raises(ValueError, match='substrate.model = "layer" is solved by the bem method, '
                                         'and on a "cylinder" roller by the plane method, not by '
                                         "line: the line method's theory is the half space's"):
        vr.solve(s, method="line", speed=2.0)


def test_the_plane_method_on_a_bonded_layer_agrees_with_the_command_line(viscoroll_solve,
                                                                          tmp_path):
    """The plane method on a cylinder on a bonded layer: PlaneSubstrateSolver at the default
    tolerance 1e-4, converged with its estimates within it, d from the base; the same record as
    viscoroll-solve's on the same scene file to that tolerance (the same solver: in fact equal)."""
    layer = {"model": "layer", "thickness": 0.004, "base": "bonded"}
    r = vr.solve(cylinder(layer), method="plane", speed=2.0)
    assert r.method == "plane" and r.converged, r.as_dict()
    assert r.tolerance == 1e-4 and r.terms > 0
    assert r.substrate == "layer (thickness 0.004 m, bonded)"
    assert r.error_a0 <= 1e-4 * r.a0 and r.error_d <= 1e-4 * r.d
    assert r.error_chi <= 1e-4 * r.chi
    with pytest.raises(AttributeError):
        r.a_long_term  # the solver computes no static long-term contact
    assert r.code == "converged" and r.reason == ""
    path = tmp_path / "layer.json"
    path.write_text(json.dumps({
        "material": {"model": "standard_linear_solid", "mu_d": 3e6, "nu": 0.5, "f": 4,
                     "tau": 0.002},
        "roller": {"profile": "cylinder", "radius": 0.0635},
        "load": 1000, "speeds": [2.0], "method": "plane", "substrate": layer}))
    done = subprocess.run([str(viscoroll_solve), "--scene", str(path)], capture_output=True,
                          text=True, check=False)
    assert done.returncode == 0, done.stderr
    line = json.loads(done.stdout)
    assert list(line) == list(r.as_dict())
    for key in ("a0", "d", "chi"):
        assert abs(line[key] - getattr(r, key)) <= 1e-6 * abs(line[key]), key
    assert line["terms"] == r.terms
    assert vr.Scene.from_json(path).substrate == layer
    # A thicker layer tends to the half space (Hunter's closed form) as (a/h)^2
    # (docs/plane-substrate.md, "Accuracy").
    thick = vr.solve(cylinder({"model": "layer", "thickness": 0.4}), method="plane", speed=2.0)
    half = vr.solve(cylinder(), method="plane", speed=2.0)
    assert thick.converged and r.a0 < thick.a0
    assert abs(thick.a0 / half.a0 - 1) <= 1e-3 and abs(thick.chi / half.chi - 1) <= 1e-3


def test_the_auto_method_answers_a_cylinder_on_a_spring_bed_by_the_plane_method():
    bed = cylinder({"model": "spring_bed", "thickness": 0.004})
    r = vr.solve(bed, speed=2.0)
    assert r.method == "plane" and r.converged and r.d > 0
    assert r.method_reason == ("auto: plane (a cylinder on a spring_bed (thickness 0.004 m): the "
                               "plane problem on the substrate, to the tolerance 1e-04 in a, d and "
                               "chi)")
    assert r.terms == 0  # the bed's closed form
    assert vr.solve(bed, speed=2.0, start=r).d == r.d  # the plane method takes no start
    s = vr.sweep(bed, speeds=[0.2, 2.0], threads=1)
    assert s["method_reason"] == [r.method_reason] * 2
    assert s["d"][1] == r.d and s["d"][0] > s["d"][1]
    assert vr.solve(bed, speed=2.0, tolerance=1e-4).tolerance == 1e-4
    with pytest.raises(ValueError, match=r"tolerance = 0 is outside the valid range 64 eps = "
                                         r"1.4e-14 <= tolerance <= 0.1 for the plane method"):
        vr.solve(bed, speed=2.0, tolerance=0)


def test_the_substrate_reads_back_and_bad_keys_are_named():
    s = scene({"model": "layer", "thickness": 0.004})
    assert s.substrate == {"model": "layer", "thickness": 0.004, "base": "bonded"}
    assert scene().substrate == {"model": "half_space"}
    assert "substrate={'model': 'layer', 'thickness': 0.004, 'base': 'bonded'}" in repr(s)
    with pytest.raises(ValueError, match="substrate.thickness = 0 is outside the valid range "
                                         r"thickness > 0 \(m, finite\)"):
        scene({"model": "layer", "thickness": 0.0})
    with pytest.raises(ValueError, match='substrate.model = "slab" is not one of'):
        scene({"model": "slab", "thickness": 0.004})


def test_the_scene_files_key_is_read(tmp_path):
    path = tmp_path / "idler.json"
    path.write_text(json.dumps({
        "material": {"model": "standard_linear_solid", "mu_d": 3e6, "nu": 0.5, "f": 4,
                     "tau": 0.002},
        "roller": {"profile": "ellipsoid", "c1": 15.748, "c2": 0.5},
        "load": 500, "speeds": [2.0],
        "substrate": {"model": "layer", "thickness": 0.004, "base": "frictionless"}}))
    s = vr.Scene.from_json(path)
    assert s.substrate == {"model": "layer", "thickness": 0.004, "base": "frictionless"}
    by_file = vr.solve(s, method="bem", speed=2.0, grid=12)
    by_call = vr.solve(scene({"model": "layer", "thickness": 0.004, "base": "frictionless"}),
                       method="bem", speed=2.0, grid=12)
    assert by_file.chi == by_call.chi and by_file.d == by_call.d
