"""FC and FB calls: the called block lowered inline at the call, its parameters copied.

With EN 1 the actual inputs (and in/outs) are copied into the callee's interface members, the
callee's networks run, then its outputs (and in/outs) are copied to the actuals; with EN 0 all
of it is jumped over and the outputs keep their values. ENO is EN, and 0 when a RET of the
callee returned FALSE (its value: TRUE, FALSE or a Bool; none is TRUE). An FC's members live once
for all its calls (`#FcName.x`), an FB's in its instance: an instance DB (`"Motor_DB".x`, the
same place a scenario or another network names) or a multi-instance in the caller's statics
(`#inst`). Recursion deeper than MAX_DEPTH is refused. docs/dialects.md, S7-1200 calls.
"""

from __future__ import annotations

from ladderworks.core.dialects.s7.graph import Block, Operand, OperandKind, Part
from ladderworks.core.dialects.s7.layout import Place
from ladderworks.core.dialects.s7.lowerer import BlockLowering
from ladderworks.core.dialects.s7.stack import ALWAYS_ON, Expr, PinGraph
from ladderworks.core.il.program import Instruction, LabelRef
from ladderworks.core.plc import typed

MAX_DEPTH = 8
_IN, _OUT = ("Input", "InOut"), ("Output", "InOut")


def callee_of(lowering: BlockLowering, part: Part) -> tuple[Block, tuple[str, ...]] | None:
    """The block a Call part runs and the scope its members live in; None if not there."""
    program = lowering.layout.program
    instance = part.instance
    if instance is not None and instance.kind is OperandKind.LOCAL and instance.path:
        found = lowering.block.member(instance.path[0])
        block = program.block(found[1].type_name.strip('"')) if found is not None else None
        if block is not None and block.kind == "FB":
            return block, (*lowering.scope, instance.path[0].lower())
    named = program.block(part.call) if part.call else None
    if named is None:
        return None
    if named.kind in ("FC", "FB"):
        return named, (f"#{named.name.lower()}",)
    if named.instance_of:
        block = program.block(named.instance_of)
        if block is not None and block.kind == "FB":
            return block, (named.name.lower(),)
    return None


def _fail(lowering: BlockLowering, index: int, where: Part, code: str,
          **args: object) -> Exception:
    return lowering.fail(index, where, code, **args)


def _copy_in(lowering: BlockLowering, index: int, part: Part, operand: Operand,
             target: Place) -> None:
    """An actual into a parameter: a bit by RD/WRT, a value by MOVE."""
    line = part.line
    if target.address.bit is not None:
        source = lowering.bit_expr(operand, False, index, part)
        lowering.statement(part, [source], [Instruction("WRT", target.address, line=line)],
                           None)
        return
    vtype = target.vtype or typed.ValueType.INT
    value = lowering.value(index, part, operand, vtype, "in")
    lowering.emit([Instruction("RD", ALWAYS_ON, line=line),
                   Instruction("S7.MOVE", None, (int(vtype), value, target.address), line=line)])


def _copy_out(lowering: BlockLowering, index: int, part: Part, source: Place,
              operand: Operand) -> None:
    """A parameter out to its actual."""
    line = part.line
    target = lowering.place(index, part, operand, guess=source.type_name)
    if source.address.bit is not None or target.address.bit is not None:
        if source.address.bit is None or target.address.bit is None:
            raise _fail(lowering, index, part, "s7-type", part=part.call, type=source.type_name)
        lowering.emit([Instruction("RD", source.address, line=line),
                       Instruction("WRT", target.address, line=line)])
        return
    vtype = source.vtype or target.vtype or typed.ValueType.INT
    lowering.emit([Instruction("RD", ALWAYS_ON, line=line),
                   Instruction("S7.MOVE", None, (int(vtype), source.address, target.address),
                               line=line)])


def lower_call(lowering: BlockLowering, index: int, graph: PinGraph, part: Part, power: Expr,
               outputs: dict[str, Expr | None]) -> Expr | None:
    """A call: EN kept, parameters in, the callee's networks, parameters out."""
    found = callee_of(lowering, part)
    if found is None:  # not exported with the program (a library block …): shown only
        return lowering.shown_only(index, part, power, "s7-call-unknown", block=part.call)
    callee, scope = found
    if lowering.depth >= MAX_DEPTH or callee is lowering.block:
        raise _fail(lowering, index, part, "s7-wire", part=callee.name,
                    why="calls nested too deep")
    line = part.line
    enabled = lowering.new_relay(index, part)
    lowering.statement(part, [power], [], enabled)
    skip = lowering.new_label()
    lowering.emit([Instruction("RD", enabled, line=line),
                   Instruction("S7.JMPN", None, (LabelRef(skip),), line=line)])
    layout = lowering.layout
    for section in _IN:
        for member in callee.members(section):
            pin = member.name.lower()
            target = layout.local(callee, (member.name,), scope)
            if target is None:
                continue
            operand = graph.operand_in.get((part.uid, pin))
            if operand is not None:
                _copy_in(lowering, index, part, operand, target)
            elif (part.uid, pin) in graph.power_in and target.address.bit is not None:
                powered = lowering.power(graph, part, pin, outputs)
                if powered is not None:
                    lowering.statement(part, [powered], [Instruction("WRT", target.address,
                                                                     line=line)], None)
    eno = lowering.new_relay(index, part)  # 1 unless a RET returns 0
    lowering.emit([Instruction("RD", ALWAYS_ON, line=line), Instruction("WRT", eno, line=line)])
    networks, diagnostics = lowering.lower_callee(callee, scope, eno)
    lowering.networks.extend(networks)
    lowering.diagnostics.extend(diagnostics)
    for section in _OUT:
        for member in callee.members(section):
            source = layout.local(callee, (member.name,), scope)
            if source is None:
                continue
            key = (part.uid, member.name.lower())
            actuals = list(graph.operand_out.get(key, []))
            if section == "InOut" and key in graph.operand_in:  # written back where it came from
                actuals.append(graph.operand_in[key])
            for operand in actuals:
                if operand.kind is not OperandKind.CONSTANT:
                    _copy_out(lowering, index, part, source, operand)
    lowering.emit([Instruction("S7.LABEL", None, (LabelRef(skip),), line=line)])
    return ("and", ("bit", enabled, False), ("bit", eno, False)) if graph.used(part.uid) \
        else None


def return_value(lowering: BlockLowering, index: int, graph: PinGraph, part: Part,
                 power: Expr) -> None:
    """A RET's value (TRUE, FALSE or a Bool; none: TRUE) into its called block's ENO when
    the RET is taken; in a block not called (an OB) it is not used."""
    if lowering.eno is None:
        return
    operand = graph.operand_in.get((part.uid, "operand"))
    if operand is None:
        return
    value = lowering.bit_expr(operand, False, index, part)
    line = part.line
    lowering.statement(part, [("and", power, value)], [Instruction("SET", lowering.eno,
                                                                    line=line)], None)
    lowering.statement(part, [("and", power, ("not", value))], [Instruction(
        "RST", lowering.eno, line=line)], None)


def prepare(lowering: BlockLowering, part: Part) -> None:
    """Lay out a callee's interface in its scope before any network names its members."""
    found = callee_of(lowering, part)
    if found is not None:
        callee, scope = found
        for section in ("Input", "Output", "InOut", "Static"):
            for member in callee.members(section):
                lowering.layout.local(callee, (member.name,), scope)
