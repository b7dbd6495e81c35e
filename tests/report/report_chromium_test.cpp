// The report opened in a real browser: headless Chromium renders it, takes a
// screenshot, and the charts must have drawn (each backend's colour and the
// hatching of flagged timings on screen) with every chart and series in the
// DOM it built. Skipped, saying why, where Chromium is not installed
// (Debian's `chromium`; TESSERA_CHROMIUM names another).

#include "ReportFixture.h"
#include "ToolProcess.h"

#include "tessera/core/ImageFile.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace tessera;

namespace {

std::string findChromium() {
    if (const char* named = std::getenv("TESSERA_CHROMIUM"); named && *named) return named;
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    size_t start = 0;
    while (start <= dirs.size()) {
        const size_t end = dirs.find(':', start);
        const std::string dir = dirs.substr(start, end == std::string::npos ? std::string::npos : end - start);
        for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
            const fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
            if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
        }
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return {};
}

std::vector<std::string> chromiumArgs() {
    // No sandbox: test machines and containers run as root, where Chromium
    // refuses its sandbox; the page is our own file.
    return {"--headless",        "--no-sandbox",   "--disable-gpu",
            "--hide-scrollbars", "--no-first-run", "--disable-dev-shm-usage",
            "--mute-audio"};
}

/// Pixels within 4 per channel of `rgb` (0xRRGGBB).
size_t pixelsOf(const Rgba8Image& image, uint32_t rgb) {
    const int r = int(rgb >> 16 & 255), g = int(rgb >> 8 & 255), b = int(rgb & 255);
    size_t n = 0;
    for (size_t p = 0; p + 3 < image.pixels.size(); p += 4)
        n += std::abs(image.pixels[p] - r) <= 4 && std::abs(image.pixels[p + 1] - g) <= 4 &&
             std::abs(image.pixels[p + 2] - b) <= 4;
    return n;
}

size_t countOf(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
    return n;
}

} // namespace

TEST(ReportChromium, ChartsRenderInHeadlessChromium) {
    const std::string chromium = findChromium();
    if (chromium.empty())
        GTEST_SKIP() << "chromium is not installed (apt-get install chromium, or set TESSERA_CHROMIUM): the report "
                        "cannot be opened in a browser here";
    const fs::path dir = fs::path(TESSERA_TEST_OUTPUT_DIR) / "report" / "chromium";
    fs::remove_all(dir);
    test::writeFixture(dir);
    auto written = test::runProgram(TESSERA_REPORT_EXE, {"--dir", dir.string()});
    ASSERT_EQ(written.exitCode, 0) << written.output;
    const std::string url = "file://" + fs::absolute(dir / "report.html").string();

    // The screenshot: the page's top, with the flags and the GPU-per-pass charts.
    const fs::path shot = dir / "chromium.png";
    std::vector<std::string> args = chromiumArgs();
    args.push_back("--screenshot=" + shot.string());
    args.push_back("--window-size=1000,1600");
    args.push_back(url);
    auto ran = test::runProgram(chromium, args);
    ASSERT_EQ(ran.exitCode, 0) << ran.output;
    auto image = readPng(shot);
    ASSERT_TRUE(image) << image.error().message << "\n" << ran.output;
    EXPECT_EQ(image->width, 1000u);
    // Not blank: the page's white is far from every pixel.
    const size_t white = pixelsOf(*image, 0xffffff);
    EXPECT_LT(white, size_t(image->width) * image->height * 95 / 100) << "the page looks blank";
    // The main passes' bars (terrain.*), r2vb's cage pass and the hatching of
    // r2vb's flagged main pass are on screen, each at least a bar's worth.
    EXPECT_GT(pixelsOf(*image, 0x3d6fd9), 500u) << "main-pass bars did not render; see " << shot;
    EXPECT_GT(pixelsOf(*image, 0x868e96), 50u) << "no hatching of the flagged pass; see " << shot;

    // The DOM Chromium built: every chart and series parsed.
    std::vector<std::string> domArgs = chromiumArgs();
    domArgs.push_back("--dump-dom");
    domArgs.push_back(url);
    auto dom = test::runProgram(chromium, domArgs);
    ASSERT_EQ(dom.exitCode, 0) << dom.output;
    EXPECT_EQ(countOf(dom.output, "<svg class=\"chart\""), 13u) << "2 views x 6 charts and the memory chart";
    for (const char* series : {"hulldomain", "r2vb", "streamout", "terrain.adaptive", "r2vb.cage", "wall-clock frame"})
        EXPECT_NE(dom.output.find("data-series=\"" + std::string(series) + "\""), std::string::npos) << series;
    EXPECT_GE(countOf(dom.output, "class=\"mark flagged\""), 4u);
}
