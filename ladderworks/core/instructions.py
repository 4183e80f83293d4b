"""The instruction table: every basic and functional instruction, read by every other part."""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum


class Kind(StrEnum):
    """What sort of instruction a row is."""

    BASIC = "basic"  # bit logic on the result stack
    FUNCTION = "function"  # a functional instruction (box in the ladder)
    END = "end"  # END1 / END2 / END


class ParamKind(StrEnum):
    """What a parameter holds."""

    NUMBER = "number"  # an integer constant with a range
    ADDRESS = "address"  # a byte address whose data has `width` bytes
    VALUE = "value"  # a constant or an address, chosen by a format parameter
    MASK = "mask"  # up to 4 binary digits (MOVE masks), printed as 4 digits
    TABLE = "table"  # a list of constants, its length given by another parameter


@dataclass(frozen=True, slots=True)
class Param:
    """One parameter of a functional instruction."""

    name: str
    kind: ParamKind
    lo: int = 0
    hi: int = 0
    width: int | str = 1  # bytes of addressed data, or the name of the format param giving it
    choices: tuple[int, ...] = ()
    length_of: str = ""  # TABLE: the NUMBER param giving the number of entries

    def allows_address(self) -> bool:
        """True if an address may be written here."""
        return self.kind in (ParamKind.ADDRESS, ParamKind.VALUE)


@dataclass(frozen=True, slots=True)
class InstructionSpec:
    """One row of the table."""

    name: str
    kind: Kind
    sub: int | None = None  # FANUC SUB number
    operand: bool = False  # basic: takes a bit address
    pushes: int = 0  # basic: change of stack depth (+1 push, -1 pop)
    writes: bool = False  # basic: writes its operand (WRT, WRT.NOT)
    inputs: tuple[str, ...] = ()  # control inputs, first -> last; the last (ACT) ends in ST0
    params: tuple[Param, ...] = ()
    w1: bool = False  # has a W1 output left in ST0
    title: str = ""  # English title
    title_tr: str = ""  # Turkish title, the seed manual's words

    @property
    def help_key(self) -> str:
        """Key of the instruction's entry in docs/instructions.md and the help browser."""
        return "instr-" + self.name.lower().replace(".", "-")

    @property
    def is_function(self) -> bool:
        """True for functional instructions."""
        return self.kind is Kind.FUNCTION

    def param(self, name: str) -> Param:
        """The parameter called `name`."""
        for param in self.params:
            if param.name == name:
                return param
        raise KeyError(name)

    def fixed_params(self) -> tuple[Param, ...]:
        """The parameters that are not a table."""
        return tuple(p for p in self.params if p.kind is not ParamKind.TABLE)

    def table_param(self) -> Param | None:
        """The TABLE parameter, if the instruction has one."""
        for param in self.params:
            if param.kind is ParamKind.TABLE:
                return param
        return None


MAX32 = 99_999_999
FORMAT_124 = (1, 2, 4)


def _num(name: str, lo: int, hi: int) -> Param:
    return Param(name, ParamKind.NUMBER, lo, hi)


def _fmt(name: str = "format") -> Param:
    return Param(name, ParamKind.NUMBER, 1, 4, choices=FORMAT_124)


def _addr(name: str, width: int | str = 1) -> Param:
    return Param(name, ParamKind.ADDRESS, width=width)


def _value(name: str, width: int | str = 2) -> Param:
    return Param(name, ParamKind.VALUE, -MAX32, MAX32, width=width)


# Binary arithmetic/compare format: thousands digit 0 = constant, 1 = address; units 1/2/4 bytes.
ARITH_FORMATS = (1, 2, 4, 1001, 1002, 1004)

