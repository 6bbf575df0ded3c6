"""pip install . : CMake builds the module _polyplan and the polyplan program and installs them,
with the package files and the libraries they link (python/CMakeLists.txt, component python), in
the wheel's staging folder. The CMake tree is kept in build/pip/, so that a second install
compiles only what changed; the developer's build/ tree is not touched.

CMAKE_BUILD_PARALLEL_LEVEL sets the compile jobs (default: every core); CXX and CMAKE_GENERATOR
choose the compiler and the generator of a new tree (default: clang++ and Ninja when installed,
as scripts/configure.sh does).
"""
import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


def version():
    """The project's version, kept in one place: CMakeLists.txt's project(polyplan VERSION ...)."""
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        return re.search(r"project\(polyplan VERSION ([0-9.]+)", f.read()).group(1)


def run(command, env):
    print(" ".join(command), flush=True)
    subprocess.run(command, env=env, check=True)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if self.inplace:  # it would put the module in the C++ library's folder polyplan/
            sys.exit("polyplan: no editable install; PYTHONPATH=build/python imports a build tree")
        tree = os.path.abspath(self.build_temp)  # one per interpreter: build/pip/temp.PLATFORM-PYTHON
        env = dict(os.environ)
        if "CXX" not in env and shutil.which("clang++"):
            env["CXX"] = "clang++"  # compiles CGAL's templates in three fifths of g++'s time
        if "CMAKE_GENERATOR" not in env and shutil.which("ninja"):
            env["CMAKE_GENERATOR"] = "Ninja"
        jobs = env.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        configure = ["cmake", "-S", ROOT, "-B", tree,
                     "-DCMAKE_BUILD_TYPE=Release", "-DPOLYPLAN_FAMILIES=all", "-DPOLYPLAN_PYTHON=ON",
                     "-DPOLYPLAN_BUILD_TESTS=OFF", "-DPOLYPLAN_BUILD_EXAMPLES=OFF",
                     f"-DPython_EXECUTABLE={sys.executable}",
                     f"-DPOLYPLAN_PYTHON_DIR={os.path.abspath(self.build_lib)}"]  # the wheel's root
        try:  # the pybind11 this interpreter imports (pip's, when pip isolates the build)
            import pybind11
            configure.append(f"-Dpybind11_DIR={pybind11.get_cmake_dir()}")
        except ImportError:
            pass  # CMake looks for Debian's pybind11-dev
        run(configure, env)
        run(["cmake", "--build", tree, "--parallel", jobs, "--target", "_polyplan", "polyplan_cli"], env)
        run(["cmake", "--install", tree, "--component", "python"], env)


setup(
    version=version(),
    packages=[],  # the package's files come from CMake's install, not from setuptools
    # A placeholder that makes the wheel one of this platform and Python; CMake builds the module.
    ext_modules=[Extension("polyplan._polyplan", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build/pip"}},
)
