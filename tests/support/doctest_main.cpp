// The test programs' main: doctest's, once the language of the messages is made English.
//
// The tests are written in English: each test of French chooses it itself (--lang fr, setLanguage, or
// a LANG of its own for a child). The locale of whoever runs the suite must not change what the others
// read: under LANG=fr_FR.UTF-8 a check of an English message would fail (issue 41). So the messages'
// variables are set as tests/grading/grade_commands.cpp's Locale("C") sets them (LC_ALL and
// LC_MESSAGES unset, LANG=C), for this program and the programs it starts, and the character set of
// the locale is kept in LC_CTYPE.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

namespace {

void setVariable(const char* name, const char* value) {
#ifdef _WIN32
    _putenv_s(name, value != nullptr ? value : "");
#else
    if (value != nullptr) ::setenv(name, value, 1);
    else ::unsetenv(name);
#endif
}

void messagesInEnglish() {
    std::string ctype;
    for (const char* variable : {"LC_ALL", "LC_CTYPE", "LANG"})
        if (const char* value = std::getenv(variable); value != nullptr && *value != '\0') {
            ctype = value;
            break;
        }
    if (!ctype.empty()) setVariable("LC_CTYPE", ctype.c_str());
    setVariable("LC_ALL", nullptr);
    setVariable("LC_MESSAGES", nullptr);
    setVariable("LANG", "C");
}

} // namespace

int main(int argc, char** argv) {
    messagesInEnglish();
    doctest::Context context(argc, argv);
    return context.run();
}
