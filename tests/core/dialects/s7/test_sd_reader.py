"""The SIMATIC SD reader: blocks, interfaces, rungs with named-wire branches, pragmas and
templates into the graph; broken texts give a diagnostic at their line, never a traceback;
tag tables refuse DTDs; `.s7res` texts."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.core.diagnostics import Severity
from ladderworks.core.dialects.s7.graph import OperandKind
from ladderworks.core.dialects.s7.sd_parser import ParseError, parse_sd
from ladderworks.core.dialects.s7.tags import read_tag_table
from ladderworks.core.dialects.s7.texts import pick, read_texts
from ladderworks.core.il.reading import parse_bytes, parse_file

FB = """\ufeff{
    S7_Optimized := "TRUE";
    S7_BlockNumber := "14";
    S7_PreferredLanguage := "LAD"
}
FUNCTION_BLOCK "Motor"
    VAR_INPUT
        StartCmd : Bool;   // start
        StopCmd : Bool;
    END_VAR
    VAR_OUTPUT
        MotorRun : Bool;
    END_VAR
    VAR
        RunTimer : TON_TIME;
        Data : Struct
            Count : Int := 3;
        END_STRUCT;
    END_VAR

    {
        S7_Language := "LAD";
        S7_NetworkTitle := "MLC_1"
    }
    NETWORK
        RUNG wire#powerrail
            Contact( #StartCmd )
            wire#w1
            I_Contact( #StopCmd )
            Coil( #MotorRun )
        END_RUNG
        RUNG wire#powerrail
            Contact( #MotorRun )
        END_RUNG wire#w1
    END_NETWORK
    { S7_Language := "LAD" }
    NETWORK
        RUNG wire#powerrail
            Contact( #MotorRun )
            { S7_Templates := "time_type := Time" }
            #RunTimer.TON(
                pt := T#5s,
                et =>
            )
        END_RUNG
    END_NETWORK
    { S7_Language := "SCL" }
    NETWORK
        #Data.Count := #Data.Count + 1;
    END_NETWORK
END_FUNCTION_BLOCK
"""


def test_a_function_block_reads_into_the_graph() -> None:
    block = parse_sd(FB).block
    assert (block.kind, block.name, block.number) == ("FB", "Motor", 14)
    assert [m.name for m in block.members("Input")] == ["StartCmd", "StopCmd"]
    assert block.members("Static")[1].members[0].start == "3"
    first, second, third = block.networks
    names = sorted(p.name for p in first.parts)
    assert names == ["Coil", "Contact", "Contact", "Contact", "O"]  # the branch joins in an O
    assert next(p for p in first.parts if p.negated).name == "Contact"
    timer = second.parts[1]
    assert timer.name == "TON" and timer.template == {"time_type": "Time"}
    assert timer.instance is not None and timer.instance.kind is OperandKind.LOCAL
    assert timer.instance.path == ("RunTimer",)
    assert third.language == "SCL" and "#Data.Count" in third.source


def test_the_block_runs_alone_with_its_interface_as_values() -> None:
    """An FB opened by itself: its interface members are places a scenario sets."""
    program = parse_bytes(FB.encode("utf-8")).program
    symbols = program.symbols
    assert symbols is not None
    for name in ("#StartCmd", "StopCmd", "#MotorRun"):
        assert symbols.address_of(name) is not None


def test_a_text_cut_mid_rung_is_a_clear_diagnostic_at_its_line() -> None:
    cut = FB[:FB.index("I_Contact( #StopCmd )") + len("I_Contact(")]
    with pytest.raises(ParseError) as caught:
        parse_sd(cut)
    diagnostic = caught.value.diagnostic
    assert diagnostic.code == "s7-cut" and diagnostic.line == cut.count("\n") + 1
    result = parse_bytes(cut.encode("utf-8"), "s7")
    assert [d.code for d in result.diagnostics] == ["s7-cut"]
    assert result.program.networks == []


@pytest.mark.parametrize("bad, code", [
    ('ORGANIZATION_BLOCK "M"\n NETWORK\n RUNG wire#powerrail\n Contact( "A" ) ? \n', "s7-syntax"),
    ('ORGANIZATION_BLOCK "M"\n NETWORK\n RUNG Contact( "A" )\n END_RUNG\n', "s7-syntax"),
    ('ORGANIZATION_BLOCK "M"\n NETWORK\n RUNG wire#powerrail\n Contact( "A )\n', "s7-cut"),
    ('ORGANIZATION_BLOCK "M"\n { S7_Language := "LAD" \n', "s7-cut"),
    ("FUNCTION_BLOCK", "s7-cut"),
    ("PROGRAM x", "s7-syntax"),
])
def test_broken_texts_give_a_diagnostic(bad: str, code: str) -> None:
    with pytest.raises(ParseError) as caught:
        parse_sd(bad)
    assert caught.value.diagnostic.code == code
    assert caught.value.diagnostic.line >= 1


def test_an_unknown_part_and_a_missing_label_are_diagnosed_at_their_network() -> None:
    text = ('ORGANIZATION_BLOCK "Main"\n NETWORK\n  RUNG wire#powerrail\n   Contact( %I0.0 )\n'
            '   Frobnicate( in := 1 )\n  END_RUNG\n END_NETWORK\n NETWORK\n'
            '  RUNG wire#powerrail\n   JumpCoil( nowhere )\n  END_RUNG\n END_NETWORK\n'
            ' NETWORK\n  RUNG wire#powerrail\n   Contact( %I0.1 )\n   Coil( %Q0.0 )\n'
            '  END_RUNG\n END_NETWORK\nEND_ORGANIZATION_BLOCK\n')
    result = parse_bytes(text.encode("utf-8"))
    assert [(d.code, d.args["network"], d.line) for d in result.diagnostics] == [
        ("s7-part-unknown", 1, 5), ("s7-label-unknown", 2, 10)]
    assert [i.name for n in result.program.networks for i in n.instructions] == ["RD", "WRT"]


def test_an_undeclared_tag_and_a_missing_call_are_warned_and_the_rest_runs() -> None:
    """A block exported without its tag table or its callees (docs: "Real exports tried"):
    the tag gets a place of LadderWorks' own, the call is shown only; both warnings."""
    text = ('ORGANIZATION_BLOCK "Main"\n NETWORK\n  RUNG wire#powerrail\n   Contact( "Nope" )\n'
            '   Coil( %Q0.0 )\n  END_RUNG\n END_NETWORK\n NETWORK\n  RUNG wire#powerrail\n'
            '   "Missing_FC"( a := 1 )\n  END_RUNG\n END_NETWORK\nEND_ORGANIZATION_BLOCK\n')
    result = parse_bytes(text.encode("utf-8"))
    assert [(d.code, d.severity) for d in result.diagnostics] == [
        ("s7-tag-undeclared", Severity.WARNING), ("s7-call-unknown", Severity.WARNING)]
    names = [i.name for n in result.program.networks for i in n.instructions]
    assert names[-2:] == ["RD", "WRT"]
    assert '"Nope"' in result.program.symbols.by_symbol


def test_a_loop_of_named_wires_gives_no_power_and_no_hang() -> None:
    text = ('ORGANIZATION_BLOCK "Main"\n NETWORK\n  RUNG wire#w1\n   Contact( %I0.0 )\n'
            '  END_RUNG wire#w2\n  RUNG wire#w2\n   Contact( %I0.1 )\n  END_RUNG wire#w1\n'
            '  RUNG wire#w1\n   Coil( %Q0.0 )\n  END_RUNG\n END_NETWORK\nEND_ORGANIZATION_BLOCK\n')
    result = parse_bytes(text.encode("utf-8"))
    assert all(d.code.startswith("s7-") for d in result.diagnostics)


def test_texts_of_an_s7res() -> None:
    texts = read_texts("\ufeffMultiLingualTexts:\n  - id: MLC_1\n    en-US: Start 'x'\n"
                       "    tr-TR: 'Başla ''x'''\n  - id: MLC_2\n    de-DE: |\n      Zeile 1\n"
                       "      Zeile 2\n")
    assert pick(texts, "MLC_1") == "Start 'x'"
    assert pick(texts, "MLC_1", "tr-TR") == "Başla 'x'"
    assert pick(texts, "MLC_2") == "Zeile 1\nZeile 2"
    assert pick(texts, "MLC_3") == ""


def test_a_tag_table_with_a_dtd_is_refused_and_nothing_is_expanded() -> None:
    bomb = ('<?xml version="1.0"?>\n<!DOCTYPE lolz [<!ENTITY lol "lol"><!ENTITY lol2 '
            '"&lol;&lol;&lol;&lol;">]>\n<Document>&lol2;</Document>')
    tags, problems = read_tag_table(bomb)
    assert tags == [] and problems[0].code == "s7-tags" and problems[0].line == 2
    external = '<!DOCTYPE x [<!ENTITY e SYSTEM "file:///etc/passwd">]><Document>&e;</Document>'
    assert read_tag_table(external)[1][0].code == "s7-tags"
    assert read_tag_table("<Document><broken></Document>")[1][0].code == "s7-tags"


def test_the_tag_table_of_an_example(tmp_path: Path) -> None:
    examples = Path(__file__).resolve().parents[4] / "resources" / "examples" / "s7"
    tags, problems = read_tag_table((examples / "timers" / "PLC tags.xml").read_text("utf-8"))
    assert problems == []
    assert [(t.name, t.type_name, t.address) for t in tags][-1] == ("Geçen Süre", "Time", "%MD0")
    assert tags[-1].comment == "TON'un geçen süresi (ET)"


def test_a_changed_s7_program_is_refused_at_save_and_the_file_kept(tmp_path: Path) -> None:
    from ladderworks.core.diagnostics import DiagnosticError
    from ladderworks.core.il.printer import encode_program

    path = tmp_path / "Main.s7dcl"
    path.write_text(FB, encoding="utf-8")
    program = parse_file(path).program
    assert encode_program(program) == path.read_bytes()
    program.networks.pop()
    with pytest.raises(DiagnosticError) as caught:
        encode_program(program)
    assert caught.value.diagnostic.code == "s7-save-changed"


def test_too_many_instances_for_the_d_area_is_a_diagnostic_not_a_crash() -> None:
    networks = "".join(
        f' NETWORK\n  RUNG wire#powerrail\n   Contact( %I0.0 )\n   "T{n}".TON( pt := T#1s )\n'
        f'   Coil( %Q0.0 )\n  END_RUNG\n END_NETWORK\n' for n in range(700))
    text = f'ORGANIZATION_BLOCK "Main"\n{networks}END_ORGANIZATION_BLOCK\n'
    result = parse_bytes(text.encode("utf-8"))
    codes = {d.code for d in result.diagnostics}
    assert codes == {"s7-memory-full"}
    assert result.diagnostics[0].args["network"] == 626  # 625 timers of 16 bytes fit


def test_instance_db_forms_and_scl_source_heads() -> None:
    for text in ('DATA_BLOCK "Valve_DB"\n"Fb_Valve"\nBEGIN\nEND_DATA_BLOCK\n',
                 'DATA_BLOCK "Valve_DB" : "Fb_Valve"\nNON_RETAIN\nBEGIN\n x := 1;\n'
                 'END_DATA_BLOCK\n'):
        block = parse_sd(text).block
        assert (block.kind, block.instance_of) == ("InstanceDB", "Fb_Valve")
    block = parse_sd('FUNCTION_BLOCK "M"\nTITLE = \'Motor\'\nVERSION : 0.1\nVAR_INPUT\n a : Bool;\n'
                     'END_VAR\nEND_FUNCTION_BLOCK\n').block
    assert [m.name for m in block.members("Input")] == ["a"]


def test_start_values_are_written_in_the_first_scan() -> None:
    from ladderworks.core.compiler import compile_program
    from ladderworks.core.plc.engine import ScanEngine

    result = parse_bytes(FB.encode("utf-8"))
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    engine = ScanEngine(compiled.binary)
    symbols = result.program.symbols
    assert symbols is not None
    at = symbols.address_of("#Data.Count")
    assert at is not None
    engine.scan()
    assert engine.memory.read(at, 2) == 3
    engine.memory.write(at, 9, 2)
    engine.scan()
    assert engine.memory.read(at, 2) == 9  # only in the first scan


def test_a_huge_file_is_refused_not_parsed(tmp_path: Path) -> None:
    path = tmp_path / "Huge.s7dcl"
    head = b'ORGANIZATION_BLOCK "Main"\n NETWORK\n  RUNG wire#powerrail\n'
    with path.open("wb") as file:
        file.write(head)
        file.write(b"   Contact( %I0.0 )\n" * (65 * 1024 * 1024 // 20))
    result = parse_file(path)
    assert [d.code for d in result.diagnostics] == ["s7-too-large"]
    assert result.program.networks == []
