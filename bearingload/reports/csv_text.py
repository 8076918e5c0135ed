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
an unused slot holds NUL, so that each slot is one vectorised ``where`` over the column; a line
is the row's bytes without the NULs. Zeros are written 0.0 (or -0.0) directly; values outside
10^-13 ... 10^32 and near-ties take the one-at-a-time path (``render._machine_text``), so every
cell is byte for byte the text ``render`` writes; a test checks this on 600,000 values.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

_POW10 = 10.0 ** np.arange(23)  # exact doubles
#: The four digit characters of 0 ... 9999 (a gather beats integer division per digit).
_FOUR = ((np.arange(10_000)[:, None] // np.array([1000, 100, 10, 1])) % 10 + ord("0")).astype(
    np.uint8
)
_FOUR_WORDS = _FOUR.view(np.uint32).ravel()
_ZERO, _DOT, _MINUS, _PLUS, _E = (np.uint8(ord(c)) for c in "0.-+e")
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
    v = np.asarray(values, dtype=float).ravel()
    out = np.zeros((v.size, FLOAT_WIDTH), np.uint8)
    return out[:, write_floats(out, v)]


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


_COUNT = np.arange(10)


def _slots(out: np.ndarray, m: np.ndarray, e: np.ndarray, fast: np.ndarray) -> np.ndarray:
    """Fill the slots of the text of ``m 10^(e-9)`` in the rows where ``fast`` (a notation no
    row uses costs nothing); return the slots some row may use."""
    used = np.zeros(FLOAT_WIDTH, bool)
    used[6:26] = True  # the digits and their points
    d = _digits(m)
    nsig = 10 - np.argmax(d[:, ::-1] != _ZERO, axis=1)  # digits up to the last nonzero one
    fixed_int = fast & (e >= 0) & (e <= 15)  # 123.45, 1200.0, 1e15 -> 1000000000000000.0
    fixed_frac = fast & (e >= -4) & (e < 0)  # 0.00012
    sci = fast & ~(fixed_int | fixed_frac)  # 1.2e-05, 1.5e+16
    shown = np.where(fixed_int, np.maximum(nsig, np.minimum(e + 1, 10)), nsig)  # zeros too
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
    out[:, 6:26:2] = np.where(_COUNT < np.where(fast, shown, 0)[:, None], d, _NUL)
    if fixed_frac.any():  # '0.' and up to three zeros
        used[1:6] = True
        out[:, 1] = np.where(fixed_frac, _ZERO, _NUL)
        out[:, 2] = np.where(fixed_frac, _DOT, _NUL)
        for j in range(3):
            out[:, 3 + j] = np.where(fixed_frac & (-e - 1 > j), _ZERO, _NUL)
    if sci.any():
        used[34:38] = True
        out[:, 7] |= np.where(sci & (nsig > 1), _DOT, _NUL)
        ae = np.abs(e).astype(np.uint8)  # below 100 on this path (|e| <= 31)
        out[:, 34] = np.where(sci, _E, _NUL)
        out[:, 35] = np.where(sci, np.where(e < 0, _MINUS, _PLUS), _NUL)
        out[:, 36] = np.where(sci, ae // 10 + _ZERO, _NUL)
        out[:, 37] = np.where(sci, ae % 10 + _ZERO, _NUL)
    return used


def _digits(m: np.ndarray) -> np.ndarray:
    """The ten digit characters of each integer ``m`` < 10^10 (n x 10 bytes)."""
    high, rest = np.divmod(m, 10**8)
    middle, low = np.divmod(rest, 10**4)
    groups = np.empty((m.size, 3), np.uint32)  # three gathers of four characters each
    groups[:, 0] = _FOUR_WORDS[high]
    groups[:, 1] = _FOUR_WORDS[middle]
    groups[:, 2] = _FOUR_WORDS[low]
    return groups.view(np.uint8)[:, 2:]


def int_cells(values: Any) -> np.ndarray:
    """The decimal text of integers (|v| < 10^19) as a byte matrix: a sign slot and as many
    digit slots as the largest needs."""
    v = np.asarray(values, dtype=np.int64).ravel()
    a = np.abs(v).astype(np.uint64)
    width = len(str(int(a.max()))) if v.size else 1
    out = np.zeros((v.size, 1 + width), np.uint8)
    out[:, 0] = np.where(v < 0, _MINUS, _NUL)
    if width <= 10:  # ten digits at once, the leading zeros dropped
        d = _digits(a.astype(np.int64))[:, 10 - width :]
        nonzero = d != _ZERO
        first = np.where(nonzero.any(axis=1), np.argmax(nonzero, axis=1), width - 1)  # 0: '0'
        out[:, 1:] = np.where(np.arange(width) >= first[:, None], d, _NUL)
        return out
    started = np.zeros(v.size, bool)
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


def join_rows(columns: Sequence[tuple[str, Any]]) -> bytes:
    """csv lines (UTF-8 bytes) from whole columns: each ``(kind, data)`` is ``("f", floats)``,
    ``("i", integers)`` or ``("t", byte matrix of text cells)``; a numeric column may come as
    ``(kind, (data, missing))`` with a mask of blank cells. The cells of every column, without
    the slots no row of it uses, are laid side by side in one byte block (cells joined by ','
    and each row ended by '\\n'), which becomes the lines once its NUL bytes are dropped."""
    cells = [_cells(kind, data) for kind, data in columns]
    n = cells[0].shape[0]
    block = np.empty((n, sum(c.shape[1] for c in cells) + len(cells)), np.uint8)
    at = 0
    for c in cells:
        block[:, at : at + c.shape[1]] = c
        at += c.shape[1]
        block[:, at] = ord(",")
        at += 1
    block[:, -1] = ord("\n")
    return block.tobytes().translate(None, b"\0")


def _cells(kind: str, data: Any) -> np.ndarray:
    """The byte matrix of one column (blank where ``data`` comes with a missing mask)."""
    missing = None
    if isinstance(data, tuple):
        data, missing = data
    if kind == "f":
        v = np.asarray(data, dtype=float).ravel()
        if v.size > 1 and _constant(v):  # one text for every row (exponent 1.5, y = 0 ...)
            cell = float_cells(v[:1])
            out = np.broadcast_to(cell, (v.size, cell.shape[1]))
        else:
            out = float_cells(v)
    elif kind == "i":
        out = int_cells(data)
    else:
        out = np.asarray(data, dtype=np.uint8)
    if missing is not None:
        out = np.array(out)  # writable
        out[missing] = 0
    return out


def _constant(v: np.ndarray) -> bool:
    """Whether every value is the first, sign included (0.0 and -0.0 are written apart)."""
    return bool(np.all(v == v[0])) and bool(np.all(np.signbit(v) == np.signbit(v[0])))
