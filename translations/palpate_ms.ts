<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ms_MY">
<context>
    <name>QObject</name>
    <message>
        <source>No sweep points to draw</source>
        <translation>Tiada titik sapuan untuk dilukis</translation>
    </message>
    <message>
        <source>%1–%2 N</source>
        <translation>%1–%2 N</translation>
    </message>
    <message>
        <source>No feel bench rows to draw</source>
        <translation>Tiada baris penanda aras haptik untuk dilukis</translation>
    </message>
    <message>
        <source>session</source>
        <translation>sesi</translation>
    </message>
    <message>
        <source> - proficient at session %1</source>
        <translation> – cekap sejak sesi %1</translation>
    </message>
    <message>
        <source> - not yet proficient</source>
        <translation> – belum cekap</translation>
    </message>
    <message>
        <source> - no expert standard</source>
        <translation> – tiada piawai pakar</translation>
    </message>
    <message>
        <source>Score (of 100)</source>
        <translation>Skor (daripada 100)</translation>
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
        <translation>Batal</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Tutup</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Simpan</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Buang</translation>
    </message>
    <message>
        <source>&amp;Yes</source>
        <translation>&amp;Ya</translation>
    </message>
    <message>
        <source>&amp;No</source>
        <translation>&amp;Tidak</translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation>Pulihkan Lalai</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Guna</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Bantuan</translation>
    </message>
</context>
<context>
    <name>palpate::ChartsPanel</name>
    <message>
        <source>1 point</source>
        <translation>1 titik</translation>
    </message>
    <message>
        <source>%1 points</source>
        <translation>%1 titik</translation>
    </message>
    <message>
        <source>&amp;Run sweep</source>
        <translation>&amp;Jalankan sapuan</translation>
    </message>
    <message>
        <source>Measure every model&apos;s tick cost and its displacement error against the flat punch (slopes calibrated for the tissue and tool in use). Runs in the background; the full sweep (both shapes, four sizes, 1 to 8 rings and the paper&apos;s methods) takes seconds.</source>
        <translation>Ukur kos tik setiap model dan ralat anjakannya berbanding penebuk rata (cerun ditentukur untuk tisu dan alat yang digunakan). Berjalan di latar belakang; sapuan penuh (kedua-dua bentuk, empat saiz, 1 hingga 8 gelang dan kaedah kertas kerja) mengambil masa beberapa saat.</translation>
    </message>
    <message>
        <source>&amp;Quick</source>
        <translation>&amp;Pantas</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>&amp;Batal</translation>
    </message>
    <message>
        <source>Stop after the model being measured; the points measured so far are shown.</source>
        <translation>Berhenti selepas model yang sedang diukur; titik yang telah diukur ditunjukkan.</translation>
    </message>
    <message>
        <source>&amp;Open CSV…</source>
        <translation>&amp;Buka CSV…</translation>
    </message>
    <message>
        <source>Show a sweep saved as CSV (palpate-cli sweep --csv, or Save CSV here).</source>
        <translation>Tunjukkan sapuan yang disimpan sebagai CSV (palpate-cli sweep --csv, atau Simpan CSV di sini).</translation>
    </message>
    <message>
        <source>S&amp;ave CSV…</source>
        <translation>S&amp;impan CSV…</translation>
    </message>
    <message>
        <source>Write the points shown as CSV (and the tissue as JSON next to it).</source>
        <translation>Tulis titik yang ditunjukkan sebagai CSV (dan tisu sebagai JSON di sebelahnya).</translation>
    </message>
    <message>
        <source>Sha&amp;pe:</source>
        <translation>B&amp;entuk:</translation>
    </message>
    <message>
        <source>The shape whose points are drawn (each shape has its own Pareto front).</source>
        <translation>Bentuk yang titiknya dilukis (setiap bentuk mempunyai hadapan Pareto sendiri).</translation>
    </message>
    <message>
        <source>No sweep loaded: press Run sweep</source>
        <translation>Tiada sapuan dimuatkan: tekan Jalankan sapuan</translation>
    </message>
    <message>
        <source>%p %</source>
        <translation>%p %</translation>
    </message>
    <message>
        <source>%1 with %2 rings</source>
        <translation>%1 dengan %2 gelang</translation>
    </message>
    <message>
        <source>In use: %1 (no mesh loaded)</source>
        <translation>Digunakan: %1 (tiada jejaring dimuatkan)</translation>
    </message>
    <message>
        <source>In use: %1 on %2 vertices</source>
        <translation>Digunakan: %1 pada %2 bucu</translation>
    </message>
    <message>
        <source>In use: %1 on %2 vertices (not measured in this sweep)</source>
        <translation>Digunakan: %1 pada %2 bucu (tidak diukur dalam sapuan ini)</translation>
    </message>
    <message>
        <source>Sweep started: building the first mesh…</source>
        <translation>Sapuan bermula: membina jejaring pertama…</translation>
    </message>
    <message>
        <source>Cancelling: the model being measured finishes first…</source>
        <translation>Membatalkan: model yang sedang diukur selesai dahulu…</translation>
    </message>
    <message>
        <source>Sweep failed: %1</source>
        <translation>Sapuan gagal: %1</translation>
    </message>
    <message>
        <source>Cancelled after %1 (%2 s); the chart shows them.</source>
        <translation>Dibatalkan selepas %1 (%2 s); carta menunjukkannya.</translation>
    </message>
    <message>
        <source>Cancelled before the first point; the chart is unchanged.</source>
        <translation>Dibatalkan sebelum titik pertama; carta tidak berubah.</translation>
    </message>
    <message>
        <source>Sweep done: %1 in %2 s.</source>
        <translation>Sapuan selesai: %1 dalam %2 s.</translation>
    </message>
    <message>
        <source>%1: cannot be read (%2)</source>
        <translation>%1: tidak dapat dibaca (%2)</translation>
    </message>
    <message>
        <source>%1: no points (only the header)</source>
        <translation>%1: tiada titik (hanya pengepala)</translation>
    </message>
    <message>
        <source>Loaded %1 (%2).</source>
        <translation>%1 dimuatkan (%2).</translation>
    </message>
    <message>
        <source>%1: not saved, there are no points</source>
        <translation>%1: tidak disimpan, tiada titik</translation>
    </message>
    <message>
        <source>%1: cannot be written (%2)</source>
        <translation>%1: tidak dapat ditulis (%2)</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>%1 disimpan.</translation>
    </message>
    <message>
        <source>Open sweep CSV</source>
        <translation>Buka CSV sapuan</translation>
    </message>
    <message>
        <source>Sweep CSV (*.csv);;All files (*)</source>
        <translation>CSV sapuan (*.csv);;Semua fail (*)</translation>
    </message>
    <message>
        <source>Save sweep CSV</source>
        <translation>Simpan CSV sapuan</translation>
    </message>
    <message>
        <source>&amp;Speed vs. accuracy</source>
        <translation>&amp;Laju lwn. ketepatan</translation>
    </message>
    <message>
        <source>Every model&apos;s tick cost against its displacement error (the sweep).</source>
        <translation>Kos tik setiap model berbanding ralat anjakannya (sapuan).</translation>
    </message>
    <message>
        <source>&amp;Feel</source>
        <translation>&amp;Rasa</translation>
    </message>
    <message>
        <source>Every model&apos;s largest force step while sliding at constant depth, against its tick cost (palpate-cli bench feel).</source>
        <translation>Lompatan daya terbesar setiap model semasa menggelongsor pada kedalaman tetap, berbanding kos tiknya (palpate-cli bench feel).</translation>
    </message>
    <message>
        <source>%1: not saved, %2 exists and is not a sweep&apos;s description (it would be replaced); choose another name</source>
        <translation>%1: tidak disimpan, %2 wujud dan bukan penerangan sapuan (ia akan diganti); pilih nama lain</translation>
    </message>
    <message>
        <source>S&amp;tiffening</source>
        <translation>Pen&amp;gerasan</translation>
    </message>
    <message>
        <source>The tissue&apos;s force against depth: the hyperelastic reference beside the linear model and the model with stiffening knots.</source>
        <translation>Daya tisu berbanding kedalaman: rujukan hiperelastik di sebelah model linear dan model dengan simpulan pengerasan.</translation>
    </message>
    <message>
        <source>%1, %2 site</source>
        <extracomment>The shape and the site of the organ sweep: &quot;Stomach, thin site&quot;</extracomment>
        <translation>%1, tapak %2</translation>
    </message>
    <message>
        <source>Sphere only, at 1442 and 3970 vertices, up to 4 rings: about a second (against the organ&apos;s FEM: the stomach at 1442 vertices, about half a minute).</source>
        <translation>Sfera sahaja, pada 1442 dan 3970 bucu, hingga 4 gelang: kira-kira sesaat (berbanding FEM organ: perut pada 1442 bucu, kira-kira setengah minit).</translation>
    </message>
    <message>
        <source>vs. punch</source>
        <translation>berbanding penebuk</translation>
    </message>
    <message>
        <source>vs. organ FEM</source>
        <translation>berbanding FEM organ</translation>
    </message>
    <message>
        <source>What Run sweep scores against: the flat punch on a half-space, or the FEM of the filled stomach (linear and hyperelastic) at its thin, thick and curved sites.</source>
        <translation>Sasaran penilaian sapuan: penebuk rata pada separuh ruang, atau FEM perut yang diisi (linear dan hiperelastik) di tapak nipis, tebal dan melengkungnya.</translation>
    </message>
    <message>
        <source>In use: %1 on %2 vertices, tissue E = %3 kPa, ν = %4. The chart shows a stored sweep of another tissue (E = %5 kPa, ν = %6), not this one: press Run sweep to measure it.</source>
        <translation>Digunakan: %1 pada %2 bucu, tisu E = %3 kPa, ν = %4. Carta menunjukkan sapuan tersimpan bagi tisu lain (E = %5 kPa, ν = %6), bukan tisu ini: tekan Jalankan sapuan untuk mengukurnya.</translation>
    </message>
    <message>
        <source>In use: %1 on %2 vertices; ringed in magenta: the sweep&apos;s point of that model and size (on its generated shape, not necessarily this mesh)</source>
        <translation>Digunakan: %1 pada %2 bucu; dibulatkan magenta: titik sapuan bagi model dan saiz itu (pada bentuk yang dijananya, tidak semestinya jejaring ini)</translation>
    </message>
</context>
<context>
    <name>palpate::ClassDialog</name>
    <message>
        <source>Class View</source>
        <translation>Paparan Kelas</translation>
    </message>
    <message>
        <source>This workstation</source>
        <translation>Stesen kerja ini</translation>
    </message>
    <message>
        <source>The class&apos;s server (%1)</source>
        <translation>Pelayan kelas (%1)</translation>
    </message>
    <message>
        <source>&amp;Refresh</source>
        <translation>&amp;Segar semula</translation>
    </message>
    <message>
        <source>&amp;Export CSV…</source>
        <translation>&amp;Eksport CSV…</translation>
    </message>
    <message>
        <source>Trainee</source>
        <translation>Pelatih</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Latihan</translation>
    </message>
    <message>
        <source>Sessions</source>
        <translation>Sesi</translation>
    </message>
    <message>
        <source>Latest</source>
        <translation>Terkini</translation>
    </message>
    <message>
        <source>Best</source>
        <translation>Terbaik</translation>
    </message>
    <message>
        <source>Against the marks</source>
        <translation>Berbanding tanda</translation>
    </message>
    <message>
        <source>Last session</source>
        <translation>Sesi terakhir</translation>
    </message>
    <message>
        <source>&amp;Results of:</source>
        <translation>&amp;Keputusan bagi:</translation>
    </message>
    <message>
        <source>Export the Class View</source>
        <translation>Eksport Paparan Kelas</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Exported %1 rows to %2.</source>
        <translation>%1 baris dieksport ke %2.</translation>
    </message>
    <message>
        <source>Reading %1…</source>
        <translation>Membaca %1…</translation>
    </message>
    <message>
        <source>Cannot read %1: %2</source>
        <translation>Tidak dapat membaca %1: %2</translation>
    </message>
    <message>
        <source>1 trainee</source>
        <translation>1 pelatih</translation>
    </message>
    <message>
        <source>%1 trainees</source>
        <translation>%1 pelatih</translation>
    </message>
    <message>
        <source>1 row</source>
        <translation>1 baris</translation>
    </message>
    <message>
        <source>%1 rows</source>
        <translation>%1 baris</translation>
    </message>
    <message>
        <source>%1: %2, %3. Exercises are matched by name across workstations.</source>
        <translation>%1: %2, %3. Latihan dipadankan mengikut nama merentas stesen kerja.</translation>
    </message>
    <message>
        <source>proficient</source>
        <translation>cekap</translation>
    </message>
    <message>
        <source>passed (once)</source>
        <translation>lulus (sekali)</translation>
    </message>
    <message>
        <source>not yet</source>
        <translation>belum</translation>
    </message>
    <message>
        <source>no marks</source>
        <translation>tiada tanda</translation>
    </message>
    <message>
        <source>%1 is the results database: choose another file</source>
        <translation>%1 ialah pangkalan data keputusan: pilih fail lain</translation>
    </message>
    <message>
        <source>%1: cannot be written (%2)</source>
        <translation>%1: tidak dapat ditulis (%2)</translation>
    </message>
    <message>
        <source>Show one class (a class is the server&apos;s: a workstation&apos;s role belongs to one)</source>
        <translation>Tunjukkan satu kelas (kelas ditetapkan oleh pelayan: peranan stesen kerja tergolong dalam satu)</translation>
    </message>
    <message>
        <source>Class</source>
        <translation>Kelas</translation>
    </message>
    <message>
        <source>C&amp;lass:</source>
        <translation>K&amp;elas:</translation>
    </message>
    <message>
        <source>%1 as %2</source>
        <translation>%1 sebagai %2</translation>
    </message>
    <message>
        <source>All</source>
        <translation>Semua</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(tiada)</translation>
    </message>
</context>
<context>
    <name>palpate::DeviceController</name>
    <message>
        <source>&amp;Device</source>
        <translation>&amp;Peranti</translation>
    </message>
    <message>
        <source>Cannot switch the device</source>
        <translation>Tidak dapat menukar peranti</translation>
    </message>
    <message>
        <source>%1 is still being opened: wait for it first</source>
        <translation>%1 masih dibuka: tunggu sehingga selesai dahulu</translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>Tidak dapat membuka %1: %2</translation>
    </message>
    <message>
        <source>%1 is connected</source>
        <translation>%1 bersambung</translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation>Membuka %1…</translation>
    </message>
</context>
<context>
    <name>palpate::DevicePanel</name>
    <message>
        <source>Disconnected</source>
        <translation>Terputus</translation>
    </message>
    <message>
        <source>Opening</source>
        <translation>Sedang dibuka</translation>
    </message>
    <message>
        <source>NeedsCalibration</source>
        <translation>Perlu penentukuran</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Sedia</translation>
    </message>
    <message>
        <source>Fault</source>
        <translation>Ralat</translation>
    </message>
    <message>
        <source>HoldOff</source>
        <translation>Ditahan</translation>
    </message>
    <message>
        <source>RampIn</source>
        <translation>Meningkat</translation>
    </message>
    <message>
        <source>Armed</source>
        <translation>Aktif</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Peranti</translation>
    </message>
    <message>
        <source>URI</source>
        <translation>URI</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Keterangan</translation>
    </message>
    <message>
        <source>The devices this build knows. Double-click one to connect.</source>
        <translation>Peranti yang diketahui oleh binaan ini. Klik dua kali untuk menyambung.</translation>
    </message>
    <message>
        <source>Waypoint File…</source>
        <translation>Fail titik laluan…</translation>
    </message>
    <message>
        <source>Choose the waypoint file the simulated device follows</source>
        <translation>Pilih fail titik laluan yang diikuti oleh peranti simulasi</translation>
    </message>
    <message>
        <source>&amp;URI:</source>
        <translation>&amp;URI:</translation>
    </message>
    <message>
        <source>Type a device URI, e.g. sim:stroke</source>
        <translation>Taip URI peranti, cth. sim:stroke</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Sambung</translation>
    </message>
    <message>
        <source>Connect to the device the URI names (switching from the current one)</source>
        <translation>Sambung ke peranti yang dinamakan oleh URI (bertukar daripada yang semasa)</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Putuskan</translation>
    </message>
    <message>
        <source>Stop sending forces and release the device</source>
        <translation>Berhenti menghantar daya dan lepaskan peranti</translation>
    </message>
    <message>
        <source>Connected Device</source>
        <translation>Peranti Bersambung</translation>
    </message>
    <message>
        <source>URI:</source>
        <translation>URI:</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Nama:</translation>
    </message>
    <message>
        <source>Max force:</source>
        <translation>Daya maks.:</translation>
    </message>
    <message>
        <source>Max stiffness:</source>
        <translation>Kekakuan maks.:</translation>
    </message>
    <message>
        <source>Max damping:</source>
        <translation>Redaman maks.:</translation>
    </message>
    <message>
        <source>Workspace radius:</source>
        <translation>Jejari ruang kerja:</translation>
    </message>
    <message>
        <source>Actuated:</source>
        <translation>Berpenggerak:</translation>
    </message>
    <message>
        <source>Buttons:</source>
        <translation>Butang:</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Keadaan</translation>
    </message>
    <message>
        <source>The device&apos;s state as the haptic loop last saw it</source>
        <translation>Keadaan peranti seperti yang terakhir dilihat oleh gelung haptik</translation>
    </message>
    <message>
        <source>The safety filter: holding forces off until the command is small, ramping in, or armed</source>
        <translation>Penapis keselamatan: menahan daya sehingga arahan kecil, meningkatkan daya, atau aktif</translation>
    </message>
    <message>
        <source>Why the force sent differs from the force the model asked for</source>
        <translation>Mengapa daya yang dihantar berbeza daripada daya yang diminta oleh model</translation>
    </message>
    <message>
        <source>Tool tip position in the scene&apos;s frame</source>
        <translation>Kedudukan hujung alat dalam kerangka adegan</translation>
    </message>
    <message>
        <source>Device:</source>
        <translation>Peranti:</translation>
    </message>
    <message>
        <source>Safety:</source>
        <translation>Keselamatan:</translation>
    </message>
    <message>
        <source>Flags:</source>
        <translation>Bendera:</translation>
    </message>
    <message>
        <source>Force:</source>
        <translation>Daya:</translation>
    </message>
    <message>
        <source>Tool:</source>
        <translation>Alat:</translation>
    </message>
    <message>
        <source>Choose a Waypoint File</source>
        <translation>Pilih Fail Titik Laluan</translation>
    </message>
    <message>
        <source>Waypoint files (*.txt *.csv *.tsv);;All files (*)</source>
        <translation>Fail titik laluan (*.txt *.csv *.tsv);;Semua fail (*)</translation>
    </message>
    <message>
        <source>No device URI: choose a device in the list or type a URI.</source>
        <translation>Tiada URI peranti: pilih peranti dalam senarai atau taip URI.</translation>
    </message>
    <message>
        <source>Cannot connect: %1</source>
        <translation>Tidak dapat menyambung: %1</translation>
    </message>
    <message>
        <source>%1 is connected again: forces stay off until the safety filter has armed.</source>
        <translation>%1 bersambung semula: daya kekal mati sehingga penapis keselamatan aktif.</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>Tidak bersambung</translation>
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
        <translation>ya</translation>
    </message>
    <message>
        <source>no (input only)</source>
        <translation>tidak (input sahaja)</translation>
    </message>
    <message>
        <source>held off</source>
        <translation>ditahan</translation>
    </message>
    <message>
        <source>ramping</source>
        <translation>meningkat</translation>
    </message>
    <message>
        <source>clamped</source>
        <translation>diapit</translation>
    </message>
    <message>
        <source>stale sample</source>
        <translation>sampel lapuk</translation>
    </message>
    <message>
        <source>overrun</source>
        <translation>terlebih masa</translation>
    </message>
    <message>
        <source>not ready</source>
        <translation>tidak sedia</translation>
    </message>
    <message>
        <source>non-finite command</source>
        <translation>arahan tidak terhingga</translation>
    </message>
    <message>
        <source>bad clock</source>
        <translation>jam rosak</translation>
    </message>
    <message>
        <source>none</source>
        <translation>tiada</translation>
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
        <translation>%1 melaporkan ralat: daya dimatikan. Putuskannya, atau sambung semula untuk mencuba lagi.</translation>
    </message>
    <message>
        <source>%1 is disconnected (unplugged?): forces are off. Plug it back in or choose another device.</source>
        <translation>%1 terputus (tercabut?): daya dimatikan. Pasangkannya semula atau pilih peranti lain.</translation>
    </message>
    <message>
        <source>%1 is coming back (%2): forces are off.</source>
        <translation>%1 sedang kembali (%2): daya dimatikan.</translation>
    </message>
    <message>
        <source>%1 is back: forces are held off until the tool eases off the tissue.</source>
        <translation>%1 telah kembali: daya ditahan sehingga alat melonggarkan tekanan pada tisu.</translation>
    </message>
    <message>
        <source>%1 is back: forces are ramping in.</source>
        <translation>%1 telah kembali: daya sedang ditingkatkan.</translation>
    </message>
    <message>
        <source>Force sent to the device (after the safety filter); marked when the model asked for more than the device&apos;s maximum force and the filter clipped it</source>
        <translation>Daya yang dihantar ke peranti (selepas penapis keselamatan); ditanda apabila model meminta lebih daripada daya maksimum peranti dan penapis mengehadkannya</translation>
    </message>
    <message>
        <source>clipped at device max %1 N (the model asked %2 N)</source>
        <translation>dihadkan pada maksimum peranti %1 N (model meminta %2 N)</translation>
    </message>
    <message>
        <source>clipped (the model asked %1 N)</source>
        <translation>dihadkan (model meminta %1 N)</translation>
    </message>
</context>
<context>
    <name>palpate::ExerciseController</name>
    <message>
        <source>Choose a trainee, or add one with New…, before starting.</source>
        <translation>Pilih pelatih, atau tambah satu dengan Baharu…, sebelum bermula.</translation>
    </message>
    <message>
        <source>Choose an exercise first.</source>
        <translation>Pilih latihan dahulu.</translation>
    </message>
    <message>
        <source>An exercise is already running: stop it first.</source>
        <translation>Latihan sedang berjalan: hentikannya dahulu.</translation>
    </message>
    <message>
        <source>Preview</source>
        <translation>Pratonton</translation>
    </message>
    <message>
        <source>Preview of &quot;%1&quot;: not stored.</source>
        <translation>Pratonton &quot;%1&quot;: tidak disimpan.</translation>
    </message>
    <message>
        <source>The recordings folder %1 cannot be created: the exercise cannot be recorded and scored.</source>
        <translation>Folder rakaman %1 tidak dapat dicipta: latihan tidak dapat dirakam dan diberi markah.</translation>
    </message>
    <message>
        <source>Exercise &quot;%1&quot; started; recording to %2</source>
        <translation>Latihan &quot;%1&quot; bermula; merakam ke %2</translation>
    </message>
    <message>
        <source>the recording was stopped</source>
        <translation>rakaman telah dihentikan</translation>
    </message>
    <message>
        <source>Marked</source>
        <translation>Ditanda</translation>
    </message>
    <message>
        <source>Stopped before the session began: nothing recorded.</source>
        <translation>Dihentikan sebelum sesi bermula: tiada apa-apa dirakam.</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>dihentikan</translation>
    </message>
    <message>
        <source>The exercise could not go on: %1</source>
        <translation>Latihan tidak dapat diteruskan: %1</translation>
    </message>
    <message>
        <source>Exercise ended: %1</source>
        <translation>Latihan tamat: %1</translation>
    </message>
    <message>
        <source>Result stored for %1.</source>
        <translation>Keputusan disimpan untuk %1.</translation>
    </message>
    <message>
        <source>Ended: %1. </source>
        <translation>Tamat: %1. </translation>
    </message>
    <message>
        <source>Exercise &quot;%1&quot;: score %2</source>
        <translation>Latihan &quot;%1&quot;: markah %2</translation>
    </message>
    <message>
        <source>There is no score to export yet.</source>
        <translation>Belum ada markah untuk dieksport.</translation>
    </message>
    <message>
        <source>This result has no recording to report from.</source>
        <translation>Keputusan ini tiada rakaman untuk dilaporkan.</translation>
    </message>
    <message>
        <source>no results database is open</source>
        <translation>tiada pangkalan data keputusan dibuka</translation>
    </message>
    <message>
        <source>%1: trainees cannot be stored.</source>
        <translation>%1: pelatih tidak dapat disimpan.</translation>
    </message>
    <message>
        <source>the session was not recorded, so it is lost</source>
        <translation>sesi tidak dirakam, jadi ia hilang</translation>
    </message>
    <message>
        <source>the session is kept in the recording %1 (palpate-cli score scores it again)</source>
        <translation>sesi disimpan dalam rakaman %1 (palpate-cli score menilainya semula)</translation>
    </message>
    <message>
        <source>The result was NOT stored: %1; %2.</source>
        <translation>Keputusan TIDAK disimpan: %1; %2.</translation>
    </message>
    <message>
        <source>%1: is the recording the report is made from; choose another file for the PDF</source>
        <translation>%1: ialah rakaman yang menjadi sumber laporan; pilih fail lain untuk PDF</translation>
    </message>
    <message>
        <source>Examination finished</source>
        <translation>Pemeriksaan selesai</translation>
    </message>
    <message>
        <source>Your level: every lump at %1 %2 (the staircase adapts it to you).</source>
        <translation>Tahap anda: setiap ketulan pada %1 %2 (tangga menyesuaikannya dengan anda).</translation>
    </message>
    <message>
        <source>The staircase was not moved: %1</source>
        <translation>Tangga tidak digerakkan: %1</translation>
    </message>
    <message>
        <source>Trial passed; next level %1.</source>
        <translation>Percubaan lulus; tahap seterusnya %1.</translation>
    </message>
    <message>
        <source>Trial failed; next level %1.</source>
        <translation>Percubaan gagal; tahap seterusnya %1.</translation>
    </message>
    <message>
        <source>Expert reference session stored for %1: it sets the pass marks.</source>
        <translation>Sesi rujukan pakar disimpan untuk %1: ia menetapkan markah lulus.</translation>
    </message>
    <message>
        <source>%1: the folder to import the exercise into cannot be made</source>
        <translation>%1: folder untuk mengimport latihan tidak dapat dibuat</translation>
    </message>
