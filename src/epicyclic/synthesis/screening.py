"""Screening: which placements of shift elements on a mechanism can reach the targets.

For one mechanism the candidate architectures are: an input and an output
shaft, ``b`` brakes on shafts other than input and output, and ``c`` clutches
between pairs of shafts.  Each gear engages k = DOF − 1 of those elements
(:mod:`~epicyclic.synthesis.kinematics`).  An architecture passes when its
C(b + c, k) element combinations can give every target ratio with *one* set of
stationary ratios inside the bounds.  Screening proves the opposite cheaply,
vectorised over all architectures of the mechanism:

1. Every combination's ratio range over the whole i0 box (corner values,
   exact for multilinear fractions) gives the set of targets it can reach
   (a bit mask).  An architecture is dropped when the union of its
   combinations' masks misses a target, or fewer combinations reach a target
   than there are gears.
2. The same test on each of the 2^S half-width sub-boxes: an architecture
   must pass in at least one sub-box (all its gears share one i0).
3. Sets must carry load: a shaft that holds a single set member and is neither
   input nor output must carry a shift element, or that set idles in every
   gear and the transmission needs one set fewer.

Exact pruning (``prune=True``): the first level examines only the element sets
holding a combination that reaches the rarest target (:func:`_pruned_level0`);
an architecture none of whose boxes admits one combination per target is dropped
(:func:`_matched`: the fit gives every gear its own combination), its survivors
keeping every box of the range test; and combinations that reach no target in any
sub-box are skipped in the bisection.  With ``symmetry`` one placement per orbit of
the mechanism's automorphisms is examined and the images are written back
(:mod:`~epicyclic.synthesis.symmetry`); with ``kernel`` the range, pass and matching
tests run compiled (:mod:`~epicyclic.synthesis.kernel`, numba, bit-equal).

Survivors go to :mod:`~epicyclic.synthesis.fitting`.  Nothing here fits a
ratio, so screening never drops an architecture that can reach the targets
(up to the tolerance widening of the ranges).

References
----------
Kahraman et al. 2004, J. Mech. Des. 126(6), section 3 (search that eliminates
kinematic configurations before the tooth counts); Moore, R. E. (1966),
*Interval Analysis* (bounds over boxes, bisection); Glover, F. (1967), Naval Res.
Logist. Q. 14(3), 313–316 (matching in convex bipartite graphs).
"""

from __future__ import annotations

import functools
import itertools
from dataclasses import dataclass

import numpy as np

from ..results.zero import clean_array
from . import kernel as compiled_kernel
from .kinematics import (
    combination_determinants,
    element_rows,
    element_shafts,
    hadamard_bound,
    hadamard_factors,
    ratio_ranges,
)
from .boxes import _children, _children_table, _grid, multilinear
from .mechanisms import PORTS, Mechanism
from .symmetry import PlacementSymmetry, automorphisms

__all__ = ["Layout", "Placement", "layout", "multilinear", "screen"]


@dataclass(frozen=True)
class Placement:
    """A mechanism with input, output and shift elements that passed screening.

    Attributes
    ----------
    input, output : int
        Shaft numbers.
    elements : tuple of int
        Element numbers (brakes first, see :func:`~epicyclic.synthesis.kinematics.element_shafts`).
    boxes : tuple of int
        Sub-boxes (bit k set: upper half of set k's range) in which the targets
        may be reached.
    """

    input: int
    output: int
    elements: tuple[int, ...]
    boxes: tuple[int, ...]


