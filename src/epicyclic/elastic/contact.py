"""Static equilibrium of springs of which some act only in compression (tooth contacts), many cases at once.

Linear springs (k_i, v_i, offset e_i) and contact springs (k_j, w_j, gap g_j) hold the
coordinates q under the loads f.  The equilibrium minimises the convex, piecewise-quadratic energy

    E(q) = ½ Σ_i k_i (v_iᵀq − e_i)² + ½ Σ_j k_j max(w_jᵀq − g_j, 0)² − fᵀq,

a complementarity problem (a contact carries k (wᵀq − g) ≥ 0 where it closes, nothing where it
opens).  It is solved by Newton's method on the active set — each step solves the linear system
of the contacts closed at the current q — with a backtracking line search on E, which makes the
method converge from any start (a spring of 10⁻¹¹ of the mean stiffness on every coordinate keeps each
step's system regular where the open contacts leave a member free); it ends when the solution of an active set keeps that set (contacts
within round-off of their boundary count either way).  The bound: at most ``iterations`` steps (default 60) of at most 30 halvings each,
else :class:`~epicyclic.elastic.errors.ElasticError`.  All cases (rows) are solved together with
batched ``numpy.linalg.solve``.

References
----------
Semismooth Newton for piecewise-quadratic contact: M. Hintermüller, K. Ito, K. Kunisch, "The
primal-dual active set strategy as a semismooth Newton method", SIAM J. Optim. 13 (2003) 865–888;
the linear complementarity form of one-sided mesh contact in planetary load sharing: A. Singh,
"Load sharing behavior in epicyclic gears: physical explanation and generalized formulation",
Mech. Mach. Theory 45 (2010) 511–530.
"""

from __future__ import annotations

import numpy as np

from .errors import ElasticError

__all__ = ["solve_contact"]


def _regularisation(k_lin, v_lin, k_con, w_con) -> float:
    """ε = 10⁻¹¹ of the mean diagonal stiffness: holds a member that the open contacts leave free (a floating sun
    touching one planet) in the Newton steps; at the equilibrium its spring carries ~10⁻¹¹ of the load."""
    diag = (v_lin * v_lin).T @ k_lin + (w_con * w_con).T @ k_con
    return 1e-11 * float(np.mean(diag))


def _energy(q, k_lin, v_lin, e_lin, k_con, w_con, g_con, f):
    s = q @ v_lin.T - e_lin
    c = np.maximum(q @ w_con.T - g_con, 0.0)
    eps = _regularisation(k_lin, v_lin, k_con, w_con)  # the energy of the regularised steps
    return 0.5 * (s * s) @ k_lin + 0.5 * (c * c) @ k_con + 0.5 * eps * np.einsum("bi,bi->b", q, q) \
        - np.einsum("bi,bi->b", f, q)


def _system(active, k_lin, v_lin, e_lin, k_con, w_con, g_con, f, *, regular: bool = True):
    base = (v_lin.T * k_lin) @ v_lin
    if regular:
        base = base + _regularisation(k_lin, v_lin, k_con, w_con) * np.eye(v_lin.shape[1])
    a = base[None] + np.einsum("bj,ji,jk->bik", active * k_con, w_con, w_con)
    rhs = f + (e_lin * k_lin) @ v_lin + (active * g_con * k_con) @ w_con
    free = np.abs(np.einsum("bii->bi", a)) == 0.0                 # a coordinate nothing holds (a planet off contact)
    if free.any():
        b, i = np.nonzero(free)
        a[b, i, i] = 1.0
        rhs[b, i] = 0.0
    return a, rhs


def _polish(act, target, tol, k_lin, v_lin, e_lin, k_con, w_con, g_con, f):
    """The equilibria of the active sets ``act`` without the regularising spring, where they keep their set.

    A member the closed contacts hold only in part (a floating sun between two opposite planets)
    makes the system singular but consistent; its least-norm solution (pseudo-inverse), the limit of
    the regularised one, is taken there.  Rows whose plain solution changes the active set or leaves the system
    unsolved (an inconsistent least-squares answer) keep ``target``.
    """
    a0, rhs0 = _system(act, k_lin, v_lin, e_lin, k_con, w_con, g_con, f, regular=False)

    def holds(q):
        """Finite, in equilibrium (the linear system solved to round-off) and keeping its active set."""
        d0 = q @ w_con.T - g_con
        residual = np.linalg.norm(np.einsum("bij,bj->bi", a0, np.nan_to_num(q)) - rhs0, axis=1)
        return np.all(((d0 > 0.0) == (act == 1.0)) | (np.abs(d0) <= tol), axis=1) & np.all(np.isfinite(q), axis=1) \
            & (residual <= 1e-9 * np.linalg.norm(rhs0, axis=1))

    try:
        plain = np.linalg.solve(a0, rhs0[..., None])[..., 0]
    except np.linalg.LinAlgError:
        plain = np.full_like(target, np.nan)
    ok = holds(plain)
    if not ok.all():
        least = np.einsum("bij,bj->bi", np.linalg.pinv(a0[~ok], rcond=1e-12), rhs0[~ok])
        plain[~ok] = least
        ok = holds(plain)
    return np.where(ok[:, None], plain, target)


