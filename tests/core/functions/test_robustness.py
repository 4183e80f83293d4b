"""Every functional instruction against garbage memory: errors are outputs, never exceptions."""

from __future__ import annotations

import random
import re
from pathlib import Path

import pytest

from ladderworks.core import dialects
from ladderworks.core import instructions as it
from ladderworks.core.il import parse
from ladderworks.core.plc.functions import FunctionContext, load_all
from ladderworks.core.plc.memory import Memory

REGISTRY = load_all()
# structure (jumps, common lines, subprograms, labels): done by the code generator
ENGINE_ONLY = {"JMP", "JMPE", "COM", "COME", "CALL", "CALLU", "SP", "SPE", "LBL", "JMPB", "JMPC"}
# a dialect's functional rows that run as functions (its structure rows are the engine's;
# its shown-only rows, `simulated` False, the generic no-op of compiler/implementations.py)
DIALECT_FUNCTIONS = {row.name for dialect in dialects.every() for row in dialect.rows
                     if row.kind is it.Kind.FUNCTION and row.flow is it.Flow.NONE
                     and (row.simulated or row.cnc)}  # Fatek FUN stubs: registered no-ops
DOC = Path(__file__).resolve().parents[3] / "docs" / "instructions.md"


def _doc_calls() -> list[tuple[str, tuple]]:
    text = DOC.read_text(encoding="utf-8")
    calls = []
    for block in re.findall(r"```lad\n(.*?)```", text, flags=re.S):
        for ins in parse(f"%@3\n{block}%\n").program.instructions():
            if ins.is_function and ins.name in REGISTRY:
                calls.append((ins.name, ins.params))
    return calls


def test_every_functional_instruction_is_registered() -> None:
    assert {s.name for s in it.FUNCTIONS} - ENGINE_ONLY | DIALECT_FUNCTIONS == set(REGISTRY)
    assert {s.name for s in it.FUNCTIONS if s.flow is not it.Flow.NONE} == ENGINE_ONLY


@pytest.mark.parametrize(("name", "params"), _doc_calls(), ids=lambda v: str(v)[:12])
def test_garbage_memory_never_raises(name: str, params: tuple) -> None:
    spec = it.BY_NAME[name]
    rng = random.Random(name)
    memory = Memory()
    sizes = {area: len(data) for area, data in memory.areas.items()}
    for _ in range(200):
        for area, size in sizes.items():
            memory.areas[area][:] = rng.randbytes(size)
        inputs = tuple(rng.random() < 0.5 for _ in spec.inputs)
        w1 = REGISTRY[name](FunctionContext(memory), {}, inputs, params)
        assert isinstance(w1, bool)
        assert {a: len(d) for a, d in memory.areas.items()} == sizes  # no area grew
