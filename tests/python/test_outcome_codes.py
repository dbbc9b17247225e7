"""Outcomes a program can read (docs/errors.md, "Outcome codes"): every result carries `code`
beside `reason` and `warning_codes` beside `warnings`, index for index, each a stable name of
viscoroll.STOP_CODES or viscoroll.WARNING_CODES."""

import pytest

import viscoroll as vr

PAPER = vr.Scene(vr.StandardLinearSolid(mu_d=3.0e6, nu=0.5, f=9.0, tau=0.01),
                 vr.Ellipsoid(c1=20.0, c2=1.596582), load=20.0)


def check(result):
    assert result.code in vr.STOP_CODES
    assert (result.code == "converged") == result.converged
    assert len(result.warning_codes) == len(result.warnings)
    assert all(c in vr.WARNING_CODES for c in result.warning_codes)


def test_the_names_are_the_enums():
    assert vr.STOP_CODES[0] == "converged" and len(set(vr.STOP_CODES)) == len(vr.STOP_CODES)
    assert {"iteration_limit", "not_a_contact", "contact_reaches_body_end",
            "tolerance_not_met"} <= set(vr.STOP_CODES)
    assert {"small_slope", "least_squares_minimum", "tolerance_not_verified",
            "chi_negative"} <= set(vr.WARNING_CODES)


@pytest.mark.parametrize("method", ["line", "bem", "plane"])
def test_every_method_has_a_code(method):
    scene = PAPER if method != "plane" else vr.Scene(PAPER.material, vr.Cylinder(radius=0.05),
                                                     load=1000.0)
    r = vr.solve(scene, method=method, speed=0.5419)
    check(r)
    assert r.code == "converged"


def test_a_stopped_iteration_and_a_breach_have_their_codes(scenes_dir):
    """The line method on a conveyor idler, whose contact reaches the roller's ends: its start
    lies outside the line equations' domain; a modulus in MPa: the (V1) breach's code."""
    idler = vr.Scene.from_json(scenes_dir / "conveyor_idler.json", temperature=0)
    r = vr.solve(idler, method="line", speed=4.0)
    check(r)
    assert not r.converged and r.code == "outside_domain"
    with pytest.warns(UserWarning):
        mistake = vr.solve(vr.Scene(vr.StandardLinearSolid(mu_d=3.0, nu=0.5, f=9.0, tau=0.01),
                                    vr.Ellipsoid(c1=20.0, c2=1.596582), load=20.0),
                           method="line", speed=1.0)
    check(mistake)
    assert "small_slope" in mistake.warning_codes


def test_a_sweep_carries_the_codes_per_speed():
    s = vr.sweep(PAPER, speeds=[0.01, 1.0, 100.0], method="line", threads=1)
    assert len(s["code"]) == 3 and len(s["warning_codes"]) == 3
    for converged, code, texts, codes in zip(s["converged"], s["code"], s["warnings"],
                                             s["warning_codes"]):
        assert (code == "converged") == converged and code in vr.STOP_CODES
        assert len(codes) == len(texts)
