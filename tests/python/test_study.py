"""vr.study: a scene over a grid of named axes as an xarray.Dataset, solved by the sweep's engine
(the same numbers as solve() and sweep(), bit for bit for any thread count, chunk placement or a
Dask cluster), written to netCDF; its checks of the axes; Ctrl-C; `import viscoroll` without
xarray, tqdm or Dask; the pickled scene a Dask task takes."""

import math
import os
import pathlib
import pickle
import subprocess
import sys
import textwrap
import warnings

import numpy as np
import pytest

import viscoroll as vr

xr = pytest.importorskip("xarray", reason="vr.study needs xarray (Debian: python3-xarray)")
pytest.importorskip("tqdm", reason="vr.study's progress bar needs tqdm (Debian: python3-tqdm)")

# The conveyor idler's cover rubber (examples/scenes/conveyor_idler.json) under a cylinder: the
# plane method on the half space, Hunter's closed form for a spectrum (microseconds a solve, plus
# about a millisecond for the record's peak pressure), which takes no seed, so that no chunk can
# change its numbers.
RUBBER = vr.Prony(g_inf=1.5e6, nu=0.5,
                  terms=[(2.0e8, 1e-7), (6.0e7, 1e-6), (1.8e7, 1e-5), (6.0e6, 1e-4),
                         (2.0e6, 1e-3), (8.0e5, 1e-2), (4.0e5, 1e-1), (2.0e5, 1.0)],
                  shift=vr.WLF(c1=8.86, c2=101.6, t_ref=0.0))
IDLER = vr.Scene(RUBBER, vr.Cylinder(radius=0.0635), load=1500 / 0.37)
AXES = {"speed": [1.0, 2.0, 4.0], "temperature": [-20.0, 0.0, 20.0],
        "load": [1000.0, 2000.0, 3000.0, 4000.0]}
COVER = vr.StandardLinearSolid(mu_d=3.0e6, nu=0.5, f=4.0, tau=0.002)
# The paper's dimensionless scene (a line method that takes seeds; a0 = 1).
_PAPER_MATERIAL = vr.StandardLinearSolid(mu_d=1.0, nu=0.5, f=9.0, tau=1.0)
PAPER = vr.Scene(_PAPER_MATERIAL, vr.Ellipsoid(c1=1.0, c2=(math.log(20) - 1) / 25),
                 load=5 / (3 * 10 * _PAPER_MATERIAL.instantaneous_compliance))


@pytest.fixture(scope="module")
def local():
    return vr.study(IDLER, progress=False, **AXES)


def without_seconds(ds):
    """The study without its run times (the one field that differs from run to run)."""
    return ds.drop_vars("seconds")


def test_the_dataset_has_the_axes_in_order_with_units_and_every_field(local):
    assert list(local.dims) == ["speed", "temperature", "load"]
    assert dict(local.sizes) == {"speed": 3, "temperature": 3, "load": 4}
    for name, values in AXES.items():
        assert local[name].values.tolist() == values
        assert local[name].attrs["units"] and local[name].attrs["long_name"]
    assert local["load"].attrs["units"] == "N/m"  # the plane method: per unit length
    assert local["temperature"].attrs["units"] == "degC"
    fields = set(vr.solve(IDLER, speed=1.0).as_dict()) - {"speed", "temperature"}
    assert fields <= set(local.data_vars)
    for name, variable in local.data_vars.items():
        assert variable.dims == ("speed", "temperature", "load"), name
        assert variable.attrs["long_name"], name
        if variable.dtype != object:
            assert "units" in variable.attrs, name
    assert local["chi"].attrs["units"] == "1"
    assert local["power_loss"].attrs["units"] == "W/m"
    assert local["pmax"].attrs["units"] == "Pa"
    assert local["converged"].dtype == bool and local["converged"].all()
    assert local["iterations"].dtype == np.int64
    assert local["method"].dtype == object and set(local["method"].values.ravel()) == {"plane"}
    assert local.attrs["viscoroll_version"] == vr.__version__
    assert local.attrs["scene"] == repr(IDLER)
    assert local.attrs["method"] == "auto"


