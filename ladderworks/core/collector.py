"""Python's cycle collector around large work: paused while a program is read, checked or
cross-referenced (tens of thousands of objects, no cycles), and a large open program frozen.

A real FANUC program laid out in the console is some 350,000 tracked objects; a full walk of
them costs ~110 ms, and editing or an autosave triggered one every few steps. So once a
program laid out in the background (gui/editor/progressive.py) is complete, freeze_alive()
takes it out of the walks, and reading the next program (gui/document.py) calls
release_frozen() first (`benchmarks/autosave_real.py`). The state of the freeze is kept here:
`gc.get_freeze_count()` walks every frozen object (16 ms with such a program frozen), too
slow to ask at each small parse the editor makes."""

from __future__ import annotations

import gc
from collections.abc import Iterator
from contextlib import contextmanager

_frozen = False  # freeze_alive() holds objects frozen


@contextmanager
def collector_paused(*, promote: bool = False) -> Iterator[None]:
    """No cycle collection meanwhile (the collector would walk the growing heap many times).

    `promote`: afterwards the objects made go straight to the oldest generation (freeze, then
    unfreeze: two list moves) instead of being walked by the next young collection; they are
    still collected with that generation. Skipped while freeze_alive() holds a freeze."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if promote and not _frozen:
            gc.freeze()
            gc.unfreeze()
        if enabled:
            gc.enable()


def freeze_alive() -> None:
    """Collect the garbage, then move every object alive to the permanent generation: later
    collections no longer walk them (reference counting still frees them)."""
    global _frozen
    gc.collect()
    gc.freeze()
    _frozen = True


def release_frozen() -> None:
    """Undo freeze_alive(): the frozen objects are walked (and their cycles collected) again."""
    global _frozen
    gc.unfreeze()
    _frozen = False
