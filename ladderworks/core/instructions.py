"""The instruction table: every basic and functional instruction, read by every other part."""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cache

from ladderworks.core.instruction_fields import Combine as Combine
from ladderworks.core.instruction_fields import Flow as Flow
from ladderworks.core.instruction_fields import Kind as Kind
from ladderworks.core.instruction_fields import Numbered as Numbered
from ladderworks.core.instruction_fields import Operation as Operation
from ladderworks.core.instruction_fields import ParamAccess as ParamAccess
from ladderworks.core.instruction_fields import ParamKind as ParamKind
from ladderworks.core.instruction_fields import StackOp as StackOp
from ladderworks.core.instruction_fields import Write as Write


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
    hi_pmc: int | None = None  # the upper limit in a FANUC (LADDER-III) program, if wider
    access: ParamAccess = ParamAccess.READ  # what is done with the data at its address
    entries: str = ""  # the param giving how many entries of `width` bytes it addresses (XMOV)
    preset: bool = False  # the preset of a timer or counter kept at this address (TMRC, CTRC)

    def highest(self, dialect: str = "seed") -> int:
        """The upper limit in a program of `dialect` ("seed" or "fanuc")."""
        return self.hi_pmc if dialect == "fanuc" and self.hi_pmc is not None else self.hi

    def allows_address(self) -> bool:
        """True if an address may be written here."""
        return self.kind in (ParamKind.ADDRESS, ParamKind.VALUE, ParamKind.RAW, ParamKind.BIT)


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
    opcode: int = 0  # the binary's opcode (basic: 1..; functional and END: FUNCTION_BASE + SUB)
    # basic: reads or writes the inverted bit (RD.NOT, WRT.NOT, ...); a jump/call flow: acts
    # when its input is 0 (S7's JMPN)
    negated: bool = False
    combine: Combine = Combine.NONE  # basic contacts and stack ops
    write: Write = Write.NONE  # basic coils
    flow: Flow = Flow.NONE  # functional: its part in the program's structure
    level: int = 0  # LEVEL_END: the level it ends (1, 2, 3)
    cnc: bool = False  # talks to the CNC: simulated without one (docs/instructions.md)
    address_format: bool = False  # a `format` of 1001/1002/1004 makes the VALUE an address
    mnemonic: str = ""  # the name written in the text when it differs from `name`
    known: bool = True  # False for a `SUB n` that is not in the table
    source: str = "seed"  # "seed": the seed manual's instruction; "pmc": FANUC 30i PMC
    family: str = ""  # the module of plc/functions that implements it ("" for none)
    numbered: Numbered = Numbered.NONE  # the T/C memory its number selects
    operation: Operation = Operation.NONE  # arithmetic: what it computes
    binary: bool = False  # arithmetic: signed binary data (ADDB, ...), else BCD
    pulse: bool = False  # runs only in the scan its input went on (a dialect's P form)
    stack: StackOp = StackOp.NONE  # basic without operand: a dialect's stack operation
    dialect: str = ""  # the dialect whose row it is (core/dialects), "" for the PMC's
    gates_boxes: bool = False  # COMMON: while off, boxes in its range see their input off too
    # False: shown only, an instruction kept, drawn and saved but not run (a warning; the scan
    # passes its input on, a contact never conducts): a dialect's "shown" rows (shown_row)
    simulated: bool = True
    # a box that is an output, as a coil is: drawn among the coils, its input flows on to the
    # outputs after it (Delta's applied instructions: `LD X2 / OUT Y1 / MOV K5 D0`)
    output: bool = False
    operand_texts: tuple[str, ...] = ()  # a shown-only instruction's operands as written

    @property
    def help_key(self) -> str:
        """Key of the instruction's entry in docs/instructions.md and the help browser."""
        return "instr-" + self.name.lower().replace(".", "-")

    @property
    def text_name(self) -> str:
        """The mnemonic as written in program text (`AND` for the functional LOGAND)."""
        return self.mnemonic or self.name

    @property
    def is_contact(self) -> bool:
        """True for RD/AND/OR and their .NOT/.STK forms (they take a bit operand)."""
        return self.combine is not Combine.NONE and self.operand

    @property
    def is_coil(self) -> bool:
        """True for WRT, WRT.NOT, SET and RST."""
        return self.write is not Write.NONE

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
INT32 = 2**31  # FANUC binary data: -2^31 .. 2^32 - 1 accepted as written (signed or unsigned)
UINT32 = 2**32 - 1
FORMAT_124 = (1, 2, 4)


