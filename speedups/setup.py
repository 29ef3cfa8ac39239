"""Build of the one C module; its headers come from the lxml it is built against (libxml2's, bundled in lxml)."""

import lxml
from setuptools import Extension, setup

setup(
    ext_modules=[
        Extension(
            "xodrcheck_speedups",
            ["xodrcheck_speedups.c"],
            include_dirs=lxml.get_include(),
            extra_compile_args=["-O2", "-Wall", "-Wextra", "-Wno-unused-parameter", "-Wno-missing-field-initializers"],
        )
    ],
)
