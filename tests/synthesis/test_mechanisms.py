"""Mechanism enumeration: canonical forms against an independent isomorphism test (networkx).

The canonical form (smallest renumbering over kind-preserving set permutations)
must give exactly one representative per isomorphism class of the member–shaft
graph.  The reference classes come from networkx's VF2 isomorphism test on a
bipartite graph (set nodes, shaft nodes, edges labelled sun/ring/carrier) —
an independent method (Tsai 2001, ch. 9: graph representation of epicyclic trains).
"""

from __future__ import annotations

import itertools

import networkx as nx
import pytest
from networkx.algorithms.isomorphism import categorical_edge_match, categorical_node_match

from epicyclic.synthesis.mechanisms import Mechanism, _connected, _partitions, canonical_members, enumerate_mechanisms


def _graph(members, kinds, free_input):
    g = nx.Graph()
    for k, kind in enumerate(kinds):
        g.add_node(("set", k), kind=kind)
    shafts = max(members) + 1
    for s in range(shafts + int(free_input)):
        g.add_node(("shaft", s), kind="shaft")
    for i, s in enumerate(members):
        g.add_edge(("set", i // 3), ("shaft", s), port=("sun", "ring", "carrier")[i % 3])
    return g


def _classes(kinds, dof, free_input=False, cap=None):
    sets = len(kinds)
    shafts = dof + sets - int(free_input)
    reps = []
    for labels in _partitions(sets, shafts, cap or sets):
        if not _connected(labels, sets):
            continue
        g = _graph(labels, kinds, free_input)
        if not any(nx.is_isomorphic(g, h, node_match=categorical_node_match("kind", None),
                                    edge_match=categorical_edge_match("port", None)) for h in reps):
            reps.append(g)
    return len(reps)


@pytest.mark.parametrize("kinds, dof, free_input, cap", [
    (("simple", "simple"), 2, False, None),
    (("simple", "simple"), 3, False, None),
    (("simple", "simple"), 3, True, None),
    (("simple", "plus"), 3, False, None),
    (("simple", "simple", "simple"), 3, False, 2),
    (("simple", "simple", "simple"), 4, False, None),
])
def test_one_representative_per_isomorphism_class(kinds, dof, free_input, cap):
    ours = enumerate_mechanisms(kinds, dof, free_input=free_input, max_members_per_shaft=cap)
    assert len(ours) == _classes(kinds, dof, free_input, cap)
    assert len({m.members for m in ours}) == len(ours)
    for m in ours:
        assert canonical_members(m.members, kinds) == m.members
        assert m.degrees_of_freedom == dof


def test_permuting_sets_gives_the_same_canonical_form():
    # ZF 8HP: S1=S2, C1=R4, R2=S3, R3=S4 (input C2, output C4)
    kinds = ("simple",) * 4
    base = (0, 1, 2, 0, 3, 4, 3, 5, 6, 5, 2, 7)
    forms = set()
    for perm in itertools.permutations(range(4)):
        forms.add(canonical_members([base[3 * perm[j] + q] for j in range(4) for q in range(3)], kinds))
    assert len(forms) == 1


def test_mechanism_properties():
    m = Mechanism(("simple", "simple"), (0, 1, 2, 0, 2, 3), free_input=True)  # Simpson
    assert (m.member_shafts, m.shafts, m.degrees_of_freedom) == (4, 5, 3)
    assert m.describe() == "S1=S2, C1=R2"
    assert m.shaft_members(4) == ()
    assert enumerate_mechanisms(("simple",), 5) == ()
