#include "grader/judge/agent_session.h"

#include "src/messages.h"

#include <algorithm>
#include <random>

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

// The drawn cases come from a seed the child never sees: each grading draws new ones.
std::vector<FunctionCheck> freshlyDrawnChecks(const LabCatalog& labs) {
    return functionChecks(labs, (std::uint64_t(std::random_device{}()) << 32) ^ std::random_device{}());
}

// The checks, then the figures, of the plan's lab (of every lab for plan.lab 0), numbered from 1.
std::vector<Item> itemsOf(const AgentPlan& plan, const std::vector<FunctionCheck>& checks, const ReferenceSet& references) {
    std::vector<Item> items;
    for (const FunctionCheck& c : checks)
        if (plan.lab == 0 || c.lab == plan.lab) items.push_back({items.size() + 1, &c, nullptr, false});
    for (const FigureReference& f : references.figures)
        if (plan.lab == 0 || f.lab == plan.lab) items.push_back({items.size() + 1, nullptr, &f, false});
    return items;
}

std::map<std::uint64_t, Item*> byId(std::vector<Item>& items) {
    std::map<std::uint64_t, Item*> index;
    for (Item& item : items) index[item.id] = &item;
    return index;
}

protocol::Request requestFor(const GradeSetup& setup, const Item& item) {
    if (item.check) return protocol::CheckRequest{item.id, item.check->calls, item.check->lab};
    return protocol::RenderRequest{item.id, fs::absolute(setup.scenes / (item.figure->id + ".toml")).string(), setup.seed,
                                   setup.threads, item.figure->lab};
}

// The items still unresolved, sent to the next run in this order, and their requests.
struct Batch {
    std::vector<Item*> sent;
    std::string requests; // one line each
};

Batch unresolvedBatch(const GradeSetup& setup, std::vector<Item>& items) {
    Batch batch;
    for (Item& item : items)
        if (!item.resolved) {
            batch.sent.push_back(&item);
            batch.requests += protocol::serialize(requestFor(setup, item)) + "\n";
        }
    return batch;
}

// Judges one run's answers and fails what they leave open. Returns whether another run is worth
// it: not after an attack on the grader, nor when the agent never started (it would do the same).
bool settleRun(const AgentPlan& plan, const AgentRun& run, const Batch& batch, const std::map<std::uint64_t, Item*>& items,
               Ledger& ledger, Reported& reported) {
    const std::string program = plan.program.filename().string();
    if (!run.violations.empty()) { // a run that attacked the grader earns nothing
        for (Item* item : batch.sent) ledger.fail(*item, tr("sandbox.attacked", {{"what", run.violations.front()}}));
        for (const std::string& v : run.violations) reported.problems.push_back(program + " " + v);
        return false;
    }
    const bool hello = readRun(run.lines, batch.sent, items, ledger);
    const auto unanswered = std::find_if(batch.sent.begin(), batch.sent.end(), [](const Item* i) { return !i->resolved; });
    if (unanswered == batch.sent.end()) return true;
    const std::string why = run.describe();
    const std::string errors = run.stderrTail.empty() ? "" : tr("grade.error_output", {{"tail", run.stderrTail}});
    if (!hello) {
        reported.problems.push_back(tr("grade.agent_silent", {{"program", program}, {"why", why}}) + errors);
        for (Item* item : batch.sent) ledger.fail(*item, tr("grade.never_started", {{"program", program}, {"why", why}}));
        return false;
    }
    // The run stopped on the first item it left unanswered; the next run starts after it.
    ledger.fail(**unanswered, tr((*unanswered)->check ? "grade.check_stopped" : "grade.figure_stopped", {{"why", why}}) + errors);
    return true;
}

} // namespace

std::string agentName(const AgentPlan& plan) { return plan.lab ? "lab" + std::to_string(plan.lab) : "all"; }

Reported runUntilDone(const GradeSetup& setup, const AgentPlan& plan, bool withChecks) {
    Reported reported;
    const fs::path scratch = fs::absolute(setup.scratch / ("agent-" + agentName(plan)));
    fs::remove_all(scratch);
    fs::create_directories(scratch);
    const std::vector<FunctionCheck> checks = withChecks ? freshlyDrawnChecks(setup.labs) : std::vector<FunctionCheck>{};
    std::vector<Item> items = itemsOf(plan, checks, setup.references);
    const std::map<std::uint64_t, Item*> index = byId(items);
    Ledger ledger(reported);
    for (int attempt = 0;; ++attempt) {
        const Batch batch = unresolvedBatch(setup, items);
        if (batch.sent.empty()) return reported;
        const AgentRun run = runAgent(
            {plan.program, {}, scratch / ("run" + std::to_string(attempt)), {setup.scenes}, {}, batch.requests}, setup.limits);
        if (!settleRun(plan, run, batch, index, ledger, reported)) return reported;
    }
}

} // namespace raylab::grader
