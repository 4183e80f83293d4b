"""The main window's actions and menus as data: name, text, key, icon, slot, menu, toolbar.

`console_menus.ConsoleMenus` builds the QActions, menus and main toolbar from these tables and
sets their texts on each language change; the PLC docks add their own actions to the menus it
built (gui/docks/__init__.py)."""

from __future__ import annotations

from dataclasses import dataclass

from PySide6.QtGui import QKeySequence

from ladderworks.core.diagnostics import QT_TRANSLATE_NOOP  # lupdate reads the name

Key = QKeySequence.StandardKey
Shortcut = QKeySequence.StandardKey | str | tuple[QKeySequence.StandardKey | str, ...] | None

# When an action is enabled (besides always): the window provides each condition.
LADDER_SHOWN = "ladder"  # the grid editor is shown (not the text view)
CAN_UNDO = "can_undo"  # the ladder's undo stack has something to undo
CAN_REDO = "can_redo"


@dataclass(frozen=True, slots=True)
class ActionSpec:
    """One action of the main window."""

    name: str  # objectName, the key of `actions_by_name`
    text: str  # English, marked for translation in context "MainWindow"
    slot: str  # a method of the window, or of one of its parts: "editor.edits.cut"
    shortcut: Shortcut = None  # several: the first is shown in the menu
    icon: str | None = None  # resources/icons/<icon>.svg, or a Qt standard pixmap "SP_…"
    menu: str | None = None  # objectName of the menu it is in
    group: int = 0  # a separator goes between two groups of one menu
    toolbar: int | None = None  # its group on the main toolbar (None: not on it)
    checkable: bool = False
    exclusive: bool = False  # one of the exclusive actions of its menu is checked
    toggles: bool = False  # the slot takes the checked state, on every change (also by code)
    enabled_when: str | None = None  # LADDER_SHOWN, CAN_UNDO, CAN_REDO
    argument: str | bool | None = None  # passed to the slot


@dataclass(frozen=True, slots=True)
class MenuSpec:
    """One menu of the menu bar, or a submenu (`parent`) placed after one of its actions."""

    name: str
    title: str
    parent: str | None = None
    after: str | None = None



MENUS: tuple[MenuSpec, ...] = (
    MenuSpec("menu_file", QT_TRANSLATE_NOOP("MainWindow", "&File")),
    MenuSpec("menu_recent", QT_TRANSLATE_NOOP("MainWindow", "Recent files"),
             parent="menu_file", after="action_open_folder"),
    MenuSpec("menu_edit", QT_TRANSLATE_NOOP("MainWindow", "&Edit")),
    MenuSpec("menu_view", QT_TRANSLATE_NOOP("MainWindow", "&View")),
    MenuSpec("menu_plc", QT_TRANSLATE_NOOP("MainWindow", "&PLC")),
    MenuSpec("menu_tools", QT_TRANSLATE_NOOP("MainWindow", "&Tools")),
    MenuSpec("menu_language", QT_TRANSLATE_NOOP("MainWindow", "&Language")),
    MenuSpec("menu_help", QT_TRANSLATE_NOOP("MainWindow", "&Help")),
)

TOOLBAR_TITLE = QT_TRANSLATE_NOOP("MainWindow", "Main toolbar")

