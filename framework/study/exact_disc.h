#pragma once
// The exact picture of one sphere on the optical axis of the default camera: each pixel's average
// over its area, integrated by quadrature converged to about 5e-8 (see exact_disc.cpp).

#include "raylab/texture.h"

namespace raylab::study {

struct CentredSphere {
    int width = 600, height = 400;
    double fovyDegrees = 60.;
    double distance = 3.; // the centre is at (0, 0, distance), the camera at the origin
    double radius = 1.;
    Color color{0.f, 0.f, 1.f};
    Color background{0.5f, 0.5f, 0.5f};
    bool cosine = true; // colour * cos(incidence), else flat
};

struct ExactImage {
    std::vector<glm::dvec3> pixels; // row-major
    std::vector<double> coverage;   // the share of each pixel the sphere covers, in [0, 1]
};

// `nodes`: Gauss-Legendre points per sub-interval in each direction.
ExactImage exactCentredSphere(const CentredSphere& s, int nodes = 16);

} // namespace raylab::study