def _num(name: str, lo: int, hi: int, hi_pmc: int | None = None) -> Param:
    return Param(name, ParamKind.NUMBER, lo, hi, hi_pmc=hi_pmc)


def _fmt(name: str = "format") -> Param:
    return Param(name, ParamKind.NUMBER, 1, 4, choices=FORMAT_124)


def _addr(name: str, width: int | str = 1, access: ParamAccess = ParamAccess.READ,
          **extra: object) -> Param:
    return Param(name, ParamKind.ADDRESS, width=width, access=access,
                 **extra)  # type: ignore[arg-type]


def _out(name: str, width: int | str = 1) -> Param:
    """An address the instruction writes."""
    return _addr(name, width, ParamAccess.WRITE)


_RW, _EITHER = ParamAccess.READ_WRITE, ParamAccess.EITHER


def _value(name: str, width: int | str = 2) -> Param:
    return Param(name, ParamKind.VALUE, -MAX32, MAX32, width=width)


# Binary arithmetic/compare format: thousands digit 0 = constant, 1 = address; units 1/2/4 bytes.
ARITH_FORMATS = (1, 2, 4, 1001, 1002, 1004)

_B = Kind.BASIC
_READ, _AND, _OR = Combine.READ, Combine.AND, Combine.OR

_BASIC: tuple[InstructionSpec, ...] = (
    InstructionSpec("RD", _B, operand=True, combine=_READ, opcode=1,
                    title="Read", title_tr="OKU"),
    InstructionSpec("RD.NOT", _B, operand=True, combine=_READ, negated=True, opcode=2,
                    title="Read inverted", title_tr="TERS OKU"),
    InstructionSpec("WRT", _B, operand=True, writes=True, write=Write.OUT, opcode=3,
                    title="Write", title_tr="YAZ"),
    InstructionSpec("WRT.NOT", _B, operand=True, writes=True, write=Write.OUT, negated=True,
                    opcode=4, title="Write inverted", title_tr="TERS YAZ"),
    InstructionSpec("AND", _B, operand=True, combine=_AND, opcode=5,
                    title="And", title_tr="VE"),
    InstructionSpec("AND.NOT", _B, operand=True, combine=_AND, negated=True, opcode=6,
                    title="And inverted", title_tr="VE DEĞİL"),
    InstructionSpec("OR", _B, operand=True, combine=_OR, opcode=7, title="Or", title_tr="VEYA"),
    InstructionSpec("OR.NOT", _B, operand=True, combine=_OR, negated=True, opcode=8,
                    title="Or inverted", title_tr="VEYA DEĞİL"),
    InstructionSpec("RD.STK", _B, operand=True, pushes=1, combine=_READ, opcode=9,
                    title="Push and read", title_tr="İTEKLE VE OKU"),
    InstructionSpec("RD.NOT.STK", _B, operand=True, pushes=1, combine=_READ, negated=True,
                    opcode=10, title="Push and read inverted", title_tr="İTEKLE VE TERS OKU"),
    InstructionSpec("AND.STK", _B, pushes=-1, combine=_AND, opcode=11,
                    title="And with stack, pop", title_tr="YIĞIN VE"),
    InstructionSpec("OR.STK", _B, pushes=-1, combine=_OR, opcode=12,
                    title="Or with stack, pop", title_tr="YIĞIN VEYA"),
    InstructionSpec("SET", _B, operand=True, writes=True, write=Write.SET, opcode=13,
                    source="pmc", title="Set coil", title_tr="SET BOBİNİ"),
    InstructionSpec("RST", _B, operand=True, writes=True, write=Write.RESET, opcode=14,
                    source="pmc", title="Reset coil", title_tr="RESET BOBİNİ"),
)

_F = Kind.FUNCTION

