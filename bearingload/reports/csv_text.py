"""csv cells of whole columns at once: the text :func:`bearingload.reports.render.render` writes.

A long csv (``bearingload batch`` over 10^5 rows and more) spends most of its time turning
numbers into text when it is done one number at a time. Here a column of floats becomes its
text with a few dozen numpy operations over the whole column:

1. the ten significant digits ``m`` (an integer in [10^9, 10^10)) and the decimal exponent ``e``
   of ``|v| = m 10^(e-9)``, from ONE correctly rounded multiplication or division by an exact
   power of ten (10^0 ... 10^22), so that ``m`` is ``v`` rounded to ten digits unless ``v``
   lies within 10^-5 of a rounding tie (then that value is written by Python, as below);
2. the text Python's ``repr`` gives the float nearest ``m 10^(e-9)`` (what
   :func:`~bearingload.reports.render.machine_number` keeps): the digits of ``m`` without its
   trailing zeros (a decimal of at most 15 digits comes back from its nearest double as
   itself, and no shorter decimal does), in fixed notation for -4 <= e <= 15 and otherwise as
   ``d.ddde±XX``.

Each cell is a row of byte *slots* (:data:`FLOAT_WIDTH`): every character has a fixed slot and
an unused slot holds NUL, so that each slot (or run of slots: the digits, masked past the last
one shown, come from lookup tables four at a time, as do '0.000' and 'e-05') is one vectorised
operation over the column; a line is the row's bytes without the NULs. Zeros are written 0.0
(or -0.0) directly; values outside 10^-13 ... 10^32 and near-ties take the one-at-a-time path
(``render._machine_text``), so every cell is byte for byte the text ``render`` writes; a test
checks this on 600,000 values.
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import cache
from typing import Any, NamedTuple

import numpy as np

_POW10 = 10.0 ** np.arange(23)  # exact doubles
#: The four digit characters of 0 ... 9999 (a gather beats integer division per digit).
_FOUR = ((np.arange(10_000)[:, None] // np.array([1000, 100, 10, 1])) % 10 + ord("0")).astype(
    np.uint8
)
_FOUR_WORDS = _FOUR.view(np.uint32).ravel()
_ZERO, _DOT, _MINUS = (np.uint8(ord(c)) for c in "0.-")
_NUL = np.uint8(0)

#: Byte slots of one float cell: sign, '0.000' before small numbers, ten digits each followed
#: by a place for the point, six zeros of whole numbers past ten digits, '.0', 'e+XX'.
FLOAT_WIDTH = 1 + 5 + 20 + 6 + 2 + 4


def float_cells(values: Any) -> np.ndarray:
    """The csv text of every float in ``values`` as a byte matrix, one row per value, with NUL
    bytes between and after its characters: ``repr(float(f"{v:.10g}"))`` once the NULs are
    dropped. Only the slots some value uses are kept.

    Raises
    ------
    ValueError
        A value is NaN or infinite (csv carries finite numbers only).
    """
    out, used = _float_slots(np.asarray(values, dtype=float).ravel())
    return out[:, used]


def _float_slots(v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Every slot of the cells of the floats ``v`` (n x :data:`FLOAT_WIDTH`) and which slots
    some cell may use."""
    out = np.zeros((v.size, FLOAT_WIDTH), np.uint8)
    return out, write_floats(out, v)


