"""The quality harnesses, commands of the tool: ``bearingload accuracy`` (the work-precision of
every method against references at 50 digits) and ``bearingload stability`` (extreme-case
families of the radial and the combined solver). Each module returns data;
``bearingload.reports`` renders it."""
