// raylab-agent: the child side of the grader. It is built with the code being graded, runs that
// code's function checks (doctest suites lab1 ... lab5) and renders its figures into a scratch
// folder, and reports each result on the channel the parent opened. It decides no grade: the
// parent compares the images and scores.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include "grader/channel.h"

#include "raylab/figure.h"
#include "raylab/image_io.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace {

using nlohmann::json;
raylab::grader::ResultChannel* g_channel = nullptr;

// Sends each check as it starts and as it ends: a check that hangs or crashes the process is the
// one that started and never ended, and the parent can skip it on the next run.
class ChannelReporter : public doctest::IReporter {
public:
    explicit ChannelReporter(const doctest::ContextOptions&) {}
    void report_query(const doctest::QueryData& data) override {
        for (unsigned k = 0; k < data.num_data; ++k)
            g_channel->send(json{{"kind", "listed"}, {"suite", data.data[k]->m_test_suite}, {"name", data.data[k]->m_name}}.dump());
    }
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats&) override {}
    void test_case_start(const doctest::TestCaseData& data) override {
        m_current = &data;
        m_messages.clear();
        g_channel->send(json{{"kind", "check-start"}, {"suite", data.m_test_suite}, {"name", data.m_name}}.dump());
    }
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats& stats) override {
        std::string message;
        for (const std::string& m : m_messages) message += (message.empty() ? "" : "\n") + m;
        g_channel->send(json{{"kind", "check"},
                             {"suite", m_current->m_test_suite},
                             {"name", m_current->m_name},
                             {"passed", stats.testCaseSuccess},
                             {"message", message}}
                            .dump(-1, ' ', false, json::error_handler_t::replace));
    }
    void test_case_exception(const doctest::TestCaseException& e) override {
        m_messages.push_back(std::string(e.is_crash ? "crashed: " : "threw: ") + e.error_string.c_str());
        if (e.is_crash) test_case_end(doctest::CurrentTestCaseStats{0, 0, 0., 0, false});
    }
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData& a) override {
        if (!a.m_failed) return;
        if (a.m_threw) m_messages.push_back(std::string(a.m_expr) + " threw: " + a.m_exception.c_str());
        else m_messages.push_back(std::string(a.m_expr) + " is false (" + a.m_decomp.c_str() + ")");
    }
    void log_message(const doctest::MessageData& m) override {
        if (m.m_severity & doctest::assertType::is_warn) return;
        m_messages.emplace_back(m.m_string.c_str());
    }
    void test_case_skipped(const doctest::TestCaseData&) override {}

private:
    const doctest::TestCaseData* m_current = nullptr;
    std::vector<std::string> m_messages;
};

REGISTER_REPORTER("raylab-channel", 1, ChannelReporter);

struct Options {
    int fd = -1;
    std::string file;
    int lab = 0; // 0: every lab
    bool checks = false;
    bool list = false;
    std::string scenes; // render the figures of this folder when set
    std::string out = "figures";
    std::string skipFile; // check names and figure ids not to run again, one a line
    int threads = 0;
    long long seed = -1; // >= 0: replaces the scenes' seeds (the grader's tests use several)
};

[[noreturn]] void usage(const std::string& problem) {
    std::fprintf(stderr,
                 "raylab-agent: %s\nusage: raylab-agent (--report-fd N | --report-file F) [--lab N] [--checks] "
                 "[--list] [--figures SCENES_DIR --out DIR] [--skip-file F] [--threads N] [--seed N]\n",
                 problem.c_str());
    std::exit(2);
}

Options parse(int argc, char** argv) {
    Options o;
    for (int k = 1; k < argc; ++k) {
        const std::string a = argv[k];
        auto value = [&]() -> std::string {
            if (k + 1 >= argc) usage(a + " needs a value");
            return argv[++k];
        };
        if (a == "--report-fd") o.fd = std::atoi(value().c_str());
        else if (a == "--report-file") o.file = value();
        else if (a == "--lab") o.lab = std::atoi(value().c_str());
        else if (a == "--checks") o.checks = true;
        else if (a == "--list") o.list = true;
        else if (a == "--figures") o.scenes = value();
        else if (a == "--out") o.out = value();
        else if (a == "--skip-file") o.skipFile = value();
        else if (a == "--threads") o.threads = std::atoi(value().c_str());
        else if (a == "--seed") o.seed = std::atoll(value().c_str());
        else usage("unknown argument " + a);
    }
    if (o.fd < 0 && o.file.empty()) usage("no result channel");
    return o;
}

std::set<std::string> readLines(const std::string& file) {
    std::set<std::string> lines;
    if (file.empty()) return lines;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.insert(line);
    return lines;
}

int runChecks(const Options& o, const std::set<std::string>& skip) {
    doctest::Context context;
    context.setOption("reporters", "raylab-channel");
    context.setOption("no-intro", true);
    context.setOption("no-version", true);
    if (o.list) { // a flag, which setOption cannot give
        const char* args[] = {"raylab-agent", "--list-test-cases"};
        context.applyCommandLine(2, args);
    }
    if (o.lab != 0) context.addFilter("test-suite", ("lab" + std::to_string(o.lab)).c_str());
    for (const std::string& name : skip) context.addFilter("test-case-exclude", name.c_str());
    return context.run();
}

void renderFigures(const Options& o, const std::set<std::string>& skip) {
    using namespace raylab;
    std::filesystem::create_directories(o.out);
    for (SceneDescription& d : loadSceneFolder(o.scenes)) {
        if (o.seed >= 0) d.seed = std::uint64_t(o.seed);
        if ((o.lab != 0 && d.lab != o.lab) || skip.count("figure:" + d.id)) continue;
        g_channel->send(json{{"kind", "figure-start"}, {"id", d.id}}.dump());
        const FigureResult r = renderScene(d, RenderOptions{o.threads, false});
        json line{{"kind", "figure"}, {"id", d.id}, {"lab", d.lab}, {"message", r.message}};
        line["status"] = r.status == FigureResult::Status::Rendered     ? "rendered"
                         : r.status == FigureResult::Status::NotDoneYet ? "todo"
                                                                        : "failed";
        if (r.image) {
            try {
                writePng(std::filesystem::path(o.out) / (d.id + ".png"), quantize(*r.image));
            } catch (const std::exception& e) {
                line["status"] = "failed";
                line["message"] = e.what();
            }
        }
        g_channel->send(line.dump(-1, ' ', false, json::error_handler_t::replace));
    }
}

} // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    try {
        raylab::grader::ResultChannel channel(o.fd, o.file);
        g_channel = &channel;
        const std::set<std::string> skip = readLines(o.skipFile);
        if (o.checks || o.list) runChecks(o, skip);
        if (!o.scenes.empty() && !o.list) renderFigures(o, skip);
        // The last word: without it the parent knows the run ended early (exit(0) in student code).
        channel.send(R"({"kind":"done"})");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raylab-agent: %s\n", e.what());
        return 1;
    }
    return 0;
}
