"""The main window's File glue: open, save, save as, questions, autosave and recovery."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import asdict
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication, QDateTime, QLocale, Qt
from PySide6.QtWidgets import QMessageBox

from ladderworks.core import dialects
from ladderworks.core.diagnostics import Diagnostic, DiagnosticError, has_errors
from ladderworks.core.dialects.delta.dvp_program import save_refused
from ladderworks.core.dialects.fatek.pdw_file import is_pdw_path
from ladderworks.core.families import new_program
from ladderworks.core.il import Program, print_program
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.il.textform import EncodeError
from ladderworks.core.plc.parameters import format_parameters, parameters_beside
from ladderworks.core.plc.timer_table import dialect_of
from ladderworks.gui import file_dialogs, folder_program, questions, save_refusal
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.document import (
    DiskState,
    ProgramDocument,
    bad_bytes_back,
    bad_bytes_shown,
    same_file,
    view_text,
)
from ladderworks.gui.editor.ladder_model import LadderModel, Mode
from ladderworks.gui.files import ReadOnlyFile, atomic_write_bytes, is_read_only
from ladderworks.gui.new_program import (
    NewProgramDialog,
    family_change,
    remember_model,
    remembered_model,
    save_filters,
)
from ladderworks.gui.os_errors import os_error_text
from ladderworks.gui.recovery import Autosaver, RecoveredCopy, RecoveryStore, Snapshot

if TYPE_CHECKING:
    from PySide6.QtCore import SignalInstance
    from PySide6.QtWidgets import QMainWindow

    from ladderworks.gui.editor.view import LadderEditor
    from ladderworks.gui.error_list import ErrorListDock
    from ladderworks.gui.parameter_document import ParameterDocument
    from ladderworks.gui.settings import Settings
    from ladderworks.gui.text_view import ProgramTextView

    _Window = QMainWindow
else:
    _Window = object

translate = QCoreApplication.translate


def _when(copy: RecoveredCopy) -> str:
    """When a recovery copy was written, in the UI language's short date and time."""
    moment = QDateTime.fromSecsSinceEpoch(int(copy.saved_at.timestamp()))
    return QLocale().toString(moment, QLocale.FormatType.ShortFormat)


