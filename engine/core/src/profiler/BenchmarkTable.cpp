// formatTable() from BenchmarkReport.h, apart so each file stays short.
#include "tessera/profiler/BenchmarkReport.h"

#include <algorithm>
#include <array>
#include <charconv>

namespace tessera::profiler {
namespace {

constexpr size_t kColumns = 5;
using Row = std::array<std::string, kColumns>;

std::string formatMs(double ms) {
    char buffer[64];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), ms, std::chars_format::fixed, 3);
    return ec == std::errc() ? std::string(buffer, end) : std::string("?");
}

Row makeRow(const PassSummary& pass) {
    std::string triangles =
        pass.statsMedianFrame ? std::to_string(trianglesOf(*pass.statsMedianFrame)) : "-";
    return {pass.name, formatMs(pass.minMs), formatMs(pass.medianMs), formatMs(pass.maxMs),
            std::move(triangles)};
}

void appendRow(std::string& out, const Row& row, const std::array<size_t, kColumns>& widths) {
    // Name left-aligned, numbers right-aligned so decimal points line up.
    out += row[0];
    out.append(widths[0] - row[0].size(), ' ');
    for (size_t c = 1; c < kColumns; ++c) {
        out.append(2 + widths[c] - row[c].size(), ' ');
        out += row[c];
    }
    out += '\n';
}

} // namespace

std::string formatTable(const BenchmarkSummary& summary) {
    const Row header = {"pass", "min ms", "median ms", "max ms", "triangles"};
    std::vector<Row> passRows;
    for (const PassSummary& pass : summary.passes) passRows.push_back(makeRow(pass));
    const std::array<Row, 2> frameRows = {makeRow(summary.gpuFrame), makeRow(summary.cpuFrame)};

    std::array<size_t, kColumns> widths{};
    auto widen = [&](const Row& row) {
        for (size_t c = 0; c < kColumns; ++c) widths[c] = std::max(widths[c], row[c].size());
    };
    widen(header);
    std::for_each(passRows.begin(), passRows.end(), widen);
    std::for_each(frameRows.begin(), frameRows.end(), widen);
    size_t lineWidth = widths[0];
    for (size_t c = 1; c < kColumns; ++c) lineWidth += 2 + widths[c];

    std::string out;
    appendRow(out, header, widths);
    out.append(lineWidth, '-').push_back('\n');
    for (const Row& row : passRows) appendRow(out, row, widths);
    if (!passRows.empty()) out.append(lineWidth, '-').push_back('\n');
    for (const Row& row : frameRows) appendRow(out, row, widths);
    out += std::to_string(summary.frames) + (summary.frames == 1 ? " frame\n" : " frames\n");
    return out;
}

} // namespace tessera::profiler
