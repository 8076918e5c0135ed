"""``bearingload stability``: numerical stability of the solvers on stiff and extreme cases."""

from __future__ import annotations

import click

from bearingload.cli.options import CONTEXT, LibraryOption, emit, library_errors, output_options


@click.command(context_settings=CONTEXT)
@click.option(
    "--size",
    type=click.Choice(["quick", "full"]),
    default="quick",
    show_default=True,
    help="quick: the reduced grid of the test suite (seconds); full: the grid of 'make bench'.",
)
@click.option(
    "--family",
    "families",
    cls=LibraryOption,
    library=("family",),
    multiple=True,
    help="Run only this family (repeatable); default: every family.",
)
@output_options
@library_errors
def stability(size: str, families: tuple[str, ...], fmt: str, output: str | None) -> None:
    """Run the solvers over a grid of stiff and extreme cases and summarise each family.

    Radial solvers (one table): clearance through 0, clearance up to 1e12 elastic approaches,
    load ratios 1e-12 to 1e12, 1 to 1000 (and 1e5) balls, light to heavy preload, one loaded
    ball, cage angles at load-zone edges, rollers and m = 1, the continuum model near eps = 0, 1,
    inf, Hertz contact for curvature ratios 1 to 1e15, heavy preload against an independent
    formula, stiffness extremes, preload with m = 3, memory of large batches, cage angles near
    symmetry, batch independence, the load zone of many balls and bad inputs. Per family:
    cases, largest equilibrium residual (recomputed from the ball loads), largest jump between
    neighbouring cases, batch dependence, iterations, NaN/inf, warnings, refusals, failures and
    the family's own check against its limit.

    Combined-load solver (a second table; the ISO/TS 16281 ring equilibrium of 'solve' with
    --axial-load, --moment, --misalignment): preload to -30 µm, clearance up to the groove
    limit 2A, axial loads and moments of both signs, a misalignment of exactly 0 and nonzero,
    F_a/F_r from 1e-9 to 1e9, 3 to 1000 balls. Per family: cases, refusals and failures with
    their reasons, NaN/inf, the residual of each equilibrium component (F_r, F_y, F_a, M, M_c)
    recomputed from the ball loads and contact angles, batch dependence, iterations and the
    family's own check. csv holds one table: with csv, name families of one kind. json is one
    document: {"radial": {...}, "combined": {...}} (the kinds run), each a table's title,
    units and rows.

    \b
    Examples:
      bearingload stability
      bearingload stability --family heavy_preload_x --family preload
      bearingload stability --family combined_misalignment --family combined_preload
      bearingload stability --size full --family combined_ball_count --format json -o z.json
    """
    from bearingload.quality import stability as radial
    from bearingload.quality import stability_combined as combined
    from bearingload.reports.render import render
    from bearingload.reports.stability import stability_document, stability_table

    names = list(families)
    radial.check_selection(size, names, radial.family_names() + combined.family_names())
    kinds = [
        (module, [n for n in names if n in module.family_names()]) for module in (radial, combined)
    ]
    chosen = [(module, picked) for module, picked in kinds if picked or not names]
    if fmt == "csv" and len(chosen) > 1:
        raise click.UsageError(
            "Invalid value for '--format': csv holds one table; name with --family only radial "
            "or only combined_* families"
        )
    tables = {
        "combined" if module is combined else "radial": stability_table(
            module, module.run(size, picked or None)
        )
        for module, picked in chosen
    }
    document = stability_document(tables) if fmt == "json" else None
    emit(render(list(tables.values()), fmt, document=document), output)
