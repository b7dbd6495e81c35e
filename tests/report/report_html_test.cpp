// The HTML report itself: every chart present with the expected series,
// flagged timings hatched, images embedded, links relative, nothing fetched.

#include "ReportFixture.h"

#include "report/BenchInput.h"
#include "report/DataUri.h"
#include "report/ReportHtml.h"
#include "report/ReportWriter.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using namespace tessera;

namespace {

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

size_t countOf(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
    return n;
}

/// The SVG of chart `id`.
std::string chart(const std::string& html, const std::string& id) {
    const size_t start = html.find("data-chart=\"" + id + "\"");
    if (start == std::string::npos) return {};
    return html.substr(start, html.find("</svg>", start) - start);
}

std::string writeFixtureReport(const std::string& name) {
    const fs::path dir = fs::path(TESSERA_TEST_OUTPUT_DIR) / "report" / name;
    fs::remove_all(dir);
    test::writeFixture(dir);
    auto written = report::writeReport({dir, dir / "report.html", "1800,900,6800,-30,-16", {}, {}});
    EXPECT_TRUE(written) << written.error().message;
    return readText(dir / "report.html");
}

} // namespace

TEST(ReportHtml, EveryChartHasItsSeries) {
    const std::string html = writeFixtureReport("html");
    for (const char* view : {"far", "close"}) {
        const std::string v = view;
        const std::string gpu = chart(html, "gpu-ms-" + v);
        ASSERT_FALSE(gpu.empty()) << "gpu-ms-" << v;
        for (const char* pass :
             {"terrain.factors", "r2vb.cage", "r2vb.factors", "streamout.cull", "terrain.lowres", "terrain.adaptive"})
            EXPECT_NE(gpu.find("data-series=\"" + std::string(pass) + "\""), std::string::npos) << v << " " << pass;
        // Stacked per backend: one bar per row and backend.
        EXPECT_NE(gpu.find("data-row=\"adaptive/detail · streamout\""), std::string::npos);
        const std::string frame = chart(html, "frame-ms-" + v);
        EXPECT_NE(frame.find("data-series=\"gpu frame\""), std::string::npos);
        EXPECT_NE(frame.find("data-series=\"wall-clock frame\""), std::string::npos);
        for (const char* id : {"triangles-", "ratio-triangles-"}) {
            const std::string svg = chart(html, id + v);
            EXPECT_NE(svg.find("data-series=\"r2vb\""), std::string::npos) << id << v;
            EXPECT_NE(svg.find("data-series=\"streamout\""), std::string::npos) << id << v;
        }
        EXPECT_NE(chart(html, "triangles-" + v).find("data-series=\"hulldomain\""), std::string::npos);
        const std::string inv = chart(html, "invocations-" + v);
        for (const char* s : {"vertex shader", "tess. evaluation", "geometry shader", "task shader", "mesh shader"})
            EXPECT_NE(inv.find("data-series=\"" + std::string(s) + "\""), std::string::npos) << s;
        EXPECT_FALSE(chart(html, "ratio-time-" + v).empty());
    }
    const std::string memory = chart(html, "memory");
    for (const char* b : test::kFixtureBackends)
        EXPECT_NE(memory.find("data-series=\"" + std::string(b) + "\""), std::string::npos) << b;
}

TEST(ReportHtml, FlaggedTimingsAreHatchedNotFacts) {
    const std::string html = writeFixtureReport("html-flags");
    const std::string gpu = chart(html, "gpu-ms-far");
    // r2vb's main pass is hatched in both far rows; no other pass is.
    const std::regex flagged("class=\"mark flagged\" data-series=\"([^\"]+)\" data-row=\"([^\"]+)\"");
    std::vector<std::string> marks;
    for (auto it = std::sregex_iterator(gpu.begin(), gpu.end(), flagged); it != std::sregex_iterator(); ++it)
        marks.push_back((*it)[1].str() + " @ " + (*it)[2].str());
    EXPECT_EQ(marks, (std::vector<std::string>{"terrain.lowres @ lowres · r2vb",
                                               "terrain.adaptive @ adaptive/detail · r2vb"}));
    EXPECT_NE(gpu.find("url(#hatch-gpu-ms-far)"), std::string::npos);
    // Its time ratio against hulldomain is marked too; triangles are facts.
    EXPECT_NE(chart(html, "ratio-time-far").find("class=\"mark flagged\" data-series=\"r2vb\""), std::string::npos);
    EXPECT_EQ(chart(html, "ratio-triangles-far").find("flagged"), std::string::npos);
    EXPECT_NE(html.find("4 timings are flagged"), std::string::npos);
    EXPECT_NE(html.find("0.43% of the 30.00 ms wall-clock frame"), std::string::npos);
}

TEST(ReportHtml, SelfContainedWithImagesAndLinks) {
    const std::string html = writeFixtureReport("html-self");
    // Screenshots of four backends and diffs of three, embedded.
    EXPECT_EQ(countOf(html, "src=\"data:image/png;base64,"), 7u);
    EXPECT_NE(html.find("33.33% of pixels differ"), std::string::npos); // the band: 12 of 36 rows
    // Nothing is fetched: no script, no external style or image.
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_EQ(html.find("src=\"http"), std::string::npos);
    EXPECT_EQ(html.find("<link"), std::string::npos);
    // Links to the traces beside it.
    for (const char* link : {"href=\"bench-hulldomain.json\"", "href=\"bench-r2vb.json\"",
                             "href=\"bench-streamout.json\"", "href=\"bench-meshshader.json\"",
                             "href=\"report-trace.json\""})
        EXPECT_NE(html.find(link), std::string::npos) << link;
    EXPECT_NE(html.find("llvmpipe (LLVM 15.0.6, 256 bits)"), std::string::npos);
    EXPECT_NE(html.find("Mesa 22.3.6"), std::string::npos);
    EXPECT_NE(html.find("--camera 1800,900,6800,-30,-16"), std::string::npos);
    EXPECT_TRUE(
        std::regex_search(html, std::regex("measured</th><td>20[0-9]{2}-[0-9]{2}-[0-9]{2} [0-9]{2}:[0-9]{2} UTC")));
}

TEST(ReportHtml, EscapesText) {
    EXPECT_EQ(report::escapeHtml("<a href=\"x\">&'"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;");
}

TEST(ReportHtml, Base64MatchesTheStandard) {
    auto b = [](const std::string& s) { return report::base64(std::vector<uint8_t>(s.begin(), s.end())); };
    EXPECT_EQ(b(""), "");
    EXPECT_EQ(b("f"), "Zg==");
    EXPECT_EQ(b("fo"), "Zm8=");
    EXPECT_EQ(b("foo"), "Zm9v");
    EXPECT_EQ(b("foobar"), "Zm9vYmFy");
}
