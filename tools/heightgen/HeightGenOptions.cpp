#include "HeightGenOptions.h"

#include "tessera/terrain/HeightMapGenerator.h"

#include <charconv>
#include <limits>
#include <string_view>

namespace tessera::heightgen {
namespace {

template <class Integer>
Result<Integer> parseInteger(std::string_view flag, std::string_view text) {
    Integer value{};
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec == std::errc::result_out_of_range)
        return fail(flag, ": ", text, " is out of range (at most ",
                    std::to_string(std::numeric_limits<Integer>::max()), ")");
    if (ec != std::errc() || end != text.data() + text.size() || text.empty())
        return fail(flag, ": expected a non-negative whole number, got '", text, "'");
    return value;
}

bool isPowerOfTwo(uint32_t v) { return v != 0 && (v & (v - 1)) == 0; }

} // namespace

std::string heightGenUsage() {
    return "usage: tessera-heightgen --out FILE [options]\n"
           "Generates an eroded mountain height map as a 16-bit grayscale PNG.\n"
           "The same options always give byte-identical files.\n"
           "\n"
           "  --out FILE              output PNG path (required; parent folders are created)\n"
           "  --size N                samples per side, a power of two in 64..8192 (default 2048)\n"
           "  --seed S                landscape seed, 0..2^64-1 (default 1)\n"
           "  --erosion-droplets N    hydraulic erosion droplets (default size*size/4; 0 = none)\n"
           "  --threads N             worker threads, 0 = all (default 0; never changes the output)\n"
           "  --quiet                 no progress bar and no summary line\n"
           "  --help                  print this help and exit\n";
}

Result<HeightGenOptions> parseHeightGenOptions(int argc, const char* const* argv) {
    HeightGenOptions options;
    for (int k = 1; k < argc; ++k) {
        std::string_view arg = argv[k];
        if (arg == "--help" || arg == "-h") {
            options.help = true;
            return options;
        }
        if (arg == "--quiet") {
            options.quiet = true;
            continue;
        }
        if (!arg.starts_with("--")) return fail("unexpected argument '", arg, "'");

        // "--flag=value" or "--flag value".
        std::string_view flag = arg, value;
        bool hasValue = false;
        if (size_t eq = arg.find('='); eq != std::string_view::npos) {
            flag = arg.substr(0, eq);
            value = arg.substr(eq + 1);
            hasValue = true;
        }
        const bool known = flag == "--size" || flag == "--seed" || flag == "--out" ||
                           flag == "--erosion-droplets" || flag == "--threads";
        if (!known) return fail("unknown option '", flag, "'");
        if (!hasValue) {
            if (k + 1 >= argc) return fail(flag, ": missing value");
            value = argv[++k];
        }

        if (flag == "--out") {
            if (value.empty()) return fail("--out: empty file name");
            options.out = std::filesystem::path(value);
        } else if (flag == "--seed") {
            auto seed = parseInteger<uint64_t>(flag, value);
            if (!seed) return seed.error();
            options.seed = *seed;
        } else {
            auto number = parseInteger<uint32_t>(flag, value);
            if (!number) return number.error();
            if (flag == "--size") options.size = *number;
            else if (flag == "--erosion-droplets") options.erosionDroplets = *number;
            else options.threads = *number;
        }
    }

    if (!isPowerOfTwo(options.size) || options.size < terrain::kMinGeneratedSize ||
        options.size > terrain::kMaxGeneratedSize)
        return fail("--size: must be a power of two between 64 and 8192, got ",
                    std::to_string(options.size));
    if (options.out.empty()) return fail("--out: required option missing");
    return options;
}

} // namespace tessera::heightgen
