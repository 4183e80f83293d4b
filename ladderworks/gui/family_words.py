"""The PLC family's own words in the GUI: the examples a field shows and the family's name,
for the program's dialect (a Delta program's examples are Delta devices, not FANUC's)."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from ladderworks.core import dialects

translate = QCoreApplication.translate

# (cross reference field, time chart field) examples of each family: "" is the PMC's
_EXAMPLES = {
    "": ("X21.7, R100, ESKIP", "R1.4 R1.7 D10:2", "R200"),
    "delta": ("X0, M100, T0, D10", "X0 Y0 T0 D10", "M200"),
    "fatek": ("X0, M100, T0, R10", "X0 Y0 T0 R10", "M200"),
    "s7": ('"Start", %Q0.0, "Motor".Q', '"Start" %Q0.0 %MW2 "IEC_Timer_0_DB".ET', "%M20.0"),
}


def _family(dialect: str | None) -> str:
    found = dialects.get(dialect)
    return found.name if found is not None and found.name in _EXAMPLES else ""


def xref_example(dialect: str | None) -> str:
    """The cross reference field's placeholder: `e.g. X0, M100, T0, D10` for Delta."""
    return translate("FamilyWords", "e.g. {0}").format(_EXAMPLES[_family(dialect)][0])


def replace_example(dialect: str | None) -> str:
    """Find and replace's `Replace with` placeholder example: `e.g. R200`."""
    return translate("FamilyWords", "e.g. {0}").format(_EXAMPLES[_family(dialect)][2])


def chart_example(dialect: str | None) -> str:
    """The time chart field's placeholder: `e.g. R1.4 R1.7 D10:2` for a PMC program."""
    return translate("FamilyWords", "e.g. {0}").format(_EXAMPLES[_family(dialect)][1])


def chart_hint(dialect: str | None) -> str:
    """What the time chart says when no signal is typed, in the family's devices."""
    if _family(dialect):
        return translate("FamilyWords", "Type the devices to watch, e.g. {0}").format(
            _EXAMPLES[_family(dialect)][1])
    return translate("TimeChart", "Type the bits to watch, e.g. R1.4 R1.7 (a value: D10:2)")


def family_title(dialect: str | None) -> str:
    """The PLC family's name: `Delta DVP`, `Fatek FBs`, `FANUC PMC`."""
    found = dialects.get(dialect)
    if found is not None:
        return found.title
    return translate("FamilyWords", "FANUC PMC")


def is_pmc(dialect: str | None) -> bool:
    """True for a PMC program (seed or LADDER-III): A-area alarms, FANUC examples."""
    return dialects.get(dialect) is None
