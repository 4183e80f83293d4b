"""PLC › Modbus server: started for the console's PLC, a real client drives what the docks show."""

from __future__ import annotations

from pathlib import Path

from pymodbus.client import ModbusTcpClient
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.il import parse_file
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.translation import UiLanguage
from ladderworks.paths import EXAMPLES
from tests.core.modbus.conftest import spindle_binary
from tests.gui.plc_docks_help import plc_docks


def test_the_menu_entry_shows_the_dock(window: MainWindow) -> None:
    docks = plc_docks(window)
    action = window.menus.actions_by_name["action_dock_modbus"]
    assert action in window.menus.menus["menu_plc"].actions()
    assert action.text() == "Modbus server"
    action.trigger()
    assert docks.modbus.isVisible()
    assert docks.modbus.address.text() == "127.0.0.1:5020"  # loopback unless told


def test_a_client_drives_the_running_plc_and_the_docks_see_it(
        qtbot: QtBot, window: MainWindow) -> None:
    docks = plc_docks(window)
    session, dock = docks.session, docks.modbus
    assert session.load(spindle_binary()) == []
    session.start()
    dock.show()
    dock.address.setText("127.0.0.1:0")
    dock.button.click()
    assert dock.running and dock.server is not None
    assert "Listening on 127.0.0.1:" in dock.status.text() and "map: pmc" in dock.status.text()
    assert dock.button.text() == "Stop server" and not dock.address.isEnabled()
    client = ModbusTcpClient("127.0.0.1", port=dock.server.port, timeout=3)
    try:
        assert client.connect()
        assert not client.write_coils(17, [True, False, True]).isError()  # X2.1, X2.3
        session.run_scans(1)  # the virtual clock: one scan
        assert client.read_holding_registers(3030, count=1).registers == [60]
        snapshots: list[object] = []
        session.snapshot_ready.connect(snapshots.append)
        assert not client.write_register(20010, 42).isError()  # D10, PLC on the virtual clock
        qtbot.waitUntil(lambda: bool(snapshots), timeout=3000)  # published to the docks
        assert session.run.snapshot().read(parse_address("D10")) == 42
        dock.show_figures()
        assert dock.clients.text() == "1"
    finally:
        client.close()
    dock.button.click()
    assert not dock.running and dock.button.text() == "Start server"
    assert "Stopped" in dock.status.text()


def test_an_address_in_use_or_malformed_is_said(window: MainWindow) -> None:
    dock = plc_docks(window).modbus
    dock.address.setText("here")
    assert not dock.start_server()
    assert "host:port" in dock.status.text()
    dock.address.setText("127.0.0.1:0")
    assert dock.start_server()
    assert dock.server is not None
    port = dock.server.port
    other = type(dock)(dock.session, window)
    other.address.setText(f"127.0.0.1:{port}")
    assert not other.start_server()
    assert f"Cannot listen on 127.0.0.1:{port}" in other.status.text()
    dock.stop_server()
    other.deleteLater()


def test_turkish(qtbot: QtBot, window: MainWindow) -> None:
    dock = plc_docks(window).modbus
    language = UiLanguage()
    try:
        language.apply("tr")
        qtbot.waitUntil(lambda: dock.windowTitle() == "Modbus sunucusu")
        assert dock.button.text() == "Sunucuyu başlat"
        assert window.menus.actions_by_name["action_dock_modbus"].text() == "Modbus sunucusu"
        assert "Durduruldu" in dock.status.text()
    finally:
        language.apply("en")