def solve_contact(k_lin, v_lin, e_lin, k_con, w_con, g_con, f, *, iterations: int = 60):
    """Equilibrium q of every case (row of ``e_lin``, ``g_con``, ``f``), and the closed contacts.

    Parameters
    ----------
    k_lin, v_lin : ndarray
        Linear springs: stiffness (L,), directions (L, n).
    e_lin : ndarray
        Their offsets (B, L) (a pin out of place).
    k_con, w_con : ndarray
        Contacts: stiffness (C,), directions (C, n).
    g_con : ndarray
        Gaps (B, C): > 0 a clearance to close first, < 0 an interference.
    f : ndarray
        Loads (B, n).
    iterations : int, default 60
        Bound on Newton steps.

    Returns
    -------
    tuple
        (q (B, n), contact deflections wᵀq − g (B, C); a contact carries k max(…, 0)).

    Raises
    ------
    ElasticError
        No equilibrium within the bound (a set held by nothing, or loads that open every contact).

    References
    ----------
    Hintermüller, Ito & Kunisch 2003 (active-set Newton); Singh 2010 (one-sided mesh contact).

    Examples
    --------
    A unit load on a mass held by a spring (k = 1) and a contact (k = 1) with a gap of 0.5:

    >>> q, d = solve_contact(np.array([1.0]), np.array([[1.0]]), np.zeros((1, 1)), np.array([1.0]),
    ...                      np.array([[1.0]]), np.array([[0.5]]), np.array([[1.0]]))
    >>> float(q[0, 0]), float(d[0, 0])
    (0.75, 0.25)
    """
    args = (k_lin, v_lin, e_lin, k_con, w_con, g_con, f)
    a, rhs = _system(np.ones_like(g_con, dtype=float), *args, regular=False)
    try:
        q = np.linalg.solve(a, rhs[..., None])[..., 0]              # every contact closed
    except np.linalg.LinAlgError:
        a, rhs = _system(np.ones_like(g_con, dtype=float), *args)
        q = np.linalg.solve(a, rhs[..., None])[..., 0]
    active = (q @ w_con.T - g_con > 0.0).astype(float)
    done = np.all(active == 1.0, axis=1)                           # the all-closed solution holds
    for _ in range(iterations):
        if done.all():
            return q, q @ w_con.T - g_con
        rows = np.flatnonzero(~done)
        sub = (k_lin, v_lin, e_lin[rows], k_con, w_con, g_con[rows], f[rows])
        act = (q[rows] @ w_con.T - g_con[rows] > 0.0).astype(float)
        a, rhs = _system(act, *sub)
        target = np.linalg.solve(a, rhs[..., None])[..., 0]
        d = target @ w_con.T - g_con[rows]
        tol = 1e-10 * np.max(np.abs(d), axis=1, keepdims=True)
        # a contact at its boundary (|δ| round-off: a planet whose other mesh is open) counts either way
        exact = np.all(((d > 0.0) == (act == 1.0)) | (np.abs(d) <= tol), axis=1)
        # rows whose target keeps its own active set are solved; the others step with a line search on E
        current = q[rows]
        step = target - current
        energy = _energy(current, *sub)
        t = np.ones(len(rows))
        trial = target.copy()
        e_trial = _energy(trial, *sub)
        slack = 1e-12 * np.abs(energy) + 1e-300                   # descent on the current energy
        for _ in range(30):                                       # backtracking: E must not rise
            worse = ~exact & (e_trial > energy + slack)
            if not worse.any():
                break
            t = np.where(worse, t / 2, t)
            trial = current + t[:, None] * step
            e_trial = _energy(trial, *sub)
        if exact.any():  # the active set found: its equilibrium without the regularising spring
            target[exact] = _polish(act[exact], target[exact], tol[exact], k_lin, v_lin, e_lin[rows[exact]], k_con,
                                    w_con, g_con[rows[exact]], f[rows[exact]])
        q[rows] = np.where(exact[:, None], target, trial)
        done[rows] = exact
    raise ElasticError(f"load sharing: no equilibrium within {iterations} Newton steps; check that every member is "
                       "held (supports, torque > 0) and that the errors are micrometres, not millimetres.")
