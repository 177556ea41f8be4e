"""Candidate mechanisms: planetary sets joined by permanent ties, up to isomorphism.

A *mechanism* is the gear train without its shift elements: S planetary sets
whose 3·S members (sun, ring, carrier of each set) are joined into shafts by
permanent ties.  It is stored as ``members``: for set k, the shaft numbers of
its sun, ring and carrier (``members[3k:3k+3]``).  Shafts are numbered by
first appearance.  An optional *free* shaft (the last number) belongs to no set:
a separate input shaft that reaches the sets only through clutches, as in the
Simpson three-speed.

Two mechanisms are the same (isomorphic) when a permutation of sets of the same
kind maps one onto the other: sun, ring and carrier are different members, so
those permutations are the whole symmetry group.  The canonical form is the
lexicographically smallest renumbered ``members`` over that group, computed
exactly (S! ≤ 720 permutations for S ≤ 6).

A mechanism is kept when

* no shaft joins two members of one set (that would lock the set),
* the sets form one connected train (otherwise it is two transmissions),
* every shaft is used (numbering is surjective), and
* optionally (``max_members_per_shaft``) no shaft joins more than that many members.

Its kinematic degrees of freedom are ``shafts − S`` (one Willis equation per
set, independent for distinct stationary ratios).

References
----------
Tsai, L.-W. (2001), *Mechanism Design: Enumeration of Kinematic Structures
According to Function*, ch. 9 (graph representation of epicyclic trains,
isomorphism); Kahraman, Ligata, Kienzle & Zini (2004), J. Mech. Des. 126(6),
1071–1081 (search over kinematic configurations); Queitsch, eq. 12 (Willis).
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator, Sequence
from dataclasses import dataclass

__all__ = ["Mechanism", "PORTS", "canonical_members", "enumerate_mechanisms", "count_mechanisms"]

#: Members of a set, in the order stored in ``Mechanism.members``.
PORTS = ("sun", "ring", "carrier")


@dataclass(frozen=True)
class Mechanism:
    """Planetary sets joined by permanent ties (canonical form).

    Attributes
    ----------
    kinds : tuple of str
        ``"simple"`` (minus set, i0 < 0) or ``"plus"`` (double-planet set, i0 > 0) per set.
    members : tuple of int
        Shaft number of sun, ring, carrier of every set (3·S entries).
    free_input : bool
        An extra shaft (number ``member_shafts``) that belongs to no set.
    """

    kinds: tuple[str, ...]
    members: tuple[int, ...]
    free_input: bool = False

    @property
    def sets(self) -> int:
        return len(self.kinds)

    @property
    def member_shafts(self) -> int:
        """Shafts made of set members."""
        return max(self.members) + 1

    @property
    def shafts(self) -> int:
        """All moving shafts (members and the free input)."""
        return self.member_shafts + int(self.free_input)

    @property
    def degrees_of_freedom(self) -> int:
        return self.shafts - self.sets

    def set_shafts(self, k: int) -> tuple[int, int, int]:
        """(sun, ring, carrier) shaft numbers of set ``k``."""
        return self.members[3 * k], self.members[3 * k + 1], self.members[3 * k + 2]

    def shaft_members(self, shaft: int) -> tuple[tuple[int, str], ...]:
        """(set, member) pairs joined in ``shaft`` (empty for the free input)."""
        return tuple((i // 3, PORTS[i % 3]) for i, s in enumerate(self.members) if s == shaft)

    def ties(self) -> tuple[tuple[tuple[int, str], ...], ...]:
        """Shafts that join two or more members (the permanent ties)."""
        return tuple(m for m in (self.shaft_members(s) for s in range(self.member_shafts)) if len(m) > 1)

    def describe(self) -> str:
        """Ties in words, e.g. ``S1=S2, C1=R4`` (sets numbered from 1)."""
        letters = {"sun": "S", "ring": "R", "carrier": "C"}
        parts = ["=".join(f"{letters[p]}{k + 1}" for k, p in tie) for tie in self.ties()]
        return ", ".join(parts) or "no ties"


def _renumber(seq: Sequence[int]) -> tuple[int, ...]:
    seen: dict[int, int] = {}
    return tuple(seen.setdefault(b, len(seen)) for b in seq)


def set_permutations(kinds: Sequence[str]) -> list[tuple[int, ...]]:
    """Permutations of set indices that keep each set's kind (the symmetry group)."""
    return [p for p in itertools.permutations(range(len(kinds))) if all(kinds[p[j]] == kinds[j] for j in range(len(kinds)))]


