"""The S7-1200 rows of the instruction table: the boxes an S7 network becomes in the engine.

Names `S7.<name>`, SUB numbers 30000-31999, basic opcodes 0x60-0x6F. A typed box has a NUMBER
parameter `type` (core/plc/typed.py's ValueType) and VALUE operands (a constant or an address).
JMPN is a LABEL_JUMP taken when its input is 0 (`negated`); RET a LABEL_JUMP to the label
after the block's last network (lowering.py). An instance (IEC_TIMER, IEC_COUNTER) is an
ADDRESS of its bytes (layout.py). A comparison and the P/N contacts leave their result in
ST0 (`w1`): the drawing's contacts of those rows.
"""

from __future__ import annotations

from ladderworks.core.instruction_fields import Flow, Operation, StackOp
from ladderworks.core.instructions import (
    FUNCTION_OPCODE,
    InstructionSpec,
    Kind,
    Param,
    ParamAccess,
    ParamKind,
)
from ladderworks.core.plc import typed

PREFIX = "S7."
NAME = "s7"
SUB_BASE = 30_000
INT32_LOW, INT32_HIGH = -(2**31), 2**31 - 1
TIMER_BYTES = 16  # IEC_TIMER: PT, ET, flags, start (S7-1200 system manual V4.2 p. 240)
COUNTER_BYTES = 12  # IEC_COUNTER as LadderWorks lays it out: CV, PV, flags


def _type() -> Param:
    return Param("type", ParamKind.NUMBER, 0, max(typed.ValueType))


def _value(name: str) -> Param:
    return Param(name, ParamKind.VALUE, INT32_LOW, INT32_HIGH, width=4)


def _out(name: str, access: ParamAccess = ParamAccess.WRITE) -> Param:
    return Param(name, ParamKind.ADDRESS, width=1, access=access)


def _optional(name: str) -> Param:  # an output pin wired to nothing: 0
    return Param(name, ParamKind.RAW, INT32_LOW, INT32_HIGH)


def _instance(size: int) -> Param:
    return Param("instance", ParamKind.ADDRESS, width=size, access=ParamAccess.READ_WRITE)


def _row(name: str, number: int, title: str, title_tr: str, *,
         inputs: tuple[str, ...] = ("EN",), params: tuple[Param, ...] = (),
         **fields: object) -> InstructionSpec:
    return InstructionSpec(PREFIX + name, Kind.FUNCTION, SUB_BASE + number, inputs=inputs,
                           params=params, title=title, title_tr=title_tr,
                           opcode=FUNCTION_OPCODE, mnemonic=name, source=NAME, dialect=NAME,
                           **fields)  # type: ignore[arg-type]


def _basic(name: str, opcode: int, title: str, title_tr: str, **fields: object) -> InstructionSpec:
    return InstructionSpec(PREFIX + name, Kind.BASIC, inputs=(), title=title, title_tr=title_tr,
                           opcode=opcode, mnemonic=name, source=NAME, dialect=NAME,
                           **fields)  # type: ignore[arg-type]


_TIMER = (_instance(TIMER_BYTES), _value("PT"), _optional("ET"))
_COUNTER = (_instance(COUNTER_BYTES), _type(), _value("PV"), _optional("CV"))
_EDGE = (Param("operand", ParamKind.BIT), Param("memory", ParamKind.BIT))
_LABEL = (Param("label", ParamKind.LABEL, 1, 9999),)
_COMPARES = (("EQ", Operation.EQUAL, "Equal", "EŞİT"),
             ("NE", Operation.NOT_EQUAL, "Not equal", "EŞİT DEĞİL"),
             ("GT", Operation.GREATER, "Greater", "BÜYÜK"),
             ("LT", Operation.LESS, "Less", "KÜÇÜK"),
             ("GE", Operation.GREATER_EQUAL, "Greater or equal", "BÜYÜK EŞİT"),
             ("LE", Operation.LESS_EQUAL, "Less or equal", "KÜÇÜK EŞİT"))

