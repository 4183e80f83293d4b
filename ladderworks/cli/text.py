"""CLI commands on program text: `check` and `format`."""

from __future__ import annotations

import argparse
import sys

from ladderworks.cli._programs import add_dialect_option, forced_dialect, load_program
from ladderworks.core.compiler import check
from ladderworks.core.diagnostics import Diagnostic, has_errors
from ladderworks.core.il import parse_for_check


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add `check` and `format`."""
    check = subparsers.add_parser("check", help="check programs, print FILE:LINE:COL: CODE message")
    check.add_argument("files", nargs="+", metavar="FILE")
    add_dialect_option(check)
    check.set_defaults(handler=_check)
    fmt = subparsers.add_parser("format", help="print a program in canonical form")
    fmt.add_argument("file", metavar="FILE")
    add_dialect_option(fmt)
    fmt.set_defaults(handler=_format)


def check_path(name: str) -> list[Diagnostic]:
    """Everything `check` reports for a file: the parser's diagnostics and, when they hold no
    error, the compiler's (the checks `compile` runs), by line; the file parsed once."""
    result = parse_for_check(name, forced_dialect())
    if not result.ok:
        return result.diagnostics
    return sorted(result.diagnostics + check(result.program), key=lambda d: (d.line, d.column))


def _check(args: argparse.Namespace) -> int:
    failed = False
    for name in args.files:
        diagnostics = check_path(name)
        for diagnostic in diagnostics:
            print(diagnostic.located(name))
        failed = failed or has_errors(diagnostics)
    return 1 if failed else 0


def _format(args: argparse.Namespace) -> int:
    from ladderworks.core.il import print_program  # `check` loads no printer

    program = load_program(args.file)
    if program is None:
        return 1
    sys.stdout.write(print_program(program))
    return 0
