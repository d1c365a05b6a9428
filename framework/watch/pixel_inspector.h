#pragma once
// The watch page's pixel inspector: for one pixel of a figure, each quantity the labs compute on the
// way to its colour, the student's value beside the reference's. The student's values come from
// their code in the grading sandbox (the labs' probes, called by a check request of the agent
// protocol, as the function checks call them); the reference's are computed here, in double, from the
// handouts' formulas, never in the student's process. Each function is called on the reference's
// inputs (the intersection on the reference ray, the normal at the reference hit), so that the first
// value that differs names the function that is wrong.
//
// The figures of one sphere (or lab 2's directions): the default camera's ray (lab 2) or the lookAt
// camera's frame (lab 4), the hit, the normal and the colour (lab 3); with lab 5's random samples, the
// pixel's screen points, their average and the pixel's colour in both pictures. Another figure is
// answered with a note saying so.

#include "watch/watch_session.h"

#include "grader/lab_catalog.h"

#include <mutex>
#include <string>

namespace raylab::watch {

class PixelInspector {
public:
    // `agents`: held while a build or a grade uses the agents, and by each inspection.
    PixelInspector(const WatchSettings& settings, const grader::LabCatalog& labs, std::mutex& agents);

    // A JSON document: {"figure", "x", "y", "rows": [{"name", "student", "reference", "differs",
    // "formula", "handout"}], "first": index of the first row that differs or -1, "note"}.
    std::string inspect(const std::string& figure, int x, int y) const;

private:
    const WatchSettings& m_settings;
    const grader::LabCatalog& m_labs;
    std::mutex& m_agents;
};

} // namespace raylab::watch