def write_floats(out: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Write the cells of the floats ``v`` into ``out`` (n x :data:`FLOAT_WIDTH`, all NUL);
    return which slots some cell may use (the others are NUL in every row)."""
    if not np.all(np.isfinite(v)):
        raise ValueError("refusing to write a non-finite number")
    a = np.abs(v)
    with np.errstate(all="ignore"):
        e = np.floor(np.log10(np.where(a > 0, a, 1.0))).astype(np.int64)
        m, e, fast = _ten_digits(a, e)
    fast &= a > 0
    negative = np.signbit(v)
    out[:, 0] = np.where(negative, _MINUS, _NUL)
    used = _slots(out, np.where(fast, m, 1e9).astype(np.int64), e, fast)
    used[0] = negative.any()
    zero = np.flatnonzero(a == 0)  # '0.0' in the slots of the first digit, its point, the next
    out[zero, 6] = _ZERO
    out[zero, 7] = _DOT
    out[zero, 8] = _ZERO
    slow = np.flatnonzero(~fast & (a > 0))
    if slow.size:
        from bearingload.reports.render import _machine_text

        for i in slow.tolist():
            text = _machine_text(float(v[i])).encode("ascii")
            out[i, :] = 0
            out[i, : len(text)] = np.frombuffer(text, np.uint8)
            used[: len(text)] = True
    return used


def _ten_digits(a: np.ndarray, e: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``m`` (ten digits, a float holding an integer), the exponent ``e``, and where both are
    certain: the power of ten is exact and the scaled value is not within 1e-5 of a tie."""
    for _ in range(2):  # log10 may miss the exponent by one next to a power of ten
        k = 9 - e
        ok = np.abs(k) <= 22
        p = _POW10[np.minimum(np.abs(k), 22)]
        s = np.where(k >= 0, a * p, a / p)
        low, high = ok & (s < 1e9), ok & (s >= 1e10)
        if not (low.any() or high.any()):
            break
        e = e - low + high
    frac = s - np.floor(s)
    fast = ok & (s >= 1e9) & (s < 1e10) & (np.abs(frac - 0.5) > 1e-5)
    m = np.rint(s)
    carry = m >= 1e10  # 9999999999.7 -> 10^10: one more digit before the point
    return np.where(carry, 1e9, m), e + carry, fast


class _Tables(NamedTuple):
    kept: np.ndarray
    sig: np.ndarray
    prefix: np.ndarray
    suffix: np.ndarray
    lead: np.ndarray


@cache
def _tables() -> _Tables:
    """Lookup tables of the cell writer, made on first use (not at import; threads that ask at
    once may each make them, alike).

    * ``kept[10^4 k + v]``: the four characters of 0 <= v < 10^4 with all but the first ``k``
      made NUL (as one uint32 word), k = 0 ... 4;
    * ``sig[v]``: how many of those four characters reach the last nonzero digit (0 for 0);
    * ``prefix[k]``: '0.' and k - 1 zeros for k = 1 ... 4 (fixed notation below 1), NUL for 0,
      as the eight bytes of one uint64 word;
    * ``suffix[e + 64]``: 'e-05', 'e+16' ... of the decimal exponent e (|e| < 64), one uint32;
    * ``lead[v]``: the four characters of v with its leading zeros NUL (0: four NUL), and
      ``lead[10^4 + v]`` the same with 0 written '0', one uint32 each.
    """
    kept = np.stack([np.where(np.arange(4) < k, _FOUR, _NUL).view(np.uint32).ravel()
                     for k in range(5)])  # fmt: skip
    nonzero = _FOUR != _ZERO
    sig = np.where(nonzero.any(axis=1), 4 - np.argmax(nonzero[:, ::-1], axis=1), 0)
    prefix = np.array([b""] + [b"0." + b"0" * k for k in range(4)], "S8").view(np.uint64)
    suffix = np.array([b"e%+03d" % x for x in range(-64, 64)], "S4").view(np.uint32)
    lead = np.where(np.maximum.accumulate(_FOUR != _ZERO, axis=1), _FOUR, _NUL)
    lead_zero = lead.copy()
    lead_zero[0, 3] = _ZERO
    leads = np.concatenate([lead, lead_zero]).view(np.uint32).ravel()
    return _Tables(kept.ravel(), sig.astype(np.uint8), prefix, suffix, leads)


def _slots(out: np.ndarray, m: np.ndarray, e: np.ndarray, fast: np.ndarray) -> np.ndarray:
    """Fill the slots of the text of ``m 10^(e-9)`` in the rows where ``fast`` (a notation no
    row uses costs nothing); return the slots some row may use."""
    kept, sig, prefix, suffix, _ = _tables()  # lead: int_cells
    used = np.zeros(FLOAT_WIDTH, bool)
    used[6:26] = True  # the digits and their points
    high, rest = np.divmod(m, 10**8)  # m: ten digits, high < 100 (its first two characters: 0)
    middle, low = np.divmod(rest, 10**4)
    nsig = np.where(low > 0, 6 + sig[low], np.where(middle > 0, 2 + sig[middle], sig[high] - 2))
    fixed_int = fast & (e >= 0) & (e <= 15)  # 123.45, 1200.0, 1e15 -> 1000000000000000.0
    fixed_frac = fast & (e >= -4) & (e < 0)  # 0.00012
    sci = fast & ~(fixed_int | fixed_frac)  # 1.2e-05, 1.5e+16
    shown = np.where(fixed_int, np.maximum(nsig, np.minimum(e + 1, 10)), nsig)  # zeros too
    shown = np.where(fast, shown, 0) + 2  # characters kept of the twelve of the three groups
    groups = np.empty((m.size, 3), np.uint32)
    for g, part in enumerate((high, middle, low)):
        groups[:, g] = kept[np.clip(shown - 4 * g, 0, 4) * 10_000 + part]
    out[:, 6:26:2] = groups.view(np.uint8)[:, 2:]
    if fixed_int.any():
        r = np.flatnonzero(fixed_int & (e <= 9))
        out[r, 7 + 2 * e[r]] = _DOT
        out[:, 33] = np.where(fixed_int & (nsig <= e + 1), _ZERO, _NUL)  # the 0 of '.0'
        used[33] = True
        if np.any(fixed_int & (e >= 10)):  # whole numbers of 11 to 16 digits
            for j in range(6):
                out[:, 26 + j] = np.where(fixed_int & (e >= 10 + j), _ZERO, _NUL)
            out[:, 32] = np.where(fixed_int & (e >= 10), _DOT, _NUL)
            used[26:33] = True
    if fixed_frac.any():  # '0.' and up to three zeros
        used[1:6] = True
        out[:, 1:6] = prefix[np.where(fixed_frac, -e, 0)].view(np.uint8).reshape(-1, 8)[:, :5]
    if sci.any():
        used[34:38] = True
        out[:, 7] |= np.where(sci & (nsig > 1), _DOT, _NUL)
        words = np.where(sci, suffix[np.clip(e, -64, 63) + 64], 0)
        out[:, 34:38] = words.view(np.uint8).reshape(-1, 4)
    return used


def int_cells(values: Any) -> np.ndarray:
    """The decimal text of integers (|v| < 10^19) as a byte matrix: a sign slot and as many
    digit slots as the largest needs."""
    v = np.asarray(values, dtype=np.int64).ravel()
    a = np.abs(v).astype(np.uint64)
    width = len(str(int(a.max()))) if v.size else 1
    out = np.zeros((v.size, 1 + width), np.uint8)
    out[:, 0] = np.where(v < 0, _MINUS, _NUL)
    if width <= 8:  # two words of four characters from a table, leading zeros NUL
        lead = _tables().lead
        high, low = np.divmod(a.astype(np.int64), 10_000)
        words = np.empty((v.size, 2), np.uint32)
        words[:, 0] = lead[high]  # 0: nothing
        words[:, 1] = np.where(high > 0, _FOUR_WORDS[low], lead[low + 10_000])  # 0: '0'
        out[:, 1:] = words.view(np.uint8)[:, 8 - width :]
        return out
    started = np.zeros(v.size, bool)  # 10^8 and more: a digit at a time
    for j in range(width):
        power = np.uint64(10 ** (width - 1 - j))
        digit = ((a // power) % np.uint64(10)).astype(np.uint8)
        started |= (digit != 0) | (j == width - 1)
        out[:, 1 + j] = np.where(started, digit + _ZERO, _NUL)
    return out


def text_cells(texts: Sequence[str]) -> np.ndarray:
    """Cells already written as text (UTF-8) as a byte matrix, NUL padded; each distinct text
    is encoded once."""
    cache: dict[str, bytes] = {}
    encoded = [cache[t] if t in cache else cache.setdefault(t, t.encode()) for t in texts]
    width = max([1, *map(len, cache.values())])
    flat = np.array(encoded, dtype=f"S{width}")
    return flat.view(np.uint8).reshape(len(encoded), width)


#: Rows from which the columns of a block are written by several threads at once (numpy's
#: array operations release the GIL; below this the threads cost more than they save).
PARALLEL_ROWS = 20_000


def join_rows(columns: Sequence[tuple[str, Any]]) -> bytearray:
    """csv lines (UTF-8 bytes) from whole columns: each ``(kind, data)`` is ``("f", floats)``,
    ``("i", integers)`` or ``("t", byte matrix of text cells)``; a numeric column may come as
    ``(kind, (data, missing))`` with a mask of blank cells. The cells of every column, without
    the slots no row of it uses, are laid side by side in one byte block (cells joined by ','
    and each row ended by '\\n'), which becomes the lines once its NUL bytes are dropped.

    From :data:`PARALLEL_ROWS` rows on, the columns are made and laid into the block by up to
    four threads (one per processor); each column's text is the same either way."""
    n = _rows(*columns[0])
    pool = _threads(len(columns)) if n >= PARALLEL_ROWS else None
    run = pool.map if pool else map
    try:  # the threads end here, also when a column fails (a NaN)
        cells = list(run(_cells, *zip(*columns, strict=True)))
        widths = [sum(hi - lo for lo, hi in runs) + 1 for _, runs in cells]  # with its ','
        starts = np.cumsum([0, *widths]).tolist()
        buffer = bytearray(n * starts[-1])  # zeros; the block is a view of it (no copy out)
        block = np.frombuffer(buffer, np.uint8).reshape(n, starts[-1])
        list(run(_lay, [block] * len(cells), cells, starts[:-1]))
    finally:
        if pool:
            pool.shutdown(cancel_futures=True)
    block[:, -1] = ord("\n")
    return buffer.translate(None, b"\0")


def _lay(block: np.ndarray, cells: tuple[np.ndarray, list[tuple[int, int]]], at: int) -> None:
    """Copy a column's used slots into the block from byte ``at`` on, and the ',' after them."""
    matrix, runs = cells
    for lo, hi in runs:
        block[:, at : at + hi - lo] = matrix[:, lo:hi]
        at += hi - lo
    block[:, at] = ord(",")


def _rows(kind: str, data: Any) -> int:
    """The number of rows of one ``(kind, data)`` column of :func:`join_rows`."""
    return len(data[0] if isinstance(data, tuple) else data)


def _threads(columns: int) -> Any:
    """A pool of one thread per processor this process may use, at most four and one per
    column; None where that is one thread."""
    import os
    from concurrent.futures import ThreadPoolExecutor

    usable = os.sched_getaffinity(0) if hasattr(os, "sched_getaffinity") else None
    workers = min(4, columns, len(usable) if usable else os.cpu_count() or 1)
    return ThreadPoolExecutor(workers) if workers > 1 else None


def _cells(kind: str, data: Any) -> tuple[np.ndarray, list[tuple[int, int]]]:
    """The byte matrix of one column (blank where ``data`` comes with a missing mask) and the
    runs of its slots that some row uses (first, last + 1)."""
    missing = None
    if isinstance(data, tuple):
        data, missing = data
    if kind == "f":
        v = np.asarray(data, dtype=float).ravel()
        constant = v.size > 1 and _constant(v)  # one text for every row (exponent 1.5, y = 0)
        out, used = _float_slots(v[:1] if constant else v)
        out = np.broadcast_to(out, (v.size, FLOAT_WIDTH)) if constant else out
        edges = np.flatnonzero(np.diff(np.concatenate([[False], used, [False]])))
        runs = list(zip(edges[::2].tolist(), edges[1::2].tolist(), strict=True))
    else:
        out = int_cells(data) if kind == "i" else np.asarray(data, dtype=np.uint8)
        runs = [(0, out.shape[1])]
    if missing is not None:
        out = np.array(out)  # writable
        out[missing] = 0
    return out, runs


def _constant(v: np.ndarray) -> bool:
    """Whether every value is the first, sign included (0.0 and -0.0 are written apart)."""
    return bool(np.all(v == v[0])) and bool(np.all(np.signbit(v) == np.signbit(v[0])))
