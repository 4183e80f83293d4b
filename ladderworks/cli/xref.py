"""CLI command `xref`: where a program reads and writes each address (docs/cross-reference.md)."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

from ladderworks.cli._programs import add_dialect_option, load_program
from ladderworks.core import dialects
from ladderworks.core.address import Address, AddressError, looks_like_address
from ladderworks.core.dialects.spelling import spelling
from ladderworks.core.instructions import spec_for
from ladderworks.core.symbols import SymbolTable, describe, resolve
from ladderworks.core.tag_names import TagNames, network_names
from ladderworks.core.xref import Access, CrossReference, Use, UseKind

HEADERS = ("ADDRESS", "SYMBOL", "NETWORK", "LABEL", "UNIT", "LINE", "INSTRUCTION", "ELEMENT",
           "ACCESS")

_KIND_TEXT = {
    UseKind.CONTACT: "contact", UseKind.CONTACT_NOT: "NOT contact", UseKind.COIL: "coil",
    UseKind.COIL_NOT: "NOT coil", UseKind.SET: "SET coil", UseKind.RESET: "RST coil",
    UseKind.PARAMETER: "parameter", UseKind.NUMBER: "number",
}
_ACCESS_TEXT = {Access.READ: "read", Access.WRITE: "write", Access.READ_WRITE: "read+write"}


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add `xref FILE [ADDR ...]`."""
    parser = subparsers.add_parser(
        "xref", help="cross reference: where each address is read and written")
    parser.add_argument("file", metavar="FILE")
    add_dialect_option(parser)
    parser.add_argument(
        "addresses", nargs="*", metavar="ADDR",
        help="an address (X21.7, R100) or a program symbol (ESKIP); all addresses without one")
    parser.set_defaults(handler=_xref)


def element_text(use: Use) -> str:
    """The element kind in words, with the parameter's name (`parameter output`)."""
    text = _KIND_TEXT[use.kind]
    return f"{text} {use.parameter}" if use.parameter else text


def use_row(use: Use, symbols: SymbolTable | None, dialect: str | None = None,
            names: TagNames | None = None, titles: Sequence[str] = ()) -> tuple[str, ...]:
    """One table row: the columns of HEADERS (a Delta program's in Delta's spelling; an S7
    program's by tag, its network as TIA names it: `Network 3: Title`)."""
    spelled = spelling(dialect)
    if names is not None and names.typed:
        spec = spec_for(use.instruction)
        named = names.name_of(use.address, use.width)
        written = names.spelled(use.address, names.width_of(use.address, use.width)) or "-"
        name = spelled.name(spec) if spec is not None else use.instruction
        network = titles[use.network] if use.network < len(titles) else ""
        return (written, named or "-", network or "-",
                use.label or "-", use.unit or "-", str(use.line or "-"), name,
                element_text(use), _ACCESS_TEXT[use.access])
    if spelled.dialect:
        spec = spec_for(use.instruction)
        written = spelled.address(use.address)
        name = spelled.name(spec) if spec is not None else use.instruction
        described = "-"
    else:
        written = str(use.address) + (f":{use.width}" if use.width > 1 else "")
        name = use.instruction
        described = describe(use.address, symbols) or "-"
    return (written, described, str(use.network + 1), use.label or "-", use.unit or "-",
            str(use.line or "-"), name, element_text(use), _ACCESS_TEXT[use.access])


def table(rows: Sequence[tuple[str, ...]]) -> str:
    """Rows under HEADERS, columns padded to their widest cell (the last is not padded)."""
    widths = [max(len(row[k]) for row in (HEADERS, *rows)) for k in range(len(HEADERS))]
    lines = []
    for row in (HEADERS, *rows):
        cells = [cell.ljust(width) for cell, width in zip(row[:-1], widths, strict=False)]
        lines.append("  ".join([*cells, row[-1]]))
    return "\n".join(lines) + "\n"



def _xref(args: argparse.Namespace) -> int:
    program = load_program(args.file)
    if program is None:
        return 1
    symbols = program.symbols
    names = TagNames.of(program)
    titles = network_names(program) if names.typed else []
    queries: list[tuple[str, Address]] = []
    for text in args.addresses:
        try:
            queries.append((text, names.resolve(text).address if names.typed
                            else dialects.parse_target(text, program.dialect)[0]
                            if dialects.get(program.dialect) else resolve(text, symbols)))
        except AddressError as error:
            reason = (error.diagnostic.message() if looks_like_address(text)
                      else f"'{text}' is neither an address nor a symbol of {args.file}")
            print(f"ladderworks-cli xref: {reason}", file=sys.stderr)
            return 2
    xref = CrossReference.from_program(program)
    if not queries:
        sys.stdout.write(table([use_row(use, symbols, program.dialect, names, titles)
                                for use in xref.sorted_uses()
                                if not names.internal(use.address)]))
        return 0
    rows: list[tuple[str, ...]] = []
    unused = False
    for text, address in queries:
        uses = [use for use in xref.uses_of(address) if not names.internal(use.address)]
        if not uses:
            named = text if text == str(address) else f"{text} ({address})"
            print(f"ladderworks-cli xref: {named} is not used in {args.file}", file=sys.stderr)
            unused = True
        rows += [use_row(use, symbols, program.dialect, names, titles) for use in uses]
    if rows:
        sys.stdout.write(table(rows))
    return 1 if unused else 0
