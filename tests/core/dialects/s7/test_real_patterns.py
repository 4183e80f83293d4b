"""What real TIA exports hold, as LadderWorks' own export (data/real_patterns.xml): parts with a
Version, a negated contact, a tag known only by its informative address, TIA's default
system memory names, an array element, a LiteralConstant with its ConstantType, a
TypedConstant, a LocalConstant and a GlobalConstant, a box TIA has and LadderWorks does not
(SCALE_X), a multi-instance call of an FB not exported, ENO wires, an STL network, an empty
network, titles in cultures without en-US. Everything opens and runs; what is not simulated
is a warning at its network and part (docs/dialects.md, "Real exports tried")."""

from __future__ import annotations

from pathlib import Path

from ladderworks.core.compiler import compile_program
from ladderworks.core.diagnostics import Severity
from ladderworks.core.dialects.s7.devices import parse_absolute
from ladderworks.core.dialects.s7.tags import read_tag_table
from ladderworks.core.dialects.s7.xml_reader import is_simaticml, read_document
from ladderworks.core.dialects.s7.xml_writer import flgnet_lines
from ladderworks.core.il.reading import parse_bytes, parse_file
from ladderworks.core.plc.engine import ScanEngine
from tests.core.dialects.s7.xml_docs import const, document, tag, wire

DATA = Path(__file__).parent / "data" / "real_patterns.xml"


def test_the_export_reads_with_warnings_only() -> None:
    result = parse_file(DATA)
    codes = [(d.code, d.args.get("network")) for d in result.diagnostics]
    assert all(d.severity is Severity.WARNING for d in result.diagnostics), \
        [d.message() for d in result.diagnostics]
    assert sorted(set(codes) - {("s7xml-part", 4)}) == [
        ("s7-call-unknown", 4), ("s7-not-simulated", 5), ("s7-part-unknown", 4),
        ("s7-tag-undeclared", 1)]
    by_code = {d.code: d for d in result.diagnostics}
    assert by_code["s7-part-unknown"].args["uid"] == "26"  # at its network and part
    assert by_code["s7-call-unknown"].args["uid"] == "27"
    assert "%I0.3" in by_code["s7-tag-undeclared"].message()


def test_titles_texts_and_operands_as_tia_shows_them() -> None:
    block = read_document(DATA.read_bytes()).blocks[0]
    assert block.networks[0].title == "Tür offen"  # no en-US text: the culture that has one
    assert [n.language for n in block.networks] == ["LAD", "LAD", "LAD", "LAD", "STL", "LAD"]
    assert block.networks[4].source.splitlines() == ["A #Baslat", "= #Gecici"]
    assert block.networks[5].parts == []
    move = block.networks[1]
    texts = {w.targets[0].pin: w.source.operand.display() for w in move.wires
             if w.source.operand is not None}
    assert texts == {"in": "5", "operand": "#Bayraklar[3]"}
    contact = block.networks[0].part("24")
    assert contact is not None and contact.negated == frozenset({"operand"})


def _engine() -> ScanEngine:
    result = parse_file(DATA)
    compiled = compile_program(result.program)
    assert compiled.binary is not None, [d.message() for d in compiled.diagnostics]
    return ScanEngine(compiled.binary)


def test_it_runs_what_it_reads() -> None:
    engine = _engine()
    symbols = parse_file(DATA).program.symbols
    engine.scan()
    # NOT "Kapi_Acik" (%I0.3, from the export's informative address) AND "AlwaysTRUE"
    assert engine.memory.bit(parse_absolute("%Q0.1")[0]) == 1
    engine.memory.set_bit(parse_absolute("%I0.3")[0], 1)
    engine.scan()
    assert engine.memory.bit(parse_absolute("%Q0.1")[0]) == 0
    # MOVE 5 → #Sayi, its ENO → #Bayraklar[3] (Array[1..8] of Bool, a byte each from #Bayraklar)
    assert engine.memory.read(symbols.by_symbol["#Sayi"], 2, signed=True) == 5
    flags = symbols.by_symbol["#Bayraklar"]
    third = type(flags)(flags.area, flags.byte + 2, 0)
    assert engine.memory.bit(third) == 1
    # #Sayi > SINIR (a LocalConstant, 10) is false: SCALE_X and the call pass no power
    assert engine.memory.read(symbols.by_symbol["#SINIR"], 2, signed=True) == 10
    assert engine.memory.bit(symbols.by_symbol["#Gecici"]) == 0


