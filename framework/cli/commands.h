#pragma once
// The raylab subcommands. Each returns the process exit status.

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::cli {

struct FiguresOptions {
    std::filesystem::path scenes;   // folder of figure scene files
    std::filesystem::path out;      // where DIR/<id>.png go
    std::vector<std::string> only;  // figure ids; empty: all
    int lab = 0;                    // only this lab's figures; 0: all
    int threads = 0;
};

// Renders figures; prints a line per figure. 1 if a figure failed or has NaN pixels, else 0
// (a figure waiting for a lab not done yet is reported, not a failure).
int runFigures(const FiguresOptions& options);

// Renders one scene file to a PNG.
int runRender(const std::filesystem::path& scene, std::filesystem::path out, int threads);

// Primary rays per second on lab 5's scene.
int runBench(const std::filesystem::path& scenes, int threads, int repeats);

// Runs the sibling program built with the other implementation, with the same arguments.
int runOtherImpl(const std::string& impl, int argc, char** argv);

} // namespace raylab::cli
