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
#include <utility>
#include <variant>

namespace tessera {

/// A failure with a message meant for the person running the program.
struct Error {
    std::string message;
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

} // namespace tessera