def _abs(uid: int, area: str, bit: int) -> str:
    return (f'<Access Scope="GlobalVariable" UId="{uid}"><Address Area="{area}" Type="Bool" '
            f'BitOffset="{bit}" /></Access>')


def test_a_box_not_simulated_passes_en_to_eno_and_nothing_else() -> None:
    """%I0.0 → SCALE_X (EN); its ENO → %Q0.0, its Q → %Q0.1 (no power: not simulated)."""
    body = ("<Parts>" + _abs(21, "Input", 0) + _abs(22, "Output", 0) + _abs(23, "Output", 1) +
            '<Part Name="Contact" UId="30" /><Part Name="SCALE_X" Version="1.0" UId="31" />'
            '<Part Name="Coil" UId="32" /><Part Name="Coil" UId="33" /></Parts><Wires>' +
            wire(40, "rail", "30:in") + wire(41, "21", "30:operand") +
            wire(42, "30:out", "31:en") + wire(43, "31:eno", "32:in") +
            wire(44, "22", "32:operand") + wire(45, "31:q", "33:in") +
            wire(46, "23", "33:operand") + "</Wires>")
    result = parse_bytes(document([body]).encode("utf-8"))
    shown = [d for d in result.diagnostics if d.code == "s7-part-unknown"]
    assert len(shown) == 1 and shown[0].severity is Severity.WARNING
    assert shown[0].args == {"network": 1, "uid": "31", "part": "SCALE_X"}
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    engine = ScanEngine(compiled.binary)
    for value in (1, 0, 1):
        engine.memory.set_bit(parse_absolute("%I0.0")[0], value)
        engine.scan()
        assert engine.memory.bit(parse_absolute("%Q0.0")[0]) == value
        assert engine.memory.bit(parse_absolute("%Q0.1")[0]) == 0


def test_default_system_memory_names_are_known_and_a_declared_tag_wins() -> None:
    body = ("<Parts>" + tag(21, "FirstScan") + _abs(22, "Output", 0) +
            '<Part Name="Contact" UId="30" /><Part Name="Coil" UId="31" /></Parts><Wires>' +
            wire(40, "rail", "30:in") + wire(41, "21", "30:operand") +
            wire(42, "30:out", "31:in") + wire(43, "22", "31:operand") + "</Wires>")
    result = parse_bytes(document([body]).encode("utf-8"))
    assert result.diagnostics == []
    assert result.program.symbols.by_symbol['"FirstScan"'] == parse_absolute("%M1.0")[0]
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    engine = ScanEngine(compiled.binary)
    engine.scan()
    first = engine.memory.bit(parse_absolute("%Q0.0")[0])
    engine.scan()
    assert (first, engine.memory.bit(parse_absolute("%Q0.0")[0])) == (1, 0)


UDT = Path(__file__).parent / "data" / "udt"


def test_a_plc_data_type_export_gives_its_members_to_a_db_and_a_missing_db_is_laid_out() -> None:
    """Tip_Motor.xml (SW.Types.PlcStruct), DB_Hat.xml ("Motor1" : "Tip_Motor"), FC_Hat.xml:
    "DB_Hat".Motor1.Calisiyor → "DB_Uyari".Lamba, a DB not exported (its DB120 is beyond
    the DBs LadderWorks addresses: a place of its own)."""
    for opened in (UDT, UDT / "FC_Hat.xml", UDT / "Tip_Motor.xml"):  # the folder, or any file
        result = parse_file(opened)
        assert [(d.code, d.severity) for d in result.diagnostics] == [
            ("s7-tag-undeclared", Severity.WARNING)]
        symbols = result.program.symbols.by_symbol
        assert {'"DB_Hat".Motor1.Calisiyor', '"DB_Hat".Motor1.Hiz', '"DB_Uyari".Lamba'} <= \
            set(symbols)
        compiled = compile_program(result.program)
        assert compiled.binary is not None
        engine = ScanEngine(compiled.binary)
        engine.scan()
        assert engine.memory.read(symbols['"DB_Hat".Adet'], 2) == 3  # its start value
        assert engine.memory.bit(symbols['"DB_Uyari".Lamba']) == 0
        engine.memory.set_bit(symbols['"DB_Hat".Motor1.Calisiyor'], 1)
        engine.scan()
        assert engine.memory.bit(symbols['"DB_Uyari".Lamba']) == 1


