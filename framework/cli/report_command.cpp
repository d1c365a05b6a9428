// raylab report: the student's lab report kit (framework/report/ does the work).
#include "build_info.h"
#include "commands.h"

#include "grader/lab_catalog.h"
#include "src/messages.h"
#include "src/terminal.h"
#include "report/report_kit.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

namespace raylab::cli {

void addReportCommand(CLI::App& app, Context& context) {
    auto request = std::make_shared<report::ReportRequest>();
    auto out = std::make_shared<std::string>("out/report-kit");
    CLI::App* command = app.add_subcommand("report", tr("cli.report"));
    command->add_option("--out", *out, tr("cli.report_out"));
    command->add_flag("--pdf", request->pdf, tr("cli.report_pdf"));
    context.addImplOption(command);
    context.addRenderOptions(command);
    command->callback([&context, request, out] {
        if (context.ranInOtherImpl()) return;
        request->referenceBuild = std::string(build::kImpl) == "reference";
        if (!request->referenceBuild) { // the report grades as `raylab grade` does, the code as it is now
            ensureFreshAgents(context, 0);
            const grader::LabCatalog course = courseLabs();
            BuiltAgents built = agentsOfThisBuild(course, course.numbers());
            request->unbuilt = std::move(built.unbuilt);
            request->buildMessage = std::move(built.message);
        }
        request->out = *out;
        request->treeOut = std::filesystem::path(build::kSourceDir) / "out";
        request->lang = languageCode(language()); // the global --lang, or the environment's (raylab/messages.h)
        request->threads = context.threads;
        request->progress = stderrIsInteractive();
        request->scenes = context.scenes;
        request->references = referenceFolders("");
        request->labs = labsFolder();
        request->programs = build::kBinaryDir;
        std::printf("%s\n", tr("report.banner", {{"impl", tr(std::string("figures.impl_") + build::kImpl)},
                                                  {"origins", build::kLabOrigins}, {"folder", *out}})
                                .c_str());
        context.exitStatus = report::writeReportKit(*request);
    });
}

} // namespace raylab::cli
