#pragma once
// Room protocol/: what the parent and an agent say to each other, and the agent itself; it includes only sandbox/ (the agent: raylab/ and protocol/).
//
// The grading protocol, the one schema both sides include: the parent (the grader) starts items
// by sending requests on one pipe; the child (the agent, holding the student's code) answers each
// with raw outputs on another. The child decides nothing: every verdict is the parent's.
//
// One message a line, a JSON object with "type". Versioned: the child's first line is a hello
// naming kProtocolVersion. Numbers that are not finite travel as the strings "nan", "inf", "-inf"
// (a NaN is a value the parent judges, not a broken message). Images travel as base64 RGB bytes.

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace raylab::grader::protocol {

inline constexpr int kVersion = 1;

// What the child can be asked to call: each probe calls one student function in a fixed way.
enum class Probe {
    FillGradient,  // lab 1: (W, H) -> the W x H texture (pre-filled with -1), 3 W H values
    Viewport,      // lab 2: default camera (W, H, fovy) -> height, width, topLeft
    GenerateRay,   // lab 2: camera (W, H, fovy, px, py, pz) moved to p, generateRay(sx, sy) -> origin, direction
    Intersect,     // lab 3: sphere (c, r), ray (o, d), tMin, tMax -> hit, t, position (t untouched: -7)
    ComputeNormal, // lab 3: sphere (c, r), point -> normal
    Li,            // lab 3: shading, sphere (c, r, colour), background, ray (o, d) -> colour
    LookAt,        // lab 4: (W, H, position, target, up, fovy) -> u, v, w, position, height, width, topLeft
    LookAtRefused, // lab 4: (position, target, up) -> 1 when std::invalid_argument, 0 when built
    SetSamples,    // lab 5: setNbPixelSamples(n) -> refused (0 or 1), nbPixelSamples()
    RenderPixel,   // lab 5: (W, H, i, j, n, seed) -> rays traced k, colour, k screen points (sx, sy)
};

struct ProbeSpec {
    Probe probe;
    const char* name;
    int lab;
    std::size_t inputs;
    std::size_t outputs; // 0: depends on the inputs or the outputs (see outputsValid)
};

const ProbeSpec& spec(Probe probe);
std::optional<Probe> probeNamed(std::string_view name);
// Whether `outputs` has the size the probe gives for `inputs`.
bool outputsValid(Probe probe, std::span<const double> inputs, std::span<const double> outputs);

struct Call {
    Probe probe;
    std::vector<double> inputs;
};

// A call's numbers (its inputs, or its outputs), read in order.
class NumberReader {
public:
    explicit NumberReader(const std::vector<double>& values) : m_values(values) {}
    double number() { return m_values.at(m_next++); }
    glm::dvec3 vec3() {
        const double x = number(), y = number();
        return {x, y, number()};
    }

private:
    const std::vector<double>& m_values;
    std::size_t m_next = 0;
};

// Parent -> child.
struct CheckRequest { // a function check: its calls, answered together
    std::uint64_t item;
    std::vector<Call> calls;
};
struct RenderRequest { // a figure: the scene file to render
    std::uint64_t item;
    std::string sceneFile;
    long long seed; // >= 0: replaces the scene's seed
    int threads;
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
