"""The ladder console's main window: menus, actions, tool palette, editor, text view, docks."""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QEvent, Qt, QTimer, Signal
from PySide6.QtGui import QAction, QCloseEvent, QShowEvent
from PySide6.QtWidgets import (
    QApplication,
    QDialog,
    QDockWidget,
    QLabel,
    QMainWindow,
    QMessageBox,
    QStackedWidget,
    QWidget,
)

from ladderworks.core.address import Address
from ladderworks.core.diagnostics import Diagnostic, has_errors
from ladderworks.core.il import Program, print_program
from ladderworks.core.ladder import Coil, Contact, FunctionBox
from ladderworks.core.ladder.logic import coil_spec, contact_spec
from ladderworks.core.models import model_of
from ladderworks.gui import compile_step, questions
from ladderworks.gui.actions_table import CAN_REDO, CAN_UNDO, CONTEXT_MENU, LADDER_SHOWN
from ladderworks.gui.cell_status import CellStatus
from ladderworks.gui.console_menus import Condition, ConsoleMenus
from ladderworks.gui.dock_tabs import WholeDockTitles
from ladderworks.gui.docks import cross_reference
from ladderworks.gui.docks.plc_docks import build_plc_docks
from ladderworks.gui.document import bad_bytes_shown
from ladderworks.gui.editor.interactions import BY_TOOL
from ladderworks.gui.editor.ladder_model import LadderModel, Mode
from ladderworks.gui.editor.name_menu import NameDisplayMenu
from ladderworks.gui.editor.view import LadderEditor
from ladderworks.gui.editor.zoom import FitWidth
from ladderworks.gui.elided_label import ElidedLabel
from ladderworks.gui.error_list import ErrorListDock
from ladderworks.gui.file_actions import FileActions
from ladderworks.gui.find_replace import FindReplaceDialog
from ladderworks.gui.forces_on_load import forces_on_load
from ladderworks.gui.help_browser import InstructionHelp
from ladderworks.gui.locale_numbers import percent
from ladderworks.gui.palette import ToolPalette
from ladderworks.gui.parameter_document import ParameterDocument
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.print_actions import PrintActions
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.scan_backend import ScanBackendChoice
from ladderworks.gui.screen_fit import rebalance_docks
from ladderworks.gui.settings import MAX_RECENT, Settings
from ladderworks.gui.signal_list import SignalListDock
from ladderworks.gui.text_view import ProgramTextView
from ladderworks.gui.tools import Tool, icon
from ladderworks.gui.translation import UiLanguage
from ladderworks.gui.undo_texts import UndoTexts

translate = QCoreApplication.translate


