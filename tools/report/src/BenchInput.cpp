#include "report/BenchInput.h"

#include "tessera/cli/NumberList.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace tessera::report {
namespace {

using nlohmann::json;

/// Reads one member of record `index`, naming the file, the record and the key
/// on failure.
class RecordReader {
public:
    RecordReader(const json& object, const std::string& file, size_t index)
        : mObject(object), mFile(file), mIndex(index) {}

    const std::string& error() const { return mError; }

    std::string text(const char* key, bool required = true) {
        const json* v = find(key, required);
        if (!v) return {};
        if (!v->is_string()) return wrongType(key, "a string"), std::string();
        return v->get<std::string>();
    }

    double number(const char* key, bool required = true) {
        const json* v = find(key, required);
        if (!v) return 0.0;
        if (!v->is_number()) return wrongType(key, "a number"), 0.0;
        return v->get<double>();
    }

    uint64_t count(const char* key, bool required = true) {
        const json* v = find(key, required);
        if (!v) return 0;
        if (!v->is_number_unsigned() && !(v->is_number_integer() && v->get<int64_t>() >= 0))
            return wrongType(key, "a whole number"), 0;
        return v->get<uint64_t>();
    }

private:
    const json* find(const char* key, bool required) {
        if (!mError.empty()) return nullptr;
        auto it = mObject.find(key);
        if (it == mObject.end() || it->is_null()) {
            if (required) mError = prefix() + " has no \"" + key + "\"";
            return nullptr;
        }
        return &*it;
    }
    void wrongType(const char* key, const char* what) {
        if (mError.empty()) mError = prefix() + ": \"" + key + "\" is not " + what;
    }
    std::string prefix() const { return mFile + ": record " + std::to_string(mIndex + 1); }

    const json& mObject;
    const std::string& mFile;
    size_t mIndex;
    std::string mError;
};

} // namespace

std::string BenchRecord::rowLabel() const {
    return view + " " + mode + (metric.empty() || metric == "-" ? std::string() : "/" + metric);
}

Result<std::vector<BenchRecord>> parseBenchRecords(const std::string& text, const std::string& name) {
    json root = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (root.is_discarded()) {
        // Parse again with exceptions for the position and reason; the
        // message names the byte, so a truncated file reads as such.
        try {
            const json again = json::parse(text);
            (void)again;
        } catch (const json::parse_error& e) {
            std::string what = e.what();
            // "[json.exception.parse_error.101] parse error at line 1, column 5: ..."
            const auto colon = what.find("parse error");
            return fail(name, ": malformed JSON (", colon == std::string::npos ? what : what.substr(colon), ")");
        }
        return fail(name, ": malformed JSON");
    }
    if (!root.is_array())
        return fail(name, ": expected a JSON array of benchmark records (tessera-demo --bench terrain --out), got ",
                    root.type_name());
    if (root.empty()) return fail(name, ": holds no benchmark records");
    std::vector<BenchRecord> records;
    for (size_t i = 0; i < root.size(); ++i) {
        const json& item = root[i];
        if (!item.is_object()) return fail(name, ": record ", std::to_string(i + 1), " is not an object");
        RecordReader in(item, name, i);
        BenchRecord r;
        r.backend = in.text("backend");
        r.device = in.text("device");
        r.driver = in.text("driver", false);
        r.view = in.text("view");
        r.mode = in.text("mode");
        r.metric = in.text("metric", false);
        if (r.metric.empty()) r.metric = "-";
        r.width = static_cast<uint32_t>(in.count("width"));
        r.height = static_cast<uint32_t>(in.count("height"));
        r.gpuMs = in.number("gpu_ms_median");
        r.cpuFrameMs = in.number("cpu_frame_ms_median");
        r.triangles = in.count("clipping_invocations");
        r.vertexShaderInvocations = in.count("vertex_shader_invocations", false);
        r.tessEvaluationInvocations = in.count("tess_evaluation_invocations", false);
        r.geometryShaderInvocations = in.count("geometry_shader_invocations", false);
        r.taskShaderInvocations = in.count("task_shader_invocations", false);
        r.meshShaderInvocations = in.count("mesh_shader_invocations", false);
        r.intermediateBytes = in.count("intermediate_bytes", false);
        r.trace = in.text("trace", false);
        const std::string passes = in.text("passes", false);
        if (in.error().empty()) {
            // The record's pass names, by the command line's list rules; an
            // empty name (a stray comma) names no pass.
            for (std::string_view word : cli::splitList(passes)) {
                if (word.empty()) continue;
                const std::string pass(word);
                const std::string key = "pass:" + pass + ":gpu_ms_median";
                PassTime p{pass, in.number(key.c_str())};
                r.passes.push_back(std::move(p));
            }
        }
        if (!in.error().empty()) return Error{in.error()};
        if (r.backend.empty()) return fail(name, ": record ", std::to_string(i + 1), " has an empty \"backend\"");
        records.push_back(std::move(r));
    }
    return records;
}

Result<std::vector<BenchRecord>> loadBenchRecords(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return fail(path.string(), ": no such file (the benchmark's JSON: tessera-demo --bench terrain --backend all "
                                   "--out FILE, or tessera-report --run)");
    if (std::filesystem::is_directory(path, ec)) return fail(path.string(), ": is a folder, not a JSON file");
    std::ifstream in(path, std::ios::binary);
    if (!in) return fail(path.string(), ": cannot open the file");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return fail(path.string(), ": cannot read the file");
    return parseBenchRecords(text.str(), path.string());
}

std::vector<std::string> backendsOf(const std::vector<BenchRecord>& records) {
    std::vector<std::string> out;
    for (const auto& r : records)
        if (r.backend == "hulldomain") {
            out.push_back(r.backend);
            break;
        }
    for (const auto& r : records)
        if (std::find(out.begin(), out.end(), r.backend) == out.end()) out.push_back(r.backend);
    return out;
}

} // namespace tessera::report