@dataclass(frozen=True, eq=False)
class Layout:
    """Every choice of shift elements on N shafts (independent of the mechanism).

    Attributes
    ----------
    shafts, brakes, clutches, engaged : int
    combos : ndarray (T, k)
        Every combination of k elements with at most b brakes and c clutches.
    element_sets : ndarray (A, b + c)
        Every choice of b brakes and c clutches (element numbers).
    set_combos : ndarray (A, C(b+c, k))
        Row numbers into ``combos`` of each element set's combinations.
    brake_shafts, touched : ndarray (A,) of int
        Bit masks of the shafts braked / touched by any element of each set.
    """

    shafts: int
    brakes: int
    clutches: int
    engaged: int
    combos: np.ndarray
    element_sets: np.ndarray
    set_combos: np.ndarray
    brake_shafts: np.ndarray
    touched: np.ndarray

    @functools.cached_property
    def blocks(self) -> list[tuple[int, int, int]]:
        """(braked-shaft bit mask, first, stop) of the runs of element sets with the same brakes."""
        edges = np.flatnonzero(np.diff(self.brake_shafts)) + 1
        starts = np.concatenate([[0], edges])
        stops = np.concatenate([edges, [len(self.brake_shafts)]])
        return [(int(self.brake_shafts[a]), int(a), int(b)) for a, b in zip(starts, stops)]

    @functools.cached_property
    def block_starts(self) -> np.ndarray:
        """First element set of each block of :attr:`blocks`."""
        return np.array([start for _, start, _ in self.blocks], dtype=np.int64)

    @functools.cached_property
    def containing(self) -> tuple[np.ndarray, np.ndarray]:
        """Inverse of ``set_combos`` (CSR): element sets ``indices[indptr[t]:indptr[t + 1]]`` hold combination t.

        Built in passes over ranges of combinations (at most 2^23 entries sorted at a time), so
        the ten-speed table (6 · 10^7 entries) needs no (A·C,) int64 sort order at once.
        """
        width = self.set_combos.shape[1]
        flat = self.set_combos.ravel()
        indptr = np.concatenate([[0], np.cumsum(np.bincount(flat, minlength=len(self.combos)))]).astype(np.int64)
        indices = np.empty(flat.size, dtype=np.int32)
        first = 0
        while first < len(self.combos):
            stop = max(int(np.searchsorted(indptr, indptr[first] + (1 << 23), side="right")) - 1, first + 1)
            where = np.flatnonzero((flat >= first) & (flat < stop))
            order = np.argsort(flat[where], kind="stable")
            indices[indptr[first]:indptr[stop]] = where[order] // width
            first = stop
        return indptr, indices

    @functools.cached_property
    def columns(self) -> np.ndarray:
        """``set_combos`` transposed and contiguous (C, A): fast per-combination gathers."""
        return np.ascontiguousarray(self.set_combos.T)


@functools.lru_cache(maxsize=16)
def layout(shafts: int, brakes: int, clutches: int, engaged: int) -> Layout:
    """All element sets of ``brakes`` brakes and ``clutches`` clutches on ``shafts`` shafts (cached).

    >>> lay = layout(4, 2, 2, 2)   # Simpson-sized: 4 shafts, 2 brakes, 2 clutches, 2 engaged
    >>> lay.element_sets.shape, lay.set_combos.shape
    ((90, 4), (90, 6))
    """
    shafts_of = element_shafts(shafts)
    n_elements = len(shafts_of)
    is_brake = np.array([len(s) == 1 for s in shafts_of])
    brake_ids = np.flatnonzero(is_brake)
    clutch_ids = np.flatnonzero(~is_brake)
    b_sets = np.array(list(itertools.combinations(brake_ids, brakes)), dtype=np.int32).reshape(-1, brakes)
    c_sets = np.array(list(itertools.combinations(clutch_ids, clutches)), dtype=np.int32).reshape(-1, clutches)
    element_sets = np.concatenate([np.repeat(b_sets, len(c_sets), axis=0), np.tile(c_sets, (len(b_sets), 1))], axis=1)
    all_combos = np.array(list(itertools.combinations(range(n_elements), engaged)), dtype=np.int32).reshape(-1, engaged)
    nb = is_brake[all_combos].sum(axis=1)
    combos = all_combos[(nb <= brakes) & (engaged - nb <= clutches)]
    weights = n_elements ** np.arange(engaged - 1, -1, -1, dtype=np.int64)
    codes = combos.astype(np.int64) @ weights  # combos are sorted rows in lexicographic order
    local = np.array(list(itertools.combinations(range(brakes + clutches), engaged)), dtype=np.int32)
    set_combos = np.empty((len(element_sets), len(local)), dtype=np.int32)
    for start in range(0, len(element_sets), 1 << 16):  # in chunks: the (A, C, k) codes of 2·10^6 sets were 1 GB
        picked = np.sort(element_sets[start:start + (1 << 16)][:, local], axis=2)  # (chunk, C, k)
        set_combos[start:start + (1 << 16)] = np.searchsorted(codes, picked.astype(np.int64) @ weights)
    bits = np.array([sum(1 << x for x in s) for s in shafts_of], dtype=np.int64)
    brake_bits = np.where(is_brake, bits, 0)
    return Layout(shafts, brakes, clutches, engaged, combos, element_sets, set_combos,
                  np.bitwise_or.reduce(brake_bits[element_sets], axis=1),
                  np.bitwise_or.reduce(bits[element_sets], axis=1))


