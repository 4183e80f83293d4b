"""Qt's own strings that its Turkish catalogue (qtbase_tr.qm) lacks or words badly.

lupdate reads these markers into our `.ts`; our translator is installed after Qt's, so Qt's
file dialog and buttons ask ours first."""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP

QT_STRINGS = (
    QT_TRANSLATE_NOOP("QFileDialog", "&Look in:"),  # qtbase_tr has only "Look in:"
    QT_TRANSLATE_NOOP("QFileDialog", "Files of &type:"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Discard"),  # qtbase_tr's "At" (throw): "Kaydetme"
)
