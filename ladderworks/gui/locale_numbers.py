"""Numbers as the UI language writes them: a decimal comma in Turkish (0,125 ms; %150)."""

from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtCore import QCoreApplication, QLocale


def decimal(value: float, places: int) -> str:
    """`value` with `places` decimals in the UI language (`0,125` in Turkish), no grouping."""
    locale = QLocale()
    locale.setNumberOptions(QLocale.NumberOption.OmitGroupSeparator)
    return locale.toString(float(value), "f", places)


def percent(value: float) -> str:
    """A percentage as the UI language writes it (`150%`, Turkish `%150`)."""
    return QCoreApplication.translate("Numbers", "{0}%").format(decimal(value, 0))


class LocaleAxis(pg.AxisItem):
    """A chart axis whose tick labels use the UI language's decimal sign."""

    def tickStrings(self, values: list[float], scale: float, spacing: float) -> list[str]:
        """Tick labels with as many decimals as the spacing needs."""
        places = 0
        step = spacing * scale
        while places < 6 and step * 10 ** places < 1 - 1e-9:
            places += 1
        return [decimal(value * scale, places) for value in values]