def test_a_map_file_is_served_and_said(tmp_path: Path, window: MainWindow) -> None:
    docks = plc_docks(window)
    session, dock = docks.session, docks.modbus
    assert session.load(spindle_binary()) == []
    session.start()
    assert dock.served.text() == "the FANUC PMC map"
    assert dock.served_label.text() == "Map to serve:"
    own = tmp_path / "hmi.csv"
    own.write_text("table,start,count,plc address,access\nholding,7,1,G30,r\n"
                   "coils,0,8,X2.0,rw\n", encoding="utf-8")
    dock.map_file.setText(str(own))
    dock.address.setText("127.0.0.1:0")
    assert dock.start_server() and dock.server is not None
    assert dock.served.text() == f"the file {own}"
    assert dock.served_label.text() == "Map served:"
    assert not dock.map_file.isEnabled() and not dock.map_choose.isEnabled()
    client = ModbusTcpClient("127.0.0.1", port=dock.server.port, timeout=3)
    try:
        assert client.connect()
        assert not client.write_coils(1, [True, False, True]).isError()  # X2.1, X2.3
        session.run_scans(1)
        assert client.read_holding_registers(7, count=1).registers == [60]  # G30
        answer = client.read_holding_registers(3030, count=1)  # not in this map
        assert answer.isError() and answer.exception_code == 2
    finally:
        client.close()
    dock.stop_server()
    dock.map_default.click()  # back to the dialect's map
    assert dock.map_file.text() == ""
    assert dock.start_server() and dock.server is not None
    assert dock.served.text() == "the FANUC PMC map"
    assert dock.server.bridge.map.name == "pmc"
    dock.stop_server()


def test_a_bad_map_file_is_said_at_its_lines(qtbot: QtBot, tmp_path: Path,
                                             window: MainWindow) -> None:
    dock = plc_docks(window).modbus
    own = tmp_path / "bad.csv"
    own.write_text("coils,0,8,X2.0,rw\nholding,0,4,Z9,rw\nholding,x,1,D0,rw\n",
                   encoding="utf-8")
    dock.map_file.setText(str(own))
    dock.address.setText("127.0.0.1:0")
    assert not dock.start_server() and not dock.running
    lines = dock.status.text().splitlines()
    assert lines[0] == f"The map {own} is not served:"
    assert lines[1].startswith("line 2: ") and "'Z9'" in lines[1]
    assert lines[2].startswith("line 3: ") and "'x'" in lines[2]
    dock.map_file.setText(str(tmp_path / "none.csv"))
    assert not dock.start_server()
    assert dock.status.text().startswith(f"Cannot read the map {tmp_path / 'none.csv'}: ")
    dock.map_file.setText(str(own))
    language = UiLanguage()
    try:
        language.apply("tr")
        qtbot.waitUntil(lambda: dock.windowTitle() == "Modbus sunucusu")
        assert not dock.start_server()
        lines = dock.status.text().splitlines()
        assert lines[0] == f"{own} haritası sunulmuyor:"
        assert lines[1].startswith("satır 2: ")
        assert dock.map_label.text() == "&Harita dosyası (CSV):"
    finally:
        language.apply("en")


def test_another_dialect_s_program_switches_or_stops_the_map(tmp_path: Path,
                                                             window: MainWindow) -> None:
    docks = plc_docks(window)
    session, dock = docks.session, docks.modbus
    assert session.load(spindle_binary()) == []
    dock.address.setText("127.0.0.1:0")
    assert dock.start_server() and dock.server is not None
    fatek = parse_file(EXAMPLES / "fatek" / "conveyor.lst").program
    assert session.load_program(fatek).binary is not None
    assert dock.running and dock.server.bridge.map.name == "fatek"
    assert dock.served.text() == "the Fatek FBs map"
    dock.stop_server()
    own = tmp_path / "hmi.csv"
    own.write_text("coils,0,8,X2.0,rw\n", encoding="utf-8")  # a PMC address
    dock.map_file.setText(str(own))
    assert not dock.start_server()  # X2.0 is no Fatek input
    assert dock.status.text().startswith(f"The map {own} is not served:\nline 1: ")
    assert session.load(spindle_binary()) == []
    assert dock.start_server() and dock.served.text() == f"the file {own}"
    assert session.load_program(fatek).binary is not None  # the file does not fit Fatek
    assert not dock.running
    assert dock.status.text().startswith(f"The map {own} is not served:\nline 1: ")
