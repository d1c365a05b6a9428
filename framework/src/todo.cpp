#include "raylab/todo.h"

#include "raylab/messages.h"

namespace raylab {

namespace {

// "lab 2" -> "2": the messages say "lab 2" or "TP 2".
std::string labNumber(const std::string& lab) { return lab.substr(lab.find_last_of(' ') + 1); }

} // namespace

NotDoneYet::NotDoneYet(std::string lab, std::string function, std::string file, int line)
    : std::logic_error(tr("todo.message", {{"lab", labNumber(lab)},
                                          {"function", titleInLanguage(function)},
                                          {"where", file + ":" + std::to_string(line)}})),
      m_lab(std::move(lab)), m_function(std::move(function)), m_file(std::move(file)), m_line(line) {}

} // namespace raylab