_FUNCTIONS: tuple[InstructionSpec, ...] = (
    InstructionSpec("TMR", _F, 3, family="timers", numbered=Numbered.TIMER, inputs=("ACT",),
                    params=(_num("timer", 1, 100, 250),), w1=True,
                    title="Timer", title_tr="ZAMANLAYICI"),
    InstructionSpec("TMRB", _F, 24, family="timers", numbered=Numbered.FIXED_TIMER, inputs=("ACT",),
                    params=(_num("timer", 1, 100, 500), _num("preset", 0, MAX32)), w1=True,
                    title="Fixed timer", title_tr="STATİK ZAMANLAYICI"),
    InstructionSpec("TMRC", _F, 54, family="timers", inputs=("ACT",),
                    params=(_num("accuracy", 0, 1, 7), _addr("preset", 2, preset=True),
                            _addr("register", 4, _RW)),
                    w1=True, title="Timer (preset at an address)", title_tr="ZAMANLAYICI"),
    InstructionSpec("DEC", _F, 4, family="decode", inputs=("ACT",),
                    params=(_addr("code", 1), _num("spec", 0, 9911)), w1=True,
                    title="Decode (BCD)", title_tr="KOD ÇÖZÜCÜ"),
    InstructionSpec("DECB", _F, 25, family="decode", inputs=("ACT",),
                    params=(_fmt(), _addr("code", "format"), _num("first", 0, MAX32),
                            _out("result", 1)),
                    title="Binary decode", title_tr="BINARY KOD ÇÖZÜCÜ"),
    InstructionSpec("CTR", _F, 5, family="counters", numbered=Numbered.COUNTER,
                    inputs=("CN0", "UPDOWN", "RST", "ACT"),
                    params=(_num("counter", 1, 20, 100),), w1=True,
                    title="Counter", title_tr="SAYICI"),
    InstructionSpec("CTRC", _F, 55, family="counters", inputs=("CN0", "UPDOWN", "RST", "ACT"),
                    params=(_addr("preset", 2, preset=True), _addr("register", 4, _RW)), w1=True,
                    title="Counter (preset at an address)", title_tr="SAYICI"),
    InstructionSpec("ROT", _F, 6, family="rotation",
                    inputs=("RN0", "BYT", "DIR", "POS", "INC", "ACT"),
                    params=(_num("positions", 1, 9999), _addr("current", 2),
                            _addr("target", 2), _out("result", 2)), w1=True,
                    title="Rotation control", title_tr="DÖNER KONTROL"),
    InstructionSpec("ROTB", _F, 26, family="rotation", inputs=("RN0", "DIR", "POS", "INC", "ACT"),
                    params=(_fmt(), _addr("positions", "format"), _addr("current", "format"),
                            _addr("target", "format"), _out("result", "format")), w1=True,
                    title="Binary rotation control", title_tr="BINARY DÖNER KONTROL"),
    InstructionSpec("COD", _F, 7, family="convert", inputs=("BYT", "RST", "ACT"),
                    params=(_num("size", 1, 100), _addr("index", 1), _out("output", 2),
                            Param("table", ParamKind.TABLE, 0, 9999, length_of="size")),
                    w1=True, title="Code conversion", title_tr="KOD TRANSFORMASYON"),
    InstructionSpec("CODB", _F, 27, family="convert", inputs=("RST", "ACT"),
                    params=(_fmt(), _num("size", 1, 256), _addr("index", 1),
                            _out("output", "format"),
                            Param("table", ParamKind.TABLE, -INT32, UINT32, length_of="size")),
                    w1=True, title="Binary code conversion",
                    title_tr="BINARY KOD TRANSFORMASYON"),
    InstructionSpec("DCNV", _F, 14, family="convert", inputs=("BYT", "CNV", "RST", "ACT"),
                    params=(_addr("input", 2), _out("output", 2)), w1=True,
                    title="Data conversion", title_tr="BİLGİ ÇEVİRİCİ"),
    InstructionSpec("DCNVB", _F, 31, family="convert", inputs=("SIN", "CNV", "RST", "ACT"),
                    params=(_fmt(), _addr("input", "format"), _out("output", "format")),
                    w1=True, title="Extended data conversion",
                    title_tr="GENİŞLETİLMİŞ BİLGİ ÇEVİRİCİ"),
    InstructionSpec("MOVE", _F, 8, family="transfer", inputs=("ACT",),
                    params=(Param("high_mask", ParamKind.MASK, 0, 15),
                            Param("low_mask", ParamKind.MASK, 0, 15),
                            _addr("input", 1), _out("output", 1)),
                    title="Masked transfer", title_tr="MASKELİ BİLGİ TRANSFERİ"),
    InstructionSpec("MOVOR", _F, 28, family="transfer", inputs=("ACT",),
                    params=(_addr("input", 1), _addr("or_data", 1), _out("output", 1)),
                    title="Transfer with OR", title_tr="VEYA İLE TRANSFER"),
    InstructionSpec("SFT", _F, 33, family="shift", inputs=("DIR", "CONT", "RST", "ACT"),
                    params=(_addr("data", 2, _RW),), w1=True,
                    title="Shift register", title_tr="KAYIT KAYDIRMA"),
    InstructionSpec("JMP", _F, 10, inputs=("ACT",), params=(_num("coils", 0, 9999),),
                    flow=Flow.JUMP, title="Jump", title_tr="ATLA"),
    InstructionSpec("JMPE", _F, 30, flow=Flow.JUMP_END, title="Jump end", title_tr="ATLAMA İPTAL"),
    InstructionSpec("COM", _F, 9, inputs=("ACT",), params=(_num("coils", 0, 9999),),
                    flow=Flow.COMMON, title="Common line control", title_tr="ORTAK HAT KONTROLU"),
    InstructionSpec("COME", _F, 29, flow=Flow.COMMON_END, title="Common line control end",
                    title_tr="ORTAK HAT KONTROLU İPTAL"),
    InstructionSpec("PARI", _F, 11, family="parity", inputs=("O.E", "RST", "ACT"),
                    params=(_addr("data", 1),), w1=True,
                    title="Parity check", title_tr="PARITY KONTROL"),
    InstructionSpec("COMP", _F, 15, family="compare", inputs=("BYT", "ACT"),
                    params=(_num("input_format", 0, 1), _value("input", 2),
                            _addr("compare", 2)), w1=True,
                    title="Compare", title_tr="MUKAYESE"),
    InstructionSpec("COMPB", _F, 32, family="compare", inputs=("ACT",),
                    params=(Param("format", ParamKind.NUMBER, 1, 1004, choices=ARITH_FORMATS),
                            _value("input", "format"), _addr("compare", "format")),
                    address_format=True, title="Binary compare", title_tr="BINARY MUKAYESE"),
    InstructionSpec("COIN", _F, 16, family="compare", inputs=("BYT", "ACT"),
                    params=(_num("input_format", 0, 1), _value("input", 2),
                            _addr("compare", 2)), w1=True,
                    title="Coincidence check", title_tr="EŞİTLİK KONTROLU"),
    InstructionSpec("DSCH", _F, 17, family="search", inputs=("BYT", "RST", "ACT"),
                    params=(_num("size", 1, 9999), _addr("table", 2, entries="size"),
                            _addr("search", 2),
                            _out("result", 2)), w1=True,
                    title="Data search", title_tr="VERİ ARAMA"),
    InstructionSpec("DSCHB", _F, 34, family="search", inputs=("RST", "ACT"),
                    params=(_fmt(), _addr("size", 4), _addr("table", "format"),
                            _addr("search", "format"), _out("result", 4)), w1=True,
                    title="Binary data search", title_tr="BINARY VERİ ARAMA"),
    InstructionSpec("XMOV", _F, 18, family="transfer", inputs=("BYT", "RW", "RST", "ACT"),
                    params=(_num("size", 1, 9999), _addr("table", 2, _EITHER, entries="size"),
                            _addr("data", 2, _EITHER),
                            _addr("index", 2)), w1=True,
                    title="Indexed transfer", title_tr="INDEX DÜZELTME VERİ TRANSFERİ"),
    InstructionSpec("XMOVB", _F, 35, family="transfer", inputs=("RW", "RST", "ACT"),
                    params=(_fmt(), _value("size", 2),
                            _addr("table", "format", _EITHER, entries="size"),
                            _addr("data", "format", _EITHER), _addr("index", 4)), w1=True,
                    title="Binary indexed transfer",
                    title_tr="BINARY INDEX DÜZELTME VERİ TRANSFERİ"),
)


