"""File › New: the PLC family and model of the new program (the last choice remembered), and
the file filter and extension a program of each family is saved with."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QComboBox, QDialog, QDialogButtonBox, QFormLayout, QLabel, QWidget

from ladderworks.core import dialects
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.families import Family, change_family, families
from ladderworks.core.il.program import SEED, Program
from ladderworks.core.models import MODELS, model_of
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.program_properties import model_title
from ladderworks.gui.settings import Settings
from ladderworks.gui.translation import ui_is_turkish

translate = QCoreApplication.translate

_MODEL_KEY = "new/model"  # the model of the last program made by File › New


def remembered_model(settings: Settings) -> str:
    """The model File › New chose last (the seed's at first, or when no longer registered)."""
    value = settings.store.value(_MODEL_KEY, SEED)
    return value if isinstance(value, str) and value in MODELS else SEED


def remember_model(settings: Settings, key: str) -> None:
    """Remember the model of a program made by File › New."""
    settings.store.setValue(_MODEL_KEY, key)
    settings.store.sync()


def family_title(family: Family) -> str:
    """A family's title in the UI language."""
    return family.title_tr if ui_is_turkish() else family.title


def save_filters(dialect: str) -> tuple[str, str]:
    """The Save As filters and the default file name of a program of `dialect`: a Delta
    instruction list `.txt`, a Fatek listing `.lst`, an S7 block `.s7dcl`/`.xml`, a PMC
    program `.LAD`."""
    every = translate("MainWindow", "All files (*)")
    found = dialects.get(dialect)
    if found is not None and found.name == "delta":
        return (translate("MainWindow", "Delta DVP instruction lists (*.txt *.TXT)") + ";;"
                + every, "program.txt")
    if found is not None and found.name == "s7":  # the block in its own form (saving.py)
        return (translate("MainWindow", "Siemens S7-1200 SIMATIC SD blocks (*.s7dcl)") + ";;"
                + translate("MainWindow", "Siemens S7-1200 SimaticML exports (*.xml)") + ";;"
                + every, "Main.s7dcl")
    if found is not None and found.name == "fatek":
        return (translate("MainWindow", "Fatek WinProladder listings (*.lst *.LST)") + ";;"
                + every, "program.lst")
    return translate("MainWindow", "Ladder programs (*.LAD *.lad)") + ";;" + every, "program.LAD"


def family_change(program: Program | None, key: str) -> Program | str:
    """The drawn `program` (None: it has errors) as a program of model `key` of another
    family, or the translated reason it stays as it is."""
    if program is None:
        return translate("MainWindow", "The program has errors: fix them first "
                         "(see the error list)")
    moved = change_family(program, key)
    if isinstance(moved, Diagnostic):
        return translate("MainWindow", "The program cannot become a {0} program: {1}").format(
            model_title(key), diagnostic_text(moved))
    return moved


class NewProgramDialog(QDialog):
    """The PLC family and model of a new program; `chosen(model key)` on OK."""

    def __init__(self, current: str, chosen: Callable[[str], None],
                 parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("dialog_new_program")
        self.setWindowTitle(translate("NewProgram", "New program"))
        self.chosen = chosen
        self.families = families()
        self.family_combo = QComboBox(self)
        self.family_combo.setObjectName("new_family")
        self.model_combo = QComboBox(self)
        self.model_combo.setObjectName("new_model")
        self.model_combo.setToolTip(translate(
            "NewProgram", "A family's models differ in their ranges; the Delta DVP series "
            "(ES2, EX2, SS2, SA2, SX2, SE) and the Fatek FBs series share one device map here "
            "(docs/dialects.md)."))
        for family in self.families:
            self.family_combo.addItem(family_title(family), family.key)
        self.family_combo.currentIndexChanged.connect(self._fill_models)
        form = QFormLayout(self)
        about = QLabel(translate(
            "NewProgram", "The PLC the program is written for: its instructions, its "
            "devices (X0, T0, D10 or X2.1, R100) and its file form."), self)
        about.setWordWrap(True)  # the dialog as wide as its lists, on a small screen too
        form.addRow(about)
        form.addRow(translate("NewProgram", "PLC family"), self.family_combo)
        form.addRow(translate("NewProgram", "Model"), self.model_combo)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok
                                   | QDialogButtonBox.StandardButton.Cancel, self)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        form.addRow(buttons)
        self.family_combo.setCurrentIndex(
            max(self.family_combo.findData(model_of(current).family), 0))
        self._fill_models()
        self.model_combo.setCurrentIndex(max(self.model_combo.findData(current), 0))
        self.accepted.connect(lambda: self.chosen(self.model_key()))

    def _fill_models(self) -> None:
        self.model_combo.clear()
        family = self.families[max(self.family_combo.currentIndex(), 0)]
        for model in family.models:
            self.model_combo.addItem(model_title(model.key), model.key)

    def choose(self, key: str) -> None:
        """Select model `key` (and its family), as a user does."""
        family = model_of(key).family
        self.family_combo.setCurrentIndex(self.family_combo.findData(family))
        self.model_combo.setCurrentIndex(self.model_combo.findData(key))

    def model_key(self) -> str:
        """The chosen model's key."""
        key = self.model_combo.currentData()
        return key if isinstance(key, str) else SEED
