"""The model's validity checks (core/validity.hpp, docs/errors.md "Validity checks") on every
result, as viscoroll-solve's: a breach joins the result's warnings and is a Python UserWarning;
strict=True (or a scene file's "strict") makes it a ValueError."""

import json
import warnings

import pytest

import viscoroll as vr


def paper(mu_d=3.0e6, **scene):
    """The paper's scene (a roller of radius 1/c1 = 50 mm), its modulus `mu_d`."""
    material = vr.StandardLinearSolid(mu_d=mu_d, nu=0.5, f=9.0, tau=0.01)
    return vr.Scene(material, vr.Ellipsoid(c1=20.0, c2=1.596582), load=20.0, **scene)


@pytest.mark.parametrize("method", [None, "line", "bem"])
def test_a_modulus_in_mpa_warns(method):
    """mu_d = 3 (MPa meant, Pa read): a contact ten times wider than the roller; solved, and said."""
    with pytest.warns(UserWarning, match=r"a0 = \S+ is \S+ times the roller radius 0.05") as caught:
        r = vr.solve(paper(mu_d=3.0), method=method, speed=1.0)
    assert r.a0 > 0.05
    # Two (V1) breaches: the scene's long-term static contact, checked before any solve and
    # listed first, and the result's; each with its code, index for index.
    assert len(r.warning_codes) == len(r.warnings)
    breaches = [w for w, c in zip(r.warnings, r.warning_codes) if c == "small_slope"]
    assert len(breaches) == 2
    scene_wide, breach = breaches
    assert scene_wide.startswith("its long-term static contact: a0 = ")
    assert "is a modulus in MPa or GPa" in breach and "is a modulus in MPa or GPa" in scene_wide
    assert any(str(w.message).endswith(breach) for w in caught)
    assert any(str(w.message).startswith("viscoroll: the scene: its long-term") for w in caught)


def test_a_modulus_in_mpa_with_strict_raises_naming_a0_and_the_radius():
    # The scene's long-term static contact breaches before any solve.
    with pytest.raises(ValueError, match=r"strict: the scene: its long-term static contact: "
                                         r"a0 = \S+ is \S+ times the roller radius 0.05") as error:
        vr.solve(paper(mu_d=3.0), speed=1.0, strict=True)
    assert "(without strict this is a warning" in str(error.value)
    with pytest.raises(ValueError, match="roller radius 0.05"):
        vr.sweep(paper(mu_d=3.0), speeds=[0.1, 1.0], strict=True)


def test_a_valid_scene_neither_warns_nor_raises():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for method in ("line", "bem"):
            r = vr.solve(paper(), method=method, speed=1.714, strict=True)
            assert r.converged and r.warnings == [] and r.warning_codes == []
            assert r.code == "converged"


def test_a_sweep_warns_once_and_every_result_carries_its_breach():
    # Three results and the scene's long-term static contact: four breaches, one warning.
    with pytest.warns(UserWarning, match=r"and 3 more breaches in this sweep") as caught:
        s = vr.sweep(paper(mu_d=3.0), speeds=[0.1, 1.0, 10.0], method="line", threads=1)
    assert len(caught) == 1
    assert all(codes.count("small_slope") == 2 for codes in s["warning_codes"])


def test_the_plane_method_is_checked_too():
    scene = vr.Scene(vr.StandardLinearSolid(mu_d=3.0, nu=0.5, f=9.0, tau=0.01),
                     vr.Cylinder(radius=0.05), load=1000.0)
    with pytest.warns(UserWarning, match="roller radius 0.05"):
        r = vr.solve(scene, speed=1.0)
    assert r.method == "plane" and "small_slope" in r.warning_codes


def test_a_density_checks_that_rolling_is_quasi_static():
    """3 MPa glassy, 1100 kg/m^3: a shear-wave speed of 52 m/s; 9.6 m/s is beyond 0.1 of it."""
    scene = paper(density=1100.0)
    assert scene.density == 1100.0 and paper().density is None
    with pytest.warns(UserWarning, match="shear-wave speed"):
        r = vr.solve(scene, method="line", speed=9.637)
    assert "quasi_static" in r.warning_codes
    assert "quasi_static" not in vr.solve(paper(), method="line", speed=9.637).warning_codes
    with pytest.raises(ValueError, match="density"):
        paper(density=-1.0)


def test_a_scene_files_strict_and_density(scenes_dir, tmp_path):
    document = json.loads((scenes_dir / "paper.json").read_text())
    document["material"]["mu_d"] = 3.0
    document.update(strict=True, density=1100.0)
    path = tmp_path / "strict.json"
    path.write_text(json.dumps(document))
    scene = vr.Scene.from_json(path)
    assert scene.strict and scene.density == 1100.0
    assert "strict=True" in repr(scene) and "density=1100" in repr(scene)
    with pytest.raises(ValueError, match="roller radius 0.05"):
        vr.solve(scene, speed=1.0)
    with pytest.warns(UserWarning, match="roller radius 0.05"):
        assert vr.solve(scene, speed=1.0, strict=False).converged
