"""The Fatek rows of the instruction table: the boxes a Fatek program becomes in the engine
(timers, counters, RST, TU/TD and comparison contacts, FUN boxes), with their FUN numbers."""

from __future__ import annotations

from dataclasses import replace

from ladderworks.core.dialects.fatek.row_parts import FO, MODE, OTHER, SUB_BASE
from ladderworks.core.dialects.fatek.row_parts import fun_row as _row
from ladderworks.core.dialects.fatek.row_parts import number as _number
from ladderworks.core.dialects.fatek.row_parts import register as _register
from ladderworks.core.dialects.fatek.row_parts import value as _value
from ladderworks.core.dialects.fatek.rows_tables import (
    ADDED_FAMILIES,
    NIBBLE_ROWS,
    TABLE_ROWS,
    WIDE_ROWS,
)
from ladderworks.core.instruction_fields import Operation
from ladderworks.core.instructions import (
    FUNCTION_OPCODE,
    Combine,
    InstructionSpec,
    Kind,
    Param,
    ParamAccess,
    ParamKind,
    StackOp,
    Write,
)

__all__ = ["OTHER", "SUB_BASE"]  # the SUB numbers, for the modules that read them here


# A parameter's label on its operand line where Fatek's differs from the row's name
_LABELS = {"output": "D", "preset": "PV"}


def operand_label(name: str) -> str:
    """The operand line's label of a row parameter: `D` for the destination, `PV` for a
    preset (FUN 7 UDCTR's `PV: 10`, the FBs manual §5.1), else the parameter's name."""
    return _LABELS.get(name, name)


# `OUT L` (retentive coil, Y only, 002:98): a basic row of its own, so a changed network is
# written `OUT L` again; it runs as WRT (no power loss is simulated). Fatek's basic opcodes 0x50..
RETENTIVE = InstructionSpec("FBS.OUTL", Kind.BASIC, operand=True, writes=True, write=Write.OUT,
                            opcode=0x50, title="Retentive output", title_tr="KALICI ÇIKIŞ",
                            mnemonic="OUT L", source="fatek", dialect="fatek")

def _logic_row(name: str, fun: int, mnemonic: str, title: str, title_tr: str
               ) -> InstructionSpec:
    return _row(name, SUB_BASE + fun, mnemonic, title, title_tr,
                params=(MODE, _value("Sa"), _value("Sb"), _register("output"), FO))


def _table_row(name: str, fun: int, mnemonic: str, title: str, title_tr: str,
               *names: str) -> InstructionSpec:
    """A table box: its operands (`Ts`, `Td`, `L`, `D` …: a table's first register, a length,
    a value) and FO0 ERR."""
    kinds = {"Ts": _register("Ts", ParamAccess.READ), "Td": _register("Td"),
             "Ta": _register("Ta", ParamAccess.READ_WRITE),
             "Tb": _register("Tb", ParamAccess.READ_WRITE),
             "L": _value("L"), "S": _value("S"), "output": _register("output")}
    return _row(name, SUB_BASE + fun, mnemonic, title, title_tr,
                params=(MODE, *(kinds[n] for n in names), FO))


def _mover_row(name: str, fun: int, mnemonic: str, title: str, title_tr: str,
               inputs: tuple[str, ...]) -> InstructionSpec:
    return _row(name, SUB_BASE + fun, mnemonic, title, title_tr, inputs=inputs,
                params=(MODE, _register("output", ParamAccess.READ_WRITE), _value("N"), FO))


