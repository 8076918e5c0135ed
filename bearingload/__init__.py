"""bearingload: load distribution among the balls and rollers of a radial rolling bearing."""

__version__ = "0.1.0"
