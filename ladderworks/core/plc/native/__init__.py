"""The native scan backend: the loaded binary compiled to machine code with llvmlite (see
docs/engine.md, "The native scan"). `unavailable()` says why it cannot run, if it cannot."""

from __future__ import annotations

import sys


def unavailable() -> str | None:
    """Why the native backend cannot run here (llvmlite missing or unusable, a big-endian
    machine: the native code loads 2- and 4-byte values as the machine's integers), or None."""
    if sys.byteorder != "little":
        return "the native scan needs a little-endian machine"
    try:
        import llvmlite.binding  # noqa: F401
    except Exception as error:  # ImportError, or a broken wheel's OSError
        return f"llvmlite is not available ({error})"
    return None
