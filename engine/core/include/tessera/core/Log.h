#pragma once
/// @file Log.h
/// Minimal leveled logging to stderr. Thread-safe; one line per call.

#include <string_view>

namespace tessera::log {

enum class Level { Debug, Info, Warning, Error };

/// Sets the lowest level that is printed (default Info).
void setLevel(Level level);
/// Prints one line with a level prefix when `level` passes the threshold.
void write(Level level, std::string_view message);

inline void debug(std::string_view m) { write(Level::Debug, m); }
inline void info(std::string_view m) { write(Level::Info, m); }
inline void warning(std::string_view m) { write(Level::Warning, m); }
inline void error(std::string_view m) { write(Level::Error, m); }

} // namespace tessera::log
