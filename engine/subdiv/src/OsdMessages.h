#pragma once
// Collects OpenSubdiv's error and warning messages (Far::Error and
// Far::Warning, printed to stdout by default) so create() can return them
// as a Result instead of letting them reach the console.

#include <string>
#include <vector>

namespace tessera::subdiv::detail {

/// While alive, OpenSubdiv messages raised on this thread are collected
/// here rather than printed. Messages from threads without a collector go
/// to Tessera's log. Installs Far's process-wide callbacks on first use.
class OsdMessages {
public:
    OsdMessages();
    ~OsdMessages();
    OsdMessages(const OsdMessages&) = delete;
    OsdMessages& operator=(const OsdMessages&) = delete;

    bool empty() const { return mMessages.empty(); }
    /// Every message so far, joined with "; ".
    std::string joined() const;

private:
    friend struct OsdMessageSink;
    std::vector<std::string> mMessages;
    OsdMessages* mOuter = nullptr;
};

} // namespace tessera::subdiv::detail
