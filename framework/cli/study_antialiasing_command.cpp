// raylab study antialiasing: each sampler's error against time on lab 5's scene (docs/accuracy.md).
#include "build_info.h"
#include "commands.h"

#include "../study/antialiasing_study.h"
#include "src/messages.h"
#include "src/scene_file.h"

#include <cstdio>
#include <memory>

namespace raylab::cli {

void addStudyAntialiasingCommand(CLI::App& app, Context& context) {
    CLI::App* study = studyCommand(app);
    auto o = std::make_shared<study::AntialiasingOptions>();
    auto out = std::make_shared<std::string>();
    CLI::App* command = study->add_subcommand("antialiasing", tr("cli.study_antialiasing"));
    command->add_option("--out", *out, tr("cli.study_out"));
    command->add_flag("--quick", o->quick, tr("cli.study_quick"));
    command->add_option("--repeats", o->repeats, tr("cli.study_repeats"))->check(integerIn(1, 50));
    context.addImplOption(command);
    context.addRenderOptions(command);
    command->callback([&context, o, out] {
        if (context.ranInOtherImpl()) return;
        o->threads = context.threads;
        o->scene = figureWithRole(context.scenes, "bench").file;
        o->thinObjects = std::filesystem::path(build::kSourceDir) / "scenes" / "study" / "adaptive_thin_objects.toml";
        o->out = !out->empty() ? std::filesystem::path(*out)
                 : o->quick   ? std::filesystem::path("out") / "study-quick"
                              : std::filesystem::path(build::kSourceDir) / "docs";
        study::runAntialiasingStudy(*o);
    });
}

} // namespace raylab::cli
