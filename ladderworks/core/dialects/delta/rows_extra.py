"""Delta DVP rows beyond the first set: the 32-bit D forms, word and bit blocks, logic,
conversion, floating point, special modules and pulse output, each with its pulse form.

Imported by `instructions.py` after its helpers are defined: each row joins its ROWS and
SPELLINGS. `ACTIONS` says what each row does (read by the implementations in
`plc/functions/delta_*.py`, which register by it); `FAMILIES` which module runs it. The
manual's API number of each is in docs/dialects.md ("Every DVP instruction").
"""

from __future__ import annotations

from collections.abc import Callable

from ladderworks.core.dialects.delta.instructions import (
    BIT_IN,
    BIT_OUT,
    COMPARISONS,
    INT16,
    INT32,
    LABEL,
    PROGRAM,
    ROWS_LIST,
    SPELLINGS,
    STK,
    WORD_IN,
    WORD_OUT,
    Spelling,
    _add,
    _bit,
    _param,
    _row,
    _value,
    _word,
)
from ladderworks.core.instructions import (
    Combine,
    Flow,
    InstructionSpec,
    Operation,
    Param,
    ParamAccess,
    ParamKind,
)

# How the reader reads the new operand kinds (reader.py).
VALUE32 = "value32"  # a K/H constant (32-bit) or a word device pair: T, C, D
WORD_OUT32 = "word-out32"  # a word device pair the program writes: T, C, D
DEVICE_OUT = "device-out"  # a bit device Y, M, S or a word device T, C, D (ZRST, DECO's D)
DEVICE_IN = "device-in"  # a bit device X, Y, M, S or a word device T, C, D (ENCO's S)
MODULE = "module"  # a K constant: a special module's number (FROM/TO)
STEP = "step"  # an S device: a step of the step ladder (STL)

_RW = ParamAccess.READ_WRITE
_next = 10_000 + 1200  # these rows' SUB numbers: 11201 on (instructions.py's reach 11030)

ACTIONS: dict[str, str] = {}  # row name -> what it does (the implementations' key)
FAMILIES: dict[str, tuple[str, ...]] = {}


def _sub() -> int:
    global _next
    _next += 1
    return _next


def _v(name: str, wide: bool) -> Param:
    return _value(name, *(INT32 if wide else INT16), width=4 if wide else 2)


def _w(name: str, wide: bool, access: ParamAccess = ParamAccess.WRITE) -> Param:
    return _word(name, 4 if wide else 2, access)


def _any(name: str, access: ParamAccess = ParamAccess.WRITE) -> Param:
    return _param(name, ParamKind.RAW, INT16[0], INT16[1], 2, access)


def _n(name: str, lo: int, hi: int) -> Param:
    return _value(name, lo, hi)


def _box(family: str, action: str, mnemonic: str, title: str, title_tr: str,
         kinds: tuple[str, ...], params: tuple[Param, ...], *, pulse_form: bool = True,
         role: str = "output", inputs: tuple[str, ...] = ("ACT",)) -> None:
    """Add `mnemonic` (and its pulse form `mnemonic`P) run by `family` as `action`."""
    forms = [("", False)] + ([("P", True)] if pulse_form else [])
    for suffix, pulse in forms:
        name = mnemonic + suffix
        row = _row(name, _sub(), title + (", on the rising edge" if pulse else ""),
                   title_tr + (" (DARBE)" if pulse else ""), params=params, pulse=pulse,
                   inputs=inputs)
        _add(name, role, kinds, row)
        ACTIONS[row.name] = action
        FAMILIES[family] = (*FAMILIES.get(family, ()), row.name)


def _both(family: str, action: str, mnemonic: str, title: str, title_tr: str,
          kinds: tuple[str, ...], make: Callable[[bool], tuple[Param, ...]], *,
          pulse_form: bool = True) -> None:
    """A 16-bit instruction and its 32-bit D form: `make(wide)` gives the params."""
    _box(family, action, mnemonic, title, title_tr, kinds, make(False), pulse_form=pulse_form)
    wide = tuple({WORD_IN: VALUE32, WORD_OUT: WORD_OUT32}.get(kind, kind) for kind in kinds)
    _box(family, action + "32", "D" + mnemonic, title + " (32-bit)", title_tr + " (32 BİT)",
         wide, make(True), pulse_form=pulse_form)