</context>
<context>
    <name>palpate::ExerciseEditorPanel</name>
    <message>
        <source>Unsaved exercise</source>
        <translation>Latihan belum disimpan</translation>
    </message>
    <message>
        <source>The exercise &quot;%1&quot; has changes that are not saved. Save them first?</source>
        <translation>Latihan &quot;%1&quot; mempunyai perubahan yang belum disimpan. Simpan dahulu?</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Buat asal</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Buat semula</translation>
    </message>
    <message>
        <source>Type:</source>
        <translation>Jenis:</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Nama:</translation>
    </message>
    <message>
        <source>Description:</source>
        <translation>Keterangan:</translation>
    </message>
    <message>
        <source>Mesh:</source>
        <translation>Jejaring:</translation>
    </message>
    <message>
        <source>Tissue preset:</source>
        <translation>Praset tisu:</translation>
    </message>
    <message>
        <source>Time limit:</source>
        <translation>Had masa:</translation>
    </message>
    <message>
        <source>Damage beyond:</source>
        <translation>Kerosakan melebihi:</translation>
    </message>
    <message>
        <source>Excessive force:</source>
        <translation>Daya berlebihan:</translation>
    </message>
    <message>
        <source>The mesh &apos;%1&apos; cannot be found.</source>
        <translation>Jejaring &apos;%1&apos; tidak ditemui.</translation>
    </message>
    <message>
        <source>New: %1</source>
        <translation>Baharu: %1</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Baharu</translation>
    </message>
    <message>
        <source>A new exercise of a type; asks before unsaved changes are lost.</source>
        <translation>Latihan baharu bagi satu jenis; bertanya sebelum perubahan yang belum disimpan hilang.</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Buka…</translation>
    </message>
    <message>
        <source>Open an exercise file (Ctrl+O).</source>
        <translation>Buka fail latihan (Ctrl+O).</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Simpan</translation>
    </message>
    <message>
        <source>Save the exercise to its file (Ctrl+S); refused while it has problems.</source>
        <translation>Simpan latihan ke failnya (Ctrl+S); ditolak selagi ada masalah.</translation>
    </message>
    <message>
        <source>Save As…</source>
        <translation>Simpan Sebagai…</translation>
    </message>
    <message>
        <source>Save the exercise to a new file (Ctrl+Shift+S).</source>
        <translation>Simpan latihan ke fail baharu (Ctrl+Shift+S).</translation>
    </message>
    <message>
        <source>Try it</source>
        <translation>Cuba</translation>
    </message>
    <message>
        <source>Run this exercise now as a trainee would, without saving it (F5).</source>
        <translation>Jalankan latihan ini sekarang seperti pelatih, tanpa menyimpannya (F5).</translation>
    </message>
    <message>
        <source>Stop placing</source>
        <translation>Berhenti meletak</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Buang</translation>
    </message>
    <message>
        <source>Move up</source>
        <translation>Naikkan</translation>
    </message>
    <message>
        <source>Move down</source>
        <translation>Turunkan</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Latihan</translation>
    </message>
    <message>
        <source>What the trainee does. Each type keeps its own points: switching back restores them.</source>
        <translation>Apa yang dilakukan oleh pelatih. Setiap jenis menyimpan titiknya sendiri: bertukar semula memulihkannya.</translation>
    </message>
    <message>
        <source>The name trainees and score reports see (name).</source>
        <translation>Nama yang dilihat oleh pelatih dan laporan markah (name).</translation>
    </message>
    <message>
        <source>Required</source>
        <translation>Wajib</translation>
    </message>
    <message>
        <source>What the trainee is asked to do, shown before the exercise starts (description).</source>
        <translation>Apa yang perlu dilakukan oleh pelatih, ditunjukkan sebelum latihan bermula (description).</translation>
    </message>
    <message>
        <source>Tissue</source>
        <translation>Tisu</translation>
    </message>
    <message>
        <source>The mesh file (mesh): a shipped mesh, a path relative to resources/ or to the exercise file, or an absolute path. Points are vertices of this file.</source>
        <translation>Fail jejaring (mesh): jejaring yang disertakan, laluan relatif kepada resources/ atau kepada fail latihan, atau laluan mutlak. Titik ialah bucu fail ini.</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Semak imbas…</translation>
    </message>
    <message>
        <source>Choose a mesh file (OBJ, OFF, PLY, STL, OM).</source>
        <translation>Pilih fail jejaring (OBJ, OFF, PLY, STL, OM).</translation>
    </message>
    <message>
        <source>Show this mesh</source>
        <translation>Tunjukkan jejaring ini</translation>
    </message>
    <message>
        <source>Draw the exercise&apos;s mesh in the viewport, so that points can be placed by clicking.</source>
        <translation>Lukis jejaring latihan dalam port pandangan, supaya titik boleh diletakkan dengan mengklik.</translation>
    </message>
    <message>
        <source>The tissue preset file (tissue_preset): how the tissue feels.</source>
        <translation>Fail praset tisu (tissue_preset): bagaimana tisu terasa.</translation>
    </message>
    <message>
        <source>Choose a tissue preset file (JSON).</source>
        <translation>Pilih fail praset tisu (JSON).</translation>
    </message>
    <message>
        <source>Limits</source>
        <translation>Had</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Time the trainee has (time_limit_s); what happens after it is not scored.</source>
        <translation>Masa yang ada pada pelatih (time_limit_s); apa yang berlaku selepasnya tidak diberi markah.</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Tissue displaced further than this counts as damage (damage.displacement_limit_mm).</source>
        <translation>Tisu yang teranjak lebih jauh daripada ini dikira sebagai kerosakan (damage.displacement_limit_mm).</translation>
    </message>
    <message>
        <source> N</source>
        <translation> N</translation>
    </message>
    <message>
        <source>A force above this is excessive (force.excessive_n); every target&apos;s lower force must stay below it.</source>
        <translation>Daya melebihi ini adalah berlebihan (force.excessive_n); daya bawah setiap sasaran mesti kekal di bawahnya.</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>Vertex</source>
        <translation>Bucu</translation>
    </message>
    <message>
        <source>Add by clicking</source>
        <translation>Tambah dengan mengklik</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Alih</translation>
    </message>
    <message>
        <source>Place by clicking</source>
        <translation>Letak dengan mengklik</translation>
    </message>
    <message>
        <source>Rubric</source>
        <translation>Rubrik</translation>
    </message>
    <message>
        <source>Metric</source>
        <translation>Metrik</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Pemberat</translation>
    </message>
    <message>
        <source>Full</source>
        <translation>Penuh</translation>
    </message>
    <message>
        <source>Zero</source>
        <translation>Sifar</translation>
    </message>
    <message>
        <source>What is measured (the rubric key; its tooltip says what it is).</source>
        <translation>Apa yang diukur (kunci rubrik; petua alatnya menerangkannya).</translation>
    </message>
    <message>
        <source>The metric&apos;s unit.</source>
        <translation>Unit metrik.</translation>
    </message>
    <message>
        <source>Relative weight (0: reported, not scored).</source>
        <translation>Pemberat relatif (0: dilaporkan, tidak diberi markah).</translation>
    </message>
    <message>
        <source>At or beyond this value the line scores full marks.</source>
        <translation>Pada atau melepasi nilai ini baris mendapat markah penuh.</translation>
    </message>
    <message>
        <source>At or beyond this value (away from full) the line scores zero.</source>
        <translation>Pada atau melepasi nilai ini (menjauhi penuh) baris mendapat sifar.</translation>
    </message>
    <message>
        <source>Grey lines are the defaults (docs/scoring.md), computed from the exercise&apos;s own numbers; editing a line sets it in the exercise.</source>
        <translation>Baris kelabu ialah lalai (docs/scoring.md), dikira daripada nombor latihan itu sendiri; menyunting baris menetapkannya dalam latihan.</translation>
    </message>
    <message>
        <source>Reset to defaults</source>
        <translation>Set semula ke lalai</translation>
    </message>
    <message>
        <source>Remove every rubric line the exercise sets: all metrics use the defaults.</source>
        <translation>Buang setiap baris rubrik yang ditetapkan oleh latihan: semua metrik menggunakan lalai.</translation>
    </message>
    <message>
        <source>New exercise: %1</source>
        <translation>Latihan baharu: %1</translation>
    </message>
    <message>
        <source>Not opened:</source>
        <translation>Tidak dibuka:</translation>
    </message>
    <message>
        <source>Opened %1.</source>
        <translation>%1 dibuka.</translation>
    </message>
    <message>
        <source>No file to save to.</source>
        <translation>Tiada fail untuk disimpan.</translation>
    </message>
    <message>
        <source>Not saved: the exercise has problems:</source>
        <translation>Tidak disimpan: latihan mempunyai masalah:</translation>
    </message>
    <message>
        <source>Not saved:</source>
        <translation>Tidak disimpan:</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>%1 disimpan.</translation>
    </message>
    <message>
        <source>Not saved.</source>
        <translation>Tidak disimpan.</translation>
    </message>
    <message>
        <source>Save exercise</source>
        <translation>Simpan latihan</translation>
    </message>
    <message>
        <source>Exercises (*.json)</source>
        <translation>Latihan (*.json)</translation>
    </message>
    <message>
        <source>Open exercise</source>
        <translation>Buka latihan</translation>
    </message>
    <message>
        <source>Exercises (*.json);;All files (*)</source>
        <translation>Latihan (*.json);;Semua fail (*)</translation>
    </message>
    <message>
        <source>Choose a mesh</source>
        <translation>Pilih jejaring</translation>
    </message>
    <message>
        <source>Meshes (*.off *.obj *.ply *.stl *.om);;All files (*)</source>
        <translation>Jejaring (*.off *.obj *.ply *.stl *.om);;Semua fail (*)</translation>
    </message>
    <message>
        <source>Choose a tissue preset</source>
        <translation>Pilih praset tisu</translation>
    </message>
    <message>
        <source>Tissue presets (*.json);;All files (*)</source>
        <translation>Praset tisu (*.json);;Semua fail (*)</translation>
    </message>
    <message>
        <source>(%1, %2, %3) mm</source>
        <translation>(%1, %2, %3) mm</translation>
    </message>
    <message>
        <source>Weights total %1; the score is 100 × Σ wᵢsᵢ / Σ wᵢ.</source>
        <translation>Jumlah pemberat %1; markah ialah 100 × Σ wᵢsᵢ / Σ wᵢ.</translation>
    </message>
    <message>
        <source>name</source>
        <translation>nama</translation>
    </message>
    <message>
        <source>description</source>
        <translation>keterangan</translation>
    </message>
    <message>
        <source>time limit</source>
        <translation>had masa</translation>
    </message>
    <message>
        <source>damage limit</source>
        <translation>had kerosakan</translation>
    </message>
    <message>
        <source>excessive force</source>
        <translation>daya berlebihan</translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>Ubah %1</translation>
    </message>
    <message>
        <source>Change the rubric&apos;s %1</source>
        <translation>Ubah %1 rubrik</translation>
    </message>
    <message>
        <source>Reset the rubric</source>
        <translation>Set semula rubrik</translation>
    </message>
    <message>
        <source>Change the mesh</source>
        <translation>Ubah jejaring</translation>
    </message>
    <message>
        <source>Change the tissue preset</source>
        <translation>Ubah praset tisu</translation>
    </message>
    <message>
        <source>Change the type to %1</source>
        <translation>Ubah jenis kepada %1</translation>
    </message>
    <message>
        <source>The viewport does not show this exercise&apos;s mesh: press Show this mesh first.</source>
        <translation>Port pandangan tidak menunjukkan jejaring latihan ini: tekan Tunjukkan jejaring ini dahulu.</translation>
    </message>
    <message>
        <source>That click was on another mesh than the exercise&apos;s: press Show this mesh first.</source>
        <translation>Klik itu pada jejaring lain daripada jejaring latihan: tekan Tunjukkan jejaring ini dahulu.</translation>
    </message>
    <message>
        <source>Vertex %1 is not on the drawn mesh.</source>
        <translation>Bucu %1 tiada pada jejaring yang dilukis.</translation>
    </message>
    <message>
        <source>mesh: &apos;%1&apos; is not found beside the exercise file or under resources/</source>
        <translation>mesh: &apos;%1&apos; tidak ditemui di sebelah fail latihan atau di bawah resources/</translation>
    </message>
    <message>
        <source>tissue_preset: &apos;%1&apos; is not found beside the exercise file or under resources/</source>
        <translation>tissue_preset: &apos;%1&apos; tidak ditemui di sebelah fail latihan atau di bawah resources/</translation>
    </message>
    <message>
        <source>mesh: %1</source>
        <translation>jejaring: %1</translation>
    </message>
    <message>
        <source>no mesh</source>
        <translation>tiada jejaring</translation>
    </message>
    <message>
        <source>mesh: the viewport shows %1, not this exercise&apos;s %2: press Show this mesh to place points by clicking</source>
        <translation>mesh: port pandangan menunjukkan %1, bukan %2 latihan ini: tekan Tunjukkan jejaring ini untuk meletak titik dengan mengklik</translation>
    </message>
    <message>
        <source>Not found.</source>
        <translation>Tidak ditemui.</translation>
    </message>
    <message>
        <source>Drawn in the viewport.</source>
        <translation>Dilukis dalam port pandangan.</translation>
    </message>
    <message>
        <source>Not drawn in the viewport.</source>
        <translation>Tidak dilukis dalam port pandangan.</translation>
    </message>
    <message>
        <source>not saved yet</source>
        <translation>belum disimpan</translation>
    </message>
    <message>
        <source>%1 — %2%3</source>
        <translation>%1 — %2%3</translation>
    </message>
    <message>
        <source>(unnamed)</source>
        <translation>(tanpa nama)</translation>
    </message>
    <message>
        <source> (modified)</source>
        <translation> (diubah)</translation>
    </message>
    <message>
        <source>Cannot try it: the exercise has problems (listed above).</source>
        <translation>Tidak dapat dicuba: latihan mempunyai masalah (disenaraikan di atas).</translation>
    </message>
    <message>
        <source>State level-of-detail targets</source>
        <translation>Nyatakan sasaran aras perincian</translation>
    </message>
    <message>
        <source>The accuracy and haptic time the model for this exercise must meet (needs)</source>
        <translation>Ketepatan dan masa haptik yang mesti dipenuhi oleh model untuk latihan ini (needs)</translation>
    </message>
    <message>
        <source>Largest displacement error against the reference (needs.max_error)</source>
        <translation>Ralat anjakan terbesar berbanding rujukan (needs.max_error)</translation>
    </message>
    <message>
        <source>Max error:</source>
        <translation>Ralat maks.:</translation>
    </message>
    <message>
        <source>Longest haptic tick the model may take (needs.budget_us)</source>
        <translation>Tik haptik terpanjang yang boleh diambil oleh model (needs.budget_us)</translation>
    </message>
    <message>
        <source>Tick budget:</source>
        <translation>Bajet tik:</translation>
    </message>
    <message>
        <source>State targets</source>
        <translation>Nyatakan sasaran</translation>
    </message>
    <message>
        <source>Remove targets</source>
        <translation>Buang sasaran</translation>
    </message>
    <message>
        <source>max error</source>
        <translation>ralat maks.</translation>
    </message>
    <message>
        <source>tick budget</source>
        <translation>bajet tik</translation>
    </message>
    <message>
        <source>tissue_preset: whether the targets can be reached with the mouse is not known: %1</source>
        <translation>tissue_preset: sama ada sasaran boleh dicapai dengan tetikus tidak diketahui: %1</translation>
    </message>
    <message>
        <source>%1: target %2 cannot be held with the mouse: its window %3–%4 N lies between %5 N at %6 mm and %7 N at %8 mm deep (one turn of the wheel apart). Widen the window to take in one of them.</source>
        <translation>%1: sasaran %2 tidak boleh ditahan dengan tetikus: tetingkapnya %3–%4 N terletak antara %5 N pada %6 mm dan %7 N pada kedalaman %8 mm (satu pusingan roda). Lebarkan tetingkap supaya merangkumi salah satunya.</translation>
    </message>
    <message>
        <source>%1: target %2 cannot be reached with the mouse: pressing %3 mm deep (the deepest) gives %4 N, below its window&apos;s %5 N. Lower the window to at most %4 N%6, or choose a stiffer tissue preset.</source>
        <translation>%1: sasaran %2 tidak boleh dicapai dengan tetikus: menekan sedalam %3 mm (paling dalam) memberi %4 N, di bawah %5 N tetingkapnya. Turunkan tetingkap kepada paling banyak %4 N%6, atau pilih praset tisu yang lebih keras.</translation>
    </message>
    <message>
        <source>tissue_preset: whether the band can be reached with the mouse is not known: %1</source>
        <translation>tissue_preset: sama ada jalur boleh dicapai dengan tetikus tidak diketahui: %1</translation>
    </message>
    <message>
        <source>trace.force_min_n: the band cannot be reached with the mouse at path point %1: pressing %2 mm deep (the deepest) gives as little as %3 N there, below the band&apos;s %4 N. Lower the band to at most %3 N%5, or choose a stiffer tissue preset.</source>
        <translation>trace.force_min_n: jalur tidak boleh dicapai dengan tetikus pada titik laluan %1: menekan sedalam %2 mm (paling dalam) memberi serendah %3 N di situ, di bawah %4 N jalur. Turunkan jalur kepada paling banyak %3 N%5, atau pilih praset tisu yang lebih keras.</translation>
    </message>
    <message>
        <source>trace.force_min_n: the band %1–%2 N lies between the forces of two turns of the wheel at path point %3: widen it.</source>
        <translation>trace.force_min_n: jalur %1–%2 N terletak antara daya dua pusingan roda pada titik laluan %3: lebarkannya.</translation>
    </message>
    <message>
        <source>Mesh unit:</source>
        <translation>Unit jejaring:</translation>
    </message>
    <message>
        <source>millimetres (mm)</source>
        <translation>milimeter (mm)</translation>
    </message>
    <message>
        <source>centimetres (cm)</source>
        <translation>sentimeter (cm)</translation>
    </message>
    <message>
        <source>metres (m)</source>
        <translation>meter (m)</translation>
    </message>
    <message>
        <source>inches (in)</source>
        <translation>inci (in)</translation>
    </message>
    <message>
        <source>scale…</source>
        <translation>skala…</translation>
    </message>
    <message>
        <source>The unit of the mesh file&apos;s coordinates (mesh_unit): a mesh from another tool may be in metres, inches or centimetres; it is scaled to mm wherever it is loaded.</source>
        <translation>Unit koordinat fail jejaring (mesh_unit): jejaring daripada alat lain mungkin dalam meter, inci atau sentimeter; ia diskalakan kepada mm di mana-mana ia dimuatkan.</translation>
    </message>
    <message>
        <source> mm per file unit</source>
        <translation> mm bagi setiap unit fail</translation>
    </message>
    <message>
        <source>How many millimetres one unit of the mesh file is (mesh_unit as a number).</source>
        <translation>Berapa milimeter satu unit fail jejaring (mesh_unit sebagai nombor).</translation>
    </message>
    <message>
        <source>mesh unit</source>
        <translation>unit jejaring</translation>
    </message>
    <message>
        <source>mesh_unit: the viewport shows %1 read in %2, this exercise reads it in %3: press Show this mesh to place points by clicking</source>
        <translation>mesh_unit: paparan menunjukkan %1 dibaca dalam %2, latihan ini membacanya dalam %3: tekan Tunjukkan jejaring ini untuk meletakkan titik dengan mengklik</translation>
    </message>
    <message>
        <source>Show the live score</source>
        <translation>Tunjukkan skor langsung</translation>
    </message>
    <message>
        <source>Hide the live score</source>
        <translation>Sembunyikan skor langsung</translation>
    </message>
    <message>
        <source>press a sequence of surface targets, each with a force window and a hold.</source>
        <translation>tekan satu siri sasaran permukaan, setiap satu dengan tetingkap daya dan tempoh tahan.</translation>
    </message>
    <message>
        <source>find a hidden stiff inclusion by palpation and mark it.</source>
        <translation>cari rangkuman keras yang tersembunyi dengan palpasi dan tandakannya.</translation>
    </message>
    <message>
        <source>trace a path on the surface, keeping the force in a band.</source>
        <translation>ikut laluan pada permukaan sambil mengekalkan daya dalam satu jalur.</translation>
    </message>
    <message>
        <source>examine the whole surface for lumps under it (or none), mark each and finish.</source>
        <translation>periksa seluruh permukaan untuk ketulan di bawahnya (atau tiada), tandakan setiap satu dan selesai.</translation>
    </message>
    <message>
        <source>A new exercise: %1</source>
        <translation>Latihan baharu: %1</translation>
    </message>
    <message>
        <source>Show the score while it runs</source>
        <translation>Tunjukkan skor semasa berjalan</translation>
    </message>
    <message>
        <source>Whether the trainee sees the score so far (show_live_score). Off by default where it would give the answer away: in detecting lumps a mark on a lump would raise it.</source>
        <translation>Sama ada pelatih melihat skor setakat ini (show_live_score). Mati secara lalai apabila ia akan mendedahkan jawapan: dalam mengesan ketulan, tanda pada ketulan akan menaikkannya.</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>The order the trainee follows.</source>
        <translation>Urutan yang diikuti oleh pelatih.</translation>
    </message>
    <message>
        <source>The item&apos;s number.</source>
        <translation>Nombor item.</translation>
    </message>
    <message>
        <source>Its vertex, in the mesh file&apos;s numbering (vertex).</source>
        <translation>Bucunya, mengikut penomboran fail jejaring (vertex).</translation>
    </message>
    <message>
        <source>The next click on the mesh moves the selected row&apos;s point there.</source>
        <translation>Klik seterusnya pada jejaring mengalihkan titik baris yang dipilih ke situ.</translation>
    </message>
    <message>
        <source>Remove the selected row (Delete).</source>
        <translation>Buang baris yang dipilih (Delete).</translation>
    </message>
    <message>
        <source>Move the selected row earlier (Ctrl+Up).</source>
        <translation>Alihkan baris yang dipilih lebih awal (Ctrl+Up).</translation>
    </message>
    <message>
        <source>Move the selected row later (Ctrl+Down).</source>
        <translation>Alihkan baris yang dipilih lebih lewat (Ctrl+Down).</translation>
    </message>
    <message>
        <source> (start)</source>
        <translation> (mula)</translation>
    </message>
    <message>
        <source> (end)</source>
        <translation> (akhir)</translation>
    </message>
    <message>
        <source>Change %1&apos;s %2</source>
        <translation>Tukar %2 bagi %1</translation>
    </message>
    <message>
        <source>Remove %1</source>
        <translation>Buang %1</translation>
    </message>
    <message>
        <source>Move %1 up</source>
        <translation>Alihkan %1 ke atas</translation>
    </message>
    <message>
        <source>Move %1 down</source>
        <translation>Alihkan %1 ke bawah</translation>
    </message>
    <message>
        <source>Click the tissue to place %1, and more after it; Esc to stop.</source>
        <translation>Klik pada tisu untuk meletakkan %1, dan lebih lagi selepasnya; Esc untuk berhenti.</translation>
    </message>
    <message>
        <source>Click the mesh where the point goes; Esc cancels.</source>
        <translation>Klik pada jejaring di tempat titik itu; Esc membatalkan.</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>Tambah %1</translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>Alihkan %1</translation>
    </message>
    <message>
        <source>tissue_preset: whether the lumps can be felt is not known: %1</source>
        <translation>tissue_preset: sama ada ketulan boleh dirasa tidak diketahui: %1</translation>
    </message>
    <message>
        <source>%1: feeling lump %2 takes about %3 N, at or above the excessive force %4 N: the trainee who finds it is marked down for pressing too hard. Make it shallower, or raise the excessive force.</source>
        <translation>%1: merasa ketulan %2 memerlukan kira-kira %3 N, pada atau melebihi daya berlebihan %4 N: pelatih yang menemuinya kehilangan markah kerana menekan terlalu kuat. Jadikan ia lebih cetek, atau naikkan daya berlebihan.</translation>
    </message>
    <message>
        <source>%1: feeling lump %2 takes about %3 N, more than a desktop device renders (%4 N). Make it shallower, or choose a softer tissue preset.</source>
        <translation>%1: merasa ketulan %2 memerlukan kira-kira %3 N, lebih daripada yang dihasilkan peranti meja (%4 N). Jadikan ia lebih cetek, atau pilih pratetap tisu yang lebih lembut.</translation>
    </message>
    <message>
        <source>%1: lump %2 cannot be felt with the mouse: the surface above it does not sink to its top (%3 mm under it) however deep the mouse presses. Make it shallower, or choose a softer tissue preset.</source>
        <translation>%1: ketulan %2 tidak dapat dirasa dengan tetikus: permukaan di atasnya tidak tenggelam ke bahagian atasnya (%3 mm di bawahnya) sedalam mana pun tetikus menekan. Jadikan ia lebih cetek, atau pilih pratetap tisu yang lebih lembut.</translation>
    </message>
    <message>
        <source>%1: lump %2 cannot be felt with the mouse: its top lies %3 mm under the surface; the surface sinks that far under a press %4 mm deep, and the lump is felt a wheel step (%5 mm) deeper, but the mouse presses at most %6 mm deep. Make it at most %7 mm deep, or train this one with a device.</source>
        <translation>%1: ketulan %2 tidak dapat dirasa dengan tetikus: bahagian atasnya terletak %3 mm di bawah permukaan; permukaan tenggelam sejauh itu di bawah tekanan sedalam %4 mm, dan ketulan dirasa satu langkah roda (%5 mm) lebih dalam, tetapi tetikus menekan paling dalam %6 mm. Jadikan ia paling dalam %7 mm, atau latih yang ini dengan peranti.</translation>
    </message>
    <message>
        <source>tissue_preset: whether the mouse presses hard enough to examine is not known: %1</source>
        <translation>tissue_preset: sama ada tetikus menekan cukup kuat untuk memeriksa tidak diketahui: %1</translation>
    </message>
    <message>
        <source>Copied %1 beside it, so that the exercise opens on other computers.</source>
        <translation>%1 disalin di sebelahnya, supaya latihan dibuka pada komputer lain.</translation>
    </message>
    <message>
        <source>coverage.min_force_n: the mouse cannot examine this tissue: pressing %1 mm deep (the deepest) gives %2 N over most of the surface, below the examining force %3 N, so nothing the trainee does counts as examined. Lower it to %4 N (what the mouse&apos;s default press gives), or choose a stiffer tissue preset.</source>
        <translation>coverage.min_force_n: tetikus tidak dapat memeriksa tisu ini: tekanan sedalam %1 mm (paling dalam) memberi %2 N pada kebanyakan permukaan, di bawah daya pemeriksaan %3 N, jadi tiada apa yang dilakukan pelatih dikira sebagai diperiksa. Turunkan kepada %4 N (yang diberi tekanan lalai tetikus), atau pilih pratetap tisu yang lebih keras.</translation>
    </message>
    <message>
        <source>Export Bundle…</source>
        <translation>Eksport Berkas…</translation>
    </message>
    <message>
        <source>Write the exercise with its mesh, preset and scripted paths as one file, to open on a trainee&apos;s computer (Exercise &gt; Open Exercise…).</source>
        <translation>Tulis latihan bersama jejaring, pratetap dan laluan berskripnya sebagai satu fail, untuk dibuka pada komputer pelatih (Latihan &gt; Buka Latihan…).</translation>
    </message>
    <message>
        <source>Bundle not written:</source>
        <translation>Berkas tidak ditulis:</translation>
    </message>
    <message>
        <source>Bundle written: %1, with the exercise&apos;s mesh, preset and scripted paths.</source>
        <translation>Berkas ditulis: %1, bersama jejaring, pratetap dan laluan berskrip latihan.</translation>
    </message>
    <message>
        <source>Export exercise bundle</source>
        <translation>Eksport berkas latihan</translation>
    </message>
    <message>
        <source>Exercise bundles (*.palpex)</source>
        <translation>Berkas latihan (*.palpex)</translation>
    </message>
    <message>
        <source> (%1–%2 N is met pressing at least two wheel steps past the default touch)</source>
        <translation> (%1–%2 N dicapai dengan menekan sekurang-kurangnya dua langkah roda melepasi sentuhan lalai)</translation>
    </message>
    <message>
        <source>Text in:</source>
        <translation>Teks dalam:</translation>
    </message>
    <message>
        <source>Which language&apos;s name and description you edit: the exercise&apos;s own, or a translation trainees who use Palpate in that language see (translations). An empty translation shows the exercise&apos;s own words.</source>
        <translation>Bahasa nama dan penerangan yang anda sunting: kata-kata latihan itu sendiri, atau terjemahan yang dilihat pelatih yang menggunakan Palpate dalam bahasa itu (translations). Terjemahan kosong menunjukkan kata-kata latihan itu sendiri.</translation>
    </message>
    <message>
        <source>Its own words</source>
        <translation>Kata-kata asal</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Checking whether the mouse can do what the exercise asks…</source>
        <translation>Menyemak sama ada tetikus dapat melakukan apa yang diminta oleh latihan…</translation>
    </message>
