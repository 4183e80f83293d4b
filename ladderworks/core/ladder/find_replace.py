"""Find and replace addresses across a ladder program, typed as addresses or program symbols."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace

from ladderworks.core import dialects
from ladderworks.core.address import Address, AddressError
from ladderworks.core.diagnostics import Refused
from ladderworks.core.il.program import Instruction, ParamValue
from ladderworks.core.ladder.edits import Edit
from ladderworks.core.ladder.model import Cell, Coil, Contact, FunctionBox, LadderNetwork
from ladderworks.core.signals import fold
from ladderworks.core.symbols import SymbolTable, resolve

OPERAND = -1  # `Found.slot` of a contact's or coil's own address (an instruction's operand)


@dataclass(frozen=True, slots=True)
class Query:
    """What to find: one address (a byte also finds its bits), else words in addresses and
    program symbols."""

    text: str
    address: Address | None = None

    def matches(self, address: Address, symbols: SymbolTable | None) -> bool:
        """True when `address` is what the query finds."""
        wanted = self.address
        if wanted is not None:
            return address == wanted or (
                wanted.bit is None and address.bit is not None
                and address.byte_address() == wanted)
        words = fold(self.text)
        if words in fold(str(address)):
            return True
        return symbols is not None and words in fold(symbols.symbol(address))


@dataclass(frozen=True, slots=True)
class Found:
    """One place an address is used: network, element anchor (None in a network kept as an
    instruction listing, then `instruction` is its index) and slot (OPERAND or parameter k)."""

    network: int
    cell: Cell | None
    address: Address
    slot: int = OPERAND
    instruction: int | None = None


def _typed(text: str, symbols: SymbolTable | None, dialect: str | None,
           want: str | None = None) -> Address:
    """A typed address: a program symbol or the PMC's spelling, or a device of the program's
    dialect (Delta's `X17`, `D0`: `want` "bit" or "word" for a T/C), else a name the program's
    symbols hold as written (an S7 tag `"Start"`, `#Run`). AddressError."""
    if dialects.get(dialect) is not None:
        try:
            return dialects.parse_target(text, dialect, want)[0]
        except AddressError:
            named = symbols.by_symbol.get(text) if symbols is not None else None
            if named is None:
                raise
            return named
    return resolve(text, symbols)


def parse_query(text: str, symbols: SymbolTable | None = None,
                dialect: str | None = None) -> Query | None:
    """The query a typed text means (None for a blank text): an address or a program symbol
    finds that address (in a Delta program a device, `M10`); other words are looked for in
    addresses and symbols."""
    text = text.strip()
    if not text:
        return None
    try:
        return Query(text, _typed(text, symbols, dialect))
    except AddressError:
        return Query(text)


def _box_params(params: tuple[ParamValue, ...]) -> list[tuple[int, Address]]:
    return [(k, p) for k, p in enumerate(params) if isinstance(p, Address)]


def find(networks: Sequence[LadderNetwork], query: Query,
         symbols: SymbolTable | None = None) -> list[Found]:
    """Every use of a matching address, network by network, top to bottom, left to right."""
    memo: dict[Address, bool] = {}  # an address is judged once (words: its symbol folded)

    def matches(address: Address) -> bool:
        known = memo.get(address)
        if known is None:
            known = memo[address] = query.matches(address, symbols)
        return known

    found: list[Found] = []
    for index, network in enumerate(networks):
        if network.listing is not None:
            for number, instruction in enumerate(network.listing):
                found += _in_instruction(index, number, instruction, matches)
            continue
        here: list[Found] = []
        for cell, element in network.cells.items():  # wires are most cells: type() is quick
            kind = type(element)
            if kind is Contact or kind is Coil:
                address = element.address  # type: ignore[union-attr]
                if address is not None and matches(address):
                    here.append(Found(index, cell, address))
            elif kind is FunctionBox:
                here += [Found(index, cell, address, k)
                         for k, address in _box_params(element.params)  # type: ignore[union-attr]
                         if matches(address)]
        if len(here) > 1:
            here.sort(key=lambda hit: (hit.cell, hit.slot))
        found += here
    return found


def _in_instruction(index: int, number: int, instruction: Instruction,
                    matches: Callable[[Address], bool]) -> list[Found]:
    found = []
    if instruction.operand is not None and matches(instruction.operand):
        found.append(Found(index, None, instruction.operand, OPERAND, number))
    found += [Found(index, None, address, k, number)
              for k, address in _box_params(instruction.params) if matches(address)]
    return found


def replacement_address(text: str, query: Query | None,
                        symbols: SymbolTable | None = None, dialect: str | None = None
                        ) -> Address:
    """The address a typed replacement names; Refused when the query is not one address, the
    replacement is not an address or symbol, or a bit would replace a byte (or the reverse)."""
    if query is None or query.address is None:
        raise Refused("replace-needs-address", text=query.text if query is not None else "")
    # AddressError is a Refused with the address's reason
    new = _typed(text.strip(), symbols, dialect, "word" if query.address.bit is None else "bit")
    if (new.bit is None) != (query.address.bit is None):
        raise Refused("replace-kind", found=str(query.address), replacement=str(new))
    if new == query.address:
        raise Refused("replace-same", found=str(new))
    return new


def _moved(address: Address, query: Query, new: Address) -> Address:
    """`address` (a hit of `query`) moved to `new`: a byte's bits keep their bit number."""
    if query.address is not None and query.address.bit is None and address.bit is not None:
        return new.with_bit(address.bit)
    return new


def replacements(networks: Sequence[LadderNetwork], hits: Sequence[Found], query: Query,
                 new: Address, written: str = "",
                 spell: Callable[[Address], str] = str) -> list[tuple[int, Edit]]:
    """The edits that replace the hits' addresses with `new`, one per network (in network
    order), not applied: `edit.apply(network)` makes it and returns the undo. An element drawn
    with its operand as written (S7's `"Start"`) gets `written` (the replacement as typed), or
    the address spelled by `spell` where a byte's bit moved."""
    by_network: dict[int, list[Found]] = {}
    for hit in hits:
        by_network.setdefault(hit.network, []).append(hit)
    edits = []
    for index in sorted(by_network):
        work = networks[index].copy()
        for hit in by_network[index]:
            if hit.instruction is not None:
                _replace_in_listing(work, hit, _moved(hit.address, query, new))
            elif hit.cell is not None:
                moved = _moved(hit.address, query, new)
                shown = written.strip() if moved == new and written.strip() else spell(moved)
                _replace_in_cell(work, hit, moved, shown,
                                 {query.text.strip(), spell(hit.address)})
        edits.append((index, Edit(work.state())))
    return edits


def _swap(params: tuple[ParamValue, ...], slot: int, new: Address) -> tuple[ParamValue, ...]:
    return (*params[:slot], new, *params[slot + 1:])


def _replace_in_cell(work: LadderNetwork, hit: Found, new: Address, shown: str,
                     old: set[str]) -> None:
    """The hit's address replaced; an operand drawn as written (`texts`, a named pin's text
    that is one of the `old` texts, quoted or not) shows `shown`."""
    assert hit.cell is not None
    element = work.cells[hit.cell]
    if isinstance(element, Contact | Coil) and hit.slot == OPERAND:
        texts = (shown, *element.texts[1:]) if element.texts else ()
        work.cells[hit.cell] = replace(element, address=new, texts=texts)
    elif isinstance(element, FunctionBox):
        names = {_bare(text) for text in old}
        named = tuple(replace(pin, text=shown) if _bare(pin.text) in names else pin
                      for pin in element.named)
        work.cells[hit.cell] = replace(element, params=_swap(element.params, hit.slot, new),
                                       named=named)


def _bare(text: str) -> str:
    """An operand text without its quotes (S7's `"Geçen Süre"` is the tag Geçen Süre)."""
    return text.strip().strip('"')


def _replace_in_listing(work: LadderNetwork, hit: Found, new: Address) -> None:
    assert work.listing is not None and hit.instruction is not None
    listing = list(work.listing)
    instruction = listing[hit.instruction]
    if hit.slot == OPERAND:
        listing[hit.instruction] = instruction._replace(operand=new)
    else:
        listing[hit.instruction] = instruction._replace(
            params=_swap(instruction.params, hit.slot, new))
    work.listing = tuple(listing)
