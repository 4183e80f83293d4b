"""The console's menus, main toolbar and actions by name, built from gui/actions_table.py."""

from __future__ import annotations

from collections.abc import Callable
from operator import attrgetter

import shiboken6
from PySide6.QtCore import QCoreApplication, QObject, Qt, SignalInstance
from PySide6.QtGui import QAction, QActionGroup, QIcon, QKeySequence
from PySide6.QtWidgets import QDockWidget, QMainWindow, QMenu, QStyle, QToolBar

from ladderworks.gui.actions_table import (
    ACTIONS,
    MENUS,
    TOOLBAR_TITLE,
    ActionSpec,
    MenuSpec,
    Shortcut,
)
from ladderworks.gui.editor.interactions import BY_TOOL, INTERACTIONS
from ladderworks.gui.tools import Tool, icon

translate = QCoreApplication.translate

# A condition of `ActionSpec.enabled_when`: the signals that may change it, and its test. A
# signal whose first argument is a bool carries the new state itself (QUndoStack.canUndoChanged
# also fires while the stack is being deleted, when its test could no longer run).
Condition = tuple[list[SignalInstance], Callable[[], bool]]


def _key_sequences(shortcut: Shortcut) -> list[QKeySequence]:
    """A spec's keys, a standard key as the platform binds it; each once, in order."""
    given = shortcut if isinstance(shortcut, tuple) else (shortcut,)
    keys: list[QKeySequence] = []
    for key in given:
        if key is None:
            continue
        found = (QKeySequence.keyBindings(key) if isinstance(key, QKeySequence.StandardKey)
                 else [QKeySequence(key)])
        keys += [sequence for sequence in found if sequence not in keys]
    return keys