</context>
<context>
    <name>palpate::ExerciseMarkers</name>
    <message>
        <source>examined from %1 N to %2 N (excessive)</source>
        <translation>diperiksa dari %1 N hingga %2 N (berlebihan)</translation>
    </message>
</context>
<context>
    <name>palpate::Exercises</name>
    <message>
        <source>Detect lumps</source>
        <translation>Kesan ketulan</translation>
    </message>
    <message>
        <source>Find the lump</source>
        <translation>Cari ketulan</translation>
    </message>
    <message>
        <source>Press targets</source>
        <translation>Tekan sasaran</translation>
    </message>
    <message>
        <source>Trace a path</source>
        <translation>Jejaki laluan</translation>
    </message>
    <message>
        <source>lump %1, %2 mm deep</source>
        <translation>ketulan %1, sedalam %2 mm</translation>
    </message>
    <message>
        <source>Mark a lump where the tool presses now (M)</source>
        <translation>Tanda ketulan di tempat alat menekan sekarang (M)</translation>
    </message>
    <message>
        <source>Search the whole surface, press in where it feels different, Mark (M) each lump; Finish (F7) when done</source>
        <translation>Cari seluruh permukaan, tekan di tempat yang terasa berbeza, Tanda (M) setiap ketulan; Tamat (F7) apabila selesai</translation>
    </message>
    <message numerus="yes">
        <source>%n finding(s) marked</source>
        <translation>
            <numerusform>%n penemuan ditanda</numerusform>
        </translation>
    </message>
    <message>
        <source>in contact</source>
        <translation>bersentuhan</translation>
    </message>
    <message>
        <source>not in contact</source>
        <translation>tidak bersentuhan</translation>
    </message>
    <message>
        <source>surface examined %p%</source>
        <translation>permukaan diperiksa %p%</translation>
    </message>
    <message>
        <source>lump</source>
        <translation>ketulan</translation>
    </message>
    <message>
        <source>Marked. Mark again to correct, or Stop to finish.</source>
        <translation>Ditanda. Tanda lagi untuk membetulkan, atau Henti untuk selesai.</translation>
    </message>
    <message>
        <source>Palpate gently; press Mark (M) while you press on the lump</source>
        <translation>Palpasi dengan lembut; tekan Tanda (M) semasa anda menekan ketulan</translation>
    </message>
    <message>
        <source>In contact</source>
        <translation>Bersentuhan</translation>
    </message>
    <message>
        <source>Not in contact</source>
        <translation>Tidak bersentuhan</translation>
    </message>
    <message>
        <source>marked</source>
        <translation>ditanda</translation>
    </message>
    <message>
        <source>not marked yet</source>
        <translation>belum ditanda</translation>
    </message>
    <message>
        <source>Target %1 of %2: press with %3 and hold</source>
        <translation>Sasaran %1 daripada %2: tekan dengan %3 dan tahan</translation>
    </message>
    <message>
        <source>On target</source>
        <translation>Pada sasaran</translation>
    </message>
    <message>
        <source>Move to the blue marker (%1 mm away)</source>
        <translation>Bergerak ke penanda biru (%1 mm jauhnya)</translation>
    </message>
    <message>
        <source>hold %p%</source>
        <translation>tahan %p%</translation>
    </message>
    <message>
        <source>All targets done</source>
        <translation>Semua sasaran selesai</translation>
    </message>
    <message>
        <source>No target left</source>
        <translation>Tiada sasaran lagi</translation>
    </message>
    <message>
        <source>start</source>
        <translation>mula</translation>
    </message>
    <message>
        <source>end</source>
        <translation>tamat</translation>
    </message>
    <message>
        <source>Follow the line with %1</source>
        <translation>Ikut garisan dengan %1</translation>
    </message>
    <message>
        <source>%1 mm from the line</source>
        <translation>%1 mm dari garisan</translation>
    </message>
    <message>
        <source>covered %p%</source>
        <translation>diliputi %p%</translation>
    </message>
    <message>
        <source>lighter than %1 N counts as not examined: press deeper (with the mouse: scroll the wheel)</source>
        <translation>lebih ringan daripada %1 N dikira tidak diperiksa: tekan lebih dalam (dengan tetikus: putar roda)</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Jejari</translation>
    </message>
    <message>
        <source>The lump&apos;s radius, mm (radius_mm).</source>
        <translation>Jejari ketulan, mm (radius_mm).</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>Kedalaman</translation>
    </message>
    <message>
        <source>From the surface to the lump&apos;s top, mm (depth_mm): a deeper lump needs a firmer press to be felt.</source>
        <translation>Dari permukaan ke bahagian atas ketulan, mm (depth_mm): ketulan yang lebih dalam memerlukan tekanan lebih kuat untuk dirasa.</translation>
    </message>
    <message>
        <source>Contrast</source>
        <translation>Kontras</translation>
    </message>
    <message>
        <source>How many times stiffer than the tissue the lump is (contrast), above 1: lower is harder to feel.</source>
        <translation>Berapa kali lebih keras ketulan daripada tisu (contrast), melebihi 1: lebih rendah lebih sukar dirasa.</translation>
    </message>
    <message>
        <source>Mark within:</source>
        <translation>Tanda dalam lingkungan:</translation>
    </message>
    <message>
        <source>A mark this far outside a lump&apos;s radius still finds it, mm (detect_lumps.tolerance_mm).</source>
        <translation>Tanda sejauh ini di luar jejari ketulan masih menemuinya, mm (detect_lumps.tolerance_mm).</translation>
    </message>
    <message>
        <source>Lump %1</source>
        <translation>Ketulan %1</translation>
    </message>
    <message>
        <source>While on, each click on the tissue hides a lump under it, with the last lump&apos;s radius, depth and contrast (Esc stops). No lumps: healthy tissue, where reporting nothing is the finding.</source>
        <translation>Semasa hidup, setiap klik pada tisu menyembunyikan ketulan di bawahnya, dengan jejari, kedalaman dan kontras ketulan terakhir (Esc berhenti). Tiada ketulan: tisu sihat, di mana tidak melaporkan apa-apa ialah dapatannya.</translation>
    </message>
    <message>
        <source>Vertices this close to the centre are in the inclusion (find_lump.inclusion.radius_mm).</source>
        <translation>Bucu sedekat ini dengan pusat berada dalam rangkuman (find_lump.inclusion.radius_mm).</translation>
    </message>
    <message>
        <source>Stiffness</source>
        <translation>Kekerasan</translation>
    </message>
    <message>
        <source>The inclusion&apos;s slopes are multiplied by this, in (0, 1]: smaller is stiffer (find_lump.inclusion.stiffness_factor).</source>
        <translation>Cerun rangkuman didarab dengan nilai ini, dalam (0, 1]: lebih kecil lebih keras (find_lump.inclusion.stiffness_factor).</translation>
    </message>
    <message>
        <source>Inclusion</source>
        <translation>Rangkuman</translation>
    </message>
    <message>
        <source>The next click on the mesh puts the inclusion&apos;s centre there.</source>
        <translation>Klik seterusnya pada jejaring meletakkan pusat rangkuman di situ.</translation>
    </message>
    <message>
        <source>Examined from:</source>
        <translation>Diperiksa dari:</translation>
    </message>
    <message>
        <source>A contact lighter than this examines nothing (coverage.min_force_n): keep it within the trainee&apos;s reach (the gauge shows it).</source>
        <translation>Sentuhan yang lebih ringan daripada ini tidak memeriksa apa-apa (coverage.min_force_n): kekalkan dalam capaian pelatih (tolok menunjukkannya).</translation>
    </message>
    <message>
        <source>Examined around:</source>
        <translation>Diperiksa sekitar:</translation>
    </message>
    <message>
        <source>A contact examines the surface this close to it, mm (coverage.radius_mm).</source>
        <translation>Sentuhan memeriksa permukaan sedekat ini dengannya, mm (coverage.radius_mm).</translation>
    </message>
    <message>
        <source>Fmin</source>
        <translation>Fmin</translation>
    </message>
    <message>
        <source>The force window&apos;s lower end, N (force_min_n).</source>
        <translation>Hujung bawah tetingkap daya, N (force_min_n).</translation>
    </message>
    <message>
        <source>Fmax</source>
        <translation>Fmax</translation>
    </message>
    <message>
        <source>The force window&apos;s upper end, N (force_max_n).</source>
        <translation>Hujung atas tetingkap daya, N (force_max_n).</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Tahan</translation>
    </message>
    <message>
        <source>How long the force must stay in the window without a break, s (hold_s).</source>
        <translation>Berapa lama daya mesti kekal dalam tetingkap tanpa putus, s (hold_s).</translation>
    </message>
    <message>
        <source>Tol.</source>
        <translation>Tol.</translation>
    </message>
    <message>
        <source>How close to the target the contact must be, mm (tolerance_mm).</source>
        <translation>Sedekat mana sentuhan mesti dengan sasaran, mm (tolerance_mm).</translation>
    </message>
    <message>
        <source>Target %1</source>
        <translation>Sasaran %1</translation>
    </message>
    <message>
        <source>While on, each click on the tissue appends a target there, with the last target&apos;s window, hold and tolerance; the first gets a window the tissue reaches with the mouse (Esc stops).</source>
        <translation>Semasa hidup, setiap klik pada tisu menambah sasaran di situ, dengan tetingkap, tempoh tahan dan toleransi sasaran terakhir; yang pertama mendapat tetingkap yang dicapai tisu dengan tetikus (Esc berhenti).</translation>
    </message>
    <message>
        <source>Band from:</source>
        <translation>Jalur dari:</translation>
    </message>
    <message>
        <source>The force band&apos;s lower end (trace.force_min_n).</source>
        <translation>Hujung bawah jalur daya (trace.force_min_n).</translation>
    </message>
    <message>
        <source>Band to:</source>
        <translation>Jalur hingga:</translation>
    </message>
    <message>
        <source>The force band&apos;s upper end (trace.force_max_n).</source>
        <translation>Hujung atas jalur daya (trace.force_max_n).</translation>
    </message>
    <message>
        <source>Tolerance:</source>
        <translation>Toleransi:</translation>
    </message>
    <message>
        <source>A path point is covered by contact this close to it (trace.tolerance_mm).</source>
        <translation>Titik laluan diliputi oleh sentuhan sedekat ini dengannya (trace.tolerance_mm).</translation>
    </message>
    <message>
        <source>Path point %1</source>
        <translation>Titik laluan %1</translation>
    </message>
    <message>
        <source>While on, each click on the tissue appends a path point there; the first sets a band the tissue reaches with the mouse, if the band is still the default (Esc stops).</source>
        <translation>Semasa hidup, setiap klik pada tisu menambah titik laluan di situ; yang pertama menetapkan jalur yang dicapai tisu dengan tetikus, jika jalur masih lalai (Esc berhenti).</translation>
    </message>
</context>
<context>
    <name>palpate::FeelChart</name>
    <message>
        <source>No feel bench yet</source>
        <translation>Belum ada penanda aras haptik</translation>
    </message>
    <message>
        <source>a slide at %1 mm depth, %2 mm/s (circles: sphere, squares: stomach); goal: step ≤ %3 % of the mean force (dashed)</source>
        <translation>gelongsor pada kedalaman %1 mm, %2 mm/s (bulatan: sfera, segi empat: perut); sasaran: lompatan ≤ %3 % daripada daya purata (putus-putus)</translation>
    </message>
    <message>
        <source>What the hand feels: force step against tick cost</source>
        <translation>Apa yang dirasai tangan: lompatan daya berbanding kos tik</translation>
    </message>
    <message>
        <source>sphere</source>
        <translation>sfera</translation>
    </message>
    <message>
        <source>stomach</source>
        <translation>perut</translation>
    </message>
    <message>
        <source>goal</source>
        <translation>sasaran</translation>
    </message>
    <message>
        <source>Tick cost (× the paper&apos;s previous method, log scale)</source>
        <translation>Kos tik (× kaedah previous kertas kerja, skala log)</translation>
    </message>
    <message>
        <source>Tick cost (µs, log scale)</source>
        <translation>Kos tik (µs, skala log)</translation>
    </message>
    <message>
        <source>Largest force step (% of the mean force, log scale)</source>
        <translation>Lompatan daya terbesar (% daripada daya purata, skala log)</translation>
    </message>
    <message>
        <source>goal: step ≤ %1 %</source>
        <translation>sasaran: lompatan ≤ %1 %</translation>
    </message>
    <message>
        <source>%1, %2 %3 vertices
largest step %4 % (normal %5 %), ripple %6 %
tick %7 µs, %8x faster than previous</source>
        <translation>%1, %2 %3 bucu
lompatan terbesar %4 % (normal %5 %), riak %6 %
tik %7 µs, %8x lebih pantas daripada previous</translation>
    </message>
    <message>
        <source>Tick cost (× previous, log)</source>
        <translation>Kos tik (× previous, log)</translation>
    </message>
    <message>
        <source>Tick cost (µs, log)</source>
        <translation>Kos tik (µs, log)</translation>
    </message>
    <message>
        <source>Largest step (% of mean force)</source>
        <translation>Lompatan terbesar (% daya purata)</translation>
    </message>
    <message>
        <source>Feel: force step against tick cost</source>
        <translation>Rasa: lompatan daya berbanding kos tik</translation>
    </message>
    <message>
        <source>slide %1 mm deep at %2 mm/s; goal: step ≤ %3 % (dashed)</source>
        <translation>gelongsor sedalam %1 mm pada %2 mm/s; sasaran: lompatan ≤ %3 % (putus-putus)</translation>
    </message>
</context>
<context>
    <name>palpate::FeelPanel</name>
    <message>
        <source>No feel bench loaded: palpate-cli bench feel --csv FILE, then Open feel CSV</source>
        <translation>Tiada penanda aras rasa dimuatkan: palpate-cli bench feel --csv FAIL, kemudian Buka CSV rasa</translation>
    </message>
    <message>
        <source>&amp;Open feel CSV…</source>
        <translation>&amp;Buka CSV rasa…</translation>
    </message>
    <message>
        <source>Show a feel bench saved as CSV (palpate-cli bench feel --csv): every model&apos;s largest force step while sliding at constant depth, against its tick cost.</source>
        <translation>Tunjukkan penanda aras rasa yang disimpan sebagai CSV (palpate-cli bench feel --csv): lompatan daya terbesar setiap model semasa menggelongsor pada kedalaman tetap, berbanding kos tiknya.</translation>
    </message>
    <message>
        <source>Tick &amp;cost:</source>
        <translation>Kos &amp;tik:</translation>
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
        <translation>Kos tik sebagai pecahan kos kaedah previous kertas kerja, diukur dalam larian yang sama pada jejaring yang sama, atau dalam mikrosaat pada mesin yang menjalankan penanda aras.</translation>
    </message>
    <message>
        <source>Loaded %1: %2 of %3 points above the goal (step ≤ %4 % of the mean force).</source>
        <translation>%1 dimuatkan: %2 daripada %3 titik di atas sasaran (lompatan ≤ %4 % daripada daya purata).</translation>
    </message>
    <message>
        <source>%1: cannot be read (%2)</source>
        <translation>%1: tidak dapat dibaca (%2)</translation>
    </message>
    <message>
        <source>%1: no rows (only the header)</source>
        <translation>%1: tiada baris (hanya pengepala)</translation>
    </message>
    <message>
        <source>Open feel CSV</source>
        <translation>Buka CSV rasa</translation>
    </message>
    <message>
        <source>Feel bench CSV (*.csv);;All files (*)</source>
        <translation>CSV penanda aras rasa (*.csv);;Semua fail (*)</translation>
    </message>
</context>
<context>
    <name>palpate::FirstRun</name>
    <message>
        <source>Cannot open the sample scene</source>
        <translation>Tidak dapat membuka adegan contoh</translation>
    </message>
    <message>
        <source>The sample mesh %1 was not found (set PALPATE_RESOURCES).</source>
        <translation>Jejaring contoh %1 tidak ditemui (tetapkan PALPATE_RESOURCES).</translation>
    </message>
    <message>
        <source>Cannot start touch mode</source>
        <translation>Tidak dapat memulakan mod sentuh</translation>
    </message>
    <message>
        <source>Touch mode: left-drag presses the tissue, the wheel sets the depth, right-drag turns the view.</source>
        <translation>Mod sentuh: seret kiri menekan tisu, roda menetapkan kedalaman, seret kanan memutar pandangan.</translation>
    </message>
    <message>
        <source>Cannot run the example exercise</source>
        <translation>Tidak dapat menjalankan latihan contoh</translation>
    </message>
    <message>
        <source>The example exercise exercises/press_targets.json was not found (set PALPATE_RESOURCES).</source>
        <translation>Latihan contoh exercises/press_targets.json tidak ditemui (tetapkan PALPATE_RESOURCES).</translation>
    </message>
    <message>
        <source>Haptic rate not applied</source>
        <translation>Kadar haptik tidak digunakan</translation>
    </message>
    <message>
        <source>User Guide</source>
        <translation>Panduan Pengguna</translation>
    </message>
    <message>
        <source>The user guide (user-guide.md) was not found. It is installed in share/doc/palpate; in a source tree it is docs/user-guide.md.</source>
        <translation>Panduan pengguna (user-guide.md) tidak ditemui. Ia dipasang dalam share/doc/palpate; dalam pepohon sumber ia ialah docs/user-guide.md.</translation>
    </message>
    <message>
        <source>Palpate User Guide</source>
        <translation>Panduan Pengguna Palpate</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>&amp;Keutamaan…</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Panduan Pengguna</translation>
    </message>
    <message>
        <source>&amp;Welcome</source>
        <translation>&amp;Selamat Datang</translation>
    </message>
</context>
<context>
    <name>palpate::ForceGauge</name>
    <message>
        <source>Force gauge</source>
        <translation>Tolok daya</translation>
    </message>
    <message>
        <source>%1 N</source>
        <translation>%1 N</translation>
    </message>
    <message>
        <source>excessive ≥ %1 N ▸</source>
        <translation>berlebihan ≥ %1 N ▸</translation>
    </message>
    <message>
        <source>Force gauge faded out: feel the force</source>
        <translation>Tolok daya dipudarkan: rasai dayanya</translation>
    </message>
    <message>
        <source>The blue line: a press at or above %1 N counts as examined.</source>
        <translation>Garis biru: tekanan pada atau melebihi %1 N dikira sebagai diperiksa.</translation>
    </message>
</context>
<context>
    <name>palpate::GuiApplication</name>
    <message>
        <source>%1 (while %2 handled an event; the window goes on)</source>
        <translation>%1 (semasa %2 mengendalikan peristiwa; tetingkap terus berjalan)</translation>
    </message>
    <message>
        <source>an unknown error (the window goes on)</source>
        <translation>ralat yang tidak diketahui (tetingkap terus berjalan)</translation>
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
        <translation>Pelatih:</translation>
    </message>
    <message>
        <source>Trainee</source>
        <translation>Pelatih</translation>
    </message>
    <message>
        <source>When</source>
        <translation>Bila</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Latihan</translation>
    </message>
    <message>
        <source>Score</source>
        <translation>Markah</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>Masa (s)</translation>
    </message>
    <message>
        <source>Report PDF…</source>
        <translation>Laporan PDF…</translation>
    </message>
    <message>
        <source>Re-scores the result&apos;s recording and writes its PDF report</source>
        <translation>Memarkah semula rakaman keputusan dan menulis laporan PDF-nya</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Main semula</translation>
    </message>
    <message>
        <source>Opens the result&apos;s recording in the Recorder</source>
        <translation>Membuka rakaman keputusan dalam Perakam</translation>
    </message>
    <message>
        <source>Scores of %1</source>
        <translation>Markah %1</translation>
    </message>
    <message>
        <source>No trainee yet</source>
        <translation>Belum ada pelatih</translation>
    </message>
    <message>
        <source>No trainees yet: add one in the Exercise dock.</source>
        <translation>Belum ada pelatih: tambah satu dalam dok Latihan.</translation>
    </message>
    <message>
        <source>No results yet.</source>
        <translation>Belum ada keputusan.</translation>
    </message>
    <message>
        <source>Session</source>
        <translation>Sesi</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Dihentikan</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>dihentikan</translation>
    </message>
    <message>
        <source>Stopped before the end: %1 points so far, not a score (not in the best or the mean)</source>
        <translation>Dihentikan sebelum tamat: %1 mata setakat ini, bukan skor (tidak dalam terbaik atau purata)</translation>
    </message>
    <message>
        <source>The time limit passed before the task was done</source>
        <translation>Had masa tamat sebelum tugasan selesai</translation>
    </message>
    <message>
        <source>%1, %2 to %3</source>
        <translation>%1, %2 hingga %3</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>%1 hingga %2</translation>
    </message>
    <message numerus="yes">
        <source>%n session(s) (%1); none scored</source>
        <translation>
            <numerusform>%n sesi (%1); tiada yang diskor</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>(%n stopped, not counted)</source>
        <translation>
            <numerusform>(%n dihentikan, tidak dikira)</numerusform>
        </translation>
    </message>
    <message>
        <source>Learning Curve…</source>
        <translation>Lengkung Pembelajaran…</translation>
    </message>
    <message>
        <source>The trainee&apos;s sessions of the selected result&apos;s exercise against the experts&apos; pass marks</source>
        <translation>Sesi pelatih bagi latihan keputusan yang dipilih berbanding markah lulus pakar</translation>
    </message>
    <message>
        <source>Learning curve</source>
        <translation>Lengkung pembelajaran</translation>
    </message>
    <message>
        <source>Select a session first.</source>
        <translation>Pilih satu sesi dahulu.</translation>
    </message>
    <message>
        <source>This session names no exercise file to draw the curve of.</source>
        <translation>Sesi ini tidak menamakan fail latihan untuk dilukis lengkungnya.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 has no scored sessions of this exercise to draw.</source>
        <translation>%1 tiada sesi bermarkah bagi latihan ini untuk dilukis.</translation>
    </message>
    <message>
        <source>%1: best %2, mean %3</source>
        <translation>%1: terbaik %2, purata %3</translation>
    </message>
    <message>
        <source>1 session (%1)</source>
        <translation>1 sesi (%1)</translation>
    </message>
    <message>
        <source>%1 sessions (%2)</source>
        <translation>%1 sesi (%2)</translation>
    </message>
    <message>
        <source>&amp;Show:</source>
        <translation>&amp;Tunjuk:</translation>
    </message>
    <message>
        <source>- proficient at session %1</source>
        <translation>- cekap sejak sesi %1</translation>
    </message>
    <message>
        <source>- not yet proficient</source>
        <translation>- belum cekap</translation>
    </message>
    <message>
        <source>- no expert standard yet: the pass marks come from experts&apos; sessions</source>
        <translation>- belum ada piawaian pakar: markah lulus datang daripada sesi pakar</translation>
    </message>
</context>
<context>
    <name>palpate::Language</name>
    <message>
        <source>en</source>
        <comment>The code of the language of this translation: de, ms. Exercise files carry their name and description under it.</comment>
        <translation>ms</translation>
    </message>