def test_every_point_is_solve_of_its_scene_bit_for_bit(local):
    for v, t, w in [(1.0, -20.0, 1000.0), (2.0, 0.0, 3000.0), (4.0, 20.0, 4000.0)]:
        scene = vr.Scene(RUBBER, vr.Cylinder(radius=0.0635), load=w, temperature=t)
        want = vr.solve(scene, speed=v).as_dict()
        got = local.sel(speed=v, temperature=t, load=w)
        for key, value in want.items():
            if key in ("seconds", "speed", "temperature"):
                continue
            if key in ("warnings", "warning_codes"):
                assert got[key].item() == "\n".join(value)
            else:
                assert got[key].item() == value, key


def test_the_numbers_do_not_depend_on_threads_or_chunks(local):
    for threads, chunk in [(1, 16), (2, 16), (2, 1), (1, 7), (None, 36)]:
        other = vr.study(IDLER, progress=False, threads=threads, chunk=chunk, **AXES)
        xr.testing.assert_equal(without_seconds(other), without_seconds(local))


def test_a_seeded_method_continues_within_a_chunk_as_sweep_does():
    """The line method: each speed of a chunk continues from the previous one's root, as in
    sweep() (here the seeds change the numbers by up to 8e-15 against cold starts), and two
    threads give one thread's numbers."""
    paper = PAPER
    speeds = np.logspace(0.2, 1, 20)  # V tau/a0 = 1.6 ... 10: every solution a root
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the paper's dimensionless scene: a0/R = 1
        one = vr.study(paper, speed=speeds, method="line", chunk=7, progress=False, threads=1)
        two = vr.study(paper, speed=speeds, method="line", chunk=7, progress=False, threads=2)
        swept = vr.sweep(paper, speeds=speeds, method="line", chunk=7, threads=2)
    assert swept["root"].all()
    xr.testing.assert_identical(without_seconds(one), without_seconds(two))
    for key, column in swept.items():
        if key in ("seconds", "speed"):
            continue
        if key in ("warnings", "warning_codes"):
            assert one[key].values.tolist() == ["\n".join(w) for w in column]
        else:
            assert np.array_equal(one[key].values, np.asarray(column)), key
    # A least-squares minimum (root False) seeds nothing: the speed after one starts cold.
    speeds = np.logspace(-1, 1, 20)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        seeded = vr.study(paper, speed=speeds, method="line", progress=False)
        cold = vr.sweep(paper, speeds=speeds, method="line", chunk=1)
    after = [k + 1 for k in range(19) if not cold["root"][k] and cold["root"][k + 1]]
    assert after
    for k in after:
        assert seeded["a0"].values[k] == cold["a0"][k] and seeded["chi"].values[k] == cold["chi"][k]
    # sweep() keeps the same rule: over these speeds, minima among them, it is the study bit for
    # bit (its chunks of 16 as the study's).
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        swept = vr.sweep(paper, speeds=speeds, method="line")
    assert np.array_equal(seeded["chi"].values, swept["chi"])
    assert np.array_equal(seeded["a0"].values, swept["a0"])


