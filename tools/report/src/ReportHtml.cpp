#include "report/ReportHtml.h"

#include "SvgChart.h"
#include "report/DataUri.h"

#include "tessera/core/ImageDiff.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>

namespace tessera::report {
namespace {

const BenchRecord* findRecord(const std::vector<BenchRecord>& records, const BenchRecord& like,
                              const std::string& backend) {
    for (const auto& r : records)
        if (r.backend == backend && r.device == like.device && r.view == like.view && r.mode == like.mode &&
            r.metric == like.metric)
            return &r;
    return nullptr;
}

/// The report's rows of one view: the records of the first backend that has
/// them, in the benchmark's order (lowres, continuous, adaptive per metric).
std::vector<const BenchRecord*> rowsOf(const std::vector<BenchRecord>& records, const std::string& view) {
    std::vector<const BenchRecord*> rows;
    std::set<std::string> seen;
    for (const auto& r : records)
        if (r.view == view && seen.insert(r.device + "|" + r.rowLabel()).second) rows.push_back(&r);
    return rows;
}

std::vector<std::string> viewsOf(const std::vector<BenchRecord>& records) {
    std::vector<std::string> views;
    for (const auto& r : records)
        if (std::find(views.begin(), views.end(), r.view) == views.end()) views.push_back(r.view);
    return views;
}

std::string rowName(const BenchRecord& r) {
    return r.mode + (r.metric.empty() || r.metric == "-" ? std::string() : "/" + r.metric);
}

std::string percent(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2f%%", v * 100.0);
    return buffer;
}

struct Context {
    const ReportInputs& in;
    std::vector<std::string> backends;
    std::map<const BenchRecord*, std::vector<TimingFlag>> flags;
    bool multiDevice = false;
};

std::string label(const Context& c, const BenchRecord& r) {
    return rowName(r) + " · " + r.backend + (c.multiDevice ? " · " + r.device : std::string());
}

/// Per (row, backend) bars of `view`, grouped by row.
template <class MakeBar> std::vector<SvgBar> barsOf(const Context& c, const std::string& view, MakeBar make) {
    std::vector<SvgBar> bars;
    for (const BenchRecord* row : rowsOf(c.in.records, view)) {
        bool first = true;
        for (const std::string& backend : c.backends) {
            const BenchRecord* r = findRecord(c.in.records, *row, backend);
            if (!r) continue;
            SvgBar bar = make(*r);
            bar.label = label(c, *r);
            bar.gapBefore = first && !bars.empty();
            first = false;
            bars.push_back(std::move(bar));
        }
    }
    return bars;
}

std::string gpuPassChart(const Context& c, const std::string& view) {
    SvgChart chart{"gpu-ms-" + view,
                   "GPU ms per pass, " + view + " view (median frame; hatched: not to be trusted)",
                   "ms",
                   {},
                   0.0};
    chart.bars = barsOf(c, view, [&](const BenchRecord& r) {
        SvgBar bar;
        const auto& flags = c.flags.at(&r);
        const bool frameFlagged = isFlagged(flags, "");
        for (const PassTime& p : r.passes)
            bar.segments.push_back(
                {p.name, p.gpuMs, frameFlagged || isFlagged(flags, p.name), formatValue(p.gpuMs) + " ms"});
        bar.note = "GPU " + formatValue(r.gpuMs) + " ms · frame " + formatValue(r.cpuFrameMs) + " ms" +
                   (flags.empty() ? "" : "  ⚠ flagged");
        return bar;
    });
    return renderSvgChart(chart);
}

std::string frameChart(const Context& c, const std::string& view) {
    SvgChart chart{
        "frame-ms-" + view, "GPU frame against wall-clock frame, " + view + " view (ms, median)", "ms", {}, 0.0};
    for (const BenchRecord* row : rowsOf(c.in.records, view)) {
        bool first = true;
        for (const std::string& backend : c.backends) {
            const BenchRecord* r = findRecord(c.in.records, *row, backend);
            if (!r) continue;
            const auto& flags = c.flags.at(r);
            SvgBar gpu{label(c, *r) + " GPU",
                       {{"gpu frame", r->gpuMs, !flags.empty(), formatValue(r->gpuMs) + " ms"}},
                       formatValue(r->gpuMs) + (flags.empty() ? "" : "  ⚠"),
                       first};
            SvgBar wall{label(c, *r) + " wall",
                        {{"wall-clock frame", r->cpuFrameMs, false, formatValue(r->cpuFrameMs) + " ms"}},
                        formatValue(r->cpuFrameMs),
                        false};
            chart.bars.push_back(std::move(gpu));
            chart.bars.push_back(std::move(wall));
            first = false;
        }
    }
    return renderSvgChart(chart);
}

std::string trianglesChart(const Context& c, const std::string& view) {
    SvgChart chart{"triangles-" + view,
                   "Triangles of the main terrain pass, " + view + " view (clipping invocations)",
                   "triangles",
                   {},
                   0.0};
    chart.bars = barsOf(c, view, [&](const BenchRecord& r) {
        SvgBar bar;
        bar.segments.push_back({r.backend, double(r.triangles), false, formatValue(double(r.triangles))});
        bar.note = formatValue(double(r.triangles));
        return bar;
    });
    return renderSvgChart(chart);
}

std::string invocationsChart(const Context& c, const std::string& view) {
    SvgChart chart{"invocations-" + view, "Shader invocations per frame, " + view + " view", "invocations", {}, 0.0};
    chart.bars = barsOf(c, view, [&](const BenchRecord& r) {
        SvgBar bar;
        bar.segments.push_back({"vertex shader", double(r.vertexShaderInvocations), false, {}});
        bar.segments.push_back({"tess. evaluation", double(r.tessEvaluationInvocations), false, {}});
        bar.segments.push_back({"geometry shader", double(r.geometryShaderInvocations), false, {}});
        bar.segments.push_back({"task shader", double(r.taskShaderInvocations), false, {}});
        bar.segments.push_back({"mesh shader", double(r.meshShaderInvocations), false, {}});
        bar.note = formatValue(double(r.vertexShaderInvocations + r.tessEvaluationInvocations +
                                      r.geometryShaderInvocations + r.taskShaderInvocations +
                                      r.meshShaderInvocations));
        return bar;
    });
    return renderSvgChart(chart);
}

std::string memoryChart(const Context& c) {
    SvgChart chart{"memory", "Intermediate memory (largest over the rows, every frame in flight)", "KiB", {}, 0.0};
    for (const std::string& backend : c.backends) {
        uint64_t bytes = 0;
        for (const auto& r : c.in.records)
            if (r.backend == backend) bytes = std::max(bytes, r.intermediateBytes);
        const double kib = double(bytes) / 1024.0;
        chart.bars.push_back(
            {backend, {{backend, kib, false, formatValue(kib) + " KiB"}}, formatValue(kib) + " KiB", false});
    }
    return renderSvgChart(chart);
}

std::string ratioChart(const Context& c, const std::string& view, bool time) {
    const std::string reference = c.backends.empty() ? std::string() : c.backends.front();
    SvgChart chart{std::string(time ? "ratio-time-" : "ratio-triangles-") + view,
                   std::string(time ? "GPU ms" : "Triangles") + " relative to " + reference + ", " + view +
                       " view (dashed: 1.0)",
                   "× " + reference,
                   {},
                   1.0};
    for (const BenchRecord* row : rowsOf(c.in.records, view)) {
        const BenchRecord* ref = findRecord(c.in.records, *row, reference);
        if (!ref) continue;
        bool first = true;
        for (const std::string& backend : c.backends) {
            if (backend == reference) continue;
            const BenchRecord* r = findRecord(c.in.records, *row, backend);
            if (!r) continue;
            const double denominator = time ? ref->gpuMs : double(ref->triangles);
            if (denominator <= 0.0) continue;
            const double ratio = (time ? r->gpuMs : double(r->triangles)) / denominator;
            const bool flagged = time && (!c.flags.at(r).empty() || !c.flags.at(ref).empty());
            char text[32];
            std::snprintf(text, sizeof text, "%.2fx", ratio);
            chart.bars.push_back({label(c, *r),
                                  {{backend, ratio, flagged, text}},
                                  std::string(text) + (flagged ? "  ⚠ not a fact" : ""),
                                  first && !chart.bars.empty()});
            first = false;
        }
    }
    return renderSvgChart(chart);
}

std::string recordTable(const Context& c) {
    std::string html = "<table class=\"records\"><thead><tr><th>view</th><th>row</th><th>backend</th>"
                       "<th>GPU ms</th><th>wall-clock frame ms</th><th>triangles</th><th>× ref (time)</th>"
                       "<th>× ref (triangles)</th><th>VS inv</th><th>TES inv</th><th>GS inv</th>"
                       "<th>interm. KiB</th><th>flags</th></tr></thead><tbody>\n";
    const std::string reference = c.backends.empty() ? std::string() : c.backends.front();
    for (const std::string& view : viewsOf(c.in.records))
        for (const BenchRecord* row : rowsOf(c.in.records, view))
            for (const std::string& backend : c.backends) {
                const BenchRecord* r = findRecord(c.in.records, *row, backend);
                if (!r) continue;
                const BenchRecord* ref = findRecord(c.in.records, *row, reference);
                const auto& flags = c.flags.at(r);
                std::string timeRatio = "-", triRatio = "-";
                char text[32];
                if (ref && ref->gpuMs > 0.0) {
                    std::snprintf(text, sizeof text, "%.2f", r->gpuMs / ref->gpuMs);
                    timeRatio = text;
                }
                if (ref && ref->triangles > 0) {
                    std::snprintf(text, sizeof text, "%.2f", double(r->triangles) / double(ref->triangles));
                    triRatio = text;
                }
                const bool timeDoubt = !flags.empty() || (ref && !c.flags.at(ref).empty());
                html += std::string("<tr") + (flags.empty() ? "" : " class=\"flagged\"") + "><td>" +
                        escapeHtml(r->view) + "</td><td>" + escapeHtml(rowName(*r)) + "</td><td>" +
                        escapeHtml(r->backend) + "</td><td" + (timeDoubt ? " class=\"doubt\"" : "") + ">" +
                        formatValue(r->gpuMs) + "</td><td>" + formatValue(r->cpuFrameMs) + "</td><td>" +
                        formatValue(double(r->triangles)) + "</td><td" + (timeDoubt ? " class=\"doubt\"" : "") + ">" +
                        timeRatio + "</td><td>" + triRatio + "</td><td>" +
                        formatValue(double(r->vertexShaderInvocations)) + "</td><td>" +
                        formatValue(double(r->tessEvaluationInvocations)) + "</td><td>" +
                        formatValue(double(r->geometryShaderInvocations)) + "</td><td>" +
                        formatValue(double(r->intermediateBytes) / 1024.0) + "</td><td>" +
                        (flags.empty() ? std::string() : "⚠ " + std::to_string(flags.size())) + "</td></tr>\n";
            }
    return html + "</tbody></table>\n";
}

std::string flagList(const Context& c) {
    std::string html;
    size_t count = 0;
    for (const auto& r : c.in.records)
        for (const TimingFlag& f : c.flags.at(&r)) {
            ++count;
            html +=
                "<li><b>" + escapeHtml(r.backend + ", " + r.rowLabel()) + "</b>: " + escapeHtml(f.reason) + "</li>\n";
        }
    if (count == 0)
        return "<p class=\"ok\" id=\"flags\">No timing was flagged: every GPU frame fits its wall-clock frame" +
               std::string(" and every main pass takes a plausible share of it.</p>\n");
    return "<div class=\"warn\" id=\"flags\"><p><b>" + std::to_string(count) +
           " timings are flagged and drawn hatched, not as facts.</b> A flagged pass's time is what its timestamps "
           "read, not what it cost; ratios that involve it are marked too.</p><ul>\n" +
           html + "</ul></div>\n";
}

std::string imagesSection(const Context& c) {
    std::string html;
    const Rgba8Image* reference = nullptr;
    std::string referenceName;
    for (const BackendExtras& b : c.in.backends)
        if (b.screenshot) {
            reference = &*b.screenshot;
            referenceName = b.backend;
            break;
        }
    if (!reference) return "<p>No screenshots were given.</p>\n";
    html += "<div class=\"shots\">\n";
    for (const BackendExtras& b : c.in.backends) {
        html += "<figure class=\"shot\" data-backend=\"" + escapeHtml(b.backend) + "\"><figcaption>" +
                escapeHtml(b.backend) + "</figcaption>";
        if (!b.screenshot) {
            html += "<p>no screenshot</p></figure>\n";
            continue;
        }
        if (auto uri = pngDataUri(*b.screenshot))
            html += "<img alt=\"" + escapeHtml(b.backend) + " screenshot\" src=\"" + uri.value() + "\">";
        if (b.backend != referenceName) {
            auto diff = diffImages(*b.screenshot, *reference);
            if (!diff) {
                html += "<p>no diff: " + escapeHtml(diff.error().message) + "</p>";
            } else if (auto uri = pngDataUri(diff->image)) {
                html += "<img class=\"diff\" alt=\"diff against " + escapeHtml(referenceName) + "\" src=\"" +
                        uri.value() + "\"><p>against " + escapeHtml(referenceName) + ": " +
                        percent(diff->differingFraction) + " of pixels differ by more than " +
                        std::to_string(kDiffChannelThreshold) + " (red), mean difference " +
                        formatValue(diff->meanDifference) + "</p>";
            }
        } else {
            html += "<p>the reference</p>";
        }
        html += "</figure>\n";
    }
    return html + "</div>\n";
}

constexpr const char* kStyle = R"(body{font:14px/1.45 system-ui,sans-serif;margin:24px;color:#212529;max-width:1200px}
h1{font-size:22px}h2{font-size:18px;margin-top:32px;border-bottom:1px solid #dee2e6}
.chart{display:block;margin:12px 0 20px}.chart-title{font-weight:600;font-size:13px}
.label,.note{font-size:11px}.axis{font-size:10px;fill:#495057}.note{fill:#495057}
table{border-collapse:collapse;font-size:12px}td,th{border:1px solid #dee2e6;padding:2px 6px;text-align:right}
td:nth-child(-n+3),th{text-align:left}tr.flagged td{background:#fff4e6}td.doubt{color:#868e96;text-decoration:line-through dotted}
.warn{background:#fff4e6;border:1px solid #f08c00;padding:4px 12px}.ok{color:#2f9e44}
.shots{display:flex;flex-wrap:wrap;gap:16px}.shot{margin:0;max-width:390px}.shot img{display:block;max-width:380px;margin-bottom:4px}
.meta td{text-align:left})";

} // namespace

std::string escapeHtml(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char ch : text) {
        switch (ch) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        case '\'':
            out += "&#39;";
            break;
        default:
            out += ch;
        }
    }
    return out;
}

std::string renderReport(const ReportInputs& in) {
    Context c{in, {}, {}, false};
    for (const BackendExtras& b : in.backends) c.backends.push_back(b.backend);
    for (const std::string& b : backendsOf(in.records))
        if (std::find(c.backends.begin(), c.backends.end(), b) == c.backends.end()) c.backends.push_back(b);
    std::set<std::string> devices, drivers, sizes;
    for (const auto& r : in.records) {
        c.flags[&r] = assessRecord(r, in.rules);
        devices.insert(r.device);
        drivers.insert(r.driver.empty() ? "-" : r.driver);
        sizes.insert(std::to_string(r.width) + "x" + std::to_string(r.height));
    }
    c.multiDevice = devices.size() > 1;
    auto join = [](const std::set<std::string>& items) {
        std::string out;
        for (const auto& item : items) out += (out.empty() ? "" : "; ") + item;
        return out;
    };

    std::string html = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
                       "<title>Tessera backend comparison</title><style>";
    html += kStyle;
    html += "</style></head><body>\n<h1>Tessera backend comparison: terrain benchmark</h1>\n";
    html += "<table class=\"meta\"><tr><th>device</th><td>" + escapeHtml(join(devices)) +
            (std::any_of(devices.begin(), devices.end(), isCpuDevice) ? " (a CPU device: GPU timings are checked "
                                                                        "against the wall-clock frame)"
                                                                      : "") +
            "</td></tr><tr><th>driver</th><td>" + escapeHtml(join(drivers)) + "</td></tr><tr><th>resolution</th><td>" +
            escapeHtml(join(sizes)) + "</td></tr><tr><th>backends</th><td>";
    for (size_t i = 0; i < c.backends.size(); ++i) html += (i ? ", " : "") + escapeHtml(c.backends[i]);
    html += " (ratios against " + escapeHtml(c.backends.empty() ? std::string("-") : c.backends.front()) +
            ")</td></tr><tr><th>measured</th><td>" + escapeHtml(in.measuredAt) + "</td></tr><tr><th>written</th><td>" +
            escapeHtml(in.writtenAt) + "</td></tr>";
    if (!in.camera.empty())
        html += "<tr><th>screenshot camera</th><td>--camera " + escapeHtml(in.camera) + "</td></tr>";
    html += "<tr><th>traces</th><td>";
    bool anyTrace = false;
    for (const BackendExtras& b : in.backends)
        if (!b.traceLink.empty()) {
            html += std::string(anyTrace ? " · " : "") + "<a href=\"" + escapeHtml(b.traceLink) + "\">" +
                    escapeHtml(b.backend) + "</a>";
            anyTrace = true;
        }
    if (!in.mergedTraceLink.empty())
        html += std::string(anyTrace ? " · " : "") + "<a href=\"" + escapeHtml(in.mergedTraceLink) +
                "\">all backends on one timeline</a>";
    html += " (open in <a href=\"https://ui.perfetto.dev\">Perfetto UI</a>)</td></tr></table>\n";
    for (const std::string& note : in.notes) html += "<p class=\"warn\">" + escapeHtml(note) + "</p>\n";

    html += "<h2>Timings flagged</h2>\n" + flagList(c);
    const std::vector<std::string> views = viewsOf(in.records);
    html += "<h2>GPU time per pass</h2>\n<p>Each bar is one backend's median frame, stacked by pass; the note "
            "beside it sets the GPU frame against the wall-clock frame of the same frames.</p>\n";
    for (const auto& view : views) html += gpuPassChart(c, view);
    html += "<h2>GPU frame and wall-clock frame</h2>\n";
    for (const auto& view : views) html += frameChart(c, view);
    html += "<h2>Ratios</h2>\n";
    for (const auto& view : views) html += ratioChart(c, view, true) + ratioChart(c, view, false);
    html += "<h2>Triangles</h2>\n";
    for (const auto& view : views) html += trianglesChart(c, view);
    html += "<h2>Shader invocations</h2>\n";
    for (const auto& view : views) html += invocationsChart(c, view);
    html += "<h2>Intermediate memory</h2>\n" + memoryChart(c);
    html += "<h2>Screenshots</h2>\n" + imagesSection(c);
    html += "<h2>Every record</h2>\n" + recordTable(c);
    html += "<p>Written by tessera-report; docs/BACKENDS.md, \"The comparison report\", says how to read it.</p>\n"
            "</body></html>\n";
    return html;
}

} // namespace tessera::report