# -- 32-bit data: DMOV ... DZCP (the 16-bit forms are instructions.py's) ----------------------
_W32 = "delta_words32"
_box(_W32, "move", "DMOV", "Move (32-bit)", "TAŞI (32 BİT)", (VALUE32, WORD_OUT32),
     (_v("source", True), _w("output", True)))
_box(_W32, "add", "DADD", "Addition (32-bit)", "TOPLAMA (32 BİT)",
     (VALUE32, VALUE32, WORD_OUT32), (_v("s1", True), _v("s2", True), _w("output", True)))
_box(_W32, "subtract", "DSUB", "Subtraction (32-bit)", "ÇIKARTMA (32 BİT)",
     (VALUE32, VALUE32, WORD_OUT32), (_v("s1", True), _v("s2", True), _w("output", True)))
_box(_W32, "multiply", "DMUL", "Multiplication (32-bit, 64-bit result)", "ÇARPMA (32 BİT)",
     (VALUE32, VALUE32, WORD_OUT32), (_v("s1", True), _v("s2", True), _word("output", 8)))
_box(_W32, "divide", "DDIV", "Division (32-bit: quotient, remainder)", "BÖLME (32 BİT)",
     (VALUE32, VALUE32, WORD_OUT32), (_v("s1", True), _v("s2", True), _word("output", 8)))
_box(_W32, "increment", "DINC", "Increment (32-bit)", "ARTTIR (32 BİT)", (WORD_OUT32,),
     (_w("output", True, _RW),))
_box(_W32, "decrement", "DDEC", "Decrement (32-bit)", "AZALT (32 BİT)", (WORD_OUT32,),
     (_w("output", True, _RW),))
_box(_W32, "compare", "DCMP", "Compare (32-bit)", "KARŞILAŞTIRMA (32 BİT)",
     (VALUE32, VALUE32, BIT_OUT), (_v("s1", True), _v("s2", True), _bit("output")))
_box(_W32, "zone", "DZCP", "Zone compare (32-bit)", "BÖLGE KARŞILAŞTIRMA (32 BİT)",
     (VALUE32, VALUE32, VALUE32, BIT_OUT),
     (_v("low", True), _v("high", True), _v("input", True), _bit("output")))

# -- 32-bit comparison contacts DLD= ... DOR>= (run by dvp_contacts, 32-bit by their width) ----
_OPERANDS32 = (_v("s1", True), _v("s2", True))
for _op in COMPARISONS:
    _test = Operation(_op)
    for _start in ("LD", "AND", "OR"):
        _name = f"D{_start}{_op}"
        _place = {"LD": "", "AND": " in series", "OR": " in parallel"}[_start]
        _place_tr = {"LD": "", "AND": " (SERİ)", "OR": " (PARALEL)"}[_start]
        _title = f"Compare {_op} contact{_place} (32-bit)"
        _title_tr = f"KARŞILAŞTIRMA KONTAĞI {_op}{_place_tr} (32 BİT)"
        if _start == "LD":
            _add(_name, "load", (VALUE32, VALUE32),
                 _row(_name, _sub(), _title, _title_tr, inputs=(), params=_OPERANDS32,
                      combine=Combine.READ, w1=True, operation=_test),
                 _row(_name, _sub(), _title, _title_tr, suffix=STK, inputs=(),
                      params=_OPERANDS32, combine=Combine.READ, pushes=1, w1=True,
                      operation=_test))
        else:
            _add(_name, "contact", (VALUE32, VALUE32),
                 _row(_name, _sub(), _title, _title_tr, params=_OPERANDS32,
                      combine=Combine.AND if _start == "AND" else Combine.OR, w1=True,
                      operation=_test))

