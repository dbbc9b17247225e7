"""viscoroll.study: a design study, a scene solved over a grid of named axes (speed, temperature,
load, thickness, the roller's dimensions, materials), returned as an xarray.Dataset; on every core
of this machine or, as Dask tasks, on a cluster (docs/python.md, "Studies: labelled arrays, all
cores, a Dask cluster").

The grid's scenes, in C order over the axes (the last axis varies fastest), are cut into chunks of
`chunk` consecutive scenes. Locally every chunk is solved in C++ by _viscoroll.solve_items, the
engine of sweep() (viscoroll::sweep_scenes: continuation within a chunk, the chunks on threads,
the GIL released); on a Dask cluster each chunk is one task calling the same function with one
thread. Either way the numbers are the same bit for bit.

xarray, tqdm and distributed are imported by study() only, so that `import viscoroll` needs none
of them.
"""

import difflib
import importlib
import itertools
import uuid
import warnings
from collections.abc import Mapping

import numpy as np

from . import _viscoroll

# The output fields of a Result (Result.as_dict(), docs/cli.md "Output"): units and long name.
# SI units, as the scene's inputs are (any consistent units work; the labels then do not). "1" is
# dimensionless (ratios, counts, flags). A pair of units is (line and bem: for the roller,
# plane: per unit length of the roller). None: a string, no units.
FIELDS = {
    "method": (None, "method that answered (plane, line or bem)"),
    "method_reason": (None, "why the auto method answered by that method"),
    "tau": ("s", "relaxation time of the standard linear solid"),
    "temperature": ("degC", "temperature of the Prony material"),
    "a_T": ("1", "time-temperature shift factor a_T"),
    "speed": ("m/s", "rolling speed"),
    "vtau": ("m", "memory length V tau"),
    "a0": ("m", "half width of the contact at y = 0"),
    "b0": ("m", "offset of the contact's centre at y = 0 ahead of the axis"),
    "l": ("m", "half length of the contact along the axis"),
    "y_minus": ("m", "lower end of the contact along the axis"),
    "y_plus": ("m", "upper end of the contact along the axis"),
    "f0_max": ("N/m", "largest load per unit length along the roller"),
    "f0_max_y": ("m", "where the load per unit length is largest"),
    "d": ("m", "penetration (on a layer or a spring bed from the rigid base)"),
    "a_long_term": ("m", "half width of the static long-term contact"),
    "l0": ("m", "half length of the static long-term contact"),
    "d0": ("m", "penetration of the static long-term contact"),
    "chi": ("1", "rolling-friction coefficient chi = F/W"),
    "rolling_resistance": (("N", "N/m"), "rolling-resistance force F = chi W"),
    "power_loss": (("W", "W/m"), "power lost to rolling resistance P = chi W V"),
    "energy_per_revolution": (("J", "J/m"), "energy lost per revolution E = chi W 2 pi R"),
    "pmax": ("Pa", "peak pressure on y = 0"),
    "pmax_x": ("m", "where the peak pressure on y = 0 is"),
    "active_terms": ("1", "retardation terms neither relaxed nor glassy at the speed"),
    "spectrum_error": ("1", "bound on the relative error of the merged spectrum"),
    "seconds": ("s", "run time of the solve"),
    "converged": ("1", "the iteration met its tolerance"),
    "root": ("1", "the line equations have a root (not a least-squares minimum)"),
    "iterations": ("1", "iterations"),
    "residual": ("1", "final residual"),
    "terms": ("1", "Chebyshev terms"),
    "gmres_iterations": ("1", "Krylov iterations of the bem"),
    "grid": ("1", "bem elements per semi-axis of the grid that answered"),
    "cells": ("1", "bem cells of the grid that answered"),
    "tolerance": ("1", "relative tolerance asked"),
    "tolerance_met": ("1", "the error estimates met the tolerance"),
    "error_d": ("m", "estimated error of d"),
    "error_chi": ("1", "estimated error of chi"),
    "error_a0": ("m", "estimated error of a0"),
    "error_b0": ("m", "estimated error of b0"),
    "error_l": ("m", "estimated error of l"),
    "error_pmax": ("Pa", "estimated error of pmax"),
    "substrate": (None, "the body under the roller (plane on a layer or a spring bed)"),
    "reason": (None, "why the iteration stopped (empty where the method gives none)"),
    "code": (None, "why the iteration stopped, a name of viscoroll.STOP_CODES"),
    "warnings": (None, "the solver's warnings and the validity checks' breaches, one per line"),
    "warning_codes": (None, "the warnings' names of viscoroll.WARNING_CODES, one per line"),
}

