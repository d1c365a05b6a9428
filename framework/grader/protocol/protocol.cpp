#include "grader/protocol/protocol.h"

#include "src/name_registry.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace raylab::grader::protocol {

using nlohmann::json;

namespace {

json number(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return v;
}

std::optional<double> numberFrom(const json& j) {
    if (j.is_number()) return j.get<double>();
    if (!j.is_string()) return std::nullopt;
    const std::string& s = j.get_ref<const std::string&>();
    if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "-inf") return -std::numeric_limits<double>::infinity();
    return std::nullopt;
}

json numbers(const std::vector<double>& values) {
    json list = json::array();
    for (double v : values)
        list.push_back(number(v));
    return list;
}

// Throws std::runtime_error with the reason when `j` is not a list of numbers.
std::vector<double> numbersFrom(const json& j, const char* what) {
    if (!j.is_array()) throw std::runtime_error(std::string(what) + " is not a list");
    std::vector<double> values;
    values.reserve(j.size());
    for (const json& v : j) {
        const std::optional<double> d = numberFrom(v);
        if (!d) throw std::runtime_error(std::string(what) + " holds something that is not a number");
        values.push_back(*d);
    }
    return values;
}

template <typename T>
T field(const json& j, const char* name) {
    const auto it = j.find(name);
    if (it == j.end()) throw std::runtime_error(std::string("no \"") + name + "\"");
    try {
        return it->get<T>();
    } catch (const json::exception&) {
        throw std::runtime_error(std::string("\"") + name + "\" has the wrong type");
    }
}

std::string dump(const json& j) {
    return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

template <typename T>
Parsed<T> parseWith(std::string_view line, T (*read)(const json&)) {
    const json j = json::parse(line, nullptr, false);
    if (!j.is_object()) return {std::nullopt, "not a JSON object: \"" + std::string(line.substr(0, 80)) + "\""};
    try {
        return {read(j), ""};
    } catch (const std::exception& e) {
        return {std::nullopt, std::string("a malformed \"") + j.value("type", "?") + "\" message: " + e.what()};
    }
}

Request readRequest(const json& j) {
    const std::string type = field<std::string>(j, "type");
    const auto item = field<std::uint64_t>(j, "item");
    if (type == "render")
        return RenderRequest{item, field<std::string>(j, "scene"), field<long long>(j, "seed"),
                             field<int>(j, "threads"), field<int>(j, "lab")};
    if (type != "check") throw std::runtime_error("unknown request type " + type);
    CheckRequest request{item, {}, field<int>(j, "lab")};
    for (const json& c : field<json>(j, "calls")) {
        const ProbeSpec* probe = probeNamed(field<std::string>(c, "probe"));
        if (probe == nullptr) throw std::runtime_error("unknown probe");
        std::vector<double> inputs = numbersFrom(field<json>(c, "inputs"), "inputs");
        if (inputs.size() != probe->inputs) throw std::runtime_error("wrong number of inputs");
        request.calls.push_back({probe, std::move(inputs)});
    }
    return request;
}

Answer readAnswer(const json& j) {
    const std::string type = field<std::string>(j, "type");
    if (type == "hello") return Hello{field<int>(j, "version")};
    if (type == "done") return Done{};
    const auto item = field<std::uint64_t>(j, "item");
    if (type == "values") {
        Values v{item, {}};
        for (const json& o : field<json>(j, "outputs"))
            v.outputs.push_back(numbersFrom(o, "outputs"));
        return v;
    }
    if (type == "picture") {
        Picture p{item, field<int>(j, "width"), field<int>(j, "height"), {}};
        if (p.width <= 0 || p.height <= 0 || double(p.width) * p.height > kMaxPixels)
            throw std::runtime_error("an image of " + std::to_string(p.width) + " x " + std::to_string(p.height));
        std::optional<std::vector<std::uint8_t>> rgb = base64Decode(field<std::string>(j, "rgb"));
        if (!rgb) throw std::runtime_error("\"rgb\" is not base64");
        if (rgb->size() != std::size_t(p.width) * std::size_t(p.height) * 3)
            throw std::runtime_error("\"rgb\" holds " + std::to_string(rgb->size()) + " bytes, not 3 W H");
        p.rgb = std::move(*rgb);
        return p;
    }
    if (type == "todo")
        return NotDone{item, field<std::string>(j, "lab"), field<std::string>(j, "function"),
                       field<std::string>(j, "file"), field<int>(j, "line")};
    if (type == "failure") return Failure{item, field<std::string>(j, "message")};
    throw std::runtime_error("unknown answer type " + type);
}

} // namespace

