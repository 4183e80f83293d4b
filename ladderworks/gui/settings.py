"""The user's settings (language, recent files, window layout, scan code) over QSettings."""

from __future__ import annotations

import hashlib

from PySide6.QtCore import QByteArray, QSettings

MAX_RECENT = 8
LANGUAGES: tuple[str, ...] = ("en", "tr")
BACKENDS: tuple[str, ...] = ("python", "native")  # the scan's code (docs/engine.md)


class Settings:
    """Typed access to the QSettings store; tests pass a QSettings on a temporary file."""

    def __init__(self, store: QSettings | None = None) -> None:
        self._store = store if store is not None else QSettings("LadderWorks", "LadderWorks")

    @property
    def store(self) -> QSettings:
        """The underlying QSettings."""
        return self._store

    def language(self) -> str | None:
        """The chosen UI language ('en' / 'tr'), or None before the user ever chose one."""
        value = self._store.value("ui/language", None)
        return str(value) if value in LANGUAGES else None

    def set_language(self, language: str) -> None:
        """Remember the UI language."""
        self._store.setValue("ui/language", language)
        self._store.sync()

    def scan_backend(self) -> str:
        """The scan's code the PLC uses: "python" (the default) or "native"."""
        value = self._store.value("plc/backend", "python")
        return str(value) if value in BACKENDS else "python"

    def set_scan_backend(self, backend: str) -> None:
        """Remember the scan's code ("python" or "native")."""
        self._store.setValue("plc/backend", backend)
        self._store.sync()

    def watch_rows(self, program: str) -> str:
        """The watch table's rows of the program at path `program` (JSON), or ""."""
        value = self._store.value(_watch_key(program), "")
        return value if isinstance(value, str) else ""

    def set_watch_rows(self, program: str, text: str) -> None:
        """Keep the watch table's rows (JSON) of the program at path `program`."""
        self._store.setValue(_watch_key(program), text)
        self._store.sync()

    def recent_files(self) -> list[str]:
        """Recently opened or saved files, newest first."""
        value = self._store.value("files/recent", [])
        if isinstance(value, str):
            return [value] if value else []
        return [str(item) for item in value] if isinstance(value, list | tuple) else []

    def add_recent_file(self, path: str) -> list[str]:
        """Put `path` first in the recent list and return the list."""
        files = [path, *(item for item in self.recent_files() if item != path)][:MAX_RECENT]
        self._store.setValue("files/recent", files)
        self._store.sync()
        return files

    def clear_recent_files(self) -> None:
        """Forget the recent files."""
        self._store.setValue("files/recent", [])
        self._store.sync()

    def window_state(self) -> tuple[QByteArray | None, QByteArray | None]:
        """Saved (geometry, dock state) of the main window."""
        geometry = self._store.value("window/geometry", None)
        state = self._store.value("window/state", None)
        return (
            geometry if isinstance(geometry, QByteArray) else None,
            state if isinstance(state, QByteArray) else None,
        )

    def set_window_state(self, geometry: QByteArray, state: QByteArray) -> None:
        """Remember the main window's geometry and dock layout."""
        self._store.setValue("window/geometry", geometry)
        self._store.setValue("window/state", state)
        self._store.sync()

    def name_display(self) -> str:
        """What the ladder shows with each element ("address", "symbol", "comment"), or ""."""
        value = self._store.value("view/names", "")
        return str(value) if isinstance(value, str) else ""

    def set_name_display(self, value: str) -> None:
        """Remember what the ladder shows with each element."""
        self._store.setValue("view/names", value)
        self._store.sync()

    def zoom(self) -> tuple[float, bool]:
        """The ladder's saved zoom factor and whether it fits the width (1.0, False at first)."""
        try:
            factor = float(self._store.value("view/zoom", 1.0))  # type: ignore[arg-type]
        except (TypeError, ValueError):
            factor = 1.0
        fit = str(self._store.value("view/fit_width", "false")).lower() == "true"
        return factor, fit

    def diagnostic_zoom(self, default: float) -> float:
        """The PLC diagnostic's saved zoom (`default` at first)."""
        try:
            return float(self._store.value("view/diagnostic_zoom", default))  # type: ignore[arg-type]
        except (TypeError, ValueError):
            return default

    def set_diagnostic_zoom(self, factor: float) -> None:
        """Remember the PLC diagnostic's zoom."""
        self._store.setValue("view/diagnostic_zoom", factor)
        self._store.sync()

    def set_zoom(self, factor: float, fit_width: bool) -> None:
        """Remember the ladder's zoom."""
        self._store.setValue("view/zoom", factor)
        self._store.setValue("view/fit_width", fit_width)
        self._store.sync()


def _watch_key(program: str) -> str:
    """A program's watch rows' key: its path hashed (a path's slashes would be groups)."""
    return "watch/" + hashlib.sha1(program.encode("utf-8", "surrogatepass")).hexdigest()