# -- blocks of words and bits (delta_blocks) --------------------------------------------------
_BL = "delta_blocks"
_box(_BL, "zone-reset", "ZRST", "Zone reset", "BÖLGE SIFIRLA", (DEVICE_OUT, DEVICE_OUT),
     (_any("first"), _any("last")))
_box(_BL, "nothing", "NOP", "No operation", "İŞLEM YOK", (), (), pulse_form=False,
     role="filler", inputs=())
_box(_BL, "nothing", "WDT", "Watchdog timer refresh (no watchdog: nothing)",
     "GÖZCÜ ZAMANLAYICI YENİLE", (), ())
_box(_BL, "block-move", "BMOV", "Block move", "BLOK TAŞI", (WORD_IN, WORD_OUT, WORD_IN),
     (_v("source", False), _w("output", False), _n("count", 1, 512)))
_both(_BL, "fill", "FMOV", "Fill move", "DOLDUR", (WORD_IN, WORD_OUT, WORD_IN),
      lambda wide: (_v("source", wide), _w("output", wide), _n("count", 1, 512)))
_both(_BL, "exchange", "XCH", "Exchange", "DEĞİŞTİR", (WORD_OUT, WORD_OUT),
      lambda wide: (_w("d1", wide, _RW), _w("d2", wide, _RW)))
_box(_BL, "shift-right", "SFTR", "Bit shift right", "BİT KAYDIR SAĞA",
     (BIT_IN, BIT_OUT, WORD_IN, WORD_IN),
     (_bit("source", ParamAccess.READ), _bit("output", _RW), _n("bits", 1, 1024),
      _n("shift", 1, 1024)))
_box(_BL, "shift-left", "SFTL", "Bit shift left", "BİT KAYDIR SOLA",
     (BIT_IN, BIT_OUT, WORD_IN, WORD_IN),
     (_bit("source", ParamAccess.READ), _bit("output", _RW), _n("bits", 1, 1024),
      _n("shift", 1, 1024)))
_box(_BL, "decode", "DECO", "Decode", "ÇÖZ", (WORD_IN, DEVICE_OUT, WORD_IN),
     (_v("source", False), _any("output"), _n("bits", 1, 8)))
_box(_BL, "encode", "ENCO", "Encode", "KODLA", (DEVICE_IN, WORD_OUT, WORD_IN),
     (_any("source", ParamAccess.READ), _w("output", False), _n("bits", 1, 8)))
_box(_BL, "alternate", "ALT", "Alternate (flip-flop)", "DEĞİŞTİR (FLİP-FLOP)", (BIT_OUT,),
     (_bit("output", _RW),))
_both(_BL, "sum", "SUM", "Number of on bits", "AÇIK BİT SAYISI", (WORD_IN, WORD_OUT),
      lambda wide: (_v("source", wide), _w("output", wide)))

# -- word logic and conversion (delta_logic) --------------------------------------------------
_LG = "delta_logic"
for _mnemonic, _action, _title, _title_tr in (
        ("WAND", "and", "Logical AND", "MANTIKSAL VE"),
        ("WOR", "or", "Logical OR", "MANTIKSAL VEYA"),
        ("WXOR", "xor", "Logical exclusive OR", "MANTIKSAL ÖZEL VEYA")):
    _box(_LG, _action, _mnemonic, _title, _title_tr, (WORD_IN, WORD_IN, WORD_OUT),
         (_v("s1", False), _v("s2", False), _w("output", False)))
    _box(_LG, _action + "32", "D" + _mnemonic[1:], _title + " (32-bit)", _title_tr + " (32 BİT)",
         (VALUE32, VALUE32, WORD_OUT32), (_v("s1", True), _v("s2", True), _w("output", True)))
_both(_LG, "negate", "NEG", "Two's complement (negation)", "İŞARET DEĞİŞTİR", (WORD_OUT,),
      lambda wide: (_w("output", wide, _RW),))
