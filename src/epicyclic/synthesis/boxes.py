"""The grid of sub-boxes of the stationary-ratio box, and values inside it by multilinear interpolation.

The screening bisects the box of stationary ratios: at level L every set's range is cut into 2^L
cells, so there are 2^(L·S) boxes and (2^L + 1)^S grid points.  Box number: digit k (base 2^L,
least significant first) is the cell along set k; grid point number: digit k (base 2^L + 1) is the
position along set k, set 0 most significant.  The combination determinants are multilinear in the
stationary ratios, so their corner values fix them on the whole grid (:func:`multilinear`).

References
----------
Moore, R. E. (1966), *Interval Analysis* (bounds over boxes, bisection); Queitsch, eq. 12
(Willis equation, one stationary ratio per row, linearly).
"""

from __future__ import annotations

import functools
import itertools

import numpy as np

__all__ = ["corner_bits", "corner_weights", "multilinear"]


def _grid(low: np.ndarray, high: np.ndarray, level: int) -> tuple[np.ndarray, np.ndarray]:
    """Grid of (2^level + 1)^S points over the box and the corner indices of each of its 2^(level·S) boxes.

    Box number: digit k (base 2^level, least significant first) is the cell along set k.
    """
    return _cached_grid(tuple(float(v) for v in low), tuple(float(v) for v in high), level)


@functools.lru_cache(maxsize=32)
def _cached_grid(low_t: tuple[float, ...], high_t: tuple[float, ...], level: int) -> tuple[np.ndarray, np.ndarray]:
    low, high = np.array(low_t), np.array(high_t)
    sets = low.size
    cells = 2 ** level
    axis = np.linspace(0.0, 1.0, cells + 1)
    codes = np.array(list(itertools.product(range(cells + 1), repeat=sets)))  # last set fastest
    points = low + (high - low) * axis[codes]
    stride = (cells + 1) ** np.arange(sets - 1, -1, -1)
    box_cells = np.array(list(itertools.product(range(cells), repeat=sets)))[:, ::-1]  # set 0 fastest
    offsets = np.array(list(itertools.product((0, 1), repeat=sets)))
    corners = ((box_cells[:, None, :] + offsets[None, :, :]) * stride).sum(axis=2)
    return points, corners


def multilinear(corner_values: np.ndarray, points: np.ndarray, level: int, sets: int) -> np.ndarray:
    """Values at grid points (numbers of :func:`_grid` at ``level``) of functions multilinear in i0.

    A function multilinear in the S stationary ratios is fixed by its values at
    the 2^S corners of the box: at fractional position t it is
    Σ_corners Π_k (t_k or 1 − t_k) · value (tensor-product linear interpolation,
    exact for multilinear functions).  The combination determinants D_x are
    multilinear (each Willis row holds one i0, linearly), so their values
    anywhere in the box cost one small matrix product instead of a solve.

    Parameters
    ----------
    corner_values : ndarray (2^S, ...)
        Values at the box's corners in the order of ``_grid(low, high, 0)``.
    points : ndarray of int
        Grid point numbers at ``level`` (set 0 most significant, base 2^level + 1).
    level, sets : int

    Returns
    -------
    ndarray (len(points), ...)

    >>> corner = np.array([0.0, 1.0, 2.0, 3.0])   # f = 2 t0 + t1 on the unit square
    >>> multilinear(corner, np.array([0, 4, 8]), 1, 2).tolist()   # (0, 0), (1/2, 1/2), (1, 1)
    [0.0, 1.5, 3.0]
    """
    cells = 2 ** level
    digits = (np.asarray(points)[:, None] // (cells + 1) ** np.arange(sets - 1, -1, -1)) % (cells + 1)
    flat = corner_values.reshape(corner_values.shape[0], -1)
    return (corner_weights(digits / cells) @ flat).reshape((len(points),) + corner_values.shape[1:])


def corner_bits(sets: int) -> np.ndarray:
    """Which end of each set's range every corner takes, (2^S, S) bool: set 0 most significant."""
    return np.array(list(itertools.product((0, 1), repeat=sets)), dtype=bool)


def corner_weights(t: np.ndarray) -> np.ndarray:
    """Weights Π_k (t_k or 1 − t_k) of the 2^S corners at fractional positions ``t`` (P, S) → (P, 2^S).

    >>> corner_weights(np.array([[0.25, 1.0]])).tolist()   # corners (0, 0), (0, 1), (1, 0), (1, 1)
    [[0.0, 0.75, 0.0, 0.25]]
    """
    bits = corner_bits(t.shape[1])
    return np.prod(np.where(bits[None, :, :], t[:, None, :], 1.0 - t[:, None, :]), axis=2)


@functools.lru_cache(maxsize=32)
def _children_table(level: int, sets: int) -> np.ndarray:
    """:func:`_children` of every box at ``level`` (row = box number), computed once."""
    return _children(np.arange(2 ** (level * sets)), level, sets)


def _children(boxes: np.ndarray, level: int, sets: int) -> np.ndarray:
    """Numbers of the 2^S sub-boxes (at ``level + 1``) of each box (at ``level``), shape (len, 2^S).

    >>> _children(np.array([0]), 0, 2).tolist()
    [[0, 2, 1, 3]]
    """
    cells = 2 ** level
    boxes = np.asarray(boxes, dtype=np.int64)
    digits = (boxes[:, None] // cells ** np.arange(sets)) % cells  # (n, S)
    halves = np.array(list(itertools.product((0, 1), repeat=sets)))  # (2^S, S)
    weights = (2 * cells) ** np.arange(sets)
    return ((2 * digits[:, None, :] + halves[None, :, :]) * weights).sum(axis=2)
