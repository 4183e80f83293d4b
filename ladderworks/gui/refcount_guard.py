"""A guard against PySide6 6.12.0's lost references to None (every void call) and True (emit)."""

from __future__ import annotations

import ctypes
import sys

from PySide6.QtCore import QRectF

# More references than a process can ever lose: with it, None/True/False are never freed,
# which is what Python 3.12 does for them anyway ("immortal" objects).
_RESERVE = 1 << 40


def void_call_loses_none() -> bool:
    """True when calling a void Qt method takes a reference to None it never gave."""
    rect = QRectF()
    before = sys.getrefcount(None)
    for _ in range(8):
        rect.setWidth(1.0)
    return sys.getrefcount(None) < before - 4


def guard_singletons() -> bool:
    """Make None, True and False immortal when this PySide6 loses references to them.

    Without it such a build aborts the process ("deallocating None") after some ten thousand
    Qt calls. Returns True when the guard was applied.
    """
    if sys.version_info >= (3, 12) or not void_call_loses_none():
        return False
    for singleton in (None, True, False):
        ctypes.c_ssize_t.from_address(id(singleton)).value += _RESERVE
    return True