def canonical_members(members: Sequence[int], kinds: Sequence[str],
                      perms: Sequence[tuple[int, ...]] | None = None) -> tuple[int, ...]:
    """Smallest renumbered member tuple over all kind-preserving set permutations.

    >>> canonical_members((0, 1, 2, 0, 2, 3), ("simple", "simple"))  # Simpson: common sun, C1 = R2
    (0, 1, 2, 0, 2, 3)
    >>> canonical_members((0, 2, 3, 0, 1, 2), ("simple", "simple"))  # the same, sets swapped
    (0, 1, 2, 0, 2, 3)
    """
    perms = perms if perms is not None else set_permutations(kinds)
    return min(_renumber([members[3 * p[j] + q] for j in range(len(kinds)) for q in range(3)]) for p in perms)


def _connected(members: Sequence[int], sets: int) -> bool:
    parent = list(range(sets))

    def find(x: int) -> int:
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    owner: dict[int, int] = {}
    for i, shaft in enumerate(members):
        k = i // 3
        if shaft in owner:
            parent[find(k)] = find(owner[shaft])
        else:
            owner[shaft] = k
    return len({find(k) for k in range(sets)}) == 1


def _partitions(sets: int, shafts: int, max_members: int) -> Iterator[tuple[int, ...]]:
    """Restricted-growth numberings of the 3·S members into exactly ``shafts`` shafts."""
    total = 3 * sets
    labels = [0] * total
    sizes = [0] * total

    def rec(i: int, used: int) -> Iterator[tuple[int, ...]]:
        if used + (total - i) < shafts or used > shafts:
            return
        if i == total:
            if used == shafts:
                yield tuple(labels)
            return
        k = i // 3
        own = labels[3 * k:i]
        for b in range(min(used + 1, shafts)):
            if b < used and (b in own or sizes[b] >= max_members):
                continue
            labels[i] = b
            sizes[b] += 1
            yield from rec(i + 1, max(used, b + 1))
            sizes[b] -= 1

    yield from rec(0, 0)


def enumerate_mechanisms(kinds: Sequence[str], degrees_of_freedom: int, *, free_input: bool = False,
                         max_members_per_shaft: int | None = None) -> tuple[Mechanism, ...]:
    """Every non-isomorphic connected mechanism of these sets with the given freedom.

    Parameters
    ----------
    kinds : sequence of {"simple", "plus"}
        One entry per set.
    degrees_of_freedom : int
        Of the mechanism without shift elements (input shaft included).
    free_input : bool, default False
        Add a separate input shaft that belongs to no set.
    max_members_per_shaft : int, optional
        At most this many members per shaft (2: ties join pairs only).

    Returns
    -------
    tuple of Mechanism
        Sorted by canonical form.

    Examples
    --------
    >>> ms = enumerate_mechanisms(("simple", "simple"), 2)
    >>> len(ms), ms[0].describe()
    (12, 'S1=S2, R1=R2')
    """
    kinds = tuple(kinds)
    sets = len(kinds)
    member_shafts = degrees_of_freedom + sets - int(free_input)
    if member_shafts < 3 or member_shafts > 3 * sets:
        return ()
    perms = set_permutations(kinds)
    cap = max_members_per_shaft or sets
    found = set()
    for labels in _partitions(sets, member_shafts, cap):
        if _connected(labels, sets):
            found.add(canonical_members(labels, kinds, perms))
    return tuple(Mechanism(kinds, m, free_input) for m in sorted(found))


def count_mechanisms(kinds: Sequence[str], degrees_of_freedom: int, *, free_input: bool = False,
                     max_members_per_shaft: int | None = None) -> int:
    """Number of non-isomorphic mechanisms (see :func:`enumerate_mechanisms`)."""
    return len(enumerate_mechanisms(kinds, degrees_of_freedom, free_input=free_input,
                                    max_members_per_shaft=max_members_per_shaft))