A = ActionSpec
ACTIONS: tuple[ActionSpec, ...] = (
    A("action_new", QT_TRANSLATE_NOOP("MainWindow", "&New..."),
      "new_program_dialog", shortcut=Key.New, icon="SP_FileIcon", menu="menu_file", toolbar=0),
    A("action_open", QT_TRANSLATE_NOOP("MainWindow", "&Open..."),
      "open_dialog", shortcut=Key.Open, icon="SP_DialogOpenButton", menu="menu_file", toolbar=0),
    A("action_open_folder", QT_TRANSLATE_NOOP("MainWindow", "Open &folder..."),
      "open_folder_dialog", icon="SP_DirOpenIcon", menu="menu_file"),
    A("action_save", QT_TRANSLATE_NOOP("MainWindow", "&Save"),
      "save", shortcut=Key.Save, icon="SP_DialogSaveButton", menu="menu_file", group=1, toolbar=0),
    A("action_save_as", QT_TRANSLATE_NOOP("MainWindow", "Save &As..."),
      "save_as_dialog", shortcut=Key.SaveAs, menu="menu_file", group=1),
    A("action_import_mod", QT_TRANSLATE_NOOP("MainWindow", "&Import .MOD..."),
      "import_mod_dialog", menu="menu_file", group=2),
    A("action_export_mod", QT_TRANSLATE_NOOP("MainWindow", "&Export .MOD..."),
      "export_mod_dialog", menu="menu_file", group=2),
    A("action_import_symbols", QT_TRANSLATE_NOOP("MainWindow", "Import s&ymbols..."),
      "import_symbols_dialog", menu="menu_file", group=2),
    A("action_program_properties", QT_TRANSLATE_NOOP("MainWindow", "Program &properties..."),
      "show_program_properties", menu="menu_file", group=3),
    A("action_quit", QT_TRANSLATE_NOOP("MainWindow", "&Quit"),
      "close", shortcut=Key.Quit, menu="menu_file", group=4),
    A("action_clear_recent", QT_TRANSLATE_NOOP("MainWindow", "Clear the list"),
      "clear_recent"),
    A("action_undo", QT_TRANSLATE_NOOP("MainWindow", "&Undo"),
      "model.undo_stack.undo", shortcut=Key.Undo, icon="SP_ArrowBack", menu="menu_edit",
      toolbar=1, enabled_when=CAN_UNDO),
    A("action_redo", QT_TRANSLATE_NOOP("MainWindow", "&Redo"),
      "model.undo_stack.redo", shortcut=("Ctrl+Y", "Ctrl+Shift+Z", Key.Redo),
      icon="SP_ArrowForward", menu="menu_edit", toolbar=1, enabled_when=CAN_REDO),
    A("action_cut", QT_TRANSLATE_NOOP("MainWindow", "Cu&t"),
      "editor.edits.cut", shortcut=Key.Cut, menu="menu_edit", group=1, enabled_when=LADDER_SHOWN),
    A("action_copy", QT_TRANSLATE_NOOP("MainWindow", "&Copy"),
      "editor.edits.copy", shortcut=Key.Copy, menu="menu_edit", group=1, enabled_when=LADDER_SHOWN),
    A("action_paste", QT_TRANSLATE_NOOP("MainWindow", "&Paste"),
      "editor.edits.paste", shortcut=Key.Paste, menu="menu_edit", group=1,
      enabled_when=LADDER_SHOWN),
    A("action_delete", QT_TRANSLATE_NOOP("MainWindow", "&Delete"),
      "editor.edits.delete_at_cursor", shortcut="Del", menu="menu_edit", group=1,
      enabled_when=LADDER_SHOWN),
    A("action_edit_element", QT_TRANSLATE_NOOP("MainWindow", "&Edit element"),
      "editor.edit_at_cursor", menu="menu_edit", group=2, enabled_when=LADDER_SHOWN),
    A("action_invert", QT_TRANSLATE_NOOP("MainWindow", "NOT (invert)"),
      "editor.edits.invert_at_cursor", icon="invert", menu="menu_edit", group=2,
      enabled_when=LADDER_SHOWN),
    A("action_or", QT_TRANSLATE_NOOP("MainWindow", "OR (add parallel)"),
      "editor.edits.or_at_cursor", icon="or", menu="menu_edit", group=2, enabled_when=LADDER_SHOWN),
    A("action_output_pins", QT_TRANSLATE_NOOP("MainWindow", "Output pins (FO)…"),
      "editor.edits.output_pins_at_cursor", menu="menu_edit", group=2,
      enabled_when=LADDER_SHOWN),
    A("action_insert_row_before", QT_TRANSLATE_NOOP("MainWindow", "Insert row before"),
      "editor.edits.insert_row_before", icon="row_before", menu="menu_edit", group=2,
      enabled_when=LADDER_SHOWN),
    A("action_insert_row_after", QT_TRANSLATE_NOOP("MainWindow", "Insert row after"),
      "editor.edits.insert_row_after", icon="row_after", menu="menu_edit", group=2,
      enabled_when=LADDER_SHOWN),
    A("action_delete_network", QT_TRANSLATE_NOOP("MainWindow", "Delete network"),
      "editor.edits.delete_network", menu="menu_edit", group=2, enabled_when=LADDER_SHOWN),
    A("action_find", QT_TRANSLATE_NOOP("MainWindow", "&Find..."),
      "show_find", shortcut=Key.Find, menu="menu_edit", group=3, argument=False),
    A("action_replace", QT_TRANSLATE_NOOP("MainWindow", "R&eplace..."),
      "show_find", shortcut="Ctrl+H", menu="menu_edit", group=3, argument=True),
    A("action_find_next", QT_TRANSLATE_NOOP("MainWindow", "Find &next"),
      "find_again", shortcut=Key.FindNext, menu="menu_edit", group=3, argument=True),
    A("action_find_previous", QT_TRANSLATE_NOOP("MainWindow", "Find pre&vious"),
      "find_again", shortcut=Key.FindPrevious, menu="menu_edit", group=3, argument=False),
    A("action_zoom_in", QT_TRANSLATE_NOOP("MainWindow", "Zoom &in"),
      "editor.zoom_in", shortcut=Key.ZoomIn, icon="zoom_in", menu="menu_view", toolbar=2,
      enabled_when=LADDER_SHOWN),
    A("action_zoom_out", QT_TRANSLATE_NOOP("MainWindow", "Zoom &out"),
      "editor.zoom_out", shortcut=Key.ZoomOut, icon="zoom_out", menu="menu_view", toolbar=2,
      enabled_when=LADDER_SHOWN),
    A("action_zoom_reset", QT_TRANSLATE_NOOP("MainWindow", "&Normal size"),
      "editor.zoom_reset", shortcut="Ctrl+0", menu="menu_view", enabled_when=LADDER_SHOWN),
    A("action_zoom_fit_width", QT_TRANSLATE_NOOP("MainWindow", "Fit &width"),
      "fit_width.set_enabled", shortcut="Ctrl+9", icon="zoom_fit_width", menu="menu_view",
      toolbar=2, checkable=True, toggles=True, enabled_when=LADDER_SHOWN),
    A("action_show_ladder", QT_TRANSLATE_NOOP("MainWindow", "Show as &ladder"),
      "show_as_ladder", shortcut="F5", menu="menu_view", group=1),
    A("action_show_text", QT_TRANSLATE_NOOP("MainWindow", "Show as &text"),
      "show_as_text", shortcut="F6", menu="menu_view", group=1),
    A("action_check", QT_TRANSLATE_NOOP("MainWindow", "C&heck"),
      "check", shortcut="F7", menu="menu_plc"),
    A("action_compile", QT_TRANSLATE_NOOP("MainWindow", "&Compile"),
      "compile", shortcut="F9", icon="compile", menu="menu_plc", toolbar=3),
    A("action_language_en", "English",
      "set_language", menu="menu_language", checkable=True, exclusive=True,
      argument="en"),
    A("action_language_tr", "Türkçe",
      "set_language", menu="menu_language", checkable=True, exclusive=True,
      argument="tr"),
    A("action_instruction_help", QT_TRANSLATE_NOOP("MainWindow", "&Instruction reference"),
      "show_instruction_help", shortcut=Key.HelpContents, menu="menu_help"),
    A("action_about", QT_TRANSLATE_NOOP("MainWindow", "&About LadderWorks"),
      "about", menu="menu_help"),
)

# The grid's right-click menu (None: a separator); the PLC's on-line actions follow.
CONTEXT_MENU: tuple[str | None, ...] = (
    "action_cut", "action_copy", "action_paste", "action_delete", None,
    "action_invert", "action_or", "action_output_pins", None, "action_insert_row_before",
    "action_insert_row_after",
    None, "action_delete_network",
)
