#pragma once
// The one-line body of every student stub: RAYLAB_TODO("lab 2", "PerspectiveCamera::generateRay");
// It throws NotDoneYet, which the renderer turns into "lab 2 not done yet: write ... in file:line"
// for that figure only, so the other figures still render.

#include <stdexcept>
#include <string>

namespace raylab {

class NotDoneYet : public std::logic_error {
public:
    NotDoneYet(std::string lab, std::string function, std::string file, int line);

    const std::string& lab() const { return m_lab; }
    const std::string& function() const { return m_function; }
    const std::string& file() const { return m_file; }
    int line() const { return m_line; }

private:
    std::string m_lab, m_function, m_file;
    int m_line;
};

} // namespace raylab

#define RAYLAB_TODO(lab, function) throw ::raylab::NotDoneYet((lab), (function), __FILE__, __LINE__)
