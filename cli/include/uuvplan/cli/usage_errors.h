// Usage errors of the command line in one form (docs/cli.md, "Common rules"): every message
// starts with "uuvplan:", an unknown command or option names the closest known one by edit
// distance ("uuvplan: unknown command 'foo' (did you mean 'loop'?)"), and every usage error
// exits with status 2 (kExitBadInput).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

namespace uuvplan::cli {

/// Levenshtein distance (insertions, deletions, substitutions, each 1).
int EditDistance(const std::string& a, const std::string& b);

/// The candidate closest to `word` by edit distance when it is close enough to be a typo (at
/// most 2 edits or a third of the word's length, whichever is larger; a name the word begins
/// counts as one edit; between equally close names, the one sharing the longest subsequence);
/// nullopt otherwise.
std::optional<std::string> ClosestName(const std::string& word,
                                       const std::vector<std::string>& candidates);

/// Checks argv before CLI11 parses it, so that an unknown command or option is named as such
/// (CLI11 would first complain of a missing required argument): the first argument must be a
/// command of `app` or a top-level flag, and every later "-x"/"--name" an option of that command.
/// Returns the message ("uuvplan: unknown ...") or nullopt when every name is known.
std::optional<std::string> UnknownNameMessage(const CLI::App& app, int argc,
                                              const char* const* argv);

/// CLI11's own parse error as uuvplan prints it: "uuvplan: " + its message (+ the --help hint).
std::string ParseErrorMessage(const CLI::ParseError& e);

}  // namespace uuvplan::cli
