"""Find in texts (Edit › Find, "Also in comments and signal descriptions"): the elements whose
own comment, program comment or manual description holds the words, and the network comments."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from ladderworks.core.address import Address
from ladderworks.core.ladder.model import Cell, Coil, Contact, LadderNetwork
from ladderworks.core.signals import fold
from ladderworks.core.symbols import SymbolTable
from ladderworks.gui.symbol_text import name_and_text


@dataclass(frozen=True, slots=True)
class TextHit:
    """A place whose text holds the words: an element (its address) or a network's comment
    line (address None, cell (line, 0) of the comment)."""

    network: int
    cell: Cell | None
    address: Address | None
    comment_line: int | None = None


def find_in_texts(networks: Sequence[LadderNetwork], text: str,
                  symbols: SymbolTable | None) -> list[TextHit]:
    """Every element (contact or coil) whose comment, program symbol comment or manual
    description (in the UI language) holds `text`, and every network comment line that does,
    network by network; case and Turkish letters folded as Find does."""
    words = fold(text.strip())
    if not words:
        return []
    memo: dict[Address, bool] = {}

    def described(address: Address) -> bool:
        known = memo.get(address)
        if known is None:
            names = name_and_text(address, symbols)
            known = memo[address] = names is not None and any(
                words in fold(part) for part in names if part)
        return known

    hits: list[TextHit] = []
    for index, network in enumerate(networks):
        hits += [TextHit(index, None, None, line)
                 for line, comment in enumerate(network.comments) if words in fold(comment)]
        here: list[TextHit] = []
        for cell, element in network.cells.items():
            if not isinstance(element, Contact | Coil) or element.address is None:
                continue
            if words in fold(element.comment or "") or described(element.address):
                here.append(TextHit(index, cell, element.address))
        here.sort(key=lambda hit: hit.cell or (0, 0))
        hits += here
    return hits