</context>
<context>
    <name>palpate::LodPanel</name>
    <message>
        <source>1 ring</source>
        <translation>1 gelang</translation>
    </message>
    <message>
        <source>%1 rings</source>
        <translation>%1 gelang</translation>
    </message>
    <message>
        <source>Targets</source>
        <translation>Sasaran</translation>
    </message>
    <message>
        <source>Levels and rings</source>
        <translation>Aras dan gelang</translation>
    </message>
    <message>
        <source>Max &amp;error:</source>
        <translation>&amp;Ralat maks.:</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>The displacement error allowed: RMS over the loaded region divided by the peak displacement, measured on the displayed (source) surface. 10 % is 0.1.</source>
        <translation>Ralat anjakan yang dibenarkan: RMS ke atas kawasan yang dibebani dibahagi dengan anjakan puncak, diukur pada permukaan (sumber) yang dipaparkan. 10 % ialah 0.1.</translation>
    </message>
    <message>
        <source>Tick &amp;budget:</source>
        <translation>&amp;Bajet tik:</translation>
    </message>
    <message>
        <source> µs</source>
        <translation> µs</translation>
    </message>
    <message>
        <source>The time one haptic tick may take on this machine, in microseconds (a 1 kHz loop has 1000 µs per tick for everything).</source>
        <translation>Masa yang boleh diambil oleh satu tik haptik pada mesin ini, dalam mikrosaat (gelung 1 kHz mempunyai 1000 µs setiap tik untuk segala-galanya).</translation>
    </message>
    <message>
        <source>&amp;Plan</source>
        <translation>&amp;Rancang</translation>
    </message>
    <message>
        <source>Make (or read from the cache next to the mesh) the coarser levels, measure every level and ring count on this machine and choose.</source>
        <translation>Bina (atau baca daripada cache di sebelah jejaring) aras yang lebih kasar, ukur setiap aras dan bilangan gelang pada mesin ini dan pilih.</translation>
    </message>
    <message>
        <source>&amp;Store targets in preset</source>
        <translation>&amp;Simpan sasaran dalam praset</translation>
    </message>
    <message>
        <source>Write these targets into the current tissue preset as its &quot;needs&quot;.</source>
        <translation>Tulis sasaran ini ke dalam praset tisu semasa sebagai &quot;needs&quot;-nya.</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>&amp;Batal</translation>
    </message>
    <message>
        <source>Stop after the candidate being measured; what was measured so far is planned.</source>
        <translation>Berhenti selepas calon yang sedang diukur; apa yang telah diukur dirancang.</translation>
    </message>
    <message>
        <source>&amp;Use chosen</source>
        <translation>&amp;Guna pilihan</translation>
    </message>
    <message>
        <source>Load the planner&apos;s choice: its level&apos;s mesh and ring count.</source>
        <translation>Muatkan pilihan perancang: jejaring arasnya dan bilangan gelang.</translation>
    </message>
    <message>
        <source>Use selected (&amp;override)</source>
        <translation>Guna yang dipilih (&amp;atasi)</translation>
    </message>
    <message>
        <source>Load the row selected in the table instead of the planner&apos;s choice.</source>
        <translation>Muatkan baris yang dipilih dalam jadual dan bukannya pilihan perancang.</translation>
    </message>
    <message>
        <source>Level</source>
        <translation>Aras</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Bucu</translation>
    </message>
    <message>
        <source>Rings</source>
        <translation>Gelang</translation>
    </message>
    <message>
        <source>Error %</source>
        <translation>Ralat %</translation>
    </message>
    <message>
        <source>Tick µs</source>
        <translation>Tik µs</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Keputusan</translation>
    </message>
    <message>
        <source>0 is the mesh itself; each further level keeps about half the vertices of the one before.</source>
        <translation>0 ialah jejaring itu sendiri; setiap aras seterusnya menyimpan kira-kira separuh bucu aras sebelumnya.</translation>
    </message>
    <message>
        <source>Vertices of the level&apos;s mesh.</source>
        <translation>Bucu jejaring aras itu.</translation>
    </message>
    <message>
        <source>Rings of neighbours the slope-ring model moves around the touched vertex.</source>
        <translation>Gelang jiran yang digerakkan oleh model gelang-cerun di sekeliling bucu yang disentuh.</translation>
    </message>
    <message>
        <source>Displacement error against the flat-punch reference on the displayed surface (RMS / peak, in %); ✓ within the max error, ✗ above it.</source>
        <translation>Ralat anjakan berbanding rujukan penebuk rata pada permukaan yang dipaparkan (RMS / puncak, dalam %); ✓ dalam ralat maks., ✗ melebihinya.</translation>
    </message>
    <message>
        <source>Median time of one haptic tick on this machine, in microseconds; ✓ within the budget, ✗ over it.</source>
        <translation>Masa median satu tik haptik pada mesin ini, dalam mikrosaat; ✓ dalam bajet, ✗ melebihinya.</translation>
    </message>
    <message>
        <source>The planner&apos;s choice, the closest when nothing fits, or your override.</source>
        <translation>Pilihan perancang, yang terdekat apabila tiada yang muat, atau pengatasan anda.</translation>
    </message>
    <message>
        <source>Max error: %1 % is absurd (at most %2 %).</source>
        <translation>Ralat maks.: %1 % tidak munasabah (paling banyak %2 %).</translation>
    </message>
    <message>
        <source>Max error: must be above 0 % (it is %1 %).</source>
        <translation>Ralat maks.: mesti melebihi 0 % (ia %1 %).</translation>
    </message>
    <message>
        <source>Tick budget: %1 µs is absurd (at most %2 µs).</source>
        <translation>Bajet tik: %1 µs tidak munasabah (paling banyak %2 µs).</translation>
    </message>
    <message>
        <source>Tick budget: must be above 0 µs (it is %1 µs).</source>
        <translation>Bajet tik: mesti melebihi 0 µs (ia %1 µs).</translation>
    </message>
    <message>
        <source>No scene yet.</source>
        <translation>Belum ada adegan.</translation>
    </message>
    <message>
        <source>Targets edited here (the scene&apos;s were %1 % and %2 µs). Store them in the preset to keep them.</source>
        <translation>Sasaran disunting di sini (sasaran adegan ialah %1 % dan %2 µs). Simpan dalam praset untuk mengekalkannya.</translation>
    </message>
    <message>
        <source>Targets edited here. Store them in the preset to keep them.</source>
        <translation>Sasaran disunting di sini. Simpan dalam praset untuk mengekalkannya.</translation>
    </message>
    <message>
        <source>Targets from the scene.</source>
        <translation>Sasaran daripada adegan.</translation>
    </message>
    <message>
        <source>Targets from %1.</source>
        <translation>Sasaran daripada %1.</translation>
    </message>
    <message>
        <source>The scene states no targets: these are the panel&apos;s defaults.</source>
        <translation>Adegan tidak menyatakan sasaran: ini ialah lalai panel.</translation>
    </message>
    <message>
        <source>No mesh file: the levels are cached next to the scene&apos;s mesh file.</source>
        <translation>Tiada fail jejaring: aras dicache di sebelah fail jejaring adegan.</translation>
    </message>
    <message>
        <source>Fix the targets first: %1</source>
        <translation>Betulkan sasaran dahulu: %1</translation>
    </message>
    <message>
        <source>Cannot measure: %1</source>
        <translation>Tidak dapat mengukur: %1</translation>
    </message>
    <message>
        <source>Loading the mesh…</source>
        <translation>Memuatkan jejaring…</translation>
    </message>
    <message>
        <source>Looking for cached levels…</source>
        <translation>Mencari aras dalam cache…</translation>
    </message>
    <message>
        <source>Generating 1 coarser level: decimating</source>
        <translation>Menjana 1 aras lebih kasar: menipiskan</translation>
    </message>
    <message>
        <source>Generating %1 coarser levels: decimating</source>
        <translation>Menjana %1 aras lebih kasar: menipiskan</translation>
    </message>
    <message>
        <source>Generating levels %1/%2: mapping to the mesh</source>
        <translation>Menjana aras %1/%2: memeta ke jejaring</translation>
    </message>
    <message>
        <source>Reading cached level %1</source>
        <translation>Membaca aras %1 dalam cache</translation>
    </message>
    <message>
        <source>Levels ready</source>
        <translation>Aras sedia</translation>
    </message>
    <message>
        <source>Measuring level %1 (%2 vertices), %3: %4 of %5</source>
        <translation>Mengukur aras %1 (%2 bucu), %3: %4 daripada %5</translation>
    </message>
    <message>
        <source>Measured %1 candidates</source>
        <translation>%1 calon diukur</translation>
    </message>
    <message>
        <source>unknown error</source>
        <translation>ralat tidak diketahui</translation>
    </message>
    <message>
        <source>Planning started…</source>
        <translation>Perancangan bermula…</translation>
    </message>
    <message>
        <source>Cancelling: the candidate being measured finishes first…</source>
        <translation>Membatalkan: calon yang sedang diukur selesai dahulu…</translation>
    </message>
    <message>
        <source>Plan failed: %1</source>
        <translation>Perancangan gagal: %1</translation>
    </message>
    <message>
        <source>Levels (%1 vertices) read from the cache %2 next to the mesh.</source>
        <translation>Aras (%1 bucu) dibaca daripada cache %2 di sebelah jejaring.</translation>
    </message>
    <message>
        <source>Levels (%1 vertices) generated: %2.</source>
        <translation>Aras (%1 bucu) dijana: %2.</translation>
    </message>
    <message>
        <source>The cache could not be written (%1): the levels other than 0 cannot be used.</source>
        <translation>Cache tidak dapat ditulis (%1): aras selain 0 tidak boleh digunakan.</translation>
    </message>
    <message>
        <source>Planned in %1 s: %2 candidates measured on this machine.</source>
        <translation>Dirancang dalam %1 s: %2 calon diukur pada mesin ini.</translation>
    </message>
    <message>
        <source>Cancelled after %1 of %2 candidates: the table is partial and the plan is made from them only.</source>
        <translation>Dibatalkan selepas %1 daripada %2 calon: jadual tidak lengkap dan rancangan dibuat daripadanya sahaja.</translation>
    </message>
    <message>
        <source>Not measured: %1</source>
        <translation>Tidak diukur: %1</translation>
    </message>
    <message>
        <source>n/a</source>
        <translation>t/b</translation>
    </message>
    <message>
        <source>chosen</source>
        <translation>dipilih</translation>
    </message>
    <message>
        <source>closest</source>
        <translation>terdekat</translation>
    </message>
    <message>
        <source>override</source>
        <translation>diatasi</translation>
    </message>
    <message>
        <source>level %1 (%2 vertices), %3: error %4 %, tick %5 µs</source>
        <translation>aras %1 (%2 bucu), %3: ralat %4 %, tik %5 µs</translation>
    </message>
    <message>
        <source>No scene mesh.</source>
        <translation>Tiada jejaring adegan.</translation>
    </message>
    <message>
        <source>Nothing measured yet: Plan measures the levels on this machine.</source>
        <translation>Belum ada apa-apa diukur: Rancang mengukur aras pada mesin ini.</translation>
    </message>
    <message>
        <source>&lt;b&gt;No plan:&lt;/b&gt; the targets are invalid.</source>
        <translation>&lt;b&gt;Tiada rancangan:&lt;/b&gt; sasaran tidak sah.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Chosen:&lt;/b&gt; %1.</source>
        <translation>&lt;b&gt;Dipilih:&lt;/b&gt; %1.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Nothing meets both targets.&lt;/b&gt; Closest: %1.</source>
        <translation>&lt;b&gt;Tiada yang memenuhi kedua-dua sasaran.&lt;/b&gt; Terdekat: %1.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Nothing meets both targets&lt;/b&gt; and no candidate could be measured.</source>
        <translation>&lt;b&gt;Tiada yang memenuhi kedua-dua sasaran&lt;/b&gt; dan tiada calon dapat diukur.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Override:&lt;/b&gt; %1.</source>
        <translation>&lt;b&gt;Diatasi:&lt;/b&gt; %1.</translation>
    </message>
    <message>
        <source>Why: %1</source>
        <translation>Sebab: %1</translation>
    </message>
    <message>
        <source>The level&apos;s mesh file %1 is missing (was the cache written or removed?); plan again.</source>
        <translation>Fail jejaring aras %1 tiada (adakah cache ditulis atau dibuang?); rancang semula.</translation>
    </message>
    <message>
        <source>Using %1 (override).</source>
        <translation>Menggunakan %1 (diatasi).</translation>
    </message>
    <message>
        <source>Using %1.</source>
        <translation>Menggunakan %1.</translation>
    </message>
    <message>
        <source>No scene mesh yet.</source>
        <translation>Belum ada jejaring adegan.</translation>
    </message>
    <message>
        <source>Ready: Plan measures the levels of %1.</source>
        <translation>Sedia: Rancang mengukur aras %1.</translation>
    </message>
    <message>
        <source>Candidates</source>
        <translation>Calon</translation>
    </message>
    <message>
        <source>The levels were not finished (cancelled); nothing was cached.</source>
        <translation>Aras tidak selesai (dibatalkan); tiada apa-apa dicache.</translation>
    </message>
    <message>
        <source>Planned in %1 s: %2 of %3 candidates could be measured on this machine.</source>
        <translation>Dirancang dalam %1 s: %2 daripada %3 calon dapat diukur pada mesin ini.</translation>
    </message>
    <message>
        <source>Cancelled while making the levels; nothing was measured.</source>
        <translation>Dibatalkan semasa membina aras; tiada apa-apa diukur.</translation>
    </message>
    <message>
        <source>Cancelled while making the levels; the table shows the previous plan.</source>
        <translation>Dibatalkan semasa membina aras; jadual menunjukkan rancangan sebelumnya.</translation>
    </message>
    <message>
        <source>Cancelled before the first candidate; nothing was measured.</source>
        <translation>Dibatalkan sebelum calon pertama; tiada apa-apa diukur.</translation>
    </message>
    <message>
        <source>Cancelled before the first candidate; the table shows the previous plan.</source>
        <translation>Dibatalkan sebelum calon pertama; jadual menunjukkan rancangan sebelumnya.</translation>
    </message>
    <message>
        <source>%1 of %2 candidates could not be measured (n/a): the row&apos;s tooltip says why.</source>
        <translation>%1 daripada %2 calon tidak dapat diukur (t/b): petua alat baris menerangkan sebabnya.</translation>
    </message>
    <message>
        <source>the plan&apos;s press</source>
        <translation>tekanan pelan</translation>
    </message>
    <message>
        <source>Pressing the hyperelastic reference for linear or stiffening tissue…</source>
        <translation>Menekan rujukan hiperelastik untuk tisu linear atau mengeras…</translation>
    </message>
    <message>
        <source>The hyperelastic reference failed: %1</source>
        <translation>Rujukan hiperelastik gagal: %1</translation>
    </message>
    <message>
        <source>Tissue: %1</source>
        <translation>Tisu: %1</translation>
    </message>
    <message>
        <source>U&amp;ndo use</source>
        <translation>Buat asal pe&amp;nggunaan</translation>
    </message>
    <message>
        <source>Back to the mesh, rings and tissue from before the first Use.</source>
        <translation>Kembali kepada jejaring, gelang dan tisu sebelum Guna yang pertama.</translation>
    </message>
</context>
<context>
    <name>palpate::MainWindow</name>
    <message>
        <source>Touch depth %1 mm</source>
        <translation>Kedalaman sentuh %1 mm</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Parameters not applied</source>
        <translation>Parameter tidak digunakan</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Peranti</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Charts</source>
        <translation>Carta</translation>
    </message>
    <message>
        <source>: not loaded</source>
        <translation>: tidak dimuatkan</translation>
    </message>
    <message>
        <source>Cannot open mesh</source>
        <translation>Tidak dapat membuka jejaring</translation>
    </message>
    <message>
        <source>About Palpate</source>
        <translation>Perihal Palpate</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Palpate %1&lt;/h3&gt;&lt;p&gt;Haptic soft-tissue deformation: the slope-ring method of Ahmad, Sulaiman and Rambli, made exact and measured.&lt;/p&gt;&lt;p&gt;Built with these libraries (Debian 12 packages):&lt;/p&gt;&lt;ul&gt;&lt;li&gt;Qt %2 (Widgets, OpenGL): LGPL-3.0&lt;/li&gt;&lt;li&gt;OpenMesh: BSD-3-Clause&lt;/li&gt;&lt;li&gt;GLM: MIT (Happy Bunny licence)&lt;/li&gt;&lt;li&gt;nlohmann/json: MIT&lt;/li&gt;&lt;li&gt;GoogleTest and Google Benchmark (tests only): BSD-3-Clause, Apache-2.0&lt;/li&gt;&lt;/ul&gt;</source>
        <translation>&lt;h3&gt;Palpate %1&lt;/h3&gt;&lt;p&gt;Ubah bentuk tisu lembut haptik: kaedah gelang-cerun Ahmad, Sulaiman dan Rambli, dijadikan tepat dan diukur.&lt;/p&gt;&lt;p&gt;Dibina dengan pustaka berikut (pakej Debian 12):&lt;/p&gt;&lt;ul&gt;&lt;li&gt;Qt %2 (Widgets, OpenGL): LGPL-3.0&lt;/li&gt;&lt;li&gt;OpenMesh: BSD-3-Clause&lt;/li&gt;&lt;li&gt;GLM: MIT (lesen Happy Bunny)&lt;/li&gt;&lt;li&gt;nlohmann/json: MIT&lt;/li&gt;&lt;li&gt;GoogleTest dan Google Benchmark (ujian sahaja): BSD-3-Clause, Apache-2.0&lt;/li&gt;&lt;/ul&gt;</translation>
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
        <translation>Kadar haptik: %1 Hz (gelung melaporkan %2 Hz)
Tik: %3
Tarikh akhir terlepas: %4
Terlebih masa: %5
Pengiraan tik: terakhir %6 µs, maks. %7 µs
Ketar: terakhir %8 µs, maks. %9 µs
Penjadualan: %10
GUI: %11 fps
Bucu teranjak: %12
Dijeda: %13</translation>
    </message>
    <message>
        <source>SCHED_FIFO</source>
        <translation>SCHED_FIFO</translation>
    </message>
    <message>
        <source>normal (SCHED_FIFO not permitted)</source>
        <translation>biasa (SCHED_FIFO tidak dibenarkan)</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ya</translation>
    </message>
    <message>
        <source>no</source>
        <translation>tidak</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Fail</translation>
    </message>
    <message>
        <source>&amp;Open Mesh…</source>
        <translation>&amp;Buka Jejaring…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Buka &amp;Terkini</translation>
    </message>
    <message>
        <source>Open Recor&amp;ding…</source>
        <translation>Buka Ra&amp;kaman…</translation>
    </message>
    <message>
        <source>Play a session recording back (the live session pauses meanwhile)</source>
        <translation>Main semula rakaman sesi (sesi langsung dijeda sementara itu)</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Keluar</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Sunting</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Buat Asal</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>Buat &amp;Semula</translation>
    </message>
    <message>
        <source>&amp;Apply Parameters</source>
        <translation>&amp;Guna Parameter</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Lihat</translation>
    </message>
    <message>
        <source>&amp;Reset Camera</source>
        <translation>&amp;Set Semula Kamera</translation>
    </message>
    <message>
        <source>&amp;Fit</source>
        <translation>&amp;Muat</translation>
    </message>
    <message>
        <source>&amp;Wireframe</source>
        <translation>&amp;Bingkai Dawai</translation>
    </message>
    <message>
        <source>Rest Shape &amp;Ghost</source>
        <translation>&amp;Bayang Bentuk Rehat</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>S&amp;imulasi</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Jeda</translation>
    </message>
    <message>
        <source>&amp;Restart</source>
        <translation>&amp;Mula Semula</translation>
    </message>
    <message>
        <source>Cannot restart</source>
        <translation>Tidak dapat memulakan semula</translation>
    </message>
    <message>
        <source>&amp;Touch Mode</source>
        <translation>Mod &amp;Sentuh</translation>
    </message>
    <message>
        <source>The mouse steers the tool: left-drag presses the tissue, the wheel sets the depth; right-drag orbits, middle-drag pans, Shift+wheel zooms</source>
        <translation>Tetikus mengemudi alat: seret kiri menekan tisu, roda menetapkan kedalaman; seret kanan memutar, seret tengah menganjak, Shift+roda mengezum</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Bantuan</translation>
    </message>
    <message>
        <source>&amp;About Palpate</source>
        <translation>Perihal P&amp;alpate</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Perihal &amp;Qt</translation>
    </message>
    <message>
        <source>Haptic ticks per second achieved by the loop thread</source>
        <translation>Tik haptik sesaat yang dicapai oleh bebenang gelung</translation>
    </message>
    <message>
        <source>Time spent in a haptic tick: the last one / the longest</source>
        <translation>Masa yang digunakan dalam satu tik haptik: yang terakhir / yang paling lama</translation>
    </message>
    <message>
        <source>Lateness of the haptic thread&apos;s wake-up after its deadline: the last / the worst</source>
        <translation>Kelewatan bebenang haptik bangun selepas tarikh akhirnya: yang terakhir / yang paling teruk</translation>
    </message>
    <message>
        <source>Ticks that finished after the next deadline (and the deadlines skipped)</source>
        <translation>Tik yang selesai selepas tarikh akhir seterusnya (dan tarikh akhir yang dilangkau)</translation>
    </message>
    <message>
        <source>Whether the haptic thread runs with SCHED_FIFO priority</source>
        <translation>Sama ada bebenang haptik berjalan dengan keutamaan SCHED_FIFO</translation>
    </message>
    <message>
        <source>Frames the viewport painted per second</source>
        <translation>Bingkai sesaat yang dilukis oleh port pandangan</translation>
    </message>
    <message>
        <source>The device URI and its state</source>
        <translation>URI peranti dan keadaannya</translation>
    </message>
    <message>
        <source>The tool is pressing the tissue</source>
        <translation>Alat sedang menekan tisu</translation>
    </message>
    <message>
        <source>Force sent to the device (after the safety filter)</source>
        <translation>Daya yang dihantar ke peranti (selepas penapis keselamatan)</translation>
    </message>
    <message>
        <source>The session is being recorded, or a recording is played back</source>
        <translation>Sesi sedang dirakam, atau rakaman sedang dimainkan semula</translation>
    </message>
    <message>
        <source>No mesh, %1</source>
        <translation>Tiada jejaring, %1</translation>
    </message>
    <message>
        <source>The tissue model diverged (%1) at tick %2: the force was zeroed and the tissue reset. %3</source>
        <translation>Model tisu mencapah (%1) pada tik %2: daya disifarkan dan tisu ditetapkan semula. %3</translation>
    </message>
    <message>
        <source>haptic -</source>
        <translation>haptik -</translation>
    </message>
    <message>
        <source>haptic stepped (%1 Hz virtual)</source>
        <translation>haptik berlangkah (%1 Hz maya)</translation>
    </message>
    <message>
        <source>haptic %1 Hz</source>
        <translation>haptik %1 Hz</translation>
    </message>
    <message>
        <source>tick %1/%2 µs</source>
        <translation>tik %1/%2 µs</translation>
    </message>
    <message>
        <source>jitter %1/%2 µs</source>
        <translation>ketar %1/%2 µs</translation>
    </message>
    <message>
        <source>overruns %1 (missed %2)</source>
        <translation>terlebih masa %1 (terlepas %2)</translation>
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
        <translation>belum bermula</translation>
    </message>
    <message>
        <source>contact: %1</source>
        <translation>sentuhan: %1</translation>
    </message>
    <message>
        <source>Palpate - playing %1</source>
        <translation>Palpate - memainkan %1</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Latihan</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Sejarah</translation>
    </message>
    <message>
        <source>Exercise Editor</source>
        <translation>Editor Latihan</translation>
    </message>
    <message>
        <source>An exercise is running: the mesh cannot change now.</source>
        <translation>Latihan sedang berjalan: jejaring tidak boleh diubah sekarang.</translation>
    </message>
    <message>
        <source>Cannot try the exercise</source>
        <translation>Tidak dapat mencuba latihan</translation>
    </message>
    <message>
        <source>E&amp;xercise</source>
        <translation>La&amp;tihan</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>&amp;Mula</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>&amp;Henti</translation>
    </message>
    <message>
        <source>&amp;Open Exercise…</source>
        <translation>&amp;Buka Latihan…</translation>
    </message>
    <message>
        <source>&amp;New Trainee…</source>
        <translation>Pelatih Bah&amp;aru…</translation>
    </message>
    <message>
        <source>&amp;Export Score Report (PDF)…</source>
        <translation>&amp;Eksport Laporan Markah (PDF)…</translation>
    </message>
    <message>
        <source>&amp;History</source>
        <translation>&amp;Sejarah</translation>
    </message>
    <message>
        <source>&amp;Author</source>
        <translation>&amp;Karang</translation>
    </message>
    <message>
        <source>&amp;Instructor Mode</source>
        <translation>Mod &amp;Jurulatih</translation>
    </message>
    <message>
        <source>&amp;Trainee Mode</source>
        <translation>Mod &amp;Pelatih</translation>
    </message>
    <message>
        <source>New Trainee</source>
        <translation>Pelatih Baharu</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Nama:</translation>
    </message>
    <message>
        <source>Trainee not added</source>
        <translation>Pelatih tidak ditambah</translation>
    </message>
    <message>
        <source>Open Exercise</source>
        <translation>Buka Latihan</translation>
    </message>
    <message>
        <source>Not an exercise</source>
        <translation>Bukan latihan</translation>
    </message>
    <message>
        <source>There is no score to export yet: run an exercise first.</source>
        <translation>Belum ada markah untuk dieksport: jalankan latihan dahulu.</translation>
    </message>
    <message>
        <source>Export Score Report</source>
        <translation>Eksport Laporan Markah</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Report not written</source>
        <translation>Laporan tidak ditulis</translation>
    </message>
    <message>
        <source>Report written: %1</source>
        <translation>Laporan ditulis: %1</translation>
    </message>
    <message>
        <source>Level of Detail</source>
        <translation>Aras Perincian</translation>
    </message>
    <message>
        <source>An exercise is running: the model cannot change now.</source>
        <translation>Latihan sedang berjalan: model tidak boleh diubah sekarang.</translation>
    </message>
    <message>
        <source>Cannot use this level</source>
        <translation>Tidak dapat menggunakan aras ini</translation>
    </message>
    <message>
        <source>Using your choice: %1, %2 rings (overrides the plan)</source>
        <translation>Menggunakan pilihan anda: %1, %2 gelang (mengatasi rancangan)</translation>
    </message>
    <message>
        <source>Using the plan&apos;s choice: %1, %2 rings</source>
        <translation>Menggunakan pilihan rancangan: %1, %2 gelang</translation>
    </message>
    <message>
        <source>Targets stored in the preset: save it (File &gt; Save Preset) to keep them</source>
        <translation>Sasaran disimpan dalam praset: simpan praset itu (Fail &gt; Simpan Praset) untuk mengekalkannya</translation>
    </message>
    <message>
        <source>the tissue preset</source>
        <translation>praset tisu</translation>
    </message>
    <message>
        <source>exercise &apos;%1&apos;</source>
        <translation>latihan &apos;%1&apos;</translation>
    </message>
    <message>
        <source>force %1</source>
        <translation>daya %1</translation>
    </message>
    <message>
        <source>Click the tissue to place; drag orbits; Esc stops placing</source>
        <translation>Klik tisu untuk meletakkan; seret memutar; Esc menghentikan peletakan</translation>
    </message>
    <message>
        <source>Pause the simulation (ticked: paused; the tissue relaxes and the force is zero)</source>
        <translation>Jeda simulasi (bertanda: dijeda; tisu kembali kendur dan daya menjadi sifar)</translation>
    </message>
    <message>
        <source>force %1 (clipped at device max)</source>
        <translation>daya %1 (dihadkan pada maksimum peranti)</translation>
    </message>
    <message>
        <source>Cannot open the device %1: %2
Running with %3 instead: choose another in the Device dock or in Edit &gt; Preferences.</source>
        <translation>Peranti %1 tidak dapat dibuka: %2
Menggunakan %3 sebagai ganti: pilih yang lain dalam dok Peranti atau dalam Sunting &gt; Keutamaan.</translation>
    </message>
    <message>
        <source>Cannot open %1; running with %2</source>
        <translation>%1 tidak dapat dibuka; menggunakan %2</translation>
    </message>
    <message>
        <source>Device not opened</source>
        <translation>Peranti tidak dibuka</translation>
    </message>
    <message>
        <source>&amp;Import Mesh…</source>
        <translation>&amp;Import Jejaring…</translation>
    </message>
    <message>
        <source>Open a mesh from another tool: its unit, repair, remeshing, previewed</source>
        <translation>Buka jaringan daripada alat lain: unitnya, pembaikan, jaringan semula, dengan pratonton</translation>
    </message>
    <message>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <source>%1 · file in %2</source>
        <translation>%1 · fail dalam %2</translation>
    </message>
    <message>
        <source>%1 · %2 vertices · %3</source>
        <translation>%1 · %2 bucu · %3</translation>
    </message>
    <message>
        <source>%1
%2
%3 vertices, %4 triangles
%5 renderer</source>
        <translation>%1
%2
%3 bucu, %4 segi tiga
pemapar %5</translation>
    </message>
    <message>
        <source>&amp;Coverage Heat Map</source>
        <translation>Peta Haba &amp;Liputan</translation>
    </message>
    <message>
        <source>Show, after a palpation exercise, where the surface was examined and how firmly</source>
        <translation>Tunjukkan, selepas latihan palpasi, di mana permukaan diperiksa dan sekuat mana</translation>
    </message>
    <message>
        <source>&amp;Finish Examination</source>
        <translation>&amp;Tamatkan Pemeriksaan</translation>
    </message>
    <message>
        <source>Finish ends a running detect-lumps examination</source>
        <translation>Tamat menamatkan pemeriksaan kesan ketulan yang sedang berjalan</translation>
    </message>
    <message>
        <source>, %1 stiffening knots</source>
        <translation>, %1 simpulan pengerasan</translation>
    </message>
    <message>
        <source>, linear tissue</source>
        <translation>, tisu linear</translation>
    </message>
    <message>
        <source>Results kept on this workstation and copied to the class&apos;s server (Preferences)</source>
        <translation>Keputusan disimpan di stesen kerja ini dan disalin ke pelayan kelas (Keutamaan)</translation>
    </message>
    <message>
        <source>The last copy to %1 stopped: %2</source>
        <translation>Salinan terakhir ke %1 terhenti: %2</translation>
    </message>
    <message>
        <source>&amp;Class View…</source>
        <translation>Paparan &amp;Kelas…</translation>
    </message>
    <message>
        <source>, linear tissue (the knots do not fit this preset: %1)</source>
        <translation>, tisu linear (simpulan tidak sesuai dengan praset ini: %1)</translation>
    </message>
    <message>
        <source>Results kept on this workstation and copied to %1 (%2)</source>
        <translation>Keputusan disimpan di stesen kerja ini dan disalin ke %1 (%2)</translation>
    </message>
    <message>
        <source>Exercises and bundles (*.json *.palpex)</source>
        <translation>Latihan dan berkas (*.json *.palpex)</translation>
    </message>
    <message>
        <source>Stiffening knots applied to the tissue (undo them in Parameters, then Apply)</source>
        <translation>Simpulan pengerasan digunakan pada tisu (buat asal dalam Parameter, kemudian Guna)</translation>
    </message>
    <message>
        <source>Another mesh: the level of detail&apos;s %1 rings stay with its scene; %2 rings again</source>
        <translation>Jejaring lain: %1 gelang tahap perincian kekal dengan adegannya; %2 gelang semula</translation>
    </message>
    <message>
        <source>mesh %1 (%2 vertices) instead of %3 (%4)</source>
        <translation>jejaring %1 (%2 bucu) menggantikan %3 (%4)</translation>
    </message>
    <message>
        <source>%1 rings instead of %2</source>
        <translation>%1 gelang menggantikan %2</translation>
    </message>
    <message>
        <source>%1 stiffening knots instead of %2</source>
        <translation>%1 simpulan pengerasan menggantikan %2</translation>
    </message>
    <message>
        <source>Nothing changed: the scene already ran this.</source>
        <translation>Tiada perubahan: adegan sudah menjalankan ini.</translation>
    </message>
    <message>
        <source>Changed: %1. Undo use goes back; opening another mesh drops these rings and knots.</source>
        <translation>Diubah: %1. Buat asal penggunaan kembali; membuka jejaring lain menggugurkan gelang dan simpulan ini.</translation>
    </message>
    <message>
        <source>Cannot undo the use</source>
        <translation>Penggunaan tidak dapat dibuat asal</translation>
    </message>
    <message>
        <source>Back to %1 with %2 rings, as before the level of detail was used</source>
        <translation>Kembali kepada %1 dengan %2 gelang, seperti sebelum tahap perincian digunakan</translation>
    </message>
    <message>
        <source>a folder</source>
        <translation>sebuah folder</translation>
    </message>
    <message>
        <source>a FIFO</source>
        <translation>sebuah FIFO</translation>
    </message>
    <message>
        <source>a device</source>
        <translation>sebuah peranti</translation>
    </message>
    <message>
        <source>a socket</source>
        <translation>sebuah soket</translation>
    </message>
    <message>
        <source>not a regular file</source>
        <translation>bukan fail biasa</translation>
    </message>
    <message>
        <source>a link to nothing</source>
        <translation>pautan kepada tiada apa-apa</translation>
    </message>
    <message>
        <source>a link to %1</source>
        <translation>pautan kepada %1</translation>
    </message>
    <message>
        <source>%1 is %2, not a regular file: the preferences are neither read from it nor saved over it; this run keeps them until it ends. Move it away to keep preferences again.</source>
        <translation>%1 ialah %2, bukan fail biasa: tetapan tidak dibaca daripadanya dan tidak disimpan menimpanya; larian ini menyimpannya sehingga ia tamat. Alihkannya untuk menyimpan tetapan semula.</translation>
    </message>
