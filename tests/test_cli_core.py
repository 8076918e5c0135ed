"""The command line of the core: solve, table, formats, errors, help, committed tables, start-up."""

from __future__ import annotations

import csv
import io
import json
import os
import subprocess
import sys
from pathlib import Path

import click
import pytest
from click.testing import CliRunner

from bearingload.cli import main, run
from bearingload.models.equilibrium import solve
from bearingload.units import KGF

from .cli_helpers import invoke
from .cli_helpers import run_process as run_cli

ROOT = Path(__file__).resolve().parents[1]


def test_solve_306_summary_lines():
    out = invoke(
        "solve",
        "-z",
        "8",
        "--load",
        "300kgf",
        "--stiffness",
        "4700kgf/mm^1.5",
        "--clearance",
        "20um",
    )
    assert out.exit_code == 0
    r = solve(8, 300 * KGF, 4700 * KGF, 0.02)
    text = out.output
    assert "z = 8, F_r = 2941.99 N (300 kgf)" in text
    assert "G_r = 20 µm (gap per side 10 µm)" in text
    assert f"{float(r.q_max) / KGF:.6g}" in text  # 167.310 kgf
    assert "heaviest ball load Q_max              167.310  kgf" in text
    assert "load zone half-angle                  85.1474  °" in text
    # the answer leads: Q_max is the first quantity of the summary
    assert text.splitlines()[4].startswith("heaviest ball load Q_max")
    lines = [ln for ln in text.splitlines() if ln.strip().startswith(("1 ", "2 ", "8 "))]
    assert len(lines) == 3


def test_solve_json_keys_and_values():
    out = invoke("solve", "-z", "9", "-F", "5kN", "-K", "3.8e5", "-G", "15um", "--format", "json")
    document = json.loads(out.output)
    assert document["units"]["q_max"] == "N" and document["units"]["x"] == "mm"
    doc = document["cases"][0]
    for key in (
        "k",
        "K_Q",
        "q_max",
        "x",
        "loaded_balls",
        "load_zone",
        "ball_loads",
        "stiffness_radial",
        "clearance",
    ):
        assert key in doc, key
    r = solve(9, 5000.0, 3.8e5, 0.015)
    assert doc["q_max"] == pytest.approx(float(r.q_max), rel=1e-9)
    assert doc["x"] == pytest.approx(float(r.x), rel=1e-9)
    assert doc["clearance"] == 0.015
    assert len(doc["ball_loads"]) == 9
    assert doc["ball_loads"][0] == pytest.approx(doc["q_max"], rel=1e-9)
    assert sum(q * __import__("math").cos(__import__("math").radians(a))
               for q, a in zip(doc["ball_loads"], doc["ball_angles"], strict=True)) == pytest.approx(5000.0, rel=1e-8)  # fmt: skip


def test_solve_half_pitch_and_preload():
    out = invoke(
        "solve", "-z", "12", "-F", "5kN", "-K", "3.8e5", "-G", "-50um", "--cage-angle", "half"
    )
    assert out.exit_code == 0
    assert "cage angle 15°" in out.output
    assert "balls carrying load 12" in {" ".join(x.split()) for x in out.output.splitlines()}


def test_csv_is_machine_readable_and_deterministic():
    a = invoke("table", "k", "--format", "csv").output
    b = invoke("table", "k", "--format", "csv").output
    assert a == b
    assert "\r" not in a
    rows = list(csv.DictReader(io.StringIO(a)))
    assert [int(r["balls"]) for r in rows] == list(range(1, 31))
    assert float(rows[7]["k"]) == pytest.approx(0.5432136169, abs=1e-10)  # 10 significant digits


@pytest.mark.parametrize("fmt", ["table", "csv", "markdown", "json"])
def test_every_format_of_table_kq(fmt):
    out = invoke("table", "kq", "--format", fmt, "--z-max", "12")
    assert out.exit_code == 0
    assert "2.1926" in out.output or "2.192604" in out.output


def test_table_under_conditions_changes_with_clearance():
    base = invoke("table", "k", "--format", "json", "--z-max", "10").output
    worn = invoke(
        "table", "k", "--format", "json", "--z-max", "10", "--clearance", "100um",
        "--load", "300kgf", "--stiffness", "4700kgf/mm^1.5",
    ).output  # fmt: skip
    k0 = {r["balls"]: r["k"] for r in json.loads(base)["rows"]}
    k1 = {r["balls"]: r["k"] for r in json.loads(worn)["rows"]}
    assert k1[8] == pytest.approx(float(solve(8, 300 * KGF, 4700 * KGF, 0.1).k), rel=1e-9)
    assert all(k1[z] >= k0[z] for z in k0)


