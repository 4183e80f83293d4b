"""The shared real Delta machine program (a WPLSoft export) needs no instruction this dialect
lacks: with its separators made spaces here (reading the CSV form itself is another part's
work), every line reads, it compiles, and it runs the same skipping scans as every scan."""

from __future__ import annotations

import random

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import decode
from ladderworks.core.il.reading import parse_bytes
from tests.core.plc.test_skipping import Driver, bytes_of, pair
from tests.real_programs import real_programs_dir

MACHINE = "METALURGICA_c91257f_proejto_clp.csv"


def spaced(raw: bytes) -> str:
    """WPLSoft's `000012,MNEMONIC,OPERAND...` lines as `MNEMONIC OPERAND ...`."""
    lines = []
    for line in raw.decode("latin-1").splitlines():
        fields = [field for field in line.replace(";", ",").split(",") if field]
        lines.append(" ".join(fields[1:] if fields and fields[0].isdigit() else fields))
    return "\n".join(lines) + "\n"


def test_the_machine_program_reads_compiles_and_runs() -> None:
    text = spaced((real_programs_dir() / "delta" / MACHINE).read_bytes())
    assert any(line.startswith(("DMUL", "DCNT", "FROM", "ZRST")) for line in text.splitlines())
    result = parse_bytes(text.encode(), "delta")
    assert [d.code for d in result.diagnostics] == []
    compiled = compile_program(result.program)
    assert compiled.binary is not None, [d.code for d in compiled.diagnostics][:5]
    engines = pair(decode(compiled.binary))
    driver = Driver(engines, random.Random(7), bytes_of(Area.X, 4), bytes_of(Area.G, 64), [])
    driver.run(600, rate=0.1)  # X inputs and module registers (FROM's CRs) change
