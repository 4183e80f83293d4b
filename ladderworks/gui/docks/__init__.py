"""The PLC utility docks of the console, installed by one call: `install_plc_docks(window)`."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication, QEvent, QObject, Qt
from PySide6.QtWidgets import QDockWidget, QMainWindow, QToolBar

from ladderworks.core.il import Program
from ladderworks.gui.plc_session import PlcSession

if TYPE_CHECKING:
    from ladderworks.gui.docks.online import OnlineMode
    from ladderworks.gui.docks.plc_control import PlcControlDock


@dataclass(slots=True)
class PlcDocks:
    """Everything `install_plc_docks` put into the window."""

    session: PlcSession
    control: PlcControlDock
    diagnostic: QDockWidget
    force_list: QDockWidget
    online: OnlineMode | None  # on-line mode needs the console's editor
    others: dict[str, QDockWidget] = field(default_factory=dict)  # issue 8's docks by name
    time_travel: QObject | None = None  # PLC › Keep scan history (gui/docks/time_travel.py)


class _Retranslate(QObject):
    """Calls `retranslate()` of each target when the window's UI language changes."""

    def __init__(self, window: QMainWindow, targets: list[object]) -> None:
        super().__init__(window)
        self.targets = targets
        window.installEventFilter(self)

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Pass LanguageChange on."""
        if event.type() == QEvent.Type.LanguageChange:
            for target in self.targets:
                target.retranslate()  # type: ignore[attr-defined]
        return False


def install_plc_docks(window: QMainWindow, session: PlcSession | None = None) -> PlcDocks:
    """Create the PLC session and every PLC dock, with their PLC / View menu actions.

    The docks start hidden (View menu toggles); the PLC menu gets the control screen, the
    diagnostic, START / STOP, on-line mode and the Disable / Force actions."""
    from ladderworks.gui.docks import alarms, bit_display, tables, time_chart
    from ladderworks.gui.docks.diagnostic import DiagnosticDock
    from ladderworks.gui.docks.dock_menus import add_dock, find_menu, register_action
    from ladderworks.gui.docks.force_list import ForceListDock
    from ladderworks.gui.docks.online import ACTION_NAMES, OnlineMode
    from ladderworks.gui.docks.plc_control import PlcControlDock

    session = session if session is not None else PlcSession(window)
    editor = getattr(window, "editor", None)

    def console_program() -> Program | None:
        if editor is None:
            return None
        program, _diagnostics = editor.model.program()
        return program

    control = PlcControlDock(session, window, console_program)
    diagnostic = DiagnosticDock(session, window)
    force_list = ForceListDock(session, window)
    for dock, toggle, area in (
            (control, "action_dock_plc_control", Qt.DockWidgetArea.RightDockWidgetArea),
            (diagnostic, "action_dock_plc_diagnostic", Qt.DockWidgetArea.RightDockWidgetArea),
            (force_list, "action_dock_force_list", Qt.DockWidgetArea.BottomDockWidgetArea)):
        add_dock(window, dock, toggle, area)
        dock.hide()
    window.tabifyDockWidget(control, diagnostic)
    online = OnlineMode(editor, session, window) if editor is not None else None
    retranslated: list[object] = [control, diagnostic, force_list]
    retranslated += [online] if online is not None else []
    _Retranslate(window, retranslated)  # the same list: time travel joins it below
    plc_menu = find_menu(window, "menu_plc")
    actions = [control.control_actions[name]
               for name in ("action_plc_control_compile", "action_plc_start", "action_plc_stop")]
    for action in actions:
        register_action(window, action)
    if online is not None:
        for name in ACTION_NAMES:
            register_action(window, online.actions[name])
    toolbar = window.findChild(QToolBar, "toolbar_main")
    if toolbar is not None:  # one path (issue 18): START / STOP next to Compile
        toolbar.addActions(actions[1:])
    if plc_menu is not None:
        plc_menu.addSeparator()
        plc_menu.addAction(control.toggleViewAction())
        plc_menu.addAction(diagnostic.toggleViewAction())
        plc_menu.addAction(force_list.toggleViewAction())
        plc_menu.addSeparator()
        for action in actions[1:]:
            plc_menu.addAction(action)
        if online is not None:
            plc_menu.addSeparator()
            for name in ACTION_NAMES:
                plc_menu.addAction(online.actions[name])
    others: dict[str, QDockWidget] = {}
    for name, module in (("bit_display", bit_display), ("time_chart", time_chart),
                         ("alarms", alarms), ("tables", tables)):
        others[name] = module.install(window, session)
    from ladderworks.gui.docks import scenario  # after the time chart: it shows its runs there

    others["scenario"] = scenario.install(window, session)
    from ladderworks.gui.docks import time_travel  # the chart's cursor shows past scans

    chart = others["time_chart"]
    travel = time_travel.install(
        window, session, diagnostic, chart if isinstance(chart, time_chart.TimeChartDock) else None,
        online)
    retranslated.append(travel)
    app = QCoreApplication.instance()
    if app is not None:
        app.aboutToQuit.connect(session.stop)  # the scan thread ends with the program
    return PlcDocks(session, control, diagnostic, force_list, online, others, travel)
