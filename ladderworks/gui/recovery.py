"""Recovery copies of unsaved work in the user's data folder, and the autosave timer."""

from __future__ import annotations

import contextlib
import json
import os
import uuid
from collections.abc import Callable
from dataclasses import dataclass
from datetime import datetime
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QLockFile, QObject, QStandardPaths, QTimer, Signal

from ladderworks.gui.files import atomic_write_bytes
from ladderworks.gui.os_errors import os_error_text

AUTOSAVE_MS = 30_000  # a copy of unsaved work every 30 s ...
PAUSE_MS = 2_000  # ... and this long after the last structural edit
INTERVAL_VARIABLE = "LADDERWORKS_AUTOSAVE_MS"  # a shorter interval (tests)


def recovery_folder() -> Path:
    """`LadderWorks/recovery` in the user's data folder (XDG_DATA_HOME, %LOCALAPPDATA%)."""
    base = QStandardPaths.writableLocation(QStandardPaths.StandardLocation.GenericDataLocation)
    return Path(base) / "LadderWorks" / "recovery"


def autosave_interval() -> int:
    """The autosave interval in milliseconds (30 s unless the environment says otherwise)."""
    with contextlib.suppress(ValueError):
        return max(50, int(os.environ.get(INTERVAL_VARIABLE, "")))
    return AUTOSAVE_MS


@dataclass(slots=True)
class Snapshot:
    """Unsaved work: the program's bytes, its file (None: untitled), PMC parameter text."""

    data: bytes
    original: Path | None
    parameters: str | None = None
    disk: dict[str, object] | None = None  # the original's DiskState when it was read


@dataclass(slots=True)
class RecoveredCopy:
    """A copy left by a session that ended without saving or closing."""

    key: str
    data_path: Path
    original: Path | None
    saved_at: datetime
    disk: dict[str, object] | None
    lock: QLockFile

    def parameters_path(self) -> Path:
        """The PMC parameters saved with the copy (may not exist)."""
        return self.data_path.with_name(self.data_path.name + ".prm")


class RecoveryStore:
    """This session's recovery copy (`KEY.LAD`, `KEY.LAD.prm`, `KEY.json`), locked while open."""

    def __init__(self, folder: Path | None = None) -> None:
        self.folder = folder if folder is not None else recovery_folder()
        self.key = f"{os.getpid()}-{uuid.uuid4().hex[:8]}"
        self._lock: QLockFile | None = None

    def _files(self, key: str) -> tuple[Path, Path, Path]:
        data = self.folder / f"{key}.LAD"
        return data, data.with_name(data.name + ".prm"), self.folder / f"{key}.json"

    def write(self, snapshot: Snapshot) -> Path:
        """Write (or replace) this session's copy; the path of its program bytes. OSError."""
        self.folder.mkdir(parents=True, exist_ok=True)
        if self._lock is None:
            self._lock = QLockFile(str(self.folder / f"{self.key}.lock"))
            self._lock.setStaleLockTime(0)
            self._lock.tryLock(0)
        data, parameters, meta = self._files(self.key)
        atomic_write_bytes(data, snapshot.data)
        if snapshot.parameters is not None:
            atomic_write_bytes(parameters, snapshot.parameters.encode("utf-8"))
        elif parameters.exists():
            parameters.unlink()
        info = {"original": str(snapshot.original) if snapshot.original else None,
                "saved_at": datetime.now().astimezone().isoformat(timespec="seconds"),
                "disk": snapshot.disk}
        atomic_write_bytes(meta, json.dumps(info, ensure_ascii=False).encode("utf-8"))
        return data

    def has_copy(self) -> bool:
        """True while this session has a copy on disk."""
        return self._files(self.key)[2].exists()

    def remove(self) -> None:
        """Remove this session's copy (saved cleanly, or closed without keeping the work)."""
        for path in self._files(self.key):
            with contextlib.suppress(FileNotFoundError):
                path.unlink()

    def close(self) -> None:
        """Remove the copy and the lock: the session ended cleanly."""
        self.remove()
        if self._lock is not None:
            self._lock.unlock()
            self._lock = None

    def orphans(self) -> list[RecoveredCopy]:
        """Copies of sessions that are gone (crashed or killed), oldest first; each is locked
        for this session until it is restored, discarded or released."""
        found: list[RecoveredCopy] = []
        if not self.folder.is_dir():
            return found
        for meta in sorted(self.folder.glob("*.json")):
            key = meta.stem
            if key == self.key:
                continue
            lock = QLockFile(str(self.folder / f"{key}.lock"))
            lock.setStaleLockTime(0)  # a live session is never stale, however old its lock
            if not lock.tryLock(0):
                continue  # its session is still running
            try:
                info = json.loads(meta.read_text("utf-8"))
                saved_at = datetime.fromisoformat(str(info["saved_at"]))
                original = Path(info["original"]) if info.get("original") else None
                disk = info.get("disk") if isinstance(info.get("disk"), dict) else None
            except (OSError, ValueError, KeyError, TypeError):
                lock.unlock()
                continue
            found.append(RecoveredCopy(key, self._files(key)[0], original, saved_at, disk,
                                       lock))
        return sorted(found, key=lambda copy: copy.saved_at)

    def discard(self, copy: RecoveredCopy) -> None:
        """Remove a recovered copy for good."""
        for path in self._files(copy.key):
            with contextlib.suppress(FileNotFoundError):
                path.unlink()
        copy.lock.unlock()
        with contextlib.suppress(FileNotFoundError):
            (self.folder / f"{copy.key}.lock").unlink()


class Autosaver(QObject):
    """Copies unsaved work every interval and after a pause following a structural edit."""

    copied = Signal(str)  # the copy's path
    failed = Signal(str)  # why a copy could not be written

    def __init__(self, store: RecoveryStore, snapshot: Callable[[], Snapshot | None],
                 parent: QObject | None = None, interval: int | None = None) -> None:
        super().__init__(parent)
        self.store = store
        self._snapshot = snapshot
        self.timer = QTimer(self)
        self.timer.setObjectName("autosave_timer")
        self.timer.setInterval(interval if interval is not None else autosave_interval())
        self.timer.timeout.connect(self.save_now)
        self.timer.start()
        self.pause = QTimer(self)
        self.pause.setSingleShot(True)
        self.pause.setInterval(min(PAUSE_MS, self.timer.interval()))
        self.pause.timeout.connect(self.save_now)

    def edited(self, *_args: object) -> None:
        """A structural edit: copy once the user pauses."""
        self.pause.start()

    def save_now(self) -> None:
        """Write the copy now (or remove it when nothing is unsaved)."""
        snapshot = self._snapshot()
        if snapshot is None:
            if self.store.has_copy():
                self.store.remove()
            return
        try:
            path = self.store.write(snapshot)
        except OSError as error:
            self.failed.emit(QCoreApplication.translate(
                "Recovery", "Cannot write the recovery copy in {0}: {1}").format(
                self.store.folder, os_error_text(error)))
            return
        self.copied.emit(str(path))
