#pragma once
/// @file Result.h
/// Checked errors for bad input at public and plugin boundaries.
///
/// Tessera follows Falcor's rule: an assert for a programming error, a Result
/// carrying a human-readable message for anything a user can get wrong
/// (a missing file, a malformed asset, a bad flag, a device that lacks a
/// feature). Messages name the thing at fault ("heights.png: not a PNG file").

#include <cassert>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace tessera {

/// A failure with a message meant for the person running the program.
///
/// Libraries speak their own language: a message about one of the caller's
/// settings names the setting in the library's words ("terrain mode lowres:
/// backend r2vb draws only ..."), never a host's spelling of it such as a
/// command-line flag. `setting` then holds those words, at the start of the
/// message, so a host that takes the setting under another name puts its
/// own in their place (naming()).
struct Error {
    std::string message;
    /// The setting the message is about, as the message begins with it;
    /// empty when it is about none.
    std::string setting = {};

    /// The message with its leading `setting` replaced by `name` (the demo's
    /// "--terrain-mode"); the message itself when it names no setting.
    std::string naming(std::string_view name) const {
        if (setting.empty() || message.compare(0, setting.size(), setting) != 0) return message;
        return std::string(name) + message.substr(setting.size());
    }
};

/// Either a value of type T or an Error. Cheap to move; never throws on access
/// in release builds (accessing the wrong alternative is a programming error).
template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : mData(std::in_place_index<0>, std::move(value)) {}
    Result(Error error) : mData(std::in_place_index<1>, std::move(error)) {}

    /// True when the result holds a value.
    bool ok() const { return mData.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { assert(ok()); return std::get<0>(mData); }
    const T& value() const& { assert(ok()); return std::get<0>(mData); }
    T&& value() && { assert(ok()); return std::get<0>(std::move(mData)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }

    const Error& error() const { assert(!ok()); return std::get<1>(mData); }

private:
    std::variant<T, Error> mData;
};

/// Result of an operation that yields nothing on success.
template <>
class [[nodiscard]] Result<void> {
public:
    Result() = default;
    Result(Error error) : mError(std::move(error)), mOk(false) {}

    bool ok() const { return mOk; }
    explicit operator bool() const { return ok(); }
    const Error& error() const { assert(!ok()); return mError; }

private:
    Error mError;
    bool mOk = true;
};

using Status = Result<void>;

/// Builds an Error from string pieces: `fail("file.png", ": not a PNG")`.
template <class... Parts>
Error fail(Parts&&... parts) {
    std::string message;
    (message.append(std::forward<Parts>(parts)), ...);
    return Error{std::move(message)};
}

/// An Error about the caller's setting `setting`, named in the library's
/// words: `failSetting("terrain mode", " lowres: backend r2vb ...")` makes
/// "terrain mode lowres: backend r2vb ..." with setting "terrain mode".
template <class... Parts>
Error failSetting(std::string setting, Parts&&... parts) {
    Error error = fail(setting, std::forward<Parts>(parts)...);
    error.setting = std::move(setting);
    return error;
}

} // namespace tessera
