// palpate-cli score --pdf: the printable report of a scored recording, read back with poppler's
// pdftotext -bbox-layout. Every text line must lie on its page and no two may overlap (the report
// was once unreadable: its lines printed on top of each other), also with long names and more
// targets than fit on a page; the per-target rows are there; the output never replaces an input and
// a failed run leaves an existing report as it was.
#include "engine/exercise/Metric.h"
#include "engine/record/RecordingReader.h"
#include "tests/record/RecordTestRig.h"
#include "tests/scoring/ScoringTestRig.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cctype>
#include <filesystem>
#include <regex>
#include <sstream>

namespace palpate {
namespace {

using test::runCli;
using test::shellQuote;

std::string exampleFile(const std::string& name) { return test::resourcesDir() + "/exercises/" + name; }

struct TextLine {
    double xMin = 0, yMin = 0, xMax = 0, yMax = 0;
    std::string text;  ///< its words, separated by single spaces
};

struct PdfPage {
    double width = 0, height = 0;
    std::vector<TextLine> lines;
};

/// The pages of `pdf` with their text lines, as pdftotext -bbox-layout finds them (points, origin
/// top left). Fails the test when pdftotext is missing or fails.
std::vector<PdfPage> readPdfLines(const std::string& pdf) {
    const auto result = test::runCommand("pdftotext -bbox-layout " + shellQuote(pdf) + " - 2>&1");
    if (result.exitCode != 0) {
        ADD_FAILURE() << "pdftotext -bbox-layout failed (it is in poppler-utils, scripts/install-deps.sh): "
                      << result.output;
        return {};
    }
    std::vector<PdfPage> pages;
    const std::regex page(R"re(<page width="([0-9.]+)" height="([0-9.]+)">)re");
    const std::regex line(R"re(<line xMin="([-0-9.]+)" yMin="([-0-9.]+)" xMax="([-0-9.]+)" yMax="([-0-9.]+)">)re");
    const std::regex word(R"re(<word [^>]*>([^<]*)</word>)re");
    std::istringstream in(result.output);
    std::string row;
    std::smatch m;
    TextLine* open = nullptr;
    while (std::getline(in, row)) {
        if (std::regex_search(row, m, page)) {
            pages.push_back({std::stod(m[1]), std::stod(m[2]), {}});
        } else if (std::regex_search(row, m, line) && !pages.empty()) {
            pages.back().lines.push_back({std::stod(m[1]), std::stod(m[2]), std::stod(m[3]), std::stod(m[4]), ""});
            open = &pages.back().lines.back();
        } else if (std::regex_search(row, m, word) && open) {
            if (!open->text.empty()) open->text += ' ';
            open->text += m[1].str();
        } else if (row.find("</line>") != std::string::npos) {
            open = nullptr;
        }
    }
    return pages;
}

/// Every line on its page, no two lines overlapping (by more than a hair: font boxes of adjacent
/// lines may touch). Returns the pages, for the checks on the content.
std::vector<PdfPage> expectReadable(const std::string& pdf) {
    const std::vector<PdfPage> pages = readPdfLines(pdf);
    EXPECT_FALSE(pages.empty()) << pdf;
    constexpr double kTouchPt = 0.5;
    for (std::size_t p = 0; p < pages.size(); ++p) {
        const PdfPage& page = pages[p];
        EXPECT_FALSE(page.lines.empty()) << "page " << p + 1 << " has no text";
        for (std::size_t i = 0; i < page.lines.size(); ++i) {
            const TextLine& a = page.lines[i];
            EXPECT_TRUE(a.xMin >= 0 && a.yMin >= 0 && a.xMax <= page.width && a.yMax <= page.height)
                << "page " << p + 1 << ": '" << a.text << "' [" << a.xMin << ", " << a.yMin << " .. " << a.xMax
                << ", " << a.yMax << "] leaves the page (" << page.width << " x " << page.height << ")";
            for (std::size_t j = i + 1; j < page.lines.size(); ++j) {
                const TextLine& b = page.lines[j];
                const double overlapX = std::min(a.xMax, b.xMax) - std::max(a.xMin, b.xMin);
                const double overlapY = std::min(a.yMax, b.yMax) - std::max(a.yMin, b.yMin);
                EXPECT_FALSE(overlapX > kTouchPt && overlapY > kTouchPt)
                    << "page " << p + 1 << ": '" << a.text << "' and '" << b.text << "' overlap by " << overlapX
                    << " x " << overlapY << " pt";
            }
        }
    }
    return pages;
}

/// The words of every page, one line of text a line.
std::string allText(const std::vector<PdfPage>& pages) {
    std::string text;
    for (const PdfPage& page : pages)
        for (const TextLine& l : page.lines) text += l.text + "\n";
    return text;
}

/// The row of the table that starts with `name` on `page` (pdftotext may join neighbouring cells
/// into one line, so a row is every line beside the first cell, left to right); "" when none.
std::string tableRow(const PdfPage& page, const std::string& name) {
    for (const TextLine& head : page.lines) {
        if (head.text != name && head.text.rfind(name + " ", 0) != 0) continue;
        std::vector<const TextLine*> row;
        for (const TextLine& cell : page.lines)
            if (cell.yMin < head.yMax && cell.yMax > head.yMin && cell.xMin >= head.xMin) row.push_back(&cell);
        std::sort(row.begin(), row.end(), [](const TextLine* a, const TextLine* b) { return a->xMin < b->xMin; });
        std::string text;
        for (const TextLine* cell : row) text += cell->text + " ";
        return text;
    }
    return {};
}

/// The per-target table: for each target a row "Target N ..." that says whether it was achieved
/// (as the JSON breakdown does).
void expectTargetRows(const std::vector<PdfPage>& pages, const nlohmann::json& targets) {
    for (std::size_t i = 0; i < targets.size(); ++i) {
        const std::string name = "Target " + std::to_string(i + 1);
        const bool achieved = targets[i]["achieved"].get<bool>();
        bool found = false;
        for (const PdfPage& page : pages) {
            const std::string row = tableRow(page, name);
            const bool saysAchieved = row.find("achieved at") != std::string::npos;
            const bool saysMissed = row.find("not achieved") != std::string::npos;
            found |= achieved ? saysAchieved && !saysMissed : saysMissed && !saysAchieved;
        }
        EXPECT_TRUE(found) << "no table row '" << name << " ... " << (achieved ? "achieved at" : "not achieved") << "'";
    }
}

std::string recordPressTargets(test::TempDir& dir) {
    const std::string path = dir.file("press.palprec");
    test::runScriptedSession(test::loadExampleExercise("press_targets"),
                             test::loadTraineeScript(exampleFile("press_targets.good.path")), path);
    return path;
}

TEST(ScoreReportPdf, ScoredRecordingIsReadable) {
    test::TempDir dir;
    const std::string recording = recordPressTargets(dir);
    const std::string pdf = dir.file("report.pdf");
    const auto r = runCli("score --exercise " + shellQuote(exampleFile("press_targets.json")) + " --recording " +
                          shellQuote(recording) + " --pdf " + shellQuote(pdf) + " --trainee 'Erika Mustermann' --json --db " +
                          shellQuote(dir.file("results.sqlite")));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // --trainee stores the result too (here in --db): the report and the stored row say the same.
    const auto stored = nlohmann::json::parse(r.output)["stored"];
    EXPECT_EQ(stored["trainee"], "Erika Mustermann");
    EXPECT_GT(stored["result_id"].get<long long>(), 0);
    EXPECT_TRUE(std::filesystem::exists(dir.file("results.sqlite")));
    const auto j = nlohmann::json::parse(r.output);
    ASSERT_EQ(j["targets"].size(), 3u);
    const std::vector<PdfPage> pages = expectReadable(pdf);
    expectTargetRows(pages, j["targets"]);
    const std::string text = allText(pages);
    EXPECT_NE(text.find("Erika Mustermann"), std::string::npos) << text;
    EXPECT_NE(text.find("Press three targets"), std::string::npos) << text;
    EXPECT_NE(text.find("sim:path:"), std::string::npos) << text;  // the device
    // Every metric of the score, by the name its row gives people ("Peak force").
    for (const auto& [key, value] : j["metrics"].items()) {
        const std::optional<Metric> metric = parseMetric(key);
        ASSERT_TRUE(metric) << key;
        std::string name = metricRow(*metric).name;
        name[0] = char(std::toupper(static_cast<unsigned char>(name[0])));
        EXPECT_NE(text.find(name), std::string::npos) << name;
    }

    // The plot labels each target's own window (not only the last one's) over its own time: the
    // labels go left to right in target order, and a higher window's label sits higher.
    const auto exercise = nlohmann::json::parse(test::readBytes(exampleFile("press_targets.json")))["press_targets"];
    std::vector<const TextLine*> labels;
    for (std::size_t i = 0; i < exercise["targets"].size(); ++i) {
        const auto& t = exercise["targets"][i];
        char label[96];
        std::snprintf(label, sizeof label, "Target %zu: %.1f – %.1f N", i + 1,
                      t.value("force_min_n", exercise["force_min_n"].get<double>()),
                      t.value("force_max_n", exercise["force_max_n"].get<double>()));
        const TextLine* found = nullptr;
        for (const PdfPage& page : pages)
            for (const TextLine& l : page.lines)
                if (l.text == label) found = &l;
        EXPECT_TRUE(found) << "no plot label '" << label << "'";
        if (found) labels.push_back(found);
    }
    ASSERT_EQ(labels.size(), 3u);
    EXPECT_LT(labels[0]->xMax, labels[1]->xMin);
    EXPECT_LT(labels[1]->xMax, labels[2]->xMin);
    EXPECT_LT(labels[2]->yMax, labels[1]->yMin);  // [1.5, 2.5] N above [1, 2] N
    // Nothing left beside the report (it is written to a temporary file and renamed) and the
    // database it was stored in.
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::directory_iterator(dir.path())) files.push_back(e.path().filename().string());
    std::sort(files.begin(), files.end());
    EXPECT_EQ(files, (std::vector<std::string>{"press.palprec", "report.pdf", "results.sqlite"}));
}

TEST(ScoreReportPdf, ADetectLumpsReportHasTheLumpsTheSurfaceExaminedAndTheForceByPhase) {
    test::TempDir dir;
    const std::string recording = dir.file("lumps.palprec");
    test::runScriptedSession(test::loadExampleExercise("detect_lumps"),
                             test::loadTraineeScript(exampleFile("detect_lumps.light.path")), recording);
    const std::string pdf = dir.file("lumps.pdf");
    const auto r = runCli("score --recording " + shellQuote(recording) + " --pdf " + shellQuote(pdf) + " --trainee Di --no-store");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::vector<PdfPage> pages = expectReadable(pdf);  // nothing overlaps, every line on its page
    const std::string text = allText(pages);
    for (const char* wanted : {"Palpation", "Lumps", "Lump 3", "missed", "8.0 mm", "Surface examined",
                               "the side examined most", "Force by phase", "Pressed too lightly",
                               "Lumps found: 2 of 3"})
        EXPECT_NE(text.find(wanted), std::string::npos) << wanted << " in\n" << text;
}

TEST(ScoreReportPdf, LongNamesAndManyTargetsStayReadable) {
    test::TempDir dir;
    const std::string recording = recordPressTargets(dir);
    // The same exercise with a long name (and a word longer than the page is wide) and more
    // targets than fit on one page.
    auto e = nlohmann::json::parse(test::readBytes(exampleFile("press_targets.json")));
    const std::string longWord(90, 'W');
    e["name"] = "Press a great many targets on the front of the stomach, one after the other, each inside its "
                "own force window " + longWord;
    auto& targets = e["press_targets"]["targets"];
    const nlohmann::json three = targets;
    for (int i = 0; i < 40; ++i) {
        auto t = three[std::size_t(i % 3)];
        t["force_min_n"] = 0.5 + 0.05 * i;
        t["force_max_n"] = 1.5 + 0.05 * i;
        targets.push_back(t);
    }
    const std::string exercise = dir.file("many.json");
    {
        const std::string text = e.dump();
        test::writeBytes(exercise, std::vector<std::uint8_t>(text.begin(), text.end()));
    }
    const std::string pdf = dir.file("long.pdf");
    const std::string trainee = "Maria Magdalena Josefina von und zu Hohenberg-Schwarzenfeld-Lichtenstein";
    const auto r = runCli("score --exercise " + shellQuote(exercise) + " --recording " + shellQuote(recording) +
                          " --pdf " + shellQuote(pdf) + " --trainee " + shellQuote(trainee) + " --json --no-store");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    ASSERT_EQ(j["targets"].size(), 43u);
    const std::vector<PdfPage> pages = expectReadable(pdf);
    expectTargetRows(pages, j["targets"]);
    EXPECT_GT(pages.size(), 1u) << "43 targets fit on one page?";
    const std::string text = allText(pages);
    for (const char* word : {"Maria", "Hohenberg-Schwarzenfeld-Lichtenstein", "Press", "great", "window"})
        EXPECT_NE(text.find(word), std::string::npos) << word;
}

// Names no one would choose, as an attacker or a broken import writes them: a hundred lines, a word
// of 5000 letters, stacks of combining marks. Every line stays on its page and none overlaps.
TEST(ScoreReportPdf, HostileNamesStayOnThePage) {
    test::TempDir dir;
    const std::string recording = recordPressTargets(dir);
    auto e = nlohmann::json::parse(test::readBytes(exampleFile("press_targets.json")));
    std::string hundredLines;
    for (int i = 0; i < 100; ++i) hundredLines += "line " + std::to_string(i + 1) + " of the name\n";
    std::string zalgo;
    for (int i = 0; i < 40; ++i) zalgo += "Z\u0351\u036b\u0343\u036a\u0302\u036b\u033d\u034f\u0334\u0319";
    const std::vector<std::pair<std::string, std::string>> names = {
        {hundredLines, "Trainee\nwith\nlines"}, {std::string(5000, 'W'), std::string(5000, 'M')}, {zalgo, zalgo}};
    for (std::size_t n = 0; n < names.size(); ++n) {
        e["name"] = names[n].first;
        const std::string exercise = dir.file("hostile" + std::to_string(n) + ".json");
        const std::string text = e.dump();
        test::writeBytes(exercise, std::vector<std::uint8_t>(text.begin(), text.end()));
        const std::string pdf = dir.file("hostile" + std::to_string(n) + ".pdf");
        const auto r = runCli("score --exercise " + shellQuote(exercise) + " --recording " + shellQuote(recording) +
                              " --pdf " + shellQuote(pdf) + " --trainee " + shellQuote(names[n].second) +
                              " --no-store");
        ASSERT_EQ(r.exitCode, 0) << r.output;
        SCOPED_TRACE("names " + std::to_string(n));
        const std::vector<PdfPage> pages = expectReadable(pdf);
        // The score and the targets' table are still there.
        const std::string all = allText(pages);
        EXPECT_NE(all.find("Score"), std::string::npos);
        EXPECT_NE(all.find("Target"), std::string::npos);
    }
}

TEST(ScoreReportPdf, NeverOverwritesAnInputAndFailsCleanly) {
    test::TempDir dir;
    const std::string recording = recordPressTargets(dir);
    const std::string exercise = dir.file("press.json");
    std::filesystem::copy_file(exampleFile("press_targets.json"), exercise);
    const auto recordingBytes = test::readBytes(recording);
    const auto exerciseBytes = test::readBytes(exercise);
    const std::string base = "score --exercise " + shellQuote(exercise) + " --recording " + shellQuote(recording);
    // The recording and the exercise, also spelt another way.
    for (const std::string& input : {recording, dir.file("./press.palprec"), exercise}) {
        const auto r = runCli(base + " --pdf " + shellQuote(input));
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find("never written over an input"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(input), std::string::npos) << r.output;
    }
    EXPECT_EQ(test::readBytes(recording), recordingBytes);
    EXPECT_EQ(test::readBytes(exercise), exerciseBytes);

    // A folder that is not there; a folder where the file should go.
    const std::string nowhere = dir.file("no/such/folder/report.pdf");
    auto r = runCli(base + " --pdf " + shellQuote(nowhere));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(nowhere), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("no")));
    std::filesystem::create_directory(dir.file("folder.pdf"));
    r = runCli(base + " --pdf " + shellQuote(dir.file("folder.pdf")));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("folder.pdf"), std::string::npos) << r.output;

    // A report that is there stays as it was when a later run fails (an exercise on another mesh).
    const std::string pdf = dir.file("report.pdf");
    ASSERT_EQ(runCli(base + " --pdf " + shellQuote(pdf)).exitCode, 0);
    const auto pdfBytes = test::readBytes(pdf);
    r = runCli("score --exercise " + shellQuote(exampleFile("find_lump.json")) + " --recording " + shellQuote(recording) +
               " --pdf " + shellQuote(pdf));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_EQ(test::readBytes(pdf), pdfBytes);
    // --no-store only names the trainee on a --pdf report; --local is where a result waits for a server.
    EXPECT_EQ(runCli(base + " --trainee X --no-store").exitCode, 2);
    EXPECT_EQ(runCli(base + " --pdf " + shellQuote(pdf) + " --no-store").exitCode, 2);
    EXPECT_EQ(runCli(base + " --trainee X --local " + shellQuote(dir.file("l.sqlite"))).exitCode, 2);
    EXPECT_FALSE(std::filesystem::exists(dir.file("l.sqlite")));
    // Nor is the report written over the database the result goes to.
    const std::string db = dir.file("results.sqlite");
    ASSERT_EQ(runCli(base + " --trainee X --db " + shellQuote(db)).exitCode, 0);
    const auto dbBytes = test::readBytes(db);
    const auto over = runCli(base + " --trainee X --db " + shellQuote(db) + " --pdf " + shellQuote(db));
    EXPECT_EQ(over.exitCode, 2);
    EXPECT_NE(over.output.find("results database"), std::string::npos) << over.output;
    EXPECT_EQ(test::readBytes(db), dbBytes);
}

}  // namespace
}  // namespace palpate
