"""The reference's ROT and JMP examples do what their text says (docs/instructions*.md)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from tests.core.plc.conftest import at, bit, engine_for, set_bit

DOCS = Path(__file__).resolve().parents[3] / "docs"
PAGES = ("instructions.md", "instructions_tr.md")


def example(page: str, anchor: str) -> str:
    """The first ```lad block of the entry with `anchor` on `page`."""
    text = (DOCS / page).read_text(encoding="utf-8")
    entry = text[text.index(f'<a id="{anchor}">'):]
    found = re.search(r"```lad\n(.*?)```", entry, flags=re.S)
    assert found
    return found.group(1)


@pytest.mark.parametrize("page", PAGES)
def test_rot_example_is_the_12_station_turret_from_2_to_11(page: str) -> None:
    engine = engine_for(example(page, "instr-rot"))
    engine.memory.write(at("X41"), 0x02)  # current position 2 (BCD)
    engine.memory.write(at("F26"), 0x11)  # target 11
    set_bit(engine, "F7.3", 1)  # ACT = 1: BYT = 0, DIR = 1, POS = 1, INC = 0
    engine.scan()
    assert bit(engine, "R231.0") == 1  # reverse is the short way
    assert engine.memory.read(at("R230")) == 0x12  # the position one before the target


@pytest.mark.parametrize("page", PAGES)
def test_jmp_example_freezes_the_first_coil_only(page: str) -> None:
    engine = engine_for(example(page, "instr-jmp"))
    set_bit(engine, "X1.1", 1)
    engine.scan()
    assert (bit(engine, "Y0.0"), bit(engine, "Y0.1")) == (1, 1)
    set_bit(engine, "X1.0", 1)
    set_bit(engine, "X1.1", 0)
    engine.scan()
    assert (bit(engine, "Y0.0"), bit(engine, "Y0.1")) == (1, 0)