class ConsoleMenus(QObject):
    """Every QAction of the window by objectName, its menus and main toolbar.

    The window's own actions come from the table; the tool actions from the interactions
    (gui/editor/interactions.py); the docks add theirs with `add`, `add_dock`, `add_toggle`,
    `add_menu` and `insert_before`, so each is in `actions_by_name` and the menus without
    anyone searching the widget tree."""

    def __init__(self, window: QMainWindow, conditions: dict[str, Condition],
                 specs: tuple[ActionSpec, ...] = ACTIONS,
                 menus: tuple[MenuSpec, ...] = MENUS) -> None:
        super().__init__(window)
        self.window = window
        self.specs = specs
        self.menu_specs = menus
        self.actions_by_name: dict[str, QAction] = {}
        self.menus: dict[str, QMenu] = {}
        self.toolbar = QToolBar(window)
        self.toolbar.setObjectName("toolbar_main")
        self.tool_actions: dict[Tool, QAction] = {}
        self.tool_group = QActionGroup(self)
        self._conditions = conditions
        for spec in specs:
            self._make(spec)
        for name, (signals, _test) in conditions.items():
            for signal in signals:  # each signal re-tests only its own condition
                signal.connect(lambda *args, n=name: self._changed(n, args))
        for interaction in INTERACTIONS:  # the palette's and the Tools menu's order
            tool = interaction.tool
            action = QAction(interaction.icon(), "", window)
            action.setObjectName(f"tool_{tool.value}")
            action.setCheckable(True)
            self.tool_group.addAction(action)
            self.tool_actions[tool] = action
            self.register(action)
        self._make_menus()
        self._fill_toolbar()
        window.addToolBar(Qt.ToolBarArea.TopToolBarArea, self.toolbar)
        self.add_toggle(self.toolbar.toggleViewAction(), "action_toolbar_main", "menu_view")
        self.update_enabled()

    # -- building ------------------------------------------------------------------------

    def _make(self, spec: ActionSpec) -> QAction:
        action = QAction(self.window)
        action.setObjectName(spec.name)
        if spec.shortcut is not None:
            action.setShortcuts(_key_sequences(spec.shortcut))
        if spec.icon is not None:
            action.setIcon(self._icon(spec.icon))
        action.setCheckable(spec.checkable)
        slot = attrgetter(spec.slot)(self.window)  # a wrong name fails here, at start
        if not callable(slot):
            raise TypeError(f"{spec.name}: {spec.slot} is not callable")
        argument = spec.argument
        if spec.toggles:
            action.toggled.connect(slot)
        elif argument is None:
            action.triggered.connect(lambda _checked=False, s=slot: s())
        else:
            action.triggered.connect(lambda _checked=False, s=slot, a=argument: s(a))
        self.register(action)
        return action

    def _icon(self, name: str) -> QIcon:
        if name.startswith("SP_"):
            pixmap = getattr(QStyle.StandardPixmap, name)
            return self.window.style().standardIcon(pixmap)
        return icon(name)

    def _make_menus(self) -> None:
        bar = self.window.menuBar()
        for menu_spec in self.menu_specs:
            if menu_spec.parent is None:
                menu = bar.addMenu("")
            else:
                menu = QMenu(self.menus[menu_spec.parent])
            menu.setObjectName(menu_spec.name)
            self.menus[menu_spec.name] = menu
            groups = [spec for spec in self.specs if spec.menu == menu_spec.name]
            exclusive = QActionGroup(menu) if any(s.exclusive for s in groups) else None
            previous: int | None = None
            for spec in groups:
                if previous is not None and spec.group != previous:
                    menu.addSeparator()
                previous = spec.group
                action = self.actions_by_name[spec.name]
                menu.addAction(action)
                if exclusive is not None and spec.exclusive:
                    exclusive.addAction(action)
            if menu_spec.parent is not None:
                self.insert_before(menu_spec.parent, menu.menuAction(), None,
                                   after=menu_spec.after)
        self.add_many("menu_tools", list(self.tool_actions.values()))

    def _fill_toolbar(self) -> None:
        previous: int | None = None
        for spec in self.specs:
            if spec.toolbar is None:
                continue
            if previous is not None and spec.toolbar != previous:
                self.toolbar.addSeparator()
            previous = spec.toolbar
            self.toolbar.addAction(self.actions_by_name[spec.name])

    # -- what the docks use --------------------------------------------------------------

    def register(self, action: QAction) -> None:
        """Make `action` findable by its objectName in `actions_by_name`."""
        self.actions_by_name[action.objectName()] = action

    def add(self, menu: str, action: QAction, *, separator: bool = False,
            toolbar: bool = False) -> None:
        """Put `action` at the end of `menu` (after a separator), and on the main toolbar."""
        self.register(action)
        if separator:
            self.menus[menu].addSeparator()
        self.menus[menu].addAction(action)
        if toolbar:
            self.toolbar.addAction(action)

    def add_menu(self, menu: str, submenu: QMenu) -> None:
        """Put `submenu` at the end of `menu`, between separators (its objectName is its key)."""
        self.menus[menu].addSeparator()
        self.menus[menu].addMenu(submenu)
        self.menus[submenu.objectName()] = submenu

    def add_many(self, menu: str, actions: list[QAction], *, separator: bool = False) -> None:
        """Put `actions` at the end of `menu`, after a separator when asked."""
        for index, action in enumerate(actions):
            self.add(menu, action, separator=separator and index == 0)

    def add_toggle(self, toggle: QAction, name: str, menu: str = "menu_view", *,
                   separator: bool = False) -> QAction:
        """A dock's (or toolbar's) show/hide action, named `name`, at the end of `menu`."""
        toggle.setObjectName(name)
        self.add(menu, toggle, separator=separator)
        return toggle

    def add_dock(self, dock: QDockWidget, toggle_name: str, area: Qt.DockWidgetArea,
                 menu: str = "menu_view", *, separator: bool = False) -> QAction:
        """Dock `dock` in the window's `area`; its toggle (in `menu`) is named `toggle_name`."""
        self.window.addDockWidget(area, dock)
        return self.add_toggle(dock.toggleViewAction(), toggle_name, menu, separator=separator)

    def insert_before(self, menu: str, action: QAction, before: str | None, *,
                      after: str | None = None) -> None:
        """Put `action` in `menu` before the action named `before` (or right after the one
        named `after`); at the end when there is none."""
        self.register(action)
        target = self.menus[menu]
        existing = target.actions()
        for index, item in enumerate(existing):
            if before is not None and item.objectName() == before:
                target.insertAction(item, action)
                return
            if after is not None and item.objectName() == after:
                if index + 1 < len(existing):
                    target.insertAction(existing[index + 1], action)
                else:
                    target.addAction(action)
                return
        target.addAction(action)

    # -- state and language --------------------------------------------------------------

    def update_enabled(self) -> None:
        """Enable each conditional action as its condition says now."""
        for name, (_signals, test) in self._conditions.items():
            self._set_enabled(name, test())

    def _changed(self, condition: str, args: tuple[object, ...]) -> None:
        if args and isinstance(args[0], bool):
            self._set_enabled(condition, args[0])
        else:
            self._set_enabled(condition, self._conditions[condition][1]())

    def _set_enabled(self, condition: str, on: bool) -> None:
        for spec in self.specs:
            action = self.actions_by_name[spec.name]
            if spec.enabled_when == condition and shiboken6.isValid(action):  # not while closing
                action.setEnabled(on)

    def retranslate(self) -> None:
        """Set the table's and the tools' texts in the current UI language."""
        for spec in self.specs:
            self.actions_by_name[spec.name].setText(translate("MainWindow", spec.text))
        for menu_spec in self.menu_specs:
            self.menus[menu_spec.name].setTitle(translate("MainWindow", menu_spec.title))
        self.toolbar.setWindowTitle(translate("MainWindow", TOOLBAR_TITLE))
        for tool, action in self.tool_actions.items():
            # the key shows in the menu's shortcut column (it works while the grid has focus)
            kind = BY_TOOL[tool]
            action.setText(f"{kind.name()}\t{kind.key}")
            action.setIconText(kind.name())
            action.setToolTip(f"{kind.name()} ({kind.key}): {kind.help()}")
            action.setStatusTip(kind.help())
