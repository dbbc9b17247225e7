#!/usr/bin/env python3
"""The default front door against a fine-grid BEM on scenes the project has not seen.

Generates seeded random scenes (rigid rollers on Prony rubbers with a WLF shift), solves each
with `viscoroll-solve --scene FILE` with no "method" key (the auto method: line where its theory
applies, else the bem at its default tolerance of 1% in d and chi) and with the reference
`--method bem --tolerance 0.002`, and reports how often the front door's d and chi are within 1%
of the reference (the aim: at least 95% of scenes), which results miss and whether
each says so (a warning, tolerance_met false, converged false), which method answered, and the run
times. One process at a time, `--threads 1` (the times are one core's).

    scripts/validate_front_door.py --check              # unit-check the generator (no solves)
    scripts/validate_front_door.py --dry-run DIR        # write the scenes only
    scripts/validate_front_door.py [--seed 38] [--count 60] [--budget 1380]
        [--binary build/release/bin/viscoroll-solve] [--csv docs/figures/front_door_validation.csv]
        [--scenes-dir /tmp/front_door_scenes] [--failures-dir /tmp/front_door_failures]
    scripts/validate_front_door.py --rescore 38:a.csv 39:b.csv --csv merged.csv   # no solves

docs/validation.md, "The default front door on unseen scenes", reports seeds 38 and 39 (60 scenes
each, about 18 minutes each on one core), merged by --rescore into
docs/figures/front_door_validation.csv. A scene whose reference does not meet its own tolerance
(or did not converge) is excluded from the percentage and listed; a second count adds the
references that converged at their largest grid with their own estimates within REF_USABLE
(0.5%). chi's error is reported plainly
relative and also over max(|chi_ref|, 1e-6 a_lt/R), the bem's own floor for chi.

Standard library only (no NumPy). The scene generator (`make_scene`):
- glassy shear modulus G_g = g_inf + sum g log-uniform in 1e5 ... 1e10 Pa, long-term
  G_inf = G_g/(1 + f), f log-uniform in 1 ... 1000; nu = 0.5 (70%) or uniform in 0.45 ... 0.5;
- 1 ... 20 Prony terms, their times at t_ref log-spaced (jittered) over a window inside
  1e-8 ... 1e2 s of 0.5 ... 1 decade per term (at most 10 decades), weights falling 0 ... 0.6
  decades per decade (jittered), summing to G_g - G_inf; WLF c1 = 8.86, c2 = 101.6 K,
  t_ref = 20 degC; temperature uniform in -40 ... 80 degC;
- roller radius R log-uniform in 5 mm ... 0.5 m; the long-term static contact's half width
  a0 = (0.02 ... 0.15) R (uniform), the load derived from it (below): 40% ellipsoids
  (c2/c1 log-uniform in 1e-3 ... 0.3), 40% crowned rollers (flat part 0 ... 0.5 of the length,
  crown radius 10 ... 1000 R log-uniform, the length such that the crowns run 1.3 ... 3 times the
  Hertz half length of the crown past the flat part), 20% flat idlers (flat part to within
  0.5 ... 0.95 edge radii of the ends, edge radii 0.08 ... 1 R, length 2 ... 10 R: the long-term
  contact reaches the ends, as in examples/scenes/conveyor_idler.json);
- one speed (15% of scenes two) log-uniform-placed on the spectrum: V = a0/tau* with
  log tau* uniform over the shifted window a_T [tau_min/10, tau_max*10], clipped to
  0.05 ... 20 m/s (a cold scene's spectrum is then glassy at every speed: that is recorded).

The load from a0 (all with the long-term plane-strain modulus E* = 2 G_inf/(1 - nu), which is
E/(1 - nu^2) with E = 2 G_inf (1 + nu)):
- ellipsoid (h = c1 x^2/2 + c2 y^2/2, c2 < c1): Hertz's ellipse (Johnson, Contact Mechanics,
  section 4.2) with minor semi-axis b = a0 across the rolling direction and major a along the
  axis, e^2 = 1 - b^2/a^2: c1/c2 = [E(e)/(1 - e^2) - K(e)]/[K(e) - E(e)] fixes e;
  c2/2 = (p0/E*) b/(e^2 a^2) [K - E] gives p0; P = (2/3) pi a b p0; d = p0 b K/E*.
- a long flat part of length Lf: Hertz's strip, a0^2 = 4 R P'/(pi E*), so P' = pi a0^2 E*/(4 R)
  and P = P' Lf.
- a crowned roller: the flat part's strip plus the two crowns taken together as the Hertz
  ellipse of curvatures (1/R, 1/Rc) with the same a0: P = pi a0^2 E* Lf/(4 R) + P_Hertz(a0),
  which is Hertz's barrel for Lf = 0 and the strip for Lf >> the crown's half length. Checked
  against each solve's own a_long_term (the CSV's a0_est/a_long_term).
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import os
import random
import statistics
import subprocess
import sys
import time

WLF_C1, WLF_C2, T_REF = 8.86, 101.6, 20.0
TOLERANCE_FRONT = 0.01  # the front door's accuracy: within 1% in d and chi
TOLERANCE_REF = 0.002


# ----------------------------------------------------------------------------------------------
# Hertz's contact


def ellip_ke(m: float) -> tuple[float, float]:
    """Complete elliptic integrals K(m), E(m) of parameter m = k^2 by the AGM."""
    if not 0.0 <= m < 1.0:
        raise ValueError(f"m = {m} outside [0, 1)")
    a, b = 1.0, math.sqrt(1.0 - m)
    c = math.sqrt(m)
    s = 0.5 * c * c  # sum 2^(n-1) c_n^2, n = 0
    p = 0.5
    for _ in range(64):  # quadratic convergence: a few steps; c stalls at an ulp of a
        if abs(c) <= 1e-16 * a:
            break
        a, b, c = 0.5 * (a + b), math.sqrt(a * b), 0.5 * (a - b)
        p *= 2.0
        s += p * c * c
    k = math.pi / (2.0 * a)
    return k, k * (1.0 - s)


def _curvature_ratio(e2: float) -> float:
    """c1/c2 = B/A of Hertz's ellipse of eccentricity^2 e2 (B across the minor axis)."""
    k, e = ellip_ke(e2)
    return (e / (1.0 - e2) - k) / (k - e)


