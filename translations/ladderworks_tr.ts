<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="tr_TR" sourcelanguage="en">
<context>
    <name>AlarmPanel</name>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="125"/>
        <source>Cannot read {0}: {1}</source>
        <translation>{0} okunamıyor: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="164"/>
        <source>Alarm message file</source>
        <translation>Alarm mesaj dosyası</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="166"/>
        <source>Alarm files (*.dat);;All files (*)</source>
        <translation>Alarm dosyaları (*.dat);;Tüm dosyalar (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="173"/>
        <source>A {0} program has no alarm messages (the alarm file is for PMC programs)</source>
        <translation>{0} programının alarm mesajları yoktur (alarm dosyası PMC programları içindir)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="180"/>
        <source>The program&apos;s messages (%@4): {0}</source>
        <translation>Programın mesajları (%@4): {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="183"/>
        <source>Alarm file... uses an AlarmMsg.dat instead</source>
        <translation>Alarm dosyası... bunun yerine bir AlarmMsg.dat kullanır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="187"/>
        <source>No alarm file</source>
        <translation>Alarm dosyası yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="189"/>
        <source>{0}: {1} messages</source>
        <translation>{0}: {1} mesaj</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="193"/>
        <source>{0} lines with problems</source>
        <translation>{0} satırda sorun var</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="200"/>
        <source>line {0}: {1}</source>
        <translation>satır {0}: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="218"/>
        <source>(no message {0} in the alarm file)</source>
        <translation>(alarm dosyasında {0} numaralı mesaj yok)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="252"/>
        <source>The bit is 0 again: RESET clears this alarm</source>
        <translation>Bit yeniden 0: RESET bu alarmı siler</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="255"/>
        <source>Seen at {0}</source>
        <translation>Görüldüğü saat: {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="298"/>
        <source>Alarms</source>
        <translation>ALARMLAR</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="299"/>
        <source>RESET</source>
        <translation>RESET</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="301"/>
        <source>Clear the alarms whose bit is 0 (the reset key)</source>
        <translation>Biti 0 olan alarmları sil (reset tuşu)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="303"/>
        <source>Alarm file...</source>
        <translation>Alarm dosyası...</translation>
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
        <translation>PLC zamanı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="309"/>
        <source>Clock</source>
        <translation>Saat</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/alarms.py" line="310"/>
        <source>Message</source>
        <translation>Mesaj</translation>
    </message>
</context>
<context>
    <name>AsciiOutput</name>
    <message>
        <location filename="../ladderworks/gui/docks/ascii_output.py" line="66"/>
        <source>ASCII output</source>
        <translation>ASCII çıkışı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/ascii_output.py" line="67"/>
        <source>Clear</source>
        <translation>Temizle</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/ascii_output.py" line="68"/>
        <source>Forget what the terminal received</source>
        <translation>Terminalin aldıklarını unut</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/ascii_output.py" line="70"/>
        <source>What FUN 94 ASCWR sends to Port 1 (a Fatek program) shows here.</source>
        <translation>FUN 94 ASCWR komutunun Port 1&apos;e gönderdikleri (bir Fatek programında) burada görünür.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/ascii_output.py" line="85"/>
        <source>{0} output(s) received</source>
        <translation>{0} çıkış alındı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/ascii_output.py" line="88"/>
        <source>{0}, line {1}: {2}</source>
        <translation>{0}, satır {1}: {2}</translation>
    </message>
</context>
<context>
    <name>BitDisplay</name>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="264"/>
        <source>{0} has {1} bytes: a box shows a byte or a word (the time chart shows any value)</source>
        <translation>{0} {1} bayttır: bir kutu bir bayt ya da bir sözcük gösterir (zaman kartı her değeri gösterir)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="339"/>
        <source>Forced to {0}</source>
        <translation>{0} değerine zorlandı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="342"/>
        <source>Click: force to the other value; right-click: force menu</source>
        <translation>Tıklama: diğer değere zorla; sağ tuş: zorlama menüsü</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="360"/>
        <source>Load a program to force inputs</source>
        <translation>Girişleri zorlamak için bir program yükleyin</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="377"/>
        <source>Force to 1</source>
        <translation>1&apos;e zorla</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="382"/>
        <source>Force to 0</source>
        <translation>0&apos;a zorla</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="387"/>
        <source>Release the force</source>
        <translation>Zorlamayı kaldır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="401"/>
        <source>Live</source>
        <translation>Canlı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="401"/>
        <source>Stopped</source>
        <translation>Durduruldu</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="408"/>
        <source>PLC bit display</source>
        <translation>PLC BIT GÖSTERİMİ</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="409"/>
        <source>START</source>
        <translation>BAŞLAT</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="410"/>
        <source>STOP</source>
        <translation>DURDUR</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="412"/>
        <source>Tag or address</source>
        <translation>Etiket ya da adres</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="413"/>
        <source>Byte</source>
        <translation>Bayt</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="414"/>
        <source>Hex</source>
        <translation>Onaltılık</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="415"/>
        <source>Dec</source>
        <translation>Ondalık</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="417"/>
        <source>e.g. &quot;Start&quot;, %MW2</source>
        <translation>ör. &quot;Start&quot;, %MW2</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/bit_display.py" line="418"/>
        <source>e.g. X12</source>
        <translation>örn. X12</translation>
    </message>
</context>
<context>
    <name>CrossReference</name>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="67"/>
        <source>Contact</source>
        <translation>Kontak</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="68"/>
        <source>NOT contact</source>
        <translation>DEĞİL kontak</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="69"/>
        <source>Coil</source>
        <translation>Çıkış</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="70"/>
        <source>NOT coil</source>
        <translation>DEĞİL çıkış</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="71"/>
        <source>SET coil</source>
        <translation>SET çıkış</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="72"/>
        <source>RST coil</source>
        <translation>RST çıkış</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="84"/>
        <source>Read</source>
        <translation>Okuma</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="86"/>
        <source>Write</source>
        <translation>Yazma</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="87"/>
        <source>Read and write</source>
        <translation>Okuma ve yazma</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="93"/>
        <source>Level {0}</source>
        <translation>{0}. seviye</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="133"/>
        <source>Address</source>
        <translation>Adres</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="133"/>
        <source>Symbol</source>
        <translation>Sembol</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="134"/>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="180"/>
        <source>Network</source>
        <translation>Devre</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="134"/>
        <source>Label</source>
        <translation>Etiket</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="135"/>
        <source>Program part</source>
        <translation>Program bölümü</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="136"/>
        <source>Element</source>
        <translation>Eleman</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="136"/>
        <source>Access</source>
        <translation>Erişim</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="137"/>
        <source>Comment</source>
        <translation>Yorum</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="287"/>
        <source>All addresses — uses: {0}</source>
        <translation>Tüm adresler — kullanım: {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="300"/>
        <source>&apos;{0}&apos; is neither an address nor a symbol of the program</source>
        <translation>&apos;{0}&apos; ne bir adres ne de programın bir sembolü</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="316"/>
        <source>{0} is not used in the program</source>
        <translation>{0} programda kullanılmıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="319"/>
        <source>{0} — uses: {1} (read: {2}, written: {3})</source>
        <translation>{0} — kullanım: {1} (okuma: {2}, yazma: {3})</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="339"/>
        <source>Cross reference</source>
        <translation>Çapraz referans</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="345"/>
        <source>&amp;Address or symbol:</source>
        <translation>&amp;Adres veya sembol:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="342"/>
        <source>Cross &amp;reference of this address</source>
        <translation>Bu adresin çapraz &amp;referansı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/cross_reference.py" line="343"/>
        <source>List every place the program reads and writes the address</source>
        <translation>Programın adresi okuduğu ve yazdığı her yeri listeler</translation>
    </message>
</context>
<context>
    <name>Diagnostic</name>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="72"/>
        <source>{count} byte(s) here are not valid {encoding}; they are kept as they are</source>
        <translation>buradaki {count} bayt geçerli {encoding} değil; olduğu gibi korunur</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="76"/>
        <source>this is not a ladder program (no %@ section and no instruction)</source>
        <translation>bu bir ladder programı değil (%@ bölümü ve komut yok)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="78"/>
        <source>line not understood in section {section}: &apos;{text}&apos;</source>
        <translation>{section} bölümünde anlaşılamayan satır: &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="80"/>
        <source>{name}: parameter {index} ({param}) must be {letter} and a number, found &apos;{text}&apos;</source>
        <translation>{name}: {index}. parametre ({param}) {letter} ve bir sayı olmalı, bulunan &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="84"/>
        <source>&apos;{text}&apos;: the number is too long</source>
        <translation>&apos;{text}&apos;: sayı çok uzun</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="24"/>
        <source>&apos;{text}&apos; is not an address (expected e.g. X2.1 or R100)</source>
        <translation>&apos;{text}&apos; bir adres değil (örneğin X2.1 veya R100 olmalı)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="26"/>
        <source>&apos;{text}&apos;: unknown area &apos;{area}&apos; (use X, Y, F, G, R, A, D, T, C or K)</source>
        <translation>&apos;{text}&apos;: bilinmeyen alan &apos;{area}&apos; (X, Y, F, G, R, A, D, T, C veya K kullanın)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="28"/>
        <source>&apos;{text}&apos;: byte number out of range for area {area} ({ranges})</source>
        <translation>&apos;{text}&apos;: {area} alanı için bayt numarası sınır dışı ({ranges})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="30"/>
        <source>&apos;{text}&apos;: bit number must be 0 to 7</source>
        <translation>&apos;{text}&apos;: bit numarası 0 ile 7 arasında olmalı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="31"/>
        <source>&apos;{text}&apos;: a bit address is needed here (e.g. {text}.0)</source>
        <translation>&apos;{text}&apos;: burada bit adresi gerekir (örneğin {text}.0)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="33"/>
        <source>&apos;{text}&apos;: a byte address is needed here, without a bit</source>
        <translation>&apos;{text}&apos;: burada bitsiz bir bayt adresi gerekir</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="35"/>
        <source>&apos;{text}&apos;: the width after &apos;:&apos; must be 1, 2 or 4</source>
        <translation>&apos;{text}&apos;: &apos;:&apos; işaretinden sonraki genişlik 1, 2 veya 4 olmalı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="37"/>
        <source>&apos;{text}&apos;: a bit address takes no width</source>
        <translation>&apos;{text}&apos;: bit adresine genişlik verilmez</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="39"/>
        <source>the ladder section must begin with %@3</source>
        <translation>ladder bölümü %@3 ile başlamalı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="40"/>
        <source>the ladder section must end with a line &apos;%&apos;</source>
        <translation>ladder bölümü &apos;%&apos; satırıyla bitmeli</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="41"/>
        <source>unexpected text &apos;{text}&apos;</source>
        <translation>beklenmeyen metin &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="42"/>
        <source>text outside any section: &apos;{text}&apos;</source>
        <translation>hiçbir bölümün içinde olmayan metin: &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="43"/>
        <source>section %@{number} appears twice</source>
        <translation>%@{number} bölümü iki kez var</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="44"/>
        <source>unknown section {header}: kept as it is</source>
        <translation>bilinmeyen bölüm {header}: olduğu gibi korundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="45"/>
        <source>unknown instruction &apos;{name}&apos;</source>
        <translation>bilinmeyen komut &apos;{name}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="46"/>
        <source>{name} needs an address</source>
        <translation>{name} bir adres ister</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="47"/>
        <source>{name} takes no operand, found &apos;{text}&apos;</source>
        <translation>{name} operand almaz, &apos;{text}&apos; bulundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="48"/>
        <source>{name} needs {expected} parameters, found {found}</source>
        <translation>{name} {expected} parametre ister, {found} bulundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="50"/>
        <source>{name}: parameter {index} ({param}) must be a number, found &apos;{text}&apos;</source>
        <translation>{name}: {index}. parametre ({param}) sayı olmalı, &apos;{text}&apos; bulundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="52"/>
        <source>{name}: parameter {index} ({param}) must be an address, found &apos;{text}&apos;</source>
        <translation>{name}: {index}. parametre ({param}) adres olmalı, &apos;{text}&apos; bulundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="54"/>
        <source>{name}: parameter {index} ({param}) must be {lo} to {hi}, found {value}</source>
        <translation>{name}: {index}. parametre ({param}) {lo} ile {hi} arasında olmalı, {value} bulundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="56"/>
        <source>{name}: parameter {index} ({param}) must be one of {choices}, found {value}</source>
        <translation>{name}: {index}. parametre ({param}) şunlardan biri olmalı: {choices}; {value} bulundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="60"/>
        <source>{name}: parameter {index} ({param}) must be up to 4 binary digits, found &apos;{text}&apos;</source>
        <translation>{name}: {index}. parametre ({param}) en çok 4 ikili hane olmalı, &apos;{text}&apos; bulundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="64"/>
        <source>SUB {number} is not in the instruction table: kept with its parameters, drawn as a box, simulated as W1 = ACT</source>
        <translation>SUB {number} komut tablosunda yok: parametreleriyle korunur, kutu olarak çizilir, W1 = ACT olarak simüle edilir</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="67"/>
        <source>a parameter line &apos;{text}&apos; without a SUB instruction before it</source>
        <translation>önünde SUB komutu olmayan parametre satırı &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="69"/>
        <source>the file is neither UTF-8 nor Turkish Windows (cp1254) text</source>
        <translation>dosya ne UTF-8 ne de Türkçe Windows (cp1254) metni</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="71"/>
        <source>syntax error at &apos;{text}&apos;</source>
        <translation>&apos;{text}&apos; yerinde yazım hatası</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="74"/>
        <source>a saved drawing ({lines} line(s)) is damaged: it is kept as comment text</source>
        <translation>kaydedilmiş bir çizim ({lines} satır) bozuk: açıklama metni olarak saklandı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="86"/>
        <source>open circuit: this element is not connected to the right side</source>
        <translation>açık devre: bu eleman sağ tarafa bağlı değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="88"/>
        <source>element not connected to the left rail</source>
        <translation>eleman sol baraya bağlı değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="89"/>
        <source>a coil must be at the right end of the network</source>
        <translation>çıkış (bobin) devrenin sağ ucunda olmalı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="91"/>
        <source>a coil cannot sit straight on the left rail</source>
        <translation>çıkış (bobin) doğrudan sol baraya bağlanamaz</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="92"/>
        <source>bridge circuit: a vertical link joins two branches in the middle</source>
        <translation>köprü devre: dikey çizgi iki kolu ortadan birleştiriyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="94"/>
        <source>short circuit: a wire bypasses the element</source>
        <translation>kısa devre: bir çizgi elemanı atlıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="95"/>
        <source>the logic needs more than 8 stack levels (ST8)</source>
        <translation>mantık 8&apos;den fazla yığın seviyesi (ST8) gerektiriyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="97"/>
        <source>power would flow right to left here; ladder flows left to right only</source>
        <translation>burada enerji sağdan sola akardı; ladder yalnız soldan sağa akar</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="99"/>
        <source>the network has no coil or function</source>
        <translation>devrede çıkış veya fonksiyon yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="100"/>
        <source>{name} needs its {count} control inputs connected</source>
        <translation>{name} fonksiyonunun {count} kontrol girişi bağlanmalı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="102"/>
        <source>this element has no address yet</source>
        <translation>bu elemanın henüz adresi yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="103"/>
        <source>this edge or comparison contact has no form for this place in the dialect (put it in series after another contact)</source>
        <translation>bu kenar ya da karşılaştırma kontağının bu PLC ailesinde bu yer için bir biçimi yok (onu başka bir kontaktan sonra seri koyun)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="106"/>
        <source>coils hang on different points of the logic; join them to one point</source>
        <translation>çıkışlar mantığın farklı noktalarına bağlı; tek noktaya bağlayın</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="108"/>
        <source>only coils may follow the output of {name}</source>
        <translation>{name} çıkışından sonra yalnız çıkış (bobin) gelebilir</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="109"/>
        <source>one function box per network: put {name} in a network of its own</source>
        <translation>her devrede bir fonksiyon kutusu olur: {name} için ayrı bir devre kullanın</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="112"/>
        <source>cell ({row}, {col}) is outside the grid</source>
        <translation>({row}, {col}) hücresi ızgaranın dışında</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="113"/>
        <source>only coils go in the coil column (cell ({row}, {col}))</source>
        <translation>çıkış sütununa yalnız çıkış konur (({row}, {col}) hücresi)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="115"/>
        <source>{name} does not fit here: a box needs two contact columns</source>
        <translation>{name} buraya sığmıyor: fonksiyon kutusu iki kontak sütunu ister</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="117"/>
        <source>an edge or comparison contact has no normally closed form</source>
        <translation>kenar ya da karşılaştırma kontağının normalde kapalı biçimi yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="119"/>
        <source>there is no suitable element at cell ({row}, {col})</source>
        <translation>({row}, {col}) hücresinde uygun eleman yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="121"/>
        <source>no function box with FO outputs at cell ({row}, {col})</source>
        <translation>({row}, {col}) hücresinde FO çıkışlı bir fonksiyon kutusu yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="123"/>
        <source>the program&apos;s {count} symbols (%@2) have no place in that family&apos;s files: the program keeps its family</source>
        <translation>programın {count} sembolünün (%@2) o ailenin dosyalarında yeri yok: program kendi ailesinde kalır</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="126"/>
        <source>instruction {step} ({name}) has no counterpart in that family: the program keeps its family</source>
        <translation>{step}. komutun ({name}) o ailede karşılığı yok: program kendi ailesinde kalır</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="129"/>
        <source>END ends the program and stays its last network: draw new networks above it</source>
        <translation>END programı bitirir ve son ağ olarak kalır: yeni ağları onun üstüne çizin</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="132"/>
        <source>a line must be horizontal or vertical</source>
        <translation>çizgi yatay veya dikey olmalı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="133"/>
        <source>the clipboard does not hold ladder elements</source>
        <translation>panoda ladder elemanı yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="135"/>
        <source>&apos;{text}&apos; is not an address or a symbol of the program: type one to replace it</source>
        <translation>&apos;{text}&apos; programın bir adresi veya sembolü değil: değiştirmek için bir adres veya sembol yazın</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="138"/>
        <source>{found} and {replacement}: replace a bit with a bit, a byte with a byte</source>
        <translation>{found} ve {replacement}: bit ile bit, bayt ile bayt değiştirilir</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="140"/>
        <source>{found} would be replaced with itself</source>
        <translation>{found} kendisiyle değiştirilmiş olur</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="142"/>
        <source>{name} with nothing pushed on the stack</source>
        <translation>yığına hiçbir şey itilmeden {name}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="143"/>
        <source>{name} writes to {address}, an input area</source>
        <translation>{name} bir giriş alanı olan {address} adresine yazıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="144"/>
        <source>{name} writes to {address}, part of the read-only R9000-R9005</source>
        <translation>{name}, salt okunur R9000-R9005 alanındaki {address} adresine yazıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="146"/>
        <source>JMP without a matching JMPE</source>
        <translation>eşi olan JMPE olmadan JMP</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="147"/>
        <source>JMPE without a JMP before it</source>
        <translation>önünde JMP olmadan JMPE</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="148"/>
        <source>COM without a matching COME</source>
        <translation>eşi olan COME olmadan COM</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="149"/>
        <source>COME without a COM before it</source>
        <translation>önünde COM olmadan COME</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="150"/>
        <source>{name} without a logic result before it (start with RD)</source>
        <translation>önünde mantık sonucu olmadan {name} (RD ile başlayın)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="152"/>
        <source>coil {address} is written more than once</source>
        <translation>{address} çıkışı birden fazla yazılıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="153"/>
        <source>logic at the end of the program is not written to any coil</source>
        <translation>programın sonundaki mantık hiçbir çıkışa yazılmıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="155"/>
        <source>not a LadderWorks binary: {reason}</source>
        <translation>LadderWorks binary dosyası değil: {reason}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="157"/>
        <source>coil {address} is written by WRT and by SET/RST (also on line {line})</source>
        <translation>{address} çıkışı hem WRT hem SET/RST ile yazılıyor (ayrıca {line}. satırda)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="159"/>
        <source>coil {address} is written by WRT and by SET/RST (also in network {other})</source>
        <translation>{address} çıkışı hem WRT hem SET/RST ile yazılıyor (ayrıca {other}. devrede)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="162"/>
        <source>LBL inside a JMP or COM range</source>
        <translation>JMP veya COM aralığı içinde LBL</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="163"/>
        <source>no LBL L{label} where this jump can reach it</source>
        <translation>bu atlamanın ulaşabileceği yerde LBL L{label} yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="165"/>
        <source>label L{label} is defined twice in this program unit</source>
        <translation>L{label} etiketi bu program biriminde iki kez tanımlı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="167"/>
        <source>JMPC is only allowed inside a subprogram</source>
        <translation>JMPC yalnızca bir alt program içinde kullanılabilir</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="168"/>
        <source>subprogram P{program} does not exist</source>
        <translation>P{program} alt programı yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="169"/>
        <source>calling P{program} here makes a subprogram call itself</source>
        <translation>burada P{program} çağrısı bir alt programın kendini çağırmasına yol açıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="171"/>
        <source>calls through P{program} nest deeper than {limit} subprograms</source>
        <translation>P{program} üzerinden çağrılar {limit} alt programdan daha derine iniyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="173"/>
        <source>SP without a matching SPE</source>
        <translation>eşleşen SPE olmadan SP</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="174"/>
        <source>SPE without an SP before it</source>
        <translation>önünde SP olmayan SPE</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="175"/>
        <source>subprogram P{program} is defined twice</source>
        <translation>P{program} alt programı iki kez tanımlı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="176"/>
        <source>only subprograms (SP ... SPE) may follow the first SP</source>
        <translation>ilk SP&apos;den sonra yalnızca alt programlar (SP ... SPE) gelebilir</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="178"/>
        <source>{name} cannot end level {level}</source>
        <translation>{name} {level}. seviyeyi bitiremez</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="179"/>
        <source>instruction after END, the end of the program</source>
        <translation>program sonu END&apos;den sonra komut</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="180"/>
        <source>a backward jump to L{label} repeated more than {limit} times in one scan</source>
        <translation>L{label} etiketine geri atlama bir taramada {limit} kereden fazla tekrarlandı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="183"/>
        <source>not an alarm message line: &apos;{text}&apos; (expected &apos;NNN text&apos; or &apos;A00.0 text&apos;)</source>
        <translation>alarm mesajı satırı değil: &apos;{text}&apos; (&apos;NNN metin&apos; veya &apos;A00.0 metin&apos; olmalı)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="185"/>
        <source>alarm number {number} is out of range (000 to 799)</source>
        <translation>{number} alarm numarası sınır dışı (000 ile 799 arası)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="187"/>
        <source>&apos;{text}&apos; is not an alarm bit (A0.0 to A99.7)</source>
        <translation>&apos;{text}&apos; bir alarm biti değil (A0.0 ile A99.7 arası)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="189"/>
        <source>message {number} appears again; the one on line {first} is used</source>
        <translation>{number} mesajı tekrar var; {first}. satırdaki kullanılıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="191"/>
        <source>message {number} has no text</source>
        <translation>{number} mesajının metni yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="192"/>
        <source>{name} is not implemented in the simulator yet</source>
        <translation>{name} simülatörde henüz yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="10"/>
        <source>ASCII format: the text opened by {quote} is never closed</source>
        <translation>ASCII biçimi: {quote} ile açılan metin hiç kapatılmamış</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="12"/>
        <source>ASCII format: a repeat count must be 1 to 999, found {count}</source>
        <translation>ASCII biçimi: tekrar sayısı 1 ile 999 arasında olmalı, bulunan {count}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="14"/>
        <source>ASCII format: &apos;{text}&apos; is not an item (expected &apos;text&apos;, MX, hex codes, &quot;w.dRn&quot;, / or \)</source>
        <translation>ASCII biçimi: &apos;{text}&apos; bir öğe değil (&apos;metin&apos;, MX, onaltılık kodlar, &quot;w.dRn&quot;, / ya da \ bekleniyor)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="18"/>
        <source>ASCII format: &quot;{text}&quot; is not a variable (expected e.g. &quot;8.2R0&quot; or &quot;4R10H&quot;)</source>
        <translation>ASCII biçimi: &quot;{text}&quot; bir değişken değil (örneğin &quot;8.2R0&quot; ya da &quot;4R10H&quot; bekleniyor)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="21"/>
        <source>ASCII format: text after END: &apos;{text}&apos;</source>
        <translation>ASCII biçimi: END&apos;den sonra metin: &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="23"/>
        <source>ASCII format: END is missing</source>
        <translation>ASCII biçimi: END eksik</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="24"/>
        <source>&apos;{name}&apos; is not a Fatek instruction</source>
        <translation>&apos;{name}&apos; bir Fatek komutu değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="26"/>
        <source>an operand line &apos;{text}&apos; without a FUN, TMR or CTR before it</source>
        <translation>önünde FUN, TMR ya da CTR olmayan bir operand satırı: &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="28"/>
        <source>{name} needs a device</source>
        <translation>{name} bir eleman (cihaz) adresi ister</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="29"/>
        <source>&apos;{text}&apos; is not a Fatek device</source>
        <translation>&apos;{text}&apos; bir Fatek elemanı değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="30"/>
        <source>{name} cannot take &apos;{text}&apos; (use {kinds})</source>
        <translation>{name} &apos;{text}&apos; alamaz ({kinds} kullanın)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="32"/>
        <source>&apos;{text}&apos; is out of range ({range})</source>
        <translation>&apos;{text}&apos; aralık dışında ({range})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="33"/>
        <source>{name} with nothing before it: a network starts with ORG</source>
        <translation>{name} önünde bir şey yok: ağ ORG ile başlar</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="35"/>
        <source>{name} needs two blocks: start the second one with LD</source>
        <translation>{name} iki blok ister: ikincisini LD ile başlatın</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="37"/>
        <source>TR{number} is set twice in this network</source>
        <translation>TR{number} bu ağda iki kez kullanılmış</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="39"/>
        <source>a network has at most {limit} TR points</source>
        <translation>bir ağda en fazla {limit} TR noktası olabilir</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="41"/>
        <source>LD TR{number} before OUT TR{number} in this network</source>
        <translation>bu ağda OUT TR{number} komutundan önce LD TR{number}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="43"/>
        <source>{name} on the left rail: put ORG SHORT before it</source>
        <translation>{name} başlangıç hattında: önüne ORG SHORT koyun</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="45"/>
        <source>{name}: {count} block(s) started with LD are not joined (ANDLD/ORLD)</source>
        <translation>{name}: LD ile başlayan {count} blok birleştirilmemiş (ANDLD/ORLD)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="47"/>
        <source>FUN {number} is not a Fatek function LadderWorks knows</source>
        <translation>FUN {number}, LadderWorks&apos;ün bildiği bir Fatek fonksiyonu değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="49"/>
        <source>{name}: the operand line {param} is missing</source>
        <translation>{name}: {param} operand satırı eksik</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="51"/>
        <source>{name} takes no more operands, found &apos;{text}&apos;</source>
        <translation>{name} başka operand almaz, bulunan &apos;{text}&apos;</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="53"/>
        <source>&apos;{text}&apos; cannot be the operand {param} (a register, or a constant)</source>
        <translation>&apos;{text}&apos;, {param} operandı olamaz (bir kaydedici ya da sabit olmalı)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="55"/>
        <source>&apos;{text}&apos; cannot be the operand {param} (a bit device: Y0, M5 …)</source>
        <translation>&apos;{text}&apos;, {param} operandı olamaz (bir bit aygıtı olmalı: Y0, M5 …)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="57"/>
        <source>{name} is kept and drawn but not simulated: its outputs stay 0</source>
        <translation>{name} korunur ve çizilir ama simüle edilmez: çıkışları 0 kalır</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="59"/>
        <source>&apos;{text}&apos; is not the time base of {name} ({base})</source>
        <translation>&apos;{text}&apos;, {name} zaman tabanı değil ({base})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="61"/>
        <source>FO {text}: no function output here (FO0-FO7 after a box)</source>
        <translation>FO {text}: burada fonksiyon çıkışı yok (bir kutudan sonra FO0-FO7)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="63"/>
        <source>&apos;{text}…&apos; is too long to be a Fatek number: the line is not read</source>
        <translation>&apos;{text}…&apos; bir Fatek sayısı olamayacak kadar uzun: satır okunmadı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="65"/>
        <source>not a WinProladder comment export: its first line must be REF, COMMENT, DESCRIPTION (tab-separated)</source>
        <translation>WinProladder yorum dışa aktarımı değil: ilk satırı REF, COMMENT, DESCRIPTION olmalı (sekmeyle ayrılmış)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="69"/>
        <source>&apos;{text}&apos; is not a Fatek device: the line is skipped</source>
        <translation>&apos;{text}&apos; bir Fatek cihazı değil: satır atlandı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="71"/>
        <source>the comments were read in code page {chosen}; they read as {others} too: check the names</source>
        <translation>yorumlar {chosen} kod sayfasında okundu; {others} olarak da okunabiliyor: adları denetleyin</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="75"/>
        <source>byte {offset} (0x{byte}) is a character in no Windows code page tried: the comments are not read</source>
        <translation>{offset}. bayt (0x{byte}) denenen hiçbir Windows kod sayfasında karakter değil: yorumlar okunmadı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="79"/>
        <source>ASCII files: &apos;{text}&apos; is not a section header such as [R1000]</source>
        <translation>ASCII dosyaları: &apos;{text}&apos;, [R1000] gibi bir bölüm başlığı değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="82"/>
        <source>not a WinProladder project: no &apos;Fatek WinProladder, File Format 1&apos; header</source>
        <translation>WinProladder projesi değil: &apos;Fatek WinProladder, File Format 1&apos; başlığı yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="84"/>
        <source>the .pdw file is cut short: its record at byte {offset} runs past the end</source>
        <translation>.pdw dosyası eksik: {offset}. bayttaki kaydı dosyanın sonunu aşıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="86"/>
        <source>the .pdw file is damaged: the record at byte {offset} fails its checksum</source>
        <translation>.pdw dosyası bozuk: {offset}. bayttaki kaydın sağlama toplamı tutmuyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="88"/>
        <source>the .pdw file is damaged: the record at byte {offset} is malformed</source>
        <translation>.pdw dosyası bozuk: {offset}. bayttaki kayıt hatalı biçimde</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="90"/>
        <source>the .pdw file holds no program (checked up to byte {offset})</source>
        <translation>.pdw dosyasında program yok ({offset}. bayta kadar bakıldı)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="92"/>
        <source>the program at byte {offset} cannot be unmasked: it has no erased memory block to recover the mask from</source>
        <translation>{offset}. bayttaki programın maskesi kaldırılamıyor: maskenin çıkarılabileceği silinmiş bir bellek bloğu yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="96"/>
        <source>the .pdw file is damaged: its program image is wrong at byte {offset}</source>
        <translation>.pdw dosyası bozuk: program görüntüsü {offset}. baytta hatalı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="98"/>
        <source>the .pdw file is damaged: the program&apos;s code does not match its checksum (byte {offset})</source>
        <translation>.pdw dosyası bozuk: programın kodu sağlama toplamıyla uyuşmuyor ({offset}. bayt)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="102"/>
        <source>instruction code {word} at byte {offset} is not one LadderWorks decodes yet: the program is read up to it</source>
        <translation>{offset}. bayttaki {word} komut kodunu LadderWorks henüz çözemiyor: program o noktaya kadar okundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="106"/>
        <source>operand code {word} at byte {offset} is not a device LadderWorks decodes yet: the program is read up to it</source>
        <translation>{offset}. bayttaki {word} operand kodu LadderWorks&apos;ün henüz çözebildiği bir cihaz değil: program o noktaya kadar okundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="110"/>
        <source>the program ends inside an instruction at byte {offset}</source>
        <translation>program {offset}. baytta bir komutun ortasında bitiyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="195"/>
        <source>&apos;{text}&apos; cannot be the device of {name} here: with it the line reads as {other} (place {other} from the palette)</source>
        <translation>&apos;{text}&apos; burada {name} komutunun aygıtı olamaz: onunla satır {other} olarak okunur ({other} komutunu paletten yerleştirin)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="198"/>
        <source>&apos;{text}&apos; is not a device (use {letters} with a number)</source>
        <translation>&apos;{text}&apos; bir aygıt değil ({letters} harflerinden biri ve bir numara kullanın)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="200"/>
        <source>&apos;{text}&apos;: {letter} is numbered in octal (digits 0 to 7)</source>
        <translation>&apos;{text}&apos;: {letter} sekizli (oktal) numaralanır (0 ile 7 arası rakamlar)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="202"/>
        <source>&apos;{text}&apos; is out of range ({first} to {last})</source>
        <translation>&apos;{text}&apos; aralık dışında ({first} ile {last} arası)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="203"/>
        <source>&apos;{text}&apos; is not a bit device</source>
        <translation>&apos;{text}&apos; bir bit aygıtı değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="204"/>
        <source>&apos;{text}&apos; is not a word device</source>
        <translation>&apos;{text}&apos; bir kelime (word) aygıtı değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="205"/>
        <source>&apos;{text}&apos; is not listed in this table (use {letters})</source>
        <translation>&apos;{text}&apos; bu tabloda listelenmez ({letters} kullanın)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="207"/>
        <source>&apos;{text}&apos;: give a device or a range FIRST-LAST of at most {most} devices</source>
        <translation>&apos;{text}&apos;: bir aygıt ya da en çok {most} aygıtlık bir İLK-SON aralığı verin</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="209"/>
        <source>{name}: operand {index} must be one of {expected}, found &apos;{text}&apos;</source>
        <translation>{name}: {index}. operand şunlardan biri olmalı: {expected}; &apos;{text}&apos; bulundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="211"/>
        <source>&apos;{text}&apos; is not a K or H constant</source>
        <translation>&apos;{text}&apos; bir K ya da H sabiti değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="212"/>
        <source>{name} is a {dialect} instruction the simulator does not run</source>
        <translation>{name}, simülatörün çalıştırmadığı bir {dialect} komutu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="214"/>
        <source>{name} is kept and drawn but not simulated: the scan passes it by</source>
        <translation>{name} korunur ve çizilir ama benzetilmez: tarama onu atlar</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="216"/>
        <source>{count} instructions are not simulated, the scan passes them by (line): {names}</source>
        <translation>{count} komut benzetilmez, tarama onları atlar (satır): {names}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="219"/>
        <source>INV inverts all the power before it: draw it on a line from the rail or a branch point, not inside a parallel block</source>
        <translation>INV kendinden önceki tüm enerjiyi tersler: onu baradan ya da bir dallanma noktasından gelen bir hatta çizin, paralel bir bloğun içine değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="222"/>
        <source>{name}: operand {index} is missing</source>
        <translation>{name}: {index}. işlenen eksik</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="223"/>
        <source>step {step} is not after step {previous}: the step numbers must grow</source>
        <translation>{step} adımı {previous} adımından sonra gelmiyor: adım numaraları artmalı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="225"/>
        <source>subroutine without its SRET (before the next pointer or END)</source>
        <translation>SRET&apos;i olmayan alt program (sonraki işaretçiden ya da END&apos;den önce)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="227"/>
        <source>SRET without a subroutine pointer (P n after FEND) before it</source>
        <translation>önünde alt program işaretçisi (FEND&apos;den sonra P n) olmayan SRET</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="229"/>
        <source>after FEND only subroutines (P n ... SRET) and END may follow</source>
        <translation>FEND&apos;den sonra yalnızca alt programlar (P n ... SRET) ve END gelebilir</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="231"/>
        <source>no pointer P{label} where this jump can reach it</source>
        <translation>bu atlamanın ulaşabileceği yerde P{label} işaretçisi yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="233"/>
        <source>no subroutine P{program} after FEND for this CALL</source>
        <translation>bu CALL için FEND&apos;den sonra P{program} alt programı yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="235"/>
        <source>{name} without a logic result before it (start with LD)</source>
        <translation>{name} önünde mantık sonucu yok (LD ile başlayın)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="237"/>
        <source>this pointer P number is used twice</source>
        <translation>bu işaretçi P numarası iki kez kullanılmış</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="239"/>
        <source>not a WPLSoft .dvp project: it does not start with the bytes 57 01 01 00</source>
        <translation>WPLSoft .dvp projesi değil: 57 01 01 00 baytlarıyla başlamıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="241"/>
        <source>the .dvp file is cut short at byte {offset}: it does not end with the line &lt;PrjectEnd&gt; WPLSoft writes last</source>
        <translation>.dvp dosyası {offset}. baytta kesilmiş: WPLSoft&apos;un en sona yazdığı &lt;PrjectEnd&gt; satırıyla bitmiyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="244"/>
        <source>byte {offset}: .dvp format version {version} is not one LadderWorks reads (214, 215 and 216 are)</source>
        <translation>bayt {offset}: .dvp biçim sürümü {version} LadderWorks&apos;ün okuduğu sürümlerden değil (214, 215 ve 216 okunur)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="247"/>
        <source>byte {offset}: the program memory of this .dvp project is not where WPLSoft puts it: the file is damaged</source>
        <translation>bayt {offset}: bu .dvp projesinin program belleği WPLSoft&apos;un koyduğu yerde değil: dosya bozuk</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="250"/>
        <source>byte {offset} (step {step}): instruction code {word} is not known to LadderWorks: kept as ?{word} with its operands</source>
        <translation>bayt {offset} (adım {step}): {word} komut kodu LadderWorks tarafından bilinmiyor: operandlarıyla ?{word} olarak korundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="253"/>
        <source>byte {offset} (step {step}): the word {word} names no device LadderWorks knows: the file is damaged or uses a device not decoded yet</source>
        <translation>bayt {offset} (adım {step}): {word} sözcüğü LadderWorks&apos;ün bildiği bir cihazı göstermiyor: dosya bozuk ya da henüz çözülmemiş bir cihaz kullanıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="256"/>
        <source>byte {offset} (step {step}): the operand word {word} is neither a device nor a constant: the file is damaged</source>
        <translation>bayt {offset} (adım {step}): {word} operand sözcüğü ne cihaz ne sabit: dosya bozuk</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="259"/>
        <source>byte {offset} (step {step}): the operand words after {word} do not fit the instruction: the file is damaged</source>
        <translation>bayt {offset} (adım {step}): {word} sonrasındaki operand sözcükleri komuta uymuyor: dosya bozuk</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="262"/>
        <source>byte {offset} (step {step}): the operand word {word} follows no instruction: the file is damaged</source>
        <translation>bayt {offset} (adım {step}): {word} operand sözcüğünden önce komut yok: dosya bozuk</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="265"/>
        <source>byte {offset}: the program does not end with END: the file is damaged</source>
        <translation>bayt {offset}: program END ile bitmiyor: dosya bozuk</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="267"/>
        <source>byte {offset} (step {step}): instructions after END: the file is damaged</source>
        <translation>bayt {offset} (adım {step}): END sonrasında komutlar var: dosya bozuk</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="270"/>
        <source>byte {offset}: a text section of the .dvp project is damaged</source>
        <translation>bayt {offset}: .dvp projesinin bir metin bölümü bozuk</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="272"/>
        <source>byte {offset}: a device comment line is not DEVICE$&amp;text</source>
        <translation>bayt {offset}: bir cihaz açıklama satırı CİHAZ$&amp;metin biçiminde değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="274"/>
        <source>the project holds no program: no compiled instruction list and an empty ladder drawing</source>
        <translation>projede program yok: derlenmiş komut listesi yok ve ladder çizimi boş</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="277"/>
        <source>the project was saved without compiling: its program is read from its ladder drawing</source>
        <translation>proje derlenmeden kaydedilmiş: programı ladder çiziminden okundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="280"/>
        <source>the project holds no compiled instruction list, and its ladder drawing has a cell LadderWorks does not read yet (byte {offset}: a branch, an edge contact ...): compile it in WPLSoft and save it again</source>
        <translation>proje derlenmiş bir komut listesi içermiyor ve ladder çiziminde LadderWorks&apos;ün henüz okumadığı bir hücre var (bayt {offset}: bir kol, bir kenar kontağı ...): WPLSoft&apos;ta derleyip yeniden kaydedin</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="284"/>
        <source>LadderWorks does not write .dvp projects (the format is only partly known): save the program as a Delta instruction list (.il) instead</source>
        <translation>LadderWorks .dvp projesi yazmaz (biçim yalnızca kısmen biliniyor): programı bunun yerine Delta komut listesi (.il) olarak kaydedin</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="287"/>
        <source>NEXT without a FOR before it</source>
        <translation>Öncesinde FOR olmayan NEXT</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="288"/>
        <source>MC or STL without its MCR or RET after it</source>
        <translation>MCR veya RET&apos;i olmayan MC veya STL</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="290"/>
        <source>MCR or RET without its MC or STL before it</source>
        <translation>Öncesinde MC veya STL olmayan MCR veya RET</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="292"/>
        <source>FOR without its NEXT</source>
        <translation>NEXT&apos;i olmayan FOR</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="294"/>
        <source>the first line must be &apos;PMC SIGNAL DATA&apos;</source>
        <translation>ilk satır &apos;PMC SIGNAL DATA&apos; olmalıdır</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="296"/>
        <source>unknown command &apos;{text}&apos; (use REMARK, PROGRAM, SET, EXPECT, WAITFOR, FORCE or RELEASE)</source>
        <translation>bilinmeyen komut &apos;{text}&apos; (REMARK, PROGRAM, SET, EXPECT, WAITFOR, FORCE veya RELEASE kullanın)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="300"/>
        <source>&apos;{text}&apos; is not a wait in ms</source>
        <translation>&apos;{text}&apos; ms cinsinden bir bekleme değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="301"/>
        <source>negative wait {text} ms</source>
        <translation>negatif bekleme {text} ms</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="302"/>
        <source>{command} needs {expected}</source>
        <translation>{command} için gereken: {expected}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="303"/>
        <source>&apos;{text}&apos; is neither an address nor a symbol of the program</source>
        <translation>&apos;{text}&apos; ne bir adres ne de programın bir sembolü</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="305"/>
        <source>&apos;{text}&apos; is not a value for {target}</source>
        <translation>&apos;{text}&apos;, {target} için bir değer değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="306"/>
        <source>unknown type &apos;{text}&apos; (use BIT, BYTE, WORD or DWORD)</source>
        <translation>bilinmeyen tip &apos;{text}&apos; (BIT, BYTE, WORD veya DWORD kullanın)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="308"/>
        <source>&apos;{text}&apos;: only bits can be forced</source>
        <translation>&apos;{text}&apos;: yalnızca bitler zorlanabilir</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="309"/>
        <source>the scenario names no program: add a line PROGRAM,path (relative to the scenario file) or give the program on the command line</source>
        <translation>senaryo bir program belirtmiyor: PROGRAM,yol satırı ekleyin (yol senaryo dosyasına göre) ya da programı komut satırında verin</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="312"/>
        <source>a second PROGRAM line (the one on line {first} counts)</source>
        <translation>ikinci bir PROGRAM satırı ({first}. satırdaki geçerlidir)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="314"/>
        <source>the program &apos;{path}&apos; cannot be loaded: {reason}</source>
        <translation>&apos;{path}&apos; programı yüklenemiyor: {reason}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="316"/>
        <source>the scenario names the program &apos;{path}&apos;; it runs on the one loaded in the PLC</source>
        <translation>senaryo &apos;{path}&apos; programını belirtiyor; PLC&apos;ye yüklenmiş olan programda çalışır</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="320"/>
        <source>not a parameter line: &apos;{text}&apos; (expected ADDRESS = VALUE, e.g. T0:4 = 1000)</source>
        <translation>parametre satırı değil: &apos;{text}&apos; (ADRES = DEĞER bekleniyor, ör. T0:4 = 1000)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="324"/>
        <source>&apos;{text}&apos;: PMC parameters are in the T, C, K and D areas only</source>
        <translation>&apos;{text}&apos;: PMC parametreleri yalnızca T, C, K ve D alanlarındadır</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="326"/>
        <source>&apos;{text}&apos; is not a value for {width} byte(s)</source>
        <translation>&apos;{text}&apos;, {width} baytlık bir değer değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="328"/>
        <source>&apos;{text}&apos; is not a number</source>
        <translation>&apos;{text}&apos; bir sayı değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="329"/>
        <source>{value} is out of range ({low} to {high})</source>
        <translation>{value} sınır dışı ({low} ile {high} arası)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="330"/>
        <source>{value} bytes: a value has 1, 2 or 4 bytes</source>
        <translation>{value} bayt: bir değer 1, 2 veya 4 bayt olur</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="331"/>
        <source>&apos;{text}&apos;: type up to 8 binary digits (0 and 1), bit 7 first</source>
        <translation>&apos;{text}&apos;: en çok 8 ikili rakam (0 ve 1) yazın, önce bit 7</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="333"/>
        <source>TMRB {number}: its preset is fixed in the program and cannot be changed here</source>
        <translation>TMRB {number}: ayar değeri programda sabittir, buradan değiştirilemez</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="337"/>
        <source>expected TABLE,START,COUNT,PLC ADDRESS,ACCESS[,WIDTH], found {count} column(s)</source>
        <translation>TABLO,BAŞLANGIÇ,ADET,PLC ADRESİ,ERİŞİM[,GENİŞLİK] bekleniyor, {count} sütun bulundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="340"/>
        <source>&apos;{text}&apos; is not a Modbus table (use coils, discrete, holding or input)</source>
        <translation>&apos;{text}&apos; bir Modbus tablosu değil (coils, discrete, holding ya da input kullanın)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="342"/>
        <source>&apos;{text}&apos; is not a number from {lo} to {hi}</source>
        <translation>&apos;{text}&apos;, {lo} ile {hi} arasında bir sayı değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="344"/>
        <source>{count} addresses from {start} run past Modbus address 65535</source>
        <translation>{start} adresinden başlayan {count} adres 65535 Modbus adresini aşıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="346"/>
        <source>&apos;{text}&apos;: the access must be r (read) or rw (read and write)</source>
        <translation>&apos;{text}&apos;: erişim r (okuma) ya da rw (okuma ve yazma) olmalı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="348"/>
        <source>{table} cannot be written over Modbus: the access must be r</source>
        <translation>{table} Modbus üzerinden yazılamaz: erişim r olmalı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="350"/>
        <source>{table} are bits: a width is for registers only</source>
        <translation>{table} bittir: genişlik yalnızca yazmaçlar içindir</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="352"/>
        <source>{count} elements from {device} run past the end of area {area} ({ranges})</source>
        <translation>{device} adresinden başlayan {count} eleman {area} alanının sonunu aşıyor ({ranges})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="354"/>
        <source>{table} {start}-{end} overlap the row on line {other}</source>
        <translation>{table} {start}-{end}, {other}. satırdaki satırla çakışıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="356"/>
        <source>the map has no row</source>
        <translation>haritada hiç satır yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="357"/>
        <source>{device}: a device&apos;s register is 16 bits: the width must be 2</source>
        <translation>{device}: bir aygıtın yazmacı 16 bittir: genişlik 2 olmalı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="360"/>
        <source>&apos;{text}&apos; is neither a name of the program nor an address</source>
        <translation>&apos;{text}&apos; ne programın bir adı ne de bir adres</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="362"/>
        <source>&apos;{text}&apos; is a {type}: watch one of its members (e.g. {text}.Q)</source>
        <translation>&apos;{text}&apos; bir {type}: üyelerinden birini izleyin (ör. {text}.Q)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="364"/>
        <source>&apos;{text}&apos; is a {type}: the watch table has no format for it</source>
        <translation>&apos;{text}&apos; bir {type}: izleme tablosunda bunun için bir biçim yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="366"/>
        <source>&apos;{text}&apos; is not a date from D#1990-01-01 to D#2169-06-06 (e.g. D#2024-01-31)</source>
        <translation>&apos;{text}&apos; D#1990-01-01 ile D#2169-06-06 arasında bir tarih değil (ör. D#2024-01-31)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="369"/>
        <source>&apos;{text}&apos; is not a time of day (e.g. TOD#12:30:00.000)</source>
        <translation>&apos;{text}&apos; bir günün saati değil (ör. TOD#12:30:00.000)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="371"/>
        <source>the value has {length} characters: at most {limit} are read</source>
        <translation>değer {length} karakter: en çok {limit} karakter okunur</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="373"/>
        <source>no modify value to write</source>
        <translation>yazılacak değiştirme değeri yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="374"/>
        <source>&apos;{text}&apos; is not TRUE or FALSE (or 1, 0)</source>
        <translation>&apos;{text}&apos; TRUE ya da FALSE (veya 1, 0) değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="375"/>
        <source>&apos;{text}&apos; is not a whole number (e.g. 12, -3, 16#FF, 2#0101)</source>
        <translation>&apos;{text}&apos; bir tam sayı değil (ör. 12, -3, 16#FF, 2#0101)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="377"/>
        <source>&apos;{text}&apos; is out of range: {low} to {high}</source>
        <translation>&apos;{text}&apos; aralığın dışında: {low} ile {high} arası</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="379"/>
        <source>&apos;{text}&apos; is not a real number (e.g. 1.5)</source>
        <translation>&apos;{text}&apos; bir gerçel sayı değil (ör. 1.5)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="380"/>
        <source>&apos;{text}&apos; is not a time (e.g. T#5S_300MS, T#1M30S or 1500 ms)</source>
        <translation>&apos;{text}&apos; bir süre değil (ör. T#5S_300MS, T#1M30S ya da 1500 ms)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="382"/>
        <source>&apos;{text}&apos; is not one character of the Latin-1 set (e.g. &apos;A&apos;)</source>
        <translation>&apos;{text}&apos; Latin-1 kümesinden tek bir karakter değil (ör. &apos;A&apos;)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="384"/>
        <source>&apos;{text}&apos; has characters a string cannot hold (only the Latin-1 set)</source>
        <translation>&apos;{text}&apos; bir dizenin tutamayacağı karakterler içeriyor (yalnızca Latin-1 kümesi)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="386"/>
        <source>&apos;{text}&apos; is longer than the string&apos;s {length} characters</source>
        <translation>&apos;{text}&apos; dizenin {length} karakterinden uzun</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/diagnostics.py" line="388"/>
        <source>&apos;{name}&apos; is neither a map file nor a global DB of the program (its global DBs: {names})</source>
        <translation>&apos;{name}&apos; ne bir harita dosyası ne de programın bir global veri bloğu (global veri blokları: {names})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="113"/>
        <source>&apos;{text}&apos; is not an S7 address (e.g. %I0.0, %MW2, %DB1.DBW4) or a tag</source>
        <translation>&apos;{text}&apos; bir S7 adresi (ör. %I0.0, %MW2, %DB1.DBW4) ya da etiket değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="115"/>
        <source>SIMATIC SD: expected {expected}, found &apos;{found}&apos;</source>
        <translation>SIMATIC SD: {expected} bekleniyordu, &apos;{found}&apos; bulundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="117"/>
        <source>SIMATIC SD: the text ends inside {what} (cut off?)</source>
        <translation>SIMATIC SD: metin {what} içinde bitiyor (kesilmiş mi?)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="119"/>
        <source>network {network}: &apos;{part}&apos; is not an instruction LadderWorks simulates</source>
        <translation>network {network}: &apos;{part}&apos; LadderWorks&apos;ün benzettiği bir komut değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="121"/>
        <source>network {network}: &apos;{text}&apos; is neither a tag, a member of the block nor an address</source>
        <translation>network {network}: &apos;{text}&apos; ne bir etiket, ne bloğun bir üyesi, ne de bir adres</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="124"/>
        <source>network {network}: {part} needs its pin {pin}</source>
        <translation>network {network}: {part} için {pin} ucu gerekli</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="126"/>
        <source>network {network}: the wiring of {part} cannot be followed ({why})</source>
        <translation>network {network}: {part} bağlantıları izlenemiyor ({why})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="128"/>
        <source>network {network}: there is no label &apos;{label}&apos; in this block</source>
        <translation>network {network}: bu blokta &apos;{label}&apos; etiketi yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="130"/>
        <source>network {network}: a {language} network is shown, not simulated</source>
        <translation>network {network}: {language} network&apos;ü gösterilir, benzetilmez</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="132"/>
        <source>network {network}: the block &apos;{block}&apos; it calls is not in the program</source>
        <translation>network {network}: çağrılan &apos;{block}&apos; bloğu programda yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="134"/>
        <source>network {network}: {text} is in none of the tag tables read; LadderWorks gives it a place of its own ({type})</source>
        <translation>network {network}: {text} okunan etiket tablolarının hiçbirinde yok; LadderWorks ona kendi yerini veriyor ({type})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="137"/>
        <source>network {network}: {part} on the type &apos;{type}&apos; is not simulated</source>
        <translation>network {network}: &apos;{type}&apos; tipinde {part} benzetilmez</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="139"/>
        <source>network {network}: no room left for &apos;{text}&apos; (DB members and instances share 10000 bytes)</source>
        <translation>network {network}: &apos;{text}&apos; için yer kalmadı (DB üyeleri ve örnekler 10000 baytı paylaşır)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="142"/>
        <source>the file has {size} MB: S7 exports over {limit} MB are not read</source>
        <translation>dosya {size} MB: {limit} MB üzerindeki S7 dışa aktarımları okunmaz</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="144"/>
        <source>tag table: {why}</source>
        <translation>etiket tablosu: {why}</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="146"/>
        <source>network {network}, row {row}, column {column}: the contact or coil has no operand</source>
        <translation>network {network}, satır {row}, sütun {column}: kontağın ya da bobinin operandı yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="149"/>
        <source>network {network}, row {row}, column {column}: &apos;{name}&apos; is no S7 element (use the S7 palette)</source>
        <translation>network {network}, satır {row}, sütun {column}: &apos;{name}&apos; bir S7 elemanı değil (S7 paletini kullanın)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="152"/>
        <source>this change cannot be written into the S7 block&apos;s file: make it in TIA Portal</source>
        <translation>bu değişiklik S7 bloğunun dosyasına yazılamıyor: TIA Portal&apos;da yapın</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="155"/>
        <source>{file}, line {line}: expected {expected}, found &apos;{found}&apos;: the source is not read</source>
        <translation>{file}, satır {line}: {expected} bekleniyordu, &apos;{found}&apos; bulundu: kaynak okunmadı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="158"/>
        <source>{file}, line {line}: the text ends inside {what} (cut off?): the source is not read</source>
        <translation>{file}, satır {line}: metin {what} içinde bitiyor (kesilmiş mi?): kaynak okunmadı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="161"/>
        <source>the S7 block&apos;s file no longer reads (line {line}): nothing is written</source>
        <translation>S7 bloğunun dosyası artık okunamıyor (satır {line}): hiçbir şey yazılmadı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="163"/>
        <source>&apos;{part}&apos; cannot be written in the S7 block&apos;s file form: make this change in TIA Portal</source>
        <translation>&apos;{part}&apos; S7 bloğunun dosya biçiminde yazılamıyor: bu değişikliği TIA Portal&apos;da yapın</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="166"/>
        <source>&apos;{text}&apos; is no S7 jump label: letters, digits and _, not starting with a digit</source>
        <translation>&apos;{text}&apos; bir S7 atlama etiketi değil: harfler, rakamlar ve _; rakamla başlamaz</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="169"/>
        <source>network {network} is not a complete S7 network yet (an element S7 does not have, an operand missing or still &lt;???&gt;): the S7 block&apos;s file is not written</source>
        <translation>network {network} henüz tamamlanmış bir S7 network&apos;ü değil (S7&apos;de olmayan bir eleman, eksik ya da hâlâ &lt;???&gt; olan bir operand): S7 bloğunun dosyası yazılmadı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="174"/>
        <source>SimaticML: the file is {size} MB, more than the {limit} MB LadderWorks reads</source>
        <translation>SimaticML: dosya {size} MB, LadderWorks&apos;ün okuduğu {limit} MB&apos;tan büyük</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="177"/>
        <source>SimaticML: {what} is refused (entities are never expanded or fetched)</source>
        <translation>SimaticML: {what} reddedildi (varlıklar asla genişletilmez ve getirilmez)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="179"/>
        <source>SimaticML: not well-formed XML ({why})</source>
        <translation>SimaticML: XML düzgün biçimlendirilmemiş ({why})</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="180"/>
        <source>SimaticML: the document holds no block (SW.Blocks.…) and no tag table</source>
        <translation>SimaticML: belgede blok (SW.Blocks.…) ve etiket tablosu yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="182"/>
        <source>{block}, network {network}: the namespace &apos;{uri}&apos; is not TIA Openness&apos;s; the network is not read</source>
        <translation>{block}, network {network}: &apos;{uri}&apos; ad alanı TIA Openness&apos;e ait değil; network okunmadı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="185"/>
        <source>{block}, network {network}: {kind} version v{version} is newer than the v5 LadderWorks knows; read as v5</source>
        <translation>{block}, network {network}: {kind} sürümü v{version}, LadderWorks&apos;ün bildiği v5&apos;ten yeni; v5 olarak okundu</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="188"/>
        <source>{block}, network {network}: wire {wire} goes to the part UId {uid}, which is not in the network</source>
        <translation>{block}, network {network}: {wire} bağlantısı UId {uid} parçasına gidiyor, bu parça networkte yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="191"/>
        <source>{block}, network {network}: the wires from part UId {uid} loop back to it</source>
        <translation>{block}, network {network}: UId {uid} parçasından çıkan bağlantılar yine ona dönüyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="194"/>
        <source>{block}, network {network}: part UId {uid} &apos;{part}&apos; is not known to LadderWorks (kept, not simulated)</source>
        <translation>{block}, network {network}: UId {uid} parçası &apos;{part}&apos; LadderWorks&apos;çe bilinmiyor (saklandı, simüle edilmez)</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="197"/>
        <source>{block}, network {network}: more than {limit} parts; the network is not read</source>
        <translation>{block}, network {network}: {limit} parçadan fazla; network okunmadı</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="200"/>
        <source>{block}, network {network}: access UId {uid} of scope &apos;{scope}&apos; names nothing LadderWorks reads; the parts wired to it are not simulated</source>
        <translation>{block}, network {network}: &apos;{scope}&apos; kapsamlı UId {uid} erişimi LadderWorks&apos;ün okuduğu hiçbir şeyi adlandırmıyor; ona bağlı parçalar benzetilmiyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/core/dialect_messages.py" line="203"/>
        <source>{block}, network {network}: part UId {uid} calls &apos;{callee}&apos;, which is not in the program</source>
        <translation>{block}, network {network}: UId {uid} parçası &apos;{callee}&apos; bloğunu çağırıyor, bu blok programda yok</translation>
    </message>
</context>
<context>
    <name>ErrorList</name>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="27"/>
        <source>network {0}, row {1}, column {2}</source>
        <translation>devre {0}, satır {1}, sütun {2}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="31"/>
        <source>network {0}</source>
        <translation>devre {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="34"/>
        <source>line {0}, column {1}</source>
        <translation>satır {0}, sütun {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="91"/>
        <source>Errors: {0}   Warnings: {1}</source>
        <translation>Hata: {0}   Uyarı: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="97"/>
        <source>Error</source>
        <translation>Hata</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="98"/>
        <source>Warning</source>
        <translation>Uyarı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="112"/>
        <source>Errors</source>
        <translation>Hatalar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="113"/>
        <source>Show warnings</source>
        <translation>Uyarıları göster</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="115"/>
        <source>Kind</source>
        <translation>Tür</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="116"/>
        <source>Where</source>
        <translation>Yer</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/error_list.py" line="117"/>
        <source>Message</source>
        <translation>Mesaj</translation>
    </message>
</context>
<context>
    <name>FamilyWords</name>
    <message>
        <location filename="../ladderworks/gui/family_words.py" line="28"/>
        <location filename="../ladderworks/gui/family_words.py" line="33"/>
        <location filename="../ladderworks/gui/family_words.py" line="38"/>
        <source>e.g. {0}</source>
        <translation>örn. {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/family_words.py" line="44"/>
        <source>Type the devices to watch, e.g. {0}</source>
        <translation>İzlenecek aygıtları yazın, örn. {0}</translation>
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
        <translation>Bulunamadı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="224"/>
        <source>network {0}</source>
        <translation>devre {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="230"/>
        <source>{0} of {1}: {2}, {3}</source>
        <translation>{0} / {1}: {2}, {3}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="264"/>
        <source>Replace {0} with {1}</source>
        <translation>{0} yerine {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="270"/>
        <source>Replaced; no more found</source>
        <translation>Değiştirildi; başka bulunamadı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="287"/>
        <source>Replace all {0} with {1}</source>
        <translation>Tüm {0} yerine {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="289"/>
        <source>{0} replaced in {1} networks</source>
        <translation>{1} devrede {0} yer değiştirildi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="298"/>
        <source>Address, symbol or words, {0}</source>
        <translation>Adres, sembol veya sözcükler, {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="300"/>
        <source>Address or symbol, {0}</source>
        <translation>Adres veya sembol, {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="305"/>
        <source>Find and replace</source>
        <translation>Bul ve değiştir</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="176"/>
        <location filename="../ladderworks/gui/find_replace.py" line="306"/>
        <source>Find:</source>
        <translation>Bul:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="226"/>
        <source>{0} ({1})</source>
        <translation>{0} ({1})</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="229"/>
        <source>network comment</source>
        <translation>devre yorumu</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="307"/>
        <source>Replace with:</source>
        <translation>Yerine:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="309"/>
        <source>Find &amp;next</source>
        <translation>&amp;Sonrakini bul</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="310"/>
        <source>Find &amp;previous</source>
        <translation>Ö&amp;ncekini bul</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="311"/>
        <source>&amp;Replace</source>
        <translation>&amp;Değiştir</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="312"/>
        <source>Replace &amp;all</source>
        <translation>&amp;Tümünü değiştir</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="313"/>
        <source>Close</source>
        <translation>Kapat</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="314"/>
        <source>Also in comments and signal descriptions</source>
        <translation>Yorumlarda ve sinyal açıklamalarında da ara</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/find_replace.py" line="315"/>
        <source>Find the words in the elements&apos; comments, the program&apos;s comments of its addresses, the manual&apos;s signal descriptions and the network comments</source>
        <translation>Kelimeleri elemanların yorumlarında, programın adres yorumlarında, kılavuzun sinyal açıklamalarında ve devre yorumlarında ara</translation>
    </message>
</context>
<context>
    <name>FitWidth</name>
    <message>
        <location filename="../ladderworks/gui/editor/zoom.py" line="74"/>
        <source>Fit width: the ladder is too narrow ({0} px) for its networks even at {1} %: close or narrow a dock, or widen the window</source>
        <translation>Genişliğe sığdır: ladder alanı devreleri için %{1} ölçekte bile çok dar ({0} piksel): bir paneli kapatın ya da daraltın veya pencereyi genişletin</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/zoom.py" line="78"/>
        <source>Fit width: every network fits at {0} % (a dock closed reads larger)</source>
        <translation>Genişliğe sığdır: her devre %{0} ölçekte sığıyor (bir panel kapatılınca büyür)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/zoom.py" line="81"/>
        <source>Fit width: every network fits the window&apos;s width</source>
        <translation>Genişliğe sığdır: her devre pencerenin genişliğine sığıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/zoom.py" line="82"/>
        <source>Fit width: {0} of {1} networks fit the window&apos;s width; the {2} wider ones scroll sideways</source>
        <translation>Genişliğe sığdır: {1} devreden {0} tanesi pencerenin genişliğine sığıyor; daha geniş {2} devre yana kaydırılır</translation>
    </message>
</context>
<context>
    <name>ForceList</name>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="93"/>
        <source>Forced and passive</source>
        <translation>Zorlananlar ve pasifler</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="95"/>
        <source>Kind</source>
        <translation>Tür</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="95"/>
        <source>Signal / element</source>
        <translation>Sinyal / eleman</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="96"/>
        <source>Value</source>
        <translation>Değer</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="98"/>
        <source>Release all</source>
        <translation>Hepsini bırak</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="99"/>
        <source>&amp;Bit:</source>
        <translation>&amp;Bit:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="100"/>
        <source>an address or a tag</source>
        <translation>bir adres ya da bir etiket</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="101"/>
        <source>Force to 1</source>
        <translation>1&apos;e zorla</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="102"/>
        <source>Force to 0</source>
        <translation>0&apos;a zorla</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="118"/>
        <source>{0} is not a bit: only bits are forced</source>
        <translation>{0} bir bit değil: yalnızca bitler zorlanır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="127"/>
        <source>Load a program to force its bits</source>
        <translation>Bitlerini zorlamak için bir program yükleyin</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="141"/>
        <location filename="../ladderworks/gui/docks/force_list.py" line="145"/>
        <source>FORCED</source>
        <translation>ZORLANMIŞ</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="152"/>
        <source>network {0}, line {1}: {2}</source>
        <translation>devre {0}, satır {1}: {2}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="158"/>
        <source>PASSIVE</source>
        <translation>PASİF</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="169"/>
        <source>Release</source>
        <translation>Bırak</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/force_list.py" line="173"/>
        <source>{0} forced, {1} passive</source>
        <translation>{0} zorlanmış, {1} pasif</translation>
    </message>
</context>
<context>
    <name>FunctionDialog</name>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="56"/>
        <source>one of {0}</source>
        <translation>şunlardan biri: {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="58"/>
        <source>{0} to {1}</source>
        <translation>{0} ile {1} arası</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="61"/>
        <source>a device of this PLC</source>
        <translation>bu PLC&apos;nin bir aygıtı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="63"/>
        <source>a constant or a device of this PLC</source>
        <translation>bir sabit ya da bu PLC&apos;nin bir aygıtı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="66"/>
        <source>byte address ({0} bytes)</source>
        <translation>bayt adresi ({0} bayt)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="68"/>
        <source>byte address</source>
        <translation>bayt adresi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="70"/>
        <source>constant or byte address</source>
        <translation>sabit veya bayt adresi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="72"/>
        <source>up to 4 binary digits, e.g. 1111</source>
        <translation>en çok 4 ikili hane, örneğin 1111</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="52"/>
        <location filename="../ladderworks/gui/function_dialog.py" line="74"/>
        <source>P{0} to P{1}</source>
        <translation>P{0} ile P{1} arası</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="49"/>
        <source>empty, P (on the rising edge), D (32-bit) or DP</source>
        <translation>boş, P (yükselen kenarda), D (32 bit) ya da DP</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="77"/>
        <source>L{0} to L{1}</source>
        <translation>L{0} ile L{1} arası</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="80"/>
        <source>constant or address, kept as written</source>
        <translation>sabit veya adres, yazıldığı gibi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="82"/>
        <source>values separated by spaces</source>
        <translation>boşlukla ayrılmış değerler</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="191"/>
        <source>{0} — {1}: fill in the parameters</source>
        <translation>{0} — {1}: parametreleri girin</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="194"/>
        <source>This instruction has no parameters.</source>
        <translation>Bu komutun parametresi yok.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="196"/>
        <source>Comment (shown with the box, written after // in the file):</source>
        <translation>Yorum (kutuyla gösterilir, dosyada // ardından yazılır):</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="199"/>
        <source>Parameter</source>
        <translation>Parametre</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="200"/>
        <source>Value</source>
        <translation>Değer</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="201"/>
        <source>Allowed</source>
        <translation>İzin verilen</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/function_dialog.py" line="235"/>
        <source>The parameters are not valid</source>
        <translation>Parametreler geçersiz</translation>
    </message>
</context>
<context>
    <name>InstructionHelp</name>
    <message>
        <location filename="../ladderworks/gui/help_browser.py" line="101"/>
        <source>Contacts, coils and blocks</source>
        <translation>Kontaklar, bobinler ve bloklar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/help_browser.py" line="206"/>
        <source>No reference entry for this instruction.</source>
        <translation>Bu komut için başvuru kaydı yok.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/help_browser.py" line="218"/>
        <source>Instruction reference</source>
        <translation>Komut başvurusu</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/help_browser.py" line="219"/>
        <source>Search, e.g. TMR</source>
        <translation>Ara, örn. TMR</translation>
    </message>
</context>
<context>
    <name>LadderEditor</name>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="146"/>
        <source>NOT</source>
        <translation>DEĞİL</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="354"/>
        <source>The comment tool works on an empty row only</source>
        <translation>YORUM takımı yalnız boş bir satırda kullanılabilir</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="46"/>
        <source>Delete</source>
        <translation>Sil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="155"/>
        <source>Insert row</source>
        <translation>Satır gir</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="183"/>
        <source>Place contact</source>
        <translation>Kontak koy</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="297"/>
        <source>This instruction is not placed from the palette in this program</source>
        <translation>Bu komut bu programda paletten yerleştirilmez</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="335"/>
        <source>Label {0}</source>
        <translation>Etiket {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="400"/>
        <source>Output pins</source>
        <translation>Çıkış uçları</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="47"/>
        <source>Place coil</source>
        <translation>Çıkış koy</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="194"/>
        <source>Select a contact or a coil for the OR tool</source>
        <translation>VEYA takımı için bir kontak veya çıkış seçin</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="198"/>
        <source>OR</source>
        <translation>VEYA</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="315"/>
        <source>Line: click the second point</source>
        <translation>ÇİZGİ: ikinci noktaya tıklayın</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="160"/>
        <source>Line</source>
        <translation>Çizgi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="57"/>
        <source>Place {0}</source>
        <translation>{0} koy</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="62"/>
        <source>Parameters of {0}</source>
        <translation>{0} parametreleri</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/inline_edit.py" line="58"/>
        <source>Operand, e.g. &quot;Start&quot;, %I0.1, #Run (// comment)</source>
        <translation>Operand, ör. &quot;Start&quot;, %I0.1, #Run (// açıklama)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/inline_edit.py" line="69"/>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="141"/>
        <source>Comment</source>
        <translation>Yorum</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="67"/>
        <source>Address {0}</source>
        <translation>Adres {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/inline_edit.py" line="59"/>
        <source>Address or symbol, e.g. X2.1 (// comment)</source>
        <translation>Adres veya sembol, örn. X2.1 (// yorum)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="427"/>
        <source>Cut</source>
        <translation>Kes</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="439"/>
        <source>Paste</source>
        <translation>Yapıştır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/ladder_edits.py" line="452"/>
        <source>Delete network</source>
        <translation>Devreyi sil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/symbol_text.py" line="86"/>
        <source>N{0} row {1} col {2}</source>
        <translation>D{0} satır {1} sütun {2}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/symbol_text.py" line="104"/>
        <source>open circuit here: draw a wire or an element</source>
        <translation>devre burada açık: bir çizgi veya bir eleman çizin</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/network_item.py" line="75"/>
        <source>N{0}</source>
        <translation>D{0}</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="72"/>
        <source>&amp;Open...</source>
        <translation>&amp;Aç...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="76"/>
        <source>&amp;Save</source>
        <translation>&amp;Kaydet</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="78"/>
        <source>Save &amp;As...</source>
        <translation>&amp;Farklı kaydet...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="80"/>
        <source>&amp;Import .MOD...</source>
        <translation>.MOD &amp;içe aktar...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="82"/>
        <source>&amp;Export .MOD...</source>
        <translation>.MOD &amp;dışa aktar...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="90"/>
        <source>Clear the list</source>
        <translation>Listeyi temizle</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="86"/>
        <source>Program &amp;properties...</source>
        <translation>Program &amp;özellikleri...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="70"/>
        <source>&amp;New...</source>
        <translation>&amp;Yeni...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="74"/>
        <source>Open &amp;folder...</source>
        <translation>&amp;Klasör aç...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="84"/>
        <source>Import s&amp;ymbols...</source>
        <translation>S&amp;embolleri içe aktar...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="88"/>
        <source>&amp;Quit</source>
        <translation>Çı&amp;kış</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="92"/>
        <location filename="../ladderworks/gui/undo_texts.py" line="13"/>
        <source>&amp;Undo</source>
        <translation>&amp;Geri al</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="95"/>
        <location filename="../ladderworks/gui/undo_texts.py" line="14"/>
        <source>&amp;Redo</source>
        <translation>&amp;Yinele</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="98"/>
        <source>Cu&amp;t</source>
        <translation>&amp;Kes</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="100"/>
        <source>&amp;Copy</source>
        <translation>K&amp;opyala</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="102"/>
        <source>&amp;Paste</source>
        <translation>&amp;Yapıştır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="105"/>
        <source>&amp;Delete</source>
        <translation>&amp;Sil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="108"/>
        <source>&amp;Edit element</source>
        <translation>Elemanı &amp;düzenle</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="110"/>
        <source>NOT (invert)</source>
        <translation>DEĞİL (ters çevir)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="113"/>
        <source>OR (add parallel)</source>
        <translation>VEYA (paralel ekle)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="115"/>
        <source>Output pins (FO)…</source>
        <translation>Çıkış uçları (FO)…</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="118"/>
        <source>Insert row before</source>
        <translation>Önceye satır gir</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="121"/>
        <source>Insert row after</source>
        <translation>Sonraya satır gir</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="124"/>
        <source>Delete network</source>
        <translation>Devreyi sil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="126"/>
        <source>&amp;Find...</source>
        <translation>&amp;Bul...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="128"/>
        <source>R&amp;eplace...</source>
        <translation>&amp;Değiştir...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="130"/>
        <source>Find &amp;next</source>
        <translation>&amp;Sonrakini bul</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="132"/>
        <source>Find pre&amp;vious</source>
        <translation>&amp;Öncekini bul</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="134"/>
        <source>Zoom &amp;in</source>
        <translation>&amp;Yakınlaştır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="137"/>
        <source>Zoom &amp;out</source>
        <translation>&amp;Uzaklaştır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="140"/>
        <source>&amp;Normal size</source>
        <translation>&amp;Normal boyut</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="142"/>
        <source>Fit &amp;width</source>
        <translation>&amp;Genişliğe sığdır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="145"/>
        <source>Show as &amp;ladder</source>
        <translation>&amp;Merdiven diyagramı olarak göster</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="147"/>
        <source>Show as &amp;text</source>
        <translation>&amp;Metin olarak göster</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="149"/>
        <source>C&amp;heck</source>
        <translation>&amp;Kontrol et</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="151"/>
        <source>&amp;Compile</source>
        <translation>&amp;Derle</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="159"/>
        <source>&amp;Instruction reference</source>
        <translation>&amp;Komut başvurusu</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="161"/>
        <source>&amp;About LadderWorks</source>
        <translation>LadderWorks &amp;hakkında</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="55"/>
        <source>&amp;File</source>
        <translation>&amp;Dosya</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="56"/>
        <source>Recent files</source>
        <translation>Son dosyalar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="58"/>
        <source>&amp;Edit</source>
        <translation>Dü&amp;zen</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="59"/>
        <source>&amp;View</source>
        <translation>&amp;Görünüm</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="60"/>
        <source>&amp;PLC</source>
        <translation>&amp;PLC</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="61"/>
        <source>&amp;Tools</source>
        <translation>&amp;Araçlar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="62"/>
        <source>&amp;Language</source>
        <translation>D&amp;il</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="63"/>
        <source>&amp;Help</source>
        <translation>&amp;Yardım</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/actions_table.py" line="66"/>
        <source>Main toolbar</source>
        <translation>Ana araç çubuğu</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="209"/>
        <source>Zoom</source>
        <translation>Yakınlaştırma</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="443"/>
        <source>Compile finished: {0} bytes (not loaded: the PLC runs the previous program)</source>
        <translation>Derleme bitti: {0} bayt (yüklenmedi: PLC önceki programı çalıştırıyor)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="455"/>
        <source>Compile finished, but the PLC refused the program</source>
        <translation>Derleme bitti, ancak PLC programı kabul etmedi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="462"/>
        <source>Compile finished: {0} bytes, loaded into the PLC</source>
        <translation>Derleme bitti: {0} bayt, PLC&apos;ye yüklendi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="540"/>
        <location filename="../ladderworks/gui/main_window.py" line="284"/>
        <location filename="../ladderworks/gui/main_window.py" line="457"/>
        <source>Untitled</source>
        <translation>Adsız</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="136"/>
        <source>Unsaved changes</source>
        <translation>Kaydedilmemiş değişiklikler</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="129"/>
        <source>Ladder programs</source>
        <translation>Ladder programları</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="130"/>
        <source>Mnemonic programs</source>
        <translation>Mnemonik programlar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="131"/>
        <source>LADDER-III exports</source>
        <translation>LADDER-III dışa aktarımları</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="132"/>
        <source>Delta DVP instruction lists</source>
        <translation>Delta DVP komut listeleri</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="134"/>
        <source>WPLSoft projects</source>
        <translation>WPLSoft projeleri</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="135"/>
        <source>Fatek WinProladder listings</source>
        <translation>Fatek WinProladder listeleri</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="137"/>
        <source>Fatek WinProladder projects</source>
        <translation>Fatek WinProladder projeleri</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="138"/>
        <source>Siemens S7-1200 SIMATIC SD blocks</source>
        <translation>Siemens S7-1200 SIMATIC SD blokları</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_dialogs.py" line="139"/>
        <source>Siemens S7-1200 SimaticML exports</source>
        <translation>Siemens S7-1200 SimaticML dışa aktarımları</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="126"/>
        <source>{0} was changed by another program</source>
        <translation>{0} başka bir program tarafından değiştirildi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="137"/>
        <source>The program has unsaved changes. Save them?</source>
        <translation>Programda kaydedilmemiş değişiklikler var. Kaydedilsin mi?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="183"/>
        <source>PLC family</source>
        <translation>PLC ailesi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="201"/>
        <location filename="../ladderworks/gui/file_actions.py" line="219"/>
        <source>Open</source>
        <translation>Aç</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="202"/>
        <location filename="../ladderworks/gui/file_actions.py" line="220"/>
        <location filename="../ladderworks/gui/file_actions.py" line="556"/>
        <location filename="../ladderworks/gui/symbol_import.py" line="58"/>
        <source>Cannot read {0}: {1}</source>
        <translation>{0} okunamıyor: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="207"/>
        <source>PMC parameters</source>
        <translation>PMC parametreleri</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="207"/>
        <source>{0}: {1} lines not understood (kept as they are); line {2}: {3}</source>
        <translation>{0}: {1} satır anlaşılamadı (olduğu gibi saklandı); satır {2}: {3}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="252"/>
        <source>The file has errors: it is shown as text</source>
        <translation>Dosyada hatalar var: metin olarak gösteriliyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="260"/>
        <source>Open program</source>
        <translation>Program aç</translation>
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
        <translation>Kaydet</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="334"/>
        <source>{0} did not parse and is not overwritten. Fix the errors and use Show as ladder, or save under another name.</source>
        <translation>{0} okunamadığı için üzerine yazılmaz. Hataları düzeltip Merdiven diyagramı olarak göster&apos;i kullanın veya başka bir adla kaydedin.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="340"/>
        <source>{0} is a WinProladder project (.pdw): LadderWorks reads it but does not write it, since what it does not decode would be lost. Save the program as a WinProladder listing (.lst) instead.</source>
        <translation>{0} bir WinProladder projesi (.pdw): LadderWorks onu okur ama yazmaz, çünkü çözemediği kısımlar kaybolurdu. Programı bunun yerine WinProladder listesi (.lst) olarak kaydedin.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="422"/>
        <location filename="../ladderworks/gui/file_actions.py" line="495"/>
        <location filename="../ladderworks/gui/folder_program.py" line="108"/>
        <source>{0} is read-only and is not replaced.</source>
        <translation>{0} salt okunurdur ve değiştirilmez.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="427"/>
        <location filename="../ladderworks/gui/file_actions.py" line="500"/>
        <location filename="../ladderworks/gui/folder_program.py" line="112"/>
        <source>Cannot write {0}: {1}</source>
        <translation>{0} yazılamıyor: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="437"/>
        <source>Fatek WinProladder listings (*.lst *.LST);;All files (*)</source>
        <translation>Fatek WinProladder listeleri (*.lst *.LST);;Tüm dosyalar (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="555"/>
        <source>Recover unsaved work</source>
        <translation>Kaydedilmemiş çalışmayı kurtar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="572"/>
        <source>Recovered unsaved work from {0}</source>
        <translation>{0} tarihli kaydedilmemiş çalışma kurtarıldı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="404"/>
        <source>Saved {0}; networks with errors are kept as drawings (see the error list)</source>
        <translation>{0} kaydedildi; hatalı devreler çizildiği gibi saklandı (hata listesine bakın)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="409"/>
        <source>Saved {0}</source>
        <translation>{0} kaydedildi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="436"/>
        <location filename="../ladderworks/gui/file_actions.py" line="441"/>
        <location filename="../ladderworks/gui/file_actions.py" line="447"/>
        <source>Save program</source>
        <translation>Programı kaydet</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="442"/>
        <source>Delta DVP instruction lists (*.il *.IL *.txt *.TXT);;All files (*)</source>
        <translation>Delta DVP komut listeleri (*.il *.IL *.txt *.TXT);;Tüm dosyalar (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="455"/>
        <source>Import .MOD</source>
        <translation>.MOD içe aktar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="456"/>
        <source>Mnemonic programs (*.MOD *.mod);;All files (*)</source>
        <translation>Mnemonik programlar (*.MOD *.mod);;Tüm dosyalar (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="478"/>
        <location filename="../ladderworks/gui/file_actions.py" line="495"/>
        <location filename="../ladderworks/gui/file_actions.py" line="499"/>
        <source>Export .MOD</source>
        <translation>.MOD dışa aktar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="479"/>
        <source>Mnemonic programs (*.MOD);;All files (*)</source>
        <translation>Mnemonik programlar (*.MOD);;Tüm dosyalar (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/file_actions.py" line="503"/>
        <source>Exported {0}</source>
        <translation>{0} dışa aktarıldı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="413"/>
        <source>Check: {0} error(s)</source>
        <translation>Kontrol: {0} hata</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="429"/>
        <source>Compile failed: {0} error(s)</source>
        <translation>Derleme başarısız: {0} hata</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="449"/>
        <source>Compile finished: {0} bytes (not loaded: the PLC keeps the program it has)</source>
        <translation>Derleme bitti: {0} bayt (yüklenmedi: PLC mevcut programını tutuyor)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="499"/>
        <source>Address {0} set</source>
        <translation>{0} adresi verildi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="502"/>
        <source>{0} copied (select a contact or coil to set its address)</source>
        <translation>{0} kopyalandı (adresini vermek için bir kontak veya bobin seçin)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="535"/>
        <source>About LadderWorks</source>
        <translation>LadderWorks hakkında</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/main_window.py" line="536"/>
        <source>LadderWorks: ladder (FANUC PMC style) programming for CNC machines.</source>
        <translation>LadderWorks: CNC tezgâhları için ladder (FANUC PMC tarzı) programlama.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/undo_texts.py" line="15"/>
        <source>&amp;Undo {0}</source>
        <translation>&amp;Geri al: {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/undo_texts.py" line="16"/>
        <source>&amp;Redo {0}</source>
        <translation>&amp;Yinele: {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/symbol_import.py" line="44"/>
        <location filename="../ladderworks/gui/symbol_import.py" line="54"/>
        <source>Import symbols</source>
        <translation>Sembolleri içe aktar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/symbol_import.py" line="45"/>
        <source>WinProladder comment exports (*.txt);;All files (*)</source>
        <translation>WinProladder yorum dışa aktarımları (*.txt);;Tüm dosyalar (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/symbol_import.py" line="74"/>
        <source>{0} symbols imported from {1}</source>
        <translation>{1} dosyasından {0} sembol içe aktarıldı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="47"/>
        <source>All files (*)</source>
        <translation>Tüm dosyalar (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="50"/>
        <source>Delta DVP instruction lists (*.txt *.TXT)</source>
        <translation>Delta DVP komut listeleri (*.txt *.TXT)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="53"/>
        <source>Siemens S7-1200 SIMATIC SD blocks (*.s7dcl)</source>
        <translation>Siemens S7-1200 SIMATIC SD blokları (*.s7dcl)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="54"/>
        <source>Siemens S7-1200 SimaticML exports (*.xml)</source>
        <translation>Siemens S7-1200 SimaticML dışa aktarımları (*.xml)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="57"/>
        <source>Fatek WinProladder listings (*.lst *.LST)</source>
        <translation>Fatek WinProladder listeleri (*.lst *.LST)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="59"/>
        <source>Ladder programs (*.LAD *.lad)</source>
        <translation>Ladder programları (*.LAD *.lad)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="66"/>
        <source>The program has errors: fix them first (see the error list)</source>
        <translation>Programda hatalar var: önce onları düzeltin (hata listesine bakın)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="70"/>
        <source>The program cannot become a {0} program: {1}</source>
        <translation>Program bir {0} programı olamaz: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/folder_program.py" line="71"/>
        <source>Open a folder of exported blocks</source>
        <translation>Dışa aktarılmış blokların klasörünü aç</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/folder_program.py" line="81"/>
        <source>{0}: no changes to save</source>
        <translation>{0}: kaydedilecek değişiklik yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/folder_program.py" line="87"/>
        <source>{0} is a folder of exported blocks: save the changed program under a file name</source>
        <translation>{0} dışa aktarılmış blokların klasörü: değişen programı bir dosya adıyla kaydedin</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/folder_program.py" line="115"/>
        <source>Saved {0} in the folder {1} (its other files are unchanged)</source>
        <translation>{0}, {1} klasörüne kaydedildi (klasörün öteki dosyaları değişmedi)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/save_refusal.py" line="41"/>
        <source>{0} is not written: {1}</source>
        <translation>{0} yazılmadı: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/save_refusal.py" line="46"/>
        <source>Not saved: {0}</source>
        <translation>Kaydedilmedi: {0}</translation>
    </message>
</context>
<context>
    <name>ModbusDock</name>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="135"/>
        <source>Modbus server</source>
        <translation>Modbus sunucusu</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="136"/>
        <source>&amp;Address (host:port):</source>
        <translation>&amp;Adres (sunucu:port):</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="215"/>
        <source>&amp;Map file (CSV):</source>
        <translation>&amp;Harita dosyası (CSV):</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="137"/>
        <location filename="../ladderworks/gui/docks/modbus.py" line="250"/>
        <source>the {0} map</source>
        <translation>{0} haritası</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="139"/>
        <source>Choose…</source>
        <translation>Seç…</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="140"/>
        <source>Dialect&apos;s map</source>
        <translation>PLC ailesinin haritası</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="141"/>
        <source>Serve the program&apos;s dialect&apos;s own map (docs/modbus.md)</source>
        <translation>Programın PLC ailesinin kendi haritasını sun (docs/modbus.md)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="143"/>
        <source>&amp;Holding registers:</source>
        <translation>&amp;Tutma yazmaçları:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="145"/>
        <source>Clients connected:</source>
        <translation>Bağlı istemciler:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="146"/>
        <source>Requests a second:</source>
        <translation>Saniyedeki istek:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="162"/>
        <source>Type the address as host:port, e.g. {0}.</source>
        <translation>Adresi sunucu:port olarak yazın, ör. {0}.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="176"/>
        <source>Cannot listen on {0}: {1}</source>
        <translation>{0} dinlenemiyor: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="190"/>
        <source>Modbus map file</source>
        <translation>Modbus harita dosyası</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="191"/>
        <source>Modbus maps (*.csv);;All files (*)</source>
        <translation>Modbus haritaları (*.csv);;Tüm dosyalar (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="207"/>
        <source>Bit memory (%MW)</source>
        <translation>Bit belleği (%MW)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="209"/>
        <source>Data block {0}</source>
        <translation>Veri bloğu {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="214"/>
        <source>&amp;Map file (CSV) or DB:</source>
        <translation>&amp;Harita dosyası (CSV) ya da DB:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="227"/>
        <source>Cannot read the map {0}: {1}</source>
        <translation>{0} haritası okunamıyor: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="230"/>
        <source>line {0}: {1}</source>
        <translation>satır {0}: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="233"/>
        <source>The map {0} is not served:</source>
        <translation>{0} haritası sunulmuyor:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="246"/>
        <source>the {0} map, holding registers in the DB {1}</source>
        <translation>{0} haritası, tutma yazmaçları {1} veri bloğunda</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="249"/>
        <source>the file {0}</source>
        <translation>{0} dosyası</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="272"/>
        <source>Stop server</source>
        <translation>Sunucuyu durdur</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="273"/>
        <source>Start server</source>
        <translation>Sunucuyu başlat</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="277"/>
        <source>Map served:</source>
        <translation>Sunulan harita:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="278"/>
        <source>Map to serve:</source>
        <translation>Sunulacak harita:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="282"/>
        <source>Listening on {0}:{1} (Modbus/TCP, any unit id), map: {2}.</source>
        <translation>{0}:{1} dinleniyor (Modbus/TCP, her birim no), harita: {2}.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="286"/>
        <source>Other computers on the network can read and write this PLC.</source>
        <translation>Ağdaki başka bilgisayarlar bu PLC&apos;yi okuyup yazabilir.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/modbus.py" line="291"/>
        <source>Stopped. An HMI on this computer connects to {0} once started.</source>
        <translation>Durduruldu. Başlatıldığında bu bilgisayardaki bir HMI {0} adresine bağlanır.</translation>
    </message>
</context>
<context>
    <name>NameDisplayMenu</name>
    <message>
        <location filename="../ladderworks/gui/editor/name_menu.py" line="23"/>
        <source>&amp;Address only</source>
        <translation>Yalnız &amp;adres</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/name_menu.py" line="25"/>
        <source>Address and &amp;symbol</source>
        <translation>Adres ve &amp;sembol</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/name_menu.py" line="26"/>
        <source>Address, symbol and &amp;comment</source>
        <translation>Adres, sembol ve &amp;yorum</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/name_menu.py" line="69"/>
        <source>Element &amp;names</source>
        <translation>Eleman &amp;adları</translation>
    </message>
</context>
<context>
    <name>NewProgram</name>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="82"/>
        <source>New program</source>
        <translation>Yeni program</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="89"/>
        <source>A family&apos;s models differ in their ranges; the Delta DVP series (ES2, EX2, SS2, SA2, SX2, SE) and the Fatek FBs series share one device map here (docs/dialects.md).</source>
        <translation>Bir ailenin modelleri aralıklarında ayrılır; Delta DVP serisi (ES2, EX2, SS2, SA2, SX2, SE) ve Fatek FBs serisi burada tek bir aygıt haritasını paylaşır (docs/dialects.md).</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="97"/>
        <source>The PLC the program is written for: its instructions, its devices (X0, T0, D10 or X2.1, R100) and its file form.</source>
        <translation>Programın yazıldığı PLC: komutları, aygıtları (X0, T0, D10 ya da X2.1, R100) ve dosya biçimi.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/new_program.py" line="102"/>
        <source>PLC family</source>
        <translation>PLC ailesi</translation>
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
        <translation>%{0}</translation>
    </message>
</context>
<context>
    <name>OperandDialog</name>
    <message>
        <location filename="../ladderworks/gui/operand_dialog.py" line="17"/>
        <source>Operands of {0}</source>
        <translation>{0} operandları</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/operand_dialog.py" line="20"/>
        <source>As TIA Portal writes them: &quot;Start&quot;, #Timer, %MW2, T#10s, 5</source>
        <translation>TIA Portal&apos;ın yazdığı gibi: &quot;Start&quot;, #Timer, %MW2, T#10s, 5</translation>
    </message>
</context>
<context>
    <name>OsError</name>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="16"/>
        <source>it does not exist</source>
        <translation>böyle bir dosya veya klasör yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="17"/>
        <location filename="../ladderworks/gui/os_errors.py" line="18"/>
        <source>permission denied</source>
        <translation>erişim izni yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="19"/>
        <source>the disk is read-only</source>
        <translation>disk salt okunur</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="20"/>
        <source>the disk is full</source>
        <translation>disk dolu</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="21"/>
        <source>the disk quota is used up</source>
        <translation>disk kotası doldu</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="22"/>
        <source>it is a folder</source>
        <translation>bu bir klasör</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="23"/>
        <source>a part of the path is not a folder</source>
        <translation>yolun bir parçası klasör değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="24"/>
        <source>it already exists</source>
        <translation>zaten var</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="25"/>
        <source>the name is too long</source>
        <translation>ad çok uzun</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="26"/>
        <location filename="../ladderworks/gui/os_errors.py" line="27"/>
        <source>it is in use</source>
        <translation>kullanımda</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="28"/>
        <source>the disk reported an input/output error</source>
        <translation>disk bir giriş/çıkış hatası bildirdi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="29"/>
        <source>too many symbolic links</source>
        <translation>çok fazla sembolik bağlantı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="30"/>
        <source>too many files are open</source>
        <translation>çok fazla dosya açık</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/os_errors.py" line="36"/>
        <source>system error: {0}</source>
        <translation>sistem hatası: {0}</translation>
    </message>
</context>
<context>
    <name>OutputPinsDialog</name>
    <message>
        <location filename="../ladderworks/gui/output_pins_dialog.py" line="38"/>
        <source>Output pins</source>
        <translation>Çıkış uçları</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/output_pins_dialog.py" line="39"/>
        <source>The outputs {0} shows on its right side (FO0 is its first output, always shown); draw each pin&apos;s coils on its row:</source>
        <translation>{0} kutusunun sağ yanında gösterdiği çıkışlar (FO0 ilk çıkışıdır, hep gösterilir); her ucun bobinlerini kendi satırına çizin:</translation>
    </message>
</context>
<context>
    <name>Param</name>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="50"/>
        <source>Timer number</source>
        <translation>Zamanlayıcı numarası</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="51"/>
        <source>Preset</source>
        <translation>Ayar değeri</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="52"/>
        <source>Accuracy</source>
        <translation>Hassasiyet</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="53"/>
        <source>Timer/counter register</source>
        <translation>Zamanlayıcı/sayıcı kaydı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="54"/>
        <source>Code signal</source>
        <translation>Kod sinyali</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="55"/>
        <source>Decode specification</source>
        <translation>Kod çözme tanımı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="56"/>
        <source>Format</source>
        <translation>Format</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="57"/>
        <source>First number</source>
        <translation>İlk sayı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="58"/>
        <source>Result</source>
        <translation>Sonuç</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="59"/>
        <source>Counter number</source>
        <translation>Sayıcı numarası</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="60"/>
        <source>Number of positions</source>
        <translation>Pozisyon sayısı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="61"/>
        <source>Current position</source>
        <translation>Mevcut pozisyon</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="62"/>
        <source>Target position</source>
        <translation>Hedef pozisyon</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="63"/>
        <source>Table size</source>
        <translation>Tablo boyu</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="64"/>
        <source>Index</source>
        <translation>İndeks</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="65"/>
        <source>Output</source>
        <translation>Çıkış</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="66"/>
        <source>Table values</source>
        <translation>Tablo değerleri</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="67"/>
        <source>Input</source>
        <translation>Giriş</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="68"/>
        <source>High 4-bit mask</source>
        <translation>Üst 4 bit maskesi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="69"/>
        <source>Low 4-bit mask</source>
        <translation>Alt 4 bit maskesi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="70"/>
        <source>OR data</source>
        <translation>VEYA verisi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="71"/>
        <source>Data</source>
        <translation>Veri</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="72"/>
        <source>Number of coils</source>
        <translation>Çıkış sayısı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="73"/>
        <source>Input format (0 constant, 1 address)</source>
        <translation>Giriş formatı (0 sabit, 1 adres)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="74"/>
        <source>Compared data</source>
        <translation>Karşılaştırılan veri</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="75"/>
        <source>Searched data</source>
        <translation>Aranan veri</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="76"/>
        <source>Operand format (0 constant, 1 address)</source>
        <translation>Operand formatı (0 sabit, 1 adres)</translation>
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
        <translation>Sabit</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="81"/>
        <source>Edge number</source>
        <translation>Kenar numarası</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="82"/>
        <source>Number of bytes</source>
        <translation>Bayt sayısı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="83"/>
        <source>Operand</source>
        <translation>Operand</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="84"/>
        <source>Limit 1</source>
        <translation>Sınır 1</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="85"/>
        <source>Limit 2</source>
        <translation>Sınır 2</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="86"/>
        <source>Subprogram</source>
        <translation>Alt program</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="87"/>
        <source>Label</source>
        <translation>Etiket</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="88"/>
        <source>DI/DO group</source>
        <translation>DI/DO grubu</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="89"/>
        <source>Control data</source>
        <translation>Kontrol verisi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="90"/>
        <source>Number of messages</source>
        <translation>Mesaj sayısı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="92"/>
        <source>Form (P, D)</source>
        <translation>Biçim (P, D)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="93"/>
        <source>Nesting level (N0-N7)</source>
        <translation>İç içelik düzeyi (N0-N7)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="94"/>
        <source>Device</source>
        <translation>Cihaz</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="95"/>
        <source>Timer or counter (T5, C3)</source>
        <translation>Zamanlayıcı ya da sayıcı (T5, C3)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="96"/>
        <source>Source 1</source>
        <translation>Kaynak 1</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="97"/>
        <source>Source 2</source>
        <translation>Kaynak 2</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="98"/>
        <source>Source</source>
        <translation>Kaynak</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="99"/>
        <source>Lower limit</source>
        <translation>Alt sınır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="100"/>
        <source>Upper limit</source>
        <translation>Üst sınır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/translation.py" line="103"/>
        <source>Parameter {0}</source>
        <translation>Parametre {0}</translation>
    </message>
</context>
<context>
    <name>PlcControl</name>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="162"/>
        <source>PLC CONTROL SCREEN</source>
        <translation>PLC KONTROL EKRANI</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="164"/>
        <source>Open .MOD…</source>
        <translation>.MOD aç…</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="165"/>
        <source>Show the console&apos;s program as text</source>
        <translation>Konsolun programını metin olarak göster</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="167"/>
        <source>Compile</source>
        <translation>Derle</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="168"/>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="355"/>
        <source>START</source>
        <translation>BAŞLAT</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="169"/>
        <source>STOP</source>
        <translation>DURDUR</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="175"/>
        <source>Shows the console&apos;s program here as mnemonic text, to read or change before Compile on this screen. F9 (PLC › Compile) loads the console&apos;s program into the PLC directly.</source>
        <translation>Konsolun programını burada mnemonic metin olarak gösterir; bu ekranda Derle&apos;den önce okumak veya değiştirmek için. F9 (PLC › Derle) konsolun programını doğrudan PLC&apos;ye yükler.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="206"/>
        <source>Program loaded from the console</source>
        <translation>Program konsoldan yüklendi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="226"/>
        <source>In the PLC: {0}</source>
        <translation>PLC&apos;deki program: {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="236"/>
        <source>Cannot read {0}: {1}</source>
        <translation>{0} okunamıyor: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="241"/>
        <source>Opened {0}</source>
        <translation>{0} açıldı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="247"/>
        <source>Open mnemonic program</source>
        <translation>Mnemonik program aç</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="248"/>
        <source>Mnemonic programs (*.MOD *.mod *.LAD *.lad);;All files (*)</source>
        <translation>Mnemonik programlar (*.MOD *.mod *.LAD *.lad);;Tüm dosyalar (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="256"/>
        <source>The console&apos;s program cannot be coded: see the error list</source>
        <translation>Konsoldaki program kodlanamıyor: hata listesine bakın</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="260"/>
        <source>Program taken from the console</source>
        <translation>Program konsoldan alındı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="295"/>
        <source>Compile failed: {0} error(s). {1}</source>
        <translation>Derleme başarısız: {0} hata. {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="307"/>
        <source>Converting…</source>
        <translation>Çevriliyor…</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="333"/>
        <source>Not loaded: the PLC keeps the program it has</source>
        <translation>Yüklenmedi: PLC mevcut programını tutuyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="338"/>
        <source>the program on this screen</source>
        <translation>bu ekrandaki program</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="342"/>
        <source>Compile finished — {0} networks, {1} bytes</source>
        <translation>Derleme bitti — {0} devre, {1} bayt</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="345"/>
        <source>({0} warning(s))</source>
        <translation>({0} uyarı)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="356"/>
        <source>{0} signal(s) are forced or element(s) passive. Start the PLC with them?</source>
        <translation>{0} sinyal zorlanmış veya eleman pasif. PLC bunlarla başlatılsın mı?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="363"/>
        <source>Compile a program first</source>
        <translation>Önce bir program derleyin</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="387"/>
        <source>scans in a process of their own</source>
        <translation>taramalar kendi süreçlerinde</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="389"/>
        <source>scans in the IDE&apos;s process</source>
        <translation>taramalar IDE&apos;nin sürecinde</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="391"/>
        <source>scan process: {0}</source>
        <translation>tarama süreci: {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="398"/>
        <source>native scan (machine code)</source>
        <translation>yerel tarama (makine kodu)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="400"/>
        <source>Python scan (native not possible: {0})</source>
        <translation>Python taraması (yerel olamadı: {0})</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="402"/>
        <source>Python scan</source>
        <translation>Python taraması</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="414"/>
        <source>{0} (line {1})</source>
        <translation>{0} (satır {1})</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="417"/>
        <source>… and {0} more</source>
        <translation>… ve {0} tane daha</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="419"/>
        <source>Not simulated, passed by in the scan ({0}): {1}</source>
        <translation>Benzetilmeyen, taramada atlanan komutlar ({0}): {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="422"/>
        <source>These instructions are kept, drawn and saved, but the simulator does not run them: a box passes its input on, a contact never conducts.</source>
        <translation>Bu komutlar korunur, çizilir ve kaydedilir, ama benzetici onları çalıştırmaz: bir kutu girişini aynen geçirir, bir kontak hiç iletmez.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="429"/>
        <source>NO PROGRAM</source>
        <translation>PROGRAM YOK</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="432"/>
        <source>RUNNING</source>
        <translation>ÇALIŞIYOR</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="435"/>
        <source>STOPPED</source>
        <translation>DURDU</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/plc_control.py" line="438"/>
        <source>scans {0} · scan time {1} / {2} / {3} ms (min/avg/max) · period {4} ms · overruns {5}</source>
        <translation>tarama {0} · tarama süresi {1} / {2} / {3} ms (en az/ort./en çok) · periyot {4} ms · aşım {5}</translation>
    </message>
</context>
<context>
    <name>PlcDiagnostic</name>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="299"/>
        <source>PLC DIAGNOSTIC</source>
        <translation>PLC TEŞHİS</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="300"/>
        <source>Address, e.g. R102.0</source>
        <translation>Adres, örneğin R102.0</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="301"/>
        <source>Find</source>
        <translation>Bul</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="302"/>
        <source>Where written</source>
        <translation>Nerede yazılıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="303"/>
        <source>Follow</source>
        <translation>Takip et</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="304"/>
        <source>Why?</source>
        <translation>Neden?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="305"/>
        <source>Go to the scan where the address last changed and mark the contacts that changed it</source>
        <translation>Adresin son değiştiği taramaya git ve onu değiştiren kontakları işaretle</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="308"/>
        <source>Back to live</source>
        <translation>Canlıya dön</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="309"/>
        <source>Zoom out (Ctrl+wheel)</source>
        <translation>Uzaklaştır (Ctrl+tekerlek)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="310"/>
        <source>Zoom in (Ctrl+wheel)</source>
        <translation>Yakınlaştır (Ctrl+tekerlek)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="312"/>
        <source>Keep the searched address in view while the PLC runs</source>
        <translation>PLC çalışırken aranan adresi ekranda tut</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="322"/>
        <source>{0} %</source>
        <translation>%{0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="393"/>
        <location filename="../ladderworks/gui/docks/online.py" line="167"/>
        <source>PAST — scan {0} at {1} ms (not live)</source>
        <translation>GEÇMİŞ — tarama {0}, {1} ms (canlı değil)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="399"/>
        <source>No program loaded</source>
        <translation>Yüklü program yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="401"/>
        <source>RUNNING — scan {0}</source>
        <translation>ÇALIŞIYOR — tarama {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="403"/>
        <source>STOPPED</source>
        <translation>DURDU</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="444"/>
        <source>&apos;{0}&apos; is not an address</source>
        <translation>&apos;{0}&apos; bir adres değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="488"/>
        <source>&apos;{0}&apos; is not in the program</source>
        <translation>&apos;{0}&apos; programda yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="498"/>
        <source>No coil writes {0}</source>
        <translation>{0} adresine yazan çıkış yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/diagnostic.py" line="508"/>
        <source>{0} of {1}: network {2}</source>
        <translation>{0} / {1}: devre {2}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/power_overlay.py" line="106"/>
        <source>PASSIVE</source>
        <translation>PASİF</translation>
    </message>
</context>
<context>
    <name>PlcOnline</name>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="65"/>
        <source>On-line mode</source>
        <translation>Çevrim içi mod</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="66"/>
        <source>Make passive (disable)</source>
        <translation>Pasif hale getir</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="67"/>
        <source>Make active again</source>
        <translation>Tekrar aktif yap</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="68"/>
        <source>Force to 1</source>
        <translation>1&apos;e zorla</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="69"/>
        <source>Force to 0</source>
        <translation>0&apos;a zorla</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="70"/>
        <source>Release the force</source>
        <translation>Zorlamayı bırak</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="89"/>
        <source>Off-line</source>
        <translation>Off-line</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="94"/>
        <source>On-line needs a compiled program in the PLC</source>
        <translation>Çevrim içi mod için PLC&apos;de derlenmiş bir program gerekir</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="100"/>
        <source>The drawing is not the program in the PLC: compile it in the PLC control screen first</source>
        <translation>Çizim PLC&apos;deki program değil: önce PLC kontrol ekranında derleyin</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="110"/>
        <location filename="../ladderworks/gui/docks/online.py" line="176"/>
        <source>On-line: the drawing shows the running PLC</source>
        <translation>Çevrim içi: çizim çalışan PLC&apos;yi gösteriyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="137"/>
        <source>Off-line: the drawing was changed; it is no longer the program the PLC runs</source>
        <translation>Off-line: çizim değişti; artık PLC&apos;nin çalıştırdığı program değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="146"/>
        <source>Off-line: another program is shown; it is not the program the PLC runs</source>
        <translation>Off-line: başka bir program gösteriliyor; PLC&apos;nin çalıştırdığı program değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="199"/>
        <source>Select a contact, coil or function first</source>
        <translation>Önce bir kontak, çıkış veya fonksiyon seçin</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="203"/>
        <source>This element has no op in the PLC program</source>
        <translation>Bu elemanın PLC programında karşılığı yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/online.py" line="226"/>
        <source>Select a contact or coil to force its signal</source>
        <translation>Sinyalini zorlamak için bir kontak veya çıkış seçin</translation>
    </message>
</context>
<context>
    <name>PlcState</name>
    <message>
        <location filename="../ladderworks/gui/plc_state.py" line="24"/>
        <source>RUN</source>
        <translation>ÇALIŞIYOR</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/plc_state.py" line="24"/>
        <source>STOP</source>
        <translation>DURDU</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/plc_state.py" line="25"/>
        <source>no program loaded</source>
        <translation>yüklü program yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/plc_state.py" line="27"/>
        <source>{0} forced</source>
        <translation>{0} zorlanmış</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/plc_state.py" line="56"/>
        <source>The simulated PLC: running (RUN) or stopped (STOP), and the program loaded into it (F9).</source>
        <translation>Benzetilen PLC: çalışıyor (ÇALIŞIYOR) veya durdu (DURDU), ve içine yüklenen program (F9).</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/plc_state.py" line="59"/>
        <source>Signals are forced: the PLC does not see the machine&apos;s values for them (PLC › Release the force).</source>
        <translation>Sinyaller zorlanmış: PLC bunlar için makinenin değerlerini görmüyor (PLC › Zorlamayı bırak).</translation>
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
        <translation>Tip</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="114"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="124"/>
        <source>Preset (ms)</source>
        <translation>Ayar değeri (ms)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="113"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="123"/>
        <source>Preset (ticks)</source>
        <translation>Ayar değeri (tık)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="115"/>
        <source>Precision</source>
        <translation>Hassasiyet</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="117"/>
        <source>Tick (ms)</source>
        <translation>Adım (ms)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="118"/>
        <source>Delay (ms)</source>
        <translation>Gecikme (ms)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="125"/>
        <source>Timer number (1-{0})</source>
        <translation>Zamanlayıcı numarası (1-{0})</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="119"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="192"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="197"/>
        <source>Preset</source>
        <translation>Ayar değeri</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="193"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="198"/>
        <source>Current value</source>
        <translation>Şimdiki değer</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="252"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="308"/>
        <source>Address</source>
        <translation>Adres</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="252"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="257"/>
        <source>Bytes</source>
        <translation>Bayt</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="116"/>
        <source>Device</source>
        <translation>Aygıt</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="118"/>
        <source>Contact</source>
        <translation>Kontak</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="121"/>
        <source>Base</source>
        <translation>Taban</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="117"/>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="124"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="253"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="258"/>
        <source>Value</source>
        <translation>Değer</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="124"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="253"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="309"/>
        <source>Hex</source>
        <translation>Onaltılık</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="129"/>
        <source>Devices ({0}0 or a range {0}0-{0}9)</source>
        <translation>Aygıtlar ({0}0 ya da bir aralık {0}0-{0}9)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="154"/>
        <source>ON</source>
        <translation>AÇIK</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="154"/>
        <source>OFF</source>
        <translation>KAPALI</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="160"/>
        <source>{0} ms</source>
        <translation>{0} ms</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="162"/>
        <source>{0}-bit up/down</source>
        <translation>{0} bit yukarı/aşağı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="163"/>
        <source>{0}-bit up</source>
        <translation>{0} bit yukarı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/device_specs.py" line="216"/>
        <source>{0} on: {1} ms a count</source>
        <translation>{0} açıkken: sayım başına {1} ms</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="308"/>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="313"/>
        <source>Bits 7..0</source>
        <translation>Bitler 7..0</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="197"/>
        <source>Counter number (1-20)</source>
        <translation>Sayıcı numarası (1-20)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="257"/>
        <source>Address (D)</source>
        <translation>Adres (D)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="313"/>
        <source>Address (K)</source>
        <translation>Adres (K)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_forms.py" line="41"/>
        <location filename="../ladderworks/gui/docks/tables.py" line="282"/>
        <source>INSERT</source>
        <translation>EKLE (INSERT)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_forms.py" line="130"/>
        <source>&amp;Add:</source>
        <translation>&amp;Ekle:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_forms.py" line="131"/>
        <source>devices, e.g. D500, T5, D0-D9</source>
        <translation>aygıtlar, örn. D500, T5, D0-D9</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_forms.py" line="132"/>
        <source>Add</source>
        <translation>Ekle</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_forms.py" line="133"/>
        <source>Any timer, counter or register of the PLC, used by the program or not; a value is typed in its cell as 100, K100 or H64</source>
        <translation>PLC&apos;nin herhangi bir zamanlayıcısı, sayıcısı veya yazmacı, programda kullanılsın ya da kullanılmasın; değer hücresine 100, K100 veya H64 olarak yazılır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/table_specs.py" line="179"/>
        <source>TMRB: the preset is fixed in the program</source>
        <translation>TMRB: ayar değeri programda sabittir</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="257"/>
        <source>&apos;{0}&apos; is not a device of these tables (use {1}); watch a bit in the bit display</source>
        <translation>&apos;{0}&apos; bu tabloların bir aygıtı değil ({1} kullanın); bir biti bit gösteriminde izleyin</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="285"/>
        <source>DELETE</source>
        <translation>SİL (DELETE)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="320"/>
        <source>PLC tables</source>
        <translation>PLC TABLOLARI</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="323"/>
        <source>A {0} program has no PMC parameter tables: its timer and counter presets are written in its instructions. Watch its T, C and D devices in the bit display and the time chart.</source>
        <translation>{0} programının PMC parametre tabloları yoktur: zamanlayıcı ve sayıcı ayar değerleri komutlarında yazılıdır. T, C ve D aygıtlarını bit gösteriminde ve zaman kartında izleyin.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="330"/>
        <source>Timers (TMR)</source>
        <translation>Zamanlayıcı (TMR)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="331"/>
        <source>Counters (CTR)</source>
        <translation>Sayıcı (CTR)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="332"/>
        <source>Data table (D)</source>
        <translation>Veri (D)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="333"/>
        <source>Keep relays (K)</source>
        <translation>Tutma rölesi (K)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="334"/>
        <source>Timers (T)</source>
        <translation>Zamanlayıcı (T)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="335"/>
        <source>Counters (C)</source>
        <translation>Sayıcı (C)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="336"/>
        <source>Registers ({0})</source>
        <translation>Yazmaçlar ({0})</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="347"/>
        <source>Presets up to {0} ms; timers 1-8 count in 48 ms ticks, 9-100 and TMRB in 8 ms</source>
        <translation>Ayar değeri en çok {0} ms; 1-8 zamanlayıcıları 48 ms, 9-100 ve TMRB 8 ms adımla sayar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/tables.py" line="350"/>
        <source>Presets in ticks (up to {0}); the precision code sets the tick: 0 default (48 ms for 1-8, else 8 ms), 1 = 1 ms, 2 = 10 ms, 3 = 100 ms, 4 = 1 s, 5 = 1 min</source>
        <translation>Ayar değerleri tık cinsinden (en çok {0}); hassasiyet kodu tıkı belirler: 0 varsayılan (1-8 için 48 ms, diğerleri 8 ms), 1 = 1 ms, 2 = 10 ms, 3 = 100 ms, 4 = 1 sn, 5 = 1 dk</translation>
    </message>
</context>
<context>
    <name>Print</name>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="54"/>
        <source>Untitled</source>
        <translation>Adsız</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="80"/>
        <source>Printing the ladder…</source>
        <translation>Ladder yazdırılıyor…</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="81"/>
        <source>Cancel</source>
        <translation>İptal</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="165"/>
        <source>Print preview</source>
        <translation>Baskı önizleme</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="183"/>
        <source>Export PDF</source>
        <translation>PDF olarak dışa aktar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="184"/>
        <source>PDF files (*.pdf)</source>
        <translation>PDF dosyaları (*.pdf)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="192"/>
        <source>&amp;Print...</source>
        <translation>&amp;Yazdır...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="193"/>
        <source>Print pre&amp;view...</source>
        <translation>Baskı ön&amp;izleme...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="194"/>
        <source>Export P&amp;DF...</source>
        <translation>P&amp;DF olarak dışa aktar...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="200"/>
        <source>Printing was cancelled or failed</source>
        <translation>Yazdırma iptal edildi veya başarısız oldu</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="202"/>
        <source>{0} pages written to {1}</source>
        <translation>{0} sayfa {1} dosyasına yazıldı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_actions.py" line="204"/>
        <source>{0} pages sent to the printer</source>
        <translation>{0} sayfa yazıcıya gönderildi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_pages.py" line="280"/>
        <source>Printed {0}</source>
        <translation>Yazdırıldı: {0}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_pages.py" line="282"/>
        <source>Page {0} / {1}</source>
        <translation>Sayfa {0} / {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_pages.py" line="309"/>
        <source>Cross reference</source>
        <translation>Çapraz referans</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_pages.py" line="312"/>
        <source>Address</source>
        <translation>Adres</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_pages.py" line="313"/>
        <source>Symbol</source>
        <translation>Sembol</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_pages.py" line="314"/>
        <source>Written in networks</source>
        <translation>Yazıldığı devreler</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/print_pages.py" line="315"/>
        <source>Read in networks</source>
        <translation>Okunduğu devreler</translation>
    </message>
</context>
<context>
    <name>ProgramProperties</name>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="53"/>
        <source>Machine-tool builder</source>
        <translation>Takım tezgâhı üreticisi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="54"/>
        <source>Machine-tool name</source>
        <translation>Takım tezgâhı adı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="55"/>
        <source>PMC &amp; NC type</source>
        <translation>PMC ve NC tipi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="56"/>
        <source>Program number</source>
        <translation>Program numarası</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="57"/>
        <source>Edition</source>
        <translation>Sürüm</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="58"/>
        <source>Drawing number</source>
        <translation>Çizim numarası</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="59"/>
        <source>Date</source>
        <translation>Tarih</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="60"/>
        <source>Designed by</source>
        <translation>Tasarlayan</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="61"/>
        <source>ROM written by</source>
        <translation>ROM&apos;a yazan</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="62"/>
        <source>Remarks</source>
        <translation>Notlar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="35"/>
        <source>LadderWorks (seed manual)</source>
        <translation>LadderWorks (temel kılavuz)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="36"/>
        <source>FANUC Series 30i-A PMC (memory-B)</source>
        <translation>FANUC Series 30i-A PMC (bellek-B)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="85"/>
        <source>yes</source>
        <translation>evet</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="85"/>
        <source>no</source>
        <translation>hayır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="88"/>
        <source>File</source>
        <translation>Dosya</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="89"/>
        <source>(not saved)</source>
        <translation>(kaydedilmedi)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="90"/>
        <location filename="../ladderworks/gui/program_properties.py" line="149"/>
        <location filename="../ladderworks/gui/program_properties.py" line="186"/>
        <source>PMC model</source>
        <translation>PMC modeli</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="91"/>
        <source>Encoding</source>
        <translation>Kodlama</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="92"/>
        <source>Byte order mark</source>
        <translation>Bayt sırası işareti (BOM)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="93"/>
        <source>Line ends</source>
        <translation>Satır sonları</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="94"/>
        <source>Framed in %@A … %@E</source>
        <translation>%@A … %@E çerçeveli</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="95"/>
        <source>Networks</source>
        <translation>Devreler</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="96"/>
        <source>Steps</source>
        <translation>Adımlar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="98"/>
        <source>Symbols (%@2)</source>
        <translation>Semboller (%@2)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="100"/>
        <source>Messages (%@4)</source>
        <translation>Mesajlar (%@4)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="180"/>
        <source>The PLC the program is written for: its address map and the ranges of its instructions. A model of another PLC family is taken when every instruction reads back the same in that family&apos;s text.</source>
        <translation>Programın yazıldığı PLC: adres haritası ve komutlarının aralıkları. Başka bir PLC ailesinin modeli, her komut o ailenin metninde aynı okunduğunda alınır.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="197"/>
        <source>Program properties</source>
        <translation>Program özellikleri</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="206"/>
        <source>General</source>
        <translation>Genel</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="207"/>
        <source>Property</source>
        <translation>Özellik</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="208"/>
        <location filename="../ladderworks/gui/program_properties.py" line="215"/>
        <source>Value</source>
        <translation>Değer</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="210"/>
        <source>Title (%@1)</source>
        <translation>Başlık (%@1)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="211"/>
        <location filename="../ladderworks/gui/program_properties.py" line="215"/>
        <source>Item</source>
        <translation>Öğe</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="211"/>
        <source>Meaning</source>
        <translation>Anlamı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="212"/>
        <source>Text</source>
        <translation>Metin</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="214"/>
        <source>System parameters (%@0)</source>
        <translation>Sistem parametreleri (%@0)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="217"/>
        <source>I/O modules (%@5)</source>
        <translation>G/Ç modülleri (%@5)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="218"/>
        <source>Address</source>
        <translation>Adres</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="218"/>
        <source>Group</source>
        <translation>Grup</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="219"/>
        <source>Base</source>
        <translation>Taban</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="219"/>
        <source>Slot</source>
        <translation>Yuva</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="220"/>
        <source>Module</source>
        <translation>Modül</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="223"/>
        <source>Sections</source>
        <translation>Bölümler</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="224"/>
        <source>Header</source>
        <translation>Başlık satırı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="224"/>
        <source>Lines</source>
        <translation>Satırlar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/program_properties.py" line="225"/>
        <source>First line</source>
        <translation>İlk satır</translation>
    </message>
</context>
<context>
    <name>QFileDialog</name>
    <message>
        <location filename="../ladderworks/gui/qt_strings.py" line="11"/>
        <source>&amp;Look in:</source>
        <translation>&amp;Konum:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/qt_strings.py" line="12"/>
        <source>Files of &amp;type:</source>
        <translation>Dosya &amp;türü:</translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <location filename="../ladderworks/gui/qt_strings.py" line="13"/>
        <source>Discard</source>
        <translation>Kaydetme</translation>
    </message>
</context>
<context>
    <name>QtLibraries</name>
    <message>
        <location filename="../ladderworks/gui/qt_libraries.py" line="71"/>
        <source>LadderWorks cannot start: Qt&apos;s X11 (xcb) platform needs system libraries that are missing: {0}.</source>
        <translation>LadderWorks başlatılamıyor: Qt&apos;nin X11 (xcb) platformunun gerektirdiği sistem kütüphaneleri eksik: {0}.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/qt_libraries.py" line="75"/>
        <source>On Debian or Ubuntu, install them with:</source>
        <translation>Debian veya Ubuntu&apos;da şu komutla kurun:</translation>
    </message>
</context>
<context>
    <name>Questions</name>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="37"/>
        <source>Cancel</source>
        <translation>İptal</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="41"/>
        <source>Save As...</source>
        <translation>Farklı Kaydet...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="46"/>
        <source>File changed on disk</source>
        <translation>Dosya diskte değişti</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="46"/>
        <source>{0} was changed by another program since you opened it. Reload it (your unsaved changes are lost), keep your version (overwrite the other change), or save yours under another name?</source>
        <translation>{0}, siz açtıktan sonra başka bir program tarafından değiştirildi. Yeniden yüklensin mi (kaydedilmemiş değişiklikleriniz kaybolur), sizin sürümünüz mü kalsın (öteki değişikliğin üzerine yazılır), yoksa sizinki başka bir adla mı kaydedilsin?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="51"/>
        <source>Reload</source>
        <translation>Yeniden yükle</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="52"/>
        <source>Keep mine</source>
        <translation>Benimki kalsın</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="58"/>
        <source>Read-only file</source>
        <translation>Salt okunur dosya</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="58"/>
        <source>{0} is read-only and is not replaced. Save the program under another name?</source>
        <translation>{0} salt okunurdur ve değiştirilmez. Program başka bir adla kaydedilsin mi?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="67"/>
        <source>Change not saved</source>
        <translation>Değişiklik kaydedilmedi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="67"/>
        <source>{0} is not overwritten: {1}. Save the program under another name?</source>
        <translation>{0} üzerine yazılmadı: {1}. Program başka bir adla kaydedilsin mi?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="75"/>
        <source>Character not in the file&apos;s encoding</source>
        <translation>Karakter dosyanın kodlamasında yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="75"/>
        <source>Line {0}, column {1}: the character &apos;{2}&apos; (U+{3:04X}) cannot be written in {4}, the encoding of {5}. Save the whole file as UTF-8 instead?</source>
        <translation>Satır {0}, sütun {1}: &apos;{2}&apos; (U+{3:04X}) karakteri {5} dosyasının kodlaması olan {4} ile yazılamaz. Dosyanın tamamı bunun yerine UTF-8 olarak kaydedilsin mi?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="80"/>
        <source>Save as UTF-8</source>
        <translation>UTF-8 olarak kaydet</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="85"/>
        <source>Recover unsaved work</source>
        <translation>Kaydedilmemiş çalışmayı kurtar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="85"/>
        <source>LadderWorks ended without saving {0}. A recovery copy from {1} was found. Restore it?</source>
        <translation>LadderWorks, {0} kaydedilmeden kapandı. {1} tarihli bir kurtarma kopyası bulundu. Geri yüklensin mi?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="89"/>
        <source>Restore</source>
        <translation>Geri yükle</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="90"/>
        <source>Discard</source>
        <translation>At</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="91"/>
        <source>Not now</source>
        <translation>Şimdi değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="96"/>
        <source>The PLC is running</source>
        <translation>PLC çalışıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="96"/>
        <source>The PLC is running. Load the new program now? It is loaded between two scans and the PLC runs on with it; forces stay.</source>
        <translation>PLC çalışıyor. Yeni program şimdi yüklensin mi? İki tarama arasında yüklenir ve PLC onunla çalışmaya devam eder; zorlamalar kalır.</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="100"/>
        <source>Reload now</source>
        <translation>Şimdi yeniden yükle</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="106"/>
        <source>Forced signals</source>
        <translation>Zorlanmış sinyaller</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="106"/>
        <source>{0} signal(s) are forced in the PLC for the program it has now. Another program is being loaded: keep these signals forced, or release them?</source>
        <translation>PLC&apos;de şu anki programı için {0} sinyal zorlanmış. Başka bir program yükleniyor: bu sinyaller zorlanmış kalsın mı, yoksa bırakılsın mı?</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="110"/>
        <source>Release the forces</source>
        <translation>Zorlamaları bırak</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/questions.py" line="111"/>
        <source>Keep them forced</source>
        <translation>Zorlanmış kalsın</translation>
    </message>
</context>
<context>
    <name>Recovery</name>
    <message>
        <location filename="../ladderworks/gui/recovery.py" line="182"/>
        <source>Cannot write the recovery copy in {0}: {1}</source>
        <translation>Kurtarma kopyası {0} içine yazılamadı: {1}</translation>
    </message>
</context>
<context>
    <name>ScanBackend</name>
    <message>
        <location filename="../ladderworks/gui/scan_backend.py" line="35"/>
        <source>Native scan (machine code)</source>
        <translation>Yerel tarama (makine kodu)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/scan_backend.py" line="36"/>
        <source>Compile the program loaded next (F9, Compile) to machine code: it scans many times faster. Where that cannot be done, the Python scan runs and the PLC control screen says why.</source>
        <translation>Bundan sonra yüklenen programı (F9, Derle) makine koduna derle: kat kat hızlı tarar. Bu yapılamazsa Python taraması çalışır ve PLC kontrol ekranı nedenini söyler.</translation>
    </message>
</context>
<context>
    <name>Scenario</name>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="94"/>
        <source>Run scenario</source>
        <translation>Senaryo çalıştır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="95"/>
        <location filename="../ladderworks/gui/docks/scenario.py" line="221"/>
        <source>Scenario files (*.csv);;All files (*)</source>
        <translation>Senaryo dosyaları (*.csv);;Tüm dosyalar (*)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="107"/>
        <source>Cannot read {0}: {1}</source>
        <translation>{0} okunamıyor: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="124"/>
        <source>Load (compile) a PLC program first</source>
        <translation>Önce bir PLC programı yükleyin (derleyin)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="183"/>
        <source>passed</source>
        <translation>geçti</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="184"/>
        <source>FAILED</source>
        <translation>BAŞARISIZ</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="168"/>
        <source>{0}: all {1} checks passed</source>
        <translation>{0}: {1} denetimin tümü geçti</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="171"/>
        <source>{0}: {1} of {2} checks failed</source>
        <translation>{0}: {2} denetimden {1} tanesi başarısız</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="220"/>
        <source>Save the recorded scenario</source>
        <translation>Kaydedilen senaryoyu sakla</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="229"/>
        <source>recorded in LadderWorks</source>
        <translation>LadderWorks ile kaydedildi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="233"/>
        <source>Recording inputs and forces...</source>
        <translation>Girişler ve zorlamalar kaydediliyor...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="243"/>
        <source>Recorded {0} changes</source>
        <translation>{0} değişiklik kaydedildi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="252"/>
        <source>Cannot write {0}: {1}</source>
        <translation>{0} yazılamıyor: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="255"/>
        <source>Saved {0}</source>
        <translation>{0} kaydedildi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="267"/>
        <source>PLC scenario</source>
        <translation>PLC senaryosu</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="268"/>
        <source>Run scenario...</source>
        <translation>Senaryo çalıştır...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="269"/>
        <source>Record scenario</source>
        <translation>Senaryo kaydet</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="271"/>
        <source>Line</source>
        <translation>Satır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="271"/>
        <source>Check</source>
        <translation>Denetim</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="272"/>
        <source>Expected</source>
        <translation>Beklenen</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="272"/>
        <source>Got</source>
        <translation>Okunan</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="273"/>
        <source>Time (ms)</source>
        <translation>Zaman (ms)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/scenario.py" line="273"/>
        <source>Result</source>
        <translation>Sonuç</translation>
    </message>
</context>
<context>
    <name>SignalList</name>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="110"/>
        <source>Program symbol</source>
        <translation>Program sembolü</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="166"/>
        <source>{0} signals</source>
        <translation>{0} sinyal</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="173"/>
        <source>Signals</source>
        <translation>Sinyaller</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="177"/>
        <source>In English</source>
        <translation>İngilizce</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="178"/>
        <source>In Turkish</source>
        <translation>Türkçe</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="180"/>
        <source>Address</source>
        <translation>Adres</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="181"/>
        <source>Name</source>
        <translation>Ad</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="182"/>
        <source>Description</source>
        <translation>Açıklama</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="206"/>
        <source>{0}: FANUC&apos;s name (* = active low: 0 means on); the seed manual writes {1}. Source: {2}</source>
        <translation>{0}: FANUC&apos;nun adı (* = aktif düşük: 0 etkin demektir); seed el kitabı {1} yazar. Kaynak: {2}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="168"/>
        <source>{0} program symbols, {1}</source>
        <translation>{0} program sembolü, {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="175"/>
        <source>Address, symbol, name or words, e.g. G8.4, SPL, acil</source>
        <translation>Adres, sembol, ad veya sözcükler, örn. G8.4, SPL, acil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/signal_list.py" line="186"/>
        <source>Double-click: use the address for the contact or coil at the cursor</source>
        <translation>Çift tıklama: adresi imleçteki kontak veya bobine ver</translation>
    </message>
</context>
<context>
    <name>TimeChart</name>
    <message>
        <location filename="../ladderworks/gui/family_words.py" line="46"/>
        <source>Type the bits to watch, e.g. R1.4 R1.7 (a value: D10:2)</source>
        <translation>İzlenecek bitleri yazın, örn. R1.4 R1.7 (bir değer: D10:2)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="206"/>
        <source>Load (compile) a PLC program first</source>
        <translation>Önce bir PLC programı yükleyin (derleyin)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="218"/>
        <source>Sampling every {0} ms</source>
        <translation>Her {0} ms&apos;de örnekleniyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="230"/>
        <source>Stopped: {0} samples</source>
        <translation>Durduruldu: {0} örnek</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="243"/>
        <source>New program loaded; sampling goes on</source>
        <translation>Yeni program yüklendi; örnekleme sürüyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="431"/>
        <source>Cursor {0} ms:</source>
        <translation>İmleç {0} ms:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="446"/>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="84"/>
        <source>Cannot write {0}: {1}</source>
        <translation>{0} yazılamıyor: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="450"/>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="458"/>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="87"/>
        <source>Saved {0}</source>
        <translation>{0} kaydedildi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="456"/>
        <source>Cannot write {0}</source>
        <translation>{0} yazılamıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="465"/>
        <source>Export time chart as CSV</source>
        <translation>Zaman kartını CSV olarak dışa aktar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="467"/>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="132"/>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="141"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV dosyaları (*.csv)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="476"/>
        <source>Export time chart as PNG</source>
        <translation>Zaman kartını PNG olarak dışa aktar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="478"/>
        <source>PNG pictures (*.png)</source>
        <translation>PNG resimleri (*.png)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="524"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="538"/>
        <source>PLC time chart</source>
        <translation>PLC ZAMAN KARTI</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="539"/>
        <source>Signals:</source>
        <translation>Sinyaller:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="541"/>
        <source>Sampling time:</source>
        <translation>ÖRNEKLEME ZAMANI:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="543"/>
        <source>START</source>
        <translation>BAŞLAT</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="544"/>
        <source>STOP</source>
        <translation>DURDUR</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="545"/>
        <source>CLEAR</source>
        <translation>TEMİZLE</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="546"/>
        <source>Fit</source>
        <translation>Sığdır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="547"/>
        <source>Zoom in</source>
        <translation>Yakınlaştır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="548"/>
        <source>Zoom out</source>
        <translation>Uzaklaştır</translation>
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
        <translation>Örnekleri CSV olarak dışa aktar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="558"/>
        <source>Save the chart as a PNG picture</source>
        <translation>Grafiği PNG resmi olarak kaydet</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_chart.py" line="560"/>
        <source>time (ms)</source>
        <translation>zaman (ms)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="111"/>
        <source>Cannot read {0}: {1}</source>
        <translation>{0} okunamıyor: {1}</translation>
    </message>
</context>
<context>
    <name>TimeTravel</name>
    <message>
        <location filename="../ladderworks/gui/docks/time_travel.py" line="62"/>
        <source>Keep scan history (time travel)</source>
        <translation>Tarama geçmişini tut (zamanda yolculuk)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_travel.py" line="63"/>
        <source>Keep every scan&apos;s power flow and values: the time chart&apos;s cursor shows an earlier scan in the PLC diagnostic</source>
        <translation>Her taramanın enerji akışını ve değerlerini tut: zaman kartının imleci PLC teşhiste önceki bir taramayı gösterir</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_travel.py" line="128"/>
        <source>before the scan history, which begins at {0} ms</source>
        <translation>tarama geçmişinden önce; geçmiş {0} ms&apos;de başlıyor</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_travel.py" line="138"/>
        <source>The cursor is before the scan history, which begins at {0} ms: no scan to show</source>
        <translation>İmleç tarama geçmişinden önce (geçmiş {0} ms&apos;de başlıyor): gösterilecek tarama yok</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_travel.py" line="173"/>
        <source>Turn on PLC › Keep scan history and give a bit address</source>
        <translation>PLC › Tarama geçmişini tut seçeneğini açın ve bir bit adresi verin</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_travel.py" line="181"/>
        <source>{0} did not change in the scans kept</source>
        <translation>{0}, tutulan taramalarda değişmedi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/time_travel.py" line="188"/>
        <source>{0} went to {1} in scan {2} at {3} ms</source>
        <translation>{0}, {2}. taramada ({3} ms) {1} oldu</translation>
    </message>
</context>
<context>
    <name>Tool</name>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="115"/>
        <source>Select</source>
        <translation>SEÇİM</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="176"/>
        <source>Input</source>
        <translation>GİRİŞ</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="191"/>
        <source>NOT input</source>
        <translation>GİRİŞ DEĞİL</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="205"/>
        <source>Output</source>
        <translation>ÇIKIŞ</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="219"/>
        <source>NOT output</source>
        <translation>ÇIKIŞ DEĞİL</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="233"/>
        <source>SET coil</source>
        <translation>SET ÇIKIŞ</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="248"/>
        <source>RST coil</source>
        <translation>RST ÇIKIŞ</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="263"/>
        <source>NOT</source>
        <translation>DEĞİL</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="277"/>
        <source>OR</source>
        <translation>VEYA</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="291"/>
        <source>Line</source>
        <translation>ÇİZGİ</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="340"/>
        <source>Comment</source>
        <translation>YORUM</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="373"/>
        <source>Delete</source>
        <translation>SİL</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="387"/>
        <source>Function</source>
        <translation>FONKSİYON</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="404"/>
        <source>Insert row before</source>
        <translation>ÖNCEYE SATIR GİR</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="419"/>
        <source>Insert row after</source>
        <translation>SONRAYA SATIR GİR</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="116"/>
        <source>Click an element or drag over cells to select; right-click: cut, copy, paste</source>
        <translation>Bir eleman seçmek için tıklayın veya hücreler üzerinde sürükleyin; sağ tık: kes, kopyala, yapıştır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="177"/>
        <source>Click a cell to place a contact (RD / AND), type its address, ENTER</source>
        <translation>Kontak (RD / AND) koymak için hücreye tıklayın, adresini yazın, ENTER</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="192"/>
        <source>Click a cell to place a NOT contact (RD.NOT / AND.NOT)</source>
        <translation>DEĞİL kontak (RD.NOT / AND.NOT) koymak için hücreye tıklayın</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="206"/>
        <source>Click a cell to place a coil (WRT), type its address, ENTER</source>
        <translation>Çıkış (WRT) koymak için hücreye tıklayın, adresini yazın, ENTER</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="220"/>
        <source>Click a cell to place a NOT coil (WRT.NOT)</source>
        <translation>DEĞİL çıkış (WRT.NOT) koymak için hücreye tıklayın</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="234"/>
        <source>Click a cell to place a SET coil (bit := 1 while the logic is 1)</source>
        <translation>SET çıkış koymak için hücreye tıklayın (mantık 1 iken bit := 1)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="249"/>
        <source>Click a cell to place an RST coil (bit := 0 while the logic is 1)</source>
        <translation>RST çıkış koymak için hücreye tıklayın (mantık 1 iken bit := 0)</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="264"/>
        <source>Click a contact or coil to turn it into its inverse</source>
        <translation>Tersine çevirmek için bir kontak veya çıkışa tıklayın</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="278"/>
        <source>Click a contact or coil to add a parallel one below it</source>
        <translation>Altına paralel eklemek için bir kontak veya çıkışa tıklayın</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="292"/>
        <source>Click a first point, then a second point: a horizontal or vertical wire</source>
        <translation>Birinci noktaya, sonra ikinci noktaya tıklayın: yatay veya dikey çizgi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="341"/>
        <source>Click the start of an empty row, type the comment, ENTER</source>
        <translation>Boş bir satırın başına tıklayın, yorumu yazın, ENTER</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="374"/>
        <source>Click an element to delete it</source>
        <translation>Silmek için elemanın üzerine tıklayın</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="388"/>
        <source>Choose a function in the list, click the diagram, fill its table</source>
        <translation>Listeden fonksiyonu seçin, diyagrama tıklayın, özellik tablosunu doldurun</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="405"/>
        <source>Click a cell to insert an empty row before it</source>
        <translation>Önüne boş satır girmek için hücreye tıklayın</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/editor/interactions.py" line="420"/>
        <source>Click a cell to insert an empty row after it</source>
        <translation>Arkasına boş satır girmek için hücreye tıklayın</translation>
    </message>
</context>
<context>
    <name>ToolPalette</name>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="30"/>
        <source>Delta DVP instructions</source>
        <translation>Delta DVP komutları</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="31"/>
        <source>Fatek FBs instructions</source>
        <translation>Fatek FBs komutları</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="32"/>
        <source>Delta DVP program structure</source>
        <translation>Delta DVP program yapısı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="33"/>
        <source>Delta DVP contacts</source>
        <translation>Delta DVP kontakları</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="34"/>
        <source>Fatek FBs program structure</source>
        <translation>Fatek FBs program yapısı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="35"/>
        <source>Fatek FBs contacts</source>
        <translation>Fatek FBs kontakları</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="36"/>
        <source>Siemens S7-1200 instructions</source>
        <translation>Siemens S7-1200 komutları</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="37"/>
        <source>S7-1200 program structure</source>
        <translation>S7-1200 program yapısı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="38"/>
        <source>S7-1200 contacts</source>
        <translation>S7-1200 kontakları</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="158"/>
        <source>Tools</source>
        <translation>Ana takım çantası</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="159"/>
        <source>Function:</source>
        <translation>Fonksiyon:</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="28"/>
        <source>Seed manual instructions</source>
        <translation>Kılavuzdaki komutlar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/palette.py" line="29"/>
        <source>FANUC PMC instructions</source>
        <translation>FANUC PMC komutları</translation>
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
        <translation>Örnekleri LADDER-III sinyal izleme sonucu olarak dışa aktar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="74"/>
        <source>Import...</source>
        <translation>İçe aktar...</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="76"/>
        <source>Show a LADDER-III trace result or a CSV trace</source>
        <translation>Bir LADDER-III izleme sonucunu ya da CSV izlemesini göster</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="116"/>
        <source>{0}, line {1}: not a trace file</source>
        <translation>{0}, satır {1}: izleme dosyası değil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="124"/>
        <source>Imported {0}: {1} samples</source>
        <translation>{0} içe aktarıldı: {1} örnek</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="131"/>
        <source>Export as LADDER-III trace result</source>
        <translation>LADDER-III izleme sonucu olarak dışa aktar</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/trace_files.py" line="140"/>
        <source>Import a trace</source>
        <translation>Bir izleme içe aktar</translation>
    </message>
</context>
<context>
    <name>WatchTable</name>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="134"/>
        <source>Watch table</source>
        <translation>İzleme tablosu</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="136"/>
        <source>Watch table: tags and addresses, live, modified on request</source>
        <translation>İzleme tablosu: etiketler ve adresler, canlı; istenince değiştirilir</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="139"/>
        <source>Name</source>
        <translation>Ad</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="139"/>
        <source>Address</source>
        <translation>Adres</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="140"/>
        <source>Display format</source>
        <translation>Görüntüleme biçimi</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="140"/>
        <source>Monitor value</source>
        <translation>İzleme değeri</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="141"/>
        <source>Modify value</source>
        <translation>Değiştirme değeri</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="142"/>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="379"/>
        <source>Modify now</source>
        <translation>Şimdi değiştir</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="143"/>
        <source>Write the modify values of the checked rows (none checked: of the selected rows) into the PLC now</source>
        <translation>İşaretli satırların değiştirme değerlerini (işaretli yoksa seçili satırlarınkini) şimdi PLC&apos;ye yaz</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="146"/>
        <source>Delete rows</source>
        <translation>Satırları sil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="292"/>
        <source>Checked: written by Modify now</source>
        <translation>İşaretli: Şimdi değiştir ile yazılır</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="302"/>
        <source>Type a name or an address to add a row</source>
        <translation>Satır eklemek için bir ad ya da adres yazın</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="305"/>
        <source>&lt;Add new&gt;</source>
        <translation>&lt;Yeni ekle&gt;</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="381"/>
        <source>Delete row</source>
        <translation>Satırı sil</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="405"/>
        <source>Check the rows to modify (or select one), then Modify now</source>
        <translation>Değiştirilecek satırları işaretleyin (ya da birini seçin), sonra Şimdi değiştir</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="415"/>
        <source>Values written: {0}, refused: {1}</source>
        <translation>Yazılan değer: {0}, reddedilen: {1}</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_table.py" line="418"/>
        <source>Values written: {0}</source>
        <translation>Yazılan değer: {0}</translation>
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
        <translation>Kayan noktalı sayı</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="17"/>
        <source>Time</source>
        <translation>Zaman</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="18"/>
        <source>Date</source>
        <translation>Tarih</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="19"/>
        <source>Time of day</source>
        <translation>Günün saati</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="20"/>
        <source>Character</source>
        <translation>Karakter</translation>
    </message>
    <message>
        <location filename="../ladderworks/gui/docks/watch_texts.py" line="21"/>
        <source>String</source>
        <translation>Dize</translation>
    </message>
</context>
</TS>