_both(_LG, "rotate-right", "ROR", "Rotate right", "SAĞA DÖNDÜR", (WORD_OUT, WORD_IN),
      lambda wide: (_w("output", wide, _RW), _n("bits", 1, 32 if wide else 16)))
_both(_LG, "rotate-left", "ROL", "Rotate left", "SOLA DÖNDÜR", (WORD_OUT, WORD_IN),
      lambda wide: (_w("output", wide, _RW), _n("bits", 1, 32 if wide else 16)))
_both(_LG, "to-bcd", "BCD", "Binary to BCD", "BINARY'DEN BCD'YE", (WORD_IN, WORD_OUT),
      lambda wide: (_v("source", wide), _w("output", wide)))
_both(_LG, "to-binary", "BIN", "BCD to binary", "BCD'DEN BINARY'YE", (WORD_IN, WORD_OUT),
      lambda wide: (_v("source", wide), _w("output", wide)))

# -- more word arithmetic (delta_math) and word shifts, FIFO (delta_words) ------------------------
_MA = "delta_math"
_both(_MA, "complement", "CML", "Complement (NOT)", "TÜMLEYEN", (WORD_IN, WORD_OUT),
      lambda wide: (_v("source", wide), _w("output", wide)))
_both(_MA, "carry-right", "RCR", "Rotate right through the carry", "ELDE İLE SAĞA DÖNDÜR",
      (WORD_OUT, WORD_IN),
      lambda wide: (_w("output", wide, _RW), _n("bits", 1, 32 if wide else 16)))
_both(_MA, "carry-left", "RCL", "Rotate left through the carry", "ELDE İLE SOLA DÖNDÜR",
      (WORD_OUT, WORD_IN),
      lambda wide: (_w("output", wide, _RW), _n("bits", 1, 32 if wide else 16)))
_both(_MA, "bit-on", "BON", "Check a bit", "BİT KONTROL", (WORD_IN, BIT_OUT, WORD_IN),
      lambda wide: (_v("source", wide), _bit("output"), _n("bit", 0, 31 if wide else 15)))
_both(_MA, "mean", "MEAN", "Mean of words", "ORTALAMA", (WORD_IN, WORD_OUT, WORD_IN),
      lambda wide: (_v("source", wide), _w("output", wide), _n("count", 1, 64)))
_both(_MA, "root", "SQR", "Square root", "KAREKÖK", (WORD_IN, WORD_OUT),
      lambda wide: (_v("source", wide), _w("output", wide)))
_both(_MA, "absolute", "ABS", "Absolute value", "MUTLAK DEĞER", (WORD_OUT,),
      lambda wide: (_w("output", wide, _RW),))
_both(_MA, "swap", "SWAP", "Swap the bytes", "BAYT DEĞİŞTİR", (WORD_OUT,),
      lambda wide: (_w("output", wide, _RW),))
_both(_MA, "to-gray", "GRY", "Binary to Gray code", "BINARY'DEN GRAY KODUNA", (WORD_IN, WORD_OUT),
      lambda wide: (_v("source", wide), _w("output", wide)))
_both(_MA, "from-gray", "GBIN", "Gray code to binary", "GRAY KODUNDAN BINARY'YE",
      (WORD_IN, WORD_OUT), lambda wide: (_v("source", wide), _w("output", wide)))
_box(_MA, "digit-move", "SMOV", "Digit move (BCD digits)", "BASAMAK TAŞI",
     (WORD_IN, WORD_IN, WORD_IN, WORD_OUT, WORD_IN),
     (_v("source", False), _n("from", 1, 4), _n("digits", 1, 4), _w("output", False, _RW),
      _n("to", 1, 4)))
for _mnemonic, _action, _title, _title_tr in (
        ("BOUT", "bit-out", "Output a bit of a word", "KELİME BİTİ ÇIKIŞI"),
        ("BSET", "bit-set", "Set a bit of a word", "KELİME BİTİ SET"),
        ("BRST", "bit-reset", "Reset a bit of a word", "KELİME BİTİ RESET")):
    _both(_MA, _action, _mnemonic, _title, _title_tr, (WORD_OUT, WORD_IN),
          lambda wide: (_w("output", wide, _RW), _n("bit", 0, 31 if wide else 15)),
          pulse_form=False)
