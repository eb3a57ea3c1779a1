"""Builds nineball._core with the project's CMake build while setuptools packs the package.

pyproject.toml holds the package's description; this file only adds the compiled core: CMake
configures the tree (tests and benchmarks off) and builds the one target nineball_python, for
the interpreter running the build, and the module is copied into the package.
"""
import glob
import os
import shutil
import subprocess
import sys

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

SOURCE = os.path.dirname(os.path.abspath(__file__))


class BuildCoreWithCMake(build_py):
    def run(self):
        super().run()
        build = os.path.join(os.path.abspath(self.get_finalized_command("build").build_temp),
                             "cmake")
        # NINEBALL_BUILD_TYPE=Debug builds in a third of the time, unoptimised (the tests'
        # pip install does): the package is the same, its physics slower.
        build_type = os.environ.get("NINEBALL_BUILD_TYPE", "Release")
        subprocess.run(["cmake", "-S", SOURCE, "-B", build, "-DCMAKE_BUILD_TYPE=" + build_type,
                        "-DNINEBALL_TESTS=OFF", "-DNINEBALL_BENCH=OFF",
                        # Built once: sources compiled several to a unit, half the build's time.
                        "-DCMAKE_UNITY_BUILD=ON",
                        "-DPython3_EXECUTABLE=" + sys.executable], check=True)
        subprocess.run(["cmake", "--build", build, "--target", "nineball_python", "--parallel",
                        str(os.cpu_count() or 1)], check=True)
        built = glob.glob(os.path.join(build, "python", "nineball", "_core.*.so"))
        if len(built) != 1:
            raise RuntimeError("the CMake build made no nineball._core: " + repr(built))
        target = os.path.join(self.build_lib, "nineball")
        os.makedirs(target, exist_ok=True)
        shutil.copy2(built[0], target)


class CompiledDistribution(Distribution):
    """A wheel for this interpreter and platform: the package holds a compiled module."""

    def has_ext_modules(self):
        return True


# Its own build folder: build/ is the CMake build's.
setup(cmdclass={"build_py": BuildCoreWithCMake}, distclass=CompiledDistribution,
      options={"build": {"build_base": "build-pip"}})
