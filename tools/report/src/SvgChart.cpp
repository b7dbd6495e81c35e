#include "SvgChart.h"

#include "report/ReportHtml.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace tessera::report {
namespace {

constexpr int kWidth = 940;
constexpr int kLabelWidth = 210;
constexpr int kBarArea = 500;
constexpr int kBarHeight = 14;
constexpr int kRowHeight = 19;
constexpr int kTop = 34;

std::string num(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2f", v);
    return buffer;
}

/// A "nice" axis maximum: 1, 2 or 5 times a power of ten at or above `v`.
double niceCeiling(double v) {
    if (v <= 0.0) return 1.0;
    const double p = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= v) return m * p;
    return 10.0 * p;
}

} // namespace

std::string formatValue(double value) {
    if (value == 0.0) return "0";
    char buffer[48];
    const double a = std::fabs(value);
    if (a >= 10000.0) {
        std::snprintf(buffer, sizeof buffer, "%.0f", value);
        std::string digits = buffer, out;
        const size_t sign = digits[0] == '-' ? 1 : 0;
        for (size_t i = 0; i < digits.size(); ++i) {
            if (i > sign && (digits.size() - i) % 3 == 0) out += ',';
            out += digits[i];
        }
        return out;
    }
    if (a >= 100.0)
        std::snprintf(buffer, sizeof buffer, "%.0f", value);
    else if (a >= 10.0)
        std::snprintf(buffer, sizeof buffer, "%.1f", value);
    else if (a >= 1.0)
        std::snprintf(buffer, sizeof buffer, "%.2f", value);
    else
        std::snprintf(buffer, sizeof buffer, "%.3f", value);
    return buffer;
}

std::string seriesColour(const std::string& series) {
    static const std::map<std::string, std::string> kFixed = {
        {"hulldomain", "#1f6fb4"},       {"r2vb", "#d0542a"},
        {"streamout", "#2f9e44"},        {"meshshader", "#ae3ec9"},
        {"gpu frame", "#5b4bb7"},
        {"wall-clock frame", "#9aa5b1"}, {"vertex shader", "#e8a33d"},
        {"tess. evaluation", "#1f6fb4"}, {"geometry shader", "#2f9e44"},
        {"task shader", "#c2255c"},      {"mesh shader", "#ae3ec9"}};
    if (auto it = kFixed.find(series); it != kFixed.end()) return it->second;
    // Passes: the main terrain passes share one colour (they draw the frame),
    // the others take palette colours in order of first use.
    if (series.rfind("terrain.", 0) == 0 && series != "terrain.factors" && series != "terrain.splat") return "#3d6fd9";
    static const char* kPalette[] = {"#f08c00", "#c2255c", "#0ca678", "#7048e8", "#e8590c", "#1098ad",
                                     "#a61e4d", "#5c940d", "#862e9c", "#d9480f", "#364fc7", "#087f5b"};
    static std::map<std::string, size_t> assigned;
    auto [it, added] = assigned.emplace(series, assigned.size());
    (void)added;
    return kPalette[it->second % (sizeof kPalette / sizeof kPalette[0])];
}

