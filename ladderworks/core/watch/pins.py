"""The live values beside a named box's pins in monitoring (TIA shows PT, ET, CV … there): each
pin's operand as the watch table finds and shows it (places.py, values.py)."""

from __future__ import annotations

from ladderworks.core.ladder.model import FunctionBox
from ladderworks.core.symbols import SymbolTable
from ladderworks.core.watch.places import WatchError, WatchPlace, resolve
from ladderworks.core.watch.values import Format, Memory, default_format, show

PinPlace = tuple[WatchPlace, Format] | None


def pin_places(box: FunctionBox, symbols: SymbolTable | None, dialect: str | None
               ) -> list[PinPlace]:
    """One per named pin: the place its operand names and its format (None: no operand, or a
    constant such as T#10s that the box shows already)."""
    found: list[PinPlace] = []
    for pin in box.named:
        try:
            place = resolve(pin.text, symbols, dialect) if pin.text.strip() else None
        except WatchError:
            place = None
        found.append((place, default_format(place, dialect)) if place is not None else None)
    return found


def pin_values(places: list[PinPlace], memory: Memory) -> list[str]:
    """The value of each pin's place now ("" for a pin without one)."""
    out: list[str] = []
    for entry in places:
        if entry is None:
            out.append("")
            continue
        try:
            out.append(show(entry[0], entry[1], memory))
        except (KeyError, IndexError):  # an area the PLC's memory does not have
            out.append("")
    return out