def hertz_ellipse(a0: float, c1: float, c2: float, e_star: float) -> dict:
    """Hertz's contact of h = c1 x^2/2 + c2 y^2/2 (c2 <= c1) with minor semi-axis a0 along x."""
    if c2 > c1:
        raise ValueError("hertz_ellipse wants c2 <= c1")
    ratio = c1 / c2
    if ratio - 1.0 < 1e-12:
        r = 1.0 / c1
        p = 4.0 * e_star * a0**3 / (3.0 * r)
        return {"load": p, "l": a0, "d": a0 * a0 / r, "e2": 0.0}
    lo, hi = -40.0, -1e-12  # ln(1 - e^2); c1/c2 grows monotonically with e^2
    for _ in range(90):
        mid = 0.5 * (lo + hi)
        if _curvature_ratio(-math.expm1(mid)) < ratio:
            hi = mid
        else:
            lo = mid
    e2 = -math.expm1(0.5 * (lo + hi))
    k, e = ellip_ke(e2)
    major = a0 / math.sqrt(1.0 - e2)
    p0 = (c2 / 2.0) * e_star * e2 * major**2 / (a0 * (k - e))
    return {
        "load": 2.0 / 3.0 * math.pi * major * a0 * p0,
        "l": major,
        "d": p0 * a0 * k / e_star,
        "e2": e2,
    }


def strip_load_per_length(a0: float, radius: float, e_star: float) -> float:
    """Hertz's strip: a0^2 = 4 R P'/(pi E*)."""
    return math.pi * a0 * a0 * e_star / (4.0 * radius)


def wlf_shift(t: float) -> float:
    return 10.0 ** (-WLF_C1 * (t - T_REF) / (WLF_C2 + t - T_REF))


# ----------------------------------------------------------------------------------------------
# The scene generator


def _sig(x: float, digits: int = 6) -> float:
    return float(f"{x:.{digits}g}")


def _logu(rng: random.Random, lo: float, hi: float) -> float:
    return 10.0 ** rng.uniform(math.log10(lo), math.log10(hi))


