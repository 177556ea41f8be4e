"""A layered (Sugiyama-style) drawing of a small directed graph: drives left, loads right.

The steps of Sugiyama, Tagawa and Toda (1981), for the few dozen nodes of a
power-flow graph:

1. **Cycles** (power circulating around a closed loop) are broken by a depth-
   first search from the sources; the edges that close a loop are laid out
   reversed and drawn back against the flow.
2. **Layers** by longest path from the sources; the nodes named ``last``
   (the loads) share the last layer; an edge spanning several layers gets a
   dummy node in each layer between, so that it is routed around the nodes.
3. **Order** within the layers: barycentre sweeps down and up, then every
   layer of up to :data:`EXHAUSTIVE` nodes is permuted exhaustively against
   its neighbours while that lowers the number of crossings; this is done
   from several starting orders (as given, reversed, fixed shuffles) and the
   order with the fewest crossings is kept.
4. **Coordinates**: layers at equal distances in x; in y every node sits near
   the mean of its neighbours, never closer to the next node than the two
   nodes' heights require.

References
----------
Sugiyama, K.; Tagawa, S.; Toda, M.: Methods for visual understanding of
hierarchical system structures.  IEEE Trans. SMC 11 (1981) 109–125.
"""

from __future__ import annotations

from collections.abc import Hashable, Mapping, Sequence
from dataclasses import dataclass
from itertools import permutations

__all__ = ["Layout", "layered_layout", "count_crossings", "EXHAUSTIVE"]

#: Layers up to this many nodes are ordered by trying every permutation.
EXHAUSTIVE = 6


@dataclass(frozen=True)
class Layout:
    """Positions of the nodes and routes of the edges.

    Attributes
    ----------
    x, y : mapping node → float
    routes : tuple of list of (x, y)
        One polyline per edge (in the order given), from its source to its
        target, through the dummy nodes of the layers it spans.
    reversed : frozenset of int
        Indices of edges that close a loop (drawn against the layer direction).
    crossings : int
        Crossings between the edge segments of adjacent layers.
    layers : tuple of tuple
        Node order per layer (dummies included, as ``("dummy", edge, k)``).
    links : tuple of (node, node)
        The segments between adjacent layers that the crossings are counted on.
    """

    x: Mapping[Hashable, float]
    y: Mapping[Hashable, float]
    routes: tuple[list[tuple[float, float]], ...]
    reversed: frozenset[int]
    crossings: int
    layers: tuple[tuple[Hashable, ...], ...]
    links: tuple[tuple[Hashable, Hashable], ...] = ()


def _break_cycles(nodes: Sequence[Hashable], edges: Sequence[tuple[Hashable, Hashable]],
                  sources: Sequence[Hashable]) -> set[int]:
    """Indices of edges that close a cycle in a depth-first search from the sources."""
    out: dict[Hashable, list[int]] = {n: [] for n in nodes}
    for k, (a, _) in enumerate(edges):
        out[a].append(k)
    state: dict[Hashable, int] = {}  # 1 on the stack, 2 done
    back: set[int] = set()
    for root in [*sources, *nodes]:
        if root in state:
            continue
        stack = [(root, iter(out[root]))]
        state[root] = 1
        while stack:
            node, it = stack[-1]
            k = next(it, None)
            if k is None:
                state[node] = 2
                stack.pop()
                continue
            target = edges[k][1]
            if state.get(target) == 1:
                back.add(k)
            elif target not in state:
                state[target] = 1
                stack.append((target, iter(out[target])))
    return back


def _layers(nodes: Sequence[Hashable], dag: Sequence[tuple[Hashable, Hashable]], last: set[Hashable]
            ) -> dict[Hashable, int]:
    layer = {n: 0 for n in nodes}
    for _ in range(len(nodes)):  # longest path by relaxation (the graph is a DAG)
        changed = False
        for a, b in dag:
            if layer[b] < layer[a] + 1:
                layer[b] = layer[a] + 1
                changed = True
        if not changed:
            break
    top = max((layer[n] for n in nodes if n not in last), default=-1) + 1
    for n in last:
        layer[n] = max(top, layer[n])
    end = max(layer.values(), default=0)
    for n in last:
        layer[n] = end
    return layer


def count_crossings(upper: Sequence[Hashable], lower: Sequence[Hashable],
                    links: Sequence[tuple[Hashable, Hashable]]) -> int:
    """Crossings of straight segments between two ordered layers."""
    pu = {n: k for k, n in enumerate(upper)}
    pl = {n: k for k, n in enumerate(lower)}
    segs = [(pu[a], pl[b]) for a, b in links if a in pu and b in pl]
    return sum(1 for i, (a1, b1) in enumerate(segs) for a2, b2 in segs[i + 1:] if (a1 - a2) * (b1 - b2) < 0)