# The word and table FUNs (fatek_words.py, fatek_tables.py; docs/dialects.md's FUN table)
WORD_ROWS: tuple[InstructionSpec, ...] = (
    _logic_row("FBS.AND", 18, "AND", "Logical AND", "MANTIKSAL VE"),
    _logic_row("FBS.OR", 19, "OR", "Logical OR", "MANTIKSAL VEYA"),
    _logic_row("FBS.XOR", 35, "XOR", "Exclusive OR", "ÖZEL VEYA"),
    _logic_row("FBS.XNR", 36, "XNR", "Exclusive NOR", "ÖZEL VEYA DEĞİL"),
    _row("FBS.SQRT", SUB_BASE + 26, "SQRT", "Square root", "KAREKÖK",
         params=(MODE, _value("S"), _register("output"), FO)),
    _row("FBS.NEG", SUB_BASE + 27, "NEG", "Negate", "İŞARET DEĞİŞTİR",
         params=(MODE, _register("output", ParamAccess.READ_WRITE)), w1=False),
    _row("FBS.ABS", SUB_BASE + 28, "ABS", "Absolute value", "MUTLAK DEĞER",
         params=(MODE, _register("output", ParamAccess.READ_WRITE)), w1=False),
    _row("FBS.EXT", SUB_BASE + 29, "EXT", "Sign extension", "İŞARET GENİŞLET",
         params=(MODE, _register("output", ParamAccess.READ_WRITE)), w1=False),
    _mover_row("FBS.SHFL", 51, "SHFL", "Shift left", "SOLA KAYDIR", ("EN", "INB")),
    _mover_row("FBS.SHFR", 52, "SHFR", "Shift right", "SAĞA KAYDIR", ("EN", "INB")),
    _mover_row("FBS.ROTL", 53, "ROTL", "Rotate left", "SOLA DÖNDÜR", ("EN",)),
    _mover_row("FBS.ROTR", 54, "ROTR", "Rotate right", "SAĞA DÖNDÜR", ("EN",)),
    _row("FBS.MOVN", SUB_BASE + 9, "MOV/", "Move inverted", "TERS TAŞI",
         params=(MODE, _value("S"), _register("output")), w1=False),
    _row("FBS.TOGG", SUB_BASE + 10, "TOGG", "Toggle", "DEĞİŞTİR (TOGGLE)",
         params=(MODE, Param("output", ParamKind.BIT, access=ParamAccess.READ_WRITE), FO)),
    _row("FBS.ZNCMP", SUB_BASE + 37, "ZNCMP", "Zone compare", "BÖLGE KARŞILAŞTIR",
         params=(MODE, _value("S"), _value("SU"), _value("SL"), FO)),
    _row("FBS.BITRD", SUB_BASE + 40, "BITRD", "Bit read", "BİT OKU",
         params=(MODE, _value("S"), _value("N"), FO)),
    _row("FBS.BITWR", SUB_BASE + 41, "BITWR", "Bit write", "BİT YAZ", inputs=("EN", "INB"),
         params=(MODE, _register("output", ParamAccess.READ_WRITE), _value("N")), w1=False),
    *(_row(name, SUB_BASE + fun, mnemonic, title, title_tr,
           params=(MODE, _value("S"), _value("Ns"), _register("output", ParamAccess.READ_WRITE),
                   _value("Nd")), w1=False)
      for name, fun, mnemonic, title, title_tr in (
          ("FBS.BITMV", 42, "BITMV", "Bit move", "BİT TAŞI"),
          ("FBS.NBMV", 43, "NBMV", "Nibble move", "YARIM BAYT TAŞI"),
          ("FBS.BYMV", 44, "BYMV", "Byte move", "BAYT TAŞI"))),
    _row("FBS.XCHG", SUB_BASE + 45, "XCHG", "Exchange", "DEĞİŞ TOKUŞ",
         params=(MODE, _register("Da", ParamAccess.READ_WRITE),
                 _register("Db", ParamAccess.READ_WRITE)), w1=False),
    _row("FBS.SWAP", SUB_BASE + 46, "SWAP", "Swap bytes", "BAYTLARI DEĞİŞTİR",
         params=(MODE, _register("output", ParamAccess.READ_WRITE)), w1=False),
    _table_row("FBS.SUM", 24, "SUM", "Table sum", "TABLO TOPLAMI", "Ts", "L", "output"),
    _table_row("FBS.MEAN", 25, "MEAN", "Table mean", "TABLO ORTALAMASI", "Ts", "L", "output"),
    _row("FBS.R_T", SUB_BASE + 100, "R->T", "Register to table", "YAZMAÇTAN TABLOYA",
         inputs=("EN", "PIN", "CLR"),
         params=(MODE, _value("Rs"), _register("Td"), _value("L"),
                 _register("Pr", ParamAccess.READ_WRITE), FO)),
    _row("FBS.T_R", SUB_BASE + 101, "T->R", "Table to register", "TABLODAN YAZMACA",
         inputs=("EN", "PIN", "CLR"),
         params=(MODE, _register("Ts", ParamAccess.READ), _value("L"),
                 _register("Pr", ParamAccess.READ_WRITE), _register("Rd"), FO)),
    _table_row("FBS.BT_M", 103, "BT_M", "Table block move", "TABLO BLOK TAŞI", "Ts", "Td", "L"),
    _table_row("FBS.T_SWP", 104, "T_SWP", "Table swap", "TABLO DEĞİŞ TOKUŞ", "Ta", "Tb", "L"),
    _table_row("FBS.T_FIL", 107, "T_FIL", "Table fill", "TABLO DOLDUR", "S", "Td", "L"),
)
TABLE_FAMILY = ("FBS.SUM", "FBS.MEAN", "FBS.R_T", "FBS.T_R", "FBS.BT_M", "FBS.T_SWP",
                "FBS.T_FIL")