def test_a_tag_table_or_type_export_is_known_as_simaticml() -> None:
    assert is_simaticml((UDT / "Tip_Motor.xml").read_text("utf-8"))
    table = ('<?xml version="1.0" encoding="utf-8"?>\n<Document><SW.Tags.PlcTagTable ID="0">'
             '<AttributeList><Name>T</Name></AttributeList></SW.Tags.PlcTagTable></Document>')
    assert is_simaticml(table)
    assert not is_simaticml("<Document><Other /></Document>")


def test_a_piece_of_an_export_is_named_for_what_it_lacks(tmp_path: Path) -> None:
    """A CompileUnit cut out of an export (as tools keep templates): no crash, s7xml-empty."""
    piece = tmp_path / "Network.xml"
    piece.write_text('<SW.Blocks.CompileUnit ID="4" CompositionName="CompileUnits">'
                     '<AttributeList><NetworkSource /></AttributeList>'
                     '</SW.Blocks.CompileUnit>', "utf-8")
    result = parse_file(piece)
    assert [(d.code, d.line) for d in result.diagnostics] == [("s7xml-empty", 1)]


def test_a_network_not_lowered_is_a_warning_and_the_rest_still_compiles() -> None:
    """A contact on a member the block does not have (s7-operand-unknown) leaves its network
    out; the other network runs."""
    bad = ("<Parts>" + tag(21, "Yok", scope="LocalVariable") + _abs(22, "Output", 1) +
           '<Part Name="Contact" UId="30" /><Part Name="Coil" UId="31" /></Parts><Wires>' +
           wire(40, "rail", "30:in") + wire(41, "21", "30:operand") +
           wire(42, "30:out", "31:in") + wire(43, "22", "31:operand") + "</Wires>")
    good = ("<Parts>" + _abs(21, "Input", 0) + _abs(22, "Output", 0) +
            '<Part Name="Contact" UId="30" /><Part Name="Coil" UId="31" /></Parts><Wires>' +
            wire(40, "rail", "30:in") + wire(41, "21", "30:operand") +
            wire(42, "30:out", "31:in") + wire(43, "22", "31:operand") + "</Wires>")
    interface = ('<Section Name="Static"><Member Name="Lamba" Datatype="Bool" /></Section>')
    result = parse_bytes(document([bad, good], interface=interface, kind="FB",
                                  name="Deneme").encode("utf-8"))
    assert [(d.code, d.severity, d.args["network"]) for d in result.diagnostics] == [
        ("s7-operand-unknown", Severity.WARNING, 1)]
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    engine = ScanEngine(compiled.binary)
    engine.memory.set_bit(parse_absolute("%I0.0")[0], 1)
    engine.scan()
    assert engine.memory.bit(parse_absolute("%Q0.0")[0]) == 1


def test_a_disabled_eno_move_a_compare_on_its_eno_and_a_box_tia_has() -> None:
    """real2/Vanalar.xml: the rail feeds three parts; MOVE (DisabledENO) 0 → "DB_Deger".Vana.
    "21".Mod (a DB not exported), its ENO → [Mod == 0] → R "DB_Deger".Vana."21".Elle;
    #Izin → %Q0.2; MOVE_BLK_VARIANT shown only."""
    result = parse_file(Path(__file__).parent / "data" / "real2" / "Vanalar.xml")
    assert sorted({(d.code, d.severity) for d in result.diagnostics}) == [
        ("s7-part-unknown", Severity.WARNING), ("s7-tag-undeclared", Severity.WARNING),
        ("s7xml-part", Severity.WARNING)]
    assert "(Int)" in next(d.message() for d in result.diagnostics
                           if d.code == "s7-tag-undeclared")
    symbols = result.program.symbols.by_symbol
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    engine = ScanEngine(compiled.binary)
    engine.memory.set_bit(symbols['"DB_Deger".Vana.21.Elle'], 1)
    engine.memory.write(symbols['"DB_Deger".Vana.21.Mod'], 7, 2)
    engine.memory.set_bit(symbols["#Izin"], 1)
    engine.scan()
    assert engine.memory.read(symbols['"DB_Deger".Vana.21.Mod'], 2) == 0
    assert engine.memory.bit(symbols['"DB_Deger".Vana.21.Elle']) == 0
    assert engine.memory.bit(parse_absolute("%Q0.2")[0]) == 1


