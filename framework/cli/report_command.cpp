// raylab report: the student's lab report kit (framework/report/ does the work).
#include "build_info.h"
#include "commands.h"

#include "raylab/messages.h"
#include "raylab/terminal.h"
#include "report/report_kit.h"

#include <cstdio>
#include <memory>
#include <string>

namespace raylab::cli {

void addReportCommand(CLI::App& app, Context& context) {
    auto request = std::make_shared<report::ReportRequest>();
    auto out = std::make_shared<std::string>("out/report-kit");
    CLI::App* command = app.add_subcommand(
        "report", "your lab report: renders and grades your figures into DIR/report.md (yours to write in; a re-run "
                  "keeps your text) and DIR/report.html");
    command->add_option("--out", *out, "the report's folder (default: out/report-kit)");
    command->add_flag("--pdf", request->pdf, "also print DIR/report.pdf (with chromium, when it is installed)");
    context.addImplOption(command);
    context.addRenderOptions(command);
    command->callback([&context, request, out] {
        if (context.ranInOtherImpl()) return;
        request->out = *out;
        request->lang = languageCode(language()); // the global --lang, or the environment's (raylab/messages.h)
        request->threads = context.threads;
        request->progress = stderrIsInteractive();
        request->referenceBuild = std::string(build::kImpl) == "reference";
        request->scenes = context.scenes;
        request->references = referencesFolder();
        request->labs = labsFolder();
        request->programs = build::kBinaryDir;
        std::printf("raylab report, %s build (%s) -> %s\n", build::kImpl, build::kLabOrigins, out->c_str());
        context.exitStatus = report::writeReportKit(*request);
    });
}

} // namespace raylab::cli
