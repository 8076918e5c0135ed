"""``python -m bearingload``: the same as the ``bearingload`` command."""

from bearingload.cli import run

run()
