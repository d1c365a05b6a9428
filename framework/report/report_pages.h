#pragma once
// The report's pages: its generated Markdown segments from what was rendered and graded, and the
// HTML of a whole document (the templates, the Markdown rendered by cmark).

#include "grader/judge/grade.h"
#include "raylab/renderer.h"
#include "report/image_sources.h"
#include "report/student_text.h"
#include "report/title_block.h"
#include "report/words.h"

#include <optional>
#include <string>
#include <vector>

namespace raylab::report {

// One figure of the kit: this build's render, and what the grader made of the same code's.
struct KitFigure {
    std::string id;
    int lab = 0;
    bool rendered = false;
    std::string message; // not done yet, or what failed
    RenderStats stats;
    int width = 0, height = 0;
    bool hasReference = false, hasDifference = false, statistical = false;
    double outlierZ = 0.; // statistical: the grader's tolerance, in standard deviations of the noise
    const grader::FigureOutcome* grade = nullptr; // null when the grader has no such figure
};

// The antialiasing section's close-up: a block of both renders, enlarged; the figures are those whose
// scene files have the roles "aliased" and "antialiased".
struct CloseUp {
    int x = 0, y = 0, width = 0, height = 0, zoom = 1;
    std::string aliased, antialiased;
};

struct KitContent {
    const Words& words;
    TitleBlock title;
    const grader::GradeResult& grade;
    const grader::LabCatalog& labs;
    std::vector<KitFigure> figures; // in the handout's order
    std::optional<CloseUp> closeUp;  // set when the kit draws the antialiasing comparison
};

// This run's document, each student segment holding its placeholder.
std::vector<Segment> reportSegments(const KitContent& content);

// report.html: the page template around the document, the student's segments framed; the address of
// each image left out (image_sources.h) is added to `leftOut`.
std::string reportHtml(const std::vector<Segment>& document, const Words& words, const ImageSources& images,
                       std::vector<std::string>& leftOut);

} // namespace raylab::report
