"""S7 programs as text: the S7 spelling of the engine's networks (display, `format`). An unchanged
block is saved byte for byte by the faithful save; a changed one is written as SIMATIC SD or
SimaticML by saving.py (`Dialect.writer`) when its graph holds the change, else Save refuses
it (`Dialect.refuse_changes`)."""

from __future__ import annotations

from ladderworks.core.address import Address, Area
from ladderworks.core.dialects.s7.devices import M_BYTES, format_absolute
from ladderworks.core.dialects.spelling import Spelling
from ladderworks.core.il.program import Instruction, Network
from ladderworks.core.instructions import InstructionSpec


def network_lines(network: Network, first: bool) -> list[str]:
    """An engine network as LadderWorks' listing in S7 spelling, each line a `//` comment (the
    CLI's `format` and `mnemonic`): not SIMATIC SD. Save never writes these: a changed S7
    program is written by saving.py or refused first (docs/dialects.md)."""
    lines = [f"// {comment}" for comment in network.comments]
    lines += [f"//   {instruction_text(instruction)}" for instruction in network.instructions]
    return lines


def mnemonic_of(spec: InstructionSpec) -> str:
    """A row's name as S7 says it: `TON` for S7.TON, the engine's own otherwise."""
    return spec.mnemonic if spec.dialect == "s7" and spec.mnemonic else spec.text_name




_ALWAYS = {Address(Area.R, 9091, 1): "TRUE", Address(Area.R, 9091, 0): "FALSE"}


def address_text(address: Address) -> str:
    """An address as S7 writes it (`%I0.0`, `%MB2`); the engine's own for the others."""
    if address in _ALWAYS:
        return _ALWAYS[address]
    if address.area is Area.R and address.byte >= M_BYTES:
        return str(address)  # a LadderWorks relay linking the parts of a network
    return format_absolute(address) or str(address)


def params_text(spec: InstructionSpec, params: tuple) -> list[str]:
    """A box's operands: addresses in S7's spelling, labels as `L n`, the rest as numbers."""
    texts: list[str] = []
    for value in params:
        if isinstance(value, Address):
            texts.append(address_text(value))
        else:
            texts.append(str(value))
    return texts


def instruction_text(instruction: Instruction) -> str:
    """One instruction on one line in S7's spelling (`RD %I0.0`, `TON D0 10000 %MB0`)."""
    spec = instruction.spec
    parts = [mnemonic_of(spec)]
    if instruction.operand is not None:
        parts.append(address_text(instruction.operand))
    parts += params_text(spec, instruction.params)
    return " ".join(parts)


def spelling() -> Spelling:
    """S7's display texts (core/dialects/spelling.py)."""
    return Spelling("s7", address_text, params_text, instruction_text, mnemonic_of)