def _arith(name: str, sub: int, operation: Operation, title: str,
           title_tr: str) -> InstructionSpec:
    return InstructionSpec(
        name, _F, sub, family="arithmetic", operation=operation, inputs=("BYT", "RST", "ACT"),
        params=(_num("operand_format", 0, 1), _addr("a", 2), _value("b", 2), _out("result", 2)),
        w1=True, title=title, title_tr=title_tr)


def _arith_b(name: str, sub: int, operation: Operation, title: str,
             title_tr: str) -> InstructionSpec:
    return InstructionSpec(
        name, _F, sub, family="arithmetic", operation=operation, binary=True,
        inputs=("RST", "ACT"),
        params=(Param("format", ParamKind.NUMBER, 1, 1004, choices=ARITH_FORMATS),
                _addr("a", "format"), _value("b", "format"), _out("result", "format")),
        w1=True, address_format=True, title=title, title_tr=title_tr)


_ARITHMETIC: tuple[InstructionSpec, ...] = (
    _arith("ADD", 19, Operation.ADD, "Addition (BCD)", "TOPLAMA"),
    _arith_b("ADDB", 36, Operation.ADD, "Binary addition", "BINARY TOPLAMA"),
    _arith("SUB", 20, Operation.SUBTRACT, "Subtraction (BCD)", "ÇIKARTMA"),
    _arith_b("SUBB", 37, Operation.SUBTRACT, "Binary subtraction", "BINARY ÇIKARTMA"),
    _arith("MUL", 21, Operation.MULTIPLY, "Multiplication (BCD)", "ÇARPMA"),
    _arith_b("MULB", 38, Operation.MULTIPLY, "Binary multiplication", "BINARY ÇARPMA"),
    _arith("DIV", 22, Operation.DIVIDE, "Division (BCD)", "BÖLME"),
    _arith_b("DIVB", 39, Operation.DIVIDE, "Binary division", "BINARY BÖLME"),
    InstructionSpec("NUME", _F, 23, family="arithmetic", inputs=("BYT", "ACT"),
                    params=(_num("constant", 0, 9999), _out("output", 2)),
                    title="Constant (BCD)", title_tr="SABİT"),
    InstructionSpec("NUMEB", _F, 40, family="arithmetic", inputs=("ACT",),
                    params=(_fmt(), _num("constant", -INT32, UINT32), _out("output", "format")),
                    title="Binary constant", title_tr="BINARY SABİT"),
)

