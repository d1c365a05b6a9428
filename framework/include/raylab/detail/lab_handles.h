#pragma once
// The renderer's handles on its camera and integrator (renderer.h): how lab 5's calls reach the
// labs' code at full speed. Nothing here is a lab's to write.

#include "raylab/integrator.h"
#include "raylab/perspective_camera.h"

namespace raylab {

// What lab 5's renderPixel calls as m_camera and m_integrator. The labs' own classes are final, so
// when the renderer has them it calls them directly, and the compiler can inline their code into
// the sample loop (docs/performance.md): the type is looked up once per renderer, and each call
// tests one flag. Any other camera or integrator (the grader's probes, tests) is called through
// its virtual function. A handle made from the final class itself is direct by construction: in a
// loop where the compiler sees it made, the test and the virtual call disappear (the renderer's
// passes, framework/src/render_passes.cpp, give a copy of the renderer such handles).
// LabHandle is what both handles share: the object as its base class, and as the lab's final class
// when it is one (`lab()`, null otherwise).
template <class Base, class Lab> class LabHandle {
public:
    explicit LabHandle(const Base& object)
        : m_object(&object), m_lab(dynamic_cast<const Lab*>(&object)), m_direct(m_lab != nullptr) {}
    explicit LabHandle(const Lab& object) : m_object(&object), m_lab(&object), m_direct(true) {}
    operator const Base&() const { return *m_object; }
    const Lab* lab() const { return m_lab; }

protected:
    const Base* m_object; // never null; a pointer so that a handle can be assigned
    const Lab* m_lab; // null for any other class
    bool m_direct;    // m_lab != nullptr, known to the compiler when it can be
};

class CameraHandle : public LabHandle<BaseCamera, PerspectiveCamera> {
public:
    using LabHandle::LabHandle;
    Ray generateRay(float sx, float sy) const {
        if (m_direct) [[likely]]
            return m_lab->generateRay(sx, sy);
        const Ray ray = m_object->generateRay(sx, sy);
        return Ray{ray.origin, ray.direction}; // a copy: see Li
    }
    int width() const { return m_object->width(); }
    int height() const { return m_object->height(); }
    float aspect() const { return m_object->aspect(); }
    const glm::vec3& position() const { return m_object->position(); }
    const glm::vec3& u() const { return m_object->u(); }
    const glm::vec3& v() const { return m_object->v(); }
    const glm::vec3& w() const { return m_object->w(); }
};

class IntegratorHandle : public LabHandle<Integrator, RayCastIntegrator> {
public:
    using LabHandle::LabHandle;
    Color Li(const Scene& scene, const Ray& ray) const {
        if (m_direct) [[likely]]
            return m_lab->Li(scene, ray);
        // The virtual call gets a copy of the ray, so that the caller's ray never has its address
        // taken: once the direct call is inlined, the compiler keeps that ray in registers. Without
        // the copy Clang kept it on the stack, stored in pieces and read back whole, which the CPU
        // cannot forward from its store buffer (docs/performance.md, "Clang").
        const Ray copy = ray;
        return m_object->Li(scene, copy);
    }
};

} // namespace raylab
