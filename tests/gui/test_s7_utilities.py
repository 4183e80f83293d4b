"""An S7 program in the utilities: the bit display, time chart, force list, cross reference and
Modbus server by tag name (`"Start"`, `"Calisma_DB".Q`, `%MW10`), never an internal relay."""

from __future__ import annotations

import struct
from pathlib import Path

import pytest
from pymodbus.client import ModbusTcpClient
from pytestqt.qtbot import QtBot

from ladderworks.core.address import Address, Area
from ladderworks.core.dialects.s7.devices import parse_absolute
from ladderworks.core.plc.typed import real_bits
from ladderworks.gui.docks.plc_docks import PlcDocks
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.translation import UiLanguage
from ladderworks.paths import EXAMPLES
from tests.gui.plc_docks_help import plc_docks

EXAMPLE = EXAMPLES / "s7" / "modbus" / "Main.s7dcl"  # its folder's tags and "DB_Modbus"


@pytest.fixture
def s7_docks(window: MainWindow) -> PlcDocks:
    """The Modbus example opened, compiled (F9) and started on the virtual clock."""
    assert window.load(EXAMPLE)
    docks = plc_docks(window)
    assert window.compile() is not None  # PLC › Compile (F9)
    assert docks.session.run.engine is not None
    docks.session.start()
    return docks


def at(text: str) -> Address:
    """An S7 absolute address."""
    return parse_absolute(text)[0]


def test_the_bit_display_takes_tags_and_shows_a_word_whole(s7_docks: PlcDocks) -> None:
    session, dock = s7_docks.session, s7_docks.bit_display
    session.set_bit(at("%I0.0"), 1)
    session.run.write(at("%IW2"), -2 & 0xFFFF, 2)
    session.run_scans(2)
    dock.start()
    for index, text in enumerate(['"Start"', "%IW2", "Calisma_DB.Q", '"DB_Modbus".Durum',
                                  "%M10.1", '"Sıcaklık"', '"Yok"']):
        dock.set_address(index, text)
    start, word, timer, durum, bit, real, missing = dock.rows[:7]
    assert dock.address_header.text() == "Tag or address"
    assert start.edit.text() == '"Start"' and start.bit_texts() == "00000001"
    assert word.edit.text() == "%IW2" and word.width == 2
    assert word.bit_texts() == "1111111111111110" and word.hex_label.text() == "FFFEh"
    assert word.dec_label.text() == "65534"  # a Word: unsigned
    assert durum.width == 2 and durum.dec_label.text() == "-2"  # an Int: signed, moved
    assert all(button.isVisibleTo(dock) for button in word.bits)
    assert not start.bits[8].isVisibleTo(dock)  # a byte: 8 bits
    assert dock.headers[15].isVisibleTo(dock)  # a word is shown: bits 15 … 8 headed
    assert word.bits[8].toolTip().startswith("%I2.0")  # bit 8 of %IW2 is %I2.0 (big-endian)
    assert word.bits[0].toolTip().startswith("%I3.0")
    assert timer.edit.text() == '"Calisma_DB".Q' and timer.address == Address(Area.D, 8)
    assert timer.bits[1].toolTip().startswith('"Calisma_DB".Q')  # no D8.1: its name alone
    assert bit.address == at("%MB10") and start.bits[0].toolTip().startswith('%I0.0  "Start"')
    assert "4 bytes" in real.error.text() and "time chart" in real.error.text()
    assert "is not an S7 address" in missing.error.text()


def test_the_time_chart_samples_tags_with_their_types(s7_docks: PlcDocks) -> None:
    session, chart = s7_docks.session, s7_docks.time_chart
    assert chart.signals_edit.placeholderText().startswith('e.g. "Start" %Q0.0 %MW2')
    chart.signals_edit.setText('"Start" "Hazır", "Calisma_DB".ET;"Sıcaklık" %MW10')
    chart.period_spin.setValue(10)
    assert chart.start()
    assert [s.label for s in chart.record.signals] == [
        '"Start"', '"Hazır"', '"Calisma_DB".ET', '"Sıcaklık"', "%MW10"]
    assert [s.width for s in chart.record.signals] == [1, 1, 4, 4, 2]
    session.run.write(at("%MD16"), real_bits(21.5), 4)
    session.set_bit(at("%I0.0"), 1)
    session.run_scans(700)
    chart.stop()
    chart.set_cursor(chart.record.times[-1])  # the last sample: 5 s after "Start"
    text = chart.cursor_label.text()
    assert '"Calisma_DB".ET = T#5S' in text and '"Sıcaklık" = 21.5' in text
    assert '"Hazır" = 1' in text and '"Start" = 1' in text
    assert chart.lane_name(chart.record.signals[4]) == '%MW10 "Hedef Hız"'


def test_a_bit_forced_by_its_tag(s7_docks: PlcDocks) -> None:
    session, forces = s7_docks.session, s7_docks.force_list
    forces.target.setText("Start")
    assert forces.force_typed(1)
    session.run_scans(2)
    assert session.run.bit(at("%Q0.0")) == 1  # "Motor" set by the forced "Start"
    assert forces.table.item(0, 1).text() == '%I0.0 "Start"'
    forces.target.setText('"Hedef Hız"')
    assert not forces.force_typed(1)
    assert "not a bit" in forces.summary.text()
    forces.target.setText('"Yok"')
    assert not forces.force_typed(0)
    session.release_all()