_ENDS: tuple[InstructionSpec, ...] = (
    InstructionSpec("END1", Kind.END, 1, flow=Flow.LEVEL_END, level=1,
                    title="End of level 1", title_tr="1. SEVİYE SONU"),
    InstructionSpec("END2", Kind.END, 2, flow=Flow.LEVEL_END, level=2,
                    title="End of level 2", title_tr="2. SEVİYE SONU"),
    InstructionSpec("END3", Kind.END, 48, flow=Flow.LEVEL_END, level=3, source="pmc",
                    title="End of level 3", title_tr="3. SEVİYE SONU"),
    InstructionSpec("END", Kind.END, 64, flow=Flow.PROGRAM_END,
                    title="End of program", title_tr="PROGRAM SONU"),
)


def _pmc(name: str, sub: int, *, inputs: tuple[str, ...] = ("ACT",),
         params: tuple[Param, ...] = (), w1: bool = False, flow: Flow = Flow.NONE,
         title: str, title_tr: str, **extra: object) -> InstructionSpec:
    """A row of an instruction of the FANUC 30i PMC that the seed manual does not have."""
    return InstructionSpec(name, _F, sub, inputs=inputs, params=params, w1=w1, flow=flow,
                           title=title, title_tr=title_tr, source="pmc",
                           **extra)  # type: ignore[arg-type]


def _logic(name: str, sub: int, title: str, title_tr: str, mnemonic: str = "") -> InstructionSpec:
    return _pmc(name, sub, family="logic", params=(
        Param("format", ParamKind.NUMBER, 1, 1004, choices=ARITH_FORMATS),
        _addr("input", "format"), Param("operand", ParamKind.VALUE, -INT32, UINT32,
                                        width="format"),
        _out("output", "format")), address_format=True, mnemonic=mnemonic,
        title=title, title_tr=title_tr)


