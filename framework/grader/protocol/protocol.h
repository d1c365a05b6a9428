#pragma once
// Room protocol/: what the parent and an agent say to each other, and the agent itself; it includes only sandbox/ and src/'s registry (the agent: raylab/ and protocol/).
//
// The grading protocol, the one schema both sides include: the parent (the grader) starts items
// by sending requests on one pipe; the child (the agent, holding the student's code) answers each
// with raw outputs on another. The child decides nothing: every verdict is the parent's.
//
// One message a line, a JSON object with "type". Versioned: the child's first line is a hello
// naming kProtocolVersion. Numbers that are not finite travel as the strings "nan", "inf", "-inf"
// (a NaN is a value the parent judges, not a broken message). Images travel as base64 RGB bytes.

#include "src/source_place.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace raylab::grader::protocol {

inline constexpr int kVersion = 1;

// What the child can be asked to call: each probe calls one student function in a fixed way. A
// lab's grading folder declares its probes, typed (framework/grader/labs/<lab>/probes.h, probe.h),
// by name; this is what the protocol keeps of one.
struct ProbeSpec {
    std::string name;
    std::size_t inputs;                        // how many numbers a call sends
    bool (*fits)(std::span<const double> answer); // whether the child's numbers are an answer
};

// Keeps `spec` for the life of the program (at static initialisation, from a lab's probes.h) and
// returns where it is kept; the same name twice is a std::logic_error naming both places (two labs
// would answer one probe). A pointer, not a reference: a reference bound to the result of a call that
// takes a temporary looks dangling to GCC 14 (-Wdangling-reference), and a Call holds a pointer anyway.
const ProbeSpec* registerProbe(ProbeSpec spec, SourcePlace where = SourcePlace::here());
// The registered probe of that name; nullptr when there is none.
const ProbeSpec* probeNamed(std::string_view name);

// The largest image an honest answer holds; anything larger is refused unread.
inline constexpr double kMaxPixels = 4096. * 4096.;

struct Call {
    const ProbeSpec* probe;
    std::vector<double> inputs;
};

// A call's numbers (its inputs, or its outputs), read in order.
class NumberReader {
public:
    explicit NumberReader(std::span<const double> values) : m_values(values) {}
    double number() {
        if (m_next >= m_values.size()) throw std::out_of_range("NumberReader: no number left");
        return m_values[m_next++];
    }
    glm::dvec3 vec3() {
        const double x = number(), y = number();
        return {x, y, number()};
    }

private:
    std::span<const double> m_values;
    std::size_t m_next = 0;
};

// Parent -> child.
// Each names its lab: an agent built for one lab (raylab-agent-labN) answers that lab's items only.
struct CheckRequest { // a function check: its calls, answered together
    std::uint64_t item;
    std::vector<Call> calls;
    int lab;
};
struct RenderRequest { // a figure: the scene file to render
    std::uint64_t item;
    std::string sceneFile;
    long long seed; // >= 0: replaces the scene's seed
    int threads;
    int lab;
};
using Request = std::variant<CheckRequest, RenderRequest>;

// Child -> parent.
struct Hello {
    int version;
};
struct Values { // the outputs of a check's calls, one list a call
    std::uint64_t item;
    std::vector<std::vector<double>> outputs;
};
struct Picture { // a rendered figure, 8-bit RGB rows top to bottom
    std::uint64_t item;
    int width, height;
    std::vector<std::uint8_t> rgb;
};
struct NotDone { // a lab stub was reached (RAYLAB_TODO)
    std::uint64_t item;
    std::string lab, function, file;
    int line;
};
struct Failure { // the student's code threw
    std::uint64_t item;
    std::string message;
};
struct Done {}; // the last word: every request was answered
using Answer = std::variant<Hello, Values, Picture, NotDone, Failure, Done>;

std::string serialize(const Request& request);
std::string serialize(const Answer& answer);

// A message, or why the line is not one (for the parent's protocol-violation reason).
template <typename T>
struct Parsed {
    std::optional<T> message;
    std::string error;
};
Parsed<Request> parseRequest(std::string_view line);
Parsed<Answer> parseAnswer(std::string_view line);

// The item an answer is for (none for Hello and Done).
std::optional<std::uint64_t> itemOf(const Answer& answer);

std::string base64Encode(std::span<const std::uint8_t> bytes);
std::optional<std::vector<std::uint8_t>> base64Decode(std::string_view text);

} // namespace raylab::grader::protocol
