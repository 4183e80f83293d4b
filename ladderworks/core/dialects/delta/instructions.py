"""Delta DVP's rows of the instruction table, and how each Delta mnemonic is spelled and read.

Delta's contacts, coils and ANB/ORB are the table's own basic rows (RD, AND.NOT, WRT, AND.STK
...): the same meaning, spelled LD, ANI, OUT, ANB. What the PMC has no row for is a row here,
named `DVP.<mnemonic>` (its text name, `mnemonic`, is Delta's): MPS/MRD/MPP/INV (stack), edge
and comparison contacts, TMR, CNT, DCNT, RST of a word, MOV and the arithmetic, CMP, ZCP,
MC/MCR, CJ, CALL, SRET, FEND, the pointer line `P n`. Each `LD`-like mnemonic has two rows: one
that starts a network's logic and one (`.STK`) that pushes, as WPLSoft's LD in the middle of a
rung does (ANB/ORB pop it).
"""

from __future__ import annotations

from dataclasses import dataclass

from ladderworks.core.instructions import (
    FUNCTION_OPCODE,
    Combine,
    Flow,
    InstructionSpec,
    Kind,
    Operation,
    Param,
    ParamAccess,
    ParamKind,
    StackOp,
)

DIALECT = "delta"
PREFIX = "DVP."
SUB_BASE = 10_000  # a Delta row's SUB number: 10000 + its API number (11000.. for others)
STK = ".STK"
INT16 = (-32768, 32767)
INT32 = (-(2**31), 2**31 - 1)

# How the reader reads each operand (docs/dialects.md): the devices allowed, and the form.
BIT_IN = "bit"  # a bit device: X, Y, M, S, T, C (contacts)
BIT_OUT = "bit-out"  # a bit device the program writes: Y, M, S
WORD_IN = "value"  # a K/H constant or a word device: T, C, D
WORD_OUT = "word-out"  # a word device the program writes: T, C, D
TIMER = "timer"  # T n
COUNTER = "counter"  # C0..C199
WIDE_COUNTER = "wide-counter"  # C200..C255
RESET = "reset"  # T, C or D (RST of a word)
LABEL = "label"  # P n, a jump target in the main program
PROGRAM = "program"  # P n, a subroutine
NEST = "nest"  # N n, an MC/MCR nesting level


@dataclass(frozen=True, slots=True)
class Spelling:
    """A Delta mnemonic: the part it plays in a rung, its rows, and its operands."""

    role: str  # "load", "contact", "block", "stack", "output", "alone"
    row: str  # the row it reads as
    stk_row: str = ""  # "load": the row when it pushes (an LD in the middle of a rung)
    operands: tuple[str, ...] = ()  # how each operand is read


def _param(name: str, kind: ParamKind, lo: int = 0, hi: int = 0, width: int = 2,
           access: ParamAccess = ParamAccess.READ) -> Param:
    return Param(name, kind, lo, hi, width=width, access=access)


def _value(name: str, lo: int = INT16[0], hi: int = INT16[1], width: int = 2) -> Param:
    return _param(name, ParamKind.VALUE, lo, hi, width)


def _word(name: str, width: int = 2, access: ParamAccess = ParamAccess.WRITE) -> Param:
    return _param(name, ParamKind.ADDRESS, width=width, access=access)


def _bit(name: str, access: ParamAccess = ParamAccess.WRITE) -> Param:
    return _param(name, ParamKind.BIT, access=access)


def _row(mnemonic: str, sub: int, title: str, title_tr: str, *, suffix: str = "",
         inputs: tuple[str, ...] = ("ACT",), params: tuple[Param, ...] = (),
         kind: Kind = Kind.FUNCTION, **fields: object) -> InstructionSpec:
    basic = kind is Kind.BASIC
    opcode = sub if basic else FUNCTION_OPCODE
    return InstructionSpec(PREFIX + mnemonic + suffix, kind, None if basic else sub,
                           inputs=inputs, params=params, title=title, title_tr=title_tr,
                           opcode=opcode, mnemonic=mnemonic, source=DIALECT, dialect=DIALECT,
                           **fields)  # type: ignore[arg-type]


_RW = ParamAccess.READ_WRITE  # a timer's or counter's value, INC/DEC's register

ROWS_LIST: list[InstructionSpec] = []
SPELLINGS: dict[str, Spelling] = {}


def _add(spelling_name: str, role: str, operands: tuple[str, ...],
         *rows: InstructionSpec) -> None:
    ROWS_LIST.extend(rows)
    SPELLINGS[spelling_name] = Spelling(role, rows[0].name, rows[1].name if role == "load" else "",
                                        operands)


