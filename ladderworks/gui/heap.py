"""The open program's objects kept out of the cycle collector's walks once it is laid out.

A real FANUC program makes some 350,000 tracked objects (networks, cells, instructions); a
full walk of them costs ~110 ms, and editing or an autosave triggers one every few steps.
Frozen objects are still freed by reference counting; only cycles among them wait until the
next program's reading calls `release` and its layout `settle`s, which collects them first:
one walk per program opened instead of one every few edits (`benchmarks/autosave_real.py`).
Only a program laid out in the background (over `progressive.AT_ONCE` networks) settles: a
small one is cheap to walk."""

from __future__ import annotations

import gc


def release() -> None:
    """Before another program is read: the objects `settle` froze are walked again, so the
    previous program's cycles, if any, are collected."""
    gc.unfreeze()


def settle() -> None:
    """Once a program is laid out (the one shown before dropped): collect the garbage, then
    every object alive moves to the permanent generation."""
    gc.collect()
    gc.freeze()
