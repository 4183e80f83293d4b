"""The LadderWorks instruction-list language: parse `.LAD` / `.MOD` text and print it back."""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ladderworks.core.il.parser import ParseResult, decode, parse
    from ladderworks.core.il.printer import print_instruction, print_program
    from ladderworks.core.il.program import Instruction, Network, Program, Section
    from ladderworks.core.il.reading import parse_bytes, parse_file, parse_for_check

__all__ = [
    "Instruction",
    "Network",
    "ParseResult",
    "Program",
    "Section",
    "decode",
    "parse",
    "parse_bytes",
    "parse_file",
    "parse_for_check",
    "print_instruction",
    "print_program",
]

# The module of each name, imported when the name is first asked for (PEP 562): `check` loads
# no printer, and importing il.program loads no parser.
_MODULE_OF = {
    "ParseResult": "parser", "decode": "parser", "parse": "parser",
    "parse_bytes": "reading", "parse_file": "reading", "parse_for_check": "reading",
    "print_instruction": "printer", "print_program": "printer",
    "Instruction": "program", "Network": "program", "Program": "program", "Section": "program",
}


def __getattr__(name: str) -> object:
    """A name of the package, imported from its module when first asked for."""
    module = _MODULE_OF.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f"{__name__}.{module}"), name)
    globals()[name] = value
    return value