# -- contacts, coils and blocks: the table's basic rows, Delta's spelling ----------------------
for _name, (_row_name, _stk_name) in {"LD": ("RD", "RD.STK"),
                                      "LDI": ("RD.NOT", "RD.NOT.STK")}.items():
    SPELLINGS[_name] = Spelling("load", _row_name, _stk_name, (BIT_IN,))
for _name, _row_name in {"AND": "AND", "ANI": "AND.NOT", "OR": "OR", "ORI": "OR.NOT"}.items():
    SPELLINGS[_name] = Spelling("contact", _row_name, "", (BIT_IN,))
SPELLINGS["ANB"] = Spelling("block", "AND.STK")
SPELLINGS["ORB"] = Spelling("block", "OR.STK")
SPELLINGS["OUT"] = Spelling("output", "WRT", "", (BIT_OUT,))
SPELLINGS["SET"] = Spelling("output", "SET", "", (BIT_OUT,))
SPELLINGS["RST"] = Spelling("output", "RST", "", (BIT_OUT,))  # T/C/D: DVP.RST (the reader)

# -- stack operations -------------------------------------------------------------------------
_B = Kind.BASIC
_add("MPS", "stack", (), _row("MPS", 0x40, "Memory push", "YIĞINA İT", kind=_B, inputs=(),
                              pushes=1, stack=StackOp.DUP))
_add("MRD", "stack", (), _row("MRD", 0x41, "Memory read", "YIĞINDAN OKU", kind=_B, inputs=(),
                              stack=StackOp.OVER))
_add("MPP", "stack", (), _row("MPP", 0x42, "Memory pop", "YIĞINDAN ÇEK", kind=_B, inputs=(),
                              pushes=-1, stack=StackOp.DROP))
_add("INV", "stack", (), _row("INV", 0x43, "Inverse", "TERSLE", kind=_B, inputs=(),
                              stack=StackOp.INVERT))

# -- edge contacts and pulse outputs ----------------------------------------------------------
_EDGES = {"P": ("Rising edge", "YÜKSELEN KENAR", Operation.RISING),
          "F": ("Falling edge", "DÜŞEN KENAR", Operation.FALLING)}
_next_sub = SUB_BASE + 1000


def _sub() -> int:
    global _next_sub
    _next_sub += 1
    return _next_sub


for _edge, (_title, _title_tr, _happens) in _EDGES.items():
    _operand = (_bit("device", ParamAccess.READ),)
    _add(f"LD{_edge}", "load", (BIT_IN,),
         _row(f"LD{_edge}", _sub(), f"{_title} contact", f"{_title_tr} KONTAĞI", inputs=(),
              params=_operand, combine=Combine.READ, w1=True, operation=_happens),
         _row(f"LD{_edge}", _sub(), f"{_title} contact", f"{_title_tr} KONTAĞI", suffix=STK,
              inputs=(), params=_operand, combine=Combine.READ, pushes=1, w1=True,
              operation=_happens))
    _add(f"AND{_edge}", "contact", (BIT_IN,),
         _row(f"AND{_edge}", _sub(), f"{_title} contact in series",
              f"{_title_tr} SERİ KONTAK", params=_operand, combine=Combine.AND, w1=True,
              operation=_happens))
    _add(f"OR{_edge}", "contact", (BIT_IN,),
         _row(f"OR{_edge}", _sub(), f"{_title} contact in parallel",
              f"{_title_tr} PARALEL KONTAK", params=_operand, combine=Combine.OR, w1=True,
              operation=_happens))
_add("PLS", "output", (BIT_OUT,), _row("PLS", _sub(), "Rising-edge pulse output",
                                         "YÜKSELEN KENAR ÇIKIŞI", params=(_bit("output"),)))
_add("PLF", "output", (BIT_OUT,), _row("PLF", _sub(), "Falling-edge pulse output",
                                         "DÜŞEN KENAR ÇIKIŞI", params=(_bit("output"),)))

