"""docs/instructions.md: a heading for every row of the instruction table, examples that parse,
compile and run."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from ladderworks.core import instructions as it
from ladderworks.core.address import parse_address
from ladderworks.core.compiler import compile_program
from ladderworks.core.il import parse
from ladderworks.core.plc.engine import ScanEngine

DOC = Path(__file__).resolve().parents[3] / "docs" / "instructions.md"
TEXT = DOC.read_text(encoding="utf-8")
HEADINGS = [line for line in TEXT.splitlines() if line.startswith("### ")]
EXAMPLES = re.findall(r"```lad\n(.*?)```", TEXT, flags=re.S)


@pytest.mark.parametrize("spec", it.ALL, ids=lambda s: s.name)
def test_every_instruction_has_a_heading(spec: it.InstructionSpec) -> None:
    matching = [h for h in HEADINGS if f'<a id="{spec.help_key}"></a>' in h]
    assert len(matching) == 1, spec.name
    assert matching[0].startswith(f"### {spec.name} "), matching[0]
    if spec.is_function and spec.sub is not None:
        assert f"(SUB {spec.sub})" in matching[0]


def test_no_heading_for_unknown_instructions() -> None:
    names = {h.split()[1] for h in HEADINGS}
    assert names == {spec.name for spec in it.ALL}


def test_every_functional_instruction_has_an_example() -> None:
    used = {line.split()[0] for block in EXAMPLES for line in block.splitlines() if line}
    used |= {it.BY_MNEMONIC[name].name for name in used if name in it.BY_MNEMONIC}
    missing = {s.name for s in it.FUNCTIONS} - used - {"JMPE", "COME"}
    assert not missing
    assert {"SP", "SPE", "SET", "RST"} <= used
    assert len(EXAMPLES) >= 75


@pytest.mark.parametrize("example", EXAMPLES)
def test_example_parses_without_errors(example: str) -> None:
    result = parse(f"%@3\n{example}%\n")
    assert result.ok, [str(d) for d in result.diagnostics]
    assert result.program.instructions()
    compiled = compile_program(result.program)
    assert compiled.binary is not None and not compiled.diagnostics, [
        str(d) for d in compiled.diagnostics]
    engine = ScanEngine(compiled.binary)
    for _ in range(5):
        engine.scan()
    assert engine.scan_count == 5


def test_sft_example_shifts_once_per_press() -> None:
    """The SFT entry's example (issue #17): DIFU gives ACT for one scan, so one shift a press."""
    entry = TEXT[TEXT.index('<a id="instr-sft">'):]
    block = re.search(r"```lad\n(.*?)```", entry, flags=re.S)
    assert block
    compiled = compile_program(parse(f"%@3\n{block.group(1)}%\n").program)
    assert compiled.binary is not None
    engine = ScanEngine(compiled.binary)
    engine.memory.write(parse_address("R100"), 1, 2)
    for press in range(1, 4):
        engine.memory.set_bit(parse_address("X1.0"), 1)
        engine.run_scans(5)
        engine.memory.set_bit(parse_address("X1.0"), 0)
        engine.run_scans(2)
        assert engine.memory.read(parse_address("R100"), 2) == 1 << press