ROWS: tuple[InstructionSpec, ...] = (
    _basic("DUP", 0x60, "Branch: keep the result", "SONUCU SAKLA", pushes=1,
           stack=StackOp.DUP),
    _basic("DROP", 0x61, "Branch: back to the kept result", "SAKLANAN SONUCA DÖN", pushes=-1,
           stack=StackOp.DROP),
    _basic("NOT", 0x62, "Invert the result (NOT)", "SONUCU TERSLE", stack=StackOp.INVERT),
    _row("TP", 1, "Pulse timer (TP)", "DARBE ÜRETME ZAMANLAYICISI", inputs=("IN",),
         params=_TIMER),
    _row("TON", 2, "On-delay timer (TON)", "GECİKMELİ KAPATAN ZAMANLAYICI", inputs=("IN",),
         params=_TIMER),
    _row("TOF", 3, "Off-delay timer (TOF)", "GECİKMELİ AÇAN ZAMANLAYICI", inputs=("IN",),
         params=_TIMER),
    _row("TONR", 4, "Retentive on-delay timer (TONR)",
         "KALICI İÇERİKLİ GECİKMELİ KAPATAN ZAMANLAYICI", inputs=("IN", "R"), params=_TIMER),
    _row("PT", 5, "Load the time (PT)", "SÜRE YÜKLE (PT)",
         params=(_instance(TIMER_BYTES), _value("PT"))),
    _row("RT", 6, "Reset the timer (RT)", "ZAMANLAYICIYI SIFIRLA (RT)",
         params=(_instance(TIMER_BYTES),)),
    _row("CTU", 10, "Up counter (CTU)", "İLERİ SAYICI", inputs=("CU", "R"), params=_COUNTER),
    _row("CTD", 11, "Down counter (CTD)", "GERİ SAYICI", inputs=("CD", "LD"), params=_COUNTER),
    _row("CTUD", 12, "Up/down counter (CTUD)", "İLERİ-GERİ SAYICI",
         inputs=("CU", "CD", "R", "LD"), params=(*_COUNTER, _optional("QD"))),
    *(_row(name, 20 + n, f"Compare {operation.value}", title_tr, inputs=("IN",),
           params=(_type(), _value("IN1"), _value("IN2")), operation=operation, w1=True)
      for n, (name, operation, _title, title_tr) in enumerate(_COMPARES)),
    _row("IN_RANGE", 30, "Value within range (IN_RANGE)", "ARALIK İÇİNDE", inputs=("IN",),
         params=(_type(), _value("MIN"), _value("VAL"), _value("MAX"))),
    _row("OUT_RANGE", 31, "Value outside range (OUT_RANGE)", "ARALIK DIŞINDA", inputs=("IN",),
         params=(_type(), _value("MIN"), _value("VAL"), _value("MAX"))),
    _row("OK", 32, "Check validity (OK)", "GEÇERLİLİK (OK)", inputs=("IN",),
         params=(_value("IN1"),)),
    _row("NOT_OK", 33, "Check invalidity (NOT_OK)", "GEÇERSİZLİK (NOT_OK)", inputs=("IN",),
         params=(_value("IN1"),)),
    _row("P", 40, "Rising edge contact (P)", "YÜKSELEN KENAR KONTAĞI", inputs=("IN",),
         params=_EDGE, operation=Operation.RISING, w1=True),
    _row("N", 41, "Falling edge contact (N)", "DÜŞEN KENAR KONTAĞI", inputs=("IN",),
         params=_EDGE, operation=Operation.FALLING, w1=True),
    _row("P_COIL", 42, "Rising edge coil (P)", "YÜKSELEN KENAR BOBİNİ", inputs=("IN",),
         params=_EDGE),
    _row("N_COIL", 43, "Falling edge coil (N)", "DÜŞEN KENAR BOBİNİ", inputs=("IN",),
         params=_EDGE),
    _row("P_TRIG", 44, "Rising edge of the result (P_TRIG)", "SONUCUN YÜKSELEN KENARI",
         inputs=("IN",), params=(Param("memory", ParamKind.BIT),)),
    _row("N_TRIG", 45, "Falling edge of the result (N_TRIG)", "SONUCUN DÜŞEN KENARI",
         inputs=("IN",), params=(Param("memory", ParamKind.BIT),)),
    _row("SR", 46, "Set/reset flip-flop (SR)", "SR FLİP-FLOP", inputs=("S", "R1"),
         params=(Param("operand", ParamKind.BIT),)),
    _row("RS", 47, "Reset/set flip-flop (RS)", "RS FLİP-FLOP", inputs=("R", "S1"),
         params=(Param("operand", ParamKind.BIT),)),
    _row("MOVE", 50, "Move (MOVE)", "TAŞI (MOVE)",
         params=(_type(), _value("IN"), _out("OUT1"))),
    _row("ADD", 51, "Add (ADD)", "TOPLA (ADD)",
         params=(_type(), _value("IN1"), _value("IN2"), _out("OUT")),
         operation=Operation.ADD),
    _row("SUB", 52, "Subtract (SUB)", "ÇIKAR (SUB)",
         params=(_type(), _value("IN1"), _value("IN2"), _out("OUT")),
         operation=Operation.SUBTRACT),
    _row("MUL", 53, "Multiply (MUL)", "ÇARP (MUL)",
         params=(_type(), _value("IN1"), _value("IN2"), _out("OUT")),
         operation=Operation.MULTIPLY),
    _row("DIV", 54, "Divide (DIV)", "BÖL (DIV)",
         params=(_type(), _value("IN1"), _value("IN2"), _out("OUT")),
         operation=Operation.DIVIDE),
    _row("INC", 55, "Increment (INC)", "BİR ARTIR (INC)",
         params=(_type(), _out("IN/OUT", ParamAccess.READ_WRITE)),
         operation=Operation.INCREMENT),
    _row("DEC", 56, "Decrement (DEC)", "BİR AZALT (DEC)",
         params=(_type(), _out("IN/OUT", ParamAccess.READ_WRITE)),
         operation=Operation.DECREMENT),
    _row("CONVERT", 57, "Convert (CONVERT)", "DÖNÜŞTÜR (CONVERT)",
         params=(_type(), Param("to", ParamKind.NUMBER, 0, max(typed.ValueType)), _value("IN"),
                 _out("OUT"))),
    _row("JMP", 60, "Jump if 1 (JMP)", "ATLA (JMP)", params=_LABEL, flow=Flow.LABEL_JUMP),
    _row("JMPN", 62, "Jump if 0 (JMPN)", "0 İSE ATLA (JMPN)", params=_LABEL,
         flow=Flow.LABEL_JUMP, negated=True),
    _row("RET", 63, "Return (RET)", "GERİ DÖN (RET)", params=_LABEL, flow=Flow.LABEL_JUMP),
    _row("LABEL", 61, "Jump label (LABEL)", "ETİKET", inputs=(), params=_LABEL,
         flow=Flow.LABEL),
)

# The modules of core/plc/functions that run these rows (merged into core/plc/families.py)
FAMILIES: dict[str, tuple[str, ...]] = {
    "s7_timers": ("S7.TP", "S7.TON", "S7.TOF", "S7.TONR", "S7.PT", "S7.RT"),
    "s7_counters": ("S7.CTU", "S7.CTD", "S7.CTUD"),
    "s7_compare": ("S7.EQ", "S7.NE", "S7.GT", "S7.LT", "S7.GE", "S7.LE", "S7.IN_RANGE",
                   "S7.OUT_RANGE", "S7.OK", "S7.NOT_OK"),
    "s7_bits": ("S7.P", "S7.N", "S7.P_COIL", "S7.N_COIL", "S7.P_TRIG", "S7.N_TRIG", "S7.SR",
                "S7.RS"),
    "s7_math": ("S7.MOVE", "S7.ADD", "S7.SUB", "S7.MUL", "S7.DIV", "S7.INC", "S7.DEC",
                "S7.CONVERT"),
}
BY_NAME: dict[str, InstructionSpec] = {spec.name: spec for spec in ROWS}
