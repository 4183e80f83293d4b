"""The PLC docks of the console, each built with what it needs: session, editor, menus."""

from __future__ import annotations

from dataclasses import dataclass

from PySide6.QtCore import QCoreApplication, Qt, QTimer
from PySide6.QtWidgets import QDockWidget, QMainWindow, QToolButton

from ladderworks.core.il import Program
from ladderworks.gui.console_menus import ConsoleMenus
from ladderworks.gui.dock_tabs import WholeDockTitles
from ladderworks.gui.docks.alarms import AlarmDock
from ladderworks.gui.docks.ascii_output import AsciiOutputDock
from ladderworks.gui.docks.bit_display import BitDisplayDock
from ladderworks.gui.docks.diagnostic import DiagnosticDock
from ladderworks.gui.docks.force_list import ForceListDock
from ladderworks.gui.docks.modbus import ModbusDock
from ladderworks.gui.docks.online import ACTION_NAMES, OnlineMode
from ladderworks.gui.docks.plc_control import PlcControlDock
from ladderworks.gui.docks.scenario import RECORD, RUN, ScenarioDock
from ladderworks.gui.docks.tables import PlcTablesDock
from ladderworks.gui.docks.time_chart import TimeChartDock
from ladderworks.gui.docks.time_travel import TimeTravel
from ladderworks.gui.docks.watch_table import WatchTableDock
from ladderworks.gui.editor.view import LadderEditor
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.plc_state import PlcStateLabel

RIGHT = Qt.DockWidgetArea.RightDockWidgetArea
BOTTOM = Qt.DockWidgetArea.BottomDockWidgetArea
LEFT = Qt.DockWidgetArea.LeftDockWidgetArea


@dataclass(slots=True)
class PlcDocks:
    """The PLC session and everything `build_plc_docks` put into the window."""

    session: PlcSession
    control: PlcControlDock
    diagnostic: DiagnosticDock
    force_list: ForceListDock
    online: OnlineMode
    bit_display: BitDisplayDock
    time_chart: TimeChartDock
    alarms: AlarmDock
    tables: PlcTablesDock
    scenario: ScenarioDock
    time_travel: TimeTravel  # PLC › Keep scan history
    modbus: ModbusDock  # PLC › Modbus server
    ascii_output: AsciiOutputDock  # PLC › ASCII output (a Fatek program's FUN 94)
    watch: WatchTableDock  # PLC › Watch table (TIA's), on the main toolbar
    # STOP / RUN, the program, forcing: in the status bar and on the main toolbar
    states: tuple[PlcStateLabel, ...] = ()

    @property
    def others(self) -> dict[str, QDockWidget]:
        """Issue 8's docks by name (bit_display, time_chart, alarms, tables, scenario)."""
        return {"bit_display": self.bit_display, "time_chart": self.time_chart,
                "alarms": self.alarms, "tables": self.tables, "scenario": self.scenario}

    def retranslate(self) -> None:
        """The helpers that are not widgets (the docks retranslate themselves)."""
        self.online.retranslate()
        self.time_travel.retranslate()


def _tab(window: QMainWindow, docks: list[QDockWidget]) -> None:
    """Put `docks` in one tab group (small screens: one dock's room for several)."""
    for dock in docks[1:]:
        window.tabifyDockWidget(docks[0], dock)


# a window at most this high (a 1024×600 panel, maximised) is a small screen: the error list
# joins the bottom PLC docks' tab group when one is opened
SMALL_HEIGHT = 720
TOOLS_MARGIN = 28  # px beside the widest tool button: the palette's margins and scroll bar
RIGHT_SHARE = 45  # % of the window's width a right-hand PLC dock takes at most
RIGHT_SHARE_SMALL = 33  # on a small screen (the ladder: ~500 of 1024 px, was 381)


def _share_the_bottom(window: QMainWindow, dock: QDockWidget) -> None:
    """On a small screen, a bottom PLC dock opened takes the error list into its tab group:
    side by side, the list (a real program's 1,333 warnings) took half the bottom row and
    left the ladder a 310×210 corner; as a tab it is one click away, and the whole row's
    width lets the dock's buttons fit on one line."""
    errors = window.findChild(QDockWidget, "dock_errors")
    if (window.height() > SMALL_HEIGHT or errors is None or errors is dock
            or errors.isFloating() or window.dockWidgetArea(errors) != BOTTOM
            or errors in window.tabifiedDockWidgets(dock)):
        return
    window.tabifyDockWidget(dock, errors)


def _narrow_the_tools(window: QMainWindow) -> None:
    """On a small screen, a right-hand PLC dock opened narrows the tool palette's group to its
    widest tool's name (the palette's 230 px leave the ladder 310 px of a 1024-px screen)."""
    palette = window.findChild(QDockWidget, "dock_palette")
    if (palette is None or palette.isFloating() or not palette.isVisible()
            or window.dockWidgetArea(palette) != LEFT):
        return
    widest = max((button.sizeHint().width() for button in palette.findChildren(QToolButton)),
                 default=0)
    if widest and palette.width() > widest + TOOLS_MARGIN:
        def narrow() -> None:
            window.resizeDocks([palette], [widest + TOOLS_MARGIN], Qt.Orientation.Horizontal)
            for titles in window.findChildren(WholeDockTitles):  # its tabs stay whole
                titles.check_soon()

        QTimer.singleShot(0, narrow)