# The axes other than the roller's arguments: units (a pair as in FIELDS) and long name.
AXES = {
    "speed": ("m/s", "rolling speed"),
    "temperature": ("degC", "temperature of the Prony material"),
    "load": (("N", "N/m"), "load (plane: per unit length)"),
    "thickness": ("m", "thickness of the layer or spring bed"),
    "material": (None, "material"),
}

# The roller's arguments as axes (any scalar argument of the scene's roller's constructor).
ROLLER_AXES = {
    "radius": ("m", "roller radius"),
    "c1": ("1/m", "curvature across the rolling direction"),
    "c2": ("1/m", "curvature along the axis"),
    "flat_length": ("m", "length of the roller's flat part"),
    "crown_radius": ("m", "radius of the roller's crowns"),
    "length": ("m", "roller length"),
    "scale": ("m", "scale of the logarithmic crown"),
    "end_drop": ("m", "end drop of the logarithmic crown"),
    "tilt": ("rad", "misalignment of the roller"),
}


def _require(module, debian, needed_for):
    """The module, else an ImportError naming the Debian package that provides it."""
    try:
        return importlib.import_module(module)
    except ImportError as error:
        raise ImportError(
            f"viscoroll.study needs {module} ({needed_for}): on Debian apt-get install {debian} "
            f"(scripts/install-deps.sh installs it); with pip, the extra 'study' (pip install "
            f"'.[study]' in the repository); {error}") from error


def _units(units, per_length):
    return units[per_length] if isinstance(units, tuple) else units


def _fail(message):
    raise ValueError("viscoroll: study(): " + message)


def _axes(scene, given):
    """The study's axes as (name, values, coordinate) in the order given, speed last where it is
    not given (the scene's speeds); checked before any solve."""
    roller_arguments = scene.roller._arguments
    roller_names = [k for k, v in roller_arguments.items() if not isinstance(v, list)]
    known = list(AXES) + roller_names
    out = []
    for name, values in given.items():
        if name not in known:
            roller = type(scene.roller).__name__
            if name in ROLLER_AXES:
                _fail(f"{name}= is not an argument of the scene's roller {roller} (its "
                      f"arguments: {', '.join(roller_names)})")
            close = difflib.get_close_matches(name, known, n=1)
            hint = f" (did you mean {close[0]}=?)" if close else ""
            _fail(f"{name}= is not an axis{hint}: the axes are speed, temperature, load, "
                  f"thickness, material and the arguments of the scene's roller {roller}: "
                  f"{', '.join(roller_names)}")
        if name == "material":
            if not isinstance(values, Mapping):
                _fail(f"material= must be a dict of name -> material, got {type(values).__name__}")
            if not values:
                _fail("material = {} is empty: an axis needs at least one value")
            for label, material in values.items():
                if not isinstance(label, str):
                    _fail(f"material= labels must be str, got {label!r}")
                if not isinstance(material, _viscoroll.Material):
                    _fail(f"material[{label!r}] = {material!r} is not a viscoroll material")
            out.append((name, list(values.values()), np.array(list(values), dtype=object)))
            continue
        if isinstance(values, (str, bytes)):
            _fail(f"{name} = {values!r} is a string, not a 1-D sequence of numbers")
        try:
            array = np.asarray(values, dtype=np.float64)
        except (TypeError, ValueError) as error:
            raise ValueError(f"viscoroll: study(): {name} = {values!r} must be a 1-D sequence of "
                             f"numbers ({error})") from error
        if array.ndim != 1:
            _fail(f"{name} = {values!r} must be a 1-D sequence of numbers (one value: [x])")
        if array.size == 0:
            _fail(f"{name} = {values!r} is empty: an axis needs at least one value")
        if name == "thickness" and scene.substrate["model"] == "half_space":
            _fail("thickness= needs a scene on a layer or a spring bed (Scene(..., substrate="
                  "{'model': 'layer', 'thickness': h, 'base': 'bonded'})); this scene's substrate "
                  "is the half space")
        out.append((name, list(array), array))
    if "speed" not in given:
        speeds = np.asarray(scene.speeds, dtype=np.float64)
        if speeds.size == 0:
            _fail("needs speeds: give speed=[...] or a scene with speeds")
        out.append(("speed", list(speeds), speeds))
    return out, roller_arguments