std::string renderSvgChart(const SvgChart& chart) {
    double maxTotal = chart.referenceLine;
    std::vector<std::string> series;
    int gaps = 0;
    for (const SvgBar& bar : chart.bars) {
        double total = 0.0;
        for (const SvgSegment& s : bar.segments) {
            total += std::max(0.0, s.value);
            if (std::find(series.begin(), series.end(), s.series) == series.end()) series.push_back(s.series);
        }
        maxTotal = std::max(maxTotal, total);
        gaps += bar.gapBefore ? 1 : 0;
    }
    const double axisMax = niceCeiling(maxTotal);
    const int legendRows = int((series.size() + 3) / 4);
    const int barsHeight = int(chart.bars.size()) * kRowHeight + gaps * 8;
    const int height = kTop + barsHeight + 26 + legendRows * 18 + 6;
    const std::string hatch = "hatch-" + chart.id;
    std::string svg;
    svg += "<svg class=\"chart\" data-chart=\"" + escapeHtml(chart.id) +
           "\" xmlns=\"http://www.w3.org/2000/svg\" "
           "width=\"" +
           std::to_string(kWidth) + "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " +
           std::to_string(kWidth) + " " + std::to_string(height) + "\" role=\"img\" aria-label=\"" +
           escapeHtml(chart.title) + "\">\n";
    svg += "<defs><pattern id=\"" + hatch +
           "\" patternUnits=\"userSpaceOnUse\" width=\"6\" height=\"6\" "
           "patternTransform=\"rotate(45)\"><rect width=\"6\" height=\"6\" fill=\"#e9ecef\"/>"
           "<rect width=\"3\" height=\"6\" fill=\"#868e96\"/></pattern></defs>\n";
    svg += "<text x=\"0\" y=\"16\" class=\"chart-title\">" + escapeHtml(chart.title) + "</text>\n";
    // Grid and axis labels.
    const int axisY = kTop + barsHeight;
    for (int t = 0; t <= 4; ++t) {
        const double x = kLabelWidth + kBarArea * t / 4.0;
        svg += "<line x1=\"" + num(x) + "\" y1=\"" + std::to_string(kTop - 4) + "\" x2=\"" + num(x) + "\" y2=\"" +
               std::to_string(axisY) + "\" stroke=\"#dee2e6\"/>";
        svg += "<text x=\"" + num(x) + "\" y=\"" + std::to_string(axisY + 13) +
               "\" text-anchor=\"middle\" class=\"axis\">" + formatValue(axisMax * t / 4.0) + "</text>\n";
    }
    svg += "<text x=\"" + std::to_string(kLabelWidth + kBarArea) + "\" y=\"" + std::to_string(kTop - 8) +
           "\" text-anchor=\"end\" class=\"axis\">" + escapeHtml(chart.unit) + "</text>\n";
    int y = kTop;
    for (const SvgBar& bar : chart.bars) {
        if (bar.gapBefore) y += 8;
        svg += "<text x=\"" + std::to_string(kLabelWidth - 6) + "\" y=\"" + std::to_string(y + 11) +
               "\" text-anchor=\"end\" class=\"label\">" + escapeHtml(bar.label) + "</text>";
        double x = kLabelWidth;
        for (const SvgSegment& s : bar.segments) {
            // A flagged mark is at least a few pixels wide, so the hatching
            // shows even where the timestamps read next to nothing.
            const double w = std::max(std::max(0.0, s.value) / axisMax * kBarArea, s.flagged ? 8.0 : 0.0);
            const std::string fill = s.flagged ? "url(#" + hatch + ")" : seriesColour(s.series);
            svg += "<rect x=\"" + num(x) + "\" y=\"" + std::to_string(y) + "\" width=\"" + num(std::max(w, 0.0)) +
                   "\" height=\"" + std::to_string(kBarHeight) + "\" fill=\"" + fill + "\"" +
                   (s.flagged ? " stroke=\"#495057\" stroke-width=\"0.5\" class=\"mark flagged\"" : " class=\"mark\"") +
                   " data-series=\"" + escapeHtml(s.series) + "\" data-row=\"" + escapeHtml(bar.label) +
                   "\" data-value=\"" + escapeHtml(formatValue(s.value)) + "\" shape-rendering=\"crispEdges\"><title>" +
                   escapeHtml(s.series + ": " + (s.tooltip.empty() ? formatValue(s.value) : s.tooltip)) +
                   "</title></rect>";
            x += w;
        }
        if (!bar.note.empty())
            svg += "<text x=\"" + num(std::min(x, double(kLabelWidth + kBarArea)) + 6) + "\" y=\"" +
                   std::to_string(y + 11) + "\" class=\"note\">" + escapeHtml(bar.note) + "</text>";
        svg += "\n";
        y += kRowHeight;
    }
    if (chart.referenceLine > 0.0) {
        const double x = kLabelWidth + chart.referenceLine / axisMax * kBarArea;
        svg += "<line x1=\"" + num(x) + "\" y1=\"" + std::to_string(kTop - 4) + "\" x2=\"" + num(x) + "\" y2=\"" +
               std::to_string(axisY) + "\" stroke=\"#212529\" stroke-dasharray=\"4 3\" class=\"reference\"/>\n";
    }
    // Legend, four series a line.
    int ly = axisY + 30;
    for (size_t i = 0; i < series.size(); ++i) {
        const int lx = kLabelWidth + int(i % 4) * 180;
        if (i > 0 && i % 4 == 0) ly += 18;
        svg += "<rect x=\"" + std::to_string(lx) + "\" y=\"" + std::to_string(ly - 10) +
               "\" width=\"12\" height=\"12\" fill=\"" + seriesColour(series[i]) +
               "\" class=\"legend\" data-series=\"" + escapeHtml(series[i]) + "\"/><text x=\"" +
               std::to_string(lx + 16) + "\" y=\"" + std::to_string(ly) + "\" class=\"label\">" +
               escapeHtml(series[i]) + "</text>";
    }
    svg += "\n</svg>\n";
    return svg;
}

} // namespace tessera::report