class FileActions(_Window):
    """File > New / Open / Save / Save As / Import / Export, and recovery: MainWindow's part
    that asks the ProgramDocument to read and write (a mixin, so the public names stay)."""

    document: ProgramDocument
    recovery: RecoveryStore
    autosaver: Autosaver
    _last_save_result: bool
    save_as_offered: bool  # inside the Save As a refused Save offered (save_refusal.py)
    pending_companions: dict[Path, bytes] = {}
    if TYPE_CHECKING:  # what MainWindow provides
        editor: LadderEditor
        text_view: ProgramTextView
        model: LadderModel
        errors: ErrorListDock
        parameters: ParameterDocument
        failed_path: Path | None
        dialect: str
        file_saved: SignalInstance
        settings: Settings

        def warn(self, title: str, text: str) -> None: ...
        def show_message(self, text: str) -> None: ...
        def update_title(self, *_args: object) -> None: ...
        def remember_file(self, path: Path) -> None: ...
        def program_shown(self, program: Program) -> None: ...

    def _install_file_state(self) -> None:
        """Create the document, its watcher and the autosaver (called once by __init__)."""
        self.document = ProgramDocument(self.model, self.text_view.document(), self.parameters,
                                        self)
        self.document.modified_changed.connect(self.update_title)
        self.document.changed_outside.connect(self._on_changed_outside)
        self._last_save_result = False
        self.save_as_offered = False
        self.recovery = RecoveryStore()
        self.autosaver = Autosaver(self.recovery, self.recovery_snapshot, self)
        self.autosaver.failed.connect(self.show_message)
        self.model.undo_stack.indexChanged.connect(self.autosaver.edited)
        self.parameters.session.parameters_changed.connect(self.autosaver.edited)

    # -- state ---------------------------------------------------------------------------

    @property
    def path(self) -> Path | None:
        """The program's file (None: untitled)."""
        return self.document.path

    @property
    def encoding(self) -> str:
        """The encoding the program is saved in."""
        return self.document.form.encoding

    def is_modified(self) -> bool:
        """True when there are unsaved changes."""
        return self.document.is_modified()

    def _on_changed_outside(self, name: str) -> None:
        self.show_message(translate(
            "MainWindow", "{0} was changed by another program").format(Path(name).name))

    def maybe_save(self) -> bool:
        """Ask to save unsaved changes; False when the user cancels."""
        if not self.is_modified():
            return True
        buttons = (QMessageBox.StandardButton.Save | QMessageBox.StandardButton.Discard
                   | QMessageBox.StandardButton.Cancel)
        answer = QMessageBox.question(
            self, translate("MainWindow", "Unsaved changes"),
            translate("MainWindow", "The program has unsaved changes. Save them?"),
            buttons, QMessageBox.StandardButton.Save)
        if answer == QMessageBox.StandardButton.Save:
            return self.save()
        return answer == QMessageBox.StandardButton.Discard

    # -- opening -------------------------------------------------------------------------

    def new_program_dialog(self) -> None:
        """File › New: ask the PLC family and model (the last one chosen first), then start an
        empty program of it (after asking to save the changes)."""
        if not self.maybe_save():
            return
        dialog = NewProgramDialog(remembered_model(self.settings), self._new_chosen, self)
        dialog.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose, True)
        self.new_dialog = dialog
        dialog.open()

    def _new_chosen(self, key: str) -> None:
        remember_model(self.settings, key)
        self.new_file(key)

    def new_file(self, model: str | None = None) -> None:
        """Start an empty program of `model` (None: the one File › New chose last); a Delta
        program holds its END."""
        key = model if model is not None else remembered_model(self.settings)
        self.document.reset()
        self.failed_path = None
        self.model.set_program(new_program(key))
        self.program_shown(new_program(key))
        self.text_view.setPlainText("")
        self.text_view.document().setModified(False)
        self.errors.set_diagnostics([])
        self.model.set_mode(Mode.LADDER)
        self.dialect = dialect_of(new_program(key))
        self.parameters.reset()
        self.recovery.remove()
        self.update_title()

    def change_family(self, key: str) -> bool:
        """Program properties: the drawn program becomes a program of model `key` of another
        family, untitled (Save As gives it a file of that family), when its instructions read
        back the same there; else a warning says why and nothing changes."""
        program, diagnostics = self.model.program()
        moved = family_change(program, key)
        if isinstance(moved, str):
            self.warn(translate("MainWindow", "PLC family"), moved)
            self.errors.set_diagnostics(diagnostics)
            return False
        self.document.reset()
        self.model.set_program(moved)
        self.program_shown(moved)
        self.model.set_mode(Mode.LADDER)
        self.dialect = dialect_of(moved)
        self.model.mark_modified()
        self.update_title()
        return True

    def _open_parameters(self, path: Path) -> None:
        """Read the PMC parameter file beside the program (the defaults when there is none)."""
        try:
            problems = self.parameters.open(path)
        except OSError as error:
            self.parameters.reset()
            self.warn(translate("MainWindow", "Open"),
                      translate("MainWindow", "Cannot read {0}: {1}").format(
                          path.name + ".prm", os_error_text(error)))
            return
        if problems:
            first = problems[0]
            self.warn(translate("MainWindow", "PMC parameters"), translate(
                "MainWindow",
                "{0}: {1} lines not understood (kept as they are); line {2}: {3}",
            ).format(path.name + ".prm", len(problems), first.line,
                     diagnostic_text(first)))

    def load(self, path: str | Path) -> bool:
        """Open a `.LAD` / `.MOD` file: as ladder, or as text with its errors listed."""
        path = Path(path)
        try:
            result, _data = self.document.read(path)
        except OSError as error:
            self.warn(translate("MainWindow", "Open"),
                      translate("MainWindow", "Cannot read {0}: {1}").format(
                          path, os_error_text(error)))
            return False
        self._open_parameters(path)
        self._show_result(path, result.program, result.ok, result.diagnostics)
        self.remember_file(path)
        self.recovery.remove()
        return True

    def _show_result(self, path: Path | None, program: Program, ok: bool,
                     diagnostics: list[Diagnostic]) -> None:
        """Show a read program: as ladder, or (it did not parse) its text, never overwritten."""
        self.dialect = dialect_of(program)
        self.errors.set_diagnostics(diagnostics)
        if any(d.code in ("invalid-bytes", "damaged-draft") for d in diagnostics):
            self.errors.show()
        if ok:
            self.failed_path = None
            self.model.set_program(program, kept=[])  # an unchanged network saves as read
            self.model.set_mode(Mode.LADDER)
            self.program_shown(program)
        else:
            self.failed_path = path
            source = program.source
            text = "\n".join(source.lines) + "\n" if source is not None else ""
            text = bad_bytes_shown(text)
            self.model.set_program(Program())
            self.program_shown(Program())
            self.text_view.setPlainText(text)
            self.text_view.document().setModified(False)
            self.model.set_mode(Mode.TEXT)
            self.errors.show()
            self.show_message(translate("MainWindow", "The file has errors: it is shown as text"))
        self.update_title()

    def open_dialog(self) -> None:
        """File > Open."""
        if not self.maybe_save():
            return
        name = file_dialogs.open_file_name(
            self, translate("MainWindow", "Open program"),
            str(self.path.parent if self.path else ""),
            file_dialogs.open_filters())
        if name:
            self.load(name)

    def open_folder_dialog(self) -> None:
        """File > Open folder: a folder of exports as one program (gui/folder_program.py)."""
        folder_program.open_dialog(self)

    # -- saving --------------------------------------------------------------------------

    def program_text(self, *, faithful: bool = False) -> str | None:
        """The current program as `.LAD` text, or None when it cannot be made (errors listed);
        `faithful`: the file's own lines, as the text view shows them (`view_text`)."""
        if self.model.showing_text:
            return None
        program, diagnostics = self.model.program()
        if program is None:
            self.errors.set_diagnostics(diagnostics)
            self.errors.show()
            return None
        return view_text(program) if faithful else print_program(program)

    def save(self) -> bool:
        """File > Save (Save As when the program has no file yet)."""
        if self.path is None:
            return self.save_as_dialog()
        return self.save_to(self.path)

    def _program_to_save(self) -> tuple[Program, list[Diagnostic]]:
        """The drawn program (unfinished networks as drafts, unchanged ones as read)."""
        return self.model.saved_program()

    def _may_write(self, path: Path) -> bool | None:
        """Ask before writing `path` (changed outside, read-only): True to go on, False when
        declined, None when another way was taken (reload, Save As) — its result is final."""
        if self.path is not None and same_file(path, self.path) and \
                self.document.changed_on_disk():
            answer = questions.changed_outside(self, path)
            if answer == "reload":
                self.load(path)
                return None
            if answer == "save_as":
                self._last_save_result = self.save_as_dialog()
                return None
            if answer != "keep":
                return False
        if is_read_only(path):
            if questions.read_only(self, path) == "save_as":
                self._last_save_result = self.save_as_dialog()
                return None
            return False
        return True

    def _encoded(self, path: Path, make: Callable[[], bytes]) -> bytes | None:
        """`make()`'s bytes; a character the encoding lacks asks to use UTF-8 (None: declined)."""
        try:
            return make()
        except EncodeError as error:
            if questions.encoding(self, path, error) != "utf8":
                return None
            self.document.use_utf8()
            return make()
        except DiagnosticError as error:  # a change its dialect cannot write (S7): kept
            self._last_save_result = save_refusal.refused(self, path, error.diagnostic)
            return None

    def save_to(self, path: str | Path) -> bool:
        """Write the program to `path` atomically, in the file's own form; a file that failed to
        parse is kept; a file changed outside or read-only asks first."""
        path = Path(path)
        showing_text = self.model.showing_text
        if showing_text and self.failed_path is not None and same_file(path, self.failed_path):
            self.warn(translate("MainWindow", "Save"), translate(
                "MainWindow",
                "{0} did not parse and is not overwritten. Fix the errors and use "
                "Show as ladder, or save under another name.").format(path.name))
            return False
        if is_pdw_path(path):
            self.warn(translate("MainWindow", "Save"), translate(
                "MainWindow",
                "{0} is a WinProladder project (.pdw): LadderWorks reads it but does not write"
                " it, since what it does not decode would be lost. Save the program as a"
                " WinProladder listing (.lst) instead.").format(path.name))
            return self.save_as_dialog()
        refused = save_refused(path, self.document.binary)
        if refused is not None:  # a .dvp project: LadderWorks writes its text forms only
            self.warn(translate("MainWindow", "Save"), diagnostic_text(refused))
            return self.save_as_dialog()
        if path.is_dir():  # a folder of exports: nothing written unless a block changed
            return folder_program.save(self, path)
        self._last_save_result = False
        go_on = self._may_write(path)
        if not go_on:
            return go_on is None and self._last_save_result
        data, drafts = self.bytes_to_save(path)
        if data is None:
            return self._last_save_result
        if not self._write(path, data):
            return False
        self.after_save(path, drafts)
        return True

    def bytes_to_save(self, path: Path) -> tuple[bytes | None, bool]:
        """The bytes Save writes to `path` and whether networks with errors are kept as
        drawings; None when nothing is written (declined, or refused: `save_refusal`)."""
        self._last_save_result = False
        self.pending_companions = {}
        if self.model.showing_text:
            text = self.text_view.toPlainText()
            text = text if text.endswith("\n") else text + "\n"
            return self._encoded(path, lambda: self.document.encode_text(text)), False
        program, diagnostics = self._program_to_save()
        self.dialect = dialect_of(program)
        drafts = has_errors(diagnostics)
        self.errors.set_diagnostics(diagnostics)
        if drafts:
            self.errors.show()
        data = self._encoded(path, lambda: self.document.encode(program))
        family = dialects.get(program.dialect)
        if data is not None and family is not None:  # S7: the changed titles' .s7res
            self.pending_companions = family.companion_files(program, path)
        return data, drafts

    def write_companions(self) -> None:
        """Write the files Save writes beside the program's (`Dialect.save_companions`), each
        atomically; OSError, ReadOnlyFile."""
        for extra, data in self.pending_companions.items():
            atomic_write_bytes(extra, data)
        self.pending_companions = {}

    def save_answer(self) -> bool:
        """What Save returns when `bytes_to_save` gave nothing (True: Save As saved it)."""
        return self._last_save_result

    def after_save(self, path: Path, drafts: bool, message: str = "") -> None:
        """The program is saved as `path`: unmodified, remembered, the status bar says so."""
        self.model.mark_saved()
        self.text_view.document().setModified(False)
        self.remember_file(path)
        self.update_title()
        self.recovery.remove()
        if drafts:
            self.show_message(translate(
                "MainWindow",
                "Saved {0}; networks with errors are kept as drawings (see the error list)",
            ).format(path.name))
        else:
            self.show_message(message or translate("MainWindow", "Saved {0}").format(path.name))
        self.file_saved.emit(str(path))

    def _write(self, path: Path, data: bytes) -> bool:
        """Write the program and its PMC parameters; warn and False when it fails."""
        name = path
        try:
            self.document.write(path, data)
            name = path.with_name(path.name + ".prm")
            self.parameters.save(path, self.dialect)
            name = next(iter(self.pending_companions), name)
            self.write_companions()
        except ReadOnlyFile:
            self.warn(translate("MainWindow", "Save"), translate(
                "MainWindow", "{0} is read-only and is not replaced.").format(name))
            return False
        except OSError as error:
            self.warn(translate("MainWindow", "Save"),
                      translate("MainWindow", "Cannot write {0}: {1}").format(
                          name, os_error_text(error)))
            return False
        return True

    def save_as_dialog(self) -> bool:
        """File > Save As (a program read from a .pdw or a .dvp project: in its text form)."""
        if self.path is not None and is_pdw_path(self.path):  # its listing (a .pdw: never)
            name = file_dialogs.save_file_name(
                self, translate("MainWindow", "Save program"), str(self.path.with_suffix(".lst")),
                translate("MainWindow", "Fatek WinProladder listings (*.lst *.LST);;All files (*)"))
            return bool(name) and self.save_to(name)
        if self.document.binary and self.path is not None:
            name = file_dialogs.save_file_name(
                self, translate("MainWindow", "Save program"), str(self.path.with_suffix(".il")),
                translate("MainWindow",
                          "Delta DVP instruction lists (*.il *.IL *.txt *.TXT);;All files (*)"))
            return bool(name) and self.save_to(name)
        filters, default = save_filters(self.model.dialect)
        name = file_dialogs.save_file_name(
            self, translate("MainWindow", "Save program"), str(self.path or default), filters)
        return bool(name) and self.save_to(name)

    def import_mod_dialog(self) -> None:
        """File > Import .MOD: open mnemonic text as a new, untitled ladder."""
        if not self.maybe_save():
            return
        name = file_dialogs.open_file_name(
            self, translate("MainWindow", "Import .MOD"), "",
            translate("MainWindow", "Mnemonic programs (*.MOD *.mod);;All files (*)"))
        if name:
            self.import_mod(name)

    def import_mod(self, path: str | Path) -> bool:
        """Read a `.MOD` file into the editor; it is saved as a new `.LAD`."""
        if not self.load(path):
            return False
        self.document.detach()
        self.failed_path = None
        self.update_title()
        return True

    def import_symbols_dialog(self) -> None:
        """File > Import symbols: a WinProladder comment export as the program's symbols."""
        from ladderworks.gui.symbol_import import import_symbols_dialog
        import_symbols_dialog(self, self)  # type: ignore[arg-type]

    def export_mod_dialog(self) -> None:
        """File > Export .MOD."""
        base = self.path.with_suffix(".MOD") if self.path else Path("program.MOD")
        name = file_dialogs.save_file_name(
            self, translate("MainWindow", "Export .MOD"), str(base),
            translate("MainWindow", "Mnemonic programs (*.MOD);;All files (*)"))
        if name:
            self.export_mod(name)

    def export_mod(self, path: str | Path) -> bool:
        """Write the program as mnemonic text to `path` (in the program's encoding)."""
        path = Path(path)
        text = self.program_text()
        if text is None:
            return False
        data = self._encoded(path, lambda: self.document.encode_text(text))
        if data is None:
            return False
        try:
            atomic_write_bytes(path, data)
        except ReadOnlyFile:
            self.warn(translate("MainWindow", "Export .MOD"), translate(
                "MainWindow", "{0} is read-only and is not replaced.").format(path))
            return False
        except OSError as error:
            self.warn(translate("MainWindow", "Export .MOD"),
                      translate("MainWindow", "Cannot write {0}: {1}").format(
                          path, os_error_text(error)))
            return False
        self.show_message(translate("MainWindow", "Exported {0}").format(path.name))
        return True

    # -- recovery ------------------------------------------------------------------------

    def recovery_snapshot(self) -> Snapshot | None:
        """The unsaved work to copy (None when nothing is unsaved)."""
        if not self.is_modified():
            return None
        document = self.document
        try:
            if self.model.showing_text:
                data = document.encode_text(self.text_view.toPlainText())
            else:
                data = document.encode(self._program_to_save()[0])
        except DiagnosticError:  # a change its dialect cannot write (S7): the file as read
            source = self.document.origin.source if self.document.origin else None
            data = "".join(line + end for line, end in zip(source.lines, source.ends,
                                                          strict=True)).encode(
                "utf-8", errors="surrogateescape") if source is not None else b""
        except EncodeError:  # a character the file cannot hold: the copy is UTF-8
            text = (bad_bytes_back(self.text_view.toPlainText())
                    if self.model.showing_text
                    else print_program(self._program_to_save()[0]))
            data = text.encode("utf-8", errors="surrogateescape")
        parameters = self.parameters.session.run.parameters
        return Snapshot(data, document.path,
                        format_parameters(parameters, self.dialect) if parameters else None,
                        asdict(document.disk) if document.disk is not None else None)

    def offer_recovery(self) -> bool:
        """Offer each copy left by a session that crashed or was killed; True when one was
        restored into this window (the others are offered again at the next start)."""
        for copy in self.recovery.orphans():
            if self.is_modified():
                copy.lock.unlock()
                continue
            name = str(copy.original) if copy.original else translate("MainWindow", "Untitled")
            when = _when(copy)
            answer = questions.restore(self, name, when)
            if (answer == "restore" and self.restore(copy)) or answer == "discard":
                self.recovery.discard(copy)
            else:
                copy.lock.unlock()
        return self.is_modified()

    def restore(self, copy: RecoveredCopy) -> bool:
        """Show a recovered copy as unsaved changes to its original file."""
        try:
            result = parse_bytes(copy.data_path.read_bytes())
            found = parameters_beside(copy.data_path)
        except OSError as error:
            self.warn(translate("MainWindow", "Recover unsaved work"),
                      translate("MainWindow", "Cannot read {0}: {1}").format(
                          copy.data_path, os_error_text(error)))
            return False
        disk = DiskState(**copy.disk) if copy.disk else None  # type: ignore[arg-type]
        self.document.adopt(copy.original, result, disk)
        if copy.original is not None:
            self._open_parameters(copy.original)
        else:
            self.parameters.reset()
        self.parameters.session.set_parameters(found.parameters)
        self._show_result(copy.original, result.program, result.ok, result.diagnostics)
        self.failed_path = None  # the original on disk is not the text that failed
        self.model.mark_modified()
        self.text_view.document().setModified(True)
        self.update_title()
        self.autosaver.save_now()
        self.show_message(translate("MainWindow", "Recovered unsaved work from {0}").format(
            _when(copy)))
        return True
