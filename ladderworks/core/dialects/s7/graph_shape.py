"""A network of the S7 graph as a comparable shape: what it means, not how a reader numbered it.

Two networks have the same shape when their parts (in order, `O` parts left out) and their
connections are the same: every input pin is fed by the same set of sources once the `O` parts
are expanded (an OR of OR is one OR), operands compared by kind, path, constant text and type.
Lines, uids and the order of wires do not count. Used to tell a changed network (sd_save.py)
and by the writers' round-trip tests.
"""

from __future__ import annotations

from ladderworks.core.dialects.s7.graph import End, Operand, OperandKind, Part, S7Network

Shape = tuple[object, ...]


def _operand(operand: Operand) -> tuple[object, ...]:
    text = operand.text if operand.kind is OperandKind.CONSTANT else ""
    path = tuple(p.lower() for p in operand.path) if operand.kind in (
        OperandKind.GLOBAL, OperandKind.LOCAL) else operand.path
    return (operand.kind.value, path, text, operand.type_name.lower())


def _part(part: Part) -> tuple[object, ...]:
    instance = _operand(part.instance) if part.instance is not None else None
    return (part.name, tuple(sorted(part.negated)), instance, tuple(sorted(part.template.items())),
            part.call.lower(), part.call_kind, part.label, part.dests)


def shape(network: S7Network) -> Shape:
    """The network's meaning as a hashable tuple (see the module's docstring)."""
    ors = {p.uid for p in network.parts if p.name == "O"}
    order = {p.uid: n for n, p in enumerate(p for p in network.parts if p.uid not in ors)}
    feeding: dict[tuple[str, str], list[End]] = {}
    for wire in network.wires:
        for target in wire.targets:
            feeding.setdefault((target.part, target.pin), []).append(wire.source)

    def key(end: End) -> tuple[object, ...]:
        if end.powerrail:
            return ("rail",)
        if end.operand is not None:
            return ("operand", _operand(end.operand))
        return ("pin", order.get(end.part, -1), end.pin)

    def sources(end: End, seen: frozenset[str]) -> frozenset[tuple[object, ...]]:
        if end.part in ors and not end.powerrail and end.operand is None:
            if end.part in seen:
                return frozenset()
            found: frozenset[tuple[object, ...]] = frozenset()
            for (uid, _pin), ends in feeding.items():
                if uid == end.part:
                    for inner in ends:
                        found |= sources(inner, seen | {end.part})
            return found
        return frozenset({key(end)})

    connections: set[tuple[object, ...]] = set()
    for wire in network.wires:
        for target in wire.targets:
            if target.part in ors:
                continue
            origin = sources(wire.source, frozenset())
            connections.add((key(target), tuple(sorted(origin, key=repr))))
    parts = tuple(_part(p) for p in network.parts if p.uid not in ors)
    return (network.title, network.comment, network.language.upper(), network.source.strip(),
            parts, tuple(sorted(connections, key=repr)))
