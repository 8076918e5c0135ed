"""Build of bearingload's compiled core (bearingload/models/_core.pyx) and of the elliptic
integrals it shares with bearingload.numerics (bearingload/_elliptic.pyx); everything else is in
pyproject.toml.

The flags are stated once here: -O2 and -ffp-contract=off (the core's double-double arithmetic
needs every product rounded on its own: a fused multiply-add would change the error terms), no
fast-math. BEARINGLOAD_CHECKED=1 builds the core with Cython's bounds and None checks and, where
the compiler has them, AddressSanitizer and UndefinedBehaviorSanitizer (for the campaigns; see
docs/architecture.md).
"""

import os

from Cython.Build import cythonize
from setuptools import Extension, setup

CHECKED = os.environ.get("BEARINGLOAD_CHECKED") == "1"
FLAGS = ["-O2", "-ffp-contract=off", "-fno-fast-math"]
SANITIZE = ["-fsanitize=address,undefined", "-fno-omit-frame-pointer", "-g"] if CHECKED else []

extensions = [
    Extension(
        name,
        [name.replace(".", "/") + ".pyx"],
        extra_compile_args=FLAGS + SANITIZE,
        extra_link_args=SANITIZE,
    )
    for name in ("bearingload._elliptic", "bearingload.models._core")
]

setup(
    ext_modules=cythonize(
        extensions,
        language_level=3,
        compiler_directives={
            "boundscheck": CHECKED,
            "wraparound": False,
            "initializedcheck": CHECKED,
            "cdivision": True,
            "nonecheck": CHECKED,
        },
    )
)
