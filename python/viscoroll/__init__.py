"""viscoroll: the steady contact of a rigid roller rolling on a viscoelastic half space.

Python bindings (pybind11, double precision) of the header-only C++ library viscoroll, which
implements Panek & Kalker (1980): the 3-D line-contact theory of an ellipsoidal roller
(method "line"), Hunter's plane problem of a cylinder ("plane") and an exact 3-D
boundary-element reference ("bem"); "auto", the default, answers by the line method where its
theory applies and its result stands, else by the bem method to 1% in d and chi.

Materials
    StandardLinearSolid(mu_d=, nu=, f=, tau=), Elastic(mu=, nu=),
    Prony(g_inf=, nu=, terms=[(g, tau), ...], shift=None) with WLF(c1=, c2=, t_ref=) or
    Arrhenius(activation_energy=, t_ref=)
Rollers
    Ellipsoid(c1=, c2=), Cylinder(radius=) (plane only), and the rollers of finite length of a
    scene file (line, bem): Crowned(radius=, flat_length=, crown_radius=, length=None,
    tilt=None), Logarithmic(radius=, length=, scale=, end_drop=None, tilt=None),
    Table(radius=, y=, h=, tilt=None), or Roller(profile="crowned", ...) with a scene file's keys
Scenes
    Scene(material=, roller=, load=, speeds=None, temperature=None, density=None,
    substrate=None) (substrate: a layer or a spring bed, {"model": "layer", "thickness": h}),
    Scene.from_json(path, temperature=None) (a scene file of the command line viscoroll-solve,
    docs/cli.md)
Solving
    solve(scene, method=None, grid=None, speed=None, start=None, setting=None,
          tolerance=None, strict=None) -> Result
    sweep(scene, speeds=None, method=None, grid=None, threads=None, chunk=16,
          with_results=False, setting=None, tolerance=None, strict=None) -> dict of arrays
    (setting="fast": the line method's fast setting, about 1 ms a solve, within 1% on the
    paper's scene; tolerance: the bem's relative accuracy in d and chi, default 0.01, or on a
    layer or a spring bed the plane method's in a0, d and chi, default 1e-4;
    strict=True: a breach of the model's assumptions raises ValueError, else it is a warning)
    study(scene, *, method=None, chunk=16, client=None, progress=True, threads=None, ...,
          speed=[...], temperature=[...], load=[...], thickness=[...], radius=[...],
          material={"name": material, ...}) -> xarray.Dataset
    (a grid of scenes over named axes, on every core or on a Dask cluster; needs xarray, tqdm
    and, for a cluster, distributed)
Results
    Result: the command line's output fields as attributes (a0, b0, l, d, chi,
    rolling_resistance, power_loss, energy_per_revolution, pmax, pmax_x, converged, root,
    iterations, residual, reason, code, warnings, warning_codes, method_reason, tolerance_met,
    error_d, error_chi, ...), as_dict(), and pressure(x, y), a(y), b(y),
    f0(y) on NumPy arrays. chi is the rolling-resistance force over the load: F = chi W is
    rolling_resistance, P = chi W V power_loss.

Invalid input raises ValueError with the library's message naming the parameter; a solve that
does not converge is returned with converged == False, a reason and a code, one of the stable
names in STOP_CODES ("converged" otherwise); each warning has its name in WARNING_CODES, so a
program branches on r.code and r.warning_codes, not on the words. The frame moves with the
roller, which travels towards +x; x is measured from its axis. Any consistent units.

Example
-------
>>> import numpy as np, viscoroll as vr
>>> mat = vr.StandardLinearSolid(mu_d=3.0e6, nu=0.5, f=9.0, tau=0.01)   # SI units
>>> scene = vr.Scene(material=mat, roller=vr.Ellipsoid(c1=20.0, c2=1.596582), load=20.0)
>>> r = vr.solve(scene, speed=1.0)              # auto: here the line method, 6 Chebyshev terms
>>> r.method, r.method_reason, r.converged, r.a0, r.chi
>>> p = r.pressure(np.linspace(-0.005, 0.005, 5), 0.0)  # float64 array of shape (5,)
>>> s = vr.sweep(scene, speeds=np.logspace(-3, 3, 61))   # all cores, GIL released
>>> s["chi"].shape, s["converged"].all()

Documentation: docs/python.md of the repository.
"""

from . import _build
_build.check_interpreter()

from . import _viscoroll  # noqa: E402 (after the interpreter's check)
from ._viscoroll import (  # noqa: E402
    WLF,
    Arrhenius,
    Crowned,
    Cylinder,
    Elastic,
    Ellipsoid,
    Logarithmic,
    Material,
    Prony,
    Result,
    Roller,
    Scene,
    Shift,
    StandardLinearSolid,
    Table,
    STOP_CODES,
    WARNING_CODES,
    __version__,
)


def _doc(function):
    """The compiled function's docstring without its leading signature line."""
    signature, _, text = function.__doc__.strip().partition("\n\n")
    return text


def solve(scene, method=None, grid=None, speed=None, start=None, setting=None, tolerance=None,
          strict=None):
    return _viscoroll.solve(scene, method, grid, speed, start, setting, tolerance, strict)


def sweep(scene, speeds=None, method=None, grid=None, threads=None,
          chunk=_viscoroll.DEFAULT_CHUNK, with_results=False, setting=None, tolerance=None,
          strict=None):
    return _viscoroll.sweep(scene, speeds, method, grid, threads, chunk, with_results, setting,
                            tolerance, strict)


from ._study import study  # noqa: E402 (imports xarray, tqdm, distributed only when called)

solve.__doc__ = _doc(_viscoroll.solve)
sweep.__doc__ = _doc(_viscoroll.sweep)

__all__ = [
    "Arrhenius",
    "Crowned",
    "Cylinder",
    "Elastic",
    "Ellipsoid",
    "Logarithmic",
    "Material",
    "Prony",
    "Result",
    "Roller",
    "STOP_CODES",
    "Scene",
    "Shift",
    "StandardLinearSolid",
    "Table",
    "WARNING_CODES",
    "WLF",
    "__version__",
    "solve",
    "study",
    "sweep",
]
