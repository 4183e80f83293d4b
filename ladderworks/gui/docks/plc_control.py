"""PLC KONTROL EKRANI: open a .MOD, compile it with green stripes, START and STOP the PLC."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from PySide6.QtCore import QCoreApplication, Qt, QTimer, Signal
from PySide6.QtGui import QAction
from PySide6.QtWidgets import (
    QDockWidget,
    QFrame,
    QHBoxLayout,
    QLabel,
    QMessageBox,
    QProgressBar,
    QScrollArea,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core.compiler import CompileResult, compile_program
from ladderworks.core.diagnostics import Diagnostic, has_errors
from ladderworks.core.il import Program, decode, print_program
from ladderworks.core.il.reading import parse_text
from ladderworks.gui import file_dialogs
from ladderworks.gui.button_flow import ButtonFlow
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.docks.mnemonic_editor import MnemonicEditor
from ladderworks.gui.document import bad_bytes_back, bad_bytes_shown
from ladderworks.gui.forces_on_load import forces_on_load
from ladderworks.gui.live_text import set_live_text
from ladderworks.gui.locale_numbers import decimal
from ladderworks.gui.os_errors import os_error_text
from ladderworks.gui.plc_session import PlcSession, PlcStatus
from ladderworks.gui.retranslate import Retranslating

translate = QCoreApplication.translate

STRIPE_MS = 25  # one step of the green stripes
STRIPE_STEPS = 40  # the stripes reach the end in at most this many steps (≈ 1 s)

RUNNING_STYLE = ("background: #2e7d32; color: white; font-weight: bold; padding: 4px 10px;"
                 " border-radius: 4px;")
STOPPED_STYLE = ("background: #c62828; color: white; font-weight: bold; padding: 4px 10px;"
                 " border-radius: 4px;")
IDLE_STYLE = ("background: #9e9e9e; color: white; font-weight: bold; padding: 4px 10px;"
              " border-radius: 4px;")

SKIPPED_STYLE = "color: #8d6e00;"  # amber text: kept but not run
SKIPPED_SHOWN = 12  # instructions named on the screen; the rest counted


def network_end_lines(program: Program) -> list[int]:
    """The last source line of each network (where its stripe ends)."""
    ends: list[int] = []
    for network in program.networks:
        lines = [ins.line for ins in network.instructions if ins.line]
        if lines:
            ends.append(max(lines))
    return ends


class PlcControlDock(Retranslating, QDockWidget):
    """The PLC control screen: mnemonic program, compile, START / STOP, scan figures."""

    compile_progress = Signal(int)  # lines converted so far
    compile_finished = Signal(object)  # CompileResult

    def __init__(self, session: PlcSession, parent: QWidget | None = None,
                 console_program: Callable[[], Program | None] | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("plcControlDock")
        self.session = session
        self.console_program = console_program
        self.path: Path | None = None
        self.result: CompileResult | None = None
        self._program: Program | None = None
        # a loaded program's text, made when the screen is first shown: printing and
        # highlighting 70k lines takes ~1.4 s that F9 need not wait for behind a hidden dock
        self._pending: Callable[[], str] | None = None
        self._ends: list[int] = []
        self._done = 0
        self.stripe_ms = STRIPE_MS
        self._timer = QTimer(self)
        self._timer.timeout.connect(self._stripe_step)

        body = QWidget(self)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        # buttons that wrap onto a second line in a narrow dock: START and STOP never hide
        # behind a toolbar's "»" overflow (a 1024×600 panel, the Turkish texts)
        self.toolbar = ButtonFlow(body)
        self.toolbar.setObjectName("plcControlToolbar")
        self.control_actions: dict[str, QAction] = {}
        for name, slot in (
                ("action_plc_open_mod", self.open_dialog),
                ("action_plc_take_console", self.take_console_program),
                (None, None),
                ("action_plc_control_compile", self.compile),
                ("action_plc_start", self.start),
                ("action_plc_stop", self.stop)):
            if name is None or slot is None:
                self.toolbar.add_separator()
                continue
            action = QAction(self)
            action.setObjectName(name)
            action.triggered.connect(lambda _checked=False, s=slot: s())
            self.toolbar.add_action(action)
            self.control_actions[name] = action
        layout.addWidget(self.toolbar)
        self.setMinimumWidth(340)  # its buttons wrap: a 1024-px screen keeps ~500 px of ladder
        state = QHBoxLayout()
        self.indicator = QLabel(body)
        self.indicator.setObjectName("plcRunIndicator")
        self.figures = QLabel(body)
        self.figures.setObjectName("plcScanFigures")
        self.figures.setWordWrap(True)  # two lines rather than a dock wider than a small screen
        state.addWidget(self.indicator)
        state.addWidget(self.figures, 1)
        layout.addLayout(state)
        self.loaded = QLabel(body)
        self.loaded.setObjectName("plcLoadedProgram")
        self.loaded_name = ""  # the name of the program in the PLC, "" when none
        layout.addWidget(self.loaded)
        # the loaded program's instructions the simulator passes by (not simulated)
        self.skipped = QLabel(body)
        self.skipped.setObjectName("plcSkippedInstructions")
        self.skipped.setWordWrap(True)
        self.skipped.setStyleSheet(SKIPPED_STYLE)
        self._skipped_of: object = None  # the list shown (PlcRun.skipped), to redo on change
        layout.addWidget(self.skipped)
        self.editor = MnemonicEditor(body)
        self.editor.textChanged.connect(self._text_changed)
        layout.addWidget(self.editor, 1)
        self.progress = QProgressBar(body)
        self.progress.setObjectName("plcCompileProgress")
        self.progress.setTextVisible(True)
        self.progress.setStyleSheet("QProgressBar::chunk { background: #43a047; }")
        layout.addWidget(self.progress)
        self.message = QLabel(body)
        self.message.setObjectName("plcCompileMessage")
        self.message.setWordWrap(True)
        layout.addWidget(self.message)
        # a 1024×600 screen with the time chart below: the screen scrolls rather than
        # making the window taller than the panel
        scroll = QScrollArea(self)
        scroll.setObjectName("plcControlScroll")
        scroll.setWidgetResizable(True)
        scroll.setFrameShape(QFrame.Shape.NoFrame)
        scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        scroll.setWidget(body)
        self.setWidget(scroll)
        self.visibilityChanged.connect(self._shown)
        session.status_changed.connect(self._show_status)
        session.running_changed.connect(lambda _running: self._update_actions())
        self.retranslate()
        self._show_status(session.run.status())

    def retranslate(self) -> None:
        """Texts in the UI language."""
        self.setWindowTitle(translate("PlcControl", "PLC CONTROL SCREEN"))
        texts = {
            "action_plc_open_mod": translate("PlcControl", "Open .MOD…"),
            "action_plc_take_console": translate("PlcControl",
                                                 "Show the console's program as text"),
            "action_plc_control_compile": translate("PlcControl", "Compile"),
            "action_plc_start": translate("PlcControl", "START"),
            "action_plc_stop": translate("PlcControl", "STOP"),
        }
        for name, text in texts.items():
            self.control_actions[name].setText(text)
        # F9 loads the console's program into the PLC; this only shows it here, to read or
        # change as mnemonic text before this screen's Compile
        self.control_actions["action_plc_take_console"].setToolTip(translate(
            "PlcControl", "Shows the console's program here as mnemonic text, to read or "
            "change before Compile on this screen. F9 (PLC › Compile) loads the console's "
            "program into the PLC directly."))
        self._show_loaded()
        self._show_skipped(force=True)
        self._show_status(self.session.run.status())

    # -- the program text ------------------------------------------------------------------

    def set_text(self, text: str, path: Path | None = None) -> None:
        """Show a mnemonic program (nothing compiled yet)."""
        self._pending = None
        self.path = path
        self.editor.setPlainText(bad_bytes_shown(text))  # what Qt's widget would change, kept
        self.editor.set_diagnostics([])
        self.editor.set_converted(0)

    def show_loaded(self, text: str | Callable[[], str], name: str) -> None:
        """The console compiled and loaded a program: show its text, converted, and name.
        A callable text is made only when the screen is shown (see `_fill`)."""
        self._timer.stop()
        self.set_text("" if callable(text) else text)
        if callable(text):
            self._pending = text
            if self.isVisible():
                self._fill()
        else:
            self.editor.set_converted(self.editor.blockCount())
        self.loaded_name = name
        self._show_loaded()
        set_live_text(self.message, lambda: translate("PlcControl",
                                                      "Program loaded from the console"))

    def _shown(self, visible: bool) -> None:
        if visible:
            self._fill()

    def _fill(self) -> None:
        """Put a loaded program's deferred text into the editor, all converted."""
        make, self._pending = self._pending, None
        if make is not None:
            self.editor.setPlainText(bad_bytes_shown(make()))
            self.editor.set_converted(self.editor.blockCount())

    def program_text(self) -> str:
        """The mnemonic text on the screen (a deferred loaded text is made first)."""
        self._fill()
        return bad_bytes_back(self.editor.toPlainText())

    def _show_loaded(self) -> None:
        self.loaded.setText(translate("PlcControl", "In the PLC: {0}").format(self.loaded_name)
                            if self.loaded_name else "")

    def open_file(self, path: str | Path) -> bool:
        """Read a .MOD / .LAD file (UTF-8 or Turkish Windows text)."""
        path = Path(path)
        try:
            text, _encoding = decode(path.read_bytes())
        except OSError as error:
            reason = error  # the except clause's name is gone after it
            set_live_text(self.message, lambda: translate("PlcControl", "Cannot read {0}: {1}")
                          .format(path, os_error_text(reason)))
            return False
        self.set_text(text, path)
        set_live_text(self.message,
                      lambda: translate("PlcControl", "Opened {0}").format(path.name))
        return True

    def open_dialog(self) -> None:
        """File > open a mnemonic program."""
        name = file_dialogs.open_file_name(
            self, translate("PlcControl", "Open mnemonic program"), "",
            translate("PlcControl", "Mnemonic programs (*.MOD *.mod *.LAD *.lad);;All files (*)"))
        if name:
            self.open_file(name)

    def take_console_program(self) -> bool:
        """Show the program drawn in the console as mnemonic code."""
        program = self.console_program() if self.console_program is not None else None
        if program is None:
            set_live_text(self.message, lambda: translate(
                "PlcControl", "The console's program cannot be coded: see the error list"))
            return False
        self.set_text(print_program(program))
        set_live_text(self.message, lambda: translate("PlcControl",
                                                      "Program taken from the console"))
        return True

    def _text_changed(self) -> None:
        if self._timer.isActive():
            self._timer.stop()
        if self.editor.converted_lines:
            self.editor.set_converted(0)

    # -- compiling -----------------------------------------------------------------------

    @property
    def compiling(self) -> bool:
        """True while the stripes advance."""
        return self._timer.isActive()

    def compile(self) -> CompileResult:
        """Check and convert the text to the binary PLC program; the stripes then show the
        networks converted, and at the end the program is loaded into the PLC."""
        self._timer.stop()
        parsed = parse_text(self.program_text())  # in whichever dialect it is written
        diagnostics: list[Diagnostic] = list(parsed.diagnostics)
        result = CompileResult(None, diagnostics)
        if not has_errors(diagnostics):
            result = compile_program(parsed.program)
            result = CompileResult(result.binary, diagnostics + result.diagnostics)
        self.result = result
        self.editor.set_diagnostics(result.diagnostics)
        self.editor.set_converted(0)
        if result.binary is None:
            errors = [d for d in result.diagnostics if d.is_error]
            first = min((d.line for d in errors if d.line), default=0)
            self.editor.set_converted(max(first - 1, 0))
            self.progress.setValue(0)
            set_live_text(self.message, lambda: translate(
                "PlcControl", "Compile failed: {0} error(s). {1}").format(
                    len(errors), diagnostic_text(errors[0]) if errors else ""))
            if first:
                self.editor.go_to_line(first)
            self.compile_finished.emit(result)
            return result
        self._program = parsed.program
        self._ends = network_end_lines(parsed.program) or [self.editor.blockCount()]
        self._done = 0
        self.progress.setRange(0, len(self._ends))
        self.progress.setValue(0)
        set_live_text(self.message, lambda: translate("PlcControl", "Converting…"))
        self._update_actions()
        if self.stripe_ms <= 0:
            while self._done < len(self._ends):
                self._stripe_step()
        else:
            self._timer.start(self.stripe_ms)
        return result

    def _stripe_step(self) -> None:
        step = max(1, -(-len(self._ends) // STRIPE_STEPS))
        self._done = min(len(self._ends), self._done + step)
        self.editor.set_converted(self._ends[self._done - 1])
        self.progress.setValue(self._done)
        self.compile_progress.emit(self.editor.converted_lines)
        if self._done < len(self._ends):
            return
        self._timer.stop()
        self.editor.set_converted(self.editor.blockCount())
        assert self.result is not None and self.result.binary is not None
        assert self._program is not None
        origin = (self._program.dialect, str(self.path) if self.path else "control screen")
        forces = forces_on_load(self, self.session, origin)
        problems = [] if forces is None else self.session.load(
            self.result.binary, self._program, origin=origin, keep_forces=forces == "keep")
        if forces is None:
            self.message.setText(translate("PlcControl", "Not loaded: the PLC keeps the "
                                           "program it has"))
        elif problems:
            self.message.setText(diagnostic_text(problems[0]))
        else:
            self.loaded_name = self.path.name if self.path else translate(
                "PlcControl", "the program on this screen")
            self._show_loaded()
            warnings = sum(1 for d in self.result.diagnostics if not d.is_error)
            text = translate("PlcControl", "Compile finished — {0} networks, {1} bytes").format(
                len(self._ends), len(self.result.binary))
            if warnings:
                text += " " + translate("PlcControl", "({0} warning(s))").format(warnings)
            self.message.setText(text)
        self._update_actions()
        self.compile_finished.emit(self.result)

    # -- START / STOP --------------------------------------------------------------------

    def confirm_forces(self, count: int) -> bool:
        """Ask before starting with forced or passive elements (tests replace this)."""
        answer = QMessageBox.question(
            self, translate("PlcControl", "START"),
            translate("PlcControl", "{0} signal(s) are forced or element(s) passive. "
                      "Start the PLC with them?").format(count))
        return answer == QMessageBox.StandardButton.Yes

    def start(self) -> bool:
        """START: run the loaded program (asks first when forces are active)."""
        if self.session.run.engine is None:
            set_live_text(self.message, lambda: translate("PlcControl", "Compile a program first"))
            return False
        forces = self.session.run.forces()
        if forces and not self.confirm_forces(len(forces)):
            return False
        return self.session.start()

    def stop(self) -> None:
        """STOP: stop scanning (outputs go to 0)."""
        self.session.stop()

    def _update_actions(self) -> None:
        running = self.session.run.running
        self.control_actions["action_plc_start"].setEnabled(self.session.run.engine is not None
                                                    and not running)
        self.control_actions["action_plc_stop"].setEnabled(running)
        self.control_actions["action_plc_control_compile"].setEnabled(
            not running and not self.compiling)

    @staticmethod
    def _scanner_text(status: PlcStatus) -> str:
        """Where the scans run, and why not in their own process when they could not."""
        text = ""
        if status.scanner == "process":
            text = " · " + translate("PlcControl", "scans in a process of their own")
        elif status.scanner == "thread":
            text = " · " + translate("PlcControl", "scans in the IDE's process")
        if status.problem:
            text += " · " + translate("PlcControl", "scan process: {0}").format(status.problem)
        return text

    @staticmethod
    def _backend_text(status: PlcStatus) -> str:
        """Which scan's code runs, and why not the native one when it was asked for."""
        if status.backend == "native":
            return " · " + translate("PlcControl", "native scan (machine code)")
        if status.backend_reason:
            return " · " + translate("PlcControl", "Python scan (native not possible: {0})"
                                     ).format(status.backend_reason)
        return " · " + translate("PlcControl", "Python scan") if status.backend else ""

    def _show_skipped(self, force: bool = False) -> None:
        """The instructions of the program in the PLC that the scan passes by, with lines."""
        found = self.session.run.skipped if self.session.run.engine is not None else []
        if found is self._skipped_of and not force:
            return
        self._skipped_of = found
        self.skipped.setVisible(bool(found))
        if not found:
            self.skipped.setText("")
            return
        shown = [translate("PlcControl", "{0} (line {1})").format(item.text, item.line)
                 for item in found[:SKIPPED_SHOWN]]
        if len(found) > SKIPPED_SHOWN:
            shown.append(translate("PlcControl", "… and {0} more").format(
                len(found) - SKIPPED_SHOWN))
        self.skipped.setText(translate(
            "PlcControl", "Not simulated, passed by in the scan ({0}): {1}").format(
                len(found), ", ".join(shown)))
        self.skipped.setToolTip(translate(
            "PlcControl", "These instructions are kept, drawn and saved, but the simulator "
            "does not run them: a box passes its input on, a contact never conducts."))

    def _show_status(self, status: PlcStatus) -> None:
        self._show_skipped()
        if not status.loaded:
            self.indicator.setText(translate("PlcControl", "NO PROGRAM"))
            self.indicator.setStyleSheet(IDLE_STYLE)
        elif status.running:
            self.indicator.setText(translate("PlcControl", "RUNNING"))
            self.indicator.setStyleSheet(RUNNING_STYLE)
        else:
            self.indicator.setText(translate("PlcControl", "STOPPED"))
            self.indicator.setStyleSheet(STOPPED_STYLE)
        if status.loaded:
            self.figures.setText(translate(
                "PlcControl",
                "scans {0} · scan time {1} / {2} / {3} ms (min/avg/max) · "
                "period {4} ms · overruns {5}").format(
                status.scan_count, decimal(status.min_ms, 3), decimal(status.avg_ms, 3),
                decimal(status.max_ms, 3),
                status.period_ms, status.overruns) + self._scanner_text(status)
                + self._backend_text(status))
        else:
            self.figures.setText("")
        self._update_actions()
