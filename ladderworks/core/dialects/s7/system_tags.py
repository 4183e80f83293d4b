"""Names a block uses that no tag table read declares: TIA's default names of the system and
clock memory bits, and any other tag or DB member not exported with the block.

A block exported alone names `"AlwaysTRUE"`, `"FirstScan"`, `"Clock_1Hz"` … without the
default tag table that declares them; LadderWorks models the system byte at %MB1 and the
clock byte at %MB0 (docs/dialects.md, S7-1200 memory), so those names are given their
addresses there when the program's own tags do not declare them [LW].
"""

from __future__ import annotations

from ladderworks.core.address import AddressError
from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.dialects.s7.devices import parse_absolute
from ladderworks.core.dialects.s7.graph import Block, Operand, OperandKind, Part, S7Program, Tag

TABLE = "System memory (TIA's default names)"
UNDECLARED = "Not in the tag tables read (laid out by LadderWorks)"
DEFAULTS: dict[str, tuple[str, str]] = {
    "System_Byte": ("Byte", "%MB1"), "FirstScan": ("Bool", "%M1.0"),
    "DiagStatusUpdate": ("Bool", "%M1.1"), "AlwaysTRUE": ("Bool", "%M1.2"),
    "AlwaysFALSE": ("Bool", "%M1.3"), "Clock_Byte": ("Byte", "%MB0"),
    "Clock_10Hz": ("Bool", "%M0.0"), "Clock_5Hz": ("Bool", "%M0.1"),
    "Clock_2.5Hz": ("Bool", "%M0.2"), "Clock_2Hz": ("Bool", "%M0.3"),
    "Clock_1.25Hz": ("Bool", "%M0.4"), "Clock_1Hz": ("Bool", "%M0.5"),
    "Clock_0.625Hz": ("Bool", "%M0.6"), "Clock_0.5Hz": ("Bool", "%M0.7"),
}
_BY_LOWER = {name.lower(): name for name in DEFAULTS}
_SPELLING = {name.lower(): name for name in (  # a guessed type as TIA spells it
    "Bool", "SInt", "Int", "DInt", "USInt", "UInt", "UDInt", "Real", "LReal", "Time", "Byte",
    "Word", "DWord", "Char")}


def implied(blocks: list[Block], tags: list[Tag]) -> list[Tag]:
    """The default system/clock memory tags the blocks name and neither the tags nor the
    blocks declare."""
    declared = {t.name.lower() for t in tags} | {b.name.lower() for b in blocks}
    found: dict[str, Tag] = {}
    for block in blocks:
        for network in block.networks:
            operands = [w.source.operand for w in network.wires] + \
                [t.operand for w in network.wires for t in w.targets]
            for operand in operands:
                if operand is None or operand.kind is not OperandKind.GLOBAL or \
                        len(operand.path) != 1:
                    continue
                name = _BY_LOWER.get(operand.path[0].lower())
                if name is not None and name.lower() not in declared:
                    type_name, address = DEFAULTS[name]
                    found.setdefault(name, Tag(name, type_name, address, "", TABLE))
    return list(found.values())


def declare(program: S7Program, operand: Operand, guess: str, network: int, part: Part
            ) -> Diagnostic | None:
    """Make a tag of a global name nothing declares (`"DB".a.b` as one name) [LW]: at the
    address the export shows (Informative) when LadderWorks has that area, else of type
    `guess`, laid out in the D area; its warning at the network and part. None (nothing made)
    for a name a block or tag has, or with neither address nor type."""
    if not (guess or operand.address) or operand.kind is not OperandKind.GLOBAL or \
            not operand.path or program.block(operand.path[0]) is not None or \
            program.tag(operand.path[0]) is not None:
        return None
    name = ".".join(operand.path)
    guess = _SPELLING.get(guess.lower(), guess)
    address = operand.address if len(operand.path) == 1 else ""
    try:
        if address:
            parse_absolute(address)
    except AddressError:
        address = ""
    program.tags.append(Tag(name, guess, address, "", UNDECLARED))
    return Diagnostic("s7-tag-undeclared", {
        "network": network, "uid": part.uid, "text": operand.display(),
        "type": address or guess}, part.line, 1, Severity.WARNING)


def constant_of(program: S7Program, operand: Operand) -> Operand | None:
    """A user constant of the tag tables (`"MAX_COUNT"`, `GlobalConstant` in SimaticML) named
    by `operand`, as the constant it stands for; None for anything else."""
    if operand.kind is not OperandKind.GLOBAL or len(operand.path) != 1:
        return None
    tag = program.tag(operand.path[0])
    if tag is None or not tag.value:
        return None
    value = tag.value.strip()
    if value.upper() in ("TRUE", "FALSE"):
        return Operand(OperandKind.CONSTANT, (), value.upper(), "Bool")
    return Operand(OperandKind.CONSTANT, (), value, tag.type_name)
