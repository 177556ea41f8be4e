"""Compiled inner loops of the screening (numba, optional): the same arithmetic, fused, without temporaries.

The screening's reference path is numpy (:mod:`~epicyclic.synthesis.screening`).  Profiled on the
six-element space (2 brakes + 4 clutches, 4 sets, 8HP targets; cProfile), its time goes to three
steps that numpy does in several passes over large temporary arrays:

* the ratio range of every combination over every box from the determinants at the box's 2^S
  corners, and the bit mask of the targets it reaches (``ratio_ranges`` + ``_masks``: the corner
  gathers alone are 2^S copies of the table);
* gathering, for every (element set, box), the masks of its C combinations and testing their
  union and count (``_passes``);
* the one-combination-per-target test by Glover's greedy rule (``_matched``);
* with four engaged elements, the first level's ranges of all 1.5 · 10⁵ combinations for every
  input/output pair over the whole box (``ratio_ranges(det[..., xs], det[..., ys])``: temporaries
  of corners × combinations × pairs).

Here each is one loop over the output, compiled with ``numba.njit(cache=True, nogil=True)`` (cached in
the user's cache folder, :func:`cache_directory`; no
GIL held: threads of one worker scale).  Every operation is the numpy path's, in the same order
on the same (finite) IEEE doubles (no ``fastmath``): the results are bit-equal (``tests/synthesis/test_kernel.py``
on random and published spaces).  numba is optional: without it (or with ``EPICYCLIC_NUMBA=0``)
:data:`AVAILABLE` is False and the screening runs its numpy path.

References
----------
Lam, S. K., Pitrou, A. & Seibert, S. (2015), "Numba: a LLVM-based Python JIT compiler", Proc. LLVM-HPC '15,
article 7; Moore, R. E. (1966), *Interval Analysis* (bounds over boxes); Glover, F. (1967), "Maximum
matching in a convex bipartite graph", Naval Res. Logist. Q. 14(3), 313–316.
"""

from __future__ import annotations

import os

import numpy as np

__all__ = ["AVAILABLE", "cache_directory", "four_cofactors", "group_tests", "passes_matched", "use_kernel", "whole_box"]

def cache_directory() -> str:
    """Where the compiled loops are cached: ``$EPICYCLIC_CACHE_DIR/numba``, else the user's cache folder.

    The user's cache folder is ``$XDG_CACHE_HOME`` (default ``~/.cache``) on Linux, ``~/Library/Caches``
    on macOS and ``%LOCALAPPDATA%`` on Windows, each with ``epicyclic/numba`` below it — never the
    installed package's folder, which may be read-only.  numba's own ``NUMBA_CACHE_DIR``, where set, wins.

    Returns
    -------
    str
    """
    import sys

    base = os.environ.get("EPICYCLIC_CACHE_DIR")
    if base:
        return os.path.join(base, "numba")
    if sys.platform == "win32":
        root = os.environ.get("LOCALAPPDATA") or os.path.join(os.path.expanduser("~"), "AppData", "Local")
    elif sys.platform == "darwin":
        root = os.path.join(os.path.expanduser("~"), "Library", "Caches")
    else:
        root = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(root, "epicyclic", "numba")


try:  # optional: pip install epicyclic[fast]
    if os.environ.get("EPICYCLIC_NUMBA", "1").strip() in ("0", "false", "no", "off"):
        raise ImportError("switched off by EPICYCLIC_NUMBA")
    import sys as _sys

    if "numba" not in _sys.modules:  # numba reads its cache folder once, when it is first imported
        os.environ.setdefault("NUMBA_CACHE_DIR", cache_directory())
    import numba
except ImportError:  # pragma: no cover - exercised where numba is absent
    numba = None

#: numba is importable and not switched off: the screening uses the compiled loops by default.
AVAILABLE = numba is not None


