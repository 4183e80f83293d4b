<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US" sourcelanguage="en">
<context>
    <name>AlarmPanel</name>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="125"/>
        <source>Cannot read {0}: {1}</source>
        <translation>Cannot read {0}: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="164"/>
        <source>Alarm message file</source>
        <translation>Alarm message file</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="166"/>
        <source>Alarm files (*.dat);;All files (*)</source>
        <translation>Alarm files (*.dat);;All files (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="173"/>
        <source>A {0} program has no alarm messages (the alarm file is for PMC programs)</source>
        <translation>A {0} program has no alarm messages (the alarm file is for PMC programs)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="180"/>
        <source>The program&apos;s messages (%@4): {0}</source>
        <translation>The program&apos;s messages (%@4): {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="183"/>
        <source>Alarm file... uses an AlarmMsg.dat instead</source>
        <translation>Alarm file... uses an AlarmMsg.dat instead</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="187"/>
        <source>No alarm file</source>
        <translation>No alarm file</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="189"/>
        <source>{0}: {1} messages</source>
        <translation>{0}: {1} messages</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="193"/>
        <source>{0} lines with problems</source>
        <translation>{0} lines with problems</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="200"/>
        <source>line {0}: {1}</source>
        <translation>line {0}: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="218"/>
        <source>(no message {0} in the alarm file)</source>
        <translation>(no message {0} in the alarm file)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="252"/>
        <source>The bit is 0 again: RESET clears this alarm</source>
        <translation>The bit is 0 again: RESET clears this alarm</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="255"/>
        <source>Seen at {0}</source>
        <translation>Seen at {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="298"/>
        <source>Alarms</source>
        <translation>Alarms</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="299"/>
        <source>RESET</source>
        <translation>RESET</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="301"/>
        <source>Clear the alarms whose bit is 0 (the reset key)</source>
        <translation>Clear the alarms whose bit is 0 (the reset key)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="303"/>
        <source>Alarm file...</source>
        <translation>Alarm file...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="306"/>
        <source>No.</source>
        <translation>No.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="307"/>
        <source>Bit</source>
        <translation>Bit</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="308"/>
        <source>PLC time</source>
        <translation>PLC time</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="309"/>
        <source>Clock</source>
        <translation>Clock</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="310"/>
        <source>Message</source>
        <translation>Message</translation>
    </message>
</context>
<context>
    <name>AsciiOutput</name>
    <message>
        <location filename="../ladderworks/gui/docks/ascii_output.py" line="66"/>
        <source>ASCII output</source>
        <translation>ASCII output</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/ascii_output.py" line="67"/>
        <source>Clear</source>
        <translation>Clear</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/ascii_output.py" line="68"/>
        <source>Forget what the terminal received</source>
        <translation>Forget what the terminal received</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/ascii_output.py" line="70"/>
        <source>What FUN 94 ASCWR sends to Port 1 (a Fatek program) shows here.</source>
        <translation>What FUN 94 ASCWR sends to Port 1 (a Fatek program) shows here.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/ascii_output.py" line="85"/>
        <source>{0} output(s) received</source>
        <translation>{0} output(s) received</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/ascii_output.py" line="88"/>
        <source>{0}, line {1}: {2}</source>
        <translation>{0}, line {1}: {2}</translation>
    </message>
</context>
<context>
    <name>BitDisplay</name>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="264"/>
        <source>{0} has {1} bytes: a box shows a byte or a word (the time chart shows any value)</source>
        <translation>{0} has {1} bytes: a box shows a byte or a word (the time chart shows any value)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="339"/>
        <source>Forced to {0}</source>
        <translation>Forced to {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="342"/>
        <source>Click: force to the other value; right-click: force menu</source>
        <translation>Click: force to the other value; right-click: force menu</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="360"/>
        <source>Load a program to force inputs</source>
        <translation>Load a program to force inputs</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="377"/>
        <source>Force to 1</source>
        <translation>Force to 1</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="382"/>
        <source>Force to 0</source>
        <translation>Force to 0</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="387"/>
        <source>Release the force</source>
        <translation>Release the force</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="401"/>
        <source>Live</source>
        <translation>Live</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="401"/>
        <source>Stopped</source>
        <translation>Stopped</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="408"/>
        <source>PLC bit display</source>
        <translation>PLC bit display</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="409"/>
        <source>START</source>
        <translation>START</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="410"/>
        <source>STOP</source>
        <translation>STOP</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="412"/>
        <source>Tag or address</source>
        <translation>Tag or address</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="413"/>
        <source>Byte</source>
        <translation>Byte</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="414"/>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="415"/>
        <source>Dec</source>
        <translation>Dec</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="417"/>
        <source>e.g. &quot;Start&quot;, %MW2</source>
        <translation>e.g. &quot;Start&quot;, %MW2</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="418"/>
        <source>e.g. X12</source>
        <translation>e.g. X12</translation>
    </message>
</context>
<context>
    <name>CrossReference</name>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="67"/>
        <source>Contact</source>
        <translation>Contact</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="68"/>
        <source>NOT contact</source>
        <translation>NOT contact</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="69"/>
        <source>Coil</source>
        <translation>Coil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="70"/>
        <source>NOT coil</source>
        <translation>NOT coil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="71"/>
        <source>SET coil</source>
        <translation>SET coil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="72"/>
        <source>RST coil</source>
        <translation>RST coil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="84"/>
        <source>Read</source>
        <translation>Read</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="86"/>
        <source>Write</source>
        <translation>Write</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="87"/>
        <source>Read and write</source>
        <translation>Read and write</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="93"/>
        <source>Level {0}</source>
        <translation>Level {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="133"/>
        <source>Address</source>
        <translation>Address</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="133"/>
        <source>Symbol</source>
        <translation>Symbol</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="134"/>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="180"/>
        <source>Network</source>
        <translation>Network</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="134"/>
        <source>Label</source>
        <translation>Label</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="135"/>
        <source>Program part</source>
        <translation>Program part</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="136"/>
        <source>Element</source>
        <translation>Element</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="136"/>
        <source>Access</source>
        <translation>Access</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="137"/>
        <source>Comment</source>
        <translation>Comment</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="287"/>
        <source>All addresses — uses: {0}</source>
        <translation>All addresses — uses: {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="300"/>
        <source>&apos;{0}&apos; is neither an address nor a symbol of the program</source>
        <translation>&apos;{0}&apos; is neither an address nor a symbol of the program</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="316"/>
        <source>{0} is not used in the program</source>
        <translation>{0} is not used in the program</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="319"/>
        <source>{0} — uses: {1} (read: {2}, written: {3})</source>
        <translation>{0} — uses: {1} (read: {2}, written: {3})</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="339"/>
        <source>Cross reference</source>
        <translation>Cross reference</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="345"/>
        <source>&amp;Address or symbol:</source>
        <translation>&amp;Address or symbol:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="342"/>
        <source>Cross &amp;reference of this address</source>
        <translation>Cross &amp;reference of this address</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="343"/>
        <source>List every place the program reads and writes the address</source>
        <translation>List every place the program reads and writes the address</translation>
    </message>
</context>
<context>
    <name>Diagnostic</name>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="72"/>
        <source>{count} byte(s) here are not valid {encoding}; they are kept as they are</source>
        <translation>{count} byte(s) here are not valid {encoding}; they are kept as they are</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="76"/>
        <source>this is not a ladder program (no %@ section and no instruction)</source>
        <translation>this is not a ladder program (no %@ section and no instruction)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="78"/>
        <source>line not understood in section {section}: &apos;{text}&apos;</source>
        <translation>line not understood in section {section}: &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="80"/>
        <source>{name}: parameter {index} ({param}) must be {letter} and a number, found &apos;{text}&apos;</source>
        <translation>{name}: parameter {index} ({param}) must be {letter} and a number, found &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="84"/>
        <source>&apos;{text}&apos;: the number is too long</source>
        <translation>&apos;{text}&apos;: the number is too long</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="24"/>
        <source>&apos;{text}&apos; is not an address (expected e.g. X2.1 or R100)</source>
        <translation>&apos;{text}&apos; is not an address (expected e.g. X2.1 or R100)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="26"/>
        <source>&apos;{text}&apos;: unknown area &apos;{area}&apos; (use X, Y, F, G, R, A, D, T, C or K)</source>
        <translation>&apos;{text}&apos;: unknown area &apos;{area}&apos; (use X, Y, F, G, R, A, D, T, C or K)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="28"/>
        <source>&apos;{text}&apos;: byte number out of range for area {area} ({ranges})</source>
        <translation>&apos;{text}&apos;: byte number out of range for area {area} ({ranges})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="30"/>
        <source>&apos;{text}&apos;: bit number must be 0 to 7</source>
        <translation>&apos;{text}&apos;: bit number must be 0 to 7</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="31"/>
        <source>&apos;{text}&apos;: a bit address is needed here (e.g. {text}.0)</source>
        <translation>&apos;{text}&apos;: a bit address is needed here (e.g. {text}.0)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="33"/>
        <source>&apos;{text}&apos;: a byte address is needed here, without a bit</source>
        <translation>&apos;{text}&apos;: a byte address is needed here, without a bit</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="35"/>
        <source>&apos;{text}&apos;: the width after &apos;:&apos; must be 1, 2 or 4</source>
        <translation>&apos;{text}&apos;: the width after &apos;:&apos; must be 1, 2 or 4</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="37"/>
        <source>&apos;{text}&apos;: a bit address takes no width</source>
        <translation>&apos;{text}&apos;: a bit address takes no width</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="39"/>
        <source>the ladder section must begin with %@3</source>
        <translation>the ladder section must begin with %@3</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="40"/>
        <source>the ladder section must end with a line &apos;%&apos;</source>
        <translation>the ladder section must end with a line &apos;%&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="41"/>
        <source>unexpected text &apos;{text}&apos;</source>
        <translation>unexpected text &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="42"/>
        <source>text outside any section: &apos;{text}&apos;</source>
        <translation>text outside any section: &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="43"/>
        <source>section %@{number} appears twice</source>
        <translation>section %@{number} appears twice</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="44"/>
        <source>unknown section {header}: kept as it is</source>
        <translation>unknown section {header}: kept as it is</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="45"/>
        <source>unknown instruction &apos;{name}&apos;</source>
        <translation>unknown instruction &apos;{name}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="46"/>
        <source>{name} needs an address</source>
        <translation>{name} needs an address</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="47"/>
        <source>{name} takes no operand, found &apos;{text}&apos;</source>
        <translation>{name} takes no operand, found &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="48"/>
        <source>{name} needs {expected} parameters, found {found}</source>
        <translation>{name} needs {expected} parameters, found {found}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="50"/>
        <source>{name}: parameter {index} ({param}) must be a number, found &apos;{text}&apos;</source>
        <translation>{name}: parameter {index} ({param}) must be a number, found &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="52"/>
        <source>{name}: parameter {index} ({param}) must be an address, found &apos;{text}&apos;</source>
        <translation>{name}: parameter {index} ({param}) must be an address, found &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="54"/>
        <source>{name}: parameter {index} ({param}) must be {lo} to {hi}, found {value}</source>
        <translation>{name}: parameter {index} ({param}) must be {lo} to {hi}, found {value}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="56"/>
        <source>{name}: parameter {index} ({param}) must be one of {choices}, found {value}</source>
        <translation>{name}: parameter {index} ({param}) must be one of {choices}, found {value}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="60"/>
        <source>{name}: parameter {index} ({param}) must be up to 4 binary digits, found &apos;{text}&apos;</source>
        <translation>{name}: parameter {index} ({param}) must be up to 4 binary digits, found &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="64"/>
        <source>SUB {number} is not in the instruction table: kept with its parameters, drawn as a box, simulated as W1 = ACT</source>
        <translation>SUB {number} is not in the instruction table: kept with its parameters, drawn as a box, simulated as W1 = ACT</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="67"/>
        <source>a parameter line &apos;{text}&apos; without a SUB instruction before it</source>
        <translation>a parameter line &apos;{text}&apos; without a SUB instruction before it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="69"/>
        <source>the file is neither UTF-8 nor Turkish Windows (cp1254) text</source>
        <translation>the file is neither UTF-8 nor Turkish Windows (cp1254) text</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="71"/>
        <source>syntax error at &apos;{text}&apos;</source>
        <translation>syntax error at &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="74"/>
        <source>a saved drawing ({lines} line(s)) is damaged: it is kept as comment text</source>
        <translation>a saved drawing ({lines} line(s)) is damaged: it is kept as comment text</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="86"/>
        <source>open circuit: this element is not connected to the right side</source>
        <translation>open circuit: this element is not connected to the right side</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="88"/>
        <source>element not connected to the left rail</source>
        <translation>element not connected to the left rail</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="89"/>
        <source>a coil must be at the right end of the network</source>
        <translation>a coil must be at the right end of the network</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="91"/>
        <source>a coil cannot sit straight on the left rail</source>
        <translation>a coil cannot sit straight on the left rail</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="92"/>
        <source>bridge circuit: a vertical link joins two branches in the middle</source>
        <translation>bridge circuit: a vertical link joins two branches in the middle</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="94"/>
        <source>short circuit: a wire bypasses the element</source>
        <translation>short circuit: a wire bypasses the element</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="95"/>
        <source>the logic needs more than 8 stack levels (ST8)</source>
        <translation>the logic needs more than 8 stack levels (ST8)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="97"/>
        <source>power would flow right to left here; ladder flows left to right only</source>
        <translation>power would flow right to left here; ladder flows left to right only</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="99"/>
        <source>the network has no coil or function</source>
        <translation>the network has no coil or function</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="100"/>
        <source>{name} needs its {count} control inputs connected</source>
        <translation>{name} needs its {count} control inputs connected</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="102"/>
        <source>this element has no address yet</source>
        <translation>this element has no address yet</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="103"/>
        <source>this edge or comparison contact has no form for this place in the dialect (put it in series after another contact)</source>
        <translation>this edge or comparison contact has no form for this place in the dialect (put it in series after another contact)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="106"/>
        <source>coils hang on different points of the logic; join them to one point</source>
        <translation>coils hang on different points of the logic; join them to one point</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="108"/>
        <source>only coils may follow the output of {name}</source>
        <translation>only coils may follow the output of {name}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="109"/>
        <source>one function box per network: put {name} in a network of its own</source>
        <translation>one function box per network: put {name} in a network of its own</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="112"/>
        <source>cell ({row}, {col}) is outside the grid</source>
        <translation>cell ({row}, {col}) is outside the grid</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="113"/>
        <source>only coils go in the coil column (cell ({row}, {col}))</source>
        <translation>only coils go in the coil column (cell ({row}, {col}))</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="115"/>
        <source>{name} does not fit here: a box needs two contact columns</source>
        <translation>{name} does not fit here: a box needs two contact columns</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="117"/>
        <source>an edge or comparison contact has no normally closed form</source>
        <translation>an edge or comparison contact has no normally closed form</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="119"/>
        <source>there is no suitable element at cell ({row}, {col})</source>
        <translation>there is no suitable element at cell ({row}, {col})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="121"/>
        <source>no function box with FO outputs at cell ({row}, {col})</source>
        <translation>no function box with FO outputs at cell ({row}, {col})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="123"/>
        <source>the program&apos;s {count} symbols (%@2) have no place in that family&apos;s files: the program keeps its family</source>
        <translation>the program&apos;s {count} symbols (%@2) have no place in that family&apos;s files: the program keeps its family</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="126"/>
        <source>instruction {step} ({name}) has no counterpart in that family: the program keeps its family</source>
        <translation>instruction {step} ({name}) has no counterpart in that family: the program keeps its family</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="129"/>
        <source>END ends the program and stays its last network: draw new networks above it</source>
        <translation>END ends the program and stays its last network: draw new networks above it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="132"/>
        <source>a line must be horizontal or vertical</source>
        <translation>a line must be horizontal or vertical</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="133"/>
        <source>the clipboard does not hold ladder elements</source>
        <translation>the clipboard does not hold ladder elements</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="135"/>
        <source>&apos;{text}&apos; is not an address or a symbol of the program: type one to replace it</source>
        <translation>&apos;{text}&apos; is not an address or a symbol of the program: type one to replace it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="138"/>
        <source>{found} and {replacement}: replace a bit with a bit, a byte with a byte</source>
        <translation>{found} and {replacement}: replace a bit with a bit, a byte with a byte</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="140"/>
        <source>{found} would be replaced with itself</source>
        <translation>{found} would be replaced with itself</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="142"/>
        <source>{name} with nothing pushed on the stack</source>
        <translation>{name} with nothing pushed on the stack</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="143"/>
        <source>{name} writes to {address}, an input area</source>
        <translation>{name} writes to {address}, an input area</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="144"/>
        <source>{name} writes to {address}, part of the read-only R9000-R9005</source>
        <translation>{name} writes to {address}, part of the read-only R9000-R9005</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="146"/>
        <source>JMP without a matching JMPE</source>
        <translation>JMP without a matching JMPE</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="147"/>
        <source>JMPE without a JMP before it</source>
        <translation>JMPE without a JMP before it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="148"/>
        <source>COM without a matching COME</source>
        <translation>COM without a matching COME</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="149"/>
        <source>COME without a COM before it</source>
        <translation>COME without a COM before it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="150"/>
        <source>{name} without a logic result before it (start with RD)</source>
        <translation>{name} without a logic result before it (start with RD)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="152"/>
        <source>coil {address} is written more than once</source>
        <translation>coil {address} is written more than once</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="153"/>
        <source>logic at the end of the program is not written to any coil</source>
        <translation>logic at the end of the program is not written to any coil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="155"/>
        <source>not a LadderWorks binary: {reason}</source>
        <translation>not a LadderWorks binary: {reason}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="157"/>
        <source>coil {address} is written by WRT and by SET/RST (also on line {line})</source>
        <translation>coil {address} is written by WRT and by SET/RST (also on line {line})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="159"/>
        <source>coil {address} is written by WRT and by SET/RST (also in network {other})</source>
        <translation>coil {address} is written by WRT and by SET/RST (also in network {other})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="162"/>
        <source>LBL inside a JMP or COM range</source>
        <translation>LBL inside a JMP or COM range</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="163"/>
        <source>no LBL L{label} where this jump can reach it</source>
        <translation>no LBL L{label} where this jump can reach it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="165"/>
        <source>label L{label} is defined twice in this program unit</source>
        <translation>label L{label} is defined twice in this program unit</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="167"/>
        <source>JMPC is only allowed inside a subprogram</source>
        <translation>JMPC is only allowed inside a subprogram</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="168"/>
        <source>subprogram P{program} does not exist</source>
        <translation>subprogram P{program} does not exist</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="169"/>
        <source>calling P{program} here makes a subprogram call itself</source>
        <translation>calling P{program} here makes a subprogram call itself</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="171"/>
        <source>calls through P{program} nest deeper than {limit} subprograms</source>
        <translation>calls through P{program} nest deeper than {limit} subprograms</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="173"/>
        <source>SP without a matching SPE</source>
        <translation>SP without a matching SPE</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="174"/>
        <source>SPE without an SP before it</source>
        <translation>SPE without an SP before it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="175"/>
        <source>subprogram P{program} is defined twice</source>
        <translation>subprogram P{program} is defined twice</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="176"/>
        <source>only subprograms (SP ... SPE) may follow the first SP</source>
        <translation>only subprograms (SP ... SPE) may follow the first SP</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="178"/>
        <source>{name} cannot end level {level}</source>
        <translation>{name} cannot end level {level}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="179"/>
        <source>instruction after END, the end of the program</source>
        <translation>instruction after END, the end of the program</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="180"/>
        <source>a backward jump to L{label} repeated more than {limit} times in one scan</source>
        <translation>a backward jump to L{label} repeated more than {limit} times in one scan</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="183"/>
        <source>not an alarm message line: &apos;{text}&apos; (expected &apos;NNN text&apos; or &apos;A00.0 text&apos;)</source>
        <translation>not an alarm message line: &apos;{text}&apos; (expected &apos;NNN text&apos; or &apos;A00.0 text&apos;)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="185"/>
        <source>alarm number {number} is out of range (000 to 799)</source>
        <translation>alarm number {number} is out of range (000 to 799)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="187"/>
        <source>&apos;{text}&apos; is not an alarm bit (A0.0 to A99.7)</source>
        <translation>&apos;{text}&apos; is not an alarm bit (A0.0 to A99.7)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="189"/>
        <source>message {number} appears again; the one on line {first} is used</source>
        <translation>message {number} appears again; the one on line {first} is used</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="191"/>
        <source>message {number} has no text</source>
        <translation>message {number} has no text</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="192"/>
        <source>{name} is not implemented in the simulator yet</source>
        <translation>{name} is not implemented in the simulator yet</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="10"/>
        <source>ASCII format: the text opened by {quote} is never closed</source>
        <translation>ASCII format: the text opened by {quote} is never closed</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="12"/>
        <source>ASCII format: a repeat count must be 1 to 999, found {count}</source>
        <translation>ASCII format: a repeat count must be 1 to 999, found {count}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="14"/>
        <source>ASCII format: &apos;{text}&apos; is not an item (expected &apos;text&apos;, MX, hex codes, &quot;w.dRn&quot;, / or \)</source>
        <translation>ASCII format: &apos;{text}&apos; is not an item (expected &apos;text&apos;, MX, hex codes, &quot;w.dRn&quot;, / or \)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="18"/>
        <source>ASCII format: &quot;{text}&quot; is not a variable (expected e.g. &quot;8.2R0&quot; or &quot;4R10H&quot;)</source>
        <translation>ASCII format: &quot;{text}&quot; is not a variable (expected e.g. &quot;8.2R0&quot; or &quot;4R10H&quot;)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="21"/>
        <source>ASCII format: text after END: &apos;{text}&apos;</source>
        <translation>ASCII format: text after END: &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="23"/>
        <source>ASCII format: END is missing</source>
        <translation>ASCII format: END is missing</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="24"/>
        <source>&apos;{name}&apos; is not a Fatek instruction</source>
        <translation>&apos;{name}&apos; is not a Fatek instruction</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="26"/>
        <source>an operand line &apos;{text}&apos; without a FUN, TMR or CTR before it</source>
        <translation>an operand line &apos;{text}&apos; without a FUN, TMR or CTR before it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="28"/>
        <source>{name} needs a device</source>
        <translation>{name} needs a device</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="29"/>
        <source>&apos;{text}&apos; is not a Fatek device</source>
        <translation>&apos;{text}&apos; is not a Fatek device</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="30"/>
        <source>{name} cannot take &apos;{text}&apos; (use {kinds})</source>
        <translation>{name} cannot take &apos;{text}&apos; (use {kinds})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="32"/>
        <source>&apos;{text}&apos; is out of range ({range})</source>
        <translation>&apos;{text}&apos; is out of range ({range})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="33"/>
        <source>{name} with nothing before it: a network starts with ORG</source>
        <translation>{name} with nothing before it: a network starts with ORG</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="35"/>
        <source>{name} needs two blocks: start the second one with LD</source>
        <translation>{name} needs two blocks: start the second one with LD</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="37"/>
        <source>TR{number} is set twice in this network</source>
        <translation>TR{number} is set twice in this network</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="39"/>
        <source>a network has at most {limit} TR points</source>
        <translation>a network has at most {limit} TR points</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="41"/>
        <source>LD TR{number} before OUT TR{number} in this network</source>
        <translation>LD TR{number} before OUT TR{number} in this network</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="43"/>
        <source>{name} on the left rail: put ORG SHORT before it</source>
        <translation>{name} on the left rail: put ORG SHORT before it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="45"/>
        <source>{name}: {count} block(s) started with LD are not joined (ANDLD/ORLD)</source>
        <translation>{name}: {count} block(s) started with LD are not joined (ANDLD/ORLD)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="47"/>
        <source>FUN {number} is not a Fatek function LadderWorks knows</source>
        <translation>FUN {number} is not a Fatek function LadderWorks knows</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="49"/>
        <source>{name}: the operand line {param} is missing</source>
        <translation>{name}: the operand line {param} is missing</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="51"/>
        <source>{name} takes no more operands, found &apos;{text}&apos;</source>
        <translation>{name} takes no more operands, found &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="53"/>
        <source>&apos;{text}&apos; cannot be the operand {param} (a register, or a constant)</source>
        <translation>&apos;{text}&apos; cannot be the operand {param} (a register, or a constant)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="55"/>
        <source>&apos;{text}&apos; cannot be the operand {param} (a bit device: Y0, M5 …)</source>
        <translation>&apos;{text}&apos; cannot be the operand {param} (a bit device: Y0, M5 …)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="57"/>
        <source>{name} is kept and drawn but not simulated: its outputs stay 0</source>
        <translation>{name} is kept and drawn but not simulated: its outputs stay 0</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="59"/>
        <source>&apos;{text}&apos; is not the time base of {name} ({base})</source>
        <translation>&apos;{text}&apos; is not the time base of {name} ({base})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="61"/>
        <source>FO {text}: no function output here (FO0-FO7 after a box)</source>
        <translation>FO {text}: no function output here (FO0-FO7 after a box)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="63"/>
        <source>&apos;{text}…&apos; is too long to be a Fatek number: the line is not read</source>
        <translation>&apos;{text}…&apos; is too long to be a Fatek number: the line is not read</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="65"/>
        <source>not a WinProladder comment export: its first line must be REF, COMMENT, DESCRIPTION (tab-separated)</source>
        <translation>not a WinProladder comment export: its first line must be REF, COMMENT, DESCRIPTION (tab-separated)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="69"/>
        <source>&apos;{text}&apos; is not a Fatek device: the line is skipped</source>
        <translation>&apos;{text}&apos; is not a Fatek device: the line is skipped</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="71"/>
        <source>the comments were read in code page {chosen}; they read as {others} too: check the names</source>
        <translation>the comments were read in code page {chosen}; they read as {others} too: check the names</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="75"/>
        <source>byte {offset} (0x{byte}) is a character in no Windows code page tried: the comments are not read</source>
        <translation>byte {offset} (0x{byte}) is a character in no Windows code page tried: the comments are not read</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="79"/>
        <source>ASCII files: &apos;{text}&apos; is not a section header such as [R1000]</source>
        <translation>ASCII files: &apos;{text}&apos; is not a section header such as [R1000]</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="82"/>
        <source>not a WinProladder project: no &apos;Fatek WinProladder, File Format 1&apos; header</source>
        <translation>not a WinProladder project: no &apos;Fatek WinProladder, File Format 1&apos; header</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="84"/>
        <source>the .pdw file is cut short: its record at byte {offset} runs past the end</source>
        <translation>the .pdw file is cut short: its record at byte {offset} runs past the end</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="86"/>
        <source>the .pdw file is damaged: the record at byte {offset} fails its checksum</source>
        <translation>the .pdw file is damaged: the record at byte {offset} fails its checksum</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="88"/>
        <source>the .pdw file is damaged: the record at byte {offset} is malformed</source>
        <translation>the .pdw file is damaged: the record at byte {offset} is malformed</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="90"/>
        <source>the .pdw file holds no program (checked up to byte {offset})</source>
        <translation>the .pdw file holds no program (checked up to byte {offset})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="92"/>
        <source>the program at byte {offset} cannot be unmasked: it has no erased memory block to recover the mask from</source>
        <translation>the program at byte {offset} cannot be unmasked: it has no erased memory block to recover the mask from</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="96"/>
        <source>the .pdw file is damaged: its program image is wrong at byte {offset}</source>
        <translation>the .pdw file is damaged: its program image is wrong at byte {offset}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="98"/>
        <source>the .pdw file is damaged: the program&apos;s code does not match its checksum (byte {offset})</source>
        <translation>the .pdw file is damaged: the program&apos;s code does not match its checksum (byte {offset})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="102"/>
        <source>instruction code {word} at byte {offset} is not one LadderWorks decodes yet: the program is read up to it</source>
        <translation>instruction code {word} at byte {offset} is not one LadderWorks decodes yet: the program is read up to it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="106"/>
        <source>operand code {word} at byte {offset} is not a device LadderWorks decodes yet: the program is read up to it</source>
        <translation>operand code {word} at byte {offset} is not a device LadderWorks decodes yet: the program is read up to it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="110"/>
        <source>the program ends inside an instruction at byte {offset}</source>
        <translation>the program ends inside an instruction at byte {offset}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="195"/>
        <source>&apos;{text}&apos; cannot be the device of {name} here: with it the line reads as {other} (place {other} from the palette)</source>
        <translation>&apos;{text}&apos; cannot be the device of {name} here: with it the line reads as {other} (place {other} from the palette)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="198"/>
        <source>&apos;{text}&apos; is not a device (use {letters} with a number)</source>
        <translation>&apos;{text}&apos; is not a device (use {letters} with a number)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="200"/>
        <source>&apos;{text}&apos;: {letter} is numbered in octal (digits 0 to 7)</source>
        <translation>&apos;{text}&apos;: {letter} is numbered in octal (digits 0 to 7)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="202"/>
        <source>&apos;{text}&apos; is out of range ({first} to {last})</source>
        <translation>&apos;{text}&apos; is out of range ({first} to {last})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="203"/>
        <source>&apos;{text}&apos; is not a bit device</source>
        <translation>&apos;{text}&apos; is not a bit device</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="204"/>
        <source>&apos;{text}&apos; is not a word device</source>
        <translation>&apos;{text}&apos; is not a word device</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="205"/>
        <source>&apos;{text}&apos; is not listed in this table (use {letters})</source>
        <translation>&apos;{text}&apos; is not listed in this table (use {letters})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="207"/>
        <source>&apos;{text}&apos;: give a device or a range FIRST-LAST of at most {most} devices</source>
        <translation>&apos;{text}&apos;: give a device or a range FIRST-LAST of at most {most} devices</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="209"/>
        <source>{name}: operand {index} must be one of {expected}, found &apos;{text}&apos;</source>
        <translation>{name}: operand {index} must be one of {expected}, found &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="211"/>
        <source>&apos;{text}&apos; is not a K or H constant</source>
        <translation>&apos;{text}&apos; is not a K or H constant</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="212"/>
        <source>{name} is a {dialect} instruction the simulator does not run</source>
        <translation>{name} is a {dialect} instruction the simulator does not run</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="214"/>
        <source>{name} is kept and drawn but not simulated: the scan passes it by</source>
        <translation>{name} is kept and drawn but not simulated: the scan passes it by</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="216"/>
        <source>{count} instructions are not simulated, the scan passes them by (line): {names}</source>
        <translation>{count} instructions are not simulated, the scan passes them by (line): {names}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="219"/>
        <source>INV inverts all the power before it: draw it on a line from the rail or a branch point, not inside a parallel block</source>
        <translation>INV inverts all the power before it: draw it on a line from the rail or a branch point, not inside a parallel block</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="222"/>
        <source>{name}: operand {index} is missing</source>
        <translation>{name}: operand {index} is missing</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="223"/>
        <source>step {step} is not after step {previous}: the step numbers must grow</source>
        <translation>step {step} is not after step {previous}: the step numbers must grow</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="225"/>
        <source>subroutine without its SRET (before the next pointer or END)</source>
        <translation>subroutine without its SRET (before the next pointer or END)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="227"/>
        <source>SRET without a subroutine pointer (P n after FEND) before it</source>
        <translation>SRET without a subroutine pointer (P n after FEND) before it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="229"/>
        <source>after FEND only subroutines (P n ... SRET) and END may follow</source>
        <translation>after FEND only subroutines (P n ... SRET) and END may follow</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="231"/>
        <source>no pointer P{label} where this jump can reach it</source>
        <translation>no pointer P{label} where this jump can reach it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="233"/>
        <source>no subroutine P{program} after FEND for this CALL</source>
        <translation>no subroutine P{program} after FEND for this CALL</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="235"/>
        <source>{name} without a logic result before it (start with LD)</source>
        <translation>{name} without a logic result before it (start with LD)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="237"/>
        <source>this pointer P number is used twice</source>
        <translation>this pointer P number is used twice</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="239"/>
        <source>not a WPLSoft .dvp project: it does not start with the bytes 57 01 01 00</source>
        <translation>not a WPLSoft .dvp project: it does not start with the bytes 57 01 01 00</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="241"/>
        <source>the .dvp file is cut short at byte {offset}: it does not end with the line &lt;PrjectEnd&gt; WPLSoft writes last</source>
        <translation>the .dvp file is cut short at byte {offset}: it does not end with the line &lt;PrjectEnd&gt; WPLSoft writes last</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="244"/>
        <source>byte {offset}: .dvp format version {version} is not one LadderWorks reads (214, 215 and 216 are)</source>
        <translation>byte {offset}: .dvp format version {version} is not one LadderWorks reads (214, 215 and 216 are)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="247"/>
        <source>byte {offset}: the program memory of this .dvp project is not where WPLSoft puts it: the file is damaged</source>
        <translation>byte {offset}: the program memory of this .dvp project is not where WPLSoft puts it: the file is damaged</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="250"/>
        <source>byte {offset} (step {step}): instruction code {word} is not known to LadderWorks: kept as ?{word} with its operands</source>
        <translation>byte {offset} (step {step}): instruction code {word} is not known to LadderWorks: kept as ?{word} with its operands</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="253"/>
        <source>byte {offset} (step {step}): the word {word} names no device LadderWorks knows: the file is damaged or uses a device not decoded yet</source>
        <translation>byte {offset} (step {step}): the word {word} names no device LadderWorks knows: the file is damaged or uses a device not decoded yet</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="256"/>
        <source>byte {offset} (step {step}): the operand word {word} is neither a device nor a constant: the file is damaged</source>
        <translation>byte {offset} (step {step}): the operand word {word} is neither a device nor a constant: the file is damaged</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="259"/>
        <source>byte {offset} (step {step}): the operand words after {word} do not fit the instruction: the file is damaged</source>
        <translation>byte {offset} (step {step}): the operand words after {word} do not fit the instruction: the file is damaged</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="262"/>
        <source>byte {offset} (step {step}): the operand word {word} follows no instruction: the file is damaged</source>
        <translation>byte {offset} (step {step}): the operand word {word} follows no instruction: the file is damaged</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="265"/>
        <source>byte {offset}: the program does not end with END: the file is damaged</source>
        <translation>byte {offset}: the program does not end with END: the file is damaged</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="267"/>
        <source>byte {offset} (step {step}): instructions after END: the file is damaged</source>
        <translation>byte {offset} (step {step}): instructions after END: the file is damaged</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="270"/>
        <source>byte {offset}: a text section of the .dvp project is damaged</source>
        <translation>byte {offset}: a text section of the .dvp project is damaged</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="272"/>
        <source>byte {offset}: a device comment line is not DEVICE$&amp;text</source>
        <translation>byte {offset}: a device comment line is not DEVICE$&amp;text</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="274"/>
        <source>the project holds no program: no compiled instruction list and an empty ladder drawing</source>
        <translation>the project holds no program: no compiled instruction list and an empty ladder drawing</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="277"/>
        <source>the project was saved without compiling: its program is read from its ladder drawing</source>
        <translation>the project was saved without compiling: its program is read from its ladder drawing</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="280"/>
        <source>the project holds no compiled instruction list, and its ladder drawing has a cell LadderWorks does not read yet (byte {offset}: a branch, an edge contact ...): compile it in WPLSoft and save it again</source>
        <translation>the project holds no compiled instruction list, and its ladder drawing has a cell LadderWorks does not read yet (byte {offset}: a branch, an edge contact ...): compile it in WPLSoft and save it again</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="284"/>
        <source>LadderWorks does not write .dvp projects (the format is only partly known): save the program as a Delta instruction list (.il) instead</source>
        <translation>LadderWorks does not write .dvp projects (the format is only partly known): save the program as a Delta instruction list (.il) instead</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="287"/>
        <source>NEXT without a FOR before it</source>
        <translation>NEXT without a FOR before it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="288"/>
        <source>MC or STL without its MCR or RET after it</source>
        <translation>MC or STL without its MCR or RET after it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="290"/>
        <source>MCR or RET without its MC or STL before it</source>
        <translation>MCR or RET without its MC or STL before it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="292"/>
        <source>FOR without its NEXT</source>
        <translation>FOR without its NEXT</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="294"/>
        <source>the first line must be &apos;PMC SIGNAL DATA&apos;</source>
        <translation>the first line must be &apos;PMC SIGNAL DATA&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="296"/>
        <source>unknown command &apos;{text}&apos; (use REMARK, PROGRAM, SET, EXPECT, WAITFOR, FORCE or RELEASE)</source>
        <translation>unknown command &apos;{text}&apos; (use REMARK, PROGRAM, SET, EXPECT, WAITFOR, FORCE or RELEASE)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="300"/>
        <source>&apos;{text}&apos; is not a wait in ms</source>
        <translation>&apos;{text}&apos; is not a wait in ms</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="301"/>
        <source>negative wait {text} ms</source>
        <translation>negative wait {text} ms</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="302"/>
        <source>{command} needs {expected}</source>
        <translation>{command} needs {expected}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="303"/>
        <source>&apos;{text}&apos; is neither an address nor a symbol of the program</source>
        <translation>&apos;{text}&apos; is neither an address nor a symbol of the program</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="305"/>
        <source>&apos;{text}&apos; is not a value for {target}</source>
        <translation>&apos;{text}&apos; is not a value for {target}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="306"/>
        <source>unknown type &apos;{text}&apos; (use BIT, BYTE, WORD or DWORD)</source>
        <translation>unknown type &apos;{text}&apos; (use BIT, BYTE, WORD or DWORD)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="308"/>
        <source>&apos;{text}&apos;: only bits can be forced</source>
        <translation>&apos;{text}&apos;: only bits can be forced</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="309"/>
        <source>the scenario names no program: add a line PROGRAM,path (relative to the scenario file) or give the program on the command line</source>
        <translation>the scenario names no program: add a line PROGRAM,path (relative to the scenario file) or give the program on the command line</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="312"/>
        <source>a second PROGRAM line (the one on line {first} counts)</source>
        <translation>a second PROGRAM line (the one on line {first} counts)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="314"/>
        <source>the program &apos;{path}&apos; cannot be loaded: {reason}</source>
        <translation>the program &apos;{path}&apos; cannot be loaded: {reason}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="316"/>
        <source>the scenario names the program &apos;{path}&apos;; it runs on the one loaded in the PLC</source>
        <translation>the scenario names the program &apos;{path}&apos;; it runs on the one loaded in the PLC</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="320"/>
        <source>not a parameter line: &apos;{text}&apos; (expected ADDRESS = VALUE, e.g. T0:4 = 1000)</source>
        <translation>not a parameter line: &apos;{text}&apos; (expected ADDRESS = VALUE, e.g. T0:4 = 1000)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="324"/>
        <source>&apos;{text}&apos;: PMC parameters are in the T, C, K and D areas only</source>
        <translation>&apos;{text}&apos;: PMC parameters are in the T, C, K and D areas only</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="326"/>
        <source>&apos;{text}&apos; is not a value for {width} byte(s)</source>
        <translation>&apos;{text}&apos; is not a value for {width} byte(s)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="328"/>
        <source>&apos;{text}&apos; is not a number</source>
        <translation>&apos;{text}&apos; is not a number</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="329"/>
        <source>{value} is out of range ({low} to {high})</source>
        <translation>{value} is out of range ({low} to {high})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="330"/>
        <source>{value} bytes: a value has 1, 2 or 4 bytes</source>
        <translation>{value} bytes: a value has 1, 2 or 4 bytes</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="331"/>
        <source>&apos;{text}&apos;: type up to 8 binary digits (0 and 1), bit 7 first</source>
        <translation>&apos;{text}&apos;: type up to 8 binary digits (0 and 1), bit 7 first</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="333"/>
        <source>TMRB {number}: its preset is fixed in the program and cannot be changed here</source>
        <translation>TMRB {number}: its preset is fixed in the program and cannot be changed here</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="337"/>
        <source>expected TABLE,START,COUNT,PLC ADDRESS,ACCESS[,WIDTH], found {count} column(s)</source>
        <translation>expected TABLE,START,COUNT,PLC ADDRESS,ACCESS[,WIDTH], found {count} column(s)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="340"/>
        <source>&apos;{text}&apos; is not a Modbus table (use coils, discrete, holding or input)</source>
        <translation>&apos;{text}&apos; is not a Modbus table (use coils, discrete, holding or input)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="342"/>
        <source>&apos;{text}&apos; is not a number from {lo} to {hi}</source>
        <translation>&apos;{text}&apos; is not a number from {lo} to {hi}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="344"/>
        <source>{count} addresses from {start} run past Modbus address 65535</source>
        <translation>{count} addresses from {start} run past Modbus address 65535</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="346"/>
        <source>&apos;{text}&apos;: the access must be r (read) or rw (read and write)</source>
        <translation>&apos;{text}&apos;: the access must be r (read) or rw (read and write)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="348"/>
        <source>{table} cannot be written over Modbus: the access must be r</source>
        <translation>{table} cannot be written over Modbus: the access must be r</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="350"/>
        <source>{table} are bits: a width is for registers only</source>
        <translation>{table} are bits: a width is for registers only</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="352"/>
        <source>{count} elements from {device} run past the end of area {area} ({ranges})</source>
        <translation>{count} elements from {device} run past the end of area {area} ({ranges})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="354"/>
        <source>{table} {start}-{end} overlap the row on line {other}</source>
        <translation>{table} {start}-{end} overlap the row on line {other}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="356"/>
        <source>the map has no row</source>
        <translation>the map has no row</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="357"/>
        <source>{device}: a device&apos;s register is 16 bits: the width must be 2</source>
        <translation>{device}: a device&apos;s register is 16 bits: the width must be 2</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="360"/>
        <source>&apos;{text}&apos; is neither a name of the program nor an address</source>
        <translation>&apos;{text}&apos; is neither a name of the program nor an address</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="362"/>
        <source>&apos;{text}&apos; is a {type}: watch one of its members (e.g. {text}.Q)</source>
        <translation>&apos;{text}&apos; is a {type}: watch one of its members (e.g. {text}.Q)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="364"/>
        <source>&apos;{text}&apos; is a {type}: the watch table has no format for it</source>
        <translation>&apos;{text}&apos; is a {type}: the watch table has no format for it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="366"/>
        <source>&apos;{text}&apos; is not a date from D#1990-01-01 to D#2169-06-06 (e.g. D#2024-01-31)</source>
        <translation>&apos;{text}&apos; is not a date from D#1990-01-01 to D#2169-06-06 (e.g. D#2024-01-31)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="369"/>
        <source>&apos;{text}&apos; is not a time of day (e.g. TOD#12:30:00.000)</source>
        <translation>&apos;{text}&apos; is not a time of day (e.g. TOD#12:30:00.000)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="371"/>
        <source>the value has {length} characters: at most {limit} are read</source>
        <translation>the value has {length} characters: at most {limit} are read</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="373"/>
        <source>no modify value to write</source>
        <translation>no modify value to write</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="374"/>
        <source>&apos;{text}&apos; is not TRUE or FALSE (or 1, 0)</source>
        <translation>&apos;{text}&apos; is not TRUE or FALSE (or 1, 0)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="375"/>
        <source>&apos;{text}&apos; is not a whole number (e.g. 12, -3, 16#FF, 2#0101)</source>
        <translation>&apos;{text}&apos; is not a whole number (e.g. 12, -3, 16#FF, 2#0101)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="377"/>
        <source>&apos;{text}&apos; is out of range: {low} to {high}</source>
        <translation>&apos;{text}&apos; is out of range: {low} to {high}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="379"/>
        <source>&apos;{text}&apos; is not a real number (e.g. 1.5)</source>
        <translation>&apos;{text}&apos; is not a real number (e.g. 1.5)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="380"/>
        <source>&apos;{text}&apos; is not a time (e.g. T#5S_300MS, T#1M30S or 1500 ms)</source>
        <translation>&apos;{text}&apos; is not a time (e.g. T#5S_300MS, T#1M30S or 1500 ms)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="382"/>
        <source>&apos;{text}&apos; is not one character of the Latin-1 set (e.g. &apos;A&apos;)</source>
        <translation>&apos;{text}&apos; is not one character of the Latin-1 set (e.g. &apos;A&apos;)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="384"/>
        <source>&apos;{text}&apos; has characters a string cannot hold (only the Latin-1 set)</source>
        <translation>&apos;{text}&apos; has characters a string cannot hold (only the Latin-1 set)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="386"/>
        <source>&apos;{text}&apos; is longer than the string&apos;s {length} characters</source>
        <translation>&apos;{text}&apos; is longer than the string&apos;s {length} characters</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="388"/>
        <source>&apos;{name}&apos; is neither a map file nor a global DB of the program (its global DBs: {names})</source>
        <translation>&apos;{name}&apos; is neither a map file nor a global DB of the program (its global DBs: {names})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="113"/>
        <source>&apos;{text}&apos; is not an S7 address (e.g. %I0.0, %MW2, %DB1.DBW4) or a tag</source>
        <translation>&apos;{text}&apos; is not an S7 address (e.g. %I0.0, %MW2, %DB1.DBW4) or a tag</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="115"/>
        <source>SIMATIC SD: expected {expected}, found &apos;{found}&apos;</source>
        <translation>SIMATIC SD: expected {expected}, found &apos;{found}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="117"/>
        <source>SIMATIC SD: the text ends inside {what} (cut off?)</source>
        <translation>SIMATIC SD: the text ends inside {what} (cut off?)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="119"/>
        <source>network {network}: &apos;{part}&apos; is not an instruction LadderWorks simulates</source>
        <translation>network {network}: &apos;{part}&apos; is not an instruction LadderWorks simulates</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="121"/>
        <source>network {network}: &apos;{text}&apos; is neither a tag, a member of the block nor an address</source>
        <translation>network {network}: &apos;{text}&apos; is neither a tag, a member of the block nor an address</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="124"/>
        <source>network {network}: {part} needs its pin {pin}</source>
        <translation>network {network}: {part} needs its pin {pin}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="126"/>
        <source>network {network}: the wiring of {part} cannot be followed ({why})</source>
        <translation>network {network}: the wiring of {part} cannot be followed ({why})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="128"/>
        <source>network {network}: there is no label &apos;{label}&apos; in this block</source>
        <translation>network {network}: there is no label &apos;{label}&apos; in this block</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="130"/>
        <source>network {network}: a {language} network is shown, not simulated</source>
        <translation>network {network}: a {language} network is shown, not simulated</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="132"/>
        <source>network {network}: the block &apos;{block}&apos; it calls is not in the program</source>
        <translation>network {network}: the block &apos;{block}&apos; it calls is not in the program</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="134"/>
        <source>network {network}: {text} is in none of the tag tables read; LadderWorks gives it a place of its own ({type})</source>
        <translation>network {network}: {text} is in none of the tag tables read; LadderWorks gives it a place of its own ({type})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="137"/>
        <source>network {network}: {part} on the type &apos;{type}&apos; is not simulated</source>
        <translation>network {network}: {part} on the type &apos;{type}&apos; is not simulated</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="139"/>
        <source>network {network}: no room left for &apos;{text}&apos; (DB members and instances share 10000 bytes)</source>
        <translation>network {network}: no room left for &apos;{text}&apos; (DB members and instances share 10000 bytes)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="142"/>
        <source>the file has {size} MB: S7 exports over {limit} MB are not read</source>
        <translation>the file has {size} MB: S7 exports over {limit} MB are not read</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="144"/>
        <source>tag table: {why}</source>
        <translation>tag table: {why}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="146"/>
        <source>network {network}, row {row}, column {column}: the contact or coil has no operand</source>
        <translation>network {network}, row {row}, column {column}: the contact or coil has no operand</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="149"/>
        <source>network {network}, row {row}, column {column}: &apos;{name}&apos; is no S7 element (use the S7 palette)</source>
        <translation>network {network}, row {row}, column {column}: &apos;{name}&apos; is no S7 element (use the S7 palette)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="152"/>
        <source>this change cannot be written into the S7 block&apos;s file: make it in TIA Portal</source>
        <translation>this change cannot be written into the S7 block&apos;s file: make it in TIA Portal</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="155"/>
        <source>{file}, line {line}: expected {expected}, found &apos;{found}&apos;: the source is not read</source>
        <translation>{file}, line {line}: expected {expected}, found &apos;{found}&apos;: the source is not read</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="158"/>
        <source>{file}, line {line}: the text ends inside {what} (cut off?): the source is not read</source>
        <translation>{file}, line {line}: the text ends inside {what} (cut off?): the source is not read</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="161"/>
        <source>the S7 block&apos;s file no longer reads (line {line}): nothing is written</source>
        <translation>the S7 block&apos;s file no longer reads (line {line}): nothing is written</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="163"/>
        <source>&apos;{part}&apos; cannot be written in the S7 block&apos;s file form: make this change in TIA Portal</source>
        <translation>&apos;{part}&apos; cannot be written in the S7 block&apos;s file form: make this change in TIA Portal</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="166"/>
        <source>&apos;{text}&apos; is no S7 jump label: letters, digits and _, not starting with a digit</source>
        <translation>&apos;{text}&apos; is no S7 jump label: letters, digits and _, not starting with a digit</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="169"/>
        <source>network {network} is not a complete S7 network yet (an element S7 does not have, an operand missing or still &lt;???&gt;): the S7 block&apos;s file is not written</source>
        <translation>network {network} is not a complete S7 network yet (an element S7 does not have, an operand missing or still &lt;???&gt;): the S7 block&apos;s file is not written</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="174"/>
        <source>SimaticML: the file is {size} MB, more than the {limit} MB LadderWorks reads</source>
        <translation>SimaticML: the file is {size} MB, more than the {limit} MB LadderWorks reads</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="177"/>
        <source>SimaticML: {what} is refused (entities are never expanded or fetched)</source>
        <translation>SimaticML: {what} is refused (entities are never expanded or fetched)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="179"/>
        <source>SimaticML: not well-formed XML ({why})</source>
        <translation>SimaticML: not well-formed XML ({why})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="180"/>
        <source>SimaticML: the document holds no block (SW.Blocks.…) and no tag table</source>
        <translation>SimaticML: the document holds no block (SW.Blocks.…) and no tag table</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="182"/>
        <source>{block}, network {network}: the namespace &apos;{uri}&apos; is not TIA Openness&apos;s; the network is not read</source>
        <translation>{block}, network {network}: the namespace &apos;{uri}&apos; is not TIA Openness&apos;s; the network is not read</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="185"/>
        <source>{block}, network {network}: {kind} version v{version} is newer than the v5 LadderWorks knows; read as v5</source>
        <translation>{block}, network {network}: {kind} version v{version} is newer than the v5 LadderWorks knows; read as v5</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="188"/>
        <source>{block}, network {network}: wire {wire} goes to the part UId {uid}, which is not in the network</source>
        <translation>{block}, network {network}: wire {wire} goes to the part UId {uid}, which is not in the network</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="191"/>
        <source>{block}, network {network}: the wires from part UId {uid} loop back to it</source>
        <translation>{block}, network {network}: the wires from part UId {uid} loop back to it</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="194"/>
        <source>{block}, network {network}: part UId {uid} &apos;{part}&apos; is not known to LadderWorks (kept, not simulated)</source>
        <translation>{block}, network {network}: part UId {uid} &apos;{part}&apos; is not known to LadderWorks (kept, not simulated)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="197"/>
        <source>{block}, network {network}: more than {limit} parts; the network is not read</source>
        <translation>{block}, network {network}: more than {limit} parts; the network is not read</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="200"/>
        <source>{block}, network {network}: access UId {uid} of scope &apos;{scope}&apos; names nothing LadderWorks reads; the parts wired to it are not simulated</source>
        <translation>{block}, network {network}: access UId {uid} of scope &apos;{scope}&apos; names nothing LadderWorks reads; the parts wired to it are not simulated</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="203"/>
        <source>{block}, network {network}: part UId {uid} calls &apos;{callee}&apos;, which is not in the program</source>
        <translation>{block}, network {network}: part UId {uid} calls &apos;{callee}&apos;, which is not in the program</translation>
    </message>
</context>
<context>
    <name>ErrorList</name>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="27"/>
        <source>network {0}, row {1}, column {2}</source>
        <translation>network {0}, row {1}, column {2}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="31"/>
        <source>network {0}</source>
        <translation>network {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="34"/>
        <source>line {0}, column {1}</source>
        <translation>line {0}, column {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="91"/>
        <source>Errors: {0}   Warnings: {1}</source>
        <translation>Errors: {0}   Warnings: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="97"/>
        <source>Error</source>
        <translation>Error</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="98"/>
        <source>Warning</source>
        <translation>Warning</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="112"/>
        <source>Errors</source>
        <translation>Errors</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="113"/>
        <source>Show warnings</source>
        <translation>Show warnings</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="115"/>
        <source>Kind</source>
        <translation>Kind</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="116"/>
        <source>Where</source>
        <translation>Where</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="117"/>
        <source>Message</source>
        <translation>Message</translation>
    </message>
</context>
<context>
    <name>FamilyWords</name>
    <message>
        <location filename="../ladderworks/gui/family_words.py" line="28"/>
        <location filename="../ladderworks/gui/family_words.py" line="33"/>
        <location filename="../ladderworks/gui/family_words.py" line="38"/>
        <source>e.g. {0}</source>
        <translation>e.g. {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/family_words.py" line="44"/>
        <source>Type the devices to watch, e.g. {0}</source>
        <translation>Type the devices to watch, e.g. {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/family_words.py" line="54"/>
        <source>FANUC PMC</source>
        <translation>FANUC PMC</translation>
    </message>
</context>
<context>
    <name>FindReplace</name>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="194"/>
        <location filename="../ladderworks/gui/find_replace.py" line="205"/>
        <location filename="../ladderworks/gui/find_replace.py" line="281"/>
        <source>Not found</source>
        <translation>Not found</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="224"/>
        <source>network {0}</source>
        <translation>network {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="230"/>
        <source>{0} of {1}: {2}, {3}</source>
        <translation>{0} of {1}: {2}, {3}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="264"/>
        <source>Replace {0} with {1}</source>
        <translation>Replace {0} with {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="270"/>
        <source>Replaced; no more found</source>
        <translation>Replaced; no more found</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="287"/>
        <source>Replace all {0} with {1}</source>
        <translation>Replace all {0} with {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="289"/>
        <source>{0} replaced in {1} networks</source>
        <translation>{0} replaced in {1} networks</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="298"/>
        <source>Address, symbol or words, {0}</source>
        <translation>Address, symbol or words, {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="300"/>
        <source>Address or symbol, {0}</source>
        <translation>Address or symbol, {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="305"/>
        <source>Find and replace</source>
        <translation>Find and replace</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="176"/>
        <location filename="../ladderworks/gui/find_replace.py" line="306"/>
        <source>Find:</source>
        <translation>Find:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="226"/>
        <source>{0} ({1})</source>
        <translation>{0} ({1})</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="229"/>
        <source>network comment</source>
        <translation>network comment</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="307"/>
        <source>Replace with:</source>
        <translation>Replace with:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="309"/>
        <source>Find &amp;next</source>
        <translation>Find &amp;next</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="310"/>
        <source>Find &amp;previous</source>
        <translation>Find &amp;previous</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="311"/>
        <source>&amp;Replace</source>
        <translation>&amp;Replace</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="312"/>
        <source>Replace &amp;all</source>
        <translation>Replace &amp;all</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="313"/>
        <source>Close</source>
        <translation>Close</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="314"/>
        <source>Also in comments and signal descriptions</source>
        <translation>Also in comments and signal descriptions</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="315"/>
        <source>Find the words in the elements&apos; comments, the program&apos;s comments of its addresses, the manual&apos;s signal descriptions and the network comments</source>
        <translation>Find the words in the elements&apos; comments, the program&apos;s comments of its addresses, the manual&apos;s signal descriptions and the network comments</translation>
    </message>
</context>
<context>
    <name>FitWidth</name>
    <message>
        <location filename="../ladderworks/gui/editor/zoom.py" line="74"/>
        <source>Fit width: the ladder is too narrow ({0} px) for its networks even at {1} %: close or narrow a dock, or widen the window</source>
        <translation>Fit width: the ladder is too narrow ({0} px) for its networks even at {1} %: close or narrow a dock, or widen the window</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/zoom.py" line="78"/>
        <source>Fit width: every network fits at {0} % (a dock closed reads larger)</source>
        <translation>Fit width: every network fits at {0} % (a dock closed reads larger)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/zoom.py" line="81"/>
        <source>Fit width: every network fits the window&apos;s width</source>
        <translation>Fit width: every network fits the window&apos;s width</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/zoom.py" line="82"/>
        <source>Fit width: {0} of {1} networks fit the window&apos;s width; the {2} wider ones scroll sideways</source>
        <translation>Fit width: {0} of {1} networks fit the window&apos;s width; the {2} wider ones scroll sideways</translation>
    </message>
</context>
<context>
    <name>ForceList</name>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="93"/>
        <source>Forced and passive</source>
        <translation>Forced and passive</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="95"/>
        <source>Kind</source>
        <translation>Kind</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="95"/>
        <source>Signal / element</source>
        <translation>Signal / element</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="96"/>
        <source>Value</source>
        <translation>Value</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="98"/>
        <source>Release all</source>
        <translation>Release all</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="99"/>
        <source>&amp;Bit:</source>
        <translation>&amp;Bit:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="100"/>
        <source>an address or a tag</source>
        <translation>an address or a tag</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="101"/>
        <source>Force to 1</source>
        <translation>Force to 1</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="102"/>
        <source>Force to 0</source>
        <translation>Force to 0</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="118"/>
        <source>{0} is not a bit: only bits are forced</source>
        <translation>{0} is not a bit: only bits are forced</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="127"/>
        <source>Load a program to force its bits</source>
        <translation>Load a program to force its bits</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="141"/>
        <location filename="../ladderworks/gui/docks/force_list.py" line="145"/>
        <source>FORCED</source>
        <translation>FORCED</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="152"/>
        <source>network {0}, line {1}: {2}</source>
        <translation>network {0}, line {1}: {2}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="158"/>
        <source>PASSIVE</source>
        <translation>PASSIVE</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="169"/>
        <source>Release</source>
        <translation>Release</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="173"/>
        <source>{0} forced, {1} passive</source>
        <translation>{0} forced, {1} passive</translation>
    </message>
</context>
<context>
    <name>FunctionDialog</name>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="56"/>
        <source>one of {0}</source>
        <translation>one of {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="58"/>
        <source>{0} to {1}</source>
        <translation>{0} to {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="61"/>
        <source>a device of this PLC</source>
        <translation>a device of this PLC</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="63"/>
        <source>a constant or a device of this PLC</source>
        <translation>a constant or a device of this PLC</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="66"/>
        <source>byte address ({0} bytes)</source>
        <translation>byte address ({0} bytes)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="68"/>
        <source>byte address</source>
        <translation>byte address</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="70"/>
        <source>constant or byte address</source>
        <translation>constant or byte address</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="72"/>
        <source>up to 4 binary digits, e.g. 1111</source>
        <translation>up to 4 binary digits, e.g. 1111</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="52"/>
        <location filename="../ladderworks/gui/function_dialog.py" line="74"/>
        <source>P{0} to P{1}</source>
        <translation>P{0} to P{1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="49"/>
        <source>empty, P (on the rising edge), D (32-bit) or DP</source>
        <translation>empty, P (on the rising edge), D (32-bit) or DP</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="77"/>
        <source>L{0} to L{1}</source>
        <translation>L{0} to L{1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="80"/>
        <source>constant or address, kept as written</source>
        <translation>constant or address, kept as written</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="82"/>
        <source>values separated by spaces</source>
        <translation>values separated by spaces</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="191"/>
        <source>{0} — {1}: fill in the parameters</source>
        <translation>{0} — {1}: fill in the parameters</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="194"/>
        <source>This instruction has no parameters.</source>
        <translation>This instruction has no parameters.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="196"/>
        <source>Comment (shown with the box, written after // in the file):</source>
        <translation>Comment (shown with the box, written after // in the file):</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="199"/>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="200"/>
        <source>Value</source>
        <translation>Value</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="201"/>
        <source>Allowed</source>
        <translation>Allowed</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="235"/>
        <source>The parameters are not valid</source>
        <translation>The parameters are not valid</translation>
    </message>
</context>
<context>
    <name>InstructionHelp</name>
    <message>
        <location filename="../ladderworks/gui/help_browser.py" line="101"/>
        <source>Contacts, coils and blocks</source>
        <translation>Contacts, coils and blocks</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/help_browser.py" line="206"/>
        <source>No reference entry for this instruction.</source>
        <translation>No reference entry for this instruction.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/help_browser.py" line="218"/>
        <source>Instruction reference</source>
        <translation>Instruction reference</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/help_browser.py" line="219"/>
        <source>Search, e.g. TMR</source>
        <translation>Search, e.g. TMR</translation>
    </message>
</context>
<context>
    <name>LadderEditor</name>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="146"/>
        <source>NOT</source>
        <translation>NOT</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="354"/>
        <source>The comment tool works on an empty row only</source>
        <translation>The comment tool works on an empty row only</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="46"/>
        <source>Delete</source>
        <translation>Delete</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="155"/>
        <source>Insert row</source>
        <translation>Insert row</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="183"/>
        <source>Place contact</source>
        <translation>Place contact</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="297"/>
        <source>This instruction is not placed from the palette in this program</source>
        <translation>This instruction is not placed from the palette in this program</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="335"/>
        <source>Label {0}</source>
        <translation>Label {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="400"/>
        <source>Output pins</source>
        <translation>Output pins</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="47"/>
        <source>Place coil</source>
        <translation>Place coil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="194"/>
        <source>Select a contact or a coil for the OR tool</source>
        <translation>Select a contact or a coil for the OR tool</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="198"/>
        <source>OR</source>
        <translation>OR</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="315"/>
        <source>Line: click the second point</source>
        <translation>Line: click the second point</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="160"/>
        <source>Line</source>
        <translation>Line</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="57"/>
        <source>Place {0}</source>
        <translation>Place {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="62"/>
        <source>Parameters of {0}</source>
        <translation>Parameters of {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/inline_edit.py" line="58"/>
        <source>Operand, e.g. &quot;Start&quot;, %I0.1, #Run (// comment)</source>
        <translation>Operand, e.g. &quot;Start&quot;, %I0.1, #Run (// comment)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/inline_edit.py" line="69"/>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="141"/>
        <source>Comment</source>
        <translation>Comment</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="67"/>
        <source>Address {0}</source>
        <translation>Address {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/inline_edit.py" line="59"/>
        <source>Address or symbol, e.g. X2.1 (// comment)</source>
        <translation>Address or symbol, e.g. X2.1 (// comment)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="427"/>
        <source>Cut</source>
        <translation>Cut</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="439"/>
        <source>Paste</source>
        <translation>Paste</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="452"/>
        <source>Delete network</source>
        <translation>Delete network</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/symbol_text.py" line="86"/>
        <source>N{0} row {1} col {2}</source>
        <translation>N{0} row {1} col {2}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/symbol_text.py" line="104"/>
        <source>open circuit here: draw a wire or an element</source>
        <translation>open circuit here: draw a wire or an element</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/network_item.py" line="75"/>
        <source>N{0}</source>
        <translation>N{0}</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="72"/>
        <source>&amp;Open...</source>
        <translation>&amp;Open...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="76"/>
        <source>&amp;Save</source>
        <translation>&amp;Save</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="78"/>
        <source>Save &amp;As...</source>
        <translation>Save &amp;As...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="80"/>
        <source>&amp;Import .MOD...</source>
        <translation>&amp;Import .MOD...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="82"/>
        <source>&amp;Export .MOD...</source>
        <translation>&amp;Export .MOD...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="90"/>
        <source>Clear the list</source>
        <translation>Clear the list</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="86"/>
        <source>Program &amp;properties...</source>
        <translation>Program &amp;properties...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="70"/>
        <source>&amp;New...</source>
        <translation>&amp;New...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="74"/>
        <source>Open &amp;folder...</source>
        <translation>Open &amp;folder...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="84"/>
        <source>Import s&amp;ymbols...</source>
        <translation>Import s&amp;ymbols...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="88"/>
        <source>&amp;Quit</source>
        <translation>&amp;Quit</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="92"/>
        <location filename="../ladderworks/gui/undo_texts.py" line="13"/>
        <source>&amp;Undo</source>
        <translation>&amp;Undo</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="95"/>
        <location filename="../ladderworks/gui/undo_texts.py" line="14"/>
        <source>&amp;Redo</source>
        <translation>&amp;Redo</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="98"/>
        <source>Cu&amp;t</source>
        <translation>Cu&amp;t</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="100"/>
        <source>&amp;Copy</source>
        <translation>&amp;Copy</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="102"/>
        <source>&amp;Paste</source>
        <translation>&amp;Paste</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="105"/>
        <source>&amp;Delete</source>
        <translation>&amp;Delete</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="108"/>
        <source>&amp;Edit element</source>
        <translation>&amp;Edit element</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="110"/>
        <source>NOT (invert)</source>
        <translation>NOT (invert)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="113"/>
        <source>OR (add parallel)</source>
        <translation>OR (add parallel)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="115"/>
        <source>Output pins (FO)…</source>
        <translation>Output pins (FO)…</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="118"/>
        <source>Insert row before</source>
        <translation>Insert row before</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="121"/>
        <source>Insert row after</source>
        <translation>Insert row after</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="124"/>
        <source>Delete network</source>
        <translation>Delete network</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="126"/>
        <source>&amp;Find...</source>
        <translation>&amp;Find...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="128"/>
        <source>R&amp;eplace...</source>
        <translation>R&amp;eplace...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="130"/>
        <source>Find &amp;next</source>
        <translation>Find &amp;next</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="132"/>
        <source>Find pre&amp;vious</source>
        <translation>Find pre&amp;vious</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="134"/>
        <source>Zoom &amp;in</source>
        <translation>Zoom &amp;in</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="137"/>
        <source>Zoom &amp;out</source>
        <translation>Zoom &amp;out</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="140"/>
        <source>&amp;Normal size</source>
        <translation>&amp;Normal size</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="142"/>
        <source>Fit &amp;width</source>
        <translation>Fit &amp;width</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="145"/>
        <source>Show as &amp;ladder</source>
        <translation>Show as &amp;ladder</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="147"/>
        <source>Show as &amp;text</source>
        <translation>Show as &amp;text</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="149"/>
        <source>C&amp;heck</source>
        <translation>C&amp;heck</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="151"/>
        <source>&amp;Compile</source>
        <translation>&amp;Compile</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="159"/>
        <source>&amp;Instruction reference</source>
        <translation>&amp;Instruction reference</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="161"/>
        <source>&amp;About LadderWorks</source>
        <translation>&amp;About LadderWorks</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="55"/>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="56"/>
        <source>Recent files</source>
        <translation>Recent files</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="58"/>
        <source>&amp;Edit</source>
        <translation>&amp;Edit</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="59"/>
        <source>&amp;View</source>
        <translation>&amp;View</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="60"/>
        <source>&amp;PLC</source>
        <translation>&amp;PLC</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="61"/>
        <source>&amp;Tools</source>
        <translation>&amp;Tools</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="62"/>
        <source>&amp;Language</source>
        <translation>&amp;Language</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="63"/>
        <source>&amp;Help</source>
        <translation>&amp;Help</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="66"/>
        <source>Main toolbar</source>
        <translation>Main toolbar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="209"/>
        <source>Zoom</source>
        <translation>Zoom</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="443"/>
        <source>Compile finished: {0} bytes (not loaded: the PLC runs the previous program)</source>
        <translation>Compile finished: {0} bytes (not loaded: the PLC runs the previous program)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="455"/>
        <source>Compile finished, but the PLC refused the program</source>
        <translation>Compile finished, but the PLC refused the program</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="462"/>
        <source>Compile finished: {0} bytes, loaded into the PLC</source>
        <translation>Compile finished: {0} bytes, loaded into the PLC</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="540"/>
        <location filename="../ladderworks/gui/main_window.py" line="284"/>
        <location filename="../ladderworks/gui/main_window.py" line="457"/>
        <source>Untitled</source>
        <translation>Untitled</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="136"/>
        <source>Unsaved changes</source>
        <translation>Unsaved changes</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="129"/>
        <source>Ladder programs</source>
        <translation>Ladder programs</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="130"/>
        <source>Mnemonic programs</source>
        <translation>Mnemonic programs</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="131"/>
        <source>LADDER-III exports</source>
        <translation>LADDER-III exports</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="132"/>
        <source>Delta DVP instruction lists</source>
        <translation>Delta DVP instruction lists</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="134"/>
        <source>WPLSoft projects</source>
        <translation>WPLSoft projects</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="135"/>
        <source>Fatek WinProladder listings</source>
        <translation>Fatek WinProladder listings</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="137"/>
        <source>Fatek WinProladder projects</source>
        <translation>Fatek WinProladder projects</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="138"/>
        <source>Siemens S7-1200 SIMATIC SD blocks</source>
        <translation>Siemens S7-1200 SIMATIC SD blocks</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="139"/>
        <source>Siemens S7-1200 SimaticML exports</source>
        <translation>Siemens S7-1200 SimaticML exports</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="126"/>
        <source>{0} was changed by another program</source>
        <translation>{0} was changed by another program</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="137"/>
        <source>The program has unsaved changes. Save them?</source>
        <translation>The program has unsaved changes. Save them?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="183"/>
        <source>PLC family</source>
        <translation>PLC family</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="201"/>
        <location filename="../ladderworks/gui/file_actions.py" line="219"/>
        <source>Open</source>
        <translation>Open</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="202"/>
        <location filename="../ladderworks/gui/file_actions.py" line="220"/>
        <location filename="../ladderworks/gui/file_actions.py" line="556"/>
        <location filename="../ladderworks/gui/symbol_import.py" line="58"/>
        <source>Cannot read {0}: {1}</source>
        <translation>Cannot read {0}: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="207"/>
        <source>PMC parameters</source>
        <translation>PMC parameters</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="207"/>
        <source>{0}: {1} lines not understood (kept as they are); line {2}: {3}</source>
        <translation>{0}: {1} lines not understood (kept as they are); line {2}: {3}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="252"/>
        <source>The file has errors: it is shown as text</source>
        <translation>The file has errors: it is shown as text</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="260"/>
        <source>Open program</source>
        <translation>Open program</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="334"/>
        <location filename="../ladderworks/gui/file_actions.py" line="340"/>
        <location filename="../ladderworks/gui/file_actions.py" line="348"/>
        <location filename="../ladderworks/gui/file_actions.py" line="422"/>
        <location filename="../ladderworks/gui/file_actions.py" line="426"/>
        <location filename="../ladderworks/gui/folder_program.py" line="87"/>
        <location filename="../ladderworks/gui/folder_program.py" line="108"/>
        <location filename="../ladderworks/gui/folder_program.py" line="112"/>
        <location filename="../ladderworks/gui/save_refusal.py" line="41"/>
        <source>Save</source>
        <translation>Save</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="334"/>
        <source>{0} did not parse and is not overwritten. Fix the errors and use Show as ladder, or save under another name.</source>
        <translation>{0} did not parse and is not overwritten. Fix the errors and use Show as ladder, or save under another name.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="340"/>
        <source>{0} is a WinProladder project (.pdw): LadderWorks reads it but does not write it, since what it does not decode would be lost. Save the program as a WinProladder listing (.lst) instead.</source>
        <translation>{0} is a WinProladder project (.pdw): LadderWorks reads it but does not write it, since what it does not decode would be lost. Save the program as a WinProladder listing (.lst) instead.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="422"/>
        <location filename="../ladderworks/gui/file_actions.py" line="495"/>
        <location filename="../ladderworks/gui/folder_program.py" line="108"/>
        <source>{0} is read-only and is not replaced.</source>
        <translation>{0} is read-only and is not replaced.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="427"/>
        <location filename="../ladderworks/gui/file_actions.py" line="500"/>
        <location filename="../ladderworks/gui/folder_program.py" line="112"/>
        <source>Cannot write {0}: {1}</source>
        <translation>Cannot write {0}: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="437"/>
        <source>Fatek WinProladder listings (*.lst *.LST);;All files (*)</source>
        <translation>Fatek WinProladder listings (*.lst *.LST);;All files (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="555"/>
        <source>Recover unsaved work</source>
        <translation>Recover unsaved work</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="572"/>
        <source>Recovered unsaved work from {0}</source>
        <translation>Recovered unsaved work from {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="404"/>
        <source>Saved {0}; networks with errors are kept as drawings (see the error list)</source>
        <translation>Saved {0}; networks with errors are kept as drawings (see the error list)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="409"/>
        <source>Saved {0}</source>
        <translation>Saved {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="436"/>
        <location filename="../ladderworks/gui/file_actions.py" line="441"/>
        <location filename="../ladderworks/gui/file_actions.py" line="447"/>
        <source>Save program</source>
        <translation>Save program</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="442"/>
        <source>Delta DVP instruction lists (*.il *.IL *.txt *.TXT);;All files (*)</source>
        <translation>Delta DVP instruction lists (*.il *.IL *.txt *.TXT);;All files (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="455"/>
        <source>Import .MOD</source>
        <translation>Import .MOD</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="456"/>
        <source>Mnemonic programs (*.MOD *.mod);;All files (*)</source>
        <translation>Mnemonic programs (*.MOD *.mod);;All files (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="478"/>
        <location filename="../ladderworks/gui/file_actions.py" line="495"/>
        <location filename="../ladderworks/gui/file_actions.py" line="499"/>
        <source>Export .MOD</source>
        <translation>Export .MOD</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="479"/>
        <source>Mnemonic programs (*.MOD);;All files (*)</source>
        <translation>Mnemonic programs (*.MOD);;All files (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="503"/>
        <source>Exported {0}</source>
        <translation>Exported {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="413"/>
        <source>Check: {0} error(s)</source>
        <translation>Check: {0} error(s)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="429"/>
        <source>Compile failed: {0} error(s)</source>
        <translation>Compile failed: {0} error(s)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="449"/>
        <source>Compile finished: {0} bytes (not loaded: the PLC keeps the program it has)</source>
        <translation>Compile finished: {0} bytes (not loaded: the PLC keeps the program it has)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="499"/>
        <source>Address {0} set</source>
        <translation>Address {0} set</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="502"/>
        <source>{0} copied (select a contact or coil to set its address)</source>
        <translation>{0} copied (select a contact or coil to set its address)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="535"/>
        <source>About LadderWorks</source>
        <translation>About LadderWorks</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="536"/>
        <source>LadderWorks: ladder (FANUC PMC style) programming for CNC machines.</source>
        <translation>LadderWorks: ladder (FANUC PMC style) programming for CNC machines.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/undo_texts.py" line="15"/>
        <source>&amp;Undo {0}</source>
        <translation>&amp;Undo {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/undo_texts.py" line="16"/>
        <source>&amp;Redo {0}</source>
        <translation>&amp;Redo {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/symbol_import.py" line="44"/>
        <location filename="../ladderworks/gui/symbol_import.py" line="54"/>
        <source>Import symbols</source>
        <translation>Import symbols</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/symbol_import.py" line="45"/>
        <source>WinProladder comment exports (*.txt);;All files (*)</source>
        <translation>WinProladder comment exports (*.txt);;All files (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/symbol_import.py" line="74"/>
        <source>{0} symbols imported from {1}</source>
        <translation>{0} symbols imported from {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="47"/>
        <source>All files (*)</source>
        <translation>All files (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="50"/>
        <source>Delta DVP instruction lists (*.txt *.TXT)</source>
        <translation>Delta DVP instruction lists (*.txt *.TXT)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="53"/>
        <source>Siemens S7-1200 SIMATIC SD blocks (*.s7dcl)</source>
        <translation>Siemens S7-1200 SIMATIC SD blocks (*.s7dcl)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="54"/>
        <source>Siemens S7-1200 SimaticML exports (*.xml)</source>
        <translation>Siemens S7-1200 SimaticML exports (*.xml)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="57"/>
        <source>Fatek WinProladder listings (*.lst *.LST)</source>
        <translation>Fatek WinProladder listings (*.lst *.LST)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="59"/>
        <source>Ladder programs (*.LAD *.lad)</source>
        <translation>Ladder programs (*.LAD *.lad)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="66"/>
        <source>The program has errors: fix them first (see the error list)</source>
        <translation>The program has errors: fix them first (see the error list)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="70"/>
        <source>The program cannot become a {0} program: {1}</source>
        <translation>The program cannot become a {0} program: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/folder_program.py" line="71"/>
        <source>Open a folder of exported blocks</source>
        <translation>Open a folder of exported blocks</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/folder_program.py" line="81"/>
        <source>{0}: no changes to save</source>
        <translation>{0}: no changes to save</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/folder_program.py" line="87"/>
        <source>{0} is a folder of exported blocks: save the changed program under a file name</source>
        <translation>{0} is a folder of exported blocks: save the changed program under a file name</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/folder_program.py" line="115"/>
        <source>Saved {0} in the folder {1} (its other files are unchanged)</source>
        <translation>Saved {0} in the folder {1} (its other files are unchanged)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/save_refusal.py" line="41"/>
        <source>{0} is not written: {1}</source>
        <translation>{0} is not written: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/save_refusal.py" line="46"/>
        <source>Not saved: {0}</source>
        <translation>Not saved: {0}</translation>
    </message>
</context>
<context>
    <name>ModbusDock</name>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="135"/>
        <source>Modbus server</source>
        <translation>Modbus server</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="136"/>
        <source>&amp;Address (host:port):</source>
        <translation>&amp;Address (host:port):</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="215"/>
        <source>&amp;Map file (CSV):</source>
        <translation>&amp;Map file (CSV):</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="137"/>
        <location filename="../ladderworks/gui/docks/modbus.py" line="250"/>
        <source>the {0} map</source>
        <translation>the {0} map</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="139"/>
        <source>Choose…</source>
        <translation>Choose…</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="140"/>
        <source>Dialect&apos;s map</source>
        <translation>Dialect&apos;s map</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="141"/>
        <source>Serve the program&apos;s dialect&apos;s own map (docs/modbus.md)</source>
        <translation>Serve the program&apos;s dialect&apos;s own map (docs/modbus.md)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="143"/>
        <source>&amp;Holding registers:</source>
        <translation>&amp;Holding registers:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="145"/>
        <source>Clients connected:</source>
        <translation>Clients connected:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="146"/>
        <source>Requests a second:</source>
        <translation>Requests a second:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="162"/>
        <source>Type the address as host:port, e.g. {0}.</source>
        <translation>Type the address as host:port, e.g. {0}.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="176"/>
        <source>Cannot listen on {0}: {1}</source>
        <translation>Cannot listen on {0}: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="190"/>
        <source>Modbus map file</source>
        <translation>Modbus map file</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="191"/>
        <source>Modbus maps (*.csv);;All files (*)</source>
        <translation>Modbus maps (*.csv);;All files (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="207"/>
        <source>Bit memory (%MW)</source>
        <translation>Bit memory (%MW)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="209"/>
        <source>Data block {0}</source>
        <translation>Data block {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="214"/>
        <source>&amp;Map file (CSV) or DB:</source>
        <translation>&amp;Map file (CSV) or DB:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="227"/>
        <source>Cannot read the map {0}: {1}</source>
        <translation>Cannot read the map {0}: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="230"/>
        <source>line {0}: {1}</source>
        <translation>line {0}: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="233"/>
        <source>The map {0} is not served:</source>
        <translation>The map {0} is not served:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="246"/>
        <source>the {0} map, holding registers in the DB {1}</source>
        <translation>the {0} map, holding registers in the DB {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="249"/>
        <source>the file {0}</source>
        <translation>the file {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="272"/>
        <source>Stop server</source>
        <translation>Stop server</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="273"/>
        <source>Start server</source>
        <translation>Start server</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="277"/>
        <source>Map served:</source>
        <translation>Map served:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="278"/>
        <source>Map to serve:</source>
        <translation>Map to serve:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="282"/>
        <source>Listening on {0}:{1} (Modbus/TCP, any unit id), map: {2}.</source>
        <translation>Listening on {0}:{1} (Modbus/TCP, any unit id), map: {2}.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="286"/>
        <source>Other computers on the network can read and write this PLC.</source>
        <translation>Other computers on the network can read and write this PLC.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="291"/>
        <source>Stopped. An HMI on this computer connects to {0} once started.</source>
        <translation>Stopped. An HMI on this computer connects to {0} once started.</translation>
    </message>
</context>
<context>
    <name>NameDisplayMenu</name>
    <message>
        <location filename="../ladderworks/gui/editor/name_menu.py" line="23"/>
        <source>&amp;Address only</source>
        <translation>&amp;Address only</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/name_menu.py" line="25"/>
        <source>Address and &amp;symbol</source>
        <translation>Address and &amp;symbol</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/name_menu.py" line="26"/>
        <source>Address, symbol and &amp;comment</source>
        <translation>Address, symbol and &amp;comment</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/name_menu.py" line="69"/>
        <source>Element &amp;names</source>
        <translation>Element &amp;names</translation>
    </message>
</context>
<context>
    <name>NewProgram</name>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="82"/>
        <source>New program</source>
        <translation>New program</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="89"/>
        <source>A family&apos;s models differ in their ranges; the Delta DVP series (ES2, EX2, SS2, SA2, SX2, SE) and the Fatek FBs series share one device map here (docs/dialects.md).</source>
        <translation>A family&apos;s models differ in their ranges; the Delta DVP series (ES2, EX2, SS2, SA2, SX2, SE) and the Fatek FBs series share one device map here (docs/dialects.md).</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="97"/>
        <source>The PLC the program is written for: its instructions, its devices (X0, T0, D10 or X2.1, R100) and its file form.</source>
        <translation>The PLC the program is written for: its instructions, its devices (X0, T0, D10 or X2.1, R100) and its file form.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="102"/>
        <source>PLC family</source>
        <translation>PLC family</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="103"/>
        <source>Model</source>
        <translation>Model</translation>
    </message>
</context>
<context>
    <name>Numbers</name>
    <message>
        <location filename="../ladderworks/gui/locale_numbers.py" line="18"/>
        <source>{0}%</source>
        <translation>{0}%</translation>
    </message>
</context>
<context>
    <name>OperandDialog</name>
    <message>
        <location filename="../ladderworks/gui/operand_dialog.py" line="17"/>
        <source>Operands of {0}</source>
        <translation>Operands of {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/operand_dialog.py" line="20"/>
        <source>As TIA Portal writes them: &quot;Start&quot;, #Timer, %MW2, T#10s, 5</source>
        <translation>As TIA Portal writes them: &quot;Start&quot;, #Timer, %MW2, T#10s, 5</translation>
    </message>
</context>
<context>
    <name>OsError</name>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="16"/>
        <source>it does not exist</source>
        <translation>it does not exist</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="17"/>
        <location filename="../ladderworks/gui/os_errors.py" line="18"/>
        <source>permission denied</source>
        <translation>permission denied</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="19"/>
        <source>the disk is read-only</source>
        <translation>the disk is read-only</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="20"/>
        <source>the disk is full</source>
        <translation>the disk is full</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="21"/>
        <source>the disk quota is used up</source>
        <translation>the disk quota is used up</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="22"/>
        <source>it is a folder</source>
        <translation>it is a folder</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="23"/>
        <source>a part of the path is not a folder</source>
        <translation>a part of the path is not a folder</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="24"/>
        <source>it already exists</source>
        <translation>it already exists</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="25"/>
        <source>the name is too long</source>
        <translation>the name is too long</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="26"/>
        <location filename="../ladderworks/gui/os_errors.py" line="27"/>
        <source>it is in use</source>
        <translation>it is in use</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="28"/>
        <source>the disk reported an input/output error</source>
        <translation>the disk reported an input/output error</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="29"/>
        <source>too many symbolic links</source>
        <translation>too many symbolic links</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="30"/>
        <source>too many files are open</source>
        <translation>too many files are open</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="36"/>
        <source>system error: {0}</source>
        <translation>system error: {0}</translation>
    </message>
</context>
<context>
    <name>OutputPinsDialog</name>
    <message>
        <location filename="../ladderworks/gui/output_pins_dialog.py" line="38"/>
        <source>Output pins</source>
        <translation>Output pins</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/output_pins_dialog.py" line="39"/>
        <source>The outputs {0} shows on its right side (FO0 is its first output, always shown); draw each pin&apos;s coils on its row:</source>
        <translation>The outputs {0} shows on its right side (FO0 is its first output, always shown); draw each pin&apos;s coils on its row:</translation>
    </message>
</context>
<context>
    <name>Param</name>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="50"/>
        <source>Timer number</source>
        <translation>Timer number</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="51"/>
        <source>Preset</source>
        <translation>Preset</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="52"/>
        <source>Accuracy</source>
        <translation>Accuracy</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="53"/>
        <source>Timer/counter register</source>
        <translation>Timer/counter register</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="54"/>
        <source>Code signal</source>
        <translation>Code signal</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="55"/>
        <source>Decode specification</source>
        <translation>Decode specification</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="56"/>
        <source>Format</source>
        <translation>Format</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="57"/>
        <source>First number</source>
        <translation>First number</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="58"/>
        <source>Result</source>
        <translation>Result</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="59"/>
        <source>Counter number</source>
        <translation>Counter number</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="60"/>
        <source>Number of positions</source>
        <translation>Number of positions</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="61"/>
        <source>Current position</source>
        <translation>Current position</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="62"/>
        <source>Target position</source>
        <translation>Target position</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="63"/>
        <source>Table size</source>
        <translation>Table size</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="64"/>
        <source>Index</source>
        <translation>Index</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="65"/>
        <source>Output</source>
        <translation>Output</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="66"/>
        <source>Table values</source>
        <translation>Table values</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="67"/>
        <source>Input</source>
        <translation>Input</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="68"/>
        <source>High 4-bit mask</source>
        <translation>High 4-bit mask</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="69"/>
        <source>Low 4-bit mask</source>
        <translation>Low 4-bit mask</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="70"/>
        <source>OR data</source>
        <translation>OR data</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="71"/>
        <source>Data</source>
        <translation>Data</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="72"/>
        <source>Number of coils</source>
        <translation>Number of coils</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="73"/>
        <source>Input format (0 constant, 1 address)</source>
        <translation>Input format (0 constant, 1 address)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="74"/>
        <source>Compared data</source>
        <translation>Compared data</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="75"/>
        <source>Searched data</source>
        <translation>Searched data</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="76"/>
        <source>Operand format (0 constant, 1 address)</source>
        <translation>Operand format (0 constant, 1 address)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="78"/>
        <source>Operand A</source>
        <translation>Operand A</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="79"/>
        <source>Operand B</source>
        <translation>Operand B</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="80"/>
        <source>Constant</source>
        <translation>Constant</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="81"/>
        <source>Edge number</source>
        <translation>Edge number</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="82"/>
        <source>Number of bytes</source>
        <translation>Number of bytes</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="83"/>
        <source>Operand</source>
        <translation>Operand</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="84"/>
        <source>Limit 1</source>
        <translation>Limit 1</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="85"/>
        <source>Limit 2</source>
        <translation>Limit 2</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="86"/>
        <source>Subprogram</source>
        <translation>Subprogram</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="87"/>
        <source>Label</source>
        <translation>Label</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="88"/>
        <source>DI/DO group</source>
        <translation>DI/DO group</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="89"/>
        <source>Control data</source>
        <translation>Control data</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="90"/>
        <source>Number of messages</source>
        <translation>Number of messages</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="92"/>
        <source>Form (P, D)</source>
        <translation>Form (P, D)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="93"/>
        <source>Nesting level (N0-N7)</source>
        <translation>Nesting level (N0-N7)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="94"/>
        <source>Device</source>
        <translation>Device</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="95"/>
        <source>Timer or counter (T5, C3)</source>
        <translation>Timer or counter (T5, C3)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="96"/>
        <source>Source 1</source>
        <translation>Source 1</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="97"/>
        <source>Source 2</source>
        <translation>Source 2</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="98"/>
        <source>Source</source>
        <translation>Source</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="99"/>
        <source>Lower limit</source>
        <translation>Lower limit</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="100"/>
        <source>Upper limit</source>
        <translation>Upper limit</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="103"/>
        <source>Parameter {0}</source>
        <translation>Parameter {0}</translation>
    </message>
</context>
<context>
    <name>PlcControl</name>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="162"/>
        <source>PLC CONTROL SCREEN</source>
        <translation>PLC CONTROL SCREEN</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="164"/>
        <source>Open .MOD…</source>
        <translation>Open .MOD…</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="165"/>
        <source>Show the console&apos;s program as text</source>
        <translation>Show the console&apos;s program as text</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="167"/>
        <source>Compile</source>
        <translation>Compile</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="168"/>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="355"/>
        <source>START</source>
        <translation>START</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="169"/>
        <source>STOP</source>
        <translation>STOP</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="175"/>
        <source>Shows the console&apos;s program here as mnemonic text, to read or change before Compile on this screen. F9 (PLC › Compile) loads the console&apos;s program into the PLC directly.</source>
        <translation>Shows the console&apos;s program here as mnemonic text, to read or change before Compile on this screen. F9 (PLC › Compile) loads the console&apos;s program into the PLC directly.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="206"/>
        <source>Program loaded from the console</source>
        <translation>Program loaded from the console</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="226"/>
        <source>In the PLC: {0}</source>
        <translation>In the PLC: {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="236"/>
        <source>Cannot read {0}: {1}</source>
        <translation>Cannot read {0}: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="241"/>
        <source>Opened {0}</source>
        <translation>Opened {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="247"/>
        <source>Open mnemonic program</source>
        <translation>Open mnemonic program</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="248"/>
        <source>Mnemonic programs (*.MOD *.mod *.LAD *.lad);;All files (*)</source>
        <translation>Mnemonic programs (*.MOD *.mod *.LAD *.lad);;All files (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="256"/>
        <source>The console&apos;s program cannot be coded: see the error list</source>
        <translation>The console&apos;s program cannot be coded: see the error list</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="260"/>
        <source>Program taken from the console</source>
        <translation>Program taken from the console</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="295"/>
        <source>Compile failed: {0} error(s). {1}</source>
        <translation>Compile failed: {0} error(s). {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="307"/>
        <source>Converting…</source>
        <translation>Converting…</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="333"/>
        <source>Not loaded: the PLC keeps the program it has</source>
        <translation>Not loaded: the PLC keeps the program it has</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="338"/>
        <source>the program on this screen</source>
        <translation>the program on this screen</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="342"/>
        <source>Compile finished — {0} networks, {1} bytes</source>
        <translation>Compile finished — {0} networks, {1} bytes</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="345"/>
        <source>({0} warning(s))</source>
        <translation>({0} warning(s))</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="356"/>
        <source>{0} signal(s) are forced or element(s) passive. Start the PLC with them?</source>
        <translation>{0} signal(s) are forced or element(s) passive. Start the PLC with them?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="363"/>
        <source>Compile a program first</source>
        <translation>Compile a program first</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="387"/>
        <source>scans in a process of their own</source>
        <translation>scans in a process of their own</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="389"/>
        <source>scans in the IDE&apos;s process</source>
        <translation>scans in the IDE&apos;s process</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="391"/>
        <source>scan process: {0}</source>
        <translation>scan process: {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="398"/>
        <source>native scan (machine code)</source>
        <translation>native scan (machine code)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="400"/>
        <source>Python scan (native not possible: {0})</source>
        <translation>Python scan (native not possible: {0})</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="402"/>
        <source>Python scan</source>
        <translation>Python scan</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="414"/>
        <source>{0} (line {1})</source>
        <translation>{0} (line {1})</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="417"/>
        <source>… and {0} more</source>
        <translation>… and {0} more</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="419"/>
        <source>Not simulated, passed by in the scan ({0}): {1}</source>
        <translation>Not simulated, passed by in the scan ({0}): {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="422"/>
        <source>These instructions are kept, drawn and saved, but the simulator does not run them: a box passes its input on, a contact never conducts.</source>
        <translation>These instructions are kept, drawn and saved, but the simulator does not run them: a box passes its input on, a contact never conducts.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="429"/>
        <source>NO PROGRAM</source>
        <translation>NO PROGRAM</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="432"/>
        <source>RUNNING</source>
        <translation>RUNNING</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="435"/>
        <source>STOPPED</source>
        <translation>STOPPED</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="438"/>
        <source>scans {0} · scan time {1} / {2} / {3} ms (min/avg/max) · period {4} ms · overruns {5}</source>
        <translation>scans {0} · scan time {1} / {2} / {3} ms (min/avg/max) · period {4} ms · overruns {5}</translation>
    </message>
</context>
<context>
    <name>PlcDiagnostic</name>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="299"/>
        <source>PLC DIAGNOSTIC</source>
        <translation>PLC DIAGNOSTIC</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="300"/>
        <source>Address, e.g. R102.0</source>
        <translation>Address, e.g. R102.0</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="301"/>
        <source>Find</source>
        <translation>Find</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="302"/>
        <source>Where written</source>
        <translation>Where written</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="303"/>
        <source>Follow</source>
        <translation>Follow</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="304"/>
        <source>Why?</source>
        <translation>Why?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="305"/>
        <source>Go to the scan where the address last changed and mark the contacts that changed it</source>
        <translation>Go to the scan where the address last changed and mark the contacts that changed it</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="308"/>
        <source>Back to live</source>
        <translation>Back to live</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="309"/>
        <source>Zoom out (Ctrl+wheel)</source>
        <translation>Zoom out (Ctrl+wheel)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="310"/>
        <source>Zoom in (Ctrl+wheel)</source>
        <translation>Zoom in (Ctrl+wheel)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="312"/>
        <source>Keep the searched address in view while the PLC runs</source>
        <translation>Keep the searched address in view while the PLC runs</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="322"/>
        <source>{0} %</source>
        <translation>{0} %</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="393"/>
        <location filename="../ladderworks/gui/docks/online.py" line="167"/>
        <source>PAST — scan {0} at {1} ms (not live)</source>
        <translation>PAST — scan {0} at {1} ms (not live)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="399"/>
        <source>No program loaded</source>
        <translation>No program loaded</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="401"/>
        <source>RUNNING — scan {0}</source>
        <translation>RUNNING — scan {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="403"/>
        <source>STOPPED</source>
        <translation>STOPPED</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="444"/>
        <source>&apos;{0}&apos; is not an address</source>
        <translation>&apos;{0}&apos; is not an address</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="488"/>
        <source>&apos;{0}&apos; is not in the program</source>
        <translation>&apos;{0}&apos; is not in the program</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="498"/>
        <source>No coil writes {0}</source>
        <translation>No coil writes {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="508"/>
        <source>{0} of {1}: network {2}</source>
        <translation>{0} of {1}: network {2}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/power_overlay.py" line="106"/>
        <source>PASSIVE</source>
        <translation>PASSIVE</translation>
    </message>
</context>
<context>
    <name>PlcOnline</name>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="65"/>
        <source>On-line mode</source>
        <translation>On-line mode</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="66"/>
        <source>Make passive (disable)</source>
        <translation>Make passive (disable)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="67"/>
        <source>Make active again</source>
        <translation>Make active again</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="68"/>
        <source>Force to 1</source>
        <translation>Force to 1</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="69"/>
        <source>Force to 0</source>
        <translation>Force to 0</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="70"/>
        <source>Release the force</source>
        <translation>Release the force</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="89"/>
        <source>Off-line</source>
        <translation>Off-line</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="94"/>
        <source>On-line needs a compiled program in the PLC</source>
        <translation>On-line needs a compiled program in the PLC</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="100"/>
        <source>The drawing is not the program in the PLC: compile it in the PLC control screen first</source>
        <translation>The drawing is not the program in the PLC: compile it in the PLC control screen first</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="110"/>
        <location filename="../ladderworks/gui/docks/online.py" line="176"/>
        <source>On-line: the drawing shows the running PLC</source>
        <translation>On-line: the drawing shows the running PLC</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="137"/>
        <source>Off-line: the drawing was changed; it is no longer the program the PLC runs</source>
        <translation>Off-line: the drawing was changed; it is no longer the program the PLC runs</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="146"/>
        <source>Off-line: another program is shown; it is not the program the PLC runs</source>
        <translation>Off-line: another program is shown; it is not the program the PLC runs</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="199"/>
        <source>Select a contact, coil or function first</source>
        <translation>Select a contact, coil or function first</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="203"/>
        <source>This element has no op in the PLC program</source>
        <translation>This element has no op in the PLC program</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="226"/>
        <source>Select a contact or coil to force its signal</source>
        <translation>Select a contact or coil to force its signal</translation>
    </message>
</context>
<context>
    <name>PlcState</name>
    <message>
        <location filename="../ladderworks/gui/plc_state.py" line="24"/>
        <source>RUN</source>
        <translation>RUN</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/plc_state.py" line="24"/>
        <source>STOP</source>
        <translation>STOP</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/plc_state.py" line="25"/>
        <source>no program loaded</source>
        <translation>no program loaded</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/plc_state.py" line="27"/>
        <source>{0} forced</source>
        <translation>{0} forced</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/plc_state.py" line="56"/>
        <source>The simulated PLC: running (RUN) or stopped (STOP), and the program loaded into it (F9).</source>
        <translation>The simulated PLC: running (RUN) or stopped (STOP), and the program loaded into it (F9).</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/plc_state.py" line="59"/>
        <source>Signals are forced: the PLC does not see the machine&apos;s values for them (PLC › Release the force).</source>
        <translation>Signals are forced: the PLC does not see the machine&apos;s values for them (PLC › Release the force).</translation>
    </message>
</context>
<context>
    <name>PlcTables</name>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="116"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="192"/>
        <source>No.</source>
        <translation>No.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="123"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="116"/>
        <source>Type</source>
        <translation>Type</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="114"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="124"/>
        <source>Preset (ms)</source>
        <translation>Preset (ms)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="113"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="123"/>
        <source>Preset (ticks)</source>
        <translation>Preset (ticks)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="115"/>
        <source>Precision</source>
        <translation>Precision</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="117"/>
        <source>Tick (ms)</source>
        <translation>Tick (ms)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="118"/>
        <source>Delay (ms)</source>
        <translation>Delay (ms)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="125"/>
        <source>Timer number (1-{0})</source>
        <translation>Timer number (1-{0})</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="119"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="192"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="197"/>
        <source>Preset</source>
        <translation>Preset</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="193"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="198"/>
        <source>Current value</source>
        <translation>Current value</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="252"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="308"/>
        <source>Address</source>
        <translation>Address</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="252"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="257"/>
        <source>Bytes</source>
        <translation>Bytes</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="116"/>
        <source>Device</source>
        <translation>Device</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="118"/>
        <source>Contact</source>
        <translation>Contact</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="121"/>
        <source>Base</source>
        <translation>Base</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="117"/>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="124"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="253"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="258"/>
        <source>Value</source>
        <translation>Value</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="124"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="253"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="309"/>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="129"/>
        <source>Devices ({0}0 or a range {0}0-{0}9)</source>
        <translation>Devices ({0}0 or a range {0}0-{0}9)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="154"/>
        <source>ON</source>
        <translation>ON</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="154"/>
        <source>OFF</source>
        <translation>OFF</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="160"/>
        <source>{0} ms</source>
        <translation>{0} ms</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="162"/>
        <source>{0}-bit up/down</source>
        <translation>{0}-bit up/down</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="163"/>
        <source>{0}-bit up</source>
        <translation>{0}-bit up</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="216"/>
        <source>{0} on: {1} ms a count</source>
        <translation>{0} on: {1} ms a count</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="308"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="313"/>
        <source>Bits 7..0</source>
        <translation>Bits 7..0</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="197"/>
        <source>Counter number (1-20)</source>
        <translation>Counter number (1-20)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="257"/>
        <source>Address (D)</source>
        <translation>Address (D)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="313"/>
        <source>Address (K)</source>
        <translation>Address (K)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_forms.py" line="41"/>
        <location filename="../ladderworks/gui/docks/tables.py" line="282"/>
        <source>INSERT</source>
        <translation>INSERT</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_forms.py" line="130"/>
        <source>&amp;Add:</source>
        <translation>&amp;Add:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_forms.py" line="131"/>
        <source>devices, e.g. D500, T5, D0-D9</source>
        <translation>devices, e.g. D500, T5, D0-D9</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_forms.py" line="132"/>
        <source>Add</source>
        <translation>Add</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_forms.py" line="133"/>
        <source>Any timer, counter or register of the PLC, used by the program or not; a value is typed in its cell as 100, K100 or H64</source>
        <translation>Any timer, counter or register of the PLC, used by the program or not; a value is typed in its cell as 100, K100 or H64</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="179"/>
        <source>TMRB: the preset is fixed in the program</source>
        <translation>TMRB: the preset is fixed in the program</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="257"/>
        <source>&apos;{0}&apos; is not a device of these tables (use {1}); watch a bit in the bit display</source>
        <translation>&apos;{0}&apos; is not a device of these tables (use {1}); watch a bit in the bit display</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="285"/>
        <source>DELETE</source>
        <translation>DELETE</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="320"/>
        <source>PLC tables</source>
        <translation>PLC tables</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="323"/>
        <source>A {0} program has no PMC parameter tables: its timer and counter presets are written in its instructions. Watch its T, C and D devices in the bit display and the time chart.</source>
        <translation>A {0} program has no PMC parameter tables: its timer and counter presets are written in its instructions. Watch its T, C and D devices in the bit display and the time chart.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="330"/>
        <source>Timers (TMR)</source>
        <translation>Timers (TMR)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="331"/>
        <source>Counters (CTR)</source>
        <translation>Counters (CTR)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="332"/>
        <source>Data table (D)</source>
        <translation>Data table (D)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="333"/>
        <source>Keep relays (K)</source>
        <translation>Keep relays (K)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="334"/>
        <source>Timers (T)</source>
        <translation>Timers (T)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="335"/>
        <source>Counters (C)</source>
        <translation>Counters (C)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="336"/>
        <source>Registers ({0})</source>
        <translation>Registers ({0})</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="347"/>
        <source>Presets up to {0} ms; timers 1-8 count in 48 ms ticks, 9-100 and TMRB in 8 ms</source>
        <translation>Presets up to {0} ms; timers 1-8 count in 48 ms ticks, 9-100 and TMRB in 8 ms</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="350"/>
        <source>Presets in ticks (up to {0}); the precision code sets the tick: 0 default (48 ms for 1-8, else 8 ms), 1 = 1 ms, 2 = 10 ms, 3 = 100 ms, 4 = 1 s, 5 = 1 min</source>
        <translation>Presets in ticks (up to {0}); the precision code sets the tick: 0 default (48 ms for 1-8, else 8 ms), 1 = 1 ms, 2 = 10 ms, 3 = 100 ms, 4 = 1 s, 5 = 1 min</translation>
    </message>
</context>
<context>
    <name>Print</name>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="54"/>
        <source>Untitled</source>
        <translation>Untitled</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="80"/>
        <source>Printing the ladder…</source>
        <translation>Printing the ladder…</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="81"/>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="165"/>
        <source>Print preview</source>
        <translation>Print preview</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="183"/>
        <source>Export PDF</source>
        <translation>Export PDF</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="184"/>
        <source>PDF files (*.pdf)</source>
        <translation>PDF files (*.pdf)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="192"/>
        <source>&amp;Print...</source>
        <translation>&amp;Print...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="193"/>
        <source>Print pre&amp;view...</source>
        <translation>Print pre&amp;view...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="194"/>
        <source>Export P&amp;DF...</source>
        <translation>Export P&amp;DF...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="200"/>
        <source>Printing was cancelled or failed</source>
        <translation>Printing was cancelled or failed</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="202"/>
        <source>{0} pages written to {1}</source>
        <translation>{0} pages written to {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="204"/>
        <source>{0} pages sent to the printer</source>
        <translation>{0} pages sent to the printer</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_pages.py" line="280"/>
        <source>Printed {0}</source>
        <translation>Printed {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_pages.py" line="282"/>
        <source>Page {0} / {1}</source>
        <translation>Page {0} / {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_pages.py" line="309"/>
        <source>Cross reference</source>
        <translation>Cross reference</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_pages.py" line="312"/>
        <source>Address</source>
        <translation>Address</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_pages.py" line="313"/>
        <source>Symbol</source>
        <translation>Symbol</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_pages.py" line="314"/>
        <source>Written in networks</source>
        <translation>Written in networks</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_pages.py" line="315"/>
        <source>Read in networks</source>
        <translation>Read in networks</translation>
    </message>
</context>
<context>
    <name>ProgramProperties</name>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="53"/>
        <source>Machine-tool builder</source>
        <translation>Machine-tool builder</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="54"/>
        <source>Machine-tool name</source>
        <translation>Machine-tool name</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="55"/>
        <source>PMC &amp; NC type</source>
        <translation>PMC &amp; NC type</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="56"/>
        <source>Program number</source>
        <translation>Program number</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="57"/>
        <source>Edition</source>
        <translation>Edition</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="58"/>
        <source>Drawing number</source>
        <translation>Drawing number</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="59"/>
        <source>Date</source>
        <translation>Date</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="60"/>
        <source>Designed by</source>
        <translation>Designed by</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="61"/>
        <source>ROM written by</source>
        <translation>ROM written by</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="62"/>
        <source>Remarks</source>
        <translation>Remarks</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="35"/>
        <source>LadderWorks (seed manual)</source>
        <translation>LadderWorks (seed manual)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="36"/>
        <source>FANUC Series 30i-A PMC (memory-B)</source>
        <translation>FANUC Series 30i-A PMC (memory-B)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="85"/>
        <source>yes</source>
        <translation>yes</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="85"/>
        <source>no</source>
        <translation>no</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="88"/>
        <source>File</source>
        <translation>File</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="89"/>
        <source>(not saved)</source>
        <translation>(not saved)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="90"/>
        <location filename="../ladderworks/gui/program_properties.py" line="149"/>
        <location filename="../ladderworks/gui/program_properties.py" line="186"/>
        <source>PMC model</source>
        <translation>PMC model</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="91"/>
        <source>Encoding</source>
        <translation>Encoding</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="92"/>
        <source>Byte order mark</source>
        <translation>Byte order mark</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="93"/>
        <source>Line ends</source>
        <translation>Line ends</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="94"/>
        <source>Framed in %@A … %@E</source>
        <translation>Framed in %@A … %@E</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="95"/>
        <source>Networks</source>
        <translation>Networks</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="96"/>
        <source>Steps</source>
        <translation>Steps</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="98"/>
        <source>Symbols (%@2)</source>
        <translation>Symbols (%@2)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="100"/>
        <source>Messages (%@4)</source>
        <translation>Messages (%@4)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="180"/>
        <source>The PLC the program is written for: its address map and the ranges of its instructions. A model of another PLC family is taken when every instruction reads back the same in that family&apos;s text.</source>
        <translation>The PLC the program is written for: its address map and the ranges of its instructions. A model of another PLC family is taken when every instruction reads back the same in that family&apos;s text.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="197"/>
        <source>Program properties</source>
        <translation>Program properties</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="206"/>
        <source>General</source>
        <translation>General</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="207"/>
        <source>Property</source>
        <translation>Property</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="208"/>
        <location filename="../ladderworks/gui/program_properties.py" line="215"/>
        <source>Value</source>
        <translation>Value</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="210"/>
        <source>Title (%@1)</source>
        <translation>Title (%@1)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="211"/>
        <location filename="../ladderworks/gui/program_properties.py" line="215"/>
        <source>Item</source>
        <translation>Item</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="211"/>
        <source>Meaning</source>
        <translation>Meaning</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="212"/>
        <source>Text</source>
        <translation>Text</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="214"/>
        <source>System parameters (%@0)</source>
        <translation>System parameters (%@0)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="217"/>
        <source>I/O modules (%@5)</source>
        <translation>I/O modules (%@5)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="218"/>
        <source>Address</source>
        <translation>Address</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="218"/>
        <source>Group</source>
        <translation>Group</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="219"/>
        <source>Base</source>
        <translation>Base</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="219"/>
        <source>Slot</source>
        <translation>Slot</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="220"/>
        <source>Module</source>
        <translation>Module</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="223"/>
        <source>Sections</source>
        <translation>Sections</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="224"/>
        <source>Header</source>
        <translation>Header</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="224"/>
        <source>Lines</source>
        <translation>Lines</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="225"/>
        <source>First line</source>
        <translation>First line</translation>
    </message>
</context>
<context>
    <name>QFileDialog</name>
    <message>
        <location filename="../ladderworks/gui/qt_strings.py" line="11"/>
        <source>&amp;Look in:</source>
        <translation>&amp;Look in:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/qt_strings.py" line="12"/>
        <source>Files of &amp;type:</source>
        <translation>Files of &amp;type:</translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <location filename="../ladderworks/gui/qt_strings.py" line="13"/>
        <source>Discard</source>
        <translation>Discard</translation>
    </message>
</context>
<context>
    <name>QtLibraries</name>
    <message>
        <location filename="../ladderworks/gui/qt_libraries.py" line="71"/>
        <source>LadderWorks cannot start: Qt&apos;s X11 (xcb) platform needs system libraries that are missing: {0}.</source>
        <translation>LadderWorks cannot start: Qt&apos;s X11 (xcb) platform needs system libraries that are missing: {0}.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/qt_libraries.py" line="75"/>
        <source>On Debian or Ubuntu, install them with:</source>
        <translation>On Debian or Ubuntu, install them with:</translation>
    </message>
</context>
<context>
    <name>Questions</name>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="37"/>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="41"/>
        <source>Save As...</source>
        <translation>Save As...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="46"/>
        <source>File changed on disk</source>
        <translation>File changed on disk</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="46"/>
        <source>{0} was changed by another program since you opened it. Reload it (your unsaved changes are lost), keep your version (overwrite the other change), or save yours under another name?</source>
        <translation>{0} was changed by another program since you opened it. Reload it (your unsaved changes are lost), keep your version (overwrite the other change), or save yours under another name?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="51"/>
        <source>Reload</source>
        <translation>Reload</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="52"/>
        <source>Keep mine</source>
        <translation>Keep mine</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="58"/>
        <source>Read-only file</source>
        <translation>Read-only file</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="58"/>
        <source>{0} is read-only and is not replaced. Save the program under another name?</source>
        <translation>{0} is read-only and is not replaced. Save the program under another name?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="67"/>
        <source>Change not saved</source>
        <translation>Change not saved</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="67"/>
        <source>{0} is not overwritten: {1}. Save the program under another name?</source>
        <translation>{0} is not overwritten: {1}. Save the program under another name?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="75"/>
        <source>Character not in the file&apos;s encoding</source>
        <translation>Character not in the file&apos;s encoding</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="75"/>
        <source>Line {0}, column {1}: the character &apos;{2}&apos; (U+{3:04X}) cannot be written in {4}, the encoding of {5}. Save the whole file as UTF-8 instead?</source>
        <translation>Line {0}, column {1}: the character &apos;{2}&apos; (U+{3:04X}) cannot be written in {4}, the encoding of {5}. Save the whole file as UTF-8 instead?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="80"/>
        <source>Save as UTF-8</source>
        <translation>Save as UTF-8</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="85"/>
        <source>Recover unsaved work</source>
        <translation>Recover unsaved work</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="85"/>
        <source>LadderWorks ended without saving {0}. A recovery copy from {1} was found. Restore it?</source>
        <translation>LadderWorks ended without saving {0}. A recovery copy from {1} was found. Restore it?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="89"/>
        <source>Restore</source>
        <translation>Restore</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="90"/>
        <source>Discard</source>
        <translation>Discard</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="91"/>
        <source>Not now</source>
        <translation>Not now</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="96"/>
        <source>The PLC is running</source>
        <translation>The PLC is running</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="96"/>
        <source>The PLC is running. Load the new program now? It is loaded between two scans and the PLC runs on with it; forces stay.</source>
        <translation>The PLC is running. Load the new program now? It is loaded between two scans and the PLC runs on with it; forces stay.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="100"/>
        <source>Reload now</source>
        <translation>Reload now</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="106"/>
        <source>Forced signals</source>
        <translation>Forced signals</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="106"/>
        <source>{0} signal(s) are forced in the PLC for the program it has now. Another program is being loaded: keep these signals forced, or release them?</source>
        <translation>{0} signal(s) are forced in the PLC for the program it has now. Another program is being loaded: keep these signals forced, or release them?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="110"/>
        <source>Release the forces</source>
        <translation>Release the forces</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="111"/>
        <source>Keep them forced</source>
        <translation>Keep them forced</translation>
    </message>
</context>
<context>
    <name>Recovery</name>
    <message>
        <location filename="../ladderworks/gui/recovery.py" line="182"/>
        <source>Cannot write the recovery copy in {0}: {1}</source>
        <translation>Cannot write the recovery copy in {0}: {1}</translation>
    </message>
</context>
<context>
    <name>ScanBackend</name>
    <message>
        <location filename="../ladderworks/gui/scan_backend.py" line="35"/>
        <source>Native scan (machine code)</source>
        <translation>Native scan (machine code)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/scan_backend.py" line="36"/>
        <source>Compile the program loaded next (F9, Compile) to machine code: it scans many times faster. Where that cannot be done, the Python scan runs and the PLC control screen says why.</source>
        <translation>Compile the program loaded next (F9, Compile) to machine code: it scans many times faster. Where that cannot be done, the Python scan runs and the PLC control screen says why.</translation>
    </message>
</context>
<context>
    <name>Scenario</name>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="94"/>
        <source>Run scenario</source>
        <translation>Run scenario</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="95"/>
        <location filename="../ladderworks/gui/docks/scenario.py" line="221"/>
        <source>Scenario files (*.csv);;All files (*)</source>
        <translation>Scenario files (*.csv);;All files (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="107"/>
        <source>Cannot read {0}: {1}</source>
        <translation>Cannot read {0}: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="124"/>
        <source>Load (compile) a PLC program first</source>
        <translation>Load (compile) a PLC program first</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="183"/>
        <source>passed</source>
        <translation>passed</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="184"/>
        <source>FAILED</source>
        <translation>FAILED</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="168"/>
        <source>{0}: all {1} checks passed</source>
        <translation>{0}: all {1} checks passed</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="171"/>
        <source>{0}: {1} of {2} checks failed</source>
        <translation>{0}: {1} of {2} checks failed</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="220"/>
        <source>Save the recorded scenario</source>
        <translation>Save the recorded scenario</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="229"/>
        <source>recorded in LadderWorks</source>
        <translation>recorded in LadderWorks</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="233"/>
        <source>Recording inputs and forces...</source>
        <translation>Recording inputs and forces...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="243"/>
        <source>Recorded {0} changes</source>
        <translation>Recorded {0} changes</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="252"/>
        <source>Cannot write {0}: {1}</source>
        <translation>Cannot write {0}: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="255"/>
        <source>Saved {0}</source>
        <translation>Saved {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="267"/>
        <source>PLC scenario</source>
        <translation>PLC scenario</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="268"/>
        <source>Run scenario...</source>
        <translation>Run scenario...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="269"/>
        <source>Record scenario</source>
        <translation>Record scenario</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="271"/>
        <source>Line</source>
        <translation>Line</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="271"/>
        <source>Check</source>
        <translation>Check</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="272"/>
        <source>Expected</source>
        <translation>Expected</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="272"/>
        <source>Got</source>
        <translation>Got</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="273"/>
        <source>Time (ms)</source>
        <translation>Time (ms)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="273"/>
        <source>Result</source>
        <translation>Result</translation>
    </message>
</context>
<context>
    <name>SignalList</name>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="110"/>
        <source>Program symbol</source>
        <translation>Program symbol</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="166"/>
        <source>{0} signals</source>
        <translation>{0} signals</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="173"/>
        <source>Signals</source>
        <translation>Signals</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="177"/>
        <source>In English</source>
        <translation>In English</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="178"/>
        <source>In Turkish</source>
        <translation>In Turkish</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="180"/>
        <source>Address</source>
        <translation>Address</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="181"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="182"/>
        <source>Description</source>
        <translation>Description</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="206"/>
        <source>{0}: FANUC&apos;s name (* = active low: 0 means on); the seed manual writes {1}. Source: {2}</source>
        <translation>{0}: FANUC&apos;s name (* = active low: 0 means on); the seed manual writes {1}. Source: {2}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="168"/>
        <source>{0} program symbols, {1}</source>
        <translation>{0} program symbols, {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="175"/>
        <source>Address, symbol, name or words, e.g. G8.4, SPL, acil</source>
        <translation>Address, symbol, name or words, e.g. G8.4, SPL, acil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="186"/>
        <source>Double-click: use the address for the contact or coil at the cursor</source>
        <translation>Double-click: use the address for the contact or coil at the cursor</translation>
    </message>
</context>
<context>
    <name>TimeChart</name>
    <message>
        <location filename="../ladderworks/gui/family_words.py" line="46"/>
        <source>Type the bits to watch, e.g. R1.4 R1.7 (a value: D10:2)</source>
        <translation>Type the bits to watch, e.g. R1.4 R1.7 (a value: D10:2)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="206"/>
        <source>Load (compile) a PLC program first</source>
        <translation>Load (compile) a PLC program first</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="218"/>
        <source>Sampling every {0} ms</source>
        <translation>Sampling every {0} ms</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="230"/>
        <source>Stopped: {0} samples</source>
        <translation>Stopped: {0} samples</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="243"/>
        <source>New program loaded; sampling goes on</source>
        <translation>New program loaded; sampling goes on</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="431"/>
        <source>Cursor {0} ms:</source>
        <translation>Cursor {0} ms:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="446"/>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="84"/>
        <source>Cannot write {0}: {1}</source>
        <translation>Cannot write {0}: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="450"/>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="458"/>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="87"/>
        <source>Saved {0}</source>
        <translation>Saved {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="456"/>
        <source>Cannot write {0}</source>
        <translation>Cannot write {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="465"/>
        <source>Export time chart as CSV</source>
        <translation>Export time chart as CSV</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="467"/>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="132"/>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="141"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV files (*.csv)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="476"/>
        <source>Export time chart as PNG</source>
        <translation>Export time chart as PNG</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="478"/>
        <source>PNG pictures (*.png)</source>
        <translation>PNG pictures (*.png)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="524"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="538"/>
        <source>PLC time chart</source>
        <translation>PLC time chart</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="539"/>
        <source>Signals:</source>
        <translation>Signals:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="541"/>
        <source>Sampling time:</source>
        <translation>Sampling time:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="543"/>
        <source>START</source>
        <translation>START</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="544"/>
        <source>STOP</source>
        <translation>STOP</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="545"/>
        <source>CLEAR</source>
        <translation>CLEAR</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="546"/>
        <source>Fit</source>
        <translation>Fit</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="547"/>
        <source>Zoom in</source>
        <translation>Zoom in</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="548"/>
        <source>Zoom out</source>
        <translation>Zoom out</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="549"/>
        <source>CSV...</source>
        <translation>CSV...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="550"/>
        <source>PNG...</source>
        <translation>PNG...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="555"/>
        <source>Export the samples as CSV</source>
        <translation>Export the samples as CSV</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="558"/>
        <source>Save the chart as a PNG picture</source>
        <translation>Save the chart as a PNG picture</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="560"/>
        <source>time (ms)</source>
        <translation>time (ms)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="111"/>
        <source>Cannot read {0}: {1}</source>
        <translation>Cannot read {0}: {1}</translation>
    </message>
</context>
<context>
    <name>TimeTravel</name>
    <message>
        <location filename="../ladderworks/gui/docks/time_travel.py" line="62"/>
        <source>Keep scan history (time travel)</source>
        <translation>Keep scan history (time travel)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_travel.py" line="63"/>
        <source>Keep every scan&apos;s power flow and values: the time chart&apos;s cursor shows an earlier scan in the PLC diagnostic</source>
        <translation>Keep every scan&apos;s power flow and values: the time chart&apos;s cursor shows an earlier scan in the PLC diagnostic</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_travel.py" line="128"/>
        <source>before the scan history, which begins at {0} ms</source>
        <translation>before the scan history, which begins at {0} ms</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_travel.py" line="138"/>
        <source>The cursor is before the scan history, which begins at {0} ms: no scan to show</source>
        <translation>The cursor is before the scan history, which begins at {0} ms: no scan to show</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_travel.py" line="173"/>
        <source>Turn on PLC › Keep scan history and give a bit address</source>
        <translation>Turn on PLC › Keep scan history and give a bit address</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_travel.py" line="181"/>
        <source>{0} did not change in the scans kept</source>
        <translation>{0} did not change in the scans kept</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_travel.py" line="188"/>
        <source>{0} went to {1} in scan {2} at {3} ms</source>
        <translation>{0} went to {1} in scan {2} at {3} ms</translation>
    </message>
</context>
<context>
    <name>Tool</name>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="115"/>
        <source>Select</source>
        <translation>Select</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="176"/>
        <source>Input</source>
        <translation>Input</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="191"/>
        <source>NOT input</source>
        <translation>NOT input</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="205"/>
        <source>Output</source>
        <translation>Output</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="219"/>
        <source>NOT output</source>
        <translation>NOT output</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="233"/>
        <source>SET coil</source>
        <translation>SET coil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="248"/>
        <source>RST coil</source>
        <translation>RST coil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="263"/>
        <source>NOT</source>
        <translation>NOT</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="277"/>
        <source>OR</source>
        <translation>OR</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="291"/>
        <source>Line</source>
        <translation>Line</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="340"/>
        <source>Comment</source>
        <translation>Comment</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="373"/>
        <source>Delete</source>
        <translation>Delete</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="387"/>
        <source>Function</source>
        <translation>Function</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="404"/>
        <source>Insert row before</source>
        <translation>Insert row before</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="419"/>
        <source>Insert row after</source>
        <translation>Insert row after</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="116"/>
        <source>Click an element or drag over cells to select; right-click: cut, copy, paste</source>
        <translation>Click an element or drag over cells to select; right-click: cut, copy, paste</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="177"/>
        <source>Click a cell to place a contact (RD / AND), type its address, ENTER</source>
        <translation>Click a cell to place a contact (RD / AND), type its address, ENTER</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="192"/>
        <source>Click a cell to place a NOT contact (RD.NOT / AND.NOT)</source>
        <translation>Click a cell to place a NOT contact (RD.NOT / AND.NOT)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="206"/>
        <source>Click a cell to place a coil (WRT), type its address, ENTER</source>
        <translation>Click a cell to place a coil (WRT), type its address, ENTER</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="220"/>
        <source>Click a cell to place a NOT coil (WRT.NOT)</source>
        <translation>Click a cell to place a NOT coil (WRT.NOT)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="234"/>
        <source>Click a cell to place a SET coil (bit := 1 while the logic is 1)</source>
        <translation>Click a cell to place a SET coil (bit := 1 while the logic is 1)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="249"/>
        <source>Click a cell to place an RST coil (bit := 0 while the logic is 1)</source>
        <translation>Click a cell to place an RST coil (bit := 0 while the logic is 1)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="264"/>
        <source>Click a contact or coil to turn it into its inverse</source>
        <translation>Click a contact or coil to turn it into its inverse</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="278"/>
        <source>Click a contact or coil to add a parallel one below it</source>
        <translation>Click a contact or coil to add a parallel one below it</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="292"/>
        <source>Click a first point, then a second point: a horizontal or vertical wire</source>
        <translation>Click a first point, then a second point: a horizontal or vertical wire</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="341"/>
        <source>Click the start of an empty row, type the comment, ENTER</source>
        <translation>Click the start of an empty row, type the comment, ENTER</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="374"/>
        <source>Click an element to delete it</source>
        <translation>Click an element to delete it</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="388"/>
        <source>Choose a function in the list, click the diagram, fill its table</source>
        <translation>Choose a function in the list, click the diagram, fill its table</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="405"/>
        <source>Click a cell to insert an empty row before it</source>
        <translation>Click a cell to insert an empty row before it</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="420"/>
        <source>Click a cell to insert an empty row after it</source>
        <translation>Click a cell to insert an empty row after it</translation>
    </message>
</context>
<context>
    <name>ToolPalette</name>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="30"/>
        <source>Delta DVP instructions</source>
        <translation>Delta DVP instructions</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="31"/>
        <source>Fatek FBs instructions</source>
        <translation>Fatek FBs instructions</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="32"/>
        <source>Delta DVP program structure</source>
        <translation>Delta DVP program structure</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="33"/>
        <source>Delta DVP contacts</source>
        <translation>Delta DVP contacts</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="34"/>
        <source>Fatek FBs program structure</source>
        <translation>Fatek FBs program structure</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="35"/>
        <source>Fatek FBs contacts</source>
        <translation>Fatek FBs contacts</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="36"/>
        <source>Siemens S7-1200 instructions</source>
        <translation>Siemens S7-1200 instructions</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="37"/>
        <source>S7-1200 program structure</source>
        <translation>S7-1200 program structure</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="38"/>
        <source>S7-1200 contacts</source>
        <translation>S7-1200 contacts</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="158"/>
        <source>Tools</source>
        <translation>Tools</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="159"/>
        <source>Function:</source>
        <translation>Function:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="28"/>
        <source>Seed manual instructions</source>
        <translation>Seed manual instructions</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="29"/>
        <source>FANUC PMC instructions</source>
        <translation>FANUC PMC instructions</translation>
    </message>
</context>
<context>
    <name>TraceFiles</name>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="71"/>
        <source>LADDER-III...</source>
        <translation>LADDER-III...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="73"/>
        <source>Export the samples as a LADDER-III signal-trace result</source>
        <translation>Export the samples as a LADDER-III signal-trace result</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="74"/>
        <source>Import...</source>
        <translation>Import...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="76"/>
        <source>Show a LADDER-III trace result or a CSV trace</source>
        <translation>Show a LADDER-III trace result or a CSV trace</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="116"/>
        <source>{0}, line {1}: not a trace file</source>
        <translation>{0}, line {1}: not a trace file</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="124"/>
        <source>Imported {0}: {1} samples</source>
        <translation>Imported {0}: {1} samples</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="131"/>
        <source>Export as LADDER-III trace result</source>
        <translation>Export as LADDER-III trace result</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="140"/>
        <source>Import a trace</source>
        <translation>Import a trace</translation>
    </message>
</context>
<context>
    <name>WatchTable</name>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="134"/>
        <source>Watch table</source>
        <translation>Watch table</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="136"/>
        <source>Watch table: tags and addresses, live, modified on request</source>
        <translation>Watch table: tags and addresses, live, modified on request</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="139"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="139"/>
        <source>Address</source>
        <translation>Address</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="140"/>
        <source>Display format</source>
        <translation>Display format</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="140"/>
        <source>Monitor value</source>
        <translation>Monitor value</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="141"/>
        <source>Modify value</source>
        <translation>Modify value</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="142"/>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="379"/>
        <source>Modify now</source>
        <translation>Modify now</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="143"/>
        <source>Write the modify values of the checked rows (none checked: of the selected rows) into the PLC now</source>
        <translation>Write the modify values of the checked rows (none checked: of the selected rows) into the PLC now</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="146"/>
        <source>Delete rows</source>
        <translation>Delete rows</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="292"/>
        <source>Checked: written by Modify now</source>
        <translation>Checked: written by Modify now</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="302"/>
        <source>Type a name or an address to add a row</source>
        <translation>Type a name or an address to add a row</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="305"/>
        <source>&lt;Add new&gt;</source>
        <translation>&lt;Add new&gt;</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="381"/>
        <source>Delete row</source>
        <translation>Delete row</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="405"/>
        <source>Check the rows to modify (or select one), then Modify now</source>
        <translation>Check the rows to modify (or select one), then Modify now</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="415"/>
        <source>Values written: {0}, refused: {1}</source>
        <translation>Values written: {0}, refused: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="418"/>
        <source>Values written: {0}</source>
        <translation>Values written: {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="11"/>
        <source>Bool</source>
        <translation>Bool</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="12"/>
        <source>DEC</source>
        <translation>DEC</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="13"/>
        <source>DEC+/-</source>
        <translation>DEC+/-</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="14"/>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="15"/>
        <source>Bin</source>
        <translation>Bin</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="16"/>
        <source>Floating-point number</source>
        <translation>Floating-point number</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="17"/>
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="18"/>
        <source>Date</source>
        <translation>Date</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="19"/>
        <source>Time of day</source>
        <translation>Time of day</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="20"/>
        <source>Character</source>
        <translation>Character</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="21"/>
        <source>String</source>
        <translation>String</translation>
    </message>
</context>
</TS>
