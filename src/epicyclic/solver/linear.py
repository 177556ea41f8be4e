"""Small dense linear algebra with a diagnosis: rank, null space, consistency, conditioning.

The solver never trusts a bare ``lstsq``: it needs to know *which* unknowns are
left free (to name the shafts), *which* givens contradict (to name them) and
whether the equations are too close to singular to be trusted.

Conditioning, not luck: the rows and columns of every system are first
equilibrated with powers of two (exact; Curtis and Reid's scaling, which
balances the magnitudes of the entries in the least-squares sense), so that a
chain of stages with a total ratio of 3^30, or a set with |i0| = 1e6, gives a
matrix whose singular values say something about the train and not about its
units.  Solutions are
refined once (Wilkinson's iterative refinement) in working precision, which
makes them accurate component by component.

The singular values s_k of the equilibrated matrix, relative to the largest,
sort the directions of the unknowns into three bands:

* s_k ≤ ``RANK_TOLERANCE``: exactly singular (round-off of an exact dependence,
  e.g. a set locked by two clutches); the direction is free or redundant;
* ``RANK_TOLERANCE`` < s_k ≤ ``NEAR_SINGULAR``: too close to singular to give a
  result (the solver raises :class:`~epicyclic.errors.NearSingularError`);
* above: solved.

References
----------
Curtis & Reid 1972, "On the automatic scaling of matrices for Gaussian
elimination", J. Inst. Maths Applics 10; Skeel 1980, "Iterative refinement implies
numerical stability for Gaussian elimination", Math. Comp. 35; Golub & Van
Loan, Matrix Computations, 4th ed., §5.5 (rank-deficient least squares by SVD).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["apply", "row_products", "span", "SMALL", "Pseudoinverse", "pseudoinverse", "equilibrate", "rank", "unreached_columns", "RANK_TOLERANCE",
           "NEAR_SINGULAR"]

#: Relative singular values at or below this are exact zeros (round-off of an exact dependence).
RANK_TOLERANCE = 1e-13
#: Relative singular values at or below this (and above RANK_TOLERANCE) are too close to singular.
NEAR_SINGULAR = 1e-10


def apply(matrix: np.ndarray, values: np.ndarray) -> np.ndarray:
    """``matrix @ values``; with one column, as one product per entry (the same numbers, signed zeros
    included, as BLAS gives, which is many times slower for a single column of many points).

    >>> m, v = np.array([[2.0], [-1.0]]), np.array([[3.0, 0.0]])
    >>> apply(m, v).tolist() == (m @ v).tolist()
    True
    """
    if matrix.ndim == 2 and matrix.shape[1] == 1 and values.ndim == 2:
        out = matrix * values
        out += 0.0  # BLAS sums into 0.0: a product −0 is +0
        return out
    return matrix @ values


#: Entries up to which a one-point product works in Python floats (numpy's call overhead is larger
#: than the arithmetic there).
SMALL = 48


def row_products(rows: list[list[float]], values: list[float]) -> list[float]:
    """``matrix @ values`` for a matrix given as its rows, in Python floats: each entry summed from 0.0,
    left to right.  For one column these are BLAS's numbers (a product per entry); for more, BLAS may
    fuse a multiply and an add (one rounding), so they are the same up to the last bit only.

    >>> row_products([[2.0, 1.0], [-1.0, 0.5]], [3.0, 4.0])
    [10.0, -1.0]
    """
    if len(values) == 1:  # one given value: a product per entry
        value = values[0]
        return [row[0] * value + 0.0 for row in rows]
    out = []
    for row in rows:
        total = 0.0
        for a, b in zip(row, values):
            total += a * b
        out.append(total)
    return out


def span(size: np.ndarray) -> tuple[float, float]:
    """The smallest non-zero and the largest entry of ``size`` (magnitudes, ≥ 0): (inf, 0) where all
    are 0; NaN where one is NaN.  Two reductions (three where some entry is 0).

    >>> span(np.array([[0.0, 2.0], [0.5, 0.0]]))
    (0.5, 2.0)
    """
    most = float(size.max(initial=0.0))
    least = float(size.min(initial=np.inf))
    if least == 0.0:
        least = float(np.min(size, where=size > 0.0, initial=np.inf))
    return least, most


def equilibrate(matrix: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Row and column scales r, c (powers of two) that make diag(r)·A·diag(c) balanced.

    Curtis and Reid's scaling: the binary logarithms ρ_i, γ_j of the scales
    minimise Σ (log2|a_ij| + ρ_i + γ_j)² over the non-zero entries (a small
    least-squares problem), then round to integers.  A chain of stages whose
    torques grow by 3 per stage gets column scales 3^−k, which a max-norm
    balancing (every entry already near 1) would not find.

    Parameters
    ----------
    matrix : ndarray (m, n)

    Returns
    -------
    r : ndarray (m,)
    c : ndarray (n,)

    References
    ----------
    Curtis & Reid 1972, "On the automatic scaling of matrices for Gaussian
    elimination", J. Inst. Maths Applics 10, 118–124.

    Examples
    --------
    >>> a = np.array([[1.0, -1e6], [0.0, 1.0]])
    >>> r, c = equilibrate(a)
    >>> bool(np.linalg.cond(r[:, None] * a * c) < 10)
    True
    """
    a = np.asarray(matrix, dtype=float)
    m, n = a.shape
    rows, cols = np.nonzero(a)
    if rows.size == 0:
        return np.ones(m), np.ones(n)
    # normal equations of the least-squares problem; the tiny ridge fixes the gauge (ρ + t, γ − t)
    logs = -np.log2(np.abs(a[rows, cols]))
    normal = np.zeros((m + n, m + n))
    normal[rows, m + cols] = 1.0  # each non-zero once
    normal[m + cols, rows] = 1.0
    normal[np.diag_indices(m + n)] = np.concatenate([np.bincount(rows, minlength=m),
                                                     np.bincount(cols, minlength=n)]) + 1e-9
    rhs = np.concatenate([np.bincount(rows, logs, m), np.bincount(cols, logs, n)])
    scale = np.exp2(np.round(np.linalg.solve(normal, rhs)))
    return scale[:m], scale[m:]


