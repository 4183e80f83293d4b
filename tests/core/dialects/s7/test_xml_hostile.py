"""Hostile and broken SimaticML: entity expansion and external entities are refused unparsed,
a 100 MB file is refused before reading, broken wiring, loops, missing blocks and unknown
parts give translated diagnostics at their network and part UId; nothing crashes, hangs or is
rewritten."""

from __future__ import annotations

from pathlib import Path

from ladderworks.core.dialects.s7 import xml_open
from ladderworks.core.dialects.s7.xml_reader import MAX_PARTS, read_document
from ladderworks.core.dialects.s7.xml_safe import MAX_BYTES, MAX_DEPTH
from ladderworks.core.il.printer import encode_program
from ladderworks.core.il.reading import parse_bytes, parse_file
from tests.core.dialects.s7.xml_docs import document, tag, wire

LAUGHS = """<?xml version="1.0"?>
<!DOCTYPE Document [
 <!ENTITY a "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa">
 <!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">
 <!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;">
 <!ENTITY d "&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;">
 <!ENTITY e "&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;">
 <!ENTITY f "&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;">
]>
<Document><Engineering version="V17" /><SW.Blocks.OB ID="0"><AttributeList><Name>&f;</Name>
</AttributeList></SW.Blocks.OB></Document>
"""
EXTERNAL = """<?xml version="1.0"?>
<!DOCTYPE Document [<!ENTITY secret SYSTEM "file:///etc/passwd">]>
<Document><SW.Blocks.OB ID="0"><AttributeList><Name>&secret;</Name></AttributeList>
</SW.Blocks.OB></Document>
"""
EXTERNAL_DTD = """<?xml version="1.0"?>
<!DOCTYPE Document SYSTEM "http://127.0.0.1:9/evil.dtd">
<Document><SW.Blocks.OB ID="0" /></Document>
"""
_PARTS = ('<Part Name="Contact" UId="23" /><Part Name="Coil" UId="24" />')


def _net(wires: str, parts: str = _PARTS) -> str:
    return f"<Parts>{tag(21, 'Start')}{tag(22, 'Lamba')}{parts}</Parts><Wires>{wires}</Wires>"


def _codes(path: Path) -> list[str]:
    return [d.code for d in parse_file(path).diagnostics]


def test_entity_expansion_is_refused_before_any_expansion(tmp_path: Path) -> None:
    found = read_document(LAUGHS)
    assert [d.code for d in found.diagnostics] == ["s7xml-dtd"]
    assert found.diagnostics[0].line == 2 and "DOCTYPE" in found.diagnostics[0].message()
    assert found.blocks == []
    path = tmp_path / "laughs.xml"
    path.write_text(LAUGHS, "utf-8")
    result = parse_file(path)
    assert [d.code for d in result.diagnostics] == ["s7xml-dtd"]
    assert encode_program(result.program) == path.read_bytes()  # saving changes nothing
    assert path.read_text("utf-8") == LAUGHS


def test_external_entities_and_dtds_are_refused_and_nothing_is_fetched() -> None:
    for text in (EXTERNAL, EXTERNAL_DTD):
        found = read_document(text)
        assert [d.code for d in found.diagnostics] == ["s7xml-dtd"]
        assert found.blocks == []
    assert "root:" not in repr(read_document(EXTERNAL))


def test_an_undeclared_entity_is_malformed_xml() -> None:
    found = read_document("<Document><SW.Blocks.OB>&x;</SW.Blocks.OB></Document>")
    assert [d.code for d in found.diagnostics] == ["s7xml-malformed"]


def test_a_100_mb_file_is_refused_without_reading_it(tmp_path: Path) -> None:
    path = tmp_path / "big.xml"
    head = document([_net(wire(30, "rail", "23:in"))]).encode()
    with open(path, "wb") as file:
        file.write(head)
        file.truncate(100 * 1024 * 1024)  # sparse: nothing written to disk
    program, diagnostics, _encoding = xml_open.open_path(path, None)
    assert [d.code for d in diagnostics] == ["s7xml-too-large"]
    assert diagnostics[0].args["size"] == 100 and program.networks == []
    assert read_document(b" " * (MAX_BYTES + 1)).diagnostics[0].code == "s7xml-too-large"
    result = parse_file(path)  # the File › Open path: refused, not parsed
    assert [d.code for d in result.diagnostics] == ["s7xml-too-large"]


def test_deep_nesting_is_refused() -> None:
    text = "<Document>" + "<a>" * (MAX_DEPTH + 5) + "</a>" * (MAX_DEPTH + 5) + "</Document>"
    assert [d.code for d in read_document(text).diagnostics] == ["s7xml-malformed"]


