"""On-line mode: the console's own ladder shows the running PLC; disable and force elements."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QObject
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QWidget

from ladderworks.core.address import Address
from ladderworks.core.compiler.binary import BinaryProgram
from ladderworks.core.ladder.model import Cell, Coil, Contact, FunctionBox
from ladderworks.core.ladder.source_model import source_model
from ladderworks.gui.docks.cell_map import program_matches
from ladderworks.gui.docks.live_ladder import LivePower, match_networks
from ladderworks.gui.docks.snapshot_gate import SnapshotGate
from ladderworks.gui.editor.view import LadderEditor
from ladderworks.gui.plc_session import PlcSession, PlcSnapshot

translate = QCoreApplication.translate

ACTION_NAMES = ("action_plc_online", "action_plc_disable", "action_plc_enable",
                "action_plc_force_1", "action_plc_force_0", "action_plc_release")


class OnlineMode(QObject):
    """Ties the console editor to the session: power flow over the drawing while on-line;
    any edit takes the view off-line (the drawing no longer is what the PLC runs)."""

    def __init__(self, editor: LadderEditor, session: PlcSession,
                 parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.editor = editor
        self.session = session
        self.live = LivePower(editor.scene())
        self.actions: dict[str, QAction] = {}
        owner = parent if isinstance(parent, QWidget) else editor
        for name in ACTION_NAMES:
            action = QAction(owner)
            action.setObjectName(name)
            self.actions[name] = action
        self.actions["action_plc_online"].setCheckable(True)
        self.actions["action_plc_online"].toggled.connect(self.set_online)
        self.actions["action_plc_disable"].triggered.connect(lambda: self.disable_selected())
        self.actions["action_plc_enable"].triggered.connect(lambda: self.enable_selected())
        self.actions["action_plc_force_1"].triggered.connect(lambda: self.force_selected(1))
        self.actions["action_plc_force_0"].triggered.connect(lambda: self.force_selected(0))
        self.actions["action_plc_release"].triggered.connect(lambda: self.release_selected())
        editor.context_actions.append(None)
        editor.context_actions.extend(self.actions[n] for n in ACTION_NAMES[1:])
        editor.model.undo_stack.indexChanged.connect(self._edited)
        editor.model.document_reset.connect(self._another_program)  # open, new: off-line
        self.past: PlcSnapshot | None = None  # time travel: an earlier scan shown instead
        self.gate = SnapshotGate(editor, self._update, session)  # shown, in budget
        session.snapshot_ready.connect(self._on_snapshot)
        session.program_loaded.connect(self._on_program)
        session.forces_changed.connect(lambda _entries: self.refresh())
        editor.verticalScrollBar().valueChanged.connect(lambda _v: self.refresh())
        editor.relaid_out.connect(lambda: self.live.restack(editor.layout_))  # rows' heights
        self._update_actions()
        self.retranslate()

    def retranslate(self) -> None:
        """Texts in the UI language."""
        texts = {
            "action_plc_online": translate("PlcOnline", "On-line mode"),
            "action_plc_disable": translate("PlcOnline", "Make passive (disable)"),
            "action_plc_enable": translate("PlcOnline", "Make active again"),
            "action_plc_force_1": translate("PlcOnline", "Force to 1"),
            "action_plc_force_0": translate("PlcOnline", "Force to 0"),
            "action_plc_release": translate("PlcOnline", "Release the force"),
        }
        for name, text in texts.items():
            self.actions[name].setText(text)

    @property
    def online(self) -> bool:
        """True while the editor shows the running PLC."""
        return self.live.attached

    def _say(self, text: str) -> None:
        self.editor.message.emit(text)

    def set_online(self, on: bool) -> bool:
        """Go on-line (when the drawing is exactly the loaded program) or off-line."""
        if not on:
            if self.live.attached:
                self.live.detach()
                self.session.run.monitor(False)
                self._say(translate("PlcOnline", "Off-line"))
            self._sync_check(False)
            return False
        binary = self.session.run.binary
        if binary is None:
            self._say(translate("PlcOnline", "On-line needs a compiled program in the PLC"))
            self._sync_check(False)
            return False
        ops = self._model_ops(binary) if source_model(self.editor.model.document.origin) \
            else match_networks(self.editor.model.networks, binary)
        if ops is None:
            self._say(translate("PlcOnline", "The drawing is not the program in the PLC: "
                                "compile it in the PLC control screen first"))
            self._sync_check(False)
            return False
        if not self.live.attached:
            self.session.run.monitor(True)
        self.live.attach(self.editor.model.networks, self.editor.layout_, binary, ops,
                         self.editor.model.symbols, self.editor.model.dialect)
        self._sync_check(True)
        self.refresh()
        self._say(translate("PlcOnline", "On-line: the drawing shows the running PLC"))
        return True

    def _model_ops(self, binary: BinaryProgram) -> list[list[int]] | None:
        """A drawing of a dialect's own model (S7): the ops of each drawn network, by the
        program's networks it was lowered to; None when the drawing is not the PLC's program."""
        program, _found = self.editor.model.program()
        model = source_model(program)
        if program is None or model is None or not program_matches(program, binary):
            return None
        return match_networks(self.editor.model.networks, binary, model.spans())

    def _sync_check(self, on: bool) -> None:
        action = self.actions["action_plc_online"]
        if action.isChecked() != on:
            action.blockSignals(True)
            action.setChecked(on)
            action.blockSignals(False)
        self._update_actions()

    def _update_actions(self) -> None:
        for name in ACTION_NAMES[1:]:
            self.actions[name].setEnabled(self.online)

    def _edited(self, _index: int) -> None:
        if self.online:
            self.set_online(False)
            self._say(translate("PlcOnline", "Off-line: the drawing was changed; it is no "
                                "longer the program the PLC runs"))

    def _another_program(self) -> None:
        """Another program is shown (File › Open, New): the last one's power flow, values and
        force marks leave the drawing with it."""
        if self.online:
            self.past = None
            self.set_online(False)
            self._say(translate("PlcOnline", "Off-line: another program is shown; it is not "
                                "the program the PLC runs"))

    def _on_program(self, _binary: BinaryProgram) -> None:
        if self.online:
            self.set_online(True)

    def _on_snapshot(self, snapshot: PlcSnapshot) -> None:
        if self.online and self.past is None:
            self.gate.offer(snapshot)

    def refresh(self) -> None:
        """Repaint the power flow now."""
        if self.online:
            self._update(self.past or self.session.run.snapshot())

    def show_past(self, snapshot: PlcSnapshot) -> None:
        """Time travel: show an earlier scan's power flow, marked as the past."""
        self.past = snapshot
        self.refresh()
        if self.online:
            self._say(translate("PlcDiagnostic", "PAST — scan {0} at {1} ms (not live)").format(
                snapshot.scan_count, snapshot.now_ms))

    def back_to_live(self) -> None:
        """Show the running PLC again."""
        if self.past is not None:
            self.past = None
            self.refresh()
            if self.online:
                self._say(translate("PlcOnline", "On-line: the drawing shows the running PLC"))

    def _update(self, snapshot: PlcSnapshot) -> None:
        forced = (self.session.run.engine.force_table.forced()
                  if self.session.run.engine is not None else {})
        visible = self.editor.mapToScene(self.editor.viewport().rect()).boundingRect()
        self.live.update(snapshot, forced, visible)

    # -- the selected element ------------------------------------------------------------

    def selected(self) -> tuple[int, Cell, object] | None:
        """(network, anchor cell, element) under the editor's cursor."""
        index, row, col = self.editor.cursor_cell
        if not 0 <= index < len(self.editor.model.networks):
            return None
        found = self.editor.model.networks[index].element_at(row, col)
        if found is None:
            return None
        return index, found[0], found[1]

    def _selected_op(self) -> int | None:
        chosen = self.selected() if self.online else None
        if chosen is None:
            self._say(translate("PlcOnline", "Select a contact, coil or function first"))
            return None
        op = self.live.op_at(chosen[0], chosen[1])
        if op is None:
            self._say(translate("PlcOnline", "This element has no op in the PLC program"))
        return op

    def disable_selected(self) -> int | None:
        """Make the selected element passive (PASİF): it no longer acts."""
        op = self._selected_op()
        if op is not None:
            self.session.disable(op)
        return op

    def enable_selected(self) -> int | None:
        """Make the selected passive element act again."""
        op = self._selected_op()
        if op is not None:
            self.session.enable(op)
        return op

    def _selected_address(self) -> Address | None:
        chosen = self.selected() if self.online else None
        element = chosen[2] if chosen is not None else None
        if isinstance(element, Contact | Coil) and element.address is not None:
            return element.address
        if isinstance(element, FunctionBox) or chosen is None or element is None:
            self._say(translate("PlcOnline", "Select a contact or coil to force its signal"))
        return None

    def force_selected(self, value: int) -> Address | None:
        """Force the selected contact's or coil's signal to 0 or 1."""
        address = self._selected_address()
        if address is not None:
            self.session.force(address, value)
        return address

    def release_selected(self) -> Address | None:
        """Release the force on the selected element's signal."""
        address = self._selected_address()
        if address is not None:
            self.session.release(address)
        return address
