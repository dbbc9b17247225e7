"""viscoroll.solve and viscoroll.sweep against the command line viscoroll-solve on the shipped
scenes: every output field to 1e-12 (relative) at single speeds (a cold start each), and a sweep
against the command line's sweep over all of a scene's speeds (both viscoroll::sweep, chunks of
16)."""

import json
import math
import subprocess

import numpy as np
import pytest

import viscoroll as vr

# (scene file, method or None for the file's, grid or None, indices of the speeds to check or None
# for all)
CASES = [
    ("paper.json", None, None, None),
    ("paper.json", "bem", 6, [0, 8, 12, 16, 24]),
    ("polyamide_cylinder.json", None, None, None),
    ("rubber_roller.json", None, None, None),
    ("rubber_roller.json", "bem", 6, [0, 3, 7]),
    ("rubber_ball.json", None, None, None),
    ("crowned_roller_line.json", None, None, None),  # a roller of finite length, line method
    ("crowned_roller_prony_line.json", None, None, None),  # the same roller on a prony spectrum
    ("crowned_roller_line.json", "bem", 8, [0, 2]),  # a roller of finite length, bem method
    ("crowned_roller_prony_line.json", "bem", 8, [1]),
    ("crowned_roller_line.json", "bem", None, [1]),  # the bem at its default tolerance, 0.01
    ("press_roll.json", None, None, None),
]

TOLERANCE = 1e-12


def run_cli(program, scene_path, method, grid, speeds, extra=()):
    """The command line's JSON lines for `speeds` (its sweep: chunks of 16 with continuation),
    with the options `extra` after the others."""
    args = [str(program), "--scene", str(scene_path),
            "--speed", ",".join(repr(float(v)) for v in speeds), *extra]
    if method:
        args += ["--method", method]
    if grid:
        args += ["--grid", str(grid)]
    done = subprocess.run(args, capture_output=True, text=True, check=False)
    assert done.returncode in (0, 1), done.stderr
    return [json.loads(line) for line in done.stdout.splitlines()]


def close(a, b):
    if a is None or b is None:  # JSON null: not finite
        return (a is None or not math.isfinite(a)) and (b is None or not math.isfinite(b))
    return abs(a - b) <= TOLERANCE * max(abs(a), abs(b)) or a == b


def compare(expected, got, where):
    """`expected`: a JSON line; `got`: field -> value. Every field but seconds."""
    for key, want in expected.items():
        if key == "seconds":
            continue
        have = got[key]
        if isinstance(want, bool) or isinstance(want, (str, list)):
            assert have == want, f"{where}: {key} = {have!r}, command line {want!r}"
        elif isinstance(want, int) and key != "residual":
            assert have == want, f"{where}: {key} = {have!r}, command line {want!r}"
        else:
            assert close(want, have), f"{where}: {key} = {have!r}, command line {want!r}"


def compare_sweep(expected, got, where):
    """`expected`: the command line's JSON lines; `got`: sweep()'s columns, row by row."""
    assert len(expected) == len(got["speed"])
    for i, line in enumerate(expected):
        row = {key: (value[i].item() if isinstance(value, np.ndarray) else value[i])
               for key, value in got.items()}
        row["method"] = line["method"]
        compare(line, row, f"{where} speed[{i}]")


@pytest.mark.parametrize("file,method,grid,indices", CASES,
                         ids=[f"{c[0]}-{c[1] or 'file'}" for c in CASES])
def test_single_speeds_match_the_command_line(viscoroll_solve, scenes_dir, file, method, grid,
                                              indices):
    scene = vr.Scene.from_json(scenes_dir / file)
    speeds = scene.speeds if indices is None else scene.speeds[indices]
    for v in speeds:
        (expected,) = run_cli(viscoroll_solve, scenes_dir / file, method, grid, [v])
        result = vr.solve(scene, method=method, grid=grid, speed=float(v))
        assert expected["method"] == result.method
        got = result.as_dict()
        assert list(got) == list(expected), "the same fields in the same order"
        compare(expected, got, f"{file} {result.method} speed {v}")


@pytest.mark.parametrize("file,method,grid", [("paper.json", None, None),
                                              ("polyamide_cylinder.json", None, None),
                                              ("rubber_ball.json", None, None),
                                              ("crowned_roller_line.json", None, None),
                                              ("crowned_roller_prony_line.json", None, None)])
def test_sweep_matches_the_command_lines_sweep(viscoroll_solve, scenes_dir, file, method, grid):
    """Both sweep with viscoroll::sweep in chunks of DEFAULT_CHUNK (paper.json: 25 speeds, two
    chunks, so the second chunk's cold start is compared too)."""
    scene = vr.Scene.from_json(scenes_dir / file)
    expected = run_cli(viscoroll_solve, scenes_dir / file, method, grid, scene.speeds)
    got = vr.sweep(scene, method=method, grid=grid, threads=1)
    assert len(expected) == len(scene.speeds)
    compare_sweep(expected, got, file)