_box(_MA, "scale", "SCAL", "Scale (slope in thousandths, offset)", "ÖLÇEKLE",
     (WORD_IN, WORD_IN, WORD_IN, WORD_OUT),
     (_v("source", False), _v("slope", False), _v("offset", False), _w("output", False)))
_both(_MA, "scale-table", "SCLP", "Scale by a parameter table", "TABLO İLE ÖLÇEKLE",
      (WORD_IN, WORD_OUT, WORD_OUT),
      lambda wide: (_v("source", wide), _w("table", wide, ParamAccess.READ),
                    _w("output", wide)))
_WO = "delta_words"
for _mnemonic, _action, _title, _title_tr in (
        ("WSFR", "word-right", "Word shift right", "KELİME KAYDIR SAĞA"),
        ("WSFL", "word-left", "Word shift left", "KELİME KAYDIR SOLA")):
    _box(_WO, _action, _mnemonic, _title, _title_tr, (WORD_IN, WORD_OUT, WORD_IN, WORD_IN),
         (_v("source", False), _w("output", False, _RW), _n("words", 1, 512),
          _n("shift", 1, 512)))
_box(_WO, "fifo-write", "SFWR", "Shift register write (FIFO)", "KAYDIRMALI YAZ (FIFO)",
     (WORD_IN, WORD_OUT, WORD_IN), (_v("source", False), _w("output", False, _RW),
                                    _n("count", 2, 512)))
_box(_WO, "fifo-read", "SFRD", "Shift register read (FIFO)", "KAYDIRMALI OKU (FIFO)",
     (WORD_OUT, WORD_OUT, WORD_IN), (_w("source", False, _RW), _w("output", False),
                                     _n("count", 2, 512)))

# -- floating point (delta_float): binary floating point in a D pair, low word first ----------
_FL = "delta_float"
_both(_FL, "float", "FLT", "Integer to floating point", "TAMSAYIDAN KAYAN NOKTAYA",
      (WORD_IN, WORD_OUT32), lambda wide: (_v("source", wide), _w("output", True)))
_box(_FL, "integer", "INT", "Floating point to integer", "KAYAN NOKTADAN TAMSAYIYA",
     (VALUE32, WORD_OUT), (_v("source", True), _w("output", False)))
_box(_FL, "integer32", "DINT", "Floating point to integer (32-bit)",
     "KAYAN NOKTADAN TAMSAYIYA (32 BİT)", (VALUE32, WORD_OUT32),
     (_v("source", True), _w("output", True)))
_box(_FL, "fmove", "DEMOV", "Floating point move", "KAYAN NOKTA TAŞI", (VALUE32, WORD_OUT32),
     (_v("source", True), _w("output", True)))
for _mnemonic, _action, _title, _title_tr in (
        ("DEADD", "fadd", "Floating point addition", "KAYAN NOKTA TOPLAMA"),
        ("DESUB", "fsubtract", "Floating point subtraction", "KAYAN NOKTA ÇIKARTMA"),
        ("DEMUL", "fmultiply", "Floating point multiplication", "KAYAN NOKTA ÇARPMA"),
        ("DEDIV", "fdivide", "Floating point division", "KAYAN NOKTA BÖLME")):
    _box(_FL, _action, _mnemonic, _title, _title_tr, (VALUE32, VALUE32, WORD_OUT32),
         (_v("s1", True), _v("s2", True), _w("output", True)))
_box(_FL, "fcompare", "DECMP", "Floating point compare", "KAYAN NOKTA KARŞILAŞTIRMA",
     (VALUE32, VALUE32, BIT_OUT), (_v("s1", True), _v("s2", True), _bit("output")))
_box(_FL, "fzone", "DEZCP", "Floating point zone compare", "KAYAN NOKTA BÖLGE KARŞILAŞTIRMA",
     (VALUE32, VALUE32, VALUE32, BIT_OUT),
     (_v("low", True), _v("high", True), _v("input", True), _bit("output")))