def _range_cmp(name: str, sub: int, width: int, title: str, title_tr: str) -> InstructionSpec:
    return _pmc(name, sub, family="compare", params=(
        Param("limit1", ParamKind.VALUE, -INT32, UINT32, width=width),
        Param("limit2", ParamKind.VALUE, -INT32, UINT32, width=width),
        Param("input", ParamKind.VALUE, -INT32, UINT32, width=width)), w1=True,
        title=title, title_tr=title_tr)


_PMC: tuple[InstructionSpec, ...] = (
    _pmc("DIFU", 57, family="edges", params=(_num("edge", 1, 2000),), w1=True,
         title="Rising edge detection", title_tr="YÜKSELEN KENAR"),
    _pmc("DIFD", 58, family="edges", params=(_num("edge", 1, 2000),), w1=True,
         title="Falling edge detection", title_tr="DÜŞEN KENAR"),
    _pmc("MOVB", 43, family="transfer", params=(_addr("input", 1), _out("output", 1)),
         title="Transfer of 1 byte", title_tr="1 BAYT TRANSFERİ"),
    _pmc("MOVW", 44, family="transfer", params=(_addr("input", 2), _out("output", 2)),
         title="Transfer of 2 bytes", title_tr="2 BAYT TRANSFERİ"),
    _pmc("MOVN", 45, family="transfer", params=(_num("bytes", 1, 9999), _addr("input", "bytes"),
                             _out("output", "bytes")),
         title="Transfer of n bytes", title_tr="N BAYT TRANSFERİ"),
    _pmc("MOVD", 47, family="transfer", params=(_addr("input", 4), _out("output", 4)),
         title="Transfer of 4 bytes", title_tr="4 BAYT TRANSFERİ"),
    _logic("LOGAND", 60, "Logical AND", "MANTIKSAL VE", mnemonic="AND"),
    _logic("LOGOR", 61, "Logical OR", "MANTIKSAL VEYA", mnemonic="OR"),
    _logic("EOR", 59, "Exclusive OR", "ÖZEL VEYA"),
    _pmc("NOT", 62, family="logic",
         params=(_fmt(), _addr("input", "format"), _out("output", "format")),
         title="Logical NOT", title_tr="MANTIKSAL DEĞİL"),
    _pmc("TMRBF", 77, family="timers", params=(_num("timer", 1, 500), _num("preset", 0, MAX32)),
         w1=True,
         title="Fixed off-delay timer", title_tr="STATİK KAPANMA GECİKMELİ ZAMANLAYICI"),
    _pmc("CTRB", 56, family="counters", numbered=Numbered.FIXED_COUNTER,
         inputs=("CN0", "UPDOWN", "RST", "ACT"),
         params=(_num("counter", 1, 100), _num("preset", 0, 32767)), w1=True,
         title="Fixed counter", title_tr="STATİK SAYICI"),
    _range_cmp("RNGB", 218, 1, "Range comparison, 1 byte", "ARALIK KARŞILAŞTIRMA (1 BAYT)"),
    _range_cmp("RNGW", 219, 2, "Range comparison, 2 bytes", "ARALIK KARŞILAŞTIRMA (2 BAYT)"),
    _range_cmp("RNGD", 220, 4, "Range comparison, 4 bytes", "ARALIK KARŞILAŞTIRMA (4 BAYT)"),
    _pmc("CALL", 65, params=(Param("program", ParamKind.PROGRAM, 1, 5000),), flow=Flow.CALL,
         title="Conditional subprogram call", title_tr="ŞARTLI ALT PROGRAM ÇAĞRISI"),
    _pmc("CALLU", 66, inputs=(), params=(Param("program", ParamKind.PROGRAM, 1, 5000),),
         flow=Flow.CALL_ALWAYS,
         title="Unconditional subprogram call", title_tr="ŞARTSIZ ALT PROGRAM ÇAĞRISI"),
    _pmc("SP", 71, inputs=(), params=(Param("program", ParamKind.PROGRAM, 1, 5000),),
         flow=Flow.SUBPROGRAM, title="Subprogram", title_tr="ALT PROGRAM"),
    _pmc("SPE", 72, inputs=(), flow=Flow.SUBPROGRAM_END,
         title="End of subprogram", title_tr="ALT PROGRAM SONU"),
    _pmc("JMPB", 68, params=(Param("label", ParamKind.LABEL, 1, 9999),),
         flow=Flow.LABEL_JUMP, title="Label jump", title_tr="ETİKETE ATLA"),
    _pmc("JMPC", 73, params=(Param("label", ParamKind.LABEL, 1, 9999),),
         flow=Flow.LABEL_JUMP_MAIN, title="Label jump to the main program",
         title_tr="ANA PROGRAMDAKİ ETİKETE ATLA"),
    _pmc("LBL", 69, inputs=(), params=(Param("label", ParamKind.LABEL, 1, 9999),),
         flow=Flow.LABEL, title="Label", title_tr="ETİKET"),
    _pmc("AXCTL", 53, family="cnc", inputs=("RST", "ACT"),
         params=(Param("group", ParamKind.NUMBER, 1, 1004), _addr("data", 8, _EITHER)), w1=True,
         cnc=True, title="PMC axis control", title_tr="PMC EKSEN KONTROLÜ"),
    _pmc("WINDR", 51, family="cnc", params=(_addr("control", 10, _EITHER),), w1=True, cnc=True,
         title="Read CNC window data", title_tr="CNC PENCERE VERİSİ OKU"),
    _pmc("WINDW", 52, family="cnc", params=(_addr("control", 10),), w1=True, cnc=True,
         title="Write CNC window data", title_tr="CNC PENCERE VERİSİ YAZ"),
    _pmc("EXIN", 42, family="cnc", params=(_addr("control", 4, _EITHER),), w1=True, cnc=True,
         title="External data input", title_tr="HARİCİ VERİ GİRİŞİ"),
    _pmc("DISPB", 41, family="cnc", params=(_num("messages", 0, 9999),), cnc=True,
         title="Extended message display", title_tr="GENİŞLETİLMİŞ MESAJ GÖSTERİMİ"),
)

