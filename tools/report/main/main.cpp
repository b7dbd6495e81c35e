// tessera-report: the backends' comparison report (docs/BACKENDS.md, "The
// comparison report"). Exit status: 0 written, 1 an input or a run failed,
// 2 a bad command line.

#include "DemoRun.h"
#include "ReportOptions.h"

#include "report/ReportWriter.h"

#include <cstdio>

using namespace tessera;

int main(int argc, char** argv) {
    auto parsed = reporttool::parseReportOptions(argc, argv);
    if (!parsed) {
        std::fprintf(stderr, "tessera-report: %s\n%s", parsed.error().message.c_str(),
                     reporttool::reportUsage().c_str());
        return 2;
    }
    const reporttool::ReportOptions& options = parsed.value();
    if (options.help) {
        std::fputs(reporttool::reportUsage().c_str(), stdout);
        return 0;
    }
    report::ReportJob job;
    job.inputDir = options.dir;
    job.html = options.out;
    job.rules.minMainPassShare = options.minMainPassPercent / 100.0;
    job.rules.minGpuFrameShare = options.minGpuFramePercent / 100.0;
    if (options.run) {
        auto demo = reporttool::findDemo(options);
        if (!demo) {
            std::fprintf(stderr, "tessera-report: %s\n", demo.error().message.c_str());
            return 1;
        }
        if (auto ran = reporttool::runDemo(options, demo.value()); !ran) {
            std::fprintf(stderr, "tessera-report: %s\n", ran.error().message.c_str());
            return 1;
        }
        job.camera = options.camera;
        job.measuredAt = report::nowUtc();
    }
    auto written = report::writeReport(job);
    if (!written) {
        std::fprintf(stderr, "tessera-report: %s\n", written.error().message.c_str());
        return 1;
    }
    for (const auto& note : written->notes) std::fprintf(stderr, "tessera-report: note: %s\n", note.c_str());
    std::fprintf(stderr, "tessera-report: wrote %s (%ju bytes; %zu records, %zu timings flagged)\n",
                 written->html.string().c_str(), written->htmlBytes, written->records, written->flags);
    if (!written->trace.empty())
        std::fprintf(stderr, "tessera-report: wrote %s (%ju bytes; one process per backend)\n",
                     written->trace.string().c_str(), written->traceBytes);
    return 0;
}
