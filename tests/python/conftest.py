"""Fixtures of the viscoroll Python tests (run by ctest as python_tests, or by hand:
PYTHONPATH=build/<dir>/python VISCOROLL_SOLVE=build/<dir>/bin/viscoroll-solve python3 -m pytest -q
tests/python; or against a `pip install`ed viscoroll: <venv>/bin/python -m pytest tests/python from
outside the source tree). The command line and panek_kalker are the references where they are
built; `pip install .` builds the module only, and the tests that compare with them skip unless a
CMake build has them (build/*/bin) or VISCOROLL_SOLVE and VISCOROLL_PANEK_KALKER name them."""

import os
import pathlib
import shutil
import signal
import subprocess
import sys
import time

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


def pytest_report_header(config):  # pylint: disable=unused-argument
    """Which viscoroll the tests run against (a build's python/ directory or an install)."""
    try:
        import viscoroll  # pylint: disable=import-outside-toplevel
    except ImportError as error:
        return f"viscoroll: cannot be imported ({error})"
    return f"viscoroll {viscoroll.__version__}: {pathlib.Path(viscoroll.__file__).parent}"


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
        pytest.skip("viscoroll-solve, the reference, is not built (pip install builds the module "
                    "only; cmake --build <dir> --target viscoroll_solve, or set VISCOROLL_SOLVE to "
                    "its path)")
    return path


@pytest.fixture(scope="session")
def panek_kalker():
    path = _program("VISCOROLL_PANEK_KALKER", "panek_kalker")
    if path is None:
        pytest.skip("panek_kalker, the reference, is not built (pip install builds the module "
                    "only; cmake --build <dir> --target panek_kalker, or set VISCOROLL_PANEK_KALKER "
                    "to its path)")
    return path


@pytest.fixture(scope="session")
def interrupted():
    """run(code): runs `code` in a child Python that first installs Python's own SIGINT handler
    (a suite started by a non-interactive shell's background job passes SIGINT on ignored, and
    Python keeps it so; ctest's children get the default back), waits for its line "started",
    sends SIGINT 1 s later and returns (seconds from the signal to the child's "interrupted
    <time.monotonic()>" line, the lines after it, stdout, stderr)."""
    def run(code):
        child = subprocess.Popen(
            [sys.executable, "-c",
             "import signal\nsignal.signal(signal.SIGINT, signal.default_int_handler)\n" + code],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=dict(os.environ))
        try:
            assert child.stdout.readline().strip() == "started"
            time.sleep(1.0)  # well into the call
            sent = time.monotonic()
            child.send_signal(signal.SIGINT)
            out, err = child.communicate(timeout=60)
        finally:
            child.kill()
        lines = out.splitlines()
        assert lines and lines[0].startswith("interrupted"), (out, err)
        assert child.returncode == 0, err
        return float(lines[0].split()[1]) - sent, lines[1:], out, err
    return run