def test_a_lad_pbox_is_p_trig_and_is_written_back_as_pbox() -> None:
    """SimaticML's LAD P_TRIG is `Part Name="PBox"` (in, bit → out): the power after it is on
    for one scan when the power before it rises."""
    body = ("<Parts>" + _abs(21, "Input", 0) + _abs(22, "Memory", 80) + _abs(23, "Output", 0) +
            '<Part Name="Contact" UId="30" /><Part Name="PBox" UId="31" />'
            '<Part Name="Coil" UId="32" /></Parts><Wires>' +
            wire(40, "rail", "30:in") + wire(41, "21", "30:operand") +
            wire(42, "30:out", "31:in") + wire(43, "22", "31:bit") +
            wire(44, "31:out", "32:in") + wire(45, "23", "32:operand") + "</Wires>")
    text = document([body])
    network = read_document(text).blocks[0].networks[0]
    assert [p.name for p in network.parts] == ["Contact", "PTrig", "Coil"]
    assert 'Name="PBox"' in "\n".join(flgnet_lines(network))
    result = parse_bytes(text.encode("utf-8"))
    assert result.diagnostics == []
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    engine = ScanEngine(compiled.binary)
    seen = []
    for value in (0, 1, 1, 0, 1):
        engine.memory.set_bit(parse_absolute("%I0.0")[0], value)
        engine.scan()
        seen.append(engine.memory.bit(parse_absolute("%Q0.0")[0]))
    assert seen == [0, 1, 0, 0, 1]


def test_a_graph_block_opens_shows_its_sequence_and_is_not_simulated() -> None:
    path = Path(__file__).parent / "data" / "graph" / "Sira.xml"
    [network] = read_document(path.read_bytes()).blocks[0].networks
    assert network.language == "GRAPH"
    assert network.source.splitlines() == [
        "GRAPH Dolum sırası", "S1 Doldur (initial)", "S2 Bosalt", "T1 Dolu: S1 -> S2",
        "T2 Bos: S2 -> S1 (jump)"]
    result = parse_file(path)
    assert [(d.code, d.severity, d.args.get("language")) for d in result.diagnostics] == [
        ("s7-not-simulated", Severity.WARNING, "GRAPH")]
    assert compile_program(result.program).binary is not None


def test_an_empty_tag_table_is_read_as_empty_not_refused() -> None:
    """TIA's "Default tag table" of a new project has no tag: an empty table, no error."""
    table = ('<?xml version="1.0" encoding="utf-8"?>\n<Document>\n  <Engineering version="V17" />'
             '\n  <SW.Tags.PlcTagTable ID="0">\n    <AttributeList>\n      <Name>Varsayılan'
             '</Name>\n    </AttributeList>\n  </SW.Tags.PlcTagTable>\n</Document>')
    assert read_tag_table(table) == ([], [])
    found = read_document(table)
    assert (found.blocks, found.tags, found.diagnostics) == ([], [], [])
    assert read_tag_table("<Document />")[1][0].code == "s7-tags"  # no table at all


def _tag_table(*tags: tuple[str, str, str]) -> str:
    rows = "".join(f'<SW.Tags.PlcTag ID="{n + 1}" CompositionName="Tags"><AttributeList>'
                   f"<DataTypeName>{kind}</DataTypeName><LogicalAddress>{address}"
                   f"</LogicalAddress><Name>{name}</Name></AttributeList></SW.Tags.PlcTag>"
                   for n, (name, kind, address) in enumerate(tags))
    return ('<?xml version="1.0" encoding="utf-8"?>\n<Document><SW.Tags.PlcTagTable ID="0">'
            "<AttributeList><Name>Default tag table</Name></AttributeList><ObjectList>"
            f"{rows}</ObjectList></SW.Tags.PlcTagTable></Document>")


def test_a_block_of_a_vci_workspace_reads_the_tags_of_its_plc_folder(tmp_path: Path) -> None:
    """TIA's Version Control Interface keeps `PLC_1/Program blocks/Main.xml` and
    `PLC_1/PLC tags/Default tag table.xml`: opening the block (or either folder) reads both."""
    body = ("<Parts>" + tag(21, "Basla") + tag(22, "Lamba") +
            '<Part Name="Contact" UId="30" /><Part Name="Coil" UId="31" /></Parts><Wires>' +
            wire(40, "rail", "30:in") + wire(41, "21", "30:operand") +
            wire(42, "30:out", "31:in") + wire(43, "22", "31:operand") + "</Wires>")
    blocks = tmp_path / "PLC_1" / "Program blocks" / "Motor"
    blocks.mkdir(parents=True)
    (blocks / "Main.xml").write_text(document([body]), "utf-8")
    table = tmp_path / "PLC_1" / "PLC tags"
    table.mkdir()
    (table / "Default tag table.xml").write_text(
        _tag_table(("Basla", "Bool", "%I0.0"), ("Lamba", "Bool", "%Q0.0")), "utf-8")
    for opened in (blocks / "Main.xml", blocks, table):
        result = parse_file(opened)
        assert result.diagnostics == [], [d.message() for d in result.diagnostics]
        assert result.program.symbols.by_symbol['"Lamba"'] == parse_absolute("%Q0.0")[0]