def use_kernel(kernel: bool | None) -> bool:
    """Whether the screening runs the compiled loops: ``kernel`` if given, else :data:`AVAILABLE`.

    Parameters
    ----------
    kernel : bool or None
        True asks for the compiled loops (refused with a clear error where numba is absent),
        False for the numpy path, None for the default.

    Raises
    ------
    ImportError
        ``kernel=True`` without numba.
    """
    if kernel is None:
        return AVAILABLE
    if kernel and not AVAILABLE:
        raise ImportError("the compiled screening kernel needs numba: pip install 'epicyclic[fast]' "
                          "(or pass kernel=None/False for the numpy path)")
    return bool(kernel)


def _jit(function):
    return numba.njit(cache=True, nogil=True)(function) if AVAILABLE else function


@_jit
def _box_mask(values, willis, elements, zero, idx, box, live, ordered, widen):  # pragma: no cover - compiled
    """Target mask of one combination (column ``live`` of ``values``) over one box."""
    corners = idx.shape[0]
    lo = np.inf
    hi = -np.inf
    bound_e = elements[live]
    sign_in = sign_out = 0.0
    for c in range(corners):
        r = idx[c, box]
        bound = zero * abs(willis[r] * bound_e)  # clean_array against Hadamard's bound
        x = values[r, live, 0]
        y = values[r, live, 1]
        if not (np.isfinite(x) and np.isfinite(y)) or abs(x) <= bound or abs(y) <= bound:
            return np.int64(0)  # no strict sign at a corner (zero within round-off, or not a number): not valid
        if c == 0:
            sign_in = 1.0 if x > 0 else -1.0
            sign_out = 1.0 if y > 0 else -1.0
        elif (x > 0) != (sign_in > 0) or (y > 0) != (sign_out > 0):
            return np.int64(0)  # a sign change inside the box
        ratio = x / y
        if ratio < lo:
            lo = ratio
        if ratio > hi:
            hi = ratio
    lo_w = lo / widen if lo > 0 else lo * widen
    hi_w = hi * widen if hi > 0 else hi / widen
    targets = ordered.size
    first = 0
    while first < targets and ordered[first] < lo_w:  # searchsorted, side="left"
        first += 1
    stop = 0
    while stop < targets and ordered[stop] <= hi_w:  # searchsorted, side="right"
        stop += 1
    if stop < first:
        stop = first
    return (np.int64(1) << np.int64(stop)) - (np.int64(1) << np.int64(first))


@_jit
def _group_tests(values, willis, elements, zero, idx, live_of, ordered, widen, rows, owner, table, full, gears,
                 match, order):  # pragma: no cover - compiled
    count = rows.size
    width = table.shape[1]
    memo = np.zeros(live_of.size, dtype=np.int64)  # masks in the current box, valid where stamp == box
    stamp = np.full(live_of.size, -1, dtype=np.int64)
    ok = np.zeros(count, dtype=np.bool_)
    matched = np.zeros(count, dtype=np.bool_)
    free = np.zeros(width, dtype=np.bool_)
    for f in order:  # by box: each (box, combination) range is computed once, when first needed
        row = rows[f]
        member = owner[f]
        union = 0
        useful = 0
        for c in range(width):
            k = table[member, c]
            if stamp[k] != row:
                live = live_of[k]
                memo[k] = np.int64(0) if live < 0 else _box_mask(values, willis, elements, zero, idx, row, live,
                                                                 ordered, widen)
                stamp[k] = row
            m = memo[k] & full
            union |= m
            useful += m != 0
        if union != full or useful < gears:
            continue
        ok[f] = True
        matched[f] = _glover(memo, table, member, full, gears, free) if match else True
    return ok, matched


