"""Build of the C module (module.c, with values.c, planview.c and lanes.c, sharing read.h); libxml2's headers come
from the lxml it is built against (bundled in lxml's wheels)."""

import lxml
from setuptools import Extension, setup

setup(
    ext_modules=[
        Extension(
            "xodrcheck_speedups",
            ["module.c", "values.c", "planview.c", "lanes.c"],
            depends=["read.h"],
            include_dirs=lxml.get_include(),
            extra_compile_args=[
                "-O2",
                "-fvisibility=hidden",
                "-Wall",
                "-Wextra",
                "-Wno-unused-parameter",
                "-Wno-missing-field-initializers",
            ],
        )
    ],
)
