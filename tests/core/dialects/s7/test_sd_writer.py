"""The SIMATIC SD writer: every SD example and test text parses, writes and parses back to the
same graph; the writing is TIA's layout (named wires only where a point is shared)."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.core.dialects.s7.graph_shape import shape
from ladderworks.core.dialects.s7.sd_parser import parse_sd
from ladderworks.core.dialects.s7.sd_writer import block_text, body_lines, texts_text
from ladderworks.core.dialects.s7.texts import read_texts

EXAMPLES = Path(__file__).resolve().parents[4] / "resources" / "examples" / "s7"
SD_FILES = sorted(EXAMPLES.glob("*/*.s7dcl"))

# the project's own test networks: branches, nested branches, a second Bool input from a wire,
# an O feeding several parts, edges, labels, calls, SCL text, quoted names, typed constants
NETWORKS = [
    """RUNG wire#powerrail
            Contact( %I0.0 )
            wire#w1
            I_Contact( %I0.2 )
            Coil( %Q0.0 )
        END_RUNG
        RUNG wire#powerrail
            Contact( %I0.1 )
        END_RUNG wire#w1
        RUNG wire#w1
            Coil( %Q0.1 )
        END_RUNG""",
    """RUNG wire#powerrail
            Contact( %I0.0 )
            Contact( %I0.1 )
            wire#w2
        END_RUNG wire#w1
        RUNG wire#powerrail
            Contact( %I0.0 )
            Contact( %I0.2 )
        END_RUNG wire#w2
        RUNG wire#powerrail
            Contact( %I0.3 )
        END_RUNG wire#w1
        RUNG wire#w1
            Not()
            Coil( %Q0.0 )
        END_RUNG""",
    """RUNG wire#powerrail
            Contact( %I0.0 )
            %M7.0.S_RS( wire#w1 )
            Coil( %Q0.0 )
        END_RUNG
        RUNG wire#powerrail
            Contact( %I0.1 )
        END_RUNG wire#w1""",
    """RUNG wire#powerrail
            P_Contact( operand := %I0.0, bit := %M9.0 )
            Coil( %Q0.0 )
            I_Coil( %Q0.1 )
            S_Coil( "Motor ""A"" 1" )
        END_RUNG""",
    """RUNG wire#powerrail
            Contact( "Up" )
            { S7_Templates := "countType := DInt" }
            "DB Sayıcı".CTUD(
                cd := wire#w3,
                r := "Reset",
                pv := DINT#40000,
                cv => "Data".Counts[2]
            )
            Coil( "Done" )
        END_RUNG
        RUNG wire#powerrail
            Contact( "Down" )
            N_Contact( operand := "Down", bit := "Data".Edge )
        END_RUNG wire#w3""",
    """Label( Start_1 )
        RUNG wire#powerrail
            { S7_Templates := "[ inType := Int, outType := Real ]" }
            Convert( in := #Count, out => #Ratio )
            { S7_Templates := "SrcType := LReal" }
            GE_Contact( in1 := #Ratio, in2 := 1.5E+3 )
            Move( in := 'abc', out1 => "Text" )
            I_JumpCoil( Start_1 )
        END_RUNG""",
]


def _block(networks: str) -> str:
    return (f'FUNCTION_BLOCK "Test"\n    VAR\n        Count : Int;\n        Ratio : Real;\n'
            f"    END_VAR\n{networks}END_FUNCTION_BLOCK\n")


def _network(body: str, language: str = "LAD") -> str:
    return (f'    {{ S7_Language := "{language}" }}\n    NETWORK\n        {body}\n'
            "    END_NETWORK\n")


def _round_trip(text: str) -> None:
    first = parse_sd(text).block
    written, _texts = block_text(first)
    again = parse_sd(written).block
    assert [shape(n) for n in again.networks] == [shape(n) for n in first.networks], written
    assert (again.kind, again.name, again.sections) == (first.kind, first.name, first.sections)


@pytest.mark.parametrize("path", SD_FILES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_every_sd_example_parses_writes_and_parses_back_equal(path: Path) -> None:
    _round_trip(path.read_text("utf-8-sig"))


@pytest.mark.parametrize("body", NETWORKS)
def test_every_test_network_parses_writes_and_parses_back_equal(body: str) -> None:
    _round_trip(_block(_network(body)))


def test_an_scl_network_keeps_its_text() -> None:
    text = _block(_network("IF #Count > 3 THEN\n            #Ratio := 1.0;\n        END_IF;",
                           "SCL"))
    _round_trip(text)
    block = parse_sd(text).block
    assert body_lines(block.networks[0]) == ["IF #Count > 3 THEN", "    #Ratio := 1.0;",
                                             "END_IF;"]


def test_a_shared_point_is_named_once_and_an_or_reads_as_tia_writes_it() -> None:
    text = (EXAMPLES / "calls" / "Kilit.s7dcl").read_text("utf-8-sig")
    written, _texts = block_text(parse_sd(text).block)

    def rungs(source: str) -> list[str]:
        lines = source.splitlines()
        return lines[lines.index("    NETWORK"):lines.index("    END_NETWORK")]

    assert rungs(written) == rungs(text)  # TIA's own layout, line for line


def test_the_timers_example_is_written_as_read_but_its_title_ids() -> None:
    text = (EXAMPLES / "timers" / "Main.s7dcl").read_text("utf-8-sig")
    block = parse_sd(text).block
    block.networks[0].title = "Bir: başlık"
    written, res = block_text(block)
    assert 'S7_NetworkTitle := "MLC_1"' in written
    assert read_texts(res) == {"MLC_1": {"en-US": "Bir: başlık"}}
    assert written.replace('S7_Language := "LAD";\n        S7_NetworkTitle := "MLC_1"',
                           'S7_Language := "LAD";\n        S7_NetworkTitle := "MLC_t1"') \
        .replace('        S7_Language := "LAD"\n    }\n    NETWORK\n        RUNG wire#powerrail\n'
                 '            { S7_Templates := "SrcType := Time" }',
                 '        S7_Language := "LAD";\n        S7_NetworkTitle := "MLC_t2"\n    }\n'
                 '    NETWORK\n        RUNG wire#powerrail\n'
                 '            { S7_Templates := "SrcType := Time" }') == "\ufeff" + text


def test_texts_are_quoted_when_yaml_needs_it() -> None:
    text = texts_text([("a", "plain"), ("b", "x: y"), ("c", "'quoted'")], "tr-TR")
    assert read_texts(text) == {"a": {"tr-TR": "plain"}, "b": {"tr-TR": "x: y"},
                                "c": {"tr-TR": "'quoted'"}}


def test_calls_keep_their_parameters_spelled_as_the_called_blocks_interface() -> None:
    folder = EXAMPLES / "calls"
    blocks = [parse_sd((folder / f"{name}.s7dcl").read_text("utf-8-sig")).block
              for name in ("Main", "Kilit", "Gecikme", "Gecikme_DB")]
    text = (folder / "Main.s7dcl").read_text("utf-8-sig")
    written, _texts = block_text(blocks[0], blocks=blocks)
    for line in ("Basla := \"Start\",", "Calisiyor := \"Motor\"", "Cikis => \"Fan\","):
        assert line in written and line in text
    bare, _texts = block_text(blocks[0])
    assert "basla := \"Start\"," in bare  # without the program: the graph's own pin names