def make_scene(rng: random.Random, index: int) -> tuple[dict, dict]:
    """One scene file (a dict) and its metadata (what was drawn, the estimates)."""
    g_glassy = _logu(rng, 1e5, 1e10)
    f = _logu(rng, 1.0, 1000.0)
    g_inf = g_glassy / (1.0 + f)
    nu = 0.5 if rng.random() < 0.7 else round(rng.uniform(0.45, 0.5), 3)
    n = rng.randint(1, 20)
    if n == 1:
        times = [_logu(rng, 1e-8, 1e2)]
    else:
        span = min(10.0, max(1.0, rng.uniform(0.5, 1.0) * (n - 1)))
        lo = rng.uniform(-8.0, 2.0 - span)
        step = span / (n - 1)
        logs = [min(2.0, max(-8.0, lo + k * step + rng.uniform(-0.15, 0.15) * step))
                for k in range(n)]
        times = [10.0**x for x in sorted(logs)]
    slope = rng.uniform(0.0, 0.6)
    raw = [10.0 ** (-slope * math.log10(t / times[0]) + rng.gauss(0.0, 0.1)) for t in times]
    total = sum(raw)
    g_sum = g_glassy - g_inf
    terms = [{"g": _sig(g_sum * w / total), "tau": _sig(t)} for w, t in zip(raw, times)]
    g_inf = _sig(g_inf)
    material = {
        "model": "prony",
        "nu": nu,
        "g_inf": g_inf,
        "terms": terms,
        "shift": {"law": "wlf", "c1": WLF_C1, "c2": WLF_C2, "t_ref": T_REF},
    }
    temperature = round(rng.uniform(-40.0, 80.0), 1)
    a_t = wlf_shift(temperature)
    e_star = 2.0 * g_inf / (1.0 - nu)

    radius = _sig(_logu(rng, 0.005, 0.5), 4)
    a0 = rng.uniform(0.02, 0.15) * radius
    kind = rng.random()
    meta = {"index": index, "g_glassy": g_glassy, "f": f, "g_inf": g_inf, "nu": nu,
            "n_terms": n, "temperature": temperature, "a_T": a_t, "radius": radius,
            "a0_over_R": a0 / radius}
    if kind < 0.4:
        c1 = _sig(1.0 / radius)
        c2 = _sig(c1 * _logu(rng, 1e-3, 0.3))
        hz = hertz_ellipse(a0, c1, c2, e_star)
        roller = {"profile": "ellipsoid", "c1": c1, "c2": c2}
        meta.update(category="ellipsoid", c2_over_c1=c2 / c1, l_est=hz["l"],
                    flat_length=0.0, crown_radius=0.0, length=0.0)
        load = hz["load"]
    elif kind < 0.8:
        crown_radius = _sig(radius * _logu(rng, 10.0, 1000.0), 4)
        hz = hertz_ellipse(a0, 1.0 / radius, 1.0 / crown_radius, e_star)
        s_end = min(hz["l"] * rng.uniform(1.3, 3.0), 0.9 * crown_radius)
        phi = rng.uniform(0.0, 0.5)
        length = _sig(2.0 * s_end / (1.0 - phi), 4)
        flat = _sig(phi * length, 4)
        roller = {"profile": "crowned", "radius": radius, "flat_length": flat,
                  "crown_radius": crown_radius, "length": length}
        load = strip_load_per_length(a0, radius, e_star) * flat + hz["load"]
        meta.update(category="crowned", c2_over_c1=radius / crown_radius,
                    l_est=flat / 2 + hz["l"], flat_length=flat, crown_radius=crown_radius,
                    length=length)
    else:
        crown_radius = _sig(radius * _logu(rng, 0.08, 1.0), 4)
        length = _sig(radius * rng.uniform(2.0, 10.0), 4)
        s_end = crown_radius * rng.uniform(0.5, 0.95)
        flat = _sig(length - 2.0 * s_end, 4)
        roller = {"profile": "crowned", "radius": radius, "flat_length": flat,
                  "crown_radius": crown_radius, "length": length}
        load = strip_load_per_length(a0, radius, e_star) * flat
        meta.update(category="flat", c2_over_c1=radius / crown_radius, l_est=length / 2,
                    flat_length=flat, crown_radius=crown_radius, length=length)

    t_lo, t_hi = times[0] * a_t, times[-1] * a_t

    def draw_speed() -> float:
        tau_star = _logu(rng, t_lo / 10.0, t_hi * 10.0)
        return _sig(min(20.0, max(0.05, a0 / tau_star)), 4)

    speeds = [draw_speed()]
    if rng.random() < 0.15:
        speeds.append(draw_speed())
    active = []
    for v in speeds:  # terms neither relaxed nor glassy: V tau a_T/a0 in [1e-2, 1e2]
        active.append(sum(1 for t in times if 1e-2 <= v * t * a_t / a0 <= 1e2))
    meta.update(load=load, a0_est=a0, speeds=speeds,
                vtau_max_over_a0=[v * t_hi / a0 for v in speeds], active_est=active)
    scene = {
        "description": (f"front-door validation scene {index} (scripts/validate_front_door.py): "
                        f"{meta['category']} roller, R = {radius} m, {n} Prony terms, "
                        f"G_g = {g_glassy:.3g} Pa, f = {f:.3g}, T = {temperature} degC; "
                        f"generated, not measured"),
        "material": material,
        "roller": roller,
        "load": _sig(load),
        "temperature": temperature,
        "speeds": speeds,
    }
    return scene, meta


def make_scenes(seed: int, count: int) -> list[tuple[dict, dict]]:
    rng = random.Random(seed)
    return [make_scene(rng, i) for i in range(count)]


# ----------------------------------------------------------------------------------------------
# Unit checks of the generator (no solves)


