"""Saving a changed S7 block in its own form: SD keeps every unchanged byte and rewrites only
the changed networks; XML keeps the document and replaces only the changed FlgNets in their
namespace (unversioned … v5); Save writes a changed program whose graph lowers to it and
refuses one whose change is not known to the graph."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest

from ladderworks.core.diagnostics import Refused
from ladderworks.core.dialects.s7 import reader, xml_open
from ladderworks.core.dialects.s7.graph import (
    Block,
    End,
    Operand,
    OperandKind,
    Part,
    S7Network,
    Wire,
)
from ladderworks.core.dialects.s7.graph_shape import shape
from ladderworks.core.dialects.s7.saving import lower_graph, save_block
from ladderworks.core.dialects.s7.sd_parser import parse_sd
from ladderworks.core.dialects.s7.sd_save import SaveRefused
from ladderworks.core.dialects.s7.source import S7Model
from ladderworks.core.dialects.s7.xml_reader import read_document
from ladderworks.core.dialects.s7.xml_writer import write_block
from ladderworks.core.il.printer import encode_program

EXAMPLES = Path(__file__).resolve().parents[4] / "resources" / "examples"
NAMES = ("timers", "counters", "compare", "jumps", "jump_list", "switch", "calls")


def _global(*path: str) -> Operand:
    return Operand(OperandKind.GLOBAL, path)


def _rename(network: S7Network, old: str, new: str) -> None:
    """Change an operand read by a pin (a contact's or coil's operand) in the graph."""
    for wire in network.wires:
        if wire.source.operand is not None and wire.source.operand.path == (old,):
            wire.source = End(operand=_global(new))


def _add_coil(network: S7Network, after: str, name: str) -> None:
    """A coil in series after the part `after` (its power out moved onto the new coil)."""
    uid = "new1"
    network.parts.append(Part(uid, "Coil"))
    network.wires.append(Wire(End(part=after, pin="out"), [End(part=uid, pin="in")]))
    network.wires.append(Wire(End(operand=_global(name)), [End(part=uid, pin="operand")]))


def _sd(data: bytes) -> Block:
    return parse_sd(data.decode("utf-8-sig")).block


@pytest.mark.parametrize("name", NAMES)
def test_an_unchanged_sd_block_saves_byte_for_byte(name: str) -> None:
    path = EXAMPLES / "s7" / name / "Main.s7dcl"
    data = path.read_bytes()
    assert save_block(data, "sd", _sd(data), []) == data
    assert save_block(data, "sd", _sd(data), range(len(_sd(data).networks))) != b""


@pytest.mark.parametrize("newline", ["\n", "\r\n"])
def test_a_changed_sd_network_is_spliced_in_and_the_rest_kept(newline: str) -> None:
    text = (EXAMPLES / "s7" / "compare" / "Main.s7dcl").read_text("utf-8-sig")
    data = ("\ufeff" + text.replace("\n", newline)).encode("utf-8")
    block = _sd(data)
    _rename(block.networks[4], "Sonuç", "Başka")
    coil = next(p for p in block.networks[2].parts if p.name == "Coil")
    _add_coil(block.networks[2], coil.uid, "Lamba 2")
    out = save_block(data, "sd", block, [2, 4])
    assert out.startswith(b"\xef\xbb\xbf")
    assert out.count(b"\r\n") == (out.count(b"\n") if newline == "\r\n" else 0)
    again = _sd(out)
    assert [shape(n) for n in again.networks] == [shape(n) for n in block.networks]
    old_lines, new_lines = data.split(b"\n"), out.split(b"\n")
    # the networks before the first change are kept line for line, pragmas (title ids) too
    first = block.networks[2].line - 1
    assert new_lines[:first] == old_lines[:first]
    assert b'Coil( "Lamba 2" )' in out and b'IsValidContact( "Ba\xc5\x9fka" )' in out
    assert out.count(b"S7_NetworkTitle") == data.count(b"S7_NetworkTitle")
    tail = data[data.index(b"MLC_r6") - 60:]
    assert out.endswith(tail)  # the last network, unchanged, and the block's end as read


def test_sd_networks_added_removed_and_moved() -> None:
    data = (EXAMPLES / "s7" / "jumps" / "Main.s7dcl").read_bytes()
    block = _sd(data)
    read = list(block.networks)
    fresh = S7Network(language="LAD")
    fresh.parts.append(Part("1", "Contact"))
    fresh.wires += [Wire(End(powerrail=True), [End(part="1", pin="in")]),
                    Wire(End(operand=_global("Yeni")), [End(part="1", pin="operand")])]
    _add_coil(fresh, "1", "Yeni Lamba")
    block.networks = [read[0], fresh, *read[2:]]  # network 2 removed, a new one in its place
    out = save_block(data, "sd", block, [1])
    again = _sd(out)
    assert [shape(n) for n in again.networks] == [shape(n) for n in block.networks]
    assert b"MLC_j2" not in out and b"MLC_j1" in out
    assert b'Contact( "Yeni" )\n            Coil( "Yeni Lamba" )' in out


def test_an_sd_part_that_cannot_be_written_is_refused() -> None:
    data = (EXAMPLES / "s7" / "timers" / "Main.s7dcl").read_bytes()
    block = _sd(data)
    block.networks[0].parts.append(Part("x", "Contact"))  # no power in
    with pytest.raises(SaveRefused):
        save_block(data, "sd", block, [0])
    with pytest.raises(SaveRefused):
        save_block(b"ORGANIZATION_BLOCK \"M\"\n NETWORK\n", "sd", block, [0])


@pytest.mark.parametrize("version", [0, 1, 2, 3, 4, 5])
def test_a_changed_xml_network_is_written_in_the_namespace_it_was_read_with(version: int
                                                                            ) -> None:
    sd = _sd((EXAMPLES / "s7" / "compare" / "Main.s7dcl").read_bytes())
    text = write_block(sd, version).replace("\n", "\r\n")
    data = text.encode("utf-8")
    found = read_document(data)
    block = found.blocks[0]
    assert save_block(data, "xml", block, []) == data
    _rename(block.networks[0], "Sıcaklık", "Basınç")
    coil = next(p for p in block.networks[5].parts if p.name == "RCoil")
    _add_coil(block.networks[5], coil.uid, "Yeni Bobin")
    out = save_block(data, "xml", block, [0, 5])
    back = read_document(out)
    assert back.diagnostics == [] and back.version == found.version
    assert [shape(n) for n in back.blocks[0].networks] == [shape(n) for n in block.networks]
    flgnet = "NetworkSource/FlgNet" + (f"/v{version}" if version else "") + '"'
    assert out.count(flgnet.encode()) == data.count(flgnet.encode()) == 6
    assert out.count(b"\r\n") == out.count(b"\n")
    # the interface, the units' IDs and texts, the networks between are kept as they were
    head = data[:data.index(b"<FlgNet")]
    assert out.startswith(head)
    units = data.split(b"<SW.Blocks.CompileUnit ")
    kept = out.split(b"<SW.Blocks.CompileUnit ")
    assert kept[2:6] == units[2:6]
    assert kept[1] != units[1] and kept[6] != units[6]
    assert kept[6][:kept[6].index(b"<FlgNet")] == units[6][:units[6].index(b"<FlgNet")]


def test_xml_networks_added_and_removed_get_fresh_ids() -> None:
    data = (EXAMPLES / "s7-xml" / "timers" / "Main.xml").read_bytes()
    block = read_document(data).blocks[0]
    first, second = block.networks
    fresh = S7Network(language="LAD", title="Yeni ağ")
    fresh.parts.append(Part("1", "Contact"))
    fresh.wires += [Wire(End(powerrail=True), [End(part="1", pin="in")]),
                    Wire(End(operand=_global("Yeni")), [End(part="1", pin="operand")])]
    _add_coil(fresh, "1", "Yeni Lamba")
    block.networks = [fresh, second]
    out = save_block(data, "xml", block, [0])
    back = read_document(out)
    assert back.diagnostics == []
    assert [shape(n) for n in back.blocks[0].networks] == [shape(n) for n in block.networks]
    ids = [int(i, 16) for i in re.findall(rb'\bID="([0-9A-F]+)"', out)]
    assert len(ids) == len(set(ids))
    assert first.line and b"TON 10 s on the start input" not in out
    assert b"Second lamp after 5 s" in out and "Yeni ağ".encode() in out


@pytest.mark.parametrize("form", ["s7", "s7-xml"])
def test_save_writes_a_changed_program_known_as_graph_networks(form: str,
                                                               tmp_path: Path) -> None:
    suffix = ".s7dcl" if form == "s7" else ".xml"
    path = EXAMPLES / form / "timers" / f"Main{suffix}"
    opener = reader.open_path if form == "s7" else xml_open.open_path
    program, diagnostics, _encoding = opener(path, None)
    assert diagnostics == []
    model = program.model
    assert isinstance(model, S7Model) and model.read is not None
    assert model.read.path == path and model.read.form == ("sd" if form == "s7" else "xml")
    assert encode_program(program) == path.read_bytes()
    _rename(model.entry.networks[1], "Lamba 2", "Lamba 1")
    assert model.changed() == [1]
    program.networks = lower_graph(model)  # the engine's networks as the edited graph gives them
    out = encode_program(program)
    assert out != path.read_bytes()
    shutil.copytree(path.parent, tmp_path / "copy")
    (tmp_path / "copy" / path.name).write_bytes(out)
    again, problems, _encoding = opener(tmp_path / "copy" / path.name, None)
    assert problems == []
    assert [shape(n) for n in again.model.entry.networks] == \
        [shape(n) for n in model.entry.networks]


def test_save_refuses_a_change_the_graph_does_not_know() -> None:
    path = EXAMPLES / "s7" / "timers" / "Main.s7dcl"
    program, _diagnostics, _encoding = reader.open_path(path, None)
    del program.networks[-1]  # an engine edit with no graph change
    with pytest.raises(Refused) as refused:
        encode_program(program)
    assert refused.value.diagnostics[0].code == "s7-save-changed"
    model = program.model
    assert isinstance(model, S7Model)
    _rename(model.entry.networks[0], "Start", "Stop")  # a graph edit the engine does not hold
    with pytest.raises(Refused):
        encode_program(program)


def test_a_changed_xml_networks_title_and_comment_are_written_in_the_culture_shown() -> None:
    data = (EXAMPLES / "s7-xml" / "timers" / "Main.xml").read_bytes()
    block = read_document(data).blocks[0]
    block.networks[1].title = "İkinci <lamba> & 5 s"
    out = save_block(data, "xml", block, [1])
    back = read_document(out)
    assert back.blocks[0].networks[1].title == "İkinci <lamba> & 5 s"
    assert back.texts[("Main", 2, "title")]["tr-TR"] == "5 s sonra ikinci lamba"  # kept
    assert back.blocks[0].networks[0].title == block.networks[0].title
    assert out.count(b"<MultilingualText ") == data.count(b"<MultilingualText ")
