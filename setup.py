"""Builds the extension contain._contain with the project's CMake build, for pip.

pyproject.toml holds the metadata; this file adds what setuptools cannot know: the version (from
CMakeLists.txt's project(), the one place it is written) and a build_ext that configures the
CMake project (Release, no tests, no CLI-only extras), builds the target contain_python for the
interpreter running pip, and copies the module into the wheel.

Environment:
  CONTAIN_CMAKE_ARGS       extra arguments for the configure step (e.g. "-G Ninja"); ccache is
                           used as the compiler launcher when it is on PATH
  CONTAIN_CMAKE_BUILD_DIR  an existing build tree of this project, configured for this
                           interpreter, to build and take the module from instead of configuring
                           a new one (what the test suite does where no ccache is available)
  CMAKE_BUILD_PARALLEL_LEVEL  jobs for the build (default: every core)
"""

import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def cmake_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    found = re.search(r"project\(\s*contain\s+VERSION\s+([0-9][0-9.]*)", text)
    if not found:
        raise RuntimeError("CMakeLists.txt: project(contain VERSION x.y.z) not found")
    return found.group(1)


class CMakeExtension(Extension):
    """The CMake target `target`, whose output is the extension module `name`."""

    def __init__(self, name, target):
        super().__init__(name, sources=[])
        self.target = target


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if shutil.which("cmake") is None:
            raise RuntimeError("building contain needs cmake (Debian: apt-get install cmake)")
        given = os.environ.get("CONTAIN_CMAKE_BUILD_DIR")
        build_dir = pathlib.Path(given).resolve() if given else pathlib.Path(self.build_temp).resolve()
        if not given:
            self.configure(build_dir)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        self.announce(f"building {ext.target} in {build_dir}", level=2)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", ext.target, "-j", jobs],
                       check=True)
        built = sorted((build_dir / "python" / "contain").glob("_contain*.so"))
        if not built:
            raise RuntimeError(f"no _contain*.so in {build_dir / 'python' / 'contain'}")
        destination = pathlib.Path(self.get_ext_fullpath(ext.name))
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], destination)
        # The plugins (GDAL, muparser) travel beside the extension, where contain::io looks.
        for name in ("libcontain_gdal.so", "libcontain_muparser.so"):
            plugin = build_dir / "python" / "contain" / name
            if plugin.exists():
                shutil.copyfile(plugin, destination.parent / plugin.name)

    def configure(self, build_dir):
        build_dir.mkdir(parents=True, exist_ok=True)
        args = [
            "cmake", "-S", str(ROOT), "-B", str(build_dir),
            "-DCMAKE_BUILD_TYPE=Release",
            "-DCONTAIN_BUILD_TESTS=OFF",
            "-DCONTAIN_BUILD_PYTHON=ON",
            f"-DPython3_EXECUTABLE={sys.executable}",
        ]
        if shutil.which("ninja") and "-G" not in os.environ.get("CONTAIN_CMAKE_ARGS", ""):
            args += ["-G", "Ninja"]
        if shutil.which("ccache"):
            args.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        args += shlex.split(os.environ.get("CONTAIN_CMAKE_ARGS", ""))
        subprocess.run(args, check=True)


setup(
    version=cmake_version(),
    ext_modules=[CMakeExtension("contain._contain", target="contain_python")],
    cmdclass={"build_ext": CMakeBuild},
)
