#pragma once
// A probe typed once, in its lab's probes.h, as the function it stands for: Answer(Inputs...). The
// parent makes its calls and reads its answers with it (judge/, inspector/); the agent answers it
// with a function of that very type (agent/probes.h). How many numbers cross the pipe, in which
// order, and whether an answer has the right shape follow from the types: nothing is packed by hand.
//
//   struct Triangle {
//       glm::dvec3 a{0.}, b{0.}, c{0.};
//       static constexpr auto fields = std::tuple{&Triangle::a, &Triangle::b, &Triangle::c};
//   };
//   inline const protocol::Probe<Hit(Triangle, Ray, double tMin, double tMax)> intersect{"triangleIntersect"};
//
//   checks.cpp:  calls.push_back(probes::intersect(triangle, ray, 0., kInf));
//                const Hit hit = probes::intersect.answer(out[k]);
//   probes.cpp:  Hit intersectProbe(Triangle t, Ray r, double tMin, double tMax) { ... }
//                RAYLAB_REGISTER_PROBE(grader::probes::intersect, intersectProbe);
//
// A lab's probes.h declares them in `namespace probes { inline namespace <its lab's id> {`: every
// lab is linked into one grader and one agent, where two labs' types of one name must stay two types.
// The framework's own (a ray, a sphere, a hit) are in probe_types.h, for every lab.

#include "grader/protocol/protocol.h"

#include <cmath>
#include <limits>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

