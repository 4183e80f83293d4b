"""Diagnostic messages in the UI language: the core's marked templates through the translator."""

from __future__ import annotations

from dataclasses import replace

from PySide6.QtCore import QCoreApplication

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.gui.translation import param_label


def diagnostic_text(diagnostic: Diagnostic) -> str:
    """The diagnostic's message in the current UI language (parameter names included)."""
    if "param" in diagnostic.args:
        args = {**diagnostic.args, "param": param_label(str(diagnostic.args["param"]))}
        diagnostic = replace(diagnostic, args=args)
    return diagnostic.message(QCoreApplication.translate)
