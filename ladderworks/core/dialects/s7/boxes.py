"""The EN/ENO boxes (MOVE, ADD … DIV, INC, DEC, CONVERT) and the jump tables (JMP_LIST,
SWITCH) of an S7 network, lowered for `lowering.BlockLowering` (through `lowerer.py`)."""

from __future__ import annotations

from ladderworks.core.dialects.s7.graph import Operand, OperandKind, Part
from ladderworks.core.dialects.s7.layout import string_value
from ladderworks.core.dialects.s7.lowerer import BlockLowering
from ladderworks.core.dialects.s7.stack import Expr, PinGraph
from ladderworks.core.dialects.s7.starts import STRING_TYPE, string_moves
from ladderworks.core.il.program import Instruction, LabelRef, ParamValue
from ladderworks.core.plc import typed

MATH = {"Add": "S7.ADD", "Sub": "S7.SUB", "Mul": "S7.MUL", "Div": "S7.DIV"}


def box(lowering: BlockLowering, index: int, graph: PinGraph, part: Part,
        power: Expr) -> Expr | None:
    """A box run while its EN has power; ENO (its result) feeds what follows."""
    name, line = part.name, part.line
    if name in ("Inc", "Dec"):
        operand = graph.operand_in.get((part.uid, "operand")) or graph.operand_in.get(
            (part.uid, "inout")) or graph.operand_in.get((part.uid, "in_out"))
        if operand is None:
            raise lowering.fail(index, part, "s7-pin-missing", part=name, pin="IN/OUT")
        vtype = lowering.vtype(index, graph, part, ("operand", "inout", "in_out"))
        target = lowering.place(index, part, operand).address
        code = [Instruction("S7." + name.upper(), None, (int(vtype), target), line=line)]
        return _result(lowering, graph, part, power, code)
    if name == "Move" and _to_string(lowering, graph, part):
        return _string_move(lowering, index, graph, part, power)
    if name == "Move":
        vtype = lowering.vtype(index, graph, part, ("in", "out1"))
        source = lowering.value(index, part, graph.operand_in.get((part.uid, "in")), vtype, "in")
        code = []
        for (uid, pin), targets in graph.operand_out.items():
            if uid == part.uid and pin.startswith("out"):
                for operand in targets:
                    code.append(Instruction("S7.MOVE", None, (
                        int(vtype), source,
                        lowering.place(index, part, operand, guess=vtype.name).address),
                        line=line))
        if not code:
            raise lowering.fail(index, part, "s7-pin-missing", part=name, pin="OUT1")
        return _result(lowering, graph, part, power, code)
    if name == "Convert":
        keys = {k.lower(): v for k, v in part.template.items()}
        source_type = typed.type_of(keys.get("intype", keys.get("srctype", ""))) or \
            lowering.vtype(index, graph, part, ("in",))
        outs = graph.operand_out.get((part.uid, "out"), [])
        if not outs:
            raise lowering.fail(index, part, "s7-pin-missing", part=name, pin="OUT")
        place = lowering.place(index, part, outs[0])
        target_type = typed.type_of(keys.get("outtype", keys.get("desttype", ""))) or \
            place.vtype or typed.ValueType.INT
        source = lowering.value(index, part, graph.operand_in.get((part.uid, "in")), source_type,
                            "in")
        code = [Instruction("S7.CONVERT", None, (int(source_type), int(target_type), source,
                                                 place.address), line=line)]
        return _result(lowering, graph, part, power, code)
    vtype = lowering.vtype(index, graph, part, ("in1", "in2", "out"))
    kinds = _declared(lowering, graph, part, ("in1", "in2", "out"))
    if not any(key.lower() == "srctype" for key in part.template) and len(kinds) > 1:
        # an automatically typed box on operands of several types: TIA converts them to
        # one type; LadderWorks does not, so the box is not simulated [LW]
        raise lowering.fail(index, part, "s7-type", part=part.name,
                            type=" / ".join(sorted(k.name.title() for k in kinds)))
    first = lowering.value(index, part, graph.operand_in.get((part.uid, "in1")), vtype, "in1")
    second = lowering.value(index, part, graph.operand_in.get((part.uid, "in2")), vtype, "in2")
    outs = graph.operand_out.get((part.uid, "out"), [])
    if not outs:
        raise lowering.fail(index, part, "s7-pin-missing", part=name, pin="OUT")
    code = [Instruction(MATH[name], None, (int(vtype), first, second,
                                           lowering.place(index, part, outs[0],
                                                          guess=vtype.name).address),
                        line=line)]
    return _result(lowering, graph, part, power, code)

