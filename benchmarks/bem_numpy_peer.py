#!/usr/bin/env python3
"""The library's boundary-element solver timed against a plain NumPy implementation of the same
BEM, side by side in one run (docs/performance.md, "The BEM against a NumPy
peer").

The peer is written from docs/bem.md, not from the C++: Love's rectangles (B1) in closed form,
the exact memory kernel (B3) by the recurrence (B4)-(B5) with Gauss-Legendre panels, the FFT
convolution (B6)-(B7) by numpy.fft.rfft2 on the zero-padded grid, and the primal-dual active set
with right-preconditioned restarted GMRES (B11, the continuum symbol as preconditioner, inexact
early solves as numerics/active_set.hpp does), the edges by (B12). It needs only NumPy.

The scene is the paper's (benchmarks/bench_bem.cpp, BM_bem_paper_scene): mu_D = 1, nu = 0.5,
f = 9, tau = 1, C1 = 1, C2 = (ln 20 - 1)/25, the load of line-contact a0 = 1, V tau/a0 = 1. The
library is timed through viscoroll-solve (--method bem --threads 1; its "seconds" field, the
solve alone, and the process's wall time), the peer with time.perf_counter around its solve;
each is the median of --repeats runs, alternated, on one core.

    python3 benchmarks/bem_numpy_peer.py --solver build/release/bin/viscoroll-solve \
        [--grids 16,32,64] [--repeats 5]
"""
import argparse
import json
import math
import statistics
import subprocess
import time

import numpy as np

MU, NU, F, TAU = 1.0, 0.5, 9.0, 1.0
C1 = 1.0
C2 = (math.log(20.0) - 1) / 25
COMPLIANCE = (1 - NU) / (2 * math.pi * MU)
LOAD = 5.0 / (3 * (1 + F) * COMPLIANCE)
SPEED = 1.0


# --- Hertz (B8) -------------------------------------------------------------------------------

def ellipk_ellipe(e):
    """K(e), E(e) (modulus e) by the arithmetic-geometric mean."""
    a, b, c = 1.0, math.sqrt(1 - e * e), e
    s, power = c * c / 2, 0.5
    for _ in range(60):  # quadratic convergence: c falls to 0 (or a rounding error) in < 10
        if abs(c) <= 1e-16 * a:
            break
        a, b, c = (a + b) / 2, math.sqrt(a * b), (a - b) / 2
        power *= 2
        s += power * c * c
    k = math.pi / (2 * a)
    return k, k * (1 - s)


def hertz(c1, c2, compliance, load):
    """Semi-axes (a along x, b along y) and approach d of Hertz's contact, gap c1 x^2/2 + c2 y^2/2."""
    swap = c2 > c1
    big, ratio = (c2, c1 / c2) if swap else (c1, c2 / c1)

    def ratio_of(kp):
        e = math.sqrt((1 - kp) * (1 + kp))
        k, E = ellipk_ellipe(e)
        return kp * kp * (k - E) / (E - kp * kp * k)

    lo, hi = math.log(1e-6), math.log(1 - 1e-15)
    for _ in range(200):  # bisection on ln k', ratio_of increasing in k'
        mid = (lo + hi) / 2
        if ratio_of(math.exp(mid)) < ratio:
            lo = mid
        else:
            hi = mid
    kp = math.exp((lo + hi) / 2)
    e2 = (1 - kp) * (1 + kp)
    k, E = ellipk_ellipe(math.sqrt(e2))
    a = (3 * compliance * load * kp * (E - kp * kp * k) / (big * e2)) ** (1 / 3)
    b = a / kp
    d = 3 * compliance * load * k / (2 * b)
    return (b, a, d) if swap else (a, b, d)


# --- influence coefficients (B1)-(B5) ---------------------------------------------------------

def love_primitive(u, v):
    au, av = np.abs(u), np.abs(v)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(au > 0, u * np.arcsinh(v / np.where(au > 0, au, 1)), 0.0)
        s = s + np.where(av > 0, v * np.arcsinh(u / np.where(av > 0, av, 1)), 0.0)
    return s


def love(x, y, hx, hy):
    """(B1): int int dx' dy' / r over the cell [-hx/2, hx/2] x [-hy/2, hy/2], at (x, y)."""
    x1, x2, y1, y2 = x - hx / 2, x + hx / 2, y - hy / 2, y + hy / 2
    return (love_primitive(x2, y2) - love_primitive(x1, y2) - love_primitive(x2, y1)
            + love_primitive(x1, y1))


GL_X, GL_W = np.polynomial.legendre.leggauss(16)


