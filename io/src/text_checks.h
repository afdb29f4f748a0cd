// Checks of an input file's text before a YAML or JSON parser sees it: the parsers
// report a NUL byte or 100,000 nested brackets as "unknown escape character" or "bad file",
// and may echo what they read. These name what is wrong and where, and never quote the file.
#pragma once

#include <string>

namespace uuvplan::io {

/// Deepest nesting of [ ] and { } a uuvplan file may have (the deepest format nests 4).
inline constexpr int kMaxNesting = 64;

/// model::InputError "<path>:<line>: ..." for a control byte other than tab, CR and LF (a NUL:
/// binary data), or for [ / { nested deeper than kMaxNesting outside strings and comments
/// (`hash_comments`: YAML's '#' to the end of the line).
void CheckInputText(const std::string& path, const std::string& text, bool hash_comments);

/// A parser's message without the text it quotes from the file (nlohmann's "; last read: '…'").
std::string WithoutQuotedInput(std::string message);

}  // namespace uuvplan::io
