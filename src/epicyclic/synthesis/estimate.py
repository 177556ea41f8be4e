"""The size of a search before it runs: mechanisms, architectures, worker time, and its bound.

Two figures, both stated before any work is done:

* :func:`estimate` — instant, from counting formulas only (nothing enumerated).
  The labelled tie patterns of S sets on m shafts (no shaft holding two members
  of one set, at most ``cap`` members per shaft) are counted exactly by a
  dynamic programme over the sets; divided by the order of the symmetry group
  (S! for sets of one kind) that is the number of mechanisms up to isomorphism
  for all but the few patterns with symmetries (Burnside's lemma: orbits ≥
  elements / group order).  Each mechanism with N shafts has at most
  P·C(N − 2, b)·C(N(N − 1)/2, c) architectures (P input/output pairs, b brakes
  off the input and output shafts, c clutches between pairs of shafts); where
  input or output must hold given members, P is scaled by the expected share
  of shafts that do.
* :func:`count` — after the mechanisms are enumerated (:func:`~epicyclic.synthesis.search.plan`):
  the same bound per mechanism, summed exactly.

A search whose architectures exceed ``[search] max_architectures`` is refused
before it starts (:func:`check`), naming the keys that narrow it.  Worker time
is the architecture count over the measured screening rate
(:data:`SCREENING_RATE`, docs/performance.md).

References
----------
Tsai, L.-W. (2001), *Mechanism Design: Enumeration of Kinematic Structures According to
Function*, ch. 9 (counting epicyclic structures up to isomorphism); Burnside's lemma
(e.g. Harary & Palmer 1973, *Graphical Enumeration*, ch. 2).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Iterable
from dataclasses import dataclass

from .spec import SynthesisError, SynthesisSpec

__all__ = ["SCREENING_RATE", "SearchEstimate", "duration", "labelled_patterns", "architectures_per_mechanism", "estimate",
           "count", "check"]

#: Architectures screened per second per worker, measured (docs/performance.md, bench_synthesis.py).
SCREENING_RATE = 1.0e6


@dataclass(frozen=True)
class SearchEstimate:
    """How big a search is: mechanisms, architectures, worker-seconds at :data:`SCREENING_RATE`.

    Attributes
    ----------
    mechanisms : int
        Tie patterns up to isomorphism (estimated, or counted when ``exact``).
    architectures : int
        Input, output and element placements on them (an upper bound per mechanism).
    exact : bool
        The mechanisms were enumerated (:func:`count`), not estimated (:func:`estimate`).
    rate : float
        Architectures per second per worker assumed.
    """

    mechanisms: int
    architectures: int
    exact: bool
    rate: float = SCREENING_RATE

    @property
    def worker_seconds(self) -> float:
        """Screening time on one worker, s."""
        return self.architectures / self.rate

    def describe(self, workers: int | None = None) -> str:
        """One line: ``≤ 1.3e8 architectures on 915 mechanisms, about 2.2 min on one worker``.

        Parameters
        ----------
        workers : int, optional
            Also give the wall time on this many workers.
        """
        what = "at most" if self.exact else "about"
        time = duration(self.worker_seconds)
        time = time if time.startswith("under") else f"{what} {time}"  # not "at most under 1 s"
        text = (f"{what} {self.architectures:.3g} architectures on {self.mechanisms:,} mechanisms"
                f"{'' if self.exact else ' (estimated)'}, {time} of screening on one worker")
        if workers and workers > 1:
            text += f", {duration(self.worker_seconds / workers)} on {workers}"
        return text

    def to_dict(self) -> dict:
        """JSON-ready: mechanisms, architectures, exact, rate (per s per worker), worker_seconds."""
        return {"mechanisms": self.mechanisms, "architectures": self.architectures, "exact": self.exact,
                "rate_per_worker_per_second": self.rate, "worker_seconds": self.worker_seconds}


def duration(seconds: float) -> str:
    """A time in words for estimates and progress: ``under 1 s``, ``42 s``, ``12 min``, ``3.5 h``.

    Parameters
    ----------
    seconds : float
    """
    if seconds < 1:
        return "under 1 s"
    if seconds < 90:
        return f"{seconds:.0f} s"
    if seconds < 5400:
        return f"{seconds / 60:.0f} min"
    return f"{seconds / 3600:.3g} h"


@functools.lru_cache(maxsize=256)
def labelled_patterns(sets: int, shafts: int, cap: int | None = None) -> int:
    """Partitions of the 3·S members of S sets into exactly ``shafts`` shafts, none holding two members of one
    set nor more than ``cap`` members (labelled: sets not permuted).

    Parameters
    ----------
    sets : int
        S.
    shafts : int
        Shafts made of members.
    cap : int, optional
        Most members per shaft (default: S, i.e. no limit beyond one per set).

    Examples
    --------
    >>> labelled_patterns(1, 3), labelled_patterns(2, 4), labelled_patterns(2, 3)
    (1, 18, 6)
    """
    cap = sets if cap is None else min(cap, sets)
    # state: number of shafts holding 1, 2, ..., cap members; each set adds its three distinct members,
    # each to a different existing shaft with room or to a new shaft
    states: dict[tuple[int, ...], int] = {tuple([0] * cap): 1}
    for _ in range(sets):
        nxt: dict[tuple[int, ...], int] = {}
        for state, ways in states.items():
            for new_state, factor in _place_three(state, cap):
                nxt[new_state] = nxt.get(new_state, 0) + ways * factor
        states = nxt
    return sum(w for s, w in states.items() if sum(s) == shafts)


def _place_three(state: tuple[int, ...], cap: int) -> Iterable[tuple[tuple[int, ...], int]]:
    """Ways to add the three members of one set: each joins a distinct shaft (of size < cap) or a new one."""
    def rec(member: int, counts: list[int], taken: list[int], factor: int):
        if member == 3:
            yield tuple(counts), factor
            return
        counts[0] += 1  # a new shaft of one member (new shafts are told apart by their member)
        taken[0] += 1
        yield from rec(member + 1, counts, taken, factor)
        counts[0] -= 1
        taken[0] -= 1
        for size in range(1, cap):  # join an existing shaft of `size` members not yet touched by this set
            free = counts[size - 1] - taken[size - 1]
            if free <= 0:
                continue
            counts[size - 1] -= 1
            counts[size] += 1
            taken[size] += 1
            yield from rec(member + 1, counts, taken, factor * free)
            taken[size] -= 1
            counts[size] += -1
            counts[size - 1] += 1

    # `taken` counts shafts already touched by this set, per size class after the move
    yield from rec(0, list(state), [0] * cap, 1)


def architectures_per_mechanism(shafts: int, free_input: bool, brakes: int, clutches: int,
                                input_share: float = 1.0, output_share: float = 1.0) -> int:
    """Architectures on one mechanism with ``shafts`` shafts (the free input included).

    Input/output pairs: N − 1 with a separate input (it is the input), N(N − 1) ordered ones otherwise,
    times the shares of shafts that may be input and output; brakes on the N − 2 other shafts;
    clutches between any two shafts.

    Parameters
    ----------
    shafts : int
    free_input : bool
    brakes, clutches : int
    input_share, output_share : float, default 1
        Expected share of member shafts allowed as input / output (1: an upper bound).

    >>> architectures_per_mechanism(4, False, 2, 2)   # 12 pairs x C(2, 2) x C(6, 2)
    180
    """
    members = shafts - int(free_input)
    pairs = members * output_share if free_input else shafts * (shafts - 1) * input_share * output_share
    return round(pairs * math.comb(shafts - 2, brakes) * math.comb(shafts * (shafts - 1) // 2, clutches))


def _share(kinds: tuple[str, ...], sets: int, member_shafts: int) -> float:
    """Expected share of member shafts holding one of ``kinds`` (members spread evenly over the shafts)."""
    if len(kinds) >= 3:
        return 1.0
    per_shaft = 3 * sets / member_shafts
    return 1.0 - (1.0 - len(kinds) / 3) ** per_shaft


def _group_order(spec: SynthesisSpec) -> int:
    return math.factorial(spec.simple) * math.factorial(spec.plus)


def estimate(spec: SynthesisSpec) -> SearchEstimate:
    """The size of the search from counting formulas alone (instant; nothing is enumerated).

    Parameters
    ----------
    spec : SynthesisSpec

    Returns
    -------
    SearchEstimate
        ``exact`` False.

    Examples
    --------
    >>> s = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2})
    >>> e = estimate(s)   # 1, 2 or 3 engaged: 9 + 6 + 1 patterns on member shafts, 16 with a separate input
    >>> e.mechanisms, e.architectures
    (32, 54765)
    """
    sets = spec.simple + spec.plus
    mechanisms = architectures = 0
    for engaged in spec.engaged:
        for free in ((False, True) if spec.free_input else (False,)):
            shafts = engaged + 1 + sets  # degrees of freedom + sets
            member_shafts = shafts - int(free)
            if not 3 <= member_shafts <= 3 * sets:
                continue
            n = -(-labelled_patterns(sets, member_shafts, spec.max_members_per_shaft) // _group_order(spec))
            mechanisms += n
            architectures += n * architectures_per_mechanism(
                shafts, free, spec.brakes, spec.clutches, _share(spec.input_members, sets, member_shafts),
                _share(spec.output_members, sets, member_shafts))
    return SearchEstimate(mechanisms, architectures, False)


def count(spec: SynthesisSpec, mechanisms: Iterable) -> SearchEstimate:
    """The bound summed over enumerated mechanisms (``exact`` True).

    Parameters
    ----------
    spec : SynthesisSpec
    mechanisms : iterable of Mechanism
        Those the search will screen.
    """
    total = number = 0
    for m in mechanisms:
        number += 1
        total += _pairs(m, spec) * math.comb(m.shafts - 2, spec.brakes) * math.comb(m.shafts * (m.shafts - 1) // 2,
                                                                                    spec.clutches)
    return SearchEstimate(number, total, True)


def _pairs(mechanism, spec: SynthesisSpec) -> int:
    """Ordered input/output pairs the screening examines (input and output members as the spec allows)."""
    def holds(shaft: int, kinds: tuple[str, ...]) -> bool:
        return any(port in kinds for _, port in mechanism.shaft_members(shaft))

    shafts = range(mechanism.member_shafts)
    if mechanism.free_input:
        return sum(holds(y, spec.output_members) for y in shafts)
    return sum(holds(x, spec.input_members) and holds(y, spec.output_members) for x in shafts for y in shafts
               if x != y)


def check(spec: SynthesisSpec, size: SearchEstimate) -> None:
    """Refuse a search larger than ``spec.max_architectures`` (message names the keys that narrow it).

    Parameters
    ----------
    spec : SynthesisSpec
    size : SearchEstimate

    Raises
    ------
    SynthesisError
    """
    if size.architectures > spec.max_architectures:
        raise SynthesisError(
            f"{spec.source}: [search], key 'max_architectures': this search has {size.describe()}, more than the bound "
            f"of {spec.max_architectures:.3g}. Narrow it ([elements] engaged, [search] max_members_per_shaft, "
            "free_input = false, fewer sets or elements) or raise [search] max_architectures deliberately and "
            "run it on a cluster (--scheduler).")