_BASIC: tuple[InstructionSpec, ...] = (
    InstructionSpec("RD", Kind.BASIC, operand=True, pushes=0,
                    title="Read", title_tr="OKU"),
    InstructionSpec("RD.NOT", Kind.BASIC, operand=True, pushes=0,
                    title="Read inverted", title_tr="TERS OKU"),
    InstructionSpec("WRT", Kind.BASIC, operand=True, writes=True,
                    title="Write", title_tr="YAZ"),
    InstructionSpec("WRT.NOT", Kind.BASIC, operand=True, writes=True,
                    title="Write inverted", title_tr="TERS YAZ"),
    InstructionSpec("AND", Kind.BASIC, operand=True, title="And", title_tr="VE"),
    InstructionSpec("AND.NOT", Kind.BASIC, operand=True,
                    title="And inverted", title_tr="VE DEĞİL"),
    InstructionSpec("OR", Kind.BASIC, operand=True, title="Or", title_tr="VEYA"),
    InstructionSpec("OR.NOT", Kind.BASIC, operand=True,
                    title="Or inverted", title_tr="VEYA DEĞİL"),
    InstructionSpec("RD.STK", Kind.BASIC, operand=True, pushes=1,
                    title="Push and read", title_tr="İTEKLE VE OKU"),
    InstructionSpec("RD.NOT.STK", Kind.BASIC, operand=True, pushes=1,
                    title="Push and read inverted", title_tr="İTEKLE VE TERS OKU"),
    InstructionSpec("AND.STK", Kind.BASIC, pushes=-1,
                    title="And with stack, pop", title_tr="YIĞIN VE"),
    InstructionSpec("OR.STK", Kind.BASIC, pushes=-1,
                    title="Or with stack, pop", title_tr="YIĞIN VEYA"),
)

_F = Kind.FUNCTION