def test_a_user_constant_of_a_tag_table_is_its_value(tmp_path: Path) -> None:
    """`SW.Tags.PlcUserConstant` (Name, DataTypeName, Value) named by a `GlobalConstant`
    access: the value, in a compare and as a contact's Bool; no place of its own."""
    (tmp_path / "Sabitler.xml").write_text(
        '<?xml version="1.0" encoding="utf-8"?>\n<Document><SW.Tags.PlcTagTable ID="0">'
        "<AttributeList><Name>Sabitler</Name></AttributeList><ObjectList>"
        '<SW.Tags.PlcUserConstant ID="1" CompositionName="UserConstants"><AttributeList>'
        "<DataTypeName>Int</DataTypeName><Name>SINIR</Name><Value>7</Value></AttributeList>"
        '</SW.Tags.PlcUserConstant><SW.Tags.PlcUserConstant ID="2" CompositionName='
        '"UserConstants"><AttributeList><DataTypeName>Bool</DataTypeName><Name>ACIK</Name>'
        "<Value>True</Value></AttributeList></SW.Tags.PlcUserConstant></ObjectList>"
        "</SW.Tags.PlcTagTable></Document>", "utf-8")
    body = ("<Parts>" + _abs(21, "Memory", 16).replace('Type="Bool"', 'Type="Int"') +
            '<Access Scope="GlobalConstant" UId="22"><Constant Name="SINIR" /></Access>'
            '<Access Scope="GlobalConstant" UId="23"><Constant Name="ACIK" /></Access>' +
            _abs(24, "Output", 0) +
            '<Part Name="Gt" UId="30"><TemplateValue Name="SrcType" Type="Type">Int'
            '</TemplateValue></Part><Part Name="Contact" UId="31" /><Part Name="Coil" UId="32" />'
            "</Parts><Wires>" + wire(40, "rail", "30:pre") + wire(41, "21", "30:in1") +
            wire(42, "22", "30:in2") + wire(43, "30:out", "31:in") + wire(44, "23", "31:operand") +
            wire(45, "31:out", "32:in") + wire(46, "24", "32:operand") + "</Wires>")
    (tmp_path / "Main.xml").write_text(document([body]), "utf-8")
    result = parse_file(tmp_path / "Main.xml")
    assert result.diagnostics == [], [d.message() for d in result.diagnostics]
    assert '"SINIR"' not in result.program.symbols.by_symbol
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    engine = ScanEngine(compiled.binary)
    for value, lamp in ((7, 0), (8, 1)):
        engine.memory.write(parse_absolute("%MW2")[0], value, 2)
        engine.scan()
        assert engine.memory.bit(parse_absolute("%Q0.0")[0]) == lamp


def test_a_folder_with_several_obs_runs_ob1(tmp_path: Path) -> None:
    """A PLC's folder holds OB1 and e.g. OB86 (a rack failure OB): OB1 is the program run,
    whatever the files' names."""
    body = ("<Parts>" + _abs(21, "Input", 0) + _abs(22, "Output", 0) +
            '<Part Name="Contact" UId="30" /><Part Name="Coil" UId="31" /></Parts><Wires>' +
            wire(40, "rail", "30:in") + wire(41, "21", "30:operand") +
            wire(42, "30:out", "31:in") + wire(43, "22", "31:operand") + "</Wires>")
    fault = document([], name="RACK_FLT").replace("<Number>1</Number>", "<Number>86</Number>")
    (tmp_path / "A_RACK_FLT.xml").write_text(fault, "utf-8")
    (tmp_path / "Z_Main.xml").write_text(document([body]), "utf-8")
    result = parse_file(tmp_path)
    assert result.program.title == {1: "Main"}
    assert [i.name for n in result.program.networks for i in n.instructions] == ["RD", "WRT"]