def _masks(valid: np.ndarray, lo: np.ndarray, hi: np.ndarray, targets: np.ndarray, tolerance: float) -> np.ndarray:
    """Bit mask of the targets each range can reach, widened by the tolerance.

    Bit j stands for the j-th smallest target (the targets a range reaches are
    consecutive in sorted order, so two searches give the mask).
    """
    ordered = np.sort(targets)
    widen = 1.0 + tolerance
    with np.errstate(invalid="ignore"):
        lo_w = np.where(lo > 0, lo / widen, lo * widen)
        hi_w = np.where(hi > 0, hi * widen, hi / widen)
    first = np.searchsorted(ordered, np.where(valid, lo_w, np.inf), side="left")
    stop = np.searchsorted(ordered, np.where(valid, hi_w, -np.inf), side="right")
    stop = np.maximum(stop, first)
    one = np.int64(1)
    return (one << stop.astype(np.int64)) - (one << first.astype(np.int64))


def _passes(masks: np.ndarray, full: int, gears: int) -> np.ndarray:
    """Rows of ``masks`` (..., C) whose union covers ``full`` with at least ``gears`` useful combinations."""
    union = np.zeros(masks.shape[:-1], dtype=np.int64)
    useful = np.zeros(masks.shape[:-1], dtype=np.int16)
    for j in range(masks.shape[-1]):
        m = masks[..., j] & full
        union |= m
        useful += m != 0
    return (union == full) & (useful >= gears)


def _passes_rows(masks: np.ndarray, full: int, gears: int) -> np.ndarray:
    """:func:`_passes` for masks laid out (C, A): one contiguous row per combination."""
    union = np.zeros(masks.shape[1], dtype=masks.dtype)
    useful = np.zeros(masks.shape[1], dtype=np.int16)
    for row in masks:
        m = row & full
        union |= m
        useful += m != 0
    return (union == full) & (useful >= gears)


def _matched(masks: np.ndarray, gears: int) -> np.ndarray:
    """Rows of ``masks`` (N, C) whose combinations can take the targets one each (a matching of all targets).

    A schedule gives every gear its own combination (:func:`~epicyclic.synthesis.fitting.assign`
    picks distinct ones), so an architecture can reach the targets in a box only if the bipartite
    graph target – combination (edge: the combination's range over the box reaches the target)
    has a matching that covers every target.  Each mask is an interval of the sorted targets
    (:func:`_masks`), so the graph is convex and Glover's greedy rule is exact: targets in
    ascending order, each takes the free combination covering it whose interval ends first.

    References
    ----------
    Glover, F. (1967), "Maximum matching in a convex bipartite graph", Naval Res. Logist. Q. 14(3), 313–316.
    """
    masks = masks.astype(np.int64)
    empty = masks == 0
    lowest = masks & -masks
    with np.errstate(divide="ignore"):
        first = np.where(empty, gears, np.log2(np.where(empty, 1, lowest).astype(float)).astype(np.int64))
        last = np.where(empty, -1, np.log2(np.where(empty, 1, masks + lowest).astype(float)).astype(np.int64) - 1)
    used = empty.copy()
    ok = np.ones(len(masks), dtype=bool)
    rows = np.arange(len(masks))
    for j in range(gears):
        key = np.where(~used & (first <= j) & (last >= j), last, gears)
        pick = key.argmin(axis=1)
        has = key[rows, pick] < gears
        ok &= has
        used[rows, pick] |= has
    return ok


