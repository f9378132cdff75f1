<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>QObject</name>
    <message>
        <source>No sweep points to draw</source>
        <translation>Keine Sweep-Punkte zum Zeichnen</translation>
    </message>
    <message>
        <source>%1–%2 N</source>
        <translation>%1–%2 N</translation>
    </message>
    <message>
        <source>No feel bench rows to draw</source>
        <translation>Keine Zeilen des Haptik-Benchmarks zum Zeichnen</translation>
    </message>
    <message>
        <source>session</source>
        <translation>Sitzung</translation>
    </message>
    <message>
        <source> - proficient at session %1</source>
        <translation> – kompetent ab Sitzung %1</translation>
    </message>
    <message>
        <source> - not yet proficient</source>
        <translation> – noch nicht kompetent</translation>
    </message>
    <message>
        <source> - no expert standard</source>
        <translation> – kein Expertenstandard</translation>
    </message>
    <message>
        <source>Score (of 100)</source>
        <translation>Bewertung (von 100)</translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <source>&amp;Yes</source>
        <translation>&amp;Ja</translation>
    </message>
    <message>
        <source>&amp;No</source>
        <translation>&amp;Nein</translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation>Standardwerte wiederherstellen</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Anwenden</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Hilfe</translation>
    </message>
</context>
<context>
    <name>palpate::ChartsPanel</name>
    <message>
        <source>1 point</source>
        <translation>1 Punkt</translation>
    </message>
    <message>
        <source>%1 points</source>
        <translation>%1 Punkte</translation>
    </message>
    <message>
        <source>&amp;Run sweep</source>
        <translation>Sweep &amp;starten</translation>
    </message>
    <message>
        <source>Measure every model&apos;s tick cost and its displacement error against the flat punch (slopes calibrated for the tissue and tool in use). Runs in the background; the full sweep (both shapes, four sizes, 1 to 8 rings and the paper&apos;s methods) takes seconds.</source>
        <translation>Misst für jedes Modell die Rechenzeit pro Tick und den Verschiebungsfehler gegenüber dem flachen Stempel (Steigungen kalibriert für das verwendete Gewebe und Werkzeug). Läuft im Hintergrund; der vollständige Sweep (beide Formen, vier Größen, 1 bis 8 Ringe und die Methoden des Artikels) dauert Sekunden.</translation>
    </message>
    <message>
        <source>&amp;Quick</source>
        <translation>&amp;Schnell</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>&amp;Abbrechen</translation>
    </message>
    <message>
        <source>Stop after the model being measured; the points measured so far are shown.</source>
        <translation>Nach dem gerade gemessenen Modell anhalten; die bisher gemessenen Punkte werden gezeigt.</translation>
    </message>
    <message>
        <source>&amp;Open CSV…</source>
        <translation>CSV ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>Show a sweep saved as CSV (palpate-cli sweep --csv, or Save CSV here).</source>
        <translation>Einen als CSV gespeicherten Sweep anzeigen (palpate-cli sweep --csv oder hier „CSV speichern“).</translation>
    </message>
    <message>
        <source>S&amp;ave CSV…</source>
        <translation>CSV speich&amp;ern…</translation>
    </message>
    <message>
        <source>Write the points shown as CSV (and the tissue as JSON next to it).</source>
        <translation>Die gezeigten Punkte als CSV schreiben (und das Gewebe als JSON daneben).</translation>
    </message>
    <message>
        <source>Sha&amp;pe:</source>
        <translation>&amp;Form:</translation>
    </message>
    <message>
        <source>The shape whose points are drawn (each shape has its own Pareto front).</source>
        <translation>Die Form, deren Punkte gezeichnet werden (jede Form hat ihre eigene Pareto-Front).</translation>
    </message>
    <message>
        <source>No sweep loaded: press Run sweep</source>
        <translation>Kein Sweep geladen: „Sweep starten“ drücken</translation>
    </message>
    <message>
        <source>%p %</source>
        <translation>%p %</translation>
    </message>
    <message>
        <source>%1 with %2 rings</source>
        <translation>%1 mit %2 Ringen</translation>
    </message>
    <message>
        <source>In use: %1 (no mesh loaded)</source>
        <translation>In Verwendung: %1 (kein Netz geladen)</translation>
    </message>
    <message>
        <source>In use: %1 on %2 vertices</source>
        <translation>In Verwendung: %1 mit %2 Knoten</translation>
    </message>
    <message>
        <source>In use: %1 on %2 vertices (not measured in this sweep)</source>
        <translation>In Verwendung: %1 mit %2 Knoten (in diesem Sweep nicht gemessen)</translation>
    </message>
    <message>
        <source>Sweep started: building the first mesh…</source>
        <translation>Sweep gestartet: das erste Netz wird erzeugt…</translation>
    </message>
    <message>
        <source>Cancelling: the model being measured finishes first…</source>
        <translation>Abbruch: das gerade gemessene Modell wird zuerst fertig…</translation>
    </message>
    <message>
        <source>Sweep failed: %1</source>
        <translation>Sweep fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Cancelled after %1 (%2 s); the chart shows them.</source>
        <translation>Abgebrochen nach %1 (%2 s); das Diagramm zeigt sie.</translation>
    </message>
    <message>
        <source>Cancelled before the first point; the chart is unchanged.</source>
        <translation>Vor dem ersten Punkt abgebrochen; das Diagramm ist unverändert.</translation>
    </message>
    <message>
        <source>Sweep done: %1 in %2 s.</source>
        <translation>Sweep fertig: %1 in %2 s.</translation>
    </message>
    <message>
        <source>%1: cannot be read (%2)</source>
        <translation>%1: kann nicht gelesen werden (%2)</translation>
    </message>
    <message>
        <source>%1: no points (only the header)</source>
        <translation>%1: keine Punkte (nur die Kopfzeile)</translation>
    </message>
    <message>
        <source>Loaded %1 (%2).</source>
        <translation>%1 geladen (%2).</translation>
    </message>
    <message>
        <source>%1: not saved, there are no points</source>
        <translation>%1: nicht gespeichert, es gibt keine Punkte</translation>
    </message>
    <message>
        <source>%1: cannot be written (%2)</source>
        <translation>%1: kann nicht geschrieben werden (%2)</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>%1 gespeichert.</translation>
    </message>
    <message>
        <source>Open sweep CSV</source>
        <translation>Sweep-CSV öffnen</translation>
    </message>
    <message>
        <source>Sweep CSV (*.csv);;All files (*)</source>
        <translation>Sweep-CSV (*.csv);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Save sweep CSV</source>
        <translation>Sweep-CSV speichern</translation>
    </message>
    <message>
        <source>&amp;Speed vs. accuracy</source>
        <translation>&amp;Tempo gegen Genauigkeit</translation>
    </message>
    <message>
        <source>Every model&apos;s tick cost against its displacement error (the sweep).</source>
        <translation>Tick-Aufwand jedes Modells gegen seinen Verschiebungsfehler (der Sweep).</translation>
    </message>
    <message>
        <source>&amp;Feel</source>
        <translation>&amp;Haptik</translation>
    </message>
    <message>
        <source>Every model&apos;s largest force step while sliding at constant depth, against its tick cost (palpate-cli bench feel).</source>
        <translation>Größter Kraftsprung jedes Modells beim Gleiten in konstanter Tiefe, gegen seinen Tick-Aufwand (palpate-cli bench feel).</translation>
    </message>
    <message>
        <source>%1: not saved, %2 exists and is not a sweep&apos;s description (it would be replaced); choose another name</source>
        <translation>%1: nicht gespeichert, %2 existiert und ist keine Beschreibung einer Messreihe (sie würde ersetzt); wählen Sie einen anderen Namen</translation>
    </message>
    <message>
        <source>S&amp;tiffening</source>
        <translation>&amp;Versteifung</translation>
    </message>
    <message>
        <source>The tissue&apos;s force against depth: the hyperelastic reference beside the linear model and the model with stiffening knots.</source>
        <translation>Die Kraft des Gewebes über der Tiefe: die hyperelastische Referenz neben dem linearen Modell und dem Modell mit Versteifungsknoten.</translation>
    </message>
    <message>
        <source>%1, %2 site</source>
        <extracomment>The shape and the site of the organ sweep: &quot;Stomach, thin site&quot;</extracomment>
        <translation>%1, Stelle „%2“</translation>
    </message>
    <message>
        <source>Sphere only, at 1442 and 3970 vertices, up to 4 rings: about a second (against the organ&apos;s FEM: the stomach at 1442 vertices, about half a minute).</source>
        <translation>Nur die Kugel, mit 1442 und 3970 Knoten, bis 4 Ringe: etwa eine Sekunde (gegen die FEM des Organs: der Magen mit 1442 Knoten, etwa eine halbe Minute).</translation>
    </message>
    <message>
        <source>vs. punch</source>
        <translation>gegen Stempel</translation>
    </message>
    <message>
        <source>vs. organ FEM</source>
        <translation>gegen Organ-FEM</translation>
    </message>
    <message>
        <source>What Run sweep scores against: the flat punch on a half-space, or the FEM of the filled stomach (linear and hyperelastic) at its thin, thick and curved sites.</source>
        <translation>Wogegen der Sweep bewertet: der flache Stempel auf einem Halbraum oder die FEM des gefüllten Magens (linear und hyperelastisch) an seinen dünnen, dicken und gekrümmten Stellen.</translation>
    </message>
    <message>
        <source>In use: %1 on %2 vertices, tissue E = %3 kPa, ν = %4. The chart shows a stored sweep of another tissue (E = %5 kPa, ν = %6), not this one: press Run sweep to measure it.</source>
        <translation>In Verwendung: %1 auf %2 Knotenpunkten, Gewebe E = %3 kPa, ν = %4. Das Diagramm zeigt einen gespeicherten Sweep eines anderen Gewebes (E = %5 kPa, ν = %6), nicht dieses: Sweep starten misst es.</translation>
    </message>
    <message>
        <source>In use: %1 on %2 vertices; ringed in magenta: the sweep&apos;s point of that model and size (on its generated shape, not necessarily this mesh)</source>
        <translation>In Verwendung: %1 auf %2 Knotenpunkten; magenta umrandet: der Punkt des Sweeps für dieses Modell und diese Größe (auf seiner erzeugten Form, nicht unbedingt diesem Netz)</translation>
    </message>
</context>
<context>
    <name>palpate::ClassDialog</name>
    <message>
        <source>Class View</source>
        <translation>Klassenansicht</translation>
    </message>
    <message>
        <source>This workstation</source>
        <translation>Dieser Arbeitsplatz</translation>
    </message>
    <message>
        <source>The class&apos;s server (%1)</source>
        <translation>Der Server der Klasse (%1)</translation>
    </message>
    <message>
        <source>&amp;Refresh</source>
        <translation>&amp;Aktualisieren</translation>
    </message>
    <message>
        <source>&amp;Export CSV…</source>
        <translation>CSV &amp;exportieren…</translation>
    </message>
    <message>
        <source>Trainee</source>
        <translation>Lernende(r)</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Übung</translation>
    </message>
    <message>
        <source>Sessions</source>
        <translation>Sitzungen</translation>
    </message>
    <message>
        <source>Latest</source>
        <translation>Letzte</translation>
    </message>
    <message>
        <source>Best</source>
        <translation>Beste</translation>
    </message>
    <message>
        <source>Against the marks</source>
        <translation>Gegen die Marken</translation>
    </message>
    <message>
        <source>Last session</source>
        <translation>Letzte Sitzung</translation>
    </message>
    <message>
        <source>&amp;Results of:</source>
        <translation>&amp;Ergebnisse von:</translation>
    </message>
    <message>
        <source>Export the Class View</source>
        <translation>Klassenansicht exportieren</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Exported %1 rows to %2.</source>
        <translation>%1 Zeilen nach %2 exportiert.</translation>
    </message>
    <message>
        <source>Reading %1…</source>
        <translation>%1 wird gelesen…</translation>
    </message>
    <message>
        <source>Cannot read %1: %2</source>
        <translation>Kann %1 nicht lesen: %2</translation>
    </message>
    <message>
        <source>1 trainee</source>
        <translation>1 Lernende(r)</translation>
    </message>
    <message>
        <source>%1 trainees</source>
        <translation>%1 Lernende</translation>
    </message>
    <message>
        <source>1 row</source>
        <translation>1 Zeile</translation>
    </message>
    <message>
        <source>%1 rows</source>
        <translation>%1 Zeilen</translation>
    </message>
    <message>
        <source>%1: %2, %3. Exercises are matched by name across workstations.</source>
        <translation>%1: %2, %3. Übungen werden über Arbeitsplätze hinweg nach Namen zugeordnet.</translation>
    </message>
    <message>
        <source>proficient</source>
        <translation>kompetent</translation>
    </message>
    <message>
        <source>passed (once)</source>
        <translation>bestanden (einmal)</translation>
    </message>
    <message>
        <source>not yet</source>
        <translation>noch nicht</translation>
    </message>
    <message>
        <source>no marks</source>
        <translation>keine Marken</translation>
    </message>
    <message>
        <source>%1 is the results database: choose another file</source>
        <translation>%1 ist die Ergebnisdatenbank: eine andere Datei wählen</translation>
    </message>
    <message>
        <source>%1: cannot be written (%2)</source>
        <translation>%1: kann nicht geschrieben werden (%2)</translation>
    </message>
    <message>
        <source>Show one class (a class is the server&apos;s: a workstation&apos;s role belongs to one)</source>
        <translation>Eine Klasse zeigen (Klassen legt der Server fest: die Rolle eines Arbeitsplatzes gehört zu einer)</translation>
    </message>
    <message>
        <source>Class</source>
        <translation>Klasse</translation>
    </message>
    <message>
        <source>C&amp;lass:</source>
        <translation>K&amp;lasse:</translation>
    </message>
    <message>
        <source>%1 as %2</source>
        <translation>%1 als %2</translation>
    </message>
    <message>
        <source>All</source>
        <translation>Alle</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
</context>
<context>
    <name>palpate::DeviceController</name>
    <message>
        <source>&amp;Device</source>
        <translation>&amp;Gerät</translation>
    </message>
    <message>
        <source>Cannot switch the device</source>
        <translation>Gerät kann nicht gewechselt werden</translation>
    </message>
    <message>
        <source>%1 is still being opened: wait for it first</source>
        <translation>%1 wird noch geöffnet: warten Sie zuerst darauf</translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>%1 is connected</source>
        <translation>%1 ist verbunden</translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation>%1 wird geöffnet…</translation>
    </message>
</context>
<context>
    <name>palpate::DevicePanel</name>
    <message>
        <source>Disconnected</source>
        <translation>Getrennt</translation>
    </message>
    <message>
        <source>Opening</source>
        <translation>Wird geöffnet</translation>
    </message>
    <message>
        <source>NeedsCalibration</source>
        <translation>Kalibrierung nötig</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Bereit</translation>
    </message>
    <message>
        <source>Fault</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>HoldOff</source>
        <translation>Zurückgehalten</translation>
    </message>
    <message>
        <source>RampIn</source>
        <translation>Einblenden</translation>
    </message>
    <message>
        <source>Armed</source>
        <translation>Scharf</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>URI</source>
        <translation>URI</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>The devices this build knows. Double-click one to connect.</source>
        <translation>Die Geräte, die dieser Build kennt. Doppelklick zum Verbinden.</translation>
    </message>
    <message>
        <source>Waypoint File…</source>
        <translation>Wegpunktdatei…</translation>
    </message>
    <message>
        <source>Choose the waypoint file the simulated device follows</source>
        <translation>Die Wegpunktdatei wählen, der das simulierte Gerät folgt</translation>
    </message>
    <message>
        <source>&amp;URI:</source>
        <translation>&amp;URI:</translation>
    </message>
    <message>
        <source>Type a device URI, e.g. sim:stroke</source>
        <translation>Eine Geräte-URI eingeben, z. B. sim:stroke</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Verbinden</translation>
    </message>
    <message>
        <source>Connect to the device the URI names (switching from the current one)</source>
        <translation>Mit dem Gerät verbinden, das die URI nennt (statt des aktuellen)</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Trennen</translation>
    </message>
    <message>
        <source>Stop sending forces and release the device</source>
        <translation>Keine Kräfte mehr senden und das Gerät freigeben</translation>
    </message>
    <message>
        <source>Connected Device</source>
        <translation>Verbundenes Gerät</translation>
    </message>
    <message>
        <source>URI:</source>
        <translation>URI:</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>Max force:</source>
        <translation>Max. Kraft:</translation>
    </message>
    <message>
        <source>Max stiffness:</source>
        <translation>Max. Steifigkeit:</translation>
    </message>
    <message>
        <source>Max damping:</source>
        <translation>Max. Dämpfung:</translation>
    </message>
    <message>
        <source>Workspace radius:</source>
        <translation>Arbeitsraumradius:</translation>
    </message>
    <message>
        <source>Actuated:</source>
        <translation>Aktuiert:</translation>
    </message>
    <message>
        <source>Buttons:</source>
        <translation>Tasten:</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>The device&apos;s state as the haptic loop last saw it</source>
        <translation>Der Zustand des Geräts, wie ihn die Haptikschleife zuletzt sah</translation>
    </message>
    <message>
        <source>The safety filter: holding forces off until the command is small, ramping in, or armed</source>
        <translation>Der Sicherheitsfilter: hält Kräfte zurück, bis der Befehl klein ist, blendet ein, oder scharf</translation>
    </message>
    <message>
        <source>Why the force sent differs from the force the model asked for</source>
        <translation>Warum die gesendete Kraft von der vom Modell verlangten abweicht</translation>
    </message>
    <message>
        <source>Tool tip position in the scene&apos;s frame</source>
        <translation>Position der Werkzeugspitze im Koordinatensystem der Szene</translation>
    </message>
    <message>
        <source>Device:</source>
        <translation>Gerät:</translation>
    </message>
    <message>
        <source>Safety:</source>
        <translation>Sicherheit:</translation>
    </message>
    <message>
        <source>Flags:</source>
        <translation>Flags:</translation>
    </message>
    <message>
        <source>Force:</source>
        <translation>Kraft:</translation>
    </message>
    <message>
        <source>Tool:</source>
        <translation>Werkzeug:</translation>
    </message>
    <message>
        <source>Choose a Waypoint File</source>
        <translation>Wegpunktdatei wählen</translation>
    </message>
    <message>
        <source>Waypoint files (*.txt *.csv *.tsv);;All files (*)</source>
        <translation>Wegpunktdateien (*.txt *.csv *.tsv);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>No device URI: choose a device in the list or type a URI.</source>
        <translation>Keine Geräte-URI: ein Gerät in der Liste wählen oder eine URI eingeben.</translation>
    </message>
    <message>
        <source>Cannot connect: %1</source>
        <translation>Verbindung nicht möglich: %1</translation>
    </message>
    <message>
        <source>%1 is connected again: forces stay off until the safety filter has armed.</source>
        <translation>%1 ist wieder verbunden: die Kräfte bleiben aus, bis der Sicherheitsfilter scharf ist.</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>Nicht verbunden</translation>
    </message>
    <message>
        <source>%1 N</source>
        <translation>%1 N</translation>
    </message>
    <message>
        <source>%1 N/mm</source>
        <translation>%1 N/mm</translation>
    </message>
    <message>
        <source>%1 N·s/mm</source>
        <translation>%1 N·s/mm</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no (input only)</source>
        <translation>nein (nur Eingabe)</translation>
    </message>
    <message>
        <source>held off</source>
        <translation>zurückgehalten</translation>
    </message>
    <message>
        <source>ramping</source>
        <translation>blendet ein</translation>
    </message>
    <message>
        <source>clamped</source>
        <translation>begrenzt</translation>
    </message>
    <message>
        <source>stale sample</source>
        <translation>veralteter Messwert</translation>
    </message>
    <message>
        <source>overrun</source>
        <translation>Überlauf</translation>
    </message>
    <message>
        <source>not ready</source>
        <translation>nicht bereit</translation>
    </message>
    <message>
        <source>non-finite command</source>
        <translation>nicht endlicher Befehl</translation>
    </message>
    <message>
        <source>bad clock</source>
        <translation>fehlerhafte Uhr</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>%1 N  (%2, %3, %4)</source>
        <translation>%1 N  (%2, %3, %4)</translation>
    </message>
    <message>
        <source>(%1, %2, %3) mm</source>
        <translation>(%1, %2, %3) mm</translation>
    </message>
    <message>
        <source>%1 reports a fault: forces are off. Disconnect it, or reconnect it to try again.</source>
        <translation>%1 meldet einen Fehler: die Kräfte sind aus. Trennen Sie es, oder verbinden Sie es neu, um es erneut zu versuchen.</translation>
    </message>
    <message>
        <source>%1 is disconnected (unplugged?): forces are off. Plug it back in or choose another device.</source>
        <translation>%1 ist getrennt (ausgesteckt?): die Kräfte sind aus. Stecken Sie es wieder ein oder wählen Sie ein anderes Gerät.</translation>
    </message>
    <message>
        <source>%1 is coming back (%2): forces are off.</source>
        <translation>%1 kommt zurück (%2): die Kräfte sind aus.</translation>
    </message>
    <message>
        <source>%1 is back: forces are held off until the tool eases off the tissue.</source>
        <translation>%1 ist zurück: die Kräfte bleiben aus, bis das Werkzeug das Gewebe entlastet.</translation>
    </message>
    <message>
        <source>%1 is back: forces are ramping in.</source>
        <translation>%1 ist zurück: die Kräfte werden eingeblendet.</translation>
    </message>
    <message>
        <source>Force sent to the device (after the safety filter); marked when the model asked for more than the device&apos;s maximum force and the filter clipped it</source>
        <translation>An das Gerät gesendete Kraft (nach dem Sicherheitsfilter); markiert, wenn das Modell mehr als die Höchstkraft des Geräts verlangte und der Filter sie begrenzte</translation>
    </message>
    <message>
        <source>clipped at device max %1 N (the model asked %2 N)</source>
        <translation>begrenzt auf das Gerätemaximum %1 N (das Modell verlangte %2 N)</translation>
    </message>
    <message>
        <source>clipped (the model asked %1 N)</source>
        <translation>begrenzt (das Modell verlangte %1 N)</translation>
    </message>
</context>
<context>
    <name>palpate::ExerciseController</name>
    <message>
        <source>Choose a trainee, or add one with New…, before starting.</source>
        <translation>Wählen Sie einen Teilnehmer, oder legen Sie mit „Neu…“ einen an, bevor Sie beginnen.</translation>
    </message>
    <message>
        <source>Choose an exercise first.</source>
        <translation>Wählen Sie zuerst eine Übung.</translation>
    </message>
    <message>
        <source>An exercise is already running: stop it first.</source>
        <translation>Eine Übung läuft bereits: beenden Sie sie zuerst.</translation>
    </message>
    <message>
        <source>Preview</source>
        <translation>Vorschau</translation>
    </message>
    <message>
        <source>Preview of &quot;%1&quot;: not stored.</source>
        <translation>Vorschau von „%1“: wird nicht gespeichert.</translation>
    </message>
    <message>
        <source>The recordings folder %1 cannot be created: the exercise cannot be recorded and scored.</source>
        <translation>Der Aufnahmeordner %1 kann nicht angelegt werden: die Übung kann nicht aufgezeichnet und bewertet werden.</translation>
    </message>
    <message>
        <source>Exercise &quot;%1&quot; started; recording to %2</source>
        <translation>Übung „%1“ gestartet; Aufnahme nach %2</translation>
    </message>
    <message>
        <source>the recording was stopped</source>
        <translation>die Aufnahme wurde beendet</translation>
    </message>
    <message>
        <source>Marked</source>
        <translation>Markiert</translation>
    </message>
    <message>
        <source>Stopped before the session began: nothing recorded.</source>
        <translation>Vor Beginn der Sitzung beendet: nichts aufgezeichnet.</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>The exercise could not go on: %1</source>
        <translation>Die Übung konnte nicht fortgesetzt werden: %1</translation>
    </message>
    <message>
        <source>Exercise ended: %1</source>
        <translation>Übung beendet: %1</translation>
    </message>
    <message>
        <source>Result stored for %1.</source>
        <translation>Ergebnis für %1 gespeichert.</translation>
    </message>
    <message>
        <source>Ended: %1. </source>
        <translation>Beendet: %1. </translation>
    </message>
    <message>
        <source>Exercise &quot;%1&quot;: score %2</source>
        <translation>Übung „%1“: Punktzahl %2</translation>
    </message>
    <message>
        <source>There is no score to export yet.</source>
        <translation>Es gibt noch keine Punktzahl zum Exportieren.</translation>
    </message>
    <message>
        <source>This result has no recording to report from.</source>
        <translation>Dieses Ergebnis hat keine Aufnahme für einen Bericht.</translation>
    </message>
    <message>
        <source>no results database is open</source>
        <translation>keine Ergebnisdatenbank ist geöffnet</translation>
    </message>
    <message>
        <source>%1: trainees cannot be stored.</source>
        <translation>%1: Teilnehmer können nicht gespeichert werden.</translation>
    </message>
    <message>
        <source>the session was not recorded, so it is lost</source>
        <translation>die Sitzung wurde nicht aufgezeichnet und ist daher verloren</translation>
    </message>
    <message>
        <source>the session is kept in the recording %1 (palpate-cli score scores it again)</source>
        <translation>die Sitzung bleibt in der Aufzeichnung %1 erhalten (palpate-cli score bewertet sie erneut)</translation>
    </message>
    <message>
        <source>The result was NOT stored: %1; %2.</source>
        <translation>Das Ergebnis wurde NICHT gespeichert: %1; %2.</translation>
    </message>
    <message>
        <source>%1: is the recording the report is made from; choose another file for the PDF</source>
        <translation>%1: ist die Aufzeichnung, aus der der Bericht entsteht; wählen Sie eine andere Datei für das PDF</translation>
    </message>
    <message>
        <source>Examination finished</source>
        <translation>Untersuchung beendet</translation>
    </message>
    <message>
        <source>Your level: every lump at %1 %2 (the staircase adapts it to you).</source>
        <translation>Ihre Stufe: jeder Knoten bei %1 %2 (die Treppe passt sie Ihnen an).</translation>
    </message>
    <message>
        <source>The staircase was not moved: %1</source>
        <translation>Die Treppe wurde nicht bewegt: %1</translation>
    </message>
    <message>
        <source>Trial passed; next level %1.</source>
        <translation>Durchgang bestanden; nächste Stufe %1.</translation>
    </message>
    <message>
        <source>Trial failed; next level %1.</source>
        <translation>Durchgang nicht bestanden; nächste Stufe %1.</translation>
    </message>
    <message>
        <source>Expert reference session stored for %1: it sets the pass marks.</source>
        <translation>Experten-Referenzsitzung für %1 gespeichert: Sie setzt die Bestehensgrenzen.</translation>
    </message>
    <message>
        <source>%1: the folder to import the exercise into cannot be made</source>
        <translation>%1: der Ordner, in den die Übung importiert wird, lässt sich nicht anlegen</translation>
    </message>