class MainWindow(Retranslating, FileActions, QMainWindow):
    """The ladder console: one program, shown as ladder (or as text when it has errors)."""

    language_changed = Signal(str)
    file_saved = Signal(str)
    program_opened = Signal(object)  # the Program now shown (its symbols, messages, sections)

    def __init__(
        self, settings: Settings, language: UiLanguage, parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self.setObjectName("main_window")
        self.settings = settings
        self.language = language
        self.dialect = "seed"  # of the open program: how its parameter file names timers
        self.failed_path: Path | None = None  # a file that did not parse: never overwritten
        self.last_warning = ""
        self.program_info = Program()  # the program as opened: title, sections, symbols
        self.program_serial = 0  # counts the programs shown (an untitled one's identity)
        self.setWindowIcon(icon("ladderworks"))

        self.model = LadderModel(self)  # the networks, the undo stack, ladder or text
        self.editor = LadderEditor(self.model, self)
        self.fit_width = FitWidth(self.editor)  # View › Fit width
        self.text_view = ProgramTextView(self)
        self.text_view.document().modificationChanged.connect(self.update_title)
        self.pages = QStackedWidget(self)
        self.pages.setObjectName("pages")
        self.pages.addWidget(self.editor)
        self.pages.addWidget(self.text_view)
        self.setCentralWidget(self.pages)
        self.model.mode_changed.connect(self._show_mode)

        self.menus = ConsoleMenus(self, self._conditions())
        self.actions_by_name = self.menus.actions_by_name
        self.tool_actions = self.menus.tool_actions
        for tool, action in self.tool_actions.items():
            action.triggered.connect(lambda _c=False, t=tool: self.set_tool(t))
        fit = self.actions_by_name["action_zoom_fit_width"]
        for name in ("action_zoom_in", "action_zoom_out", "action_zoom_reset"):
            self.actions_by_name[name].triggered.connect(lambda _c=False: fit.setChecked(False))
        fit.toggled.connect(self._fit_toggled)  # after fit_width.set_enabled: says what fits
        self.names_menu = NameDisplayMenu(self.settings, self)  # View › Element names
        self.menus.add_menu("menu_view", self.names_menu)
        self.recent_menu = self.menus.menus["menu_recent"]
        self.recent_actions: list[QAction] = []
        for index in range(MAX_RECENT):
            action = QAction(self)
            action.setObjectName(f"action_recent_{index}")
            action.triggered.connect(lambda _c=False, i=index: self._open_recent(i))
            self.recent_actions.append(action)
            self.menus.register(action)
        self._make_docks()
        self.dock_titles = WholeDockTitles(self)  # tabbed docks: whole titles, tabs scroll
        self._status_text: Callable[[], str] | None = None
        self._make_status_bar()
        named = self.actions_by_name
        self.editor.context_actions = [named[name] if name else None for name in CONTEXT_MENU]
        self.plc_docks = build_plc_docks(self, self.menus, PlcSession(self), self.editor)
        self.names_menu.changed.connect(self.editor.relayout)
        self.names_menu.changed.connect(self.plc_docks.diagnostic.view.relayout)
        self.plc_docks.diagnostic.remember_zoom(self.settings)  # its zoom, saved
        self.plc_docks.watch.keep_in(self.settings)  # each program's watch rows
        # PLC › Native scan: the scan's code of the programs loaded (kept in the settings)
        self.scan_backend = ScanBackendChoice(self.plc_docks.session, self.settings, self)
        self.menus.add("menu_plc", self.scan_backend.action, separator=True)
        self.cross_reference = cross_reference.install(self, self.menus, self.editor,
                                                       self.errors)
        self.printing = PrintActions(self, self, self.menus)  # File › Print, Export PDF
        self.undo_texts = UndoTexts(self.model.undo_stack, self.actions_by_name["action_undo"],
                                    self.actions_by_name["action_redo"])  # "Undo Delete"
        # PMC parameters (T/C/K/D set in the PLC tables) are saved with the program
        self.parameters = ParameterDocument(self.plc_docks.session)
        self.plc_docks.session.parameters_changed.connect(self.update_title)
        self._install_file_state()

        self.model.modified_changed.connect(self.update_title)
        self.editor.tool_requested.connect(self.set_tool)
        self.editor.hover_changed.connect(self._show_hover)
        self.editor.message.connect(self.show_message)
        self.set_tool(Tool.SELECT)
        self.editor.set_function(self.tool_palette.current_function())
        self.model.document_reset.connect(self._palette_for_program)
        self.retranslate()
        self.resize(1200, 800)
        self._first_show = True
        self.help_window: InstructionHelp | None = None
        self.find_dialog: FindReplaceDialog | None = None
        state = settings.window_state()[1]  # the geometry: screen_fit.place_main_window
        if state is not None:
            self.restoreState(state)
        self.new_file()
        zoom, fit_width = settings.zoom()
        self.editor.set_zoom(zoom)
        self.actions_by_name["action_zoom_fit_width"].setChecked(fit_width)

    # -- actions, menus and docks -------------------------------------------------------

    def _conditions(self) -> dict[str, Condition]:
        """What the table's `enabled_when` names mean in this window."""
        stack = self.model.undo_stack
        return {
            LADDER_SHOWN: ([self.model.mode_changed], lambda: not self.model.showing_text),
            CAN_UNDO: ([stack.canUndoChanged], stack.canUndo),
            CAN_REDO: ([stack.canRedoChanged], stack.canRedo),
        }

    def _make_docks(self) -> None:
        """The editing docks: tools and signals tabbed on the left, the errors below."""
        self.tool_palette = ToolPalette(list(self.tool_actions.values()), self)  # tools' order
        self.tool_palette.function_chosen.connect(self._on_function_chosen)
        self.signals_dock = SignalListDock(self)
        self.signals_dock.address_chosen.connect(self.use_signal)
        self.errors = ErrorListDock(self)
        self.errors.activated.connect(self.go_to_diagnostic)
        self.errors.diagnostics_changed.connect(self.text_view.set_diagnostics)
        left = Qt.DockWidgetArea.LeftDockWidgetArea
        self.menus.add_dock(self.tool_palette, "action_dock_palette", left, separator=True)
        self.menus.add_dock(self.errors, "action_dock_errors",
                            Qt.DockWidgetArea.BottomDockWidgetArea)
        self.menus.add_dock(self.signals_dock, "action_dock_signals", left)
        self.tabifyDockWidget(self.tool_palette, self.signals_dock)
        self.tool_palette.raise_()

    def _make_status_bar(self) -> None:
        self.cell_label = ElidedLabel(self)
        self.cell_label.setObjectName("status_cell")
        self.cell_label.setMinimumWidth(140)
        self.statusBar().addPermanentWidget(self.cell_label)
        self.cell_status = CellStatus(self.editor, self.cell_label)  # the cursor's cell, now
        self.zoom_label = QLabel(self)
        self.zoom_label.setObjectName("status_zoom")
        self.statusBar().addPermanentWidget(self.zoom_label)
        self.editor.zoom_changed.connect(self._show_zoom)
        self.fit_width.fitted_changed.connect(self._show_zoom)

    def _fit_toggled(self, on: bool) -> None:
        self._show_zoom()
        if on:
            self.show_message(self.fit_width.describe)

    def _show_zoom(self, *_args: object) -> None:
        self.zoom_label.setText(percent(self.editor.zoom() * 100))
        # fit width says what it fitted: "9,812 of 10,000 networks fit…" (issue 31)
        self.zoom_label.setToolTip(self.fit_width.describe() or translate("MainWindow", "Zoom"))
        if self._status_text == self.fit_width.describe and self.statusBar().currentMessage():
            self.show_message(self.fit_width.describe)  # refitted (a dock opened): said anew

    # -- language ------------------------------------------------------------------------

    def retranslate(self) -> None:
        """Set every text in the current UI language (the docks set their own)."""
        self.dock_titles.check_soon()  # longer titles: a side group widens for its tabs
        self.menus.retranslate()
        self.plc_docks.retranslate()
        self.scan_backend.retranslate()
        self.printing.retranslate()
        self.undo_texts.retranslate()  # after the menus: Edit › Undo names its step
        for code in ("en", "tr"):
            self.actions_by_name[f"action_language_{code}"].setChecked(
                self.language.current == code
            )
        self.update_title()
        self._retranslate_status()
        self._show_zoom()
        self.editor.viewport().update()  # the networks' numbers (N1 / D1) are drawn words

    def set_language(self, code: str) -> None:
        """Switch the UI language live and remember it."""
        applied = self.language.apply(code)
        self.settings.set_language(applied)
        # deliver the LanguageChange events now, so every widget is retranslated on return
        QCoreApplication.sendPostedEvents(None, QEvent.Type.LanguageChange)
        self.language_changed.emit(applied)

    # -- tools ---------------------------------------------------------------------------

    def set_tool(self, tool: Tool) -> None:
        """Make `tool` the current tool of the grid editor."""
        self.tool_actions[tool].setChecked(True)
        self.editor.set_tool(tool)
        self.show_message(lambda: BY_TOOL[tool].help(), 4000)

    def current_tool(self) -> Tool:
        """The checked tool."""
        return self.editor.tool

    def _palette_for_program(self) -> None:
        """The palette offers the functional instructions of the open program's dialect."""
        self.tool_palette.set_dialect(self.model.dialect)
        self.editor.set_function(self.tool_palette.current_function())

    def _on_function_chosen(self, name: str) -> None:
        self.editor.set_function(name)
        self.set_tool(Tool.FUNCTION)

    def _show_hover(self, text: str) -> None:
        self.cell_label.setText(text)

    def show_message(self, text: str | Callable[[], str], timeout: int = 6000) -> None:
        """A status-bar message; one given as a function is said again after a language
        switch, a plain text is taken away then (it would stay in the old language)."""
        self._status_text = text if callable(text) else None
        self.statusBar().showMessage(text() if callable(text) else text, timeout)

    def _retranslate_status(self) -> None:
        if self.statusBar().currentMessage():
            if self._status_text is not None:
                self.statusBar().showMessage(self._status_text(), 6000)
            else:
                self.statusBar().clearMessage()
        index, row, col = self.editor.cursor_cell
        if index < len(self.editor.networks) and self.cell_label.text():
            self.cell_label.setText(self.editor.describe_cell(index, row, col))

    # -- documents -----------------------------------------------------------------------

    def update_title(self, *_args: object) -> None:
        """The window's title: the file's name, `*` when modified."""
        name = self.path.name if self.path else translate("MainWindow", "Untitled")
        if self.path is not None and self.path.is_dir():  # a folder of exports (S7)
            name += os.sep
        star = "*" if self.is_modified() else ""
        self.setWindowTitle(f"{name}{star} — LadderWorks")

    def warn(self, title: str, text: str) -> None:
        """Show a warning without blocking (the text is kept in `last_warning`)."""
        self.last_warning = text
        box = QMessageBox(
            QMessageBox.Icon.Warning, title, text, QMessageBox.StandardButton.Ok, self
        )
        box.setObjectName("warning_box")
        box.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose, True)
        box.open()

    def program_shown(self, program: Program) -> None:
        """A program is now shown: its symbols and messages go to the docks."""
        self.program_info = program
        self.program_serial += 1  # an untitled drawing is another program than the last
        # the cell under the cursor of the program now shown, not the last one's
        shown = self.editor.networks and not self.model.showing_text
        self.cell_label.setText(self.editor.describe_cell(*self.editor.cursor_cell) if shown
                                else "")
        self.signals_dock.set_symbols(program.symbols)
        self.plc_docks.session.set_symbols(program.symbols)
        self.plc_docks.session.set_console_dialect(program.dialect)  # the docks' examples
        self.plc_docks.ascii_output.use_program(self.path)  # a Fatek program's ASCII files
        self.plc_docks.watch.use_program(self.path, program)  # its names, its kept rows
        self.program_opened.emit(program)

    def show_program_properties(self) -> QDialog:
        """File › Program properties: title, system parameters, I/O modules, sections, form."""
        from ladderworks.gui.program_properties import ProgramPropertiesDialog

        dialog = ProgramPropertiesDialog(self.program_info, self.path, self, self.set_pmc_model)
        dialog.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose, True)
        self.properties_dialog = dialog
        dialog.open()
        return dialog

    def set_pmc_model(self, key: str) -> None:
        """Make `key` the program's PMC model (Program properties): its ranges from now on,
        kept in the file at the next Save; a model of another family: `change_family`."""
        program = self.program_info
        if model_of(key).family != model_of(program.dialect).family:
            self.change_family(key)
            return
        origin = self.model.document.origin  # the program the ladder was laid out from
        if origin is None:  # a new program: its model is this one's
            self.model.document.origin = origin = program
        program.dialect = origin.dialect = key
        self.dialect = key
        self.model.mark_modified()
        self.update_title()

    def remember_file(self, path: Path) -> None:
        """Put `path` first in File › Recent files."""
        self.settings.add_recent_file(str(path))
        self._update_recent_menu()

    def _update_recent_menu(self) -> None:
        self.recent_menu.clear()
        files = self.settings.recent_files()
        for action, name in zip(self.recent_actions, files, strict=False):
            action.setText(name)
            action.setData(name)
            self.recent_menu.addAction(action)
        self.recent_menu.addSeparator()
        self.recent_menu.addAction(self.actions_by_name["action_clear_recent"])
        self.recent_menu.setEnabled(True)

    def _open_recent(self, index: int) -> None:
        files = self.settings.recent_files()
        if index < len(files) and self.maybe_save():
            self.load(files[index])

    def clear_recent(self) -> None:
        """File › Recent files › Clear the list."""
        self.settings.clear_recent_files()
        self._update_recent_menu()

    def _show_mode(self, mode: str) -> None:
        self.pages.setCurrentWidget(self.text_view if mode == Mode.TEXT else self.editor)
        if mode == Mode.TEXT:
            self.cell_label.setText("")  # no cell: the text view has its own cursor

    def show_as_text(self) -> None:
        """Show the program as instruction-list text."""
        if self.model.showing_text:
            return
        text = self.program_text(faithful=True)
        if text is None:
            return
        self.text_view.setPlainText(bad_bytes_shown(text))
        self.text_view.document().setModified(False)
        self.model.set_mode(Mode.TEXT)

    def show_as_ladder(self) -> bool:
        """Parse the text view and show it as ladder; errors stay in the text view."""
        if not self.model.showing_text:
            return True
        modified = self.text_view.document().isModified()
        result = self.document.read_text(self.text_view.toPlainText())  # in the file's form
        self.errors.set_diagnostics(result.diagnostics)
        if not result.ok:
            self.errors.show()
            return False
        self.failed_path = None
        self.model.set_program(result.program)
        self.model.set_mode(Mode.LADDER)
        self.program_shown(result.program)
        if modified:
            self.model.mark_modified()
        self.update_title()
        return True

    # -- PLC -----------------------------------------------------------------------------

    def check(self) -> list[Diagnostic]:
        """Check the program (grid and text rules) and list the diagnostics."""
        if not self.show_as_ladder():
            return self.errors.diagnostics()
        program, diagnostics = self.model.program()
        if program is not None:
            diagnostics = diagnostics + compile_step.check(program)
        self.errors.set_diagnostics(diagnostics)
        self.errors.show()
        errors = sum(1 for d in diagnostics if d.is_error)
        self.show_message(lambda: translate("MainWindow", "Check: {0} error(s)").format(errors))
        return diagnostics

    def compile(self) -> bytes | None:
        """PLC > Compile: the binary PLC program, or None with the errors listed."""
        if not self.show_as_ladder():
            return None
        program, diagnostics = self.model.program()
        binary: bytes | None = None
        if program is not None and not has_errors(diagnostics):
            binary, more = compile_step.compile_program(program)
            diagnostics = diagnostics + more
        self.errors.set_diagnostics(diagnostics)
        if binary is None:
            self.errors.show()
            errors = sum(1 for d in diagnostics if d.is_error)
            self.show_message(lambda: translate(
                "MainWindow", "Compile failed: {0} error(s)").format(errors))
        else:
            assert program is not None
            self.show_message(self._load_into_plc(binary, program))
        return binary

    def _load_into_plc(self, binary: bytes, program: Program) -> str:
        """One path (issue 18): the compiled program goes into the simulated PLC the docks
        use; a running PLC reloads between two scans after asking, and runs on. The status
        bar message."""
        session = self.plc_docks.session
        running = session.run.running
        if running and questions.reload_running(self) != "reload":
            return translate("MainWindow", "Compile finished: {0} bytes (not loaded: the PLC "
                             "runs the previous program)").format(len(binary))
        name = str(self.path) if self.path else f"untitled {self.program_serial}"
        origin = (program.dialect, name)
        forces = forces_on_load(self, session, origin)
        if forces is None:
            return translate("MainWindow", "Compile finished: {0} bytes (not loaded: the PLC "
                             "keeps the program it has)").format(len(binary))
        problems = session.load(binary, program, origin=origin, keep_forces=forces == "keep")
        if problems:
            self.errors.set_diagnostics(problems)
            self.errors.show()
            return translate("MainWindow", "Compile finished, but the PLC refused the program")
        self.plc_docks.scenario.program_path = self.path  # a recorded scenario's PROGRAM
        name = self.path.name if self.path else translate("MainWindow", "Untitled")
        # printed when the control screen is shown (~1.4 s of F9 behind a hidden dock)
        self.plc_docks.control.show_loaded(lambda: print_program(program), name)
        if running:
            session.start()
        return translate("MainWindow", "Compile finished: {0} bytes, loaded into the PLC").format(
            len(binary))

    def go_to_diagnostic(self, diagnostic: Diagnostic) -> None:
        """Jump to the diagnostic's cell in the ladder, or its line in the text view."""
        if self.model.showing_text or (diagnostic.network is None and diagnostic.line):
            if not self.model.showing_text:
                self.show_as_text()
            self.text_view.go_to(diagnostic.line, diagnostic.column)
            return
        self.editor.go_to(diagnostic)

    def show_find(self, replacing: bool = False) -> FindReplaceDialog | None:
        """Edit › Find (Ctrl+F) / Replace (Ctrl+H): addresses and symbols in the ladder."""
        if not self.show_as_ladder():
            return None
        if self.find_dialog is None:
            self.find_dialog = FindReplaceDialog(self.editor, self)
        self.find_dialog.start(replacing)
        return self.find_dialog

    def find_again(self, forward: bool = True) -> None:
        """Edit › Find next (F3) / Find previous (Shift+F3): the last search again, from the
        cursor; the Find dialog opens when nothing was searched for yet."""
        dialog = self.find_dialog
        if dialog is None or dialog.query() is None:
            self.show_find(False)
            return
        if self.show_as_ladder():
            dialog.find_again(forward)
            self.show_message(dialog.message.text())

    # -- help and closing ----------------------------------------------------------------

    def use_signal(self, address: Address) -> None:
        """A signal double-clicked in the list: onto the element at the cursor, else copied."""
        if self.editor.edits.assign_address_at_cursor(address):
            self.show_message(translate("MainWindow", "Address {0} set").format(address))
            return
        QApplication.clipboard().setText(str(address))
        self.show_message(translate(
            "MainWindow", "{0} copied (select a contact or coil to set its address)",
        ).format(address))

    def instruction_at_cursor(self) -> str:
        """The instruction help should show: the element at the cursor, else the palette's."""
        index, row, col = self.editor.cursor_cell
        if index < len(self.model.networks):
            found = self.model.networks[index].element_at(row, col)
            if found is not None:
                element = found[1]
                if isinstance(element, FunctionBox):
                    return element.name
                if isinstance(element, Contact):
                    return contact_spec(element).name
                if isinstance(element, Coil):
                    return coil_spec(element).name
        return self.tool_palette.current_function()

    def show_instruction_help(self, name: str | None = None) -> InstructionHelp:
        """Help > Instruction reference (F1): `name`'s entry, or the element at the cursor's."""
        if self.help_window is None:
            self.help_window = InstructionHelp(self)
        self.help_window.show_instruction(name or self.instruction_at_cursor(),
                                          self.model.dialect)  # a Delta LD: Delta's entry
        self.help_window.show()
        self.help_window.raise_()
        return self.help_window

    def about(self) -> None:
        """Help > About."""
        QMessageBox.about(
            self,
            translate("MainWindow", "About LadderWorks"),
            translate(
                "MainWindow", "LadderWorks: ladder (FANUC PMC style) programming for CNC machines."
            ),
        )

    def showEvent(self, event: QShowEvent) -> None:
        """On the first show, keep the bottom docks low (a fifth of the window, at most 170 px)
        so the ladder has the room."""
        super().showEvent(event)
        if self._first_show:
            self._first_show = False
            if self.settings.window_state()[1] is None:
                bottom = [dock for dock in self.findChildren(QDockWidget)
                          if self.dockWidgetArea(dock) == Qt.DockWidgetArea.BottomDockWidgetArea
                          and dock.isVisible()]
                if bottom:
                    low = max(100, min(170, self.height() // 5))
                    self.resizeDocks(bottom, [low] * len(bottom), Qt.Orientation.Vertical)
            else:  # a layout saved on a larger screen: the ladder gets its room back
                QTimer.singleShot(0, lambda: rebalance_docks(self, self.editor.viewport()))

    def closeEvent(self, event: QCloseEvent) -> None:
        """Ask about unsaved changes; remember the window layout."""
        if not self.maybe_save():
            event.ignore()
            return
        self.settings.set_window_state(self.saveGeometry(), self.saveState())
        self.settings.set_zoom(self.editor.zoom(), self.fit_width.enabled)
        self.autosaver.timer.stop()
        self.recovery.close()  # saved or discarded: the recovery copy goes
        if self.help_window is not None:
            self.help_window.close()
        self.plc_docks.session.close()  # the PLC stops; its scan process ends
        event.accept()
