"""The Fatek FUNs added for issue 37's last part: the table FUNs (FBs-PLC manual §7, "Table
Instructions", FUN 100-113) T→T, the searches R-T_S and T-T_C, T_SHF, T_ROT, QUEUE, STACK and
SORT, the nibble moves FUN 47 UNIT, 48 DIST, FUN 23 DIV48 and 31 CRC16, with their inputs,
operands in the listing's order and FO outputs (docs/dialects.md, Fatek's FUN table).

A control input's two states are the words above and under its slash (`L/R` 1 left, `D/S` 1
different, `A/D` 1 ascending, `I/O` 1 in): the FB-PLC manual's §6.1 rule for `U/D`."""

from __future__ import annotations

from ladderworks.core.dialects.fatek.row_parts import (
    FO,
    MODE,
    SUB_BASE,
    fun_row,
    number,
    register,
    value,
)
from ladderworks.core.instructions import InstructionSpec, Param, ParamAccess

_READ, _BOTH = ParamAccess.READ, ParamAccess.READ_WRITE


def _table(fun: int, name: str, mnemonic: str, title: str, title_tr: str,
           inputs: tuple[str, ...], *params: Param) -> InstructionSpec:
    return fun_row(f"FBS.{name}", SUB_BASE + fun, mnemonic, title, title_tr, inputs=inputs,
                   params=(MODE, *params, FO))


TABLE_ROWS: tuple[InstructionSpec, ...] = (
    # FO0 PEND, FO1 ERR as FUN 100/101 [chosen]
    _table(102, "T_T", "T->T", "Table to table", "TABLODAN TABLOYA", ("EN", "PIN", "CLR"),
           register("Ts", _READ), register("Td"), value("L"), register("Pr", _BOTH)),
    # FO0 FND, FO1 END, FO2 ERR
    _table(105, "R_T_S", "R-T_S", "Table search", "TABLODA ARA", ("EN", "FHD"),
           value("Rs"), register("Ts", _READ), value("L"), register("Pr", _BOTH)),
    _table(106, "T_T_C", "T-T_C", "Table compare", "TABLO KARŞILAŞTIR", ("EN", "FHD", "D/S"),
           register("Ta", _READ), register("Tb", _READ), value("L"), register("Pr", _BOTH)),
    # FO0 ERR
    _table(108, "T_SHF", "T_SHF", "Table shift", "TABLO KAYDIR", ("EN", "L/R"),
           value("IW"), register("Ts", _BOTH), value("L"), register("OW")),
    _table(109, "T_ROT", "T_ROT", "Table rotate", "TABLO DÖNDÜR", ("EN", "L/R"),
           register("Ts", _BOTH), value("L")),
    # FO0 EPT, FO1 FUL, FO2 ERR
    _table(110, "QUEUE", "QUEUE", "Queue (first in, first out)", "KUYRUK (İLK GİREN İLK ÇIKAR)",
           ("EN", "I/O"), value("IW"), register("QU", _BOTH), value("L"), register("Pr", _BOTH),
           register("OW")),
    _table(111, "STACK", "STACK", "Stack (last in, first out)", "YIĞIN (SON GİREN İLK ÇIKAR)",
           ("EN", "I/O"), value("IW"), register("ST", _BOTH), value("L"), register("Pr", _BOTH),
           register("OW")),
    # FO0 ERR [chosen]: Rs, the zone table Ts (L pairs lower, upper), L, the result bits D
    _table(112, "BKCMP", "BKCMP", "Block compare", "BLOK KARŞILAŞTIR", ("EN",),
           value("Rs"), register("Ts", _READ), value("L"), register("output")),
    # FO0 ERR
    _table(113, "SORT", "SORT", "Data sort", "VERİ SIRALA", ("EN", "A/D"),
           register("S", _READ), register("output"), value("L")),
)
# FUN 47 UNIT (S: the first of N registers) and 48 DIST (S: a value), N, D; FO0 ERR
NIBBLE_ROWS: tuple[InstructionSpec, ...] = (
    _table(47, "UNIT", "UNIT", "Nibble unite", "YARIM BAYT BİRLEŞTİR", ("EN",),
           register("S", _READ), value("N"), register("output")),
    _table(48, "DIST", "DIST", "Nibble distribute", "YARIM BAYT DAĞIT", ("EN",),
           value("S"), value("N"), register("output")),
)
# FUN 23 DIV48 (EN, U/S; Sa, Sb, D: three registers each) and 31 CRC16 (MD, S, N, D); FO0
# D=0, FO1 ERR (the FBs manual's pages 7-2 and 7-10)
WIDE_ROWS: tuple[InstructionSpec, ...] = (
    _table(23, "DIV48", "DIV48", "48-bit division", "48 BİTLİK BÖLME", ("EN", "U/S"),
           register("Sa", _READ), register("Sb", _READ), register("output")),
    _table(31, "CRC16", "CRC16", "CRC16 calculation", "CRC16 HESAPLA", ("EN",),
           number("MD", 0, 255), register("S", _READ), value("N"), register("output")),
)
# the modules of core/plc/functions that run them (merged into rows.FAMILIES)
ADDED_FAMILIES: dict[str, tuple[str, ...]] = {
    "fatek_tables": ("FBS.T_T",),
    "fatek_table_ops": tuple(spec.name for spec in TABLE_ROWS if spec.name != "FBS.T_T"),
    "fatek_bits": ("FBS.UNIT", "FBS.DIST"),
    "fatek_data": ("FBS.DIV48",),
    "fatek_convert": ("FBS.CRC16",),
}