</context>
<context>
    <name>palpate::ExerciseEditorPanel</name>
    <message>
        <source>Unsaved exercise</source>
        <translation>Ungespeicherte Übung</translation>
    </message>
    <message>
        <source>The exercise &quot;%1&quot; has changes that are not saved. Save them first?</source>
        <translation>Die Übung „%1“ hat ungespeicherte Änderungen. Zuerst speichern?</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <source>Type:</source>
        <translation>Typ:</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>Description:</source>
        <translation>Beschreibung:</translation>
    </message>
    <message>
        <source>Mesh:</source>
        <translation>Netz:</translation>
    </message>
    <message>
        <source>Tissue preset:</source>
        <translation>Gewebevorgabe:</translation>
    </message>
    <message>
        <source>Time limit:</source>
        <translation>Zeitlimit:</translation>
    </message>
    <message>
        <source>Damage beyond:</source>
        <translation>Schaden ab:</translation>
    </message>
    <message>
        <source>Excessive force:</source>
        <translation>Übermäßige Kraft:</translation>
    </message>
    <message>
        <source>The mesh &apos;%1&apos; cannot be found.</source>
        <translation>Das Netz „%1“ wurde nicht gefunden.</translation>
    </message>
    <message>
        <source>New: %1</source>
        <translation>Neu: %1</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Neu</translation>
    </message>
    <message>
        <source>A new exercise of a type; asks before unsaved changes are lost.</source>
        <translation>Eine neue Übung eines Typs; fragt, bevor ungespeicherte Änderungen verloren gehen.</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Öffnen…</translation>
    </message>
    <message>
        <source>Open an exercise file (Ctrl+O).</source>
        <translation>Eine Übungsdatei öffnen (Strg+O).</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>Save the exercise to its file (Ctrl+S); refused while it has problems.</source>
        <translation>Die Übung in ihre Datei speichern (Strg+S); verweigert, solange sie Probleme hat.</translation>
    </message>
    <message>
        <source>Save As…</source>
        <translation>Speichern unter…</translation>
    </message>
    <message>
        <source>Save the exercise to a new file (Ctrl+Shift+S).</source>
        <translation>Die Übung in eine neue Datei speichern (Strg+Umschalt+S).</translation>
    </message>
    <message>
        <source>Try it</source>
        <translation>Ausprobieren</translation>
    </message>
    <message>
        <source>Run this exercise now as a trainee would, without saving it (F5).</source>
        <translation>Diese Übung jetzt wie ein Teilnehmer durchführen, ohne sie zu speichern (F5).</translation>
    </message>
    <message>
        <source>Stop placing</source>
        <translation>Platzieren beenden</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Move up</source>
        <translation>Nach oben</translation>
    </message>
    <message>
        <source>Move down</source>
        <translation>Nach unten</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Übung</translation>
    </message>
    <message>
        <source>What the trainee does. Each type keeps its own points: switching back restores them.</source>
        <translation>Was der Teilnehmer tut. Jeder Typ behält seine eigenen Punkte: beim Zurückwechseln sind sie wieder da.</translation>
    </message>
    <message>
        <source>The name trainees and score reports see (name).</source>
        <translation>Der Name, den Teilnehmer und Bewertungsberichte sehen (name).</translation>
    </message>
    <message>
        <source>Required</source>
        <translation>Erforderlich</translation>
    </message>
    <message>
        <source>What the trainee is asked to do, shown before the exercise starts (description).</source>
        <translation>Was der Teilnehmer tun soll, angezeigt vor dem Start der Übung (description).</translation>
    </message>
    <message>
        <source>Tissue</source>
        <translation>Gewebe</translation>
    </message>
    <message>
        <source>The mesh file (mesh): a shipped mesh, a path relative to resources/ or to the exercise file, or an absolute path. Points are vertices of this file.</source>
        <translation>Die Netzdatei (mesh): ein mitgeliefertes Netz, ein Pfad relativ zu resources/ oder zur Übungsdatei, oder ein absoluter Pfad. Punkte sind Knoten dieser Datei.</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>Choose a mesh file (OBJ, OFF, PLY, STL, OM).</source>
        <translation>Eine Netzdatei wählen (OBJ, OFF, PLY, STL, OM).</translation>
    </message>
    <message>
        <source>Show this mesh</source>
        <translation>Dieses Netz zeigen</translation>
    </message>
    <message>
        <source>Draw the exercise&apos;s mesh in the viewport, so that points can be placed by clicking.</source>
        <translation>Das Netz der Übung im Ansichtsfenster zeichnen, damit Punkte per Klick gesetzt werden können.</translation>
    </message>
    <message>
        <source>The tissue preset file (tissue_preset): how the tissue feels.</source>
        <translation>Die Gewebevorgabedatei (tissue_preset): wie sich das Gewebe anfühlt.</translation>
    </message>
    <message>
        <source>Choose a tissue preset file (JSON).</source>
        <translation>Eine Gewebevorgabedatei wählen (JSON).</translation>
    </message>
    <message>
        <source>Limits</source>
        <translation>Grenzen</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Time the trainee has (time_limit_s); what happens after it is not scored.</source>
        <translation>Die Zeit, die der Teilnehmer hat (time_limit_s); was danach geschieht, wird nicht bewertet.</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Tissue displaced further than this counts as damage (damage.displacement_limit_mm).</source>
        <translation>Gewebe, das weiter als dies verschoben wird, zählt als Schaden (damage.displacement_limit_mm).</translation>
    </message>
    <message>
        <source> N</source>
        <translation> N</translation>
    </message>
    <message>
        <source>A force above this is excessive (force.excessive_n); every target&apos;s lower force must stay below it.</source>
        <translation>Eine Kraft darüber ist übermäßig (force.excessive_n); die untere Kraft jedes Ziels muss darunter bleiben.</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>Vertex</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>Add by clicking</source>
        <translation>Per Klick hinzufügen</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <source>Place by clicking</source>
        <translation>Per Klick platzieren</translation>
    </message>
    <message>
        <source>Rubric</source>
        <translation>Bewertungsschema</translation>
    </message>
    <message>
        <source>Metric</source>
        <translation>Kennzahl</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Gewicht</translation>
    </message>
    <message>
        <source>Full</source>
        <translation>Voll</translation>
    </message>
    <message>
        <source>Zero</source>
        <translation>Null</translation>
    </message>
    <message>
        <source>What is measured (the rubric key; its tooltip says what it is).</source>
        <translation>Was gemessen wird (der Schlüssel im Bewertungsschema; sein Tooltip erklärt ihn).</translation>
    </message>
    <message>
        <source>The metric&apos;s unit.</source>
        <translation>Die Einheit der Kennzahl.</translation>
    </message>
    <message>
        <source>Relative weight (0: reported, not scored).</source>
        <translation>Relatives Gewicht (0: berichtet, nicht bewertet).</translation>
    </message>
    <message>
        <source>At or beyond this value the line scores full marks.</source>
        <translation>Bei diesem Wert oder darüber hinaus erhält die Zeile die volle Punktzahl.</translation>
    </message>
    <message>
        <source>At or beyond this value (away from full) the line scores zero.</source>
        <translation>Bei diesem Wert oder darüber hinaus (weg von „voll“) erhält die Zeile null Punkte.</translation>
    </message>
    <message>
        <source>Grey lines are the defaults (docs/scoring.md), computed from the exercise&apos;s own numbers; editing a line sets it in the exercise.</source>
        <translation>Graue Zeilen sind die Vorgaben (docs/scoring.md), berechnet aus den Zahlen der Übung; das Bearbeiten einer Zeile setzt sie in der Übung.</translation>
    </message>
    <message>
        <source>Reset to defaults</source>
        <translation>Auf Vorgaben zurücksetzen</translation>
    </message>
    <message>
        <source>Remove every rubric line the exercise sets: all metrics use the defaults.</source>
        <translation>Jede Zeile des Bewertungsschemas entfernen, die die Übung setzt: alle Kennzahlen nutzen die Vorgaben.</translation>
    </message>
    <message>
        <source>New exercise: %1</source>
        <translation>Neue Übung: %1</translation>
    </message>
    <message>
        <source>Not opened:</source>
        <translation>Nicht geöffnet:</translation>
    </message>
    <message>
        <source>Opened %1.</source>
        <translation>%1 geöffnet.</translation>
    </message>
    <message>
        <source>No file to save to.</source>
        <translation>Keine Datei zum Speichern.</translation>
    </message>
    <message>
        <source>Not saved: the exercise has problems:</source>
        <translation>Nicht gespeichert: die Übung hat Probleme:</translation>
    </message>
    <message>
        <source>Not saved:</source>
        <translation>Nicht gespeichert:</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>%1 gespeichert.</translation>
    </message>
    <message>
        <source>Not saved.</source>
        <translation>Nicht gespeichert.</translation>
    </message>
    <message>
        <source>Save exercise</source>
        <translation>Übung speichern</translation>
    </message>
    <message>
        <source>Exercises (*.json)</source>
        <translation>Übungen (*.json)</translation>
    </message>
    <message>
        <source>Open exercise</source>
        <translation>Übung öffnen</translation>
    </message>
    <message>
        <source>Exercises (*.json);;All files (*)</source>
        <translation>Übungen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Choose a mesh</source>
        <translation>Netz wählen</translation>
    </message>
    <message>
        <source>Meshes (*.off *.obj *.ply *.stl *.om);;All files (*)</source>
        <translation>Netze (*.off *.obj *.ply *.stl *.om);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Choose a tissue preset</source>
        <translation>Gewebevorgabe wählen</translation>
    </message>
    <message>
        <source>Tissue presets (*.json);;All files (*)</source>
        <translation>Gewebevorgaben (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>(%1, %2, %3) mm</source>
        <translation>(%1, %2, %3) mm</translation>
    </message>
    <message>
        <source>Weights total %1; the score is 100 × Σ wᵢsᵢ / Σ wᵢ.</source>
        <translation>Summe der Gewichte %1; die Punktzahl ist 100 × Σ wᵢsᵢ / Σ wᵢ.</translation>
    </message>
    <message>
        <source>name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>time limit</source>
        <translation>Zeitlimit</translation>
    </message>
    <message>
        <source>damage limit</source>
        <translation>Schadensgrenze</translation>
    </message>
    <message>
        <source>excessive force</source>
        <translation>übermäßige Kraft</translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>%1 ändern</translation>
    </message>
    <message>
        <source>Change the rubric&apos;s %1</source>
        <translation>%1 des Bewertungsschemas ändern</translation>
    </message>
    <message>
        <source>Reset the rubric</source>
        <translation>Bewertungsschema zurücksetzen</translation>
    </message>
    <message>
        <source>Change the mesh</source>
        <translation>Netz ändern</translation>
    </message>
    <message>
        <source>Change the tissue preset</source>
        <translation>Gewebevorgabe ändern</translation>
    </message>
    <message>
        <source>Change the type to %1</source>
        <translation>Typ zu %1 ändern</translation>
    </message>
    <message>
        <source>The viewport does not show this exercise&apos;s mesh: press Show this mesh first.</source>
        <translation>Das Ansichtsfenster zeigt nicht das Netz dieser Übung: zuerst „Dieses Netz zeigen“ drücken.</translation>
    </message>
    <message>
        <source>That click was on another mesh than the exercise&apos;s: press Show this mesh first.</source>
        <translation>Dieser Klick war auf einem anderen Netz als dem der Übung: zuerst „Dieses Netz zeigen“ drücken.</translation>
    </message>
    <message>
        <source>Vertex %1 is not on the drawn mesh.</source>
        <translation>Knoten %1 liegt nicht auf dem gezeichneten Netz.</translation>
    </message>
    <message>
        <source>mesh: &apos;%1&apos; is not found beside the exercise file or under resources/</source>
        <translation>mesh: „%1“ wurde weder neben der Übungsdatei noch unter resources/ gefunden</translation>
    </message>
    <message>
        <source>tissue_preset: &apos;%1&apos; is not found beside the exercise file or under resources/</source>
        <translation>tissue_preset: „%1“ wurde weder neben der Übungsdatei noch unter resources/ gefunden</translation>
    </message>
    <message>
        <source>mesh: %1</source>
        <translation>Netz: %1</translation>
    </message>
    <message>
        <source>no mesh</source>
        <translation>kein Netz</translation>
    </message>
    <message>
        <source>mesh: the viewport shows %1, not this exercise&apos;s %2: press Show this mesh to place points by clicking</source>
        <translation>mesh: das Ansichtsfenster zeigt %1, nicht %2 dieser Übung: „Dieses Netz zeigen“ drücken, um Punkte per Klick zu setzen</translation>
    </message>
    <message>
        <source>Not found.</source>
        <translation>Nicht gefunden.</translation>
    </message>
    <message>
        <source>Drawn in the viewport.</source>
        <translation>Im Ansichtsfenster gezeichnet.</translation>
    </message>
    <message>
        <source>Not drawn in the viewport.</source>
        <translation>Nicht im Ansichtsfenster gezeichnet.</translation>
    </message>
    <message>
        <source>not saved yet</source>
        <translation>noch nicht gespeichert</translation>
    </message>
    <message>
        <source>%1 — %2%3</source>
        <translation>%1 — %2%3</translation>
    </message>
    <message>
        <source>(unnamed)</source>
        <translation>(ohne Namen)</translation>
    </message>
    <message>
        <source> (modified)</source>
        <translation> (geändert)</translation>
    </message>
    <message>
        <source>Cannot try it: the exercise has problems (listed above).</source>
        <translation>Ausprobieren nicht möglich: die Übung hat Probleme (oben aufgeführt).</translation>
    </message>
    <message>
        <source>State level-of-detail targets</source>
        <translation>Detailstufen-Ziele angeben</translation>
    </message>
    <message>
        <source>The accuracy and haptic time the model for this exercise must meet (needs)</source>
        <translation>Die Genauigkeit und die Haptikzeit, die das Modell für diese Übung einhalten muss (needs)</translation>
    </message>
    <message>
        <source>Largest displacement error against the reference (needs.max_error)</source>
        <translation>Größter Verschiebungsfehler gegenüber der Referenz (needs.max_error)</translation>
    </message>
    <message>
        <source>Max error:</source>
        <translation>Max. Fehler:</translation>
    </message>
    <message>
        <source>Longest haptic tick the model may take (needs.budget_us)</source>
        <translation>Längster Haptik-Tick, den das Modell brauchen darf (needs.budget_us)</translation>
    </message>
    <message>
        <source>Tick budget:</source>
        <translation>Tick-Budget:</translation>
    </message>
    <message>
        <source>State targets</source>
        <translation>Ziele angeben</translation>
    </message>
    <message>
        <source>Remove targets</source>
        <translation>Ziele entfernen</translation>
    </message>
    <message>
        <source>max error</source>
        <translation>max. Fehler</translation>
    </message>
    <message>
        <source>tick budget</source>
        <translation>Tick-Budget</translation>
    </message>
    <message>
        <source>tissue_preset: whether the targets can be reached with the mouse is not known: %1</source>
        <translation>tissue_preset: ob die Ziele mit der Maus erreichbar sind, ist nicht bekannt: %1</translation>
    </message>
    <message>
        <source>%1: target %2 cannot be held with the mouse: its window %3–%4 N lies between %5 N at %6 mm and %7 N at %8 mm deep (one turn of the wheel apart). Widen the window to take in one of them.</source>
        <translation>%1: Ziel %2 lässt sich mit der Maus nicht halten: sein Fenster %3–%4 N liegt zwischen %5 N bei %6 mm und %7 N bei %8 mm Tiefe (eine Raststufe des Mausrads auseinander). Das Fenster so verbreitern, dass es einen der beiden Werte einschließt.</translation>
    </message>
    <message>
        <source>%1: target %2 cannot be reached with the mouse: pressing %3 mm deep (the deepest) gives %4 N, below its window&apos;s %5 N. Lower the window to at most %4 N%6, or choose a stiffer tissue preset.</source>
        <translation>%1: Ziel %2 ist mit der Maus nicht erreichbar: %3 mm tief gedrückt (am tiefsten) ergibt %4 N, unter den %5 N seines Fensters. Das Fenster auf höchstens %4 N senken%6 oder ein steiferes Gewebe-Preset wählen.</translation>
    </message>
    <message>
        <source>tissue_preset: whether the band can be reached with the mouse is not known: %1</source>
        <translation>tissue_preset: ob das Band mit der Maus erreichbar ist, ist nicht bekannt: %1</translation>
    </message>
    <message>
        <source>trace.force_min_n: the band cannot be reached with the mouse at path point %1: pressing %2 mm deep (the deepest) gives as little as %3 N there, below the band&apos;s %4 N. Lower the band to at most %3 N%5, or choose a stiffer tissue preset.</source>
        <translation>trace.force_min_n: das Band ist mit der Maus an Pfadpunkt %1 nicht erreichbar: %2 mm tief gedrückt (am tiefsten) ergibt dort nur %3 N, unter den %4 N des Bands. Das Band auf höchstens %3 N senken%5 oder ein steiferes Gewebe-Preset wählen.</translation>
    </message>
    <message>
        <source>trace.force_min_n: the band %1–%2 N lies between the forces of two turns of the wheel at path point %3: widen it.</source>
        <translation>trace.force_min_n: das Band %1–%2 N liegt an Pfadpunkt %3 zwischen den Kräften zweier Raststufen des Mausrads: verbreitern.</translation>
    </message>
    <message>
        <source>Mesh unit:</source>
        <translation>Netzeinheit:</translation>
    </message>
    <message>
        <source>millimetres (mm)</source>
        <translation>Millimeter (mm)</translation>
    </message>
    <message>
        <source>centimetres (cm)</source>
        <translation>Zentimeter (cm)</translation>
    </message>
    <message>
        <source>metres (m)</source>
        <translation>Meter (m)</translation>
    </message>
    <message>
        <source>inches (in)</source>
        <translation>Zoll (in)</translation>
    </message>
    <message>
        <source>scale…</source>
        <translation>Skalierung…</translation>
    </message>
    <message>
        <source>The unit of the mesh file&apos;s coordinates (mesh_unit): a mesh from another tool may be in metres, inches or centimetres; it is scaled to mm wherever it is loaded.</source>
        <translation>Die Einheit der Koordinaten der Netzdatei (mesh_unit): Ein Netz aus einem anderen Werkzeug kann in Metern, Zoll oder Zentimetern vorliegen; es wird überall, wo es geladen wird, auf mm skaliert.</translation>
    </message>
    <message>
        <source> mm per file unit</source>
        <translation> mm je Dateieinheit</translation>
    </message>
    <message>
        <source>How many millimetres one unit of the mesh file is (mesh_unit as a number).</source>
        <translation>Wie viele Millimeter eine Einheit der Netzdatei ist (mesh_unit als Zahl).</translation>
    </message>
    <message>
        <source>mesh unit</source>
        <translation>Netzeinheit</translation>
    </message>
    <message>
        <source>mesh_unit: the viewport shows %1 read in %2, this exercise reads it in %3: press Show this mesh to place points by clicking</source>
        <translation>mesh_unit: Die Ansicht zeigt %1 in %2 gelesen, diese Übung liest es in %3: „Dieses Netz zeigen“ drücken, um Punkte per Klick zu setzen</translation>
    </message>
    <message>
        <source>Show the live score</source>
        <translation>Live-Bewertung zeigen</translation>
    </message>
    <message>
        <source>Hide the live score</source>
        <translation>Live-Bewertung ausblenden</translation>
    </message>
    <message>
        <source>press a sequence of surface targets, each with a force window and a hold.</source>
        <translation>eine Folge von Zielen auf der Oberfläche drücken, jedes mit Kraftfenster und Haltezeit.</translation>
    </message>
    <message>
        <source>find a hidden stiff inclusion by palpation and mark it.</source>
        <translation>eine verborgene steife Einlagerung ertasten und markieren.</translation>
    </message>
    <message>
        <source>trace a path on the surface, keeping the force in a band.</source>
        <translation>einem Pfad auf der Oberfläche folgen und die Kraft in einem Band halten.</translation>
    </message>
    <message>
        <source>examine the whole surface for lumps under it (or none), mark each and finish.</source>
        <translation>die ganze Oberfläche auf Knoten darunter (oder keine) untersuchen, jeden markieren und abschließen.</translation>
    </message>
    <message>
        <source>A new exercise: %1</source>
        <translation>Eine neue Übung: %1</translation>
    </message>
    <message>
        <source>Show the score while it runs</source>
        <translation>Bewertung während der Übung zeigen</translation>
    </message>
    <message>
        <source>Whether the trainee sees the score so far (show_live_score). Off by default where it would give the answer away: in detecting lumps a mark on a lump would raise it.</source>
        <translation>Ob die Lernenden die bisherige Bewertung sehen (show_live_score). Standardmäßig aus, wo sie die Antwort verraten würde: beim Erkennen von Knoten würde eine Markierung auf einem Knoten sie erhöhen.</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>The order the trainee follows.</source>
        <translation>Die Reihenfolge, der die Lernenden folgen.</translation>
    </message>
    <message>
        <source>The item&apos;s number.</source>
        <translation>Die Nummer des Eintrags.</translation>
    </message>
    <message>
        <source>Its vertex, in the mesh file&apos;s numbering (vertex).</source>
        <translation>Sein Knotenpunkt, in der Nummerierung der Netzdatei (vertex).</translation>
    </message>
    <message>
        <source>The next click on the mesh moves the selected row&apos;s point there.</source>
        <translation>Der nächste Klick auf das Netz verschiebt den Punkt der gewählten Zeile dorthin.</translation>
    </message>
    <message>
        <source>Remove the selected row (Delete).</source>
        <translation>Die gewählte Zeile entfernen (Entf).</translation>
    </message>
    <message>
        <source>Move the selected row earlier (Ctrl+Up).</source>
        <translation>Die gewählte Zeile nach vorn schieben (Strg+Hoch).</translation>
    </message>
    <message>
        <source>Move the selected row later (Ctrl+Down).</source>
        <translation>Die gewählte Zeile nach hinten schieben (Strg+Runter).</translation>
    </message>
    <message>
        <source> (start)</source>
        <translation> (Anfang)</translation>
    </message>
    <message>
        <source> (end)</source>
        <translation> (Ende)</translation>
    </message>
    <message>
        <source>Change %1&apos;s %2</source>
        <translation>%2 von %1 ändern</translation>
    </message>
    <message>
        <source>Remove %1</source>
        <translation>%1 entfernen</translation>
    </message>
    <message>
        <source>Move %1 up</source>
        <translation>%1 nach oben</translation>
    </message>
    <message>
        <source>Move %1 down</source>
        <translation>%1 nach unten</translation>
    </message>
    <message>
        <source>Click the tissue to place %1, and more after it; Esc to stop.</source>
        <translation>Klicken Sie auf das Gewebe, um %1 zu setzen, und weitere danach; Esc beendet.</translation>
    </message>
    <message>
        <source>Click the mesh where the point goes; Esc cancels.</source>
        <translation>Klicken Sie auf das Netz, wo der Punkt hin soll; Esc bricht ab.</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>%1 hinzufügen</translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>%1 verschieben</translation>
    </message>
    <message>
        <source>tissue_preset: whether the lumps can be felt is not known: %1</source>
        <translation>tissue_preset: ob die Knoten fühlbar sind, ist nicht bekannt: %1</translation>
    </message>
    <message>
        <source>%1: feeling lump %2 takes about %3 N, at or above the excessive force %4 N: the trainee who finds it is marked down for pressing too hard. Make it shallower, or raise the excessive force.</source>
        <translation>%1: um Knoten %2 zu fühlen, braucht es etwa %3 N, mindestens die übermäßige Kraft %4 N: wer ihn findet, verliert Punkte für zu starkes Drücken. Legen Sie ihn flacher, oder erhöhen Sie die übermäßige Kraft.</translation>
    </message>
    <message>
        <source>%1: feeling lump %2 takes about %3 N, more than a desktop device renders (%4 N). Make it shallower, or choose a softer tissue preset.</source>
        <translation>%1: um Knoten %2 zu fühlen, braucht es etwa %3 N, mehr als ein Desktop-Gerät ausgibt (%4 N). Legen Sie ihn flacher, oder wählen Sie eine weichere Gewebevorgabe.</translation>
    </message>
    <message>
        <source>%1: lump %2 cannot be felt with the mouse: the surface above it does not sink to its top (%3 mm under it) however deep the mouse presses. Make it shallower, or choose a softer tissue preset.</source>
        <translation>%1: Knoten %2 ist mit der Maus nicht fühlbar: die Oberfläche darüber sinkt nicht bis zu seiner Oberseite (%3 mm darunter), wie tief die Maus auch drückt. Legen Sie ihn flacher, oder wählen Sie eine weichere Gewebevorgabe.</translation>
    </message>
    <message>
        <source>%1: lump %2 cannot be felt with the mouse: its top lies %3 mm under the surface; the surface sinks that far under a press %4 mm deep, and the lump is felt a wheel step (%5 mm) deeper, but the mouse presses at most %6 mm deep. Make it at most %7 mm deep, or train this one with a device.</source>
        <translation>%1: Knoten %2 ist mit der Maus nicht fühlbar: seine Oberseite liegt %3 mm unter der Oberfläche; die Oberfläche sinkt bei einem %4 mm tiefen Druck so weit ein, und der Knoten ist einen Radschritt (%5 mm) tiefer fühlbar, aber die Maus drückt höchstens %6 mm tief. Legen Sie ihn höchstens %7 mm tief, oder üben Sie diesen mit einem Gerät.</translation>
    </message>
    <message>
        <source>tissue_preset: whether the mouse presses hard enough to examine is not known: %1</source>
        <translation>tissue_preset: ob die Maus fest genug drückt, um zu untersuchen, ist nicht bekannt: %1</translation>
    </message>
    <message>
        <source>Copied %1 beside it, so that the exercise opens on other computers.</source>
        <translation>%1 daneben kopiert, damit die Übung auf anderen Rechnern öffnet.</translation>
    </message>
    <message>
        <source>coverage.min_force_n: the mouse cannot examine this tissue: pressing %1 mm deep (the deepest) gives %2 N over most of the surface, below the examining force %3 N, so nothing the trainee does counts as examined. Lower it to %4 N (what the mouse&apos;s default press gives), or choose a stiffer tissue preset.</source>
        <translation>coverage.min_force_n: mit der Maus lässt sich dieses Gewebe nicht untersuchen: ein %1 mm tiefer Druck (der tiefste) gibt auf dem größten Teil der Oberfläche %2 N, unter der Untersuchungskraft %3 N, sodass nichts, was die Lernenden tun, als untersucht zählt. Senken Sie sie auf %4 N (was der voreingestellte Druck der Maus gibt), oder wählen Sie eine steifere Gewebevorgabe.</translation>
    </message>
    <message>
        <source>Export Bundle…</source>
        <translation>Paket exportieren…</translation>
    </message>
    <message>
        <source>Write the exercise with its mesh, preset and scripted paths as one file, to open on a trainee&apos;s computer (Exercise &gt; Open Exercise…).</source>
        <translation>Die Übung mit Netz, Gewebevorgabe und vorgegebenen Pfaden als eine Datei schreiben, zum Öffnen auf dem Rechner der Lernenden (Übung &gt; Übung öffnen…).</translation>
    </message>
    <message>
        <source>Bundle not written:</source>
        <translation>Paket nicht geschrieben:</translation>
    </message>
    <message>
        <source>Bundle written: %1, with the exercise&apos;s mesh, preset and scripted paths.</source>
        <translation>Paket geschrieben: %1, mit Netz, Gewebevorgabe und vorgegebenen Pfaden der Übung.</translation>
    </message>
    <message>
        <source>Export exercise bundle</source>
        <translation>Übungspaket exportieren</translation>
    </message>
    <message>
        <source>Exercise bundles (*.palpex)</source>
        <translation>Übungspakete (*.palpex)</translation>
    </message>
    <message>
        <source> (%1–%2 N is met pressing at least two wheel steps past the default touch)</source>
        <translation> (%1–%2 N werden mindestens zwei Mausradstufen tiefer als die Standardberührung erreicht)</translation>
    </message>
    <message>
        <source>Text in:</source>
        <translation>Text auf:</translation>
    </message>
    <message>
        <source>Which language&apos;s name and description you edit: the exercise&apos;s own, or a translation trainees who use Palpate in that language see (translations). An empty translation shows the exercise&apos;s own words.</source>
        <translation>Welche Sprache Sie bei Name und Beschreibung bearbeiten: die eigenen Worte der Übung oder eine Übersetzung, die Lernende sehen, die Palpate in dieser Sprache verwenden (translations). Eine leere Übersetzung zeigt die eigenen Worte der Übung.</translation>
    </message>
    <message>
        <source>Its own words</source>
        <translation>Eigene Worte</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Checking whether the mouse can do what the exercise asks…</source>
        <translation>Es wird geprüft, ob die Maus schafft, was die Übung verlangt …</translation>
    </message>
</context>
<context>
    <name>palpate::ExerciseMarkers</name>
    <message>
        <source>examined from %1 N to %2 N (excessive)</source>
        <translation>untersucht ab %1 N bis %2 N (übermäßig)</translation>
    </message>
</context>
<context>
    <name>palpate::Exercises</name>
    <message>
        <source>Detect lumps</source>
        <translation>Knoten finden</translation>
    </message>
    <message>
        <source>Find the lump</source>
        <translation>Die Verhärtung finden</translation>
    </message>
    <message>
        <source>Press targets</source>
        <translation>Ziele drücken</translation>
    </message>
    <message>
        <source>Trace a path</source>
        <translation>Einem Pfad folgen</translation>
    </message>
    <message>
        <source>lump %1, %2 mm deep</source>
        <translation>Knoten %1, %2 mm tief</translation>
    </message>
    <message>
        <source>Mark a lump where the tool presses now (M)</source>
        <translation>Einen Knoten dort markieren, wo das Werkzeug jetzt drückt (M)</translation>
    </message>
    <message>
        <source>Search the whole surface, press in where it feels different, Mark (M) each lump; Finish (F7) when done</source>
        <translation>Die ganze Oberfläche absuchen, wo es sich anders anfühlt eindrücken, jeden Knoten markieren (M); zum Schluss Beenden (F7)</translation>
    </message>
    <message numerus="yes">
        <source>%n finding(s) marked</source>
        <translation>
            <numerusform>%n Befund markiert</numerusform>
            <numerusform>%n Befunde markiert</numerusform>
        </translation>
    </message>
    <message>
        <source>in contact</source>
        <translation>in Kontakt</translation>
    </message>
    <message>
        <source>not in contact</source>
        <translation>nicht in Kontakt</translation>
    </message>
    <message>
        <source>surface examined %p%</source>
        <translation>Oberfläche untersucht %p%</translation>
    </message>
    <message>
        <source>lump</source>
        <translation>Verhärtung</translation>
    </message>
    <message>
        <source>Marked. Mark again to correct, or Stop to finish.</source>
        <translation>Markiert. Erneut markieren, um zu korrigieren, oder „Stoppen“, um abzuschließen.</translation>
    </message>
    <message>
        <source>Palpate gently; press Mark (M) while you press on the lump</source>
        <translation>Behutsam abtasten; „Markieren“ (M) drücken, während Sie auf die Verhärtung drücken</translation>
    </message>
    <message>
        <source>In contact</source>
        <translation>In Kontakt</translation>
    </message>
    <message>
        <source>Not in contact</source>
        <translation>Kein Kontakt</translation>
    </message>
    <message>
        <source>marked</source>
        <translation>markiert</translation>
    </message>
    <message>
        <source>not marked yet</source>
        <translation>noch nicht markiert</translation>
    </message>
    <message>
        <source>Target %1 of %2: press with %3 and hold</source>
        <translation>Ziel %1 von %2: mit %3 drücken und halten</translation>
    </message>
    <message>
        <source>On target</source>
        <translation>Auf dem Ziel</translation>
    </message>
    <message>
        <source>Move to the blue marker (%1 mm away)</source>
        <translation>Zur blauen Markierung bewegen (%1 mm entfernt)</translation>
    </message>
    <message>
        <source>hold %p%</source>
        <translation>halten %p%</translation>
    </message>
    <message>
        <source>All targets done</source>
        <translation>Alle Ziele erledigt</translation>
    </message>
    <message>
        <source>No target left</source>
        <translation>Kein Ziel mehr</translation>
    </message>
    <message>
        <source>start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>end</source>
        <translation>Ende</translation>
    </message>
    <message>
        <source>Follow the line with %1</source>
        <translation>Der Linie mit %1 folgen</translation>
    </message>
    <message>
        <source>%1 mm from the line</source>
        <translation>%1 mm von der Linie</translation>
    </message>
    <message>
        <source>covered %p%</source>
        <translation>abgedeckt %p%</translation>
    </message>
    <message>
        <source>lighter than %1 N counts as not examined: press deeper (with the mouse: scroll the wheel)</source>
        <translation>leichter als %1 N gilt als nicht untersucht: tiefer drücken (mit der Maus: Mausrad drehen)</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <source>The lump&apos;s radius, mm (radius_mm).</source>
        <translation>Der Radius des Knotens, mm (radius_mm).</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>Tiefe</translation>
    </message>
    <message>
        <source>From the surface to the lump&apos;s top, mm (depth_mm): a deeper lump needs a firmer press to be felt.</source>
        <translation>Von der Oberfläche bis zur Oberseite des Knotens, mm (depth_mm): ein tieferer Knoten braucht festeren Druck, um gefühlt zu werden.</translation>
    </message>
    <message>
        <source>Contrast</source>
        <translation>Kontrast</translation>
    </message>
    <message>
        <source>How many times stiffer than the tissue the lump is (contrast), above 1: lower is harder to feel.</source>
        <translation>Wie viel Mal steifer als das Gewebe der Knoten ist (contrast), über 1: niedriger ist schwerer zu fühlen.</translation>
    </message>
    <message>
        <source>Mark within:</source>
        <translation>Markieren innerhalb:</translation>
    </message>
    <message>
        <source>A mark this far outside a lump&apos;s radius still finds it, mm (detect_lumps.tolerance_mm).</source>
        <translation>Eine Markierung so weit außerhalb des Knotenradius findet ihn noch, mm (detect_lumps.tolerance_mm).</translation>
    </message>
    <message>
        <source>Lump %1</source>
        <translation>Knoten %1</translation>
    </message>
    <message>
        <source>While on, each click on the tissue hides a lump under it, with the last lump&apos;s radius, depth and contrast (Esc stops). No lumps: healthy tissue, where reporting nothing is the finding.</source>
        <translation>Solange an, verbirgt jeder Klick auf das Gewebe einen Knoten darunter, mit Radius, Tiefe und Kontrast des letzten Knotens (Esc beendet). Keine Knoten: gesundes Gewebe, wo nichts zu melden der Befund ist.</translation>
    </message>
    <message>
        <source>Vertices this close to the centre are in the inclusion (find_lump.inclusion.radius_mm).</source>
        <translation>Knotenpunkte so nah am Mittelpunkt gehören zur Einlagerung (find_lump.inclusion.radius_mm).</translation>
    </message>
    <message>
        <source>Stiffness</source>
        <translation>Steifigkeit</translation>
    </message>
    <message>
        <source>The inclusion&apos;s slopes are multiplied by this, in (0, 1]: smaller is stiffer (find_lump.inclusion.stiffness_factor).</source>
        <translation>Die Steigungen der Einlagerung werden hiermit multipliziert, in (0, 1]: kleiner ist steifer (find_lump.inclusion.stiffness_factor).</translation>
    </message>
    <message>
        <source>Inclusion</source>
        <translation>Einlagerung</translation>
    </message>
    <message>
        <source>The next click on the mesh puts the inclusion&apos;s centre there.</source>
        <translation>Der nächste Klick auf das Netz setzt den Mittelpunkt der Einlagerung dorthin.</translation>
    </message>
    <message>
        <source>Examined from:</source>
        <translation>Untersucht ab:</translation>
    </message>
    <message>
        <source>A contact lighter than this examines nothing (coverage.min_force_n): keep it within the trainee&apos;s reach (the gauge shows it).</source>
        <translation>Ein leichterer Kontakt untersucht nichts (coverage.min_force_n): halten Sie ihn in Reichweite der Lernenden (die Anzeige zeigt ihn).</translation>
    </message>
    <message>
        <source>Examined around:</source>
        <translation>Untersucht im Umkreis:</translation>
    </message>
    <message>
        <source>A contact examines the surface this close to it, mm (coverage.radius_mm).</source>
        <translation>Ein Kontakt untersucht die Oberfläche so nah um ihn, mm (coverage.radius_mm).</translation>
    </message>
    <message>
        <source>Fmin</source>
        <translation>Fmin</translation>
    </message>
    <message>
        <source>The force window&apos;s lower end, N (force_min_n).</source>
        <translation>Unteres Ende des Kraftfensters, N (force_min_n).</translation>
    </message>
    <message>
        <source>Fmax</source>
        <translation>Fmax</translation>
    </message>
    <message>
        <source>The force window&apos;s upper end, N (force_max_n).</source>
        <translation>Oberes Ende des Kraftfensters, N (force_max_n).</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Halten</translation>
    </message>
    <message>
        <source>How long the force must stay in the window without a break, s (hold_s).</source>
        <translation>Wie lange die Kraft ohne Unterbrechung im Fenster bleiben muss, s (hold_s).</translation>
    </message>
    <message>
        <source>Tol.</source>
        <translation>Tol.</translation>
    </message>
    <message>
        <source>How close to the target the contact must be, mm (tolerance_mm).</source>
        <translation>Wie nah am Ziel der Kontakt sein muss, mm (tolerance_mm).</translation>
    </message>
    <message>
        <source>Target %1</source>
        <translation>Ziel %1</translation>
    </message>
    <message>
        <source>While on, each click on the tissue appends a target there, with the last target&apos;s window, hold and tolerance; the first gets a window the tissue reaches with the mouse (Esc stops).</source>
        <translation>Solange an, fügt jeder Klick auf das Gewebe dort ein Ziel an, mit Fenster, Haltezeit und Toleranz des letzten Ziels; das erste erhält ein Fenster, das das Gewebe mit der Maus erreicht (Esc beendet).</translation>
    </message>
    <message>
        <source>Band from:</source>
        <translation>Band von:</translation>
    </message>
    <message>
        <source>The force band&apos;s lower end (trace.force_min_n).</source>
        <translation>Unteres Ende des Kraftbands (trace.force_min_n).</translation>
    </message>
    <message>
        <source>Band to:</source>
        <translation>Band bis:</translation>
    </message>
    <message>
        <source>The force band&apos;s upper end (trace.force_max_n).</source>
        <translation>Oberes Ende des Kraftbands (trace.force_max_n).</translation>
    </message>
    <message>
        <source>Tolerance:</source>
        <translation>Toleranz:</translation>
    </message>
    <message>
        <source>A path point is covered by contact this close to it (trace.tolerance_mm).</source>
        <translation>Ein Pfadpunkt gilt als abgedeckt bei Kontakt so nah an ihm (trace.tolerance_mm).</translation>
    </message>
    <message>
        <source>Path point %1</source>
        <translation>Pfadpunkt %1</translation>
    </message>
    <message>
        <source>While on, each click on the tissue appends a path point there; the first sets a band the tissue reaches with the mouse, if the band is still the default (Esc stops).</source>
        <translation>Solange an, fügt jeder Klick auf das Gewebe dort einen Pfadpunkt an; der erste setzt ein Band, das das Gewebe mit der Maus erreicht, wenn das Band noch der Standard ist (Esc beendet).</translation>
    </message>
</context>
<context>
    <name>palpate::FeelChart</name>
    <message>
        <source>No feel bench yet</source>
        <translation>Noch kein Haptik-Benchmark</translation>
    </message>
    <message>
        <source>a slide at %1 mm depth, %2 mm/s (circles: sphere, squares: stomach); goal: step ≤ %3 % of the mean force (dashed)</source>
        <translation>Gleiten in %1 mm Tiefe, %2 mm/s (Kreise: Kugel, Quadrate: Magen); Ziel: Sprung ≤ %3 % der mittleren Kraft (gestrichelt)</translation>
    </message>
    <message>
        <source>What the hand feels: force step against tick cost</source>
        <translation>Was die Hand spürt: Kraftsprung gegen Tick-Aufwand</translation>
    </message>
    <message>
        <source>sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <source>stomach</source>
        <translation>Magen</translation>
    </message>
    <message>
        <source>goal</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Tick cost (× the paper&apos;s previous method, log scale)</source>
        <translation>Tick-Aufwand (× Methode „previous“ des Artikels, log. Skala)</translation>
    </message>
    <message>
        <source>Tick cost (µs, log scale)</source>
        <translation>Tick-Aufwand (µs, log. Skala)</translation>
    </message>
    <message>
        <source>Largest force step (% of the mean force, log scale)</source>
        <translation>Größter Kraftsprung (% der mittleren Kraft, log. Skala)</translation>
    </message>
    <message>
        <source>goal: step ≤ %1 %</source>
        <translation>Ziel: Sprung ≤ %1 %</translation>
    </message>
    <message>
        <source>%1, %2 %3 vertices
largest step %4 % (normal %5 %), ripple %6 %
tick %7 µs, %8x faster than previous</source>
        <translation>%1, %2 %3 Knoten
größter Sprung %4 % (normal %5 %), Welligkeit %6 %
Tick %7 µs, %8-mal schneller als previous</translation>
    </message>
    <message>
        <source>Tick cost (× previous, log)</source>
        <translation>Tick-Aufwand (× previous, log)</translation>
    </message>
    <message>
        <source>Tick cost (µs, log)</source>
        <translation>Tick-Aufwand (µs, log)</translation>
    </message>
    <message>
        <source>Largest step (% of mean force)</source>
        <translation>Größter Sprung (% der mittleren Kraft)</translation>
    </message>
    <message>
        <source>Feel: force step against tick cost</source>
        <translation>Haptik: Kraftsprung gegen Tick-Aufwand</translation>
    </message>
    <message>
        <source>slide %1 mm deep at %2 mm/s; goal: step ≤ %3 % (dashed)</source>
        <translation>Gleiten %1 mm tief mit %2 mm/s; Ziel: Sprung ≤ %3 % (gestrichelt)</translation>
    </message>
</context>
<context>
    <name>palpate::FeelPanel</name>
    <message>
        <source>No feel bench loaded: palpate-cli bench feel --csv FILE, then Open feel CSV</source>
        <translation>Kein Haptik-Benchmark geladen: palpate-cli bench feel --csv DATEI, dann Haptik-CSV öffnen</translation>
    </message>
    <message>
        <source>&amp;Open feel CSV…</source>
        <translation>Haptik-CSV &amp;öffnen…</translation>
    </message>
    <message>
        <source>Show a feel bench saved as CSV (palpate-cli bench feel --csv): every model&apos;s largest force step while sliding at constant depth, against its tick cost.</source>
        <translation>Einen als CSV gespeicherten Haptik-Benchmark zeigen (palpate-cli bench feel --csv): größter Kraftsprung jedes Modells beim Gleiten in konstanter Tiefe, gegen seinen Tick-Aufwand.</translation>
    </message>
    <message>
        <source>Tick &amp;cost:</source>
        <translation>Tick-&amp;Aufwand:</translation>
    </message>
    <message>
        <source>× previous</source>
        <translation>× previous</translation>
    </message>
    <message>
        <source>µs</source>
        <translation>µs</translation>
    </message>
    <message>
        <source>The tick cost as a fraction of the paper&apos;s previous method&apos;s, measured in the same run on the same mesh, or in microseconds on the machine that ran the bench.</source>
        <translation>Der Tick-Aufwand als Anteil an dem der Methode „previous“ des Artikels, im selben Lauf auf demselben Netz gemessen, oder in Mikrosekunden auf dem Rechner, auf dem der Benchmark lief.</translation>
    </message>
    <message>
        <source>Loaded %1: %2 of %3 points above the goal (step ≤ %4 % of the mean force).</source>
        <translation>%1 geladen: %2 von %3 Punkten über dem Ziel (Sprung ≤ %4 % der mittleren Kraft).</translation>
    </message>
    <message>
        <source>%1: cannot be read (%2)</source>
        <translation>%1: kann nicht gelesen werden (%2)</translation>
    </message>
    <message>
        <source>%1: no rows (only the header)</source>
        <translation>%1: keine Zeilen (nur die Kopfzeile)</translation>
    </message>
    <message>
        <source>Open feel CSV</source>
        <translation>Haptik-CSV öffnen</translation>
    </message>
    <message>
        <source>Feel bench CSV (*.csv);;All files (*)</source>
        <translation>Haptik-Benchmark-CSV (*.csv);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>palpate::FirstRun</name>
    <message>
        <source>Cannot open the sample scene</source>
        <translation>Die Beispielszene kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>The sample mesh %1 was not found (set PALPATE_RESOURCES).</source>
        <translation>Das Beispielnetz %1 wurde nicht gefunden (PALPATE_RESOURCES setzen).</translation>
    </message>
    <message>
        <source>Cannot start touch mode</source>
        <translation>Der Tastmodus kann nicht gestartet werden</translation>
    </message>
    <message>
        <source>Touch mode: left-drag presses the tissue, the wheel sets the depth, right-drag turns the view.</source>
        <translation>Tastmodus: Ziehen mit der linken Maustaste drückt das Gewebe, das Mausrad stellt die Tiefe ein, Ziehen mit der rechten Maustaste dreht die Ansicht.</translation>
    </message>
    <message>
        <source>Cannot run the example exercise</source>
        <translation>Die Beispielübung kann nicht gestartet werden</translation>
    </message>
    <message>
        <source>The example exercise exercises/press_targets.json was not found (set PALPATE_RESOURCES).</source>
        <translation>Die Beispielübung exercises/press_targets.json wurde nicht gefunden (PALPATE_RESOURCES setzen).</translation>
    </message>
    <message>
        <source>Haptic rate not applied</source>
        <translation>Haptikrate nicht übernommen</translation>
    </message>
    <message>
        <source>User Guide</source>
        <translation>Benutzerhandbuch</translation>
    </message>
    <message>
        <source>The user guide (user-guide.md) was not found. It is installed in share/doc/palpate; in a source tree it is docs/user-guide.md.</source>
        <translation>Das Benutzerhandbuch (user-guide.md) wurde nicht gefunden. Es wird in share/doc/palpate installiert; in einem Quellbaum liegt es in docs/user-guide.md.</translation>
    </message>
    <message>
        <source>Palpate User Guide</source>
        <translation>Palpate-Benutzerhandbuch</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>&amp;Einstellungen…</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <source>&amp;Welcome</source>
        <translation>&amp;Willkommen</translation>
    </message>
</context>
<context>
    <name>palpate::ForceGauge</name>
    <message>
        <source>Force gauge</source>
        <translation>Kraftanzeige</translation>
    </message>
    <message>
        <source>%1 N</source>
        <translation>%1 N</translation>
    </message>
    <message>
        <source>excessive ≥ %1 N ▸</source>
        <translation>zu stark ≥ %1 N ▸</translation>
    </message>
    <message>
        <source>Force gauge faded out: feel the force</source>
        <translation>Kraftanzeige ausgeblendet: spüren Sie die Kraft</translation>
    </message>
    <message>
        <source>The blue line: a press at or above %1 N counts as examined.</source>
        <translation>Die blaue Linie: ein Druck ab %1 N gilt als untersucht.</translation>
    </message>
</context>
<context>
    <name>palpate::GuiApplication</name>
    <message>
        <source>%1 (while %2 handled an event; the window goes on)</source>
        <translation>%1 (während %2 ein Ereignis bearbeitete; das Fenster läuft weiter)</translation>
    </message>
    <message>
        <source>an unknown error (the window goes on)</source>
        <translation>ein unbekannter Fehler (das Fenster läuft weiter)</translation>
    </message>
    <message>
        <source>Palpate</source>
        <translation>Palpate</translation>
    </message>
</context>
<context>
    <name>palpate::HistoryPanel</name>
    <message>
        <source>Trainee:</source>
        <translation>Teilnehmer:</translation>
    </message>
    <message>
        <source>Trainee</source>
        <translation>Teilnehmer</translation>
    </message>
    <message>
        <source>When</source>
        <translation>Wann</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Übung</translation>
    </message>
    <message>
        <source>Score</source>
        <translation>Punktzahl</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>Report PDF…</source>
        <translation>PDF-Bericht…</translation>
    </message>
    <message>
        <source>Re-scores the result&apos;s recording and writes its PDF report</source>
        <translation>Bewertet die Aufnahme des Ergebnisses neu und schreibt ihren PDF-Bericht</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Wiedergabe</translation>
    </message>
    <message>
        <source>Opens the result&apos;s recording in the Recorder</source>
        <translation>Öffnet die Aufnahme des Ergebnisses im Rekorder</translation>
    </message>
    <message>
        <source>Scores of %1</source>
        <translation>Punktzahlen von %1</translation>
    </message>
    <message>
        <source>No trainee yet</source>
        <translation>Noch kein Teilnehmer</translation>
    </message>
    <message>
        <source>No trainees yet: add one in the Exercise dock.</source>
        <translation>Noch keine Teilnehmer: legen Sie im Dock „Übung“ einen an.</translation>
    </message>
    <message>
        <source>No results yet.</source>
        <translation>Noch keine Ergebnisse.</translation>
    </message>
    <message>
        <source>Session</source>
        <translation>Sitzung</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>Stopped before the end: %1 points so far, not a score (not in the best or the mean)</source>
        <translation>Vor dem Ende abgebrochen: bis dahin %1 Punkte, kein Ergebnis (nicht im Besten oder im Mittel)</translation>
    </message>
    <message>
        <source>The time limit passed before the task was done</source>
        <translation>Die Zeit lief ab, bevor die Aufgabe erledigt war</translation>
    </message>
    <message>
        <source>%1, %2 to %3</source>
        <translation>%1, %2 bis %3</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>%1 bis %2</translation>
    </message>
    <message numerus="yes">
        <source>%n session(s) (%1); none scored</source>
        <translation>
            <numerusform>%n Sitzung (%1); keine bewertet</numerusform>
            <numerusform>%n Sitzungen (%1); keine bewertet</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>(%n stopped, not counted)</source>
        <translation>
            <numerusform>(%n abgebrochen, nicht gezählt)</numerusform>
            <numerusform>(%n abgebrochen, nicht gezählt)</numerusform>
        </translation>
    </message>
    <message>
        <source>Learning Curve…</source>
        <translation>Lernkurve…</translation>
    </message>
    <message>
        <source>The trainee&apos;s sessions of the selected result&apos;s exercise against the experts&apos; pass marks</source>
        <translation>Die Sitzungen der lernenden Person in der Übung des gewählten Ergebnisses, gegen die Bestehensgrenzen der Experten</translation>
    </message>
    <message>
        <source>Learning curve</source>
        <translation>Lernkurve</translation>
    </message>
    <message>
        <source>Select a session first.</source>
        <translation>Wählen Sie zuerst eine Sitzung.</translation>
    </message>
    <message>
        <source>This session names no exercise file to draw the curve of.</source>
        <translation>Diese Sitzung nennt keine Übungsdatei, deren Kurve gezeichnet werden könnte.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 has no scored sessions of this exercise to draw.</source>
        <translation>%1 hat keine bewerteten Sitzungen dieser Übung zum Zeichnen.</translation>
    </message>
    <message>
        <source>%1: best %2, mean %3</source>
        <translation>%1: bestes %2, Mittel %3</translation>
    </message>
    <message>
        <source>1 session (%1)</source>
        <translation>1 Sitzung (%1)</translation>
    </message>
    <message>
        <source>%1 sessions (%2)</source>
        <translation>%1 Sitzungen (%2)</translation>
    </message>
    <message>
        <source>&amp;Show:</source>
        <translation>&amp;Zeigen:</translation>
    </message>
    <message>
        <source>- proficient at session %1</source>
        <translation>- kompetent ab Sitzung %1</translation>
    </message>
    <message>
        <source>- not yet proficient</source>
        <translation>- noch nicht kompetent</translation>
    </message>
    <message>
        <source>- no expert standard yet: the pass marks come from experts&apos; sessions</source>
        <translation>- noch kein Expertenstandard: die Bestehensgrenzen kommen aus Sitzungen von Experten</translation>
    </message>
</context>
<context>
    <name>palpate::Language</name>
    <message>
        <source>en</source>
        <comment>The code of the language of this translation: de, ms. Exercise files carry their name and description under it.</comment>
        <translation>de</translation>
    </message>
</context>
<context>
    <name>palpate::LodPanel</name>
    <message>
        <source>1 ring</source>
        <translation>1 Ring</translation>
    </message>
    <message>
        <source>%1 rings</source>
        <translation>%1 Ringe</translation>
    </message>
    <message>
        <source>Targets</source>
        <translation>Ziele</translation>
    </message>
    <message>
        <source>Levels and rings</source>
        <translation>Stufen und Ringe</translation>
    </message>
    <message>
        <source>Max &amp;error:</source>
        <translation>Max. &amp;Fehler:</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>The displacement error allowed: RMS over the loaded region divided by the peak displacement, measured on the displayed (source) surface. 10 % is 0.1.</source>
        <translation>Der erlaubte Verschiebungsfehler: RMS über den belasteten Bereich geteilt durch die maximale Verschiebung, gemessen auf der angezeigten (Quell-)Oberfläche. 10 % ist 0,1.</translation>
    </message>
    <message>
        <source>Tick &amp;budget:</source>
        <translation>Tick-&amp;Budget:</translation>
    </message>
    <message>
        <source> µs</source>
        <translation> µs</translation>
    </message>
    <message>
        <source>The time one haptic tick may take on this machine, in microseconds (a 1 kHz loop has 1000 µs per tick for everything).</source>
        <translation>Die Zeit, die ein Haptik-Tick auf diesem Rechner dauern darf, in Mikrosekunden (eine 1-kHz-Schleife hat 1000 µs pro Tick für alles).</translation>
    </message>
    <message>
        <source>&amp;Plan</source>
        <translation>&amp;Planen</translation>
    </message>
    <message>
        <source>Make (or read from the cache next to the mesh) the coarser levels, measure every level and ring count on this machine and choose.</source>
        <translation>Die gröberen Stufen erzeugen (oder aus dem Cache neben dem Netz lesen), jede Stufe und Ringanzahl auf diesem Rechner messen und wählen.</translation>
    </message>
    <message>
        <source>&amp;Store targets in preset</source>
        <translation>Ziele in Vorgabe &amp;speichern</translation>
    </message>
    <message>
        <source>Write these targets into the current tissue preset as its &quot;needs&quot;.</source>
        <translation>Diese Ziele als „needs“ in die aktuelle Gewebevorgabe schreiben.</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>&amp;Abbrechen</translation>
    </message>
    <message>
        <source>Stop after the candidate being measured; what was measured so far is planned.</source>
        <translation>Nach dem gerade gemessenen Kandidaten anhalten; das bisher Gemessene wird geplant.</translation>
    </message>
    <message>
        <source>&amp;Use chosen</source>
        <translation>Auswahl &amp;verwenden</translation>
    </message>
    <message>
        <source>Load the planner&apos;s choice: its level&apos;s mesh and ring count.</source>
        <translation>Die Wahl des Planers laden: das Netz ihrer Stufe und die Ringanzahl.</translation>
    </message>
    <message>
        <source>Use selected (&amp;override)</source>
        <translation>Markierte verwenden (&amp;überschreiben)</translation>
    </message>
    <message>
        <source>Load the row selected in the table instead of the planner&apos;s choice.</source>
        <translation>Die in der Tabelle markierte Zeile statt der Wahl des Planers laden.</translation>
    </message>
    <message>
        <source>Level</source>
        <translation>Stufe</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>Rings</source>
        <translation>Ringe</translation>
    </message>
    <message>
        <source>Error %</source>
        <translation>Fehler %</translation>
    </message>
    <message>
        <source>Tick µs</source>
        <translation>Tick µs</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Urteil</translation>
    </message>
    <message>
        <source>0 is the mesh itself; each further level keeps about half the vertices of the one before.</source>
        <translation>0 ist das Netz selbst; jede weitere Stufe behält etwa die Hälfte der Knoten der vorigen.</translation>
    </message>
    <message>
        <source>Vertices of the level&apos;s mesh.</source>
        <translation>Knoten des Netzes der Stufe.</translation>
    </message>
    <message>
        <source>Rings of neighbours the slope-ring model moves around the touched vertex.</source>
        <translation>Ringe von Nachbarn, die das Slope-Ring-Modell um den berührten Knoten bewegt.</translation>
    </message>
    <message>
        <source>Displacement error against the flat-punch reference on the displayed surface (RMS / peak, in %); ✓ within the max error, ✗ above it.</source>
        <translation>Verschiebungsfehler gegenüber der Flachstempel-Referenz auf der angezeigten Oberfläche (RMS / Spitze, in %); ✓ innerhalb des max. Fehlers, ✗ darüber.</translation>
    </message>
    <message>
        <source>Median time of one haptic tick on this machine, in microseconds; ✓ within the budget, ✗ over it.</source>
        <translation>Medianzeit eines Haptik-Ticks auf diesem Rechner, in Mikrosekunden; ✓ innerhalb des Budgets, ✗ darüber.</translation>
    </message>
    <message>
        <source>The planner&apos;s choice, the closest when nothing fits, or your override.</source>
        <translation>Die Wahl des Planers, die nächstliegende, wenn nichts passt, oder Ihre Überschreibung.</translation>
    </message>
    <message>
        <source>Max error: %1 % is absurd (at most %2 %).</source>
        <translation>Max. Fehler: %1 % ist absurd (höchstens %2 %).</translation>
    </message>
    <message>
        <source>Max error: must be above 0 % (it is %1 %).</source>
        <translation>Max. Fehler: muss über 0 % liegen (er ist %1 %).</translation>
    </message>
    <message>
        <source>Tick budget: %1 µs is absurd (at most %2 µs).</source>
        <translation>Tick-Budget: %1 µs ist absurd (höchstens %2 µs).</translation>
    </message>
    <message>
        <source>Tick budget: must be above 0 µs (it is %1 µs).</source>
        <translation>Tick-Budget: muss über 0 µs liegen (es ist %1 µs).</translation>
    </message>
    <message>
        <source>No scene yet.</source>
        <translation>Noch keine Szene.</translation>
    </message>
    <message>
        <source>Targets edited here (the scene&apos;s were %1 % and %2 µs). Store them in the preset to keep them.</source>
        <translation>Ziele hier bearbeitet (die der Szene waren %1 % und %2 µs). In der Vorgabe speichern, um sie zu behalten.</translation>
    </message>
    <message>
        <source>Targets edited here. Store them in the preset to keep them.</source>
        <translation>Ziele hier bearbeitet. In der Vorgabe speichern, um sie zu behalten.</translation>
    </message>
    <message>
        <source>Targets from the scene.</source>
        <translation>Ziele aus der Szene.</translation>
    </message>
    <message>
        <source>Targets from %1.</source>
        <translation>Ziele aus %1.</translation>
    </message>
    <message>
        <source>The scene states no targets: these are the panel&apos;s defaults.</source>
        <translation>Die Szene nennt keine Ziele: dies sind die Vorgaben des Bereichs.</translation>
    </message>
    <message>
        <source>No mesh file: the levels are cached next to the scene&apos;s mesh file.</source>
        <translation>Keine Netzdatei: die Stufen werden neben der Netzdatei der Szene zwischengespeichert.</translation>
    </message>
    <message>
        <source>Fix the targets first: %1</source>
        <translation>Zuerst die Ziele korrigieren: %1</translation>
    </message>
    <message>
        <source>Cannot measure: %1</source>
        <translation>Messen nicht möglich: %1</translation>
    </message>
    <message>
        <source>Loading the mesh…</source>
        <translation>Netz wird geladen…</translation>
    </message>
    <message>
        <source>Looking for cached levels…</source>
        <translation>Suche nach zwischengespeicherten Stufen…</translation>
    </message>
    <message>
        <source>Generating 1 coarser level: decimating</source>
        <translation>Erzeuge 1 gröbere Stufe: Dezimierung</translation>
    </message>
    <message>
        <source>Generating %1 coarser levels: decimating</source>
        <translation>Erzeuge %1 gröbere Stufen: Dezimierung</translation>
    </message>
    <message>
        <source>Generating levels %1/%2: mapping to the mesh</source>
        <translation>Erzeuge Stufen %1/%2: Abbildung auf das Netz</translation>
    </message>
    <message>
        <source>Reading cached level %1</source>
        <translation>Lese zwischengespeicherte Stufe %1</translation>
    </message>
    <message>
        <source>Levels ready</source>
        <translation>Stufen bereit</translation>
    </message>
    <message>
        <source>Measuring level %1 (%2 vertices), %3: %4 of %5</source>
        <translation>Messe Stufe %1 (%2 Knoten), %3: %4 von %5</translation>
    </message>
    <message>
        <source>Measured %1 candidates</source>
        <translation>%1 Kandidaten gemessen</translation>
    </message>
    <message>
        <source>unknown error</source>
        <translation>unbekannter Fehler</translation>
    </message>
    <message>
        <source>Planning started…</source>
        <translation>Planung gestartet…</translation>
    </message>
    <message>
        <source>Cancelling: the candidate being measured finishes first…</source>
        <translation>Abbruch: der gerade gemessene Kandidat wird zuerst fertig…</translation>
    </message>
    <message>
        <source>Plan failed: %1</source>
        <translation>Planung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Levels (%1 vertices) read from the cache %2 next to the mesh.</source>
        <translation>Stufen (%1 Knoten) aus dem Cache %2 neben dem Netz gelesen.</translation>
    </message>
    <message>
        <source>Levels (%1 vertices) generated: %2.</source>
        <translation>Stufen (%1 Knoten) erzeugt: %2.</translation>
    </message>
    <message>
        <source>The cache could not be written (%1): the levels other than 0 cannot be used.</source>
        <translation>Der Cache konnte nicht geschrieben werden (%1): die Stufen außer 0 sind nicht verwendbar.</translation>
    </message>
    <message>
        <source>Planned in %1 s: %2 candidates measured on this machine.</source>
        <translation>In %1 s geplant: %2 Kandidaten auf diesem Rechner gemessen.</translation>
    </message>
    <message>
        <source>Cancelled after %1 of %2 candidates: the table is partial and the plan is made from them only.</source>
        <translation>Nach %1 von %2 Kandidaten abgebrochen: die Tabelle ist unvollständig, und die Planung beruht nur auf ihnen.</translation>
    </message>
    <message>
        <source>Not measured: %1</source>
        <translation>Nicht gemessen: %1</translation>
    </message>
    <message>
        <source>n/a</source>
        <translation>k. A.</translation>
    </message>
    <message>
        <source>chosen</source>
        <translation>gewählt</translation>
    </message>
    <message>
        <source>closest</source>
        <translation>nächstliegend</translation>
    </message>
    <message>
        <source>override</source>
        <translation>überschrieben</translation>
    </message>
    <message>
        <source>level %1 (%2 vertices), %3: error %4 %, tick %5 µs</source>
        <translation>Stufe %1 (%2 Knoten), %3: Fehler %4 %, Tick %5 µs</translation>
    </message>
    <message>
        <source>No scene mesh.</source>
        <translation>Kein Szenennetz.</translation>
    </message>
    <message>
        <source>Nothing measured yet: Plan measures the levels on this machine.</source>
        <translation>Noch nichts gemessen: „Planen“ misst die Stufen auf diesem Rechner.</translation>
    </message>
    <message>
        <source>&lt;b&gt;No plan:&lt;/b&gt; the targets are invalid.</source>
        <translation>&lt;b&gt;Keine Planung:&lt;/b&gt; die Ziele sind ungültig.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Chosen:&lt;/b&gt; %1.</source>
        <translation>&lt;b&gt;Gewählt:&lt;/b&gt; %1.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Nothing meets both targets.&lt;/b&gt; Closest: %1.</source>
        <translation>&lt;b&gt;Nichts erfüllt beide Ziele.&lt;/b&gt; Nächstliegend: %1.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Nothing meets both targets&lt;/b&gt; and no candidate could be measured.</source>
        <translation>&lt;b&gt;Nichts erfüllt beide Ziele&lt;/b&gt;, und kein Kandidat konnte gemessen werden.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Override:&lt;/b&gt; %1.</source>
        <translation>&lt;b&gt;Überschrieben:&lt;/b&gt; %1.</translation>
    </message>
    <message>
        <source>Why: %1</source>
        <translation>Warum: %1</translation>
    </message>
    <message>
        <source>The level&apos;s mesh file %1 is missing (was the cache written or removed?); plan again.</source>
        <translation>Die Netzdatei %1 der Stufe fehlt (wurde der Cache geschrieben oder gelöscht?); neu planen.</translation>
    </message>
    <message>
        <source>Using %1 (override).</source>
        <translation>Verwende %1 (überschrieben).</translation>
    </message>
    <message>
        <source>Using %1.</source>
        <translation>Verwende %1.</translation>
    </message>
    <message>
        <source>No scene mesh yet.</source>
        <translation>Noch kein Szenennetz.</translation>
    </message>
    <message>
        <source>Ready: Plan measures the levels of %1.</source>
        <translation>Bereit: „Planen“ misst die Stufen von %1.</translation>
    </message>
    <message>
        <source>Candidates</source>
        <translation>Kandidaten</translation>
    </message>
    <message>
        <source>The levels were not finished (cancelled); nothing was cached.</source>
        <translation>Die Stufen wurden nicht fertig (abgebrochen); nichts wurde zwischengespeichert.</translation>
    </message>
    <message>
        <source>Planned in %1 s: %2 of %3 candidates could be measured on this machine.</source>
        <translation>In %1 s geplant: %2 von %3 Kandidaten konnten auf diesem Rechner gemessen werden.</translation>
    </message>
    <message>
        <source>Cancelled while making the levels; nothing was measured.</source>
        <translation>Beim Erzeugen der Stufen abgebrochen; nichts wurde gemessen.</translation>
    </message>
    <message>
        <source>Cancelled while making the levels; the table shows the previous plan.</source>
        <translation>Beim Erzeugen der Stufen abgebrochen; die Tabelle zeigt die vorige Planung.</translation>
    </message>
    <message>
        <source>Cancelled before the first candidate; nothing was measured.</source>
        <translation>Vor dem ersten Kandidaten abgebrochen; nichts wurde gemessen.</translation>
    </message>
    <message>
        <source>Cancelled before the first candidate; the table shows the previous plan.</source>
        <translation>Vor dem ersten Kandidaten abgebrochen; die Tabelle zeigt die vorige Planung.</translation>
    </message>
    <message>
        <source>%1 of %2 candidates could not be measured (n/a): the row&apos;s tooltip says why.</source>
        <translation>%1 von %2 Kandidaten konnten nicht gemessen werden (k. A.): der Tooltip der Zeile sagt, warum.</translation>
    </message>
    <message>
        <source>the plan&apos;s press</source>
        <translation>der Druck des Plans</translation>
    </message>
    <message>
        <source>Pressing the hyperelastic reference for linear or stiffening tissue…</source>
        <translation>Die hyperelastische Referenz wird gedrückt: lineares oder versteifendes Gewebe…</translation>
    </message>
    <message>
        <source>The hyperelastic reference failed: %1</source>
        <translation>Die hyperelastische Referenz scheiterte: %1</translation>
    </message>
    <message>
        <source>Tissue: %1</source>
        <translation>Gewebe: %1</translation>
    </message>
    <message>
        <source>U&amp;ndo use</source>
        <translation>Verwendung rückgä&amp;ngig</translation>
    </message>
    <message>
        <source>Back to the mesh, rings and tissue from before the first Use.</source>
        <translation>Zurück zu Netz, Ringen und Gewebe von vor der ersten Verwendung.</translation>
    </message>
</context>
<context>
    <name>palpate::MainWindow</name>
    <message>
        <source>Touch depth %1 mm</source>
        <translation>Drucktiefe %1 mm</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Parameters not applied</source>
        <translation>Parameter nicht übernommen</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Charts</source>
        <translation>Diagramme</translation>
    </message>
    <message>
        <source>: not loaded</source>
        <translation>: nicht geladen</translation>
    </message>
    <message>
        <source>Cannot open mesh</source>
        <translation>Netz kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>About Palpate</source>
        <translation>Über Palpate</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Palpate %1&lt;/h3&gt;&lt;p&gt;Haptic soft-tissue deformation: the slope-ring method of Ahmad, Sulaiman and Rambli, made exact and measured.&lt;/p&gt;&lt;p&gt;Built with these libraries (Debian 12 packages):&lt;/p&gt;&lt;ul&gt;&lt;li&gt;Qt %2 (Widgets, OpenGL): LGPL-3.0&lt;/li&gt;&lt;li&gt;OpenMesh: BSD-3-Clause&lt;/li&gt;&lt;li&gt;GLM: MIT (Happy Bunny licence)&lt;/li&gt;&lt;li&gt;nlohmann/json: MIT&lt;/li&gt;&lt;li&gt;GoogleTest and Google Benchmark (tests only): BSD-3-Clause, Apache-2.0&lt;/li&gt;&lt;/ul&gt;</source>
        <translation>&lt;h3&gt;Palpate %1&lt;/h3&gt;&lt;p&gt;Haptische Weichgewebeverformung: die Slope-Ring-Methode von Ahmad, Sulaiman und Rambli, exakt gemacht und vermessen.&lt;/p&gt;&lt;p&gt;Erstellt mit diesen Bibliotheken (Debian-12-Pakete):&lt;/p&gt;&lt;ul&gt;&lt;li&gt;Qt %2 (Widgets, OpenGL): LGPL-3.0&lt;/li&gt;&lt;li&gt;OpenMesh: BSD-3-Clause&lt;/li&gt;&lt;li&gt;GLM: MIT (Happy-Bunny-Lizenz)&lt;/li&gt;&lt;li&gt;nlohmann/json: MIT&lt;/li&gt;&lt;li&gt;GoogleTest und Google Benchmark (nur Tests): BSD-3-Clause, Apache-2.0&lt;/li&gt;&lt;/ul&gt;</translation>
    </message>
    <message>
        <source>Haptic rate: %1 Hz (loop says %2 Hz)
Ticks: %3
Missed deadlines: %4
Overruns: %5
Tick compute: last %6 µs, max %7 µs
Jitter: last %8 µs, max %9 µs
Scheduling: %10
GUI: %11 fps
Displaced vertices: %12
Paused: %13</source>
        <translation>Haptikrate: %1 Hz (Schleife meldet %2 Hz)
Ticks: %3
Verpasste Fristen: %4
Überläufe: %5
Tick-Rechenzeit: zuletzt %6 µs, max. %7 µs
Jitter: zuletzt %8 µs, max. %9 µs
Scheduling: %10
GUI: %11 fps
Verschobene Knoten: %12
Pausiert: %13</translation>
    </message>
    <message>
        <source>SCHED_FIFO</source>
        <translation>SCHED_FIFO</translation>
    </message>
    <message>
        <source>normal (SCHED_FIFO not permitted)</source>
        <translation>normal (SCHED_FIFO nicht erlaubt)</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Open Mesh…</source>
        <translation>Netz ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>Open Recor&amp;ding…</source>
        <translation>&amp;Aufnahme öffnen…</translation>
    </message>
    <message>
        <source>Play a session recording back (the live session pauses meanwhile)</source>
        <translation>Eine Sitzungsaufnahme wiedergeben (die laufende Sitzung pausiert solange)</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>&amp;Apply Parameters</source>
        <translation>Parameter &amp;übernehmen</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Reset Camera</source>
        <translation>Kamera &amp;zurücksetzen</translation>
    </message>
    <message>
        <source>&amp;Fit</source>
        <translation>&amp;Einpassen</translation>
    </message>
    <message>
        <source>&amp;Wireframe</source>
        <translation>&amp;Drahtgitter</translation>
    </message>
    <message>
        <source>Rest Shape &amp;Ghost</source>
        <translation>&amp;Ruheform als Schatten</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>&amp;Restart</source>
        <translation>&amp;Neu starten</translation>
    </message>
    <message>
        <source>Cannot restart</source>
        <translation>Neustart nicht möglich</translation>
    </message>
    <message>
        <source>&amp;Touch Mode</source>
        <translation>&amp;Tastmodus</translation>
    </message>
    <message>
        <source>The mouse steers the tool: left-drag presses the tissue, the wheel sets the depth; right-drag orbits, middle-drag pans, Shift+wheel zooms</source>
        <translation>Die Maus steuert das Werkzeug: Ziehen mit links drückt das Gewebe, das Mausrad stellt die Tiefe ein; Ziehen mit rechts dreht, mit der mittleren Taste verschiebt, Umschalt+Mausrad zoomt</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About Palpate</source>
        <translation>&amp;Über Palpate</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <source>Haptic ticks per second achieved by the loop thread</source>
        <translation>Haptik-Ticks pro Sekunde, die der Schleifen-Thread erreicht</translation>
    </message>
    <message>
        <source>Time spent in a haptic tick: the last one / the longest</source>
        <translation>In einem Haptik-Tick verbrachte Zeit: der letzte / der längste</translation>
    </message>
    <message>
        <source>Lateness of the haptic thread&apos;s wake-up after its deadline: the last / the worst</source>
        <translation>Verspätung des Aufwachens des Haptik-Threads nach seiner Frist: die letzte / die schlimmste</translation>
    </message>
    <message>
        <source>Ticks that finished after the next deadline (and the deadlines skipped)</source>
        <translation>Ticks, die nach der nächsten Frist endeten (und die übersprungenen Fristen)</translation>
    </message>
    <message>
        <source>Whether the haptic thread runs with SCHED_FIFO priority</source>
        <translation>Ob der Haptik-Thread mit SCHED_FIFO-Priorität läuft</translation>
    </message>
    <message>
        <source>Frames the viewport painted per second</source>
        <translation>Bilder pro Sekunde, die das Ansichtsfenster zeichnete</translation>
    </message>
    <message>
        <source>The device URI and its state</source>
        <translation>Die Geräte-URI und ihr Zustand</translation>
    </message>
    <message>
        <source>The tool is pressing the tissue</source>
        <translation>Das Werkzeug drückt auf das Gewebe</translation>
    </message>
    <message>
        <source>Force sent to the device (after the safety filter)</source>
        <translation>An das Gerät gesendete Kraft (nach dem Sicherheitsfilter)</translation>
    </message>
    <message>
        <source>The session is being recorded, or a recording is played back</source>
        <translation>Die Sitzung wird aufgenommen, oder eine Aufnahme wird wiedergegeben</translation>
    </message>
    <message>
        <source>No mesh, %1</source>
        <translation>Kein Netz, %1</translation>
    </message>
    <message>
        <source>The tissue model diverged (%1) at tick %2: the force was zeroed and the tissue reset. %3</source>
        <translation>Das Gewebemodell divergierte (%1) bei Tick %2: die Kraft wurde auf null gesetzt und das Gewebe zurückgesetzt. %3</translation>
    </message>
    <message>
        <source>haptic -</source>
        <translation>Haptik -</translation>
    </message>
    <message>
        <source>haptic stepped (%1 Hz virtual)</source>
        <translation>Haptik schrittweise (%1 Hz virtuell)</translation>
    </message>
    <message>
        <source>haptic %1 Hz</source>
        <translation>Haptik %1 Hz</translation>
    </message>
    <message>
        <source>tick %1/%2 µs</source>
        <translation>Tick %1/%2 µs</translation>
    </message>
    <message>
        <source>jitter %1/%2 µs</source>
        <translation>Jitter %1/%2 µs</translation>
    </message>
    <message>
        <source>overruns %1 (missed %2)</source>
        <translation>Überläufe %1 (verpasst %2)</translation>
    </message>
    <message>
        <source>SCHED_FIFO %1</source>
        <translation>SCHED_FIFO %1</translation>
    </message>
    <message>
        <source>GUI %1 fps</source>
        <translation>GUI %1 fps</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>not started</source>
        <translation>nicht gestartet</translation>
    </message>
    <message>
        <source>contact: %1</source>
        <translation>Kontakt: %1</translation>
    </message>
    <message>
        <source>Palpate - playing %1</source>
        <translation>Palpate - %1 wird wiedergegeben</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Übung</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <source>Exercise Editor</source>
        <translation>Übungseditor</translation>
    </message>
    <message>
        <source>An exercise is running: the mesh cannot change now.</source>
        <translation>Eine Übung läuft: das Netz kann jetzt nicht geändert werden.</translation>
    </message>
    <message>
        <source>Cannot try the exercise</source>
        <translation>Übung kann nicht ausprobiert werden</translation>
    </message>
    <message>
        <source>E&amp;xercise</source>
        <translation>Üb&amp;ung</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>&amp;Starten</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>S&amp;toppen</translation>
    </message>
    <message>
        <source>&amp;Open Exercise…</source>
        <translation>Übung ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>&amp;New Trainee…</source>
        <translation>&amp;Neuer Teilnehmer…</translation>
    </message>
    <message>
        <source>&amp;Export Score Report (PDF)…</source>
        <translation>Bewertungsbericht &amp;exportieren (PDF)…</translation>
    </message>
    <message>
        <source>&amp;History</source>
        <translation>&amp;Verlauf</translation>
    </message>
    <message>
        <source>&amp;Author</source>
        <translation>Erste&amp;llen</translation>
    </message>
    <message>
        <source>&amp;Instructor Mode</source>
        <translation>&amp;Ausbildermodus</translation>
    </message>
    <message>
        <source>&amp;Trainee Mode</source>
        <translation>&amp;Teilnehmermodus</translation>
    </message>
    <message>
        <source>New Trainee</source>
        <translation>Neuer Teilnehmer</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>Trainee not added</source>
        <translation>Teilnehmer nicht hinzugefügt</translation>
    </message>
    <message>
        <source>Open Exercise</source>
        <translation>Übung öffnen</translation>
    </message>
    <message>
        <source>Not an exercise</source>
        <translation>Keine Übung</translation>
    </message>
    <message>
        <source>There is no score to export yet: run an exercise first.</source>
        <translation>Es gibt noch keine Punktzahl zum Exportieren: führen Sie zuerst eine Übung durch.</translation>
    </message>
    <message>
        <source>Export Score Report</source>
        <translation>Bewertungsbericht exportieren</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Report not written</source>
        <translation>Bericht nicht geschrieben</translation>
    </message>
    <message>
        <source>Report written: %1</source>
        <translation>Bericht geschrieben: %1</translation>
    </message>
    <message>
        <source>Level of Detail</source>
        <translation>Detailstufen</translation>
    </message>
    <message>
        <source>An exercise is running: the model cannot change now.</source>
        <translation>Eine Übung läuft: das Modell kann jetzt nicht geändert werden.</translation>
    </message>
    <message>
        <source>Cannot use this level</source>
        <translation>Diese Stufe kann nicht verwendet werden</translation>
    </message>
    <message>
        <source>Using your choice: %1, %2 rings (overrides the plan)</source>
        <translation>Verwende Ihre Wahl: %1, %2 Ringe (überschreibt die Planung)</translation>
    </message>
    <message>
        <source>Using the plan&apos;s choice: %1, %2 rings</source>
        <translation>Verwende die Wahl der Planung: %1, %2 Ringe</translation>
    </message>
    <message>
        <source>Targets stored in the preset: save it (File &gt; Save Preset) to keep them</source>
        <translation>Ziele in der Vorgabe gespeichert: speichern Sie sie (Datei &gt; Vorgabe speichern), um sie zu behalten</translation>
    </message>
    <message>
        <source>the tissue preset</source>
        <translation>die Gewebevorgabe</translation>
    </message>
    <message>
        <source>exercise &apos;%1&apos;</source>
        <translation>Übung „%1“</translation>
    </message>
    <message>
        <source>force %1</source>
        <translation>Kraft %1</translation>
    </message>
    <message>
        <source>Click the tissue to place; drag orbits; Esc stops placing</source>
        <translation>Auf das Gewebe klicken zum Platzieren; Ziehen dreht; Esc beendet das Platzieren</translation>
    </message>
    <message>
        <source>Pause the simulation (ticked: paused; the tissue relaxes and the force is zero)</source>
        <translation>Simulation anhalten (mit Haken: angehalten; das Gewebe entspannt sich, die Kraft ist null)</translation>
    </message>
    <message>
        <source>force %1 (clipped at device max)</source>
        <translation>Kraft %1 (auf das Gerätemaximum begrenzt)</translation>
    </message>
    <message>
        <source>Cannot open the device %1: %2
Running with %3 instead: choose another in the Device dock or in Edit &gt; Preferences.</source>
        <translation>Das Gerät %1 kann nicht geöffnet werden: %2
Stattdessen läuft %3: wählen Sie ein anderes im Gerät-Dock oder unter Bearbeiten &gt; Einstellungen.</translation>
    </message>
    <message>
        <source>Cannot open %1; running with %2</source>
        <translation>%1 kann nicht geöffnet werden; es läuft %2</translation>
    </message>
    <message>
        <source>Device not opened</source>
        <translation>Gerät nicht geöffnet</translation>
    </message>
    <message>
        <source>&amp;Import Mesh…</source>
        <translation>Netz &amp;importieren…</translation>
    </message>
    <message>
        <source>Open a mesh from another tool: its unit, repair, remeshing, previewed</source>
        <translation>Ein Netz aus einem anderen Programm öffnen: Einheit, Reparatur, Neuvernetzung, mit Vorschau</translation>
    </message>
    <message>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <source>%1 · file in %2</source>
        <translation>%1 · Datei in %2</translation>
    </message>
    <message>
        <source>%1 · %2 vertices · %3</source>
        <translation>%1 · %2 Knoten · %3</translation>
    </message>
    <message>
        <source>%1
%2
%3 vertices, %4 triangles
%5 renderer</source>
        <translation>%1
%2
%3 Knoten, %4 Dreiecke
%5-Renderer</translation>
    </message>
    <message>
        <source>&amp;Coverage Heat Map</source>
        <translation>&amp;Abdeckungskarte</translation>
    </message>
    <message>
        <source>Show, after a palpation exercise, where the surface was examined and how firmly</source>
        <translation>Nach einer Tastübung zeigen, wo und wie fest die Oberfläche untersucht wurde</translation>
    </message>
    <message>
        <source>&amp;Finish Examination</source>
        <translation>Untersuchung &amp;beenden</translation>
    </message>
    <message>
        <source>Finish ends a running detect-lumps examination</source>
        <translation>Beenden beendet eine laufende Untersuchung „Knoten finden“</translation>
    </message>
    <message>
        <source>, %1 stiffening knots</source>
        <translation>, %1 Versteifungsknoten</translation>
    </message>
    <message>
        <source>, linear tissue</source>
        <translation>, lineares Gewebe</translation>
    </message>
    <message>
        <source>Results kept on this workstation and copied to the class&apos;s server (Preferences)</source>
        <translation>Ergebnisse bleiben auf diesem Arbeitsplatz und werden auf den Server der Klasse kopiert (Einstellungen)</translation>
    </message>
    <message>
        <source>The last copy to %1 stopped: %2</source>
        <translation>Die letzte Kopie nach %1 brach ab: %2</translation>
    </message>
    <message>
        <source>&amp;Class View…</source>
        <translation>&amp;Klassenansicht…</translation>
    </message>
    <message>
        <source>, linear tissue (the knots do not fit this preset: %1)</source>
        <translation>, lineares Gewebe (die Knoten passen nicht zu diesem Preset: %1)</translation>
    </message>
    <message>
        <source>Results kept on this workstation and copied to %1 (%2)</source>
        <translation>Ergebnisse auf diesem Arbeitsplatz gespeichert und nach %1 kopiert (%2)</translation>
    </message>
    <message>
        <source>Exercises and bundles (*.json *.palpex)</source>
        <translation>Übungen und Pakete (*.json *.palpex)</translation>
    </message>
    <message>
        <source>Stiffening knots applied to the tissue (undo them in Parameters, then Apply)</source>
        <translation>Versteifungsknoten auf das Gewebe angewandt (in Parameter rückgängig machen, dann Anwenden)</translation>
    </message>
    <message>
        <source>Another mesh: the level of detail&apos;s %1 rings stay with its scene; %2 rings again</source>
        <translation>Ein anderes Netz: die %1 Ringe der Detailstufe bleiben bei ihrer Szene; wieder %2 Ringe</translation>
    </message>
    <message>
        <source>mesh %1 (%2 vertices) instead of %3 (%4)</source>
        <translation>Netz %1 (%2 Knotenpunkte) statt %3 (%4)</translation>
    </message>
    <message>
        <source>%1 rings instead of %2</source>
        <translation>%1 Ringe statt %2</translation>
    </message>
    <message>
        <source>%1 stiffening knots instead of %2</source>
        <translation>%1 Versteifungsknoten statt %2</translation>
    </message>
    <message>
        <source>Nothing changed: the scene already ran this.</source>
        <translation>Nichts geändert: die Szene lief schon so.</translation>
    </message>
    <message>
        <source>Changed: %1. Undo use goes back; opening another mesh drops these rings and knots.</source>
        <translation>Geändert: %1. Verwendung rückgängig kehrt zurück; ein anderes Netz verwirft diese Ringe und Knoten.</translation>
    </message>
    <message>
        <source>Cannot undo the use</source>
        <translation>Verwendung lässt sich nicht rückgängig machen</translation>
    </message>
    <message>
        <source>Back to %1 with %2 rings, as before the level of detail was used</source>
        <translation>Zurück zu %1 mit %2 Ringen, wie vor der Verwendung der Detailstufe</translation>
    </message>
    <message>
        <source>a folder</source>
        <translation>ein Ordner</translation>
    </message>
    <message>
        <source>a FIFO</source>
        <translation>eine FIFO</translation>
    </message>
    <message>
        <source>a device</source>
        <translation>ein Gerät</translation>
    </message>
    <message>
        <source>a socket</source>
        <translation>ein Socket</translation>
    </message>
    <message>
        <source>not a regular file</source>
        <translation>keine gewöhnliche Datei</translation>
    </message>
    <message>
        <source>a link to nothing</source>
        <translation>ein Verweis ins Leere</translation>
    </message>
    <message>
        <source>a link to %1</source>
        <translation>ein Verweis auf %1</translation>
    </message>
    <message>
        <source>%1 is %2, not a regular file: the preferences are neither read from it nor saved over it; this run keeps them until it ends. Move it away to keep preferences again.</source>
        <translation>%1 ist %2, keine gewöhnliche Datei: Die Einstellungen werden weder daraus gelesen noch darüber gespeichert; dieser Lauf behält sie bis zu seinem Ende. Verschieben Sie sie, um Einstellungen wieder zu behalten.</translation>
    </message>
</context>
<context>
    <name>palpate::MeshImportDialog</name>
    <message>
        <source>Import Mesh</source>
        <translation>Netz importieren</translation>
    </message>
    <message>
        <source>Choose a mesh file to preview.</source>
        <translation>Wählen Sie eine Netzdatei für die Vorschau.</translation>
    </message>
    <message>
        <source>A mesh from another tool (OBJ, OFF, PLY, STL, OM)</source>
        <translation>Ein Netz aus einem anderen Programm (OBJ, OFF, PLY, STL, OM)</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>Datei:</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>cm</source>
        <translation>cm</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <source>in</source>
        <translation>in</translation>
    </message>
    <message>
        <source>Scale…</source>
        <translation>Faktor…</translation>
    </message>
    <message>
        <source> mm per file unit</source>
        <translation> mm je Dateieinheit</translation>
    </message>
    <message>
        <source>Unit of the file:</source>
        <translation>Einheit der Datei:</translation>
    </message>
    <message>
        <source>Repair faults</source>
        <translation>Fehler reparieren</translation>
    </message>
    <message>
        <source>Orient the faces consistently, split non-manifold edges and vertices, remove degenerate triangles and duplicate vertices (CGAL). Without it a mesh with faults is refused.</source>
        <translation>Flächen einheitlich ausrichten, nicht-mannigfaltige Kanten und Knoten auftrennen, entartete Dreiecke und doppelte Knoten entfernen (CGAL). Ohne dies wird ein fehlerhaftes Netz abgelehnt.</translation>
    </message>
    <message>
        <source>Keep the largest piece</source>
        <translation>Größtes Teil behalten</translation>
    </message>
    <message>
        <source>Keep all pieces</source>
        <translation>Alle Teile behalten</translation>
    </message>
    <message>
        <source>Fill holes</source>
        <translation>Löcher füllen</translation>
    </message>
    <message>
        <source>Repair:</source>
        <translation>Reparatur:</translation>
    </message>
    <message>
        <source>Remesh to even triangles, edge</source>
        <translation>Gleichmäßig neu vernetzen, Kante</translation>
    </message>
    <message>
        <source>Isotropic remeshing: even triangles make the slope model&apos;s rings round</source>
        <translation>Isotrope Neuvernetzung: gleichmäßige Dreiecke machen die Ringe des Steigungsmodells rund</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Remesh:</source>
        <translation>Neu vernetzen:</translation>
    </message>
    <message>
        <source>Cancel Preview</source>
        <translation>Vorschau abbrechen</translation>
    </message>
    <message>
        <source>Preview</source>
        <translation>Vorschau</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>Vorher</translation>
    </message>
    <message>
        <source>After</source>
        <translation>Nachher</translation>
    </message>
    <message>
        <source>Ring roundness: the spread of the distances to ring k&apos;s vertices (coefficient of variation; 0 is a circle, a regular mesh gives about 0.1 at ring 2), and the spread of the edge lengths</source>
        <translation>Rundheit der Ringe: die Streuung der Abstände zu den Knoten von Ring k (Variationskoeffizient; 0 ist ein Kreis, ein regelmäßiges Netz ergibt etwa 0,1 bei Ring 2) und die Streuung der Kantenlängen</translation>
    </message>
    <message>
        <source>Ring roundness (CV)</source>
        <translation>Rundheit der Ringe (VK)</translation>
    </message>
    <message>
        <source>Import…</source>
        <translation>Importieren…</translation>
    </message>
    <message>
        <source>Write the previewed mesh (in mm) to a new file and open it</source>
        <translation>Das Netz der Vorschau (in mm) in eine neue Datei schreiben und öffnen</translation>
    </message>
    <message>
        <source>Meshes (*.obj *.off *.ply *.stl *.om);;All files (*)</source>
        <translation>Netze (*.obj *.off *.ply *.stl *.om);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Import Mesh As</source>
        <translation>Netz importieren als</translation>
    </message>
    <message>
        <source>Meshes (*.off *.obj *.ply *.stl *.om)</source>
        <translation>Netze (*.off *.obj *.ply *.stl *.om)</translation>
    </message>
    <message>
        <source>Cannot import</source>
        <translation>Import nicht möglich</translation>
    </message>
    <message>
        <source>Choose a file for the imported mesh.</source>
        <translation>Wählen Sie eine Datei für das importierte Netz.</translation>
    </message>
    <message>
        <source>The preview is not finished yet: wait for it, then import.</source>
        <translation>Die Vorschau ist noch nicht fertig: warten Sie darauf und importieren Sie dann.</translation>
    </message>
    <message>
        <source>nothing previewed</source>
        <translation>keine Vorschau</translation>
    </message>
    <message>
        <source>There is no mesh to import: %1</source>
        <translation>Es gibt kein Netz zu importieren: %1</translation>
    </message>
    <message>
        <source>%1: is the mesh being imported; choose another file for the result</source>
        <translation>%1: ist das Netz, das importiert wird; wählen Sie eine andere Datei für das Ergebnis</translation>
    </message>
    <message>
        <source>reading</source>
        <translation>lesen</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>done</source>
        <translation>fertig</translation>
    </message>
    <message>
        <source>%1 · file in %2</source>
        <translation>%1 · Datei in %2</translation>
    </message>
    <message>
        <source>Not read</source>
        <translation>Nicht gelesen</translation>
    </message>
    <message>
        <source>Suggested %1: %2</source>
        <translation>Vorgeschlagen %1: %2</translation>
    </message>
    <message>
        <source>Try %1: %2</source>
        <translation>Versuchen Sie %1: %2</translation>
    </message>
    <message>
        <source>Source: %1 vertices, %2 polygons</source>
        <translation>Quelle: %1 Knoten, %2 Polygone</translation>
    </message>
    <message>
        <source> · result: %1 vertices, %2 triangles</source>
        <translation> · Ergebnis: %1 Knoten, %2 Dreiecke</translation>
    </message>
    <message>
        <source>Errors</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>Problems found</source>
        <translation>Gefundene Probleme</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>Warnungen</translation>
    </message>
    <message>
        <source>Changes made</source>
        <translation>Vorgenommene Änderungen</translation>
    </message>
    <message>
        <source>Tolerated while reading</source>
        <translation>Beim Lesen toleriert</translation>
    </message>
    <message>
        <source>&lt;p&gt;No problems found.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Keine Probleme gefunden.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Ring %1</source>
        <translation>Ring %1</translation>
    </message>
    <message>
        <source>Edge length</source>
        <translation>Kantenlänge</translation>
    </message>
    <message>
        <source>waiting</source>
        <translation>wartet</translation>
    </message>
    <message>
        <source>cancelling…</source>
        <translation>wird abgebrochen…</translation>
    </message>
</context>
<context>
    <name>palpate::MeshOpener</name>
    <message>
        <source>Which unit is this mesh in?</source>
        <translation>In welcher Einheit ist dieses Netz?</translation>
    </message>
    <message>
        <source>%1 is %2 if its coordinates are millimetres.</source>
        <translation>%1 ist %2 groß, wenn seine Koordinaten Millimeter sind.</translation>
    </message>
    <message>
        <source>Open in %1</source>
        <translation>In %1 öffnen</translation>
    </message>
    <message>
        <source>Open as mm</source>
        <translation>Als mm öffnen</translation>
    </message>
    <message>
        <source>Import…</source>
        <translation>Importieren…</translation>
    </message>
    <message>
        <source>Cannot open mesh</source>
        <translation>Netz kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>Import Mesh can repair the faults and scale the file to mm.</source>
        <translation>„Netz importieren“ kann die Fehler reparieren und die Datei auf mm skalieren.</translation>
    </message>
    <message>
        <source>An exercise is running: the mesh cannot change now.</source>
        <translation>Eine Übung läuft: das Netz kann jetzt nicht geändert werden.</translation>
    </message>
    <message>
        <source>Open Mesh</source>
        <translation>Netz öffnen</translation>
    </message>
    <message>
        <source>Meshes (*.obj *.off *.ply *.stl *.om);;All files (*)</source>
        <translation>Netze (*.obj *.off *.ply *.stl *.om);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>palpate::MetricText</name>
    <message>
        <source>Work done %1 %: the lines that count mistakes earn that share of their points.</source>
        <translation>Erledigte Arbeit %1 %: die Zeilen, die Fehler zählen, erhalten diesen Anteil ihrer Punkte.</translation>
    </message>
</context>
<context>
    <name>palpate::Metrics</name>
    <message>
        <source>completion</source>
        <translation>Erledigt</translation>
    </message>
    <message>
        <source>share of the task done: targets achieved, lump marked, path covered, examination finished (else the surface examined)</source>
        <translation>Anteil der erledigten Aufgabe: Ziele erreicht, Verhärtung markiert, Pfad abgedeckt, Untersuchung beendet (sonst der untersuchte Teil der Oberfläche)</translation>
    </message>
    <message>
        <source>time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>exercise time until the task was complete (all of it if it was not)</source>
        <translation>Übungszeit bis zum Abschluss der Aufgabe (die ganze, wenn sie nicht abgeschlossen wurde)</translation>
    </message>
    <message>
        <source>target error</source>
        <translation>Zielabweichung</translation>
    </message>
    <message>
        <source>mean distance from the target while pressing inside its force window</source>
        <translation>mittlerer Abstand vom Ziel, während die Kraft in seinem Kraftfenster lag</translation>
    </message>
    <message>
        <source>hold in window fraction</source>
        <translation>Anteil im Fenster gehalten</translation>
    </message>
    <message>
        <source>time inside the force window / time on a target in contact</source>
        <translation>Zeit im Kraftfenster / Zeit mit Kontakt auf einem Ziel</translation>
    </message>
    <message>
        <source>peak force</source>
        <translation>Spitzenkraft</translation>
    </message>
    <message>
        <source>largest force rendered</source>
        <translation>größte ausgegebene Kraft</translation>
    </message>
    <message>
        <source>mean force</source>
        <translation>mittlere Kraft</translation>
    </message>
    <message>
        <source>mean force magnitude while in contact</source>
        <translation>mittlerer Kraftbetrag während des Kontakts</translation>
    </message>
    <message>
        <source>impulse</source>
        <translation>Kraftstoß</translation>
    </message>
    <message>
        <source>integral of the force magnitude over time</source>
        <translation>Integral des Kraftbetrags über die Zeit</translation>
    </message>
    <message>
        <source>excessive force events</source>
        <translation>Überkraft-Ereignisse</translation>
    </message>
    <message>
        <source>times the force rose above the excessive force</source>
        <translation>wie oft die Kraft über die zu hohe Kraft stieg</translation>
    </message>
    <message>
        <source>excessive force fraction</source>
        <translation>Anteil mit Überkraft</translation>
    </message>
    <message>
        <source>time above the excessive force / time in contact</source>
        <translation>Zeit über der zu hohen Kraft / Zeit in Kontakt</translation>
    </message>
    <message>
        <source>damage time</source>
        <translation>Schadenszeit</translation>
    </message>
    <message>
        <source>time with tissue displaced beyond the displacement limit</source>
        <translation>Zeit, in der Gewebe über die Verschiebungsgrenze hinaus verschoben war</translation>
    </message>
    <message>
        <source>damage area</source>
        <translation>Schadensfläche</translation>
    </message>
    <message>
        <source>largest surface area displaced beyond the limit at one time</source>
        <translation>größte gleichzeitig über die Grenze hinaus verschobene Oberfläche</translation>
    </message>
    <message>
        <source>max displacement</source>
        <translation>größte Verschiebung</translation>
    </message>
    <message>
        <source>largest displacement of any vertex from rest</source>
        <translation>größte Verschiebung eines Knotens aus der Ruhelage</translation>
    </message>
    <message>
        <source>path length</source>
        <translation>Weglänge</translation>
    </message>
    <message>
        <source>distance travelled by the tool tip</source>
        <translation>von der Werkzeugspitze zurückgelegte Strecke</translation>
    </message>
    <message>
        <source>economy</source>
        <translation>Wirtschaftlichkeit</translation>
    </message>
    <message>
        <source>ideal path length / path length (1 = no wasted motion)</source>
        <translation>ideale Weglänge / Weglänge (1 = keine unnötige Bewegung)</translation>
    </message>
    <message>
        <source>lump error</source>
        <translation>Abweichung von der Verhärtung</translation>
    </message>
    <message>
        <source>distance from the contact point at the mark to the inclusion centre</source>
        <translation>Abstand des Kontaktpunkts bei der Markierung vom Mittelpunkt der Einlagerung</translation>
    </message>
    <message>
        <source>contact fraction</source>
        <translation>Kontaktanteil</translation>
    </message>
    <message>
        <source>time in contact / tracing time</source>
        <translation>Zeit in Kontakt / Nachfahrzeit</translation>
    </message>
    <message>
        <source>band fraction</source>
        <translation>Anteil im Kraftband</translation>
    </message>
    <message>
        <source>time in contact with the force in the band / tracing time</source>
        <translation>Zeit in Kontakt mit der Kraft im Band / Nachfahrzeit</translation>
    </message>
    <message>
        <source>path distance</source>
        <translation>Abstand vom Pfad</translation>
    </message>
    <message>
        <source>mean distance of the contact point from the path while in contact</source>
        <translation>mittlerer Abstand des Kontaktpunkts vom Pfad während des Kontakts</translation>
    </message>
    <message>
        <source>sensitivity</source>
        <translation>Sensitivität</translation>
    </message>
    <message>
        <source>lumps found / lumps hidden</source>
        <translation>gefundene Knoten / versteckte Knoten</translation>
    </message>
    <message>
        <source>positive predictive value</source>
        <translation>positiver Vorhersagewert</translation>
    </message>
    <message>
        <source>findings on a lump / findings</source>
        <translation>Befunde auf einem Knoten / Befunde</translation>
    </message>
    <message>
        <source>false alarms</source>
        <translation>Fehlalarme</translation>
    </message>
    <message>
        <source>findings matched to no lump</source>
        <translation>Befunde, die keinem Knoten zugeordnet sind</translation>
    </message>
    <message>
        <source>localisation</source>
        <translation>Lokalisierung</translation>
    </message>
    <message>
        <source>mean distance from a found lump&apos;s centre to the finding on it</source>
        <translation>mittlerer Abstand vom Mittelpunkt eines gefundenen Knotens zum Befund darauf</translation>
    </message>
    <message>
        <source>coverage fraction</source>
        <translation>abgedeckter Anteil</translation>
    </message>
    <message>
        <source>surface area examined with at least the coverage force / surface area</source>
        <translation>mit mindestens der Abdeckungskraft untersuchte Oberfläche / Oberfläche</translation>
    </message>
    <message>
        <source>events</source>
        <translation>Ereignisse</translation>
    </message>
    <message>
        <source>findings</source>
        <translation>Befunde</translation>
    </message>
</context>
<context>
    <name>palpate::Models</name>
    <message>
        <source>Mass-spring, symplectic Euler</source>
        <translation>Masse-Feder, symplektischer Euler</translation>
    </message>
    <message>
        <source>Masses on the vertices, edge and anchor springs, penalty contact; explicit symplectic Euler with automatic sub-steps. Cost: every vertex per sub-step, O(n).</source>
        <translation>Massen auf den Knoten, Kanten- und Ankerfedern, Strafkontakt; expliziter symplektischer Euler mit automatischen Teilschritten. Aufwand: jeder Knoten pro Teilschritt, O(n).</translation>
    </message>
    <message>
        <source>Mass-spring, RK4</source>
        <translation>Masse-Feder, RK4</translation>
    </message>
    <message>
        <source>The mass-spring model with classic Runge-Kutta 4 (four stages per sub-step). Cost: every vertex, four times per sub-step, O(n): over 1 ms from a few thousand vertices.</source>
        <translation>Das Masse-Feder-Modell mit klassischem Runge-Kutta 4 (vier Stufen pro Teilschritt). Aufwand: jeder Knoten, viermal pro Teilschritt, O(n): über 1 ms ab einigen tausend Knoten.</translation>
    </message>
    <message>
        <source>Mass-spring, backward Euler</source>
        <translation>Masse-Feder, impliziter Euler</translation>
    </message>
    <message>
        <source>The mass-spring model with the implicit backward Euler step (conjugate gradients): unconditionally stable, dissipative. Cost: every vertex per CG iteration, O(n).</source>
        <translation>Das Masse-Feder-Modell mit dem impliziten Euler-Schritt (konjugierte Gradienten): unbedingt stabil, dissipativ. Aufwand: jeder Knoten pro CG-Iteration, O(n).</translation>
    </message>
    <message>
        <source>Mass-spring, local rings</source>
        <translation>Masse-Feder, lokale Ringe</translation>
    </message>
    <message>
        <source>The mass-spring model on the touched vertex&apos;s rings only (and what still moves); the rest is pinned at rest. Cost: the rings, about the same at every mesh size.</source>
        <translation>Das Masse-Feder-Modell nur auf den Ringen des berührten Knotens (und was sich noch bewegt); der Rest ist in Ruhe fixiert. Aufwand: die Ringe, bei jeder Netzgröße etwa gleich.</translation>
    </message>
    <message>
        <source>Radius of influence (Basdogan)</source>
        <translation>Einflussradius (Basdogan)</translation>
    </message>
    <message>
        <source>Geometric: every vertex within a radius follows the tool by a polynomial profile of its distance; force k_s × depth. Cost: the vertices within the radius.</source>
        <translation>Geometrisch: jeder Knoten innerhalb eines Radius folgt dem Werkzeug nach einem Polynomprofil seines Abstands; Kraft k_s × Tiefe. Aufwand: die Knoten innerhalb des Radius.</translation>
    </message>
    <message>
        <source>Free-form deformation (FFD)</source>
        <translation>Freiformdeformation (FFD)</translation>
    </message>
    <message>
        <source>Geometric: the mesh embedded in a Bernstein lattice whose control points near the contact move; force k_s × depth. Cost: every vertex per tick, O(n).</source>
        <translation>Geometrisch: das Netz eingebettet in ein Bernstein-Gitter, dessen Kontrollpunkte nahe dem Kontakt sich bewegen; Kraft k_s × Tiefe. Aufwand: jeder Knoten pro Tick, O(n).</translation>
    </message>
    <message>
        <source>Volumetric slope-rings</source>
        <translation>Volumetrische Slope-Rings</translation>
    </message>
    <message>
        <source>The slope-ring update on rings of a tetrahedral fill of the surface (the paper&apos;s future work); uses the slopes and springs below. Cost: the rings of the tet graph.</source>
        <translation>Das Slope-Ring-Update auf Ringen einer Tetraederfüllung der Oberfläche (die künftige Arbeit des Artikels); verwendet die Steigungen und Federn unten. Aufwand: die Ringe des Tetraedergraphen.</translation>
    </message>
    <message>
        <source>Coherent rings (ours)</source>
        <translation>Kohärente Ringe (unseres)</translation>
    </message>
    <message>
        <source>Ours: exact warm-started nearest-vertex search, only the rings processed, incremental work per tick. Cost: the rings of the touched vertex.</source>
        <translation>Unseres: exakte warmgestartete Suche nach dem nächsten Knoten, nur die Ringe verarbeitet, inkrementelle Arbeit pro Tick. Aufwand: die Ringe des berührten Knotens.</translation>
    </message>
    <message>
        <source>Proposed (paper)</source>
        <translation>Vorgeschlagen (Artikel)</translation>
    </message>
    <message>
        <source>The paper&apos;s method: its octree searchNode (faithful, can miss the nearest vertex) and only the rings. Cost: the rings of the touched vertex.</source>
        <translation>Die Methode des Artikels: sein Octree-searchNode (getreu, kann den nächsten Knoten verfehlen) und nur die Ringe. Aufwand: die Ringe des berührten Knotens.</translation>
    </message>
    <message>
        <source>Hybrid (paper)</source>
        <translation>Hybrid (Artikel)</translation>
    </message>
    <message>
        <source>The paper&apos;s hybrid: its octree searchNode, and the whole model processed every tick. Cost: every vertex per tick, O(n).</source>
        <translation>Der Hybrid des Artikels: sein Octree-searchNode, und das ganze Modell wird in jedem Tick verarbeitet. Aufwand: jeder Knoten pro Tick, O(n).</translation>
    </message>
    <message>
        <source>Previous (paper)</source>
        <translation>Vorherig (Artikel)</translation>
    </message>
    <message>
        <source>The paper&apos;s baseline: linear nearest-vertex search, and the whole model processed every tick. Cost: every vertex per tick, O(n).</source>
        <translation>Die Basislinie des Artikels: lineare Suche nach dem nächsten Knoten, und das ganze Modell wird in jedem Tick verarbeitet. Aufwand: jeder Knoten pro Tick, O(n).</translation>
    </message>
</context>
<context>
    <name>palpate::PalpationSummaryText</name>
    <message>
        <source>Lumps found: %1 of %2, false alarms: %3 (sensitivity %4, predictive value %5)</source>
        <translation>Gefundene Knoten: %1 von %2, Fehlalarme: %3 (Sensitivität %4, Vorhersagewert %5)</translation>
    </message>
    <message>
        <source>Findings on a lump lay %1 mm from its centre on average</source>
        <translation>Befunde auf einem Knoten lagen im Mittel %1 mm von seiner Mitte entfernt</translation>
    </message>
    <message>
        <source>Surface examined at %1 N or more: %2 %</source>
        <translation>Mit %1 N oder mehr untersuchte Oberfläche: %2 %</translation>
    </message>
    <message>
        <source>Force: searching %1 N, palpating %2 N (medians; %3 times)</source>
        <translation>Kraft: Suchen %1 N, Tasten %2 N (Mediane; %3-fach)</translation>
    </message>
    <message>
        <source>Pressed too lightly to reach the deepest lump: it lies %1 mm under the surface, and over it the surface sank %2 mm at most.</source>
        <translation>Zu leicht gedrückt, um den tiefsten Knoten zu erreichen: er liegt %1 mm unter der Oberfläche, und darüber sank die Oberfläche höchstens %2 mm ein.</translation>
    </message>
    <message>
        <source>Press to about %1 N or more to feel it.</source>
        <translation>Drücken Sie mit etwa %1 N oder mehr, um ihn zu fühlen.</translation>
    </message>
    <message>
        <source>Examined %1 % of the surface at %2 N or more: cover all of it, in overlapping rows.</source>
        <translation>%1 % der Oberfläche mit %2 N oder mehr untersucht: untersuchen Sie alles, in überlappenden Reihen.</translation>
    </message>
    <message>
        <source>Pressed no harder to palpate than to search (median %1 N against %2 N): press in on a spot that feels different.</source>
        <translation>Beim Tasten nicht fester gedrückt als beim Suchen (Median %1 N gegen %2 N): drücken Sie dort tiefer, wo es sich anders anfühlt.</translation>
    </message>
    <message>
        <source>1 finding was on no lump: mark only where the tissue resists more than around it.</source>
        <translation>1 Befund lag auf keinem Knoten: markieren Sie nur, wo das Gewebe mehr Widerstand leistet als ringsum.</translation>
    </message>
    <message>
        <source>%1 findings were on no lump: mark only where the tissue resists more than around it.</source>
        <translation>%1 Befunde lagen auf keinem Knoten: markieren Sie nur, wo das Gewebe mehr Widerstand leistet als ringsum.</translation>
    </message>
</context>
<context>
    <name>palpate::ParameterPanel</name>
    <message>
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <source>|m%1| (touched)</source>
        <translation>|m%1| (berührt)</translation>
    </message>
    <message>
        <source>|m%1| (ring %2)</source>
        <translation>|m%1| (Ring %2)</translation>
    </message>
    <message>
        <source>deformation model</source>
        <translation>Deformationsmodell</translation>
    </message>
    <message>
        <source>haptic rate</source>
        <translation>Haptikrate</translation>
    </message>
    <message>
        <source>Model and loop</source>
        <translation>Modell und Schleife</translation>
    </message>
    <message>
        <source>Slopes (magnitudes, |m1| &gt; |m2| &gt; …)</source>
        <translation>Steigungen (Beträge, |m1| &gt; |m2| &gt; …)</translation>
    </message>
    <message>
        <source>Springs and contact</source>
        <translation>Federn und Kontakt</translation>
    </message>
    <message>
        <source>Octree</source>
        <translation>Octree</translation>
    </message>
    <message>
        <source>Tissue and tool</source>
        <translation>Gewebe und Werkzeug</translation>
    </message>
    <message>
        <source>The tissue&apos;s elasticity and the probe&apos;s flat tip: Calibrate slopes turns them into slopes and a spring stiffness for the current mesh (flat punch on a half-space, docs/calibration.md).</source>
        <translation>Die Elastizität des Gewebes und die flache Spitze der Sonde: „Steigungen kalibrieren“ macht daraus Steigungen und eine Federsteifigkeit für das aktuelle Netz (flacher Stempel auf einem Halbraum, docs/calibration.md).</translation>
    </message>
    <message>
        <source>Tissue preset:</source>
        <translation>Gewebevorgabe:</translation>
    </message>
    <message>
        <source>Choose a tissue…</source>
        <translation>Gewebe wählen…</translation>
    </message>
    <message>
        <source>Load a shipped tissue preset: E, ν, the tool radius and slopes calibrated for the default stomach mesh (one undoable step). Each entry&apos;s tooltip names its source.</source>
        <translation>Eine mitgelieferte Gewebevorgabe laden: E, ν, der Werkzeugradius und Steigungen, kalibriert für das Standard-Magennetz (ein rückgängig machbarer Schritt). Der Tooltip jedes Eintrags nennt seine Quelle.</translation>
    </message>
    <message>
        <source>Ca&amp;librate slopes</source>
        <translation>Steigungen ka&amp;librieren</translation>
    </message>
    <message>
        <source>Slopes for the ring count and spring k for the current mesh from E, ν and the tool radius (flat punch: |m1| = 1 / (2 a E*), k = 1 / |m1|), then the error the calibrated model leaves against the punch. One undoable step; Apply sends them.</source>
        <translation>Steigungen für die Ringanzahl und Feder k für das aktuelle Netz aus E, ν und dem Werkzeugradius (flacher Stempel: |m1| = 1 / (2 a E*), k = 1 / |m1|), dann der Fehler, den das kalibrierte Modell gegenüber dem Stempel lässt. Ein rückgängig machbarer Schritt; „Übernehmen“ sendet sie.</translation>
    </message>
    <message>
        <source>Deformation model:</source>
        <translation>Deformationsmodell:</translation>
    </message>
    <message>
        <source>Which model deforms the tissue: the slope-ring methods (ours and the paper&apos;s three), then the literature&apos;s other models (docs/models.md).</source>
        <translation>Welches Modell das Gewebe verformt: die Slope-Ring-Methoden (unsere und die drei des Artikels), dann die anderen Modelle der Literatur (docs/models.md).</translation>
    </message>
    <message>
        <source>Haptic rate:</source>
        <translation>Haptikrate:</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>Ticks per second of the haptic loop, %1..%2 Hz (haptics usually runs at 1000 Hz).</source>
        <translation>Ticks pro Sekunde der Haptikschleife, %1..%2 Hz (Haptik läuft meist mit 1000 Hz).</translation>
    </message>
    <message>
        <source>Read with signs, the paper&apos;s &quot;m1 &gt; m2 &gt; m3&quot; would move the outer rings further than the touched vertex. Palpate orders the magnitudes instead, |m1| &gt; |m2| &gt; |m3| &gt; …, so the displacement decays away from the touched vertex.</source>
        <translation>Mit Vorzeichen gelesen würde „m1 &gt; m2 &gt; m3“ des Artikels die äußeren Ringe weiter bewegen als den berührten Knoten. Palpate ordnet stattdessen die Beträge, |m1| &gt; |m2| &gt; |m3| &gt; …, sodass die Verschiebung vom berührten Knoten weg abnimmt.</translation>
    </message>
    <message>
        <source>The paper&apos;s range is (0, 1) mm/N; larger values need a raised slope limit and a stable loop gain.</source>
        <translation>Der Bereich des Artikels ist (0, 1) mm/N; größere Werte brauchen eine angehobene Steigungsgrenze und eine stabile Schleifenverstärkung.</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>automatisch</translation>
    </message>
    <message>
        <source>Open preset…</source>
        <translation>Vorgabe öffnen…</translation>
    </message>
    <message>
        <source>Read a tissue preset file (JSON) into the fields; one undoable step.</source>
        <translation>Eine Gewebevorgabedatei (JSON) in die Felder lesen; ein rückgängig machbarer Schritt.</translation>
    </message>
    <message>
        <source>Save preset…</source>
        <translation>Vorgabe speichern…</translation>
    </message>
    <message>
        <source>Write the fields to a tissue preset file (JSON).</source>
        <translation>Die Felder in eine Gewebevorgabedatei (JSON) schreiben.</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <source>Send these parameters to the haptic loop (enabled while they are valid).</source>
        <translation>Diese Parameter an die Haptikschleife senden (aktiv, solange sie gültig sind).</translation>
    </message>
    <message>
        <source>entered in the Parameters panel</source>
        <translation>im Parameterbereich eingegeben</translation>
    </message>
    <message>
        <source>E = %1 kPa, ν = %2, tool radius %3 mm</source>
        <translation>E = %1 kPa, ν = %2, Werkzeugradius %3 mm</translation>
    </message>
    <message>
        <source>Source: %1</source>
        <translation>Quelle: %1</translation>
    </message>
    <message>
        <source>Calibrate slopes needs a mesh: open one first.</source>
        <translation>„Steigungen kalibrieren“ braucht ein Netz: zuerst eines öffnen.</translation>
    </message>
    <message>
        <source>Not calibrated: %1</source>
        <translation>Nicht kalibriert: %1</translation>
    </message>
    <message>
        <source>Parameters panel default (gelatin phantom, as palpate-cli)</source>
        <translation>Vorgabe des Parameterbereichs (Gelatinephantom, wie palpate-cli)</translation>
    </message>
    <message>
        <source>Calibrate slopes</source>
        <translation>Steigungen kalibrieren</translation>
    </message>
    <message>
        <source>displacement error %1 % (RMS/peak over r ≤ 5a), force error %2 %</source>
        <translation>Verschiebungsfehler %1 % (RMS/Spitze über r ≤ 5a), Kraftfehler %2 %</translation>
    </message>
    <message>
        <source>1 ring</source>
        <translation>1 Ring</translation>
    </message>
    <message>
        <source>%1 rings</source>
        <translation>%1 Ringe</translation>
    </message>
    <message>
        <source>at vertex %1 of %2 vertices, pressed %3 mm in; %4 vertices compared.</source>
        <translation>bei Knoten %1 von %2 Knoten, %3 mm eingedrückt; %4 Knoten verglichen.</translation>
    </message>
    <message>
        <source>Note: %1</source>
        <translation>Hinweis: %1</translation>
    </message>
    <message>
        <source>(for the calibrated slopes; the slopes have changed since)</source>
        <translation>(für die kalibrierten Steigungen; die Steigungen haben sich seitdem geändert)</translation>
    </message>
    <message>
        <source>Preset: %1</source>
        <translation>Vorgabe: %1</translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>%1 ändern</translation>
    </message>
    <message>
        <source>%1 parameters</source>
        <translation>%1 Parameter</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>haptic rate = %1 Hz must be in %2..%3 Hz</source>
        <translation>Haptikrate = %1 Hz muss in %2..%3 Hz liegen</translation>
    </message>
    <message>
        <source>%1 (automatic)</source>
        <translation>%1 (automatisch)</translation>
    </message>
    <message>
        <source>Loop gain |m1| × k_c = %1, α = %2</source>
        <translation>Schleifenverstärkung |m1| × k_c = %1, α = %2</translation>
    </message>
    <message>
        <source>α·(1 + gain) = %1 ≥ 2: unstable (the surface oscillates and grows)</source>
        <translation>α·(1 + Verstärkung) = %1 ≥ 2: instabil (die Oberfläche schwingt und wächst)</translation>
    </message>
    <message>
        <source>Stability margin: needs the mesh (the mass-spring step bound depends on its springs)</source>
        <translation>Stabilitätsreserve: braucht das Netz (die Schrittgrenze des Masse-Feder-Modells hängt von seinen Federn ab)</translation>
    </message>
    <message>
        <source>Beyond the stability margin (%1&#xa0;%): Apply asks for confirmation</source>
        <translation>Jenseits der Stabilitätsreserve (%1&#xa0;%): „Übernehmen“ fragt nach einer Bestätigung</translation>
    </message>
    <message>
        <source>Stability margin %1&#xa0;%</source>
        <translation>Stabilitätsreserve %1&#xa0;%</translation>
    </message>
    <message>
        <source>%1 is outside the paper&apos;s range (0, 1) mm/N: allowed by the slope limit %2 mm/N and the loop-gain bound.</source>
        <translation>%1 liegt außerhalb des Bereichs des Artikels (0, 1) mm/N: erlaubt durch die Steigungsgrenze %2 mm/N und die Schranke der Schleifenverstärkung.</translation>
    </message>
    <message>
        <source>%1 are outside the paper&apos;s range (0, 1) mm/N: allowed by the slope limit %2 mm/N and the loop-gain bound.</source>
        <translation>%1 liegen außerhalb des Bereichs des Artikels (0, 1) mm/N: erlaubt durch die Steigungsgrenze %2 mm/N und die Schranke der Schleifenverstärkung.</translation>
    </message>
    <message>
        <source>Beyond the stability margin</source>
        <translation>Jenseits der Stabilitätsreserve</translation>
    </message>
    <message>
        <source>This parameter set is beyond its stability margin:
%1

The model may diverge (or the device buzz); the divergence guard would then zero the force and reset the tissue. Apply anyway?</source>
        <translation>Dieser Parametersatz liegt jenseits seiner Stabilitätsreserve:
%1

Das Modell kann divergieren (oder das Gerät brummen); der Divergenzschutz würde dann die Kraft auf null setzen und das Gewebe zurücksetzen. Trotzdem übernehmen?</translation>
    </message>
    <message>
        <source>%1: could not be read</source>
        <translation>%1: konnte nicht gelesen werden</translation>
    </message>
    <message>
        <source>Preset not loaded; the fields are unchanged:</source>
        <translation>Vorgabe nicht geladen; die Felder sind unverändert:</translation>
    </message>
    <message>
        <source>Load preset %1</source>
        <translation>Vorgabe %1 laden</translation>
    </message>
    <message>
        <source>Loaded %1</source>
        <translation>%1 geladen</translation>
    </message>
    <message>
        <source>(saved with a stability margin of %1&#xa0;% at %2&#xa0;Hz)</source>
        <translation>(gespeichert mit einer Stabilitätsreserve von %1&#xa0;% bei %2&#xa0;Hz)</translation>
    </message>
    <message>
        <source>%1: not saved, the parameters are not valid (see above); the file could not be read back</source>
        <translation>%1: nicht gespeichert, die Parameter sind ungültig (siehe oben); die Datei konnte nicht zurückgelesen werden</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Open preset</source>
        <translation>Vorgabe öffnen</translation>
    </message>
    <message>
        <source>Tissue presets (*.json);;All files (*)</source>
        <translation>Gewebevorgaben (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Save preset</source>
        <translation>Vorgabe speichern</translation>
    </message>
    <message>
        <source>α·(1 + gain) = %1 &lt; 2: loop-gain margin %2&#xa0;%</source>
        <translation>α·(1 + Verstärkung) = %1 &lt; 2: Reserve der Schleifenverstärkung %2&#xa0;%</translation>
    </message>
    <message>
        <source>Far beyond the stability margin: Apply asks for confirmation</source>
        <translation>Weit jenseits der Stabilitätsreserve: „Übernehmen“ fragt nach einer Bestätigung</translation>
    </message>
    <message>
        <source>Close to the stability margin: %1&#xa0;% left (warning below %2&#xa0;%)</source>
        <translation>Nahe an der Stabilitätsgrenze: %1&#xa0;% Reserve (Warnung unter %2&#xa0;%)</translation>
    </message>
    <message>
        <source>The contact force iteration converges while α·(1 + gain) &lt; 2, with the loop gain |m1| × k_c (docs/method.md): the loop-gain margin is 1 − α·(1 + gain) / 2. What the model renders, k_s·|m1|·k_c / (1 + gain) (and, for ours with friction, the proxy&apos;s spring), must stay below the stiffness the device renders passively at the haptic rate (1 N/mm at 1 kHz); a lagging or alternating relaxation (α away from 1 / (1 + gain)) asks more of it (docs/stability.md).</source>
        <translation>Die Iteration der Kontaktkraft konvergiert, solange α·(1 + Verstärkung) &lt; 2, mit der Schleifenverstärkung |m1| × k_c (docs/method.md): die Reserve der Schleifenverstärkung ist 1 − α·(1 + Verstärkung) / 2. Was das Modell darstellt, k_s·|m1|·k_c / (1 + Verstärkung) (und bei unserem Modell mit Reibung die Feder des Proxys), muss unter der Steifigkeit bleiben, die das Gerät bei der Haptikrate passiv darstellt (1 N/mm bei 1 kHz); eine nachlaufende oder alternierende Relaxation (α abseits von 1 / (1 + Verstärkung)) verlangt mehr davon (docs/stability.md).</translation>
    </message>
    <message>
        <source>How far the set is from its derived stability bound at the haptic rate (docs/stability.md): the explicit mass-spring integrators&apos; step bound h·ω_max &lt; 2 (RK4 2.78), ω_max from Gershgorin&apos;s bound and the sub-steps the model takes; and for every model the stiffness it renders (for mass-spring measured on the mesh) against the stiffness the device renders passively (Colgate and Brown, 1 N/mm at 1 kHz). Backward Euler has no step bound.</source>
        <translation>Wie weit der Satz von seiner hergeleiteten Stabilitätsgrenze bei der Haptikrate entfernt ist (docs/stability.md): die Schrittgrenze der expliziten Masse-Feder-Integratoren h·ω_max &lt; 2 (RK4 2,78), ω_max aus der Gerschgorin-Schranke und den Teilschritten des Modells; und für jedes Modell die dargestellte Steifigkeit (bei Masse-Feder am Netz gemessen) gegenüber der Steifigkeit, die das Gerät passiv darstellt (Colgate und Brown, 1 N/mm bei 1 kHz). Impliziter Euler hat keine Schrittgrenze.</translation>
    </message>
    <message>
        <source>&amp;Revert</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <source>Set the fields back to what the haptic loop runs (one undoable step).</source>
        <translation>Setzt die Felder auf das zurück, was die Haptikschleife verwendet (ein rückgängig machbarer Schritt).</translation>
    </message>
    <message>
        <source>Applied to the running tissue at %1</source>
        <translation>Um %1 auf das laufende Gewebe angewendet</translation>
    </message>
    <message>
        <source>Revert to the running tissue</source>
        <translation>Auf das laufende Gewebe zurücksetzen</translation>
    </message>
    <message numerus="yes">
        <source>%n more</source>
        <translation>
            <numerusform>%n weiteres</numerusform>
            <numerusform>%n weitere</numerusform>
        </translation>
    </message>
    <message>
        <source>Not applied: %1 differ from the running tissue. Apply (Ctrl+Return) sends them; Revert goes back to what runs.</source>
        <translation>Nicht angewendet: %1 weichen vom laufenden Gewebe ab. Anwenden (Strg+Eingabe) sendet sie; Zurücksetzen stellt her, was läuft.</translation>
    </message>
    <message>
        <source>Apply stiffening knots</source>
        <translation>Versteifungsknoten anwenden</translation>
    </message>
    <message>
        <source>Not applied: the parameters are not valid (see the Parameters panel).</source>
        <translation>Nicht angewandt: die Parameter sind ungültig (siehe Parameter).</translation>
    </message>
</context>
<context>
    <name>palpate::Parameters</name>
    <message>
        <source>ring count</source>
        <translation>Ringanzahl</translation>
    </message>
    <message>
        <source>slope limit</source>
        <translation>Steigungsgrenze</translation>
    </message>
    <message>
        <source>spring stiffness</source>
        <translation>Federsteifigkeit</translation>
    </message>
    <message>
        <source>damping ratio</source>
        <translation>Dämpfungsgrad</translation>
    </message>
    <message>
        <source>contact stiffness</source>
        <translation>Kontaktsteifigkeit</translation>
    </message>
    <message>
        <source>force relaxation</source>
        <translation>Kraftrelaxation</translation>
    </message>
    <message>
        <source>vertex mass</source>
        <translation>Knotenmasse</translation>
    </message>
    <message>
        <source>octree depth</source>
        <translation>Octree-Tiefe</translation>
    </message>
    <message>
        <source>leaf capacity</source>
        <translation>Blattkapazität</translation>
    </message>
    <message>
        <source>Young&apos;s modulus</source>
        <translation>Elastizitätsmodul</translation>
    </message>
    <message>
        <source>Poisson&apos;s ratio</source>
        <translation>Poissonzahl</translation>
    </message>
    <message>
        <source>tool radius</source>
        <translation>Werkzeugradius</translation>
    </message>
    <message>
        <source>Young&apos;s modulus E:</source>
        <translation>Elastizitätsmodul E:</translation>
    </message>
    <message>
        <source>Stiffness of the tissue, kPa (soft tissue: about 1 to 30 kPa).</source>
        <translation>Steifigkeit des Gewebes, kPa (Weichgewebe: etwa 1 bis 30 kPa).</translation>
    </message>
    <message>
        <source>Poisson&apos;s ratio ν:</source>
        <translation>Poissonzahl ν:</translation>
    </message>
    <message>
        <source>Tool radius a:</source>
        <translation>Werkzeugradius a:</translation>
    </message>
    <message>
        <source>Symplectic Euler</source>
        <translation>Symplektischer Euler</translation>
    </message>
    <message>
        <source>RK4</source>
        <translation>RK4</translation>
    </message>
    <message>
        <source>Backward Euler (implicit)</source>
        <translation>Impliziter Euler</translation>
    </message>
    <message>
        <source>Ring count:</source>
        <translation>Ringanzahl:</translation>
    </message>
    <message>
        <source>Rings of neighbours displaced with the touched vertex (ring r: the vertices r edges away). The paper uses 2; each ring adds a slope below.</source>
        <translation>Ringe von Nachbarn, die mit dem berührten Knoten verschoben werden (Ring r: die Knoten r Kanten entfernt). Der Artikel verwendet 2; jeder Ring fügt unten eine Steigung hinzu.</translation>
    </message>
    <message>
        <source>Slope magnitude |m| in mm/N: how far the vertex moves per newton of contact force; the model applies the paper&apos;s sign (m &lt; 0), which moves the vertex into the tissue.</source>
        <translation>Steigungsbetrag |m| in mm/N: wie weit sich der Knoten pro Newton Kontaktkraft bewegt; das Modell wendet das Vorzeichen des Artikels an (m &lt; 0), das den Knoten ins Gewebe bewegt.</translation>
    </message>
    <message>
        <source>Slope limit:</source>
        <translation>Steigungsgrenze:</translation>
    </message>
    <message>
        <source>Every slope magnitude must stay below this limit. The paper&apos;s range ends at 1 mm/N; calibrated soft tissue may need more (at most 100 mm/N), allowed while the loop gain stays stable. Slopes above 1 mm/N are marked as outside the paper&apos;s range.</source>
        <translation>Jeder Steigungsbetrag muss unter dieser Grenze bleiben. Der Bereich des Artikels endet bei 1 mm/N; kalibriertes Weichgewebe kann mehr brauchen (höchstens 100 mm/N), erlaubt, solange die Schleifenverstärkung stabil bleibt. Steigungen über 1 mm/N werden als außerhalb des Bereichs des Artikels markiert.</translation>
    </message>
    <message>
        <source>Spring stiffness k:</source>
        <translation>Federsteifigkeit k:</translation>
    </message>
    <message>
        <source>Stiffness of the springs that tie each vertex to its rest position. The touched vertex&apos;s spring reaction is the force rendered to the user.</source>
        <translation>Steifigkeit der Federn, die jeden Knoten an seine Ruhelage binden. Die Federreaktion des berührten Knotens ist die Kraft, die der Benutzer spürt.</translation>
    </message>
    <message>
        <source>Damping ratio:</source>
        <translation>Dämpfungsgrad:</translation>
    </message>
    <message>
        <source>Damping of the return springs as a fraction of critical: 1 returns without overshoot, below 1 the tissue rings before it settles (0..100).</source>
        <translation>Dämpfung der Rückstellfedern als Anteil der kritischen: 1 kehrt ohne Überschwingen zurück, unter 1 schwingt das Gewebe, bevor es zur Ruhe kommt (0..100).</translation>
    </message>
    <message>
        <source>Contact stiffness k_c:</source>
        <translation>Kontaktsteifigkeit k_c:</translation>
    </message>
    <message>
        <source>Stiffness of the tool-tissue contact (a penalty spring). The loop gain is |m1| × k_c.</source>
        <translation>Steifigkeit des Kontakts zwischen Werkzeug und Gewebe (eine Straffeder). Die Schleifenverstärkung ist |m1| × k_c.</translation>
    </message>
    <message>
        <source>Force relaxation α:</source>
        <translation>Kraftrelaxation α:</translation>
    </message>
    <message>
        <source>Per-tick relaxation α of the contact force, in (0, 1]. Automatic (0) uses α = 1 / (1 + gain), which solves the contact in one tick for any gain. The update is stable while α·(1 + gain) &lt; 2.</source>
        <translation>Relaxation α der Kontaktkraft pro Tick, in (0, 1]. Automatisch (0) verwendet α = 1 / (1 + Verstärkung), was den Kontakt für jede Verstärkung in einem Tick löst. Das Update ist stabil, solange α·(1 + Verstärkung) &lt; 2.</translation>
    </message>
    <message>
        <source>Vertex mass:</source>
        <translation>Knotenmasse:</translation>
    </message>
    <message>
        <source>Lumped mass per vertex, for the relaxation after the tool lets go.</source>
        <translation>Konzentrierte Masse pro Knoten, für die Relaxation, nachdem das Werkzeug loslässt.</translation>
    </message>
    <message>
        <source>Max depth:</source>
        <translation>Max. Tiefe:</translation>
    </message>
    <message>
        <source>Levels below the octree&apos;s root (1..20).</source>
        <translation>Ebenen unter der Wurzel des Octrees (1..20).</translation>
    </message>
    <message>
        <source>Leaf capacity:</source>
        <translation>Blattkapazität:</translation>
    </message>
    <message>
        <source>A node with at most this many vertices is not split (1..100000).</source>
        <translation>Ein Knoten des Baums mit höchstens so vielen Netzknoten wird nicht geteilt (1..100000).</translation>
    </message>
    <message>
        <source>vertices</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>How the tissue bulges sideways when pressed, 0..0.4999 (soft tissue is nearly incompressible: about 0.45 to 0.49; 0.5 would be incompressible).</source>
        <translation>Wie stark sich das Gewebe beim Drücken seitlich wölbt, 0..0,4999 (Weichgewebe ist nahezu inkompressibel: etwa 0,45 bis 0,49; 0,5 wäre inkompressibel).</translation>
    </message>
    <message>
        <source>Radius of the probe&apos;s flat tip, mm (0.01..1000).</source>
        <translation>Radius der flachen Sondenspitze, mm (0,01..1000).</translation>
    </message>
    <message>
        <source>Control points per axis:</source>
        <translation>Kontrollpunkte pro Achse:</translation>
    </message>
    <message>
        <source>Lattice resolution: control points per axis, Bernstein degree + 1 (2..16).</source>
        <translation>Gitterauflösung: Kontrollpunkte pro Achse, Bernstein-Grad + 1 (2..16).</translation>
    </message>
    <message>
        <source>Moved per axis:</source>
        <translation>Bewegt pro Achse:</translation>
    </message>
    <message>
        <source>Control points moved per axis: the block nearest the contact (1..control points).</source>
        <translation>Pro Achse bewegte Kontrollpunkte: der Block, der dem Kontakt am nächsten liegt (1..Kontrollpunkte).</translation>
    </message>
    <message>
        <source>Lattice margin:</source>
        <translation>Gitterrand:</translation>
    </message>
    <message>
        <source>The lattice is the mesh&apos;s bounding box grown by this fraction of its diagonal, in (0, 1].</source>
        <translation>Das Gitter ist der Hüllquader des Netzes, vergrößert um diesen Anteil seiner Diagonale, in (0, 1].</translation>
    </message>
    <message>
        <source>Stiffness k_s:</source>
        <translation>Steifigkeit k_s:</translation>
    </message>
    <message>
        <source>The rendered force is k_s times the touched vertex&apos;s displacement, N/mm.</source>
        <translation>Die ausgegebene Kraft ist k_s mal die Verschiebung des berührten Knotens, N/mm.</translation>
    </message>
    <message>
        <source>Vertex mass m:</source>
        <translation>Knotenmasse m:</translation>
    </message>
    <message>
        <source>Lumped mass per vertex, kg.</source>
        <translation>Konzentrierte Masse pro Knoten, kg.</translation>
    </message>
    <message>
        <source>Anchor stiffness k_a:</source>
        <translation>Ankersteifigkeit k_a:</translation>
    </message>
    <message>
        <source>Spring from each vertex to its rest position, N/mm: what holds the shape.</source>
        <translation>Feder von jedem Knoten zu seiner Ruhelage, N/mm: sie hält die Form.</translation>
    </message>
    <message>
        <source>Edge stiffness k_e:</source>
        <translation>Kantensteifigkeit k_e:</translation>
    </message>
    <message>
        <source>Spring along each mesh edge, N/mm: spreads the dent to the neighbours.</source>
        <translation>Feder entlang jeder Netzkante, N/mm: verteilt die Delle auf die Nachbarn.</translation>
    </message>
    <message>
        <source>Penalty stiffness between the tool tip and the touched vertex, N/mm.</source>
        <translation>Straf-Steifigkeit zwischen Werkzeugspitze und berührtem Knoten, N/mm.</translation>
    </message>
    <message>
        <source>Damping ratio ζ:</source>
        <translation>Dämpfungsgrad ζ:</translation>
    </message>
    <message>
        <source>Velocity damping as a fraction of the anchor spring&apos;s critical damping (0..100).</source>
        <translation>Geschwindigkeitsdämpfung als Anteil der kritischen Dämpfung der Ankerfeder (0..100).</translation>
    </message>
    <message>
        <source>Sub-steps:</source>
        <translation>Teilschritte:</translation>
    </message>
    <message>
        <source>Explicit integrators: sub-steps per tick; 0 = automatic (inside the stability bound); at most the max sub-steps.</source>
        <translation>Explizite Integratoren: Teilschritte pro Takt; 0 = automatisch (innerhalb der Stabilitätsgrenze); höchstens die maximalen Teilschritte.</translation>
    </message>
    <message>
        <source>Max sub-steps:</source>
        <translation>Max. Teilschritte:</translation>
    </message>
    <message>
        <source>Cap on automatic sub-steps (bounded work per tick).</source>
        <translation>Obergrenze für automatische Teilschritte (begrenzte Arbeit pro Takt).</translation>
    </message>
    <message>
        <source>CG iterations (max):</source>
        <translation>CG-Iterationen (max.):</translation>
    </message>
    <message>
        <source>Backward Euler: conjugate-gradient iteration cap.</source>
        <translation>Rückwärts-Euler: Obergrenze der Iterationen des konjugierten Gradientenverfahrens.</translation>
    </message>
    <message>
        <source>CG tolerance:</source>
        <translation>CG-Toleranz:</translation>
    </message>
    <message>
        <source>Backward Euler: relative residual at which conjugate gradients stop, in (0, 1).</source>
        <translation>Rückwärts-Euler: relatives Residuum, bei dem das CG-Verfahren anhält, in (0, 1).</translation>
    </message>
    <message>
        <source>Simulated rings:</source>
        <translation>Simulierte Ringe:</translation>
    </message>
    <message>
        <source>Rings of the touched vertex that are simulated; everything else is pinned at rest.</source>
        <translation>Ringe des berührten Knotens, die simuliert werden; alles andere bleibt in Ruhelage fixiert.</translation>
    </message>
    <message>
        <source>Integrator:</source>
        <translation>Integrator:</translation>
    </message>
    <message>
        <source>The local variant&apos;s integrator: symplectic Euler, RK4 or backward Euler.</source>
        <translation>Der Integrator der lokalen Variante: symplektischer Euler, RK4 oder Rückwärts-Euler.</translation>
    </message>
    <message>
        <source>Rest tolerance:</source>
        <translation>Ruhetoleranz:</translation>
    </message>
    <message>
        <source>A vertex outside the rings this close to rest and moving less than this per tick stops being simulated, mm.</source>
        <translation>Ein Knoten außerhalb der Ringe, der so nah an der Ruhelage ist und sich pro Takt weniger bewegt, wird nicht mehr simuliert, mm.</translation>
    </message>
    <message>
        <source>Radius R:</source>
        <translation>Radius R:</translation>
    </message>
    <message>
        <source>Every vertex within this distance of the touched vertex (in 3D, whatever the edges) moves, mm.</source>
        <translation>Jeder Knoten innerhalb dieses Abstands vom berührten Knoten (in 3D, unabhängig von den Kanten) bewegt sich, mm.</translation>
    </message>
    <message>
        <source>Profile degree:</source>
        <translation>Profilgrad:</translation>
    </message>
    <message>
        <source>The profile is (1 − r/R)^degree (2..8); a preset file&apos;s own coefficients are kept until the degree changes.</source>
        <translation>Das Profil ist (1 − r/R)^Grad (2..8); die eigenen Koeffizienten einer Voreinstellungsdatei bleiben, bis sich der Grad ändert.</translation>
    </message>
    <message>
        <source>Static friction μs:</source>
        <translation>Haftreibung μs:</translation>
    </message>
    <message>
        <source>static friction coefficient</source>
        <translation>Haftreibungskoeffizient</translation>
    </message>
    <message>
        <source>Coulomb friction between tool and tissue: the tool sticks until the sideways force exceeds μs times the normal force (0..5; 0 and 0: no friction). Moist soft tissue: about 0.3.</source>
        <translation>Coulomb-Reibung zwischen Werkzeug und Gewebe: Das Werkzeug haftet, bis die seitliche Kraft μs mal die Normalkraft übersteigt (0..5; 0 und 0: keine Reibung). Feuchtes Weichgewebe: etwa 0,3.</translation>
    </message>
    <message>
        <source>Sliding friction μd:</source>
        <translation>Gleitreibung μd:</translation>
    </message>
    <message>
        <source>sliding friction coefficient</source>
        <translation>Gleitreibungskoeffizient</translation>
    </message>
    <message>
        <source>While the tool slides, the sideways force is μd times the normal force (0..5, at most μs).</source>
        <translation>Während das Werkzeug gleitet, ist die seitliche Kraft μd mal die Normalkraft (0..5, höchstens μs).</translation>
    </message>
    <message>
        <source>Stiffening knots:</source>
        <translation>Versteifungsknoten:</translation>
    </message>
    <message>
        <source>stiffening knots</source>
        <translation>Versteifungsknoten</translation>
    </message>
    <message>
        <source>Points of the strain-stiffening curve, calibrated from the hyperelastic reference. 0: linear tissue, the paper&apos;s model.</source>
        <translation>Punkte der Kurve, mit der das Gewebe unter Dehnung steifer wird, kalibriert an der hyperelastischen Referenz. 0: lineares Gewebe, das Modell des Artikels.</translation>
    </message>
    <message>
        <source>Contact force above which the next stiffening compliance applies, N.</source>
        <translation>Kontaktkraft, oberhalb der die nächste Versteifungsnachgiebigkeit gilt, N.</translation>
    </message>
    <message>
        <source>Above its knot the tissue yields this fraction of |m1| per further newton: below 1, it stiffens.</source>
        <translation>Oberhalb seines Knotens gibt das Gewebe je weiteres Newton um diesen Anteil von |m1| nach: unter 1 wird es steifer.</translation>
    </message>
    <message>
        <source>stiffening exponent</source>
        <translation>Versteifungsexponent</translation>
    </message>
    <message>
        <source>Stiffening b (reference):</source>
        <translation>Versteifung b (Referenz):</translation>
    </message>
    <message>
        <source>How fast the tissue stiffens with strain: b of the exponential law of the hyperelastic reference (0..100; 0: neo-Hookean). It does not change the force by itself: Charts &gt; Stiffening &gt; Compute solves the reference with it, and Apply knots puts the model&apos;s stiffening knots into the tissue.</source>
        <translation>Wie schnell das Gewebe mit der Dehnung steifer wird: b des Exponentialgesetzes der hyperelastischen Referenz (0..100; 0: Neo-Hooke). Es ändert die Kraft nicht von selbst: Diagramme &gt; Versteifung &gt; Berechnen löst die Referenz damit, und Knoten anwenden setzt die Versteifungsknoten des Modells in das Gewebe.</translation>
    </message>
</context>
<context>
    <name>palpate::Preferences</name>
    <message>
        <source>%1 gf</source>
        <translation>%1 gf</translation>
    </message>
    <message>
        <source>%1 N</source>
        <translation>%1 N</translation>
    </message>
</context>
<context>
    <name>palpate::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Systemvorgabe</translation>
    </message>
    <message>
        <source>A new language applies when Palpate is started again.</source>
        <translation>Eine neue Sprache gilt ab dem nächsten Start von Palpate.</translation>
    </message>
    <message>
        <source>newtons (N)</source>
        <translation>Newton (N)</translation>
    </message>
    <message>
        <source>gram-force (gf, 1 gf = 9.81 mN)</source>
        <translation>Pond (gf, 1 gf = 9,81 mN)</translation>
    </message>
    <message>
        <source>As the tissue preset says</source>
        <translation>Wie die Gewebevorgabe angibt</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>Ticks per second of the haptic loop. Higher rates feel stiffer tissue as stable, and need a faster computer.</source>
        <translation>Ticks pro Sekunde der Haptikschleife. Höhere Raten geben steiferes Gewebe stabil wieder und brauchen einen schnelleren Rechner.</translation>
    </message>
    <message>
        <source>Built-in default (the mouse)</source>
        <translation>Eingebaute Vorgabe (die Maus)</translation>
    </message>
    <message>
        <source>The device the window uses when it starts (--device overrides it).</source>
        <translation>Das Gerät, das das Fenster beim Start verwendet (--device hat Vorrang).</translation>
    </message>
    <message>
        <source>Recordings (in recordings/) and the trainees&apos; results (results.sqlite) are kept here.</source>
        <translation>Aufnahmen (in recordings/) und die Ergebnisse der Teilnehmer (results.sqlite) werden hier abgelegt.</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Durchsuchen…</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Sprache:</translation>
    </message>
    <message>
        <source>&amp;Forces shown in:</source>
        <translation>&amp;Kräfte anzeigen in:</translation>
    </message>
    <message>
        <source>&amp;Haptic rate:</source>
        <translation>&amp;Haptikrate:</translation>
    </message>
    <message>
        <source>&amp;Device at start:</source>
        <translation>&amp;Gerät beim Start:</translation>
    </message>
    <message>
        <source>Device: %1</source>
        <translation>Gerät: %1</translation>
    </message>
    <message>
        <source>The data folder must be an absolute path.</source>
        <translation>Der Datenordner muss ein absoluter Pfad sein.</translation>
    </message>
    <message>
        <source>Data Folder</source>
        <translation>Datenordner</translation>
    </message>
    <message>
        <source>Data f&amp;older:</source>
        <translation>Daten&amp;ordner:</translation>
    </message>
    <message>
        <source>F&amp;ade the force gauge as the trainee improves</source>
        <translation>Kraftanzeige &amp;ausblenden, wenn Lernende besser werden</translation>
    </message>
    <message>
        <source>Continuous force feedback breeds dependence: each good session of an exercise fades the gauge, each poor one brings it back</source>
        <translation>Ständige Kraftrückmeldung macht abhängig: Jede gute Sitzung einer Übung blendet die Anzeige weiter aus, jede schwache holt sie zurück</translation>
    </message>
    <message>
        <source> good sessions to fade out</source>
        <translation> gute Sitzungen bis ausgeblendet</translation>
    </message>
    <message>
        <source>good at </source>
        <translation>gut ab </translation>
    </message>
    <message>
        <source> / 100 or more</source>
        <translation> / 100</translation>
    </message>
    <message>
        <source>Guidance:</source>
        <translation>Hilfen:</translation>
    </message>
    <message>
        <source>none (results stay on this workstation)</source>
        <translation>keiner (die Ergebnisse bleiben auf diesem Arbeitsplatz)</translation>
    </message>
    <message>
        <source>The class&apos;s PostgreSQL server, postgresql://user@host/database: every result is kept here first and copied there when it answers. The password goes in ~/.pgpass, never here (docs/results-store.md).</source>
        <translation>Der PostgreSQL-Server der Klasse, postgresql://benutzer@host/datenbank: jedes Ergebnis wird zuerst hier gespeichert und dorthin kopiert, sobald er antwortet. Das Passwort gehört in ~/.pgpass, nie hierher (docs/results-store.md).</translation>
    </message>
    <message>
        <source>Class&apos;s &amp;server:</source>
        <translation>&amp;Server der Klasse:</translation>
    </message>
    <message>
        <source>Class&apos;s server: postgresql://[user@]host[:port]/database</source>
        <translation>Server der Klasse: postgresql://[benutzer@]host[:port]/datenbank</translation>
    </message>
    <message>
        <source>Class&apos;s server: no password here; put it in ~/.pgpass (docs/results-store.md).</source>
        <translation>Server der Klasse: kein Passwort hier; es gehört in ~/.pgpass (docs/results-store.md).</translation>
    </message>
    <message>
        <source>Class&apos;s server: %1</source>
        <translation>Server der Klasse: %1</translation>
    </message>
</context>
<context>
    <name>palpate::RecorderPanel</name>
    <message>
        <source>%1 is not a Palpate recording (%2)</source>
        <translation>%1 ist keine Palpate-Aufnahme (%2)</translation>
    </message>
    <message>
        <source>%1: the header is damaged (%2); %3 chunks were recovered, but a replay needs the header</source>
        <translation>%1: der Kopf ist beschädigt (%2); %3 Blöcke wurden wiederhergestellt, aber eine Wiedergabe braucht den Kopf</translation>
    </message>
    <message>
        <source>%1 damaged region(s) skipped (%2 bytes)</source>
        <translation>%1 beschädigte Bereich(e) übersprungen (%2 Bytes)</translation>
    </message>
    <message>
        <source>%1 ticks lost</source>
        <translation>%1 Ticks verloren</translation>
    </message>
    <message>
        <source>%1 ticks dropped while recording (%2 gap(s))</source>
        <translation>%1 Ticks beim Aufnehmen verworfen (%2 Lücke(n))</translation>
    </message>
    <message>
        <source>%1 chunk(s) whose hash disagrees with their ticks</source>
        <translation>%1 Block/Blöcke, deren Hash nicht zu ihren Ticks passt</translation>
    </message>
    <message>
        <source>not closed cleanly (the program ended while recording)</source>
        <translation>nicht sauber geschlossen (das Programm endete während der Aufnahme)</translation>
    </message>
    <message>
        <source>%1 is damaged. Recovered %2 chunks (%3 ticks); lost: %4.</source>
        <translation>%1 ist beschädigt. %2 Blöcke (%3 Ticks) wiederhergestellt; verloren: %4.</translation>
    </message>
    <message>
        <source>%1 is incomplete. Recovered %2 chunks (%3 ticks); lost: %4.</source>
        <translation>%1 ist unvollständig. %2 Blöcke (%3 Ticks) wiederhergestellt; verloren: %4.</translation>
    </message>
    <message>
        <source>offset %1, %2 bytes: %3</source>
        <translation>Offset %1, %2 Bytes: %3</translation>
    </message>
    <message>
        <source> (ticks %1 to %2)</source>
        <translation> (Ticks %1 bis %2)</translation>
    </message>
    <message>
        <source>…</source>
        <translation>…</translation>
    </message>
    <message>
        <source>Mark: %1</source>
        <translation>Markierung: %1</translation>
    </message>
    <message>
        <source>Exercise event: %1</source>
        <translation>Übungsereignis: %1</translation>
    </message>
    <message>
        <source>Parameters applied</source>
        <translation>Parameter übernommen</translation>
    </message>
    <message>
        <source>Scene changed without a description (the replay stops here)</source>
        <translation>Szene ohne Beschreibung geändert (die Wiedergabe endet hier)</translation>
    </message>
    <message>
        <source>Scene changed: %1</source>
        <translation>Szene geändert: %1</translation>
    </message>
    <message>
        <source>Device changed: %1</source>
        <translation>Gerät gewechselt: %1</translation>
    </message>
    <message>
        <source>(not described)</source>
        <translation>(nicht beschrieben)</translation>
    </message>
    <message>
        <source>Device state: %1</source>
        <translation>Gerätezustand: %1</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Pausiert</translation>
    </message>
    <message>
        <source>Resumed</source>
        <translation>Fortgesetzt</translation>
    </message>
    <message>
        <source>%1 command(s) lost: the replay may differ from here</source>
        <translation>%1 Befehl(e) verloren: die Wiedergabe kann ab hier abweichen</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>Aufnahme</translation>
    </message>
    <message>
        <source>Playback</source>
        <translation>Wiedergabe</translation>
    </message>
    <message>
        <source>● &amp;Record</source>
        <translation>● &amp;Aufnehmen</translation>
    </message>
    <message>
        <source>■ S&amp;top</source>
        <translation>■ S&amp;toppen</translation>
    </message>
    <message>
        <source>Stop recording and close the file cleanly (Ctrl+Shift+R)</source>
        <translation>Aufnahme beenden und die Datei sauber schließen (Strg+Umschalt+R)</translation>
    </message>
    <message>
        <source>Folder…</source>
        <translation>Ordner…</translation>
    </message>
    <message>
        <source>Mark text (optional)</source>
        <translation>Markierungstext (optional)</translation>
    </message>
    <message>
        <source>The text of the next mark; Return adds it</source>
        <translation>Der Text der nächsten Markierung; Eingabetaste fügt sie hinzu</translation>
    </message>
    <message>
        <source>&amp;Mark</source>
        <translation>&amp;Markieren</translation>
    </message>
    <message>
        <source>Add a mark at the current tick of the recording (M)</source>
        <translation>Eine Markierung beim aktuellen Tick der Aufnahme setzen (M)</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>Open a recording to play it back (the live session pauses while it plays)</source>
        <translation>Eine Aufnahme zur Wiedergabe öffnen (die laufende Sitzung pausiert währenddessen)</translation>
    </message>
    <message>
        <source>Back to &amp;Live</source>
        <translation>Zurück zu &amp;Live</translation>
    </message>
    <message>
        <source>Close the recording and resume the live session</source>
        <translation>Die Aufnahme schließen und die laufende Sitzung fortsetzen</translation>
    </message>
    <message>
        <source>▶ &amp;Play</source>
        <translation>▶ &amp;Abspielen</translation>
    </message>
    <message>
        <source>Play or pause the recording (Space while the timeline has the focus)</source>
        <translation>Die Aufnahme abspielen oder pausieren (Leertaste, wenn die Zeitleiste den Fokus hat)</translation>
    </message>
    <message>
        <source>Playback speed</source>
        <translation>Wiedergabegeschwindigkeit</translation>
    </message>
    <message>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <source>Current time / length of the recording (loop clock)</source>
        <translation>Aktuelle Zeit / Länge der Aufnahme (Schleifenuhr)</translation>
    </message>
    <message>
        <source>Replaying from the start to reach that tick</source>
        <translation>Wiedergabe vom Anfang, um diesen Tick zu erreichen</translation>
    </message>
    <message>
        <source>Folder for New Recordings</source>
        <translation>Ordner für neue Aufnahmen</translation>
    </message>
    <message>
        <source>%1: the recordings folder cannot be created</source>
        <translation>%1: der Aufnahmeordner kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>Mark %1</source>
        <translation>Markierung %1</translation>
    </message>
    <message>
        <source>Recording to %1…</source>
        <translation>Aufnahme nach %1…</translation>
    </message>
    <message>
        <source>Not recording.
Folder: %1</source>
        <translation>Keine Aufnahme.
Ordner: %1</translation>
    </message>
    <message>
        <source>%1 %2 · %3 ticks · %4 · %5 B/tick · drops %6 (%7 gaps)</source>
        <translation>%1 %2 · %3 Ticks · %4 · %5 B/Tick · verworfen %6 (%7 Lücken)</translation>
    </message>
    <message>
        <source>● REC</source>
        <translation>● REC</translation>
    </message>
    <message>
        <source>Saved %1:</source>
        <translation>%1 gespeichert:</translation>
    </message>
    <message>
        <source>Stopped %1:</source>
        <translation>%1 gestoppt:</translation>
    </message>
    <message>
        <source> · %1 commands lost</source>
        <translation> · %1 Befehle verloren</translation>
    </message>
    <message>
        <source>%1
Elapsed loop time, ticks written, file size, bytes per tick, ticks dropped because the writer fell behind (each run is a gap)</source>
        <translation>%1
Vergangene Schleifenzeit, geschriebene Ticks, Dateigröße, Bytes pro Tick, verworfene Ticks, weil der Schreiber zurückfiel (jede Folge ist eine Lücke)</translation>
    </message>
    <message>
        <source>Added “%1” · next mark text</source>
        <translation>„%1“ hinzugefügt · Text der nächsten Markierung</translation>
    </message>
    <message>
        <source>Record the live session to a new file in %1 (Ctrl+Shift+R).
Starting resets the tissue to rest and the force ramps in again (as after a device switch): a recording replays from its start alone.</source>
        <translation>Die laufende Sitzung in eine neue Datei in %1 aufnehmen (Strg+Umschalt+R).
Der Start setzt das Gewebe in Ruhe zurück, und die Kraft wird erneut eingeblendet (wie nach einem Gerätewechsel): eine Aufnahme lässt sich allein von ihrem Anfang wiedergeben.</translation>
    </message>
    <message>
        <source>Go back to the live session to record</source>
        <translation>Zum Aufnehmen zur laufenden Sitzung zurückkehren</translation>
    </message>
    <message>
        <source>Where new recordings go: %1</source>
        <translation>Wohin neue Aufnahmen gehen: %1</translation>
    </message>
    <message>
        <source>❚❚ &amp;Pause</source>
        <translation>❚❚ &amp;Pause</translation>
    </message>
    <message>
        <source>Open Recording</source>
        <translation>Aufnahme öffnen</translation>
    </message>
    <message>
        <source>Palpate recordings (*.palprec);;All files (*)</source>
        <translation>Palpate-Aufnahmen (*.palprec);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation>%1 wird geöffnet…</translation>
    </message>
    <message>
        <source>%1: cannot replay: %2</source>
        <translation>%1: Wiedergabe nicht möglich: %2</translation>
    </message>
    <message>
        <source>Replaying to %1… %2 %</source>
        <translation>Wiedergabe bis %1… %2 %</translation>
    </message>
    <message>
        <source>%1
Recorded with Palpate %2 at %3 Hz on %4; device %5; %6 ticks, %7 events</source>
        <translation>%1
Aufgenommen mit Palpate %2 bei %3 Hz am %4; Gerät %5; %6 Ticks, %7 Ereignisse</translation>
    </message>
    <message>
        <source>Dropped while recording</source>
        <translation>Beim Aufnehmen verworfen</translation>
    </message>
    <message>
        <source>Damaged (%1)</source>
        <translation>Beschädigt (%1)</translation>
    </message>
    <message>
        <source>Lost (damaged or missing)</source>
        <translation>Verloren (beschädigt oder fehlend)</translation>
    </message>
    <message>
        <source>Past where the replay stops (%1)</source>
        <translation>Hinter dem Ende der Wiedergabe (%1)</translation>
    </message>
    <message>
        <source>—:— / —:—</source>
        <translation>—:— / —:—</translation>
    </message>
    <message>
        <source>%1 / %2  (tick %3)</source>
        <translation>%1 / %2  (Tick %3)</translation>
    </message>
    <message>
        <source>Open a recording to play it back and check its replay.</source>
        <translation>Eine Aufnahme öffnen, um sie wiederzugeben und ihre Wiedergabe zu prüfen.</translation>
    </message>
    <message>
        <source>Replay check: play or go to the end (End) to compare every tick with the recording.</source>
        <translation>Wiedergabeprüfung: abspielen oder ans Ende gehen (Ende), um jeden Tick mit der Aufnahme zu vergleichen.</translation>
    </message>
    <message>
        <source>✔ The replay matches the recording bit for bit (%1 ticks, %2 chunk hashes checked).</source>
        <translation>✔ Die Wiedergabe stimmt Bit für Bit mit der Aufnahme überein (%1 Ticks, %2 Block-Hashes geprüft).</translation>
    </message>
    <message>
        <source>✘ The replay differs from the recording (%1 ticks). First: %2</source>
        <translation>✘ Die Wiedergabe weicht von der Aufnahme ab (%1 Ticks). Zuerst: %2</translation>
    </message>
    <message>
        <source>✘ %1 of %2 chunk hashes differ from the replay&apos;s.</source>
        <translation>✘ %1 von %2 Block-Hashes weichen von denen der Wiedergabe ab.</translation>
    </message>
    <message>
        <source>The replay stopped early: %1. The %2 ticks replayed match the recording.</source>
        <translation>Die Wiedergabe endete früh: %1. Die %2 wiedergegebenen Ticks stimmen mit der Aufnahme überein.</translation>
    </message>
    <message>
        <source>%1: is a folder, not a recording</source>
        <translation>%1: ist ein Ordner, keine Aufzeichnung</translation>
    </message>
    <message>
        <source>%1: is not a regular file (a FIFO or a device), not a recording</source>
        <translation>%1: ist keine gewöhnliche Datei (ein FIFO oder ein Gerät), keine Aufzeichnung</translation>
    </message>
    <message>
        <source>Divergence guard fired: %1</source>
        <translation>Divergenzwächter ausgelöst: %1</translation>
    </message>
</context>
<context>
    <name>palpate::RecordingController</name>
    <message>
        <source>Recorder</source>
        <translation>Rekorder</translation>
    </message>
    <message>
        <source>Re&amp;cord</source>
        <translation>&amp;Aufnehmen</translation>
    </message>
    <message>
        <source>Record the live session to a new file (again: stop). Starting resets the tissue to rest and the force ramps in again</source>
        <translation>Die laufende Sitzung in eine neue Datei aufnehmen (nochmals: beenden). Der Start setzt das Gewebe in Ruhe zurück, und die Kraft wird erneut eingeblendet</translation>
    </message>
    <message>
        <source>Add &amp;Mark</source>
        <translation>&amp;Markierung setzen</translation>
    </message>
    <message>
        <source>Mark the current moment of the recording (the Recorder dock&apos;s text, if any)</source>
        <translation>Den aktuellen Moment der Aufnahme markieren (mit dem Text aus dem Rekorder-Dock, falls vorhanden)</translation>
    </message>
    <message>
        <source>Go back to the live session before recording</source>
        <translation>Vor dem Aufnehmen zur laufenden Sitzung zurückkehren</translation>
    </message>
    <message>
        <source>Load a mesh before recording: there is no session to record</source>
        <translation>Vor dem Aufnehmen ein Netz laden: es gibt keine Sitzung zum Aufnehmen</translation>
    </message>
    <message>
        <source>Recording to %1</source>
        <translation>Aufnahme nach %1</translation>
    </message>
    <message>
        <source>Cannot record: %1</source>
        <translation>Aufnahme nicht möglich: %1</translation>
    </message>
    <message>
        <source>The recording failed: %1</source>
        <translation>Die Aufnahme ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Recording saved: %1</source>
        <translation>Aufnahme gespeichert: %1</translation>
    </message>
    <message>
        <source>mark (trainee)</source>
        <translation>Markierung (Teilnehmer)</translation>
    </message>
    <message>
        <source>Mark added: %1</source>
        <translation>Markierung gesetzt: %1</translation>
    </message>
    <message>
        <source>Recording stopped: %1 (%2 keeps what was written before)</source>
        <translation>Aufnahme beendet: %1 (%2 behält, was vorher geschrieben wurde)</translation>
    </message>
    <message>
        <source>● REC %1</source>
        <translation>● REC %1</translation>
    </message>
    <message>
        <source>▶ playback</source>
        <translation>▶ Wiedergabe</translation>
    </message>
    <message>
        <source>A recording is still being opened; try again when it is done</source>
        <translation>Eine Aufnahme wird noch geöffnet; versuchen Sie es erneut, wenn das fertig ist</translation>
    </message>
    <message>
        <source>Recording stopped to play %1 back</source>
        <translation>Aufnahme beendet, um %1 wiederzugeben</translation>
    </message>
</context>
<context>
    <name>palpate::RecordingTimeline</name>
    <message>
        <source>Recording timeline</source>
        <translation>Zeitleiste der Aufnahme</translation>
    </message>
    <message>
        <source>Arrows step, Page Up and Page Down jump, Home and End go to the ends, Ctrl+arrows go to the previous or next event, Space plays or pauses</source>
        <translation>Pfeiltasten gehen schrittweise, Bild auf und Bild ab springen, Pos1 und Ende gehen an die Enden, Strg+Pfeiltasten gehen zum vorigen oder nächsten Ereignis, Leertaste spielt ab oder pausiert</translation>
    </message>
    <message>
        <source>Open a recording to scrub through it</source>
        <translation>Eine Aufnahme öffnen, um darin zu navigieren</translation>
    </message>
    <message>
        <source>%1 (tick %2)</source>
        <translation>%1 (Tick %2)</translation>
    </message>
    <message>
        <source>tick %1</source>
        <translation>Tick %1</translation>
    </message>
    <message>
        <source>%1 at %2</source>
        <translation>%1 bei %2</translation>
    </message>
    <message>
        <source>… and %1 more here</source>
        <translation>… und %1 weitere hier</translation>
    </message>
    <message>
        <source>%1: ticks %2 to %3</source>
        <translation>%1: Ticks %2 bis %3</translation>
    </message>
</context>
<context>
    <name>palpate::ResultUploader</name>
    <message>
        <source>Results: sending…</source>
        <translation>Ergebnisse: werden gesendet…</translation>
    </message>
    <message>
        <source>Results: all sent</source>
        <translation>Ergebnisse: alle gesendet</translation>
    </message>
    <message>
        <source>Results: server does not answer</source>
        <translation>Ergebnisse: Server antwortet nicht</translation>
    </message>
    <message>
        <source>Results: 1 waiting</source>
        <translation>Ergebnisse: 1 wartet</translation>
    </message>
    <message>
        <source>Results: %1 waiting</source>
        <translation>Ergebnisse: %1 warten</translation>
    </message>
    <message>
        <source>Results: %1 waiting, %2 refused (see the tooltip)</source>
        <translation>Ergebnisse: %1 warten, %2 abgelehnt (siehe Tooltip)</translation>
    </message>
</context>
<context>
    <name>palpate::ResultsDatabase</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>is a folder, not a results database</source>
        <translation>ist ein Ordner, keine Ergebnisdatenbank</translation>
    </message>
    <message>
        <source>cannot be read (permission denied)</source>
        <translation>kann nicht gelesen werden (Zugriff verweigert)</translation>
    </message>
    <message>
        <source>cannot be created: folder %1 does not exist</source>
        <translation>kann nicht angelegt werden: Ordner %1 existiert nicht</translation>
    </message>
    <message>
        <source>cannot be created: folder %1 is not writable</source>
        <translation>kann nicht angelegt werden: Ordner %1 ist nicht beschreibbar</translation>
    </message>
    <message>
        <source>the Qt SQLite driver (QSQLITE) is not installed</source>
        <translation>der Qt-SQLite-Treiber (QSQLITE) ist nicht installiert</translation>
    </message>
    <message>
        <source>cannot be opened: %1</source>
        <translation>kann nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>not a results database (%1)</source>
        <translation>keine Ergebnisdatenbank (%1)</translation>
    </message>
    <message>
        <source>schema version %1 is newer than this build reads (%2): update Palpate</source>
        <translation>Schemaversion %1 ist neuer, als dieser Build lesen kann (%2): Palpate aktualisieren</translation>
    </message>
    <message>
        <source>is an SQLite database but not a Palpate results database</source>
        <translation>ist eine SQLite-Datenbank, aber keine Palpate-Ergebnisdatenbank</translation>
    </message>
    <message>
        <source>cannot create the tables: %1</source>
        <translation>die Tabellen können nicht angelegt werden: %1</translation>
    </message>
    <message>
        <source>cannot migrate from schema version 1 to 2: %1</source>
        <translation>Migration von Schemaversion 1 auf 2 nicht möglich: %1</translation>
    </message>
    <message>
        <source>not open</source>
        <translation>nicht geöffnet</translation>
    </message>
    <message>
        <source>a trainee needs a name</source>
        <translation>ein Teilnehmer braucht einen Namen</translation>
    </message>
    <message>
        <source>cannot add trainee &quot;%1&quot;: %2</source>
        <translation>Teilnehmer „%1“ kann nicht hinzugefügt werden: %2</translation>
    </message>
    <message>
        <source>no trainee with id %1</source>
        <translation>kein Teilnehmer mit der ID %1</translation>
    </message>
    <message>
        <source>cannot store the result: %1</source>
        <translation>das Ergebnis kann nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <source>cannot migrate from schema version 2 to 3: %1</source>
        <translation>Schema-Version 2 kann nicht zu 3 migriert werden: %1</translation>
    </message>
    <message>
        <source>cannot migrate from schema version 3 to 4: %1</source>
        <translation>Schema-Version 3 kann nicht zu 4 migriert werden: %1</translation>
    </message>
    <message>
        <source>cannot store the staircase of %1: %2</source>
        <translation>Die Treppe (Staircase) von %1 kann nicht gespeichert werden: %2</translation>
    </message>
    <message>
        <source>is not a PostgreSQL URL (postgresql://[user@]host[:port]/database)</source>
        <translation>ist keine PostgreSQL-URL (postgresql://[benutzer@]host[:port]/datenbank)</translation>
    </message>
    <message>
        <source>a password in the URL is refused: put it in ~/.pgpass or the file PGPASSFILE names (docs/results-store.md)</source>
        <translation>ein Passwort in der URL wird abgelehnt: es gehört in ~/.pgpass oder in die Datei, die PGPASSFILE nennt (docs/results-store.md)</translation>
    </message>
    <message>
        <source>names no database (postgresql://host/database)</source>
        <translation>nennt keine Datenbank (postgresql://host/datenbank)</translation>
    </message>
    <message>
        <source>the Qt PostgreSQL driver (QPSQL, Debian package libqt6sql6-psql) is not installed</source>
        <translation>der Qt-PostgreSQL-Treiber (QPSQL, Debian-Paket libqt6sql6-psql) ist nicht installiert</translation>
    </message>
    <message>
        <source>cannot connect: %1</source>
        <translation>keine Verbindung: %1</translation>
    </message>
    <message>
        <source>the database holds other tables: not a Palpate results database</source>
        <translation>die Datenbank enthält andere Tabellen: keine Palpate-Ergebnisdatenbank</translation>
    </message>
    <message>
        <source>cannot migrate from schema version 4 to 5: %1</source>
        <translation>kann nicht von Schemaversion 4 auf 5 migrieren: %1</translation>
    </message>
    <message>
        <source>cannot mark result %1 as sent: %2</source>
        <translation>kann Ergebnis %1 nicht als gesendet markieren: %2</translation>
    </message>
    <message>
        <source>a result without a uid cannot be copied</source>
        <translation>ein Ergebnis ohne uid kann nicht kopiert werden</translation>
    </message>
    <message>
        <source>cannot store result %1: %2</source>
        <translation>kann Ergebnis %1 nicht speichern: %2</translation>
    </message>
    <message>
        <source>this role may not read the results (%1): the instructor grants it a workstation or instructor role (palpate-cli results grant, docs/results-store.md)</source>
        <translation>diese Rolle darf die Ergebnisse nicht lesen (%1): die Lehrkraft gibt ihr eine Arbeitsplatz- oder Lehrkraftrolle (palpate-cli results grant, docs/results-store.md)</translation>
    </message>
    <message>
        <source>cannot read this connection&apos;s role: %1</source>
        <translation>die Rolle dieser Verbindung ist nicht lesbar: %1</translation>
    </message>
    <message>
        <source>role %1</source>
        <translation>Rolle %1</translation>
    </message>
    <message>
        <source>role %1, class %2</source>
        <translation>Rolle %1, Klasse %2</translation>
    </message>
    <message>
        <source>, TLS</source>
        <translation>, TLS</translation>
    </message>
    <message>
        <source>, no TLS</source>
        <translation>, ohne TLS</translation>
    </message>
    <message>
        <source>cannot migrate from schema version 5 to 6: %1</source>
        <translation>Migration von Schemaversion 5 auf 6 nicht möglich: %1</translation>
    </message>
    <message>
        <source>the server already has a trainee of that name in another class</source>
        <translation>der Server hat bereits einen Lernenden dieses Namens in einer anderen Klasse</translation>
    </message>
    <message>
        <source>option &apos;%1&apos; is not accepted in the URL (who connects and where come from the URL&apos;s own parts; docs/results-store.md lists the options)</source>
        <translation>Option &apos;%1&apos; wird in der URL nicht angenommen (wer sich verbindet und wohin, ergibt sich aus den eigenen Teilen der URL; docs/results-store.md nennt die Optionen)</translation>
    </message>
    <message>
        <source>option &apos;%1&apos; has a value libpq cannot take (a &apos;;&apos; or a NUL)</source>
        <translation>Option &apos;%1&apos; hat einen Wert, den libpq nicht annehmen kann (ein &apos;;&apos; oder ein NUL)</translation>
    </message>
    <message>
        <source>connect_timeout must be 1 to %1 seconds (0 would wait for ever)</source>
        <translation>connect_timeout muss 1 bis %1 Sekunden sein (0 würde ewig warten)</translation>
    </message>
    <message>
        <source>is not a regular file (a device, a FIFO or a socket): not a results database</source>
        <translation>ist keine gewöhnliche Datei (ein Gerät, eine FIFO oder ein Socket): keine Ergebnisdatenbank</translation>
    </message>
    <message>
        <source>The server refused %1&apos;s result of &quot;%2&quot; (%3, %4): %5. It stays on this workstation; rename the trainee here or ask the instructor (results grant, docs/results-store.md), then send again.</source>
        <translation>Der Server hat das Ergebnis von %1 in „%2“ (%3, %4) abgelehnt: %5. Es bleibt auf diesem Arbeitsplatz; benennen Sie den Teilnehmer hier um oder fragen Sie die Lehrkraft (results grant, docs/results-store.md) und senden Sie dann erneut.</translation>
    </message>
    <message>
        <source>the results schema is damaged (%1): restore the file from a copy (Palpate does not repair it)</source>
        <translation>das Schema der Ergebnisse ist beschädigt (%1): Stellen Sie die Datei aus einer Kopie wieder her (Palpate repariert sie nicht)</translation>
    </message>
    <message>
        <source>table %1 is missing</source>
        <translation>Tabelle %1 fehlt</translation>
    </message>
    <message>
        <source>table %1 has no column %2</source>
        <translation>Tabelle %1 hat keine Spalte %2</translation>
    </message>
    <message>
        <source>the results schema is damaged (%1): the server&apos;s administrator restores it from a backup</source>
        <translation>das Schema der Ergebnisse ist beschädigt (%1): Die Administration des Servers stellt es aus einer Sicherung wieder her</translation>
    </message>
    <message>
        <source>the server did not answer within %1 s (the URL&apos;s statement_timeout sets the wait, docs/results-store.md)</source>
        <translation>der Server hat nicht innerhalb von %1 s geantwortet (statement_timeout in der URL legt die Wartezeit fest, docs/results-store.md)</translation>
    </message>
    <message>
        <source>statement_timeout must be 1 to %1 seconds</source>
        <translation>statement_timeout muss 1 bis %1 Sekunden betragen</translation>
    </message>
    <message>
        <source>is read-only and of schema version %1 (this build reads %2): open it once where it can be written, to update it</source>
        <translation>ist schreibgeschützt und hat Schemaversion %1 (dieser Build liest %2): einmal dort öffnen, wo sie beschrieben werden kann, um sie zu aktualisieren</translation>
    </message>
    <message>
        <source>cannot be read or written (%1): is the disk full?</source>
        <translation>kann nicht gelesen oder geschrieben werden (%1): ist der Datenträger voll?</translation>
    </message>
</context>
<context>
    <name>palpate::ResultsRoles</name>
    <message>
        <source>%1: roles exist on a PostgreSQL server only, not in an SQLite file</source>
        <translation>%1: Rollen gibt es nur auf einem PostgreSQL-Server, nicht in einer SQLite-Datei</translation>
    </message>
    <message>
        <source>role name &quot;%1&quot; is refused: letters, digits, _ . @ - only, starting with a letter or _</source>
        <translation>Rollenname &quot;%1&quot; abgelehnt: nur Buchstaben, Ziffern, _ . @ -, am Anfang ein Buchstabe oder _</translation>
    </message>
    <message>
        <source>a workstation needs a class (--class NAME)</source>
        <translation>ein Arbeitsplatz braucht eine Klasse (--class NAME)</translation>
    </message>
    <message>
        <source>role %1 is refused: it is a built-in or group role, not a workstation&apos;s or an instructor&apos;s login (CREATE ROLE name LOGIN makes one)</source>
        <translation>Rolle %1 wird abgelehnt: Sie ist eine eingebaute oder Gruppenrolle, keine Anmeldung eines Arbeitsplatzes oder einer Lehrkraft (CREATE ROLE name LOGIN legt eine an)</translation>
    </message>
</context>
<context>
    <name>palpate::SaveFileChoice</name>
    <message>
        <source>Replace the file?</source>
        <translation>Datei ersetzen?</translation>
    </message>
    <message>
        <source>%1 already exists. Replace it?</source>
        <translation>%1 existiert bereits. Ersetzen?</translation>
    </message>
</context>
<context>
    <name>palpate::SceneOverlay</name>
    <message>
        <source>rest shape</source>
        <translation>Ruheform</translation>
    </message>
    <message>
        <source>touched</source>
        <translation>berührt</translation>
    </message>
    <message>
        <source>ring %1</source>
        <translation>Ring %1</translation>
    </message>
    <message>
        <source>dent %1 mm deep</source>
        <translation>Delle %1 mm tief</translation>
    </message>
</context>
<context>
    <name>palpate::ScoreCard</name>
    <message>
        <source>Score</source>
        <translation>Punktzahl</translation>
    </message>
    <message>
        <source>Metric</source>
        <translation>Kennzahl</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Sub-score</source>
        <translation>Teilpunktzahl</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <source>Export PDF…</source>
        <translation>PDF exportieren…</translation>
    </message>
    <message>
        <source>History…</source>
        <translation>Verlauf…</translation>
    </message>
    <message>
        <source>No score yet: run an exercise.</source>
        <translation>Noch keine Punktzahl: führen Sie eine Übung durch.</translation>
    </message>
    <message>
        <source>completed</source>
        <translation>abgeschlossen</translation>
    </message>
    <message>
        <source>time up</source>
        <translation>Zeit abgelaufen</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>gestoppt</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>%1: %2 (%3)</source>
        <translation>%1: %2 (%3)</translation>
    </message>
    <message>
        <source>%1 / 100</source>
        <translation>%1 / 100</translation>
    </message>
    <message>
        <source>not scored</source>
        <translation>nicht bewertet</translation>
    </message>
    <message>
        <source>Stopped: %1 points so far, not a score</source>
        <translation>Abgebrochen: bisher %1 Punkte, keine Bewertung</translation>
    </message>
</context>
<context>
    <name>palpate::ScoreReportPdf</name>
    <message>
        <source>Time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>|F| (N)</source>
        <translation>|F| (N)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>cannot be written: folder %1 does not exist</source>
        <translation>kann nicht geschrieben werden: Ordner %1 existiert nicht</translation>
    </message>
    <message>
        <source>Palpate score report</source>
        <translation>Palpate-Bewertungsbericht</translation>
    </message>
    <message>
        <source>Score: %1 / 100</source>
        <translation>Punktzahl: %1 / 100</translation>
    </message>
    <message>
        <source>Metric</source>
        <translation>Kennzahl</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Sub-score</source>
        <translation>Teilpunktzahl</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Gewicht</translation>
    </message>
    <message>
        <source>Contribution</source>
        <translation>Beitrag</translation>
    </message>
    <message>
        <source>n/a</source>
        <translation>k. A.</translation>
    </message>
    <message>
        <source>Warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <source>Force over time</source>
        <translation>Kraft über die Zeit</translation>
    </message>
    <message>
        <source>%1 – %2 N</source>
        <translation>%1 – %2 N</translation>
    </message>
    <message>
        <source>%1 (continued)</source>
        <translation>%1 (Fortsetzung)</translation>
    </message>
    <message>
        <source>Palpate score report, page %1</source>
        <translation>Palpate-Bewertungsbericht, Seite %1</translation>
    </message>
    <message>
        <source>Target %1</source>
        <translation>Ziel %1</translation>
    </message>
    <message>
        <source>Force band</source>
        <translation>Kraftband</translation>
    </message>
    <message>
        <source>T%1</source>
        <translation>Z%1</translation>
    </message>
    <message>
        <source>completed in %1 s</source>
        <translation>abgeschlossen in %1 s</translation>
    </message>
    <message>
        <source>time limit reached (%1 s)</source>
        <translation>Zeitlimit erreicht (%1 s)</translation>
    </message>
    <message>
        <source>not finished (%1 s scored)</source>
        <translation>nicht beendet (%1 s bewertet)</translation>
    </message>
    <message>
        <source>not recorded</source>
        <translation>nicht aufgezeichnet</translation>
    </message>
    <message>
        <source>Exercise:</source>
        <translation>Übung:</translation>
    </message>
    <message>
        <source>(unnamed)</source>
        <translation>(ohne Namen)</translation>
    </message>
    <message>
        <source>Trainee:</source>
        <translation>Teilnehmer:</translation>
    </message>
    <message>
        <source>Date:</source>
        <translation>Datum:</translation>
    </message>
    <message>
        <source>Device:</source>
        <translation>Gerät:</translation>
    </message>
    <message>
        <source>Result:</source>
        <translation>Ergebnis:</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>achieved at %1 s</source>
        <translation>erreicht bei %1 s</translation>
    </message>
    <message>
        <source>not achieved</source>
        <translation>nicht erreicht</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>Targets</source>
        <translation>Ziele</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Force window</source>
        <translation>Kraftfenster</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Halten</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Abweichung</translation>
    </message>
    <message>
        <source>On target</source>
        <translation>Auf dem Ziel</translation>
    </message>
    <message>
        <source>In window</source>
        <translation>Im Fenster</translation>
    </message>
    <message>
        <source>Shaded: each target&apos;s own force window, over the time it was the target to press.</source>
        <translation>Schattiert: das Kraftfenster jedes Ziels, über die Zeit, in der es das zu drückende Ziel war.</translation>
    </message>
    <message>
        <source>Shaded: the force band to keep while tracing.</source>
        <translation>Schattiert: das beim Nachfahren einzuhaltende Kraftband.</translation>
    </message>
    <message>
        <source>Breakdown</source>
        <translation>Aufschlüsselung</translation>
    </message>
    <message>
        <source>cannot be written: it is a folder</source>
        <translation>kann nicht geschrieben werden: es ist ein Ordner</translation>
    </message>
    <message>
        <source>cannot be drawn (the PDF writer did not start)</source>
        <translation>kann nicht gezeichnet werden (der PDF-Schreiber startete nicht)</translation>
    </message>
    <message>
        <source>cannot be drawn</source>
        <translation>kann nicht gezeichnet werden</translation>
    </message>
    <message>
        <source>cannot be drawn (empty document)</source>
        <translation>kann nicht gezeichnet werden (leeres Dokument)</translation>
    </message>
    <message>
        <source>Palpate score report, page %1 of %2</source>
        <translation>Palpate-Bewertungsbericht, Seite %1 von %2</translation>
    </message>
    <message>
        <source>Palpation</source>
        <translation>Palpation</translation>
    </message>
    <message>
        <source>Lump %1</source>
        <translation>Knoten %1</translation>
    </message>
    <message>
        <source>%1 x</source>
        <translation>%1-fach</translation>
    </message>
    <message>
        <source>found</source>
        <translation>gefunden</translation>
    </message>
    <message>
        <source>missed</source>
        <translation>übersehen</translation>
    </message>
    <message>
        <source>Lumps</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>Lump</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>Tiefe</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <source>Contrast</source>
        <translation>Kontrast</translation>
    </message>
    <message>
        <source>Off by</source>
        <translation>Abweichung</translation>
    </message>
    <message>
        <source>%1 N</source>
        <translation>%1 N</translation>
    </message>
    <message>
        <source>Search</source>
        <translation>Suchen</translation>
    </message>
    <message>
        <source>Force by phase</source>
        <translation>Kraft nach Phase</translation>
    </message>
    <message>
        <source>Phase</source>
        <translation>Phase</translation>
    </message>
    <message>
        <source>10th pct.</source>
        <translation>10. Perz.</translation>
    </message>
    <message>
        <source>Median</source>
        <translation>Median</translation>
    </message>
    <message>
        <source>90th pct.</source>
        <translation>90. Perz.</translation>
    </message>
    <message>
        <source>Largest</source>
        <translation>Größte</translation>
    </message>
    <message>
        <source>Ticks</source>
        <translation>Takte</translation>
    </message>
    <message>
        <source>the side examined most</source>
        <translation>die am meisten untersuchte Seite</translation>
    </message>
    <message>
        <source>the opposite side</source>
        <translation>die gegenüberliegende Seite</translation>
    </message>
    <message>
        <source>examined at %1 to %2 N (largest force); grey: not examined</source>
        <translation>untersucht mit %1 bis %2 N (größte Kraft); grau: nicht untersucht</translation>
    </message>
    <message>
        <source>Surface examined</source>
        <translation>Untersuchte Oberfläche</translation>
    </message>
</context>
<context>
    <name>palpate::SpeedAccuracyChart</name>
    <message>
        <source>No sweep yet</source>
        <translation>Noch kein Sweep</translation>
    </message>
    <message>
        <source>Slope&amp;#8209;ring, rings:</source>
        <translation>Slope&amp;#8209;Ring, Ringe:</translation>
    </message>
    <message>
        <source>Paper (2 rings):</source>
        <translation>Artikel (2 Ringe):</translation>
    </message>
    <message>
        <source>Other models:</source>
        <translation>Andere Modelle:</translation>
    </message>
    <message>
        <source>Pareto front (dashed)</source>
        <translation>Pareto-Front (gestrichelt)</translation>
    </message>
    <message>
        <source>in use</source>
        <translation>in Verwendung</translation>
    </message>
    <message>
        <source>Sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <source>Stomach</source>
        <translation>Magen</translation>
    </message>
    <message>
        <source>Pareto</source>
        <translation>Pareto</translation>
    </message>
    <message>
        <source>Tick cost (µs, log)</source>
        <translation>Tick-Aufwand (µs, log)</translation>
    </message>
    <message>
        <source>Haptic tick cost (µs, log scale)</source>
        <translation>Aufwand eines Haptik-Ticks (µs, logarithmische Skala)</translation>
    </message>
    <message>
        <source>error vs. the flat punch: RMS / peak over r ≤ 5a</source>
        <translation>Fehler gegenüber dem flachen Stempel: RMS / Spitze über r ≤ 5a</translation>
    </message>
    <message>
        <source>E = %1 kPa, ν = %2, tool radius a = %3 mm</source>
        <translation>E = %1 kPa, ν = %2, Werkzeugradius a = %3 mm</translation>
    </message>
    <message>
        <source>%1: speed against accuracy</source>
        <translation>%1: Geschwindigkeit gegen Genauigkeit</translation>
    </message>
    <message>
        <source>Displacement error (%)</source>
        <translation>Verschiebungsfehler (%)</translation>
    </message>
    <message>
        <source>%1, %2 %3 vertices
tick %4 µs, displacement error %5 %, force error %6 %%7</source>
        <translation>%1, %2 %3 Knoten
Tick %4 µs, Verschiebungsfehler %5 %, Kraftfehler %6 %%7</translation>
    </message>
    <message>
        <source>on the Pareto front</source>
        <translation>auf der Pareto-Front</translation>
    </message>
    <message>
        <source>Pareto front</source>
        <translation>Pareto-Front</translation>
    </message>
    <message>
        <source>current configuration</source>
        <translation>aktuelle Konfiguration</translation>
    </message>
    <message>
        <source>%1 stiffening</source>
        <translation>%1 versteifend</translation>
    </message>
    <message>
        <source>error vs. the filled organ&apos;s linear FEM at its %1 site:</source>
        <translation>Fehler gegen die lineare FEM des gefüllten Organs an der Stelle „%1“:</translation>
    </message>
    <message>
        <source>RMS / peak over r ≤ 5a</source>
        <translation>RMS / Spitze über r ≤ 5a</translation>
    </message>
</context>
<context>
    <name>palpate::StiffeningPanel</name>
    <message>
        <source>The tissue changed: press Compute for its curve.</source>
        <translation>Das Gewebe hat sich geändert: Berechnen drücken für seine Kurve.</translation>
    </message>
    <message>
        <source>Cannot compute: %1</source>
        <translation>Kann nicht berechnen: %1</translation>
    </message>
    <message>
        <source>Pressing the hyperelastic half-space to %1 mm…</source>
        <translation>Der hyperelastische Halbraum wird %1 mm tief eingedrückt…</translation>
    </message>
    <message>
        <source>The reference could not be computed: %1</source>
        <translation>Die Referenz konnte nicht berechnet werden: %1</translation>
    </message>
    <message>
        <source>Press Compute: the hyperelastic reference is solved for this tissue (a few seconds).</source>
        <translation>Berechnen drücken: die hyperelastische Referenz wird für dieses Gewebe gelöst (einige Sekunden).</translation>
    </message>
    <message>
        <source>Depth of the tissue under the tool (mm)</source>
        <translation>Tiefe des Gewebes unter dem Werkzeug (mm)</translation>
    </message>
    <message>
        <source>Force (N)</source>
        <translation>Kraft (N)</translation>
    </message>
    <message>
        <source>At %1 mm the reference is %2 times the linear force: the linear model is %3 % low there, the %4 knots are within %5 % everywhere on the curve%6.</source>
        <translation>Bei %1 mm ist die Referenz das %2-Fache der linearen Kraft: das lineare Modell liegt dort %3 % zu niedrig, die %4 Knoten liegen überall auf der Kurve innerhalb von %5 %%6.</translation>
    </message>
    <message>
        <source> (the solve stopped early: %1)</source>
        <translation> (die Lösung brach früh ab: %1)</translation>
    </message>
    <message>
        <source>Press &amp;to:</source>
        <translation>Ein&amp;drücken bis:</translation>
    </message>
    <message>
        <source>How deep the hyperelastic punch goes (0.1 to 1.5 tool radii).</source>
        <translation>Wie tief der hyperelastische Stempel eindrückt (0,1 bis 1,5 Werkzeugradien).</translation>
    </message>
    <message>
        <source>&amp;Compute</source>
        <translation>&amp;Berechnen</translation>
    </message>
    <message>
        <source>Solve the hyperelastic reference for this tissue (a flat punch of the tool&apos;s radius, a few seconds) and fit the stiffening knots to it.</source>
        <translation>Die hyperelastische Referenz für dieses Gewebe lösen (ein flacher Stempel mit dem Radius des Werkzeugs, einige Sekunden) und die Versteifungsknoten daran anpassen.</translation>
    </message>
    <message>
        <source>Force against depth</source>
        <translation>Kraft über der Tiefe</translation>
    </message>
    <message>
        <source>E = %1 kPa, ν = %2, a = %3 mm, %4 (b = %5)</source>
        <translation>E = %1 kPa, ν = %2, a = %3 mm, %4 (b = %5)</translation>
    </message>
    <message>
        <source>Hyperelastic FEM</source>
        <translation>Hyperelastische FEM</translation>
    </message>
    <message>
        <source>Linear model</source>
        <translation>Lineares Modell</translation>
    </message>
    <message>
        <source>1 knot</source>
        <translation>1 Knoten</translation>
    </message>
    <message>
        <source>%1 knots</source>
        <translation>%1 Knoten</translation>
    </message>
    <message>
        <source>the preset&apos;s knot</source>
        <translation>der Knoten des Presets</translation>
    </message>
    <message>
        <source>the preset&apos;s %1 knots</source>
        <translation>die %1 Knoten des Presets</translation>
    </message>
    <message>
        <source>The knots do not fit these slopes: %1</source>
        <translation>Die Knoten passen nicht zu diesen Steigungen: %1</translation>
    </message>
    <message>
        <source>&amp;Apply knots</source>
        <translation>Knoten &amp;anwenden</translation>
    </message>
    <message>
        <source>Put these knots into the tissue in use (Parameters: one step to undo) and apply it: the model stiffens as the reference does. The mesh and the rings stay as they are.</source>
        <translation>Diese Knoten in das verwendete Gewebe setzen (Parameter: ein Schritt zum Rückgängigmachen) und anwenden: das Modell versteift sich wie die Referenz. Netz und Ringe bleiben, wie sie sind.</translation>
    </message>
</context>
<context>
    <name>palpate::TraineePanel</name>
    <message>
        <source>Trainee</source>
        <translation>Teilnehmer</translation>
    </message>
    <message>
        <source>New…</source>
        <translation>Neu…</translation>
    </message>
    <message>
        <source>Add a trainee</source>
        <translation>Einen Teilnehmer hinzufügen</translation>
    </message>
    <message>
        <source>Trainee:</source>
        <translation>Teilnehmer:</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Übung</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Öffnen…</translation>
    </message>
    <message>
        <source>Choose an exercise file</source>
        <translation>Eine Übungsdatei wählen</translation>
    </message>
    <message>
        <source>Exercise:</source>
        <translation>Übung:</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Starten</translation>
    </message>
    <message>
        <source>Start the exercise (F6)</source>
        <translation>Die Übung starten (F6)</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stoppen</translation>
    </message>
    <message>
        <source>End the exercise now and score it (Shift+F6)</source>
        <translation>Die Übung jetzt beenden und bewerten (Umschalt+F6)</translation>
    </message>
    <message>
        <source>Mark</source>
        <translation>Markieren</translation>
    </message>
    <message>
        <source>Mark the lump where the tool presses now (M)</source>
        <translation>Die Verhärtung dort markieren, wo das Werkzeug jetzt drückt (M)</translation>
    </message>
    <message>
        <source>Choose a trainee and an exercise, then Start (F6).</source>
        <translation>Einen Teilnehmer und eine Übung wählen, dann „Starten“ (F6).</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>Wird gestartet…</translation>
    </message>
    <message>
        <source>Time left %1 s · score so far %2</source>
        <translation>Verbleibende Zeit %1 s · bisherige Punktzahl %2</translation>
    </message>
    <message>
        <source>%1 (preview, not saved)</source>
        <translation>%1 (Vorschau, nicht gespeichert)</translation>
    </message>
    <message>
        <source>Finish</source>
        <translation>Beenden</translation>
    </message>
    <message>
        <source>End the examination: every lump you found is marked (F7)</source>
        <translation>Untersuchung beenden: Jeder gefundene Knoten ist markiert (F7)</translation>
    </message>
    <message>
        <source>E&amp;xpert reference session</source>
        <translation>E&amp;xperten-Referenzsitzung</translation>
    </message>
    <message>
        <source>An instructor&apos;s session: stored as an expert&apos;s, it sets the exercise&apos;s pass marks (expert mean ± 2 SD) and moves no staircase</source>
        <translation>Eine Sitzung der Lehrkraft: als Expertensitzung gespeichert, setzt sie die Bestehensgrenzen der Übung (Expertenmittel ± 2 SD) und bewegt keine Treppe</translation>
    </message>
    <message>
        <source>Time left %1 s · score at Finish</source>
        <translation>Verbleibende Zeit %1 s · Punktzahl bei Beenden</translation>
    </message>
    <message>
        <source>%1 (in %2)</source>
        <translation>%1 (in %2)</translation>
    </message>
</context>
<context>
    <name>palpate::WelcomePage</name>
    <message>
        <source>Welcome to Palpate</source>
        <translation>Willkommen bei Palpate</translation>
    </message>
    <message>
        <source>&lt;h2&gt;Welcome to Palpate&lt;/h2&gt;</source>
        <translation>&lt;h2&gt;Willkommen bei Palpate&lt;/h2&gt;</translation>
    </message>
    <message>
        <source>Palpate lets you feel a soft tissue model through a haptic device, or with the mouse. Here are four things to try first; you find this page again under Help &gt; Welcome, and the user guide under Help &gt; User Guide (F1).</source>
        <translation>Mit Palpate ertasten Sie ein Weichgewebemodell über ein haptisches Gerät oder mit der Maus. Hier sind vier Dinge zum Ausprobieren; diese Seite finden Sie wieder unter Hilfe &gt; Willkommen, das Benutzerhandbuch unter Hilfe &gt; Benutzerhandbuch (F1).</translation>
    </message>
    <message>
        <source>Open the sample scene</source>
        <translation>Die Beispielszene öffnen</translation>
    </message>
    <message>
        <source>The stomach wall model with its default tissue, ready to be pressed.</source>
        <translation>Das Modell der Magenwand mit seinem Standardgewebe, bereit zum Drücken.</translation>
    </message>
    <message>
        <source>Try touch mode with the mouse</source>
        <translation>Den Tastmodus mit der Maus ausprobieren</translation>
    </message>
    <message>
        <source>Left-drag presses the tissue, the wheel sets the depth; right-drag turns the view. No haptic device needed.</source>
        <translation>Ziehen mit der linken Maustaste drückt das Gewebe, das Mausrad stellt die Tiefe ein; Ziehen mit der rechten Maustaste dreht die Ansicht. Kein haptisches Gerät nötig.</translation>
    </message>
    <message>
        <source>Run the example exercise</source>
        <translation>Die Beispielübung durchführen</translation>
    </message>
    <message>
        <source>&quot;Press three targets&quot; as a preview: the Exercise dock guides you and scores the run (nothing is stored).</source>
        <translation>„Drei Ziele drücken“ als Vorschau: das Dock „Übung“ leitet Sie an und bewertet den Durchgang (nichts wird gespeichert).</translation>
    </message>
    <message>
        <source>Read the user guide</source>
        <translation>Das Benutzerhandbuch lesen</translation>
    </message>
    <message>
        <source>What every window, dock and menu does, with pictures.</source>
        <translation>Was jedes Fenster, Dock und Menü tut, mit Bildern.</translation>
    </message>
    <message>
        <source>&amp;Don&apos;t show this again at start</source>
        <translation>&amp;Beim Start nicht mehr anzeigen</translation>
    </message>
</context>
</TS>