</context>
<context>
    <name>palpate::MeshImportDialog</name>
    <message>
        <source>Import Mesh</source>
        <translation>Import Jaringan</translation>
    </message>
    <message>
        <source>Choose a mesh file to preview.</source>
        <translation>Pilih fail jaringan untuk pratonton.</translation>
    </message>
    <message>
        <source>A mesh from another tool (OBJ, OFF, PLY, STL, OM)</source>
        <translation>Jaringan daripada alat lain (OBJ, OFF, PLY, STL, OM)</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Semak imbas…</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>Fail:</translation>
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
        <translation>Skala…</translation>
    </message>
    <message>
        <source> mm per file unit</source>
        <translation> mm setiap unit fail</translation>
    </message>
    <message>
        <source>Unit of the file:</source>
        <translation>Unit fail:</translation>
    </message>
    <message>
        <source>Repair faults</source>
        <translation>Baiki kerosakan</translation>
    </message>
    <message>
        <source>Orient the faces consistently, split non-manifold edges and vertices, remove degenerate triangles and duplicate vertices (CGAL). Without it a mesh with faults is refused.</source>
        <translation>Arahkan muka secara konsisten, pisahkan tepi dan bucu bukan-manifold, buang segi tiga merosot dan bucu berganda (CGAL). Tanpanya jaringan yang rosak ditolak.</translation>
    </message>
    <message>
        <source>Keep the largest piece</source>
        <translation>Simpan kepingan terbesar</translation>
    </message>
    <message>
        <source>Keep all pieces</source>
        <translation>Simpan semua kepingan</translation>
    </message>
    <message>
        <source>Fill holes</source>
        <translation>Isi lubang</translation>
    </message>
    <message>
        <source>Repair:</source>
        <translation>Pembaikan:</translation>
    </message>
    <message>
        <source>Remesh to even triangles, edge</source>
        <translation>Jaring semula kepada segi tiga sekata, tepi</translation>
    </message>
    <message>
        <source>Isotropic remeshing: even triangles make the slope model&apos;s rings round</source>
        <translation>Jaringan semula isotropik: segi tiga sekata menjadikan gelang model cerun bulat</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Remesh:</source>
        <translation>Jaring semula:</translation>
    </message>
    <message>
        <source>Cancel Preview</source>
        <translation>Batalkan Pratonton</translation>
    </message>
    <message>
        <source>Preview</source>
        <translation>Pratonton</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>Sebelum</translation>
    </message>
    <message>
        <source>After</source>
        <translation>Selepas</translation>
    </message>
    <message>
        <source>Ring roundness: the spread of the distances to ring k&apos;s vertices (coefficient of variation; 0 is a circle, a regular mesh gives about 0.1 at ring 2), and the spread of the edge lengths</source>
        <translation>Kebulatan gelang: sebaran jarak ke bucu gelang k (pekali variasi; 0 ialah bulatan, jaringan sekata memberi kira-kira 0.1 pada gelang 2), dan sebaran panjang tepi</translation>
    </message>
    <message>
        <source>Ring roundness (CV)</source>
        <translation>Kebulatan gelang (CV)</translation>
    </message>
    <message>
        <source>Import…</source>
        <translation>Import…</translation>
    </message>
    <message>
        <source>Write the previewed mesh (in mm) to a new file and open it</source>
        <translation>Tulis jaringan pratonton (dalam mm) ke fail baharu dan bukanya</translation>
    </message>
    <message>
        <source>Meshes (*.obj *.off *.ply *.stl *.om);;All files (*)</source>
        <translation>Jaringan (*.obj *.off *.ply *.stl *.om);;Semua fail (*)</translation>
    </message>
    <message>
        <source>Import Mesh As</source>
        <translation>Import Jaringan Sebagai</translation>
    </message>
    <message>
        <source>Meshes (*.off *.obj *.ply *.stl *.om)</source>
        <translation>Jaringan (*.off *.obj *.ply *.stl *.om)</translation>
    </message>
    <message>
        <source>Cannot import</source>
        <translation>Tidak dapat mengimport</translation>
    </message>
    <message>
        <source>Choose a file for the imported mesh.</source>
        <translation>Pilih fail untuk jaringan yang diimport.</translation>
    </message>
    <message>
        <source>The preview is not finished yet: wait for it, then import.</source>
        <translation>Pratonton belum selesai: tunggu, kemudian import.</translation>
    </message>
    <message>
        <source>nothing previewed</source>
        <translation>tiada pratonton</translation>
    </message>
    <message>
        <source>There is no mesh to import: %1</source>
        <translation>Tiada jaringan untuk diimport: %1</translation>
    </message>
    <message>
        <source>%1: is the mesh being imported; choose another file for the result</source>
        <translation>%1: ialah jaringan yang sedang diimport; pilih fail lain untuk hasilnya</translation>
    </message>
    <message>
        <source>reading</source>
        <translation>membaca</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>dibatalkan</translation>
    </message>
    <message>
        <source>done</source>
        <translation>selesai</translation>
    </message>
    <message>
        <source>%1 · file in %2</source>
        <translation>%1 · fail dalam %2</translation>
    </message>
    <message>
        <source>Not read</source>
        <translation>Tidak dibaca</translation>
    </message>
    <message>
        <source>Suggested %1: %2</source>
        <translation>Dicadangkan %1: %2</translation>
    </message>
    <message>
        <source>Try %1: %2</source>
        <translation>Cuba %1: %2</translation>
    </message>
    <message>
        <source>Source: %1 vertices, %2 polygons</source>
        <translation>Sumber: %1 bucu, %2 poligon</translation>
    </message>
    <message>
        <source> · result: %1 vertices, %2 triangles</source>
        <translation> · hasil: %1 bucu, %2 segi tiga</translation>
    </message>
    <message>
        <source>Errors</source>
        <translation>Ralat</translation>
    </message>
    <message>
        <source>Problems found</source>
        <translation>Masalah ditemui</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>Amaran</translation>
    </message>
    <message>
        <source>Changes made</source>
        <translation>Perubahan dibuat</translation>
    </message>
    <message>
        <source>Tolerated while reading</source>
        <translation>Diterima semasa membaca</translation>
    </message>
    <message>
        <source>&lt;p&gt;No problems found.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Tiada masalah ditemui.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Ring %1</source>
        <translation>Gelang %1</translation>
    </message>
    <message>
        <source>Edge length</source>
        <translation>Panjang tepi</translation>
    </message>
    <message>
        <source>waiting</source>
        <translation>menunggu</translation>
    </message>
    <message>
        <source>cancelling…</source>
        <translation>membatalkan…</translation>
    </message>
</context>
<context>
    <name>palpate::MeshOpener</name>
    <message>
        <source>Which unit is this mesh in?</source>
        <translation>Dalam unit apakah jaringan ini?</translation>
    </message>
    <message>
        <source>%1 is %2 if its coordinates are millimetres.</source>
        <translation>%1 bersaiz %2 jika koordinatnya dalam milimeter.</translation>
    </message>
    <message>
        <source>Open in %1</source>
        <translation>Buka dalam %1</translation>
    </message>
    <message>
        <source>Open as mm</source>
        <translation>Buka sebagai mm</translation>
    </message>
    <message>
        <source>Import…</source>
        <translation>Import…</translation>
    </message>
    <message>
        <source>Cannot open mesh</source>
        <translation>Tidak dapat membuka jejaring</translation>
    </message>
    <message>
        <source>Import Mesh can repair the faults and scale the file to mm.</source>
        <translation>Import Jaringan boleh membaiki kerosakan dan menskalakan fail kepada mm.</translation>
    </message>
    <message>
        <source>An exercise is running: the mesh cannot change now.</source>
        <translation>Latihan sedang berjalan: jejaring tidak boleh diubah sekarang.</translation>
    </message>
    <message>
        <source>Open Mesh</source>
        <translation>Buka Jejaring</translation>
    </message>
    <message>
        <source>Meshes (*.obj *.off *.ply *.stl *.om);;All files (*)</source>
        <translation>Jejaring (*.obj *.off *.ply *.stl *.om);;Semua fail (*)</translation>
    </message>
</context>
<context>
    <name>palpate::MetricText</name>
    <message>
        <source>Work done %1 %: the lines that count mistakes earn that share of their points.</source>
        <translation>Kerja yang dibuat %1 %: baris yang mengira kesilapan mendapat bahagian itu daripada markahnya.</translation>
    </message>
</context>
<context>
    <name>palpate::Metrics</name>
    <message>
        <source>completion</source>
        <translation>penyiapan</translation>
    </message>
    <message>
        <source>share of the task done: targets achieved, lump marked, path covered, examination finished (else the surface examined)</source>
        <translation>bahagian tugas yang selesai: sasaran dicapai, ketulan ditanda, laluan diliputi, pemeriksaan selesai (jika tidak, permukaan yang diperiksa)</translation>
    </message>
    <message>
        <source>time</source>
        <translation>masa</translation>
    </message>
    <message>
        <source>exercise time until the task was complete (all of it if it was not)</source>
        <translation>masa latihan sehingga tugas selesai (keseluruhannya jika tidak selesai)</translation>
    </message>
    <message>
        <source>target error</source>
        <translation>ralat sasaran</translation>
    </message>
    <message>
        <source>mean distance from the target while pressing inside its force window</source>
        <translation>jarak purata dari sasaran semasa menekan dalam tetingkap daya sasaran itu</translation>
    </message>
    <message>
        <source>hold in window fraction</source>
        <translation>pecahan tahanan dalam tetingkap</translation>
    </message>
    <message>
        <source>time inside the force window / time on a target in contact</source>
        <translation>masa dalam tetingkap daya / masa bersentuhan pada sasaran</translation>
    </message>
    <message>
        <source>peak force</source>
        <translation>daya puncak</translation>
    </message>
    <message>
        <source>largest force rendered</source>
        <translation>daya terbesar yang dihasilkan</translation>
    </message>
    <message>
        <source>mean force</source>
        <translation>daya purata</translation>
    </message>
    <message>
        <source>mean force magnitude while in contact</source>
        <translation>magnitud daya purata semasa bersentuhan</translation>
    </message>
    <message>
        <source>impulse</source>
        <translation>impuls</translation>
    </message>
    <message>
        <source>integral of the force magnitude over time</source>
        <translation>kamiran magnitud daya terhadap masa</translation>
    </message>
    <message>
        <source>excessive force events</source>
        <translation>peristiwa daya berlebihan</translation>
    </message>
    <message>
        <source>times the force rose above the excessive force</source>
        <translation>bilangan kali daya naik melebihi daya berlebihan</translation>
    </message>
    <message>
        <source>excessive force fraction</source>
        <translation>pecahan daya berlebihan</translation>
    </message>
    <message>
        <source>time above the excessive force / time in contact</source>
        <translation>masa melebihi daya berlebihan / masa bersentuhan</translation>
    </message>
    <message>
        <source>damage time</source>
        <translation>masa kerosakan</translation>
    </message>
    <message>
        <source>time with tissue displaced beyond the displacement limit</source>
        <translation>masa tisu teranjak melebihi had anjakan</translation>
    </message>
    <message>
        <source>damage area</source>
        <translation>luas kerosakan</translation>
    </message>
    <message>
        <source>largest surface area displaced beyond the limit at one time</source>
        <translation>luas permukaan terbesar yang teranjak melebihi had pada satu masa</translation>
    </message>
    <message>
        <source>max displacement</source>
        <translation>anjakan maksimum</translation>
    </message>
    <message>
        <source>largest displacement of any vertex from rest</source>
        <translation>anjakan terbesar mana-mana bucu dari kedudukan rehat</translation>
    </message>
    <message>
        <source>path length</source>
        <translation>panjang laluan</translation>
    </message>
    <message>
        <source>distance travelled by the tool tip</source>
        <translation>jarak yang dilalui oleh hujung alat</translation>
    </message>
    <message>
        <source>economy</source>
        <translation>ekonomi</translation>
    </message>
    <message>
        <source>ideal path length / path length (1 = no wasted motion)</source>
        <translation>panjang laluan ideal / panjang laluan (1 = tiada gerakan sia-sia)</translation>
    </message>
    <message>
        <source>lump error</source>
        <translation>ralat ketulan</translation>
    </message>
    <message>
        <source>distance from the contact point at the mark to the inclusion centre</source>
        <translation>jarak dari titik sentuhan semasa tanda ke pusat kemasukan</translation>
    </message>
    <message>
        <source>contact fraction</source>
        <translation>pecahan sentuhan</translation>
    </message>
    <message>
        <source>time in contact / tracing time</source>
        <translation>masa bersentuhan / masa menjejak</translation>
    </message>
    <message>
        <source>band fraction</source>
        <translation>pecahan dalam jalur</translation>
    </message>
    <message>
        <source>time in contact with the force in the band / tracing time</source>
        <translation>masa bersentuhan dengan daya dalam jalur / masa menjejak</translation>
    </message>
    <message>
        <source>path distance</source>
        <translation>jarak dari laluan</translation>
    </message>
    <message>
        <source>mean distance of the contact point from the path while in contact</source>
        <translation>jarak purata titik sentuhan dari laluan semasa bersentuhan</translation>
    </message>
    <message>
        <source>sensitivity</source>
        <translation>kepekaan</translation>
    </message>
    <message>
        <source>lumps found / lumps hidden</source>
        <translation>ketulan dijumpai / ketulan tersembunyi</translation>
    </message>
    <message>
        <source>positive predictive value</source>
        <translation>nilai ramalan positif</translation>
    </message>
    <message>
        <source>findings on a lump / findings</source>
        <translation>penemuan pada ketulan / penemuan</translation>
    </message>
    <message>
        <source>false alarms</source>
        <translation>penggera palsu</translation>
    </message>
    <message>
        <source>findings matched to no lump</source>
        <translation>penemuan yang tidak dipadankan dengan mana-mana ketulan</translation>
    </message>
    <message>
        <source>localisation</source>
        <translation>penyetempatan</translation>
    </message>
    <message>
        <source>mean distance from a found lump&apos;s centre to the finding on it</source>
        <translation>jarak purata dari pusat ketulan yang dijumpai ke penemuan padanya</translation>
    </message>
    <message>
        <source>coverage fraction</source>
        <translation>pecahan liputan</translation>
    </message>
    <message>
        <source>surface area examined with at least the coverage force / surface area</source>
        <translation>luas permukaan yang diperiksa dengan sekurang-kurangnya daya liputan / luas permukaan</translation>
    </message>
    <message>
        <source>events</source>
        <translation>peristiwa</translation>
    </message>
    <message>
        <source>findings</source>
        <translation>penemuan</translation>
    </message>
</context>
<context>
    <name>palpate::Models</name>
    <message>
        <source>Mass-spring, symplectic Euler</source>
        <translation>Jisim-spring, Euler simplektik</translation>
    </message>
    <message>
        <source>Masses on the vertices, edge and anchor springs, penalty contact; explicit symplectic Euler with automatic sub-steps. Cost: every vertex per sub-step, O(n).</source>
        <translation>Jisim pada bucu, spring tepi dan sauh, sentuhan penalti; Euler simplektik eksplisit dengan sub-langkah automatik. Kos: setiap bucu bagi setiap sub-langkah, O(n).</translation>
    </message>
    <message>
        <source>Mass-spring, RK4</source>
        <translation>Jisim-spring, RK4</translation>
    </message>
    <message>
        <source>The mass-spring model with classic Runge-Kutta 4 (four stages per sub-step). Cost: every vertex, four times per sub-step, O(n): over 1 ms from a few thousand vertices.</source>
        <translation>Model jisim-spring dengan Runge-Kutta 4 klasik (empat peringkat bagi setiap sub-langkah). Kos: setiap bucu, empat kali bagi setiap sub-langkah, O(n): melebihi 1 ms mulai beberapa ribu bucu.</translation>
    </message>
    <message>
        <source>Mass-spring, backward Euler</source>
        <translation>Jisim-spring, Euler ke belakang</translation>
    </message>
    <message>
        <source>The mass-spring model with the implicit backward Euler step (conjugate gradients): unconditionally stable, dissipative. Cost: every vertex per CG iteration, O(n).</source>
        <translation>Model jisim-spring dengan langkah Euler ke belakang yang tersirat (kecerunan konjugat): stabil tanpa syarat, melesapkan. Kos: setiap bucu bagi setiap lelaran CG, O(n).</translation>
    </message>
    <message>
        <source>Mass-spring, local rings</source>
        <translation>Jisim-spring, gelang setempat</translation>
    </message>
    <message>
        <source>The mass-spring model on the touched vertex&apos;s rings only (and what still moves); the rest is pinned at rest. Cost: the rings, about the same at every mesh size.</source>
        <translation>Model jisim-spring pada gelang bucu yang disentuh sahaja (dan apa yang masih bergerak); selebihnya dipaku pada rehat. Kos: gelang itu, lebih kurang sama pada setiap saiz jejaring.</translation>
    </message>
    <message>
        <source>Radius of influence (Basdogan)</source>
        <translation>Jejari pengaruh (Basdogan)</translation>
    </message>
    <message>
        <source>Geometric: every vertex within a radius follows the tool by a polynomial profile of its distance; force k_s × depth. Cost: the vertices within the radius.</source>
        <translation>Geometri: setiap bucu dalam satu jejari mengikut alat mengikut profil polinomial jaraknya; daya k_s × kedalaman. Kos: bucu dalam jejari itu.</translation>
    </message>
    <message>
        <source>Free-form deformation (FFD)</source>
        <translation>Ubah bentuk bentuk bebas (FFD)</translation>
    </message>
    <message>
        <source>Geometric: the mesh embedded in a Bernstein lattice whose control points near the contact move; force k_s × depth. Cost: every vertex per tick, O(n).</source>
        <translation>Geometri: jejaring dibenamkan dalam kekisi Bernstein yang titik kawalannya berhampiran sentuhan bergerak; daya k_s × kedalaman. Kos: setiap bucu bagi setiap tik, O(n).</translation>
    </message>
    <message>
        <source>Volumetric slope-rings</source>
        <translation>Gelang-cerun volumetrik</translation>
    </message>
    <message>
        <source>The slope-ring update on rings of a tetrahedral fill of the surface (the paper&apos;s future work); uses the slopes and springs below. Cost: the rings of the tet graph.</source>
        <translation>Kemas kini gelang-cerun pada gelang isian tetrahedron permukaan (kerja masa depan kertas kerja); menggunakan cerun dan spring di bawah. Kos: gelang graf tet.</translation>
    </message>
    <message>
        <source>Coherent rings (ours)</source>
        <translation>Gelang koheren (kami)</translation>
    </message>
    <message>
        <source>Ours: exact warm-started nearest-vertex search, only the rings processed, incremental work per tick. Cost: the rings of the touched vertex.</source>
        <translation>Kami: carian bucu terdekat yang tepat dan bermula panas, hanya gelang diproses, kerja berperingkat setiap tik. Kos: gelang bucu yang disentuh.</translation>
    </message>
    <message>
        <source>Proposed (paper)</source>
        <translation>Dicadangkan (kertas kerja)</translation>
    </message>
    <message>
        <source>The paper&apos;s method: its octree searchNode (faithful, can miss the nearest vertex) and only the rings. Cost: the rings of the touched vertex.</source>
        <translation>Kaedah kertas kerja: searchNode octree-nya (setia, boleh terlepas bucu terdekat) dan hanya gelang. Kos: gelang bucu yang disentuh.</translation>
    </message>
    <message>
        <source>Hybrid (paper)</source>
        <translation>Hibrid (kertas kerja)</translation>
    </message>
    <message>
        <source>The paper&apos;s hybrid: its octree searchNode, and the whole model processed every tick. Cost: every vertex per tick, O(n).</source>
        <translation>Hibrid kertas kerja: searchNode octree-nya, dan seluruh model diproses setiap tik. Kos: setiap bucu bagi setiap tik, O(n).</translation>
    </message>
    <message>
        <source>Previous (paper)</source>
        <translation>Terdahulu (kertas kerja)</translation>
    </message>
    <message>
        <source>The paper&apos;s baseline: linear nearest-vertex search, and the whole model processed every tick. Cost: every vertex per tick, O(n).</source>
        <translation>Garis dasar kertas kerja: carian bucu terdekat secara linear, dan seluruh model diproses setiap tik. Kos: setiap bucu bagi setiap tik, O(n).</translation>
    </message>
</context>
<context>
    <name>palpate::PalpationSummaryText</name>
    <message>
        <source>Lumps found: %1 of %2, false alarms: %3 (sensitivity %4, predictive value %5)</source>
        <translation>Ketulan ditemui: %1 daripada %2, penggera palsu: %3 (kepekaan %4, nilai ramalan %5)</translation>
    </message>
    <message>
        <source>Findings on a lump lay %1 mm from its centre on average</source>
        <translation>Penemuan pada ketulan terletak purata %1 mm dari pusatnya</translation>
    </message>
    <message>
        <source>Surface examined at %1 N or more: %2 %</source>
        <translation>Permukaan diperiksa pada %1 N atau lebih: %2 %</translation>
    </message>
    <message>
        <source>Force: searching %1 N, palpating %2 N (medians; %3 times)</source>
        <translation>Daya: mencari %1 N, meraba %2 N (median; %3 kali)</translation>
    </message>
    <message>
        <source>Pressed too lightly to reach the deepest lump: it lies %1 mm under the surface, and over it the surface sank %2 mm at most.</source>
        <translation>Ditekan terlalu ringan untuk mencapai ketulan paling dalam: ia terletak %1 mm di bawah permukaan, dan di atasnya permukaan tenggelam paling banyak %2 mm.</translation>
    </message>
    <message>
        <source>Press to about %1 N or more to feel it.</source>
        <translation>Tekan kira-kira %1 N atau lebih untuk merasainya.</translation>
    </message>
    <message>
        <source>Examined %1 % of the surface at %2 N or more: cover all of it, in overlapping rows.</source>
        <translation>Memeriksa %1 % permukaan pada %2 N atau lebih: liputi semuanya, dalam baris bertindih.</translation>
    </message>
    <message>
        <source>Pressed no harder to palpate than to search (median %1 N against %2 N): press in on a spot that feels different.</source>
        <translation>Tidak menekan lebih kuat untuk palpasi berbanding mencari (median %1 N berbanding %2 N): tekan ke dalam pada tempat yang terasa berbeza.</translation>
    </message>
    <message>
        <source>1 finding was on no lump: mark only where the tissue resists more than around it.</source>
        <translation>1 dapatan bukan pada ketulan: tandakan hanya di mana tisu menentang lebih daripada sekelilingnya.</translation>
    </message>
    <message>
        <source>%1 findings were on no lump: mark only where the tissue resists more than around it.</source>
        <translation>%1 dapatan bukan pada ketulan: tandakan hanya di mana tisu menentang lebih daripada sekelilingnya.</translation>
    </message>
