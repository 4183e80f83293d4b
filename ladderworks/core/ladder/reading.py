"""Reading a network's code back into series/parallel blocks (`read_rung`), or `Undrawable`."""

from __future__ import annotations

from ladderworks.core.il.program import Instruction
from ladderworks.core.instructions import (
    Combine,
    Kind,
    StackOp,
)
from ladderworks.core.ladder.logic import (
    Branch,
    Leaf,
    Logic,
    Output,
    Rung,
    Series,
    parallel,
    series,
)
from ladderworks.core.ladder.model import Coil, Contact, FunctionBox
from ladderworks.core.ladder.row_contacts import contact_combine


class Undrawable(Exception):
    """The instructions have no faithful ladder picture (kept as a listing instead)."""


_PREVIOUS = Leaf(Contact(None, comment="the result written so far"))  # chain start marker


def _join(stack: list[Logic], contact: Contact, combine: Combine, pushes: int, name: str
          ) -> None:
    """A contact read into the symbolic stack: RD starts, RD.STK pushes, AND/OR join."""
    if combine is Combine.READ:
        if bool(stack) != (pushes > 0):  # RD starts the logic, RD.STK pushes onto it
            raise Undrawable(name)
        stack.append(Leaf(contact))
        return
    if not stack or pushes:
        raise Undrawable(name)
    top = stack.pop()
    stack.append(series(top, Leaf(contact)) if combine is Combine.AND
                 else parallel(top, Leaf(contact)))


def _branch_block(stack: list[Logic], name: str) -> Logic | None:
    """A stack branch's block read since its MPS / MRD / MPP; None for coils on the branch
    point itself (`MPP / OUT y`: drawn as a branch of wire; layout keeps the coding)."""
    top = stack[0] if len(stack) == 1 else None
    if top is _PREVIOUS:
        return None
    if not isinstance(top, Series) or top.items[0] is not _PREVIOUS:
        raise Undrawable(name)
    rest = top.items[1:]
    return rest[0] if len(rest) == 1 else Series(rest)


class _Level:
    """An MPS level being read: its branches, and whether its MPP came (`last`)."""

    def __init__(self, branches: list[Branch]) -> None:
        self.branches = branches
        self.last = False


def _branch_op(op: StackOp, phase: str, levels: list[_Level], stack: list[Logic], rung: Rung,
               name: str) -> None:
    """MPS starts the branches (the logic so far is their common part) — or, inside a branch
    before its coils, the branch's own branches (nested MPS) —, MRD a next branch, MPP the
    last (after closing the nested levels whose MPP came); anything else (INV) has no picture."""
    if op is StackOp.DUP and phase == "logic" and not levels and rung.box is None \
            and len(stack) == 1:
        rung.logic = stack[0]
        levels.append(_Level(rung.branches))
        return
    if op is StackOp.DUP and phase == "coils" and not levels and rung.box is None \
            and not rung.chain and not rung.branches:  # MPS after the rung's first outputs
        levels.append(_Level(rung.branches))
        return
    if op is StackOp.DUP and phase == "branch" and levels:
        block = _branch_block(stack, name)
        if block is None:
            raise Undrawable(name)
        inner: list[Branch] = []
        levels[-1].branches.append((block, [], inner))
        levels.append(_Level(inner))
        return
    if op in (StackOp.OVER, StackOp.DROP) and levels and phase == "coils":
        while levels and levels[-1].last:
            if len(levels.pop().branches) < 2:
                raise Undrawable(name)
        if not levels:
            raise Undrawable(name)
        levels[-1].last = op is StackOp.DROP
        return
    raise Undrawable(name)


