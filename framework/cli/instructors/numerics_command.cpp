// raylab numerics: every measurement of docs/numerics.md; raylab study intersection: the
// intersection's part of it (issue 5's accuracy-against-time study).
#include "cli/build_info.h"
#include "cli/commands.h"

#include "study/instructors/numerics_study.h"

#include "src/atomic_file.h"
#include "src/messages.h"

#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

namespace raylab::cli {

namespace {

struct NumericsOptions {
    std::filesystem::path out;
    study::StudyOptions study;
};

using Measurement = std::function<study::Table(const study::StudyOptions&)>;

// Runs the measurements in order, printing each table as it is done, then writes DIR/<id>.csv for
// each and DIR/<name>.md with them all.
int runMeasurements(const std::vector<Measurement>& measurements, const NumericsOptions& o, const std::string& name) {
    std::printf("raylab %s: %s build (%s), %d rays per configuration, %d timing runs -> %s\n", name.c_str(),
                build::kImpl, build::kLabOrigins, o.study.rays, o.study.repeats, o.out.string().c_str());
    std::string markdown = "<!-- written by `raylab " + name + "` (" + build::kImpl + " build: " + build::kLabOrigins +
                           "); do not edit -->\n\n";
    for (const Measurement& measure : measurements) {
        const auto start = std::chrono::steady_clock::now();
        const study::Table table = measure(o.study);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::string md = study::toMarkdown(table);
        std::printf("\n%s(%s.csv, %.1f s)\n", md.c_str(), table.id.c_str(), seconds);
        std::fflush(stdout);
        study::writeCsv(o.out, table);
        markdown += md + "\n";
    }
    const std::filesystem::path file = o.out / (name + ".md");
    writeFileAtomically(file, markdown);
    std::printf("\nwrote %s and one CSV per table in %s\n", file.filename().string().c_str(), o.out.string().c_str());
    return 0;
}

void addOptions(CLI::App* command, NumericsOptions& o, Context& context) {
    command->add_option("--out", o.out, tr("cli.numerics_out"));
    command->add_option("--rays", o.study.rays, tr("cli.numerics_rays"))->check(integerIn(100, 100000000));
    command->add_option("--repeats", o.study.repeats, tr("cli.numerics_repeats"))->check(integerIn(1, 1000));
    context.addImplOption(command);
}

} // namespace

void addNumericsCommands(CLI::App& app, Context& context) {
    auto all = std::make_shared<NumericsOptions>();
    all->out = "out/numerics";
    CLI::App* numerics = app.add_subcommand("numerics", tr("cli.numerics"));
    addOptions(numerics, *all, context);
    numerics->add_option("--max-samples", all->study.maxSamples, tr("cli.numerics_max_samples"))
        ->check(integerIn(1000, std::int64_t(1) << 31));
    numerics->callback([&context, all] {
        if (context.ranInOtherImpl()) return;
        context.exitStatus = runMeasurements(
            {study::studyFarSpheres, study::studyIntersectionTimes, study::studyLargeCoordinates,
             [](const study::StudyOptions&) { return study::studyFarDisc(); },
             [](const study::StudyOptions&) { return study::studyDegenerateCameras(); },
             [](const study::StudyOptions&) { return study::studyPixelCentres(); }, study::studyAccumulation},
            *all, "numerics");
    });

    CLI::App* study = studyCommand(app);
    auto intersection = std::make_shared<NumericsOptions>();
    intersection->out = "out/study/intersection";
    CLI::App* command = study->add_subcommand("intersection", tr("cli.study_intersection"));
    addOptions(command, *intersection, context);
    command->callback([&context, intersection] {
        if (context.ranInOtherImpl()) return;
        context.exitStatus = runMeasurements({study::studyFarSpheres, study::studyIntersectionTimes,
                                              study::studyLargeCoordinates,
                                              [](const study::StudyOptions&) { return study::studyFarDisc(); }},
                                             *intersection, "study-intersection");
    });
}

} // namespace raylab::cli