def _scenes(scene, axes, roller_arguments):
    """The scene of every point of the axes other than speed, in C order."""
    base = scene.__getstate__()
    base["speeds"] = []
    others = [(name, values) for name, values, _ in axes if name != "speed"]
    scenes = []
    for point in itertools.product(*(range(len(values)) for _, values in others)):
        state = dict(base)
        roller = dict(roller_arguments)
        at = {}
        for (name, values), k in zip(others, point):
            value = values[k]
            at[name] = value
            if name in ("material", "temperature", "load"):
                state[name] = value
            elif name == "thickness":
                state["substrate"] = dict(base["substrate"], thickness=value)
            else:
                roller[name] = value
        if "material" in at and "temperature" not in at:
            # The scene's temperature for a material with a shift law (its t_ref where the scene
            # has none), none for the others.
            material = at["material"]
            shifted = isinstance(material, _viscoroll.Prony) and material.shift is not None
            state["temperature"] = base["temperature"] if shifted else None
        try:
            if any(name in roller_arguments for name in at):
                state["roller"] = type(scene.roller)(**roller)
            one = _viscoroll.Scene.__new__(_viscoroll.Scene)
            one.__setstate__(state)
        except ValueError as error:
            where = ", ".join(f"{name}={value!r}" for name, value in at.items())
            raise ValueError(f"{error} (the study's scene at {where})") from error
        scenes.append(one)
    return scenes


def _solve_chunk(items, method, grid, setting, tolerance, strict):
    """One chunk of a study on one thread: a Dask task (pickled by reference, so a worker imports
    viscoroll). Returns (records, breaches) as solve_items does."""
    return _viscoroll.solve_items(items, method, grid, setting, tolerance, strict, 1,
                                  max(len(items), 1), None)


def _run_local(items, options, threads, chunk, bar):
    progress = None
    if bar is not None:
        def progress(done):
            bar.update(done - bar.n)
    return _viscoroll.solve_items(items, *options, threads, chunk, progress)


def _client(client):
    """(client, owned): a distributed.Client for `client` (None: none), owned when made here."""
    if client is None:
        return None, False
    distributed = _require("distributed", "python3-distributed", "a Dask cluster's client")
    if isinstance(client, distributed.Client):
        return client, False
    if client == "active":
        try:
            return distributed.get_client(), False
        except ValueError as error:
            raise ValueError("viscoroll: study(): client='active', but no Dask client is active "
                             "(distributed.Client(...) makes one)") from error
    if isinstance(client, str):
        return distributed.Client(client), True
    _fail(f"client = {client!r} must be None (this machine), 'active' (distributed.get_client()), "
          "a scheduler's address or a distributed.Client")
    return None, False


def _run_dask(client, items, options, chunk, bar):
    distributed = _require("distributed", "python3-distributed", "a Dask cluster's client")
    token = uuid.uuid4().hex[:12]
    bounds = [(k, min(k + chunk, len(items))) for k in range(0, len(items), chunk)]
    futures = [client.submit(_solve_chunk, items[a:b], *options,
                             key=f"viscoroll-study-{token}-{i}")
               for i, (a, b) in enumerate(bounds)]
    where = {future.key: i for i, future in enumerate(futures)}
    done = [None] * len(futures)
    try:
        for future in distributed.as_completed(futures):
            i = where[future.key]
            done[i] = future.result()  # a task's exception is raised here
            if bar is not None:
                bar.update(bounds[i][1] - bounds[i][0])
    except BaseException:
        client.cancel(futures)
        raise
    records, breaches = [], []
    for chunk_records, chunk_breaches in done:
        records += chunk_records
        breaches += chunk_breaches
    return records, breaches


