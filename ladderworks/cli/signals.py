"""CLI command `signals`: look up F, G, X and Y signals by address, name or text."""

from __future__ import annotations

import argparse
import sys

from ladderworks.core.signals import Signal, search


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add `signals [QUERY]`."""
    parser = subparsers.add_parser(
        "signals", help="list the signals matching an address, a name or words (all without one)")
    parser.add_argument(
        "query", nargs="*", metavar="QUERY",
        help="an address (G8.4, G8), a name (SPL) or words (acil dur); Turkish letters optional")
    parser.set_defaults(handler=_signals)


def signal_line(signal: Signal) -> str:
    """One line: address, name, English, Turkish, notes and board, two spaces apart."""
    fields = [str(signal.address), signal.name, signal.english, signal.turkish, signal.notes]
    if signal.board:
        fields.append(f"[{signal.board}]")
    return "  ".join(field for field in fields if field)


def _signals(args: argparse.Namespace) -> int:
    query = " ".join(args.query)
    found = search(query)
    if not found:
        print(f"ladderworks-cli signals: no signal matches '{query}'", file=sys.stderr)
        return 1
    for signal in found:
        print(signal_line(signal))
    return 0
