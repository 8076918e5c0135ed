"""The import structure of the package (docs/architecture.md): no circles, imports only downwards.

Every ``import`` and ``from ... import`` of every module under ``bearingload/`` is read from its
syntax tree, including the imports inside functions (which hide a circle from the interpreter
but not from a reader), and resolved to the module it names (``from bearingload.models import
equilibrium`` is the module ``bearingload.models.equilibrium``). The compiled modules (``.pyx``)
are modules of the graph too, their ``import`` and ``cimport`` lines read from their text.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "bearingload"

#: Rank of each top-level part of the package: a module imports only modules of its own rank or
#: lower ones. Reports and commands sit on top; the papers' checks and the quality harnesses use
#: the services and models below them, never the reports that render them.
LAYERS = {
    "bearingload": 0,  # the package's own __init__ (lazy public names, no static import)
    "errors": 0,
    "constants": 0,
    "lazy_dataclass": 0,  # dataclasses.dataclass, the comparison and text methods built on use
    "units": 1,
    "validate": 1,
    "numerics": 1,
    "_elliptic": 1,  # compiled: the AGM and one Hertz point contact, for numerics, contact, models
    "contact": 2,
    "bearings": 3,
    "models": 3,
    "studies": 4,
    "papers": 5,
    "quality": 5,
    "reports": 6,
    "plan": 7,  # one case: the engine, the refusals, the lives; its json document from reports/
    "batch": 8,  # a csv of cases: reads, solves through studies/, writes through reports/
    "tables_ci": 8,  # a folder of tables against its manifest: compares what cli/ regenerates
    "cli": 9,
    "__main__": 10,
}

#: Circles between two files still to be removed (none).
KNOWN_CIRCLES: set[frozenset[str]] = set()


def _modules(compiled: bool = False) -> dict[str, tuple[Path, bool]]:
    """Module name -> (file, is a package's __init__); the ``.pyx`` ones too if ``compiled``."""
    out = {}
    for path in [*PACKAGE.rglob("*.py"), *(PACKAGE.rglob("*.pyx") if compiled else [])]:
        parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
        is_package = parts[-1] == "__init__"
        if is_package:
            parts = parts[:-1]
        out[".".join(parts)] = (path, is_package)
    return out


def _resolve(name: str, modules: dict[str, tuple[Path, bool]]) -> str | None:
    while name and name not in modules:
        name = name.rpartition(".")[0]
    return name or None


#: ``from bearingload.x cimport/import ...`` and ``(c)import bearingload.x`` of a .pyx file.
_PYX_IMPORT = re.compile(r"^\s*(?:from|c?import)\s+(bearingload(?:\.\w+)*)", re.MULTILINE)


def import_graph() -> dict[str, set[str]]:
    """Module -> the package's modules it imports anywhere in its file."""
    modules = _modules(compiled=True)
    graph: dict[str, set[str]] = {}
    for name, (path, is_package) in modules.items():
        base = name.split(".") if is_package else name.split(".")[:-1]
        targets: set[str] = set()
        if path.suffix == ".pyx":  # Cython: not Python's syntax; its imports by their lines
            for w in _PYX_IMPORT.findall(path.read_text(encoding="utf-8")):
                target = _resolve(w, modules)
                if target is not None and target != name:
                    targets.add(target)
            graph[name] = targets
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                wanted = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                parent = base[: len(base) - node.level + 1] if node.level else []
                module = ".".join(parent + ([node.module] if node.module else []))
                wanted = [f"{module}.{a.name}" for a in node.names]
            else:
                continue
            for w in wanted:
                if w.split(".")[0] == "bearingload":
                    target = _resolve(w, modules)
                    if target is not None and target != name:
                        targets.add(target)
        graph[name] = targets
    return graph


def _part(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else parts[0]


def test_the_graph_sees_imports_inside_functions():
    """The walk reads function-level imports (the hiding place of the circles it guards)."""
    graph = import_graph()
    # compensating_clearances imports the root finder inside the function
    assert "bearingload.numerics" in graph["bearingload.studies.compensation"]
    # the command modules import their studies inside the command functions
    assert "bearingload.quality.stability" in graph["bearingload.cli.stability"]


def test_no_file_imports_a_file_that_imports_it():
    graph = import_graph()
    circles = {
        frozenset({a, b}) for a, targets in graph.items() for b in targets if a in graph.get(b, ())
    }
    assert circles <= KNOWN_CIRCLES, sorted(sorted(c) for c in circles - KNOWN_CIRCLES)


def test_no_longer_circle():
    """No circle through three or more files either (Tarjan's strongly connected components)."""
    graph = import_graph()
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    components: list[set[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = set()
            while True:
                w = stack.pop()
                component.add(w)
                if w == v:
                    break
            if len(component) > 1:
                components.append(component)

    for v in sorted(graph):
        if v not in index:
            visit(v)
    assert [c for c in components if frozenset(c) not in KNOWN_CIRCLES] == []


def test_every_part_has_a_layer():
    assert {_part(m) for m in import_graph()} <= set(LAYERS)


def test_the_graph_sees_the_compiled_modules():
    """The Hertz point contact in C (``_elliptic.pyx``) sits below contact/ and the models, which
    both use it (contact.hertz imports it, the core cimports it)."""
    graph = import_graph()
    assert "bearingload._elliptic" in graph["bearingload.contact.hertz"]
    assert "bearingload._elliptic" in graph["bearingload.models._core"]
    assert "bearingload._elliptic" in graph["bearingload.numerics"]
    assert graph["bearingload._elliptic"] == set()


@pytest.mark.parametrize("lower", ["studies", "papers", "quality", "models", "bearings"])
def test_below_reports_nothing_builds_a_report(lower):
    """Studies, the papers' checks and the harnesses return data; only reports/ and cli/ import
    the renderer."""
    graph = import_graph()
    offending = [
        (m, t)
        for m, targets in graph.items()
        if _part(m) == lower
        for t in targets
        if _part(t) in ("reports", "cli")
    ]
    assert offending == []


def test_imports_run_downwards():
    graph = import_graph()
    upwards = [
        (m, t)
        for m, targets in sorted(graph.items())
        for t in sorted(targets)
        if LAYERS[_part(t)] > LAYERS[_part(m)]
    ]
    assert upwards == []


def test_no_function_is_over_80_lines_of_code():
    """The standard 'no function over ~80 lines' had no test (the brief says there is one):
    every function of the package, its docstring aside, fits in 80 lines."""
    import ast
    from pathlib import Path

    import bearingload

    long = []
    for path in sorted(Path(bearingload.__file__).parent.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                body = node.body
                if ast.get_docstring(node) is not None:
                    body = body[1:]
                if body and body[-1].end_lineno - body[0].lineno + 1 > 80:  # type: ignore[operator]
                    long.append(f"{path.name}:{node.name}")
    assert long == []


def test_the_batch_command_is_at_most_900_lines():
    """The batch command (bearingload/batch/ and cli/batch.py) is held to 900 lines, docstrings
    and comments included, as ``wc -l`` counts them: it grows by merging rules into
    the plan, not by copies of them."""
    files = [*sorted((PACKAGE / "batch").glob("*.py")), PACKAGE / "cli" / "batch.py"]
    lines = sum(len(f.read_text(encoding="utf-8").splitlines()) for f in files)
    assert len(files) == 5 and lines <= 900


def _kernel_functions() -> list[tuple[str, str, list[str]]]:
    """(file, header, body lines without the docstring) of every top-level function of the
    compiled core's sources (.pyx and the .pxi files they include); the header joined over
    its lines."""
    out = []
    for path in sorted([*PACKAGE.rglob("*.pyx"), *PACKAGE.rglob("*.pxi")]):
        lines = path.read_text(encoding="utf-8").splitlines()
        starts = [i for i, line in enumerate(lines) if line.startswith(("cdef ", "cpdef ", "def "))]
        for i in starts:
            if "(" not in lines[i]:  # a cdef variable, struct or enum
                continue
            top = (k for k in range(i + 1, len(lines)) if lines[k][:1] not in ("", " ", "#"))
            end = next(top, len(lines))
            j = i
            while not lines[j].rstrip().endswith(":"):  # the header may run over lines
                j += 1
            body = [line for line in lines[j + 1 : end] if line.strip()]
            if body and body[0].strip().startswith('"""'):
                k = 0
                while not (body[k].rstrip().endswith('"""') and (k or body[k].count('"""') == 2)):
                    k += 1
                body = body[k + 1 :]
            out.append((path.name, " ".join(line.strip() for line in lines[i : j + 1]), body))
    return out


def test_kernel_sources_exist_and_their_functions_fit_in_80_lines():
    functions = _kernel_functions()
    assert len(functions) > 20  # (the parse finds the kernels)
    long = [f"{name}:{head}" for name, head, body in functions if len(body) > 80]
    assert long == []


def test_every_kernel_touches_no_python_object():
    """Every C-level function of the core is ``noexcept nogil`` (no Python object inside); the
    Python boundary is its ``def`` functions alone."""
    heads = [head for _, head, _ in _kernel_functions() if head.startswith("cdef ")]
    assert len(heads) > 20
    assert [head for head in heads if "noexcept nogil" not in head] == []


def test_a_plain_solve_compiles_no_pattern_it_does_not_use():
    """solve 306 -F 1kN compiled at import the patterns of pairs (7205BDB), seals, designation
    prefixes and suffixes, the ISO designations and stiffness units, none of which a plain GOST
    designation with a load in N uses: they are compiled at their first use. A fresh interpreter records every pattern re
    compiles while the command runs."""
    import subprocess
    import sys

    from bearingload.bearings import angular, catalog, designation
    from bearingload.units import _STIFFNESS_UNIT

    record = (
        "import re, sys\n"
        "seen = []\n"
        "compile = re._compile\n"
        "def recording(pattern, flags):\n"
        "    seen.append(pattern)\n"
        "    return compile(pattern, flags)\n"
        "re._compile = recording\n"
        "from bearingload.cli import run\n"
        "try:\n"
        "    run(['solve', '306', '-F', '1kN'])\n"
        "except SystemExit:\n"
        "    pass\n"
        "print(repr(seen), file=sys.stderr)\n"
    )
    done = subprocess.run([sys.executable, "-c", record], capture_output=True, text=True)
    seen = eval(done.stderr.strip().splitlines()[-1])  # a list of pattern texts
    unused = [
        angular._PAIR,
        angular._PAIR_LIKE,
        catalog._SEAL,
        designation._PREFIX,
        designation._SUFFIX_TOKENS,
        designation._ISO[1],
        designation._ROLLER[1],
        *(pattern for first, pattern, _ in designation._UNMODELLED if "3" not in first),
        _STIFFNESS_UNIT,
    ]
    assert [p for p in unused if getattr(p, "pattern", p) in seen] == []
    assert designation._GOST[1] in seen  # the recording sees the patterns the run uses


#: Modules that read an exception's text on purpose: the quality harnesses grade what a
#: refusal says (that it names the value; refusals of one kind counted together), they do not
#: decide or reword by it.
READS_MESSAGES = {"quality/stability.py", "quality/stability_combined.py"}


#: Methods that search, cut or rewrite a text.
_TEXT_METHODS = {
    "split",
    "rsplit",
    "replace",
    "partition",
    "rpartition",
    "startswith",
    "endswith",
    "removeprefix",
    "removesuffix",
    "find",
    "rfind",
    "index",
    "rindex",
    "count",
    "strip",
    "lstrip",
    "rstrip",
    "splitlines",
}


def _message_reads(tree: ast.AST) -> list[int]:
    """Lines where the text of a caught exception (``str(exc)``, ``repr(exc)``, ``f"{exc}"``,
    ``exc.args``, ``exc.message``, ``exc.problem``, ``exc.way_out``, or a name bound to one of
    them) is compared, searched, split, cut, replaced or matched by a regular expression:
    control flow or rewording by message text. Reading a field whole (to show it, or to build
    a new error of it) is not flagged."""
    caught = {h.name for h in ast.walk(tree) if isinstance(h, ast.ExceptHandler) and h.name}
    texts: set[str] = set()

    def is_text(node: ast.AST) -> bool:
        if isinstance(node, ast.Name):
            return node.id in texts
        if isinstance(node, ast.Call) and getattr(node.func, "id", None) in ("str", "repr"):
            return bool(node.args) and getattr(node.args[0], "id", None) in caught
        if isinstance(node, ast.JoinedStr):
            return any(
                isinstance(v, ast.FormattedValue) and getattr(v.value, "id", None) in caught
                for v in node.values
            )
        if isinstance(node, ast.Subscript):
            return is_text(node.value)
        return (
            isinstance(node, ast.Attribute)
            and node.attr in ("message", "problem", "way_out", "args")
            and getattr(node.value, "id", None) in caught
        )

    for node in ast.walk(tree):  # names bound to an exception's text
        if isinstance(node, ast.Assign) and is_text(node.value):
            texts.update(t.id for t in node.targets if isinstance(t, ast.Name))
    lines = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Compare):
            sides = [node.left, *node.comparators]
            if any(is_text(c) for c in sides) and not all(
                isinstance(o, (ast.Is, ast.IsNot)) for o in node.ops
            ):
                lines.append(node.lineno)
        elif isinstance(node, ast.Attribute) and node.attr in _TEXT_METHODS:
            if is_text(node.value):
                lines.append(node.lineno)
        elif isinstance(node, ast.Subscript) and is_text(node.value):
            lines.append(node.lineno)
        elif isinstance(node, ast.Call) and getattr(node.func, "value", None) is not None:
            regex = getattr(node.func.value, "id", None) == "re"
            if regex and any(is_text(a) for a in node.args):
                lines.append(node.lineno)
    return sorted(set(lines))


def test_no_module_decides_or_rewords_by_an_exception_text():
    """Errors carry fields (parameter, problem, way_out, reason): a caller acts on those, never
    on the text of the message."""
    import ast

    found = []
    for path in sorted(PACKAGE.rglob("*.py")):
        name = path.relative_to(PACKAGE).as_posix()
        if name in READS_MESSAGES:
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        found += [f"{name}:{line}" for line in _message_reads(tree)]
    assert found == []


def test_the_message_check_finds_a_splice():
    source = (
        "try:\n    f()\nexcept ValueError as exc:\n    if 'small' in str(exc):\n        pass\n"
        "    text = exc.message.replace('a', 'b')\n"
        "    t = str(exc)\n    if 'x' in t:\n        pass\n"
        "    re.search('y', repr(exc))\n    f'{exc}'.split(':')\n"
        "    exc.args[0].removeprefix('bearing: ')\n    if exc.way_out == WAY:\n        pass\n"
        "    if exc.way_out is None:\n        pass\n"
        "    raise InputError('a', exc.problem, way_out='w')\n"
    )
    assert _message_reads(ast.parse(source)) == [4, 6, 8, 10, 11, 12, 13]


def _is_private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def _is_module(name: str, modules: dict[str, tuple[Path, bool]]) -> bool:
    """A module of the package: a Python file, a package or a compiled one (``models._core``)."""
    if name in modules:
        return True
    *parent, last = name.split(".")
    folder = PACKAGE.parent.joinpath(*parent)
    return (folder / f"{last}.pyx").exists() or any(folder.glob(f"{last}.*.so"))


def private_reads(modules: dict[str, tuple[Path, bool]] | None = None) -> set[tuple[str, str]]:
    """(module, ``other_module._name``): every read of a private name of another module of the
    package, by ``from other import _name`` or by ``alias._name`` where ``alias`` is a module
    of the package (imported as such anywhere in the file, ``import a.b as m``, ``from a
    import b``, ``from a import b as m``). Private modules (``_core``, ``_ring``) are modules,
    not names read: importing them is not counted; dunder names are not private."""
    modules = _modules() if modules is None else modules
    found: set[tuple[str, str]] = set()
    for name, (path, is_package) in modules.items():
        base = name.split(".") if is_package else name.split(".")[:-1]
        tree = ast.parse(path.read_text(encoding="utf-8"))
        aliases: dict[str, str] = {}  # a local name -> the module of the package it binds
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                for a in node.names:
                    if a.asname and _is_module(a.name, modules):
                        aliases[a.asname] = a.name
                    elif _is_module(a.name, modules):
                        aliases[a.name.split(".")[0]] = a.name.split(".")[0]
            elif isinstance(node, ast.ImportFrom):
                parent = base[: len(base) - node.level + 1] if node.level else []
                module = ".".join(parent + ([node.module] if node.module else []))
                if module.split(".")[0] != "bearingload":
                    continue
                for a in node.names:
                    full = f"{module}.{a.name}"
                    if _is_module(full, modules):
                        aliases[a.asname or a.name] = full
                    elif _is_private(a.name) and module != name:
                        found.add((name, full))
        for node in ast.walk(tree):
            if not (isinstance(node, ast.Attribute) and _is_private(node.attr)):
                continue
            value, dotted = node.value, []
            while isinstance(value, ast.Attribute):
                dotted.insert(0, value.attr)
                value = value.value
            if isinstance(value, ast.Name) and value.id in aliases:
                owner = ".".join([aliases[value.id], *dotted])
                if owner != name and _is_module(owner, modules):
                    found.add((name, f"{owner}.{node.attr}"))
    return found


def _short(read: tuple[str, str]) -> tuple[str, str]:
    return read[0].removeprefix("bearingload."), read[1].removeprefix("bearingload.")


def test_no_module_reads_another_modules_private_names():
    """A name that starts with ``_`` belongs to its module: another module that needs it needs
    a public name (or the function it is used by)."""
    assert sorted(_short(r) for r in private_reads()) == []


def test_the_private_read_walk_sees_both_forms(tmp_path):
    """``from module import _name`` and ``module_alias._name``."""
    (tmp_path / "a.py").write_text("_hidden = 1\n", encoding="utf-8")
    (tmp_path / "b.py").write_text("from bearingload.x.a import _hidden\n", encoding="utf-8")
    (tmp_path / "c.py").write_text("from bearingload.x import a as m\n\nm._hidden\n", "utf-8")
    modules = {
        "bearingload.x.a": (tmp_path / "a.py", False),
        "bearingload.x.b": (tmp_path / "b.py", False),
        "bearingload.x.c": (tmp_path / "c.py", False),
    }
    assert private_reads(modules) == {
        ("bearingload.x.b", "bearingload.x.a._hidden"),
        ("bearingload.x.c", "bearingload.x.a._hidden"),
    }


#: What computes service lives: the plan calls it, the reports only render its answers.
LIFE_COMPUTERS = (
    "bearingload.bearings.service_life",
    "bearingload.bearings.modified_life",
    "bearingload.studies.life_basis",
)
#: Names of other modules that compute lives.
LIFE_FUNCTIONS = ("pair_lives", "pair_service_values", "service_values", "service_lives")


def life_computations(package: Path) -> list[str]:
    """``module: what`` of every import in ``package`` of a module or function that computes
    service lives (:data:`LIFE_COMPUTERS`, :data:`LIFE_FUNCTIONS`)."""
    found = []
    for path in sorted(package.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.module:
                names = [a.name for a in node.names]
                if node.module in LIFE_COMPUTERS:
                    found.append(f"{path.name}: {node.module}")
                found += [f"{path.name}: {n}" for n in names if n in LIFE_FUNCTIONS]
            elif isinstance(node, ast.Import):
                found += [f"{path.name}: {a.name}" for a in node.names if a.name in LIFE_COMPUTERS]
    return found


def test_reports_compute_no_lives():
    """Lives (one bearing's, each bearing's of a pair and the pair's) come from the plan; the
    reports render them."""
    assert life_computations(PACKAGE / "reports") == []


def test_the_life_walk_sees_an_import(tmp_path):
    (tmp_path / "r.py").write_text(
        "from bearingload.studies.bearing_pair import pair_lives\n"
        "import bearingload.bearings.service_life\n",
        encoding="utf-8",
    )
    assert life_computations(tmp_path) == [
        "r.py: pair_lives",
        "r.py: bearingload.bearings.service_life",
    ]
