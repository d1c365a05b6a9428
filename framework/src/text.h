#pragma once
// Numbers and vectors as error messages show them: shortest form, "(1, 2, 3)", "nan", "inf".

#include <glm/vec3.hpp>

#include <string>

namespace raylab {

std::string showNumber(double value);
std::string showVector(const glm::vec3& v);

} // namespace raylab