for _mnemonic, _action, _title, _title_tr in (
        ("DRAD", "radians", "Degrees to radians", "DERECEDEN RADYANA"),
        ("DDEG", "degrees", "Radians to degrees", "RADYANDAN DERECEYE"),
        ("DEXP", "exp", "Exponential", "ÜSTEL"),
        ("DLN", "ln", "Natural logarithm", "DOĞAL LOGARİTMA"),
        ("DESQR", "sqrt", "Floating point square root", "KAYAN NOKTA KAREKÖK"),
        ("DSIN", "sin", "Sine", "SİNÜS"), ("DCOS", "cos", "Cosine", "KOSİNÜS"),
        ("DTAN", "tan", "Tangent", "TANJANT"), ("DASIN", "asin", "Arc sine", "ARK SİNÜS"),
        ("DACOS", "acos", "Arc cosine", "ARK KOSİNÜS"),
        ("DATAN", "atan", "Arc tangent", "ARK TANJANT"),
        ("DSINH", "sinh", "Hyperbolic sine", "HİPERBOLİK SİNÜS"),
        ("DCOSH", "cosh", "Hyperbolic cosine", "HİPERBOLİK KOSİNÜS"),
        ("DTANH", "tanh", "Hyperbolic tangent", "HİPERBOLİK TANJANT")):
    _box(_FL, _action, _mnemonic, _title, _title_tr, (VALUE32, WORD_OUT32),
         (_v("source", True), _w("output", True)))
_box(_FL, "log", "DLOG", "Logarithm", "LOGARİTMA", (VALUE32, VALUE32, WORD_OUT32),
     (_v("base", True), _v("source", True), _w("output", True)))
_box(_FL, "power", "DPOW", "Power", "ÜS ALMA", (VALUE32, VALUE32, WORD_OUT32),
     (_v("base", True), _v("exponent", True), _w("output", True)))
# floating-point contacts FLD= ... FOR>= (API 275-292): run by delta_float (ACTIONS), drawn as
# the comparisons; their operands are named f1, f2 so coding keeps them apart from DLD=
_FLOATS = (_v("f1", True), _v("f2", True))
for _op in COMPARISONS:
    _test = Operation(_op)
    for _start in ("LD", "AND", "OR"):
        _name = f"F{_start}{_op}"
        _place = {"LD": "", "AND": " in series", "OR": " in parallel"}[_start]
        _place_tr = {"LD": "", "AND": " (SERİ)", "OR": " (PARALEL)"}[_start]
        _title = f"Compare {_op} contact{_place} (floating point)"
        _title_tr = f"KARŞILAŞTIRMA KONTAĞI {_op}{_place_tr} (KAYAN NOKTA)"
        _made: tuple[InstructionSpec, ...]
        if _start == "LD":
            _made = (_row(_name, _sub(), _title, _title_tr, inputs=(), params=_FLOATS,
                          combine=Combine.READ, w1=True, operation=_test),
                     _row(_name, _sub(), _title, _title_tr, suffix=STK, inputs=(),
                          params=_FLOATS, combine=Combine.READ, pushes=1, w1=True,
                          operation=_test))
            _add(_name, "load", (VALUE32, VALUE32), *_made)
        else:
            _made = (_row(_name, _sub(), _title, _title_tr, params=_FLOATS,
                          combine=Combine.AND if _start == "AND" else Combine.OR, w1=True,
                          operation=_test),)
            _add(_name, "contact", (VALUE32, VALUE32), *_made)
        for _contact in _made:
            ACTIONS[_contact.name] = "fcontact"
            FAMILIES[_FL] = (*FAMILIES[_FL], _contact.name)

# -- special modules and pulse output (delta_modules) -----------------------------------------
_MD = "delta_modules"
_both(_MD, "from", "FROM", "Read a special module's registers", "ÖZEL MODÜLDEN OKU",
      (MODULE, WORD_IN, WORD_OUT, WORD_IN),
      lambda wide: (_n("module", 0, 7), _v("register", False), _w("output", wide),
                    _n("count", 1, 100)))