def check_generator() -> None:
    fails = []

    def expect(cond: bool, what: str) -> None:
        if not cond:
            fails.append(what)

    # Elliptic integrals: K(0) = E(0) = pi/2;
    # K(0.5) = 1.8540746773013719, E(0.5) = 1.3506438810476755.
    k, e = ellip_ke(0.0)
    expect(abs(k - math.pi / 2) < 1e-15 and abs(e - math.pi / 2) < 1e-15, "K(0), E(0)")
    k, e = ellip_ke(0.5)
    expect(abs(k - 1.8540746773013719) < 1e-14, f"K(0.5) = {k}")
    expect(abs(e - 1.3506438810476755) < 1e-14, f"E(0.5) = {e}")
    # Hertz: the circle's limit a^3 = 3 P R/(4 E*), approached by c2 -> c1.
    r, es, a0 = 0.05, 1e6, 1e-3
    p_circle = 4.0 * es * a0**3 / (3.0 * r)
    hz = hertz_ellipse(a0, 1 / r, (1 - 1e-6) / r, es)
    expect(abs(hz["load"] / p_circle - 1) < 1e-5, f"circle limit {hz['load'] / p_circle}")
    expect(abs(hz["d"] / (a0 * a0 / r) - 1) < 1e-5, "circle penetration a^2/R")
    # Hertz against the bem's a_long_term of examples/scenes/paper.json (exact Hertz there):
    # c1 = 20, c2 = 1.596582, 20 N, G_inf = 0.3 MPa, nu = 0.5: a = 5.301 mm, l = 27.48 mm.
    es = 2 * 0.3e6 / 0.5
    lo, hi = 1e-3, 1e-2
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if hertz_ellipse(mid, 20.0, 1.596582, es)["load"] < 20.0:
            lo = mid
        else:
            hi = mid
    hz = hertz_ellipse(lo, 20.0, 1.596582, es)
    expect(abs(lo - 5.301e-3) < 0.6e-6, f"paper.json a = {lo}")
    expect(abs(hz["l"] - 27.48e-3) < 6e-6, f"paper.json l = {hz['l']}")
    # Slender limit: the ellipse's F0(0) = (pi/2) a0 p0 tends to the strip's pi a0^2 E*/(4R)
    # only logarithmically; check only its order.
    hz = hertz_ellipse(a0, 1 / r, 1e-4 / r, es)
    p0 = 3 * hz["load"] / (2 * math.pi * a0 * hz["l"])
    ratio = (math.pi / 2 * a0 * p0) / strip_load_per_length(a0, r, es)
    expect(0.5 < ratio < 1.5, f"slender ellipse F0(0)/strip {ratio}")
    # The strip: a0^2 = 4 R P'/(pi E*) inverted.
    pp = strip_load_per_length(a0, r, es)
    expect(abs(math.sqrt(4 * r * pp / (math.pi * es)) / a0 - 1) < 1e-14, "strip")
    # WLF: a_T(t_ref) = 1, a_T(-40) = 10^(8.86*60/41.6).
    expect(wlf_shift(20.0) == 1.0, "a_T(t_ref)")
    expect(abs(math.log10(wlf_shift(-40.0)) - 8.86 * 60 / 41.6) < 1e-12, "a_T(-40)")

    # The scenes: reproducible, in range, valid for the scene reader's ranges.
    s1 = json.dumps([s for s, _ in make_scenes(38, 200)])
    s2 = json.dumps([s for s, _ in make_scenes(38, 200)])
    expect(s1 == s2, "same seed, same scenes")
    expect(s1 != json.dumps([s for s, _ in make_scenes(39, 200)]), "another seed, other scenes")
    cats = {"ellipsoid": 0, "crowned": 0, "flat": 0}
    two = 0
    for scene, meta in make_scenes(38, 2000):
        m, ro = scene["material"], scene["roller"]
        gg = m["g_inf"] + sum(t["g"] for t in m["terms"])
        where = f"scene {meta['index']}"
        expect(1e5 * 0.999 <= gg <= 1e10 * 1.001, f"{where}: G_g {gg}")
        expect(0.999 <= gg / m["g_inf"] - 1 <= 1000 * 1.001, f"{where}: f {gg / m['g_inf'] - 1}")
        expect(1 <= len(m["terms"]) <= 20, f"{where}: terms")
        expect(all(1e-8 * 0.99 <= t["tau"] <= 1e2 * 1.01 and t["g"] > 0 for t in m["terms"]),
               f"{where}: term range")
        taus = [t["tau"] for t in m["terms"]]
        expect(taus == sorted(taus) and len(set(taus)) == len(taus), f"{where}: times distinct")
        expect(0.45 <= m["nu"] <= 0.5, f"{where}: nu")
        expect(-40 <= scene["temperature"] <= 80, f"{where}: T")
        expect(scene["temperature"] > T_REF - WLF_C2, f"{where}: T above the WLF limit")
        expect(all(0.05 <= v <= 20 for v in scene["speeds"]), f"{where}: speeds")
        expect(scene["load"] > 0 and math.isfinite(scene["load"]), f"{where}: load")
        expect(0.02 <= meta["a0_over_R"] <= 0.15, f"{where}: a0/R")
        expect(0.005 * 0.999 <= meta["radius"] <= 0.5 * 1.001, f"{where}: R")
        cats[meta["category"]] += 1
        two += len(scene["speeds"]) == 2
        if ro["profile"] == "ellipsoid":
            q = ro["c2"] / ro["c1"]
            expect(1e-3 * 0.999 <= q <= 0.3 * 1.001, f"{where}: c2/c1 {q}")
            # The load gives back a0 (P ~ a0^3 at fixed curvatures; rounded inputs: to 1e-4).
            es = 2 * m["g_inf"] / (1 - m["nu"])
            p = hertz_ellipse(meta["a0_est"], ro["c1"], ro["c2"], es)["load"]
            back = meta["a0_est"] * (scene["load"] / p) ** (1 / 3)
            expect(abs(back / meta["a0_est"] - 1) < 1e-4, f"{where}: Hertz a0 round trip")
        else:
            expect(0 <= ro["flat_length"] < ro["length"], f"{where}: flat < length")
            s_end = (ro["length"] - ro["flat_length"]) / 2
            expect(s_end < ro["crown_radius"], f"{where}: crowns end on their circles")
            if meta["category"] == "crowned":
                expect(ro["flat_length"] <= 0.5 * ro["length"] * 1.001, f"{where}: flat part")
                expect(10 * 0.999 <= ro["crown_radius"] / ro["radius"] <= 1000 * 1.001,
                       f"{where}: crown radius")
                expect(meta["l_est"] < ro["length"] / 2, f"{where}: contact inside the roller")
    expect(min(cats.values()) > 300, f"categories {cats}")
    expect(150 < two < 450, f"two speeds in {two} of 2000")
    if fails:
        print("generator check FAILED:\n  " + "\n  ".join(fails[:30]), file=sys.stderr)
        sys.exit(1)
    print(f"generator check passed (2000 scenes: {cats}, {two} with two speeds)")


