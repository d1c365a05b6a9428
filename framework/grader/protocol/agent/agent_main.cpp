// raylab-agent: the child side of the grader. It is built with the code being graded; it reads the
// requests the parent sends (a check's probe calls, a figure's scene file), runs the student's code
// on them and answers each with what came out: numbers, pixels, "not done yet" or an exception's
// message. It judges nothing: the parent drew the inputs and compares the outputs itself.

#include "grader/protocol/agent/agent_lab.h"
#include "grader/protocol/agent/probes.h"
#include "grader/sandbox/channel.h"
#include "grader/protocol/protocol.h"

#include "src/figure.h"
#include "raylab/image_io.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

namespace protocol = raylab::grader::protocol;

struct Options {
    int requestFd = -1, reportFd = -1;
    std::string requestFile, reportFile;
};

[[noreturn]] void usage(const std::string& problem) {
    std::fprintf(
        stderr,
        "raylab-agent: %s\nusage: raylab-agent (--request-fd N | --request-file F) (--report-fd N | --report-file F)\n"
        "It answers the grader's requests; it is not meant to be run by hand.\n",
        problem.c_str());
    std::exit(2);
}

Options parse(int argc, char** argv) {
    Options o;
    for (int k = 1; k < argc; ++k) {
        const std::string a = argv[k];
        if (k + 1 >= argc) usage(a + " needs a value");
        const std::string value = argv[++k];
        if (a == "--request-fd")
            o.requestFd = std::atoi(value.c_str());
        else if (a == "--request-file")
            o.requestFile = value;
        else if (a == "--report-fd")
            o.reportFd = std::atoi(value.c_str());
        else if (a == "--report-file")
            o.reportFile = value;
        else
            usage("unknown argument " + a);
    }
    if ((o.requestFd < 0 && o.requestFile.empty()) || (o.reportFd < 0 && o.reportFile.empty())) usage("no channel");
    return o;
}

// Runs `work` and turns what the student's code throws into the answer for `item`, of lab `lab`; an
// agent built for another lab does not run it.
template <typename Work>
protocol::Answer answering(std::uint64_t item, int lab, Work work) {
    if (raylab::agent::kAgentLab != 0 && lab != raylab::agent::kAgentLab)
        return protocol::Failure{item, "raylab-agent-lab" + std::to_string(raylab::agent::kAgentLab) + " answers lab " +
                                           std::to_string(raylab::agent::kAgentLab) + " only, not lab " + std::to_string(lab)};
    try {
        return work();
    } catch (const raylab::NotDoneYet& e) {
        return protocol::NotDone{item, e.lab(), e.function(), e.file(), e.line()};
    } catch (const std::exception& e) {
        return protocol::Failure{item, e.what()};
    }
}

protocol::Answer answer(const protocol::CheckRequest& request) {
    return answering(request.item, request.lab, [&]() -> protocol::Answer {
        protocol::Values values{request.item, {}};
        for (const protocol::Call& call : request.calls)
            values.outputs.push_back(raylab::agent::callProbe(call));
        return values;
    });
}

protocol::Answer answer(const protocol::RenderRequest& request) {
    return answering(request.item, request.lab, [&]() -> protocol::Answer {
        raylab::SceneDescription d = raylab::loadSceneFile(request.sceneFile);
        if (request.seed >= 0) d.seed = std::uint64_t(request.seed);
        const raylab::FigureResult r = renderScene(d, raylab::RenderOptions{request.threads, false});
        if (r.todo) throw *r.todo;
        if (r.status != raylab::FigureResult::Status::Rendered || !r.image)
            return protocol::Failure{request.item, r.message};
        raylab::Image8 image = raylab::quantize(*r.image);
        return protocol::Picture{request.item, image.width, image.height, std::move(image.rgb)};
    });
}

} // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    try {
        raylab::grader::RequestChannel requests(o.requestFd, o.requestFile);
        raylab::grader::ResultChannel channel(o.reportFd, o.reportFile);
        channel.send(protocol::serialize(protocol::Hello{protocol::kVersion}));
        for (std::string line; requests.receive(line);) {
            const protocol::Parsed<protocol::Request> request = protocol::parseRequest(line);
            if (!request.message) throw std::runtime_error("a request the agent cannot read: " + request.error);
            channel.send(protocol::serialize(std::visit([](const auto& r) { return answer(r); }, *request.message)));
        }
        // The last word: without it the parent knows the run ended early (exit(0) in student code).
        channel.send(protocol::serialize(protocol::Done{}));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raylab-agent: %s\n", e.what());
        return 1;
    }
    return 0;
}
