"""Fixtures of the viscoroll Python tests (run by ctest as python_tests, or by hand:
PYTHONPATH=build/<dir>/python VISCOROLL_SOLVE=build/<dir>/bin/viscoroll-solve python3 -m pytest -q
tests/python). The command line and panek_kalker are the references where they are built."""

import os
import pathlib
import shutil

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("VISCOROLL_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
SCENES = SOURCE_DIR / "examples" / "scenes"


def _program(variable, name):
    """The program named by the environment variable, else build/*/bin/<name>, else None."""
    path = os.environ.get(variable)
    if path:
        return pathlib.Path(path) if pathlib.Path(path).is_file() else None
    found = sorted((SOURCE_DIR / "build").glob("*/bin/" + name))
    return found[0] if found else shutil.which(name) and pathlib.Path(shutil.which(name))


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="session")
def scenes_dir():
    return SCENES


@pytest.fixture(scope="session")
def viscoroll_solve():
    path = _program("VISCOROLL_SOLVE", "viscoroll-solve")
    if path is None:
        pytest.skip("viscoroll-solve is not built (set VISCOROLL_SOLVE to its path; "
                    "cmake --build <dir> --target viscoroll_solve)")
    return path


@pytest.fixture(scope="session")
def panek_kalker():
    path = _program("VISCOROLL_PANEK_KALKER", "panek_kalker")
    if path is None:
        pytest.skip("panek_kalker is not built (set VISCOROLL_PANEK_KALKER to its path; "
                    "cmake --build <dir> --target panek_kalker)")
    return path