</context>
<context>
    <name>palpate::ParameterPanel</name>
    <message>
        <source>Undo</source>
        <translation>Buat asal</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Buat semula</translation>
    </message>
    <message>
        <source>|m%1| (touched)</source>
        <translation>|m%1| (disentuh)</translation>
    </message>
    <message>
        <source>|m%1| (ring %2)</source>
        <translation>|m%1| (gelang %2)</translation>
    </message>
    <message>
        <source>deformation model</source>
        <translation>model ubah bentuk</translation>
    </message>
    <message>
        <source>haptic rate</source>
        <translation>kadar haptik</translation>
    </message>
    <message>
        <source>Model and loop</source>
        <translation>Model dan gelung</translation>
    </message>
    <message>
        <source>Slopes (magnitudes, |m1| &gt; |m2| &gt; …)</source>
        <translation>Cerun (magnitud, |m1| &gt; |m2| &gt; …)</translation>
    </message>
    <message>
        <source>Springs and contact</source>
        <translation>Spring dan sentuhan</translation>
    </message>
    <message>
        <source>Octree</source>
        <translation>Octree</translation>
    </message>
    <message>
        <source>Tissue and tool</source>
        <translation>Tisu dan alat</translation>
    </message>
    <message>
        <source>The tissue&apos;s elasticity and the probe&apos;s flat tip: Calibrate slopes turns them into slopes and a spring stiffness for the current mesh (flat punch on a half-space, docs/calibration.md).</source>
        <translation>Keanjalan tisu dan hujung rata prob: Tentukur cerun menukarkannya kepada cerun dan kekakuan spring untuk jejaring semasa (penebuk rata pada separuh ruang, docs/calibration.md).</translation>
    </message>
    <message>
        <source>Tissue preset:</source>
        <translation>Praset tisu:</translation>
    </message>
    <message>
        <source>Choose a tissue…</source>
        <translation>Pilih tisu…</translation>
    </message>
    <message>
        <source>Load a shipped tissue preset: E, ν, the tool radius and slopes calibrated for the default stomach mesh (one undoable step). Each entry&apos;s tooltip names its source.</source>
        <translation>Muatkan praset tisu yang disertakan: E, ν, jejari alat dan cerun yang ditentukur untuk jejaring perut lalai (satu langkah boleh dibuat asal). Petua alat setiap entri menamakan sumbernya.</translation>
    </message>
    <message>
        <source>Ca&amp;librate slopes</source>
        <translation>Ten&amp;tukur cerun</translation>
    </message>
    <message>
        <source>Slopes for the ring count and spring k for the current mesh from E, ν and the tool radius (flat punch: |m1| = 1 / (2 a E*), k = 1 / |m1|), then the error the calibrated model leaves against the punch. One undoable step; Apply sends them.</source>
        <translation>Cerun untuk bilangan gelang dan spring k untuk jejaring semasa daripada E, ν dan jejari alat (penebuk rata: |m1| = 1 / (2 a E*), k = 1 / |m1|), kemudian ralat yang ditinggalkan oleh model yang ditentukur berbanding penebuk. Satu langkah boleh dibuat asal; Guna menghantarnya.</translation>
    </message>
    <message>
        <source>Deformation model:</source>
        <translation>Model ubah bentuk:</translation>
    </message>
    <message>
        <source>Which model deforms the tissue: the slope-ring methods (ours and the paper&apos;s three), then the literature&apos;s other models (docs/models.md).</source>
        <translation>Model yang mengubah bentuk tisu: kaedah gelang-cerun (kami dan tiga kaedah kertas kerja), kemudian model lain daripada literatur (docs/models.md).</translation>
    </message>
    <message>
        <source>Haptic rate:</source>
        <translation>Kadar haptik:</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>Ticks per second of the haptic loop, %1..%2 Hz (haptics usually runs at 1000 Hz).</source>
        <translation>Tik sesaat gelung haptik, %1..%2 Hz (haptik biasanya berjalan pada 1000 Hz).</translation>
    </message>
    <message>
        <source>Read with signs, the paper&apos;s &quot;m1 &gt; m2 &gt; m3&quot; would move the outer rings further than the touched vertex. Palpate orders the magnitudes instead, |m1| &gt; |m2| &gt; |m3| &gt; …, so the displacement decays away from the touched vertex.</source>
        <translation>Dibaca dengan tanda, &quot;m1 &gt; m2 &gt; m3&quot; kertas kerja akan menggerakkan gelang luar lebih jauh daripada bucu yang disentuh. Palpate sebaliknya menyusun magnitud, |m1| &gt; |m2| &gt; |m3| &gt; …, supaya anjakan berkurang menjauhi bucu yang disentuh.</translation>
    </message>
    <message>
        <source>The paper&apos;s range is (0, 1) mm/N; larger values need a raised slope limit and a stable loop gain.</source>
        <translation>Julat kertas kerja ialah (0, 1) mm/N; nilai lebih besar memerlukan had cerun yang dinaikkan dan gandaan gelung yang stabil.</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>automatik</translation>
    </message>
    <message>
        <source>Open preset…</source>
        <translation>Buka praset…</translation>
    </message>
    <message>
        <source>Read a tissue preset file (JSON) into the fields; one undoable step.</source>
        <translation>Baca fail praset tisu (JSON) ke dalam medan; satu langkah boleh dibuat asal.</translation>
    </message>
    <message>
        <source>Save preset…</source>
        <translation>Simpan praset…</translation>
    </message>
    <message>
        <source>Write the fields to a tissue preset file (JSON).</source>
        <translation>Tulis medan ke fail praset tisu (JSON).</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Guna</translation>
    </message>
    <message>
        <source>Send these parameters to the haptic loop (enabled while they are valid).</source>
        <translation>Hantar parameter ini ke gelung haptik (didayakan selagi ia sah).</translation>
    </message>
    <message>
        <source>entered in the Parameters panel</source>
        <translation>dimasukkan dalam panel Parameter</translation>
    </message>
    <message>
        <source>E = %1 kPa, ν = %2, tool radius %3 mm</source>
        <translation>E = %1 kPa, ν = %2, jejari alat %3 mm</translation>
    </message>
    <message>
        <source>Source: %1</source>
        <translation>Sumber: %1</translation>
    </message>
    <message>
        <source>Calibrate slopes needs a mesh: open one first.</source>
        <translation>Tentukur cerun memerlukan jejaring: buka satu dahulu.</translation>
    </message>
    <message>
        <source>Not calibrated: %1</source>
        <translation>Tidak ditentukur: %1</translation>
    </message>
    <message>
        <source>Parameters panel default (gelatin phantom, as palpate-cli)</source>
        <translation>Lalai panel Parameter (fantom gelatin, seperti palpate-cli)</translation>
    </message>
    <message>
        <source>Calibrate slopes</source>
        <translation>Tentukur cerun</translation>
    </message>
    <message>
        <source>displacement error %1 % (RMS/peak over r ≤ 5a), force error %2 %</source>
        <translation>ralat anjakan %1 % (RMS/puncak ke atas r ≤ 5a), ralat daya %2 %</translation>
    </message>
    <message>
        <source>1 ring</source>
        <translation>1 gelang</translation>
    </message>
    <message>
        <source>%1 rings</source>
        <translation>%1 gelang</translation>
    </message>
    <message>
        <source>at vertex %1 of %2 vertices, pressed %3 mm in; %4 vertices compared.</source>
        <translation>pada bucu %1 daripada %2 bucu, ditekan %3 mm ke dalam; %4 bucu dibandingkan.</translation>
    </message>
    <message>
        <source>Note: %1</source>
        <translation>Nota: %1</translation>
    </message>
    <message>
        <source>(for the calibrated slopes; the slopes have changed since)</source>
        <translation>(untuk cerun yang ditentukur; cerun telah berubah sejak itu)</translation>
    </message>
    <message>
        <source>Preset: %1</source>
        <translation>Praset: %1</translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>Ubah %1</translation>
    </message>
    <message>
        <source>%1 parameters</source>
        <translation>%1 parameter</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>haptic rate = %1 Hz must be in %2..%3 Hz</source>
        <translation>kadar haptik = %1 Hz mesti dalam %2..%3 Hz</translation>
    </message>
    <message>
        <source>%1 (automatic)</source>
        <translation>%1 (automatik)</translation>
    </message>
    <message>
        <source>Loop gain |m1| × k_c = %1, α = %2</source>
        <translation>Gandaan gelung |m1| × k_c = %1, α = %2</translation>
    </message>
    <message>
        <source>α·(1 + gain) = %1 ≥ 2: unstable (the surface oscillates and grows)</source>
        <translation>α·(1 + gandaan) = %1 ≥ 2: tidak stabil (permukaan berayun dan membesar)</translation>
    </message>
    <message>
        <source>Stability margin: needs the mesh (the mass-spring step bound depends on its springs)</source>
        <translation>Margin kestabilan: memerlukan jejaring (had langkah jisim-spring bergantung pada springnya)</translation>
    </message>
    <message>
        <source>Beyond the stability margin (%1&#xa0;%): Apply asks for confirmation</source>
        <translation>Melepasi margin kestabilan (%1&#xa0;%): Guna meminta pengesahan</translation>
    </message>
    <message>
        <source>Stability margin %1&#xa0;%</source>
        <translation>Margin kestabilan %1&#xa0;%</translation>
    </message>
    <message>
        <source>%1 is outside the paper&apos;s range (0, 1) mm/N: allowed by the slope limit %2 mm/N and the loop-gain bound.</source>
        <translation>%1 berada di luar julat kertas kerja (0, 1) mm/N: dibenarkan oleh had cerun %2 mm/N dan had gandaan gelung.</translation>
    </message>
    <message>
        <source>%1 are outside the paper&apos;s range (0, 1) mm/N: allowed by the slope limit %2 mm/N and the loop-gain bound.</source>
        <translation>%1 berada di luar julat kertas kerja (0, 1) mm/N: dibenarkan oleh had cerun %2 mm/N dan had gandaan gelung.</translation>
    </message>
    <message>
        <source>Beyond the stability margin</source>
        <translation>Melepasi margin kestabilan</translation>
    </message>
    <message>
        <source>This parameter set is beyond its stability margin:
%1

The model may diverge (or the device buzz); the divergence guard would then zero the force and reset the tissue. Apply anyway?</source>
        <translation>Set parameter ini melepasi margin kestabilannya:
%1

Model mungkin mencapah (atau peranti berdengung); pengawal pencapahan kemudian akan mensifarkan daya dan menetapkan semula tisu. Guna juga?</translation>
    </message>
    <message>
        <source>%1: could not be read</source>
        <translation>%1: tidak dapat dibaca</translation>
    </message>
    <message>
        <source>Preset not loaded; the fields are unchanged:</source>
        <translation>Praset tidak dimuatkan; medan tidak berubah:</translation>
    </message>
    <message>
        <source>Load preset %1</source>
        <translation>Muatkan praset %1</translation>
    </message>
    <message>
        <source>Loaded %1</source>
        <translation>%1 dimuatkan</translation>
    </message>
    <message>
        <source>(saved with a stability margin of %1&#xa0;% at %2&#xa0;Hz)</source>
        <translation>(disimpan dengan margin kestabilan %1&#xa0;% pada %2&#xa0;Hz)</translation>
    </message>
    <message>
        <source>%1: not saved, the parameters are not valid (see above); the file could not be read back</source>
        <translation>%1: tidak disimpan, parameter tidak sah (lihat di atas); fail tidak dapat dibaca semula</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 disimpan</translation>
    </message>
    <message>
        <source>Open preset</source>
        <translation>Buka praset</translation>
    </message>
    <message>
        <source>Tissue presets (*.json);;All files (*)</source>
        <translation>Praset tisu (*.json);;Semua fail (*)</translation>
    </message>
    <message>
        <source>Save preset</source>
        <translation>Simpan praset</translation>
    </message>
    <message>
        <source>α·(1 + gain) = %1 &lt; 2: loop-gain margin %2&#xa0;%</source>
        <translation>α·(1 + gandaan) = %1 &lt; 2: margin gandaan gelung %2&#xa0;%</translation>
    </message>
    <message>
        <source>Far beyond the stability margin: Apply asks for confirmation</source>
        <translation>Jauh melepasi margin kestabilan: Guna meminta pengesahan</translation>
    </message>
    <message>
        <source>Close to the stability margin: %1&#xa0;% left (warning below %2&#xa0;%)</source>
        <translation>Hampir dengan had kestabilan: tinggal %1&#xa0;% (amaran di bawah %2&#xa0;%)</translation>
    </message>
    <message>
        <source>The contact force iteration converges while α·(1 + gain) &lt; 2, with the loop gain |m1| × k_c (docs/method.md): the loop-gain margin is 1 − α·(1 + gain) / 2. What the model renders, k_s·|m1|·k_c / (1 + gain) (and, for ours with friction, the proxy&apos;s spring), must stay below the stiffness the device renders passively at the haptic rate (1 N/mm at 1 kHz); a lagging or alternating relaxation (α away from 1 / (1 + gain)) asks more of it (docs/stability.md).</source>
        <translation>Lelaran daya sentuhan menumpu selagi α·(1 + gandaan) &lt; 2, dengan gandaan gelung |m1| × k_c (docs/method.md): margin gandaan gelung ialah 1 − α·(1 + gandaan) / 2. Apa yang dipaparkan oleh model, k_s·|m1|·k_c / (1 + gandaan) (dan, bagi model kami dengan geseran, spring proksi), mesti kekal di bawah kekakuan yang dipaparkan secara pasif oleh peranti pada kadar haptik (1 N/mm pada 1 kHz); pengenduran yang lewat atau berselang-seli (α jauh daripada 1 / (1 + gandaan)) memerlukan lebih daripadanya (docs/stability.md).</translation>
    </message>
    <message>
        <source>How far the set is from its derived stability bound at the haptic rate (docs/stability.md): the explicit mass-spring integrators&apos; step bound h·ω_max &lt; 2 (RK4 2.78), ω_max from Gershgorin&apos;s bound and the sub-steps the model takes; and for every model the stiffness it renders (for mass-spring measured on the mesh) against the stiffness the device renders passively (Colgate and Brown, 1 N/mm at 1 kHz). Backward Euler has no step bound.</source>
        <translation>Sejauh mana set ini daripada had kestabilan terbitannya pada kadar haptik (docs/stability.md): had langkah pengamir jisim-spring eksplisit h·ω_max &lt; 2 (RK4 2.78), ω_max daripada had Gershgorin dan sub-langkah yang diambil oleh model; dan bagi setiap model kekakuan yang dipaparkannya (bagi jisim-spring diukur pada jejaring) berbanding kekakuan yang dipaparkan secara pasif oleh peranti (Colgate dan Brown, 1 N/mm pada 1 kHz). Euler ke belakang tiada had langkah.</translation>
    </message>
    <message>
        <source>&amp;Revert</source>
        <translation>&amp;Kembalikan</translation>
    </message>
    <message>
        <source>Set the fields back to what the haptic loop runs (one undoable step).</source>
        <translation>Kembalikan medan kepada apa yang dijalankan oleh gelung haptik (satu langkah boleh buat asal).</translation>
    </message>
    <message>
        <source>Applied to the running tissue at %1</source>
        <translation>Digunakan pada tisu yang berjalan pada %1</translation>
    </message>
    <message>
        <source>Revert to the running tissue</source>
        <translation>Kembali kepada tisu yang berjalan</translation>
    </message>
    <message numerus="yes">
        <source>%n more</source>
        <translation>
            <numerusform>%n lagi</numerusform>
        </translation>
    </message>
    <message>
        <source>Not applied: %1 differ from the running tissue. Apply (Ctrl+Return) sends them; Revert goes back to what runs.</source>
        <translation>Belum digunakan: %1 berbeza daripada tisu yang berjalan. Guna (Ctrl+Return) menghantarnya; Kembalikan kembali kepada apa yang berjalan.</translation>
    </message>
    <message>
        <source>Apply stiffening knots</source>
        <translation>Guna simpulan pengerasan</translation>
    </message>
    <message>
        <source>Not applied: the parameters are not valid (see the Parameters panel).</source>
        <translation>Tidak digunakan: parameter tidak sah (lihat panel Parameter).</translation>
    </message>
</context>
<context>
    <name>palpate::Parameters</name>
    <message>
        <source>ring count</source>
        <translation>bilangan gelang</translation>
    </message>
    <message>
        <source>slope limit</source>
        <translation>had cerun</translation>
    </message>
    <message>
        <source>spring stiffness</source>
        <translation>kekakuan spring</translation>
    </message>
    <message>
        <source>damping ratio</source>
        <translation>nisbah redaman</translation>
    </message>
    <message>
        <source>contact stiffness</source>
        <translation>kekakuan sentuhan</translation>
    </message>
    <message>
        <source>force relaxation</source>
        <translation>pengenduran daya</translation>
    </message>
    <message>
        <source>vertex mass</source>
        <translation>jisim bucu</translation>
    </message>
    <message>
        <source>octree depth</source>
        <translation>kedalaman octree</translation>
    </message>
    <message>
        <source>leaf capacity</source>
        <translation>kapasiti daun</translation>
    </message>
    <message>
        <source>Young&apos;s modulus</source>
        <translation>modulus Young</translation>
    </message>
    <message>
        <source>Poisson&apos;s ratio</source>
        <translation>nisbah Poisson</translation>
    </message>
    <message>
        <source>tool radius</source>
        <translation>jejari alat</translation>
    </message>
    <message>
        <source>Young&apos;s modulus E:</source>
        <translation>Modulus Young E:</translation>
    </message>
    <message>
        <source>Stiffness of the tissue, kPa (soft tissue: about 1 to 30 kPa).</source>
        <translation>Kekakuan tisu, kPa (tisu lembut: kira-kira 1 hingga 30 kPa).</translation>
    </message>
    <message>
        <source>Poisson&apos;s ratio ν:</source>
        <translation>Nisbah Poisson ν:</translation>
    </message>
    <message>
        <source>Tool radius a:</source>
        <translation>Jejari alat a:</translation>
    </message>
    <message>
        <source>Symplectic Euler</source>
        <translation>Euler simplektik</translation>
    </message>
    <message>
        <source>RK4</source>
        <translation>RK4</translation>
    </message>
    <message>
        <source>Backward Euler (implicit)</source>
        <translation>Euler ke belakang (tersirat)</translation>
    </message>
    <message>
        <source>Ring count:</source>
        <translation>Bilangan gelang:</translation>
    </message>
    <message>
        <source>Rings of neighbours displaced with the touched vertex (ring r: the vertices r edges away). The paper uses 2; each ring adds a slope below.</source>
        <translation>Gelang jiran yang dianjak bersama bucu yang disentuh (gelang r: bucu yang r tepi jauhnya). Kertas kerja menggunakan 2; setiap gelang menambah satu cerun di bawah.</translation>
    </message>
    <message>
        <source>Slope magnitude |m| in mm/N: how far the vertex moves per newton of contact force; the model applies the paper&apos;s sign (m &lt; 0), which moves the vertex into the tissue.</source>
        <translation>Magnitud cerun |m| dalam mm/N: sejauh mana bucu bergerak bagi setiap newton daya sentuhan; model menggunakan tanda kertas kerja (m &lt; 0), yang menggerakkan bucu ke dalam tisu.</translation>
    </message>
    <message>
        <source>Slope limit:</source>
        <translation>Had cerun:</translation>
    </message>
    <message>
        <source>Every slope magnitude must stay below this limit. The paper&apos;s range ends at 1 mm/N; calibrated soft tissue may need more (at most 100 mm/N), allowed while the loop gain stays stable. Slopes above 1 mm/N are marked as outside the paper&apos;s range.</source>
        <translation>Setiap magnitud cerun mesti kekal di bawah had ini. Julat kertas kerja berakhir pada 1 mm/N; tisu lembut yang ditentukur mungkin memerlukan lebih (paling banyak 100 mm/N), dibenarkan selagi gandaan gelung kekal stabil. Cerun melebihi 1 mm/N ditanda sebagai di luar julat kertas kerja.</translation>
    </message>
    <message>
        <source>Spring stiffness k:</source>
        <translation>Kekakuan spring k:</translation>
    </message>
    <message>
        <source>Stiffness of the springs that tie each vertex to its rest position. The touched vertex&apos;s spring reaction is the force rendered to the user.</source>
        <translation>Kekakuan spring yang mengikat setiap bucu pada kedudukan rehatnya. Tindak balas spring bucu yang disentuh ialah daya yang dirasai pengguna.</translation>
    </message>
    <message>
        <source>Damping ratio:</source>
        <translation>Nisbah redaman:</translation>
    </message>
    <message>
        <source>Damping of the return springs as a fraction of critical: 1 returns without overshoot, below 1 the tissue rings before it settles (0..100).</source>
        <translation>Redaman spring pemulih sebagai pecahan redaman genting: 1 kembali tanpa lajakan, di bawah 1 tisu berayun sebelum tenang (0..100).</translation>
    </message>
    <message>
        <source>Contact stiffness k_c:</source>
        <translation>Kekakuan sentuhan k_c:</translation>
    </message>
    <message>
        <source>Stiffness of the tool-tissue contact (a penalty spring). The loop gain is |m1| × k_c.</source>
        <translation>Kekakuan sentuhan alat-tisu (spring penalti). Gandaan gelung ialah |m1| × k_c.</translation>
    </message>
    <message>
        <source>Force relaxation α:</source>
        <translation>Pengenduran daya α:</translation>
    </message>
    <message>
        <source>Per-tick relaxation α of the contact force, in (0, 1]. Automatic (0) uses α = 1 / (1 + gain), which solves the contact in one tick for any gain. The update is stable while α·(1 + gain) &lt; 2.</source>
        <translation>Pengenduran α daya sentuhan setiap tik, dalam (0, 1]. Automatik (0) menggunakan α = 1 / (1 + gandaan), yang menyelesaikan sentuhan dalam satu tik untuk sebarang gandaan. Kemas kini stabil selagi α·(1 + gandaan) &lt; 2.</translation>
    </message>
    <message>
        <source>Vertex mass:</source>
        <translation>Jisim bucu:</translation>
    </message>
    <message>
        <source>Lumped mass per vertex, for the relaxation after the tool lets go.</source>
        <translation>Jisim tergumpal setiap bucu, untuk pengenduran selepas alat dilepaskan.</translation>
    </message>
    <message>
        <source>Max depth:</source>
        <translation>Kedalaman maks.:</translation>
    </message>
    <message>
        <source>Levels below the octree&apos;s root (1..20).</source>
        <translation>Aras di bawah akar octree (1..20).</translation>
    </message>
    <message>
        <source>Leaf capacity:</source>
        <translation>Kapasiti daun:</translation>
    </message>
    <message>
        <source>A node with at most this many vertices is not split (1..100000).</source>
        <translation>Nod dengan paling banyak bilangan bucu ini tidak dipecahkan (1..100000).</translation>
    </message>
    <message>
        <source>vertices</source>
        <translation>bucu</translation>
    </message>
    <message>
        <source>How the tissue bulges sideways when pressed, 0..0.4999 (soft tissue is nearly incompressible: about 0.45 to 0.49; 0.5 would be incompressible).</source>
        <translation>Sejauh mana tisu membonjol ke sisi apabila ditekan, 0..0.4999 (tisu lembut hampir tidak boleh mampat: kira-kira 0.45 hingga 0.49; 0.5 bermakna tidak boleh mampat langsung).</translation>
    </message>
    <message>
        <source>Radius of the probe&apos;s flat tip, mm (0.01..1000).</source>
        <translation>Jejari hujung rata prob, mm (0.01..1000).</translation>
    </message>
    <message>
        <source>Control points per axis:</source>
        <translation>Titik kawalan setiap paksi:</translation>
    </message>
    <message>
        <source>Lattice resolution: control points per axis, Bernstein degree + 1 (2..16).</source>
        <translation>Resolusi kekisi: titik kawalan setiap paksi, darjah Bernstein + 1 (2..16).</translation>
    </message>
    <message>
        <source>Moved per axis:</source>
        <translation>Digerakkan setiap paksi:</translation>
    </message>
    <message>
        <source>Control points moved per axis: the block nearest the contact (1..control points).</source>
        <translation>Titik kawalan yang digerakkan setiap paksi: blok yang paling hampir dengan sentuhan (1..titik kawalan).</translation>
    </message>
    <message>
        <source>Lattice margin:</source>
        <translation>Jidar kekisi:</translation>
    </message>
    <message>
        <source>The lattice is the mesh&apos;s bounding box grown by this fraction of its diagonal, in (0, 1].</source>
        <translation>Kekisi ialah kotak sempadan jejaring yang dibesarkan dengan pecahan pepenjurunya ini, dalam (0, 1].</translation>
    </message>
    <message>
        <source>Stiffness k_s:</source>
        <translation>Kekakuan k_s:</translation>
    </message>
    <message>
        <source>The rendered force is k_s times the touched vertex&apos;s displacement, N/mm.</source>
        <translation>Daya yang dipaparkan ialah k_s darab anjakan bucu yang disentuh, N/mm.</translation>
    </message>
    <message>
        <source>Vertex mass m:</source>
        <translation>Jisim bucu m:</translation>
    </message>
    <message>
        <source>Lumped mass per vertex, kg.</source>
        <translation>Jisim tergumpal setiap bucu, kg.</translation>
    </message>
    <message>
        <source>Anchor stiffness k_a:</source>
        <translation>Kekakuan sauh k_a:</translation>
    </message>
    <message>
        <source>Spring from each vertex to its rest position, N/mm: what holds the shape.</source>
        <translation>Spring dari setiap bucu ke kedudukan rehatnya, N/mm: yang mengekalkan bentuk.</translation>
    </message>
    <message>
        <source>Edge stiffness k_e:</source>
        <translation>Kekakuan sisi k_e:</translation>
    </message>
    <message>
        <source>Spring along each mesh edge, N/mm: spreads the dent to the neighbours.</source>
        <translation>Spring di sepanjang setiap sisi jejaring, N/mm: menyebarkan lekuk kepada jiran.</translation>
    </message>
    <message>
        <source>Penalty stiffness between the tool tip and the touched vertex, N/mm.</source>
        <translation>Kekakuan penalti antara hujung alat dan bucu yang disentuh, N/mm.</translation>
    </message>
    <message>
        <source>Damping ratio ζ:</source>
        <translation>Nisbah redaman ζ:</translation>
    </message>
    <message>
        <source>Velocity damping as a fraction of the anchor spring&apos;s critical damping (0..100).</source>
        <translation>Redaman halaju sebagai pecahan redaman kritikal spring sauh (0..100).</translation>
    </message>
    <message>
        <source>Sub-steps:</source>
        <translation>Sub-langkah:</translation>
    </message>
    <message>
        <source>Explicit integrators: sub-steps per tick; 0 = automatic (inside the stability bound); at most the max sub-steps.</source>
        <translation>Pengamir eksplisit: sub-langkah setiap detik; 0 = automatik (dalam had kestabilan); paling banyak sub-langkah maksimum.</translation>
    </message>
    <message>
        <source>Max sub-steps:</source>
        <translation>Sub-langkah maks.:</translation>
    </message>
    <message>
        <source>Cap on automatic sub-steps (bounded work per tick).</source>
        <translation>Had bagi sub-langkah automatik (kerja terhad setiap detik).</translation>
    </message>
    <message>
        <source>CG iterations (max):</source>
        <translation>Lelaran CG (maks.):</translation>
    </message>
    <message>
        <source>Backward Euler: conjugate-gradient iteration cap.</source>
        <translation>Euler ke belakang: had lelaran kecerunan konjugat.</translation>
    </message>
    <message>
        <source>CG tolerance:</source>
        <translation>Toleransi CG:</translation>
    </message>
    <message>
        <source>Backward Euler: relative residual at which conjugate gradients stop, in (0, 1).</source>
        <translation>Euler ke belakang: baki relatif di mana kecerunan konjugat berhenti, dalam (0, 1).</translation>
    </message>
    <message>
        <source>Simulated rings:</source>
        <translation>Gelang yang disimulasi:</translation>
    </message>
    <message>
        <source>Rings of the touched vertex that are simulated; everything else is pinned at rest.</source>
        <translation>Gelang bucu yang disentuh yang disimulasi; yang lain disemat pada kedudukan rehat.</translation>
    </message>
    <message>
        <source>Integrator:</source>
        <translation>Pengamir:</translation>
    </message>
    <message>
        <source>The local variant&apos;s integrator: symplectic Euler, RK4 or backward Euler.</source>
        <translation>Pengamir varian tempatan: Euler simplektik, RK4 atau Euler ke belakang.</translation>
    </message>
    <message>
        <source>Rest tolerance:</source>
        <translation>Toleransi rehat:</translation>
    </message>
    <message>
        <source>A vertex outside the rings this close to rest and moving less than this per tick stops being simulated, mm.</source>
        <translation>Bucu di luar gelang yang sedekat ini dengan kedudukan rehat dan bergerak kurang daripada ini setiap detik tidak lagi disimulasi, mm.</translation>
    </message>
    <message>
        <source>Radius R:</source>
        <translation>Jejari R:</translation>
    </message>
    <message>
        <source>Every vertex within this distance of the touched vertex (in 3D, whatever the edges) moves, mm.</source>
        <translation>Setiap bucu dalam jarak ini dari bucu yang disentuh (dalam 3D, tanpa mengira sisi) bergerak, mm.</translation>
    </message>
    <message>
        <source>Profile degree:</source>
        <translation>Darjah profil:</translation>
    </message>
    <message>
        <source>The profile is (1 − r/R)^degree (2..8); a preset file&apos;s own coefficients are kept until the degree changes.</source>
        <translation>Profil ialah (1 − r/R)^darjah (2..8); pekali fail praset sendiri dikekalkan sehingga darjah berubah.</translation>
    </message>
    <message>
        <source>Static friction μs:</source>
        <translation>Geseran statik μs:</translation>
    </message>
    <message>
        <source>static friction coefficient</source>
        <translation>pekali geseran statik</translation>
    </message>
    <message>
        <source>Coulomb friction between tool and tissue: the tool sticks until the sideways force exceeds μs times the normal force (0..5; 0 and 0: no friction). Moist soft tissue: about 0.3.</source>
        <translation>Geseran Coulomb antara alat dan tisu: alat melekat sehingga daya sisi melebihi μs kali daya normal (0..5; 0 dan 0: tiada geseran). Tisu lembut lembap: kira-kira 0.3.</translation>
    </message>
    <message>
        <source>Sliding friction μd:</source>
        <translation>Geseran gelongsor μd:</translation>
    </message>
    <message>
        <source>sliding friction coefficient</source>
        <translation>pekali geseran gelongsor</translation>
    </message>
    <message>
        <source>While the tool slides, the sideways force is μd times the normal force (0..5, at most μs).</source>
        <translation>Semasa alat menggelongsor, daya sisi ialah μd kali daya normal (0..5, paling banyak μs).</translation>
    </message>
    <message>
        <source>Stiffening knots:</source>
        <translation>Simpulan pengerasan:</translation>
    </message>
    <message>
        <source>stiffening knots</source>
        <translation>simpulan pengerasan</translation>
    </message>
    <message>
        <source>Points of the strain-stiffening curve, calibrated from the hyperelastic reference. 0: linear tissue, the paper&apos;s model.</source>
        <translation>Titik lengkung pengerasan terikan, ditentukur daripada rujukan hiperelastik. 0: tisu linear, model kertas kerja.</translation>
    </message>
    <message>
        <source>Contact force above which the next stiffening compliance applies, N.</source>
        <translation>Daya sentuhan yang melebihinya pematuhan pengerasan seterusnya digunakan, N.</translation>
    </message>
    <message>
        <source>Above its knot the tissue yields this fraction of |m1| per further newton: below 1, it stiffens.</source>
        <translation>Melebihi simpulannya tisu mengalah sebanyak pecahan |m1| ini bagi setiap newton tambahan: di bawah 1, ia mengeras.</translation>
    </message>
    <message>
        <source>stiffening exponent</source>
        <translation>eksponen pengerasan</translation>
    </message>
    <message>
        <source>Stiffening b (reference):</source>
        <translation>Pengerasan b (rujukan):</translation>
    </message>
    <message>
        <source>How fast the tissue stiffens with strain: b of the exponential law of the hyperelastic reference (0..100; 0: neo-Hookean). It does not change the force by itself: Charts &gt; Stiffening &gt; Compute solves the reference with it, and Apply knots puts the model&apos;s stiffening knots into the tissue.</source>
        <translation>Betapa cepat tisu mengeras dengan terikan: b hukum eksponen rujukan hiperelastik (0..100; 0: neo-Hookean). Ia tidak mengubah daya dengan sendirinya: Carta &gt; Pengerasan &gt; Kira menyelesaikan rujukan dengannya, dan Guna simpulan memasukkan simpulan pengerasan model ke dalam tisu.</translation>
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
        <translation>Keutamaan</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Lalai sistem</translation>
    </message>
    <message>
        <source>A new language applies when Palpate is started again.</source>
        <translation>Bahasa baharu digunakan apabila Palpate dimulakan semula.</translation>
    </message>
    <message>
        <source>newtons (N)</source>
        <translation>newton (N)</translation>
    </message>
    <message>
        <source>gram-force (gf, 1 gf = 9.81 mN)</source>
        <translation>daya gram (gf, 1 gf = 9.81 mN)</translation>
    </message>
    <message>
        <source>As the tissue preset says</source>
        <translation>Seperti yang dinyatakan oleh praset tisu</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>Ticks per second of the haptic loop. Higher rates feel stiffer tissue as stable, and need a faster computer.</source>
        <translation>Tik sesaat gelung haptik. Kadar lebih tinggi memaparkan tisu lebih keras dengan stabil, dan memerlukan komputer lebih pantas.</translation>
    </message>
    <message>
        <source>Built-in default (the mouse)</source>
        <translation>Lalai terbina dalam (tetikus)</translation>
    </message>
    <message>
        <source>The device the window uses when it starts (--device overrides it).</source>
        <translation>Peranti yang digunakan oleh tetingkap semasa bermula (--device mengatasinya).</translation>
    </message>
    <message>
        <source>Recordings (in recordings/) and the trainees&apos; results (results.sqlite) are kept here.</source>
        <translation>Rakaman (dalam recordings/) dan keputusan pelatih (results.sqlite) disimpan di sini.</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Semak Imbas…</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Bahasa:</translation>
    </message>
    <message>
        <source>&amp;Forces shown in:</source>
        <translation>&amp;Daya ditunjukkan dalam:</translation>
    </message>
    <message>
        <source>&amp;Haptic rate:</source>
        <translation>&amp;Kadar haptik:</translation>
    </message>
    <message>
        <source>&amp;Device at start:</source>
        <translation>&amp;Peranti semasa mula:</translation>
    </message>
    <message>
        <source>Device: %1</source>
        <translation>Peranti: %1</translation>
    </message>
    <message>
        <source>The data folder must be an absolute path.</source>
        <translation>Folder data mesti laluan mutlak.</translation>
    </message>
    <message>
        <source>Data Folder</source>
        <translation>Folder Data</translation>
    </message>
    <message>
        <source>Data f&amp;older:</source>
        <translation>&amp;Folder data:</translation>
    </message>
    <message>
        <source>F&amp;ade the force gauge as the trainee improves</source>
        <translation>&amp;Pudarkan tolok daya apabila pelatih bertambah baik</translation>
    </message>
    <message>
        <source>Continuous force feedback breeds dependence: each good session of an exercise fades the gauge, each poor one brings it back</source>
        <translation>Maklum balas daya berterusan menimbulkan kebergantungan: setiap sesi baik sesuatu latihan memudarkan tolok, setiap sesi lemah mengembalikannya</translation>
    </message>
    <message>
        <source> good sessions to fade out</source>
        <translation> sesi baik sehingga pudar</translation>
    </message>
    <message>
        <source>good at </source>
        <translation>baik pada </translation>
    </message>
    <message>
        <source> / 100 or more</source>
        <translation> / 100 atau lebih</translation>
    </message>
    <message>
        <source>Guidance:</source>
        <translation>Bimbingan:</translation>
    </message>
    <message>
        <source>none (results stay on this workstation)</source>
        <translation>tiada (keputusan kekal di stesen kerja ini)</translation>
    </message>
    <message>
        <source>The class&apos;s PostgreSQL server, postgresql://user@host/database: every result is kept here first and copied there when it answers. The password goes in ~/.pgpass, never here (docs/results-store.md).</source>
        <translation>Pelayan PostgreSQL kelas, postgresql://pengguna@hos/pangkalan: setiap keputusan disimpan di sini dahulu dan disalin ke sana apabila ia menjawab. Kata laluan diletakkan dalam ~/.pgpass, bukan di sini (docs/results-store.md).</translation>
    </message>
    <message>
        <source>Class&apos;s &amp;server:</source>
        <translation>&amp;Pelayan kelas:</translation>
    </message>
    <message>
        <source>Class&apos;s server: postgresql://[user@]host[:port]/database</source>
        <translation>Pelayan kelas: postgresql://[pengguna@]hos[:port]/pangkalan</translation>
    </message>
    <message>
        <source>Class&apos;s server: no password here; put it in ~/.pgpass (docs/results-store.md).</source>
        <translation>Pelayan kelas: tiada kata laluan di sini; letakkannya dalam ~/.pgpass (docs/results-store.md).</translation>
    </message>
    <message>
        <source>Class&apos;s server: %1</source>
        <translation>Pelayan kelas: %1</translation>
    </message>
</context>
<context>
    <name>palpate::RecorderPanel</name>
    <message>
        <source>%1 is not a Palpate recording (%2)</source>
        <translation>%1 bukan rakaman Palpate (%2)</translation>
    </message>
    <message>
        <source>%1: the header is damaged (%2); %3 chunks were recovered, but a replay needs the header</source>
        <translation>%1: pengepala rosak (%2); %3 ketulan dipulihkan, tetapi main semula memerlukan pengepala</translation>
    </message>
    <message>
        <source>%1 damaged region(s) skipped (%2 bytes)</source>
        <translation>%1 kawasan rosak dilangkau (%2 bait)</translation>
    </message>
    <message>
        <source>%1 ticks lost</source>
        <translation>%1 tik hilang</translation>
    </message>
    <message>
        <source>%1 ticks dropped while recording (%2 gap(s))</source>
        <translation>%1 tik tercicir semasa merakam (%2 jurang)</translation>
    </message>
    <message>
        <source>%1 chunk(s) whose hash disagrees with their ticks</source>
        <translation>%1 ketulan yang cincangnya tidak sepadan dengan tiknya</translation>
    </message>
    <message>
        <source>not closed cleanly (the program ended while recording)</source>
        <translation>tidak ditutup dengan bersih (program tamat semasa merakam)</translation>
    </message>
    <message>
        <source>%1 is damaged. Recovered %2 chunks (%3 ticks); lost: %4.</source>
        <translation>%1 rosak. %2 ketulan (%3 tik) dipulihkan; hilang: %4.</translation>
    </message>
    <message>
        <source>%1 is incomplete. Recovered %2 chunks (%3 ticks); lost: %4.</source>
        <translation>%1 tidak lengkap. %2 ketulan (%3 tik) dipulihkan; hilang: %4.</translation>
    </message>
    <message>
        <source>offset %1, %2 bytes: %3</source>
        <translation>ofset %1, %2 bait: %3</translation>
    </message>
    <message>
        <source> (ticks %1 to %2)</source>
        <translation> (tik %1 hingga %2)</translation>
    </message>
    <message>
        <source>…</source>
        <translation>…</translation>
    </message>
    <message>
        <source>Mark: %1</source>
        <translation>Tanda: %1</translation>
    </message>
    <message>
        <source>Exercise event: %1</source>
        <translation>Peristiwa latihan: %1</translation>
    </message>
    <message>
        <source>Parameters applied</source>
        <translation>Parameter digunakan</translation>
    </message>
    <message>
        <source>Scene changed without a description (the replay stops here)</source>
        <translation>Adegan berubah tanpa keterangan (main semula berhenti di sini)</translation>
    </message>
    <message>
        <source>Scene changed: %1</source>
        <translation>Adegan berubah: %1</translation>
    </message>
    <message>
        <source>Device changed: %1</source>
        <translation>Peranti bertukar: %1</translation>
    </message>
    <message>
        <source>(not described)</source>
        <translation>(tidak diterangkan)</translation>
    </message>
    <message>
        <source>Device state: %1</source>
        <translation>Keadaan peranti: %1</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Dijeda</translation>
    </message>
    <message>
        <source>Resumed</source>
        <translation>Disambung semula</translation>
    </message>
    <message>
        <source>%1 command(s) lost: the replay may differ from here</source>
        <translation>%1 arahan hilang: main semula mungkin berbeza mulai sini</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>Rakaman</translation>
    </message>
    <message>
        <source>Playback</source>
        <translation>Main semula</translation>
    </message>
    <message>
        <source>● &amp;Record</source>
        <translation>● &amp;Rakam</translation>
    </message>
    <message>
        <source>■ S&amp;top</source>
        <translation>■ &amp;Henti</translation>
    </message>
    <message>
        <source>Stop recording and close the file cleanly (Ctrl+Shift+R)</source>
        <translation>Hentikan rakaman dan tutup fail dengan bersih (Ctrl+Shift+R)</translation>
    </message>
    <message>
        <source>Folder…</source>
        <translation>Folder…</translation>
    </message>
    <message>
        <source>Mark text (optional)</source>
        <translation>Teks tanda (pilihan)</translation>
    </message>
    <message>
        <source>The text of the next mark; Return adds it</source>
        <translation>Teks tanda seterusnya; Return menambahnya</translation>
    </message>
    <message>
        <source>&amp;Mark</source>
        <translation>&amp;Tanda</translation>
    </message>
    <message>
        <source>Add a mark at the current tick of the recording (M)</source>
        <translation>Tambah tanda pada tik semasa rakaman (M)</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Buka…</translation>
    </message>
    <message>
        <source>Open a recording to play it back (the live session pauses while it plays)</source>
        <translation>Buka rakaman untuk dimainkan semula (sesi langsung dijeda semasa ia dimainkan)</translation>
    </message>
    <message>
        <source>Back to &amp;Live</source>
        <translation>Kembali ke &amp;Langsung</translation>
    </message>
    <message>
        <source>Close the recording and resume the live session</source>
        <translation>Tutup rakaman dan sambung semula sesi langsung</translation>
    </message>
    <message>
        <source>▶ &amp;Play</source>
        <translation>▶ &amp;Main</translation>
    </message>
    <message>
        <source>Play or pause the recording (Space while the timeline has the focus)</source>
        <translation>Main atau jeda rakaman (Space apabila garis masa mempunyai fokus)</translation>
    </message>
    <message>
        <source>Playback speed</source>
        <translation>Kelajuan main semula</translation>
    </message>
    <message>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <source>Current time / length of the recording (loop clock)</source>
        <translation>Masa semasa / panjang rakaman (jam gelung)</translation>
    </message>
    <message>
        <source>Replaying from the start to reach that tick</source>
        <translation>Memainkan semula dari mula untuk mencapai tik itu</translation>
    </message>
    <message>
        <source>Folder for New Recordings</source>
        <translation>Folder untuk Rakaman Baharu</translation>
    </message>
    <message>
        <source>%1: the recordings folder cannot be created</source>
        <translation>%1: folder rakaman tidak dapat dicipta</translation>
    </message>
    <message>
        <source>Mark %1</source>
        <translation>Tanda %1</translation>
    </message>
    <message>
        <source>Recording to %1…</source>
        <translation>Merakam ke %1…</translation>
    </message>
    <message>
        <source>Not recording.
Folder: %1</source>
        <translation>Tidak merakam.
Folder: %1</translation>
    </message>
    <message>
        <source>%1 %2 · %3 ticks · %4 · %5 B/tick · drops %6 (%7 gaps)</source>
        <translation>%1 %2 · %3 tik · %4 · %5 B/tik · cicir %6 (%7 jurang)</translation>
    </message>
    <message>
        <source>● REC</source>
        <translation>● RAKAM</translation>
    </message>
    <message>
        <source>Saved %1:</source>
        <translation>Disimpan %1:</translation>
    </message>
    <message>
        <source>Stopped %1:</source>
        <translation>Dihentikan %1:</translation>
    </message>
    <message>
        <source> · %1 commands lost</source>
        <translation> · %1 arahan hilang</translation>
    </message>
    <message>
        <source>%1
Elapsed loop time, ticks written, file size, bytes per tick, ticks dropped because the writer fell behind (each run is a gap)</source>
        <translation>%1
Masa gelung berlalu, tik ditulis, saiz fail, bait setiap tik, tik yang tercicir kerana penulis ketinggalan (setiap siri ialah satu jurang)</translation>
    </message>
    <message>
        <source>Added “%1” · next mark text</source>
        <translation>Ditambah “%1” · teks tanda seterusnya</translation>
    </message>
    <message>
        <source>Record the live session to a new file in %1 (Ctrl+Shift+R).
Starting resets the tissue to rest and the force ramps in again (as after a device switch): a recording replays from its start alone.</source>
        <translation>Rakam sesi langsung ke fail baharu dalam %1 (Ctrl+Shift+R).
Memulakan menetapkan semula tisu kepada rehat dan daya meningkat semula (seperti selepas menukar peranti): rakaman dimainkan semula dari permulaannya sahaja.</translation>
    </message>
    <message>
        <source>Go back to the live session to record</source>
        <translation>Kembali ke sesi langsung untuk merakam</translation>
    </message>
    <message>
        <source>Where new recordings go: %1</source>
        <translation>Ke mana rakaman baharu pergi: %1</translation>
    </message>
    <message>
        <source>❚❚ &amp;Pause</source>
        <translation>❚❚ &amp;Jeda</translation>
    </message>
    <message>
        <source>Open Recording</source>
        <translation>Buka Rakaman</translation>
    </message>
    <message>
        <source>Palpate recordings (*.palprec);;All files (*)</source>
        <translation>Rakaman Palpate (*.palprec);;Semua fail (*)</translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation>Membuka %1…</translation>
    </message>
    <message>
        <source>%1: cannot replay: %2</source>
        <translation>%1: tidak dapat dimainkan semula: %2</translation>
    </message>
    <message>
        <source>Replaying to %1… %2 %</source>
        <translation>Memainkan semula ke %1… %2 %</translation>
    </message>
    <message>
        <source>%1
Recorded with Palpate %2 at %3 Hz on %4; device %5; %6 ticks, %7 events</source>
        <translation>%1
Dirakam dengan Palpate %2 pada %3 Hz pada %4; peranti %5; %6 tik, %7 peristiwa</translation>
    </message>
    <message>
        <source>Dropped while recording</source>
        <translation>Tercicir semasa merakam</translation>
    </message>
    <message>
        <source>Damaged (%1)</source>
        <translation>Rosak (%1)</translation>
    </message>
    <message>
        <source>Lost (damaged or missing)</source>
        <translation>Hilang (rosak atau tiada)</translation>
    </message>
    <message>
        <source>Past where the replay stops (%1)</source>
        <translation>Melepasi titik main semula berhenti (%1)</translation>
    </message>
    <message>
        <source>—:— / —:—</source>
        <translation>—:— / —:—</translation>
    </message>
    <message>
        <source>%1 / %2  (tick %3)</source>
        <translation>%1 / %2  (tik %3)</translation>
    </message>
    <message>
        <source>Open a recording to play it back and check its replay.</source>
        <translation>Buka rakaman untuk memainkannya semula dan menyemak main semulanya.</translation>
    </message>
    <message>
        <source>Replay check: play or go to the end (End) to compare every tick with the recording.</source>
        <translation>Semakan main semula: main atau pergi ke penghujung (End) untuk membandingkan setiap tik dengan rakaman.</translation>
    </message>
    <message>
        <source>✔ The replay matches the recording bit for bit (%1 ticks, %2 chunk hashes checked).</source>
        <translation>✔ Main semula sepadan dengan rakaman bit demi bit (%1 tik, %2 cincangan ketulan disemak).</translation>
    </message>
    <message>
        <source>✘ The replay differs from the recording (%1 ticks). First: %2</source>
        <translation>✘ Main semula berbeza daripada rakaman (%1 tik). Pertama: %2</translation>
    </message>
    <message>
        <source>✘ %1 of %2 chunk hashes differ from the replay&apos;s.</source>
        <translation>✘ %1 daripada %2 cincangan ketulan berbeza daripada main semula.</translation>
    </message>
    <message>
        <source>The replay stopped early: %1. The %2 ticks replayed match the recording.</source>
        <translation>Main semula berhenti awal: %1. %2 tik yang dimainkan semula sepadan dengan rakaman.</translation>
    </message>
    <message>
        <source>%1: is a folder, not a recording</source>
        <translation>%1: ialah folder, bukan rakaman</translation>
    </message>
    <message>
        <source>%1: is not a regular file (a FIFO or a device), not a recording</source>
        <translation>%1: bukan fail biasa (FIFO atau peranti), bukan rakaman</translation>
    </message>
    <message>
        <source>Divergence guard fired: %1</source>
        <translation>Pengawal divergens bertindak: %1</translation>
    </message>
</context>
<context>
    <name>palpate::RecordingController</name>
    <message>
        <source>Recorder</source>
        <translation>Perakam</translation>
    </message>
    <message>
        <source>Re&amp;cord</source>
        <translation>&amp;Rakam</translation>
    </message>
    <message>
        <source>Record the live session to a new file (again: stop). Starting resets the tissue to rest and the force ramps in again</source>
        <translation>Rakam sesi langsung ke fail baharu (sekali lagi: berhenti). Memulakan menetapkan semula tisu kepada rehat dan daya meningkat semula</translation>
    </message>
    <message>
        <source>Add &amp;Mark</source>
        <translation>Tambah &amp;Tanda</translation>
    </message>
    <message>
        <source>Mark the current moment of the recording (the Recorder dock&apos;s text, if any)</source>
        <translation>Tandakan detik semasa rakaman (teks dok Perakam, jika ada)</translation>
    </message>
    <message>
        <source>Go back to the live session before recording</source>
        <translation>Kembali ke sesi langsung sebelum merakam</translation>
    </message>
    <message>
        <source>Load a mesh before recording: there is no session to record</source>
        <translation>Muatkan jejaring sebelum merakam: tiada sesi untuk dirakam</translation>
    </message>
    <message>
        <source>Recording to %1</source>
        <translation>Merakam ke %1</translation>
    </message>
    <message>
        <source>Cannot record: %1</source>
        <translation>Tidak dapat merakam: %1</translation>
    </message>
    <message>
        <source>The recording failed: %1</source>
        <translation>Rakaman gagal: %1</translation>
    </message>
    <message>
        <source>Recording saved: %1</source>
        <translation>Rakaman disimpan: %1</translation>
    </message>
    <message>
        <source>mark (trainee)</source>
        <translation>tanda (pelatih)</translation>
    </message>
    <message>
        <source>Mark added: %1</source>
        <translation>Tanda ditambah: %1</translation>
    </message>
    <message>
        <source>Recording stopped: %1 (%2 keeps what was written before)</source>
        <translation>Rakaman dihentikan: %1 (%2 menyimpan apa yang ditulis sebelumnya)</translation>
    </message>
    <message>
        <source>● REC %1</source>
        <translation>● RAKAM %1</translation>
    </message>
    <message>
        <source>▶ playback</source>
        <translation>▶ main semula</translation>
    </message>
    <message>
        <source>A recording is still being opened; try again when it is done</source>
        <translation>Rakaman masih dibuka; cuba lagi apabila selesai</translation>
    </message>
    <message>
        <source>Recording stopped to play %1 back</source>
        <translation>Rakaman dihentikan untuk memainkan semula %1</translation>
    </message>
</context>
<context>
    <name>palpate::RecordingTimeline</name>
    <message>
        <source>Recording timeline</source>
        <translation>Garis masa rakaman</translation>
    </message>
    <message>
        <source>Arrows step, Page Up and Page Down jump, Home and End go to the ends, Ctrl+arrows go to the previous or next event, Space plays or pauses</source>
        <translation>Anak panah melangkah, Page Up dan Page Down melompat, Home dan End pergi ke hujung, Ctrl+anak panah pergi ke peristiwa sebelum atau seterusnya, Space main atau jeda</translation>
    </message>
    <message>
        <source>Open a recording to scrub through it</source>
        <translation>Buka rakaman untuk meneliti melaluinya</translation>
    </message>
    <message>
        <source>%1 (tick %2)</source>
        <translation>%1 (tik %2)</translation>
    </message>
    <message>
        <source>tick %1</source>
        <translation>tik %1</translation>
    </message>
    <message>
        <source>%1 at %2</source>
        <translation>%1 pada %2</translation>
    </message>
    <message>
        <source>… and %1 more here</source>
        <translation>… dan %1 lagi di sini</translation>
    </message>
    <message>
        <source>%1: ticks %2 to %3</source>
        <translation>%1: tik %2 hingga %3</translation>
    </message>
</context>
<context>
    <name>palpate::ResultUploader</name>
    <message>
        <source>Results: sending…</source>
        <translation>Keputusan: sedang dihantar…</translation>
    </message>
    <message>
        <source>Results: all sent</source>
        <translation>Keputusan: semua dihantar</translation>
    </message>
    <message>
        <source>Results: server does not answer</source>
        <translation>Keputusan: pelayan tidak menjawab</translation>
    </message>
    <message>
        <source>Results: 1 waiting</source>
        <translation>Keputusan: 1 menunggu</translation>
    </message>
    <message>
        <source>Results: %1 waiting</source>
        <translation>Keputusan: %1 menunggu</translation>
    </message>
    <message>
        <source>Results: %1 waiting, %2 refused (see the tooltip)</source>
        <translation>Keputusan: %1 menunggu, %2 ditolak (lihat petua alat)</translation>
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
        <translation>ialah folder, bukan pangkalan data keputusan</translation>
    </message>
    <message>
        <source>cannot be read (permission denied)</source>
        <translation>tidak dapat dibaca (kebenaran ditolak)</translation>
    </message>
    <message>
        <source>cannot be created: folder %1 does not exist</source>
        <translation>tidak dapat dicipta: folder %1 tidak wujud</translation>
    </message>
    <message>
        <source>cannot be created: folder %1 is not writable</source>
        <translation>tidak dapat dicipta: folder %1 tidak boleh ditulis</translation>
    </message>
    <message>
        <source>the Qt SQLite driver (QSQLITE) is not installed</source>
        <translation>pemacu SQLite Qt (QSQLITE) tidak dipasang</translation>
    </message>
    <message>
        <source>cannot be opened: %1</source>
        <translation>tidak dapat dibuka: %1</translation>
    </message>
    <message>
        <source>not a results database (%1)</source>
        <translation>bukan pangkalan data keputusan (%1)</translation>
    </message>
    <message>
        <source>schema version %1 is newer than this build reads (%2): update Palpate</source>
        <translation>versi skema %1 lebih baharu daripada yang dibaca oleh binaan ini (%2): kemas kini Palpate</translation>
    </message>
    <message>
        <source>is an SQLite database but not a Palpate results database</source>
        <translation>ialah pangkalan data SQLite tetapi bukan pangkalan data keputusan Palpate</translation>
    </message>
    <message>
        <source>cannot create the tables: %1</source>
        <translation>tidak dapat mencipta jadual: %1</translation>
    </message>
    <message>
        <source>cannot migrate from schema version 1 to 2: %1</source>
        <translation>tidak dapat berpindah daripada versi skema 1 ke 2: %1</translation>
    </message>
    <message>
        <source>not open</source>
        <translation>tidak dibuka</translation>
    </message>
    <message>
        <source>a trainee needs a name</source>
        <translation>pelatih memerlukan nama</translation>
    </message>
    <message>
        <source>cannot add trainee &quot;%1&quot;: %2</source>
        <translation>tidak dapat menambah pelatih &quot;%1&quot;: %2</translation>
    </message>
    <message>
        <source>no trainee with id %1</source>
        <translation>tiada pelatih dengan id %1</translation>
    </message>
    <message>
        <source>cannot store the result: %1</source>
        <translation>tidak dapat menyimpan keputusan: %1</translation>
    </message>
    <message>
        <source>cannot migrate from schema version 2 to 3: %1</source>
        <translation>tidak dapat memindahkan skema versi 2 ke 3: %1</translation>
    </message>
    <message>
        <source>cannot migrate from schema version 3 to 4: %1</source>
        <translation>tidak dapat memindahkan daripada versi skema 3 ke 4: %1</translation>
    </message>
    <message>
        <source>cannot store the staircase of %1: %2</source>
        <translation>tidak dapat menyimpan tangga (staircase) %1: %2</translation>
    </message>
    <message>
        <source>is not a PostgreSQL URL (postgresql://[user@]host[:port]/database)</source>
        <translation>bukan URL PostgreSQL (postgresql://[pengguna@]hos[:port]/pangkalan)</translation>
    </message>
    <message>
        <source>a password in the URL is refused: put it in ~/.pgpass or the file PGPASSFILE names (docs/results-store.md)</source>
        <translation>kata laluan dalam URL ditolak: letakkannya dalam ~/.pgpass atau fail yang dinamakan PGPASSFILE (docs/results-store.md)</translation>
    </message>
    <message>
        <source>names no database (postgresql://host/database)</source>
        <translation>tidak menamakan pangkalan data (postgresql://hos/pangkalan)</translation>
    </message>
    <message>
        <source>the Qt PostgreSQL driver (QPSQL, Debian package libqt6sql6-psql) is not installed</source>
        <translation>pemacu PostgreSQL Qt (QPSQL, pakej Debian libqt6sql6-psql) tidak dipasang</translation>
    </message>
    <message>
        <source>cannot connect: %1</source>
        <translation>tidak dapat bersambung: %1</translation>
    </message>
    <message>
        <source>the database holds other tables: not a Palpate results database</source>
        <translation>pangkalan data memegang jadual lain: bukan pangkalan data keputusan Palpate</translation>
    </message>
    <message>
        <source>cannot migrate from schema version 4 to 5: %1</source>
        <translation>tidak dapat memindahkan daripada versi skema 4 ke 5: %1</translation>
    </message>
    <message>
        <source>cannot mark result %1 as sent: %2</source>
        <translation>tidak dapat menandakan keputusan %1 sebagai dihantar: %2</translation>
    </message>
    <message>
        <source>a result without a uid cannot be copied</source>
        <translation>keputusan tanpa uid tidak dapat disalin</translation>
    </message>
    <message>
        <source>cannot store result %1: %2</source>
        <translation>tidak dapat menyimpan keputusan %1: %2</translation>
    </message>
    <message>
        <source>this role may not read the results (%1): the instructor grants it a workstation or instructor role (palpate-cli results grant, docs/results-store.md)</source>
        <translation>peranan ini tidak boleh membaca keputusan (%1): pengajar memberinya peranan stesen kerja atau pengajar (palpate-cli results grant, docs/results-store.md)</translation>
    </message>
    <message>
        <source>cannot read this connection&apos;s role: %1</source>
        <translation>peranan sambungan ini tidak dapat dibaca: %1</translation>
    </message>
    <message>
        <source>role %1</source>
        <translation>peranan %1</translation>
    </message>
    <message>
        <source>role %1, class %2</source>
        <translation>peranan %1, kelas %2</translation>
    </message>
    <message>
        <source>, TLS</source>
        <translation>, TLS</translation>
    </message>
    <message>
        <source>, no TLS</source>
        <translation>, tanpa TLS</translation>
    </message>
    <message>
        <source>cannot migrate from schema version 5 to 6: %1</source>
        <translation>tidak dapat berpindah dari versi skema 5 ke 6: %1</translation>
    </message>
    <message>
        <source>the server already has a trainee of that name in another class</source>
        <translation>pelayan sudah mempunyai pelatih bernama itu dalam kelas lain</translation>
    </message>
    <message>
        <source>option &apos;%1&apos; is not accepted in the URL (who connects and where come from the URL&apos;s own parts; docs/results-store.md lists the options)</source>
        <translation>pilihan &apos;%1&apos; tidak diterima dalam URL (siapa yang bersambung dan ke mana datang daripada bahagian URL itu sendiri; docs/results-store.md menyenaraikan pilihan)</translation>
    </message>
    <message>
        <source>option &apos;%1&apos; has a value libpq cannot take (a &apos;;&apos; or a NUL)</source>
        <translation>pilihan &apos;%1&apos; mempunyai nilai yang tidak dapat diterima oleh libpq (&apos;;&apos; atau NUL)</translation>
    </message>
    <message>
        <source>connect_timeout must be 1 to %1 seconds (0 would wait for ever)</source>
        <translation>connect_timeout mestilah 1 hingga %1 saat (0 akan menunggu selama-lamanya)</translation>
    </message>
    <message>
        <source>is not a regular file (a device, a FIFO or a socket): not a results database</source>
        <translation>bukan fail biasa (peranti, FIFO atau soket): bukan pangkalan data keputusan</translation>
    </message>
    <message>
        <source>The server refused %1&apos;s result of &quot;%2&quot; (%3, %4): %5. It stays on this workstation; rename the trainee here or ask the instructor (results grant, docs/results-store.md), then send again.</source>
        <translation>Pelayan menolak keputusan %1 bagi &quot;%2&quot; (%3, %4): %5. Ia kekal di stesen kerja ini; namakan semula pelatih di sini atau tanya pengajar (results grant, docs/results-store.md), kemudian hantar semula.</translation>
    </message>
    <message>
        <source>the results schema is damaged (%1): restore the file from a copy (Palpate does not repair it)</source>
        <translation>skema keputusan rosak (%1): pulihkan fail daripada salinan (Palpate tidak membaikinya)</translation>
    </message>
    <message>
        <source>table %1 is missing</source>
        <translation>jadual %1 tiada</translation>
    </message>
    <message>
        <source>table %1 has no column %2</source>
        <translation>jadual %1 tiada lajur %2</translation>
    </message>
    <message>
        <source>the results schema is damaged (%1): the server&apos;s administrator restores it from a backup</source>
        <translation>skema keputusan rosak (%1): pentadbir pelayan memulihkannya daripada sandaran</translation>
    </message>
    <message>
        <source>the server did not answer within %1 s (the URL&apos;s statement_timeout sets the wait, docs/results-store.md)</source>
        <translation>pelayan tidak menjawab dalam %1 s (statement_timeout dalam URL menetapkan tempoh menunggu, docs/results-store.md)</translation>
    </message>
    <message>
        <source>statement_timeout must be 1 to %1 seconds</source>
        <translation>statement_timeout mestilah 1 hingga %1 saat</translation>
    </message>
    <message>
        <source>is read-only and of schema version %1 (this build reads %2): open it once where it can be written, to update it</source>
        <translation>hanya boleh dibaca dan berversi skema %1 (binaan ini membaca %2): buka sekali di tempat ia boleh ditulis untuk mengemas kininya</translation>
    </message>
    <message>
        <source>cannot be read or written (%1): is the disk full?</source>
        <translation>tidak boleh dibaca atau ditulis (%1): adakah cakera penuh?</translation>
    </message>
</context>
<context>
    <name>palpate::ResultsRoles</name>
    <message>
        <source>%1: roles exist on a PostgreSQL server only, not in an SQLite file</source>
        <translation>%1: peranan hanya wujud pada pelayan PostgreSQL, bukan dalam fail SQLite</translation>
    </message>
    <message>
        <source>role name &quot;%1&quot; is refused: letters, digits, _ . @ - only, starting with a letter or _</source>
        <translation>nama peranan &quot;%1&quot; ditolak: huruf, digit, _ . @ - sahaja, bermula dengan huruf atau _</translation>
    </message>
    <message>
        <source>a workstation needs a class (--class NAME)</source>
        <translation>stesen kerja memerlukan kelas (--class NAME)</translation>
    </message>
    <message>
        <source>role %1 is refused: it is a built-in or group role, not a workstation&apos;s or an instructor&apos;s login (CREATE ROLE name LOGIN makes one)</source>
        <translation>peranan %1 ditolak: ia peranan terbina dalam atau peranan kumpulan, bukan log masuk stesen kerja atau pengajar (CREATE ROLE name LOGIN membuatnya)</translation>
    </message>
</context>
<context>
    <name>palpate::SaveFileChoice</name>
    <message>
        <source>Replace the file?</source>
        <translation>Ganti fail?</translation>
    </message>
    <message>
        <source>%1 already exists. Replace it?</source>
        <translation>%1 sudah wujud. Gantikannya?</translation>
    </message>
</context>
<context>
    <name>palpate::SceneOverlay</name>
    <message>
        <source>rest shape</source>
        <translation>bentuk rehat</translation>
    </message>
    <message>
        <source>touched</source>
        <translation>disentuh</translation>
    </message>
    <message>
        <source>ring %1</source>
        <translation>gelang %1</translation>
    </message>
    <message>
        <source>dent %1 mm deep</source>
        <translation>lekuk sedalam %1 mm</translation>
    </message>
</context>
<context>
    <name>palpate::ScoreCard</name>
    <message>
        <source>Score</source>
        <translation>Markah</translation>
    </message>
    <message>
        <source>Metric</source>
        <translation>Metrik</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Nilai</translation>
    </message>
    <message>
        <source>Sub-score</source>
        <translation>Sub-markah</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Mata</translation>
    </message>
    <message>
        <source>Export PDF…</source>
        <translation>Eksport PDF…</translation>
    </message>
    <message>
        <source>History…</source>
        <translation>Sejarah…</translation>
    </message>
    <message>
        <source>No score yet: run an exercise.</source>
        <translation>Belum ada markah: jalankan latihan.</translation>
    </message>
    <message>
        <source>completed</source>
        <translation>selesai</translation>
    </message>
    <message>
        <source>time up</source>
        <translation>masa tamat</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>dihentikan</translation>
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
        <translation>tidak diberi markah</translation>
    </message>
    <message>
        <source>Stopped: %1 points so far, not a score</source>
        <translation>Dihentikan: %1 mata setakat ini, bukan skor</translation>
    </message>
</context>
<context>
    <name>palpate::ScoreReportPdf</name>
    <message>
        <source>Time (s)</source>
        <translation>Masa (s)</translation>
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
        <translation>tidak dapat ditulis: folder %1 tidak wujud</translation>
    </message>
    <message>
        <source>Palpate score report</source>
        <translation>Laporan markah Palpate</translation>
    </message>
    <message>
        <source>Score: %1 / 100</source>
        <translation>Markah: %1 / 100</translation>
    </message>
    <message>
        <source>Metric</source>
        <translation>Metrik</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Nilai</translation>
    </message>
    <message>
        <source>Sub-score</source>
        <translation>Sub-markah</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Pemberat</translation>
    </message>
    <message>
        <source>Contribution</source>
        <translation>Sumbangan</translation>
    </message>
    <message>
        <source>n/a</source>
        <translation>t/b</translation>
    </message>
    <message>
        <source>Warning: %1</source>
        <translation>Amaran: %1</translation>
    </message>
    <message>
        <source>Force over time</source>
        <translation>Daya mengikut masa</translation>
    </message>
    <message>
        <source>%1 – %2 N</source>
        <translation>%1 – %2 N</translation>
    </message>
    <message>
        <source>%1 (continued)</source>
        <translation>%1 (sambungan)</translation>
    </message>
    <message>
        <source>Palpate score report, page %1</source>
        <translation>Laporan markah Palpate, halaman %1</translation>
    </message>
    <message>
        <source>Target %1</source>
        <translation>Sasaran %1</translation>
    </message>
    <message>
        <source>Force band</source>
        <translation>Jalur daya</translation>
    </message>
    <message>
        <source>T%1</source>
        <translation>S%1</translation>
    </message>
    <message>
        <source>completed in %1 s</source>
        <translation>selesai dalam %1 s</translation>
    </message>
    <message>
        <source>time limit reached (%1 s)</source>
        <translation>had masa dicapai (%1 s)</translation>
    </message>
    <message>
        <source>not finished (%1 s scored)</source>
        <translation>tidak selesai (%1 s dinilai)</translation>
    </message>
    <message>
        <source>not recorded</source>
        <translation>tidak direkodkan</translation>
    </message>
    <message>
        <source>Exercise:</source>
        <translation>Latihan:</translation>
    </message>
    <message>
        <source>(unnamed)</source>
        <translation>(tanpa nama)</translation>
    </message>
    <message>
        <source>Trainee:</source>
        <translation>Pelatih:</translation>
    </message>
    <message>
        <source>Date:</source>
        <translation>Tarikh:</translation>
    </message>
    <message>
        <source>Device:</source>
        <translation>Peranti:</translation>
    </message>
    <message>
        <source>Result:</source>
        <translation>Keputusan:</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>achieved at %1 s</source>
        <translation>dicapai pada %1 s</translation>
    </message>
    <message>
        <source>not achieved</source>
        <translation>tidak dicapai</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>Targets</source>
        <translation>Sasaran</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Sasaran</translation>
    </message>
    <message>
        <source>Force window</source>
        <translation>Tetingkap daya</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Tahan</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Keputusan</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Ralat</translation>
    </message>
    <message>
        <source>On target</source>
        <translation>Pada sasaran</translation>
    </message>
    <message>
        <source>In window</source>
        <translation>Dalam tetingkap</translation>
    </message>
    <message>
        <source>Shaded: each target&apos;s own force window, over the time it was the target to press.</source>
        <translation>Berlorek: tetingkap daya setiap sasaran, sepanjang masa ia menjadi sasaran untuk ditekan.</translation>
    </message>
    <message>
        <source>Shaded: the force band to keep while tracing.</source>
        <translation>Berlorek: jalur daya yang perlu dikekalkan semasa menjejak.</translation>
    </message>
    <message>
        <source>Breakdown</source>
        <translation>Pecahan</translation>
    </message>
    <message>
        <source>cannot be written: it is a folder</source>
        <translation>tidak boleh ditulis: ia ialah folder</translation>
    </message>
    <message>
        <source>cannot be drawn (the PDF writer did not start)</source>
        <translation>tidak boleh dilukis (penulis PDF tidak bermula)</translation>
    </message>
    <message>
        <source>cannot be drawn</source>
        <translation>tidak boleh dilukis</translation>
    </message>
    <message>
        <source>cannot be drawn (empty document)</source>
        <translation>tidak boleh dilukis (dokumen kosong)</translation>
    </message>
    <message>
        <source>Palpate score report, page %1 of %2</source>
        <translation>Laporan markah Palpate, halaman %1 daripada %2</translation>
    </message>
    <message>
        <source>Palpation</source>
        <translation>Palpasi</translation>
    </message>
    <message>
        <source>Lump %1</source>
        <translation>Ketulan %1</translation>
    </message>
    <message>
        <source>%1 x</source>
        <translation>%1 kali</translation>
    </message>
    <message>
        <source>found</source>
        <translation>ditemui</translation>
    </message>
    <message>
        <source>missed</source>
        <translation>terlepas</translation>
    </message>
    <message>
        <source>Lumps</source>
        <translation>Ketulan</translation>
    </message>
    <message>
        <source>Lump</source>
        <translation>Ketulan</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>Kedalaman</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Jejari</translation>
    </message>
    <message>
        <source>Contrast</source>
        <translation>Kontras</translation>
    </message>
    <message>
        <source>Off by</source>
        <translation>Tersasar</translation>
    </message>
    <message>
        <source>%1 N</source>
        <translation>%1 N</translation>
    </message>
    <message>
        <source>Search</source>
        <translation>Carian</translation>
    </message>
    <message>
        <source>Force by phase</source>
        <translation>Daya mengikut fasa</translation>
    </message>
    <message>
        <source>Phase</source>
        <translation>Fasa</translation>
    </message>
    <message>
        <source>10th pct.</source>
        <translation>Pers. ke-10</translation>
    </message>
    <message>
        <source>Median</source>
        <translation>Median</translation>
    </message>
    <message>
        <source>90th pct.</source>
        <translation>Pers. ke-90</translation>
    </message>
    <message>
        <source>Largest</source>
        <translation>Terbesar</translation>
    </message>
    <message>
        <source>Ticks</source>
        <translation>Detik</translation>
    </message>
    <message>
        <source>the side examined most</source>
        <translation>sisi yang paling banyak diperiksa</translation>
    </message>
    <message>
        <source>the opposite side</source>
        <translation>sisi bertentangan</translation>
    </message>
    <message>
        <source>examined at %1 to %2 N (largest force); grey: not examined</source>
        <translation>diperiksa pada %1 hingga %2 N (daya terbesar); kelabu: tidak diperiksa</translation>
    </message>
    <message>
        <source>Surface examined</source>
        <translation>Permukaan diperiksa</translation>
    </message>
</context>
<context>
    <name>palpate::SpeedAccuracyChart</name>
    <message>
        <source>No sweep yet</source>
        <translation>Belum ada sapuan</translation>
    </message>
    <message>
        <source>Slope&amp;#8209;ring, rings:</source>
        <translation>Gelang&amp;#8209;cerun, gelang:</translation>
    </message>
    <message>
        <source>Paper (2 rings):</source>
        <translation>Kertas kerja (2 gelang):</translation>
    </message>
    <message>
        <source>Other models:</source>
        <translation>Model lain:</translation>
    </message>
    <message>
        <source>Pareto front (dashed)</source>
        <translation>Hadapan Pareto (putus-putus)</translation>
    </message>
    <message>
        <source>in use</source>
        <translation>digunakan</translation>
    </message>
    <message>
        <source>Sphere</source>
        <translation>Sfera</translation>
    </message>
    <message>
        <source>Stomach</source>
        <translation>Perut</translation>
    </message>
    <message>
        <source>Pareto</source>
        <translation>Pareto</translation>
    </message>
    <message>
        <source>Tick cost (µs, log)</source>
        <translation>Kos tik (µs, log)</translation>
    </message>
    <message>
        <source>Haptic tick cost (µs, log scale)</source>
        <translation>Kos tik haptik (µs, skala log)</translation>
    </message>
    <message>
        <source>error vs. the flat punch: RMS / peak over r ≤ 5a</source>
        <translation>ralat berbanding penebuk rata: RMS / puncak ke atas r ≤ 5a</translation>
    </message>
    <message>
        <source>E = %1 kPa, ν = %2, tool radius a = %3 mm</source>
        <translation>E = %1 kPa, ν = %2, jejari alat a = %3 mm</translation>
    </message>
    <message>
        <source>%1: speed against accuracy</source>
        <translation>%1: kelajuan berbanding ketepatan</translation>
    </message>
    <message>
        <source>Displacement error (%)</source>
        <translation>Ralat anjakan (%)</translation>
    </message>
    <message>
        <source>%1, %2 %3 vertices
tick %4 µs, displacement error %5 %, force error %6 %%7</source>
        <translation>%1, %2 %3 bucu
tik %4 µs, ralat anjakan %5 %, ralat daya %6 %%7</translation>
    </message>
    <message>
        <source>on the Pareto front</source>
        <translation>pada hadapan Pareto</translation>
    </message>
    <message>
        <source>Pareto front</source>
        <translation>Hadapan Pareto</translation>
    </message>
    <message>
        <source>current configuration</source>
        <translation>konfigurasi semasa</translation>
    </message>
    <message>
        <source>%1 stiffening</source>
        <translation>%1 mengeras</translation>
    </message>
    <message>
        <source>error vs. the filled organ&apos;s linear FEM at its %1 site:</source>
        <translation>ralat berbanding FEM linear organ yang diisi di tapak %1:</translation>
    </message>
    <message>
        <source>RMS / peak over r ≤ 5a</source>
        <translation>RMS / puncak atas r ≤ 5a</translation>
    </message>
</context>
<context>
    <name>palpate::StiffeningPanel</name>
    <message>
        <source>The tissue changed: press Compute for its curve.</source>
        <translation>Tisu berubah: tekan Kira untuk lengkungnya.</translation>
    </message>
    <message>
        <source>Cannot compute: %1</source>
        <translation>Tidak dapat mengira: %1</translation>
    </message>
    <message>
        <source>Pressing the hyperelastic half-space to %1 mm…</source>
        <translation>Menekan separuh ruang hiperelastik hingga %1 mm…</translation>
    </message>
    <message>
        <source>The reference could not be computed: %1</source>
        <translation>Rujukan tidak dapat dikira: %1</translation>
    </message>
    <message>
        <source>Press Compute: the hyperelastic reference is solved for this tissue (a few seconds).</source>
        <translation>Tekan Kira: rujukan hiperelastik diselesaikan untuk tisu ini (beberapa saat).</translation>
    </message>
    <message>
        <source>Depth of the tissue under the tool (mm)</source>
        <translation>Kedalaman tisu di bawah alat (mm)</translation>
    </message>
    <message>
        <source>Force (N)</source>
        <translation>Daya (N)</translation>
    </message>
    <message>
        <source>At %1 mm the reference is %2 times the linear force: the linear model is %3 % low there, the %4 knots are within %5 % everywhere on the curve%6.</source>
        <translation>Pada %1 mm rujukan ialah %2 kali daya linear: model linear %3 % terlalu rendah di situ, %4 simpulan berada dalam %5 % di seluruh lengkung%6.</translation>
    </message>
    <message>
        <source> (the solve stopped early: %1)</source>
        <translation> (penyelesaian berhenti awal: %1)</translation>
    </message>
    <message>
        <source>Press &amp;to:</source>
        <translation>Tekan &amp;hingga:</translation>
    </message>
    <message>
        <source>How deep the hyperelastic punch goes (0.1 to 1.5 tool radii).</source>
        <translation>Sedalam mana penebuk hiperelastik menekan (0.1 hingga 1.5 jejari alat).</translation>
    </message>
    <message>
        <source>&amp;Compute</source>
        <translation>&amp;Kira</translation>
    </message>
    <message>
        <source>Solve the hyperelastic reference for this tissue (a flat punch of the tool&apos;s radius, a few seconds) and fit the stiffening knots to it.</source>
        <translation>Selesaikan rujukan hiperelastik untuk tisu ini (penebuk rata sebesar jejari alat, beberapa saat) dan padankan simpulan pengerasan kepadanya.</translation>
    </message>
    <message>
        <source>Force against depth</source>
        <translation>Daya berbanding kedalaman</translation>
    </message>
    <message>
        <source>E = %1 kPa, ν = %2, a = %3 mm, %4 (b = %5)</source>
        <translation>E = %1 kPa, ν = %2, a = %3 mm, %4 (b = %5)</translation>
    </message>
    <message>
        <source>Hyperelastic FEM</source>
        <translation>FEM hiperelastik</translation>
    </message>
    <message>
        <source>Linear model</source>
        <translation>Model linear</translation>
    </message>
    <message>
        <source>1 knot</source>
        <translation>1 simpulan</translation>
    </message>
    <message>
        <source>%1 knots</source>
        <translation>%1 simpulan</translation>
    </message>
    <message>
        <source>the preset&apos;s knot</source>
        <translation>simpulan praset</translation>
    </message>
    <message>
        <source>the preset&apos;s %1 knots</source>
        <translation>%1 simpulan praset</translation>
    </message>
    <message>
        <source>The knots do not fit these slopes: %1</source>
        <translation>Simpulan tidak sesuai dengan cerun ini: %1</translation>
    </message>
    <message>
        <source>&amp;Apply knots</source>
        <translation>&amp;Guna simpulan</translation>
    </message>
    <message>
        <source>Put these knots into the tissue in use (Parameters: one step to undo) and apply it: the model stiffens as the reference does. The mesh and the rings stay as they are.</source>
        <translation>Masukkan simpulan ini ke dalam tisu yang digunakan (Parameter: satu langkah untuk buat asal) dan gunakannya: model mengeras seperti rujukan. Jejaring dan gelang kekal seperti sedia ada.</translation>
    </message>
</context>
<context>
    <name>palpate::TraineePanel</name>
    <message>
        <source>Trainee</source>
        <translation>Pelatih</translation>
    </message>
    <message>
        <source>New…</source>
        <translation>Baharu…</translation>
    </message>
    <message>
        <source>Add a trainee</source>
        <translation>Tambah pelatih</translation>
    </message>
    <message>
        <source>Trainee:</source>
        <translation>Pelatih:</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Latihan</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Buka…</translation>
    </message>
    <message>
        <source>Choose an exercise file</source>
        <translation>Pilih fail latihan</translation>
    </message>
    <message>
        <source>Exercise:</source>
        <translation>Latihan:</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Mula</translation>
    </message>
    <message>
        <source>Start the exercise (F6)</source>
        <translation>Mulakan latihan (F6)</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Henti</translation>
    </message>
    <message>
        <source>End the exercise now and score it (Shift+F6)</source>
        <translation>Tamatkan latihan sekarang dan beri markah (Shift+F6)</translation>
    </message>
    <message>
        <source>Mark</source>
        <translation>Tanda</translation>
    </message>
    <message>
        <source>Mark the lump where the tool presses now (M)</source>
        <translation>Tandakan ketulan di tempat alat menekan sekarang (M)</translation>
    </message>
    <message>
        <source>Choose a trainee and an exercise, then Start (F6).</source>
        <translation>Pilih pelatih dan latihan, kemudian Mula (F6).</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>Sedang bermula…</translation>
    </message>
    <message>
        <source>Time left %1 s · score so far %2</source>
        <translation>Baki masa %1 s · markah setakat ini %2</translation>
    </message>
    <message>
        <source>%1 (preview, not saved)</source>
        <translation>%1 (pratonton, tidak disimpan)</translation>
    </message>
    <message>
        <source>Finish</source>
        <translation>Tamat</translation>
    </message>
    <message>
        <source>End the examination: every lump you found is marked (F7)</source>
        <translation>Tamatkan pemeriksaan: setiap ketulan yang ditemui telah ditanda (F7)</translation>
    </message>
    <message>
        <source>E&amp;xpert reference session</source>
        <translation>Sesi rujukan pa&amp;kar</translation>
    </message>
    <message>
        <source>An instructor&apos;s session: stored as an expert&apos;s, it sets the exercise&apos;s pass marks (expert mean ± 2 SD) and moves no staircase</source>
        <translation>Sesi pengajar: disimpan sebagai sesi pakar, ia menetapkan markah lulus latihan (purata pakar ± 2 SP) dan tidak menggerakkan tangga</translation>
    </message>
    <message>
        <source>Time left %1 s · score at Finish</source>
        <translation>Baki masa %1 s · markah apabila Tamat</translation>
    </message>
    <message>
        <source>%1 (in %2)</source>
        <translation>%1 (dalam %2)</translation>
    </message>
</context>
<context>
    <name>palpate::WelcomePage</name>
    <message>
        <source>Welcome to Palpate</source>
        <translation>Selamat Datang ke Palpate</translation>
    </message>
    <message>
        <source>&lt;h2&gt;Welcome to Palpate&lt;/h2&gt;</source>
        <translation>&lt;h2&gt;Selamat Datang ke Palpate&lt;/h2&gt;</translation>
    </message>
    <message>
        <source>Palpate lets you feel a soft tissue model through a haptic device, or with the mouse. Here are four things to try first; you find this page again under Help &gt; Welcome, and the user guide under Help &gt; User Guide (F1).</source>
        <translation>Palpate membolehkan anda merasai model tisu lembut melalui peranti haptik, atau dengan tetikus. Berikut empat perkara untuk dicuba dahulu; halaman ini boleh ditemui semula di bawah Bantuan &gt; Selamat Datang, dan panduan pengguna di bawah Bantuan &gt; Panduan Pengguna (F1).</translation>
    </message>
    <message>
        <source>Open the sample scene</source>
        <translation>Buka adegan contoh</translation>
    </message>
    <message>
        <source>The stomach wall model with its default tissue, ready to be pressed.</source>
        <translation>Model dinding perut dengan tisu lalainya, sedia untuk ditekan.</translation>
    </message>
    <message>
        <source>Try touch mode with the mouse</source>
        <translation>Cuba mod sentuh dengan tetikus</translation>
    </message>
    <message>
        <source>Left-drag presses the tissue, the wheel sets the depth; right-drag turns the view. No haptic device needed.</source>
        <translation>Seret kiri menekan tisu, roda menetapkan kedalaman; seret kanan memutar pandangan. Tiada peranti haptik diperlukan.</translation>
    </message>
    <message>
        <source>Run the example exercise</source>
        <translation>Jalankan latihan contoh</translation>
    </message>
    <message>
        <source>&quot;Press three targets&quot; as a preview: the Exercise dock guides you and scores the run (nothing is stored).</source>
        <translation>&quot;Tekan tiga sasaran&quot; sebagai pratonton: dok Latihan membimbing anda dan memberi markah (tiada apa-apa disimpan).</translation>
    </message>
    <message>
        <source>Read the user guide</source>
        <translation>Baca panduan pengguna</translation>
    </message>
    <message>
        <source>What every window, dock and menu does, with pictures.</source>
        <translation>Apa yang dilakukan oleh setiap tetingkap, dok dan menu, dengan gambar.</translation>
    </message>
    <message>
        <source>&amp;Don&apos;t show this again at start</source>
        <translation>&amp;Jangan tunjukkan lagi semasa mula</translation>
    </message>
</context>
</TS>
