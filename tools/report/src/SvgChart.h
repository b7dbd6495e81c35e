#pragma once
/// @file SvgChart.h
/// Horizontal bar charts as inline SVG (private to tessera_report): a bar per
/// row, made of stacked segments, each segment a series. Flagged segments are
/// hatched and grey, never drawn as plain facts.

#include <string>
#include <vector>

namespace tessera::report {

struct SvgSegment {
    std::string series;
    double value = 0.0;
    bool flagged = false;
    std::string tooltip; ///< the <title> of the mark
};

struct SvgBar {
    std::string label;
    std::vector<SvgSegment> segments;
    std::string note;       ///< text right of the bar
    bool gapBefore = false; ///< extra space above: a new group
};

struct SvgChart {
    std::string id; ///< data-chart
    std::string title;
    std::string unit; ///< axis unit ("ms", "triangles")
    std::vector<SvgBar> bars;
    double referenceLine = 0.0; ///< a dashed line at this value (0: none)
};

/// The colour of a series: fixed for the backends and the frame series, a
/// palette colour by first use for pass names.
std::string seriesColour(const std::string& series);

/// The chart's SVG, with a legend of its series.
std::string renderSvgChart(const SvgChart& chart);

/// A number for labels: three significant figures, thousands separated.
std::string formatValue(double value);

} // namespace tessera::report