def panel_nodes(edges):
    """Gauss-Legendre nodes and weights of the panels between consecutive `edges` (in [0, 1])."""
    nodes, weights = [], []
    for a, b in zip(edges[:-1], edges[1:]):
        nodes.append((a + b) / 2 + (b - a) / 2 * GL_X)
        weights.append((b - a) / 2 * GL_W)
    return np.concatenate(nodes), np.concatenate(weights)


def memory_rows(m, ys, hx, hy, length):
    """(B3)-(B5): M_L(i hx, y) for i = -m .. m and every y of `ys` (shape (len(ys), 2m + 1))."""
    # A step [X_i, X_i + hx] in two halves: the kinks of K_e at s = +-hx/2 fall on their
    # common end; the halves are graded towards it (the row y = 0 has a u ln u kink there).
    graded = [0.0] + [0.5 - 0.5 ** k for k in range(2, 30)] + [0.5]
    edges = sorted(set(graded + [1 - g for g in graded]))
    t, w = panel_nodes(np.array(edges))
    offsets = np.arange(-m, m + 1) * hx
    s = offsets[:, None] + hx * t[None, :]                       # (steps, nodes)
    weight = np.exp(-(s - offsets[:, None]) / length) * (hx * w / length)[None, :]
    steps = np.empty((len(ys), 2 * m + 1))
    for r, y in enumerate(ys):
        steps[r] = np.sum(weight * love(s, y, hx, hy), axis=1)
    # (B5): the tail beyond X_max = m hx, int_0^inf e^-t K_e(X_max + L t, y) dt on t-panels.
    tail_edges = [0.0]
    t_end = min(1.0, max(hx, m * hx) / length) / 2
    while tail_edges[-1] < 45:
        tail_edges.append(min(t_end, 45.0))
        t_end = t_end * 2 if t_end < 8 else t_end + 8
    tt, tw = panel_nodes(np.array(tail_edges))
    out = np.empty((len(ys), 2 * m + 1))
    for r, y in enumerate(ys):
        out[r, -1] = np.sum(tw * np.exp(-tt) * love(m * hx + length * tt, y, hx, hy))
    decay = math.exp(-hx / length)
    for i in range(2 * m - 1, -1, -1):
        out[:, i] = decay * out[:, i + 1] + steps[:, i]
    return out


def influence_table(nx, ny, hx, hy, compliance, terms):
    """(B6): c [K_e + sum f_k M_{L_k}] at offsets (di, dj), di = -(nx-1) .. nx-1, dj = 0 .. ny-1."""
    m = nx - 1
    ys = np.arange(ny) * hy
    xs = np.arange(-m, m + 1) * hx
    table = love(xs[None, :], ys[:, None], hx, hy)
    for f, length in terms:
        table = table + f * memory_rows(m, ys, hx, hy, length)
    return compliance * table


def fft_size(n):
    best = 1 << (n - 1).bit_length()
    p2 = 1
    while p2 < 2 * n:
        p3 = p2
        while p3 < 2 * n:
            p5 = p3
            while p5 < 2 * n:
                if n <= p5 < best:
                    best = p5
                p5 *= 5
            p3 *= 3
        p2 *= 2
    return best


# --- the solver (B7), (B11), (B12) ------------------------------------------------------------