BITS_FAMILY = ("FBS.MOVN", "FBS.TOGG", "FBS.ZNCMP", "FBS.BITRD", "FBS.BITWR", "FBS.BITMV",
               "FBS.NBMV", "FBS.BYMV", "FBS.XCHG", "FBS.SWAP")
WORD_FAMILY = tuple(spec.name for spec in WORD_ROWS
                    if spec.name not in TABLE_FAMILY + BITS_FAMILY)



def _branch_row(name: str, opcode: int, mnemonic: str, title: str, title_tr: str,
                stack: StackOp, pushes: int) -> InstructionSpec:
    return InstructionSpec(name, Kind.BASIC, params=(_number("tr", 0, 39),), pushes=pushes,
                           stack=stack, opcode=opcode, title=title, title_tr=title_tr,
                           mnemonic=mnemonic, source="fatek", dialect="fatek")


# A TR point as a rung's branch point (`OUT TR n` … `LD TR n`, docs/dialects.md): the result
# kept on the stack (as Delta's MPS / MRD / MPP), the point's number kept to print it again
BRANCH_ROWS = (
    _branch_row("FBS.TRPUSH", 0x51, "OUT TR", "Branch point (TR)", "DALLANMA NOKTASI (TR)",
                StackOp.DUP, 1),
    _branch_row("FBS.TRREAD", 0x52, "LD TR", "Next branch (TR)", "SONRAKİ DAL (TR)",
                StackOp.OVER, 0),
    _branch_row("FBS.TRLAST", 0x53, "LD TR", "Last branch (TR)", "SON DAL (TR)",
                StackOp.DROP, -1),
)

