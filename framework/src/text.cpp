#include "src/text.h"

#include <sstream>

namespace raylab {

std::string showNumber(double value) {
    std::ostringstream out;
    out.precision(9); // enough to tell any two floats apart
    out << value;
    return out.str();
}

std::string showVector(const glm::vec3& v) {
    std::ostringstream out;
    out.precision(9);
    out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return out.str();
}

} // namespace raylab