@pytest.mark.parametrize("file", ["paper.json", "crowned_roller_line.json",
                                  "crowned_roller_prony_line.json"])
def test_the_fast_setting_matches_the_command_lines(viscoroll_solve, scenes_dir, file):
    """setting="fast" and --setting fast: the same solver (6-point panels for one relaxation
    time, the spectrum's own for a prony material) and options, in a sweep and at one speed."""
    scene = vr.Scene.from_json(scenes_dir / file)
    expected = run_cli(viscoroll_solve, scenes_dir / file, None, None, scene.speeds,
                       ["--setting", "fast"])
    default = run_cli(viscoroll_solve, scenes_dir / file, None, None, scene.speeds)
    got = vr.sweep(scene, threads=1, setting="fast")
    assert len(expected) == len(scene.speeds)
    compare_sweep(expected, got, f"{file} fast")
    # Not the default run (another discretisation of the integrals at least).
    assert any(line["l"] != plain["l"] for line, plain in zip(expected, default))
    (first,) = run_cli(viscoroll_solve, scenes_dir / file, None, None, scene.speeds[:1],
                       ["--setting", "fast"])
    one = vr.solve(scene, speed=float(scene.speeds[0]), setting="fast")
    compare(first, one.as_dict(), f"{file} fast, one speed")


def test_a_scene_files_setting_is_the_default_of_solve_and_sweep(scenes_dir, tmp_path):
    """"setting": "fast" in the file: sweep() and solve() as with setting="fast"; setting="default"
    replaces it; the bem method ignores it."""
    document = json.loads((scenes_dir / "paper.json").read_text())
    document["setting"] = "fast"
    path = tmp_path / "paper_fast.json"
    path.write_text(json.dumps(document))
    fast_file = vr.Scene.from_json(path)
    paper = vr.Scene.from_json(scenes_dir / "paper.json")
    assert fast_file.setting == "fast" and paper.setting is None
    speeds = paper.speeds[:3]

    def same(x, y):
        assert x.keys() == y.keys()
        for key in x:
            if key != "seconds":
                assert list(x[key]) == list(y[key]), key

    same(vr.sweep(fast_file, speeds=speeds, threads=1),
         vr.sweep(paper, speeds=speeds, threads=1, setting="fast"))
    same(vr.sweep(fast_file, speeds=speeds, threads=1, setting="default"),
         vr.sweep(paper, speeds=speeds, threads=1))
    assert vr.solve(fast_file, speed=float(speeds[1])).l == \
        vr.solve(paper, speed=float(speeds[1]), setting="fast").l
    assert vr.solve(fast_file, method="bem", grid=6, speed=float(speeds[1])).converged


def test_scene_from_json_reads_what_the_command_line_reads(scenes_dir):
    scene = vr.Scene.from_json(scenes_dir / "paper.json")
    assert scene.method == "line" and scene.grid == 6 and scene.load == 20.0
    assert isinstance(scene.material, vr.StandardLinearSolid)
    assert (scene.material.mu_d, scene.material.nu, scene.material.f, scene.material.tau) == \
        (3.0e6, 0.5, 9.0, 0.01)
    assert isinstance(scene.roller, vr.Ellipsoid) and scene.roller.c2 == 1.596582
    assert scene.speeds.dtype == np.float64 and scene.speeds.shape == (25,)
    cylinder = vr.Scene.from_json(str(scenes_dir / "polyamide_cylinder.json"))
    assert isinstance(cylinder.roller, vr.Cylinder) and cylinder.method == "plane"
    crowned = vr.Scene.from_json(scenes_dir / "crowned_roller_line.json")
    assert type(crowned.roller) is vr.Crowned and crowned.method == "line"
    assert repr(crowned.roller) == ("Crowned(radius=0.05, flat_length=0.05, crown_radius=1, "
                                    "length=0.16)")
    assert (crowned.roller.radius, crowned.roller.tilt) == (0.05, 0.0)
    assert vr.solve(crowned, method="bem", grid=4, speed=1.0).converged


@pytest.mark.parametrize("method,grid", [("plane", None), ("line", None), ("bem", 6)])
def test_an_elastic_scene_matches_the_command_line(viscoroll_solve, tmp_path, method, grid):
    """An elastic material (no shipped scene has one), as a scene file and as Python objects."""
    document = {"material": {"model": "elastic", "mu": 1.0e6, "nu": 0.3},
                "roller": {"profile": "ellipsoid", "c1": 20.0, "c2": 1.0}, "load": 10.0,
                "speeds": [0.0, 1.0]}
    path = tmp_path / "elastic.json"
    path.write_text(json.dumps(document))
    expected = run_cli(viscoroll_solve, path, method, grid, [1.0])[0]
    built = vr.Scene(material=vr.Elastic(mu=1.0e6, nu=0.3), roller=vr.Ellipsoid(c1=20.0, c2=1.0),
                     load=10.0)
    for scene in (vr.Scene.from_json(path), built):
        result = vr.solve(scene, method=method, grid=grid, speed=1.0)
        compare(expected, result.as_dict(), f"elastic {method}")
        assert result.tau == 0.0


