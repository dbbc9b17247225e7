"""`pip install --no-build-isolation .`: the Python module viscoroll (docs/python.md, "Build, try,
install") for the interpreter that runs pip.

CMake stays the one description of the build: build_ext below configures the project's own
CMakeLists.txt (Release, only the module: no tests, examples, benchmarks, header checks or install
rules) with -DPython3_EXECUTABLE=<this interpreter>, builds the one target viscoroll_python
(CMAKE_BUILD_PARALLEL_LEVEL jobs, 2 unless set) and copies what python/CMakeLists.txt puts in
<build>/python/viscoroll/ (the extension _viscoroll and the generated _build.py) into the wheel;
the package's .py files (__init__.py, _study.py) are python/viscoroll/'s. Everything setuptools
and CMake write stays under build/ (.gitignore). VISCOROLL_CMAKE_ARGS adds arguments to the
configure step (for example -DVISCOROLL_FFTW=OFF)."""

import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.egg_info import egg_info

ROOT = pathlib.Path(__file__).resolve().parent


def project_version():
    """The version of the top-level CMakeLists.txt's `project(viscoroll VERSION ...)`, which CMake
    also compiles into the extension as viscoroll.__version__."""
    found = re.search(r"^project\(viscoroll VERSION ([0-9.]+)",
                      (ROOT / "CMakeLists.txt").read_text(), re.MULTILINE)
    if not found:
        raise SystemExit("viscoroll: no `project(viscoroll VERSION x.y.z` in CMakeLists.txt")
    return found.group(1)


def numpy_requirement():
    """NumPy of the major version this interpreter has: `import viscoroll` refuses another one
    (viscoroll/_build.py; pybind11 binds NumPy's C API of the build's major version). Without NumPy
    the build stops here, before compiling, rather than install a module that cannot be imported."""
    try:
        import numpy  # pylint: disable=import-outside-toplevel
    except ImportError as error:
        raise SystemExit(
            f"viscoroll: NumPy cannot be imported in {sys.executable} ({error}); the module needs "
            "it. On Debian: apt-get install python3-numpy, and make the virtual environment with "
            "--system-site-packages (docs/python.md)") from error
    major = int(numpy.__version__.split(".")[0])
    return f"numpy>={major},<{major + 1}"


class CMakeBuild(build_ext):
    """The extension viscoroll._viscoroll and viscoroll/_build.py, built by CMake."""

    def build_extension(self, ext):
        cmake = shutil.which("cmake")
        if cmake is None:
            raise SystemExit("viscoroll: cmake not found (Debian: apt-get install cmake; "
                             "scripts/install-deps.sh installs every dependency)")
        build_dir = pathlib.Path(self.build_temp).resolve() / "cmake"
        build_dir.mkdir(parents=True, exist_ok=True)
        configure = [cmake, "-S", str(ROOT), "-B", str(build_dir),
                     "-DCMAKE_BUILD_TYPE=Release",
                     f"-DPython3_EXECUTABLE={sys.executable}",
                     "-DVISCOROLL_PYTHON=ON",
                     "-DVISCOROLL_BUILD_TESTS=OFF",
                     "-DVISCOROLL_BUILD_EXAMPLES=OFF",
                     "-DVISCOROLL_BUILD_BENCHMARKS=OFF",
                     "-DVISCOROLL_HEADER_CHECKS=OFF",
                     "-DVISCOROLL_INSTALL=OFF"]
        if (not (build_dir / "CMakeCache.txt").exists() and "CMAKE_GENERATOR" not in os.environ
                and shutil.which("ninja")):
            configure += ["-G", "Ninja"]
        configure += shlex.split(os.environ.get("VISCOROLL_CMAKE_ARGS", ""))
        env = dict(os.environ)
        env.setdefault("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        subprocess.run(configure, check=True, env=env)
        subprocess.run([cmake, "--build", str(build_dir), "--target", "viscoroll_python"],
                       check=True, env=env)

        built = build_dir / "python" / "viscoroll"
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        if not (built / target.name).is_file():
            found = sorted(path.name for path in built.glob("_viscoroll*"))
            raise SystemExit(f"viscoroll: CMake built {found} in {built}, not {target.name} "
                             f"(the extension suffix of {sys.executable})")
        shutil.copy2(built / target.name, target)
        shutil.copy2(built / "_build.py", target.parent / "_build.py")


class EggInfoUnderBuild(egg_info):
    """setuptools' viscoroll.egg-info under build/ (.gitignore), not next to the package in
    python/."""

    def finalize_options(self):
        if self.egg_base is None:
            (ROOT / "build").mkdir(exist_ok=True)
            self.egg_base = os.path.relpath(ROOT / "build")
        super().finalize_options()


setup(
    version=project_version(),
    install_requires=[numpy_requirement()],
    packages=["viscoroll"],
    package_dir={"": "python"},
    include_package_data=False,  # not python/viscoroll/_build.py.in
    ext_modules=[Extension("viscoroll._viscoroll", sources=[])],
    cmdclass={"build_ext": CMakeBuild, "egg_info": EggInfoUnderBuild},
    zip_safe=False,
)