class Operator:
    def __init__(self, table, nx, ny, hx, hy, compliance, terms):
        self.nx, self.ny = nx, ny
        self.nfx, self.nfy = fft_size(2 * nx - 1), fft_size(2 * ny - 1)
        wrapped = np.zeros((self.nfy, self.nfx))
        full = np.concatenate([table[:0:-1], table])                # dj = -(ny-1) .. ny-1
        dj = np.arange(-(ny - 1), ny) % self.nfy
        di = np.arange(-(nx - 1), nx) % self.nfx
        wrapped[np.ix_(dj, di)] = full
        self.kernel = np.fft.rfft2(wrapped)
        # (B11): the inverse continuum symbol on the half spectrum.
        kx = 2 * np.pi * np.arange(self.nfx // 2 + 1) / (self.nfx * hx)
        n = np.arange(self.nfy)
        ky = 2 * np.pi * np.where(n <= self.nfy // 2, n, n - self.nfy) / (self.nfy * hy)
        qx = 2 * np.sin(kx * hx / 2) / hx
        qy = 2 * np.sin(ky * hy / 2) / hy
        kmin = min(2 * np.pi / (self.nfx * hx), 2 * np.pi / (self.nfy * hy))
        k = np.maximum(np.sqrt(qx[None, :] ** 2 + qy[:, None] ** 2), kmin)
        memory = np.ones_like(k, dtype=complex)
        for f, length in terms:
            memory = memory + f / (1 - 1j * kx[None, :] * length)
        self.symbol = k / (2 * np.pi * compliance * memory)

    def _apply(self, spectrum, p):
        return np.fft.irfft2(np.fft.rfft2(p, s=(self.nfy, self.nfx)) * spectrum,
                             s=(self.nfy, self.nfx))[: self.ny, : self.nx]

    def apply(self, p):
        return self._apply(self.kernel, p)

    def precondition(self, p):
        return self._apply(self.symbol, p)


def gmres(apply_a, apply_m, b, x, tol, restart, max_steps):
    """Restarted GMRES with right preconditioning (Saad, Alg. 9.5), as numerics/gmres.hpp."""
    bnorm = np.linalg.norm(b)
    r = b - apply_a(x)
    rnorm = np.linalg.norm(r)
    steps = 0
    while rnorm > tol * bnorm and steps < max_steps:
        v = np.zeros((restart + 1, b.size))
        h = np.zeros((restart + 1, restart))
        cs, sn, g = np.zeros(restart), np.zeros(restart), np.zeros(restart + 1)
        v[0] = r / rnorm
        g[0] = rnorm
        k = 0
        while k < restart and steps < max_steps:
            steps += 1
            w = apply_a(apply_m(v[k]))
            for i in range(k + 1):
                h[i, k] = v[i] @ w
                w = w - h[i, k] * v[i]
            h[k + 1, k] = np.linalg.norm(w)
            if h[k + 1, k] != 0:
                v[k + 1] = w / h[k + 1, k]
            for i in range(k):
                t = cs[i] * h[i, k] + sn[i] * h[i + 1, k]
                h[i + 1, k] = -sn[i] * h[i, k] + cs[i] * h[i + 1, k]
                h[i, k] = t
            denom = math.hypot(h[k, k], h[k + 1, k])
            cs[k], sn[k] = (h[k, k] / denom, h[k + 1, k] / denom) if denom else (1.0, 0.0)
            h[k, k] = cs[k] * h[k, k] + sn[k] * h[k + 1, k]
            h[k + 1, k] = 0
            g[k + 1] = -sn[k] * g[k]
            g[k] = cs[k] * g[k]
            k += 1
            if abs(g[k]) <= tol * bnorm / 2:
                break
        y = np.linalg.solve(np.triu(h[:k, :k]), g[:k])
        x = x + apply_m(v[:k].T @ y)
        r = b - apply_a(x)
        rnorm = np.linalg.norm(r)
    return x, steps, rnorm <= tol * bnorm


def solve(n, tolerance=1e-10, coarse=1e-3, restart=80):
    """The paper's scene on N = n elements per semi-axis: (d, chi, a0, l, pmax, active-set
    iterations, GMRES steps)."""
    a_h, b_h, d_h = hertz(C1, C2, (1 + F) * COMPLIANCE, LOAD)
    half = math.ceil(1.6 * n - 1e-9)
    nx = ny = 2 * half + 1
    hx, hy = a_h / n, b_h / n
    terms = [(F, SPEED * TAU)]
    table = influence_table(nx, ny, hx, hy, COMPLIANCE, terms)
    op = Operator(table, nx, ny, hx, hy, COMPLIANCE, terms)
    x = (np.arange(nx) - half) * hx
    y = (np.arange(ny) - half) * hy
    h = C1 * x[None, :] ** 2 / 2 + C2 * y[:, None] ** 2 / 2
    # The start: Hertz of the compliance between the long-term and the instantaneous one.
    weight = F * a_h / (a_h + SPEED * TAU)
    a_g, b_g, d_g = hertz(C1, C2, (1 + weight) * COMPLIANCE, LOAD)
    p0 = 3 * LOAD / (2 * math.pi * a_g * b_g)
    s2 = 1 - (x[None, :] / a_g) ** 2 - (y[:, None] / b_g) ** 2
    p = np.where(s2 > 0, p0 * np.sqrt(np.maximum(s2, 0)), 0.0)
    active, d = p > 0, d_g
    area, scale = hx * hy, d_h
    seen, coarse_on = set(), coarse > tolerance
    iterations = steps = 0
    for _ in range(200):
        key = active.tobytes()
        if key in seen:
            if not coarse_on:
                raise RuntimeError("active set cycles")
            coarse_on, seen = False, set()
        seen.add(key)
        idx = np.flatnonzero(active.ravel())
        na = idx.size

        def apply_a(z):
            full = np.zeros(nx * ny)
            full[idx] = z[:na]
            u = op.apply(full.reshape(ny, nx)).ravel()
            return np.append(u[idx] - z[na], scale * area * z[:na].sum() / LOAD)

        def apply_m(z):
            full = np.zeros(nx * ny)
            full[idx] = z[:na]
            return np.append(op.precondition(full.reshape(ny, nx)).ravel()[idx], z[na])

        b = np.append(-h.ravel()[idx], scale)
        x0 = np.append(np.maximum(p.ravel()[idx], 0), d)
        sol, k, ok = gmres(apply_a, apply_m, b, x0, coarse if coarse_on else tolerance, restart,
                           5000 - steps)
        steps += k
        iterations += 1
        if not ok:
            raise RuntimeError("GMRES did not converge")
        p = np.zeros(nx * ny)
        p[idx] = sol[:na]
        p = p.reshape(ny, nx)
        d = sol[na]
        gap = op.apply(p) - d + h
        new = np.where(active, p > 0, gap < -tolerance * scale)
        changed = bool(np.any(new != active))
        active = new
        if not changed and coarse_on:
            coarse_on = False
            seen.discard(key)
            continue
        if not changed:
            break
    else:
        raise RuntimeError("active-set iteration limit")
    # (B12): edges from p^2 on y = 0 and the row loads towards the tip; chi by Eq. (51).
    row = p[half]
    imax = int(np.argmax(row))
    lead = trail = imax
    while lead + 1 < nx and row[lead + 1] > 0:
        lead += 1
    while trail > 0 and row[trail - 1] > 0:
        trail -= 1

    def offset(last, prev):
        a2, b2 = last * last, prev * prev
        return min(a2 / (b2 - a2), 1.0) if b2 > a2 else 0.5

    xl = x[lead] + hx * (offset(row[lead], row[lead - 1]) if lead > trail else 0.5)
    xt = x[trail] - hx * (offset(row[trail], row[trail + 1]) if lead > trail else 0.5)
    loads = p.sum(axis=1)
    top = half
    while top + 1 < ny and loads[top + 1] > 0:
        top += 1
    tip = y[top] + hy / 2
    if top - 1 > half and loads[top - 1] > loads[top]:
        y1, y2, f1, f2 = y[top - 1], y[top], loads[top - 1], loads[top]
        tip = min(math.sqrt(y2 * y2 + f2 * (y2 * y2 - y1 * y1) / (f1 - f2)), y2 + hy)
    chi = C1 * float((x[None, :] * p).sum() / p.sum())
    return {"d": d, "chi": chi, "a0": (xl - xt) / 2, "l": tip, "pmax": float(p.max()),
            "iterations": iterations, "gmres_iterations": steps}


def library(solver, n):
    args = [solver, "--method", "bem", "--mu-d", repr(MU), "--nu", repr(NU), "--f", repr(F),
            "--tau", repr(TAU), "--speed", repr(SPEED), "--c1", repr(C1), "--c2", repr(C2),
            "--load", repr(LOAD), "--grid", str(n), "--threads", "1", "--format", "json"]
    start = time.perf_counter()
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    wall = time.perf_counter() - start
    record = json.loads(out.splitlines()[0])
    return record, wall


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--solver", default="build/release/bin/viscoroll-solve")
    parser.add_argument("--grids", default="16,32,64")
    parser.add_argument("--repeats", type=int, default=5)
    opts = parser.parse_args()
    print(f"numpy {np.__version__}; {opts.repeats} runs each, alternated; medians")
    print("  N  cells    library solve  library process  NumPy peer   peer/library(solve)  "
          "peer/library(process)  max rel. diff d, chi, a0, l, pmax")
    for n in (int(g) for g in opts.grids.split(",")):
        lib_t, lib_wall, peer_t = [], [], []
        for _ in range(opts.repeats):
            record, wall = library(opts.solver, n)
            lib_t.append(record["seconds"])
            lib_wall.append(wall)
            start = time.perf_counter()
            peer = solve(n)
            peer_t.append(time.perf_counter() - start)
        pmax = record["pmax"]
        diff = max(abs(peer[k] / record[k] - 1) for k in ("d", "chi", "a0", "l"))
        diff = max(diff, abs(peer["pmax"] / pmax - 1))
        ls, lw, ps = (statistics.median(v) for v in (lib_t, lib_wall, peer_t))
        print(f"{n:3d} {record['cells']:6d}   {ls:10.4f} s   {lw:10.4f} s   {ps:10.4f} s   "
              f"{ps / ls:10.1f}            {ps / lw:10.1f}             {diff:.1e} "
              f"(GMRES {record['gmres_iterations']} vs {peer['gmres_iterations']}, "
              f"active set {record['iterations']} vs {peer['iterations']})")


if __name__ == "__main__":
    main()