# ----------------------------------------------------------------------------------------------
# Solving and comparing


def run(binary: str, scene_path: str, extra: list[str], timeout: float) -> dict:
    cmd = [binary, "--scene", scene_path, "--threads", "1", *extra]
    t0 = time.monotonic()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"cmd": cmd, "status": "timeout", "wall": time.monotonic() - t0, "lines": [],
                "stderr": ""}
    wall = time.monotonic() - t0
    lines = []
    for line in p.stdout.splitlines():
        line = line.strip()
        if line:
            lines.append(json.loads(line))
    return {"cmd": cmd, "status": p.returncode, "wall": wall, "lines": lines,
            "stderr": p.stderr.strip()}


def rel(a, b):
    if a is None or b is None:
        return None
    if b == 0:
        return 0.0 if a == 0 else math.inf
    return abs(a - b) / abs(b)


def warnings_of(rec: dict) -> list[str]:
    w = rec.get("warnings") or []
    if isinstance(w, str):
        w = [w] if w else []
    return list(w)


def fmt(x, spec=".4g"):
    if x is None:
        return ""
    if isinstance(x, bool):
        return "true" if x else "false"
    if isinstance(x, float):
        return format(x, spec)
    return str(x)


def study(args) -> int:
    binary = args.binary
    os.makedirs(args.scenes_dir, exist_ok=True)
    scenes = make_scenes(args.seed, args.count)
    rows = []
    t_start = time.monotonic()
    done = 0
    for scene, meta in scenes:
        if time.monotonic() - t_start > args.budget:
            print(f"budget of {args.budget} s spent: stopped after {done} of {len(scenes)} scenes",
                  file=sys.stderr)
            break
        path = os.path.join(args.scenes_dir, f"scene_{args.seed}_{meta['index']:03d}.json")
        with open(path, "w") as fh:
            json.dump(scene, fh, indent=1)
        front = run(binary, path, [], args.timeout)
        ref = run(binary, path, ["--method", "bem", "--tolerance", str(TOLERANCE_REF)],
                  args.timeout)
        done += 1
        for k, v in enumerate(scene["speeds"]):
            fr = next((r for r in front["lines"] if r.get("speed") == v), None)
            rr = next((r for r in ref["lines"] if r.get("speed") == v), None)
            row = {
                "seed": args.seed, "scene": meta["index"], "speed_index": k,
                "category": meta["category"],
                "radius": meta["radius"], "c2_over_c1": meta["c2_over_c1"],
                "flat_length": meta["flat_length"], "crown_radius": meta["crown_radius"],
                "length": meta["length"], "n_terms": meta["n_terms"],
                "g_glassy": meta["g_glassy"], "f": meta["f"], "g_inf": meta["g_inf"],
                "nu": meta["nu"], "temperature": meta["temperature"], "a_T": meta["a_T"],
                "speed": v, "vtau_max_over_a0": meta["vtau_max_over_a0"][k],
                "active_terms_est": meta["active_est"][k], "load": scene["load"],
                "a0_est": meta["a0_est"], "l_est": meta["l_est"],
                "front_status": front["status"], "ref_status": ref["status"],
                "front_wall_s": front["wall"], "ref_wall_s": ref["wall"],
                "front_stderr": "" if fr else front["stderr"][:300],
                "ref_stderr": "" if rr else ref["stderr"][:300],
            }
            if fr:
                fw = warnings_of(fr)
                row.update(
                    method=fr.get("method"), method_reason=fr.get("method_reason"),
                    front_converged=fr.get("converged"),
                    front_tolerance=fr.get("tolerance"),
                    front_tolerance_met=fr.get("tolerance_met"),
                    front_grid=fr.get("grid"), front_error_d=fr.get("error_d"),
                    front_error_chi=fr.get("error_chi"), d=fr.get("d"), chi=fr.get("chi"),
                    a_long_term=fr.get("a_long_term"), l0=fr.get("l0"),
                    front_seconds=fr.get("seconds"), front_warnings=" | ".join(fw),
                    front_n_warnings=len(fw))
            if rr:
                row.update(
                    ref_converged=rr.get("converged"), ref_tolerance_met=rr.get("tolerance_met"),
                    ref_grid=rr.get("grid"), ref_cells=rr.get("cells"),
                    ref_error_d=rr.get("error_d"), ref_error_chi=rr.get("error_chi"),
                    d_ref=rr.get("d"), chi_ref=rr.get("chi"), ref_seconds=rr.get("seconds"),
                    ref_a_long_term=rr.get("a_long_term"),
                    ref_warnings=" | ".join(warnings_of(rr)))
            ref_ok = bool(rr and rr.get("converged") and rr.get("tolerance_met"))
            row["ref_ok"] = ref_ok
            if fr and rr:
                row["rel_err_d"] = rel(fr.get("d"), rr.get("d"))
                row["rel_err_chi"] = rel(fr.get("chi"), rr.get("chi"))
                if rr.get("error_d") is not None and rr.get("d"):
                    row["ref_rel_error_d"] = rr["error_d"] / abs(rr["d"])
                if rr.get("error_chi") is not None and rr.get("chi"):
                    row["ref_rel_error_chi"] = rr["error_chi"] / abs(rr["chi"])
            ed, ec = row.get("rel_err_d"), row.get("rel_err_chi")
            within = (fr is not None and fr.get("converged") is True and ed is not None
                      and ec is not None and ed <= TOLERANCE_FRONT and ec <= TOLERANCE_FRONT)
            row["within_1pct"] = within
            add_floor(row)
            # What the result says about itself: strict (converged or tolerance_met false),
            # loose (any warning at all).
            row["says_missed_strict"] = bool(
                fr is None or fr.get("converged") is not True or fr.get("tolerance_met") is False)
            row["says_missed_any"] = bool(row["says_missed_strict"] or (fr and warnings_of(fr)))
            rows.append(row)
            print(f"scene {meta['index']:3d}.{k} {meta['category']:9s} "
                  f"{fmt(row.get('method'))}: d {fmt(ed, '.2e')} chi {fmt(ec, '.2e')} "
                  f"{'ok' if within else 'MISS'} ref_ok={ref_ok} "
                  f"({front['wall']:.1f} s, ref {ref['wall']:.1f} s)", file=sys.stderr,
                  flush=True)
            if not within and ref_ok and args.failures_dir:
                os.makedirs(args.failures_dir, exist_ok=True)
                with open(os.path.join(args.failures_dir,
                                       f"scene_{args.seed}_{meta['index']:03d}.json"), "w") as fh:
                    json.dump(scene, fh, indent=1)
    total = time.monotonic() - t_start
    write_csv(rows, args.csv)
    report(rows, done, len(scenes), total, args)
    return 0