_both(_MD, "to", "TO", "Write a special module's registers", "ÖZEL MODÜLE YAZ",
      (MODULE, WORD_IN, WORD_IN, WORD_IN),
      lambda wide: (_n("module", 0, 7), _v("register", False), _v("source", wide),
                    _n("count", 1, 100)))
_both(_MD, "pulses", "PLSY", "Pulse output (pulses counted)", "DARBE ÇIKIŞI",
      (WORD_IN, WORD_IN, BIT_OUT),
      lambda wide: (_value("frequency", 0, 200_000 if wide else 32767, 4 if wide else 2),
                    _value("count", 0, INT32[1] if wide else 32767, 4 if wide else 2),
                    _bit("output")),
      pulse_form=False)

# -- step ladder: STL Sn ... RET (the reader reads STL as LD Sn, a COMMON range gated by it, LD Sn
# again; a range ends at the next STL or RET; SET/OUT of an S device in a step moves on) -------
STEP_ROW = _row("STL", _sub(), "Step ladder: step start", "ADIM BAŞLANGICI",
                params=(_param("coils", ParamKind.NUMBER, 0, 0), _bit("step", ParamAccess.READ)),
                flow=Flow.COMMON, gates_boxes=True)
STEP_NEXT_ROW = _row("STL", _sub(), "Step ladder: end of the step before", "ADIM SONU",
                     suffix=".END", inputs=(), flow=Flow.COMMON_END)
RETURN_ROW = _row("RET", _sub(), "Step ladder: return", "ADIM DÖNÜŞÜ", inputs=(),
                  flow=Flow.COMMON_END)
_add("RET", "alone", (), RETURN_ROW)
ROWS_LIST.extend((STEP_ROW, STEP_NEXT_ROW))
SPELLINGS["STL"] = Spelling("step", STEP_ROW.name, "", (BIT_OUT,))
STEP_MOVES = {"SET": "step-set", "OUT": "step-out"}  # a step's SET/OUT of an S device
STEP_MOVE_ROWS: dict[str, str] = {}
for _mnemonic, _action in STEP_MOVES.items():
    _moving = _row(_mnemonic, _sub(), "Step ladder: move to a step", "ADIMA GEÇ",
                   suffix=".STEP", params=(_bit("step"), _bit("from", _RW)))
    ROWS_LIST.append(_moving)
    STEP_MOVE_ROWS[_mnemonic] = _moving.name
    ACTIONS[_moving.name] = _action
    FAMILIES[_BL] = (*FAMILIES[_BL], _moving.name)

# -- FOR n ... NEXT: FOR is a label (a number no P uses) that keeps its count for the text; NEXT
# is read as a box that counts the runs (on while another run is due) and a jump back to it -----
LOOP_LABELS = 100_000  # the labels of FOR lines: 100000 + their number in the program
_LOOP_LABEL = _param("label", ParamKind.LABEL, LOOP_LABELS, 2**31 - 1)
LOOP_ROW = _row("FOR", _sub(), "Repeat (start)", "TEKRARLA (BAŞLANGIÇ)", inputs=(),
                params=(_LOOP_LABEL, _n("count", 1, 32767)), flow=Flow.LABEL)
LOOP_TEST_ROW = _row("NEXT", _sub(), "Repeat (end): count the runs", "TEKRARLA (SON)",
                     inputs=(), params=(_n("count", 1, 32767),), w1=True)
LOOP_BACK_ROW = _row("NEXT", _sub(), "Repeat (end): back to FOR", "TEKRARLA (GERİ DÖN)",
                     suffix=".JUMP", params=(_LOOP_LABEL,), flow=Flow.LABEL_JUMP)
