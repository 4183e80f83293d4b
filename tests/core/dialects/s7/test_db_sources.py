"""Global DB sources (`.db`, TIA's "Generate source from blocks") beside the blocks: members
(STRUCT, nested structs, arrays, PLC data types, String, LReal, Char) resolve as
`"DB".member`, their start values (declared, then the BEGIN section's) are in place after the
first scan; MOVE of a string constant, LReal compares; a broken source is a warning naming its
file and line, never a traceback."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.core.compiler import compile_program
from ladderworks.core.dialects.s7 import reader
from ladderworks.core.dialects.s7.devices import parse_absolute
from ladderworks.core.dialects.s7.layout import Layout, size_of, string_value
from ladderworks.core.dialects.s7.sd_parser import ParseError, parse_sources
from ladderworks.core.il.program import Program
from ladderworks.core.plc import typed
from ladderworks.core.plc.engine import ScanEngine

DB = """TYPE "Motor_UDT"
VERSION : 0.1
   STRUCT
      Speed : Int := 10;
      Run : Bool;
   END_STRUCT;

END_TYPE

DATA_BLOCK "Hat_DB"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
NON_RETAIN
   STRUCT
      Count : Int := 3;
      Ratio : LReal := 0.1;
      Limit : LReal := 2.5;
      Name : String[10] := 'abc';
      Wide : WString[4] := WSTRING#'Işık';
      Letter : Char := 'A';
      Flags : Byte := 16#0F;
      Counts : Array[0..3] of Int := [4(1)];
      Lamps : Array[1..3] of Bool;
      Data : Struct
         Speed : Int;
         Edge { S7_SetPoint := 'True'} : Bool;
         Deep : Struct
            Total : DInt := 7;
         END_STRUCT;
      END_STRUCT;
      M1 : "Motor_UDT";
   END_STRUCT;


BEGIN
   Count := 5;
   Counts[2] := -7;
   Data.Speed := 100;
   "M1".Speed := 20;
   Lamps[3] := TRUE;
   Name := 'Sıcak';
END_DATA_BLOCK
"""

MAIN = """ORGANIZATION_BLOCK "Main"
    NETWORK
        RUNG wire#powerrail
            Contact( "Hat_DB".Lamps[3] )
            Move( in := 'Merhaba dünya', out1 => "Hat_DB".Name )
        END_RUNG
    END_NETWORK
    NETWORK
        RUNG wire#powerrail
            { S7_Templates := "SrcType := LReal" }
            GT_Contact( in1 := "Hat_DB".Ratio, in2 := 0.05 )
            { S7_Templates := "SrcType := LReal" }
            LT_Contact( in1 := "Hat_DB".Ratio, in2 := "Hat_DB".Limit )
            Coil( %Q0.0 )
        END_RUNG
    END_NETWORK
    NETWORK
        RUNG wire#powerrail
            { S7_Templates := "SrcType := LReal" }
            EQ_Contact( in1 := "Hat_DB".Ratio, in2 := 0.1 )
            Coil( %Q0.1 )
        END_RUNG
    END_NETWORK
    NETWORK
        RUNG wire#powerrail
            Contact( %I0.0 )
            { S7_Templates := "SrcType := LReal" }
            Add( in1 := "Hat_DB".Ratio, in2 := 0.2, out => "Hat_DB".Limit )
        END_RUNG
    END_NETWORK
