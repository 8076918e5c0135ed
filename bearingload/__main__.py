"""``python -m bearingload``: the same as the ``bearingload`` command."""

from .cli import run

run()
