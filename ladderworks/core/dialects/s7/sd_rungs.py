"""The SD rung vocabulary (element spellings → graph parts and their main pins) and the
resolution of named wires (`wire#w1`) into the graph's wires and `O` parts (sd_parser.py)."""

from __future__ import annotations

from dataclasses import dataclass

from ladderworks.core.dialects.s7.graph import End, Part, S7Network, Wire

# SD element → (graph part name, negated pins, main input pin, main output pin)
SIMPLE: dict[str, tuple[str, frozenset[str], str, str]] = {
    "contact": ("Contact", frozenset(), "in", "out"),
    "i_contact": ("Contact", frozenset({"operand"}), "in", "out"),
    "p_contact": ("PContact", frozenset(), "in", "out"),
    "n_contact": ("NContact", frozenset(), "in", "out"),
    "coil": ("Coil", frozenset(), "in", "out"),
    "i_coil": ("Coil", frozenset({"operand"}), "in", "out"),
    "s_coil": ("SCoil", frozenset(), "in", "out"),
    "r_coil": ("RCoil", frozenset(), "in", "out"),
    "p_coil": ("PCoil", frozenset(), "in", "out"),
    "n_coil": ("NCoil", frozenset(), "in", "out"),
    "pt_coil": ("PTCoil", frozenset(), "in", "out"),
    "rt_coil": ("RTCoil", frozenset(), "in", "out"),
    "jumpcoil": ("Jump", frozenset(), "en", ""),
    "i_jumpcoil": ("JumpN", frozenset(), "en", ""),
    "return": ("Return", frozenset(), "en", ""),
    "returntrue": ("Return", frozenset(), "en", ""),
    "returnfalse": ("Return", frozenset(), "en", ""),
    "returncoil": ("Return", frozenset(), "en", ""),
    "isvalidcontact": ("Ok", frozenset(), "in", "out"),
    "isnotvalidcontact": ("NotOk", frozenset(), "in", "out"),
    "eq_contact": ("Eq", frozenset(), "in", "out"), "ne_contact": ("Ne", frozenset(), "in", "out"),
    "gt_contact": ("Gt", frozenset(), "in", "out"), "lt_contact": ("Lt", frozenset(), "in", "out"),
    "ge_contact": ("Ge", frozenset(), "in", "out"), "le_contact": ("Le", frozenset(), "in", "out"),
    "in_range": ("InRange", frozenset(), "in", "out"),
    "inrange": ("InRange", frozenset(), "in", "out"),
    "out_range": ("OutRange", frozenset(), "in", "out"),
    "outrange": ("OutRange", frozenset(), "in", "out"),
    "not": ("Not", frozenset(), "in", "out"),
    "p_trig": ("PTrig", frozenset(), "in", "out"), "n_trig": ("NTrig", frozenset(), "in", "out"),
    "move": ("Move", frozenset(), "en", "eno"), "add": ("Add", frozenset(), "en", "eno"),
    "sub": ("Sub", frozenset(), "en", "eno"), "mul": ("Mul", frozenset(), "en", "eno"),
    "div": ("Div", frozenset(), "en", "eno"), "inc": ("Inc", frozenset(), "en", "eno"),
    "dec": ("Dec", frozenset(), "en", "eno"), "convert": ("Convert", frozenset(), "en", "eno"),
    "jumplist": ("JumpList", frozenset(), "en", ""), "switch": ("Switch", frozenset(), "en", ""),
}
CMP = {"==": "Eq", "<>": "Ne", ">": "Gt", "<": "Lt", ">=": "Ge", "<=": "Le"}
# `<instance>.TON(…)` and the counters: part name, main input, main output
INSTANCE = {"tp": ("TP", "in", "q"), "ton": ("TON", "in", "q"), "tof": ("TOF", "in", "q"),
             "tonr": ("TONR", "in", "q"), "ctu": ("CTU", "cu", "q"), "ctd": ("CTD", "cd", "q"),
             "ctud": ("CTUD", "cu", "qu"), "s_sr": ("Sr", "s", "q"), "s_rs": ("Rs", "r", "q")}
# the pin a single argument `Name( x )` goes to, by part name
SINGLE = {"Jump": "label", "JumpN": "label", "Label": "label", "Sr": "r1", "Rs": "s1",
           "PTrig": "bit", "NTrig": "bit", "Return": "operand"}



@dataclass(slots=True)
class Link:
    """A connection before named wires are resolved: ("wire", name) / ("end", End) → End."""

    source: tuple[str, object]
    target: End
    line: int


def wire_ref(text: str) -> tuple[str, object]:
    name = text.split("#", 1)[1]
    return ("rail", None) if name.lower() == "powerrail" else ("wire", name)


def pins(part: Part) -> tuple[str, str]:
    """A part's main input and output pins (its power in and out)."""
    for key, (name, _neg, main_in, main_out) in SIMPLE.items():
        if name == part.name and not key.startswith("return"):
            return main_in, main_out
    for name, main_in, main_out in INSTANCE.values():
        if name == part.name:
            return main_in, main_out
    if part.name == "Return":
        return "en", ""
    if part.name == "Label":
        return "", ""
    return "en", "eno"  # calls, CMP boxes by name, an unknown part


def resolve_links(network: S7Network, links: list[Link]) -> None:
    """Turn the rungs' links into wires: a named wire with several sources becomes an `O` part
    (in1 … inN → out) and every use of the name takes its output."""
    sources: dict[str, list[tuple[tuple[str, object], int]]] = {}
    for link in links:
        if link.target.part.startswith("@"):
            sources.setdefault(link.target.part[1:], []).append((link.source, link.line))
    points: dict[str, End | None] = {}

    def point(ref: tuple[str, object], seen: frozenset[str] = frozenset()) -> End | None:
        kind, value = ref
        if kind == "rail":
            return End(powerrail=True)
        if kind == "end":
            return value  # type: ignore[return-value]
        if kind != "wire":
            return None
        name = str(value)
        if name in points:
            return points[name]
        if name in seen:  # a loop of named wires: no power
            return None
        found = sources.get(name, [])
        if len(found) == 1:
            end = point(found[0][0], seen | {name})
        elif found:
            uid = f"O_{name}"
            network.parts.append(Part(uid, "O", line=found[0][1]))
            for n, (ref_n, line) in enumerate(found, start=1):
                source = point(ref_n, seen | {name})
                if source is not None:
                    network.wires.append(Wire(source, [End(part=uid, pin=f"in{n}")], line))
            end = End(part=uid, pin="out")
        else:
            end = None
        points[name] = end
        return end

    for link in links:
        if link.target.part.startswith("@"):
            continue
        source = point(link.source)
        if source is not None:
            network.wires.append(Wire(source, [link.target], link.line))
    # pins fed by a wire name (`c.S_RS( wire#w1 )`)
    for wire in list(network.wires):
        if wire.source.part.startswith("@"):
            source = point(("wire", wire.source.part[1:]))
            network.wires.remove(wire)
            if source is not None:
                network.wires.append(Wire(source, wire.targets, wire.line))
