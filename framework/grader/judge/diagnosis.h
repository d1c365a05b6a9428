#pragma once
// The catalogue of classic mistakes, each lab's in its grading folder (framework/grader/labs/<lab>/references/
// mistakes.toml), and their signatures: each mistake's rendering of the figures it changes, a quarter
// of the size, kept with the figure (references/mistakes/<mistake>/<figure>.png in the folder of the
// figure's reference, whichever lab's the mistake is): a new lab's figures and their signatures stay in
// its own folder. A failing image is matched against them.

#include "raylab/image_io.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace raylab::grader {

inline constexpr int kSignatureScale = 4; // signatures are averaged over 4 x 4 pixel blocks

struct Mistake {
    std::string id;    // its patch framework/grader/labs/<lab>/mistakes/<id>.patch, its signatures' <figure's references>/mistakes/<id>/
    std::string nameEn, nameFr; // "fovy not halved", "fovy non divisé par deux"
    std::string hintEn, hintFr; // "use tan(fovy / 2): fovy is the full angle"
    std::string label; // its number in the handouts, "2.1": M2.1 in English, E2.1 in French; may be empty
    int lab = 0;       // the lab whose file holds the mistake
    std::string function; // where in that lab: "PerspectiveCamera::updateViewport (perspective_camera.cpp)"
    std::string check;    // the function check expected to catch it ("updateViewport: ...")
    std::string checkHint; // the message id of the hint that check gives it ("hint.lab2.viewport_height"); may be empty
    std::vector<std::pair<std::string, Image8>> signatures; // figure id, signature
    std::filesystem::path folder; // the reference folder whose mistakes.toml lists it
    // In the current language (raylab/messages.h).
    const std::string& name() const;
    const std::string& hint() const;
    // The placeholders of the diagnosis messages: name, hint, label ("M2.1 ", or empty), lab, function.
    std::vector<std::pair<std::string_view, std::string>> args() const;
};

struct Diagnosis {
    const Mistake* mistake = nullptr; // null: no mistake of the catalogue fits
    const Mistake* alike = nullptr;   // another mistake that draws the same picture (within 0.25 LSB)
    double distance = 0.;             // mean absolute difference to its signature, LSB
    double referenceDistance = 0.;    // the same to the reference
    std::string text() const; // "your image matches 'fovy not halved' (lab 2, updateViewport): use tan(fovy / 2) ..."
};

// Reads the catalogues (mistakes.toml of each reference folder that has one) and every signature
// present in any of the folders; a mistake with none has none, and a signature of a mistake that no
// catalogue lists (a lab left out of the course) is not read. Throws when two mistakes have one id.
std::vector<Mistake> loadMistakes(const std::vector<std::filesystem::path>& referenceFolders);

// Where mistake `mistake`'s signature of figure `figure` is kept: mistakes/<mistake>/ in the folder
// of `referenceFolders` that holds the figure's reference (<figure>.toml), else in the first one.
std::filesystem::path signatureFolder(const std::vector<std::filesystem::path>& referenceFolders, const std::string& figure,
                                      const std::string& mistake);

// Averages kSignatureScale x kSignatureScale blocks (an image that does not divide keeps its
// whole blocks only).
Image8 downsample(const Image8& image);

// The closest signature of this figure among the mistakes `suspect` accepts (those whose code may
// be wrong), when it fits: much closer to the student's image than the reference is, and within a
// few LSB on average.
Diagnosis diagnose(const std::vector<Mistake>& mistakes, const std::string& figure, const Image8& student,
                   const Image8& reference, const std::function<bool(const Mistake&)>& suspect);

} // namespace raylab::grader
