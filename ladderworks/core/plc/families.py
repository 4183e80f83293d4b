"""The functional instructions each module of `plc/functions` implements, by name: the checks
read them here to know an instruction has an implementation without loading one (`check` loads
no engine). `plc/functions` keeps them true: its `function` decorator refuses a name that its
module does not declare here, and `load_all` refuses a declared name that nothing registered."""

from __future__ import annotations

from ladderworks.core import dialects

FAMILIES: dict[str, tuple[str, ...]] = {
    "arithmetic": ("ADD", "ADDB", "SUB", "SUBB", "MUL", "MULB", "DIV", "DIVB", "NUME", "NUMEB"),
    "cnc": ("AXCTL", "WINDR", "WINDW", "EXIN", "DISPB"),
    "compare": ("COMP", "COIN", "COMPB", "RNGB", "RNGW", "RNGD"),
    "convert": ("COD", "CODB", "DCNV", "DCNVB"),
    "counters": ("CTR", "CTRC", "CTRB"),
    "decode": ("DEC", "DECB"),
    "edges": ("DIFU", "DIFD"),
    "logic": ("LOGAND", "LOGOR", "EOR", "NOT"),
    "parity": ("PARI",),
    "rotation": ("ROT", "ROTB"),
    "search": ("DSCH", "DSCHB"),
    "shift": ("SFT",),
    "timers": ("TMR", "TMRB", "TMRBF", "TMRC"),
    "transfer": ("MOVE", "MOVOR", "MOVB", "MOVW", "MOVN", "MOVD", "XMOV", "XMOVB"),
}

# Each dialect's families (its `Dialect.families`: which module runs which of its rows).
for _dialect in dialects.every():
    FAMILIES.update(_dialect.families)

# Every functional instruction that has an implementation.
IMPLEMENTED: frozenset[str] = frozenset(name for names in FAMILIES.values() for name in names)
