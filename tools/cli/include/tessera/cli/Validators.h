#pragma once
/// @file Validators.h
/// CLI11 validators with Tessera's messages, shared by every program so a
/// range or a choice is checked and worded the same way everywhere. A failed
/// check reads `--flag <message>` (CommandLine::parse). Numbers are read by
/// the rules of NumberList.h, as every list is.

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace tessera::cli {

/// A whole number in [lo, hi]: `expects a whole number from lo to hi, got "x"`.
CLI::Validator count(uint64_t lo, uint64_t hi);
/// A finite number in [lo, hi]: `expects a number from lo to hi, got "x"`.
CLI::Validator number(double lo, double hi);
/// One of `choices`: `expects a, b or c, got "x"`.
CLI::Validator oneOf(std::vector<std::string> choices);
/// A non-empty path: `needs a file name`.
CLI::Validator nonEmpty();

/// "a, b or c", for messages that list choices.
std::string listChoices(const std::vector<std::string>& choices);
/// A number as a user writes it ("14.99", "20"), for messages.
std::string formatNumber(double value);

} // namespace tessera::cli
