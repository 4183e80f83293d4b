"""The grid as a graph for decompose.py: elements as edges between nets, the nets a set of
nets reaches, series/parallel reduction to a block, and loops."""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass

from ladderworks.core.ladder.logic import Logic, Parallel, first_cell, parallel, series
from ladderworks.core.ladder.model import Cell


@dataclass(slots=True)
class Edge:
    """A contact (or a reduced block) between two nets, power flowing src → dst."""

    src: int
    dst: int
    logic: Logic
    cell: Cell


def reach(start: set[int], edges: list[Edge], forward: bool) -> set[int]:
    """The nets reached from `start` along the edges (forward: src → dst, else back)."""
    seen = set(start)
    todo = list(start)
    nxt: dict[int, list[int]] = defaultdict(list)
    for e in edges:
        a, b = (e.src, e.dst) if forward else (e.dst, e.src)
        nxt[a].append(b)
    while todo:
        n = todo.pop()
        for m in nxt[n]:
            if m not in seen:
                seen.add(m)
                todo.append(m)
    return seen


def joined(a: int, goal: set[int], edges: list[Edge], skip: Edge) -> bool:
    """True when net `a` reaches `goal` through other elements in either direction."""
    others = [e for e in edges if e is not skip]
    both = others + [Edge(e.dst, e.src, e.logic, e.cell) for e in others]
    return bool(reach({a}, both, True) & goal)


def reduce_block(edges: list[Edge], left: int, target: int) -> Logic | Edge:
    """Series/parallel reduction between the rail and a target net; returns the block, or an
    element of what is left when the circuit is not series/parallel (a bridge)."""
    edges = list(edges)
    changed = True
    while changed and edges:
        changed = False
        groups: dict[tuple[int, int], list[Edge]] = defaultdict(list)
        for e in edges:
            groups[(e.src, e.dst)].append(e)
        for (src, dst), group in groups.items():
            if len(group) > 1:
                logic = group[0].logic
                for e in group[1:]:
                    logic = parallel(logic, e.logic)
                assert isinstance(logic, Parallel)
                logic = Parallel(tuple(sorted(logic.items, key=first_cell)))
                cell = min(e.cell for e in group)
                edges = [e for e in edges if e not in group] + [Edge(src, dst, logic, cell)]
                changed = True
        ins: dict[int, list[Edge]] = defaultdict(list)
        outs: dict[int, list[Edge]] = defaultdict(list)
        for e in edges:
            ins[e.dst].append(e)
            outs[e.src].append(e)
        for n in list(ins):
            if n in (left, target) or len(ins[n]) != 1 or len(outs[n]) != 1:
                continue
            a, b = ins[n][0], outs[n][0]
            if a is b or a not in edges or b not in edges:
                continue
            edges = [e for e in edges if e is not a and e is not b]
            edges.append(Edge(a.src, b.dst, series(a.logic, b.logic), min(a.cell, b.cell)))
            changed = True
    if len(edges) == 1 and edges[0].src == left and edges[0].dst == target:
        return edges[0].logic
    inner = [e for e in edges if e.src not in (left, target) and e.dst not in (left, target)]
    return min(inner or edges, key=lambda e: e.cell)


def cycle_edge(edges: list[Edge]) -> Edge | None:
    """An element on a loop (power would have to flow back to the left), or None."""
    outs: dict[int, list[Edge]] = defaultdict(list)
    for e in edges:
        outs[e.src].append(e)
    state: dict[int, int] = {}

    def visit(n: int) -> Edge | None:
        state[n] = 1
        for e in outs[n]:
            if state.get(e.dst) == 1:
                return e
            if e.dst not in state:
                found = visit(e.dst)
                if found is not None:
                    return found
        state[n] = 2
        return None

    for e in sorted(edges, key=lambda e: e.cell):
        if e.src not in state:
            found = visit(e.src)
            if found is not None:
                return found
    return None