def _fields(records):
    """Every record's keys, each after the key before it in the first record that has it."""
    keys, seen = [], set()
    for record in records:
        signature = tuple(record)
        if signature in seen:
            continue
        seen.add(signature)
        at = 0
        for key in record:
            if key in keys:
                at = keys.index(key) + 1
            else:
                keys.insert(at, key)
                at += 1
    return keys


def _column(values):
    """A field's values (None where missing) as a NumPy array: str (lists joined by newlines;
    '' where missing), bool or int64 where every value is one, else float64 (NaN where missing)."""
    present = [v for v in values if v is not None]
    if any(isinstance(v, (str, list)) for v in present):
        return np.array(["\n".join(v) if isinstance(v, list) else "" if v is None else str(v)
                         for v in values], dtype=object)
    if len(present) == len(values):
        if all(isinstance(v, bool) for v in values):
            return np.array(values, dtype=bool)
        if all(isinstance(v, int) and not isinstance(v, bool) for v in values):
            return np.array(values, dtype=np.int64)
    return np.array([np.nan if v is None else float(v) for v in values], dtype=np.float64)


def _dataset(xr, axes, records, attrs):
    names = [name for name, _, _ in axes]
    shape = tuple(len(values) for _, values, _ in axes)
    per_length = bool(records) and all(r.get("method") == "plane" for r in records)
    coords = {}
    for name, _, coordinate in axes:
        units, long_name = AXES.get(name) or ROLLER_AXES.get(name, ("", name))
        coordinate_attrs = {"long_name": long_name}
        if units is not None:
            coordinate_attrs["units"] = _units(units, per_length)
        coords[name] = (name, coordinate, coordinate_attrs)
    data = {}
    for key in _fields(records):
        if key in names:  # the record's speed or temperature is the coordinate
            continue
        units, long_name = FIELDS.get(key, ("", key))
        variable_attrs = {"long_name": long_name}
        if units is not None:
            variable_attrs["units"] = _units(units, per_length)
        column = _column([r.get(key) for r in records]).reshape(shape)
        data[key] = (names, column, variable_attrs)
    return xr.Dataset(data, coords=coords, attrs=attrs)