def chi_floor(row: dict) -> float:
    """The bem's floor for chi, 1e-6 a_lt/R (chi_floor = 1e-6 C1 a_H in BemSolver::solve), from
    the reference's a_long_term; 0 where it has none (a flat idler whose long-term contact
    reaches the ends)."""
    alt = row.get("ref_a_long_term")
    return 1e-6 * alt / row["radius"] if alt else 0.0


def add_floor(row: dict) -> None:
    """chi's error over max(|chi_ref|, 1e-6 a_lt/R): the bem's own floor for chi (chi_floor =
    1e-6 C1 a_H in BemSolver::solve), under which chi is zero to the tolerance."""
    ec, chi_ref = row.get("rel_err_chi"), row.get("chi_ref")
    if ec is None or chi_ref is None:
        row["rel_err_chi_floor"], row["within_1pct_floor"] = None, False
        return
    floor = chi_floor(row)
    row["rel_err_chi_floor"] = ec * abs(chi_ref) / max(abs(chi_ref), floor) if chi_ref else 0.0
    ed = row.get("rel_err_d")
    row["within_1pct_floor"] = bool(
        row.get("front_converged") is True and ed is not None and ed <= TOLERANCE_FRONT
        and row["rel_err_chi_floor"] <= TOLERANCE_FRONT)


def _parse(v: str):
    if v == "":
        return None
    if v in ("true", "false"):
        return v == "true"
    try:
        return int(v)
    except ValueError:
        pass
    try:
        return float(v)
    except ValueError:
        return v


def rescore(specs: list[str], args) -> int:
    """Merge the CSVs of earlier runs (SEED:FILE; the seed column is filled from SEED where
    missing), recompute the criteria and print the report: no solves."""
    rows, seeds = [], []
    for spec in specs:
        seed, _, path = spec.partition(":")
        seeds.append(seed)
        with open(path, newline="") as fh:
            for raw in csv.DictReader(fh):
                r = {k: _parse(v) for k, v in raw.items()}
                if r.get("seed") is None:
                    r["seed"] = int(seed)
                add_floor(r)
                rows.append(r)
    write_csv(rows, args.csv)
    args.seed = "+".join(seeds)
    scenes = {(r["seed"], r["scene"]) for r in rows}
    report(rows, len(scenes), len(scenes), float("nan"), args)
    return 0


