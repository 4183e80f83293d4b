"""Forced bits and disabled elements: one list, applied by the engine at scan boundaries."""

from __future__ import annotations

from dataclasses import dataclass

from ladderworks.core.address import Address, Area
from ladderworks.core.plc.memory import Memory


@dataclass(frozen=True, slots=True)
class ForceEntry:
    """One item of the list: a forced bit (`address`, `value`) or a disabled op (`op`)."""

    kind: str  # "force" or "disable"
    address: Address | None = None
    value: bool | None = None
    op: int | None = None
    line: int = 0  # source line of a disabled op

    def __str__(self) -> str:
        if self.kind == "force":
            return f"force {self.address} = {int(bool(self.value))}"
        return f"disable op {self.op} (line {self.line})"


class ForceTable:
    """Forced bits (held at their value before and after the logic) and disabled ops."""

    def __init__(self) -> None:
        self._forced: dict[Address, bool] = {}
        self._disabled: dict[int, int] = {}  # op index -> source line
        self._masks: list[tuple[bytearray, int, int, int]] = []  # area, byte, and, or
        self.version = 0  # bumps whenever the disabled set changes

    def force(self, address: Address, value: bool) -> None:
        """Hold the bit at `address` at `value`."""
        if address.bit is None:
            raise ValueError(f"only bits can be forced, not {address}")
        self._forced[address] = bool(value)
        self._masks = []

    def release(self, address: Address) -> bool:
        """Stop forcing `address`; False if it was not forced."""
        self._masks = []
        return self._forced.pop(address, None) is not None

    def disable(self, op: int, line: int = 0) -> None:
        """Disable op `op`: an open contact, a coil not written, a function not executed."""
        if op not in self._disabled:
            self._disabled[op] = line
            self.version += 1

    def enable(self, op: int) -> bool:
        """Enable op `op` again; False if it was not disabled."""
        if self._disabled.pop(op, None) is None:
            return False
        self.version += 1
        return True

    def clear(self) -> None:
        """Release every force and enable every op."""
        self._forced.clear()
        self._masks = []
        if self._disabled:
            self._disabled.clear()
            self.version += 1

    @property
    def disabled(self) -> frozenset[int]:
        """The disabled op indices."""
        return frozenset(self._disabled)

    def forced(self) -> dict[Address, bool]:
        """The forced bits and their values."""
        return dict(self._forced)

    def disabled_lines(self) -> dict[int, int]:
        """The disabled op indices and their source lines."""
        return dict(self._disabled)

    def forget_memory(self) -> None:
        """Memory's areas changed (a scan process began or ended): find them again at apply."""
        self._masks = []

    def entries(self) -> list[ForceEntry]:
        """Everything forced or disabled, forces first (by address), then ops in order."""
        items = [ForceEntry("force", address, value)
                 for address, value in sorted(self._forced.items())]
        items += [ForceEntry("disable", op=op, line=line)
                  for op, line in sorted(self._disabled.items())]
        return items

    def apply(self, memory: Memory) -> None:
        """Write every forced bit into memory (called before and after the logic)."""
        if not self._forced:
            return
        if not self._masks:
            masks: dict[tuple[Area, int], tuple[int, int]] = {}
            for address, value in self._forced.items():
                assert address.bit is not None
                keep, set_bits = masks.get((address.area, address.byte), (0xFF, 0))
                bit = 1 << address.bit
                keep &= 0xFF ^ bit
                if value:
                    set_bits |= bit
                masks[(address.area, address.byte)] = (keep, set_bits)
            self._masks = [(memory.areas[area], byte, keep, set_bits)
                           for (area, byte), (keep, set_bits) in masks.items()]
        for data, byte, keep, set_bits in self._masks:
            data[byte] = data[byte] & keep | set_bits
