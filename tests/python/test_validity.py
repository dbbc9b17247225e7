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
    breach = [w for w in r.warnings if w.startswith("a0 = ")]
    assert len(breach) == 1 and "is a modulus in MPa or GPa" in breach[0]
    assert any(str(w.message).endswith(breach[0]) for w in caught)
    # The scene's long-term static contact is checked too, before any solve.
    scene_wide = [w for w in r.warnings if w.startswith("its long-term static contact: a0 = ")]
    assert len(scene_wide) == 1 and "is a modulus in MPa or GPa" in scene_wide[0]
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
            assert r.converged and r.warnings == []


def test_a_sweep_warns_once_and_every_result_carries_its_breach():
    # Three results and the scene's long-term static contact: four breaches, one warning.
    with pytest.warns(UserWarning, match=r"and 3 more breaches in this sweep") as caught:
        s = vr.sweep(paper(mu_d=3.0), speeds=[0.1, 1.0, 10.0], method="line", threads=1)
    assert len(caught) == 1
    assert all(any(w.startswith("a0 = ") for w in ws) for ws in s["warnings"])


def test_the_plane_method_is_checked_too():
    scene = vr.Scene(vr.StandardLinearSolid(mu_d=3.0, nu=0.5, f=9.0, tau=0.01),
                     vr.Cylinder(radius=0.05), load=1000.0)
    with pytest.warns(UserWarning, match="roller radius 0.05"):
        r = vr.solve(scene, speed=1.0)
    assert r.method == "plane" and any(w.startswith("a0 = ") for w in r.warnings)


def test_a_density_checks_that_rolling_is_quasi_static():
    """3 MPa glassy, 1100 kg/m^3: a shear-wave speed of 52 m/s; 9.6 m/s is beyond 0.1 of it."""
    scene = paper(density=1100.0)
    assert scene.density == 1100.0 and paper().density is None
    with pytest.warns(UserWarning, match="shear-wave speed"):
        r = vr.solve(scene, method="line", speed=9.637)
    assert any("shear-wave speed" in w for w in r.warnings)
    assert not any("shear-wave speed" in w for w in vr.solve(paper(), method="line",
                                                               speed=9.637).warnings)
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
