"""A conveyor idler's indentation rolling resistance over belt speed (1 ... 8 m/s), temperature
(-30 ... 40 degC) and the thickness of the belt's bottom cover (3 ... 12 mm): vr.study of the plane
method on a bonded rubber layer. The rubber is examples/scenes/conveyor_idler.json's (an
eight-term Prony series with the WLF shift c1 = 8.86, c2 = 101.6 K at t_ref = 0 degC); the idler a
cylinder of radius 63.5 mm carrying 1500 N over its 0.37 m face, solved per unit length
(1500/0.37 N/m) to 1e-3 in a0, d and chi. Writes OUT_DIR/conveyor_study.nc (the Dataset, with the
power per idler) and OUT_DIR/conveyor_study.png (heat maps of chi and of the power per idler over
temperature x speed, one column per cover thickness). --client ADDRESS solves on a Dask cluster
(a scheduler's address, or "active"); --quick solves a 2 x 2 x 2 grid (the test's).

usage: PYTHONPATH=build/release/python python3 examples/python/conveyor_study.py OUT_DIR
           [--client ADDRESS] [--quick]
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (after the back end)
import numpy as np  # noqa: E402

import viscoroll as vr  # noqa: E402

FACE = 0.37  # m: the idler's face, which carries the belt
RUBBER = vr.Prony(g_inf=1.5e6, nu=0.5,
                  terms=[(2.0e8, 1e-7), (6.0e7, 1e-6), (1.8e7, 1e-5), (6.0e6, 1e-4),
                         (2.0e6, 1e-3), (8.0e5, 1e-2), (4.0e5, 1e-1), (2.0e5, 1.0)],
                  shift=vr.WLF(c1=8.86, c2=101.6, t_ref=0.0))
IDLER = vr.Scene(RUBBER, vr.Cylinder(radius=0.0635), load=1500.0 / FACE,
                 substrate={"model": "layer", "thickness": 0.006, "base": "bonded"})


def compute(client=None, quick=False):
    """The study: thickness x temperature x speed (speed varies fastest)."""
    if quick:
        axes = {"thickness": [0.003, 0.012], "temperature": [-30.0, 40.0], "speed": [1.0, 8.0]}
    else:
        axes = {"thickness": [0.003, 0.006, 0.009, 0.012],
                "temperature": np.arange(-30.0, 41.0, 10.0), "speed": np.arange(1.0, 9.0)}
    ds = vr.study(IDLER, method="plane", tolerance=1e-3, client=client, **axes)
    ds["power_per_idler"] = ds["power_loss"] * FACE
    ds["power_per_idler"].attrs = {"units": "W", "long_name": "power lost per idler (0.37 m face)"}
    return ds


def draw(ds, path):
    """Heat maps over temperature x speed: chi (top row) and the power per idler (bottom row), a
    column per cover thickness, each row on one colour scale."""
    columns = ds.sizes["thickness"]
    figure, axes = plt.subplots(2, columns, figsize=(3.2 * columns + 1, 6), squeeze=False,
                                constrained_layout=True)
    for i, (name, label) in enumerate((("chi", "chi"), ("power_per_idler", "P per idler (W)"))):
        low, high = ds[name].min().item(), ds[name].max().item()
        for j, h in enumerate(ds["thickness"].values):
            at = ds[name].sel(thickness=h)
            mesh = axes[i][j].pcolormesh(at["speed"], at["temperature"], at, shading="nearest",
                                         vmin=low, vmax=high)
            axes[i][j].set(xlabel="speed (m/s)", ylabel="temperature (degC)",
                           title=f"{label}, cover {h * 1e3:g} mm")
        figure.colorbar(mesh, ax=axes[i].tolist(), label=label)
    figure.savefig(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", type=pathlib.Path, help="output directory")
    parser.add_argument("--client", help="a Dask scheduler's address (tcp://host:8786), or "
                        "'active'; default: this machine's cores")
    parser.add_argument("--quick", action="store_true", help="a 2 x 2 x 2 grid")
    args = parser.parse_args()
    ds = compute(args.client, args.quick)
    args.out.mkdir(parents=True, exist_ok=True)
    ds.to_netcdf(args.out / "conveyor_study.nc")
    draw(ds, args.out / "conveyor_study.png")
    worst = ds["power_per_idler"].where(ds["converged"]).max().item()
    print(f"wrote {args.out}/conveyor_study.nc and conveyor_study.png: {ds['chi'].size} scenes, "
          f"{int(ds['converged'].sum())} converged, chi {ds['chi'].min().item():.4f} ... "
          f"{ds['chi'].max().item():.4f}, power per idler up to {worst:.1f} W")


if __name__ == "__main__":
    main()
