"""`import viscoroll` in an interpreter that cannot load the build's extension fails at import
with an ImportError naming the interpreter the build is for (viscoroll/_build.py, written by
python/CMakeLists.txt), not later at the first NumPy call."""

import os
import subprocess
import sys

import numpy
import pytest

import viscoroll  # noqa: F401 (the package's _build module, as this interpreter loads it)
from viscoroll import _build


def import_with_numpy(tmp_path, numpy_init):
    """`python -c "import viscoroll"` with a stub package `numpy` (its __init__.py `numpy_init`)
    first on sys.path: the interpreter is this one, the stub its NumPy."""
    stub = tmp_path / "stub" / "numpy"
    stub.mkdir(parents=True)
    (stub / "__init__.py").write_text(numpy_init)
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(tmp_path / "stub"), env.get("PYTHONPATH", "")])
    return subprocess.run([sys.executable, "-c", "import viscoroll"], env=env,
                          capture_output=True, text=True, timeout=120, check=False)


MAJOR = int(numpy.__version__.split(".")[0])


@pytest.mark.parametrize("numpy_init,says", [
    ("raise ModuleNotFoundError(\"No module named 'numpy'\", name='numpy')\n",
     "NumPy cannot be imported in"),
    (f"__version__ = '{MAJOR + 1}.0.0'\n", f"has NumPy {MAJOR + 1}.0.0, another major version"),
    (f"__version__ = '{MAJOR - 1}.26.4'\n", "another major version"),
    ("", "NumPy of no version"),
], ids=["missing", "next major", "previous major", "no version"])
def test_an_interpreter_without_the_builds_numpy_fails_at_import(tmp_path, numpy_init, says):
    done = import_with_numpy(tmp_path, numpy_init)
    assert done.returncode != 0
    last = done.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError: viscoroll: "), done.stderr
    assert says in last
    assert f"viscoroll was built for {_build.executable} (Python {_build.python_version}" in last
    assert sys.executable in last


def test_the_builds_interpreter_passes_the_check():
    """This interpreter runs the module (the tests import it): the check passes, and what the
    build recorded is its Python and NumPy major version."""
    _build.check_interpreter()
    assert _build.python_version.split(".")[:2] == [str(v) for v in sys.version_info[:2]]
    assert _build.numpy_version.split(".")[0] == str(MAJOR)
