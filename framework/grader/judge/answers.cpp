#include "grader/judge/answers.h"

#include "src/messages.h"
#include "raylab/todo.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace raylab::grader {

namespace {

// An answer of the right type and size for the item, judged; false when it is a protocol violation.
bool accept(Ledger& ledger, Item& item, const protocol::Answer& answer, std::string& violation) {
    if (const auto* todo = std::get_if<protocol::NotDone>(&answer)) {
        const std::string message = NotDoneYet(todo->lab, todo->function, todo->file, todo->line).what();
        const int stubLab = std::atoi(todo->lab.c_str() + std::min(todo->lab.size(), todo->lab.find_last_of(' ') + 1)); // "lab 3"
        if (item.check)
            ledger.resolveCheck(item, false, message, stubLab);
        else
            ledger.resolveFigure(item, RenderedFigure{std::nullopt, message, stubLab});
        return true;
    }
    if (const auto* failure = std::get_if<protocol::Failure>(&answer)) {
        if (item.check)
            ledger.resolveCheck(item, false, tr("grade.threw", {{"what", failure->message}}));
        else
            ledger.resolveFigure(item, RenderedFigure{std::nullopt, tr("grade.render_failed", {{"what", failure->message}})});
        return true;
    }
    if (item.figure) {
        const auto* picture = std::get_if<protocol::Picture>(&answer);
        if (!picture) {
            violation = "a figure was answered with something other than a picture";
            return false;
        }
        ledger.resolveFigure(item, RenderedFigure{Image8{picture->width, picture->height, picture->rgb}, ""});
        return true;
    }
    const auto* values = std::get_if<protocol::Values>(&answer);
    if (!values) {
        violation = "a function check was answered with something other than values";
        return false;
    }
    const std::vector<protocol::Call>& calls = item.check->calls;
    if (values->outputs.size() != calls.size()) {
        violation = std::to_string(values->outputs.size()) + " outputs for " + std::to_string(calls.size()) + " calls";
        return false;
    }
    for (std::size_t k = 0; k < calls.size(); ++k)
        if (!calls[k].probe->fits(values->outputs[k])) {
            violation = "the output of " + calls[k].probe->name + " is not of its probe's shape";
            return false;
        }
    // A check whose message is broken (a placeholder without a value: the course's mistake) costs
    // that check alone, never the lab's other checks nor the other labs.
    try {
        Judge judge;
        item.check->judge(values->outputs, judge);
        ledger.resolveCheck(item, judge.passed(), judge.message());
    } catch (const std::logic_error& e) {
        ledger.resolveCheck(item, false, tr("grade.check_unjudged", {{"what", e.what()}}));
    }
    return true;
}

} // namespace

bool readRun(const std::vector<std::string>& lines, const std::vector<Item*>& sent,
             const std::map<std::uint64_t, Item*>& items, Ledger& ledger) {
    std::size_t next = 0; // the item whose answer is awaited
    bool hello = false;
    const auto awaited = [&]() -> Item& { return *sent[std::min(next, sent.size() - 1)]; };
    const auto violate = [&](Item& item, const std::string& reason) {
        const bool wasAwaited = &item == &awaited() && next < sent.size();
        ledger.fail(item, "protocol violation: " + reason);
        if (wasAwaited) ++next;
    };
    for (const std::string& line : lines) {
        if (sent.empty()) break;
        const protocol::Parsed<protocol::Answer> parsed = protocol::parseAnswer(line);
        if (!parsed.message) {
            violate(awaited(), parsed.error);
            continue;
        }
        const protocol::Answer& answer = *parsed.message;
        if (const auto* h = std::get_if<protocol::Hello>(&answer)) {
            if (hello || h->version != protocol::kVersion)
                violate(awaited(), hello ? "a second hello"
                                         : "protocol version " + std::to_string(h->version) + ", not " +
                                               std::to_string(protocol::kVersion));
            hello = true;
            continue;
        }
        if (std::holds_alternative<protocol::Done>(answer)) {
            if (next < sent.size()) violate(awaited(), "\"done\" before every item was answered");
            continue;
        }
        const std::uint64_t id = *protocol::itemOf(answer);
        const auto it = items.find(id);
        if (!hello)
            violate(it != items.end() ? *it->second : awaited(), "an answer before the hello");
        else if (it == items.end())
            violate(awaited(), "an answer for item " + std::to_string(id) + ", which does not exist");
        else if (it->second->resolved)
            violate(*it->second, "a second answer");
        else if (next >= sent.size() || it->second != sent[next])
            violate(*it->second, "an answer out of order");
        else {
            std::string violation;
            if (accept(ledger, *sent[next], answer, violation))
                ++next;
            else
                violate(*sent[next], violation);
        }
    }
    return hello;
}

} // namespace raylab::grader
