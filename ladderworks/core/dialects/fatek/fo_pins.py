"""A box's FO1, FO2 … read on the box's own network (its output pins) where it can be drawn so."""

from __future__ import annotations

from collections.abc import Iterable

from ladderworks.core.address import Address
from ladderworks.core.dialects.fatek.listing import Record
from ladderworks.core.il.program import Instruction
from ladderworks.core.instructions import Combine, Kind

_COILS = ("OUT", "OUTS", "OUTR", "SET", "RST")


def _reads_byte(ins: Instruction, fo: Address) -> bool:
    """Whether an instruction reads a bit of the box's FO byte (an earlier pin)."""
    operand = ins.operand
    return ins.spec.is_contact and operand is not None and \
        (operand.area, operand.byte) == (fo.area, fo.byte)


def _is_coil(record: Record) -> bool:
    """A coil record (not a TR point, not the RST box of a timer or counter)."""
    if record.mnemonic not in _COILS or record.modifier == "TR":
        return False
    operand = record.operand.upper()
    return not (record.mnemonic == "RST" and operand[:1] in ("T", "C"))


def _in_series(ins: Instruction) -> bool:
    """A plain contact in series after a pin (`AND X3`, `AND NOT X4`)."""
    spec = ins.spec
    return spec.kind is Kind.BASIC and spec.is_contact and spec.combine is Combine.AND \
        and not spec.pushes


def _series_record(record: Record) -> bool:
    """`AND X3` / `AND NOT X4` (not an edge contact, not a TR point)."""
    return record.mnemonic == "AND" and record.modifier in ("", "NOT")


def on_the_box(instructions: list[Instruction], fo: Address, after: Iterable[Record]) -> bool:
    """Whether `FO n` stays on its box's network as a pin: the network ends with the box and
    its outputs (coils on its pins, contacts in series after a pin), and the records after
    `FO n` (to the next FO, END or the network's end) are contacts in series (`AND X3`,
    `AND NOT X4`: drawn after the pin) then one or more coils."""
    last = next((i for i in range(len(instructions) - 1, -1, -1)
                 if instructions[i].spec.kind is Kind.FUNCTION), None)
    if last is None or fo not in instructions[last].params:
        return False
    if not all(ins.spec.is_coil or _reads_byte(ins, fo) or _in_series(ins)
               for ins in instructions[last + 1:]):
        return False
    count = 0
    for record in after:
        if record.mnemonic in ("FO", "END"):
            break
        if not count and _series_record(record):
            continue
        if not _is_coil(record):
            return False
        count += 1
    return count > 0