def read_rung(instructions: list[Instruction] | tuple[Instruction, ...]) -> Rung:
    """The meaning of one network's instructions; Undrawable for code with no ladder picture
    (unbalanced stack, OR after an output, a function without its control inputs, ...)."""
    stack: list[Logic] = []
    rung = Rung()
    phase = "logic"  # then "coils" after the first WRT / the function; "chain" after more logic
    levels: list[_Level] = []  # Delta's stack branches: the MPS levels open
    for ins in instructions:
        spec = ins.spec
        name = ins.name
        if phase == "closed" and rung.box is not None and rung.box.spec.output:
            # an output box with more after it: its logic feeds outputs, the box the first
            rung.logic, rung.coils, rung.box, rung.inputs = rung.inputs[0], [rung.box], None, []
            phase = "coils"
        if rung.box is not None and phase in ("coils", "closed", "pins") \
                and _reads_output(rung.box, ins):
            rung.pins.append((Contact(ins.operand, False, ins.comment, ins.lead), None, []))
            phase = "pins"
            stack = [_PREVIOUS]
            continue
        # a dialect's edge or comparison contact
        joins = contact_combine(spec) if spec.kind is Kind.FUNCTION else None
        if phase == "pins" and not spec.is_coil and (
                rung.pins[-1][2] or (spec.kind is not Kind.BASIC and joins is None)
                or spec.stack is not StackOp.NONE):
            raise Undrawable(name)  # a pin's block comes before its coils, no box after
        if spec.kind is Kind.BASIC and spec.stack is StackOp.INVERT:
            if phase not in ("logic", "chain", "branch") or len(stack) != 1:
                raise Undrawable(name)  # INV inside a block: not the power at its place
            stack[0] = series(stack[0], Leaf(Contact(None, False, ins.comment, ins.lead, name)))
            continue
        if spec.is_coil or (spec.output and phase != "logic"):
            if phase == "pins":
                if ins.operand is None:
                    raise Undrawable(name)
                contact, block, coils = rung.pins[-1]
                if not coils:  # the block after the pin (`FO 1 / AND X3`), as a chain's
                    block = _pin_block(stack, name)
                    rung.pins[-1] = (contact, block, coils)
                coils.append(Coil(ins.operand, spec.negated, ins.comment, ins.lead,
                                  spec.write, name if spec.dialect else ""))
                continue
            if phase == "logic":
                if rung.box is None and len(stack) != 1:
                    raise Undrawable(name)
                if rung.box is None:
                    rung.logic = stack[0]
            elif levels:
                if phase == "branch":  # the branch's first coil (more may follow)
                    levels[-1].branches.append((_branch_block(stack, name), [], []))
            elif phase == "chain":
                top = stack[0] if len(stack) == 1 else None
                if not isinstance(top, Series) or top.items[0] is not _PREVIOUS:
                    raise Undrawable(name)
                rest = top.items[1:]
                rung.chain.append((rest[0] if len(rest) == 1 else Series(rest), []))
            phase = "coils"
            coil: Output
            if spec.output:
                coil = FunctionBox.new(name, ins.params, ins.comment, ins.lead)
            elif ins.operand is None:
                raise Undrawable(name)
            else:
                coil = Coil(ins.operand, spec.negated, ins.comment, ins.lead, spec.write,
                            name if spec.dialect else "")  # a dialect's own coil row: kept
            (levels[-1].branches[-1][1] if levels else rung.chain[-1][1] if rung.chain
             else rung.coils).append(coil)
            continue
        if spec.kind is Kind.BASIC and spec.stack is not StackOp.NONE:
            _branch_op(spec.stack, phase, levels, stack, rung, name)
            rung.stack_dialect = spec.dialect
            rung.stack_params.append((spec.stack, tuple(ins.params)))
            phase = "branch"
            stack = [_PREVIOUS]
            continue
        if levels and phase == "coils":
            raise Undrawable(name)  # logic after a branch's coils without MRD / MPP
        if phase == "coils" and rung.box is None and (spec.kind is Kind.BASIC or joins):
            phase = "chain"
            stack = [_PREVIOUS]
        if phase not in ("logic", "chain", "branch", "pins"):
            raise Undrawable(name)
        if joins is not None:
            _join(stack, Contact(None, False, ins.comment, ins.lead, name, ins.params), joins,
                  spec.pushes, name)
            continue
        if spec.kind is not Kind.BASIC:
            if phase in ("chain", "branch") or len(stack) != len(spec.inputs):
                raise Undrawable(name)
            rung.box = FunctionBox.new(name, ins.params, ins.comment, ins.lead)
            rung.inputs = list(stack)
            stack = []
            phase = "coils" if spec.w1 else "closed"
            continue
        if not spec.is_contact:  # AND.STK / OR.STK: join the top two values
            if len(stack) < 2 or spec.combine is Combine.READ:
                raise Undrawable(name)
            b = stack.pop()
            a = stack.pop()
            stack.append(series(a, b) if spec.combine is Combine.AND else parallel(a, b))
            continue
        contact = Contact(ins.operand, spec.negated, ins.comment, ins.lead)
        _join(stack, contact, spec.combine, spec.pushes, name)
    if rung.box is None and rung.logic is None:
        raise Undrawable("no output")
    if phase in ("chain", "branch") or (phase == "pins" and not rung.pins[-1][2]
                                        and stack != [_PREVIOUS]):
        raise Undrawable("logic after the last coil")
    if any(not level.last or len(level.branches) < 2 for level in levels):
        raise Undrawable("MPS without its MPP")
    if rung.box is not None and not rung.box.spec.w1 and rung.coils:
        raise Undrawable("coils")
    return rung


def _pin_block(stack: list[Logic], name: str) -> Logic | None:
    """The block in series after a box's output pin: None when the pin feeds its coils."""
    if len(stack) != 1:
        raise Undrawable(name)
    top = stack[0]
    if top is _PREVIOUS:
        return None
    if not isinstance(top, Series) or top.items[0] is not _PREVIOUS:
        raise Undrawable(name)  # OR with the pin: no picture
    rest = top.items[1:]
    return rest[0] if len(rest) == 1 else Series(rest)


def _reads_output(box: FunctionBox, ins: Instruction) -> bool:
    """Whether `ins` reads a bit of the box's output byte on its own (`RD FO.1`): a pin."""
    spec = ins.spec
    byte = box.output_byte()
    operand = ins.operand
    return (byte is not None and operand is not None and operand.bit is not None
            and spec.kind is Kind.BASIC and spec.combine is Combine.READ and spec.is_contact
            and not spec.pushes and not spec.negated
            and (operand.area, operand.byte) == (byte.area, byte.byte))
