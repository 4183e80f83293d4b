"""Texts shared by the parser tests and the grammar-coverage test."""

FANUC_FORM = """%@3
RD X1.0
SUB 24
0001
1000
WRT Y0.1
RD X1.1
SUB 7
2
R100
R102
10
20
WRT R5.0
%
"""

ONE_LINE_FORM = """%@3
RD X1.0
TMRB 1 1000
WRT Y0.1
RD X1.1
COD 2 R100 R102 10 20
WRT R5.0
%
"""

SECTIONS = """; a FANUC listing with other sections
%@0
 system parameters: anything here is kept verbatim
%
%@1
MY MACHINE
%
%@3
RD X0.0
WRT Y0.0
%
%@4
A00.0 message text
%
"""

COMMENTS = """%@3
, a comma comment line
// network 1 comment
; FANUC comment
RD X2.1  // trailing, Türkçe: İŞ MİLİ
// inside the network
AND X2.3
WRT R102.0

RD X2.5
WRT R102.1
// trailing comment at the end
%
"""

BAD = """%@3
RD Q2.1
RD X2.9
FOO 1
TMR 200
RD X1.1 !!
SUB 99
TMRB 1
WRT
AND.STK X1.0
R100
MOVE 1112 0000 R10 R11
DECB 3 R10 1 R11
ADDB 2 R10 R12 R14
%
"""

LADDER_III = """;N
%@A
%@0
2 BINARY
%
%@1
2 TEST MACHINE * P001
7 19/03/22 11:04
%
%@2-C
X21.7   ESKIP
G8.4    *ESP
P3      C62297
%
%@3

;--------------- module.lad \t(SIGNALS )
N00000:
RD         X21.7
WRT        G54.0
N00001:  ; a label with a comment
RD.NOT     R10.0
SUB 40
2
-25600
D100
N00002:
RD  X21.0
AND.NOT    X21.1
WRT.NOT    G8.4
%
%@4
A0.1\t1000 ALARM MESSAGE
%
%@5
X03 1 0 1 /6
%
%@E
"""

ALL_TEXTS = [FANUC_FORM, ONE_LINE_FORM, SECTIONS, COMMENTS, BAD, LADDER_III]