def test_the_cross_reference_lists_tags_under_their_networks(window: MainWindow,
                                                             s7_docks: PlcDocks) -> None:
    dock = window.cross_reference
    dock.show()
    dock.refresh()
    model = dock.model
    texts = [[model.data(model.index(row, col)) for col in range(8)]
             for row in range(model.rowCount())]
    assert texts and not any("R8192" in str(cell) or cell == "TRUE"
                             for row in texts for cell in row)
    assert ["%MW10", '"Hedef Hız"'] in [row[:2] for row in texts]
    assert any(row[1] == '"DB_Modbus".Komut' and row[0] == "" for row in texts)
    dock.show_address('"Motor"')
    assert model.rowCount() == 3
    assert [model.data(model.index(r, 0)) for r in range(3)] == ["%Q0.0"] * 3
    assert model.data(model.index(0, 2)) == "Network 1: Start sets the motor"  # TIA's name
    assert model.data(model.index(0, 7)) == "Motor contactor"  # the tag's comment
    assert dock.summary.text().startswith('"Motor" — uses: 3')
    dock.show_address("Yok")
    assert "neither an address nor a symbol" in dock.summary.text()


def test_the_diagnostic_view_names_elements_by_tag(s7_docks: PlcDocks) -> None:
    view = s7_docks.diagnostic.view
    view.symbols = s7_docks.session.symbols
    assert view.describe_address(at("%Q0.0")) == ('"Motor"', "Motor contactor")
    assert view.describe_address(Address(Area.D, 16)) == ('"DB_Modbus".Komut', "")
    assert view.describe_address(Address(Area.R, 8192, 0)) is None  # an internal relay


def test_the_modbus_dock_serves_a_global_db(s7_docks: PlcDocks) -> None:
    session, dock = s7_docks.session, s7_docks.modbus
    dock.show()
    assert dock.holding.isVisibleTo(dock)
    assert dock.map_label.text() == "&Map file (CSV) or DB:"
    assert [dock.holding.itemText(i) for i in range(dock.holding.count())] == [
        "Bit memory (%MW)", 'Data block "DB_Modbus"']
    assert dock.served.text() == "the Siemens S7-1200 map"
    dock.holding.setCurrentIndex(1)
    assert dock.served.text() == 'the Siemens S7-1200 map, holding registers in the DB' \
        ' "DB_Modbus"'
    dock.address.setText("127.0.0.1:0")
    assert dock.start_server() and dock.server is not None
    assert dock.server.bridge.map.name == 's7 "DB_Modbus"'
    client = ModbusTcpClient("127.0.0.1", port=dock.server.port, timeout=3)
    try:
        assert client.connect()
        assert not client.write_register(0, 1234).isError()  # "DB_Modbus".Komut
        session.run.write(at("%MD16"), real_bits(-7.25), 4)  # "Sıcaklık"
        session.run_scans(1)
        assert session.run.read(at("%MW10"), 2) == 1234  # moved to "Hedef Hız"
        high, low = client.read_holding_registers(2, count=2).registers
        assert struct.unpack(">f", struct.pack(">HH", high, low))[0] == -7.25
        assert not client.write_coil(10000, True).isError()  # "Start" %I0.0
        session.run_scans(1)
        assert client.read_coils(0, count=1).bits[0]  # "Motor" %Q0.0
    finally:
        client.close()
    dock.stop_server()
    dock.holding.setCurrentIndex(0)
    dock.map_file.setText("DB_Yok")  # a name typed: neither a file nor a DB
    assert not dock.start_server()
    assert "'DB_Yok' is neither a map file nor a global DB" in dock.status.text()
    dock.map_file.setText("db_modbus")  # typed as the CLI's --map
    assert 'holding registers in the DB "DB_Modbus"' in dock.served.text()


def test_turkish_texts(qtbot: QtBot, window: MainWindow, s7_docks: PlcDocks) -> None:
    language = UiLanguage()
    try:
        language.apply("tr")
        qtbot.waitUntil(lambda: s7_docks.modbus.windowTitle() == "Modbus sunucusu")
        assert s7_docks.modbus.holding_label.text() == "&Tutma yazmaçları:"
        assert s7_docks.modbus.holding.itemText(0) == "Bit belleği (%MW)"
        assert s7_docks.force_list.force_buttons[0].text() == "1'e zorla"
        assert s7_docks.bit_display.address_header.text() == "Etiket ya da adres"
    finally:
        language.apply("en")


def test_the_scenario_dock_shows_typed_checks(qtbot: QtBot, tmp_path: Path,
                                              s7_docks: PlcDocks) -> None:
    dock = s7_docks.scenario
    path = tmp_path / "typed.scenario.csv"
    path.write_text('PMC SIGNAL DATA\nSET,0,"Start",1\nWAITFOR,6000,"Calisma_DB".ET,>=T#5s\n'
                    'EXPECT,0,"Çalışma Süresi",T#4s\n', encoding="utf-8")
    with qtbot.waitSignal(dock.finished, timeout=10_000) as blocker:
        dock.run_file(path)
    assert [c.passed for c in blocker.args[0].checks] == [True, False]
    rows = [dock.checks.topLevelItem(i) for i in range(dock.checks.topLevelItemCount())]
    assert [(r.text(1), r.text(2), r.text(3)) for r in rows] == [
        ('WAITFOR "Calisma_DB".ET', ">=T#5S", "T#5S"),
        ('EXPECT "Çalışma Süresi"', "T#4S", "T#5S")]
