"""Scene(substrate=...): the roller on a layer of the rubber bonded to or lying on a rigid base,
or on the belt-conveyor spring bed; the bem method's body (docs/bem.md, B15-B19), the auto
method's choice for it, the plane and line methods' refusal, and the scene file's key."""

import json

import pytest

import viscoroll as vr

RUBBER = vr.StandardLinearSolid(mu_d=3.0e6, nu=0.5, f=4.0, tau=0.002)
IDLER = vr.Ellipsoid(c1=15.748, c2=0.5)


def scene(substrate=None):
    return vr.Scene(RUBBER, IDLER, load=500.0, substrate=substrate)


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


def test_the_line_and_plane_methods_refuse_a_layer_naming_the_bem():
    s = scene({"model": "layer", "thickness": 0.004, "base": "frictionless"})
    with pytest.raises(ValueError, match='is solved by the bem method only: the line method'):
        vr.solve(s, method="line", speed=2.0)
    cylinder = vr.Scene(RUBBER, vr.Cylinder(radius=0.0635), load=5000.0,
                        substrate={"model": "layer", "thickness": 0.004})
    with pytest.raises(ValueError, match='is solved by the bem method only'):
        vr.solve(cylinder, speed=2.0)


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
