#include "tessera/core/BinaryFile.h"

#include <fstream>

namespace tessera::core {

Status checkBinaryHeader(std::span<const uint8_t> bytes, const BinaryFormat& format, const std::string& name) {
    constexpr size_t kMagicBytes = 8;
    if (bytes.size() < kMagicBytes && std::memcmp(bytes.data(), format.magic, bytes.size()) == 0)
        return fail(name, ": truncated: ", std::to_string(bytes.size()), " bytes");
    if (bytes.size() < kMagicBytes || std::memcmp(bytes.data(), format.magic, kMagicBytes) != 0)
        return fail(name, ": not a Tessera ", format.kind, " (no ", std::string(format.magic, kMagicBytes), " magic)");
    if (bytes.size() < format.headerBytes + format.checksumBytes)
        return fail(name, ": truncated: ", std::to_string(bytes.size()), " bytes, the header alone takes ",
                    std::to_string(format.headerBytes + format.checksumBytes));
    const uint32_t version = getLittle<uint32_t>(bytes, kMagicBytes);
    if (version != format.version)
        return fail(name, ": version ", std::to_string(version), ", this build reads version ",
                    std::to_string(format.version), " (", format.remedy, ")");
    return {};
}

Status checkBinarySizeAndChecksum(std::span<const uint8_t> bytes, uint64_t expected, const std::string& what,
                                  const std::string& name) {
    if (bytes.size() < expected)
        return fail(name, ": truncated: ", std::to_string(bytes.size()), " bytes, ", what, " need ",
                    std::to_string(expected));
    if (bytes.size() > expected)
        return fail(name, ": ", std::to_string(bytes.size() - expected), " bytes after the end of ", what);
    const size_t payload = size_t(expected - sizeof(uint64_t));
    if (getLittle<uint64_t>(bytes, payload) != fnv1a(bytes.first(payload)))
        return fail(name, ": checksum mismatch (the file is corrupted)");
    return {};
}

Result<std::vector<uint8_t>> readBinaryFile(const std::filesystem::path& file, const char* kind, const char* hint) {
    std::ifstream in(file, std::ios::binary | std::ios::ate);
    if (!in) return fail(file.string(), ": cannot open the ", kind, hint);
    // One read of the whole file: its size first.
    const std::streamoff size = in.tellg();
    if (size < 0) return fail(file.string(), ": cannot read the ", kind);
    std::vector<uint8_t> bytes(static_cast<size_t>(size));
    in.seekg(0);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size())))
        return fail(file.string(), ": cannot read the ", kind);
    return bytes;
}

Status writeBinaryFile(const std::filesystem::path& file, std::span<const uint8_t> bytes, const char* kind) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    // Flushed before the check: a full disk shows only when the buffer goes out.
    if (!out || !out.flush()) return fail(file.string(), ": cannot write the ", kind);
    return {};
}

} // namespace tessera::core