def _raise_when_shown(window: QMainWindow, dock: QDockWidget) -> None:
    """Its toggle brings a tabbed dock to the front, not only back into its group, and gives
    it a fair share of the window: a bottom dock at least a third of the height (a large
    screen has room for a readable chart), a right-hand dock at most 45 % of the width (the
    ladder keeps the rest; a third on a small screen). A dock's minimum size still wins on a
    small screen."""

    def shown(checked: bool) -> None:
        if not checked:
            return
        area = window.dockWidgetArea(dock)
        if area == BOTTOM:
            _share_the_bottom(window, dock)
        elif area == RIGHT and window.height() <= SMALL_HEIGHT:
            _narrow_the_tools(window)
        dock.raise_()
        third = window.height() // 3
        small = window.height() <= SMALL_HEIGHT
        # a small screen's right-hand dock takes a third: the ladder keeps its coils in view
        widest = window.width() * (RIGHT_SHARE_SMALL if small else RIGHT_SHARE) // 100
        if area == BOTTOM and window.height() <= SMALL_HEIGHT:
            # a third, not more: the ladder keeps the rest (once the tab group is laid out)
            QTimer.singleShot(0, lambda: window.resizeDocks([dock], [third],
                                                            Qt.Orientation.Vertical))
        elif area == BOTTOM and dock.height() < third:
            window.resizeDocks([dock], [third], Qt.Orientation.Vertical)
        elif area == RIGHT and dock.width() > widest:
            window.resizeDocks([dock], [widest], Qt.Orientation.Horizontal)
        elif area == RIGHT and dock.width() < window.width() // 3:  # a large screen's room
            window.resizeDocks([dock], [window.width() // 3], Qt.Orientation.Horizontal)

    dock.toggleViewAction().triggered.connect(shown)


def build_plc_docks(window: QMainWindow, menus: ConsoleMenus, session: PlcSession,
                    editor: LadderEditor) -> PlcDocks:
    """Create every PLC dock over `session`, with its View toggle and PLC / File actions.

    The docks start hidden except the alarm panel. The right-hand docks share one tab group,
    and the run-time docks at the bottom share the alarm panel's, so a 1024×600 screen holds
    them; a user can drag them apart on a large one."""

    def console_program() -> Program | None:
        program, _diagnostics = editor.model.program()
        return program

    control = PlcControlDock(session, window, console_program)
    diagnostic = DiagnosticDock(session, window)
    bits = BitDisplayDock(session, window)
    tables = PlcTablesDock(session, window)
    alarms = AlarmDock(session, window)
    chart = TimeChartDock(session, window)
    scenario = ScenarioDock(session, window, chart)
    force_list = ForceListDock(session, window)
    online = OnlineMode(editor, session, window)
    travel = TimeTravel(session, diagnostic, chart, online, window)
    modbus = ModbusDock(session, window)
    ascii_output = AsciiOutputDock(session, window)
    watch = WatchTableDock(session, window)

    plc = "menu_plc"
    menus.add_dock(control, "action_dock_plc_control", RIGHT, plc, separator=True)
    menus.add_dock(diagnostic, "action_dock_plc_diagnostic", RIGHT, plc)
    menus.add_dock(force_list, "action_dock_force_list", BOTTOM, plc)
    menus.add_dock(bits, "action_dock_bit_display", RIGHT)
    menus.add_dock(chart, "action_dock_time_chart", BOTTOM)
    menus.add_dock(alarms, "action_dock_alarms", BOTTOM)
    menus.add_dock(tables, "action_dock_plc_tables", RIGHT)
    menus.add_dock(scenario, "action_dock_scenario", BOTTOM)
    menus.add_dock(ascii_output, "action_dock_ascii_output", BOTTOM, plc)
    menus.add_dock(watch, "action_dock_watch_table", BOTTOM, plc)
    # tabbed while hidden: a tab group of shown docks sizes the window's first layout by
    # all of them, and leaves a tab bar behind with their titles
    for dock in (control, diagnostic, bits, tables, alarms, chart, scenario, force_list,
                 ascii_output, watch):
        dock.hide()
        _raise_when_shown(window, dock)
    _tab(window, [control, diagnostic, bits, tables])
    _tab(window, [alarms, chart, scenario, force_list, ascii_output, watch])
    alarms.show()

    # one path (issue 18): Compile, START and STOP on the main toolbar and in the PLC menu
    run = [control.control_actions[name] for name in ("action_plc_start", "action_plc_stop")]
    menus.register(control.control_actions["action_plc_control_compile"])
    menus.add(plc, run[0], separator=True, toolbar=True)
    menus.add(plc, run[1], toolbar=True)
    states = (PlcStateLabel(session, lambda: control.loaded_name, window),
              PlcStateLabel(session, lambda: control.loaded_name, window))
    states[0].setObjectName("toolbar_plc_state")
    menus.toolbar.addWidget(states[0])  # beside START / STOP
    menus.toolbar.addAction(watch.toggleViewAction())  # after the PLC's state
    states[1].setObjectName("status_plc_state")
    window.statusBar().addPermanentWidget(states[1])
    menus.add_many(plc, [online.actions[name] for name in ACTION_NAMES], separator=True)
    menus.insert_before("menu_file", alarms.file_action, "action_quit")
    menus.add(plc, alarms.reset_action)
    for name in (RUN, RECORD):
        action = scenario.actions_by_name[name]
        action.triggered.connect(scenario.show)
        action.triggered.connect(scenario.raise_)
        menus.add(plc, action)
    menus.add(plc, travel.action)
    menus.add_dock(modbus, "action_dock_modbus", RIGHT, plc, separator=True)
    modbus.hide()
    _raise_when_shown(window, modbus)
    window.tabifyDockWidget(control, modbus)
    app = QCoreApplication.instance()
    if app is not None:
        app.aboutToQuit.connect(modbus.stop_server)  # the server thread ends with the program
        app.aboutToQuit.connect(session.close)  # the scan process ends with the program
    return PlcDocks(session, control, diagnostic, force_list, online, bits, chart, alarms,
                    tables, scenario, travel, modbus, ascii_output, watch, states)