END_ORGANIZATION_BLOCK
"""


class Folder:
    """The program of a folder holding Main.s7dcl and Hat_DB.db, compiled and run."""

    def __init__(self, tmp_path: Path, db: str = DB) -> None:
        (tmp_path / "Main.s7dcl").write_text(MAIN, encoding="utf-8")
        (tmp_path / "Hat_DB.db").write_text(db, encoding="utf-8")
        program, self.diagnostics, _encoding = reader.open_path(tmp_path / "Main.s7dcl", None)
        self.program: Program = program
        compiled = compile_program(program)
        assert compiled.binary is not None, [d.message() for d in compiled.diagnostics]
        self.engine = ScanEngine(compiled.binary)

    def at(self, name: str):
        symbols = self.program.symbols
        assert symbols is not None
        address = symbols.address_of(name)
        assert address is not None, name
        return address

    def value(self, name: str, vtype: typed.ValueType) -> int | float:
        return typed.read(self.engine.memory, self.at(name), vtype)

    def string(self, name: str) -> tuple[int, int, bytes]:
        base = self.at(name)
        data = self.engine.memory.areas[base.area]
        return data[base.byte], data[base.byte + 1], bytes(
            data[base.byte + 2:base.byte + 2 + data[base.byte + 1]])


def test_a_db_source_parses_with_its_types_and_start_values() -> None:
    udt, db = (p.block for p in parse_sources(DB))
    assert (udt.kind, db.kind) == ("Type", "GlobalDB")
    assert [m.name for m in db.members("Static")][:3] == ["Count", "Ratio", "Limit"]
    assert db.starts[("counts[2]",)] == "-7" and db.starts[("m1", "speed")] == "20"
    data = next(m for m in db.members("Static") if m.name == "Data")
    assert [m.name for m in data.members] == ["Speed", "Edge", "Deep"]


def test_db_members_resolve_and_start_values_are_applied_at_cold_start(tmp_path: Path) -> None:
    plc = Folder(tmp_path)
    assert plc.diagnostics == [], [d.message() for d in plc.diagnostics]
    plc.engine.scan()
    assert plc.value('"Hat_DB".Count', typed.ValueType.INT) == 5  # BEGIN wins
    assert plc.value('"Hat_DB".Data.Speed', typed.ValueType.INT) == 100
    assert plc.value('"Hat_DB".Data.Deep.Total', typed.ValueType.DINT) == 7
    assert plc.value('"Hat_DB".M1.Speed', typed.ValueType.INT) == 20
    assert plc.value('"Hat_DB".Ratio', typed.ValueType.LREAL) == 0.1  # exactly, not a Real
    assert plc.value('"Hat_DB".Letter', typed.ValueType.CHAR) == ord("A")
    assert plc.value('"Hat_DB".Flags', typed.ValueType.BYTE) == 15
    memory = plc.engine.memory
    layout_counts = [typed.read(memory, _element(plc, "Counts", n, 2), typed.ValueType.INT)
                     for n in range(4)]
    assert layout_counts == [1, 1, -7, 1]
    # the BEGIN section's 'Sıcak' was moved over by the first network (Lamps[3] is TRUE)
    assert plc.string('"Hat_DB".Name') == (10, 10, "Merhaba dü".encode("cp1254"))
    base = plc.at('"Hat_DB".Wide')
    wide = bytes(memory.areas[base.area][base.byte:base.byte + 12])
    assert wide == bytes([0, 4, 0, 4]) + "Işık".encode("utf-16-be")


def _element(plc: Folder, name: str, index: int, width: int):
    base = plc.at(f'"Hat_DB".{name}')
    return type(base)(base.area, base.byte + index * width)


def test_lreal_compares_and_adds_in_double_precision(tmp_path: Path) -> None:
    plc = Folder(tmp_path)
    plc.engine.scan()
    q0, q1 = parse_absolute("%Q0.0")[0], parse_absolute("%Q0.1")[0]
    assert plc.engine.memory.bit(q0) == 1  # 0.05 < 0.1 < 2.5
    assert plc.engine.memory.bit(q1) == 1  # 0.1 == 0.1 as LReals (a Real 0.1 is not)
    plc.engine.memory.set_bit(parse_absolute("%I0.0")[0], 1)
    plc.engine.scan()
    plc.engine.scan()
    assert plc.value('"Hat_DB".Limit', typed.ValueType.LREAL) == 0.1 + 0.2
    assert plc.engine.memory.bit(q0) == 1


def test_sizes_follow_the_s7_types() -> None:
    assert size_of("String[10]") == 12 and size_of("String") == 256
    assert size_of("WString[4]") == 12 and size_of("LReal") == 8 and size_of("Char") == 1
    assert size_of("Array[0..3] of Int") == 8 and size_of("Array[1..3] of Bool") == 3
    assert size_of("Array[0..1] of String[3]") == 12  # 5 bytes, each element at an even byte
    assert string_value("'It''s $N$41'") == "It's \nA" and string_value("12") is None


def test_array_elements_resolve_by_constant_index_and_refuse_out_of_bounds() -> None:
    blocks = parse_sources(DB)
    from ladderworks.core.dialects.s7.graph import S7Program

    layout = Layout(S7Program([b.block for b in blocks]))
    first = layout.global_name(("Hat_DB", "Counts[0]"))
    third = layout.global_name(("Hat_DB", "Counts[3]"))
    assert first is not None and third is not None
    assert third.address.byte - first.address.byte == 6 and third.type_name == "Int"
    assert layout.global_name(("Hat_DB", "Counts[4]")) is None
    assert layout.global_name(("Hat_DB", "Counts[#i]")) is None
    lamp = layout.global_name(("Hat_DB", "Lamps[1]"))
    assert lamp is not None and lamp.address.bit == 0


@pytest.mark.parametrize("bad, code", [
    ("DATA_BLOCK \"D\"\n   STRUCT\n      a : Int;\n", "s7-db-cut"),
    ("DATA_BLOCK \"D\"\n   STRUCT\n      a : Array[0..3 of Int", "s7-db-cut"),
    ("DATA_BLOCK \"D\"\nSTRUCT a : Int; END_STRUCT;\nBEGIN\n   a = 3;\nEND_DATA_BLOCK\n",
     "s7-db-syntax"),
    ("DATA_BLOCK \"D\"\nBEGIN\n   a := 3\nEND_DATA_BLOCK\n", "s7-db-syntax"),
    ("DATA_BLOCK \"D\"\nBEGIN\n   a[1 := 3;\n", "s7-db-cut"),
    ("DATA_BLOCK \"D\"\n{ S7_Optimized_Access := 'TRUE'\nSTRUCT\n", "s7-db-cut"),
])
def test_a_broken_db_source_is_a_warning_at_its_line(tmp_path: Path, bad: str,
                                                     code: str) -> None:
    (tmp_path / "Main.s7dcl").write_text(MAIN, encoding="utf-8")
    (tmp_path / "Bad.db").write_text(bad, encoding="utf-8")
    _program, diagnostics, _encoding = reader.open_path(tmp_path / "Main.s7dcl", None)
    found = [d for d in diagnostics if d.code.startswith("s7-db")]
    assert [d.code for d in found] == [code]
    assert found[0].args["file"] == "Bad.db" and int(str(found[0].args["line"])) >= 1
    assert "Bad.db, line" in found[0].message()
    with pytest.raises(ParseError):
        parse_sources(bad)


def test_an_xml_global_db_with_array_subelements_and_a_db_source_beside_xml_blocks(
        tmp_path: Path) -> None:
    from ladderworks.core.dialects.s7 import xml_open
    from ladderworks.core.dialects.s7.sd_parser import parse_sd
    from ladderworks.core.dialects.s7.xml_writer import write_block
    from tests.core.dialects.s7.xml_docs import document

    db = document([], kind="GlobalDB", name="Veri", interface=(
        '<Section Name="Static"><Member Name="Dizi" Datatype="Array[1..3] of Int">'
        '<Subelement Path="1"><StartValue>4</StartValue></Subelement>'
        '<Subelement Path="3"><StartValue>-2</StartValue></Subelement></Member>'
        '<Member Name="Oran" Datatype="LReal"><StartValue>0.3</StartValue></Member>'
        '<Member Name="Ad" Datatype="String[8]"><StartValue>\'Pompa\'</StartValue></Member>'
        '<Member Name="Acik" Datatype="Bool"><StartValue>TRUE</StartValue></Member>'
        "</Section>"))
    main = parse_sd(MAIN.replace('"Hat_DB".Lamps[3]', '"Veri".Acik')).block
    (tmp_path / "Main.xml").write_text(write_block(main), "utf-8")
    (tmp_path / "Veri.xml").write_text(db, "utf-8")
    (tmp_path / "Hat_DB.db").write_text(DB, "utf-8")
    program, diagnostics, _encoding = xml_open.open_path(tmp_path, None)
    assert [d.code for d in diagnostics if d.is_error] == [], [d.message() for d in diagnostics]
    compiled = compile_program(program)
    assert compiled.binary is not None
    engine = ScanEngine(compiled.binary)
    engine.scan()
    symbols = program.symbols
    assert symbols is not None
    first = symbols.address_of('"Veri".Dizi')
    assert first is not None
    memory = engine.memory
    values = [memory.read(type(first)(first.area, first.byte + 2 * n), 2, signed=True)
              for n in range(3)]
    assert values == [4, 0, -2]
    ratio = symbols.address_of('"Veri".Oran')
    assert ratio is not None and typed.read(memory, ratio, typed.ValueType.LREAL) == 0.3
    name = symbols.address_of('"Veri".Ad')
    assert name is not None
    data = memory.areas[name.area]
    assert bytes(data[name.byte:name.byte + 7]) == bytes([8, 5]) + b"Pompa"
    # "Veri".Acik starts TRUE: the MOVE of 'Merhaba dünya' into "Hat_DB".Name ran, cut at 10
    hat = symbols.address_of('"Hat_DB".Name')
    assert hat is not None
    assert bytes(memory.areas[hat.area][hat.byte:hat.byte + 12]) == \
        bytes([10, 10]) + "Merhaba dü".encode("cp1254")


@pytest.mark.parametrize("type_name, text, shown", [
    ("Bool", "TRUE", "TRUE"), ("Int", "-7", "-7"), ("DInt", "DINT#70000", "70000"),
    ("Real", "1.5", "1.5"), ("LReal", "0.1", "0.1"), ("LReal", "LREAL#-2.25", "-2.25"),
    ("Time", "T#1m30s", "T#1M_30S"), ("Time", "T#-250ms", "T#-250MS"),
    ("Byte", "16#0F", "16#0F"), ("Word", "16#BEEF", "16#BEEF"), ("Char", "'A'", "'A'"),
    ("String[5]", "'Işık $'ta''", "'Işık '"), ("String", "'a$$b'", "'a$$b'"),
    ("WString[3]", "WSTRING#'ğüş'", "WSTRING#'ğüş'"), ("USInt", "255", "255"),
])
def test_values_are_shown_and_taken_as_tia_spells_them(type_name: str, text: str,
                                                       shown: str) -> None:
    from ladderworks.core.address import Address, Area
    from ladderworks.core.dialects.s7.layout import Place
    from ladderworks.core.dialects.s7.values import show, store
    from ladderworks.core.plc.memory import Memory

    memory = Memory(byteorder="big")
    place = Place(Address(Area.D, 10, 0 if type_name == "Bool" else None), type_name)
    store(memory, place, text)
    assert show(memory, place) == shown
    store(memory, place, shown)  # what is shown is taken back
    assert show(memory, place) == shown


@pytest.mark.parametrize("type_name, text", [
    ("Int", "70000"), ("Int", "abc"), ("String[4]", "abc"), ("LReal", "x"), ("Struct", "1"),
    ("USInt", "-1"), ("Time", "5"), ("Real", "1.0E39"), ("Real", "-3.5e38")])
def test_a_value_not_of_the_type_is_refused(type_name: str, text: str) -> None:
    from ladderworks.core.address import Address, Area
    from ladderworks.core.dialects.s7.layout import Place
    from ladderworks.core.dialects.s7.values import store
    from ladderworks.core.plc.memory import Memory

    with pytest.raises(ValueError):
        store(Memory(byteorder="big"), Place(Address(Area.D, 0), type_name), text)


def test_a_db_source_is_written_back_and_reads_the_same() -> None:
    from ladderworks.core.dialects.s7.sd_writer import source_text

    first = [p.block for p in parse_sources(DB)]
    text = "\n".join(source_text(b) for b in first)
    again = [p.block for p in parse_sources(text)]
    assert [(b.kind, b.name, b.sections, b.starts) for b in again] == \
        [(b.kind, b.name, b.sections, b.starts) for b in first]
    assert "   STRUCT\n      Count : Int := 3;" in text and "   Counts[2] := -7;" in text


def test_arrays_of_structs_and_of_plc_data_types_resolve_by_offset() -> None:
    from ladderworks.core.dialects.s7.graph import S7Program

    text = DB.replace("      M1 : \"Motor_UDT\";", """      M1 : "Motor_UDT";
      Motors : Array[1..3] of "Motor_UDT";
      Cells : Array[0..1] of Struct
         Level : Int;
         Full : Bool;
         Timer : TON_TIME;
      END_STRUCT;
      After : Int;""")
    layout = Layout(S7Program([p.block for p in parse_sources(text)]))
    cells = next(m for m in parse_sources(text)[1].block.members("Static") if m.name == "Cells")
    assert cells.type_name == "Array[0..1] of Struct" and len(cells.members) == 3
    first = layout.global_name(("Hat_DB", "Cells[0]", "Level"))
    second = layout.global_name(("Hat_DB", "Cells[1]", "Level"))
    full = layout.global_name(("Hat_DB", "Cells[1]", "Full"))
    q = layout.global_name(("Hat_DB", "Cells[1]", "Timer", "Q"))
    after = layout.global_name(("Hat_DB", "After"))
    assert None not in (first, second, full, q, after)
    assert second.address.byte - first.address.byte == 20  # Int 2, Bool 1 (+1), TON 16
    assert full.address.bit == 0 and full.address.byte == second.address.byte + 2
    assert q.address == type(q.address)(q.address.area, second.address.byte + 4 + 8, 1)
    assert after.address.byte >= first.address.byte + 40  # the array takes its room
    motor = layout.global_name(("Hat_DB", "Motors[3]", "Speed"))
    run = layout.global_name(("Hat_DB", "Motors[1]", "Run"))
    assert motor is not None and run is not None and motor.type_name == "Int"
    assert motor.address.byte - run.address.byte == 2 * 4 - 2  # elements of 4 bytes
    assert layout.global_name(("Hat_DB", "Cells[2]", "Level")) is None
    assert layout.global_name(("Hat_DB", "Cells[0]", "Nothing")) is None