def _unique_positions(values: np.ndarray, size: int) -> tuple[np.ndarray, np.ndarray]:
    """``np.unique`` of integers in [0, size) by marking (no sort), and each number's position in it (−1: absent)."""
    mark = np.zeros(size, dtype=bool)
    mark[values.ravel()] = True
    unique = np.flatnonzero(mark)
    position = np.full(size, -1, dtype=np.int64)
    position[unique] = np.arange(unique.size)
    return unique, position


def _holding(lay: Layout, combos: np.ndarray) -> np.ndarray:
    """Element sets (sorted numbers) that hold at least one of these combinations (:attr:`Layout.containing`)."""
    indptr, indices = lay.containing
    starts = indptr[combos]
    lengths = indptr[combos + 1] - starts
    total = int(lengths.sum())
    mark = np.zeros(len(lay.element_sets), dtype=bool)
    if total:
        mark[indices[np.repeat(starts - np.cumsum(lengths) + lengths, lengths) + np.arange(total)]] = True
    return np.flatnonzero(mark)


def _pruned_level0(lay: Layout, pair: int, allowed: list[np.ndarray], directions: list, full: int,
                   gears: int, compiled: bool = False) -> tuple[np.ndarray, np.ndarray] | None:
    """First-level survivors of one input/output pair, found from the rarest target (exact).

    An element set passes only if some combination of it reaches each target, so it holds one of
    the combinations that reach target j, for every j.  Only the element sets holding a
    combination that reaches the target fewest element sets can reach (counted with
    :attr:`Layout.containing`) are examined; the rest cannot pass.  The survivors come in the
    order of the full scan: by block of brakes, then direction, then element set, each with whether
    it admits one combination per target (:func:`_matched`): rows (input, output, element set)
    of a (3, n) array, and the n matched flags; None when none survives.  ``allowed`` (per direction):
    the element sets that brake neither input nor output, touch every shaft that must carry an
    element (and represent their orbit under the mechanism's symmetries).
    """
    indptr, _ = lay.containing
    sizes = np.diff(indptr)
    found, flags, order = [], [], []
    for d, (a, b, rows, _reach) in enumerate(directions):
        masks = rows[pair] & full
        bits = (masks[None, :] >> np.arange(gears, dtype=masks.dtype)[:, None]) & 1  # (gears, T)
        if not bits.any(axis=1).all():
            continue  # some target out of reach of every combination
        rarest = int(np.argmin(bits.astype(np.int64) @ sizes))
        held = _holding(lay, np.flatnonzero(bits[rarest]))
        held = held[allowed[d][held]]
        if compiled:  # the same tests in one compiled loop, without the (held, C) gather
            keep, matched = compiled_kernel.passes_matched(masks, held, lay.set_combos, gears)
            matched = matched[keep]
        else:
            gathered = masks[lay.set_combos[held]]
            keep = _passes(gathered, full, gears)
            matched = _matched(gathered[keep], gears)
        ok = held[keep]
        found.append(np.stack([np.full(ok.size, a), np.full(ok.size, b), ok]))
        flags.append(matched)
        order.append(np.stack([np.searchsorted(lay.block_starts, ok, side="right"), np.full(ok.size, d), ok]))
    if not found:
        return None
    sort = np.lexsort(np.concatenate(order, axis=1)[::-1])
    return np.concatenate(found, axis=1)[:, sort], np.concatenate(flags)[sort]


