"""Exploration: every combination of shift elements that gives a one-DOF drive.

For a train with m clutches and brakes there are 2^m shift states.  Each is
tested by linear algebra on the Willis rows alone (no statics): with L the
rows of the planetary sets and stages and E_k one row per engaged element,
the state is a drive between input and output exactly when

* rank [L; E] = n − 1 (one degree of freedom, n moving shafts), and
* rank [L; E; e_in] = n (the input speed fixes every shaft), and
* the output does not stand still.

The ratio i = n_in/n_out follows from one solve.  A state whose rows are not
independent is *redundant* (an element can be released without changing the
drive); such states are listed only on request.  4 sets and 6 elements
(64 states) take a few milliseconds (benchmarks/bench_transmission.py).

References
----------
Queitsch part 1, eq. 12 (Willis) and the Getriebefreiheitsgrad F.
"""

from __future__ import annotations

import html
import itertools
import time
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from ..model.train import GearTrain
from ..solver.assembly import matrices
from ..text import markdown_text
from .errors import ShiftScheduleError
from .results import RATIO_TOLERANCE, classify

__all__ = ["Combination", "Exploration", "explore"]


@dataclass(frozen=True)
class Combination:
    """One shift state that drives the output from the input.

    Attributes
    ----------
    engaged : tuple of str
    ratio : float
        n_in / n_out.
    kind : str
        reverse, direct, overdrive or reduction.
    gear : str or None
        The schedule's gear with this state, if any.
    redundant : bool
        An engaged element could be released without changing the drive.
    duplicates : tuple of tuple of str
        Other states with the same ratio.
    """

    engaged: tuple[str, ...]
    ratio: float
    kind: str
    gear: str | None = None
    redundant: bool = False
    duplicates: tuple[tuple[str, ...], ...] = ()

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data of one shift state: engaged elements, ratio n_in/n_out, kind, gear, duplicates.

        Returns
        -------
        dict
            ``engaged``, ``ratio``, ``kind`` (reverse, direct, overdrive, reduction), ``gear``
            (or ``None``), ``redundant`` and ``duplicates``.
        """
        return {"engaged": list(self.engaged), "ratio": self.ratio, "kind": self.kind, "gear": self.gear,
                "redundant": self.redundant, "duplicates": [list(d) for d in self.duplicates]}


@dataclass(frozen=True)
class Exploration:
    """All one-DOF drives of a train between input and output.

    Attributes
    ----------
    name, input, output : str
    elements : tuple of str
        The shift elements explored.
    combinations : tuple of Combination
        Forward gears by falling ratio, then reverse gears.
    states : int
        Shift states tested (2^m).
    held : int
        States with one DOF in which the output stands still.
    seconds : float
        Wall time of the exploration.
    """

    name: str
    input: str
    output: str
    elements: tuple[str, ...]
    combinations: tuple[Combination, ...]
    states: int
    held: int
    seconds: float

    def __len__(self) -> int:
        return len(self.combinations)

    @property
    def distinct_ratios(self) -> tuple[float, ...]:
        """The different ratios reachable (duplicates merged), same order."""
        out: list[float] = []
        for c in self.combinations:
            if not any(abs(c.ratio - r) <= RATIO_TOLERANCE * max(1.0, abs(r)) for r in out):
                out.append(c.ratio)
        return tuple(out)

    def find(self, engaged: Sequence[str]) -> Combination | None:
        """The combination with exactly these engaged elements, or None."""
        key = frozenset(engaged)
        return next((c for c in self.combinations if frozenset(c.engaged) == key), None)

    HEADER = ("engaged", "ratio", "kind", "gear", "same ratio as")

    def _rows(self) -> list[list[str]]:
        return [["+".join(c.engaged) or "—", f"{c.ratio:.4f}", c.kind + (" (redundant)" if c.redundant else ""),
                 c.gear or "", "; ".join("+".join(d) for d in c.duplicates)] for c in self.combinations]

    def _footer(self) -> str:
        return (f"{len(self.combinations)} drives ({len(self.distinct_ratios)} distinct ratios) among "
                f"{self.states} shift states of {len(self.elements)} elements; {self.held} hold the output; "
                f"{self.seconds * 1e3:.1f} ms")

    def table(self) -> str:
        """Every driving shift state as a plain-text table (engaged, ratio, kind, gear, same ratio as).

        A footer counts the drives, distinct ratios, states tried, states that hold the
        output and the time taken.

        Returns
        -------
        str
        """
        rows = [list(self.HEADER)] + self._rows()
        widths = [max(len(r[k]) for r in rows) for k in range(len(self.HEADER))]
        lines = [f"{self.name}: drives from {self.input!r} to {self.output!r}"]
        for k, r in enumerate(rows):
            lines.append("  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip())
            if k == 0:
                lines.append("  ".join("-" * w for w in widths))
        lines.append(self._footer())
        return "\n".join(lines)

    def markdown(self) -> str:
        """:meth:`table` as a Markdown table (cells escaped), footer below.

        Returns
        -------
        str
        """
        lines = ["| " + " | ".join(self.HEADER) + " |", "|" + "---|" * len(self.HEADER)]
        lines += ["| " + " | ".join(markdown_text(c) for c in r) + " |" for r in self._rows()]
        return "\n".join(lines + ["", markdown_text(self._footer())])

    def _repr_html_(self) -> str:
        head = "".join(f"<th>{html.escape(h)}</th>" for h in self.HEADER)
        body = "".join("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>" for r in self._rows())
        return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table><p>{html.escape(self._footer())}</p>"

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data: the train, input, output, shift elements, states tried and every combination.

        Returns
        -------
        dict
            ``name``, ``input``, ``output``, ``elements``, ``states``, ``held`` and
            ``combinations`` (:meth:`Combination.to_dict` of each).
        """
        return {"name": self.name, "input": self.input, "output": self.output, "elements": list(self.elements),
                "states": self.states, "held": self.held,
                "combinations": [c.to_dict() for c in self.combinations]}

    def __str__(self) -> str:
        return self.table()

    def __repr__(self) -> str:
        return (f"<Exploration {self.name!r}: {len(self.combinations)} drives, "
                f"{len(self.distinct_ratios)} distinct ratios from {self.states} states>")