CSV_FIELDS = [
    "seed", "scene", "speed_index", "category", "radius", "c2_over_c1", "flat_length",
    "crown_radius",
    "length", "n_terms", "g_glassy", "f", "g_inf", "nu", "temperature", "a_T", "speed",
    "vtau_max_over_a0", "active_terms_est", "load", "a0_est", "a_long_term", "ref_a_long_term",
    "l_est", "l0", "method", "method_reason", "front_converged", "front_tolerance",
    "front_tolerance_met", "front_grid", "front_error_d", "front_error_chi", "d", "chi", "d_ref",
    "chi_ref", "rel_err_d", "rel_err_chi", "rel_err_chi_floor", "within_1pct",
    "within_1pct_floor", "says_missed_strict", "says_missed_any",
    "ref_ok", "ref_converged", "ref_tolerance_met", "ref_grid", "ref_cells", "ref_rel_error_d",
    "ref_rel_error_chi", "front_seconds", "ref_seconds", "front_wall_s", "ref_wall_s",
    "front_status", "ref_status", "front_n_warnings", "front_warnings", "ref_warnings",
    "front_stderr", "ref_stderr",
]


def write_csv(rows: list[dict], path: str) -> None:
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(CSV_FIELDS)
        for r in rows:
            w.writerow([fmt(r.get(k), ".6g") for k in CSV_FIELDS])


# A reference that did not meet TOLERANCE_REF at its largest grid but converged there with its
# own estimated error (chi's over the bem's floor) at most half the front door's tolerance.
REF_USABLE = 0.005


def ref_usable(r: dict) -> bool:
    """The reference met TOLERANCE_REF, or converged with its estimates within REF_USABLE."""
    if r["ref_ok"]:
        return True
    ed, ec, chi_ref = r.get("ref_rel_error_d"), r.get("ref_rel_error_chi"), r.get("chi_ref")
    if r.get("ref_converged") is not True or ed is None or ec is None or not chi_ref:
        return False
    return ed <= REF_USABLE and ec * abs(chi_ref) / max(abs(chi_ref), chi_floor(r)) <= REF_USABLE


def report(rows: list[dict], done: int, planned: int, total: float, args) -> None:
    ok_rows = [r for r in rows if r["ref_ok"]]
    bad_ref = [r for r in rows if not r["ref_ok"]]
    within = [r for r in ok_rows if r["within_1pct"]]
    misses = [r for r in ok_rows if not r["within_1pct"]]
    scenes_ok = sorted({(r.get("seed"), r["scene"]) for r in ok_rows})
    scenes_within = [s for s in scenes_ok
                     if all(r["within_1pct"] for r in ok_rows
                            if (r.get("seed"), r["scene"]) == s)]
    within_floor = [r for r in ok_rows if r.get("within_1pct_floor")]
    out = []
    if total == total:
        out.append(f"seed {args.seed}: {done} of {planned} scenes solved ({len(rows)} results) "
                   f"in {total:.0f} s")
    else:
        out.append(f"seeds {args.seed}: {done} scenes ({len(rows)} results), rescored")
    out.append(f"reference (bem, tolerance {TOLERANCE_REF}) not met or not converged: "
               f"{len(bad_ref)} results in "
               f"{len({(r.get('seed'), r['scene']) for r in bad_ref})} scenes "
               f"(excluded)")
    if ok_rows:
        out.append(f"within 1% in d and chi: {len(within)} of {len(ok_rows)} results "
                   f"({100 * len(within) / len(ok_rows):.1f}%); scenes all within: "
                   f"{len(scenes_within)} of {len(scenes_ok)} "
                   f"({100 * len(scenes_within) / max(1, len(scenes_ok)):.1f}%)")
        out.append(f"within 1% with chi's error over max(chi_ref, 1e-6 a_lt/R) (the bem's floor): "
                   f"{len(within_floor)} of {len(ok_rows)} "
                   f"({100 * len(within_floor) / len(ok_rows):.1f}%)")
        wide = [r for r in rows if ref_usable(r)]
        wide_in = [r for r in wide if r.get("within_1pct_floor")]
        out.append(f"with the references that converged at their largest grid with estimates "
                   f"<= {REF_USABLE:.1%} (chi over the floor): {len(wide_in)} of {len(wide)} "
                   f"results within 1% ({100 * len(wide_in) / max(1, len(wide)):.1f}%); "
                   f"those outside:")
        for r in wide:
            if not r.get("within_1pct_floor"):
                out.append(f"    scene {r.get('seed')}:{r['scene']}.{r['speed_index']} "
                           f"{r['category']} method={r.get('method')} d err "
                           f"{fmt(r.get('rel_err_d'), '.3%')} chi err (floored) "
                           f"{fmt(r.get('rel_err_chi_floor'), '.3%')} ref est d/chi "
                           f"{fmt(r.get('ref_rel_error_d'), '.2%')}/"
                           f"{fmt(r.get('ref_rel_error_chi'), '.2%')} converged="
                           f"{r.get('front_converged')} tolerance_met="
                           f"{r.get('front_tolerance_met')} says={r['says_missed_any']}")
        front_bad = [r for r in rows if r.get("front_converged") is not True]
        out.append(f"front door results not converged (each says converged false): "
                   f"{len(front_bad)}")
    for m in ("line", "bem", "plane", None):
        sub = [r for r in ok_rows if r.get("method") == m]
        if sub:
            w = sum(r["within_1pct"] for r in sub)
            out.append(f"  method {m}: {len(sub)} results, {w} within 1%")
    by_cat = {}
    for r in ok_rows:
        by_cat.setdefault(r["category"], []).append(r)
    for c, sub in sorted(by_cat.items()):
        out.append(f"  {c}: {len(sub)} results, {sum(r['within_1pct'] for r in sub)} within 1%")
    for key in ("front_wall_s", "ref_wall_s"):
        vals = [r[key] for r in rows if r.get("speed_index") == 0 and r.get(key) is not None]
        if vals:
            out.append(f"  {key}: median {statistics.median(vals):.2f} s, max {max(vals):.2f} s")
    for m in ("line", "bem"):
        vals = [r["front_seconds"] for r in rows
                if r.get("method") == m and r.get("front_seconds") is not None]
        if vals:
            out.append(f"  front seconds per solve ({m}): median {statistics.median(vals):.3f} s")
    worst_d = max(ok_rows, key=lambda r: r.get("rel_err_d") or 0.0, default=None)
    worst_c = max(ok_rows, key=lambda r: r.get("rel_err_chi") or 0.0, default=None)
    if worst_d:
        out.append(f"worst d: scene {worst_d.get('seed')}:{worst_d['scene']} "
                   f"({worst_d.get('method')}) "
                   f"{fmt(worst_d.get('rel_err_d'), '.3%')}")
    if worst_c:
        out.append(f"worst chi: scene {worst_c.get('seed')}:{worst_c['scene']} "
                   f"({worst_c.get('method')}) "
                   f"{fmt(worst_c.get('rel_err_chi'), '.3%')}")
    out.append(f"misses ({len(misses)}):")
    for r in misses:
        out.append(f"  scene {r.get('seed')}:{r['scene']}.{r['speed_index']} {r['category']} "
                   f"method={r.get('method')} d err {fmt(r.get('rel_err_d'), '.3%')} chi err "
                   f"{fmt(r.get('rel_err_chi'), '.3%')} "
                   f"(floored {fmt(r.get('rel_err_chi_floor'), '.3%')}) "
                   f"chi_ref {fmt(r.get('chi_ref'))} "
                   f"converged={r.get('front_converged')} tolerance_met="
                   f"{r.get('front_tolerance_met')} says(strict)={r['says_missed_strict']} "
                   f"says(any warning)={r['says_missed_any']} grid={r.get('front_grid')} "
                   f"est err d/chi {fmt(r.get('front_error_d'))}/{fmt(r.get('front_error_chi'))}"
                   f"\n    reason: {r.get('method_reason')}\n    warnings: "
                   f"{r.get('front_warnings') or r.get('front_stderr')}")
    out.append(f"excluded (reference not met) ({len(bad_ref)}):")
    for r in bad_ref:
        out.append(f"  scene {r.get('seed')}:{r['scene']}.{r['speed_index']} {r['category']} "
                   f"ref converged="
                   f"{r.get('ref_converged')} tolerance_met={r.get('ref_tolerance_met')} grid="
                   f"{r.get('ref_grid')} status={r['ref_status']} front method={r.get('method')}"
                   f" d err {fmt(r.get('rel_err_d'), '.3%')} chi err "
                   f"{fmt(r.get('rel_err_chi'), '.3%')} {(r.get('ref_stderr') or '')[:200]}")
    for c in ("ellipsoid", "crowned", "flat"):  # the bem's a_long_term: Hertz, or the line's
        rc = [r["a0_est"] / r["ref_a_long_term"] for r in rows if r.get("ref_a_long_term")
              and r.get("speed_index") == 0 and r["category"] == c]
        if rc:
            out.append(f"a0 estimate / the bem's a_long_term ({c}): "
                       f"{min(rc):.3f} ... {max(rc):.3f} (median {statistics.median(rc):.3f})")
    print("\n".join(out))