def screen(mechanism: Mechanism, lay: Layout, low: np.ndarray, high: np.ndarray, forward: np.ndarray,
           reverse: np.ndarray, tolerance: float, levels: int = 2,
           input_members: tuple[str, ...] = PORTS, output_members: tuple[str, ...] = PORTS,
           interpolate: bool = True, prune: bool = True, kernel: bool | None = None,
           symmetry: bool = True) -> tuple[list[Placement], int]:
    """Every (input, output, element set) of the mechanism that survives screening.

    Parameters
    ----------
    mechanism : Mechanism
    lay : Layout
        From :func:`layout` with ``mechanism.shafts`` shafts.
    low, high : ndarray (S,)
        Box of stationary ratios (signed; low < high).
    forward, reverse : ndarray
        Target ratios (forward > 0, reverse < 0).
    tolerance : float
        Relative tolerance on each target.
    levels : int, default 2
        Bisection levels after the whole box (each halves every i0 range);
        at most 16 // S are used (2^16 boxes).
    input_members, output_members : tuple of str
        Members ("sun", "ring", "carrier") the input / output shaft must hold
        one of (a separate input shaft is always allowed).
    interpolate : bool, default True
        Determinants inside the box by multilinear interpolation of their values
        at its corners (:func:`multilinear`; exact, as they are multilinear in
        i0), instead of solving every grid point again (False: the reference).
    prune : bool, default True
        Examine at the first level only the element sets that hold a combination
        reaching the rarest target (:func:`_pruned_level0`; exact: every other set
        misses that target; False: the reference, every element set scanned).
    kernel : bool, optional
        The range and matching tests in compiled loops (:mod:`~epicyclic.synthesis.kernel`, bit-equal
        results); default: when numba is importable.  False: the numpy path (the reference).
    symmetry : bool, default True
        With ``prune``: examine one placement per orbit of the mechanism's automorphisms
        (:mod:`~epicyclic.synthesis.symmetry`) and write the images back (the same placements).

    Returns
    -------
    placements : list of Placement
        With the finest boxes in which the targets may be reached.
    examined : int
        Architectures (input, output, element set) examined.
    """
    mech = mechanism
    compiled = compiled_kernel.use_kernel(kernel)
    low, high = np.asarray(low, float), np.asarray(high, float)
    group = automorphisms(mech, low, high) if prune and symmetry else ()
    sym = PlacementSymmetry(group, lay.element_sets) if group else None
    sets = mech.sets
    levels = min(levels, 16 // sets)  # at most 2^16 boxes
    targets = np.concatenate([forward, reverse]).astype(float)
    gears = targets.size
    full = (1 << gears) - 1
    points, corners = _grid(low, high, 0)
    det = combination_determinants(mech, points, lay.combos, element_rows(mech.shafts), compiled)  # (2^S, T, N)
    whole_box = det
    single = [x for x in range(mech.member_shafts) if len(mech.shaft_members(x)) == 1]
    if mech.free_input:
        pairs = [(mech.member_shafts, y) for y in range(mech.member_shafts)]
    else:
        pairs = list(itertools.combinations(range(mech.member_shafts), 2))

    def role_ok(shaft: int, kinds: tuple[str, ...]) -> bool:
        return any(port in kinds for _, port in mech.shaft_members(shaft))

    pairs = [(x, y) for x, y in pairs
             if role_ok(y, output_members) and (mech.free_input or role_ok(x, input_members))
             or not mech.free_input and role_ok(x, output_members) and role_ok(y, input_members)]
    if not pairs:
        return [], 0
    level0: list[tuple[np.ndarray, np.ndarray]] = []  # (input, output, element set) rows, matched
    examined = 0
    if gears > 62:
        raise ValueError("screening handles at most 62 target ratios")
    xs, ys = np.array([p[0] for p in pairs]), np.array([p[1] for p in pairs])
    if compiled:  # the same ranges and masks without the (corners, combinations, pairs) temporaries
        valid, fwd_mask, rev_mask, zero = compiled_kernel.whole_box(det, xs, ys, targets, tolerance)
    else:
        valid, lo, hi = ratio_ranges(det[..., xs], det[..., ys])  # (T, pairs)
        fwd_mask = _masks(valid, lo, hi, targets, tolerance)
        rev_mask = _masks(valid, 1.0 / hi, 1.0 / lo, targets, tolerance)  # y -> x: 1/ratio
        zero = np.all(det[..., xs] == 0, axis=0) | np.all(det[..., ys] == 0, axis=0)  # (T, pairs)
    reach_fwd = np.bitwise_or.reduce(fwd_mask, axis=0)  # targets any combination can reach, per pair
    reach_rev = np.bitwise_or.reduce(rev_mask, axis=0)

    narrow = np.int32 if gears <= 31 else np.int64  # half the bytes to gather per architecture
    fwd_rows = np.ascontiguousarray(fwd_mask.T, dtype=narrow)  # (pairs, T)
    rev_rows = np.ascontiguousarray(rev_mask.T, dtype=narrow)
    # combinations that reach no target in any sub-box of an input/output: valid over the whole box
    # with no target in range (a sub-box's range lies inside it), or a determinant zero at every corner
    # (multilinear, so zero throughout: no sub-box is valid)
    dead_fwd = (valid & (fwd_mask & full == 0)) | zero
    dead_rev = (valid & (rev_mask & full == 0)) | zero
    dead = {}
    for p, (x, y) in enumerate(pairs):
        dead[(x, y)], dead[(y, x)] = dead_fwd[:, p], dead_rev[:, p]
    for p, (x, y) in enumerate(pairs):
        if reach_fwd[p] != full and (mech.free_input or reach_rev[p] != full):
            continue  # some target is out of reach of every combination, in both directions
        io = (1 << x) | (1 << y)
        need = sum(1 << s for s in single if s not in (x, y)) | ((1 << x) if mech.free_input else 0)
        blocks = [(start, stop, b) for b, (bits, start, stop) in enumerate(lay.blocks) if not bits & io]
        if not blocks:
            continue
        directions = [d for d in ([(x, y, fwd_rows, reach_fwd)] if mech.free_input else
                                  [(x, y, fwd_rows, reach_fwd), (y, x, rev_rows, reach_rev)])
                      if (mech.free_input or role_ok(d[0], input_members)) and role_ok(d[1], output_members)]
        if prune:
            allowed = ((lay.brake_shafts & io) == 0) & ((lay.touched & need) == need)
            examined += int(np.count_nonzero(allowed)) * len(directions)  # images included
            per = [allowed & sym.representatives(d[0], d[1]) if sym else allowed for d in directions]
            found = _pruned_level0(lay, p, per, directions, full, gears, compiled)
            if found is not None:
                level0.append(found)
            continue
        for start, stop, block in blocks:
            covered = (lay.touched[start:stop] & need) == need
            examined += int(covered.sum()) * len(directions)
            for a, b, rows, reach in directions:
                if reach[p] != full:
                    continue
                ok = _passes_rows(rows[p][lay.columns[:, start:stop]], full, gears) & covered
                j = start + np.flatnonzero(ok)
                level0.append((np.stack([np.full(j.size, a), np.full(j.size, b), j]), np.ones(j.size, dtype=bool)))
    # the reference's order after bisection: groups (input, output) by first appearance among the
    # first level's survivors (pruned or not), then the first level's order
    found = np.concatenate([f for f, _ in level0], axis=1) if level0 else np.zeros((3, 0), dtype=np.int64)
    matched = np.concatenate([m for _, m in level0]) if level0 else np.zeros(0, dtype=bool)
    reps = None
    if sym is not None:  # every image of a representative, in the full scan's order
        reps = {(int(a), int(b), int(j)) for a, b, j in found[:, matched].T}
        found, source = sym.orbits(found)
        matched = matched[source]
        pair_index = np.zeros((mech.shafts, mech.shafts), dtype=np.int64)
        for p, (x, y) in enumerate(pairs):
            pair_index[x, y] = pair_index[y, x] = p
        first_of = np.array([x for x, _ in pairs])[pair_index[found[0], found[1]]]
        order = np.lexsort((found[2], found[0] != first_of, np.searchsorted(lay.block_starts, found[2], side="right"),
                            pair_index[found[0], found[1]]))
        found, matched = found[:, order], matched[order]
    _, first = np.unique(found[0] * mech.shafts + found[1], return_index=True)
    group_rank = {(int(found[0, i]), int(found[1, i])): r for r, i in enumerate(np.sort(first))}
    at_rank = np.flatnonzero(matched)
    survivors = [(int(a), int(b), int(j)) for a, b, j in found[:, at_rank].T]
    first_rank = dict(zip(survivors, at_rank.tolist()))
    # bisection: every survivor keeps the boxes (at the current level) in which it may reach the targets
    boxes = {s: np.zeros(1, dtype=np.int64) for s in survivors if reps is None or s in reps}
    for level in range(1, levels + 1):
        if not boxes:
            break
        points, corners = _grid(low, high, level)
        groups: dict[tuple[int, int], list[tuple[int, np.ndarray]]] = {}
        children = _children_table(level - 1, sets)
        for (a, b, j), parents in boxes.items():
            groups.setdefault((a, b), []).append((j, children[parents].ravel()))
        if not interpolate:  # the reference: every grid point solved again, for every shaft
            used = np.unique(lay.set_combos[[s[2] for s in boxes]])
            at = np.unique(corners[np.unique(np.concatenate([c for m in groups.values() for _, c in m]))])
            det = combination_determinants(mech, points[at], lay.combos[used], element_rows(mech.shafts))
        nxt = {}
        for (a, b), members in groups.items():
            sets_j = np.array([j for j, _ in members])
            counts = np.array([c.size for _, c in members])
            flat = np.concatenate([c for _, c in members])
            needed, box_of = _unique_positions(flat, len(corners))  # sorted boxes, and each one's position
            owner = np.repeat(np.arange(len(members)), counts)
            if interpolate:  # exact (multilinear in i0): only this group's combinations, points and two shafts
                member_cols = lay.set_combos[sets_j]
                cols, col_of = _unique_positions(member_cols, len(lay.combos))
                live = cols[~dead[(a, b)][cols]] if prune else cols  # the others' masks are 0 in every box
                here, row_of = _unique_positions(corners[needed], len(points))
                raw = multilinear(whole_box[:, live[:, None], np.array([a, b])], here, level, sets)
                idx = row_of[corners[needed].T]  # (2^S, boxes) rows of raw
                if compiled:  # the same tests, each (box, combination) range computed on demand
                    live_of = np.full(len(cols), -1, dtype=np.int64)
                    live_of[col_of[live]] = np.arange(len(live))
                    willis, elements = hadamard_factors(mech, points[here], lay.combos[live])
                    ok, matched = compiled_kernel.group_tests(raw, willis, elements, idx, live_of, targets, tolerance,
                                                              box_of[flat], owner, col_of[member_cols], match=prune)
                else:
                    pair = clean_array(raw, hadamard_bound(mech, points[here], lay.combos[live])[:, :, None])
                    valid, lo, hi = ratio_ranges(pair[:, :, 0][idx], pair[:, :, 1][idx])  # (boxes, live)
                    mask = np.zeros((len(needed), len(cols)), dtype=np.int64)
                    mask[:, np.searchsorted(cols, live)] = _masks(valid, lo, hi, targets, tolerance)
            else:
                member_cols = np.searchsorted(used, lay.set_combos[sets_j])  # (M, C) columns of det
                cols = np.unique(member_cols)
                idx = np.searchsorted(at, corners[needed].T)  # (2^S, boxes) rows of det
                valid, lo, hi = ratio_ranges(det[:, cols, a][idx], det[:, cols, b][idx])  # (boxes, cols)
                mask = _masks(valid, lo, hi, targets, tolerance)
            if not (compiled and interpolate):
                gathered = mask[np.searchsorted(needed, flat)[:, None], np.searchsorted(cols, member_cols)[owner]]
                ok = _passes(gathered, full, gears)
                matched = ok.copy()
                if prune:  # an architecture none of whose boxes admits one combination per target is dropped
                    matched[ok] = _matched(gathered[ok], gears)
            alive = np.zeros(len(members), dtype=bool)
            alive[owner[matched]] = True
            offsets = np.concatenate([[0], np.cumsum(counts)]).tolist()
            for m in np.flatnonzero(alive).tolist():  # its boxes stay those of the range test: the fit starts where it did
                nxt[(a, b, int(sets_j[m]))] = members[m][1][ok[offsets[m]:offsets[m + 1]]]
        boxes = nxt
    if sym is not None:
        boxes = sym.expand(boxes, levels, sets)
    if levels:
        boxes = dict(sorted(boxes.items(), key=lambda item: (group_rank[item[0][:2]], first_rank[item[0]])))
    elif sym is not None:
        boxes = dict(sorted(boxes.items(), key=lambda item: first_rank[item[0]]))
    return [Placement(a, b, tuple(int(e) for e in lay.element_sets[j]), tuple(bx))
            for (a, b, j), bx in boxes.items()], examined
