# pip install --no-build-isolation ./python   (from the repository root; no network needed)
# Needs Debian's python3-dev python3-pybind11 python3-numpy libcgal-dev libeigen3-dev libgmp-dev libmpfr-dev.
import os

from pybind11.setup_helpers import Pybind11Extension
from setuptools import setup

here = os.path.dirname(os.path.abspath(__file__))
ext = Pybind11Extension(
    "seamless_snapping._core",
    [os.path.join("src", "module.cpp")],
    include_dirs=[os.path.join(here, "..", "include"), "/usr/include/eigen3"],
    libraries=["mpfr", "gmp"],
    cxx_std=17,
    # CGAL's interval arithmetic needs -frounding-math; no FMA contraction (bit-identical results)
    extra_compile_args=["-frounding-math", "-ffp-contract=off", "-O2"],
)
setup(name="seamless_snapping", version="0.1.0", packages=["seamless_snapping"], ext_modules=[ext],
      install_requires=["numpy"], python_requires=">=3.9")
