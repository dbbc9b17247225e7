"""Panek & Kalker (1980), Figs. 3-6, from Python: the paper's nondimensional scene (mu_D = 1,
nu = 0.5, f = 9, tau = 1, C1 = 1, C2 = (ln 20 - 1)/25: a 5:1 static long-term ellipse with
a0 = 1), 61 speeds V tau = 1e-3 ... 1e3, the line method with 6 Chebyshev terms, continued
serially through every speed (chunk = all speeds) as examples/panek_kalker.cpp does, so that the
numbers are panek_kalker's. Writes fig3.png ... fig6.png to DIR (default out/python_figures).

usage: PYTHONPATH=build/release/python python3 examples/python/paper_figures.py [DIR]
"""
import math, pathlib, sys
import matplotlib; matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import viscoroll as vr

def compute(n=61, terms=6):
    mat = vr.StandardLinearSolid(mu_d=1.0, nu=0.5, f=9.0, tau=1.0)
    scene = vr.Scene(material=mat, roller=vr.Ellipsoid(c1=1.0, c2=(math.log(20) - 1) / 25),
                     load=5 / (3 * 10 * mat.instantaneous_compliance))
    vtau = [10.0 ** (-3 + 6.0 * i / (n - 1)) for i in range(n)]  # as panek_kalker, bit for bit
    return scene, vr.sweep(scene, vtau, method="line", grid=terms, chunk=n, with_results=True)

def main(out=pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/python_figures")):
    scene, s = compute()
    a0, l0, x = s["a_long_term"], s["l0"], s["vtau"]  # a0 = 1: lengths below are in units of a0
    ax3, ax4, ax5, ax6 = (plt.figure().gca() for _ in range(4))
    for ax, curves in ((ax3, {"a(0)/a0": s["a0"] / a0, "b(0)/a0": s["b0"] / a0, "l/l0": s["l"] / l0}),
                       (ax4, {"chi": s["chi"], "d/(C1 a0^2)": s["d"] / a0**2})):
        [ax.semilogx(x, y, label=label) for label, y in curves.items()]
    for r in (r for r in s["results"] if np.isclose(r.vtau, [0.01, 0.1, 1, 10, 100], rtol=1e-9).any()):
        y, xi = -r.l * np.cos(np.linspace(0, np.pi, 401)), -np.cos(np.linspace(0, np.pi, 401))
        ax5.plot(np.r_[y, y[::-1]], np.r_[r.b(y) + r.a(y), (r.b(y) - r.a(y))[::-1]], label=f"V tau = {r.vtau:g}")
        ax6.plot(xi, r.pressure(r.b0 + r.a0 * xi, 0.0) / r.pmax, label=f"V tau = {r.vtau:g}")
    out.mkdir(parents=True, exist_ok=True)
    for k, ax, what in zip((3, 4, 5, 6), (ax3, ax4, ax5, ax6), ("a(0), b(0), l against V tau/a0",
                           "chi, d against V tau/a0", "zones x = b(y) +- a(y)", "p(x, 0)/pmax, x = b(0) + a(0) xi")):
        ax.set(title=f"Fig. {k}: {what}"); ax.legend(); ax.figure.savefig(out / f"fig{k}.png")
    print(f"wrote {out}/fig3.png ... fig6.png; {int(s['converged'].sum())} of {len(x)} converged")

if __name__ == "__main__":
    main()
