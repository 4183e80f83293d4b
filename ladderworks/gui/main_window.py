"""The ladder console's main window: menus, actions, tool palette, editor, text view, docks."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QEvent, Qt, Signal
from PySide6.QtGui import QAction, QActionGroup, QCloseEvent, QKeySequence, QShowEvent
from PySide6.QtWidgets import (
    QApplication,
    QDialog,
    QDockWidget,
    QLabel,
    QMainWindow,
    QMenu,
    QMessageBox,
    QStackedWidget,
    QToolBar,
    QWidget,
)

from ladderworks.core.address import Address
from ladderworks.core.diagnostics import Diagnostic, has_errors
from ladderworks.core.il import Program, print_program
from ladderworks.core.ladder import Coil, Contact, FunctionBox
from ladderworks.gui import compile_step, questions
from ladderworks.gui.document import bad_bytes_back, bad_bytes_shown
from ladderworks.gui.editor.interactions import BY_TOOL, INTERACTIONS
from ladderworks.gui.editor.ladder_model import LadderModel, Mode
from ladderworks.gui.editor.name_menu import NameDisplayMenu
from ladderworks.gui.editor.view import LadderEditor
from ladderworks.gui.editor.zoom import FitWidth
from ladderworks.gui.error_list import ErrorListDock
from ladderworks.gui.file_actions import FileActions
from ladderworks.gui.find_replace import FindReplaceDialog
from ladderworks.gui.help_browser import InstructionHelp
from ladderworks.gui.locale_numbers import percent
from ladderworks.gui.palette import ToolPalette
from ladderworks.gui.parameter_document import ParameterDocument
from ladderworks.gui.settings import MAX_RECENT, Settings
from ladderworks.gui.signal_list import SignalListDock
from ladderworks.gui.text_view import ProgramTextView
from ladderworks.gui.tools import Tool, icon
from ladderworks.gui.translation import UiLanguage

translate = QCoreApplication.translate


class MainWindow(FileActions, QMainWindow):
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
        self.setWindowIcon(icon("ladderworks"))

        self.model = LadderModel(self)  # the networks, the undo stack, ladder or text
        self.editor = LadderEditor(self.model, self)
        self.fit_width = FitWidth(self.editor)  # View › Fit width
        self.text_view = ProgramTextView(self)
        self.text_view.document().modificationChanged.connect(self._update_title)
        self.pages = QStackedWidget(self)
        self.pages.setObjectName("pages")
        self.pages.addWidget(self.editor)
        self.pages.addWidget(self.text_view)
        self.setCentralWidget(self.pages)
        self.model.mode_changed.connect(self._show_mode)

        self.actions_by_name: dict[str, QAction] = {}
        self._texts: list[tuple[QAction | QMenu | QToolBar, Callable[[], str]]] = []
        self._make_actions()
        self.tool_palette = ToolPalette([self.tool_actions[cls.tool] for cls in INTERACTIONS],
                                        self)
        self.tool_palette.function_chosen.connect(self._on_function_chosen)
        self.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, self.tool_palette)
        self.errors = ErrorListDock(self)
        self.errors.activated.connect(self.go_to_diagnostic)
        self.errors.diagnostics_changed.connect(self.text_view.set_diagnostics)
        self.addDockWidget(Qt.DockWidgetArea.BottomDockWidgetArea, self.errors)
        self.signals_dock = SignalListDock(self)
        self.signals_dock.address_chosen.connect(self.use_signal)
        self.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, self.signals_dock)
        self.tabifyDockWidget(self.tool_palette, self.signals_dock)
        self.tool_palette.raise_()
        self._make_menus()
        self._status_text: Callable[[], str] | None = None
        self._make_status_bar()
        named = self.actions_by_name
        self.editor.context_actions = [
            named[name] if name else None for name in (
                "action_cut", "action_copy", "action_paste", "action_delete", "",
                "action_invert", "action_or", "", "action_insert_row_before",
                "action_insert_row_after", "", "action_delete_network")]
        from ladderworks.gui.docks import install_plc_docks  # the PLC docks (issues 7, 8)

        self.plc_docks = install_plc_docks(self)
        from ladderworks.gui.docks import cross_reference  # issue 18: xref dock, Tools menu

        self.cross_reference = cross_reference.install(self)
        from ladderworks.gui import print_actions  # issue 18: File › Print, Export PDF

        print_actions.install(self)
        # PMC parameters (T/C/K/D set in the PLC tables) are saved with the program
        self.parameters = ParameterDocument(self.plc_docks.session)
        self.plc_docks.session.parameters_changed.connect(self._update_title)
        self._install_file_state()

        self.model.modified_changed.connect(self._update_title)
        self.editor.tool_requested.connect(self.set_tool)
        self.editor.hover_changed.connect(self._show_hover)
        self.editor.message.connect(self._show_message)
        self.set_tool(Tool.SELECT)
        self.editor.set_function(self.tool_palette.current_function())
        self.retranslate()
        self.resize(1200, 800)
        self._first_show = True
        self.help_window: InstructionHelp | None = None
        self.find_dialog: FindReplaceDialog | None = None
        geometry, state = settings.window_state()
        if geometry is not None:
            self.restoreGeometry(geometry)
        if state is not None:
            self.restoreState(state)
        self.new_file()
        zoom, fit_width = settings.zoom()
        self.editor.set_zoom(zoom)
        self.actions_by_name["action_zoom_fit_width"].setChecked(fit_width)

    # -- actions and menus ---------------------------------------------------------------

    def _action(
        self,
        name: str,
        text: Callable[[], str],
        slot: Callable[[], object] | None,
        shortcut: QKeySequence | QKeySequence.StandardKey | str | None = None,
        icon_name: str | None = None,
    ) -> QAction:
        action = QAction(self)
        action.setObjectName(name)
        if shortcut is not None:
            action.setShortcut(QKeySequence(shortcut))
        if icon_name is not None:
            action.setIcon(icon(icon_name))
        if slot is not None:
            action.triggered.connect(lambda _checked=False, s=slot: s())
        self.actions_by_name[name] = action
        self._texts.append((action, text))
        return action

    def _make_actions(self) -> None:
        key = QKeySequence.StandardKey
        ed = self.editor
        a = self._action
        a("action_new", lambda: translate("MainWindow", "&New"), self.new_file, key.New)
        a("action_open", lambda: translate("MainWindow", "&Open..."), self.open_dialog, key.Open)
        a("action_save", lambda: translate("MainWindow", "&Save"), self.save, key.Save)
        a(
            "action_save_as",
            lambda: translate("MainWindow", "Save &As..."),
            self.save_as_dialog,
            key.SaveAs,
        )
        a(
            "action_import_mod",
            lambda: translate("MainWindow", "&Import .MOD..."),
            self.import_mod_dialog,
        )
        a(
            "action_export_mod",
            lambda: translate("MainWindow", "&Export .MOD..."),
            self.export_mod_dialog,
        )
        a(
            "action_clear_recent",
            lambda: translate("MainWindow", "Clear the list"),
            self._clear_recent,
        )
        a(
            "action_program_properties",
            lambda: translate("MainWindow", "Program &properties..."),
            self.show_program_properties,
        )
        a("action_quit", lambda: translate("MainWindow", "&Quit"), self.close, key.Quit)
        undo = self.model.undo_stack.createUndoAction(self)
        undo.setObjectName("action_undo")
        undo.setShortcut(QKeySequence(key.Undo))
        self.actions_by_name["action_undo"] = undo
        self._texts.append((undo, lambda: translate("MainWindow", "&Undo")))
        redo = self.model.undo_stack.createRedoAction(self)
        redo.setObjectName("action_redo")
        # Ctrl+Y everywhere (docs/ui.md), Ctrl+Shift+Z too, and the platform's own key
        redo_keys = [QKeySequence("Ctrl+Y"), QKeySequence("Ctrl+Shift+Z")]
        redo.setShortcuts(redo_keys + [k for k in QKeySequence.keyBindings(key.Redo)
                                       if k not in redo_keys])
        self.actions_by_name["action_redo"] = redo
        self._texts.append((redo, lambda: translate("MainWindow", "&Redo")))
        a("action_cut", lambda: translate("MainWindow", "Cu&t"), ed.cut, key.Cut)
        a("action_copy", lambda: translate("MainWindow", "&Copy"), ed.copy, key.Copy)
        a("action_paste", lambda: translate("MainWindow", "&Paste"), ed.paste, key.Paste)
        a("action_delete", lambda: translate("MainWindow", "&Delete"), ed.delete_at_cursor, "Del")
        a(
            "action_edit_element",
            lambda: translate("MainWindow", "&Edit element"),
            ed.edit_at_cursor,
        )
        a(
            "action_invert",
            lambda: translate("MainWindow", "NOT (invert)"),
            ed.invert_at_cursor,
            None,
            "invert",
        )
        a(
            "action_or",
            lambda: translate("MainWindow", "OR (add parallel)"),
            ed.or_at_cursor,
            None,
            "or",
        )
        a(
            "action_insert_row_before",
            lambda: translate("MainWindow", "Insert row before"),
            ed.insert_row_before,
            None,
            "row_before",
        )
        a(
            "action_insert_row_after",
            lambda: translate("MainWindow", "Insert row after"),
            ed.insert_row_after,
            None,
            "row_after",
        )
        a("action_delete_network", lambda: translate("MainWindow", "Delete network"),
          ed.delete_network)
        a("action_find", lambda: translate("MainWindow", "&Find..."),
          lambda: self.show_find(replacing=False), key.Find)
        a("action_replace", lambda: translate("MainWindow", "R&eplace..."),
          lambda: self.show_find(replacing=True), "Ctrl+H")
        a("action_zoom_in", lambda: translate("MainWindow", "Zoom &in"), ed.zoom_in, key.ZoomIn)
        a("action_zoom_out", lambda: translate("MainWindow", "Zoom &out"), ed.zoom_out, key.ZoomOut)
        a(
            "action_zoom_reset",
            lambda: translate("MainWindow", "&Normal size"),
            ed.zoom_reset,
            "Ctrl+0",
        )
        fit = a("action_zoom_fit_width", lambda: translate("MainWindow", "Fit &width"), None,
                "Ctrl+9", "zoom_fit_width")
        fit.setCheckable(True)
        fit.toggled.connect(self.fit_width.set_enabled)
        for name in ("action_zoom_in", "action_zoom_out", "action_zoom_reset"):
            self.actions_by_name[name].triggered.connect(lambda _c=False: fit.setChecked(False))
        a(
            "action_show_ladder",
            lambda: translate("MainWindow", "Show as &ladder"),
            self.show_as_ladder,
            "F5",
        )
        a(
            "action_show_text",
            lambda: translate("MainWindow", "Show as &text"),
            self.show_as_text,
            "F6",
        )
        a("action_check", lambda: translate("MainWindow", "C&heck"), self.check, "F7")
        a(
            "action_compile",
            lambda: translate("MainWindow", "&Compile"),
            self.compile,
            "F9",
            "compile",
        )
        a("action_language_en", lambda: "English", lambda: self.set_language("en"))
        a("action_language_tr", lambda: "Türkçe", lambda: self.set_language("tr"))
        a(
            "action_instruction_help",
            lambda: translate("MainWindow", "&Instruction reference"),
            self.show_instruction_help,
            QKeySequence.StandardKey.HelpContents,
        )
        a("action_about", lambda: translate("MainWindow", "&About LadderWorks"), self.about)
        languages = QActionGroup(self)
        for code in ("en", "tr"):
            action = self.actions_by_name[f"action_language_{code}"]
            action.setCheckable(True)
            languages.addAction(action)
        self.recent_actions: list[QAction] = []
        for index in range(MAX_RECENT):
            action = QAction(self)
            action.setObjectName(f"action_recent_{index}")
            action.triggered.connect(lambda _c=False, i=index: self._open_recent(i))
            self.recent_actions.append(action)
            self.actions_by_name[action.objectName()] = action
        self.tool_group = QActionGroup(self)
        self.tool_actions: dict[Tool, QAction] = {}
        for interaction in INTERACTIONS:  # the palette's and the Tools menu's order
            tool = interaction.tool
            action = QAction(interaction.icon(), "", self)
            action.setObjectName(f"tool_{tool.value}")
            action.setCheckable(True)
            action.triggered.connect(lambda _c=False, t=tool: self.set_tool(t))
            self.tool_group.addAction(action)
            self.tool_actions[tool] = action
            self.actions_by_name[action.objectName()] = action

    def _menu(self, name: str, text: Callable[[], str], names: list[str | None]) -> QMenu:
        menu = self.menuBar().addMenu("")
        menu.setObjectName(name)
        self._texts.append((menu, text))
        for item in names:
            if item is None:
                menu.addSeparator()
            else:
                menu.addAction(self.actions_by_name[item])
        return menu

    def _make_menus(self) -> None:
        file_menu = self._menu(
            "menu_file", lambda: translate("MainWindow", "&File"), ["action_new", "action_open"]
        )
        self.recent_menu = QMenu(file_menu)
        self.recent_menu.setObjectName("menu_recent")
        self._texts.append((self.recent_menu, lambda: translate("MainWindow", "Recent files")))
        file_menu.addMenu(self.recent_menu)
        for item in (
            "action_save",
            "action_save_as",
            None,
            "action_import_mod",
            "action_export_mod",
            None,
            "action_program_properties",
            None,
            "action_quit",
        ):
            if item is None:
                file_menu.addSeparator()
            else:
                file_menu.addAction(self.actions_by_name[item])
        self._menu(
            "menu_edit",
            lambda: translate("MainWindow", "&Edit"),
            [
                "action_undo",
                "action_redo",
                None,
                "action_cut",
                "action_copy",
                "action_paste",
                "action_delete",
                None,
                "action_edit_element",
                "action_invert",
                "action_or",
                "action_insert_row_before",
                "action_insert_row_after",
                "action_delete_network",
                None,
                "action_find",
                "action_replace",
            ],
        )
        view = self._menu(
            "menu_view",
            lambda: translate("MainWindow", "&View"),
            [
                "action_zoom_in",
                "action_zoom_out",
                "action_zoom_reset",
                "action_zoom_fit_width",
                None,
                "action_show_ladder",
                "action_show_text",
                None,
            ],
        )
        view.addMenu(NameDisplayMenu(self.settings, self))  # element names (issue 18)
        view.addSeparator()
        for dock, name in (
            (self.tool_palette, "action_dock_palette"),
            (self.errors, "action_dock_errors"),
            (self.signals_dock, "action_dock_signals"),
        ):
            toggle = dock.toggleViewAction()
            toggle.setObjectName(name)
            self.actions_by_name[name] = toggle
            view.addAction(toggle)
        self._menu(
            "menu_plc", lambda: translate("MainWindow", "&PLC"), ["action_check", "action_compile"]
        )
        tools = self._menu(
            "menu_tools",
            lambda: translate("MainWindow", "&Tools"),
            [f"tool_{cls.tool.value}" for cls in INTERACTIONS],
        )
        tools.addSeparator()
        self._menu(
            "menu_language",
            lambda: translate("MainWindow", "&Language"),
            ["action_language_en", "action_language_tr"],
        )
        self._menu(
            "menu_help",
            lambda: translate("MainWindow", "&Help"),
            ["action_instruction_help", "action_about"],
        )
        toolbar = QToolBar(self)
        toolbar.setObjectName("toolbar_main")
        self._texts.append((toolbar, lambda: translate("MainWindow", "Main toolbar")))
        for item in (
            "action_new",
            "action_open",
            "action_save",
            None,
            "action_undo",
            "action_redo",
            None,
            "action_zoom_in",
            "action_zoom_out",
            "action_zoom_fit_width",
            None,
            "action_compile",
        ):
            if item is None:
                toolbar.addSeparator()
            else:
                toolbar.addAction(self.actions_by_name[item])
        style = self.style()
        sp = style.StandardPixmap
        for name, pixmap in (
            ("action_new", sp.SP_FileIcon),
            ("action_open", sp.SP_DialogOpenButton),
            ("action_save", sp.SP_DialogSaveButton),
            ("action_undo", sp.SP_ArrowBack),
            ("action_redo", sp.SP_ArrowForward),
        ):
            self.actions_by_name[name].setIcon(style.standardIcon(pixmap))
        self.actions_by_name["action_zoom_in"].setIcon(icon("zoom_in"))
        self.actions_by_name["action_zoom_out"].setIcon(icon("zoom_out"))
        toolbar_toggle = toolbar.toggleViewAction()
        toolbar_toggle.setObjectName("action_toolbar_main")
        self.actions_by_name["action_toolbar_main"] = toolbar_toggle
        view.addAction(toolbar_toggle)
        self.addToolBar(Qt.ToolBarArea.TopToolBarArea, toolbar)
        self._update_recent_menu()

    def _make_status_bar(self) -> None:
        self.cell_label = QLabel(self)
        self.cell_label.setObjectName("status_cell")
        self.cell_label.setMinimumWidth(140)
        self.statusBar().addPermanentWidget(self.cell_label)
        self.zoom_label = QLabel(self)
        self.zoom_label.setObjectName("status_zoom")
        self.statusBar().addPermanentWidget(self.zoom_label)
        self.editor.zoom_changed.connect(self._show_zoom)

    def _show_zoom(self, *_args: object) -> None:
        self.zoom_label.setText(percent(self.editor.zoom() * 100))
        self.zoom_label.setToolTip(translate("MainWindow", "Zoom"))

    # -- language ------------------------------------------------------------------------

    def retranslate(self) -> None:
        """Set every text in the current UI language."""
        for widget, text in self._texts:
            if isinstance(widget, QAction):
                widget.setText(text())
            elif isinstance(widget, QMenu):
                widget.setTitle(text())
            else:
                widget.setWindowTitle(text())
        for tool, action in self.tool_actions.items():
            # the key shows in the menu's shortcut column (it works while the grid has focus)
            kind = BY_TOOL[tool]
            action.setText(f"{kind.name()}\t{kind.key}")
            action.setIconText(kind.name())
            action.setToolTip(f"{kind.name()} ({kind.key}): {kind.help()}")
            action.setStatusTip(kind.help())
        for code in ("en", "tr"):
            self.actions_by_name[f"action_language_{code}"].setChecked(
                self.language.current == code
            )
        self._update_title()
        self._retranslate_status()
        self._show_zoom()
        self.editor.viewport().update()  # the networks' numbers (N1 / D1) are drawn words

    def changeEvent(self, event: QEvent) -> None:
        """Retranslate on a language change."""
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
        super().changeEvent(event)

    def set_language(self, code: str) -> None:
        """Switch the UI language live and remember it."""
        applied = self.language.apply(code)
        self.settings.set_language(applied)
        # deliver the LanguageChange events now, so every widget is retranslated on return
        QCoreApplication.sendPostedEvents(None, QEvent.Type.LanguageChange)
        self.retranslate()
        self.language_changed.emit(applied)

    # -- tools ---------------------------------------------------------------------------

    def set_tool(self, tool: Tool) -> None:
        """Make `tool` the current tool of the grid editor."""
        self.tool_actions[tool].setChecked(True)
        self.editor.set_tool(tool)
        self._show_message(lambda: BY_TOOL[tool].help(), 4000)

    def current_tool(self) -> Tool:
        """The checked tool."""
        return self.editor.tool

    def _on_function_chosen(self, name: str) -> None:
        self.editor.set_function(name)
        self.set_tool(Tool.FUNCTION)

    def _show_hover(self, text: str) -> None:
        self.cell_label.setText(text)

    def _show_message(self, text: str | Callable[[], str], timeout: int = 6000) -> None:
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

    def _update_title(self, *_args: object) -> None:
        name = self.path.name if self.path else translate("MainWindow", "Untitled")
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

    def _program_shown(self, program: Program) -> None:
        """A program is now shown: its symbols and messages go to the docks."""
        self.program_info = program
        self.signals_dock.set_symbols(program.symbols)
        session = getattr(getattr(self, "plc_docks", None), "session", None)
        if session is not None:
            session.set_symbols(program.symbols)
        self.program_opened.emit(program)

    def show_program_properties(self) -> QDialog:
        """File › Program properties: title, system parameters, I/O modules, sections, form."""
        from ladderworks.gui.program_properties import ProgramPropertiesDialog

        dialog = ProgramPropertiesDialog(self.program_info, self.path, self)
        dialog.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose, True)
        self.properties_dialog = dialog
        dialog.open()
        return dialog

    def _remember(self, path: Path) -> None:
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

    def _clear_recent(self) -> None:
        self.settings.clear_recent_files()
        self._update_recent_menu()

    def _show_mode(self, mode: str) -> None:
        self.pages.setCurrentWidget(self.text_view if mode == Mode.TEXT else self.editor)

    def show_as_text(self) -> None:
        """Show the program as instruction-list text."""
        if self.model.showing_text:
            return
        text = self.program_text()
        if text is None:
            return
        self.text_view.setPlainText(bad_bytes_shown(text))
        self.text_view.document().setModified(False)
        self.model.set_mode(Mode.TEXT)

    def show_as_ladder(self) -> bool:
        """Parse the text view and show it as ladder; errors stay in the text view."""
        if not self.model.showing_text:
            return True
        from ladderworks.core.il import parse

        modified = self.text_view.document().isModified()
        result = parse(bad_bytes_back(self.text_view.toPlainText()))
        self.errors.set_diagnostics(result.diagnostics)
        if not result.ok:
            self.errors.show()
            return False
        self.failed_path = None
        self.model.set_program(result.program)
        self.model.set_mode(Mode.LADDER)
        self._program_shown(result.program)
        if modified:
            self.model.mark_modified()
        self._update_title()
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
        self._show_message(lambda: translate("MainWindow", "Check: {0} error(s)").format(errors))
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
            self._show_message(lambda: translate(
                "MainWindow", "Compile failed: {0} error(s)").format(errors))
        else:
            assert program is not None
            self._show_message(self._load_into_plc(binary, program))
        return binary

    def _load_into_plc(self, binary: bytes, program: Program) -> str:
        """One path (issue 18): the compiled program goes into the simulated PLC the docks
        use; a running PLC reloads between two scans after asking, and runs on. The status
        bar message."""
        session = self.plc_docks.session
        running = session.running
        if running and questions.reload_running(self) != "reload":
            return translate("MainWindow", "Compile finished: {0} bytes (not loaded: the PLC "
                             "runs the previous program)").format(len(binary))
        problems = session.load(binary, program)
        if problems:
            self.errors.set_diagnostics(problems)
            self.errors.show()
            return translate("MainWindow", "Compile finished, but the PLC refused the program")
        name = self.path.name if self.path else translate("MainWindow", "Untitled")
        self.plc_docks.control.show_loaded(print_program(program), name)
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

    # -- help and closing ----------------------------------------------------------------

    def use_signal(self, address: Address) -> None:
        """A signal double-clicked in the list: onto the element at the cursor, else copied."""
        if self.editor.assign_address_at_cursor(address):
            self._show_message(translate("MainWindow", "Address {0} set").format(address))
            return
        QApplication.clipboard().setText(str(address))
        self._show_message(translate(
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
                    return "RD.NOT" if element.negated else "RD"
                if isinstance(element, Coil):
                    return "WRT.NOT" if element.negated else "WRT"
        return self.tool_palette.current_function()

    def show_instruction_help(self, name: str | None = None) -> InstructionHelp:
        """Help > Instruction reference (F1): `name`'s entry, or the element at the cursor's."""
        if self.help_window is None:
            self.help_window = InstructionHelp(self)
        self.help_window.show_instruction(name or self.instruction_at_cursor())
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
        """On the first show, keep the bottom docks low so the ladder has the room."""
        super().showEvent(event)
        if self._first_show:
            self._first_show = False
            if self.settings.window_state()[1] is None:
                bottom = [dock for dock in self.findChildren(QDockWidget)
                          if self.dockWidgetArea(dock) == Qt.DockWidgetArea.BottomDockWidgetArea
                          and dock.isVisible()]
                if bottom:
                    self.resizeDocks(bottom, [170] * len(bottom), Qt.Orientation.Vertical)

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
        event.accept()
