#pragma once
// The parent's side of one agent's runs: the items it started and what each came to. Each run's
// answers are read here, in order, one per item; anything else on the channel fails an item as a
// protocol violation with the reason (protocol.h).

#include "grader/judge/checks/checks.h"
#include "grader/judge/grade.h"
#include "grader/protocol/protocol.h"

#include "raylab/image_io.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace raylab::grader {

// A figure as the agent answered it: its pixels, or why there are none.
struct RenderedFigure {
    std::optional<Image8> image;
    std::string reason;
    int stubLab = 0; // the lab whose stub the render reached
    bool stopped = false; // the run ended without this answer (Ledger::fail)
};

// What an agent answered, over all its runs, judged.
struct Reported {
    std::map<std::string, CheckOutcome> checks;    // by name
    std::vector<std::string> order;                // the names in the order the checks ran
    std::map<std::string, RenderedFigure> figures; // by id
    std::vector<std::string> problems;
};

// One item the parent starts: a function check, or a figure to render.
struct Item {
    std::uint64_t id = 0;
    const FunctionCheck* check = nullptr;
    const FigureReference* figure = nullptr;
    bool resolved = false;
};

// Records what each item came to: its answer judged, or why it has none.
class Ledger {
public:
    explicit Ledger(Reported& reported) : m_reported(reported) {}

    void resolveCheck(Item& item, bool passed, const std::string& message, int stubLab = 0) {
        if (item.resolved) return;
        item.resolved = true;
        m_reported.order.push_back(item.check->id);
        m_reported.checks[item.check->id] = CheckOutcome{item.check->lab, item.check->id, passed, message, 0., 0., stubLab};
    }
    void resolveFigure(Item& item, RenderedFigure figure) {
        if (item.resolved) return;
        item.resolved = true;
        m_reported.figures[item.figure->id] = std::move(figure);
    }
    // The item fails with the reason. An item answered already fails too (a second answer undoes a
    // pass or a picture), but one that failed keeps its first reason.
    void fail(Item& item, const std::string& reason) {
        if (!item.resolved) {
            if (item.check) {
                resolveCheck(item, false, reason);
                m_reported.checks[item.check->id].stopped = true;
            } else {
                resolveFigure(item, RenderedFigure{std::nullopt, reason, 0, true});
            }
        } else if (item.check) {
            CheckOutcome& c = m_reported.checks[item.check->id];
            if (c.passed) c = CheckOutcome{c.lab, c.name, false, reason, 0., 0., 0, true};
        } else {
            RenderedFigure& f = m_reported.figures[item.figure->id];
            if (f.image) f = RenderedFigure{std::nullopt, reason, 0, true};
        }
    }

private:
    Reported& m_reported;
};

// Reads one run's answers: exactly one for each item it was sent (`sent`, in order), after a hello.
// Anything else fails the item it names (or the one awaited) as a protocol violation. `items`: every
// item of the agent by id. Returns whether the child said hello.
bool readRun(const std::vector<std::string>& lines, const std::vector<Item*>& sent,
             const std::map<std::uint64_t, Item*>& items, Ledger& ledger);

} // namespace raylab::grader
