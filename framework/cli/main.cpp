// raylab: the course's command-line tool. `raylab --help` lists the commands.
#include "build_info.h"
#include "commands.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
    using namespace raylab;
    CLI::App app{"raylab: the ray-tracing labs of TP1 (premières images).\n"
                 "This program was built as the " + std::string(build::kImpl) + " build: " + build::kLabOrigins};
    app.require_subcommand(1);
    std::string impl = build::kImpl;
    int threads = 0;
    std::string scenesDir = build::kScenesDir;
    auto addCommon = [&](CLI::App* command) {
        command->add_option("--threads", threads, "render threads (0: one per core)")->check(CLI::NonNegativeNumber);
        command->add_option("--scenes", scenesDir, "the folder of figure scene files")->check(CLI::ExistingDirectory);
    };

    cli::FiguresOptions figures;
    CLI::App* figuresCmd = app.add_subcommand("figures", "render every lab figure to DIR/<id>.png");
    figuresCmd->add_option("--impl", impl, "whose lab code renders: student (labs/) or reference (solutions/)")
        ->check(CLI::IsMember({"student", "reference"}));
    figuresCmd->add_option("--out", figures.out, "output folder (default: out/<impl>)");
    figuresCmd->add_option("--only", figures.only, "render only these figure ids");
    addCommon(figuresCmd);

    int lab = 0;
    CLI::App* labCmd = app.add_subcommand("lab", "render lab N's figures from your code in labs/");
    labCmd->add_option("N", lab, "the lab number, 1 to 5")->required()->check(CLI::Range(1, 5));
    labCmd->add_option("--out", figures.out, "output folder (default: out/student)");
    addCommon(labCmd);

    std::string sceneFile, renderOut;
    CLI::App* renderCmd = app.add_subcommand("render", "render one scene file (TOML) to a PNG");
    renderCmd->add_option("FILE", sceneFile, "the scene file")->required();
    renderCmd->add_option("--out", renderOut, "the PNG to write (default: out/<scene name>.png)");
    addCommon(renderCmd);

    int repeats = 3;
    CLI::App* benchCmd = app.add_subcommand("bench", "primary rays per second on lab 5's scene at 1, 4, 16, 64 samples");
    benchCmd->add_option("--impl", impl, "whose lab code: student or reference")->check(CLI::IsMember({"student", "reference"}));
    benchCmd->add_option("--repeats", repeats, "renders per measurement (the median is shown)")->check(CLI::Range(1, 100));
    addCommon(benchCmd);

    CLI11_PARSE(app, argc, argv);

    // The student and the reference code define the same functions, so each lives in its own program.
    if (impl != build::kImpl) return cli::runOtherImpl(impl, argc, argv);
    try {
        if (figuresCmd->parsed() || labCmd->parsed()) {
            figures.scenes = scenesDir;
            figures.threads = threads;
            figures.lab = lab;
            if (figures.out.empty()) figures.out = std::filesystem::path("out") / impl;
            return cli::runFigures(figures);
        }
        if (renderCmd->parsed()) return cli::runRender(sceneFile, renderOut, threads);
        if (benchCmd->parsed()) return cli::runBench(scenesDir, threads, repeats);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raylab: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
