"""The whole-column csv writer (reports/csv_text.py) against the one-value-at-a-time text of the
renderer: byte for byte, on random numbers of every magnitude and on the awkward ones."""

from __future__ import annotations

import numpy as np
import pytest

from bearingload.reports.csv_text import float_cells, int_cells, join_rows, text_cells
from bearingload.reports.render import Column, Table, _machine_text, csv_block, render


def _texts(cells: np.ndarray) -> list[str]:
    return [bytes(row).replace(b"\0", b"").decode() for row in cells]


AWKWARD = [
    0.0, -0.0, 1.0, -1.0, 0.1, 1 / 3, 2 / 3, 1.5, 100.0, 1e-4, 1e-5, 9.99999999995e-5,
    1e9, 1e10, 9999999999.5, 9999999999.4, 12345678905.0, 123456789012.0, 1e15, 1e16,
    9.9999999995e15, 1e22, 1e-13, 1e-14, 1e31, 1e32, 1e300, -1e-300, 5e-324,
    2.2250738585072014e-308, 1.7976931348623157e308, 0.30000000000000004, 1.0000000005,
    1.00000000049999, 2.5e-5, 123.456, -987654.321,
]  # fmt: skip


def test_awkward_floats_match_the_renderer():
    assert _texts(float_cells(AWKWARD)) == [_machine_text(v) for v in AWKWARD]


@pytest.mark.parametrize("seed", range(3))
def test_random_floats_of_every_magnitude_match_the_renderer(seed):
    rng = np.random.default_rng(seed)
    n = 200_000
    v = rng.random(n) * 10.0 ** rng.integers(-20, 40, n)
    v[::3] *= -1
    v[::5] = np.round(v[::5])  # whole numbers
    v[::7] = np.round(v[::7] * 1e3) / 1e3  # few digits
    v[::11] = rng.integers(10**9, 10**12, v[::11].size) + 0.5  # ties at ten digits
    powers = 10.0 ** np.arange(-25, 40)
    v = np.concatenate([v, powers, powers * (1 - 2e-16), powers * (1 + 2e-16), -powers])
    assert _texts(float_cells(v)) == [_machine_text(x) for x in v.tolist()]


def test_non_finite_refused_with_its_column():
    with pytest.raises(ValueError, match="non-finite"):
        float_cells([1.0, np.nan])
    cols = [Column("a", "a"), Column("b", "b")]
    with pytest.raises(ValueError, match="column 'b'"):
        csv_block(cols, {"a": [1.0, 2.0], "b": np.array([1.0, np.inf])})


def test_integers_match_str():
    v = np.array([0, -1, 7, 10, 99, 100, -123456789, 9999999999, -9999999999, 2**62, -(2**62)])
    assert _texts(int_cells(v)) == [str(x) for x in v.tolist()]
    small = np.arange(-1000, 1000)
    assert _texts(int_cells(small)) == [str(x) for x in small.tolist()]
    rng = np.random.default_rng(5)
    for top in (10**4, 10**5, 10**8 - 1, 10**8, 10**10 - 1):  # each width's path
        v = np.concatenate([[0, top, -top], rng.integers(-top, top, 3000)])
        assert _texts(int_cells(v)) == [str(x) for x in v.tolist()], top


def test_join_rows_blanks_and_text():
    text = text_cells(["a", "é", ""])
    floats = ("f", (np.array([1.5, 0.0, 2.0]), np.array([False, True, False])))
    assert (
        join_rows([("t", text), floats, ("i", np.array([1, 2, 3]))])
        == "a,1.5,1\né,,2\n,2.0,3\n".encode()
    )


def test_render_csv_is_csv_block():
    """Small tables (render) and long streamed ones (csv_block) write the same bytes."""
    cols = [Column("v", "v", "N", 6), Column("n", "n"), Column("t", "t"), Column("o", "o")]
    values = {
        "v": AWKWARD,
        "n": list(range(len(AWKWARD))),
        "t": ["x,y", 'q"', "plain"] * 12 + ["µm"],
        "o": [None, True, 3, 2.5] * 9 + ["z"],
    }
    rows = [dict(zip(values, r, strict=True)) for r in zip(*values.values(), strict=True)]
    whole = render([Table("t", cols, rows)], "csv")
    assert whole == "v [N],n,t,o\n" + csv_block(cols, values)
    assert '"x,y"' in whole and '"q"""' in whole


def test_threaded_block_is_the_serial_block(monkeypatch):
    """A long block's columns are made by threads (the lookup tables made on first use by
    several at once): the bytes are those of one thread, and of the renderer."""
    from bearingload.reports import csv_text

    rng = np.random.default_rng(3)
    n = csv_text.PARALLEL_ROWS + 1
    v = rng.random(n) * 10.0 ** rng.integers(-8, 20, n)
    columns = [
        ("i", np.arange(n)),
        ("f", v),
        ("f", -v[::-1]),
        ("f", (np.round(v), v > 1e10)),
        ("f", np.full(n, 1.5)),
        ("t", text_cells(["exact", "x"] * (n // 2) + ["exact"])),
    ]
    csv_text._tables.cache_clear()
    threaded = join_rows(columns)
    monkeypatch.setattr(csv_text, "PARALLEL_ROWS", n + 1)
    assert join_rows(columns) == threaded
    lines = threaded.decode().splitlines()
    for i in (0, 1, n - 1):
        blank = "" if v[i] > 1e10 else _machine_text(float(np.round(v[i])))
        text = "exact" if i % 2 == 0 else "x"
        expected = [str(i), _machine_text(v[i]), _machine_text(-v[n - 1 - i]), blank, "1.5", text]
        assert lines[i] == ",".join(expected)
    assert sum(line.split(",")[3] == "" for line in lines) == int(np.sum(v > 1e10)) > 0


def test_a_failing_threaded_block_leaves_no_thread_behind(monkeypatch):
    """A NaN in a long block: the renderer's error names its column, and the writer threads
    have ended when it is raised (not when the pool happens to be collected)."""
    import os
    import threading

    from bearingload.reports import csv_text
    from bearingload.reports.render import csv_bytes

    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: {0, 1, 2, 3}, raising=False)

    n = csv_text.PARALLEL_ROWS
    values = {k: np.arange(n, dtype=float) for k in "abcd"}
    values["c"][n // 2] = np.nan
    before = threading.active_count()
    with pytest.raises(ValueError, match="non-finite number in column 'c'") as caught:
        csv_bytes([Column(k, k) for k in "abcd"], values)
    assert threading.active_count() == before
    del caught


def test_negative_zero_beside_a_blank_cell_keeps_its_sign():
    """A list column with a None beside -0.0 wrote 0.0 (the blank's filler was 'v or 0');
    the same column without the None writes -0.0, as the renderer does one value at a time."""
    cols = [Column("v", "v")]
    assert csv_block(cols, {"v": [-0.0, None, 1.5]}) == "-0.0\n\n1.5\n"
    assert csv_block(cols, {"v": [-0.0, 1.5]}) == f"{_machine_text(-0.0)}\n1.5\n"
