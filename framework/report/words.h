#pragma once
// Every sentence of the report, in one table per language (a message catalogue can take them over
// as they are), and the numbers written by the language's typography.

#include <string>

namespace raylab::report {

struct Words {
    const char* lang;
    const char* title;
    const char* intro;
    const char* name;
    const char* group;
    const char* course;
    const char* date;
    const char* total;
    const char* totalDetail; // "%s / %s function checks, %s / %s figures"
    const char* lab;
    const char* figure;
    const char* picturesRow; // the names of the pictures in a figure's row
    const char* renderTime;
    const char* scaleReading;
    const char* statisticalReading;
    const char* noDifference;
    const char* grade;
    const char* yourText;
    const char* yourTextHint;
    const char* comparison;
    const char* comparisonIntro;
    const char* aliased;
    const char* antialiased;
    const char* cost; // "%s: %s samples per pixel, %s rays, %s"
    const char* closeUp; // "Close-up: pixels x %s to %s, y %s to %s of the %s x %s picture, each enlarged %s times."
    const char* kept;
    const char* keptIntro;
    const char* keptFrom; // "From the section %s:"
    const char* editedGenerated; // "Your edit of the generated part %s:"
    const char* fullReport;
    const char* colon; // ": " or " : " with a no-break space
    const char* fillTitleBlock; // a note when report.toml still holds its placeholders
    const char* tomlTemplate;   // report.toml as created on the first run
};

// English unless `lang` is "fr".
const Words& wordsFor(const std::string& lang);

// `value` with `digits` decimals (-1: the shortest exact form), a decimal comma in French.
std::string number(double value, int digits, const Words& words);

// "0.005 s", "0,005 s".
std::string seconds(double value, const Words& words);

// printf's %s for each `args` in `format` (the tables' sentences hold %s only).
std::string fill(const char* format, std::initializer_list<std::string> args);

} // namespace raylab::report
