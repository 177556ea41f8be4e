"""Symmetries of a mechanism: placements that are one transmission under another labelling.

:mod:`~epicyclic.synthesis.mechanisms` keeps one mechanism per isomorphism class (sets of one kind
permuted, shafts renumbered by first appearance).  What remains is the symmetry *of* a mechanism,
its automorphism group: the kind-preserving permutations p of its sets that map its ties onto
themselves.  Each carries a permutation σ of the shafts (σ maps the member q of set p[j] to the
member q of set j), and with it of the shift elements (a brake on x to a brake on σx, a clutch
x–y to a clutch σx–σy) and of the whole architecture (input, output, element set).  If the
architecture P reaches the targets with stationary ratios i0, its image σP reaches them with
i0'_j = i0_{p[j]} (set j of σP is set p[j] of P, relabelled): the same transmission.  So where
the stationary-ratio box is the same for permuted sets (it is per kind), σP passes the screening
exactly when P does, in the boxes with set coordinates permuted the same way.

The screening (``screen(symmetry=True)``) examines one representative per orbit, the
lexicographically smallest (input, output, element set) under the group, and writes every image
back, so its output is the unreduced one.  Measured on the full 4-set space, 14 % of the mechanisms
have a non-trivial group (order 2 to 24), which leaves about 93 % of the architectures to examine.

What is *not* a symmetry here: reversing a lever (sun and ring swapped) maps i0 to 1/i0, outside
the box of any simple set with |i0| > 1, and swapping input and output inverts every ratio (the
screening already shares the determinants of both directions); renaming shafts is the numbering
by first appearance, already canonical.

References
----------
Tsai, L.-W. (2001), *Mechanism Design: Enumeration of Kinematic Structures According to Function*,
ch. 9 (isomorphism and automorphisms of the graphs of epicyclic trains); Harary, F. & Palmer, E. M.
(1973), *Graphical Enumeration*, ch. 2 (orbits of a permutation group, Burnside's lemma); Queitsch,
eq. 12 (Willis equation, one stationary ratio per set).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .kinematics import element_shafts
from .mechanisms import Mechanism, set_permutations

__all__ = ["Automorphism", "PlacementSymmetry", "automorphisms", "element_map", "element_set_images", "box_images",
           "box_order"]


@dataclass(frozen=True)
class Automorphism:
    """A non-trivial symmetry of a mechanism.

    Attributes
    ----------
    sets : tuple of int
        p: set j of the image is set ``sets[j]`` of the original.
    shafts : tuple of int
        σ: shaft x goes to shaft ``shafts[x]`` (the separate input shaft to itself).
    """

    sets: tuple[int, ...]
    shafts: tuple[int, ...]


def automorphisms(mechanism: Mechanism, low: np.ndarray | None = None,
                  high: np.ndarray | None = None) -> tuple[Automorphism, ...]:
    """The non-identity kind-preserving set permutations that map the mechanism onto itself.

    Parameters
    ----------
    mechanism : Mechanism
    low, high : ndarray (S,), optional
        The box of stationary ratios: only permutations that keep it (low and high equal for
        the permuted sets) are symmetries of the search.

    Returns
    -------
    tuple of Automorphism

    Examples
    --------
    >>> m = Mechanism(("simple", "simple"), (0, 1, 2, 0, 1, 3))   # common sun and ring
    >>> automorphisms(m)
    (Automorphism(sets=(1, 0), shafts=(0, 1, 3, 2)),)
    """
    members = mechanism.members
    found = []
    for p in set_permutations(mechanism.kinds):
        if p == tuple(range(mechanism.sets)):
            continue
        if low is not None and high is not None and any(
                low[p[j]] != low[j] or high[p[j]] != high[j] for j in range(mechanism.sets)):
            continue
        sigma: dict[int, int] = {}
        ok = True
        for j in range(mechanism.sets):
            for q in range(3):
                old, new = members[3 * p[j] + q], members[3 * j + q]
                if sigma.setdefault(old, new) != new:
                    ok = False
        if ok and len(set(sigma.values())) == len(sigma):
            shafts = tuple(sigma[x] for x in range(mechanism.member_shafts)) + \
                ((mechanism.member_shafts,) if mechanism.free_input else ())
            found.append(Automorphism(tuple(p), shafts))
    return tuple(found)


def element_map(shafts: tuple[int, ...]) -> np.ndarray:
    """Element number → its image under the shaft permutation (numbers of :func:`element_shafts`).

    Parameters
    ----------
    shafts : tuple of int
        σ (:attr:`Automorphism.shafts`).

    >>> element_map((1, 0, 2)).tolist()   # brakes 0, 1, 2; clutches 0-1, 0-2, 1-2
    [1, 0, 2, 3, 5, 4]
    """
    elements = element_shafts(len(shafts))
    number = {s: e for e, s in enumerate(elements)}
    return np.array([number[tuple(sorted(shafts[x] for x in s))] for s in elements], dtype=np.int64)


def element_set_images(element_sets: np.ndarray, shafts: tuple[int, ...]) -> np.ndarray:
    """Row number of each element set's image under σ, for rows sorted lexicographically (``Layout.element_sets``).

    Parameters
    ----------
    element_sets : ndarray of int (A, w)
        Sorted rows of sorted element numbers (brakes first).
    shafts : tuple of int
        σ.
    """
    images = np.sort(element_map(shafts)[element_sets], axis=1)
    weights = len(element_shafts(len(shafts))) ** np.arange(element_sets.shape[1] - 1, -1, -1, dtype=np.int64)
    codes = element_sets.astype(np.int64) @ weights
    found = np.searchsorted(codes, images @ weights)
    assert np.array_equal(codes[found], images @ weights), "element sets are not closed under the automorphism"
    return found


def box_images(boxes: np.ndarray, level: int, sets: tuple[int, ...]) -> np.ndarray:
    """Box numbers at ``level`` with their set coordinates permuted: digit j of the image is digit ``sets[j]``.

    Box number: digit k (base 2^level, least significant first) is the cell along set k.

    Parameters
    ----------
    boxes : ndarray of int
    level : int
    sets : tuple of int
        p (:attr:`Automorphism.sets`).

    >>> box_images(np.array([1, 2]), 1, (1, 0)).tolist()   # (set 0 upper) -> (set 1 upper)
    [2, 1]
    """
    cells = 2 ** level
    count = len(sets)
    digits = (np.asarray(boxes, dtype=np.int64)[:, None] // cells ** np.arange(count)) % cells
    return (digits[:, list(sets)] * cells ** np.arange(count)).sum(axis=1)


def box_order(boxes: np.ndarray, level: int, count: int) -> np.ndarray:
    """Boxes at ``level`` in the order the bisection visits them (halves of level 1 first, set 0 first).

    The bisection keeps each box's children in the order of ``itertools.product((0, 1), repeat=S)``
    after their parent's place, so its order is lexicographic in (bit of level 1 of every set, …,
    bit of the last level of every set).

    Parameters
    ----------
    boxes : ndarray of int
    level : int
    count : int
        Number of sets S.

    >>> box_order(np.array([0, 1, 2, 3]), 1, 2).tolist()   # children of box 0: (0, 0), (0, 1), (1, 0), (1, 1)
    [0, 2, 1, 3]
    """
    boxes = np.asarray(boxes, dtype=np.int64)
    cells = 2 ** level
    digits = (boxes[:, None] // cells ** np.arange(count)) % cells  # (n, S)
    key = np.zeros(boxes.size, dtype=np.int64)
    for step in range(level):  # most significant: level 1
        for k in range(count):
            key = (key << 1) | ((digits[:, k] >> (level - 1 - step)) & 1)
    return boxes[np.argsort(key, kind="stable")]


class PlacementSymmetry:
    """The automorphisms of one mechanism acting on its placements in one layout (for the screening).

    Parameters
    ----------
    group : tuple of Automorphism
        From :func:`automorphisms` (non-empty).
    element_sets : ndarray of int (A, w)
        ``Layout.element_sets``.
    """

    def __init__(self, group: tuple[Automorphism, ...], element_sets: np.ndarray):
        self.group = group
        self.images = [element_set_images(element_sets, g.shafts) for g in group]
        self.count = len(element_sets)

    def representatives(self, a: int, b: int) -> np.ndarray:
        """Element sets j for which (a, b, j) is the lexicographically smallest of its orbit (bool, (A,))."""
        keep = np.ones(self.count, dtype=bool)
        for g, image in zip(self.group, self.images):
            moved = (g.shafts[a], g.shafts[b])
            if moved < (a, b):
                return np.zeros(self.count, dtype=bool)
            if moved == (a, b):
                keep &= image >= np.arange(self.count)
        return keep

    def orbits(self, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Rows (input, output, element set) of shape (3, n) and all their images, each once: (3, m), and
        the row of ``rows`` each came from (m,)."""
        sigma = [np.asarray(g.shafts) for g in self.group]
        every = np.concatenate([rows] + [np.stack([s[rows[0]], s[rows[1]], image[rows[2]]])
                                         for s, image in zip(sigma, self.images)], axis=1)
        source = np.tile(np.arange(rows.shape[1]), len(sigma) + 1)
        code = (every[0] * len(sigma[0]) + every[1]) * self.count + every[2]
        _, first = np.unique(code, return_index=True)
        first = np.sort(first)
        return every[:, first], source[first]

    def expand(self, boxes: dict, level: int, sets: int) -> dict:
        """Surviving representatives (input, output, element set) → boxes, with every image added.

        An image's boxes are the representative's with set coordinates permuted
        (:func:`box_images`), in the bisection's order (:func:`box_order`).
        """
        out = dict(boxes)
        for (a, b, j), found in boxes.items():
            for g, image in zip(self.group, self.images):
                key = (g.shafts[a], g.shafts[b], int(image[j]))
                if key not in out:
                    out[key] = box_order(box_images(found, level, g.sets), level, sets)
        return out