class Scheduled(Protocol):
    """What :func:`explore` reads of a :class:`~epicyclic.transmission.Transmission`."""

    train: GearTrain
    input: str
    output: str
    name: str
    schedule: Any


#: Singular values below this fraction of the largest count as zero (unscaled kinematic rows: ratios of
#: real transmissions are within a few decades of 1, and the search tries up to 2^20 states).
_RANK_TOLERANCE = 1e-10


def _rank(matrix: np.ndarray) -> int:
    if matrix.shape[0] == 0:
        return 0
    s = np.linalg.svd(matrix, compute_uv=False)
    return int(np.sum(s > _RANK_TOLERANCE * max(s[0], 1e-300))) if s.size and s[0] > 0 else 0


def explore(
    transmission: Scheduled | GearTrain,
    input: str | None = None,
    output: str | None = None,
    *,
    elements: Sequence[str] | None = None,
    include_redundant: bool = False,
) -> Exploration:
    """Every combination of engaged shift elements that drives ``output`` from ``input``.

    Parameters
    ----------
    transmission : Transmission or GearTrain
        With a Transmission, input and output default to its own and the
        schedule's gear names are attached to the states they use.
    input, output : str, optional
        Required with a bare GearTrain.
    elements : sequence of str, optional
        The clutches and brakes to combine (default: all of the train's).
    include_redundant : bool, default False
        Also list states with more engaged elements than needed.

    Returns
    -------
    Exploration

    Raises
    ------
    ShiftScheduleError
        Unknown shafts or elements, or more than 20 elements (2^20 states).

    Examples
    --------
    >>> from epicyclic.transmission.library import build
    >>> ex = explore(build("simpson_c4"))
    >>> [(c.gear, round(c.ratio, 4)) for c in ex.combinations if c.gear]
    [('1', 2.4583), ('2', 1.4583), ('3', 1.0), ('R', -2.1818)]
    """
    start = time.perf_counter()
    schedule: dict[frozenset, str] = {}
    if not isinstance(transmission, GearTrain) and isinstance(getattr(transmission, "train", None), GearTrain):
        train = transmission.train
        input = input or transmission.input
        output = output or transmission.output
        name = transmission.name
        schedule = {frozenset(v): g for g, v in transmission.schedule.items()}
    elif isinstance(transmission, GearTrain):
        train = transmission
        name = train.name
        if input is None or output is None:
            raise ShiftScheduleError("explore: give input and output shafts with a bare GearTrain.")
    else:
        raise ShiftScheduleError(f"explore: expected a Transmission or GearTrain, got {type(transmission).__name__}.")
    for role, shaft in (("input", input), ("output", output)):
        if shaft not in train.moving_shafts:
            raise ShiftScheduleError(
                f"explore: {role} must be a moving shaft of the train, got {shaft!r}; shafts are "
                f"{', '.join(repr(s) for s in train.moving_shafts)}."
            )
    if input == output:
        raise ShiftScheduleError(f"explore: input and output must differ, got {input!r} twice.")
    shift = [e.name for e in train.shift_elements]
    chosen = list(shift if elements is None else elements)
    unknown = [n for n in chosen if n not in shift]
    if unknown:
        raise ShiftScheduleError(
            f"explore: {', '.join(repr(n) for n in unknown)} is not a clutch or brake of the train; "
            f"shift elements are {', '.join(repr(n) for n in shift) or 'none'}."
        )
    if len(chosen) > 20:
        raise ShiftScheduleError(f"explore: {len(chosen)} elements give 2^{len(chosen)} states; give at most 20.")

    # rows of every element once: all chosen engaged, the others open
    mats = matrices(train.with_engaged(chosen), [input, output])
    k = mats.kinematics
    nlev = len(mats.levers)
    base = k[:nlev]
    link_row = {link.element.name: k[nlev + j] for j, link in enumerate(mats.links)}
    n = k.shape[1]
    col = mats.speed_index
    e_in = np.zeros(n)
    e_in[col[input]] = 1.0
    out_col = col[output]
    base_rank = _rank(base)
    needed = n - 1 - base_rank

    found: list[Combination] = []
    held = 0
    sizes = range(0, len(chosen) + 1) if include_redundant else [needed] if 0 <= needed <= len(chosen) else []
    for size in sizes:
        for combo in itertools.combinations(chosen, size):
            rows = np.vstack([base] + [link_row[c][None, :] for c in combo]) if combo else base
            rank = _rank(rows)
            if rank != n - 1:
                continue
            a = np.vstack([rows, e_in])
            if _rank(a) != n:
                continue
            rhs = np.zeros(a.shape[0])
            rhs[-1] = 1.0
            speeds, *_ = np.linalg.lstsq(a, rhs, rcond=None)
            n_out = speeds[out_col]
            if abs(n_out) < 1e-12:
                held += 1
                continue
            ratio = float(1.0 / n_out)
            found.append(Combination(combo, ratio, classify(ratio), schedule.get(frozenset(combo)),
                                     redundant=rows.shape[0] > rank))
    total_states = 2 ** len(chosen)  # states of other sizes cannot have exactly one DOF without redundancy
    # duplicates
    with_dups = []
    for c in found:
        same = tuple(d.engaged for d in found
                     if d is not c and abs(d.ratio - c.ratio) <= 1e-9 * max(1.0, abs(c.ratio)))
        with_dups.append(Combination(c.engaged, c.ratio, c.kind, c.gear, c.redundant, same))
    with_dups.sort(key=lambda c: (c.ratio < 0, -abs(c.ratio) if c.ratio > 0 else abs(c.ratio), len(c.engaged)))
    return Exploration(name, input, output, tuple(chosen), tuple(with_dups), total_states, held,
                       time.perf_counter() - start)


