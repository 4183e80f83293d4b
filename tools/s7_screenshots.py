"""Screenshots of the S7 Modbus example in the Modbus dock, bit display and time chart, in
English and Turkish: `xvfb-run -a -s "-screen 0 1024x600x24" python tools/s7_screenshots.py OUT`
writes OUT/s7_{modbus,bit_display,time_chart}_{en,tr}.png (QWidget.grab)."""

from __future__ import annotations

import os
import sys
import tempfile
from pathlib import Path

from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QApplication, QDockWidget

from ladderworks.core.address import Address
from ladderworks.core.dialects.s7.devices import parse_absolute
from ladderworks.core.plc.typed import real_bits
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.settings import Settings
from ladderworks.gui.translation import UiLanguage
from ladderworks.paths import EXAMPLES

BITS = ('"Start"', '"Motor"', "%IW2", '"Hedef Hız"', '"Calisma_DB".Q', "%M10.1", '"Sıcaklık"')
SIGNALS = '"Start" "Motor" "Hazır" "Calisma_DB".ET "Sıcaklık" %MW10'


def at(text: str) -> Address:
    """An S7 absolute address."""
    return parse_absolute(text)[0]


def shoot(app: QApplication, settings: Settings, code: str, out: Path) -> None:
    """One language's three screenshots."""
    language = UiLanguage()
    language.apply(code)
    window = MainWindow(settings, language)
    window.resize(1024, 600)
    window.show()
    assert window.load(EXAMPLES / "s7" / "modbus" / "Main.s7dcl")
    docks = window.plc_docks
    session = docks.session
    session.run.realtime = False
    assert window.compile() is not None
    session.start()
    session.run.write(at("%MD16"), real_bits(21.5), 4)
    session.run.write(at("%IW2"), -27648 & 0xFFFF, 2)
    bits = docks.bit_display
    bits.show()
    bits.start()
    for index, text in enumerate(BITS):
        bits.set_address(index, text)
    chart = docks.time_chart
    chart.show()
    chart.signals_edit.setText(SIGNALS)
    chart.period_spin.setValue(10)
    assert chart.start()
    session.run_scans(50)
    session.set_bit(at("%I0.0"), 1)  # "Start" pressed for 300 ms
    session.run_scans(30)
    session.set_bit(at("%I0.0"), 0)
    session.run.write(at("%MD16"), real_bits(23.25), 4)
    session.run_scans(620)
    chart.stop()
    chart.fit()
    chart.set_cursor(3000)
    modbus = docks.modbus
    modbus.show()
    modbus.holding.setCurrentIndex(1)  # "DB_Modbus" as the holding registers
    modbus.address.setText("127.0.0.1:0")
    modbus.start_server()
    app.processEvents()
    dock: QDockWidget
    for name, dock in (("modbus", modbus), ("bit_display", bits), ("time_chart", chart)):
        dock.setFloating(True)
        width = 520 if name == "modbus" else 760
        dock.resize(max(width, dock.sizeHint().width()), 400 if name == "modbus" else 440)
        app.processEvents()
        dock.grab().save(str(out / f"s7_{name}_{code}.png"))
    modbus.stop_server()
    window.editor.undo_stack.setClean()
    window.close()
    window.deleteLater()
    app.processEvents()


def main() -> int:
    """Write the screenshots into the folder given."""
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(".")
    out.mkdir(parents=True, exist_ok=True)
    app = QApplication.instance() or QApplication(sys.argv)
    assert isinstance(app, QApplication)
    folder = Path(tempfile.mkdtemp())
    os.environ["XDG_DATA_HOME"] = str(folder / "data")  # recovery copies: not the user's
    settings = Settings(QSettings(str(folder / "settings.ini"), QSettings.Format.IniFormat))
    for code in ("en", "tr"):
        shoot(app, settings, code, out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
