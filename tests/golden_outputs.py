"""Golden CLI outputs: the exact full output of every command in every format, stored as files.

``make golden`` (``python -m tests.golden_outputs``) runs every command below and writes its
output to ``tests/golden/<name>.txt``, rewrites the output under every ``$ bearingload ...``
line of the ```console blocks of the README and of every ``docs/*.md`` page, and writes the
command-line reference ``docs/cli.md`` (:mod:`tests.cli_reference`); ``tests/test_golden.py``
and ``tests/test_docs.py`` fail when a stored output, a page or the reference differs from what
the code prints now (as sqlite-utils checks its CLI docs).
"""

from __future__ import annotations

import re
import shlex
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
GOLDEN = ROOT / "tests" / "golden"
README = ROOT / "README.md"
DOCS = ROOT / "docs"
FORMATS = ("table", "csv", "markdown", "json")

HAND = "solve -z 8 -F 300kgf -K 4700kgf/mm^1.5 -G 20um"
#: name -> command line (without 'bearingload'); each in every format where it has --format.
COMMANDS = {
    "solve_hand": HAND,
    "solve_hand_per_ball": HAND + " --per-ball",
    "solve_half_preload": "solve -z 12 -F 5kN -K 3.8e5 -G -50um --cage-angle half",
    "solve_general_angle": "solve -z 9 -F 1kN -K 1e5 -G 10um --cage-angle 17",
    "solve_all_methods": HAND + " --method all",
    "solve_continuum": HAND + " --method continuum",
    "solve_stribeck": HAND + " --method stribeck",
    "solve_306_c3": "solve 306 -F 300kgf -G C3",
    "solve_306_c3_geometry": "solve 306 -F 300kgf -G C3 --show-geometry",
    "solve_306_range": "solve 306 -F 300kgf -G C3 --clearance-pick range",
    "solve_6306_range_all": "solve 6306 -F 3kN -G C3 --clearance-pick range --method all",
    "sweep_hand": "sweep -z 9 -F 1kN -K 1e5 -G 10um --steps 9",
    "sweep_306_c3": "sweep 306 -F 300kgf -G C3 --steps 5",
    "sweep_rollers_preload": "sweep -z 14 -F 10kN -K 8e5 -m 10/9 -G -5um --steps 3",
    "sweep_kurochkin": "sweep -z 7 --kurochkin-T 0.567 --steps 5",
    "solve_6205_combined": "solve 6205 -F 1.4kN -A 700N -G C3",
    "solve_7205bdb_pair": "solve 7205BDB --preload 500N -F 2kN -A 1kN",
    "solve_peer_axial_outer": "solve -z 7 --ball-diameter 11.5 --pitch-diameter 43.5 "
    "--modulus 210000 -F 0 -A 1kN -G 10um -C 23.4kN --rotating outer --per-ball",
    "sweep_6205_combined": "sweep 6205 -F 1.4kN -A 700N -G C3 --steps 5",
    "sweep_peer_misalignment": "sweep -z 7 --ball-diameter 11.5 --pitch-diameter 43.5 "
    "--modulus 210000 -F 1kN -G 10um -C 23.4kN --rotating outer --misalignment 2mrad --steps 3",
    "table_k": "table k --z-max 12",
    "table_kq_306": "table kq --bearing 306 -F 300kgf -G 20um --z-max 10",
    "table_k_all": "table k --method all --z-max 10",
    "table_life_6205_combined": "table life --bearing 6205 -F 1.4kN -A 700N",
    "table_life_peer": "table life -z 7 --ball-diameter 11.5 --pitch-diameter 43.5 --modulus "
    "210000 -C 23.4kN -F 1kN --clearances -5um,0,5um,10um,20um",
    "table_life_6205_speed": "table life -b 6205 -F 1kN --speed 10000 --clearances "
    "-10um,0,10um,40um",
    "table_life_7205bdb_speed": "table life -b 7205BDB -F 1kN -A 200N --preloads 0,300N "
    "--speed 10000",
    "catalog_bore_30": "catalog --bore 30",
    "catalog_show_306": "catalog show 306",
    "catalog_show_6208_skf": "catalog show 6208 --maker SKF",
    "solve_6205_overload": "solve 6205 -F 500kN",
    "solve_61806": "solve 61806 -F 500N --show-geometry",
    "solve_nu206": "solve NU206 -F 5kN --show-geometry",
    "fit_208": "fit examples/bearing208_kuzmenko2014.csv --load-unit kgf --base 200kgf:0.8mm "
    "--base 1000kgf:1.67mm --balls 9",
    "batch_cases": "batch examples/cases.csv",
    "batch_combined": "batch examples/combined_cases.csv",
    "errata_summary": "errata --summary",
    "errata_sabadash_differing": "errata --paper sabadash --only-differing",
}


def run(command: str) -> str:
    """The output of ``bearingload COMMAND`` (standard output, as a user sees it)."""
    from click.testing import CliRunner

    from bearingload.cli import main

    result = CliRunner().invoke(main, shlex.split(command), catch_exceptions=False)
    if result.exit_code != 0:
        raise RuntimeError(f"bearingload {command} failed ({result.exit_code}): {result.output}")
    return result.output


def expected() -> dict[str, str]:
    """file name -> content, for every command in every format."""
    out = {}
    for name, command in COMMANDS.items():
        for fmt in FORMATS:
            out[f"{name}.{fmt}.txt"] = run(f"{command} --format {fmt}")
    return out


def doc_pages() -> list[Path]:
    """The README and every Markdown page of ``docs/``: the files whose console examples are real."""
    return [README, *sorted(DOCS.glob("*.md"))]


def page_text(path: Path) -> str:
    """The page at ``path`` with every console example's output as the code prints it now."""
    text = path.read_text(encoding="utf-8")

    def block(match: re.Match[str]) -> str:
        parts = re.split(r"^\$ ", match.group(1), flags=re.M)
        rebuilt = parts[0]
        for part in parts[1:]:
            command = part.partition("\n")[0]
            output = run(shlex.join(shlex.split(command)[1:]))
            rebuilt += f"$ {command}\n" + "\n".join(x.rstrip() for x in output.splitlines()) + "\n"
        return f"```console\n{rebuilt}```"

    return re.sub(r"```console\n(.*?)```", block, text, flags=re.S)


def readme_text() -> str:
    """The README with every console example's output as the code prints it now."""
    return page_text(README)


def main() -> None:
    import os

    os.chdir(ROOT)  # example files are named relative to the repository
    GOLDEN.mkdir(exist_ok=True)
    files = expected()
    for old in GOLDEN.glob("*.txt"):
        if old.name not in files:
            old.unlink()
    for name, content in files.items():
        (GOLDEN / name).write_text(content, encoding="utf-8", newline="\n")
    for page in doc_pages():
        page.write_text(page_text(page), encoding="utf-8", newline="\n")
    from .cli_reference import CLI_DOC, write

    write()
    print(
        f"wrote {len(files)} golden outputs, the console examples of README.md and docs/, "
        f"and {CLI_DOC.relative_to(ROOT)}",
        file=sys.stderr,
    )


if __name__ == "__main__":
    main()
