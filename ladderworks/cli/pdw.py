"""CLI command `pdw`: a WinProladder project's program as WinProladder's mnemonic listing (the
lines the other commands' FILE:LINE refer to for a .pdw) and its element comments."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add `pdw FILE [--comments]`."""
    parser = subparsers.add_parser(
        "pdw", help="print a WinProladder project's (.pdw) program as its mnemonic listing")
    parser.add_argument("file", metavar="FILE")
    parser.add_argument("--comments", action="store_true",
                        help="print its element comments (DEVICE<TAB>COMMENT) instead")
    parser.set_defaults(handler=_pdw)


def _pdw(args: argparse.Namespace) -> int:
    from ladderworks.core.diagnostics import Diagnostic
    from ladderworks.core.dialects.fatek.pdw_file import is_pdw, read_pdw

    try:
        data = Path(args.file).read_bytes()
    except OSError as error:
        print(f"ladderworks-cli pdw: {args.file}: {error.strerror or error}", file=sys.stderr)
        return 1
    if not is_pdw(data):
        print(Diagnostic("pdw-header", {"offset": 0}, 1, 1).located(args.file), file=sys.stderr)
        return 1
    pdw = read_pdw(data)
    if args.comments:
        for device, text in pdw.comments.items():
            print(f"{device}\t{text}")
    else:
        for line in pdw.lines:
            print(line)
    if pdw.error is not None:
        where = Diagnostic(pdw.error.code, dict(pdw.error.args_map), max(1, len(pdw.lines)), 1)
        print(where.located(args.file), file=sys.stderr)
        return 1
    return 0