def study(scene, *, method=None, chunk=_viscoroll.DEFAULT_CHUNK, client=None, progress=True,
          threads=None, tolerance=None, grid=None, setting=None, strict=None, **axes):
    """Solve a scene over a grid of named axes; return an xarray.Dataset.

    Parameters
    ----------
    scene : Scene
        The base scene: every point of the grid is this scene with the axes' values in place.
    **axes : 1-D sequences, each a dimension of the result, in the order given
        speed (default: the scene's speeds, as the last dimension); temperature (degrees
        Celsius; a Prony material with a shift law); load; thickness (the scene's layer or
        spring bed); any scalar argument of the scene's roller's constructor (Cylinder: radius;
        Crowned: radius, flat_length, crown_radius, length, tilt; Ellipsoid: c1, c2; ...);
        material, a dict name -> material (a dimension labelled by the names; the scene's
        temperature applies to those with a shift law).
    method, grid, setting, tolerance, strict : as for solve(), for every scene.
    chunk : int, optional
        Consecutive scenes per chunk, 1..1048576 (default 16). The grid's scenes, in C order
        (the last axis fastest), are cut into chunks; within one, each scene continues from the
        previous one's solution where both have the same material and temperature (line, bem;
        the plane method takes no seed, so its numbers do not depend on the chunk). A chunk is
        the unit of work: of a thread here, of a task on a cluster.
    client : None, "active", str or distributed.Client, optional
        None: this machine, every chunk solved in C++ on `threads` threads with the GIL
        released. "active": the Dask client of distributed.get_client(); an address
        ("tcp://host:8786"): a client of that scheduler, closed afterwards; or a Client. Each
        chunk is then one task solved on one thread of a worker. The numbers are the same bit
        for bit either way.
    progress : bool, optional
        A tqdm progress bar over the scenes (tqdm.auto: a widget in a notebook).
    threads : int, optional
        Local threads, 0..4096; None or 0: every core.

    Returns
    -------
    xarray.Dataset
        Dimensions the axes, with coordinates (units and long_name attributes); a variable per
        output field of the results (Result.as_dict(): a0, b0, l, d, chi, rolling_resistance,
        power_loss, energy_per_revolution, pmax, converged, iterations, seconds, ...; method,
        reason, warnings as strings), each with units (SI) and long_name; a field a method does
        not give is NaN ('' for a string). Attributes: viscoroll_version, scene (its repr),
        method asked, chunk. ds.to_netcdf(path) writes it.

    Raises
    ------
    ValueError
        An unknown or empty axis, thickness without a substrate, or any invalid value, before
        any solve, naming the keyword; with strict, a breach of the model's assumptions.
    ImportError
        xarray (or tqdm for the progress bar, distributed for a client) missing, naming the
        Debian package.
    """
    xr = _require("xarray", "python3-xarray", "the study's labelled arrays")
    if not isinstance(scene, _viscoroll.Scene):
        _fail(f"scene = {scene!r} is not a viscoroll.Scene")
    if isinstance(chunk, bool) or not isinstance(chunk, (int, np.integer)) \
            or not 1 <= chunk <= 1 << 20:
        _fail(f"chunk = {chunk!r} is outside the valid range 1 <= chunk <= 1048576")
    chunk = int(chunk)
    axes, roller_arguments = _axes(scene, axes)
    scenes = _scenes(scene, axes, roller_arguments)
    speed_at = [name for name, _, _ in axes].index("speed")
    speeds = axes[speed_at][1]
    others = [len(values) for name, values, _ in axes if name != "speed"]
    items = []
    for point in np.ndindex(*(len(values) for _, values, _ in axes)):
        rest = point[:speed_at] + point[speed_at + 1:]
        k = int(np.ravel_multi_index(rest, others)) if others else 0
        items.append((scenes[k], float(speeds[point[speed_at]])))
    options = (method, grid, setting, tolerance, strict)
    # Every item checked by solve()'s rules before any work (a cluster's included).
    _viscoroll.solve_items(items, *options, threads, chunk, None, True)

    dask_client, owned = _client(client)
    bar = None
    if progress:
        tqdm = _require("tqdm.auto", "python3-tqdm",
                        "the progress bar; progress=False runs without")
        bar = tqdm.tqdm(total=len(items), unit="scene", desc="viscoroll study")
    try:
        if dask_client is None:
            records, breaches = _run_local(items, options, threads, chunk, bar)
        else:
            records, breaches = _run_dask(dask_client, items, options, chunk, bar)
        if bar is not None:
            bar.update(len(items) - bar.n)  # the solves that ended after the last poll
    finally:
        if bar is not None:
            bar.close()
        if owned:
            dask_client.close()

    unique = list(dict.fromkeys(breaches))
    if unique:
        more = (f" (and {len(unique) - 1} more breaches in this study: see its variable "
                f"warnings)") if len(unique) > 1 else ""
        warnings.warn(unique[0] + more, UserWarning, stacklevel=2)

    asked = method if method is not None else scene.method or "auto"
    attrs = {"title": "viscoroll study", "viscoroll_version": _viscoroll.__version__,
             "scene": repr(scene), "method": asked, "chunk": chunk}
    if scene.description:
        attrs["description"] = scene.description
    for name, value in (("grid", grid), ("tolerance", tolerance), ("setting", setting)):
        if value is not None:
            attrs[name] = value
    if strict is not None:
        attrs["strict"] = int(bool(strict))
    return _dataset(xr, axes, records, attrs)
