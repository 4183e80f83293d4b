"""The guard against PySide6 builds that lose references to None on void calls."""

from __future__ import annotations

import sys

from PySide6.QtCore import QRectF

from ladderworks.gui.refcount_guard import guard_singletons, void_call_loses_none


def test_many_void_calls_do_not_free_none() -> None:
    guard_singletons()
    rect = QRectF()
    for _ in range(30_000):  # more than None's natural reference count in a small process
        rect.setWidth(2.0)
    assert rect.width() == 2.0
    if void_call_loses_none():
        assert sys.version_info >= (3, 12) or sys.getrefcount(None) > 1 << 39
