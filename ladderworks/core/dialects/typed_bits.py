"""A contact's or coil's device typed in the editor, read as the dialect's reader reads its line.

The editor takes what the dialect's text takes and refuses what it refuses: `LD T0` is Delta's
timer contact, `OUT X0` is refused as the reader refuses it (`dialect-operand`). The typed text
is written as the one line the element is (after a contact on X0 for a coil) and read back."""

from __future__ import annotations

from ladderworks.core import dialects
from ladderworks.core.address import Address
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.instructions import InstructionSpec, Write, lookup

_START = "RD"  # the row of a contact that starts a rung (every dialect spells it: LD, ORG)


def read_bit(spec: InstructionSpec, text: str, dialect: str) -> Address | Diagnostic:
    """The Address of the device `text` typed on an element of row `spec` (a contact's RD or
    RD.NOT, a coil's WRT/SET/RST/own row) in a program of `dialect`, or the reader's diagnostic
    (its column counted in `text`)."""
    from ladderworks.core.il.reading import parse_text

    found = dialects.get(dialect)
    start = lookup(_START)
    if found is None or start is None:
        raise ValueError(dialect)
    typed = text.strip()
    head = f"{found.instruction_name(spec)} "
    lines = [head + typed]
    if spec.write is not Write.NONE:  # a coil: after a contact on X0
        lines.insert(0, f"{found.instruction_name(start)} X0")
    result = parse_text("\n".join([*lines, "END", ""]), dialect)
    errors = [d for d in result.diagnostics if d.is_error]
    if errors:
        return errors[0]
    read = [i for i in result.program.instructions() if i.name != start.name or not lines[1:]]
    for instruction in read:
        if instruction.name == spec.name and isinstance(instruction.operand, Address):
            return instruction.operand
    other = lookup(read[0].name) if read else None  # Delta's RST T0: a word's reset
    return Diagnostic("typed-other-row", {
        "text": typed, "name": found.instruction_name(spec),
        "other": found.instruction_name(other) if other is not None else "?"})
