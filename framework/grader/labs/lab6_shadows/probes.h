#pragma once
// Lab 6's probes, typed once for both sides (grader/protocol/probe.h): the parent calls them and reads
// their answers (checks.cpp, inspector.cpp), the agent answers them (probes.cpp). A scene is one
// sphere (none when its radius is 0) and one plane (none when its normal is 0).

#include "grader/protocol/probe_types.h"

namespace raylab::grader::probes {
inline namespace lab6_shadows {

struct Plane {
    glm::dvec3 point{0.};
    glm::dvec3 normal{0.}; // unit, or 0: no plane
    static constexpr auto fields = std::tuple{&Plane::point, &Plane::normal};
};
struct Light {
    glm::dvec3 position{0.};
    glm::dvec3 intensity{1.};
    static constexpr auto fields = std::tuple{&Light::position, &Light::intensity};
};
// What inShadow's scene holds besides its light.
struct Objects {
    Sphere sphere;
    Plane plane;
    static constexpr auto fields = std::tuple{&Objects::sphere, &Objects::plane};
};
// Li's, each object with its colour.
struct ColouredObjects {
    Sphere sphere;
    glm::dvec3 sphereColour{0.};
    Plane plane;
    glm::dvec3 planeColour{0.};
    static constexpr auto fields = std::tuple{&ColouredObjects::sphere, &ColouredObjects::sphereColour,
                                              &ColouredObjects::plane, &ColouredObjects::planeColour};
};

inline const protocol::Probe<bool(Objects, glm::dvec3 point, glm::dvec3 lightPosition)> inShadow{"inShadow"};
// The colour PointLightIntegrator::Li gives with that ambient term, its shadow test on or off, in a
// scene of those objects and that one light.
inline const protocol::Probe<glm::dvec3(double ambient, bool shadows, ColouredObjects, Light, glm::dvec3 background, Ray)>
    pointLightLi{"PointLightIntegrator::Li"};

} // namespace lab6_shadows
} // namespace raylab::grader::probes
