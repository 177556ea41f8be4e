"""Small dense linear algebra with a diagnosis: rank, null space, consistency.

The solver never trusts a bare ``lstsq``: it needs to know *which* unknowns are
left free (to name the shafts) and *which* givens contradict (to name them).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Pseudoinverse", "pseudoinverse", "RELATIVE_TOLERANCE"]

#: Singular values below this fraction of the largest count as zero.
RELATIVE_TOLERANCE = 1e-10


@dataclass(frozen=True, eq=False)
class Pseudoinverse:
    """SVD-based pseudoinverse of a matrix A with its rank and null space.

    Attributes
    ----------
    matrix : ndarray (m, n)
    inverse : ndarray (n, m)
        Moore–Penrose pseudoinverse: x = inverse @ b is the least-squares,
        minimum-norm solution of A x = b.
    rank : int
    null_space : ndarray (n, n - rank)
        Orthonormal basis of the null space (free directions of x).
    """

    matrix: np.ndarray
    inverse: np.ndarray
    rank: int
    null_space: np.ndarray

    def free_columns(self, tolerance: float = 1e-9) -> list[int]:
        """Columns of x that the equations leave free (non-zero in the null space)."""
        if self.null_space.shape[1] == 0:
            return []
        weight = np.linalg.norm(self.null_space, axis=1)
        return [int(k) for k in np.flatnonzero(weight > tolerance)]

    def residual(self, x: np.ndarray, b: np.ndarray) -> np.ndarray:
        """|A x − b| per row (broadcast over trailing point axes)."""
        return np.abs(self.matrix @ x - b)

    def is_consistent(self, x: np.ndarray, b: np.ndarray, scale: float | np.ndarray) -> np.ndarray | bool:
        """Whether A x = b holds to round-off, relative to ``scale``.

        With full row rank every right-hand side is reachable, so no check is needed.
        """
        if self.rank == self.matrix.shape[0]:
            return True
        res = self.residual(x, b)
        limit = 1e-8 * (np.asarray(scale) + 1e-300)
        return np.all(res <= limit, axis=0)


def pseudoinverse(matrix: np.ndarray) -> Pseudoinverse:
    """Pseudoinverse, rank and null space of ``matrix`` from one SVD.

    >>> p = pseudoinverse(np.array([[1.0, -1.0]]))
    >>> p.rank, p.free_columns()
    (1, [0, 1])
    """
    matrix = np.atleast_2d(np.asarray(matrix, dtype=float))
    m, n = matrix.shape
    if m == 0:
        return Pseudoinverse(matrix, np.zeros((n, 0)), 0, np.eye(n))
    u, s, vt = np.linalg.svd(matrix, full_matrices=True)
    largest = s[0] if s.size else 0.0
    rank = int(np.sum(s > RELATIVE_TOLERANCE * max(largest, 1e-300))) if largest > 0 else 0
    inverse = (vt[:rank].T / s[:rank]) @ u[:, :rank].T
    null_space = vt[rank:].T
    return Pseudoinverse(matrix, inverse, rank, null_space)
