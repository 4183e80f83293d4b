"""docs/instructions_tr.md: the Turkish reference matches the English one entry by entry."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from ladderworks.core import instructions as it
from ladderworks.core.compiler import compile_program
from ladderworks.core.il import parse

DOCS = Path(__file__).resolve().parents[2] / "docs"
TEXT_EN = (DOCS / "instructions.md").read_text(encoding="utf-8")
TEXT_TR = (DOCS / "instructions_tr.md").read_text(encoding="utf-8")
ANCHOR = re.compile(r'<a id="(instr-[^"]+)"></a>')
LAD_BLOCK = re.compile(r"```lad\n(.*?)```", flags=re.S)
MARK = re.compile(r"\[(seed|pmc|choice)\b")
ENGLISH_LINE_STARTS = ("Control inputs", "Parameters", "Behaviour", "Example", "As ADD",
                       "Marks used", "Errors", "Data formats", "Error outputs")


def headings(text: str) -> list[str]:
    """The `### ` heading lines of a reference page."""
    return [line for line in text.splitlines() if line.startswith("### ")]


def sections(text: str) -> dict[str, str]:
    """The text of each entry, keyed by its anchor; "" holds the part before the first entry."""
    parts = re.split(r"^### ", text, flags=re.M)
    result = {"": parts[0]}
    for part in parts[1:]:
        found = ANCHOR.search(part.splitlines()[0])
        assert found, part.splitlines()[0]
        result[found.group(1)] = part
    return result


def wrapped(block: str) -> str:
    """A ladder example as a file section: between `%@3` and `%` unless it has them."""
    if block.lstrip().startswith("%@"):
        return block
    return f"%@3\n{block}%\n"


def test_file_is_utf8_with_turkish_letters() -> None:
    raw = (DOCS / "instructions_tr.md").read_bytes()
    assert raw.decode("utf-8") == TEXT_TR
    for letter in "İıŞşĞğÇçÖöÜü":
        assert letter in TEXT_TR, letter


@pytest.mark.parametrize("spec", it.ALL, ids=lambda s: s.name)
def test_every_instruction_has_one_turkish_heading(spec: it.InstructionSpec) -> None:
    anchor = f'<a id="{spec.help_key}"></a>'
    assert TEXT_TR.count(anchor) == 1, spec.name
    matching = [h for h in headings(TEXT_TR) if anchor in h]
    assert len(matching) == 1, spec.name
    assert matching[0].startswith(f"### {spec.name} — {spec.title_tr} "), matching[0]
    if spec.is_function and spec.sub is not None:
        assert f"(SUB {spec.sub})" in matching[0]


def test_anchors_in_the_same_order_as_the_english_page() -> None:
    assert ANCHOR.findall(TEXT_TR) == ANCHOR.findall(TEXT_EN)
    assert len(headings(TEXT_TR)) == len(headings(TEXT_EN)) == len(it.ALL)


def test_section_headings_match_in_number() -> None:
    def level2(text: str) -> list[str]:
        return [line for line in text.splitlines() if line.startswith("## ")]

    assert len(level2(TEXT_TR)) == len(level2(TEXT_EN))


def test_examples_identical_to_the_english_page() -> None:
    assert LAD_BLOCK.findall(TEXT_TR) == LAD_BLOCK.findall(TEXT_EN)


def test_each_entry_keeps_its_examples_and_marks() -> None:
    english, turkish = sections(TEXT_EN), sections(TEXT_TR)
    assert english.keys() == turkish.keys()
    for key, text in english.items():
        assert LAD_BLOCK.findall(turkish[key]) == LAD_BLOCK.findall(text), key
        assert sorted(MARK.findall(turkish[key])) == sorted(MARK.findall(text)), key


@pytest.mark.parametrize("block", LAD_BLOCK.findall(TEXT_TR))
def test_example_parses_and_compiles(block: str) -> None:
    result = parse(wrapped(block))
    assert result.ok, [str(d) for d in result.diagnostics]
    assert result.program.instructions()
    compiled = compile_program(result.program)
    assert compiled.binary is not None and not compiled.diagnostics, [
        str(d) for d in compiled.diagnostics]


def test_no_english_section_words_left() -> None:
    for line in TEXT_TR.splitlines():
        start = line.lstrip(" -*").lstrip()
        assert not start.startswith(ENGLISH_LINE_STARTS), line
    for word in ("Behaviour", "Control inputs", "Parameters:"):
        assert word not in TEXT_TR, word
