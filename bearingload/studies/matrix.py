"""The 5x5 tangent stiffness matrix of a combined-load case as csv and batch write it: the names
of its rows and columns and of its 25 entries (json keeps the matrix whole, ``stiffness_matrix``).
One rule beside the solve that gives the matrix (:mod:`bearingload.studies.combined_bearing`),
kept light: the reports' quantities import it at start-up."""

from __future__ import annotations

from typing import Any

#: The 5x5 tangent stiffness matrix of a combined-load case (json ``stiffness_matrix``, a list of
#: rows): its rows, the forces and moments (name, unit), and its columns, the displacements and
#: tilts (name, unit); entry i, j is d(row i)/d(column j).
MATRIX_ROWS = (("F_x", "N"), ("F_y", "N"), ("F_a", "N"), ("M", "N mm"), ("M_c", "N mm"))
MATRIX_COLUMNS = (("x", "mm"), ("y", "mm"), ("axial", "mm"), ("tilt", "rad"), ("tilt_cross", "rad"))


def matrix_key(i: int, j: int) -> str:
    """The csv column of entry (i, j) of ``stiffness_matrix`` (0-based, as json indexes it):
    ``stiffness_matrix_23`` is json's ``stiffness_matrix[1][2]``, dF_y/d(axial)."""
    return f"stiffness_matrix_{i + 1}{j + 1}"


MATRIX_KEYS = tuple(
    matrix_key(i, j) for i in range(len(MATRIX_ROWS)) for j in range(len(MATRIX_COLUMNS))
)


def matrix_columns(r: Any) -> dict[str, Any]:
    """The entries of the cases' ``stiffness_matrix`` under :data:`MATRIX_KEYS`, each an array
    over the cases (csv's and batch's columns; json keeps the matrix whole)."""
    import numpy as np

    m = np.asarray(r.stiffness_matrix, dtype=float).reshape(-1, 5, 5)
    return {matrix_key(i, j): m[:, i, j] for i in range(5) for j in range(5)}


def radial_matrix(k: Any) -> list[list[float | None]]:
    """The radial engine's 2x2 ``d(F_x, F_y)/d(x, y)`` [N/mm] in the place it has in the 5x5
    ``stiffness_matrix`` (json's one layout for every engine), the entries of the axial
    displacement and the tilts ``None``: the radial engine holds the ring axially and untilted,
    so it does not determine them (a load option, ``axial_load`` 0, solves them)."""
    import numpy as np

    block = np.asarray(k, dtype=float).reshape(2, 2)
    size = len(MATRIX_ROWS)
    return [
        [float(block[i, j]) if i < 2 and j < 2 else None for j in range(size)] for i in range(size)
    ]


def radial_matrix_columns(k: Any) -> dict[str, Any]:
    """The entries of :func:`radial_matrix` under :data:`MATRIX_KEYS` (csv's and batch's
    columns, as :func:`matrix_columns` gives a combined case's): the radial engine's 2x2 block
    ``k`` (shape (..., 2, 2)) an array over the cases each, the undetermined entries ``None``."""
    import numpy as np

    m = np.asarray(k, dtype=float).reshape(-1, 2, 2)
    size = len(MATRIX_ROWS)
    return {
        matrix_key(i, j): m[:, i, j] if i < 2 and j < 2 else None
        for i in range(size)
        for j in range(size)
    }