# -- comparison contacts (API 215-246) ---------------------------------------------------------
COMPARISONS = ("=", ">", "<", "<>", "<=", ">=")
_API = {"LD": 215, "AND": 232, "OR": 240}
_OPERANDS2 = (_value("s1"), _value("s2"))
for _offset, _op in enumerate(COMPARISONS):
    _test = Operation(_op)  # the comparison the contact makes (Operation.EQUAL for "=")
    for _start, _api in _API.items():
        _name = _start + _op
        _place = {"LD": "", "AND": " in series", "OR": " in parallel"}[_start]
        _place_tr = {"LD": "", "AND": " (SERİ)", "OR": " (PARALEL)"}[_start]
        _title = f"Compare {_op} contact{_place}"  # as the edge contacts' titles
        _title_tr = f"KARŞILAŞTIRMA KONTAĞI {_op}{_place_tr}"
        if _start == "LD":
            _add(_name, "load", (WORD_IN, WORD_IN),
                 _row(_name, SUB_BASE + _api + _offset, _title, _title_tr, inputs=(),
                      params=_OPERANDS2, combine=Combine.READ, w1=True, operation=_test),
                 _row(_name, SUB_BASE + 500 + _api + _offset, _title, _title_tr, suffix=STK,
                      inputs=(), params=_OPERANDS2, combine=Combine.READ, pushes=1, w1=True,
                      operation=_test))
        else:
            _add(_name, "contact", (WORD_IN, WORD_IN),
                 _row(_name, SUB_BASE + _api + _offset, _title, _title_tr, params=_OPERANDS2,
                      combine=Combine.AND if _start == "AND" else Combine.OR, w1=True,
                      operation=_test))

# -- timers and counters ----------------------------------------------------------------------
_add("TMR", "output", (TIMER, WORD_IN),
     _row("TMR", _sub(), "16-bit timer", "ZAMANLAYICI",
          params=(_word("timer", access=_RW), _value("preset", 0, INT16[1]))))
_add("CNT", "output", (COUNTER, WORD_IN),
     _row("CNT", _sub(), "16-bit counter", "SAYICI",
          params=(_word("counter", access=_RW), _value("preset", 0, INT16[1]))))
_add("DCNT", "output", (WIDE_COUNTER, WORD_IN),
     _row("DCNT", _sub(), "32-bit up/down counter", "32 BİT YUKARI/AŞAĞI SAYICI",
          params=(_word("counter", 4, _RW), _value("preset", INT32[0], INT32[1], 4))))
RESET_ROW = _row("RST", _sub(), "Reset a timer, counter or register", "SIFIRLA",
                 suffix=".WORD", params=(_word("output"),))
ROWS_LIST.append(RESET_ROW)

# -- data: move, arithmetic, compare (API 10-25), each with its pulse form (xxxP) -------------
_DATA: dict[str, tuple[int, Operation, tuple[str, ...], tuple[Param, ...], str, str]] = {
    "CMP": (10, Operation.COMPARE, (WORD_IN, WORD_IN, BIT_OUT),
            (_value("s1"), _value("s2"), _bit("output")), "Compare", "KARŞILAŞTIRMA"),
    "ZCP": (11, Operation.ZONE_COMPARE, (WORD_IN, WORD_IN, WORD_IN, BIT_OUT),
            (_value("low"), _value("high"), _value("input"), _bit("output")),
            "Zone compare", "BÖLGE KARŞILAŞTIRMA"),
    "MOV": (12, Operation.MOVE, (WORD_IN, WORD_OUT), (_value("source"), _word("output")),
            "Move", "TAŞI"),
    "ADD": (20, Operation.ADD, (WORD_IN, WORD_IN, WORD_OUT),
            (_value("s1"), _value("s2"), _word("output")), "Addition", "TOPLAMA"),
    "SUB": (21, Operation.SUBTRACT, (WORD_IN, WORD_IN, WORD_OUT),
            (_value("s1"), _value("s2"), _word("output")), "Subtraction", "ÇIKARTMA"),
    "MUL": (22, Operation.MULTIPLY, (WORD_IN, WORD_IN, WORD_OUT),
            (_value("s1"), _value("s2"), _word("output", 4)),
            "Multiplication (32-bit result)", "ÇARPMA"),
    "DIV": (23, Operation.DIVIDE, (WORD_IN, WORD_IN, WORD_OUT),
            (_value("s1"), _value("s2"), _word("output", 4)),
            "Division (quotient, remainder)", "BÖLME"),
    "INC": (24, Operation.INCREMENT, (WORD_OUT,), (_word("output", access=_RW),),
            "Increment", "ARTTIR"),
    "DEC": (25, Operation.DECREMENT, (WORD_OUT,), (_word("output", access=_RW),),
            "Decrement", "AZALT"),
}
for _name, (_api, _does, _kinds, _params, _title, _title_tr) in _DATA.items():
    _add(_name, "output", _kinds, _row(_name, SUB_BASE + _api, _title, _title_tr,
                                       params=_params, operation=_does))
    _add(_name + "P", "output", _kinds,
         _row(_name + "P", SUB_BASE + 300 + _api, _title + ", on the rising edge",
              _title_tr + " (DARBE)", params=_params, operation=_does, pulse=True))

