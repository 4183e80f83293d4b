"""How a program's addresses, operands and instructions are written for display, by dialect.

The console, the diagnostic view, the cross reference and printing show a Delta program in
Delta's spelling (`X17`, `LD= T0 K5`) and a PMC program in the PMC's (`X1.7`): one `Spelling`
per dialect, chosen by `Program.dialect`.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from functools import cache

from ladderworks.core import dialects
from ladderworks.core.address import Address
from ladderworks.core.il.program import Instruction
from ladderworks.core.instructions import InstructionSpec


@dataclass(frozen=True, slots=True)
class Spelling:
    """The display texts of one dialect; `dialect` "" for the PMC's own."""

    dialect: str
    address: Callable[[Address], str]
    params: Callable[[InstructionSpec, tuple], list[str]]
    instruction: Callable[[Instruction], str]
    name: Callable[[InstructionSpec], str]


def _pmc() -> Spelling:
    from ladderworks.core.il.printer import format_params, print_instruction

    return Spelling("", str, format_params, print_instruction, lambda spec: spec.text_name)


@cache
def spelling(dialect: str | None) -> Spelling:
    """The spelling of programs of `dialect` ("seed"/"fanuc"/None: the PMC's)."""
    found = dialects.get(dialect)
    if found is None:
        return _pmc()
    if found.spelling:
        make = found.function(found.spelling)
        made = make()
        assert isinstance(made, Spelling)
        return made
    pmc = _pmc()
    return Spelling(found.name, found.format_address, pmc.params, pmc.instruction,
                    found.instruction_name)
