"""The pins of the S7 boxes as TIA draws them: names, rows, and the graph's pin each one is.

`LAYOUTS` gives, for each box part, its inputs and outputs top to bottom as (shown name, the
graph's pin names it may have); `box_pins` finds what is wired to each in a network; the
grid → graph writer (`from_grid.py`) reads the same table back.
"""

from __future__ import annotations

from ladderworks.core.dialects.s7.graph import Part
from ladderworks.core.dialects.s7.stack import PinGraph
from ladderworks.core.ladder.model import Pin

PinSpec = tuple[str, tuple[str, ...]]  # (name shown, the graph's pin names for it)
TYPE_KEYS = ("srctype", "src_type", "time_type", "timetype", "counttype", "count_type",
             "value_type", "valuetype", "type")
_TIMER_OUT: tuple[PinSpec, ...] = (("Q", ("q",)), ("ET", ("et",)))
_EN: PinSpec = ("EN", ("en",))
_ENO: PinSpec = ("ENO", ("eno",))
LAYOUTS: dict[str, tuple[tuple[PinSpec, ...], tuple[PinSpec, ...]]] = {
    **{name: ((("IN", ("in",)), ("PT", ("pt",))), _TIMER_OUT) for name in ("TP", "TON", "TOF")},
    "TONR": ((("IN", ("in",)), ("R", ("r",)), ("PT", ("pt",))), _TIMER_OUT),
    "CTU": ((("CU", ("cu",)), ("R", ("r",)), ("PV", ("pv",))), (("Q", ("q",)),
                                                               ("CV", ("cv",)))),
    "CTD": ((("CD", ("cd",)), ("LD", ("ld",)), ("PV", ("pv",))), (("Q", ("q",)),
                                                                 ("CV", ("cv",)))),
    "CTUD": ((("CU", ("cu",)), ("CD", ("cd",)), ("R", ("r",)), ("LD", ("ld",)),
              ("PV", ("pv",))), (("QU", ("qu",)), ("QD", ("qd",)), ("CV", ("cv",)))),
    **{name: ((("", ("pre", "en")), ("MIN", ("min",)), ("VAL", ("val", "in")),
               ("MAX", ("max",))), (("", ("out", "eno")),)) for name in ("InRange", "OutRange")},
    "Move": ((_EN, ("IN", ("in",))), (_ENO, ("OUT1", ("out1", "out")))),
    **{name: ((_EN, ("IN1", ("in1",)), ("IN2", ("in2",))), (_ENO, ("OUT", ("out",))))
       for name in ("Add", "Sub", "Mul", "Div")},
    **{name: ((_EN, ("IN/OUT", ("operand", "inout", "in_out"))), (_ENO,))
       for name in ("Inc", "Dec")},
    "Convert": ((_EN, ("IN", ("in",))), (_ENO, ("OUT", ("out",)))),
    "Sr": ((("S", ("s",)), ("R1", ("r1",))), (("Q", ("q", "out")),)),
    "Rs": ((("R", ("r",)), ("S1", ("s1",))), (("Q", ("q", "out")),)),
    "PTrig": ((("CLK", ("clk", "in")),), (("Q", ("q", "out")),)),
    "NTrig": ((("CLK", ("clk", "in")),), (("Q", ("q", "out")),)),
    "JumpList": ((_EN, ("K", ("k",))), ()),
    "Switch": ((_EN, ("K", ("k",))), ()),
}
BOXES = frozenset(LAYOUTS)
INSTANCED = frozenset(("TP", "TON", "TOF", "TONR", "CTU", "CTD", "CTUD"))
TITLES = {"InRange": "IN_RANGE", "OutRange": "OUT_RANGE", "Convert": "CONV", "Sr": "SR",
          "Rs": "RS", "PTrig": "P_TRIG", "NTrig": "N_TRIG", "JumpList": "JMP_LIST"}
ROWS = {"InRange": "S7.IN_RANGE", "OutRange": "S7.OUT_RANGE", "PTrig": "S7.P_TRIG",
        "NTrig": "S7.N_TRIG", "JumpList": "", "Switch": ""}
