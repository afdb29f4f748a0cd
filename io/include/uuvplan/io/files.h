// Whole files: reading one as text with the reason it cannot be read, resolving a path written
// in another file, and writing one atomically (a temporary file beside it, then a rename), so
// that an output is written whole or not at all.
#pragma once

#include <map>
#include <string>

namespace uuvplan::io {

/// Why `path` cannot be read as a file ("it is a directory", the system's reason), "" if it can.
std::string UnreadableReason(const std::string& path);

/// The whole file; throws model::InputError "<path>: cannot open file: <reason>".
std::string ReadFileText(const std::string& path);

/// `file` as written in `base_file`: relative to the directory of `base_file`.
std::string ResolveBeside(const std::string& base_file, const std::string& file);

/// Writes `text` to `path` atomically (temporary file + rename); model::InputError naming the
/// path when it cannot.
void WriteFileAtomically(const std::string& path, const std::string& text);

}  // namespace uuvplan::io
