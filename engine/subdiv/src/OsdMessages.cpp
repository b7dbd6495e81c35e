#include "OsdMessages.h"

#include "tessera/core/Log.h"

#include <opensubdiv/far/error.h>

#include <mutex>

namespace tessera::subdiv::detail {

namespace Far = OpenSubdiv::Far;

namespace {
thread_local OsdMessages* tCollector = nullptr;
} // namespace

struct OsdMessageSink {
    static void add(const char* message) {
        std::string text = message ? message : "";
        if (tCollector)
            tCollector->mMessages.push_back(std::move(text));
        else
            log::warning("OpenSubdiv: " + text);
    }
    static void onError(Far::ErrorType, const char* message) { add(message); }
    static void onWarning(const char* message) { add(message); }
};

OsdMessages::OsdMessages() : mOuter(tCollector) {
    static std::once_flag installed;
    std::call_once(installed, [] {
        Far::SetErrorCallback(&OsdMessageSink::onError);
        Far::SetWarningCallback(&OsdMessageSink::onWarning);
    });
    tCollector = this;
}

OsdMessages::~OsdMessages() {
    tCollector = mOuter;
}

std::string OsdMessages::joined() const {
    std::string text;
    for (const std::string& message : mMessages) {
        if (!text.empty()) text += "; ";
        text += message;
    }
    return text;
}

} // namespace tessera::subdiv::detail