def main() -> int:
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--seed", type=int, default=38)
    ap.add_argument("--count", type=int, default=60)
    ap.add_argument("--budget", type=float, default=1380.0,
                    help="seconds after which no new scene is started (default 1380)")
    ap.add_argument("--timeout", type=float, default=300.0, help="seconds per run")
    ap.add_argument("--binary", default=os.path.join(root, "build/release/bin/viscoroll-solve"))
    ap.add_argument("--csv", default=os.path.join(root, "docs/figures/front_door_validation.csv"))
    ap.add_argument("--scenes-dir", default="/tmp/front_door_scenes")
    ap.add_argument("--failures-dir", default="/tmp/front_door_failures")
    ap.add_argument("--check", action="store_true", help="unit-check the generator and exit")
    ap.add_argument("--dry-run", metavar="DIR", help="write the scenes to DIR and exit")
    ap.add_argument("--rescore", nargs="+", metavar="SEED:CSV",
                    help="merge earlier runs' CSVs into --csv and report (no solves)")
    args = ap.parse_args()
    if args.check:
        check_generator()
        return 0
    if args.rescore:
        return rescore(args.rescore, args)
    if args.dry_run:
        os.makedirs(args.dry_run, exist_ok=True)
        for scene, meta in make_scenes(args.seed, args.count):
            with open(os.path.join(args.dry_run, f"scene_{args.seed}_{meta['index']:03d}.json"),
                      "w") as fh:
                json.dump(scene, fh, indent=1)
        return 0
    return study(args)


if __name__ == "__main__":
    sys.exit(main())
