"""Random Delta lists of the 32-bit, block, float, module, step-ladder and loop instructions:
read, checked, compiled and run without a traceback; memory keeps its size; a program the checks
pass runs the same in fast and monitored mode."""

from __future__ import annotations

import random

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.dialects.delta import instructions as rows
from ladderworks.core.dialects.delta import rows_extra as extra
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.plc.engine import ScanEngine

_CHOICES = {
    rows.BIT_IN: ["X0", "X7", "M0", "M4095", "S1023", "T0"],
    rows.BIT_OUT: ["Y0", "M0", "M4090", "S0", "S1023"],
    rows.WORD_IN: ["K1", "K3", "K16", "K-7", "K9", "D0", "D4998", "T0", "C0"],
    rows.WORD_OUT: ["D0", "D2", "D4998", "D9998", "T0", "C0"],
    extra.VALUE32: ["K100000", "H0FFFF", "D0", "D4998", "C235", "K-1"],
    extra.WORD_OUT32: ["D0", "D4", "D4997", "D9998", "C235"],
    extra.DEVICE_OUT: ["M0", "M4095", "Y0", "D0", "D9999", "T0", "S0"],
    extra.DEVICE_IN: ["X0", "M4090", "D0", "T0"],
    extra.MODULE: ["K0", "K7", "K8"],
    rows.WIDE_COUNTER: ["C235", "C200"],
}
_NEW = sorted(name for name, spelling in rows.SPELLINGS.items()
              if spelling.row in extra.ACTIONS or spelling.row.startswith("DVP.D"))


def _line(rng: random.Random, name: str) -> str:
    kinds = rows.SPELLINGS[name].operands
    operands = [rng.choice(_CHOICES.get(kind, ["K1"])) for kind in kinds]
    if rng.random() < 0.1:  # a wrong operand count now and then
        operands = operands[:-1] if operands else ["K1"]
    return " ".join([name, *operands])


def _program(rng: random.Random) -> str:
    lines: list[str] = []
    for _ in range(rng.randrange(1, 10)):
        shape = rng.randrange(8)
        if shape == 0:
            lines += ["STL S0", "OUT Y1", "LD X1", "SET S1", "STL S1", "LD X2", "OUT S0", "RET"]
        elif shape == 1:
            lines += [f"FOR K{rng.randrange(1, 4)}", "LD M1000", _line(rng, rng.choice(_NEW)),
                      "NEXT"]
        else:
            lines += [f"LD X{rng.randrange(4)}", _line(rng, rng.choice(_NEW))]
    return "\n".join(lines) + "\nEND\n"


def test_random_lists_never_raise_and_keep_memory_sizes() -> None:
    rng = random.Random(36)
    ran = 0
    for _ in range(120):
        text = _program(rng)
        result = parse_bytes(text.encode(), "delta")
        compiled = compile_program(result.program)
        if not result.ok or compiled.binary is None:
            continue
        engines = (ScanEngine(compiled.binary), ScanEngine(compiled.binary, monitored=True))
        sizes = {area: len(data) for area, data in engines[0].memory.areas.items()}
        for scan in range(12):
            for engine in engines:
                engine.memory.areas[Area.X][0] = (scan * 37) & 0xFF
                engine.memory.areas[Area.D][0:4] = bytes((scan, 0, scan * 3 & 0xFF, 0))
                engine.scan()
            assert engines[0].memory.snapshot() == engines[1].memory.snapshot(), text
        assert {area: len(data) for area, data in engines[0].memory.areas.items()} == sizes
        ran += 1
    assert ran > 30
