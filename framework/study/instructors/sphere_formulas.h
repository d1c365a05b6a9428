#pragma once
// Two ways to write the ray/sphere intersection, in any floating-point type T, for the numerics
// study (raylab numerics, raylab study intersection) and as the foil of the numerics tests.
// The lab code (SphereGeometry::intersect, solutions/lab3) is the stable one in float; here both
// forms exist in float, double and long double, so that they can be compared with each other and
// with a long double reference. Header only, no dependence on the lab code.

#include <glm/vec3.hpp>

#include <cmath>

namespace raylab::study {

// A 3-vector of T: glm does not promise long double, and the study needs it.
template <class T>
struct V3 {
    T x{}, y{}, z{};

    static V3 from(const glm::vec3& v) { return {T(v.x), T(v.y), T(v.z)}; }
    glm::vec3 toFloat() const { return {float(x), float(y), float(z)}; }
    V3 operator+(const V3& b) const { return {x + b.x, y + b.y, z + b.z}; }
    V3 operator-(const V3& b) const { return {x - b.x, y - b.y, z - b.z}; }
    V3 operator*(T s) const { return {x * s, y * s, z * s}; }
    V3 operator/(T s) const { return {x / s, y / s, z / s}; }
};

template <class T>
T dot(const V3<T>& a, const V3<T>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <class T>
T length(const V3<T>& a) {
    return std::sqrt(dot(a, a));
}

// The nearest root in [tMin, tMax], as SphereGeometry::intersect chooses it.
template <class T>
struct SphereHit {
    bool hit = false;
    T t = 0;
};

template <class T>
SphereHit<T> nearestIn(T t0, T t1, T tMin, T tMax) {
    if (t0 > t1) std::swap(t0, t1);
    if (t0 >= tMin && t0 <= tMax) return {true, t0};
    if (t1 >= tMin && t1 <= tMax) return {true, t1};
    return {};
}

// The textbook formula: a t^2 + b t + c = 0 with b = 2 oc.d, disc = b^2 - 4ac,
// t = (-b -+ sqrt(disc)) / 2a. For a sphere at distance D, b^2 and 4ac are both about 4 D^2 and
// their difference about 4 r^2: the subtraction keeps only log2(r^2 / D^2) fewer bits, so in float
// a sphere 10^4 radii away has a discriminant made of rounding noise. And -b + sqrt(disc) cancels
// when one root is near 0 (the far root seen from inside, the near one from the surface).
template <class T>
SphereHit<T> textbookIntersect(const V3<T>& o, const V3<T>& d, const V3<T>& centre, T radius, T tMin, T tMax) {
    const V3<T> oc = o - centre;
    const T a = dot(d, d);
    const T b = T(2) * dot(oc, d);
    const T c = dot(oc, oc) - radius * radius;
    const T disc = b * b - T(4) * a * c;
    if (disc < T(0)) return {};
    const T s = std::sqrt(disc);
    return nearestIn((-b - s) / (T(2) * a), (-b + s) / (T(2) * a), tMin, tMax);
}

// Ray Tracing Gems, chapter 7 (Haines, Guenther, Akenine-Moller): with b' = oc.d and
// l = oc - (b'/a) d, the vector from the centre to the ray's closest point,
// b'^2 - a c = a (r^2 - |l|^2) = a (r - |l|)(r + |l|): no large squares cancel. The roots come
// from q = -b' - sign(b') sqrt(disc) as c / q and q / a: -b' and -sign(b') sqrt(disc) have the same
// sign, so q is a sum, never a cancelling difference. This is the reference solution's formula.
template <class T>
SphereHit<T> stableIntersect(const V3<T>& o, const V3<T>& d, const V3<T>& centre, T radius, T tMin, T tMax) {
    const V3<T> oc = o - centre;
    const T a = dot(d, d);
    const T bPrime = dot(oc, d);
    const T c = dot(oc, oc) - radius * radius;
    const T lLength = length(oc - d * (bPrime / a));
    const T disc = a * (radius - lLength) * (radius + lLength);
    if (disc < T(0)) return {};
    const T q = -bPrime - std::copysign(std::sqrt(disc), bPrime);
    if (q == T(0)) return nearestIn(T(0), T(0), tMin, tMax); // b' = disc = 0: tangent at the origin
    return nearestIn(c / q, q / a, tMin, tMax);
}

// How far the ray's line passes from the centre: |oc - (oc.d / d.d) d|.
template <class T>
T closestDistance(const V3<T>& o, const V3<T>& d, const V3<T>& centre) {
    const V3<T> oc = o - centre;
    return length(oc - d * (dot(oc, d) / dot(d, d)));
}

// The outward unit normal at the hit, (o + t d - centre) / radius, all in T.
template <class T>
V3<T> normalAt(const V3<T>& o, const V3<T>& d, const V3<T>& centre, T radius, T t) {
    return (o + d * t - centre) / radius;
}

// The angle between two vectors, accurate for tiny angles too (atan2 of |a x b| and a.b).
inline long double angleBetween(const V3<long double>& a, const V3<long double>& b) {
    return std::atan2(length(cross(a, b)), dot(a, b));
}

} // namespace raylab::study
