"""The open program's file: path, text form, disk state, modified state, load and save."""

from __future__ import annotations

import hashlib
import os
from dataclasses import dataclass, replace
from pathlib import Path

from PySide6.QtCore import QFileSystemWatcher, QObject, Signal
from PySide6.QtGui import QTextDocument

from ladderworks.core.collector import release_frozen
from ladderworks.core.diagnostics import DiagnosticError
from ladderworks.core.dialects.delta.dvp_file import is_dvp
from ladderworks.core.il import Program
from ladderworks.core.il.parser import ParseResult
from ladderworks.core.il.printer import encode_program, print_faithful
from ladderworks.core.il.reading import parse_file, parse_read, parse_text
from ladderworks.core.il.textform import UTF8, TextForm, encode_text, split_lines
from ladderworks.core.ladder.convert import adopt_origin, damaged_drafts
from ladderworks.core.ladder.source_model import source_file
from ladderworks.gui.editor.ladder_model import LadderModel
from ladderworks.gui.files import atomic_write_bytes, write_target
from ladderworks.gui.parameter_document import ParameterDocument


@dataclass(frozen=True, slots=True)
class DiskState:
    """What the file on disk was when it was read or written: time, size and content hash."""

    mtime_ns: int
    size: int
    digest: str

    @classmethod
    def of(cls, path: Path, data: bytes | None = None) -> DiskState | None:
        """The state of `path` now (None when it does not exist or cannot be read)."""
        try:
            info = os.stat(path)
            content = data if data is not None else Path(path).read_bytes()
        except OSError:
            return None
        return cls(info.st_mtime_ns, info.st_size, hashlib.sha256(content).hexdigest())

    def same_content(self, other: DiskState | None) -> bool:
        """True when `other` holds the same bytes (a touch without a change is no change)."""
        return other is not None and (other.size, other.digest) == (self.size, self.digest)


# Qt drops lone surrogates, so a kept invalid byte (U+DC80..U+DCFF after surrogateescape) is
# shown in the text view as a private-use character of plane 16 and mapped back on save.
_BAD_BYTE = 0xDC00
_SHOWN_BAD_BYTE = 0x10FC00


# Characters a Qt text widget would not give back as they were: its toPlainText() turns the
# line and paragraph separators into a line feed (a line more than the file has) and a
# no-break space into a space; shown as visible private-use characters, given back on return.
_QT_CHANGES = {"\u2028": chr(0x10FD28), "\u2029": chr(0x10FD29), "\u00a0": chr(0x10FDA0)}
_QT_BACK = {shown: ch for ch, shown in _QT_CHANGES.items()}
_QT_SHOWN = str.maketrans(_QT_CHANGES)
_QT_RETURNED = str.maketrans(_QT_BACK)


def bad_bytes_shown(text: str) -> str:
    """Text for a Qt text widget: each kept invalid byte as a visible private-use character
    (and the characters Qt would change, _QT_CHANGES)."""
    if text.isascii():
        return text
    return "".join(chr(_SHOWN_BAD_BYTE + ord(ch) - _BAD_BYTE) if "\udc80" <= ch <= "\udcff"
                   else ch for ch in text).translate(_QT_SHOWN)


def bad_bytes_back(text: str) -> str:
    """Text from a Qt text widget with the invalid bytes it showed back as they were."""
    if text.isascii():
        return text
    low, high = chr(_SHOWN_BAD_BYTE + 0x80), chr(_SHOWN_BAD_BYTE + 0xFF)
    return "".join(chr(_BAD_BYTE + ord(ch) - _SHOWN_BAD_BYTE) if low <= ch <= high else ch
                   for ch in text).translate(_QT_RETURNED)


def view_text(program: Program) -> str:
    """The text the text view shows: the file's own lines (as Save writes them, so a line
    number of a diagnostic is the view's line), each ended by LF."""
    try:
        lines = split_lines(print_faithful(program))
    except DiagnosticError:  # a change its dialect cannot write (S7): the file's lines
        lines = list(program.source.lines) if program.source is not None else []
    return "\n".join(lines) + "\n" if lines else ""


def same_file(a: Path, b: Path) -> bool:
    """True when two paths name the same file (through symlinks)."""
    return write_target(a) == write_target(b)


