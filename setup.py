"""Build the compiled simulation kernel (rbi.sim._dop853) when the package is built.

Everything else about the package is in pyproject.toml. The kernel is a Cython extension
compiled with OpenMP where the compiler supports it (GCC and Clang on Linux), so a batch of runs
shares the cores; without OpenMP it builds single-threaded.
"""

import os
import sys
import tempfile

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext


def _compiler_takes(compiler, flag: str) -> bool:
    with tempfile.TemporaryDirectory() as folder:
        source = os.path.join(folder, "probe.c")
        with open(source, "w") as handle:
            handle.write("#include <omp.h>\nint main(void) { return omp_get_max_threads() > 0 ? 0 : 1; }\n")
        try:
            objects = compiler.compile([source], output_dir=folder, extra_postargs=[flag])
            compiler.link_executable(objects, os.path.join(folder, "probe"), extra_postargs=[flag])
        except Exception:
            return False
    return True


class BuildWithOpenMP(build_ext):
    """Adds OpenMP flags when the C compiler accepts them."""

    def build_extensions(self):
        flag = "/openmp" if self.compiler.compiler_type == "msvc" else "-fopenmp"
        use_openmp = os.environ.get("RBI_NO_OPENMP") != "1" and _compiler_takes(self.compiler, flag)
        for extension in self.extensions:
            extension.extra_compile_args = ["-O3"] if self.compiler.compiler_type != "msvc" else ["/O2"]
            if use_openmp:
                extension.extra_compile_args.append(flag)
                if self.compiler.compiler_type != "msvc":
                    extension.extra_link_args = [flag]
        if not use_openmp:
            print("rbi: building the simulation kernel without OpenMP (batches run on one core)", file=sys.stderr)
        super().build_extensions()


setup(
    ext_modules=[Extension("rbi.sim._dop853", ["src/rbi/sim/_dop853.pyx"], include_dirs=["src/rbi/sim"])],
    cmdclass={"build_ext": BuildWithOpenMP},
)
