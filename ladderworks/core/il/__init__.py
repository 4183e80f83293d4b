"""The LadderWorks instruction-list language: parse `.LAD` / `.MOD` text and print it back."""

from ladderworks.core.il.parser import (
    ParseResult,
    check_file,
    decode,
    parse,
    parse_bytes,
    parse_file,
)
from ladderworks.core.il.printer import print_instruction, print_program
from ladderworks.core.il.program import Instruction, Network, Program, Section

__all__ = [
    "Instruction",
    "Network",
    "ParseResult",
    "Program",
    "Section",
    "check_file",
    "decode",
    "parse",
    "parse_bytes",
    "parse_file",
    "print_instruction",
    "print_program",
]
