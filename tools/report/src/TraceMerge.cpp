#include "report/TraceMerge.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace tessera::report {
namespace {

using nlohmann::json;

Result<json> readTrace(const TraceSource& source) {
    const std::string name = source.path.string();
    std::ifstream in(source.path, std::ios::binary);
    if (!in) return fail(name, ": no such file or cannot open it (", source.backend, "'s trace)");
    std::ostringstream text;
    text << in.rdbuf();
    json root = json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
    if (root.is_discarded()) return fail(name, ": malformed JSON (", source.backend, "'s trace)");
    if (root.is_object()) {
        auto events = root.find("traceEvents");
        if (events == root.end() || !events->is_array())
            return fail(name, ": not a Chrome trace (no \"traceEvents\" array)");
        return std::move(*events);
    }
    if (root.is_array()) return root;
    return fail(name, ": not a Chrome trace (expected an object or an array of events)");
}

std::string deviceOf(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    json root = json::parse(in, nullptr, false);
    if (!root.is_object()) return {};
    auto meta = root.find("metadata");
    if (meta == root.end() || !meta->is_object()) return {};
    auto device = meta->find("device");
    return device != meta->end() && device->is_string() ? device->get<std::string>() : std::string();
}

json metadataEvent(const char* name, int pid, const char* key, json value) {
    return json{{"name", name}, {"ph", "M"}, {"pid", pid}, {"tid", 0}, {"args", json{{key, std::move(value)}}}};
}

} // namespace

Result<MergedTrace> mergeTraces(const std::vector<TraceSource>& sources) {
    MergedTrace merged;
    json events = json::array();
    json backends = json::array();
    int pid = 0;
    for (const TraceSource& source : sources) {
        auto read = readTrace(source);
        if (!read) return read.error();
        ++pid;
        json& input = read.value();
        double start = std::numeric_limits<double>::infinity();
        for (const json& e : input)
            if (e.is_object() && e.value("ph", "") != "M" && e.contains("ts") && e["ts"].is_number())
                start = std::min(start, e["ts"].get<double>());
        if (start == std::numeric_limits<double>::infinity()) start = 0.0;
        const std::string device = deviceOf(source.path);
        const std::string processName = device.empty() ? source.backend : source.backend + " (" + device + ")";
        events.push_back(metadataEvent("process_name", pid, "name", processName));
        events.push_back(metadataEvent("process_sort_index", pid, "sort_index", pid));
        for (json& e : input) {
            if (!e.is_object()) continue;
            // The source's own process names and orders are replaced by ours.
            const std::string phase = e.value("ph", "");
            const std::string eventName = e.value("name", "");
            if (phase == "M" && (eventName == "process_name" || eventName == "process_sort_index")) continue;
            e["pid"] = pid;
            if (e.contains("ts") && e["ts"].is_number()) {
                // Three decimals of a microsecond, as the writer's own.
                const double shifted = e["ts"].get<double>() - start;
                e["ts"] = std::round(shifted * 1000.0) / 1000.0;
            }
            events.push_back(std::move(e));
        }
        merged.backends.push_back(source.backend);
        backends.push_back(json{
            {"pid", pid}, {"backend", source.backend}, {"device", device}, {"trace", source.path.filename().string()}});
    }
    merged.events = events.size();
    json root{{"displayTimeUnit", "ms"},
              {"traceEvents", std::move(events)},
              {"metadata", json{{"application", "tessera-report"},
                                {"backends", std::move(backends)},
                                {"note", "each backend's trace is shifted to start at 0"}}}};
    merged.json = root.dump();
    return merged;
}

} // namespace tessera::report
