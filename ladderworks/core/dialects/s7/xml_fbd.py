"""An FBD network of the S7 graph redrawn as LAD where it maps (docs/dialects.md, "SimaticML
XML"): an operand on a power input becomes a contact (normally closed when negated), a negated
input fed by a box a `Not`, an `A` box a series of what feeds it, an unwired EN or a compare
without power input takes the rail. An `X` box, or an `A` input that cannot be put in series,
stays as it is (the lowering then names it as not simulated).
"""

from __future__ import annotations

import re

from ladderworks.core.dialects.s7.graph import End, Part, S7Network, Wire

_COILS = ("Coil", "SCoil", "RCoil", "PCoil", "NCoil")
_POWER: dict[str, tuple[str, ...]] = {
    **{name: ("in",) for name in _COILS},
    "TP": ("in",), "TON": ("in",), "TOF": ("in",), "TONR": ("in", "r"),
    "CTU": ("cu", "r"), "CTD": ("cd", "ld"), "CTUD": ("cu", "cd", "r", "ld"),
    "Sr": ("s", "r1"), "Rs": ("r", "s1"),
}
_PURE = ("Eq", "Ne", "Gt", "Lt", "Ge", "Le", "InRange", "OutRange", "Ok", "NotOk")
_GATE_PIN = re.compile(r"^in\d+$")
Edge = tuple[End, End]


def _power_pins(part: Part) -> tuple[str, ...] | None:
    """The pins of a part that take power (None: every `inN` of a gate)."""
    if part.name in ("A", "O", "X"):
        return None
    if part.name in _PURE:
        return ("in",)
    return _POWER.get(part.name, ("en",))


def _is_power_pin(part: Part, pin: str) -> bool:
    pins = _power_pins(part)
    return bool(_GATE_PIN.match(pin)) if pins is None else pin in pins


def to_lad(network: S7Network) -> None:
    """Rewrite an FBD network's parts and wires in place into the LAD form the lowering runs."""
    parts = {p.uid: p for p in network.parts}
    edges: list[Edge] = [(w.source, t) for w in network.wires for t in w.targets]
    added: set[str] = set()

    def new_part(part: Part) -> Part:
        network.parts.append(part)
        parts[part.uid] = part
        added.add(part.uid)
        return part

    result: list[Edge] = []
    for source, target in edges:
        part = parts.get(target.part)
        if part is None or not _is_power_pin(part, target.pin):
            result.append((source, target))
            continue
        negated = target.pin in part.negated
        if source.operand is not None:  # an operand on a power input: a contact
            contact = new_part(Part(f"{part.uid}.{target.pin}", "Contact",
                                    frozenset({"operand"}) if negated else frozenset(),
                                    line=part.line))
            result += [(End(powerrail=True), End(part=contact.uid, pin="in")),
                       (source, End(part=contact.uid, pin="operand")),
                       (End(part=contact.uid, pin="out"), target)]
        elif negated and source.part:  # a box's output, negated: a Not between
            inverter = new_part(Part(f"{part.uid}.{target.pin}", "Not", line=part.line))
            result += [(source, End(part=inverter.uid, pin="in")),
                       (End(part=inverter.uid, pin="out"), target)]
        else:
            result.append((source, target))
        if negated:
            part.negated = part.negated - {target.pin}
    fed = {(t.part, t.pin) for _s, t in result}
    for part in list(network.parts):  # no power wire: the rail (an FBD box runs unless EN says)
        pins = _power_pins(part)
        if part.name in _PURE or pins == ("en",):
            pin = pins[0] if pins else "en"
            if (part.uid, pin) not in fed:
                result.append((End(powerrail=True), End(part=part.uid, pin=pin)))
    for gate in [p for p in network.parts if p.name == "A"]:
        result = _series(gate, parts, result, added)
    network.parts = [p for p in network.parts if p.uid in parts]
    network.wires = [Wire(source, [target], 0) for source, target in result]


def _series(gate: Part, parts: dict[str, Part], edges: list[Edge], added: set[str]
            ) -> list[Edge]:
    """An `A` box as the series of its inputs; the edges unchanged when they do not allow it."""
    inputs = sorted(((t.pin, s) for s, t in edges if t.part == gate.uid and s.operand is None
                     and _GATE_PIN.match(t.pin)), key=lambda item: int(item[0][2:]))
    if not inputs:
        return edges
    plan: list[tuple[str, End]] = []  # (a later input's part, its output end)
    for _pin, source in inputs[1:]:
        feeder = parts.get(source.part)
        chainable = feeder is not None and ((feeder.uid in added and feeder.name == "Contact")
                                            or feeder.name in _PURE)
        rail_fed = [s for s, t in edges if t.part == source.part and t.pin == "in"]
        readers = [t for s, t in edges if s.part == source.part and s.pin == source.pin]
        if not chainable or len(readers) != 1 or any(not s.powerrail for s in rail_fed):
            return edges
        plan.append((source.part, source))
    previous = inputs[0][1]
    kept = [(s, t) for s, t in edges if t.part != gate.uid or s.operand is not None]
    for uid, output in plan:
        kept = [(s, t) for s, t in kept if not (t.part == uid and t.pin == "in")]
        kept.append((previous, End(part=uid, pin="in")))
        previous = output
    final = [(previous if s.part == gate.uid else s, t) for s, t in kept]
    del parts[gate.uid]
    return final