def test_output_file_written_whole(tmp_path):
    target = tmp_path / "k.csv"
    out = invoke("table", "k", "--format", "csv", "-o", str(target))
    assert out.exit_code == 0 and out.output == ""
    assert target.read_text() == invoke("table", "k", "--format", "csv").output
    assert [p.name for p in tmp_path.iterdir()] == ["k.csv"]  # no temporary file left


def test_output_not_written_on_error(tmp_path):
    target = tmp_path / "bad.csv"
    r = run_cli("table", "k", "--load", "-1", "-o", str(target))
    assert r.returncode == 2
    assert not target.exists()


@pytest.mark.parametrize(
    "args, message",
    [
        (["solve", "-z", "0", "-F", "1", "-K", "1"], "Invalid value for '--balls'"),
        (["solve", "-z", "8", "-F", "-300", "-K", "1"], "Invalid value for '--load': must be greater than 0 N (got -300 N)"),
        (["solve", "-z", "8", "-F", "nan", "-K", "1"], "Invalid value for '--load'"),
        (["solve", "-z", "8", "-F", "3parsec", "-K", "1"], "unknown unit 'parsec'"),
        (["solve", "-z", "8", "-F", "1", "-K", "1", "-G", "5 furlong"], "Invalid value for '--clearance'"),
        (["solve", "-z", "8", "-F", "1", "-K", "0"], "Invalid value for '--stiffness'"),
        (["solve", "-z", "8", "-F", "1", "-K", "1", "--format", "xml"], "Invalid value for '--format'"),
        (["solve", "-z", "8", "-F", "1", "-K", "1", "--cage-angle", "north"], "Invalid value for '--cage-angle'"),
        (["solve", "-z", "2", "-F", "1", "-K", "1", "--cage-angle", "half"], "a ball must sit on the load line"),
        (["solve", "-z", "8", "-F", "1", "-K", "1", "-m", "0.2"], "Invalid value for '--exponent'"),
        (["solve", "-z", "8", "-K", "1"], "Missing option '--load'"),
        (["table", "xyz"], "Invalid value for '{k|kq|life}'"),
        (["table", "k", "--z-max", "0"], "Invalid value for '--z-max'"),
    ],
)  # fmt: skip
def test_bad_input_is_one_error_line_exit_2(args, message):
    r = run_cli(*args)
    assert r.returncode == 2, r.stderr
    assert r.stdout == ""
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1, r.stderr
    assert lines[0].startswith("Error: ")
    assert message in lines[0]
    assert "Traceback" not in r.stderr


def _commands(group: click.Group, prefix: tuple[str, ...] = ()):
    for name, cmd in group.commands.items():
        yield prefix + (name,), cmd
        if isinstance(cmd, click.Group):
            yield from _commands(cmd, prefix + (name,))


def test_every_command_has_help_with_examples():
    for path, cmd in _commands(main):
        out = invoke(*path, "--help")
        assert out.exit_code == 0
        assert "Usage:" in out.output
        assert "Example" in out.output, path
        assert cmd.help and len(cmd.help) > 40, path
        assert invoke(*path, "-h").output == out.output


def test_version():
    out = invoke("--version")
    assert out.output.startswith("bearingload, version ")


def test_run_success_and_failure(capsys):
    run(["table", "k", "--z-max", "3", "--format", "csv"])
    assert capsys.readouterr().out.startswith(
        "method,load [N],stiffness [N/mm^1.5],clearance [mm],cage_angle [°],exponent,balls,loaded_balls,k\nexact,1000.0,100000.0,0.0,0.0,1.5,1,1,1.0"
    )
    with pytest.raises(SystemExit) as info:
        run(["solve", "-z", "8", "-F", "0", "-K", "1"])
    assert info.value.code == 2
    err = capsys.readouterr().err
    assert err.startswith("Error: Invalid value for '--load'") and err.count("\n") == 1


def test_committed_tables_match_the_code():
    """tables/ is what its manifest's commands print (bearingload tables check: every listed
    file, cell by cell within 1e-9, and no file the manifest does not list)."""
    r = invoke("tables", "check", str(ROOT / "tables"))
    assert r.exit_code == 0, f"run `make tables` and commit the result:\n{r.output}"
    assert r.output.startswith("28 listed files of ")