class ProgramDocument(QObject):
    """The program's file state; MainWindow asks it to read, encode and write."""

    changed_outside = Signal(str)  # the path: another program changed the file on disk
    modified_changed = Signal()

    def __init__(self, model: LadderModel, text: QTextDocument, parameters: ParameterDocument,
                 parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.model = model
        self.text = text
        self.parameters = parameters
        self.path: Path | None = None
        self.form = TextForm()
        self.origin: Program | None = None
        self.binary = False  # read from a WPLSoft .dvp project: never written back over it
        self.disk: DiskState | None = None
        # a folder of exports: the file of its entry block (Save writes a change there) and
        # what it was when read or last written
        self.entry: Path | None = None
        self.entry_disk: DiskState | None = None
        self.watcher = QFileSystemWatcher(self)
        self.watcher.fileChanged.connect(self._on_file_changed)
        model.modified_changed.connect(self.modified_changed)
        text.modificationChanged.connect(self.modified_changed)
        parameters.session.parameters_changed.connect(self.modified_changed)

    # -- state --------------------------------------------------------------------------

    def is_modified(self) -> bool:
        """True when there are unsaved changes (ladder or text, and the PMC parameters)."""
        if self.parameters.modified:
            return True
        if self.model.showing_text:
            return self.text.isModified()
        return self.model.is_modified()

    def changed_on_disk(self) -> bool:
        """True when the file now differs from what was read or last written."""
        if self.path is None or self.disk is None:
            return False
        now = DiskState.of(self.path)
        return now is not None and not self.disk.same_content(now)

    def entry_changed_on_disk(self) -> bool:
        """True when a folder's entry file now differs from what was read or last written."""
        if self.entry is None or self.entry_disk is None:
            return False
        now = DiskState.of(self.entry)
        return now is None or not self.entry_disk.same_content(now)

    def _watch(self, path: Path | None) -> None:
        if self.watcher.files():
            self.watcher.removePaths(self.watcher.files())
        if path is not None and path.exists():
            self.watcher.addPath(str(path))

    def _on_file_changed(self, name: str) -> None:
        if self.path is None or Path(name) != self.path:
            return
        if not self.path.exists():
            return  # removed (or being replaced): asked about on save
        self._watch(self.path)  # a replaced file is dropped from the watch list
        if self.changed_on_disk():
            self.changed_outside.emit(name)

    # -- reading ------------------------------------------------------------------------

    def reset(self) -> None:
        """A new, untitled program in UTF-8 with LF line ends."""
        self.path = None
        self.form = TextForm()
        self.origin = None
        self.disk = None
        self.binary = False
        self._folder_entry(None)
        self._watch(None)

    def _folder_entry(self, entry: Path | None) -> None:
        self.entry = entry
        self.entry_disk = DiskState.of(entry) if entry is not None else None

    def read(self, path: Path) -> tuple[ParseResult, bytes]:
        """Read and parse `path` (OSError); it becomes the document's file. A folder of
        exports (S7's: an OB, its blocks, DBs and tag tables) is read as one program."""
        folder = path.is_dir()
        data = b"" if folder else path.read_bytes()
        release_frozen()  # the program shown so far is dropped: its objects walked again
        # with Fatek's comment export beside it: symbols; a folder: its dialect's opener
        result = parse_file(path) if folder else parse_read(path, data)
        if result.program.source is not None:
            result.diagnostics = sorted(
                result.diagnostics + damaged_drafts(result.program.source.lines),
                key=lambda d: (d.line, d.column))
        self.path = path
        self.form = result.program.form
        self.origin = result.program
        self.binary = is_dvp(data)
        self.disk = None if folder else DiskState.of(path, data)
        self._folder_entry(source_file(result.program) if folder else None)
        self._watch(path)
        return result, data

    def adopt(self, path: Path | None, result: ParseResult, disk: DiskState | None) -> None:
        """Take a program read elsewhere (a recovery copy) as the one of `path`."""
        self.path = path
        self.form = result.program.form
        self.origin = result.program
        self.disk = disk
        self._folder_entry(None)
        self._watch(path)

    def detach(self) -> None:
        """Forget the file (an imported `.MOD` is saved as a new program)."""
        self.path = None
        self.disk = None
        self._folder_entry(None)
        self._watch(None)

    # -- writing ------------------------------------------------------------------------

    def encode(self, program: Program) -> bytes:
        """The bytes Save writes for `program` in the document's form; EncodeError."""
        if program.source is None and self.origin is not None:
            adopt_origin(program, self.origin)  # the file it was read from: a faithful save
        if program.form == self.form:
            return encode_program(program)
        return encode_text(print_faithful(program), self.form)

    def read_text(self, text: str) -> ParseResult:
        """Parse the text view's text as a text of this document's file: its lines end with
        the file's line end, and the program keeps the file's form (encoding, BOM)."""
        text = bad_bytes_back(text)
        newline = self.form.newline
        result = parse_text(text.replace("\n", newline) if newline != "\n" else text)  # sniffed
        source = result.program.source
        if source is not None:
            source.form = replace(self.form, final_newline=source.form.final_newline)
        return result

    def encode_text(self, text: str) -> bytes:
        """Text from the text view as bytes in the document's form (its line ends); EncodeError."""
        text = bad_bytes_back(text)
        if self.form.newline != "\n":
            text = text.replace("\n", self.form.newline)
        return encode_text(text, self.form)

    def use_utf8(self) -> None:
        """Save in UTF-8 from now on (the user's answer to a character the encoding lacks)."""
        self.form = replace(self.form, encoding=UTF8,
                            bom=b"\xef\xbb\xbf" if self.form.bom else b"")

    def write(self, path: Path, data: bytes) -> None:
        """Write atomically (ReadOnlyFile, OSError); `path` becomes the document's file."""
        atomic_write_bytes(path, data)
        self.path = path
        self.binary = False  # now the text form's file
        self.disk = DiskState.of(path, data)
        self._folder_entry(None)
        self._watch(path)

    def write_entry(self, data: bytes) -> None:
        """Write a folder's entry file atomically (ReadOnlyFile, OSError); the folder stays
        the document's path."""
        assert self.entry is not None
        atomic_write_bytes(self.entry, data)
        self.entry_disk = DiskState.of(self.entry, data)

