"""Writing S7 programs: an unchanged block is saved byte for byte by the faithful save; a new or
changed network cannot be written as SIMATIC SD yet, so Save refuses it with a message."""

from __future__ import annotations

from ladderworks.core.diagnostics import Refused
from ladderworks.core.dialects.s7.devices import format_absolute
from ladderworks.core.il.program import Network
from ladderworks.core.instructions import InstructionSpec


def network_lines(network: Network, first: bool) -> list[str]:
    """Refused: a changed S7 block is saved from TIA Portal (docs/dialects.md, S7-1200)."""
    raise Refused("s7-save-changed")


def mnemonic_of(spec: InstructionSpec) -> str:
    """A row's name as S7 says it: `TON` for S7.TON, the engine's own otherwise."""
    return spec.mnemonic if spec.dialect == "s7" and spec.mnemonic else spec.text_name


__all__ = ["format_absolute", "mnemonic_of", "network_lines"]
