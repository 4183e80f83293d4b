"""A TR point read back as one of a box's inputs (`OUT TR 0`, `AND OPEN`, `LD TR 0`, `FUN 140`):
the block the point saved is copied where it is read, so the box's inputs are plain logic and
the network draws as one box with its inputs wired (docs/dialects.md, Fatek)."""

from __future__ import annotations

from ladderworks.core.address import Address
from ladderworks.core.dialects.fatek.branches import Lowered
from ladderworks.core.il.program import Instruction
from ladderworks.core.instructions import Combine, Kind, Write


def block_start(instructions: list[Instruction]) -> int | None:
    """Where the value on top of the stack began (its RD / RD.STK), None when a box with
    several inputs, a coil or anything but contact logic made it."""
    needed = 1
    for index in range(len(instructions) - 1, -1, -1):
        spec = instructions[index].spec
        if spec.kind is Kind.FUNCTION:
            if spec.inputs != ("IN",):
                return None
            continue  # an edge or comparison contact: in series with what is before it
        if spec.write is not Write.NONE:
            return None
        if not spec.operand:  # AND.STK / OR.STK: one more value below
            needed += 1
            continue
        if spec.combine is Combine.READ:
            needed -= 1
            if needed == 0:
                return index
    return None


def pushed_copy(block: list[Instruction], line: int, column: int) -> list[Instruction]:
    """The block's instructions again, its first read pushing (RD -> RD.STK), at `line`."""
    first = block[0]
    name = first.name if first.spec.pushes else first.name + ".STK"
    copies = [Instruction(name, first.operand, line=line, column=column)]
    copies += [ins._replace(line=line, column=column) for ins in block[1:]]
    return copies


def drop_unread(parts: list[Lowered], points: dict[Address, int]) -> None:
    """Remove the `OUT TR n` of points no instruction reads any more (all copied)."""
    read = {ins.operand for part in parts for ins in part.instructions
            if ins.spec.kind is Kind.BASIC and ins.spec.write is Write.NONE and ins.operand}
    for part in parts:
        keep = [k for k, ins in enumerate(part.instructions)
                if not (ins.spec.write is Write.OUT and not ins.spec.negated
                        and ins.operand in points and ins.operand not in read)]
        if len(keep) != len(part.instructions):
            part.instructions = [part.instructions[k] for k in keep]
            part.records = [part.records[k] for k in keep]
