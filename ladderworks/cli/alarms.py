"""CLI command `alarms`: check an AlarmMsg.dat file and list its messages."""

from __future__ import annotations

import argparse
import sys

from ladderworks import paths
from ladderworks.core.alarms import alarm_address, format_number, load_alarm_file
from ladderworks.core.diagnostics import has_errors


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add `alarms [FILE]`."""
    parser = subparsers.add_parser(
        "alarms", help="check an AlarmMsg.dat and list its messages as NNN  A0.0  text")
    parser.add_argument("file", nargs="?", default=str(paths.alarm_file()),
                        metavar="FILE", help="the message file (default: the sample)")
    parser.set_defaults(handler=_alarms)


def _alarms(args: argparse.Namespace) -> int:
    table, diagnostics = load_alarm_file(args.file)
    for number in table:
        print(f"{format_number(number)}  {alarm_address(number)}  {table.messages[number]}")
    for diagnostic in diagnostics:
        print(diagnostic.located(args.file), file=sys.stderr)
    return 1 if has_errors(diagnostics) else 0
