// The class ledger's pieces: a safe folder name for any student name, one to one; CSV cells that a
// real CSV reader reads back as they were.
#include "grader/class_run.h"
#include "raylab/csv.h"
#include "support/read_csv.h"

#include <doctest/doctest.h>

#include <set>
#include <string>
#include <vector>

using raylab::grader::printableName;
using raylab::grader::safeStudentName;

namespace {

const std::vector<std::string> kHostileNames{
    "alice", "Alice", "x$(touch PWNED)", "back`tick`", "double\"quote", "single'quote", "with space", "-leading-dash",
    ".hidden", "..", "ünïcödé 名前", "a,b", "new\nline", "grades.csv", "build", "students", "%41", "A", "%", "a%2Cb",
    "tab\there", std::string("nul\0byte", 8), std::string(300, 'x'), std::string(300, 'x') + "y", std::string(200, '%'),
    std::string(200, '%') + "~"};

} // namespace

TEST_SUITE("class run") {

TEST_CASE("safe student names: one to one, file names of plain characters that no tool reads as an option") {
    std::set<std::string> seen;
    for (const std::string& name : kHostileNames) {
        const std::string safe = safeStudentName(name);
        CAPTURE(printableName(name));
        CAPTURE(safe);
        CHECK(seen.insert(safe).second);
        CHECK(!safe.empty());
        CHECK(safe.size() <= 160);
        CHECK(safe.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.%~") ==
              std::string::npos);
        CHECK(safe[0] != '-');
        CHECK(safe[0] != '.');
    }
    CHECK(safeStudentName("alice") == "alice"); // plain names stay readable
    CHECK(safeStudentName("a,b") == "a%2Cb");
    CHECK(safeStudentName("a%2Cb") == "a%252Cb");
}

TEST_CASE("printable names: one line, control characters shown") {
    CHECK(printableName("new\nline") == "new\\nline");
    CHECK(printableName("tab\there\x01") == "tab\\there\\x01");
    CHECK(printableName("ünïcödé") == "ünïcödé");
}

TEST_CASE("CSV lines read back by a CSV reader as the cells they were written from") {
    const std::vector<std::string> cells{"plain", "a,b", "double\"quote", "new\nline", "", " spaced ", "crlf\r\nx"};
    const auto rows = raylab::test::readCsv(raylab::csvLine(cells) + raylab::csvLine({"1", "2"}));
    REQUIRE(rows.size() == 2);
    CHECK(rows[0] == cells);
    CHECK(rows[1] == std::vector<std::string>{"1", "2"});
    CHECK(raylab::csvLine({"a", "b"}) == "a,b\n");
}

} // TEST_SUITE