def layered_layout(nodes: Sequence[Hashable], edges: Sequence[tuple[Hashable, Hashable]], *,
                   first: Sequence[Hashable] = (), last: Sequence[Hashable] = (),
                   heights: Mapping[Hashable, float] | None = None, dx: float = 2.0, gap: float = 0.35
                   ) -> Layout:
    """Lay out a directed graph in layers from ``first`` (left) to ``last`` (right).

    Parameters
    ----------
    nodes, edges : sequences
        Edges as (source, target); parallel edges allowed.
    first, last : sequences of nodes
        Sources start at layer 0; ``last`` nodes share the last layer.
    heights : mapping node → float
        Vertical size of each node (data units, default 0.5; dummies 0.1).
    dx, gap : float
        Distance between layers; clearance between two nodes of a layer.

    Examples
    --------
    >>> lay = layered_layout(["a", "b", "c"], [("a", "b"), ("b", "c"), ("c", "b")], first=["a"])
    >>> sorted(lay.x.items()), sorted(lay.reversed)
    ([('a', 0.0), ('b', 2.0), ('c', 4.0)], [2])
    """
    heights = dict(heights or {})
    back = _break_cycles(nodes, edges, first)
    dag = [(b, a) if k in back else (a, b) for k, (a, b) in enumerate(edges)]
    layer = _layers(nodes, [e for e in dag if e[0] != e[1]], set(last))
    # dummy chains for edges spanning more than one layer
    chains: list[list[Hashable]] = []
    for k, (a, b) in enumerate(dag):
        chain: list[Hashable] = [a]
        for j in range(layer[a] + 1, layer[b]):
            dummy = ("dummy", k, j)
            layer[dummy] = j
            heights[dummy] = 0.1
            chain.append(dummy)
        chain.append(b)
        chains.append(chain)
    links = [(u, v) for chain in chains for u, v in zip(chain, chain[1:])]
    count = max(layer.values(), default=0) + 1
    order: list[list[Hashable]] = [[] for _ in range(count)]
    for n in [*nodes, *(d for c in chains for d in c[1:-1])]:
        order[layer[n]].append(n)

    best, order = min((_ordered(start, links) for start in _starts(order)), key=lambda found: found[0])
    y = _coordinates(order, links, heights, gap)
    x = {n: dx * layer[n] for n in layer}
    routes = []
    for k, chain in enumerate(chains):
        points = [(x[n], y[n]) for n in chain]
        routes.append(points[::-1] if k in back else points)
    real = set(nodes)
    return Layout({n: x[n] for n in real}, {n: y[n] for n in real}, tuple(routes), frozenset(back), best,
                  tuple(tuple(layer_nodes) for layer_nodes in order), tuple(links))


def _starts(order: list[list[Hashable]], shuffles: int = 12) -> list[list[list[Hashable]]]:
    """Initial orders for the crossing reduction: as given, reversed, and a few fixed shuffles."""
    import random

    starts = [[list(layer) for layer in order], [layer[::-1] for layer in order]]
    for seed in range(shuffles):
        rng = random.Random(seed)
        starts.append([rng.sample(layer, len(layer)) for layer in order])
    return starts


def _ordered(order: list[list[Hashable]], links: list[tuple[Hashable, Hashable]]) -> tuple[int, list[list[Hashable]]]:
    """Barycentre sweeps, then exhaustive per-layer permutations while they lower the crossing count."""
    count = len(order)

    def crossings() -> int:
        return sum(count_crossings(order[j], order[j + 1], links) for j in range(count - 1))

    def neighbours(n: Hashable, side: int) -> list[Hashable]:
        return [u for u, v in links if v == n] if side < 0 else [v for u, v in links if u == n]

    def sweep(j: int, side: int) -> None:
        ref = {n: k for k, n in enumerate(order[j + side])}
        here = {n: k for k, n in enumerate(order[j])}

        def key(n: Hashable) -> float:
            near = [ref[m] for m in neighbours(n, side) if m in ref]
            return sum(near) / len(near) if near else here[n]

        order[j].sort(key=key)

    for _ in range(6):
        for j in range(1, count):
            sweep(j, -1)
        for j in range(count - 2, -1, -1):
            sweep(j, +1)
    best = crossings()
    improved = True
    while improved and best:
        improved = False
        for j in range(count):
            if len(order[j]) > EXHAUSTIVE or len(order[j]) < 2:
                continue
            keep = order[j]
            for perm in permutations(keep):
                order[j] = list(perm)
                value = crossings()
                if value < best:
                    best, keep, improved = value, list(perm), True
            order[j] = keep
    return best, order


def _coordinates(order: list[list[Hashable]], links: list[tuple[Hashable, Hashable]],
                 heights: Mapping[Hashable, float], gap: float) -> dict[Hashable, float]:
    """y of every node: stacked per layer, then pulled towards its neighbours (order and clearance kept)."""
    def size(n: Hashable) -> float:
        return heights.get(n, 0.5)

    y: dict[Hashable, float] = {}
    for nodes in order:
        total = sum(size(n) for n in nodes) + gap * (len(nodes) - 1)
        top = total / 2
        for n in nodes:
            y[n] = top - size(n) / 2
            top -= size(n) + gap
    for _ in range(8):
        for nodes in order:
            wanted = []
            for n in nodes:
                near = [y[v] for u, v in links if u == n] + [y[u] for u, v in links if v == n]
                wanted.append(sum(near) / len(near) if near else y[n])
            # place top to bottom as near to the wish as the clearance allows, then re-centre on the wishes
            placed = []
            for k, n in enumerate(nodes):
                target = wanted[k]
                if placed:
                    prev_n, prev_y = nodes[k - 1], placed[-1]
                    target = min(target, prev_y - (size(prev_n) + size(n)) / 2 - gap)
                placed.append(target)
            shift = (sum(wanted) - sum(placed)) / len(nodes)
            for n, value in zip(nodes, placed):
                y[n] = value + shift
    return y