def test_a_cut_export_says_where(tmp_path: Path) -> None:
    text = document([_net(wire(30, "rail", "23:in"))])
    cut = text[: len(text) // 2]
    found = read_document(cut)
    assert [d.code for d in found.diagnostics] == ["s7xml-malformed"]
    assert found.diagnostics[0].line == cut.count("\n") + 1
    path = tmp_path / "cut.xml"
    path.write_text(cut, "utf-8")
    result = parse_file(path)
    assert encode_program(result.program) == cut.encode()


def test_a_wire_to_a_missing_part_names_its_network_and_uid(tmp_path: Path) -> None:
    wires = (wire(30, "rail", "23:in") + wire(31, "21", "23:operand") +
             wire(32, "23:out", "99:in") + wire(33, "22", "24:operand"))
    found = read_document(document([_net(wire(40, "rail", "23:in")), _net(wires)]))
    problems = [d for d in found.diagnostics if d.code == "s7xml-wire"]
    assert len(problems) == 1
    assert problems[0].args == {"block": "Main", "network": 2, "wire": "32", "uid": "99"}
    assert "99" in problems[0].message()
    path = tmp_path / "Main.xml"
    path.write_text(document([_net(wires)]), "utf-8")
    assert "s7xml-wire" in _codes(path)


def test_an_identcon_to_a_missing_access_is_named_too() -> None:
    found = read_document(document([_net(wire(30, "77", "23:operand"))]))
    assert [d.args["uid"] for d in found.diagnostics if d.code == "s7xml-wire"] == ["77"]


def test_a_loop_of_wires_names_a_part_and_does_not_hang(tmp_path: Path) -> None:
    wires = (wire(30, "23:out", "24:in") + wire(31, "24:out", "23:in") +
             wire(32, "21", "23:operand") + wire(33, "22", "24:operand"))
    path = tmp_path / "Main.xml"
    path.write_text(document([_net(wires)]), "utf-8")
    result = parse_file(path)
    loop = [d for d in result.diagnostics if d.code == "s7xml-loop"]
    assert len(loop) == 1 and loop[0].args["uid"] in ("23", "24")
    assert loop[0].args["network"] == 1


def test_a_call_of_a_missing_block_and_an_unknown_part(tmp_path: Path) -> None:
    parts = ('<Call UId="23"><CallInfo Name="Yok" BlockType="FC" /></Call>'
             '<Part Name="Calculate" UId="24" />')
    wires = wire(30, "rail", "23:en", "24:en") + wire(31, "24:out", "22")
    path = tmp_path / "Main.xml"
    path.write_text(document([_net(wires, parts)]), "utf-8")
    result = parse_file(path)
    by_code = {d.code: d for d in result.diagnostics}
    assert by_code["s7xml-call-missing"].args == {"block": "Main", "network": 1, "uid": "23",
                                                  "callee": "Yok"}
    assert by_code["s7xml-part"].args["uid"] == "24"
    assert "Calculate" in by_code["s7xml-part"].message()
    assert "s7-part-unknown" in by_code or "s7-call-unknown" in by_code  # the lowering too


def test_too_many_parts_are_refused_per_network() -> None:
    parts = "".join(f'<Part Name="Contact" UId="{n}" />' for n in range(100, 100 + MAX_PARTS + 1))
    found = read_document(document([_net("", parts)]))
    assert [d.code for d in found.diagnostics] == ["s7xml-too-many"]
    assert found.blocks[0].networks[0].parts == []


def test_a_long_series_lowers_without_recursion_trouble() -> None:
    count = MAX_PARTS - 2
    parts = "".join(f'<Part Name="Contact" UId="{n}" />' for n in range(100, 100 + count))
    wires = wire(30, "rail", "100:in") + "".join(
        wire(1000 + n, f"{n}:out", f"{n + 1}:in") for n in range(100, 99 + count)) + "".join(
        wire(5000 + n, "21", f"{n}:operand") for n in range(100, 100 + count))
    result = parse_bytes(document([_net(wires, parts)]).encode())
    assert all(d.code != "s7xml-loop" for d in result.diagnostics)


def test_a_tag_table_document_is_not_a_program() -> None:
    text = ('<Document><SW.Tags.PlcTagTable ID="0"><AttributeList><Name>T</Name></AttributeList>'
            '<ObjectList><SW.Tags.PlcTag ID="1"><AttributeList><DataTypeName>Bool</DataTypeName>'
            "<LogicalAddress>%I0.0</LogicalAddress><Name>Start</Name></AttributeList>"
            "</SW.Tags.PlcTag></ObjectList></SW.Tags.PlcTagTable></Document>")
    found = read_document(text)
    assert [(t.name, t.address, t.table) for t in found.tags] == [("Start", "%I0.0", "T")]
    assert found.blocks == [] and found.diagnostics == []


def test_an_unknown_encoding_or_stray_bytes_are_malformed_not_a_crash() -> None:
    found = read_document('<?xml version="1.0" encoding="tf-8"?><Document />')
    assert [d.code for d in found.diagnostics] == ["s7xml-malformed"]
    assert read_document("\udcff<Document />").diagnostics[0].code == "s7xml-malformed"


def test_a_loop_or_a_long_series_is_kept_as_a_listing_in_the_drawing() -> None:
    from ladderworks.core.ladder.convert import program_to_ladder

    loop = (wire(30, "23:out", "24:in") + wire(31, "24:out", "23:in") +
            wire(32, "21", "23:operand") + wire(33, "22", "24:operand"))
    count = MAX_PARTS - 2
    parts = "".join(f'<Part Name="Contact" UId="{n}" />' for n in range(100, 100 + count))
    series = wire(30, "rail", "100:in") + "".join(
        wire(1000 + n, f"{n}:out", f"{n + 1}:in") for n in range(100, 99 + count)) + "".join(
        wire(5000 + n, "21", f"{n}:operand") for n in range(100, 100 + count))
    result = parse_bytes(document([_net(loop), _net(series, parts)]).encode())
    drawn = program_to_ladder(result.program).networks
    assert len(drawn) == 2 and all(n.listing is not None for n in drawn)