RELATIONS = {"EQ": "==", "NE": "<>", "GT": ">", "LT": "<", "GE": ">=", "LE": "<="}
MAIN_IN = ("in", "pre", "en", "cu", "cd", "s", "r", "clk")  # as the lowering takes power
MAIN_OUT = ("out", "eno", "q", "qu", "")


def title(part: Part) -> str:
    """The name written in the box: TON, MOVE, IN_RANGE, the called block's name."""
    return part.call if part.name == "Call" else TITLES.get(part.name, part.name.upper())


def rows_of(name: str) -> tuple[str, ...]:
    """The engine rows a box part is lowered to (its Q is the recorded result of that op)."""
    row = ROWS.get(name, "S7." + name.upper())
    return (row,) if row else ()


def main_in(part: Part, graph: PinGraph) -> str:
    """The pin power comes in by (the first wired of the lowering's order; "in" when none)."""
    return next((pin for pin in MAIN_IN if (part.uid, pin) in graph.power_in), "in")


def gate_pins(part: Part, graph: PinGraph) -> list[str]:
    """An O/A gate's input pins in1 … inN in order."""
    return sorted({pin for (uid, pin) in (*graph.power_in, *graph.operand_in)
                   if uid == part.uid and pin.startswith("in")}, key=lambda p: (len(p), p))


def _text(graph: PinGraph, part: Part, keys: tuple[str, ...], output: bool) -> str:
    for key in keys:
        if output:
            found = graph.operand_out.get((part.uid, key), [])
            if found:
                return found[0].display()
        elif (part.uid, key) in graph.operand_in:
            return graph.operand_in[(part.uid, key)].display()
    return ""


def _wired(graph: PinGraph, part: Part) -> tuple[list[str], list[str]]:
    """A call's parameter pins as wired, inputs then outputs, in the order of the wires."""
    inputs: list[str] = []
    outputs: list[str] = []
    for wire in graph.network.wires:
        if wire.source.part == part.uid and wire.source.pin.lower() not in ("eno", "") \
                and wire.source.pin not in outputs:
            outputs.append(wire.source.pin)
        for end in wire.targets:
            if end.part == part.uid and end.pin.lower() != "en" and end.pin not in inputs:
                inputs.append(end.pin)
    return inputs, outputs


def box_pins(part: Part, graph: PinGraph) -> list[Pin]:
    """The pins of a box part with what is wired to each (operands as TIA writes them)."""
    found: list[Pin] = []
    if part.name == "Call":
        inputs, outputs = _wired(graph, part)
        found = [Pin("EN", 0), Pin("ENO", 0, output=True)]
        found += [Pin(name, row, text=_text(graph, part, (name.lower(),), False))
                  for row, name in enumerate(inputs, start=1)]
        found += [Pin(name, row, output=True, text=_text(graph, part, (name.lower(),), True))
                  for row, name in enumerate(outputs, start=1)]
        return found
    ins, outs = LAYOUTS[part.name]
    for row, (name, keys) in enumerate(ins):
        found.append(Pin(name, row, text=_text(graph, part, keys, False),
                         negated=any(k in part.negated for k in keys)))
    extra_outs = list(outs)
    if part.name == "Move":  # OUT2, OUT3 … as wired
        count = sum(1 for (uid, pin) in graph.operand_out if uid == part.uid
                    and pin.startswith("out") and pin[3:].isdigit())
        extra_outs += [(f"OUT{n}", (f"out{n}",)) for n in range(2, count + 1)]
    for row, (name, keys) in enumerate(extra_outs):
        found.append(Pin(name, row, output=True, text=_text(graph, part, keys, True)))
    if part.name == "Switch":
        for n in range(1, len(part.dests) + 1):
            relation = part.template.get(f"op{n}", "EQ").upper()
            key = f"{relation.lower()}{n}"
            found.append(Pin(RELATIONS.get(relation, relation), len(ins) + n - 1,
                             text=_text(graph, part, (key,), False)))
    if part.name in ("JumpList", "Switch"):
        for n, dest in enumerate(part.dests):
            found.append(Pin(f"DEST{n}", n + 1, output=True, text=dest))
        if part.template.get("else"):
            found.append(Pin("ELSE", len(part.dests) + 1, output=True,
                             text=part.template["else"]))
    return found
