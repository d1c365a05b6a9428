#include "watch/page_document.h"

#include "watch/compiler_errors.h"

#include "src/messages.h"
#include "src/text.h"

#include <nlohmann/json.hpp>

namespace raylab::watch {

using Json = nlohmann::json;

namespace {

// The page's words in the reader's language: the catalogue's [watch.page] table.
Json pageWords() {
    Json words = Json::object();
    constexpr std::string_view prefix = "watch.page.";
    for (const auto& [id, text] : messageCatalogue(language()))
        if (id.starts_with(prefix)) words[id.substr(prefix.size())] = text;
    return words;
}

} // namespace

std::string pageDocument(const std::string& graded, const PageFacts& facts) {
    Json state = Json::parse(graded, nullptr, false);
    if (!state.is_object()) state = Json::object();
    // The grade shown is not of the code as saved: the latest save did not compile.
    const bool stale = !facts.buildOutput.empty();
    state["stale"] = stale;
    for (const char* list : {"figures", "checks"})
        if (state.contains(list) && state[list].is_array())
            for (Json& item : state[list]) item["stale"] = stale;
    state["lab"] = facts.lab;
    state["phase"] = facts.phase;
    state["language"] = languageCode(language());
    state["words"] = pageWords();
    Json changed = Json::array();
    for (const std::string& file : facts.changed) changed.push_back(printableText(file));
    state["changed"] = changed;
    Json errors = Json::array();
    for (const CompilerError& e : compilerErrors(facts.buildOutput, facts.sourceDir))
        errors.push_back({{"file", printableText(e.file)}, {"line", e.line}, {"column", e.column}, {"message", printableText(e.message)}});
    state["build"] = {{"errors", errors}, {"output", printableText(facts.buildOutput)}};
    state["seconds"] = {{"build", facts.buildSeconds}, {"grade", facts.gradeSeconds}};
    return jsonText(state);
}

std::string jsonText(const Json& value) { return value.dump(-1, ' ', false, Json::error_handler_t::replace); }

} // namespace raylab::watch
