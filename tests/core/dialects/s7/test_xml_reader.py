"""The SimaticML XML reader: the same graph as the SD reader for every example, namespaces
unversioned … v5 (a newer one read with a warning, a foreign one refused), every part kind,
interfaces, constants, addresses, labels, calls, SCL text, all cultures of the titles."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from ladderworks.cli import main
from ladderworks.core.dialects.s7.graph import OperandKind
from ladderworks.core.dialects.s7.sd_parser import parse_sd
from ladderworks.core.dialects.s7.texts import pick, read_texts
from ladderworks.core.dialects.s7.xml_reader import read_document
from ladderworks.core.dialects.s7.xml_writer import write_block
from ladderworks.core.il.printer import encode_program
from ladderworks.core.il.reading import parse_bytes, parse_file
from tests.core.dialects.s7.xml_docs import const, document, same_block, tag, wire

ROOT = Path(__file__).resolve().parents[4] / "resources" / "examples"
NAMES = ("timers", "counters", "compare", "jumps", "jump_list", "switch")
OPENNESS = "http://www.siemens.com/automation/Openness/SW/"


def _sd(name: str, stem: str = "Main"):
    folder = ROOT / "s7" / name
    parsed = parse_sd((folder / f"{stem}.s7dcl").read_text("utf-8-sig"))
    texts = read_texts((folder / "Main.s7res").read_text("utf-8-sig"))
    for network, (title, _comment) in zip(parsed.block.networks, parsed.title_ids, strict=True):
        network.title = pick(texts, title) if title else ""
    return parsed.block


@pytest.mark.parametrize("name", NAMES)
def test_the_xml_twin_gives_the_same_graph_as_the_sd_example(name: str) -> None:
    found = read_document((ROOT / "s7-xml" / name / "Main.xml").read_bytes())
    assert found.diagnostics == []
    assert len(found.blocks) == 1
    sd, xml = _sd(name), found.blocks[0]
    assert same_block(sd, xml) == []
    assert [n.title for n in xml.networks] == [n.title for n in sd.networks]


@pytest.mark.parametrize("stem", ["Main", "Kilit", "Gecikme", "Gecikme_DB"])
def test_every_block_of_the_calls_example_reads_alike(stem: str) -> None:
    found = read_document((ROOT / "s7-xml" / "calls" / f"{stem}.xml").read_bytes())
    assert found.diagnostics == []
    assert same_block(_sd("calls", stem), found.blocks[0]) == []


@pytest.mark.parametrize("scenario", ["Main", "Kilit"])
def test_the_calls_example_passes_both_scenarios(scenario: str,
                                                 capsys: pytest.CaptureFixture[str]) -> None:
    folder = ROOT / "s7-xml" / "calls"
    assert main(["test", str(folder / f"{scenario}.xml"),
                 str(folder / f"{scenario}.scenario.csv")]) == 0, capsys.readouterr().out


def test_an_fb_call_runs_without_its_instance_db_export(tmp_path: Path,
                                                        capsys: pytest.CaptureFixture[str]
                                                        ) -> None:
    folder = ROOT / "s7-xml" / "calls"
    for name in ("Main.xml", "Kilit.xml", "Gecikme.xml", "PLC tags.xml", "Main.scenario.csv"):
        (tmp_path / name).write_bytes((folder / name).read_bytes())
    assert main(["test", str(tmp_path / "Main.xml"), str(tmp_path / "Main.scenario.csv")]) == 0
    assert "1 passed, 0 failed" in capsys.readouterr().out
    (tmp_path / "Gecikme.xml").unlink()
    result = parse_file(tmp_path / "Main.xml")
    missing = [d for d in result.diagnostics if d.code == "s7xml-call-missing"]
    assert [(d.args["network"], d.args["callee"]) for d in missing] == [(2, "Gecikme")]


@pytest.mark.parametrize("name", NAMES)
def test_the_xml_example_passes_the_sd_examples_scenario(name: str,
                                                         capsys: pytest.CaptureFixture[str]
                                                         ) -> None:
    folder = ROOT / "s7-xml" / name
    assert main(["test", str(folder / "Main.xml"), str(folder / "Main.scenario.csv")]) == 0
    assert "1 passed, 0 failed" in capsys.readouterr().out


def test_the_timer_example_passes_scanning_every_scan(capsys: pytest.CaptureFixture[str]
                                                      ) -> None:
    folder = ROOT / "s7-xml" / "timers"
    assert main(["test", "--every-scan", str(folder / "Main.xml"),
                 str(folder / "Main.scenario.csv")]) == 0, capsys.readouterr().out


@pytest.mark.parametrize("name", NAMES)
def test_the_xml_example_opens_clean_and_saves_byte_for_byte(name: str) -> None:
    path = ROOT / "s7-xml" / name / "Main.xml"
    result = parse_file(path)
    assert result.diagnostics == []
    assert result.program.dialect == "s7"
    assert result.program.networks
    assert encode_program(result.program) == path.read_bytes()


def test_a_folder_of_xml_exports_opens_as_one_program(capsys: pytest.CaptureFixture[str]
                                                      ) -> None:
    assert main(["check", str(ROOT / "s7-xml" / "counters")]) == 0, capsys.readouterr().out


# -- namespaces --------------------------------------------------------------------------
_NET = ("<Parts>" + tag(21, "Start") + tag(22, "Lamba") +
        '<Part Name="Contact" UId="23" /><Part Name="Coil" UId="24" /></Parts><Wires>' +
        wire(30, "rail", "23:in") + wire(31, "21", "23:operand") + wire(32, "23:out", "24:in") +
        wire(33, "22", "24:operand") + "</Wires>")


@pytest.mark.parametrize("version", ["", "/v1", "/v2", "/v3", "/v4", "/v5"])
def test_every_known_namespace_version_reads_alike(version: str) -> None:
    text = document([_NET], flgnet=OPENNESS + "NetworkSource/FlgNet" + version,
                    interface_ns=OPENNESS + "Interface" + version,
                    interface='<Section Name="Temp"><Member Name="x" Datatype="Bool" /></Section>')
    found = read_document(text)
    assert found.diagnostics == []
    reference = read_document(document([_NET], interface='<Section Name="Temp"><Member '
                                       'Name="x" Datatype="Bool" /></Section>')).blocks[0]
    assert same_block(found.blocks[0], reference) == []
    assert [p.name for p in found.blocks[0].networks[0].parts] == ["Contact", "Coil"]


def test_a_newer_namespace_version_is_read_as_v5_with_a_warning() -> None:
    found = read_document(document([_NET], flgnet=OPENNESS + "NetworkSource/FlgNet/v6"))
    assert [d.code for d in found.diagnostics] == ["s7xml-version"]
    assert "v6" in found.diagnostics[0].message() and found.diagnostics[0].severity == "warning"
    assert len(found.blocks[0].networks[0].parts) == 2


def test_a_newer_interface_namespace_is_read_with_a_warning() -> None:
    found = read_document(document([_NET], interface_ns=OPENNESS + "Interface/v7",
                                   interface='<Section Name="Temp"><Member Name="x" '
                                   'Datatype="Bool" /></Section>'))
    assert [(d.code, d.args["kind"], d.args["version"]) for d in found.diagnostics] == [
        ("s7xml-version", "Interface", 7)]
    assert found.blocks[0].members("Temp")[0].name == "x"


def test_a_foreign_namespace_is_refused_at_its_network() -> None:
    found = read_document(document([_NET], flgnet="http://example.com/FlgNet"))
    assert [d.code for d in found.diagnostics] == ["s7xml-namespace"]
    assert found.diagnostics[0].args["network"] == 1
    assert found.blocks[0].networks[0].parts == []


def test_writer_and_reader_agree_in_every_namespace_version() -> None:
    sd = _sd("jumps")
    for version in range(6):
        text = write_block(sd, version)
        assert (f"FlgNet/v{version}" in text) == bool(version)
        found = read_document(text)
        assert found.diagnostics == []
        assert same_block(sd, found.blocks[0]) == []


# -- part kinds ----------------------------------------------------------------------------
# (part XML, its wires, expected (pin → operand display) reads, expected output writes)
def _one(part: str, wires: str, accesses: str = "") -> tuple:
    found = read_document(document([f"<Parts>{accesses}{part}</Parts><Wires>{wires}</Wires>"]))
    assert [d.code for d in found.diagnostics if d.code != "s7xml-part"] == []
    network = found.blocks[0].networks[0]
    reads = {t.pin: w.source.operand.display() for w in network.wires for t in w.targets
             if w.source.operand is not None}
    writes = {w.source.pin: t.operand.display() for w in network.wires for t in w.targets
              if t.operand is not None}
    power = sorted(t.pin for w in network.wires for t in w.targets
                   if (w.source.powerrail or w.source.part) and t.part)
    return network, reads, writes, power


@pytest.mark.parametrize("name", ["Contact", "PContact", "NContact", "Coil", "SCoil", "RCoil",
                                  "PCoil", "NCoil", "Ok", "NotOk"])
def test_contacts_and_coils(name: str) -> None:
    negated = '<Negated Name="operand" />' if name == "Contact" else ""
    network, reads, _writes, power = _one(
        f'<Part Name="{name}" UId="23">{negated}</Part>',
        wire(30, "rail", "23:" + ("pre" if name in ("Ok", "NotOk") else "in")) +
        wire(31, "21", "23:operand") + wire(32, "22", "23:bit"),
        tag(21, "Start") + tag(22, "Kenar"))
    part = network.parts[0]
    assert part.name == name
    assert reads == {"operand": '"Start"', "bit": '"Kenar"'}
    assert power == ["in"]
    assert part.negated == (frozenset({"operand"}) if name == "Contact" else frozenset())


@pytest.mark.parametrize("name", ["TP", "TON", "TOF", "TONR"])
def test_timers(name: str) -> None:
    network, reads, writes, power = _one(
        f'<Part Name="{name}" UId="23" Version="1.0"><Instance Scope="GlobalVariable" UId="24">'
        '<Component Name="T_DB" /></Instance><TemplateValue Name="time_type" Type="Type">Time'
        "</TemplateValue></Part>",
        wire(30, "rail", "23:IN") + wire(31, "21", "23:PT") + wire(32, "23:ET", "22") +
        wire(33, "23:Q", "open") + (wire(34, "25", "23:R") if name == "TONR" else ""),
        const(21, "T#2s") + tag(22, "Geçen") + tag(25, "Sıfır"))
    part = network.parts[0]
    assert part.instance.path == ("T_DB",) and part.instance.kind is OperandKind.GLOBAL
    assert part.template == {"time_type": "Time"}
    assert reads["pt"] == "T#2s" and writes == {"et": '"Geçen"'} and power == ["in"]
    assert ("r" in reads) == (name == "TONR")


@pytest.mark.parametrize("name", ["CTU", "CTD", "CTUD"])
def test_counters_with_a_local_instance(name: str) -> None:
    count = {"CTU": "CU", "CTD": "CD", "CTUD": "CU"}[name]
    network, reads, writes, power = _one(
        f'<Part Name="{name}" UId="23"><Instance Scope="LocalVariable" UId="24"><Component '
        'Name="Cnt" /></Instance><TemplateValue Name="value_type" Type="Type">Int'
        "</TemplateValue></Part>",
        wire(30, "rail", f"23:{count}") + wire(31, "21", "23:PV") + wire(32, "23:CV", "22"),
        const(21, "Int#5") + tag(22, "Değer"))
    part = network.parts[0]
    assert part.instance.display() == "#Cnt"
    assert reads == {"pv": "Int#5"} and writes == {"cv": '"Değer"'}
    assert power == [count.lower()]
    constant = next(w.source.operand for w in network.wires if w.source.operand)
    assert constant.type_name == "Int"


@pytest.mark.parametrize("name", ["Eq", "Ne", "Gt", "Lt", "Ge", "Le"])
def test_comparisons(name: str) -> None:
    network, reads, _writes, power = _one(
        f'<Part Name="{name}" UId="23"><TemplateValue Name="SrcType" Type="Type">Int'
        "</TemplateValue></Part>",
        wire(30, "rail", "23:pre") + wire(31, "21", "23:in1") + wire(32, "22", "23:in2"),
        tag(21, "Seviye") + const(22, "10", "Int"))
    assert reads == {"in1": '"Seviye"', "in2": "10"}
    assert power == ["in"]  # SimaticML's pre is the SD reader's in
    assert network.parts[0].template == {"SrcType": "Int"}


@pytest.mark.parametrize("name", ["InRange", "OutRange"])
def test_ranges(name: str) -> None:
    _network, reads, _writes, power = _one(
        f'<Part Name="{name}" UId="23" />',
        wire(30, "rail", "23:pre") + wire(31, "21", "23:min") + wire(32, "22", "23:in") +
        wire(33, "20", "23:max"),
        const(21, "50", "Int") + tag(22, "Sıcaklık") + const(20, "150", "Int"))
    assert reads == {"min": "50", "in": '"Sıcaklık"', "max": "150"} and power == ["in"]


@pytest.mark.parametrize("name", ["Move", "Add", "Sub", "Mul", "Div", "Convert"])
def test_boxes(name: str) -> None:
    first = "in" if name in ("Move", "Convert") else "in1"
    out = "out1" if name == "Move" else "out"
    _network, reads, writes, power = _one(
        f'<Part Name="{name}" UId="23"><TemplateValue Name="Card" Type="Cardinality">2'
        "</TemplateValue></Part>",
        wire(30, "rail", "23:en") + wire(31, "21", f"23:{first}") +
        wire(32, "22", "23:in2") + wire(33, f"23:{out}", "20") + wire(34, "23:eno", "open"),
        tag(21, "A") + const(22, "3", "Int") + tag(20, "DB", "Toplam"))
    assert reads[first] == '"A"' and writes == {out: '"DB".Toplam'} and power == ["en"]


@pytest.mark.parametrize("name", ["Inc", "Dec"])
def test_inc_dec(name: str) -> None:
    _network, reads, _writes, power = _one(
        f'<Part Name="{name}" UId="23" />',
        wire(30, "rail", "23:en") + wire(31, "21", "23:operand"), tag(21, "Sayaç"))
    assert reads == {"operand": '"Sayaç"'} and power == ["en"]


def test_sr_rs_and_or_branches() -> None:
    network, reads, _writes, power = _one(
        '<Part Name="Contact" UId="23" /><Part Name="Contact" UId="24" />'
        '<Part Name="O" UId="25"><TemplateValue Name="Card" Type="Cardinality">2</TemplateValue>'
        '</Part><Part Name="Sr" UId="26" />',
        wire(30, "rail", "23:in", "24:in") + wire(31, "21", "23:operand") +
        wire(32, "22", "24:operand") + wire(33, "23:out", "25:in1") +
        wire(34, "24:out", "25:in2") + wire(35, "25:out", "26:s") + wire(36, "22", "26:r1") +
        wire(37, "20", "26:operand"),
        tag(21, "A") + tag(22, "B") + tag(20, "Röle"))
    assert [p.name for p in network.parts] == ["Contact", "Contact", "O", "Sr"]
    rail = next(w for w in network.wires if w.source.powerrail)
    assert [t.part for t in rail.targets] == ["23", "24"]  # one wire, two targets: a branch
    assert reads["r1"] == '"B"' and power == ["in", "in", "in1", "in2", "s"]


def test_labels_jumps_jump_lists_switches_and_return() -> None:
    label = '<Access Scope="Label" UId="{0}"><Label Name="{1}" /></Access>'
    network, reads, _writes, _power = _one(
        '<Part Name="Jump" UId="23" /><Part Name="JumpN" UId="24" />'
        '<Part Name="JumpList" UId="25"><TemplateValue Name="Card" Type="Cardinality">2'
        '</TemplateValue></Part><Part Name="Switch" UId="26"><TemplateValue Name="SrcType" '
        'Type="Type">Int</TemplateValue></Part><Part Name="Return" UId="27" />',
        wire(30, "rail", "23:in", "24:in", "25:en", "26:en", "27:in") +
        wire(31, "10", "23:label") + wire(32, "11", "24:label") + wire(33, "21", "25:k") +
        wire(34, "25:dest1", "13") + wire(35, "25:dest0", "12") + wire(36, "21", "26:k") +
        wire(37, "22", "26:gt1") + wire(38, "26:dest0", "10") + wire(39, "26:else", "11"),
        "".join(label.format(uid, name) for uid, name in
                ((10, "Son"), (11, "Bas"), (12, "E0"), (13, "E1"))) +
        tag(21, "Seçim") + const(22, "7", "Int"))
    jump, jump_n, table, switch, ret = network.parts
    assert (jump.label, jump_n.label) == ("Son", "Bas")
    assert table.dests == ("E0", "E1")
    assert switch.dests == ("Son",) and switch.template["else"] == "Bas"
    assert switch.template["op1"] == "GT" and reads["gt1"] == "7"
    powered = sorted(t.pin for w in network.wires if w.source.powerrail for t in w.targets)
    assert powered == ["en", "en", "en", "en", "en"]  # Jump's and Return's in are en
    assert ret.name == "Return"


def test_a_network_label_declaration_is_a_label_part() -> None:
    body = ('<Labels><LabelDeclaration UId="20"><Label Name="AA_1" /></LabelDeclaration>'
            "</Labels>" + _NET)
    network = read_document(document([body])).blocks[0].networks[0]
    assert (network.parts[0].name, network.parts[0].label) == ("Label", "AA_1")


def test_calls_of_fcs_and_fbs() -> None:
    network, reads, writes, power = _one(
        '<Call UId="23"><CallInfo Name="Blink" BlockType="FC"><Parameter Name="Period" '
        'Section="Input" Type="Time" /></CallInfo></Call>'
        '<Call UId="24"><CallInfo Name="Motor" BlockType="FB"><Instance Scope="GlobalVariable" '
        'UId="25"><Component Name="Motor_DB" /></Instance></CallInfo></Call>',
        wire(30, "rail", "23:en") + wire(31, "21", "23:Period") + wire(32, "23:eno", "24:en") +
        wire(33, "24:Run", "22"),
        const(21, "T#1s") + tag(22, "Lamba"))
    fc, fb = network.parts
    assert (fc.name, fc.call, fc.call_kind) == ("Call", "Blink", "FC")
    # an FB on a global instance DB is called by the DB's name, as SD writes it
    assert (fb.call, fb.call_kind, fb.instance) == ("Motor_DB", "FB", None)
    assert reads == {"period": "T#1s"} and writes == {"run": '"Lamba"'}
    assert power == ["en", "en"]


# -- operands, interface, texts, SCL -------------------------------------------------------
def test_operands_addresses_arrays_and_constants() -> None:
    accesses = (
        '<Access Scope="GlobalVariable" UId="21"><Symbol><Component Name="Start" />'
        '<Address Area="Input" Type="Bool" BitOffset="3" Informative="true" /></Symbol></Access>'
        '<Access Scope="GlobalVariable" UId="22"><Address Area="Memory" Type="Word" '
        'BitOffset="16" /></Access>'
        '<Access Scope="GlobalVariable" UId="20"><Address Area="DB" Type="Word" BlockNumber="1" '
        'BitOffset="32" /></Access>'
        '<Access Scope="LocalVariable" UId="19"><Symbol><Component Name="Arr" '
        'AccessModifier="Array"><Access Scope="LiteralConstant"><Constant><ConstantType>DInt'
        "</ConstantType><ConstantValue>3</ConstantValue></Constant></Access></Component>"
        '<Component Name="Q" /></Symbol></Access>'
        + const(18, "TRUE", "Bool") + const(17, "1.5", "Real"))
    network, reads, writes, _power = _one(
        '<Part Name="Contact" UId="23" /><Part Name="Move" UId="24" /><Part Name="Coil" '
        'UId="25" /><Part Name="Add" UId="26" />',
        wire(30, "rail", "23:in") + wire(31, "21", "23:operand") + wire(32, "23:out", "24:en") +
        wire(33, "22", "24:in") + wire(34, "24:out1", "20") + wire(35, "24:eno", "25:in") +
        wire(36, "19", "25:operand") + wire(37, "18", "26:in1") + wire(38, "17", "26:in2"),
        accesses)
    operands = {t.pin: w.source.operand for w in network.wires for t in w.targets
                if w.source.operand is not None}
    start = next(w.source.operand for w in network.wires
                 if w.source.operand and w.source.operand.path == ("Start",))
    assert start.address == "%I0.3" and start.kind is OperandKind.GLOBAL
    assert reads["in"] == "%MW2" and writes == {"out1": "%DB1.DBW4"}
    assert reads["operand"] == "#Arr[3].Q"
    assert (operands["in1"].text, operands["in1"].type_name) == ("TRUE", "Bool")
    assert (operands["in2"].text, operands["in2"].type_name) == ("1.5", "")


def test_interface_sections_nested_members_start_values_and_return() -> None:
    interface = (
        '<Section Name="Input"><Member Name="Start" Datatype="Bool"><Comment><MultiLanguageText '
        'Lang="en-US">start it</MultiLanguageText></Comment></Member></Section>'
        '<Section Name="Static"><Member Name="Data" Datatype="Struct"><Member Name="Count" '
        'Datatype="Int"><StartValue>3</StartValue></Member></Member>'
        '<Member Name="T1" Datatype="TON_TIME" /></Section>'
        '<Section Name="Return"><Member Name="Ret_Val" Datatype="Int" /></Section>')
    block = read_document(document([_NET], interface=interface, kind="FC",
                                   name="Hesap")).blocks[0]
    assert (block.kind, block.name, block.number, block.return_type) == ("FC", "Hesap", 1, "Int")
    assert block.members("Input")[0].comment == "start it"
    data = block.members("Static")[0]
    assert (data.type_name, data.members[0].name, data.members[0].start) == ("Struct", "Count",
                                                                             "3")
    assert "Return" not in block.sections


def test_global_and_instance_dbs_are_blocks_without_networks() -> None:
    text = document([], kind="GlobalDB", name="Veri", interface='<Section Name="Static">'
                    '<Member Name="Toplam" Datatype="DInt"><StartValue>5</StartValue></Member>'
                    "</Section>")
    block = read_document(text).blocks[0]
    assert (block.kind, block.members("Static")[0].start, block.networks) == ("GlobalDB", "5", [])
    text = text.replace("SW.Blocks.GlobalDB", "SW.Blocks.InstanceDB").replace(
        "<Number>", "<InstanceOfName>Motor</InstanceOfName><Number>")
    assert read_document(text).blocks[0].instance_of == "Motor"


def test_titles_keep_every_culture_and_show_one() -> None:
    found = read_document(document([_NET, _NET]))
    assert found.texts[("Main", 2, "title")] == {"de-DE": "Netzwerk 2",
                                                 "tr-TR": "Network 2 başlığı"}
    assert found.blocks[0].networks[1].title == "Network 2 başlığı"  # tr-TR before de-DE


def test_an_scl_network_keeps_its_text_and_is_not_simulated() -> None:
    scl = ('<StructuredText xmlns="http://www.siemens.com/automation/Openness/SW/NetworkSource/'
           'StructuredText/v3"><Token Text="IF" /><Blank /><Access Scope="LocalVariable">'
           '<Symbol><Component Name="a" /></Symbol></Access><Blank /><Token Text="THEN" />'
           '<NewLine /><Blank Num="2" /><Access Scope="GlobalVariable"><Symbol><Component '
           'Name="b" /></Symbol></Access><Blank /><Token Text=":=" /><Blank /><Access '
           'Scope="LiteralConstant"><Constant><ConstantType>Int</ConstantType><ConstantValue>1'
           '</ConstantValue></Constant></Access><Token Text=";" /><NewLine /><Token '
           'Text="END_IF" /><Token Text=";" /></StructuredText>')
    found = read_document(document([scl, _NET]))
    network = found.blocks[0].networks[0]
    result = parse_bytes(document([scl]).encode(), "s7")
    assert [d.code for d in result.diagnostics] == ["s7-not-simulated"]
    assert network.language == "SCL" and network.parts == []
    assert network.source == 'IF #a THEN\n  "b" := 1;\nEND_IF;'
    assert found.diagnostics == []


def test_the_cli_runs_an_xml_block_by_tag_name(capsys: pytest.CaptureFixture[str]) -> None:
    path = ROOT / "s7-xml" / "timers" / "Main.xml"
    assert main(["run", str(path), "--set", "Start=1", "--ms", "5010", "--scan-period", "10",
                 "--print", "Lamba 1,Lamba 2"]) == 0
    assert capsys.readouterr().out.splitlines() == ["Lamba 1 = 0", "Lamba 2 = 1"]


def test_a_folder_with_a_global_db_and_a_tag_table(tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    db = document([], kind="GlobalDB", name="Veri", interface=(
        '<Section Name="Static"><Member Name="Bayrak" Datatype="Bool" /><Member Name="Sayi" '
        'Datatype="Int"><StartValue>7</StartValue></Member></Section>'))
    main_net = ("<Parts>" + tag(21, "Start") + tag(22, "Veri", "Bayrak") +
                '<Part Name="Contact" UId="23" /><Part Name="Coil" UId="24" /></Parts><Wires>' +
                wire(30, "rail", "23:in") + wire(31, "21", "23:operand") +
                wire(32, "23:out", "24:in") + wire(33, "22", "24:operand") + "</Wires>")
    second = ("<Parts>" + tag(21, "Veri", "Bayrak") + tag(22, "Lamba") + tag(25, "Veri", "Sayi") +
              '<Access Scope="GlobalVariable" UId="26"><Address Area="Memory" Type="Int" '
              'BitOffset="80" /></Access><Part Name="Contact" UId="23" /><Part Name="Coil" '
              'UId="24" /><Part Name="Move" UId="27" /></Parts><Wires>' +
              wire(30, "rail", "23:in", "27:en") + wire(31, "21", "23:operand") +
              wire(32, "23:out", "24:in") + wire(33, "22", "24:operand") +
              wire(34, "25", "27:in") + wire(35, "27:out1", "26") + "</Wires>")
    (tmp_path / "Main.xml").write_text(document([main_net, second]), "utf-8")
    (tmp_path / "Veri.xml").write_text(db, "utf-8")
    (tmp_path / "PLC tags.xml").write_bytes((ROOT / "s7" / "jumps" / "PLC tags.xml").read_bytes())
    result = parse_file(tmp_path)
    assert [d.code for d in result.diagnostics] == []
    assert main(["run", str(tmp_path / "Main.xml"), "--set", "Start=1", "--scans", "2",
                 "--print", "Lamba,%MW10:2"]) == 0  # Sayi's start value 7 moved
    assert capsys.readouterr().out.splitlines() == ["Lamba = 1", "%MW10:2 = 7"]


def test_an_stl_network_keeps_its_statements_as_text() -> None:
    stl = ('<StatementList xmlns="http://www.siemens.com/automation/Openness/SW/NetworkSource/'
           'StatementList/v4"><StlStatement><StlToken Text="A" /><Access Scope="GlobalVariable">'
           '<Symbol><Component Name="Start" /></Symbol></Access></StlStatement><StlStatement>'
           '<StlToken Text="=" /><Access Scope="GlobalVariable"><Address Area="Output" '
           'Type="Bool" BitOffset="1" /></Access><LineComment><Text>lamba</Text></LineComment>'
           "</StlStatement></StatementList>")
    network = read_document(document([stl])).blocks[0].networks[0]
    assert network.language == "STL"
    assert network.source == 'A "Start"\n= %Q0.1//lamba'


def test_utf8_bom_and_crlf_exports_save_byte_for_byte(tmp_path: Path) -> None:
    source = (ROOT / "s7-xml" / "timers" / "Main.xml").read_bytes()
    for name, data in (("bom", b"\xef\xbb\xbf" + source),
                       ("crlf", source.replace(b"\n", b"\r\n"))):
        folder = tmp_path / name
        folder.mkdir()
        (folder / "Main.xml").write_bytes(data)
        shutil.copyfile(ROOT / "s7-xml" / "timers" / "PLC tags.xml", folder / "PLC tags.xml")
        result = parse_file(folder / "Main.xml")
        assert result.diagnostics == [] and result.program.networks
        assert encode_program(result.program) == data


def test_a_multi_instance_call_runs_the_fb_in_the_callers_statics(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    fb = (ROOT / "s7-xml" / "calls" / "Gecikme.xml").read_text("utf-8")
    caller = document([
        "<Parts>" + tag(21, "Motor") + tag(22, "Fan") + const(23, "T#3s") +
        '<Call UId="24"><CallInfo Name="Gecikme" BlockType="FB"><Instance '
        'Scope="LocalVariable" UId="25"><Component Name="Gec" /></Instance></CallInfo></Call>'
        "</Parts><Wires>" + wire(30, "rail", "24:en") + wire(31, "21", "24:Giris") +
        wire(32, "23", "24:Sure") + wire(33, "24:Cikis", "22") + "</Wires>"],
        kind="FB", name="Hat", interface='<Section Name="Static"><Member Name="Gec" '
        'Datatype="&quot;Gecikme&quot;" /></Section>')
    block = read_document(caller).blocks[0]
    assert block.members("Static")[0].type_name == '"Gecikme"'  # as the SD reader keeps it
    call = block.networks[0].parts[0]
    assert (call.call, call.call_kind, call.instance.display()) == ("Gec", "FB", "#Gec")
    (tmp_path / "Hat.xml").write_text(caller, "utf-8")
    (tmp_path / "Gecikme.xml").write_text(fb, "utf-8")
    (tmp_path / "PLC tags.xml").write_bytes(
        (ROOT / "s7-xml" / "calls" / "PLC tags.xml").read_bytes())
    assert main(["run", str(tmp_path / "Hat.xml"), "--set", "Motor=1", "--ms", "3100",
                 "--scan-period", "10", "--print", "Fan"]) == 0, capsys.readouterr()
    assert capsys.readouterr().out.splitlines() == ["Fan = 1"]
