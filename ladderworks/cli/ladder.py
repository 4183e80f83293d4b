"""CLI commands on the ladder: `ladder` (text-art drawing) and `mnemonic` (grid round trip)."""

from __future__ import annotations

import argparse
import sys

from ladderworks.cli._programs import add_dialect_option, load_program
from ladderworks.core.il import print_program
from ladderworks.core.ladder.art import draw_document
from ladderworks.core.ladder.convert import ladder_to_program, program_to_ladder


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add `ladder` and `mnemonic`."""
    ladder = subparsers.add_parser("ladder", help="print a program as ladder text art")
    ladder.add_argument("file", metavar="FILE")
    add_dialect_option(ladder)
    ladder.set_defaults(handler=_ladder)
    mnemonic = subparsers.add_parser(
        "mnemonic", help="convert a program to the ladder grid and back; print the .MOD text")
    mnemonic.add_argument("file", metavar="FILE")
    add_dialect_option(mnemonic)
    mnemonic.set_defaults(handler=_mnemonic)



def _ladder(args: argparse.Namespace) -> int:
    program = load_program(args.file)
    if program is None:
        return 1
    sys.stdout.write(draw_document(program_to_ladder(program)))
    return 0


def _mnemonic(args: argparse.Namespace) -> int:
    program = load_program(args.file)
    if program is None:
        return 1
    converted, diagnostics = ladder_to_program(program_to_ladder(program))
    for diagnostic in diagnostics:
        print(f"{args.file}: network {(diagnostic.network or 0) + 1} cell {diagnostic.cell}: "
              f"{diagnostic.code} {diagnostic.message()}", file=sys.stderr)
    sys.stdout.write(print_program(converted))
    return 1 if diagnostics else 0