# FUN n of the listing -> the row it becomes
ROWS: tuple[InstructionSpec, ...] = (
    RETENTIVE,
    *BRANCH_ROWS,
    _row("FBS.TMR", OTHER, "TMR", "Timer", "ZAMANLAYICI",
         params=(_number("timer", 0, 255), _value("preset"), FO)),
    _row("FBS.CTR", OTHER + 1, "CTR", "Counter", "SAYICI", inputs=("CK", "CLR"),
         params=(_number("counter", 0, 255), _value("preset"), FO)),
    _row("FBS.UDCTR", SUB_BASE + 7, "UDCTR", "Up/down counter", "YUKARI-AŞAĞI SAYICI",
         inputs=("CK", "U/D", "CLR"),
         params=(_register("CV", ParamAccess.READ_WRITE), _value("preset"), FO)),
    _row("FBS.RST", OTHER + 2, "RST", "Reset a timer or counter", "ZAMANLAYICI/SAYICI SIFIRLA",
         params=(_number("kind", 0, 1), _number("number", 0, 255)), w1=False),
    _row("FBS.TU", OTHER + 3, "TU", "Rising edge contact", "YÜKSELEN KENAR KONTAĞI", inputs=("IN",),
         params=(Param("device", ParamKind.BIT),), operation=Operation.RISING),
    _row("FBS.TD", OTHER + 4, "TD", "Falling edge contact", "DÜŞEN KENAR KONTAĞI", inputs=("IN",),
         params=(Param("device", ParamKind.BIT),), operation=Operation.FALLING),
    _row("FBS.MOV", SUB_BASE + 8, "MOV", "Move", "TAŞI",
         params=(MODE, _value("S"), _register("output")), w1=False),
    _row("FBS.ADD", SUB_BASE + 11, "(+)", "Addition", "TOPLAMA",
         params=(MODE, _value("Sa"), _value("Sb"), _register("output"), FO)),
    _row("FBS.SUB", SUB_BASE + 12, "(-)", "Subtraction", "ÇIKARMA",
         params=(MODE, _value("Sa"), _value("Sb"), _register("output"), FO)),
    _row("FBS.MUL", SUB_BASE + 13, "(*)", "Multiplication", "ÇARPMA",
         params=(MODE, _value("Sa"), _value("Sb"), _register("output"), FO)),
    _row("FBS.DIV", SUB_BASE + 14, "(/)", "Division", "BÖLME",
         params=(MODE, _value("Sa"), _value("Sb"), _register("output"), FO)),
    _row("FBS.INC", SUB_BASE + 15, "(+1)", "Increment", "BİR ARTIR",
         params=(MODE, _register("output", ParamAccess.READ_WRITE), FO)),
    _row("FBS.DEC", SUB_BASE + 16, "(-1)", "Decrement", "BİR AZALT",
         params=(MODE, _register("output", ParamAccess.READ_WRITE), FO)),
    _row("FBS.CMP", SUB_BASE + 17, "CMP", "Compare", "KARŞILAŞTIR",
         params=(MODE, _value("Sa"), _value("Sb"), FO)),
    _row("FBS.BCD", SUB_BASE + 20, "BCD", "Binary to BCD", "İKİLİDEN BCD'YE",
         params=(MODE, _value("S"), _register("output"), FO)),
    _row("FBS.BIN", SUB_BASE + 21, "BIN", "BCD to binary", "BCD'DEN İKİLİYE",
         params=(MODE, _value("S"), _register("output"), FO)),
    *WORD_ROWS,
    *NIBBLE_ROWS,
    *WIDE_ROWS,
    *TABLE_ROWS,
    _row("FBS.ASCWR", SUB_BASE + 94, "ASCWR", "ASCII write", "ASCII YAZ",
         inputs=("EN", "PAU", "ABT"),
         params=(_number("MD", 0, 255), _register("S", ParamAccess.READ),
                 _register("Pt", ParamAccess.READ_WRITE), FO)),
    *(_row(name, SUB_BASE + fun, symbol, f"Compare contact {symbol}",
           f"KARŞILAŞTIRMA KONTAĞI {symbol}", inputs=("IN",),
           params=(MODE, _value("Sa"), _value("Sb")), operation=Operation(symbol[1:-1]))
      for fun, name, symbol in ((170, "FBS.EQ", "(=)"), (171, "FBS.GT", "(>)"),
                                (172, "FBS.LT", "(<)"), (173, "FBS.NE", "(<>)"),
                                (174, "FBS.GE", "(>=)"), (175, "FBS.LE", "(<=)"))),
    # drawn and kept, not simulated (a warning at their line; FO stay 0). Inputs as
    # WinProladder's printout draws them: HSPSO EN, PAU, ABT (outputs ACT, ERR, DN = FO0-FO2)
    *(_row(name, SUB_BASE + fun, mnemonic, title, title_tr, params=(_number("fun", 0, 999), FO),
           cnc=True, inputs=inputs)
      for fun, name, mnemonic, title, title_tr, inputs in (
          (140, "FBS.HSPSO", "HSPSO", "High-speed pulse output", "YÜKSEK HIZLI DARBE ÇIKIŞI",
           ("EN", "PAU", "ABT")),
          (141, "FBS.MPARA", "MPARA", "Positioning parameters", "KONUMLAMA PARAMETRELERİ",
           ("EN",)),
          (142, "FBS.PSOFF", "PSOFF", "Stop the pulse output", "DARBE ÇIKIŞINI DURDUR", ("EN",)),
          (143, "FBS.PSCNV", "PSCNV", "Pulse position to a value", "DARBE KONUMUNU DEĞERE ÇEVİR",
           ("EN",)),
          (176, "FBS.176", "FUN 176", "FUN 176", "FUN 176", ("EN",)))),
    # any other FUN n a program holds: kept, drawn as a box with up to 4 inputs, run as nothing
    _row("FBS.FUN", OTHER + 5, "FUN", "Function not simulated", "BENZETİLMEYEN FONKSİYON",
         inputs=("EN", "IN2", "IN3", "IN4"), params=(_number("fun", 0, 999), FO), cnc=True),
)
UNKNOWN_FUN = "FBS.FUN"  # the row of a FUN the table has no row for

