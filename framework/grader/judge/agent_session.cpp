#include "grader/judge/agent_session.h"

#include "src/messages.h"

#include <algorithm>
#include <chrono>
#include <cmath>
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
    return protocol::RenderRequest{item.id, fs::absolute(sceneFile(setup, item.figure->id)).string(), setup.seed,
                                   setup.threads, item.figure->lab};
}

int labOf(const Item& item) { return item.check ? item.check->lab : item.figure->lab; }

// The items of one lab still unresolved (the lab of the first of them), sent to the next run in this
// order, and their requests: each run spends one lab's time only.
struct Batch {
    int lab = 0;
    std::vector<Item*> sent;
    std::string requests; // one line each
};

Batch unresolvedBatch(const GradeSetup& setup, std::vector<Item>& items) {
    Batch batch;
    for (Item& item : items)
        if (!item.resolved && (batch.sent.empty() || labOf(item) == batch.lab)) {
            batch.lab = labOf(item);
            batch.sent.push_back(&item);
            batch.requests += protocol::serialize(requestFor(setup, item)) + "\n";
        }
    return batch;
}

// Judges one run's answers and fails what they leave open. Returns why no other run is worth it,
// for every item still open: an attack on the grader, or an agent that never started (it would do
// the same); empty when the next run may go on.
std::string settleRun(const AgentPlan& plan, const AgentRun& run, const Batch& batch,
                      const std::map<std::uint64_t, Item*>& items, Ledger& ledger, Reported& reported) {
    const std::string program = plan.program.filename().string();
    if (!run.violations.empty()) { // a run that attacked the grader earns nothing
        const std::string why = tr("sandbox.attacked", {{"what", run.violations.front()}});
        for (Item* item : batch.sent) ledger.fail(*item, why);
        for (const std::string& v : run.violations) reported.problems.push_back(program + " " + v);
        return why;
    }
    const bool hello = readRun(run.lines, batch.sent, items, ledger);
    const auto unanswered = std::find_if(batch.sent.begin(), batch.sent.end(), [](const Item* i) { return !i->resolved; });
    if (unanswered == batch.sent.end()) return "";
    const std::string why = run.describe();
    const std::string errors = run.stderrTail.empty() ? "" : tr("grade.error_output", {{"tail", run.stderrTail}});
    if (!hello) {
        reported.problems.push_back(tr("grade.agent_silent", {{"program", program}, {"why", why}}) + errors);
        return tr("grade.never_started", {{"program", program}, {"why", why}});
    }
    // The run stopped on the first item it left unanswered; the next run starts after it.
    ledger.fail(**unanswered, tr((*unanswered)->check ? "grade.check_stopped" : "grade.figure_stopped", {{"why", why}}) + errors);
    return "";
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
    // Each lab's wall-clock time over every run of it: an agent that sleeps, stops or answers slowly spends it too.
    std::map<int, double> spent;
    for (int attempt = 0;; ++attempt) {
        const Batch batch = unresolvedBatch(setup, items);
        if (batch.sent.empty()) return reported;
        const double budget = labBudgetSeconds(setup.references, batch.lab, setup.budget);
        if (spent[batch.lab] >= budget) {
            const std::string why = tr("grade.lab_budget_spent", {{"lab", std::to_string(batch.lab)},
                                                                  {"seconds", std::to_string(std::lround(budget))}});
            reported.problems.push_back(why);
            for (Item* item : batch.sent) ledger.fail(*item, why);
            continue;
        }
        SandboxLimits limits = setup.limits;
        limits.totalSeconds = std::min(limits.totalSeconds, budget - spent[batch.lab]);
        const auto start = std::chrono::steady_clock::now();
        const AgentRun run = runAgent(
            {plan.program, {}, scratch / ("run" + std::to_string(attempt)), sceneFolders(setup), {}, batch.requests}, limits);
        spent[batch.lab] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (const std::string why = settleRun(plan, run, batch, index, ledger, reported); !why.empty()) {
            for (Item& item : items)
                if (!item.resolved) ledger.fail(item, why);
            return reported;
        }
    }
}

} // namespace raylab::grader
