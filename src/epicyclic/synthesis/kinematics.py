"""Kinematics of many candidate transmissions at once (numpy, no per-candidate loop).

For a mechanism with N shafts and S Willis rows ``L(i0)`` (one per set,
``n_sun − i0·n_ring − (1 − i0)·n_carrier = 0``), a shift element is a row
``E``: a brake on shaft x is ``e_x``, a clutch between x and y is ``e_x − e_y``.
A combination of k = N − S − 1 engaged elements is a gear when the square
matrix ``[L; E; e_in]`` is regular, and then (Cramer's rule)

.. math:: n_\\mathrm{out}/n_\\mathrm{in} = D_\\mathrm{out} / D_\\mathrm{in},
          \\qquad D_x = \\det [L; E; e_x].

``D_x`` for every shaft x at once is the vector of signed maximal minors of
``[L; E]`` (the generalized cross product).  It is computed in the mechanism's
null space: with ``V`` an orthonormal basis of the null space of ``L`` and
``R`` of its row space, ``D_x = κ · c(E V) · v_x`` with κ = det(L R)·det[R V]
and c the cofactor vector of the k×(k+1) matrix ``E V``.  Values within
round-off of zero (relative to the largest ``D_x`` of the combination, the
project's one rule :mod:`epicyclic.results.zero`) are exactly zero.  So one mechanism
gives the determinants of every combination, for every choice of input and
output, from a handful of small products (:func:`combination_determinants`).

``D_x`` is multilinear in the stationary ratios (each Willis row holds one i0,
linearly).  Hence a gear ratio ``D_in/D_out`` is a multilinear fraction: it is
monotone in each i0 on any line parallel to an axis, and its extremes over a
box of i0 lie at the box's corners (:func:`ratio_ranges`).  That bound is what
prunes the search before any ratio is fitted.

References
----------
Queitsch, eq. 12 (Willis equation with s = i0); Benford & Leising 1981 (a shift
state adds one lever constraint per element); Kahraman et al. 2004, J. Mech.
Des. 126(6), eqs. 1–5 (kinematics of a general one-DOF automatic transmission
as one linear system per gear).
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..results.zero import ZERO_TOLERANCE, clean_array
from .boxes import corner_bits, corner_weights
from .mechanisms import Mechanism

__all__ = [
    "combination_determinants",
    "corner_points",
    "element_count",
    "element_rows",
    "element_shafts",
    "gear_ratios",
    "hadamard_bound",
    "hadamard_factors",
    "ratio_ranges",
    "RatioFunctions",
    "willis_matrices",
]


def element_count(shafts: int) -> int:
    """Candidate shift elements of a mechanism: one brake per shaft, one clutch per pair of shafts."""
    return shafts + shafts * (shafts - 1) // 2


def element_shafts(shafts: int) -> list[tuple[int, ...]]:
    """Element number → (shaft,) for a brake, (shaft, shaft) for a clutch; brakes first."""
    return [(x,) for x in range(shafts)] + list(itertools.combinations(range(shafts), 2))


def element_rows(shafts: int) -> np.ndarray:
    """Kinematic row of every candidate element, shape (elements, shafts)."""
    rows = np.zeros((element_count(shafts), shafts))
    for e, s in enumerate(element_shafts(shafts)):
        rows[e, s[0]] = 1.0
        if len(s) == 2:
            rows[e, s[1]] = -1.0
    return rows


def willis_matrices(mechanism: Mechanism, ratios: np.ndarray) -> np.ndarray:
    """Willis rows at many stationary-ratio vectors: ``ratios`` (P, S) → (P, S, N).

    >>> from epicyclic.synthesis.mechanisms import Mechanism
    >>> m = Mechanism(("simple",), (0, 1, 2))
    >>> willis_matrices(m, np.array([[-2.0]])).tolist()
    [[[1.0, 2.0, -3.0]]]
    """
    ratios = np.atleast_2d(np.asarray(ratios, dtype=float))
    points, sets = ratios.shape
    out = np.zeros((points, sets, mechanism.shafts))
    for k in range(sets):
        s, r, c = mechanism.set_shafts(k)
        out[:, k, s] += 1.0
        out[:, k, r] -= ratios[:, k]
        out[:, k, c] -= 1.0 - ratios[:, k]
    return out


def _det(m: np.ndarray) -> np.ndarray:
    """Determinants of a stack of small square matrices (explicit for k ≤ 3, fast for many)."""
    k = m.shape[-1]
    if k == 0:
        return np.ones(m.shape[:-2])
    if k == 1:
        return m[..., 0, 0]
    if k == 2:
        return m[..., 0, 0] * m[..., 1, 1] - m[..., 0, 1] * m[..., 1, 0]
    if k == 3:
        return (m[..., 0, 0] * (m[..., 1, 1] * m[..., 2, 2] - m[..., 1, 2] * m[..., 2, 1])
                - m[..., 0, 1] * (m[..., 1, 0] * m[..., 2, 2] - m[..., 1, 2] * m[..., 2, 0])
                + m[..., 0, 2] * (m[..., 1, 0] * m[..., 2, 1] - m[..., 1, 1] * m[..., 2, 0]))
    return np.linalg.det(m)


def combination_determinants(mechanism: Mechanism, ratios: np.ndarray, combos: np.ndarray,
                             rows: np.ndarray | None = None, compiled: bool = False) -> np.ndarray:
    """``D[p, t, x] = det[L(i0_p); E_t; e_x]`` for points p, combinations t, shafts x.

    Parameters
    ----------
    mechanism : Mechanism
    ratios : ndarray, shape (P, S)
        Stationary ratios per point.
    combos : ndarray of int, shape (T, k)
        Element numbers (see :func:`element_shafts`) of each combination,
        k = degrees of freedom − 1.
    rows : ndarray, optional
        Element rows (default :func:`element_rows`).
    compiled : bool, default False
        Four engaged elements: the cofactors in the compiled loop
        (:func:`~epicyclic.synthesis.kernel.four_cofactors`, bit-equal; needs numba).

    Returns
    -------
    ndarray, shape (P, T, N)
    """
    ratios = np.atleast_2d(np.asarray(ratios, dtype=float))
    n = mechanism.shafts
    rows = element_rows(n) if rows is None else rows
    lmat = willis_matrices(mechanism, ratios)
    _, _, vt = np.linalg.svd(lmat)  # (P, N, N)
    sets = mechanism.sets
    basis_row = np.swapaxes(vt[:, :sets, :], 1, 2)  # (P, N, S)
    basis_null = np.swapaxes(vt[:, sets:, :], 1, 2)  # (P, N, d)
    kappa = _det(lmat @ basis_row) * np.linalg.det(np.concatenate([basis_row, basis_null], axis=2))
    funcs = rows @ basis_null  # (P, elements, d)
    cof = _cofactors(funcs, combos, compiled)  # (P, T, d)
    det = np.matmul(cof, np.swapaxes(basis_null, 1, 2), out=np.empty(cof.shape[:2] + (n,)))
    det *= kappa[:, None, None]
    # round-off of an exact zero (an output that stands still, or a combination that is no gear, whose
    # minors all vanish) is zero, relative to Hadamard's bound of the minors
    return _clean_in_place(det, hadamard_bound(mechanism, ratios, combos, rows)[:, :, None])


def _clean_in_place(values: np.ndarray, scale: np.ndarray) -> np.ndarray:
    """``clean_array(values, scale)`` written into ``values``, a block of points at a time.

    The same test and the same result (``tests/synthesis/test_kinematics.py``), without its
    full-size temporaries: with four engaged elements a table is 170 MB, and each temporary of that
    size is a fresh mmap whose pages the kernel faults in and zeroes (a quarter of a task's CPU time).
    """
    step = max(1, (8 << 20) // max(values[0].nbytes, 1))  # blocks of about 8 MB: reused heap memory
    for start in range(0, values.shape[0], step):
        block = values[start:start + step]
        with np.errstate(invalid="ignore", over="ignore"):
            zero = (np.abs(block) <= ZERO_TOLERANCE * np.abs(scale[start:start + step])) & np.isfinite(block)
        block[zero] = 0.0
        block += 0.0  # as clean_array: no negative zero
    return values


def hadamard_bound(mechanism: Mechanism, ratios: np.ndarray, combos: np.ndarray,
                   rows: np.ndarray | None = None) -> np.ndarray:
    """Hadamard's bound of every minor D_x = det[L; E; e_x]: the product of the row norms, shape (P, T).

    |det M| ≤ Π ||row_i|| (Hadamard 1893), and e_x has norm 1, so one bound holds for every
    shaft x.  It is the scale against which round-off of an exact zero is recognised: a
    combination that is no gear has *all* its minors zero, which its largest minor cannot tell.

    Parameters
    ----------
    mechanism : Mechanism
    ratios : ndarray (P, S)
    combos : ndarray of int (T, k)
    rows : ndarray, optional
        Element rows (default :func:`element_rows`).

    References
    ----------
    Hadamard, J. (1893), "Résolution d'une question relative aux déterminants", Bull. Sci. Math. 17.
    """
    willis, elements = hadamard_factors(mechanism, ratios, combos, rows)
    return willis[:, None] * elements[None, :]


def hadamard_factors(mechanism: Mechanism, ratios: np.ndarray, combos: np.ndarray,
                     rows: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The two factors of :func:`hadamard_bound`: Willis rows' norms per point (P,), element rows' per combination (T,).

    Parameters
    ----------
    mechanism : Mechanism
    ratios : ndarray (P, S)
    combos : ndarray of int (T, k)
    rows : ndarray, optional
        Element rows (default :func:`element_rows`).

    References
    ----------
    Hadamard, J. (1893), Bull. Sci. Math. 17.
    """
    ratios = np.atleast_2d(np.asarray(ratios, dtype=float))
    rows = element_rows(mechanism.shafts) if rows is None else rows
    willis = np.prod(np.sqrt(1.0 + ratios ** 2 + (1.0 - ratios) ** 2), axis=1)  # (P,)
    elements = np.prod(np.linalg.norm(rows, axis=1)[np.asarray(combos)], axis=1)  # (T,)
    return willis, elements


def _cofactors(funcs: np.ndarray, combos: np.ndarray, compiled: bool = False) -> np.ndarray:
    """Signed maximal minors c_i = (−1)^(i+k) det(F without column i) of each k×(k+1) matrix F."""
    k = combos.shape[1]
    d = funcs.shape[2]
    if compiled and k == 4 and d == 5:  # the same terms in the same order, compiled (bit-equal)
        from .kernel import four_cofactors

        return four_cofactors(funcs, combos)
    if k == 3 and d == 4:  # the common case (three engaged elements): 2×2 minors of the first two rows
        a, b, c = (funcs[:, combos[:, j], :] for j in range(3))  # (P, T, 4) each
        m = {(i, j): a[..., i] * b[..., j] - a[..., j] * b[..., i] for i, j in itertools.combinations(range(4), 2)}
        out = np.empty(a.shape)
        for i in range(4):
            p, q, r = [j for j in range(4) if j != i]
            det = m[(p, q)] * c[..., r] - m[(p, r)] * c[..., q] + m[(q, r)] * c[..., p]
            out[..., i] = det if (i + k) % 2 == 0 else -det
        return out
    if k == 4 and d == 5:  # four engaged: Laplace expansion along the first two rows (2×2 minors, no LU)
        pairs = list(itertools.combinations(range(5), 2))
        first, second = [i for i, _ in pairs], [j for _, j in pairs]
        # 2×2 minors of every pair of element rows once (P, E, E, 10), then gathered per combination
        minors = funcs[:, :, None, first] * funcs[:, None, :, second] - funcs[:, :, None, second] * funcs[:, None, :, first]
        upper = minors[:, combos[:, 0], combos[:, 1], :]  # (P, T, 10)
        lower = minors[:, combos[:, 2], combos[:, 3], :]
        top = {pair: upper[..., n] for n, pair in enumerate(pairs)}
        bottom = {pair: lower[..., n] for n, pair in enumerate(pairs)}
        out = np.empty(upper.shape[:2] + (5,))
        for i in range(5):
            cols = [j for j in range(5) if j != i]
            det = np.zeros(upper.shape[:2])
            for p, q in itertools.combinations(range(4), 2):
                r, t = (x for x in range(4) if x not in (p, q))
                term = top[(cols[p], cols[q])] * bottom[(cols[r], cols[t])]
                det += term if (p + q) % 2 else -term  # sign (-1)^(p + q + 1) of the Laplace expansion
            out[..., i] = det if (i + k) % 2 == 0 else -det
        return out
    picked = funcs[:, combos, :]  # (P, T, k, d)
    out = np.empty(picked.shape[:2] + (d,))
    for i in range(d):
        cols = [j for j in range(d) if j != i]
        out[..., i] = (-1) ** (i + k) * _det(picked[..., cols])
    return out


def corner_points(low: np.ndarray, high: np.ndarray) -> np.ndarray:
    """All 2^S corners of the box [low, high] (arrays of length S), shape (2^S, S)."""
    low, high = np.asarray(low, float), np.asarray(high, float)
    return np.where(corner_bits(low.size), high, low)


def ratio_ranges(det_in: np.ndarray, det_out: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Bounds of ratio = D_in/D_out over a box from its corner values (axis 0).

    Returns ``valid`` (both determinants keep one sign at every corner, so
    neither vanishes in the box: a multilinear function lies between its
    corner values), and the smallest and largest ratio over the box.
    """
    corners = det_in.shape[0]
    valid = (np.abs(np.sign(det_in).sum(axis=0)) == corners) & (np.abs(np.sign(det_out).sum(axis=0)) == corners)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = det_in / det_out
    return valid, np.where(valid, ratio.min(axis=0), np.nan), np.where(valid, ratio.max(axis=0), np.nan)


def gear_ratios(mechanism: Mechanism, ratios: np.ndarray, combos: np.ndarray, input: int, output: int,
                rows: np.ndarray | None = None) -> np.ndarray:
    """Gear ratio n_in/n_out of each combination at each point, shape (P, T); NaN where no gear.

    Examples
    --------
    >>> from epicyclic.synthesis.mechanisms import Mechanism
    >>> m = Mechanism(("simple",), (0, 1, 2))        # sun 0, ring 1, carrier 2
    >>> # brake on the ring (element 1), sun in, carrier out: 1 - i0
    >>> gear_ratios(m, np.array([[-2.0]]), np.array([[1]]), 0, 2).round(9).tolist()
    [[3.0]]
    """
    det = combination_determinants(mechanism, ratios, combos, rows)
    d_in, d_out = det[..., input], det[..., output]
    ok = (d_in != 0) & (d_out != 0)  # zeros are exact after clean_array
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(ok, d_in / d_out, np.nan)


@dataclass(frozen=True)
class RatioFunctions:
    """Gear ratios of some combinations as functions of the stationary ratios over one box, with their derivatives.

    ``D_in`` and ``D_out`` are multilinear in i0, so their values at the box's 2^S corners fix them
    everywhere in it: at fractional position t, ``D(i0) = Σ_c w_c(t) D_c`` with
    ``w_c = Π_k (t_k or 1 − t_k)`` (tensor-product linear interpolation, exact for multilinear
    functions), and ``∂D/∂i0_k = Σ_c (∂w_c/∂t_k) D_c / (high_k − low_k)``.  One small product per
    point replaces the null-space solve of :func:`gear_ratios`, and the derivatives are exact instead
    of finite differences: the ratio fit's inner loop.  Inside the box the weights are convex, so the
    values agree with :func:`gear_ratios` to round-off (``tests/synthesis/test_kinematics.py``); a
    value within round-off of zero at a point (against Hadamard's bound there) is zero, as there.

    Build with :meth:`of`.

    Attributes
    ----------
    low, high : ndarray (S,)
        The box.
    inputs, outputs : ndarray (2^S, C)
        ``D_in`` and ``D_out`` of each combination at the corners (order of :func:`corner_points`).
    elements : ndarray (C,)
        The element factor of Hadamard's bound of each combination (:func:`hadamard_factors`).

    References
    ----------
    Kahraman et al. 2004, J. Mech. Des. 126(6), eqs. 1–5 (gear ratios from stationary ratios);
    Hadamard, J. (1893), Bull. Sci. Math. 17.
    """

    low: np.ndarray
    high: np.ndarray
    inputs: np.ndarray
    outputs: np.ndarray
    elements: np.ndarray

    @classmethod
    def of(cls, mechanism: Mechanism, low: np.ndarray, high: np.ndarray, combos: np.ndarray, input: int,
           output: int) -> RatioFunctions:
        """The ratio functions of ``combos`` (rows of element numbers) from ``input`` to ``output`` over [low, high]."""
        low, high = np.asarray(low, dtype=float), np.asarray(high, dtype=float)
        det = combination_determinants(mechanism, corner_points(low, high), combos)
        _, elements = hadamard_factors(mechanism, low[None, :], combos)
        return cls(low, high, np.ascontiguousarray(det[..., input]), np.ascontiguousarray(det[..., output]), elements)

    def _position(self, ratios: np.ndarray) -> np.ndarray:
        return np.clip((ratios - self.low) / (self.high - self.low), 0.0, 1.0)

    def _gradients(self, point: np.ndarray) -> np.ndarray:
        """∂w_c/∂i0_k at one point, (S, 2^S): the k-th factor of each weight replaced by ±1 / width_k."""
        t = self._position(point)
        bits = corner_bits(t.size)
        factors = np.where(bits, t, 1.0 - t)  # (2^S, S)
        grads = np.empty((t.size, bits.shape[0]))
        for k, width in enumerate((self.high - self.low).tolist()):
            others = factors.copy()
            others[:, k] = np.where(bits[:, k], 1.0, -1.0)
            grads[k] = np.prod(others, axis=1) / width
        return grads

    def _clean(self, values: np.ndarray, ratios: np.ndarray) -> np.ndarray:
        """``clean_array`` against Hadamard's bound at each point (P, C)."""
        willis = np.prod(np.sqrt(1.0 + ratios ** 2 + (1.0 - ratios) ** 2), axis=1)
        bound = ZERO_TOLERANCE * willis[:, None] * self.elements[None, :]
        return np.where(np.abs(values) <= bound, 0.0, values) + 0.0

    def __call__(self, ratios: np.ndarray) -> np.ndarray:
        """Gear ratio of every combination at points ``ratios`` (P, S) → (P, C); NaN where no gear."""
        ratios = np.atleast_2d(np.asarray(ratios, dtype=float))
        weights = corner_weights(self._position(ratios))
        num, den = self._clean(weights @ self.inputs, ratios), self._clean(weights @ self.outputs, ratios)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where((num != 0) & (den != 0), num / den, np.nan)

    def with_jacobian(self, ratios: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Ratios (C,) at one point (S,) and their derivatives ∂r/∂i0, shape (C, S); NaN where no gear."""
        point = np.asarray(ratios, dtype=float)[None, :]
        weights, grads = corner_weights(self._position(point))[0], self._gradients(point[0])
        num, den = self._clean(weights @ self.inputs, point)[0], self._clean(weights @ self.outputs, point)[0]
        d_num, d_den = grads @ self.inputs, grads @ self.outputs  # (S, C)
        ok = (num != 0) & (den != 0)
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = np.where(ok, num / den, np.nan)
            jacobian = np.where(ok[:, None], ((d_num * den - num * d_den) / den ** 2).T, np.nan)
        return ratio, jacobian


def combinations_of(elements: Sequence[int], size: int) -> np.ndarray:
    """All ``size``-subsets of ``elements`` as an int array (rows sorted)."""
    out = np.array(list(itertools.combinations(sorted(elements), size)), dtype=int)
    return out.reshape(-1, size)