# The edge and comparison contacts in their other places (issue 38): `ORG TU X2` / `ORGF 170`
# starting a rung (READ), `LD TU` / `LDF` pushing a block (READ, push), `OR TU` / `ORF` in
# parallel (OR). The series rows above are the AND place. Named `FBS.TU.ORG`, `.LD`, `.OR`.
PLACES = (("ORG", Combine.READ, 0), ("LD", Combine.READ, 1), ("OR", Combine.OR, 0))


def _placed(series: InstructionSpec, index: int, place: str, combine: Combine,
            pushes: int) -> InstructionSpec:
    return InstructionSpec(
        f"{series.name}.{place}", Kind.FUNCTION, OTHER + 10 + index,
        inputs=("IN",) if combine is Combine.OR else (), params=series.params, w1=True,
        title=series.title, title_tr=series.title_tr, opcode=FUNCTION_OPCODE,
        mnemonic=series.mnemonic, source="fatek", dialect="fatek", operation=series.operation,
        combine=combine, pushes=pushes)


_SERIES = tuple(spec for spec in ROWS if spec.inputs == ("IN",))
PLACED: tuple[InstructionSpec, ...] = tuple(
    _placed(series, 3 * k + j, place, combine, pushes)
    for k, series in enumerate(_SERIES)
    for j, (place, combine, pushes) in enumerate(PLACES))
ROWS = (*ROWS, *PLACED)
# a series contact row's row for a place: FORMS["FBS.TU"]["ORG"]
FORMS: dict[str, dict[str, InstructionSpec]] = {
    series.name: {place: spec for spec in PLACED
                  for place in (spec.name.rsplit(".", 1)[1],)
                  if spec.name.rsplit(".", 1)[0] == series.name}
    for series in _SERIES}
SERIES_OF: dict[str, InstructionSpec] = {  # a placed row's series row (its FUN number, spelling)
    spec.name: series for series in _SERIES for spec in FORMS[series.name].values()}

BY_FUN: dict[int, InstructionSpec] = {
    spec.sub - SUB_BASE: spec for spec in ROWS if spec.sub is not None and spec.sub < OTHER}
# the FUNs run as nothing (their FO stay 0): `simulated` False, so the checks warn and a run
# names them (core/compiler/skipped.py), as for Delta's shown-only rows
ROWS = tuple(replace(spec, simulated=False) if spec.cnc else spec for spec in ROWS)
BY_FUN = {number: replace(spec, simulated=False) if spec.cnc else spec
          for number, spec in BY_FUN.items()}
NOT_SIMULATED: frozenset[str] = frozenset(spec.name for spec in ROWS if spec.cnc)


COMPARISON_FUNS = range(170, 176)

# The modules of core/plc/functions that run these rows (merged into core/plc/families.py)
FAMILIES: dict[str, tuple[str, ...]] = {
    "fatek_data": ("FBS.MOV", "FBS.ADD", "FBS.SUB", "FBS.MUL", "FBS.DIV", "FBS.INC", "FBS.DEC",
                   "FBS.CMP", "FBS.EQ", "FBS.GT", "FBS.LT", "FBS.NE", "FBS.GE", "FBS.LE"),
    "fatek_io": ("FBS.ASCWR", "FBS.HSPSO", "FBS.MPARA", "FBS.PSOFF", "FBS.PSCNV", "FBS.176",
                 "FBS.FUN"),
    "fatek_convert": ("FBS.BCD", "FBS.BIN"),
    "fatek_words": WORD_FAMILY,
    "fatek_tables": TABLE_FAMILY,
    "fatek_bits": BITS_FAMILY,
    "fatek_contacts": tuple(spec.name for spec in PLACED),
    "fatek_timing": ("FBS.TMR", "FBS.CTR", "FBS.UDCTR", "FBS.RST", "FBS.TU", "FBS.TD"),
}
for _module, _names in ADDED_FAMILIES.items():
    FAMILIES[_module] = (*FAMILIES.get(_module, ()), *_names)
