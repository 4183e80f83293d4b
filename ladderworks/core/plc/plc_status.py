"""What the PLC control screen and the docks are shown: status, snapshots, scan figures."""

from __future__ import annotations

from dataclasses import dataclass, field

from ladderworks.core.address import Address, Area
from ladderworks.core.plc.engine import DEFAULT_PERIOD_MS


@dataclass(frozen=True, slots=True)
class PlcStatus:
    """What the PLC control screen shows: running or not, scans and their times (ms)."""

    loaded: bool = False
    running: bool = False
    scan_count: int = 0
    now_ms: int = 0
    period_ms: int = DEFAULT_PERIOD_MS
    min_ms: float = 0.0
    avg_ms: float = 0.0
    max_ms: float = 0.0
    overruns: int = 0
    scanner: str = ""  # "process" (the scan process), "thread" (the IDE's), "" (not real time)
    problem: str = ""  # why the scans are not in the scan process after all ("" if they are)
    backend: str = ""  # the scan's code that runs: "native", "python" ("" with no program)
    backend_reason: str = ""  # why the Python scan runs although native was asked for


@dataclass(frozen=True, slots=True)
class PlcSnapshot:
    """A consistent copy of the PLC between two scans: every area and the power flow."""

    scan_count: int = 0
    now_ms: int = 0
    areas: dict[Area, bytes] = field(default_factory=dict)
    power_flow: bytes = b""  # ST0 after each op (all 0 unless monitored)
    monitored: bool = False
    disabled: frozenset[int] = frozenset()
    byteorder: str = "little"  # the memory's (Memory.byteorder: "big" for S7)

    def bit(self, address: Address) -> int:
        """The bit at a bit address (0 or 1)."""
        assert address.bit is not None
        return self.areas[address.area][address.byte] >> address.bit & 1

    def read(self, address: Address, width: int = 1) -> int:
        """The `width`-byte value at a byte address, in the memory's byte order."""
        data = self.areas[address.area]
        if self.byteorder == "big":
            return int.from_bytes(data[address.byte:address.byte + width], "big")
        return int.from_bytes(data[address.byte:address.byte + width], "little")


class ScanFigures:
    """Min/avg/max of scans run on the virtual clock (the runner keeps its own)."""

    def __init__(self) -> None:
        self.count = 0
        self.total = 0.0
        self.low = float("inf")
        self.high = 0.0

    def add(self, seconds: float) -> None:
        """Count one scan that took `seconds`."""
        self.count += 1
        self.total += seconds
        self.low = min(self.low, seconds)
        self.high = max(self.high, seconds)
