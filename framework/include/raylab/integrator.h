#pragma once
// An integrator turns a ray into the colour it brings back (its radiance, "L_i").

#include "raylab/scene.h"

#include <string_view>

namespace raylab {

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual Color Li(const Scene& scene, const Ray& ray) const = 0;
};

// Lab 2's picture: the ray direction d mapped to a colour, (d + 1) / 2. Looks at no object.
class DirectionIntegrator final : public Integrator {
public:
    Color Li(const Scene& scene, const Ray& ray) const override;
};

// Lab 3's three pictures, as the handout asks for them: a setting of the student's integrator.
// The framework never switches on it; a scene file names its picture ("flat", "cosine" ...) and
// lab 3's grading folder registers each name with its shading (integrator_registry.h).
enum class Shading {
    Flat,              // the sphere's colour
    PlaceholderNormal, // cosine shading with the constant normal normalize(1, 1, 1), facing the ray
    Cosine,            // colour * max(-d . n, 0)
};

// Lab 3: casts the ray into the scene and shades the nearest hit; a miss sees the background.
class RayCastIntegrator final : public Integrator {
public:
    explicit RayCastIntegrator(Shading shading) : m_shading(shading) {}
    Color Li(const Scene& scene, const Ray& ray) const override;
    Shading shading() const { return m_shading; }

private:
    Shading m_shading;
};

} // namespace raylab