_FUNCTIONS: tuple[InstructionSpec, ...] = (
    InstructionSpec("TMR", _F, 3, inputs=("ACT",), params=(_num("timer", 1, 100),), w1=True,
                    title="Timer", title_tr="ZAMANLAYICI"),
    InstructionSpec("TMRB", _F, 24, inputs=("ACT",),
                    params=(_num("timer", 1, 100), _num("preset", 0, MAX32)), w1=True,
                    title="Fixed timer", title_tr="STATİK ZAMANLAYICI"),
    InstructionSpec("TMRC", _F, 54, inputs=("ACT",),
                    params=(_num("accuracy", 0, 1), _addr("preset", 2), _addr("register", 4)),
                    w1=True, title="Timer (preset at an address)", title_tr="ZAMANLAYICI"),
    InstructionSpec("DEC", _F, 4, inputs=("ACT",),
                    params=(_addr("code", 1), _num("spec", 0, 9911)), w1=True,
                    title="Decode (BCD)", title_tr="KOD ÇÖZÜCÜ"),
    InstructionSpec("DECB", _F, 25, inputs=("ACT",),
                    params=(_fmt(), _addr("code", "format"), _num("first", 0, MAX32),
                            _addr("result", 1)),
                    title="Binary decode", title_tr="BINARY KOD ÇÖZÜCÜ"),
    InstructionSpec("CTR", _F, 5, inputs=("CN0", "UPDOWN", "RST", "ACT"),
                    params=(_num("counter", 1, 20),), w1=True,
                    title="Counter", title_tr="SAYICI"),
    InstructionSpec("CTRC", _F, 55, inputs=("CN0", "UPDOWN", "RST", "ACT"),
                    params=(_addr("preset", 2), _addr("register", 4)), w1=True,
                    title="Counter (preset at an address)", title_tr="SAYICI"),
    InstructionSpec("ROT", _F, 6, inputs=("RN0", "BYT", "DIR", "POS", "INC", "ACT"),
                    params=(_num("positions", 1, 9999), _addr("current", 2),
                            _addr("target", 2), _addr("result", 2)), w1=True,
                    title="Rotation control", title_tr="DÖNER KONTROL"),
    InstructionSpec("ROTB", _F, 26, inputs=("RN0", "DIR", "POS", "INC", "ACT"),
                    params=(_fmt(), _addr("positions", "format"), _addr("current", "format"),
                            _addr("target", "format"), _addr("result", "format")), w1=True,
                    title="Binary rotation control", title_tr="BINARY DÖNER KONTROL"),
    InstructionSpec("COD", _F, 7, inputs=("BYT", "RST", "ACT"),
                    params=(_num("size", 1, 100), _addr("index", 1), _addr("output", 2),
                            Param("table", ParamKind.TABLE, 0, 9999, length_of="size")),
                    w1=True, title="Code conversion", title_tr="KOD TRANSFORMASYON"),
    InstructionSpec("CODB", _F, 27, inputs=("RST", "ACT"),
                    params=(_fmt(), _num("size", 1, 256), _addr("index", 1),
                            _addr("output", "format"),
                            Param("table", ParamKind.TABLE, -MAX32, MAX32, length_of="size")),
                    w1=True, title="Binary code conversion",
                    title_tr="BINARY KOD TRANSFORMASYON"),
    InstructionSpec("DCNV", _F, 14, inputs=("BYT", "CNV", "RST", "ACT"),
                    params=(_addr("input", 2), _addr("output", 2)), w1=True,
                    title="Data conversion", title_tr="BİLGİ ÇEVİRİCİ"),
    InstructionSpec("DCNVB", _F, 31, inputs=("SIN", "CNV", "RST", "ACT"),
                    params=(_fmt(), _addr("input", "format"), _addr("output", "format")),
                    w1=True, title="Extended data conversion",
                    title_tr="GENİŞLETİLMİŞ BİLGİ ÇEVİRİCİ"),
    InstructionSpec("MOVE", _F, 8, inputs=("ACT",),
                    params=(Param("high_mask", ParamKind.MASK, 0, 15),
                            Param("low_mask", ParamKind.MASK, 0, 15),
                            _addr("input", 1), _addr("output", 1)),
                    title="Masked transfer", title_tr="MASKELİ BİLGİ TRANSFERİ"),
    InstructionSpec("MOVOR", _F, 28, inputs=("ACT",),
                    params=(_addr("input", 1), _addr("or_data", 1), _addr("output", 1)),
                    title="Transfer with OR", title_tr="VEYA İLE TRANSFER"),
    InstructionSpec("SFT", _F, 33, inputs=("DIR", "CONT", "RST", "ACT"),
                    params=(_addr("data", 2),), w1=True,
                    title="Shift register", title_tr="KAYIT KAYDIRMA"),
    InstructionSpec("JMP", _F, 10, inputs=("ACT",), params=(_num("coils", 0, 9999),),
                    title="Jump", title_tr="ATLA"),
    InstructionSpec("JMPE", _F, 30, title="Jump end", title_tr="ATLAMA İPTAL"),
    InstructionSpec("COM", _F, 9, inputs=("ACT",), params=(_num("coils", 0, 9999),),
                    title="Common line control", title_tr="ORTAK HAT KONTROLU"),
    InstructionSpec("COME", _F, 29, title="Common line control end",
                    title_tr="ORTAK HAT KONTROLU İPTAL"),
    InstructionSpec("PARI", _F, 11, inputs=("O.E", "RST", "ACT"),
                    params=(_addr("data", 1),), w1=True,
                    title="Parity check", title_tr="PARITY KONTROL"),
    InstructionSpec("COMP", _F, 15, inputs=("BYT", "ACT"),
                    params=(_num("input_format", 0, 1), _value("input", 2),
                            _addr("compare", 2)), w1=True,
                    title="Compare", title_tr="MUKAYESE"),
    InstructionSpec("COMPB", _F, 32, inputs=("ACT",),
                    params=(Param("format", ParamKind.NUMBER, 1, 1004, choices=ARITH_FORMATS),
                            _value("input", "format"), _addr("compare", "format")),
                    title="Binary compare", title_tr="BINARY MUKAYESE"),
    InstructionSpec("COIN", _F, 16, inputs=("BYT", "ACT"),
                    params=(_num("input_format", 0, 1), _value("input", 2),
                            _addr("compare", 2)), w1=True,
                    title="Coincidence check", title_tr="EŞİTLİK KONTROLU"),
    InstructionSpec("DSCH", _F, 17, inputs=("BYT", "RST", "ACT"),
                    params=(_num("size", 1, 9999), _addr("table", 2), _addr("search", 2),
                            _addr("result", 2)), w1=True,
                    title="Data search", title_tr="VERİ ARAMA"),
    InstructionSpec("DSCHB", _F, 34, inputs=("RST", "ACT"),
                    params=(_fmt(), _addr("size", 4), _addr("table", "format"),
                            _addr("search", "format"), _addr("result", 4)), w1=True,
                    title="Binary data search", title_tr="BINARY VERİ ARAMA"),
    InstructionSpec("XMOV", _F, 18, inputs=("BYT", "RW", "RST", "ACT"),
                    params=(_num("size", 1, 9999), _addr("table", 2), _addr("data", 2),
                            _addr("index", 2)), w1=True,
                    title="Indexed transfer", title_tr="INDEX DÜZELTME VERİ TRANSFERİ"),
    InstructionSpec("XMOVB", _F, 35, inputs=("RW", "RST", "ACT"),
                    params=(_fmt(), _num("size", 1, 9999), _addr("table", "format"),
                            _addr("data", "format"), _addr("index", 4)), w1=True,
                    title="Binary indexed transfer",
                    title_tr="BINARY INDEX DÜZELTME VERİ TRANSFERİ"),
)


def _arith(name: str, sub: int, title: str, title_tr: str) -> InstructionSpec:
    return InstructionSpec(
        name, _F, sub, inputs=("BYT", "RST", "ACT"),
        params=(_num("operand_format", 0, 1), _addr("a", 2), _value("b", 2), _addr("result", 2)),
        w1=True, title=title, title_tr=title_tr)


