#pragma once
/// @file ReportFixture.h
/// A report's inputs written by hand: the terrain benchmark's JSON for three
/// backends on lavapipe (r2vb's main pass reading 0.13 ms of a 30 ms frame,
/// as the issue saw), their traces and screenshots. No GPU needed.

#include "tessera/core/ImageFile.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace tessera::test {

/// The backends of the fixture, in the report's order.
inline constexpr const char* kFixtureBackends[] = {"hulldomain", "r2vb", "streamout", "meshshader"};

inline nlohmann::json fixtureRecord(const std::string& backend, const std::string& view, const std::string& mode,
                                    const std::string& metric, double mainMs, double cpuMs, const std::string& device) {
    nlohmann::json r;
    r["backend"] = backend;
    r["device"] = device;
    r["driver"] = "Mesa 22.3.6";
    r["view"] = view;
    r["mode"] = mode;
    r["metric"] = metric;
    r["width"] = 320;
    r["height"] = 180;
    r["cpu_frame_ms_median"] = cpuMs;
    r["clipping_invocations"] = 21302;
    r["triangles"] = 21302;
    const bool mesh = backend == "meshshader";
    r["vertex_shader_invocations"] = backend == "hulldomain" ? 959 : mesh ? 0 : 72537;
    r["tess_evaluation_invocations"] = backend == "hulldomain" ? 19786 : 0;
    r["geometry_shader_invocations"] = backend == "streamout" ? 959 : 0;
    r["task_shader_invocations"] = mesh ? 992 : 0;
    r["mesh_shader_invocations"] = mesh ? 171264 : 0;
    r["intermediate_bytes"] = backend == "hulldomain" ? 25088
                              : backend == "r2vb"     ? 724787
                              : mesh                  ? 294720
                                                      : 341811;
    r["trace"] = "bench-" + backend + ".json";
    std::vector<std::pair<std::string, double>> passes;
    if (backend == "hulldomain") passes = {{"terrain.factors", 0.019}};
    if (backend == "r2vb") passes = {{"r2vb.cage", 0.029}, {"r2vb.factors", 0.023}, {"r2vb.copyFactors", 0.013}};
    if (backend == "streamout") passes = {{"streamout.cage", 0.018}, {"streamout.cull", 0.012}};
    if (mesh) passes = {{"terrain.factors", 0.019}};
    passes.push_back({"terrain." + mode, mainMs});
    std::string names;
    double total = 0.0;
    for (const auto& [name, ms] : passes) {
        names += (names.empty() ? "" : ",") + name;
        r["pass:" + name + ":gpu_ms_median"] = ms;
        total += ms;
    }
    r["passes"] = names;
    r["gpu_ms_median"] = total;
    return r;
}

/// The lavapipe fixture: r2vb's main pass implausible in every row.
inline nlohmann::json fixtureRecords(const std::string& device = "llvmpipe (LLVM 15.0.6, 256 bits)") {
    nlohmann::json records = nlohmann::json::array();
    for (const char* view : {"far", "close"})
        for (const char* mode : {"lowres", "adaptive"})
            for (const char* backend : kFixtureBackends) {
                const std::string b = backend;
                const double main = b == "r2vb" ? 0.13 : b == "hulldomain" ? 18.0 : b == "meshshader" ? 19.0 : 21.0;
                records.push_back(
                    fixtureRecord(b, view, mode, std::string(mode) == "adaptive" ? "detail" : "-", main, 30.0, device));
            }
    return records;
}

inline void writeText(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

/// A trace like TraceWriter's: metadata, a frame slice and a GPU pass.
inline nlohmann::json fixtureTrace(const std::string& backend, double startUs) {
    nlohmann::json events = nlohmann::json::array();
    events.push_back(
        {{"name", "process_name"}, {"ph", "M"}, {"pid", 1}, {"tid", 0}, {"args", {{"name", "tessera bench terrain"}}}});
    events.push_back({{"name", "thread_name"}, {"ph", "M"}, {"pid", 1}, {"tid", 1}, {"args", {{"name", "CPU main"}}}});
    events.push_back({{"name", "frame"},
                      {"cat", "frame"},
                      {"ph", "X"},
                      {"pid", 1},
                      {"tid", 1},
                      {"ts", startUs},
                      {"dur", 30000.0},
                      {"args", {{"frame", 0}}}});
    events.push_back({{"name", "terrain.adaptive"},
                      {"cat", "gpu"},
                      {"ph", "X"},
                      {"pid", 1},
                      {"tid", 1000},
                      {"ts", startUs + 100.0},
                      {"dur", 130.0},
                      {"args", {{"frame", 0}}}});
    events.push_back({{"name", "intermediate bytes"},
                      {"ph", "C"},
                      {"pid", 1},
                      {"ts", startUs + 200.0},
                      {"args", {{"value", 1024}}}});
    return {{"displayTimeUnit", "ms"},
            {"traceEvents", events},
            {"metadata", {{"backend", backend}, {"device", "llvmpipe (LLVM 15.0.6, 256 bits)"}}}};
}

/// A flat image with a band of another colour: backends differ in the band.
inline Rgba8Image fixtureImage(uint8_t band) {
    Rgba8Image image{64, 36, std::vector<uint8_t>(64 * 36 * 4)};
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x) {
            uint8_t* p = &image.pixels[(y * image.width + x) * 4];
            const bool inBand = y >= 12 && y < 24;
            p[0] = inBand ? band : 90;
            p[1] = 140;
            p[2] = 200;
            p[3] = 255;
        }
    return image;
}

/// Writes bench.json, the four traces and screenshots into `dir`.
inline void writeFixture(const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    writeText(dir / "bench.json", fixtureRecords().dump(2));
    double start = 5.0e6;
    for (const char* backend : kFixtureBackends) {
        writeText(dir / ("bench-" + std::string(backend) + ".json"), fixtureTrace(backend, start).dump());
        start += 4.0e6;
    }
    (void)writePng(dir / "screenshot-hulldomain.png", fixtureImage(90));
    (void)writePng(dir / "screenshot-r2vb.png", fixtureImage(250));
    (void)writePng(dir / "screenshot-streamout.png", fixtureImage(250));
    (void)writePng(dir / "screenshot-meshshader.png", fixtureImage(90));
}

} // namespace tessera::test
