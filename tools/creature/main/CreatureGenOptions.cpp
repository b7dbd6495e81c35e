#include "CreatureGenOptions.h"

#include <charconv>
#include <string_view>

namespace tessera::creature {

namespace {

Result<uint32_t> parseCount(std::string_view flag, std::string_view text, uint64_t lo, uint64_t hi) {
    uint64_t value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size())
        return fail(std::string(flag), ": expected a whole number, got '", std::string(text), "'");
    if (value < lo || value > hi)
        return fail(std::string(flag), ": ", std::string(text), " is out of range ", std::to_string(lo), "..",
                    std::to_string(hi));
    return static_cast<uint32_t>(value);
}

} // namespace

Result<CreatureGenOptions> parseCreatureGenOptions(int argc, const char* const* argv) {
    CreatureGenOptions o;
    for (int i = 1; i < argc; ++i) {
        std::string_view arg = argv[i];
        std::string_view value;
        bool hasValue = false;
        if (auto eq = arg.find('='); arg.starts_with("--") && eq != std::string_view::npos) {
            value = arg.substr(eq + 1);
            arg = arg.substr(0, eq);
            hasValue = true;
        }
        auto next = [&]() -> Result<std::string_view> {
            if (hasValue) return value;
            if (i + 1 >= argc) return fail(std::string(arg), ": missing value");
            return std::string_view(argv[++i]);
        };
        auto flagOnly = [&]() -> Status {
            if (hasValue) return fail(std::string(arg), ": takes no value");
            return {};
        };
        Result<uint32_t> number = 0u;
        if (arg == "--help" || arg == "-h") {
            o.help = true;
            continue;
        }
        if (arg == "--uncompressed" || arg == "--quiet") {
            if (auto s = flagOnly(); !s) return s.error();
            (arg == "--quiet" ? o.quiet : o.uncompressed) = true;
            continue;
        }
        auto text = next();
        if (!text) return text.error();
        if (arg == "--out") o.out = std::string(*text);
        else if (arg == "--report") o.report = std::string(*text);
        else if (arg == "--seed") number = parseCount(arg, *text, 0, UINT32_MAX);
        else if (arg == "--map-size") number = parseCount(arg, *text, 64, 2048);
        else if (arg == "--sculpt-triangles") number = parseCount(arg, *text, 10'000, 20'000'000);
        else if (arg == "--cage-triangles") number = parseCount(arg, *text, 500, 50'000);
        else return fail("unknown option '", std::string(arg), "'");
        if (!number) return number.error();
        if (arg == "--seed") o.seed = *number;
        if (arg == "--map-size") o.mapSize = *number;
        if (arg == "--sculpt-triangles") o.sculptTriangles = *number;
        if (arg == "--cage-triangles") o.cageTriangles = *number;
        if ((arg == "--out" || arg == "--report") && text->empty()) return fail(std::string(arg), ": empty path");
    }
    if (!o.help && o.out.empty()) return fail("--out FILE.glb is required");
    return o;
}

std::string creatureGenUsage() {
    return "usage: tessera-creaturegen --seed N --out FILE.glb [--map-size 2048] [--sculpt-triangles 1000000]\n"
           "                           [--cage-triangles 5000] [--report FILE.json] [--uncompressed] [--quiet]\n"
           "Generates a Froblin-like creature, bakes its displacement and normal maps and writes a glTF 2.0\n"
           "binary (Draco-compressed cage unless --uncompressed).\n";
}

} // namespace tessera::creature
