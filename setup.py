"""Builds the C++ core of the Python module (pound._core) with CMake for `pip install .`.

The build goes into pip's temporary folder, or into $POUND_BUILD_DIR when set (a folder kept
between installs, so a second install only relinks).
"""

import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = pathlib.Path(os.environ.get("POUND_BUILD_DIR") or
                             pathlib.Path(self.build_temp).resolve() / "cmake")
        generator = ["-G", "Ninja"] if shutil.which("ninja") else []
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build), *generator,
                        "-DCMAKE_BUILD_TYPE=Release", "-DPOUND_BUILD_TESTS=OFF",
                        "-DPOUND_BUILD_BENCH=OFF", "-DPOUND_PYTHON=ON",
                        f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "pound_python_core"],
                       check=True)
        built = next((build / "python" / "pound").glob("_core*.so"))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


# setuptools' own build folder apart from CMake's build/ of README's commands.
setup(ext_modules=[Extension("pound._core", sources=[])], cmdclass={"build_ext": CMakeBuild},
      options={"build": {"build_base": "build-pip"}})
