#pragma once
// The watch page's pixel inspector: for one pixel of a figure, each quantity the labs compute on the
// way to its colour, the student's value beside the reference's. The rows are each lab's, from its
// grading folder (framework/grader/inspector/inspector_steps.h, the labs' inspector.cpp): this file
// knows no lab. The student's values come from their code in the grading sandbox (the labs' probes,
// called by a check request of the agent protocol, as the function checks call them), never in this
// process. A lab that registers no rows is said ("no inspector for lab N").

#include "watch/watch_session.h"

#include "grader/lab_catalog.h"

#include <nlohmann/json_fwd.hpp>

#include <mutex>
#include <string>

namespace raylab::watch {

class PixelInspector {
public:
    // `agents`: held while a build or a grade uses the agents, and by each inspection.
    PixelInspector(const WatchSettings& settings, const grader::LabCatalog& labs, std::mutex& agents);

    // A JSON document: {"figure", "x", "y", "rows": [{"name", "student", "reference", "differs",
    // "formula", "handout", "reference_only", "follows"}], "first": index of the first row that
    // differs or -1, "note"}. Throws nothing: a problem is the answer's note.
    std::string inspect(const std::string& figure, int x, int y) const;

private:
    std::string inspectPixel(nlohmann::json& answer, const std::string& figure, int x, int y) const;

    const WatchSettings& m_settings;
    const grader::LabCatalog& m_labs;
    std::mutex& m_agents;
};

} // namespace raylab::watch
