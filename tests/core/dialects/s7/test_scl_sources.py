"""SCL sources as TIA generates them (`.scl`: TYPE, DATA_BLOCK and code blocks with a
`BEGIN … END_FUNCTION_BLOCK` body): the interfaces and DBs are read, a code block's body is one
SCL network shown and not simulated, and a changed source is never written over
(docs/dialects.md, "Real exports tried"). LadderWorks' own sources in data/scl/."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.core.diagnostics import Severity
from ladderworks.core.dialects.s7.saving import save_block
from ladderworks.core.dialects.s7.scl_source import parse_scl, split
from ladderworks.core.dialects.s7.sd_save import SaveRefused
from ladderworks.core.dialects.s7.source import S7Model
from ladderworks.core.il.reading import parse_file

SCL = Path(__file__).parent / "data" / "scl"


def test_a_code_block_keeps_its_interface_and_its_body_as_one_scl_network() -> None:
    text = (SCL / "FB_Sayac.scl").read_text("utf-8")
    [parsed] = parse_scl(text)
    block = parsed.block
    assert (block.kind, block.name, block.language) == ("FB", "FB_Sayac", "SCL")
    assert [m.name for m in block.members("Input")] == ["Darbe"]
    assert [m.name for m in block.members("Temp")] == ["Ham", "Bitler"]  # AT: its own [LW]
    [network] = block.networks
    assert network.language == "SCL"
    assert network.source.splitlines()[0] == "// Count the rising edges of #Darbe."
    assert network.source.splitlines()[-1] == "#Onceki := #Darbe;"
    lines = text.split("\n")
    assert lines[network.line - 1].strip().startswith("//")
    assert lines[network.end_line - 1].strip() == "#Onceki := #Darbe;"


def test_the_blanked_text_keeps_every_line() -> None:
    text = (SCL / "FB_Sayac.scl").read_text("utf-8")
    blanked, bodies = split(text)
    assert blanked.count("\n") == text.count("\n") and len(bodies) == 1
    assert "BEGIN" not in blanked and "END_FUNCTION_BLOCK" in blanked


def test_types_and_dbs_of_one_source_with_start_values() -> None:
    found = parse_scl((SCL / "DB_Sayim.scl").read_text("utf-8"))
    assert [(p.block.kind, p.block.name) for p in found] == [("Type", "UDT_Sayim"),
                                                             ("GlobalDB", "DB_Sayim")]
    assert [m.name for m in found[1].block.members("Static")] == ["Veri", "Limit"]


def test_opening_an_scl_source_shows_it_not_simulated_and_refuses_a_change() -> None:
    result = parse_file(SCL / "FB_Sayac.scl")
    assert [(d.code, d.severity) for d in result.diagnostics] == [
        ("s7-not-simulated", Severity.WARNING)]
    model = result.program.model
    assert isinstance(model, S7Model) and model.read is not None and model.read.form == "scl"
    assert "DB_Sayim" in [b.name for b in model.graph.blocks]  # the folder's DB
    model.entry.networks[0].source += "\n#Adet := 0;"  # a change of the SCL text
    with pytest.raises(SaveRefused) as refused:
        save_block(model.read.data, model.read.form, model.entry,
                   model.read.changed(model.entry))
    assert refused.value.code == "s7-save-unwritable"


def test_a_folder_of_db_and_type_sources_alone_opens() -> None:
    folder = SCL / "only_dbs"
    folder.mkdir(exist_ok=True)
    try:
        (folder / "DB_Sayim.scl").write_bytes((SCL / "DB_Sayim.scl").read_bytes())
        result = parse_file(folder)
        assert [d.code for d in result.diagnostics] == []
    finally:
        (folder / "DB_Sayim.scl").unlink(missing_ok=True)
        folder.rmdir()