# -- program control --------------------------------------------------------------------------
_add("CJ", "output", (LABEL,), _row("CJ", SUB_BASE, "Conditional jump", "KOŞULLU ATLAMA",
                                     params=(_param("label", ParamKind.LABEL, 0, 255),),
                                     flow=Flow.LABEL_JUMP))
_add("CALL", "output", (PROGRAM,),
     _row("CALL", SUB_BASE + 1, "Call subroutine", "ALT PROGRAM ÇAĞRISI",
          params=(_param("program", ParamKind.PROGRAM, 0, 255),), flow=Flow.CALL))
_add("SRET", "alone", (), _row("SRET", SUB_BASE + 2, "Subroutine return", "ALT PROGRAM DÖNÜŞÜ",
                               inputs=(), flow=Flow.SUBPROGRAM_END))
_add("FEND", "alone", (), _row("FEND", SUB_BASE + 6, "End of the main program",
                               "ANA PROGRAM SONU", inputs=(), kind=Kind.END,
                               flow=Flow.MAIN_END))
LABEL_ROW = _row("P", _sub(), "Pointer (jump target)", "İŞARETÇİ", inputs=(),
                 params=(_param("label", ParamKind.LABEL, 0, 255),), flow=Flow.LABEL)
SUBROUTINE_ROW = _row("P", _sub(), "Pointer (subroutine start)", "ALT PROGRAM İŞARETÇİSİ",
                      suffix=".SUB", inputs=(),
                      params=(_param("program", ParamKind.PROGRAM, 0, 255),),
                      flow=Flow.SUBPROGRAM)
ROWS_LIST += [LABEL_ROW, SUBROUTINE_ROW]
# MC N: the coils up to its MCR are written 0 while its input is off (the table's COM range:
# `coils` 0 = up to the end instruction; N is the nesting level, kept for the text)
_add("MC", "output", (NEST,), _row("MC", _sub(), "Master control", "ANA KONTROL",
                                    params=(_param("coils", ParamKind.NUMBER, 0, 0),
                                            _param("nest", ParamKind.NUMBER, 0, 7)),
                                    flow=Flow.COMMON, gates_boxes=True))
_add("MCR", "alone", (NEST,), _row("MCR", _sub(), "Master control reset", "ANA KONTROL SONU",
                                    inputs=(), params=(_param("nest", ParamKind.NUMBER, 0, 7),),
                                    flow=Flow.COMMON_END))
SPELLINGS["END"] = Spelling("alone", "END")  # the table's own END (end of program)

DATA_NAMES = tuple(_DATA)  # the data instructions above (their plain and P rows)

# Delta instructions first listed as not simulated (table.py adds rows_extra's list and takes
# out every one read since: NOT_SIMULATED)
LISTED_NOT_SIMULATED: frozenset[str] = frozenset((
    "NOP", "ALT", "ALTP", "EI", "DI", "IRET", "FOR", "NEXT", "WDT", "BMOV", "FMOV", "CML", "XCH",
    "BCD", "BIN", "WAND", "WOR", "WXOR", "NEG", "ROR", "ROL", "RCR", "RCL", "SFTR", "SFTL", "ZRST",
    "DECO", "ENCO", "SUM", "BON", "MEAN", "SQR", "FLT", "REF", "REFF", "MTR", "SPD", "PLSY",
    "PWM", "PLSR", "DRVI", "DRVA", "ZRN", "TKY", "HKY", "DSW", "SEGD", "SEGL", "ARWS", "ASC", "PR",
    "FROM", "TO", "RS", "MODRD", "MODWR", "MODRW", "STMR", "RAMP", "TTMR", "SER", "ABSD", "INCD",
    "IST", "HSCS", "HSCR", "HSZ", "SPD", "ANS", "ANR", "SORT", "TCMP", "TZCP", "TADD", "TSUB",
    "TRD", "TWR", "GRY", "GBIN", "RAND", "DTM", "STOP", "STP", "RET", "PID", "SWAP", "BKCMP",
    "MOVR", "CNT32", "DMOV", "DADD", "DSUB", "DMUL", "DDIV", "DINC", "DDEC", "DCMP", "DZCP",
    "DMOVP", "DADDP", "DSUBP", "DMULP", "DDIVP", "DINCP", "DDECP", "DCMPP", "DZCPP", "STL",
    "CJP", "CALLP",
    *(f"D{start}{op}" for start in ("LD", "AND", "OR") for op in COMPARISONS)))
