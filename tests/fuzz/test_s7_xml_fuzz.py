"""Fuzzing the SimaticML reader: mutated XML examples and generated FlgNets read, lower and
open through the CLI without a traceback (a diagnostic or a program, never an exception)."""

from __future__ import annotations

import contextlib
import io
from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ladderworks.cli import main
from ladderworks.core.dialects.s7.xml_reader import read_document
from ladderworks.core.il.reading import parse_bytes
from tests.hypothesis_profiles import examples

ROOT = Path(__file__).resolve().parents[2] / "resources" / "examples" / "s7-xml"
_EXAMPLES = [p.read_bytes() for p in sorted(ROOT.glob("*/Main.xml"))]
_INSERTS = [b"<!DOCTYPE d [<!ENTITY x 'y'>]>", b"&x;", b"&amp;", b"<", b">", b"\x00", b"\xff",
            b'<Part Name="Foo" UId="21" />', b'<NameCon UId="999" Name="in" />',
            b'<IdentCon UId="998" />', b"<Powerrail />", b'<OpenCon UId="5" />',
            b'<Wire UId="1"><NameCon UId="22" Name="out" /><NameCon UId="21" Name="in" /></Wire>',
            b'<Call UId="40"><CallInfo Name="X" BlockType="FB" /></Call>',
            b'xmlns="http://www.siemens.com/automation/Openness/SW/NetworkSource/FlgNet/v9"',
            b'<Access Scope="Label" UId="50"><Label Name="L" /></Access>', "Ş".encode()]
_SETTINGS = settings(max_examples=examples(150), deadline=None, suppress_health_check=[
    HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.function_scoped_fixture])


def _mutate(data: bytes, draw: st.DrawFn) -> bytes:
    chunk = bytearray(data)
    for _ in range(draw(st.integers(1, 10))):
        position = draw(st.integers(0, len(chunk)))
        action = draw(st.sampled_from(["insert", "delete", "replace", "duplicate", "swap"]))
        if action == "insert":
            chunk[position:position] = draw(st.sampled_from(_INSERTS))
        elif action == "duplicate" and chunk:
            end = min(len(chunk), position + draw(st.integers(1, 600)))
            chunk[position:position] = chunk[position:end] * draw(st.integers(1, 4))
        elif action == "swap":  # a UId or a pin name turned into another
            for old, new in ((b'UId="2', b'UId="3'), (b'Name="in"', b'Name="out"'),
                             (b'Name="Coil"', b'Name="O"'), (b"TON", b"CTUD")):
                if draw(st.booleans()):
                    chunk = bytearray(bytes(chunk).replace(old, new, 1))
        elif chunk and position < len(chunk):
            if action == "delete":
                del chunk[position:position + draw(st.integers(1, 40))]
            else:
                chunk[position] = draw(st.integers(0, 255))
    return bytes(chunk)


@_SETTINGS
@given(data=st.data())
def test_mutated_xml_examples_read_and_lower_without_an_exception(data: st.DataObject) -> None:
    source = data.draw(st.sampled_from(_EXAMPLES))
    mutated = _mutate(source, data.draw)
    read_document(mutated)
    parse_bytes(mutated, "s7")


@settings(max_examples=examples(40), deadline=None, suppress_health_check=[
    HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_mutated_xml_examples_through_the_cli(data: st.DataObject, tmp_path: Path) -> None:
    source = data.draw(st.sampled_from(_EXAMPLES))
    path = tmp_path / "Main.xml"
    path.write_bytes(_mutate(source, data.draw))
    for command in (["check", str(path)], ["run", str(path), "--scans", "2"]):
        out = io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out):
            code = main(command)
        assert code in (0, 1), out.getvalue()[-2000:]
        assert "Traceback" not in out.getvalue()


_PIN = st.sampled_from(["in", "out", "operand", "pre", "en", "eno", "IN", "PT", "Q", "ET", "CU",
                        "PV", "CV", "in1", "in2", "k", "dest0", "label", "bogus"])
_PART = st.sampled_from(["Contact", "Coil", "SCoil", "O", "TON", "CTU", "Eq", "InRange", "Move",
                         "Add", "Jump", "JumpList", "Switch", "Return", "Sr", "Nonsense", "A",
                         "X", "Not"])


@_SETTINGS
@given(parts=st.lists(_PART, min_size=1, max_size=8),
       wires=st.lists(st.tuples(st.integers(0, 9), _PIN, st.integers(0, 9), _PIN), max_size=14),
       language=st.sampled_from(["LAD", "FBD"]),
       negated=st.lists(st.tuples(st.integers(0, 7), _PIN), max_size=3))
def test_generated_flgnets_never_raise(parts: list[str], wires: list[tuple], language: str,
                                       negated: list[tuple]) -> None:
    body = '<Access Scope="GlobalVariable" UId="9"><Symbol><Component Name="Start" /></Symbol>' \
           "</Access>" + "".join(
               f'<Part Name="{name}" UId="{n}">' + "".join(
                   f'<Negated Name="{pin}" />' for k, pin in negated if k == n) + "</Part>"
               for n, name in enumerate(parts))
    links = "".join(
        f'<Wire UId="{100 + n}">' + ("<Powerrail />" if a == 8 else f'<IdentCon UId="{a}" />'
                                     if a == 9 else f'<NameCon UId="{a}" Name="{pa}" />') +
        f'<NameCon UId="{b}" Name="{pb}" /></Wire>' for n, (a, pa, b, pb) in enumerate(wires))
    text = ('<Document><SW.Blocks.OB ID="0"><AttributeList><Name>Main</Name></AttributeList>'
            '<ObjectList><SW.Blocks.CompileUnit ID="1"><AttributeList><NetworkSource><FlgNet '
            'xmlns="http://www.siemens.com/automation/Openness/SW/NetworkSource/FlgNet/v4">'
            f"<Parts>{body}</Parts><Wires>{links}</Wires></FlgNet></NetworkSource>"
            f"<ProgrammingLanguage>{language}</ProgrammingLanguage></AttributeList>"
            "</SW.Blocks.CompileUnit></ObjectList></SW.Blocks.OB></Document>")
    parse_bytes(text.encode(), "s7")