@dataclass(frozen=True, eq=False)
class Pseudoinverse:
    """Equilibrated SVD of a matrix A: pseudoinverse, rank, null space and nearly singular directions.

    Attributes
    ----------
    matrix : ndarray (m, n)
    inverse : ndarray (n, m)
        Moore–Penrose pseudoinverse of the equilibrated matrix, mapped back:
        x = inverse @ b is the least-squares, minimum-norm (in the scaled
        unknowns) solution of A x = b.  Use :meth:`solve` for a refined one.
    rank : int
        Singular values above ``RANK_TOLERANCE`` (relative), the near-singular ones included.
    null_space : ndarray (n, n - rank)
        Basis of the null space (free directions of x), columns of unit length.
    near_singular : tuple of (float, ndarray, ndarray)
        For each singular value in the near-singular band: its relative size,
        the direction of the unknowns (right singular vector, original
        coordinates, unit length) and the weights of the rows (left singular
        vector) that nearly cancel.
    """

    matrix: np.ndarray
    inverse: np.ndarray
    rank: int
    null_space: np.ndarray
    near_singular: tuple[tuple[float, np.ndarray, np.ndarray], ...] = ()

    def free_columns(self, tolerance: float = 1e-9) -> list[int]:
        """Columns of x that the equations leave free (non-zero in the null space)."""
        if self.null_space.shape[1] == 0:
            return []
        weight = np.linalg.norm(self.null_space, axis=1)
        return [int(k) for k in np.flatnonzero(weight > tolerance)]

    def solve(self, b: np.ndarray) -> np.ndarray:
        """x with A x = b (least squares), refined once; ``b`` may carry trailing point axes."""
        b = np.asarray(b, dtype=float)
        x = self.inverse @ b
        return x + self.inverse @ (b - self.matrix @ x)

    def residual(self, x: np.ndarray, b: np.ndarray) -> np.ndarray:
        """|A x − b| per row (broadcast over trailing point axes)."""
        return np.abs(self.matrix @ x - b)

    def is_consistent(self, x: np.ndarray, b: np.ndarray, scale: float | np.ndarray) -> np.ndarray | bool:
        """Whether A x = b holds to round-off, relative to ``scale``.

        With full row rank every right-hand side is reachable, so no check is needed.
        The residual of each row is compared with the size of its terms |A|·|x|
        and with ``scale`` (the size of the given values).
        """
        if self.rank == self.matrix.shape[0]:
            return True
        res = self.residual(x, b)
        terms = np.abs(self.matrix) @ np.abs(x) + np.abs(b)
        limit = 1e-8 * (np.asarray(scale) + 1e-300) + 1e-9 * terms
        return np.all(res <= limit, axis=0)