FUNCTION_OPCODE = 0x80  # the binary's opcode of every functional instruction and END


def _with_opcode(spec: InstructionSpec) -> InstructionSpec:
    return spec if spec.kind is Kind.BASIC else replace(spec, opcode=FUNCTION_OPCODE)


BASIC: tuple[InstructionSpec, ...] = _BASIC
SEED_FUNCTIONS: tuple[InstructionSpec, ...] = tuple(
    _with_opcode(s) for s in _FUNCTIONS + _ARITHMETIC)
PMC_FUNCTIONS: tuple[InstructionSpec, ...] = tuple(_with_opcode(s) for s in _PMC)
FUNCTIONS: tuple[InstructionSpec, ...] = SEED_FUNCTIONS + PMC_FUNCTIONS
ENDS: tuple[InstructionSpec, ...] = tuple(_with_opcode(s) for s in _ENDS)
ALL: tuple[InstructionSpec, ...] = BASIC + FUNCTIONS + ENDS

BY_NAME: dict[str, InstructionSpec] = {spec.name: spec for spec in ALL}
BY_SUB: dict[int, InstructionSpec] = {
    spec.sub: spec for spec in FUNCTIONS + ENDS if spec.sub is not None
}
BY_OPCODE: dict[int, InstructionSpec] = {spec.opcode: spec for spec in BASIC}
# Functional instructions whose text name clashes with a basic one (`AND`, `OR`): in the
# one-line form the basic one has one operand, the functional one its four parameters.
BY_MNEMONIC: dict[str, InstructionSpec] = {spec.mnemonic: spec for spec in FUNCTIONS
                                           if spec.mnemonic}

# The seed manual's order of the functional instructions (its table in section 5): the rows'.
MANUAL_ORDER: tuple[str, ...] = tuple(spec.name for spec in SEED_FUNCTIONS)
# The FANUC 30i PMC instructions beyond the seed manual, in the palette's order: the rows'.
PMC_ORDER: tuple[str, ...] = tuple(spec.name for spec in PMC_FUNCTIONS)
# The text form of a functional instruction by its number: `SUB 219` (beside the arithmetic SUB).
SUB_KEYWORD = "SUB"


def palette_groups() -> tuple[tuple[str, tuple[InstructionSpec, ...]], ...]:
    """The functional instructions by palette group (their `source`), in the table's order."""
    groups: dict[str, list[InstructionSpec]] = {}
    for spec in FUNCTIONS:
        groups.setdefault(spec.source, []).append(spec)
    return tuple((source, tuple(specs)) for source, specs in groups.items())