namespace {

// Built on first use: the probes register during static initialisation, in any order of files.
NameRegistry<ProbeSpec>& probes() {
    static NameRegistry<ProbeSpec> registry("probe");
    return registry;
}

} // namespace

const ProbeSpec* registerProbe(ProbeSpec spec, SourcePlace where) {
    const std::string name = spec.name;
    return &probes().add(name, std::move(spec), where).value;
}

const ProbeSpec* probeNamed(std::string_view name) {
    const auto* probe = probes().find(name);
    return probe != nullptr ? &probe->value : nullptr;
}

std::string serialize(const Request& request) {
    if (const auto* r = std::get_if<RenderRequest>(&request))
        return dump({{"type", "render"},
                     {"item", r->item},
                     {"scene", r->sceneFile},
                     {"seed", r->seed},
                     {"threads", r->threads},
                     {"lab", r->lab}});
    const auto& c = std::get<CheckRequest>(request);
    json calls = json::array();
    for (const Call& call : c.calls)
        calls.push_back({{"probe", call.probe->name}, {"inputs", numbers(call.inputs)}});
    return dump({{"type", "check"}, {"item", c.item}, {"calls", calls}, {"lab", c.lab}});
}

std::string serialize(const Answer& answer) {
    struct Writer {
        json operator()(const Hello& h) const { return {{"type", "hello"}, {"version", h.version}}; }
        json operator()(const Done&) const { return {{"type", "done"}}; }
        json operator()(const Values& v) const {
            json outputs = json::array();
            for (const std::vector<double>& o : v.outputs)
                outputs.push_back(numbers(o));
            return {{"type", "values"}, {"item", v.item}, {"outputs", outputs}};
        }
        json operator()(const Picture& p) const {
            return {{"type", "picture"},
                    {"item", p.item},
                    {"width", p.width},
                    {"height", p.height},
                    {"rgb", base64Encode(p.rgb)}};
        }
        json operator()(const NotDone& n) const {
            return {{"type", "todo"},         {"item", n.item}, {"lab", n.lab},
                    {"function", n.function}, {"file", n.file}, {"line", n.line}};
        }
        json operator()(const Failure& f) const {
            return {{"type", "failure"}, {"item", f.item}, {"message", f.message}};
        }
    };
    return dump(std::visit(Writer{}, answer));
}

Parsed<Request> parseRequest(std::string_view line) {
    return parseWith<Request>(line, readRequest);
}
Parsed<Answer> parseAnswer(std::string_view line) {
    return parseWith<Answer>(line, readAnswer);
}

std::optional<std::uint64_t> itemOf(const Answer& answer) {
    return std::visit(
        [](const auto& a) -> std::optional<std::uint64_t> {
            if constexpr (requires { a.item; })
                return a.item;
            else
                return std::nullopt;
        },
        answer);
}

namespace {
constexpr std::string_view kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
}

std::string base64Encode(std::span<const std::uint8_t> bytes) {
    std::string text;
    text.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t k = 0; k < bytes.size(); k += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - k);
        std::uint32_t group = std::uint32_t(bytes[k]) << 16;
        if (n > 1) group |= std::uint32_t(bytes[k + 1]) << 8;
        if (n > 2) group |= bytes[k + 2];
        for (std::size_t c = 0; c < 4; ++c)
            text += c <= n ? kAlphabet[(group >> (18 - 6 * c)) & 63] : '=';
    }
    return text;
}

std::optional<std::vector<std::uint8_t>> base64Decode(std::string_view text) {
    if (text.size() % 4 != 0) return std::nullopt;
    std::array<int, 256> value;
    value.fill(-1);
    for (std::size_t k = 0; k < kAlphabet.size(); ++k)
        value[std::uint8_t(kAlphabet[k])] = int(k);
    std::vector<std::uint8_t> bytes;
    bytes.reserve(text.size() / 4 * 3);
    for (std::size_t k = 0; k < text.size(); k += 4) {
        const std::size_t padding = k + 4 == text.size() ? (text[k + 3] == '=') + (text[k + 2] == '=') : 0;
        std::uint32_t group = 0;
        for (std::size_t c = 0; c < 4; ++c) {
            const int v = c >= 4 - padding ? 0 : value[std::uint8_t(text[k + c])];
            if (v < 0) return std::nullopt;
            group = group << 6 | std::uint32_t(v);
        }
        for (std::size_t c = 0; c < 3 - padding; ++c)
            bytes.push_back(std::uint8_t(group >> (16 - 8 * c)));
    }
    return bytes;
}

} // namespace raylab::grader::protocol
