"""The PLC's state where it is always seen: STOP / RUN, the program loaded, and forcing."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QCoreApplication, QTimer
from PySide6.QtWidgets import QLabel, QWidget

from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.retranslate import Retranslating

translate = QCoreApplication.translate

# the colours of the state: green while running, grey when stopped, amber while forced
RUN_STYLE = "QLabel { background: #2e7d32; color: white; padding: 1px 6px; font-weight: bold; }"
STOP_STYLE = "QLabel { background: #616161; color: white; padding: 1px 6px; font-weight: bold; }"
FORCED_STYLE = ("QLabel { background: #ff8f00; color: black; padding: 1px 6px; "
                "font-weight: bold; }")


def state_text(running: bool, name: str, forced: int) -> str:
    """`RUN · spindle.LAD · 2 forced` in the UI language."""
    parts = [translate("PlcState", "RUN") if running else translate("PlcState", "STOP"),
             name or translate("PlcState", "no program loaded")]
    if forced:
        parts.append(translate("PlcState", "{0} forced").format(forced))
    return " · ".join(parts)


class PlcStateLabel(Retranslating, QLabel):
    """STOP / RUN, the program in the PLC and the forced signals, in the PLC's colours; it
    follows the session's signals and a live language switch."""

    def __init__(self, session: PlcSession, loaded_name: Callable[[], str],
                 parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.session = session
        self.loaded_name = loaded_name  # the name of the program in the PLC ("" for none)
        session.running_changed.connect(lambda _running: self.refresh())
        session.forces_changed.connect(lambda _forces: self.refresh())
        # the name is set once the load has returned: read it after the signal
        session.program_loaded.connect(lambda _binary: QTimer.singleShot(0, self.refresh))
        self.refresh()

    @property
    def forced(self) -> int:
        """The number of forced signals now."""
        return len(self.session.run.forces())

    def refresh(self) -> None:
        """Show the state now."""
        running, forced = self.session.run.running, self.forced
        self.setText(state_text(running, self.loaded_name(), forced))
        self.setStyleSheet(FORCED_STYLE if forced else RUN_STYLE if running else STOP_STYLE)
        tip = translate("PlcState", "The simulated PLC: running (RUN) or stopped (STOP), and "
                        "the program loaded into it (F9).")
        if forced:
            tip += "\n" + translate("PlcState", "Signals are forced: the PLC does not see the "
                                    "machine's values for them (PLC › Release the force).")
        self.setToolTip(tip)

    def retranslate(self) -> None:
        """The texts in the UI language."""
        self.refresh()