def test_a_dask_cluster_gives_the_local_numbers_bit_for_bit(local, monkeypatch):
    distributed = pytest.importorskip(
        "distributed", reason="the Dask path needs distributed (Debian: python3-distributed)")
    # The workers are processes of their own: they import this viscoroll (a build's python/
    # directory or an install), wherever the tests run from.
    package_parent = str(pathlib.Path(vr.__file__).resolve().parent.parent)
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join(
        [package_parent] + [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # distributed's own (ports, deprecations)
        cluster = distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1,
                                           dashboard_address=None)
    with cluster, distributed.Client(cluster) as client:
        on_dask = vr.study(IDLER, client=client, progress=True, **AXES)
        xr.testing.assert_identical(without_seconds(on_dask), without_seconds(local))
        # client="active": the client of this context; other chunks, the same numbers.
        active = vr.study(IDLER, client="active", chunk=5, progress=False, **AXES)
        xr.testing.assert_equal(without_seconds(active), without_seconds(local))
        # A seeded method: the workers' pickled scenes continue as the caller's do.
        speeds, loads = np.logspace(0.2, 1, 6), [2.0, 2.2]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the paper's dimensionless scene: a0/R = 1
            here = vr.study(PAPER, load=loads, speed=speeds, method="line", chunk=4,
                            progress=False)
            there = vr.study(PAPER, load=loads, speed=speeds, method="line", chunk=4,
                             client=client, progress=False)
        xr.testing.assert_identical(without_seconds(there), without_seconds(here))
        # A task's error reaches the caller as the local one would.
        with pytest.raises(ValueError, match="strict"):
            vr.study(vr.Scene(COVER, vr.Cylinder(radius=0.001), load=1000.0), client=client,
                     speed=[1.0], strict=True, progress=False)
    with pytest.raises(ValueError, match="client='active'"):
        vr.study(IDLER, client="active", speed=[1.0], progress=False)


def test_a_material_axis_labels_its_dimension_and_fills_what_a_material_lacks():
    materials = {"cover": COVER, "idler rubber": RUBBER}
    ds = vr.study(IDLER, material=materials, speed=[1.0, 3.0], progress=False)
    assert list(ds.dims) == ["material", "speed"]
    assert ds["material"].values.tolist() == ["cover", "idler rubber"]
    # The standard linear solid has tau and vtau, the spectrum temperature, a_T, active_terms.
    assert np.isnan(ds["a_T"].sel(material="cover")).all()
    assert (ds["a_T"].sel(material="idler rubber") == 1.0).all()  # the scene's 0 degC = t_ref
    assert np.isnan(ds["tau"].sel(material="idler rubber")).all()
    assert (ds["tau"].sel(material="cover") == 0.002).all()
    want = vr.solve(vr.Scene(COVER, vr.Cylinder(radius=0.0635), load=1500 / 0.37), speed=3.0)
    assert ds["chi"].sel(material="cover", speed=3.0).item() == want.chi


def test_a_thickness_axis_on_a_layer_and_a_roller_axis():
    layer = vr.Scene(COVER, vr.Cylinder(radius=0.0635), load=1000.0,
                     substrate={"model": "layer", "thickness": 0.004, "base": "bonded"})
    ds = vr.study(layer, thickness=[0.003, 0.012], speed=[2.0], method="plane", tolerance=1e-3,
                  progress=False)
    assert list(ds.dims) == ["thickness", "speed"]
    assert ds["thickness"].attrs["units"] == "m"
    assert ds["converged"].all()
    assert ds["substrate"].values.ravel().tolist() == [
        "layer (thickness 0.003 m, bonded)", "layer (thickness 0.012 m, bonded)"]
    thin = vr.Scene(COVER, vr.Cylinder(radius=0.0635), load=1000.0,
                    substrate={"model": "layer", "thickness": 0.003, "base": "bonded"})
    want = vr.solve(thin, method="plane", speed=2.0, tolerance=1e-3)
    for key in ("a0", "d", "chi", "error_chi", "terms"):
        assert ds[key].sel(thickness=0.003, speed=2.0).item() == getattr(want, key), key
    assert ds["d"].attrs["units"] == "m" and ds["error_d"].attrs["units"] == "m"
    # A roller's constructor argument is an axis.
    radii = vr.study(IDLER, radius=[0.05, 0.1], speed=[1.0], progress=False)
    want = vr.solve(vr.Scene(RUBBER, vr.Cylinder(radius=0.1), load=1500 / 0.37), speed=1.0)
    assert radii["chi"].sel(radius=0.1, speed=1.0).item() == want.chi
    assert radii["radius"].attrs["units"] == "m"


def test_to_netcdf_round_trip(local, tmp_path):
    pytest.importorskip("netCDF4", reason="netCDF4 files need netCDF4 (Debian: python3-netcdf4)")
    path = tmp_path / "study.nc"
    local.to_netcdf(path)
    with xr.open_dataset(path) as back:
        back.load()
        xr.testing.assert_identical(back, local)
        assert back["converged"].dtype == bool
        assert back["method"].values.ravel()[0] == "plane"


def test_bad_input_raises_value_error_naming_the_keyword():
    def fails(match, **kwargs):
        with pytest.raises(ValueError, match=match):
            vr.study(IDLER, progress=False, **kwargs)

    fails("speeds= is not an axis \\(did you mean speed=", speeds=[1.0])
    fails("colour= is not an axis", colour=[1.0])
    fails("flat_length= is not an argument of the scene's roller Cylinder", flat_length=[0.1])
    fails("load = \\[\\] is empty", load=[], speed=[1.0])
    fails("material = \\{\\} is empty", material={}, speed=[1.0])
    fails("material= must be a dict", material=[COVER], speed=[1.0])
    fails("thickness= needs a scene on a layer or a spring bed", thickness=[0.01], speed=[1.0])
    fails("speed = 'fast' is a string", speed="fast")
    fails("load = .* must be a 1-D sequence", load=[[1.0, 2.0]], speed=[1.0])
    fails("load = -1 is outside the valid range", load=[1000.0, -1.0], speed=[1.0])
    fails("speed = -1 is outside the valid range", speed=[1.0, -1.0])
    fails("needs speeds", temperature=[0.0])
    fails("chunk = 0 is outside", chunk=0, speed=[1.0])
    fails("temperature is valid only with a Prony material with a shift law",
          material={"cover": COVER}, temperature=[0.0], speed=[1.0])
    fails("method = \"lines\" is not one of", method="lines", speed=[1.0])
    with pytest.raises(ValueError, match="crown_radius = -1 is outside the valid range"):
        crowned = vr.Scene(RUBBER, vr.Crowned(radius=0.0635, flat_length=0.37, crown_radius=0.005,
                                              length=0.38), load=1500.0)
        vr.study(crowned, crown_radius=[0.005, -1.0], speed=[1.0], progress=False)


def test_the_scene_and_its_parts_pickle_to_the_same_bits(scenes_dir):
    crowned = vr.Crowned(radius=0.0635, flat_length=0.37, crown_radius=0.005, length=0.38,
                         tilt=0.001)
    for thing in (RUBBER, COVER, vr.Elastic(mu=1e6, nu=0.45), vr.WLF(c1=8.86, c2=101.6, t_ref=0.0),
                  vr.Arrhenius(activation_energy=1e5, t_ref=20.0), crowned,
                  vr.Crowned(radius=0.05, flat_length=0.05, crown_radius=1.0),
                  vr.Logarithmic(radius=0.05, length=0.1, scale=1e-5),
                  vr.Table(radius=0.05, y=[-0.05, -0.01, 0.01, 0.05], h=[1e-4, 0, 0, 1e-4]),
                  vr.Ellipsoid(c1=20.0, c2=1.596582), vr.Cylinder(radius=0.0635)):
        copy = pickle.loads(pickle.dumps(thing))
        assert type(copy) is type(thing) and repr(copy) == repr(thing)
    assert type(crowned)(**crowned._arguments).__repr__() == repr(crowned)
    layer = vr.Scene(COVER, vr.Cylinder(radius=0.0635), load=1000.0, speeds=[1.0, 2.0],
                     substrate={"model": "spring_bed", "thickness": 0.004}, density=1100.0)
    for scene in (IDLER, layer, vr.Scene(RUBBER, crowned, load=1500.0, temperature=-20.0),
                  vr.Scene.from_json(scenes_dir / "paper.json"),
                  vr.Scene.from_json(scenes_dir / "conveyor_idler.json", temperature=20.0)):
        copy = pickle.loads(pickle.dumps(scene))
        assert repr(copy) == repr(scene)
        assert copy.__getstate__().keys() == scene.__getstate__().keys()
        for key in ("load", "temperature", "method", "grid", "tolerance", "setting", "strict",
                    "description", "density", "substrate"):
            assert getattr(copy, key) == getattr(scene, key), key
    a = vr.solve(layer, speed=1.0, method="plane", tolerance=1e-3).as_dict()
    b = vr.solve(pickle.loads(pickle.dumps(layer)), speed=1.0, method="plane",
                 tolerance=1e-3).as_dict()
    assert {k: v for k, v in a.items() if k != "seconds"} == \
        {k: v for k, v in b.items() if k != "seconds"}


def test_breaches_are_one_warning_and_in_the_variables_warnings_and_warning_codes():
    small = vr.Scene(COVER, vr.Cylinder(radius=0.002), load=1000.0)  # a0/R > 0.2
    with pytest.warns(UserWarning, match="limit a0/R <= 0.2.*more breaches in this study"):
        ds = vr.study(small, speed=[1.0, 2.0], progress=False)
    assert all("small_slope" in c.split("\n") for c in ds["warning_codes"].values.ravel())


# Run by the fixture `interrupted` (conftest.py).
CHILD = textwrap.dedent("""
    import time
    import numpy as np
    import viscoroll as vr
    mat = vr.StandardLinearSolid(mu_d=1.0, nu=0.5, f=9.0, tau=1.0)
    scene = vr.Scene(material=mat, roller=vr.Ellipsoid(c1=1.0, c2=0.0798),
                     load=5 / (3 * 10 * mat.instantaneous_compliance))
    vr.study(scene, speed=[1.0], progress=False)  # xarray imported before the clock starts
    print("started", flush=True)
    try:
        vr.study(scene, speed=np.logspace(-1, 1, 50), load=np.linspace(1, 2, 100),
                 method="line", threads=2)
        print("finished", flush=True)
    except KeyboardInterrupt:
        print("interrupted", time.monotonic(), flush=True)
    print("afterwards", vr.study(scene, speed=[1.0], progress=False)["converged"].all().item(),
          flush=True)
""")


def test_ctrl_c_stops_a_study_within_a_second(interrupted):
    # 5000 line solves: about a minute on two threads, if not stopped.
    delay, after, out, err = interrupted(CHILD)
    print(f"study: KeyboardInterrupt {delay * 1e3:.0f} ms after SIGINT")
    assert 0 <= delay < 1.0
    assert after == ["afterwards True"], (out, err)


def test_import_viscoroll_needs_no_xarray_tqdm_or_dask():
    """A finder that refuses xarray, tqdm, dask and distributed: viscoroll imports and solves, and
    study() raises ImportError naming the Debian package."""
    code = textwrap.dedent("""
        import sys
        class Refuse:
            def find_spec(self, name, path=None, target=None):
                if name.split(".")[0] in ("xarray", "tqdm", "dask", "distributed"):
                    raise ImportError(f"No module named {name!r} (refused)", name=name)
        sys.meta_path.insert(0, Refuse())
        import viscoroll as vr
        scene = vr.Scene(vr.Elastic(mu=1e6, nu=0.5), vr.Cylinder(radius=0.05), load=100.0)
        assert vr.solve(scene, speed=1.0).converged
        try:
            vr.study(scene, speed=[1.0])
        except ImportError as error:
            print(error)
    """)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=120, check=False)
    assert done.returncode == 0, done.stderr
    assert "viscoroll.study needs xarray" in done.stdout
    assert "apt-get install python3-xarray" in done.stdout


def test_the_conveyor_example_on_a_reduced_grid(source_dir, tmp_path):
    example = source_dir / "examples" / "python" / "conveyor_study.py"
    if not example.is_file():
        pytest.skip("examples/python/conveyor_study.py is not here (an install's tests)")
    pytest.importorskip("matplotlib", reason="the example draws with matplotlib")
    pytest.importorskip("netCDF4", reason="the example writes netCDF (python3-netcdf4)")
    done = subprocess.run([sys.executable, str(example), str(tmp_path), "--quick"],
                          capture_output=True, text=True, timeout=300, check=False)
    assert done.returncode == 0, done.stdout + done.stderr
    with xr.open_dataset(tmp_path / "conveyor_study.nc") as ds:
        assert list(ds.dims) == ["thickness", "temperature", "speed"]
        assert ds["converged"].all()
        assert (ds["chi"] > 0).all()
    assert sorted(p.name for p in tmp_path.glob("*.png"))
