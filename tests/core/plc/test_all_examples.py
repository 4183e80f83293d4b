"""Every example program runs in both modes and the two modes agree scan for scan."""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile
from ladderworks.core.il import parse_file
from ladderworks.core.plc.engine import ScanEngine
from tests.core.plc.conftest import EXAMPLES


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.LAD")), ids=lambda p: p.name)
def test_fast_and_monitored_modes_compute_the_same_memory(path: Path) -> None:
    binary = compile(parse_file(path).program)
    fast = ScanEngine(binary)
    monitored = ScanEngine(binary)
    monitored.monitored = True
    rng = random.Random(path.name)
    flowed = bytearray(len(monitored.power_flow))
    for scan in range(300):
        if scan % 7 == 0:
            for area in (Area.X, Area.F, Area.R):  # inputs, and relays set from outside
                size = 16 if area is Area.R else 48
                data = bytes(rng.randrange(256) for _ in range(size))
                fast.memory.areas[area][:size] = data
                monitored.memory.areas[area][:size] = data
        fast.scan()
        monitored.scan()
        assert fast.memory.snapshot() == monitored.memory.snapshot(), scan
        flowed = bytearray(a | b for a, b in zip(flowed, monitored.power_flow, strict=True))
    assert sum(flowed) >= len(flowed) // 3  # the power flow really is recorded