def _arith_b(name: str, sub: int, title: str, title_tr: str) -> InstructionSpec:
    return InstructionSpec(
        name, _F, sub, inputs=("RST", "ACT"),
        params=(Param("format", ParamKind.NUMBER, 1, 1004, choices=ARITH_FORMATS),
                _addr("a", "format"), _value("b", "format"), _addr("result", "format")),
        w1=True, title=title, title_tr=title_tr)


_ARITHMETIC: tuple[InstructionSpec, ...] = (
    _arith("ADD", 19, "Addition (BCD)", "TOPLAMA"),
    _arith_b("ADDB", 36, "Binary addition", "BINARY TOPLAMA"),
    _arith("SUB", 20, "Subtraction (BCD)", "ÇIKARTMA"),
    _arith_b("SUBB", 37, "Binary subtraction", "BINARY ÇIKARTMA"),
    _arith("MUL", 21, "Multiplication (BCD)", "ÇARPMA"),
    _arith_b("MULB", 38, "Binary multiplication", "BINARY ÇARPMA"),
    _arith("DIV", 22, "Division (BCD)", "BÖLME"),
    _arith_b("DIVB", 39, "Binary division", "BINARY BÖLME"),
    InstructionSpec("NUME", _F, 23, inputs=("BYT", "ACT"),
                    params=(_num("constant", 0, 9999), _addr("output", 2)),
                    title="Constant (BCD)", title_tr="SABİT"),
    InstructionSpec("NUMEB", _F, 40, inputs=("ACT",),
                    params=(_fmt(), _num("constant", -MAX32, MAX32), _addr("output", "format")),
                    title="Binary constant", title_tr="BINARY SABİT"),
)

_ENDS: tuple[InstructionSpec, ...] = (
    InstructionSpec("END1", Kind.END, 1, title="End of level 1", title_tr="1. SEVİYE SONU"),
    InstructionSpec("END2", Kind.END, 2, title="End of level 2", title_tr="2. SEVİYE SONU"),
    InstructionSpec("END", Kind.END, 64, title="End of program", title_tr="PROGRAM SONU"),
)

BASIC: tuple[InstructionSpec, ...] = _BASIC
FUNCTIONS: tuple[InstructionSpec, ...] = _FUNCTIONS + _ARITHMETIC
ENDS: tuple[InstructionSpec, ...] = _ENDS
ALL: tuple[InstructionSpec, ...] = BASIC + FUNCTIONS + ENDS

BY_NAME: dict[str, InstructionSpec] = {spec.name: spec for spec in ALL}
BY_SUB: dict[int, InstructionSpec] = {
    spec.sub: spec for spec in FUNCTIONS + ENDS if spec.sub is not None
}

# The seed manual's order of the functional instructions (its table in section 5).
MANUAL_ORDER: tuple[str, ...] = (
    "TMR", "TMRB", "TMRC", "DEC", "DECB", "CTR", "CTRC", "ROT", "ROTB", "COD", "CODB",
    "DCNV", "DCNVB", "MOVE", "MOVOR", "SFT", "JMP", "JMPE", "COM", "COME", "PARI", "COMP",
    "COMPB", "COIN", "DSCH", "DSCHB", "XMOV", "XMOVB", "ADD", "ADDB", "SUB", "SUBB", "MUL",
    "MULB", "DIV", "DIVB", "NUME", "NUMEB",
)


def lookup(name: str) -> InstructionSpec | None:
    """The row for a mnemonic (case-insensitive), or None."""
    return BY_NAME.get(name.upper())


def width_of(spec: InstructionSpec, param: Param, values: dict[str, object]) -> int:
    """Bytes of data addressed by `param`, resolving a width given by a format parameter."""
    if isinstance(param.width, int):
        return param.width
    fmt = values.get(param.width)
    if isinstance(fmt, int):
        return fmt % 10 if fmt % 10 in FORMAT_124 else 1
    return 1


def value_is_address(spec: InstructionSpec, values: dict[str, object]) -> bool | None:
    """For instructions with a VALUE parameter: does the format say it is an address?"""
    if "input_format" in values:
        return values["input_format"] == 1
    if "operand_format" in values:
        return values["operand_format"] == 1
    fmt = values.get("format")
    if isinstance(fmt, int) and spec.name in ("COMPB", "ADDB", "SUBB", "MULB", "DIVB"):
        return fmt >= 1000
    return None