def test_an_automatically_typed_add_on_mixed_types_is_not_simulated() -> None:
    """`<Part Name="Add" DisabledENO="true">` with `<AutomaticTyped Name="SrcType"/>` and no
    SrcType: on Int + Real TIA converts, LadderWorks does not (warning); on Int + Int it runs."""
    interface = ('<Section Name="Input"><Member Name="a" Datatype="Int" />'
                 '<Member Name="b" Datatype="Real" /><Member Name="c" Datatype="Int" />'
                 '</Section><Section Name="Output"><Member Name="s" Datatype="Real" />'
                 '<Member Name="t" Datatype="Int" /></Section>')

    def add(first: str, second: str, out: str) -> str:
        return ("<Parts>" + tag(21, first, scope="LocalVariable") +
                tag(22, second, scope="LocalVariable") + tag(23, out, scope="LocalVariable") +
                '<Part Name="Add" UId="30" DisabledENO="true"><TemplateValue Name="Card" '
                'Type="Cardinality">2</TemplateValue><AutomaticTyped Name="SrcType" /></Part>'
                "</Parts><Wires>" + wire(40, "rail", "30:en") + wire(41, "21", "30:in1") +
                wire(42, "22", "30:in2") + wire(43, "30:out", "23") + "</Wires>")

    text = document([add("a", "b", "s"), add("a", "c", "t")], interface=interface, kind="FC",
                    name="funkce")
    result = parse_bytes(text.encode("utf-8"))
    assert [(d.code, d.severity, d.args["network"], d.args["type"])
            for d in result.diagnostics] == [("s7-type", Severity.WARNING, 1, "Int / Real")]
    symbols = result.program.symbols.by_symbol
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    engine = ScanEngine(compiled.binary)
    engine.memory.write(symbols["#a"], 2, 2)
    engine.memory.write(symbols["#c"], 3, 2)
    engine.scan()
    assert engine.memory.read(symbols["#t"], 2) == 5


def test_an_access_of_a_scope_not_read_is_named_and_its_network_left_out() -> None:
    body = ('<Parts><Access Scope="Indirect" UId="21" />' + _abs(22, "Output", 0) +
            '<Part Name="Contact" UId="30" /><Part Name="Coil" UId="31" /></Parts><Wires>' +
            wire(40, "rail", "30:in") + wire(41, "21", "30:operand") +
            wire(42, "30:out", "31:in") + wire(43, "22", "31:operand") + "</Wires>")
    result = parse_bytes(document([body]).encode("utf-8"))
    found = [(d.code, d.severity) for d in result.diagnostics]
    assert found == [("s7xml-access", Severity.WARNING), ("s7-operand-unknown", Severity.WARNING)]
    assert "Indirect" in result.diagnostics[0].message()
    assert "<Indirect>" in result.diagnostics[1].message()


def test_disabled_eno_keeps_eno_on_when_the_box_overflows() -> None:
    """ADD 32767 + 1 into an Int overflows: its ENO is 0, unless the box's ENO is disabled
    (`DisabledENO="true"`, as TIA writes boxes placed without ENO), when ENO is EN."""
    def net(disabled: bool, coil: int) -> str:
        flag = ' DisabledENO="true"' if disabled else ""
        return ("<Parts>" + const(21, "32767", "Int") + const(22, "1", "Int") +
                _abs(23, "Memory", 160).replace('Type="Bool"', 'Type="Int"') +
                _abs(24, "Output", coil) +
                f'<Part Name="Add" UId="30"{flag}><TemplateValue Name="SrcType" Type="Type">Int'
                '</TemplateValue></Part><Part Name="Coil" UId="31" /></Parts><Wires>' +
                wire(40, "rail", "30:en") + wire(41, "21", "30:in1") + wire(42, "22", "30:in2") +
                wire(43, "30:out", "23") + wire(44, "30:eno", "31:in") +
                wire(45, "24", "31:operand") + "</Wires>")

    text = document([net(False, 0), net(True, 1)])
    parts = read_document(text).blocks[0].networks[1].parts
    assert [p.disabled_eno for p in parts] == [True, False]
    assert 'DisabledENO="true"' in "\n".join(
        flgnet_lines(read_document(text).blocks[0].networks[1]))
    result = parse_bytes(text.encode("utf-8"))
    assert result.diagnostics == []
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    engine = ScanEngine(compiled.binary)
    engine.scan()
    assert (engine.memory.bit(parse_absolute("%Q0.0")[0]),
            engine.memory.bit(parse_absolute("%Q0.1")[0])) == (0, 1)