def _python(code: str) -> subprocess.CompletedProcess:
    """``code`` run by a fresh interpreter (the test's environment), its output captured."""
    return subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=60, env=os.environ
    )


def test_terminal_calculation_imports_no_scipy():
    code = (
        "import sys\n"
        "from bearingload.cli import main\n"
        "main.main(args=['table', 'k'], standalone_mode=False)\n"
        "main.main(args=['solve', '-z', '8', '-F', '1', '-K', '1'], standalone_mode=False)\n"
        "print('scipy' in sys.modules, 'tabulate' in sys.modules)\n"
    )
    r = _python(code)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip().splitlines()[-1] == "False False"


def test_console_command_runs_no_garbage_collection_in_a_terminal_calculation():
    """Start-up: the cyclic collector found nothing to free in solve 306 and traversed every
    module, class and option built so far twenty times while click and the command line were
    imported and a dozen more while the command ran (several ms); a long batch still runs it
    (bearingload.__main__.GC_ALLOCATIONS). Counted from the console entry point on, imports
    included."""
    code = (
        "import gc, sys\n"
        "from bearingload.__main__ import main\n"
        "runs = []\n"
        "gc.callbacks.append(lambda phase, info: runs.append(phase))\n"
        "sys.argv = ['bearingload', 'solve', '306', '-F', '1kN', '--format', 'json']\n"
        "try:\n"
        "    main()\n"
        "except SystemExit:\n"
        "    pass\n"
        "print(runs.count('start'), 'bearingload.cli' in sys.modules, file=sys.stderr)\n"
    )
    r = _python(code)
    assert r.returncode == 0, r.stderr
    assert r.stderr.strip().splitlines()[-1] == "0 True"


def test_console_command_spares_the_collector_its_pass_at_exit():
    """Start-up: at exit the interpreter ran the collector over every object still alive, a
    pass the process's end makes needless (about a sixth of numpy's import time in solve
    306); the console command freezes them out of it. The check is an exit handler registered
    before the command's, so it runs after it; the command line run in-process (tests,
    scripts) leaves the collector as it was."""
    code = (
        "import atexit, gc, sys\n"
        "atexit.register(lambda: print('frozen', gc.get_freeze_count() > 0, gc.get_count()[0]))\n"
        "from bearingload.__main__ import main\n"
        "sys.argv = ['bearingload', 'solve', '306', '-F', '1kN', '--format', 'json']\n"
        "main()\n"
    )
    r = _python(code)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip().splitlines()[-1] == "frozen True 0"
    in_process = (
        "import atexit, gc\n"
        "threshold = gc.get_threshold()\n"
        "atexit.register(lambda: print('frozen', gc.get_freeze_count() > 0))\n"
        "from bearingload.cli import run\n"
        "run(['solve', '306', '-F', '1kN', '--format', 'json'])\n"
        "print('threshold kept', gc.get_threshold() == threshold)\n"
    )
    r = _python(in_process)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip().splitlines()[-2:] == ["threshold kept True", "frozen False"]


@pytest.mark.parametrize(
    "args, absent",
    [
        (["table", "k"], ["numpy.ma", "importlib.resources", "bearingload.bearings.catalog"]),
        (
            ["solve", "-z", "8", "-F", "300kgf", "-K", "4700kgf/mm^1.5", "-G", "20um"],
            ["numpy.ma", "importlib.resources", "bearingload.bearings.catalog"],
        ),
        (
            ["solve", "306", "-F", "300kgf"],
            ["numpy.ma", "importlib.resources", "bearingload.bearings.oil", "scipy"],
        ),
    ],
)
def test_terminal_calculation_skips_modules_it_does_not_need(args, absent):
    """Start-up: np.unique imports numpy.ma (7 ms), importlib.resources pulls in pathlib,
    tempfile and shutil (10 ms), the catalogue is not needed for a ring given by z and K, and
    the radial engine on a catalogue bearing needs no scipy (its solver and contacts are the
    compiled core's and the package's own)."""
    code = (
        "import sys\n"
        "from bearingload.cli import main\n"
        f"main.main(args={args!r}, standalone_mode=False)\n"
        f"print(sorted(m for m in {absent!r} if m in sys.modules))\n"
    )
    r = _python(code)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip().splitlines()[-1] == "[]"