def numbered_row(numbered: Numbered) -> InstructionSpec:
    """The row of the timer or counter that uses `numbered` T/C memory (TMR for TIMER)."""
    for spec in FUNCTIONS:
        if spec.numbered is numbered:
            return spec
    raise KeyError(numbered)


def add_rows(rows: tuple[InstructionSpec, ...]) -> None:
    """Join a dialect's rows to the table (core/dialects does, when it registers a dialect).

    Their names carry the dialect's prefix (`DVP.TMR`), so no row of the PMC is replaced."""
    for spec in rows:
        known = BY_NAME.get(spec.name)
        if known is not None and known is not spec:
            raise ValueError(f"two rows named {spec.name}")
        BY_NAME[spec.name] = spec
        if spec.kind is Kind.BASIC:
            BY_OPCODE[spec.opcode] = spec
        elif spec.sub is not None:
            BY_SUB[spec.sub] = spec


SHOWN_MARK = "?"  # `DVP.SHOWN?DMUL D7 K1 D9`: a shown-only row, its mnemonic and operands


def lookup(name: str) -> InstructionSpec | None:
    """The row for a mnemonic (case-insensitive), or None."""
    found = BY_NAME.get(name) or BY_NAME.get(name.upper())
    if found is None and SHOWN_MARK in name:
        return shown_row(name.upper())
    return found


def shown_name(base: InstructionSpec, mnemonic: str, operands: tuple[str, ...]) -> str:
    """The name of an instruction kept but not simulated: its dialect's shown row `base`, the
    mnemonic and the operands as written (`DVP.SHOWN?DMUL D7 K1 D9`)."""
    return " ".join((f"{base.name}{SHOWN_MARK}{mnemonic}", *operands)).upper()


@cache
def shown_row(name: str) -> InstructionSpec | None:
    """The row of a shown-only instruction named by `shown_name`: its base row (a dialect's
    row with `simulated` False) with the mnemonic and operand texts; None if it is not one."""
    head, _, rest = name.partition(SHOWN_MARK)
    base = BY_NAME.get(head)
    words = rest.split(" ")
    if base is None or base.simulated or not words[0]:
        return None
    return replace(base, name=name, mnemonic=words[0], operand_texts=tuple(words[1:]))


@cache
def unknown_sub(number: int, count: int) -> InstructionSpec:
    """A row for a `SUB n` the table does not know: ACT, `count` parameters kept as written.

    It is drawn as a box, compiled, and simulated as a CNC-side instruction with no CNC
    (W1 = ACT); docs/instructions.md says so.
    """
    params = tuple(Param(f"p{k}", ParamKind.RAW, -INT32, UINT32, access=ParamAccess.EITHER)
                   for k in range(1, count + 1))
    return InstructionSpec(f"SUB.{number}", Kind.FUNCTION, number, inputs=("ACT",),
                           params=params, w1=True, cnc=True, known=False, source="pmc",
                           opcode=FUNCTION_OPCODE, title=f"SUB {number}",
                           title_tr=f"SUB {number}")


def spec_for(name: str, param_count: int = 0) -> InstructionSpec | None:
    """The row for an instruction's name as stored in a Program (`SUB.219` for an unknown SUB)."""
    spec = lookup(name)
    if spec is None and name.upper().startswith("SUB.") and name[4:].isdigit():
        return unknown_sub(int(name[4:]), param_count)
    return spec


def width_of(spec: InstructionSpec, param: Param, values: dict[str, object]) -> int:
    """Bytes of data addressed by `param`, resolving a width given by a format parameter."""
    if isinstance(param.width, int):
        return param.width
    fmt = values.get(param.width)
    if isinstance(fmt, int):
        return fmt % 10 if fmt % 10 in FORMAT_124 else 1
    return 1


def value_is_address(spec: InstructionSpec, values: dict[str, object]) -> bool | None:
    """For instructions with a VALUE parameter: does the format say it is an address?

    None when nothing selects it: a constant or an address may be written (RNGW, XMOVB size).
    """
    if "input_format" in values:
        return values["input_format"] == 1
    if "operand_format" in values:
        return values["operand_format"] == 1
    fmt = values.get("format")
    if isinstance(fmt, int) and spec.address_format:
        return fmt >= 1000
    return None
