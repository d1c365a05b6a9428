#include "raylab/todo.h"

namespace raylab {

NotDoneYet::NotDoneYet(std::string lab, std::string function, std::string file, int line)
    : std::logic_error(lab + " not done yet: write " + function + " in " + file + ":" + std::to_string(line)),
      m_lab(std::move(lab)), m_function(std::move(function)), m_file(std::move(file)), m_line(line) {}

} // namespace raylab