def test_terminal_calculation_compiles_no_named_tuple_annotation():
    """Start-up: a NamedTuple in typing's class form, under a module's postponed annotations,
    compiles each field's annotation text when its module is imported (a ForwardRef each: the
    six result types of bearingload.contact.hertz took about 1 ms of solve 306). Every
    NamedTuple of the modules solve 306 imports has its field types as objects."""
    code = (
        "import sys, typing\n"
        "from bearingload.cli import main\n"
        "main.main(args=['solve', '306', '-F', '1kN'], standalone_mode=False)\n"
        "found, text = 0, []\n"
        "for name, module in list(sys.modules.items()):\n"
        "    if not name.startswith('bearingload'):\n"
        "        continue\n"
        "    for obj in list(vars(module).values()):\n"
        "        if isinstance(obj, type) and issubclass(obj, tuple) and hasattr(obj, '_fields'):\n"
        "            found += 1\n"
        "            hints = getattr(obj, '__annotations__', {})\n"
        "            text += [f'{obj.__qualname__}.{k}' for k, v in hints.items()\n"
        "                     if isinstance(v, (str, typing.ForwardRef))]\n"
        "print(found > 0, text)\n"
    )
    r = _python(code)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip().splitlines()[-1] == "True []"


@pytest.mark.parametrize("fmt", ["table", "markdown", "csv", "json"])
@pytest.mark.parametrize("method", ["stribeck", "continuum", "palmgren"])
def test_per_ball_without_the_exact_model_is_refused(fmt, method):
    """Only the exact model gives each ball's load: '--per-ball --method stribeck' ended table
    and markdown with an internal error (an empty list of balls indexed, exit 3) and wrote a
    csv of its header alone. It is refused naming --per-ball (the library's Solution.report
    too), as --plot is; with the exact model among the methods (all) the balls are printed."""
    from bearingload import analyse
    from bearingload.errors import InputError

    out = CliRunner().invoke(
        main, ["solve", "6205", "-F", "1kN", "--per-ball", "--method", method, "--format", fmt]
    )
    assert out.exit_code == 2, out.output
    assert (
        f"Error: Invalid value for '--per-ball': the ball loads are the exact model's; '--method' "
        f"{method} gives none (use '--method' exact or all)\n"
    ) in out.output
    with pytest.raises(InputError) as info:  # the library refuses it as the command line does
        analyse("6205", load="1kN", method=method).report(fmt, per_ball=True)
    assert info.value.parameter == "per_ball"
    ok = invoke("solve", "6205", "-F", "1kN", "--per-ball", "--method", "all", "--format", fmt)
    assert ok.exit_code == 0 and "internal error" not in ok.output


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs a /dev/full device (Linux)")
@pytest.mark.parametrize("fmt", ["table", "json"])
def test_output_to_a_full_device_is_one_error_line_not_an_internal_error(fmt):
    """Standard output on a full disk (/dev/full) was reported as an internal error, a bug to
    report; it is the disk, said in one line with exit status 1."""
    with open("/dev/full", "w") as full:
        done = subprocess.run(
            [sys.executable, "-m", "bearingload", "solve", "6205", "-F", "1kN", "--format", fmt],
            stdout=full,
            stderr=subprocess.PIPE,
            text=True,
            timeout=60,
        )
    assert done.returncode == 1
    assert done.stderr == "Error: cannot write the output: No space left on device\n"


@pytest.mark.skipif(os.name != "posix", reason="closes file descriptor 1 in the child (POSIX)")
def test_a_closed_standard_output_is_no_internal_error_and_output_to_a_file_is_written(tmp_path):
    """With standard output closed (``>&-``) Python has no sys.stdout; flushing it at the end
    of run() said 'internal error (AttributeError ...)' with exit 3, also for batch -o, whose
    output goes to its file and which needs no standard output."""
    cases = Path(__file__).resolve().parent.parent / "examples" / "cases.csv"
    out = tmp_path / "out.csv"
    args = ("batch", str(cases), "-o", str(out), "-q", "--format", "csv")
    done = subprocess.run(
        [sys.executable, "-m", "bearingload", *args],
        stderr=subprocess.PIPE,
        text=True,
        timeout=120,
        preexec_fn=lambda: os.close(1),  # noqa: PLW1509 (no threads in the child yet)
    )
    assert "internal error" not in done.stderr
    assert done.returncode == 0, done.stderr
    assert out.read_text(encoding="utf-8").startswith("row,bearing,")