ROWS_LIST.extend((LOOP_ROW, LOOP_TEST_ROW, LOOP_BACK_ROW))
SPELLINGS["FOR"] = Spelling("loop", LOOP_ROW.name, "", (WORD_IN,))
SPELLINGS["NEXT"] = Spelling("loop", LOOP_TEST_ROW.name)
ACTIONS[LOOP_TEST_ROW.name] = "loop-next"
FAMILIES[_BL] = (*FAMILIES[_BL], LOOP_TEST_ROW.name)

# -- CJP Pn / CALLP Pn: read as a rising-edge box (that keeps the pointer for the text) and the
# CJ / CALL it gates --------------------------------------------------------------------------
PULSED: dict[str, str] = {}  # the edge row's name -> the mnemonic of the jump or call it gates
for _mnemonic, _target, _kind, _title, _title_tr in (
        ("CJP", "CJ", ParamKind.LABEL, "Conditional jump, on the rising edge",
         "KOŞULLU ATLAMA (DARBE)"),
        ("CALLP", "CALL", ParamKind.PROGRAM, "Call subroutine, on the rising edge",
         "ALT PROGRAM ÇAĞRISI (DARBE)")):
    _edge = _row(_mnemonic, _sub(), _title, _title_tr, params=(_param("pointer", _kind, 0, 255),),
                 w1=True, pulse=True)
    _add(_mnemonic, "output", (LABEL if _kind is ParamKind.LABEL else PROGRAM,), _edge)
    PULSED[_edge.name] = _target
    ACTIONS[_edge.name] = "edge"
    FAMILIES[_BL] = (*FAMILIES[_BL], _edge.name)

# Mnemonics of the manual's instruction list not simulated (docs/dialects.md says why): a
# "not simulated" diagnostic rather than "unknown" (with those instructions.py lists).
MORE_NOT_SIMULATED: frozenset[str] = frozenset(
    f"{d}{name}{p}" for name in (
        "ANS", "ANR", "SER", "ABSD", "INCD", "TTMR", "STMR", "RAMP", "DTM", "SORT", "ASCI",
        "HEX", "CCD", "VRRD", "VRSC", "PID", "MODRD", "MODWR", "MODRW", "FWD", "REV", "RDST",
        "RSTEF", "LRC", "CRC", "SWRD", "RAD", "DEG", "EBCD", "EBIN", "EXP", "LN", "LOG", "ESQR",
        "POW", "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SINH", "COSH", "TANH", "DELAY",
        "GPWM", "FTC", "CVM", "MEMR", "MEMW", "PWD", "RTMU", "RTMD", "RAND", "ABSR",
        "PLSV", "TCMP", "TZCP", "TADD", "TSUB", "TRD", "TWR", "MVM", "HOUR", "ADDR", "SUBR",
        "MULR", "DIVR", "MMOV", "GPS", "SPA", "WSUM", "MAND", "MOR", "MXOR",
        "MXNR", "MINV", "MCMP", "MBRD", "MBWR", "MBC", "PPMR", "PPMA", "CIMR", "CIMA", "PTPO",
        "HST", "CLLM", "VSPO", "ICF", "CMPT", "ASDRW", "CSFO", "REF", "REFF",
        "MTR", "HSCS", "HSCR", "HSZ", "SPD", "PWM", "PLSR", "IST", "TKY", "HKY", "DSW", "SEGD",
        "SEGL", "ARWS", "ASC", "PR", "RS", "PRUN", "DRVI", "DRVA", "ZRN")
    for d in ("", "D") for p in ("", "P")) | frozenset((
        "EI", "DI", "IRET", "BLD", "BLDI", "BAND", "BANI", "BOR", "BORI",
        *(f"{start}{op}" for start in ("LD", "AND", "OR") for op in ("&", "|", "^")),
        *(f"D{start}{op}" for start in ("LD", "AND", "OR") for op in ("&", "|", "^"))))

# BIT_IN is the source of SFTR/SFTL; kept here so the reader's table names every kind used.
KINDS_USED = (BIT_IN, BIT_OUT, WORD_IN, WORD_OUT, VALUE32, WORD_OUT32, DEVICE_OUT, DEVICE_IN,
              MODULE)
