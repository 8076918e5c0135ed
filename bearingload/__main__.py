"""The ``bearingload`` command: ``python -m bearingload`` and the console script both run
:func:`main`, the command line (:func:`bearingload.cli.run`) in a process of its own.

The process's cyclic garbage collector is set here, before the command line's modules are
imported, and not by :func:`~bearingload.cli.run` (which tests and scripts also call within a
process of their own).
"""

from __future__ import annotations

import gc

#: Container objects allocated (net) between two runs of the cyclic garbage collector, for the
#: command: a terminal calculation allocates fewer (its modules, classes and options, no cycles
#: to free) and runs none, where Python's default of 700 runs it twenty times while click and
#: the command line are imported and a dozen more while it runs; a long batch still runs it. [-]
GC_ALLOCATIONS = 100_000


def main() -> None:
    """Run the command line, the collector set for a process that ends with the command.

    Besides :data:`GC_ALLOCATIONS`: at exit the interpreter runs the collector over every object
    still alive (numpy's, click's and the package's modules and classes, several ms), which the
    process's end frees anyway; the command leaves no cycle that must be collected (its files
    are closed by with-blocks, the standard streams flushed by the interpreter), so they are
    frozen out of that pass.
    """
    import atexit

    gc.set_threshold(GC_ALLOCATIONS, *gc.get_threshold()[1:])
    atexit.register(gc.freeze)
    from bearingload.cli import run

    run()


if __name__ == "__main__":
    main()