def _svd(matrix: np.ndarray, scaling: tuple[np.ndarray, np.ndarray] | None = None):
    r, c = equilibrate(matrix) if scaling is None else scaling
    scaled = matrix * r[:, None] * c[None, :]
    u, s, vt = np.linalg.svd(scaled, full_matrices=True)
    largest = s[0] if s.size else 0.0
    relative = s / largest if largest > 0 else np.zeros_like(s)
    return r, c, u, s, vt, relative


def pseudoinverse(matrix: np.ndarray, scaling: tuple[np.ndarray, np.ndarray] | None = None) -> Pseudoinverse:
    """Pseudoinverse, rank, null space and near-singular directions of ``matrix`` from one SVD.

    ``scaling`` (row and column scales) defaults to :func:`equilibrate`'s; a
    matrix that differs from another only by factors near 1 (another loss
    pattern) may reuse that one's.

    >>> p = pseudoinverse(np.array([[1.0, -1.0]]))
    >>> p.rank, p.free_columns()
    (1, [0, 1])
    >>> p = pseudoinverse(np.array([[1.0, -1.0], [1.0, -1.0 - 1e-12]]))
    >>> p.rank, p.free_columns(), round(p.near_singular[0][0] * 1e12, 2)
    (2, [], 0.25)
    """
    matrix = np.atleast_2d(np.asarray(matrix, dtype=float))
    m, n = matrix.shape
    if m == 0 or n == 0:
        return Pseudoinverse(matrix, np.zeros((n, m)), 0, np.eye(n))
    r, c, u, s, vt, relative = _svd(matrix, scaling)
    rank = int(np.sum(relative > RANK_TOLERANCE))
    inverse = c[:, None] * ((vt[:rank].T / s[:rank]) @ u[:, :rank].T) * r[None, :]
    null = c[:, None] * vt[rank:].T
    null = null / np.maximum(np.linalg.norm(null, axis=0), 1e-300)
    near = []
    for k in range(rank):
        if relative[k] <= NEAR_SINGULAR:
            direction = c * vt[k]
            near.append((float(relative[k]), direction / np.linalg.norm(direction), u[:, k] * r))
    return Pseudoinverse(matrix, inverse, rank, null, tuple(near))


def rank(matrix: np.ndarray) -> int:
    """Numerical rank of ``matrix`` after equilibration (relative tolerance ``RANK_TOLERANCE``)."""
    matrix = np.atleast_2d(np.asarray(matrix, dtype=float))
    if matrix.size == 0:
        return 0
    r, c = equilibrate(matrix)
    s = np.linalg.svd(matrix * r[:, None] * c[None, :], compute_uv=False)
    return int(np.sum(s > RANK_TOLERANCE * s[0])) if s[0] > 0 else 0


def unreached_columns(matrix: np.ndarray, sources: list[int]) -> np.ndarray:
    """Columns of ``matrix`` that no row chain joins to a column in ``sources``.

    The equations A x = 0 fall apart into blocks that share no unknown; a block
    that holds none of the given unknowns (``sources``) has the solution 0,
    exactly, and its unknowns are set so instead of to round-off.

    >>> unreached_columns(np.array([[1.0, -2.0, 0.0], [0.0, 0.0, 1.0]]), [0]).tolist()
    [2]
    """
    a = np.asarray(matrix) != 0
    n = a.shape[1]
    reached = np.zeros(n, dtype=bool)
    reached[list(sources)] = True
    while True:
        rows = a[:, reached].any(axis=1)
        grown = reached | a[rows].any(axis=0)
        if (grown == reached).all():
            return np.flatnonzero(~reached)
        reached = grown
