#pragma once
/// @file BenchDriver.h
/// What the five benchmarks (--bench terrain, characters, subdiv, crowd and
/// crowd-sim) share, written once: the backends and devices a benchmark runs
/// on, its warm-up, measured frames and frame size, what it does when a
/// backend cannot run, its per-backend Chrome traces and its outputs (the
/// JSON to a file or stdout, the tables). Each benchmark says only what
/// differs in its BenchPlan and measures its own rows.

#include "tessera/runtime/Options.h"
#include "tessera/runtime/RenderSession.h"
#include "tessera/core/Result.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace tessera::runtime {

/// How one benchmark differs from the others.
struct BenchPlan {
    /// The benchmark's name ("terrain"): its traces' application is
    /// "tessera bench <name>".
    const char* name = "";
    /// The benchmark in the runtime's words (setting::kTerrainBenchmark),
    /// which its own errors begin with.
    const char* setting = "";
    /// The backends `--backend all` compares, in the order of the rows, the
    /// reference (kComparisonReference) first.
    std::vector<std::string> comparison;
    /// Without --backend: every backend of kBackendPreference, in that order
    /// (true), or only the best one the device runs (false).
    bool everyPreferred = true;
    /// Without --device: every Vulkan device (true) or the default one.
    bool everyDevice = false;
    /// Warm-up frames (or steps) and measured ones unless given.
    uint32_t warmup = 3, frames = 10;
    /// Whether a warm-up of 0 takes the default too: the GPU benchmarks always
    /// warm up, so pipeline creation and first-use costs stay out of the
    /// first row.
    bool alwaysWarmUp = true;
    /// The frame size unless --width or --height is given.
    uint32_t width = kDefaultWidth, height = kDefaultHeight;
    /// Whether it renders: false (the crowd simulation's) leaves the
    /// profiler off and writes no traces.
    bool renders = true;
};

class BenchDriver {
public:
    /// Turns the global profiler on, lists the backends and devices and
    /// makes the trace directory (Options::benchOutDir; with --backend all
    /// next to the output or in the current directory). An error names a
    /// directory that cannot be made or devices that cannot be listed.
    static Result<BenchDriver> start(const Options& options, BenchPlan plan);

    const Options& options() const { return mOptions; }
    /// The backends in the order of the rows; "" stands for the best one
    /// the device runs.
    const std::vector<std::string>& backends() const { return mBackends; }
    /// The devices (Options::device's form: a name or an index); "" stands
    /// for the default one.
    const std::vector<std::string>& devices() const { return mDevices; }
    /// Whether the backends are compared (--backend all): they share the
    /// emulated tessellator's levels.
    bool comparing() const { return mOptions.backend == "all"; }
    uint32_t warmup() const { return mWarmup; }
    uint32_t frames() const { return mFrames; }
    uint32_t width() const { return mWidth; }
    uint32_t height() const { return mHeight; }
    /// The options of a run on `backend` at the benchmark's frame size, on
    /// the device the options name or on `device`.
    Options runOptions(const std::string& backend) const;
    Options runOptions(const std::string& backend, const std::string& device) const;

    /// Runs `render` for `count` frames inside the global profiler's frames,
    /// numbered from `first`; returns the number after the last.
    uint32_t renderFrames(uint32_t first, uint32_t count, const std::function<void(uint32_t frame)>& render) const;
    /// Marks the frames from `firstFrame` on, begun at `startNs`, as one row
    /// named `label` on the trace's CPU track, so the trace reads as the
    /// table's rows.
    void markRow(const std::string& label, uint64_t firstFrame, uint64_t startNs) const;

    /// bench-<stem>.json in the trace directory; "" when no traces are written.
    std::string tracePath(const std::string& stem) const;
    /// Writes the global profiler's events to `path` as a Chrome trace whose
    /// metadata names the benchmark and `session`'s backend, device, driver
    /// and size; nothing when `path` is empty.
    Status writeTrace(const std::string& path, const RenderSession& session) const;

    /// `backend` (on `device`, "" for the default) could not run: `why`.
    /// When the benchmark runs on several backends or devices it goes on
    /// without this one: a warning, a note "<backend> skipped[ on device
    /// D]: <why>" in `notes`, and an ok Status. With one, `why` ends it.
    Status skip(const std::string& backend, const Error& why, std::vector<std::string>& notes,
                const std::string& device = {}) const;

    /// The benchmark's end: an error when it measured no row (`rows` 0),
    /// else `json` to Options::benchOut and `table` to stdout, or without
    /// one the JSON to stdout and the table to stderr (so stdout stays clean
    /// JSON). An output that cannot be written is an error naming it.
    Status finish(size_t rows, const std::string& json, const std::string& table) const;

private:
    BenchDriver(const Options& options, BenchPlan plan);

    Options mOptions;
    BenchPlan mPlan;
    std::vector<std::string> mBackends;
    std::vector<std::string> mDevices;
    std::filesystem::path mTraceDir;
    uint32_t mWarmup = 0, mFrames = 0, mWidth = 0, mHeight = 0;
};

} // namespace tessera::runtime