def group_tests(values: np.ndarray, willis: np.ndarray, elements: np.ndarray, idx: np.ndarray, live_of: np.ndarray,
                targets: np.ndarray, tolerance: float, rows: np.ndarray, owner: np.ndarray, table: np.ndarray,
                match: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """The bisection's tests of one input/output group in one compiled loop, each box range computed on demand.

    For every architecture f (element set ``owner[f]`` in box ``rows[f]``), the masks of its C
    combinations ``table[owner[f]]`` over the box, then the range test and the matching test of
    :func:`passes_matched`.  A mask is the numpy path's: the determinants cleaned against
    Hadamard's bound ``willis · elements`` (``clean_array``), valid when both keep one strict sign
    at all the box's corners, spanning the smallest to the largest corner ratio (exact for
    multilinear fractions), widened by the tolerance (``ratio_ranges``, ``_masks``).  Only the
    (box, combination) pairs some architecture holds are computed, each once.

    Parameters
    ----------
    values : ndarray (points, live, 2)
        Determinants of the input (0) and output (1) shaft at the grid points, not yet cleaned.
    willis, elements : ndarray (points,), (live,)
        Factors of Hadamard's bound (:func:`~epicyclic.synthesis.kinematics.hadamard_factors`).
    idx : ndarray of int (2^S, boxes)
        Rows of ``values`` at each box's corners.
    live_of : ndarray of int (columns,)
        Column of ``values`` of each combination column, or −1 (a combination that reaches no
        target in any box: mask 0).
    targets : ndarray
        Target ratios (any order).
    tolerance : float
        Relative tolerance on each target.
    rows, owner : ndarray of int (F,)
        Box and element set of each architecture.
    table : ndarray of int (M, C)
        Combination columns of each element set.
    match : bool, default True
        Also run the matching.

    Returns
    -------
    ok, matched : ndarray of bool (F,)

    References
    ----------
    Moore, R. E. (1966), *Interval Analysis*, ch. 2 (bounds over boxes); Hadamard, J. (1893),
    Bull. Sci. Math. 17; Glover, F. (1967), Naval Res. Logist. Q. 14(3), 313–316.
    """
    from ..results.zero import ZERO_TOLERANCE

    gears = int(np.asarray(targets).size)
    return _group_tests(np.ascontiguousarray(values, dtype=np.float64), np.ascontiguousarray(willis, dtype=np.float64),
                        np.ascontiguousarray(elements, dtype=np.float64), float(ZERO_TOLERANCE),
                        np.ascontiguousarray(idx, dtype=np.int64), np.ascontiguousarray(live_of, dtype=np.int64),
                        np.sort(np.asarray(targets, dtype=np.float64)), 1.0 + float(tolerance),
                        np.ascontiguousarray(rows, dtype=np.int64), np.ascontiguousarray(owner, dtype=np.int64),
                        np.ascontiguousarray(table, dtype=np.int32), np.int64((1 << gears) - 1), gears, bool(match),
                        _by_box(np.asarray(rows), np.asarray(idx).shape[1]))


def _by_box(rows: np.ndarray, boxes: int) -> np.ndarray:
    """The stable order of ``rows`` (box numbers below ``boxes``): numpy's radix sort where they fit 16 bits."""
    narrow = rows.astype(np.int16) if boxes <= np.iinfo(np.int16).max else rows
    return np.argsort(narrow, kind="stable").astype(np.int64)


@_jit
def _glover(masks, table, member, full, gears, free):  # pragma: no cover - compiled
    width = table.shape[1]
    for c in range(width):
        free[c] = True
    for j in range(gears):
        pick = -1
        best = gears
        for c in range(width):
            m = masks[table[member, c]] & full
            if m == 0 or not free[c] or not (m >> j) & 1:
                continue
            last = 0  # highest set bit: the interval's end
            while m >> (last + 1):
                last += 1
            if last < best:
                best = last
                pick = c
        if pick < 0:
            return False
        free[pick] = False
    return True


@_jit
def _passes_matched(masks, held, table, full, gears, match):  # pragma: no cover - compiled
    count = held.size
    width = table.shape[1]
    ok = np.zeros(count, dtype=np.bool_)
    matched = np.zeros(count, dtype=np.bool_)
    free = np.zeros(width, dtype=np.bool_)
    for f in range(count):
        member = held[f]
        union = 0
        useful = 0
        for c in range(width):
            m = masks[table[member, c]] & full
            union |= m
            useful += m != 0
        if union != full or useful < gears:
            continue
        ok[f] = True
        matched[f] = _glover(masks, table, member, full, gears, free) if match else True
    return ok, matched


def passes_matched(masks: np.ndarray, held: np.ndarray, table: np.ndarray, gears: int,
                   match: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """Range test and one-combination-per-target test of many element sets in one loop (compiled).

    Element set ``held[f]`` gathers ``masks[table[held[f], c]]`` for its C combinations; it passes
    when their union holds every target and at least ``gears`` of them reach one (``_passes``), and
    is matched when the targets, in ascending order, can each take a distinct combination by
    Glover's greedy rule (``_matched``: the free combination covering the target whose interval
    ends first).

    Parameters
    ----------
    masks : ndarray of int (combinations,)
        Target bit masks over the box (intervals of the sorted targets).
    held : ndarray of int (F,)
        Element sets to test (rows of ``table``).
    table : ndarray of int32 (A, C)
        Combination numbers of each element set (``Layout.set_combos``, not copied).
    gears : int
        Number of targets.
    match : bool, default True
        Also run the matching (False: ``matched`` equals ``ok``).

    Returns
    -------
    ok, matched : ndarray of bool (F,)

    References
    ----------
    Glover, F. (1967), Naval Res. Logist. Q. 14(3), 313–316.
    """
    full = (1 << gears) - 1
    table = table if table.dtype == np.int32 and table.flags.c_contiguous else np.ascontiguousarray(table, np.int32)
    return _passes_matched(np.ascontiguousarray(masks, dtype=np.int64), np.ascontiguousarray(held, dtype=np.int64),
                           table, np.int64(full), gears, bool(match))


@_jit
def _interval_mask(lo, hi, ordered, widen):  # pragma: no cover - compiled
    """``_masks`` of one valid range [lo, hi]."""
    lo_w = lo / widen if lo > 0 else lo * widen
    hi_w = hi * widen if hi > 0 else hi / widen
    targets = ordered.size
    first = 0
    while first < targets and ordered[first] < lo_w:
        first += 1
    stop = 0
    while stop < targets and ordered[stop] <= hi_w:
        stop += 1
    if stop < first:
        stop = first
    return (np.int64(1) << np.int64(stop)) - (np.int64(1) << np.int64(first))


@_jit
def _whole_box(det, xs, ys, ordered, widen):  # pragma: no cover - compiled
    corners, count, _ = det.shape
    pairs = xs.size
    forward = np.zeros((count, pairs), dtype=np.int64)
    backward = np.zeros((count, pairs), dtype=np.int64)
    valid = np.zeros((count, pairs), dtype=np.bool_)
    zero = np.zeros((count, pairs), dtype=np.bool_)
    for t in range(count):
        for p in range(pairs):
            x, y = xs[p], ys[p]
            zero_in = zero_out = True
            pos_in = neg_in = pos_out = neg_out = 0
            for c in range(corners):
                a = det[c, t, x]
                b = det[c, t, y]
                zero_in &= a == 0
                zero_out &= b == 0
                pos_in += a > 0
                neg_in += a < 0
                pos_out += b > 0
                neg_out += b < 0
            zero[t, p] = zero_in or zero_out
            if not ((pos_in == corners or neg_in == corners) and (pos_out == corners or neg_out == corners)):
                continue
            valid[t, p] = True
            lo = np.inf
            hi = -np.inf
            for c in range(corners):
                ratio = det[c, t, x] / det[c, t, y]
                if ratio < lo:
                    lo = ratio
                if ratio > hi:
                    hi = ratio
            forward[t, p] = _interval_mask(lo, hi, ordered, widen)
            backward[t, p] = _interval_mask(1.0 / hi, 1.0 / lo, ordered, widen)
    return valid, forward, backward, zero


def whole_box(det: np.ndarray, xs: np.ndarray, ys: np.ndarray, targets: np.ndarray,
              tolerance: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The first screening level's ranges of every combination and input/output pair over the whole box (compiled).

    The numpy path's ``ratio_ranges(det[..., xs], det[..., ys])``, the masks of the ratio x → y
    and of its inverse y → x (``_masks`` of [lo, hi] and of [1/hi, 1/lo]), and whether a
    determinant is zero at every corner, without the (corners, combinations, pairs) temporaries.

    Parameters
    ----------
    det : ndarray (2^S, combinations, shafts)
        Cleaned determinants at the box's corners (:func:`~epicyclic.synthesis.kinematics.combination_determinants`).
    xs, ys : ndarray of int (pairs,)
        Shafts of each pair.
    targets : ndarray
        Target ratios (any order).
    tolerance : float
        Relative tolerance on each target.

    Returns
    -------
    valid, forward, backward, zero : ndarray (combinations, pairs)
        Bool, int64 masks x → y and y → x, bool.

    References
    ----------
    Moore, R. E. (1966), *Interval Analysis*, ch. 2 (bounds over boxes).
    """
    return _whole_box(np.ascontiguousarray(det, dtype=np.float64), np.ascontiguousarray(xs, dtype=np.int64),
                      np.ascontiguousarray(ys, dtype=np.int64), np.sort(np.asarray(targets, dtype=np.float64)),
                      1.0 + float(tolerance))


@_jit
def _four_cofactors(funcs, combos, top_of, sign_of):  # pragma: no cover - compiled
    points, _, d = funcs.shape
    count = combos.shape[0]
    out = np.empty((points, count, d))
    upper = np.empty(10)
    lower = np.empty(10)
    for p in range(points):
        for t in range(count):
            a, b, c, e = combos[t, 0], combos[t, 1], combos[t, 2], combos[t, 3]
            n = 0
            for i in range(d):  # 2x2 minors of rows (a, b) and (c, e), pairs (i, j) in lexicographic order
                for j in range(i + 1, d):
                    upper[n] = funcs[p, a, i] * funcs[p, b, j] - funcs[p, a, j] * funcs[p, b, i]
                    lower[n] = funcs[p, c, i] * funcs[p, e, j] - funcs[p, c, j] * funcs[p, e, i]
                    n += 1
            for i in range(d):
                det = 0.0
                for s in range(6):
                    term = upper[top_of[i, s, 0]] * lower[top_of[i, s, 1]]
                    if sign_of[s] > 0:
                        det += term
                    else:
                        det += -term
                out[p, t, i] = det if i % 2 == 0 else -det
    return out


def four_cofactors(funcs: np.ndarray, combos: np.ndarray) -> np.ndarray:
    """Signed maximal minors of every 4 × 5 matrix ``funcs[p, combos[t]]`` by Laplace expansion (compiled).

    The numpy path's :func:`~epicyclic.synthesis.kinematics._cofactors` for four engaged elements
    (the common case of 9 shafts), term by term in the same order: the 2 × 2 minors of the first
    two rows and of the last two, ``a_i b_j − a_j b_i``, then for every deleted column the six
    products of complementary minors summed with the expansion's signs from 0.  Bit-equal, without
    the (points, elements, elements, 10) table of minors and its gathers.

    Parameters
    ----------
    funcs : ndarray (P, elements, 5)
        Element rows in the null-space basis at each point.
    combos : ndarray of int (T, 4)
        Element numbers of each combination.

    Returns
    -------
    ndarray (P, T, 5)
        ``c_i = (−1)^(i+4) det(F without column i)``.

    References
    ----------
    Laplace expansion by complementary minors: Horn, R. A. & Johnson, C. R. (2013), *Matrix
    Analysis*, 2nd ed., section 0.8.9.
    """
    import itertools

    pairs = list(itertools.combinations(range(5), 2))
    top_of = np.zeros((5, 6, 2), dtype=np.int64)
    sign_of = np.zeros(6, dtype=np.int64)
    for i in range(5):
        cols = [j for j in range(5) if j != i]
        for s, (p, q) in enumerate(itertools.combinations(range(4), 2)):
            r, t = (x for x in range(4) if x not in (p, q))
            top_of[i, s] = pairs.index((cols[p], cols[q])), pairs.index((cols[r], cols[t]))
            sign_of[s] = 1 if (p + q) % 2 else -1
    return _four_cofactors(np.ascontiguousarray(funcs, dtype=np.float64), np.ascontiguousarray(combos, dtype=np.int64),
                           top_of, sign_of)