@pytest.mark.parametrize("file", ["crowned_roller_line.json", "crowned_roller_prony_line.json"])
def test_a_tilted_roller_matches_the_command_line_and_mirrors(viscoroll_solve, scenes_dir,
                                                              tmp_path, file):
    """The shipped crowned roller misaligned by +-2 mrad (the asymmetric contact of the line
    method, docs/rollers.md "Tilt"): every field as the command line's, and the opposite tilt
    mirrors the ends to the iteration's tolerance (4 eps^0.6, tests/line/line_profile_tilt)."""
    document = json.loads((scenes_dir / file).read_text())
    ends = {}
    for tilt in (0.002, -0.002):
        document["roller"]["tilt"] = tilt
        path = tmp_path / f"tilt{tilt}.json"
        path.write_text(json.dumps(document))
        (expected,) = run_cli(viscoroll_solve, path, None, None, [0.1])
        result = vr.solve(vr.Scene.from_json(path), speed=0.1)
        compare(expected, result.as_dict(), f"{file} tilt {tilt}")
        assert result.converged
        ends[tilt] = (result.y_minus, result.y_plus)
    tolerance = 4 * np.finfo(float).eps ** 0.6 * (ends[0.002][1] - ends[0.002][0])
    assert ends[0.002][0] + ends[0.002][1] < 0  # the load moves to the side pressed harder
    assert abs(ends[0.002][0] + ends[-0.002][1]) < tolerance
    assert abs(ends[0.002][1] + ends[-0.002][0]) < tolerance


def without_method(scene_path, tmp_path, **changes):
    """The scene file with neither method nor grid (the auto method), and `changes`."""
    document = json.loads(scene_path.read_text())
    document.pop("method", None)
    document.pop("grid", None)
    document.update(changes)
    path = tmp_path / ("auto_" + scene_path.name)
    path.write_text(json.dumps(document))
    return path


# The paper's scene (the line method answers), the same rubber with c2 close to the line theory's
# limit (a contact not slender: the bem at 1%), and a scene of the paper's dimensionless kind where
# the line equations have no root at some speeds (each of those answered by the bem method).
AUTO_SCENES = {
    "paper": lambda scenes_dir, tmp_path: without_method(scenes_dir / "paper.json", tmp_path),
    "short contact": lambda scenes_dir, tmp_path: without_method(
        scenes_dir / "paper.json", tmp_path,
        roller={"profile": "ellipsoid", "c1": 20.0, "c2": 6.0}, speeds=[0.01, 1.0]),
}


@pytest.mark.parametrize("name", list(AUTO_SCENES))
def test_an_auto_scene_matches_the_command_line(viscoroll_solve, scenes_dir, tmp_path, name):
    """No method in the file: the auto method in both, each result the command line's record
    (method_reason included) at single speeds and in a sweep."""
    path = AUTO_SCENES[name](scenes_dir, tmp_path)
    scene = vr.Scene.from_json(path)
    assert scene.method is None
    speeds = scene.speeds[[0, 12, 24]] if len(scene.speeds) > 3 else scene.speeds
    for v in speeds:
        (expected,) = run_cli(viscoroll_solve, path, None, None, [v])
        result = vr.solve(scene, speed=float(v))
        assert expected["method"] == result.method and "method_reason" in expected
        got = result.as_dict()
        assert list(got) == list(expected), "the same fields in the same order"
        compare(expected, got, f"auto {name} speed {v}")
    expected = run_cli(viscoroll_solve, path, None, None, speeds)
    compare_sweep(expected, vr.sweep(scene, speeds=speeds, threads=1), f"auto {name} sweep")


def test_an_auto_sweep_of_both_methods_matches_the_command_line(viscoroll_solve, tmp_path):
    """A sweep where the line method stands at some speeds and not at others (no root): the
    command line's choice speed by speed, each result its record; the fields one method lacks are
    nan in the sweep's columns."""
    document = {"material": {"model": "standard_linear_solid", "mu_d": 1.0, "nu": 0.5, "f": 9.0,
                             "tau": 1.0},
                "roller": {"profile": "ellipsoid", "c1": 1.0, "c2": (math.log(20) - 1) / 25},
                "load": 5 / (3 * 10 * (1 - 0.5) / (2 * math.pi)),
                "speeds": [0.0257, 0.0326, 0.0412]}
    path = tmp_path / "both.json"
    path.write_text(json.dumps(document))
    expected = run_cli(viscoroll_solve, path, None, None, document["speeds"])
    assert {line["method"] for line in expected} == {"line", "bem"}
    got = vr.sweep(vr.Scene.from_json(path), threads=1)
    assert got["method"] == [line["method"] for line in expected]
    for i, line in enumerate(expected):
        row = {key: (value[i].item() if isinstance(value, np.ndarray) else value[i])
               for key, value in got.items()}
        compare(line, row, f"both speed[{i}]")
        missing = set(row) - set(line)
        assert all(row[key] is None or math.isnan(row[key]) for key in missing), missing