namespace raylab::grader::protocol {

// The longest list an honest answer holds (an image's pixels, a pixel's samples).
inline constexpr double kMaxItems = kMaxPixels;

// How a value of type T crosses the pipe, as numbers: `size` of them (0: it varies, a list), `put`
// appends them, `get` reads them back, `fits` says whether the numbers at `at` hold one (the child's
// answer is checked so before it is read) and moves past them.
template <class T> struct Wire;

template <> struct Wire<double> {
    static constexpr std::size_t size = 1;
    static void put(std::vector<double>& out, double v) { out.push_back(v); }
    static double get(NumberReader& in) { return in.number(); }
    static bool fits(std::span<const double> numbers, std::size_t& at) { return at++ < numbers.size(); }
};

// 1 or 0.
template <> struct Wire<bool> {
    static constexpr std::size_t size = 1;
    static void put(std::vector<double>& out, bool v) { out.push_back(v ? 1. : 0.); }
    static bool get(NumberReader& in) { return in.number() != 0.; }
    static bool fits(std::span<const double> numbers, std::size_t& at) {
        if (at >= numbers.size()) return false;
        const double v = numbers[at++];
        return v == 0. || v == 1.;
    }
};

// A whole number in int's range.
template <> struct Wire<int> {
    static constexpr std::size_t size = 1;
    static void put(std::vector<double>& out, int v) { out.push_back(double(v)); }
    static int get(NumberReader& in) { return int(in.number()); }
    static bool fits(std::span<const double> numbers, std::size_t& at) {
        if (at >= numbers.size()) return false;
        const double v = numbers[at++];
        return v == std::floor(v) && v >= double(std::numeric_limits<int>::min()) && v <= double(std::numeric_limits<int>::max());
    }
};

template <> struct Wire<glm::dvec3> {
    static constexpr std::size_t size = 3;
    static void put(std::vector<double>& out, const glm::dvec3& v) {
        for (int k = 0; k < 3; ++k) out.push_back(v[k]); // not insert({...}): GCC 12 -O3 warns it overflows (a false alarm)
    }
    static glm::dvec3 get(NumberReader& in) { return in.vec3(); }
    static bool fits(std::span<const double> numbers, std::size_t& at) { return (at += 3) <= numbers.size(); }
};

// Its length, then its items.
template <class T> struct Wire<std::vector<T>> {
    static constexpr std::size_t size = 0;
    static void put(std::vector<double>& out, const std::vector<T>& list) {
        out.push_back(double(list.size()));
        for (const T& item : list) Wire<T>::put(out, item);
    }
    static std::vector<T> get(NumberReader& in) {
        std::vector<T> list(std::size_t(in.number()));
        for (T& item : list) item = Wire<T>::get(in);
        return list;
    }
    static bool fits(std::span<const double> numbers, std::size_t& at) {
        if (at >= numbers.size()) return false;
        const double length = numbers[at++];
        if (!(length >= 0. && length <= kMaxItems && length == std::floor(length))) return false;
        for (double k = 0.; k < length; ++k)
            if (!Wire<T>::fits(numbers, at)) return false;
        return true;
    }
};

// A struct that lists its members, in the order they cross: static constexpr auto fields =
// std::tuple{&S::a, &S::b}. Each member a type with a Wire.
template <class T>
concept WireStruct = requires { std::tuple_size<std::remove_const_t<decltype(T::fields)>>::value; };

template <class Pointer> struct MemberOf;
template <class Class, class Value> struct MemberOf<Value Class::*> {
    using type = Value;
};
// The Wire of the member a pointer to member points to.
template <class Pointer> using WireOf = Wire<typename MemberOf<Pointer>::type>;

template <WireStruct T> struct Wire<T> {
    static constexpr std::size_t size = std::apply(
        [](auto... member) {
            const bool fixed = ((WireOf<decltype(member)>::size != 0) && ...);
            return fixed ? (std::size_t(0) + ... + WireOf<decltype(member)>::size) : std::size_t(0);
        },
        T::fields);
    static void put(std::vector<double>& out, const T& v) {
        std::apply([&](auto... member) { (WireOf<decltype(member)>::put(out, v.*member), ...); }, T::fields);
    }
    static T get(NumberReader& in) {
        T v{};
        std::apply([&](auto... member) { ((v.*member = WireOf<decltype(member)>::get(in)), ...); }, T::fields);
        return v;
    }
    static bool fits(std::span<const double> numbers, std::size_t& at) {
        return std::apply([&](auto... member) { return (WireOf<decltype(member)>::fits(numbers, at) && ...); },
                          T::fields);
    }
};

template <class Signature> class Probe;

template <class Answer, class... Inputs> class Probe<Answer(Inputs...)> {
public:
    static_assert(((Wire<Inputs>::size != 0) && ...), "a probe's inputs are of a fixed size");

    explicit Probe(std::string name, SourcePlace where = SourcePlace::here())
        : m_spec(registerProbe({std::move(name), (std::size_t(0) + ... + Wire<Inputs>::size), &fits}, where)) {}

    // The parent: a call of the probe on these inputs.
    Call operator()(const Inputs&... inputs) const {
        std::vector<double> numbers;
        (Wire<Inputs>::put(numbers, inputs), ...);
        return {m_spec, std::move(numbers)};
    }
    // The parent: the answer to a call, once the protocol has found that it fits.
    Answer answer(std::span<const double> numbers) const {
        NumberReader in(numbers);
        return Wire<Answer>::get(in);
    }
    // A call's inputs, as the function takes them.
    static std::tuple<Inputs...> inputs(std::span<const double> numbers) {
        NumberReader in(numbers);
        return {Wire<Inputs>::get(in)...}; // braced: read in order
    }
    // An answer's numbers, as the agent sends them.
    static std::vector<double> answerNumbers(const Answer& answer) {
        std::vector<double> out;
        Wire<Answer>::put(out, answer);
        return out;
    }
    // The agent: calls `function` on a call's inputs and returns its answer's numbers.
    static std::vector<double> answerWith(Answer (*function)(Inputs...), std::span<const double> numbers) {
        return answerNumbers(std::apply(function, inputs(numbers)));
    }

    const ProbeSpec* spec() const { return m_spec; }
    // Whether numbers from the child are an answer: all of them, and nothing more.
    static bool fits(std::span<const double> numbers) {
        std::size_t at = 0;
        return Wire<Answer>::fits(numbers, at) && at == numbers.size();
    }

private:
    const ProbeSpec* m_spec;
};

} // namespace raylab::grader::protocol