def _outputs(graph: PinGraph, part: Part) -> list[Operand]:
    return [operand for (uid, pin), targets in graph.operand_out.items()
            if uid == part.uid and pin.startswith("out") for operand in targets]


def _to_string(lowering: BlockLowering, graph: PinGraph, part: Part) -> bool:
    """Whether a MOVE writes a String/WString (its outputs' declared type)."""
    for operand in _outputs(graph, part):
        place = lowering.layout.resolve(lowering.block, operand, "", lowering.scope)
        if place is not None and STRING_TYPE.match(place.type_name.strip()):
            return True
    return False


def _string_move(lowering: BlockLowering, index: int, graph: PinGraph, part: Part,
                 power: Expr) -> Expr | None:
    """MOVE of a string constant to Strings: the actual length and the characters (cut at each
    target's max length) written while EN has power; a String variable's MOVE is not
    simulated (s7-type)."""
    source = graph.operand_in.get((part.uid, "in"))
    chars = string_value(source.text) if source is not None and \
        source.kind is OperandKind.CONSTANT else None
    if chars is None:
        raise lowering.fail(index, part, "s7-type", part=part.name, type="String")
    code: list[Instruction] = []
    for operand in _outputs(graph, part):
        place = lowering.place(index, part, operand)
        code += [Instruction(i.name, None, i.params, line=part.line)
                 for i in string_moves(place, chars)[1:]]  # the max length stays
    return _result(lowering, graph, part, power, code)


def jump_table(lowering: BlockLowering, index: int, graph: PinGraph, part: Part,
               power: Expr) -> None:
    """JMP_LIST: K = n jumps to DEST n, beyond them the next network (003:552-578). SWITCH:
    the first comparison that holds jumps to its DEST, none: ELSE (003:653-677)."""
    vtype = lowering.vtype(index, graph, part, ("k",))
    k = lowering.value(index, part, graph.operand_in.get((part.uid, "k")), vtype, "k")
    keep = lowering.new_relay(index, part)
    lowering.statement(part, [power], [], keep)
    line = part.line
    cases: list[tuple[str, ParamValue, str]] = []
    if part.name == "JumpList":
        cases = [("S7.EQ", n, dest) for n, dest in enumerate(part.dests)]
    else:
        for n, dest in enumerate(part.dests, start=1):
            relation = part.template.get(f"op{n}", "EQ").upper()
            operand = graph.operand_in.get((part.uid, f"{relation.lower()}{n}"))
            cases.append(("S7." + relation, lowering.value(index, part, operand, vtype,
                                                       relation), dest))
    for row, value, dest in cases:
        target = lowering.labels.get(dest.lower())
        if target is None:
            raise lowering.fail(index, part, "s7-label-unknown", label=dest)
        lowering.emit([Instruction("RD", keep, line=line),
                   Instruction(row, None, (int(vtype), k, value), line=line),
                   Instruction("S7.JMP", None, (LabelRef(target),), line=line)])
    otherwise = part.template.get("else", "")
    if otherwise:
        target = lowering.labels.get(otherwise.lower())
        if target is None:
            raise lowering.fail(index, part, "s7-label-unknown", label=otherwise)
        lowering.emit([Instruction("RD", keep, line=line),
                   Instruction("S7.JMP", None, (LabelRef(target),), line=line)])


def _declared(lowering: BlockLowering, graph: PinGraph, part: Part, pins: tuple[str, ...]
              ) -> set[typed.ValueType]:
    """The declared types of the tags and members wired to a box's pins."""
    found: set[typed.ValueType] = set()
    for pin in pins:
        operand = graph.operand_in.get((part.uid, pin)) or next(
            iter(graph.operand_out.get((part.uid, pin), [])), None)
        if operand is None or operand.kind not in (OperandKind.GLOBAL, OperandKind.LOCAL):
            continue
        place = lowering.layout.resolve(lowering.block, operand, "", lowering.scope)
        if place is not None and place.vtype is not None:
            found.add(place.vtype)
    return found


def _result(lowering: BlockLowering, graph: PinGraph, part: Part, power: Expr,
            code: list[Instruction]) -> Expr | None:
    """A box's code run on its EN; its ENO kept for what reads it: the box's result, or its EN
    when the box's ENO is disabled (`DisabledENO`: errors are not reported)."""
    keep = lowering.keep(graph, part)
    if not part.disabled_eno or keep is None:
        return lowering.statement(part, [power], code, keep)
    lowering.statement(part, [power], [], keep)
    lowering.statement(part, [power], code, None)
    return ("bit", keep, False)
