#pragma once
/// @file SettingFlags.h
/// tessera-demo's names for the settings the libraries name in their own
/// words. The engine and the runtime never spell a demo flag: a message
/// about a setting begins with the library's words for it ("terrain mode
/// lowres: backend r2vb ...", Error::setting), and the runtime names
/// settings inside its advice through runtime::Reporter::name(). The demo
/// puts its flags in their place where it reports, from this one table
/// ("terrain mode" -> "--terrain-mode").

#include "tessera/core/Result.h"

#include <span>
#include <string>
#include <string_view>

namespace tessera::demo {

/// One entry of the table: the libraries' words and the demo's name for them.
struct SettingFlag {
    std::string_view words; ///< as a library names the setting ("terrain mode")
    std::string_view flag;  ///< as the demo takes it ("--terrain-mode")
};

/// Every entry, sorted by words.
std::span<const SettingFlag> settingFlags();

/// The demo's flag for the setting the libraries call `words`; `words`
/// themselves when the demo has no name for them.
std::string flagFor(std::string_view words);

/// `error`'s message with its leading setting named by the demo's flag
/// (Error::naming); the message as it is when it names no setting.
std::string withFlags(const Error& error);

} // namespace tessera::demo
